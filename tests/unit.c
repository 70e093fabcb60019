/* Unit tests: every function of motus.h and every error path. Built in float and in double (MOTUS_DOUBLE). */
#include "motus.h"
#include "support/motus_test.h"

#include <float.h>
#include <stddef.h>

#ifdef MOTUS_DOUBLE
#define REAL_MAX DBL_MAX
#define REAL_MIN_NORMAL DBL_MIN
#else
#define REAL_MAX FLT_MAX
#define REAL_MIN_NORMAL FLT_MIN
#endif

/* The same declaration raylib.h makes (raylib 5/6). tests/raylib_layout.c repeats this check against the
   real raylib.h when raylib is found; this one runs everywhere. */
typedef struct Vector2 {
    float x;
    float y;
} Vector2;

/* C99 compile-time check: the array size is negative, a compile error, when the condition is false. */
#define STATIC_CHECK(name, condition) typedef char static_check_##name[(condition) ? 1 : -1]
#ifndef MOTUS_DOUBLE
STATIC_CHECK(vec2_size, sizeof(motus_vec2) == sizeof(Vector2));
STATIC_CHECK(vec2_x, offsetof(motus_vec2, x) == offsetof(Vector2, x));
STATIC_CHECK(vec2_y, offsetof(motus_vec2, y) == offsetof(Vector2, y));
#endif
STATIC_CHECK(vec2_no_padding, sizeof(motus_vec2) == 2 * sizeof(motus_real));

static const motus_real DT = (motus_real)(1.0 / 60.0);

static motus_real not_a_number(void) { return (motus_real)NAN; }
static motus_real infinity(void) { return (motus_real)HUGE_VAL; }

/* A particle with every field set to a distinct value, to see that a rejected call changed nothing. */
static motus_particle sample_particle(void) {
    motus_particle p = {{0, 0}, {0, 0}, {0, 0}, 0};
    memset(&p, 0, sizeof p);
    p.position = motus_v2(400, 300);
    p.velocity = motus_v2(3, -4);
    p.force = motus_v2(10, 20);
    p.inverse_mass = MOTUS_R(0.5);
    return p;
}
#define ENSURE_UNCHANGED(particle, before) ENSURE(memcmp(&(particle), &(before), sizeof(before)) == 0)

TEST(version_macros) {
    ENSURE_EQ_INT(MOTUS_VERSION, MOTUS_VERSION_MAJOR * 10000 + MOTUS_VERSION_MINOR * 100 + MOTUS_VERSION_PATCH);
    {
        char expected[32];
        sprintf(expected, "%d.%d.%d", MOTUS_VERSION_MAJOR, MOTUS_VERSION_MINOR, MOTUS_VERSION_PATCH);
        ENSURE(strcmp(expected, MOTUS_VERSION_STRING) == 0);
    }
}

TEST(vec2_layout_matches_raylib) {
#ifndef MOTUS_DOUBLE
    /* An array copied byte for byte, as a game handing particle positions to raylib would. */
    motus_vec2 points[2];
    Vector2 as_raylib[2];
    points[0] = motus_v2(5, 6);
    points[1] = motus_v2(7, 8);
    memcpy(as_raylib, points, sizeof points);
    ENSURE(as_raylib[1].x == 7.0f && as_raylib[1].y == 8.0f);
#endif
    ENSURE_EQ_INT(sizeof(motus_vec2), 2 * sizeof(motus_real));
}

TEST(vec2_helpers) {
    motus_vec2 a = motus_v2(3, 4), b = motus_v2(1, -2);
    ENSURE(a.x == 3 && a.y == 4);
    ENSURE(motus_vec2_add(a, b).x == 4 && motus_vec2_add(a, b).y == 2);
    ENSURE(motus_vec2_sub(a, b).x == 2 && motus_vec2_sub(a, b).y == 6);
    ENSURE(motus_vec2_scale(a, 2).x == 6 && motus_vec2_scale(a, 2).y == 8);
    ENSURE(motus_vec2_dot(a, b) == -5);
    ENSURE(motus_vec2_length(a) == 5);
}

TEST(real_is_finite) {
    ENSURE(motus_real_is_finite(0));
    ENSURE(motus_real_is_finite(-1));
    ENSURE(motus_real_is_finite(REAL_MAX));
    ENSURE(motus_real_is_finite(-REAL_MAX));
    ENSURE(motus_real_is_finite(REAL_MIN_NORMAL / 4)); /* subnormal */
    ENSURE(!motus_real_is_finite(infinity()));
    ENSURE(!motus_real_is_finite(-infinity()));
    ENSURE(!motus_real_is_finite(not_a_number()));
    ENSURE(motus_vec2_is_finite(motus_v2(1, 2)));
    ENSURE(!motus_vec2_is_finite(motus_v2(1, not_a_number())));
    ENSURE(!motus_vec2_is_finite(motus_v2(infinity(), 2)));
}

TEST(init_sets_state) {
    motus_particle p = sample_particle();
    ENSURE_EQ_INT(motus_particle_init(&p, motus_v2(400, 300), 2), MOTUS_OK);
    ENSURE(p.position.x == 400 && p.position.y == 300);
    ENSURE(p.velocity.x == 0 && p.velocity.y == 0);
    ENSURE(p.force.x == 0 && p.force.y == 0);
    ENSURE(p.inverse_mass == MOTUS_R(0.5));
    ENSURE(motus_particle_mass(&p) == 2);
    ENSURE_EQ_INT(motus_particle_check(&p), MOTUS_OK);
}

TEST(init_rejects_bad_mass) {
    const motus_real bad_masses[] = {0, -1, -REAL_MAX, REAL_MIN_NORMAL / 1024};
    int i;
    for (i = 0; i < (int)(sizeof bad_masses / sizeof bad_masses[0]); ++i) {
        motus_particle p = sample_particle(), before = p;
        ENSURE_EQ_INT(motus_particle_init(&p, motus_v2(0, 0), bad_masses[i]), MOTUS_ERROR_INVALID_MASS);
        ENSURE_UNCHANGED(p, before);
    }
    {
        motus_particle p = sample_particle(), before = p;
        ENSURE_EQ_INT(motus_particle_init(&p, motus_v2(0, 0), not_a_number()), MOTUS_ERROR_NOT_FINITE);
        ENSURE_EQ_INT(motus_particle_init(&p, motus_v2(0, 0), infinity()), MOTUS_ERROR_NOT_FINITE);
        ENSURE_UNCHANGED(p, before);
    }
}

TEST(init_rejects_bad_position_and_null) {
    motus_particle p = sample_particle(), before = p;
    ENSURE_EQ_INT(motus_particle_init(&p, motus_v2(not_a_number(), 0), 1), MOTUS_ERROR_NOT_FINITE);
    ENSURE_EQ_INT(motus_particle_init(&p, motus_v2(0, -infinity()), 1), MOTUS_ERROR_NOT_FINITE);
    ENSURE_EQ_INT(motus_particle_init_immovable(&p, motus_v2(infinity(), 0)), MOTUS_ERROR_NOT_FINITE);
    ENSURE_UNCHANGED(p, before);
    ENSURE_EQ_INT(motus_particle_init(NULL, motus_v2(0, 0), 1), MOTUS_ERROR_NULL_POINTER);
    ENSURE_EQ_INT(motus_particle_init_immovable(NULL, motus_v2(0, 0)), MOTUS_ERROR_NULL_POINTER);
}

TEST(immovable_particle_ignores_forces) {
    motus_particle wall = sample_particle();
    int i;
    ENSURE_EQ_INT(motus_particle_init_immovable(&wall, motus_v2(5, 6)), MOTUS_OK);
    ENSURE(wall.inverse_mass == 0);
    ENSURE(motus_particle_mass(&wall) == infinity());
    for (i = 0; i < 100; ++i) {
        ENSURE_EQ_INT(motus_particle_add_force(&wall, motus_v2(1e6f, -1e6f)), MOTUS_OK);
        ENSURE_EQ_INT(motus_particle_step(&wall, DT), MOTUS_OK);
    }
    ENSURE(wall.position.x == 5 && wall.position.y == 6);
    ENSURE(wall.velocity.x == 0 && wall.velocity.y == 0);
    ENSURE(wall.force.x == 1e8f); /* the accumulator still adds up; it just moves nothing */
}

TEST(mass_getter) {
    motus_particle p = {{0, 0}, {0, 0}, {0, 0}, 0};
    motus_particle_init(&p, motus_v2(0, 0), 4);
    ENSURE(motus_particle_mass(&p) == 4);
    ENSURE(motus_particle_mass(NULL) != motus_particle_mass(NULL)); /* NaN */
}

TEST(check_reports_broken_fields) {
    motus_particle p = sample_particle();
    ENSURE_EQ_INT(motus_particle_check(&p), MOTUS_OK);
    p.velocity.y = not_a_number();
    ENSURE_EQ_INT(motus_particle_check(&p), MOTUS_ERROR_NOT_FINITE);
    p = sample_particle();
    p.force.x = infinity();
    ENSURE_EQ_INT(motus_particle_check(&p), MOTUS_ERROR_NOT_FINITE);
    p = sample_particle();
    p.position.x = -infinity();
    ENSURE_EQ_INT(motus_particle_check(&p), MOTUS_ERROR_NOT_FINITE);
    p = sample_particle();
    p.inverse_mass = not_a_number();
    ENSURE_EQ_INT(motus_particle_check(&p), MOTUS_ERROR_NOT_FINITE);
    p = sample_particle();
    p.inverse_mass = -1;
    ENSURE_EQ_INT(motus_particle_check(&p), MOTUS_ERROR_INVALID_MASS);
    ENSURE_EQ_INT(motus_particle_check(NULL), MOTUS_ERROR_NULL_POINTER);
}

TEST(add_and_clear_forces) {
    motus_particle p = {{0, 0}, {0, 0}, {0, 0}, 0};
    motus_particle_init(&p, motus_v2(0, 0), 2);
    ENSURE_EQ_INT(motus_particle_add_force(&p, motus_v2(0, -100)), MOTUS_OK); /* W */
    ENSURE_EQ_INT(motus_particle_add_force(&p, motus_v2(100, 0)), MOTUS_OK);  /* D */
    ENSURE(p.force.x == 100 && p.force.y == -100);
    ENSURE_EQ_INT(motus_particle_add_force(&p, motus_v2(-100, 0)), MOTUS_OK); /* A cancels D */
    ENSURE(p.force.x == 0 && p.force.y == -100);
    ENSURE_EQ_INT(motus_particle_clear_forces(&p), MOTUS_OK);
    ENSURE(p.force.x == 0 && p.force.y == 0);
    ENSURE_EQ_INT(motus_particle_clear_forces(NULL), MOTUS_ERROR_NULL_POINTER);
}

TEST(add_force_rejects_bad_input) {
    motus_particle p = sample_particle(), before = p;
    ENSURE_EQ_INT(motus_particle_add_force(&p, motus_v2(not_a_number(), 0)), MOTUS_ERROR_NOT_FINITE);
    ENSURE_EQ_INT(motus_particle_add_force(&p, motus_v2(0, infinity())), MOTUS_ERROR_NOT_FINITE);
    ENSURE_UNCHANGED(p, before);
    p.force = motus_v2(REAL_MAX, 0);
    before = p;
    ENSURE_EQ_INT(motus_particle_add_force(&p, motus_v2(REAL_MAX, 0)), MOTUS_ERROR_OVERFLOW);
    ENSURE_UNCHANGED(p, before);
    p.force.x = not_a_number(); /* an accumulator that is already broken is reported, not added to */
    before = p;
    ENSURE_EQ_INT(motus_particle_add_force(&p, motus_v2(1, 1)), MOTUS_ERROR_NOT_FINITE);
    ENSURE_UNCHANGED(p, before);
    ENSURE_EQ_INT(motus_particle_add_force(NULL, motus_v2(1, 1)), MOTUS_ERROR_NULL_POINTER);
}

TEST(step_is_semi_implicit_euler) {
    /* One step by hand: v1 = v0 + F/m*dt, x1 = x0 + v1*dt (the new velocity). */
    motus_particle p = sample_particle();
    const motus_real dt = MOTUS_R(0.25);
    motus_real vx = p.velocity.x + p.force.x * p.inverse_mass * dt;
    motus_real vy = p.velocity.y + p.force.y * p.inverse_mass * dt;
    motus_real xx = p.position.x + vx * dt, xy = p.position.y + vy * dt;
    ENSURE_EQ_INT(motus_particle_step(&p, dt), MOTUS_OK);
    ENSURE(p.velocity.x == vx && p.velocity.y == vy);
    ENSURE(p.position.x == xx && p.position.y == xy);
    ENSURE(p.force.x == 10 && p.force.y == 20); /* step does not clear forces */
}

TEST(step_rejects_bad_time_step) {
    const motus_real bad[] = {0, -DT, -0.0};
    int i;
    motus_particle p = sample_particle(), before = p;
    for (i = 0; i < 3; ++i) ENSURE_EQ_INT(motus_particle_step(&p, bad[i]), MOTUS_ERROR_INVALID_TIME_STEP);
    ENSURE_EQ_INT(motus_particle_step(&p, not_a_number()), MOTUS_ERROR_INVALID_TIME_STEP);
    ENSURE_EQ_INT(motus_particle_step(&p, infinity()), MOTUS_ERROR_INVALID_TIME_STEP);
    ENSURE_UNCHANGED(p, before);
    ENSURE_EQ_INT(motus_particle_step(NULL, DT), MOTUS_ERROR_NULL_POINTER);
}

TEST(step_rejects_broken_particle) {
    /* A NaN anywhere in the particle is reported and the particle is left as it came: NaN does not spread. */
    motus_real *fields[7];
    int i;
    for (i = 0; i < 7; ++i) {
        motus_particle p = sample_particle(), before;
        fields[0] = &p.position.x, fields[1] = &p.position.y, fields[2] = &p.velocity.x;
        fields[3] = &p.velocity.y, fields[4] = &p.force.x, fields[5] = &p.force.y, fields[6] = &p.inverse_mass;
        *fields[i] = i % 2 ? not_a_number() : infinity();
        before = p;
        ENSURE_EQ_INT(motus_particle_step(&p, DT), MOTUS_ERROR_NOT_FINITE);
        ENSURE_EQ_INT(motus_particle_step_linear_drag(&p, 1, DT), MOTUS_ERROR_NOT_FINITE);
        ENSURE_UNCHANGED(p, before);
    }
    {
        motus_particle p = sample_particle(), before;
        p.inverse_mass = -1;
        before = p;
        ENSURE_EQ_INT(motus_particle_step(&p, DT), MOTUS_ERROR_INVALID_MASS);
        ENSURE_EQ_INT(motus_particle_step_linear_drag(&p, 1, DT), MOTUS_ERROR_INVALID_MASS);
        ENSURE_UNCHANGED(p, before);
    }
}

TEST(step_reports_overflow) {
    motus_particle p = sample_particle(), before;
    p.velocity = motus_v2(REAL_MAX, 0);
    p.force = motus_v2(REAL_MAX, 0);
    p.inverse_mass = 1;
    before = p;
    ENSURE_EQ_INT(motus_particle_step(&p, 1), MOTUS_ERROR_OVERFLOW);
    ENSURE_EQ_INT(motus_particle_step_linear_drag(&p, 0, 1), MOTUS_ERROR_OVERFLOW);
    ENSURE_UNCHANGED(p, before);
    /* Position overflow alone, with a velocity that is still finite. */
    p = sample_particle();
    p.position = motus_v2(REAL_MAX, 0);
    p.velocity = motus_v2(REAL_MAX / 2, 0);
    before = p;
    ENSURE_EQ_INT(motus_particle_step(&p, 4), MOTUS_ERROR_OVERFLOW);
    ENSURE_UNCHANGED(p, before);
}

TEST(damp_per_step) {
    motus_particle p = sample_particle(), before;
    ENSURE_EQ_INT(motus_particle_damp_per_step(&p, MOTUS_R(0.99)), MOTUS_OK);
    ENSURE(p.velocity.x == 3 * MOTUS_R(0.99) && p.velocity.y == -4 * MOTUS_R(0.99));
    ENSURE_EQ_INT(motus_particle_damp_per_step(&p, 1), MOTUS_OK);
    ENSURE(p.velocity.x == 3 * MOTUS_R(0.99));
    ENSURE_EQ_INT(motus_particle_damp_per_step(&p, 0), MOTUS_OK);
    ENSURE(p.velocity.x == 0 && p.velocity.y == 0);
    p = sample_particle();
    before = p;
    ENSURE_EQ_INT(motus_particle_damp_per_step(&p, MOTUS_R(1.01)), MOTUS_ERROR_INVALID_DAMPING);
    ENSURE_EQ_INT(motus_particle_damp_per_step(&p, MOTUS_R(-0.5)), MOTUS_ERROR_INVALID_DAMPING);
    ENSURE_EQ_INT(motus_particle_damp_per_step(&p, not_a_number()), MOTUS_ERROR_INVALID_DAMPING);
    ENSURE_UNCHANGED(p, before);
    p.velocity.x = not_a_number();
    before = p;
    ENSURE_EQ_INT(motus_particle_damp_per_step(&p, MOTUS_R(0.5)), MOTUS_ERROR_NOT_FINITE);
    ENSURE_UNCHANGED(p, before);
    ENSURE_EQ_INT(motus_particle_damp_per_step(NULL, MOTUS_R(0.5)), MOTUS_ERROR_NULL_POINTER);
}

/* Coast for one second at `rate` steps per second with per-second damping; return the speed left. */
static motus_real speed_after_one_second(int rate, motus_real retained_per_second) {
    motus_particle p = {{0, 0}, {0, 0}, {0, 0}, 0};
    int i;
    motus_particle_init(&p, motus_v2(0, 0), 1);
    p.velocity = motus_v2(100, 0);
    for (i = 0; i < rate; ++i) {
        motus_particle_step(&p, MOTUS_R(1.0) / (motus_real)rate);
        motus_particle_damp_per_second(&p, retained_per_second, MOTUS_R(1.0) / (motus_real)rate);
    }
    return p.velocity.x;
}

TEST(damp_per_second_is_frame_rate_independent) {
    /* 0.99 per step at 60 Hz is 0.547 per second. Per-second damping keeps 54.7 at 30, 60 and 144 Hz; the
       tolerance is rounding: one relative epsilon per multiplication. */
    const motus_real retained = motus_damping_per_second_from_per_step(MOTUS_R(0.99), 60);
    ENSURE_NEAR(retained, pow(0.99, 60), 4 * MOTUS_REAL_EPSILON);
    ENSURE_NEAR(speed_after_one_second(30, retained), 100 * pow(0.99, 60), 100 * 40 * MOTUS_REAL_EPSILON);
    ENSURE_NEAR(speed_after_one_second(60, retained), 100 * pow(0.99, 60), 100 * 70 * MOTUS_REAL_EPSILON);
    ENSURE_NEAR(speed_after_one_second(144, retained), 100 * pow(0.99, 60), 100 * 150 * MOTUS_REAL_EPSILON);
    ENSURE(speed_after_one_second(60, 1) == 100);
    ENSURE(speed_after_one_second(60, 0) == 0);
}

TEST(damp_per_second_rejects_bad_input) {
    motus_particle p = sample_particle(), before = p;
    ENSURE_EQ_INT(motus_particle_damp_per_second(&p, MOTUS_R(1.5), DT), MOTUS_ERROR_INVALID_DAMPING);
    ENSURE_EQ_INT(motus_particle_damp_per_second(&p, -1, DT), MOTUS_ERROR_INVALID_DAMPING);
    ENSURE_EQ_INT(motus_particle_damp_per_second(&p, not_a_number(), DT), MOTUS_ERROR_INVALID_DAMPING);
    ENSURE_EQ_INT(motus_particle_damp_per_second(&p, MOTUS_R(0.5), 0), MOTUS_ERROR_INVALID_TIME_STEP);
    ENSURE_EQ_INT(motus_particle_damp_per_second(&p, MOTUS_R(0.5), infinity()), MOTUS_ERROR_INVALID_TIME_STEP);
    ENSURE_UNCHANGED(p, before);
    p.velocity.y = infinity();
    before = p;
    ENSURE_EQ_INT(motus_particle_damp_per_second(&p, MOTUS_R(0.5), DT), MOTUS_ERROR_NOT_FINITE);
    ENSURE_UNCHANGED(p, before);
    ENSURE_EQ_INT(motus_particle_damp_per_second(NULL, MOTUS_R(0.5), DT), MOTUS_ERROR_NULL_POINTER);
    ENSURE(motus_damping_per_second_from_per_step(2, 60) != motus_damping_per_second_from_per_step(2, 60));
    ENSURE(motus_damping_per_second_from_per_step(MOTUS_R(0.5), 0) !=
           motus_damping_per_second_from_per_step(MOTUS_R(0.5), 0));
}

/* The continuous solution of dv/dt = a - k*v from x0, v0, in double. */
static double drag_position(double x0, double v0, double a, double k, double t) {
    if (k == 0) return x0 + v0 * t + 0.5 * a * t * t;
    return x0 + (a / k) * t + (v0 - a / k) * (1 - exp(-k * t)) / k;
}
static double drag_velocity(double v0, double a, double k, double t) {
    if (k == 0) return v0 + a * t;
    return a / k + (v0 - a / k) * exp(-k * t);
}

/* Run the exact drag stepper for one second at `rate` and compare with the closed form. */
static void check_linear_drag(double k, int rate) {
    motus_particle p = {{0, 0}, {0, 0}, {0, 0}, 0};
    const double a = 50, v0 = -20, x0 = 400;
    int i;
    motus_particle_init(&p, motus_v2((motus_real)x0, 300), 2);
    p.velocity.x = (motus_real)v0;
    motus_particle_add_force(&p, motus_v2(100, 0));
    for (i = 0; i < rate; ++i) ENSURE_EQ_INT(motus_particle_step_linear_drag(&p, (motus_real)k, MOTUS_R(1.0) / (motus_real)rate), MOTUS_OK);
    /* Rounding only: each step rounds x (about 400) and v (about 30) to a few ulps. */
    ENSURE_NEAR(p.position.x, drag_position(x0, v0, a, k, 1.0), rate * 4 * 430 * MOTUS_REAL_EPSILON);
    ENSURE_NEAR(p.velocity.x, drag_velocity(v0, a, k, 1.0), rate * 4 * 60 * MOTUS_REAL_EPSILON);
    ENSURE(p.position.y == 300);
}

TEST(step_linear_drag_is_exact_at_any_rate) {
    const double rates_k[] = {0, 0.05, 0.6, 3, 40};
    int i;
    for (i = 0; i < 5; ++i) {
        check_linear_drag(rates_k[i], 30);
        check_linear_drag(rates_k[i], 60);
        check_linear_drag(rates_k[i], 144);
        check_linear_drag(rates_k[i], 1); /* one step of a whole second */
    }
}

TEST(step_linear_drag_series_meets_direct_formula) {
    /* phi1, phi2 switch from series to expm1 at u = 0.5: both sides must agree there. */
    motus_real below1, below2, above1, above2;
    motus_real u = MOTUS_R(0.5);
    motus__drag_phi(u * (1 - MOTUS_REAL_EPSILON), &below1, &below2);
    motus__drag_phi(u, &above1, &above2);
    ENSURE_NEAR(below1, (1 - exp(-0.5)) / 0.5, 8 * MOTUS_REAL_EPSILON);
    ENSURE_NEAR(above1, (1 - exp(-0.5)) / 0.5, 8 * MOTUS_REAL_EPSILON);
    ENSURE_NEAR(below2, (0.5 - 1 + exp(-0.5)) / 0.25, 8 * MOTUS_REAL_EPSILON);
    ENSURE_NEAR(above2, (0.5 - 1 + exp(-0.5)) / 0.25, 8 * MOTUS_REAL_EPSILON);
    motus__drag_phi(0, &below1, &below2);
    ENSURE(below1 == 1 && below2 == MOTUS_R(0.5));
}

TEST(step_linear_drag_rejects_bad_input) {
    motus_particle p = sample_particle(), before = p;
    ENSURE_EQ_INT(motus_particle_step_linear_drag(&p, -1, DT), MOTUS_ERROR_INVALID_DAMPING);
    ENSURE_EQ_INT(motus_particle_step_linear_drag(&p, not_a_number(), DT), MOTUS_ERROR_NOT_FINITE);
    ENSURE_EQ_INT(motus_particle_step_linear_drag(&p, infinity(), DT), MOTUS_ERROR_NOT_FINITE);
    ENSURE_EQ_INT(motus_particle_step_linear_drag(&p, 1, 0), MOTUS_ERROR_INVALID_TIME_STEP);
    ENSURE_EQ_INT(motus_particle_step_linear_drag(&p, 1, not_a_number()), MOTUS_ERROR_INVALID_TIME_STEP);
    ENSURE_UNCHANGED(p, before);
    ENSURE_EQ_INT(motus_particle_step_linear_drag(NULL, 1, DT), MOTUS_ERROR_NULL_POINTER);
}

TEST(result_strings_are_distinct) {
    int i, j;
    for (i = 0; i < MOTUS_RESULT_COUNT; ++i) {
        const char *message = motus_result_string((motus_result)i);
        ENSURE(message != NULL && strlen(message) > 1);
        ENSURE(strcmp(message, motus_result_string(MOTUS_RESULT_COUNT)) != 0);
        for (j = 0; j < i; ++j) ENSURE(strcmp(message, motus_result_string((motus_result)j)) != 0);
    }
    ENSURE(strcmp(motus_result_string((motus_result)12345), "unknown motus_result value") == 0);
}

static const motus_test_case TESTS[] = {
    TEST_CASE(version_macros),
    TEST_CASE(vec2_layout_matches_raylib),
    TEST_CASE(vec2_helpers),
    TEST_CASE(real_is_finite),
    TEST_CASE(init_sets_state),
    TEST_CASE(init_rejects_bad_mass),
    TEST_CASE(init_rejects_bad_position_and_null),
    TEST_CASE(immovable_particle_ignores_forces),
    TEST_CASE(mass_getter),
    TEST_CASE(check_reports_broken_fields),
    TEST_CASE(add_and_clear_forces),
    TEST_CASE(add_force_rejects_bad_input),
    TEST_CASE(step_is_semi_implicit_euler),
    TEST_CASE(step_rejects_bad_time_step),
    TEST_CASE(step_rejects_broken_particle),
    TEST_CASE(step_reports_overflow),
    TEST_CASE(damp_per_step),
    TEST_CASE(damp_per_second_is_frame_rate_independent),
    TEST_CASE(damp_per_second_rejects_bad_input),
    TEST_CASE(step_linear_drag_is_exact_at_any_rate),
    TEST_CASE(step_linear_drag_series_meets_direct_formula),
    TEST_CASE(step_linear_drag_rejects_bad_input),
    TEST_CASE(result_strings_are_distinct),
};

int main(int argc, char **argv) { return motus_test_main(argc, argv, TESTS, TEST_COUNT(TESTS)); }
