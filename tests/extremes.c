/* Extremes: far from the origin, overflow near the float maximum, damping factors, subnormal speeds, and
   the adversarial classes of issue 11 item 8 (a stable dt of -0, an attractor 1e13 and 1e20 m away, the exact
   stepper at drag 1e38 over 1e20 s, a spring of 1e20 N/m at its rest length of 1e20 m, a subnormal dt split
   in substeps, the stable dt without scratch, a quadratic drag at a speed whose square overflows, an
   attractor whose strength is near the largest real). Built in float and in double (MOTUS_DOUBLE). The
   far-from-origin and subnormal tests print the figures they measure (run
   `motus_extremes far_from_origin_plain_step_loses_small_steps`, ...). */
#define MOTUS_IMPLEMENTATION
#include "motus.h"
#include "support/motus_test.h"

#include <float.h>

#ifdef MOTUS_DOUBLE
#define REAL_MAX DBL_MAX
#define REAL_MIN_NORMAL DBL_MIN
#define REAL_TRUE_MIN 4.9406564584124654e-324
#define PRECISION "double"
#else
#define REAL_MAX FLT_MAX
#define REAL_MIN_NORMAL FLT_MIN
#define REAL_TRUE_MIN 1.40129846e-45f
#define PRECISION "float"
#endif

/* motus_method_name, never NULL (GCC's -Wformat-overflow sees the NULL for a bad method through the inlining). */
static const char *method_name(motus_method method) {
    const char *name = motus_method_name(method);
    return name ? name : "?";
}

static const motus_real DT = (motus_real)(1.0 / 60.0);

static motus_real not_a_number(void) { return (motus_real)NAN; }
static motus_real infinity(void) { return (motus_real)HUGE_VAL; }
static int same_bytes(const void *a, const void *b, size_t n) { return memcmp(a, b, n) == 0; }
static int is_subnormal(motus_real x) { return x != 0 && x < REAL_MIN_NORMAL && x > -REAL_MIN_NORMAL; }

/* =================================================================================================
   Far from the origin: 1e6 m, 1 m/s, dt 1/60, 60 s
   ================================================================================================= */
#define FAR 1e6
#define FAR_STEPS 3600 /* 60 s at 60 Hz */

static motus_particle far_particle(void) {
    motus_particle p;
    motus_particle_init(&p, motus_v2((motus_real)FAR, -(motus_real)FAR), 1);
    p.velocity = motus_v2(1, -1);
    return p;
}
/* Where FAR_STEPS steps of v*dt should land: the stepped dt (1/60 rounded to motus_real), summed in double. */
static double far_expected(void) { return FAR + FAR_STEPS * (double)((motus_real)1 * DT); }

TEST(far_from_origin_plain_step_loses_small_steps) {
    motus_particle p = far_particle();
    double error;
    int i;
    for (i = 0; i < FAR_STEPS; ++i) ENSURE_EQ_INT(motus_particle_step(&p, DT), MOTUS_OK);
    error = fabs((double)p.position.x - far_expected());
    printf("  %s, plain step: x = %.6f after 60 s at 1 m/s from 1e6 m, error %.3g m\n", PRECISION,
           (double)p.position.x, error);
#ifdef MOTUS_DOUBLE
    ENSURE(error < 1e-6); /* 3600 roundings of half an ulp (5.8e-11 m) at most */
#else
    /* 0.0167 m is below half an ulp (0.03125 m) at 1e6 m: every step rounds back, the particle stays. */
    ENSURE(p.position.x == (motus_real)FAR && p.position.y == -(motus_real)FAR);
    ENSURE(error > 59.9);
#endif
}

TEST(far_from_origin_compensated_step_keeps_small_steps) {
    motus_particle p = far_particle(), plain = far_particle();
    motus_vec2 carry = motus_v2(0, 0);
    double error, error_with_carry;
    int i;
    for (i = 0; i < FAR_STEPS; ++i) {
        ENSURE_EQ_INT(motus_particle_step_compensated(&p, &carry, DT), MOTUS_OK);
        motus_particle_step(&plain, DT);
    }
    error = fabs((double)p.position.x - far_expected());
    error_with_carry = fabs((double)p.position.x + (double)carry.x - far_expected());
    printf("  %s, compensated step: x = %.6f, error %.3g m (x + carry: %.3g m)\n", PRECISION, (double)p.position.x,
           error, error_with_carry);
    /* The stored position is the nearest value to x + carry (half an ulp), and x + carry is off only by the
       rounding of each v*dt + carry (an ulp of 0.017 m per step). */
    ENSURE(error <= 0.5 * (FAR * MOTUS_REAL_EPSILON) + 1e-9);
    ENSURE(error_with_carry < FAR_STEPS * 4 * 0.0167 * MOTUS_REAL_EPSILON);
    ENSURE(fabs(-(double)p.position.y - far_expected()) == error); /* y mirrors x */
    ENSURE(same_bytes(&p.velocity, &plain.velocity, sizeof p.velocity)); /* the velocity is the plain step's */
}

TEST(compensated_step_is_the_plain_step_near_the_origin) {
    /* With carry 0 the first step is motus_particle_step's bit for bit, force included; near the origin
       the two agree to rounding over a long run. */
    motus_particle p, q;
    motus_vec2 carry = motus_v2(0, 0);
    int i;
    motus_particle_init(&p, motus_v2(3, -2), 2);
    p.velocity = motus_v2(MOTUS_R(0.7), 5);
    motus_particle_add_force(&p, motus_v2(100, -30));
    q = p;
    ENSURE_EQ_INT(motus_particle_step_compensated(&p, &carry, DT), MOTUS_OK);
    ENSURE_EQ_INT(motus_particle_step(&q, DT), MOTUS_OK);
    ENSURE(same_bytes(&p, &q, sizeof p));
    for (i = 0; i < 600; ++i) {
        motus_particle_step_compensated(&p, &carry, DT);
        motus_particle_step(&q, DT);
    }
    ENSURE(same_bytes(&p.velocity, &q.velocity, sizeof p.velocity));
    ENSURE_NEAR(p.position.x, q.position.x, 600 * 4 * 5000 * MOTUS_REAL_EPSILON);
}

TEST(compensated_step_rejects_bad_input) {
    motus_particle p = far_particle(), before;
    motus_vec2 carry = motus_v2(MOTUS_R(0.01), 0), carry_before = carry, bad_carry = motus_v2(not_a_number(), 0);
    before = p;
    ENSURE_EQ_INT(motus_particle_step_compensated(NULL, &carry, DT), MOTUS_ERROR_NULL_POINTER);
    ENSURE_EQ_INT(motus_particle_step_compensated(&p, NULL, DT), MOTUS_ERROR_NULL_POINTER);
    ENSURE_EQ_INT(motus_particle_step_compensated(&p, &carry, -DT), MOTUS_ERROR_INVALID_TIME_STEP);
    ENSURE_EQ_INT(motus_particle_step_compensated(&p, &carry, not_a_number()), MOTUS_ERROR_INVALID_TIME_STEP);
    ENSURE_EQ_INT(motus_particle_step_compensated(&p, &bad_carry, DT), MOTUS_ERROR_NOT_FINITE);
    p.velocity.y = infinity();
    ENSURE_EQ_INT(motus_particle_step_compensated(&p, &carry, DT), MOTUS_ERROR_NOT_FINITE);
    p = before;
    p.inverse_mass = -1;
    ENSURE_EQ_INT(motus_particle_step_compensated(&p, &carry, DT), MOTUS_ERROR_INVALID_MASS);
    p = before;
    p.position.x = REAL_MAX;
    p.velocity.x = REAL_MAX / 2;
    before = p;
    ENSURE_EQ_INT(motus_particle_step_compensated(&p, &carry, 4), MOTUS_ERROR_OVERFLOW);
    ENSURE(same_bytes(&p, &before, sizeof p));
    ENSURE(same_bytes(&carry, &carry_before, sizeof carry));
}


TEST(far_from_origin_compensated_step_3d) {
    /* The same in 3D, each axis at its own distance (z at -1e6 m moving -1 m/s): the carry keeps every
       component's small steps; the plain 3D step loses them in float as the 2D one does. */
    motus_particle3 p, plain;
    motus_vec3 carry = motus_v3(0, 0, 0);
    double error_x, error_z;
    int i;
    motus_particle3_init(&p, motus_v3((motus_real)FAR, 5, -(motus_real)FAR), 1);
    p.velocity = motus_v3(1, 0, -1);
    plain = p;
    for (i = 0; i < FAR_STEPS; ++i) {
        ENSURE_EQ_INT(motus_particle3_step_compensated(&p, &carry, DT), MOTUS_OK);
        ENSURE_EQ_INT(motus_particle3_step(&plain, DT), MOTUS_OK);
    }
    error_x = fabs((double)p.position.x - far_expected());
    error_z = fabs(-(double)p.position.z - far_expected());
    printf("  %s, 3D compensated step: x error %.3g m, z error %.3g m; plain x error %.3g m\n", PRECISION, error_x,
           error_z, fabs((double)plain.position.x - far_expected()));
    ENSURE(error_x <= 0.5 * (FAR * MOTUS_REAL_EPSILON) + 1e-9);
    ENSURE(error_z == error_x);
    ENSURE(p.position.y == 5);
    ENSURE(same_bytes(&p.velocity, &plain.velocity, sizeof p.velocity));
#ifndef MOTUS_DOUBLE
    ENSURE(plain.position.x == (motus_real)FAR && plain.position.z == -(motus_real)FAR);
#endif
}

/* =================================================================================================
   Overflow near the float maximum: reported, nothing written
   ================================================================================================= */
/* |got/expected - 1| <= 1e-5, expected formed in long double, each product within the real's range:
   valgrind computes long double as double, where (long double)DBL_MAX * 2 overflows */
static int near_relative(motus_real got, long double expected) {
    return motus_real_is_finite(got) && fabsl((long double)got / expected - 1) <= 1e-5L;
}
TEST(particle_step_overflow_near_max) {
    /* Velocity: v + F/m*dt past the maximum; position: x + v*dt past it; both near +-max; 2D and 3D. */
    const motus_real near_max = REAL_MAX * MOTUS_R(0.75);
    int sign;
    for (sign = -1; sign <= 1; sign += 2) {
        const motus_real s = (motus_real)sign;
        motus_particle p, before;
        motus_particle3 q, before3;
        memset(&q, 0, sizeof q);
        motus_particle_init(&p, motus_v2(0, 0), 1);
        p.velocity = motus_v2(0, s * near_max);
        p.force = motus_v2(0, s * near_max);
        before = p;
        ENSURE_EQ_INT(motus_particle_step(&p, 1), MOTUS_ERROR_OVERFLOW);
        ENSURE(same_bytes(&p, &before, sizeof p));
        p.force = motus_v2(0, 0);
        p.position = motus_v2(s * near_max, 0);
        p.velocity = motus_v2(s * near_max, 0);
        before = p;
        ENSURE_EQ_INT(motus_particle_step(&p, 1), MOTUS_ERROR_OVERFLOW);
        ENSURE(same_bytes(&p, &before, sizeof p));
        /* A quarter step is fine: dt small enough to stay finite. */
        ENSURE_EQ_INT(motus_particle_step(&p, MOTUS_R(0.25)), MOTUS_OK);
        ENSURE(motus_real_is_finite(p.position.x));
        /* A force at the maximum on a light particle: F/m overflows, F/m*dt does not (the rescue takes it),
           while at dt = 4 it does. */
        motus_particle_init(&p, motus_v2(0, 0), MOTUS_R(0.5));
        p.force = motus_v2(s * REAL_MAX, 0);
        before = p;
        ENSURE_EQ_INT(motus_particle_step(&p, 4), MOTUS_ERROR_OVERFLOW);
        ENSURE(same_bytes(&p, &before, sizeof p));
        ENSURE_EQ_INT(motus_particle_step(&p, MOTUS_R(1e-6)), MOTUS_OK);
        ENSURE(near_relative(p.velocity.x, s * (long double)REAL_MAX * ((long double)MOTUS_R(1e-6) * 2)));
        motus_particle3_init(&q, motus_v3(0, 0, s * near_max), 1);
        q.velocity = motus_v3(0, 0, s * near_max);
        before3 = q;
        ENSURE_EQ_INT(motus_particle3_step(&q, 1), MOTUS_ERROR_OVERFLOW);
        ENSURE(same_bytes(&q, &before3, sizeof q));
        q.force = motus_v3(s * REAL_MAX, 0, 0);
        q.inverse_mass = 2;
        q.velocity = motus_v3(0, 0, 0);
        before3 = q;
        ENSURE_EQ_INT(motus_particle3_step(&q, 4), MOTUS_ERROR_OVERFLOW);
        ENSURE(same_bytes(&q, &before3, sizeof q));
    }
}

/* A 2D state of n particles over its own arrays. */
typedef struct small_state {
    motus_real x[16], y[16], z[16], vx[16], vy[16], vz[16], fx[16], fy[16], fz[16], inverse_mass[16];
    motus_state state;
} small_state;
static void small_state_bind(small_state *b, int dims, int count) {
    memset(&b->state, 0, sizeof b->state);
    b->state.dimensions = dims;
    b->state.count = count;
    b->state.position[0] = b->x, b->state.position[1] = b->y;
    b->state.velocity[0] = b->vx, b->state.velocity[1] = b->vy;
    b->state.force[0] = b->fx, b->state.force[1] = b->fy;
    if (dims == 3) {
        b->state.position[2] = b->z;
        b->state.velocity[2] = b->vz;
        b->state.force[2] = b->fz;
    }
    b->state.inverse_mass = b->inverse_mass;
}
static void small_state_fill(small_state *b) {
    int i;
    for (i = 0; i < 16; ++i) {
        b->x[i] = b->y[i] = b->z[i] = (motus_real)i;
        b->vx[i] = b->vy[i] = b->vz[i] = 1;
        b->fx[i] = b->fy[i] = b->fz[i] = 1;
        b->inverse_mass[i] = 1;
    }
}

TEST(step_overflow_near_max_one_method_per_family) {
    /* Euler, Verlet, Runge-Kutta, composition (Forest-Ruth) and the exact stepper, 2D and 3D: particle `at`
       (in a whole vector, or the partial one) at max/8 in position and velocity, or velocity and force:
       fine at dt 1/4; at dt 16 never MOTUS_OK. Release builds write and report MOTUS_ERROR_NOT_FINITE (the
       inputs are gone, the step cannot tell overflow from bad data); MOTUS_CHECKED builds report
       MOTUS_ERROR_OVERFLOW and write nothing. */
    static const motus_method methods[5] = {MOTUS_SEMI_IMPLICIT_EULER, MOTUS_VELOCITY_VERLET, MOTUS_RK4,
                                            MOTUS_FOREST_RUTH, MOTUS_EXACT_LINEAR_DRAG};
    const motus_real near_max = REAL_MAX / 8;
    static small_state b, before;
    int m, which, dims, at;
    for (dims = 2; dims <= 3; ++dims)
        for (m = 0; m < 5; ++m)
            for (at = 0; at < 16; at += 15)
                for (which = 0; which < 2; ++which) {
                    motus_scene scene;
                    motus_result r;
                    memset(&scene, 0, sizeof scene);
                    scene.method = methods[m];
                    scene.damping_per_step = MOTUS_R(0.01);
                    small_state_fill(&b);
                    small_state_bind(&b, dims, 16);
                    if (which == 0) b.x[at] = b.vx[at] = near_max, b.z[at] = b.vz[at] = -near_max;
                    else b.vy[at] = b.fy[at] = -near_max;
                    ENSURE_EQ_INT(motus_step(&scene, &b.state, MOTUS_R(0.25), NULL, 0), MOTUS_OK);
                    memcpy(&before, &b, sizeof b);
                    r = motus_step(&scene, &b.state, 16, NULL, 0);
#ifdef MOTUS_CHECKED
                    ENSURE_EQ_INT(r, MOTUS_ERROR_OVERFLOW);
                    ENSURE(same_bytes(&b, &before, sizeof b));
#else
                    ENSURE_EQ_INT(r, MOTUS_ERROR_NOT_FINITE);
#endif
                    if (r == MOTUS_OK)
                        fprintf(stderr, "  %s, %dD, particle %d: no overflow reported\n",
                                method_name(methods[m]), dims, at);
                }
}

/* =================================================================================================
   The rescue: a step whose result fits while an intermediate overflows is taken, not refused
   ================================================================================================= */
/* One particle of a small_state alone, as a state of count 1 over its own components. */
static motus_state small_state_one(small_state *b, int dims, int at) {
    motus_state one = b->state;
    int d;
    one.count = 1;
    for (d = 0; d < dims; ++d) {
        one.position[d] += at;
        one.velocity[d] += at;
        one.force[d] += at;
    }
    one.inverse_mass += at;
    return one;
}
/* Whether every particle but `at` has the same position and velocity bits in a and b. */
static int small_state_same_but(const small_state *a, const small_state *b, int at) {
    int i, same = 1;
    for (i = 0; i < 16; ++i)
        if (i != at)
            same &= same_bytes(&a->x[i], &b->x[i], sizeof a->x[i]) & same_bytes(&a->vx[i], &b->vx[i], sizeof a->vx[i]) &
                    same_bytes(&a->y[i], &b->y[i], sizeof a->y[i]) & same_bytes(&a->vy[i], &b->vy[i], sizeof a->vy[i]) &
                    same_bytes(&a->z[i], &b->z[i], sizeof a->z[i]) & same_bytes(&a->vz[i], &b->vz[i], sizeof a->vz[i]);
    return same;
}
TEST(step_rescued_where_only_an_intermediate_overflows) {
    /* F*(1/m) past the largest real while the step's result fits (THE RESCUE in motus.h), for every method,
       2D and 3D, at a particle in a whole group of lanes (5) and at the last one (15), in four scenes: plain;
       gravity and 1% damping per step; walls the particle reaches; and a 2-substep step with linear drag.
       F = largest/4 N on 0.01 kg for 1 ms (a = 25 times the largest real, v = 2.5% of it). Each comes out OK
       (before: MOTUS_ERROR_NOT_FINITE), the velocity right to 1e-5 (plain scene); the rescued particle is what
       it is when stepped alone (a state of 1: the same bits whatever its group's lanes), and the other
       particles are what they are without it, bit for bit. Where the result itself does not fit (dt = 1 s),
       the step is still refused. */
    const motus_real largest = REAL_MAX, h = (motus_real)1e-3;
    static small_state b, plain, copy;
    int dims, m, at, kind;
    for (dims = 2; dims <= 3; ++dims)
        for (m = 0; m < MOTUS_METHOD_COUNT; ++m)
            for (kind = 0; kind < 4; ++kind)
                for (at = 5; at < 16; at += 10) {
                    motus_scene scene;
                    motus_state alone;
                    motus_real x_alone[3], v_alone[3];
                    int d;
                    memset(&scene, 0, sizeof scene);
                    scene.method = (motus_method)m;
                    if (kind == 1) scene.gravity = motus_v3(0, (motus_real)9.81, 0), scene.damping_per_step = MOTUS_R(0.01);
                    if (kind == 2) scene.bounds_min = motus_v3(-100, -100, -100), scene.bounds_max = motus_v3(100, 100, 100);
                    if (kind == 3) scene.substeps = 2, scene.linear_drag = MOTUS_R(0.5);
                    if (kind == 3 && m == MOTUS_EXACT_LINEAR_DRAG) scene.substeps = 1;
                    small_state_fill(&plain);
                    memcpy(&b, &plain, sizeof b);
                    small_state_bind(&plain, dims, 16);
                    small_state_bind(&b, dims, 16);
                    b.fx[at] = largest / 4, b.inverse_mass[at] = 100;
                    b.fy[at] = -largest / 8;
                    memcpy(&copy, &b, sizeof copy);
                    small_state_bind(&copy, dims, 16);
                    alone = small_state_one(&copy, dims, at);
                    ENSURE_EQ_INT(motus_step(&scene, &alone, h, NULL, 0), MOTUS_OK);
                    for (d = 0; d < dims; ++d) x_alone[d] = alone.position[d][0], v_alone[d] = alone.velocity[d][0];
                    ENSURE_EQ_INT(motus_step(&scene, &plain.state, h, NULL, 0), MOTUS_OK);
                    ENSURE_EQ_INT(motus_step(&scene, &b.state, h, NULL, 0), MOTUS_OK);
                    if (kind == 0 && !(near_relative(b.vx[at], (long double)largest * ((long double)h * 100 / 4) + 1) &&
                                       near_relative(b.vy[at], -(long double)largest * ((long double)h * 100 / 8) + 1))) {
                        fprintf(stderr, "  %s, %dD, particle %d: v (%g, %g), expected (%Lg, %Lg)\n",
                                method_name((motus_method)m), dims, at, (double)b.vx[at], (double)b.vy[at],
                                (long double)largest * ((long double)h * 100 / 4) + 1,
                                -(long double)largest * ((long double)h * 100 / 8) + 1);
                        motus_test_failures++;
                    }
                    if (kind == 2) ENSURE(b.x[at] <= 100 && b.x[at] >= -100 && b.y[at] <= 100 && b.y[at] >= -100);
                    ENSURE(same_bytes(&b.x[at], &x_alone[0], sizeof x_alone[0]) && same_bytes(&b.vx[at], &v_alone[0], sizeof v_alone[0]));
                    ENSURE(same_bytes(&b.y[at], &x_alone[1], sizeof x_alone[1]) && same_bytes(&b.vy[at], &v_alone[1], sizeof v_alone[1]));
                    if (dims == 3) ENSURE(same_bytes(&b.z[at], &x_alone[2], sizeof x_alone[2]) && same_bytes(&b.vz[at], &v_alone[2], sizeof v_alone[2]));
                    if (!small_state_same_but(&b, &plain, at)) {
                        fprintf(stderr, "  %s, %dD, scene %d: a particle changed by its neighbour's rescue\n",
                                method_name((motus_method)m), dims, kind);
                        motus_test_failures++;
                    }
                    /* the result itself past the largest real: refused (not where walls can stop the particle:
                       explicit Euler moves it by its old velocity and the wall's restitution 0 takes the new one) */
                    if (kind == 2) continue;
                    small_state_fill(&b);
                    small_state_bind(&b, dims, 16);
                    b.fx[at] = largest / 4, b.inverse_mass[at] = 100;
                    {
                        const motus_result r = motus_step(&scene, &b.state, 1, NULL, 0);
#ifdef MOTUS_CHECKED
                        ENSURE_EQ_INT(r, MOTUS_ERROR_OVERFLOW);
#else
                        ENSURE_EQ_INT(r, MOTUS_ERROR_NOT_FINITE);
#endif
                    }
                }
}

TEST(method_sums_overflow_only_where_the_step_does) {
    /* RK4 added its stages' velocities (and accelerations) as k1 + 2*k2 + 2*k3 + k4 before multiplying by
       h/6, and velocity Verlet its accelerations as a0 + a1 before h/2: sums of up to six times the largest
       value, which overflowed where the step fits. Now each term is a change of x or v. For every method,
       2D and 3D, at a particle in a whole group of lanes (5) and at the last one (15): a velocity of 0.4
       times the largest real (no force; dt = 2^-10 s), and a gravity of 0.6 times it (dt = 2^-20 s). Each
       step is MOTUS_OK, the particle's new velocity and position right to 1e-5 (before: RK4 failed both, and
       velocity Verlet the second, with MOTUS_ERROR_NOT_FINITE), and the other particles are what they are
       without it, bit for bit. */
    const motus_real largest = REAL_MAX;
    static small_state b, plain;
    int dims, m, at, kind;
    for (dims = 2; dims <= 3; ++dims)
        for (m = 0; m < MOTUS_METHOD_COUNT; ++m)
            for (kind = 0; kind < 2; ++kind)
                for (at = 5; at < 16; at += 10) {
                    const motus_real h = kind == 0 ? MOTUS_R(1.0) / 1024 : MOTUS_R(1.0) / 1048576;
                    const long double fast = (long double)largest * 0.4L, g = (long double)largest * 0.6L;
                    long double expected_x, expected_v;
                    motus_scene scene;
                    memset(&scene, 0, sizeof scene);
                    scene.method = (motus_method)m;
                    small_state_fill(&plain);
                    small_state_bind(&plain, dims, 16);
                    if (kind == 1) { /* every particle at rest: a uniform gravity moves them all alike */
                        int i;
                        for (i = 0; i < 16; ++i) plain.vx[i] = plain.vy[i] = plain.vz[i] = 0;
                    }
                    memcpy(&b, &plain, sizeof b);
                    small_state_bind(&b, dims, 16);
                    if (kind == 0) {
                        b.vx[at] = (motus_real)fast;
                        expected_x = (long double)b.x[at] + fast * h;
                        expected_v = fast;
                    } else {
                        scene.gravity = motus_v3((motus_real)g, 0, 0);
                        b.fx[at] = 0; /* the others' force of 1 N is nothing beside g */
                        expected_v = g * h;
                        /* explicit Euler moves by the old velocity (0), semi-implicit Euler by the new one (g*h^2),
                           the others exactly as constant acceleration does (g*h^2/2) */
                        expected_x = (long double)b.x[at] + g * h * h *
                                     (m == MOTUS_EXPLICIT_EULER ? 0 : m == MOTUS_SEMI_IMPLICIT_EULER ? 1 : 0.5L);
                    }
                    ENSURE_EQ_INT(motus_step(&scene, &plain.state, h, NULL, 0), MOTUS_OK);
                    ENSURE_EQ_INT(motus_step(&scene, &b.state, h, NULL, 0), MOTUS_OK);
                    if (!near_relative(b.vx[at], expected_v) || !near_relative(b.x[at], expected_x)) {
                        fprintf(stderr, "  %s, %dD, particle %d, case %d: x %g v %g, expected x %Lg v %Lg\n",
                                method_name((motus_method)m), dims, at, kind, (double)b.x[at], (double)b.vx[at],
                                expected_x, expected_v);
                        motus_test_failures++;
                    }
                    if (!small_state_same_but(&b, &plain, at)) {
                        fprintf(stderr, "  %s, %dD, case %d: a particle changed by its neighbour's velocity\n",
                                method_name((motus_method)m), dims, kind);
                        motus_test_failures++;
                    }
                }
}

TEST(fast_kernel_hands_a_term_out_of_range_to_the_general_kernel) {
    /* The fast kernels inline the textbook formulas of the tether, the attractor and quadratic drag and stop
       at a group with a lane out of their range, which the general kernel then steps (it scales those
       terms). For every method that takes these terms, 2D and 3D, at a particle in a whole group of lanes
       (5) and at the last one (15): a particle exactly on the attractor; one so far from it that |r|^3
       overflows; one so fast that |v|^2 overflows (quadratic drag); one whose offset from the tether
       overflows. Each step is OK and finite, that particle's result is what it is when stepped alone (the
       general kernel), and the others are what they are without it, bit for bit. */
    const motus_real largest = REAL_MAX, h = (motus_real)1e-3;
    static small_state b, plain, copy;
    int dims, m, at, kind, d;
    for (dims = 2; dims <= 3; ++dims)
        for (m = 0; m < MOTUS_METHOD_COUNT; ++m)
            for (kind = 0; kind < 4; ++kind)
                for (at = 5; at < 16; at += 10) {
                    motus_scene scene;
                    motus_state alone;
                    int finite = 1;
                    if (m == MOTUS_EXACT_LINEAR_DRAG) continue; /* takes none of these terms */
                    memset(&scene, 0, sizeof scene);
                    scene.method = (motus_method)m;
                    small_state_fill(&plain);
                    memcpy(&b, &plain, sizeof b);
                    if (kind == 0) { /* exactly on the attractor (no pull there); plain's is 0.5 m off */
                        scene.attractor_strength = 1;
                        scene.attractor = motus_v3((motus_real)at + MOTUS_R(0.5), (motus_real)at + MOTUS_R(0.5),
                                                   (motus_real)at + MOTUS_R(0.5));
                        b.x[at] = b.y[at] = b.z[at] = (motus_real)at + MOTUS_R(0.5);
                    } else if (kind == 1) { /* |r|^3 past the largest real, the pull tiny */
                        scene.attractor_strength = 1;
                        b.x[at] = (motus_real)(4 * cbrt((double)largest));
                    } else if (kind == 2) { /* |v|^2 past the largest real, c*|v|*v = 1e-3*|v| */
                        b.vx[at] = (motus_real)(2 * sqrt((double)largest));
                        scene.quadratic_drag = (motus_real)(1e-3 / (double)b.vx[at]);
                    } else { /* x - tether past the largest real, k*(x - tether) not */
                        scene.tether = motus_v3(-largest / 4 * 3, 0, 0);
                        scene.tether_stiffness = (motus_real)1e-3;
                        b.x[at] = largest / 4 * 3;
                    }
                    memcpy(&copy, &b, sizeof copy);
                    small_state_bind(&plain, dims, 16);
                    small_state_bind(&b, dims, 16);
                    small_state_bind(&copy, dims, 16);
                    alone = small_state_one(&copy, dims, at);
                    ENSURE_EQ_INT(motus_step(&scene, &alone, h, NULL, 0), MOTUS_OK);
                    ENSURE_EQ_INT(motus_step(&scene, &plain.state, h, NULL, 0), MOTUS_OK);
                    ENSURE_EQ_INT(motus_step(&scene, &b.state, h, NULL, 0), MOTUS_OK);
                    for (d = 0; d < dims; ++d) {
                        const motus_real *x = d == 0 ? b.x : d == 1 ? b.y : b.z;
                        const motus_real *v = d == 0 ? b.vx : d == 1 ? b.vy : b.vz;
                        const motus_real *xa = d == 0 ? copy.x : d == 1 ? copy.y : copy.z;
                        const motus_real *va = d == 0 ? copy.vx : d == 1 ? copy.vy : copy.vz;
                        finite &= motus_real_is_finite(x[at]) & motus_real_is_finite(v[at]);
                        ENSURE(same_bytes(&x[at], &xa[at], sizeof x[at]) && same_bytes(&v[at], &va[at], sizeof v[at]));
                    }
                    ENSURE(finite);
                    if (!small_state_same_but(&b, &plain, at)) {
                        fprintf(stderr, "  %s, %dD, case %d, particle %d: a particle changed by its neighbour's"
                                        " trip to the general kernel\n", method_name((motus_method)m), dims, kind, at);
                        motus_test_failures++;
                    }
                }
}

/* The power of two nearest below x (x > 0, normal). */
static motus_real power_of_two_below(double x) {
    int e;
    (void)frexp(x, &e);
    return (motus_real)ldexp(1.0, e - 1);
}
TEST(step_rescued_where_a_term_overflows) {
    /* A term's acceleration past the largest real while the step's result fits: a tether of 1e-8 times the
       largest real (N/m) pulling 1 kg from 1e10 m, an attractor of half the largest real (m^3/s^2) at 0.01 m,
       and a quadratic drag of 1e-30 times it (1/m) at 1e16 m/s (a = 100, 5e3 and about 30 times the largest
       real), each at a dt where the step is a twentieth of the motion's time scale. THE RESCUE steps that
       particle in time units of 2^-s s; a power of two scales exactly, so the result is, bit for bit, the
       step of the same problem written in units of 2^-32 s (the velocity times 2^-32, the tether's k and
       the attractor's strength times 2^-64, dt times 2^32), which overflows nowhere. For every method that
       takes these terms, 2D and 3D, at a particle in a whole group of lanes (5) and at the last one (15):
       MOTUS_OK (before: MOTUS_ERROR_NOT_FINITE), those bits, also for the particle stepped alone (the
       general kernel), and the other particles as they are without it, bit for bit. */
    const motus_real largest = REAL_MAX, unit = (motus_real)ldexp(1.0, 32), unit2 = unit * unit;
    static small_state b, plain, oracle, copy;
    int dims, m, at, kind, d;
    for (dims = 2; dims <= 3; ++dims)
        for (m = 0; m < MOTUS_METHOD_COUNT; ++m)
            for (kind = 0; kind < 3; ++kind)
                for (at = 5; at < 16; at += 10) {
                    motus_scene scene, scaled;
                    motus_state alone;
                    motus_real h;
                    if (m == MOTUS_EXACT_LINEAR_DRAG) continue; /* takes none of these terms */
                    memset(&scene, 0, sizeof scene);
                    scene.method = (motus_method)m;
                    small_state_fill(&plain);
                    small_state_bind(&plain, dims, 16);
                    memcpy(&b, &plain, sizeof b);
                    small_state_bind(&b, dims, 16);
                    b.fx[at] = b.fy[at] = b.fz[at] = 0;
                    b.vx[at] = b.vy[at] = b.vz[at] = 0;
                    b.y[at] = b.z[at] = 0;
                    if (kind == 0) { /* w = sqrt(k/m), h = w/20 */
                        scene.tether_stiffness = largest * (motus_real)1e-8;
                        b.x[at] = (motus_real)1e10;
                        h = power_of_two_below(0.05 / sqrt((double)scene.tether_stiffness));
                    } else if (kind == 1) { /* the orbit's time scale sqrt(r^3/mu) */
                        scene.attractor = motus_v3(-100, -100, -100);
                        scene.attractor_strength = largest / 2;
                        b.x[at] = -100 + (motus_real)0.01, b.y[at] = b.z[at] = -100;
                        h = power_of_two_below(0.05 * sqrt(1e-6 / (double)scene.attractor_strength));
                    } else { /* the drag's time scale 1/(c*|v|) */
                        scene.quadratic_drag = largest * (motus_real)1e-30;
                        b.vx[at] = (motus_real)1e16;
                        h = power_of_two_below(0.05 / ((double)scene.quadratic_drag * 1e16));
                    }
                    memcpy(&oracle, &b, sizeof b);
                    small_state_bind(&oracle, dims, 16);
                    scaled = scene;
                    scaled.tether_stiffness = scene.tether_stiffness / unit2;
                    scaled.attractor_strength = scene.attractor_strength / unit2;
                    oracle.vx[at] = b.vx[at] / unit;
                    alone = small_state_one(&oracle, dims, at);
                    ENSURE_EQ_INT(motus_step(&scaled, &alone, h * unit, NULL, 0), MOTUS_OK);
                    for (d = 0; d < dims; ++d) alone.velocity[d][0] *= unit;
                    ENSURE_EQ_INT(motus_step(&scene, &plain.state, h, NULL, 0), MOTUS_OK);
                    /* alone (a state of 1: the general kernel, which stops at the same test as a fast one) */
                    memcpy(&copy, &b, sizeof b);
                    small_state_bind(&copy, dims, 16);
                    alone = small_state_one(&copy, dims, at);
                    ENSURE_EQ_INT(motus_step(&scene, &alone, h, NULL, 0), MOTUS_OK);
                    ENSURE(same_bytes(&copy.x[at], &oracle.x[at], sizeof b.x[at]) && same_bytes(&copy.vx[at], &oracle.vx[at], sizeof b.x[at]));
                    ENSURE_EQ_INT(motus_step(&scene, &b.state, h, NULL, 0), MOTUS_OK);
                    if (!(same_bytes(&b.x[at], &oracle.x[at], sizeof b.x[at]) && same_bytes(&b.vx[at], &oracle.vx[at], sizeof b.x[at]) &&
                          same_bytes(&b.y[at], &oracle.y[at], sizeof b.x[at]) && same_bytes(&b.vy[at], &oracle.vy[at], sizeof b.x[at]) &&
                          (dims == 2 || (same_bytes(&b.z[at], &oracle.z[at], sizeof b.x[at]) &&
                                         same_bytes(&b.vz[at], &oracle.vz[at], sizeof b.x[at]))))) {
                        fprintf(stderr, "  %s, %dD, particle %d, term %d: x %.9g v %.9g, in units of 2^-32 s x %.9g v %.9g\n",
                                method_name((motus_method)m), dims, at, kind, (double)b.x[at], (double)b.vx[at],
                                (double)oracle.x[at], (double)oracle.vx[at]);
                        motus_test_failures++;
                    }
                    ENSURE(b.vx[at] != 0 && motus_real_is_finite(b.vx[at])); /* it moved, and not to a NaN */
                    if (!small_state_same_but(&b, &plain, at)) {
                        fprintf(stderr, "  %s, %dD, term %d: a particle changed by its neighbour's rescue\n",
                                method_name((motus_method)m), dims, kind);
                        motus_test_failures++;
                    }
                }
}
TEST(particle_step_rescued_as_the_engine) {
    /* motus_particle_step where F*(1/m) overflows and a*dt fits (F = largest/4 on 0.01 kg, 1 ms): OK, the
       velocity right, and the bits of the engine's semi-implicit Euler on the same particle (2D and 3D);
       where a*dt itself does not fit (dt = 1 s), OVERFLOW with nothing written. */
    const motus_real largest = REAL_MAX, h = (motus_real)1e-3;
    motus_particle p, q, before;
    motus_particle3 p3, q3;
    motus_scene scene;
    motus_state state;
    memset(&scene, 0, sizeof scene);
    motus_particle_init(&p, motus_v2(3, 4), MOTUS_R(0.01));
    p.velocity = motus_v2(1, -1);
    p.force = motus_v2(largest / 4, -largest / 4);
    q = p;
    ENSURE_EQ_INT(motus_particle_step(&p, h), MOTUS_OK);
    ENSURE(near_relative(p.velocity.x, (long double)largest * ((long double)q.inverse_mass * h / 4) + 1));
    ENSURE(near_relative(p.velocity.y, -(long double)largest * ((long double)q.inverse_mass * h / 4) - 1));
    state = motus_state_of_particles(&q, 1);
    ENSURE_EQ_INT(motus_step(&scene, &state, h, NULL, 0), MOTUS_OK);
    ENSURE(same_bytes(&p, &q, sizeof p));
    motus_particle3_init(&p3, motus_v3(3, 4, 5), MOTUS_R(0.01));
    p3.velocity = motus_v3(1, -1, 2);
    p3.force = motus_v3(0, largest / 4, -largest / 4);
    q3 = p3;
    ENSURE_EQ_INT(motus_particle3_step(&p3, h), MOTUS_OK);
    ENSURE(near_relative(p3.velocity.z, -(long double)largest * ((long double)q3.inverse_mass * h / 4) + 2));
    state = motus_state_of_particles3(&q3, 1);
    ENSURE_EQ_INT(motus_step(&scene, &state, h, NULL, 0), MOTUS_OK);
    ENSURE(same_bytes(&p3, &q3, sizeof p3));
    /* the result itself past the largest real */
    p = q;
    p.force = motus_v2(largest / 4, 0);
    before = p;
    ENSURE_EQ_INT(motus_particle_step(&p, 1), MOTUS_ERROR_OVERFLOW);
    ENSURE(same_bytes(&p, &before, sizeof p));
}

/* =================================================================================================
   Damping factors 0, 1, above 1, negative, NaN
   ================================================================================================= */
TEST(damping_factors_accepted_or_rejected_as_documented) {
    /* The fraction removed, in [0, 1] (-0 too: it is 0); everything else is MOTUS_ERROR_INVALID_DAMPING with
       nothing changed, in the particle functions (2D, 3D) and in the scene (per step and per second). */
    const motus_real accepted[] = {0, -MOTUS_R(0.0), MOTUS_R(0.5), 1};
    const motus_real rejected[] = {1 + MOTUS_REAL_EPSILON, 2, infinity(), -MOTUS_R(1e-30), MOTUS_R(-0.5),
                                   -1, -infinity(), not_a_number(), -not_a_number()};
    static small_state b, b_before;
    motus_scene scene;
    motus_particle p, before;
    motus_particle3 q3, before3;
    int i, per_second;
    motus_particle_init(&p, motus_v2(1, 2), 1);
    p.velocity = motus_v2(3, -4);
    before = p;
    motus_particle3_init(&q3, motus_v3(1, 2, 3), 1);
    q3.velocity = motus_v3(3, -4, 5);
    before3 = q3;
    small_state_fill(&b);
    small_state_bind(&b, 2, 1);
    memcpy(&b_before, &b, sizeof b);
    for (i = 0; i < (int)(sizeof rejected / sizeof rejected[0]); ++i) {
        ENSURE_EQ_INT(motus_particle_damp_per_step(&p, rejected[i]), MOTUS_ERROR_INVALID_DAMPING);
        ENSURE_EQ_INT(motus_particle_damp_per_second(&p, rejected[i], DT), MOTUS_ERROR_INVALID_DAMPING);
        ENSURE_EQ_INT(motus_particle3_damp_per_step(&q3, rejected[i]), MOTUS_ERROR_INVALID_DAMPING);
        ENSURE_EQ_INT(motus_particle3_damp_per_second(&q3, rejected[i], DT), MOTUS_ERROR_INVALID_DAMPING);
        for (per_second = 0; per_second < 2; ++per_second) {
            memset(&scene, 0, sizeof scene);
            if (per_second) scene.damping_per_second = rejected[i];
            else scene.damping_per_step = rejected[i];
            ENSURE_EQ_INT(motus_scene_check(&scene, 2, 1, NULL), MOTUS_ERROR_INVALID_DAMPING);
            ENSURE_EQ_INT(motus_step(&scene, &b.state, DT, NULL, 0), MOTUS_ERROR_INVALID_DAMPING);
        }
    }
    ENSURE(same_bytes(&p, &before, sizeof p));
    ENSURE(same_bytes(&q3, &before3, sizeof q3));
    ENSURE(same_bytes(&b, &b_before, sizeof b));
    for (i = 0; i < (int)(sizeof accepted / sizeof accepted[0]); ++i) {
        motus_particle q = before, r = before;
        const motus_real f = accepted[i];
        ENSURE_EQ_INT(motus_particle_damp_per_step(&q, f), MOTUS_OK);
        ENSURE_EQ_INT(motus_particle_damp_per_second(&r, f, DT), MOTUS_OK);
        if (f == 0) { /* removes nothing: the velocity exactly */
            ENSURE(same_bytes(&q, &before, sizeof q) && same_bytes(&r, &before, sizeof r));
        } else if (f == 1) { /* removes everything, per step and per second at any dt */
            ENSURE(q.velocity.x == 0 && q.velocity.y == 0 && r.velocity.x == 0 && r.velocity.y == 0);
        } else {
            ENSURE(q.velocity.x == MOTUS_R(1.5) && q.velocity.y == -2);
            ENSURE_NEAR(r.velocity.x, 3 * pow(0.5, (double)DT), 8 * MOTUS_REAL_EPSILON);
        }
        for (per_second = 0; per_second < 2; ++per_second) {
            motus_particle single = before;
            memset(&scene, 0, sizeof scene);
            if (per_second) scene.damping_per_second = f;
            else scene.damping_per_step = f;
            b.state.force[0] = b.state.force[1] = NULL;
            b.state.inverse_mass = NULL;
            b.x[0] = before.position.x, b.y[0] = before.position.y;
            b.vx[0] = before.velocity.x, b.vy[0] = before.velocity.y;
            ENSURE_EQ_INT(motus_step(&scene, &b.state, DT, NULL, 0), MOTUS_OK);
            motus_particle_step(&single, DT);
            if (per_second) motus_particle_damp_per_second(&single, f, DT);
            else motus_particle_damp_per_step(&single, f);
            ENSURE(same_bytes(&b.vx[0], &single.velocity.x, sizeof b.vx[0]));
            ENSURE(same_bytes(&b.vy[0], &single.velocity.y, sizeof b.vy[0]));
            ENSURE(same_bytes(&b.x[0], &single.position.x, sizeof b.x[0]));
        }
    }
}

/* =================================================================================================
   Subnormals: damping flushes slow components to exact zero
   ================================================================================================= */
TEST(rest_speed_keeps_v_dt_normal) {
    /* The default threshold: above REAL_MIN_NORMAL/1e-7, so v*dt is normal for every dt >= 1e-7 s. */
    const motus_real rest = (motus_real)(MOTUS_REST_SPEED);
    ENSURE(rest > REAL_MIN_NORMAL / MOTUS_R(1e-7));
    ENSURE(!is_subnormal(rest * MOTUS_R(1e-7)));
    ENSURE(rest < MOTUS_R(1e-20)); /* and invisible to a game */
}

TEST(damping_flushes_to_exact_zero_at_the_rest_speed) {
    const motus_real rest = (motus_real)(MOTUS_REST_SPEED);
    motus_particle p;
    motus_particle3 q;
    motus_particle_init(&p, motus_v2(0, 0), 1);
    motus_particle3_init(&q, motus_v3(0, 0, 0), 1);
    /* Just below after damping: zero, of the component's sign. Just above: kept. */
    p.velocity = motus_v2(rest * MOTUS_R(1.5), -rest * MOTUS_R(1.5));
    ENSURE_EQ_INT(motus_particle_damp_per_step(&p, MOTUS_R(0.5)), MOTUS_OK);
    ENSURE(p.velocity.x == 0 && !signbit(p.velocity.x) && p.velocity.y == 0 && signbit(p.velocity.y));
    p.velocity = motus_v2(rest * 4, -rest * 4);
    ENSURE_EQ_INT(motus_particle_damp_per_step(&p, MOTUS_R(0.5)), MOTUS_OK);
    ENSURE(p.velocity.x == rest * 2 && p.velocity.y == -rest * 2);
    q.velocity = motus_v3(rest * 4, 1, -rest * MOTUS_R(1.5));
    ENSURE_EQ_INT(motus_particle3_damp_per_step(&q, MOTUS_R(0.5)), MOTUS_OK);
    ENSURE(q.velocity.x == rest * 2 && q.velocity.y == MOTUS_R(0.5) && q.velocity.z == 0 && signbit(q.velocity.z));
    /* Damping 0 removes nothing and flushes nothing, as a scene without damping: a subnormal velocity
       stays (the flush belongs to damping that acts). */
    p.velocity = motus_v2(REAL_MIN_NORMAL / 8, 1);
    ENSURE_EQ_INT(motus_particle_damp_per_second(&p, 0, DT), MOTUS_OK);
    ENSURE(p.velocity.x == REAL_MIN_NORMAL / 8 && p.velocity.y == 1);
}

/* Damp (1, -0.3) by 0.01 removed per step, or the per-second equivalent, until it stops; returns the steps
   taken, counts the steps that left a subnormal component. */
static int steps_to_rest(int per_second, int *subnormal_steps) {
    const motus_real damping = (motus_real)(1 - pow(0.99, 60));
    motus_particle p;
    int steps = 0;
    motus_particle_init(&p, motus_v2(0, 0), 1);
    p.velocity = motus_v2(1, MOTUS_R(-0.3));
    *subnormal_steps = 0;
    while ((p.velocity.x != 0 || p.velocity.y != 0) && steps < 1000000) {
        if (per_second) motus_particle_damp_per_second(&p, damping, DT);
        else motus_particle_damp_per_step(&p, MOTUS_R(0.01));
        *subnormal_steps += is_subnormal(p.velocity.x) || is_subnormal(p.velocity.y);
        ++steps;
    }
    return steps;
}

TEST(damping_reaches_exact_zero_without_subnormals) {
    /* A plain v *= 0.99 from 1 m/s never reaches 0: below 50 times the smallest subnormal, 0.99*v rounds
       back to v, so the speed stays subnormal (and slow) for ever. With the flush: exact zero at 1e-30
       (1e-300 in double), after ln(1e-30)/ln(0.99) = 6,874 steps (68,732), never a subnormal. */
    motus_real v = 1;
    int old_steps, old_subnormal = 0, per_second, subnormal, steps;
    for (old_steps = 0; old_steps < 200000; ++old_steps) {
        v = v * MOTUS_R(0.99);
        old_subnormal += is_subnormal(v);
    }
    printf("  %s, plain v *= 0.99: after %d steps v = %g, subnormal for the last %d steps\n", PRECISION, old_steps,
           (double)v, old_subnormal);
    ENSURE(v != 0 && is_subnormal(v));
    for (per_second = 0; per_second < 2; ++per_second) {
        steps = steps_to_rest(per_second, &subnormal);
        printf("  %s, %s damping with the flush: exact zero after %d steps (%d of them subnormal)\n", PRECISION,
               per_second ? "per-second" : "per-step", steps, subnormal);
        ENSURE_EQ_INT(subnormal, 0);
        ENSURE_NEAR(steps, log((double)(motus_real)(MOTUS_REST_SPEED)) / log(0.99), 3);
    }
}

TEST(scene_damping_reaches_exact_zero_as_the_particle_path) {
    /* A scene over 13 particles (a whole vector and a partial one) under per-step and per-second damping,
       nothing else: every velocity reaches exact zero, no subnormal on the way, and the scene agrees with
       motus_particle_step + damping bit for bit at every step. */
    static small_state b;
    motus_scene scene;
    motus_particle p[13];
    int per_second, i, step;
    for (per_second = 0; per_second < 2; ++per_second) {
        const motus_real damping = per_second ? MOTUS_R(0.99) : MOTUS_R(0.1);
        int subnormal = 0, mismatch = 0, moving = 1;
        memset(&scene, 0, sizeof scene);
        if (per_second) scene.damping_per_second = damping;
        else scene.damping_per_step = damping;
        small_state_bind(&b, 2, 13);
        b.state.force[0] = b.state.force[1] = NULL;
        b.state.inverse_mass = NULL;
        for (i = 0; i < 13; ++i) {
            motus_particle_init(&p[i], motus_v2((motus_real)i, -(motus_real)i), 1);
            p[i].velocity = motus_v2((motus_real)(i - 6) * MOTUS_R(0.37), (motus_real)(i % 3) - 1);
            b.x[i] = p[i].position.x, b.y[i] = p[i].position.y;
            b.vx[i] = p[i].velocity.x, b.vy[i] = p[i].velocity.y;
        }
        for (step = 0; step < 20000 && moving; ++step) {
            ENSURE_EQ_INT(motus_step(&scene, &b.state, DT, NULL, 0), MOTUS_OK);
            moving = 0;
            for (i = 0; i < 13; ++i) {
                motus_particle_step(&p[i], DT);
                if (per_second) motus_particle_damp_per_second(&p[i], damping, DT);
                else motus_particle_damp_per_step(&p[i], damping);
                mismatch += !same_bytes(&b.vx[i], &p[i].velocity.x, sizeof b.vx[i]) ||
                            !same_bytes(&b.vy[i], &p[i].velocity.y, sizeof b.vy[i]) ||
                            !same_bytes(&b.x[i], &p[i].position.x, sizeof b.x[i]);
                subnormal += is_subnormal(b.vx[i]) || is_subnormal(b.vy[i]);
                moving |= b.vx[i] != 0 || b.vy[i] != 0;
            }
        }
        ENSURE(!moving);
        ENSURE_EQ_INT(mismatch, 0);
        ENSURE_EQ_INT(subnormal, 0);
    }
}

TEST(scene_without_damping_does_not_flush) {
    /* The flush belongs to damping: a scene without it keeps a tiny velocity (the costly-terms path, with
       quadratic drag, included). */
    static small_state b;
    motus_scene scene;
    int general;
    for (general = 0; general < 2; ++general) {
        memset(&scene, 0, sizeof scene);
        scene.quadratic_drag = general ? MOTUS_R(0.5) : 0;
        small_state_bind(&b, 2, 1);
        b.state.force[0] = b.state.force[1] = NULL;
        b.state.inverse_mass = NULL;
        b.x[0] = b.y[0] = 0;
        b.vx[0] = (motus_real)(MOTUS_REST_SPEED) / 4, b.vy[0] = 0;
        ENSURE_EQ_INT(motus_step(&scene, &b.state, DT, NULL, 0), MOTUS_OK);
        ENSURE(b.vx[0] == (motus_real)(MOTUS_REST_SPEED) / 4);
    }
}

/* =================================================================================================
   Adversarial inputs (issue 11, item 8)
   ================================================================================================= */
TEST(substeps_for_a_stable_dt_of_negative_zero_is_too_stiff) {
    /* (a) -0 passes "max_stable_dt >= 0" and is finite: it must end as MOTUS_ERROR_TOO_STIFF, not a division
       by zero turned into an int (undefined behaviour). Nothing written. */
    int n = 1234;
    ENSURE_EQ_INT(motus_substeps_for(1, -MOTUS_R(0.0), 1, &n), MOTUS_ERROR_TOO_STIFF);
    ENSURE_EQ_INT(motus_substeps_for(DT, -MOTUS_R(0.0), MOTUS_R(0.5), &n), MOTUS_ERROR_TOO_STIFF);
    ENSURE_EQ_INT(motus_substeps_for(REAL_TRUE_MIN, -MOTUS_R(0.0), 1, &n), MOTUS_ERROR_TOO_STIFF);
    ENSURE_EQ_INT(motus_substeps_for(1, 0, 1, &n), MOTUS_ERROR_TOO_STIFF);
    /* A stable dt whose safety product underflows to 0 is as stiff. */
    ENSURE_EQ_INT(motus_substeps_for(1, REAL_TRUE_MIN, MOTUS_R(0.25), &n), MOTUS_ERROR_TOO_STIFF);
    ENSURE_EQ_INT(n, 1234);
    /* dt 0 needs one substep whatever the limit. */
    ENSURE_EQ_INT(motus_substeps_for(0, -MOTUS_R(0.0), 1, &n), MOTUS_OK);
    ENSURE_EQ_INT(n, 1);
}

/* One state over the caller's arrays (a particle or a few): x, y, z and vx, vy, vz, z read only in 3D. */
static motus_state state_of(int dims, int count, motus_real *x, motus_real *y, motus_real *z, motus_real *vx,
                            motus_real *vy, motus_real *vz) {
    motus_state state;
    memset(&state, 0, sizeof state);
    state.dimensions = dims;
    state.count = count;
    state.position[0] = x, state.position[1] = y, state.position[2] = z;
    state.velocity[0] = vx, state.velocity[1] = vy, state.velocity[2] = vz;
    return state;
}

/* The acceleration of the inverse-square pull at r from the attractor, in long double, in units of the
   largest component s (-((mu*u/|u|^3)/s)/s with u = r/s, each factor no larger than the result or mu):
   under valgrind long double has double's range and precision, and |r|^3 at 1e-150 m is below it. */
static void pull(const double *r, int dims, double mu, double *a) {
    long double s = 0, u2 = 0, u[3];
    int d;
    for (d = 0; d < dims; ++d)
        if (fabsl((long double)r[d]) > s) s = fabsl((long double)r[d]);
    for (d = 0; d < dims; ++d) {
        u[d] = (long double)r[d] / s;
        u2 += u[d] * u[d];
    }
    for (d = 0; d < dims; ++d) a[d] = (double)(-((long double)mu * (u[d] / (u2 * sqrtl(u2)))) / s / s);
}

TEST(attractor_pull_far_away_is_representable) {
    /* (c) At |r| = 1e13 and 1e20 m, with mu chosen so that the pull is about 0.01 m/s^2 (mu = 1e24 and 1e38,
       representable in float), r^2 (1e40 at 1e20 m) overflows float: the pull must still be there and right
       to 1e-5, in 2D and 3D, on an axis and on a diagonal, for a few methods. One step of 1 s from rest. */
    static const motus_method methods[3] = {MOTUS_SEMI_IMPLICIT_EULER, MOTUS_VELOCITY_VERLET, MOTUS_RK4};
    static const double distances[2] = {1e13, 1e20};
    int k, m, dims, diagonal;
    for (k = 0; k < 2; ++k)
        for (dims = 2; dims <= 3; ++dims)
            for (diagonal = 0; diagonal < 2; ++diagonal)
                for (m = 0; m < 3; ++m) {
                    const double mu = 0.01 * distances[k] * distances[k];
                    double r[3], a[3];
                    motus_real x[3], y[3], z[3], vx[3] = {0, 0, 0}, vy[3] = {0, 0, 0}, vz[3] = {0, 0, 0};
                    motus_scene scene;
                    motus_state state;
                    int d;
                    memset(&scene, 0, sizeof scene);
                    scene.method = methods[m];
                    scene.attractor_strength = (motus_real)mu;
                    r[0] = distances[k];
                    r[1] = diagonal ? -distances[k] : 0;
                    r[2] = dims == 3 && diagonal ? distances[k] : 0;
                    x[0] = (motus_real)r[0], y[0] = (motus_real)r[1], z[0] = (motus_real)r[2];
                    r[0] = (double)x[0], r[1] = (double)y[0], r[2] = (double)z[0]; /* what the state holds */
                    pull(r, dims, (double)scene.attractor_strength, a);
                    state = state_of(dims, 1, x, y, z, vx, vy, vz);
                    ENSURE_EQ_INT(motus_step(&scene, &state, 1, NULL, 0), MOTUS_OK);
                    for (d = 0; d < dims; ++d) {
                        const motus_real got = d == 0 ? vx[0] : d == 1 ? vy[0] : vz[0];
                        if (a[d] == 0) ENSURE(got == 0);
                        else if (!(fabs((double)got / a[d] - 1) <= 1e-5)) {
                            fprintf(stderr, "  %s, %dD, |r| %g%s: a[%d] = %g, expected %g\n",
                                    method_name(methods[m]), dims, distances[k], diagonal ? " diagonal" : "",
                                    d, (double)got, a[d]);
                            motus_test_failures++;
                        }
                    }
                }
}

TEST(tether_pull_from_far_across_is_representable) {
    /* A particle at +0.75*largest tethered at -0.75*largest: x - tether overflows, the pull k*(x - tether)/m
       with k = 2^-20 N/m and 1 kg does not (1.5*largest*2^-20). One step of 1 s from rest must give that
       velocity to rounding, in 2D and 3D, and a particle at the tether itself feels nothing. */
    static const motus_method methods[3] = {MOTUS_SEMI_IMPLICIT_EULER, MOTUS_VELOCITY_VERLET, MOTUS_RK4};
    const double largest = (double)(sizeof(motus_real) == sizeof(float) ? FLT_MAX : DBL_MAX);
    int m, dims;
    for (dims = 2; dims <= 3; ++dims)
        for (m = 0; m < 3; ++m) {
            motus_real x[2], y[2] = {0, 0}, z[2] = {0, 0}, vx[2] = {0, 0}, vy[2] = {0, 0}, vz[2] = {0, 0};
            motus_scene scene;
            motus_state state;
            double expected;
            memset(&scene, 0, sizeof scene);
            scene.method = methods[m];
            scene.tether = motus_v3((motus_real)(-0.75 * largest), 0, 0);
            scene.tether_stiffness = (motus_real)ldexp(1, -20);
            x[0] = (motus_real)(0.75 * largest);
            x[1] = scene.tether.x;
            expected = -(((double)x[0] * 0.5 - (double)scene.tether.x * 0.5) * ldexp(1, -19)); /* halves: no overflow in double */
            state = state_of(dims, 2, x, y, z, vx, vy, vz);
            /* a step of 2^-30 s keeps the particle where it is to rounding: the pull is the same at every stage */
            ENSURE_EQ_INT(motus_step(&scene, &state, (motus_real)ldexp(1, -30), NULL, 0), MOTUS_OK);
            if (!(fabs((double)vx[0] / (expected * ldexp(1, -30)) - 1) <= 1e-5)) {
                fprintf(stderr, "  %s, %dD: v %g, expected %g\n", method_name(methods[m]), dims, (double)vx[0],
                        expected * ldexp(1, -30));
                motus_test_failures++;
            }
            ENSURE(vx[1] == 0 && x[1] == scene.tether.x && vy[0] == 0 && vz[0] == 0);
        }
}

TEST(quadratic_drag_at_a_speed_whose_square_overflows) {
    /* |v| = 2*sqrt(largest) (3.7e19 m/s in float, 2.7e154 in double): |v|^2 overflows, c*|v|*v*dt does not
       with c = 1e-3/|v| per m. Along a fixed direction the speed follows u' = -c*u^2, u(t) = u0/(1 + c*u0*t):
       one step of 1 s slows it by a factor 1/(1 + 1e-3) to 1e-5 (semi-implicit Euler's error is 1e-6 of
       it), MOTUS_OK, on an axis and on a diagonal, 2D and 3D, for a one-, a two- and a four-stage method.
       Before, a = -v*inf: MOTUS_ERROR_NOT_FINITE (OVERFLOW checked) with a finite answer. */
    static const motus_method methods[3] = {MOTUS_SEMI_IMPLICIT_EULER, MOTUS_VELOCITY_VERLET, MOTUS_RK4};
    const double speed = 2 * sqrt((double)REAL_MAX);
    int m, dims, diagonal;
    for (dims = 2; dims <= 3; ++dims)
        for (diagonal = 0; diagonal < 2; ++diagonal)
            for (m = 0; m < 3; ++m) {
                motus_real x[1] = {0}, y[1] = {0}, z[1] = {0}, v0[3], vx[1], vy[1], vz[1];
                motus_scene scene;
                motus_state state;
                double u0 = 0, kept;
                int d;
                memset(&scene, 0, sizeof scene);
                v0[0] = (motus_real)speed;
                v0[1] = diagonal ? (motus_real)-speed : 0;
                v0[2] = dims == 3 && diagonal ? (motus_real)speed : 0;
                for (d = 0; d < dims; ++d) u0 += v0[d] != 0; /* components of the same magnitude */
                u0 = (double)v0[0] * sqrt(u0);             /* (their squares overflow double too) */
                scene.method = methods[m];
                scene.quadratic_drag = (motus_real)(1e-3 / u0);
                kept = 1 / (1 + (double)scene.quadratic_drag * u0);
                vx[0] = v0[0], vy[0] = v0[1], vz[0] = v0[2];
                state = state_of(dims, 1, x, y, z, vx, vy, vz);
                ENSURE_EQ_INT(motus_step(&scene, &state, 1, NULL, 0), MOTUS_OK);
                for (d = 0; d < dims; ++d) {
                    const motus_real got = d == 0 ? vx[0] : d == 1 ? vy[0] : vz[0];
                    const double expected = (double)v0[d] * kept;
                    if (expected == 0 ? got != 0 : !(fabs((double)got / expected - 1) <= 1e-5)) {
                        fprintf(stderr, "  %s, %dD%s: v[%d] = %g, expected %g\n", method_name(methods[m]), dims,
                                diagonal ? " diagonal" : "", d, (double)got, expected);
                        motus_test_failures++;
                    }
                }
            }
}

TEST(attractor_pull_is_right_at_every_distance) {
    /* The pull is mu/(r^2*|r|) where r^2*|r| is a normal real and the pull finite, and the scaled form
       elsewhere: at every distance from 1e-18 to 1e18 m in float (1e-150 to 1e150 m in double), in steps of
       10^0.25 (crossing where r^2*|r| leaves the normal reals: 2.3e-13 m in float, and 7e12 m, and where r^2
       does: 1.8e19 m), with mu = |r|^2 (a pull of 1 m/s^2), on an axis and on a diagonal, 2D and 3D: one
       step of 1e-3 s from rest gives v = a*dt to 16 ulps (the reference has double's precision under
       valgrind; a subnormal r^2*|r| is off by 2e-6 relative at 5.6e-14 m in float, and far more below). */
    const double widest = sizeof(motus_real) == sizeof(float) ? 18 : 150;
    double exponent;
    int dims, diagonal, d;
    for (exponent = -widest; exponent <= widest; exponent += 0.25)
        for (dims = 2; dims <= 3; ++dims)
            for (diagonal = 0; diagonal < 2; ++diagonal) {
                const double distance = pow(10, exponent);
                motus_real x[1], y[1], z[1], vx[1] = {0}, vy[1] = {0}, vz[1] = {0};
                motus_scene scene;
                motus_state state;
                double r[3], a[3];
                x[0] = (motus_real)distance;
                y[0] = diagonal ? (motus_real)(-0.75 * distance) : 0;
                z[0] = dims == 3 && diagonal ? (motus_real)(0.5 * distance) : 0;
                memset(&scene, 0, sizeof scene);
                scene.method = MOTUS_SEMI_IMPLICIT_EULER;
                scene.attractor_strength = (motus_real)(distance * distance);
                r[0] = (double)x[0], r[1] = (double)y[0], r[2] = (double)z[0];
                pull(r, dims, (double)scene.attractor_strength, a);
                state = state_of(dims, 1, x, y, z, vx, vy, vz);
                ENSURE_EQ_INT(motus_step(&scene, &state, (motus_real)1e-3, NULL, 0), MOTUS_OK);
                for (d = 0; d < dims; ++d) {
                    const double got = (double)(d == 0 ? vx[0] : d == 1 ? vy[0] : vz[0]), want = a[d] * 1e-3;
                    if (!(fabs(got - want) <= 16 * (double)MOTUS_REAL_EPSILON * fabs(want))) {
                        fprintf(stderr, "  %dD%s, |x| %g m: v[%d] = %.9g, expected %.9g\n", dims,
                                diagonal ? " diagonal" : "", distance, d, got, want);
                        motus_test_failures++;
                    }
                }
            }
}

TEST(attractor_pull_of_a_strength_near_the_largest_real) {
    /* mu = largest/1.2 at r = (0.9, +-0.9[, 0.9]) m: mu*(1/s)^2 overflows (s = 0.9), the pull mu/|r|^2 along
       each axis (mu*0.9/|r|^3: 0.39*mu in 2D, 0.23*mu in 3D) does not. One step of 1e-3 s from rest with a
       method whose first stage is the only one the velocity sees at order 0 (Euler): v = a*dt to 1e-5,
       MOTUS_OK. Before, the pull was infinite: NOT_FINITE (OVERFLOW checked). And at r = (0.5, 0): the pull
       mu/0.25 itself overflows, and the step of 1 ms is rescued; one of 1 s, whose velocity does not fit
       either, is refused. */
    static const motus_method methods[2] = {MOTUS_SEMI_IMPLICIT_EULER, MOTUS_EXPLICIT_EULER};
    int m, dims;
    for (dims = 2; dims <= 3; ++dims)
        for (m = 0; m < 2; ++m) {
            motus_real x[1] = {(motus_real)0.9}, y[1] = {(motus_real)-0.9}, z[1], vx[1] = {0}, vy[1] = {0},
                       vz[1] = {0};
            motus_scene scene;
            motus_state state;
            double r[3], a[3];
            int d;
            z[0] = dims == 3 ? (motus_real)0.9 : 0;
            memset(&scene, 0, sizeof scene);
            scene.method = methods[m];
            scene.attractor_strength = (motus_real)(REAL_MAX / 1.2);
            r[0] = (double)x[0], r[1] = (double)y[0], r[2] = (double)z[0];
            pull(r, dims, (double)scene.attractor_strength, a);
            state = state_of(dims, 1, x, y, z, vx, vy, vz);
            ENSURE_EQ_INT(motus_step(&scene, &state, (motus_real)1e-3, NULL, 0), MOTUS_OK);
            for (d = 0; d < dims; ++d) {
                const motus_real got = d == 0 ? vx[0] : d == 1 ? vy[0] : vz[0];
                if (!(fabs((double)got / (a[d] * 1e-3) - 1) <= 1e-5)) {
                    fprintf(stderr, "  %s, %dD: v[%d] = %g, expected %g\n", method_name(methods[m]), dims, d,
                            (double)got, a[d] * 1e-3);
                    motus_test_failures++;
                }
            }
            /* the pull itself past the largest real (mu/0.25) where the velocity of 1 ms fits: rescued (THE
               RESCUE; before, refused), v = -(mu*1e-3)/0.25 */
            x[0] = (motus_real)0.5, y[0] = 0, z[0] = 0, vx[0] = vy[0] = vz[0] = 0;
            ENSURE_EQ_INT(motus_step(&scene, &state, (motus_real)1e-3, NULL, 0), MOTUS_OK);
            ENSURE(fabs((double)vx[0] / (-((double)scene.attractor_strength * 1e-3) / 0.25) - 1) <= 1e-5);
            ENSURE(vy[0] == 0 && vz[0] == 0);
            /* where the velocity of the step does not fit either (1 s): refused (NOT_FINITE, or OVERFLOW
               when checked) */
            x[0] = (motus_real)0.5, y[0] = 0, z[0] = 0, vx[0] = vy[0] = vz[0] = 0;
            ENSURE(motus_step(&scene, &state, 1, NULL, 0) != MOTUS_OK);
        }
}

TEST(exact_stepper_at_huge_drag_and_dt) {
    /* (d) Drag 1e38 /s over 1e20 s: u = k*h = 1e58 overflows float, and h^2/2 = 5e39 too. The particle ends
       at the terminal velocity a/k (1e-37 m/s, a normal float) after moving v0/k + a*(dt - 1/k)/k: finite,
       correct, MOTUS_OK (not OVERFLOW). 2D and 3D. */
    int dims;
    for (dims = 2; dims <= 3; ++dims) {
        const double k = (double)(motus_real)1e38, h = (double)(motus_real)1e20;
        const double v0[3] = {1e30, -5, 2}, g[3] = {0, 10, -20};
        motus_real x[3] = {0, 0, 0}, y[3] = {0, 0, 0}, z[3] = {0, 0, 0};
        motus_real vx[3], vy[3], vz[3];
        motus_real *xs[3] = {x, y, z}, *vs[3] = {vx, vy, vz};
        motus_scene scene;
        motus_state state;
        int d;
        memset(&scene, 0, sizeof scene);
        memset(&state, 0, sizeof state);
        scene.method = MOTUS_EXACT_LINEAR_DRAG;
        scene.linear_drag = (motus_real)k;
        scene.gravity = motus_v3((motus_real)g[0], (motus_real)g[1], (motus_real)g[2]);
        vx[0] = (motus_real)v0[0], vy[0] = (motus_real)v0[1], vz[0] = (motus_real)v0[2];
        state.dimensions = dims;
        state.count = 1;
        for (d = 0; d < 3; ++d) state.position[d] = xs[d], state.velocity[d] = vs[d];
        ENSURE_EQ_INT(motus_step(&scene, &state, (motus_real)h, NULL, 0), MOTUS_OK);
        for (d = 0; d < dims; ++d) {
            const double v_expected = g[d] / k, x_expected = (double)(motus_real)v0[d] / k + g[d] * (h - 1 / k) / k;
            ENSURE(motus_real_is_finite(vs[d][0]) && motus_real_is_finite(xs[d][0]));
            if (v_expected == 0) ENSURE(vs[d][0] == 0);
            else ENSURE_NEAR((double)vs[d][0] / v_expected, 1, 1e-5);
            ENSURE_NEAR((double)xs[d][0] / x_expected, 1, 1e-5);
        }
    }
}

TEST(spring_of_1e20_at_its_rest_length_of_1e20) {
    /* (e) Stiffness = rest length = 1e20, the ends 1e20 m apart on an axis: the length must not be formed as
       sqrt(d^2) (1e40 overflows float); the force is exactly 0, the step MOTUS_OK, nothing moves. Between two
       particles and to an anchor; 2D and 3D; with spring damping. */
    static const motus_method methods[3] = {MOTUS_SEMI_IMPLICIT_EULER, MOTUS_LEAPFROG, MOTUS_RK4};
    int m, dims, anchored;
    for (dims = 2; dims <= 3; ++dims)
        for (anchored = 0; anchored < 2; ++anchored)
            for (m = 0; m < 3; ++m) {
                const motus_real L = (motus_real)1e20;
                motus_real x[2] = {0, 0}, y[2] = {0, 0}, z[2] = {0, 0}, vx[2] = {0, 0}, vy[2] = {0, 0}, vz[2] = {0, 0};
                motus_real scratch[3 * 6 * 16]; /* 3D, 4 evaluations: 18 stage arrays of a group of lanes (at most 16) */
                motus_spring spring;
                motus_scene scene;
                motus_state state;
                memset(&scene, 0, sizeof scene);
                memset(&spring, 0, sizeof spring);
                scene.method = methods[m];
                spring.a = 0;
                spring.b = anchored ? -1 : 1;
                spring.stiffness = L;
                spring.rest_length = L;
                spring.damping = 3;
                if (dims == 3) z[1] = L, spring.anchor = motus_v3(0, 0, L);
                else y[1] = -L, spring.anchor = motus_v3(0, -L, 0);
                scene.springs = &spring;
                scene.spring_count = 1;
                state = state_of(dims, 2, x, y, z, vx, vy, vz);
                ENSURE(motus_scratch_size(&scene, &state) <= sizeof scratch);
                ENSURE_EQ_INT(motus_step(&scene, &state, MOTUS_R(0.5), scratch, sizeof scratch), MOTUS_OK);
                ENSURE(vx[0] == 0 && vy[0] == 0 && vz[0] == 0 && vx[1] == 0 && vy[1] == 0 && vz[1] == 0);
                ENSURE(x[0] == 0 && y[0] == 0 && z[0] == 0);
                ENSURE(dims == 3 ? z[1] == L : y[1] == -L);
            }
}

TEST(subnormal_dt_in_substeps_still_moves) {
    /* (f) dt of one or three of the smallest subnormals, split in 4 substeps: dt/4 rounds to 0, which would
       step nothing. The step must still move a moving particle (fewer substeps), for every method. The
       methods whose stages take a fraction of the step (position Verlet and midpoint h/2, RK4 h/6,
       Forest-Ruth theta*h/2, McLachlan 0.405*h) cannot move by less than their fraction of h: at the smallest subnormals
       that fraction is not representable (x + v*h/2 is x), so they get 16 times the dt, which the substep
       split still rounds to a few ulps. */
    const motus_real dts_whole[2] = {REAL_TRUE_MIN, 3 * REAL_TRUE_MIN};
    const motus_real dts_split[2] = {16 * REAL_TRUE_MIN, 48 * REAL_TRUE_MIN};
    int m, i;
    for (m = 0; m < MOTUS_METHOD_COUNT; ++m)
        for (i = 0; i < 2; ++i) {
            const int splits = m == MOTUS_POSITION_VERLET || m == MOTUS_MIDPOINT || m == MOTUS_RK4 ||
                               m == MOTUS_FOREST_RUTH || m == MOTUS_MCLACHLAN4;
            const motus_real *dts = splits ? dts_split : dts_whole;
            motus_real x[2] = {0, 0}, y[2] = {0, 0}, vx[2] = {1, -1}, vy[2] = {0, 2};
            motus_scene scene;
            motus_state state;
            int n = 0;
            memset(&scene, 0, sizeof scene);
            memset(&state, 0, sizeof state);
            scene.method = (motus_method)m;
            scene.substeps = 4;
            state.count = 2;
            state.position[0] = x, state.position[1] = y;
            state.velocity[0] = vx, state.velocity[1] = vy;
            ENSURE_EQ_INT(motus_step(&scene, &state, dts[i], NULL, 0), MOTUS_OK);
            if (!(x[0] > 0 && x[1] < 0 && y[1] > 0)) {
                fprintf(stderr, "  %s, dt %g in 4 substeps: did not move (x %g, %g)\n",
                        method_name((motus_method)m), (double)dts[i], (double)x[0], (double)x[1]);
                motus_test_failures++;
            }
            ENSURE(x[0] <= 4 * dts[i]); /* no more than a few of the substeps it could take */
            /* motus_substeps_for agrees: dt/n is not 0. */
            ENSURE_EQ_INT(motus_substeps_for(dts[i], REAL_TRUE_MIN, 1, &n), MOTUS_OK);
            ENSURE(n >= 1 && dts[i] / (motus_real)n > 0);
        }
}

TEST(scene_max_stable_dt_needs_scratch_for_springs) {
    /* (g) Springs and no scratch (NULL, too small, misaligned): MOTUS_ERROR_SCRATCH_TOO_SMALL, nothing
       written (not *max_dt, not the scratch). Without springs no scratch is needed. */
    motus_real x[3] = {0, 1, 2}, y[3] = {0, 0, 0}, vx[3] = {0, 0, 0}, vy[3] = {0, 0, 0};
    motus_real scratch[16], scratch_before[16];
    motus_spring springs[2];
    motus_scene scene;
    motus_state state;
    motus_real max_dt = -3;
    int i;
    memset(&scene, 0, sizeof scene);
    memset(&state, 0, sizeof state);
    memset(springs, 0, sizeof springs);
    springs[0].a = 0, springs[0].b = 1, springs[0].stiffness = 100;
    springs[1].a = 2, springs[1].b = -1, springs[1].stiffness = 400;
    scene.springs = springs;
    scene.spring_count = 2;
    state.count = 3;
    state.position[0] = x, state.position[1] = y;
    state.velocity[0] = vx, state.velocity[1] = vy;
    for (i = 0; i < 16; ++i) scratch[i] = scratch_before[i] = (motus_real)(i * 3 + 1);
    ENSURE_EQ_INT(motus_scene_max_stable_dt(&scene, &state, &max_dt, NULL, 0), MOTUS_ERROR_SCRATCH_TOO_SMALL);
    ENSURE_EQ_INT(motus_scene_max_stable_dt(&scene, &state, &max_dt, NULL, 1 << 20), MOTUS_ERROR_SCRATCH_TOO_SMALL);
    ENSURE_EQ_INT(motus_scene_max_stable_dt(&scene, &state, &max_dt, scratch, 6 * sizeof(motus_real) - 1),
                  MOTUS_ERROR_SCRATCH_TOO_SMALL);
    ENSURE_EQ_INT(motus_scene_max_stable_dt(&scene, &state, &max_dt, (char *)scratch + 1, sizeof scratch - 1),
                  MOTUS_ERROR_SCRATCH_TOO_SMALL);
    ENSURE(max_dt == -3);
    ENSURE(same_bytes(scratch, scratch_before, sizeof scratch));
    /* Enough scratch: 2*sqrt(m/k) with k = 400 on 1 kg (the anchored spring): 0.1 s; the pair 100*(1 + 1). */
    ENSURE_EQ_INT(motus_scene_max_stable_dt(&scene, &state, &max_dt, scratch, 6 * sizeof(motus_real)), MOTUS_OK);
    ENSURE_NEAR(max_dt, 0.1, 8 * MOTUS_REAL_EPSILON);
    scene.spring_count = 0;
    max_dt = -3;
    ENSURE_EQ_INT(motus_scene_max_stable_dt(&scene, &state, &max_dt, NULL, 0), MOTUS_OK);
    ENSURE(max_dt == infinity());
}

static const motus_test_case TESTS[] = {
    TEST_CASE(far_from_origin_plain_step_loses_small_steps),
    TEST_CASE(far_from_origin_compensated_step_keeps_small_steps),
    TEST_CASE(far_from_origin_compensated_step_3d),
    TEST_CASE(compensated_step_is_the_plain_step_near_the_origin),
    TEST_CASE(compensated_step_rejects_bad_input),
    TEST_CASE(particle_step_overflow_near_max),
    TEST_CASE(step_overflow_near_max_one_method_per_family),
    TEST_CASE(step_rescued_where_only_an_intermediate_overflows),
    TEST_CASE(step_rescued_where_a_term_overflows),
    TEST_CASE(particle_step_rescued_as_the_engine),
    TEST_CASE(method_sums_overflow_only_where_the_step_does),
    TEST_CASE(fast_kernel_hands_a_term_out_of_range_to_the_general_kernel),
    TEST_CASE(damping_factors_accepted_or_rejected_as_documented),
    TEST_CASE(rest_speed_keeps_v_dt_normal),
    TEST_CASE(damping_flushes_to_exact_zero_at_the_rest_speed),
    TEST_CASE(damping_reaches_exact_zero_without_subnormals),
    TEST_CASE(scene_damping_reaches_exact_zero_as_the_particle_path),
    TEST_CASE(scene_without_damping_does_not_flush),
    TEST_CASE(substeps_for_a_stable_dt_of_negative_zero_is_too_stiff),
    TEST_CASE(attractor_pull_far_away_is_representable),
    TEST_CASE(tether_pull_from_far_across_is_representable),
    TEST_CASE(quadratic_drag_at_a_speed_whose_square_overflows),
    TEST_CASE(attractor_pull_is_right_at_every_distance),
    TEST_CASE(attractor_pull_of_a_strength_near_the_largest_real),
    TEST_CASE(exact_stepper_at_huge_drag_and_dt),
    TEST_CASE(spring_of_1e20_at_its_rest_length_of_1e20),
    TEST_CASE(subnormal_dt_in_substeps_still_moves),
    TEST_CASE(scene_max_stable_dt_needs_scratch_for_springs),
};

int main(int argc, char **argv) { return motus_test_main(argc, argv, TESTS, TEST_COUNT(TESTS)); }
