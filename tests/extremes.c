/* Extremes: far from the origin, overflow near the float maximum, damping factors, subnormal speeds.
   Built in float and in double (MOTUS_DOUBLE). */
#include "motus.h"
#include "support/motus_test.h"

TEST(placeholder) { ENSURE(1); }

static const motus_test_case TESTS[] = {
    TEST_CASE(placeholder),
};

int main(int argc, char **argv) { return motus_test_main(argc, argv, TESTS, TEST_COUNT(TESTS)); }
