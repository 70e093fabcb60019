/* motus_test.h - the tests' only framework: ENSURE macros and a runner that takes a test name.

   A test program defines its tests with TEST(name) { ... } and lists them once in a table:
       static const motus_test_case TESTS[] = { TEST_CASE(name), ... };
       int main(int argc, char **argv) { return motus_test_main(argc, argv, TESTS, TEST_COUNT(TESTS)); }
   `prog name` runs one test (ctest registers each name, parsed from the TEST(...) lines), `prog` runs all,
   `prog --list` prints the names. An unknown name fails, so a test missing from the table cannot pass. */
#ifndef MOTUS_TEST_H
#define MOTUS_TEST_H

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

/* Random numbers for the tests: xorshift32 (Marsaglia, 2003) on the caller's state (not 0), the same
   sequence in every build. */
static inline uint32_t motus_test_xorshift32(uint32_t *state) {
    *state ^= *state << 13;
    *state ^= *state >> 17;
    *state ^= *state << 5;
    return *state;
}

static int motus_test_failures;

#define TEST(name) static void test_##name(void)
#define TEST_CASE(name) { #name, test_##name }
#define TEST_COUNT(table) ((int)(sizeof(table) / sizeof((table)[0])))

#define ENSURE(condition)                                                                                   \
    do {                                                                                                    \
        if (!(condition)) {                                                                                 \
            fprintf(stderr, "%s:%d: ENSURE(%s) failed\n", __FILE__, __LINE__, #condition);                  \
            motus_test_failures++;                                                                          \
        }                                                                                                   \
    } while (0)

/* |actual - expected| <= tolerance, printed with enough digits to see the difference. NaN fails. */
#define ENSURE_NEAR(actual, expected, tolerance)                                                            \
    motus_test_near((double)(actual), (double)(expected), (double)(tolerance), #actual, __FILE__, __LINE__)

#define ENSURE_EQ_INT(actual, expected)                                                                     \
    do {                                                                                                    \
        long motus_test_a_ = (long)(actual), motus_test_e_ = (long)(expected);                              \
        if (motus_test_a_ != motus_test_e_) {                                                               \
            fprintf(stderr, "%s:%d: %s = %ld, expected %ld\n", __FILE__, __LINE__, #actual, motus_test_a_,  \
                    motus_test_e_);                                                                         \
            motus_test_failures++;                                                                          \
        }                                                                                                   \
    } while (0)

static int motus_test_near(double actual, double expected, double tolerance, const char *what, const char *file,
                           int line) {
    double error = fabs(actual - expected);
    if (!(error <= tolerance)) {
        fprintf(stderr, "%s:%d: %s = %.9g, expected %.9g within %.3g (off by %.3g)\n", file, line, what, actual,
                expected, tolerance, error);
        motus_test_failures++;
        return 0;
    }
    return 1;
}

typedef struct motus_test_case {
    const char *name;
    void (*run)(void);
} motus_test_case;

static int motus_test_run_one(const motus_test_case *test) {
    int before = motus_test_failures;
    test->run();
    printf("%-44s %s\n", test->name, motus_test_failures == before ? "ok" : "FAILED");
    return motus_test_failures == before;
}

static int motus_test_main(int argc, char **argv, const motus_test_case *tests, int count) {
    int i, passed = 0, failed = 0;
    if (argc > 1 && strcmp(argv[1], "--list") == 0) {
        for (i = 0; i < count; ++i) printf("%s\n", tests[i].name);
        return 0;
    }
    for (i = 0; i < count; ++i) {
        if (argc > 1 && strcmp(argv[1], tests[i].name) != 0) continue;
        if (motus_test_run_one(&tests[i])) passed++;
        else failed++;
    }
    if (passed + failed == 0) {
        fprintf(stderr, "no test named '%s' (try --list)\n", argc > 1 ? argv[1] : "");
        return 2;
    }
    printf("%d passed, %d failed\n", passed, failed);
    return failed == 0 ? 0 : 1;
}

#endif
