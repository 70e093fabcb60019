/* Extremes: far from the origin, overflow near the float maximum, damping factors, subnormal speeds.
   Built in float and in double (MOTUS_DOUBLE). The far-from-origin and subnormal tests print the figures
   they measure (run `motus_extremes far_from_origin_plain_step_loses_small_steps`, ...). */
#include "motus.h"
#include "support/motus_test.h"

#include <float.h>

#ifdef MOTUS_DOUBLE
#define REAL_MAX DBL_MAX
#define REAL_MIN_NORMAL DBL_MIN
#define PRECISION "double"
#else
#define REAL_MAX FLT_MAX
#define REAL_MIN_NORMAL FLT_MIN
#define PRECISION "float"
#endif

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
    ENSURE_EQ_INT(motus_particle_step_compensated(&p, &carry, 0), MOTUS_ERROR_INVALID_TIME_STEP);
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

/* =================================================================================================
   Overflow near the float maximum: reported, nothing written
   ================================================================================================= */
TEST(particle_step_overflow_near_max) {
    /* Velocity: v + F/m*dt past the maximum; position: x + v*dt past it; both near +-max. */
    const motus_real near_max = REAL_MAX * MOTUS_R(0.75);
    int sign;
    for (sign = -1; sign <= 1; sign += 2) {
        motus_particle p, before;
        motus_particle_init(&p, motus_v2(0, 0), 1);
        p.velocity = motus_v2(0, (motus_real)sign * near_max);
        p.force = motus_v2(0, (motus_real)sign * near_max);
        before = p;
        ENSURE_EQ_INT(motus_particle_step(&p, 1), MOTUS_ERROR_OVERFLOW);
        ENSURE_EQ_INT(motus_particle_step_linear_drag(&p, 0, 1), MOTUS_ERROR_OVERFLOW);
        ENSURE(same_bytes(&p, &before, sizeof p));
        p.force = motus_v2(0, 0);
        p.position = motus_v2((motus_real)sign * near_max, 0);
        p.velocity = motus_v2((motus_real)sign * near_max, 0);
        before = p;
        ENSURE_EQ_INT(motus_particle_step(&p, 1), MOTUS_ERROR_OVERFLOW);
        ENSURE(same_bytes(&p, &before, sizeof p));
        /* One step short of the edge is fine: dt small enough to stay finite. */
        ENSURE_EQ_INT(motus_particle_step(&p, MOTUS_R(0.25)), MOTUS_OK);
        ENSURE(motus_real_is_finite(p.position.x));
        /* A force at the maximum on a light particle: F/m overflows before dt can shrink it. */
        motus_particle_init(&p, motus_v2(0, 0), MOTUS_R(0.5));
        p.force = motus_v2((motus_real)sign * REAL_MAX, 0);
        before = p;
        ENSURE_EQ_INT(motus_particle_step(&p, MOTUS_R(1e-6)), MOTUS_ERROR_OVERFLOW);
        ENSURE(same_bytes(&p, &before, sizeof p));
    }
}

TEST(stepper_overflow_near_max_one_method_per_family) {
    /* Euler, Verlet, Runge-Kutta, composition (Forest-Ruth) and the exact stepper: particle 0 fine,
       particle 1 at max/8 in position and velocity (or force; RK4 sums 6 slopes, so not much nearer):
       fine at dt 1/4, MOTUS_ERROR_OVERFLOW at dt 16 with nothing written, not the particles, not the
       stepper. */
    static const motus_method methods[5] = {MOTUS_SEMI_IMPLICIT_EULER, MOTUS_VELOCITY_VERLET, MOTUS_RK4,
                                            MOTUS_FOREST_RUTH, MOTUS_EXACT_LINEAR_DRAG};
    const motus_real near_max = REAL_MAX / 8;
    int m, which;
    for (m = 0; m < 5; ++m)
        for (which = 0; which < 2; ++which) {
            motus_vec2 scratch[8 * 2];
            motus_stepper_desc desc;
            motus_stepper stepper, stepper_before;
            motus_particle p[2], before[2];
            memset(&desc, 0, sizeof desc);
            memset(&stepper, 0, sizeof stepper);
            desc.capacity = 2;
            desc.method = methods[m];
            desc.scratch = scratch;
            desc.scratch_bytes = sizeof scratch;
            ENSURE_EQ_INT(motus_stepper_init(&stepper, &desc), MOTUS_OK);
            motus_particle_init(&p[0], motus_v2(1, 2), 1);
            motus_particle_init(&p[1], motus_v2(0, 0), 1);
            if (which == 0) p[1].position = p[1].velocity = motus_v2(near_max, -near_max);
            else p[1].velocity = p[1].force = motus_v2(-near_max, near_max);
            ENSURE_EQ_INT(motus_stepper_step(&stepper, p, 2, NULL, MOTUS_R(0.25)), MOTUS_OK); /* fine at 0.25 */
            memcpy(before, p, sizeof p);
            stepper_before = stepper;
            if (motus_stepper_step(&stepper, p, 2, NULL, 16) != MOTUS_ERROR_OVERFLOW) {
                fprintf(stderr, "  %s, %s: no overflow reported\n", motus_method_name(methods[m]),
                        which ? "velocity" : "position");
                motus_test_failures++;
            }
            ENSURE(same_bytes(p, before, sizeof p));
            ENSURE(same_bytes(&stepper, &stepper_before, sizeof stepper));
        }
}

/* A 2D batch of n particles with their own arrays. */
typedef struct small_batch {
    motus_real x[16], y[16], vx[16], vy[16], fx[16], fy[16], inverse_mass[16];
    motus_batch batch;
} small_batch;
static void small_batch_bind(small_batch *b) {
    memset(&b->batch, 0, sizeof b->batch);
    b->batch.dimensions = 2;
    b->batch.position[0] = b->x, b->batch.position[1] = b->y;
    b->batch.velocity[0] = b->vx, b->batch.velocity[1] = b->vy;
    b->batch.force[0] = b->fx, b->batch.force[1] = b->fy;
    b->batch.inverse_mass = b->inverse_mass;
}

TEST(batch_overflow_near_max_is_reported) {
    /* Release builds write the range and report a non-finite result (MOTUS_ERROR_NOT_FINITE: the inputs
       are gone, so the step cannot tell overflow from bad data); MOTUS_CHECKED builds (batch_checked.*
       in tests/batch.c) report MOTUS_ERROR_OVERFLOW and write nothing. Here: position and velocity
       overflow, in a whole vector and in the partial one, are never reported as OK. */
    static small_batch b;
    motus_scene scene;
    int at, which, i;
    for (at = 0; at < 16; at += 15)
        for (which = 0; which < 2; ++which) {
            memset(&scene, 0, sizeof scene);
            scene.has = MOTUS_HAS_FORCES | MOTUS_HAS_PARTICLE_MASS | MOTUS_HAS_DAMPING_PER_STEP;
            scene.damping = MOTUS_R(0.99);
            small_batch_bind(&b);
            for (i = 0; i < 16; ++i) {
                b.x[i] = b.y[i] = (motus_real)i;
                b.vx[i] = b.vy[i] = b.fx[i] = b.fy[i] = 1;
                b.inverse_mass[i] = 1;
            }
            if (which == 0) b.x[at] = b.vx[at] = REAL_MAX * MOTUS_R(0.75);
            else b.fy[at] = REAL_MAX, b.inverse_mass[at] = 4;
            ENSURE_EQ_INT(motus_batch_check(&scene, &b.batch, 0, 16, NULL, NULL), MOTUS_OK);
            ENSURE(motus_batch_step(&scene, &b.batch, 0, 16, 1) != MOTUS_OK);
        }
}

/* =================================================================================================
   Damping factors 0, 1, above 1, negative, NaN
   ================================================================================================= */
TEST(damping_factors_accepted_or_rejected_as_documented) {
    /* [0, 1] is accepted (-0 too: it is 0); everything else is MOTUS_ERROR_INVALID_DAMPING with the
       particle unchanged, in both particle functions and in the batch scene (per step and per second). */
    const motus_real accepted[] = {0, -MOTUS_R(0.0), MOTUS_R(0.5), 1};
    const motus_real rejected[] = {1 + MOTUS_REAL_EPSILON, 2, infinity(), -MOTUS_R(1e-30), MOTUS_R(-0.5),
                                   -1, -infinity(), not_a_number(), -not_a_number()};
    static small_batch b;
    motus_scene scene;
    motus_particle p, before;
    int i, per_second;
    motus_particle_init(&p, motus_v2(1, 2), 1);
    p.velocity = motus_v2(3, -4);
    before = p;
    small_batch_bind(&b);
    memset(&scene, 0, sizeof scene);
    for (i = 0; i < (int)(sizeof rejected / sizeof rejected[0]); ++i) {
        ENSURE_EQ_INT(motus_particle_damp_per_step(&p, rejected[i]), MOTUS_ERROR_INVALID_DAMPING);
        ENSURE_EQ_INT(motus_particle_damp_per_second(&p, rejected[i], DT), MOTUS_ERROR_INVALID_DAMPING);
        for (per_second = 0; per_second < 2; ++per_second) {
            scene.has = per_second ? MOTUS_HAS_DAMPING_PER_SECOND : MOTUS_HAS_DAMPING_PER_STEP;
            scene.damping = rejected[i];
            ENSURE_EQ_INT(motus_scene_check(&scene, &b.batch), MOTUS_ERROR_INVALID_DAMPING);
            ENSURE_EQ_INT(motus_batch_step(&scene, &b.batch, 0, 1, DT), MOTUS_ERROR_INVALID_DAMPING);
        }
    }
    ENSURE(same_bytes(&p, &before, sizeof p));
    for (i = 0; i < (int)(sizeof accepted / sizeof accepted[0]); ++i) {
        motus_particle q = before, r = before;
        const motus_real f = accepted[i];
        ENSURE_EQ_INT(motus_particle_damp_per_step(&q, f), MOTUS_OK);
        ENSURE_EQ_INT(motus_particle_damp_per_second(&r, f, DT), MOTUS_OK);
        if (f == 1) { /* keeps the velocity exactly */
            ENSURE(same_bytes(&q, &before, sizeof q) && same_bytes(&r, &before, sizeof r));
        } else if (f == 0) { /* stops the particle, per step and per second at any dt */
            ENSURE(q.velocity.x == 0 && q.velocity.y == 0 && r.velocity.x == 0 && r.velocity.y == 0);
        } else {
            ENSURE(q.velocity.x == MOTUS_R(1.5) && q.velocity.y == -2);
            ENSURE_NEAR(r.velocity.x, 3 * pow(0.5, (double)DT), 8 * MOTUS_REAL_EPSILON);
        }
        for (per_second = 0; per_second < 2; ++per_second) {
            motus_particle single = before;
            scene.has = per_second ? MOTUS_HAS_DAMPING_PER_SECOND : MOTUS_HAS_DAMPING_PER_STEP;
            scene.damping = f;
            b.x[0] = before.position.x, b.y[0] = before.position.y;
            b.vx[0] = before.velocity.x, b.vy[0] = before.velocity.y;
            ENSURE_EQ_INT(motus_batch_step(&scene, &b.batch, 0, 1, DT), MOTUS_OK);
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
    motus_particle_init(&p, motus_v2(0, 0), 1);
    /* Just below after damping: zero, of the component's sign. Just above: kept. */
    p.velocity = motus_v2(rest * MOTUS_R(1.5), -rest * MOTUS_R(1.5));
    ENSURE_EQ_INT(motus_particle_damp_per_step(&p, MOTUS_R(0.5)), MOTUS_OK);
    ENSURE(p.velocity.x == 0 && !signbit(p.velocity.x) && p.velocity.y == 0 && signbit(p.velocity.y));
    p.velocity = motus_v2(rest * 4, -rest * 4);
    ENSURE_EQ_INT(motus_particle_damp_per_step(&p, MOTUS_R(0.5)), MOTUS_OK);
    ENSURE(p.velocity.x == rest * 2 && p.velocity.y == -rest * 2);
    /* A velocity that comes in subnormal leaves as zero; a normal one at 1 is left alone (bit for bit). */
    p.velocity = motus_v2(REAL_MIN_NORMAL / 8, 1);
    ENSURE_EQ_INT(motus_particle_damp_per_second(&p, 1, DT), MOTUS_OK);
    ENSURE(p.velocity.x == 0 && p.velocity.y == 1);
}

/* Damp (1, -0.3) by 0.99 per step, or the per-second equivalent, until it stops; returns the steps taken,
   counts the steps that left a subnormal component. */
static int steps_to_rest(int per_second, int *subnormal_steps) {
    const motus_real retained = motus_damping_per_second_from_per_step(MOTUS_R(0.99), 60);
    motus_particle p;
    int steps = 0;
    motus_particle_init(&p, motus_v2(0, 0), 1);
    p.velocity = motus_v2(1, MOTUS_R(-0.3));
    *subnormal_steps = 0;
    while ((p.velocity.x != 0 || p.velocity.y != 0) && steps < 1000000) {
        if (per_second) motus_particle_damp_per_second(&p, retained, DT);
        else motus_particle_damp_per_step(&p, MOTUS_R(0.99));
        *subnormal_steps += is_subnormal(p.velocity.x) || is_subnormal(p.velocity.y);
        ++steps;
    }
    return steps;
}

TEST(damping_reaches_exact_zero_without_subnormals) {
    /* The old damping (v *= 0.99) from 1 m/s never reaches 0: below 50 times the smallest subnormal,
       0.99*v rounds back to v, so the speed stays subnormal (and slow) for ever. With the flush: exact zero
       at 1e-30 (1e-300 in double), after ln(1e-30)/ln(0.99) = 6,874 steps (68,732), never a subnormal. */
    motus_real v = 1;
    int old_steps, old_subnormal = 0, per_second, subnormal, steps;
    for (old_steps = 0; old_steps < 200000; ++old_steps) {
        v = v * MOTUS_R(0.99);
        old_subnormal += is_subnormal(v);
    }
    printf("  %s, old damping: after %d steps v = %g, subnormal for the last %d steps\n", PRECISION, old_steps,
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

TEST(batch_damping_reaches_exact_zero_as_the_particle_path) {
    /* A batch of 13 particles (a whole vector and a partial one) under per-step and per-second damping,
       gravity off: every velocity reaches exact zero, no subnormal on the way, and the batch agrees with
       motus_particle_step + damping bit for bit at every step. */
    static small_batch b;
    motus_scene scene;
    motus_particle p[13];
    int per_second, i, step, subnormal = 0, mismatch = 0, moving = 1;
    for (per_second = 0; per_second < 2; ++per_second) {
        memset(&scene, 0, sizeof scene);
        scene.has = per_second ? MOTUS_HAS_DAMPING_PER_SECOND : MOTUS_HAS_DAMPING_PER_STEP;
        scene.damping = per_second ? MOTUS_R(0.01) : MOTUS_R(0.9);
        scene.inverse_mass = 1;
        small_batch_bind(&b);
        for (i = 0; i < 13; ++i) {
            motus_particle_init(&p[i], motus_v2((motus_real)i, -(motus_real)i), 1);
            p[i].velocity = motus_v2((motus_real)(i - 6) * MOTUS_R(0.37), (motus_real)(i % 3) - 1);
            b.x[i] = p[i].position.x, b.y[i] = p[i].position.y;
            b.vx[i] = p[i].velocity.x, b.vy[i] = p[i].velocity.y;
        }
        for (step = 0; step < 20000 && moving; ++step) {
            ENSURE_EQ_INT(motus_batch_step(&scene, &b.batch, 0, 13, DT), MOTUS_OK);
            moving = 0;
            for (i = 0; i < 13; ++i) {
                motus_particle_step(&p[i], DT);
                if (per_second) motus_particle_damp_per_second(&p[i], scene.damping, DT);
                else motus_particle_damp_per_step(&p[i], scene.damping);
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

TEST(batch_without_damping_does_not_flush) {
    /* The flush belongs to damping: a scene without it keeps a tiny velocity (the general kernel, which
       always multiplies by a neutral damping of 1, included). */
    static small_batch b;
    motus_scene scene;
    int general;
    for (general = 0; general < 2; ++general) {
        memset(&scene, 0, sizeof scene);
        scene.has = general ? MOTUS_HAS_QUADRATIC_DRAG : 0u;
        scene.inverse_mass = 1;
        small_batch_bind(&b);
        b.x[0] = b.y[0] = 0;
        b.vx[0] = (motus_real)(MOTUS_REST_SPEED) / 4, b.vy[0] = 0;
        ENSURE_EQ_INT(motus_batch_step(&scene, &b.batch, 0, 1, DT), MOTUS_OK);
        ENSURE(b.vx[0] == (motus_real)(MOTUS_REST_SPEED) / 4);
    }
}

static const motus_test_case TESTS[] = {
    TEST_CASE(far_from_origin_plain_step_loses_small_steps),
    TEST_CASE(far_from_origin_compensated_step_keeps_small_steps),
    TEST_CASE(compensated_step_is_the_plain_step_near_the_origin),
    TEST_CASE(compensated_step_rejects_bad_input),
    TEST_CASE(particle_step_overflow_near_max),
    TEST_CASE(stepper_overflow_near_max_one_method_per_family),
    TEST_CASE(batch_overflow_near_max_is_reported),
    TEST_CASE(damping_factors_accepted_or_rejected_as_documented),
    TEST_CASE(rest_speed_keeps_v_dt_normal),
    TEST_CASE(damping_flushes_to_exact_zero_at_the_rest_speed),
    TEST_CASE(damping_reaches_exact_zero_without_subnormals),
    TEST_CASE(batch_damping_reaches_exact_zero_as_the_particle_path),
    TEST_CASE(batch_without_damping_does_not_flush),
};

int main(int argc, char **argv) { return motus_test_main(argc, argv, TESTS, TEST_COUNT(TESTS)); }
