/* Stability limits and the extremes: where each method's amplitude starts to grow on a spring (measured by
   bisection with the real stepper, against motus_method_stability_limit), automatic substepping, dt from
   1e-7 s to 1 s, 10^7-step runs, masses from 1e-20 to 1e20 and immovable particles.
   Built in float and in double (MOTUS_DOUBLE). `motus_stability bisect_thresholds` prints the measured
   thresholds next to theory. No timing. */
#include "motus.h"
#include "support/motus_test.h"

#include <float.h>
#include <limits.h>

#ifdef MOTUS_DOUBLE
#define REAL_MAX DBL_MAX
#define REAL_MIN DBL_MIN
#else
#define REAL_MAX FLT_MAX
#define REAL_MIN FLT_MIN
#endif
#define EPS ((double)MOTUS_REAL_EPSILON)
#define CAPACITY 8

static motus_real not_a_number(void) { return (motus_real)NAN; }
static motus_real infinity(void) { return (motus_real)HUGE_VAL; }
static int same_bytes(const void *a, const void *b, size_t size) { return memcmp(a, b, size) == 0; }

/* A stepper with its own scratch: 8 arrays of CAPACITY is more than any method takes. */
typedef struct test_stepper {
    motus_stepper stepper;
    motus_vec2 scratch[8 * CAPACITY];
} test_stepper;

static void stepper_init(test_stepper *s, motus_method method) {
    motus_stepper_desc desc;
    memset(s, 0, sizeof *s);
    memset(&desc, 0, sizeof desc);
    desc.capacity = CAPACITY;
    desc.method = method;
    desc.scratch = s->scratch;
    desc.scratch_bytes = sizeof s->scratch;
    ENSURE(motus_stepper_scratch_size(method, CAPACITY) <= sizeof s->scratch);
    ENSURE_EQ_INT(motus_stepper_init(&s->stepper, &desc), MOTUS_OK);
}

/* The methods with a finite, nonzero limit: the ones substepping can keep stable. */
static int has_finite_limit(motus_method m) {
    motus_real limit = motus_method_stability_limit(m);
    return limit > 0 && motus_real_is_finite(limit);
}

/* =================================================================================================
   The oscillator: one particle of mass M on a zero-length spring of stiffness K to the origin
   =================================================================================================
   w = sqrt(K/M) = 2 rad/s, so h = z/2 is exact in binary for the z the bisection tries up to rounding of
   z itself. The amplitude is |(x, v/w)|, which the exact motion keeps at 1. */
#define OSC_MASS MOTUS_R(0.5)
#define OSC_STIFFNESS MOTUS_R(2.0)
#define OSC_OMEGA 2.0

typedef struct oscillator {
    test_stepper s;
    motus_particle particle;
    motus_spring spring;
    motus_forces forces;
} oscillator;

static void oscillator_init(oscillator *o, motus_method method, motus_real damping) {
    memset(o, 0, sizeof *o);
    stepper_init(&o->s, method);
    ENSURE_EQ_INT(motus_particle_init(&o->particle, motus_v2(1, 0), OSC_MASS), MOTUS_OK);
    o->spring.a = 0;
    o->spring.b = -1;
    o->spring.stiffness = OSC_STIFFNESS;
    o->spring.damping = damping;
    o->forces.springs = &o->spring;
    o->forces.spring_count = 1;
}

static double amplitude(const motus_particle *p, double omega) {
    double x = (double)p->position.x, y = (double)p->position.y;
    double vx = (double)p->velocity.x / omega, vy = (double)p->velocity.y / omega;
    return sqrt(x * x + y * y + vx * vx + vy * vy);
}

/* The largest amplitude over `steps` steps of h, from amplitude 1. A step that overflows counts as
   growth without end (HUGE_VAL). */
static double largest_amplitude(motus_method method, motus_real h, int steps, motus_real damping) {
    oscillator o;
    double largest = 1;
    int i;
    oscillator_init(&o, method, damping);
    for (i = 0; i < steps; ++i) {
        double a;
        if (motus_stepper_step(&o.s.stepper, &o.particle, 1, &o.forces, h) != MOTUS_OK) return HUGE_VAL;
        a = amplitude(&o.particle, OSC_OMEGA);
        if (a > largest) largest = a;
    }
    return largest;
}

/* The amplitude after `steps` steps of h (HUGE_VAL if a step overflows). */
static double final_amplitude(motus_method method, motus_real h, int steps, motus_real damping) {
    oscillator o;
    int i;
    oscillator_init(&o, method, damping);
    for (i = 0; i < steps; ++i)
        if (motus_stepper_step(&o.s.stepper, &o.particle, 1, &o.forces, h) != MOTUS_OK) return HUGE_VAL;
    return amplitude(&o.particle, OSC_OMEGA);
}

/* "Grows": the amplitude passes 1000 within 4000 steps. Below the limit a symplectic method's amplitude
   wobbles, more as z nears the limit (the invariant ellipse of the step stretches like 1/sqrt(limit - z)),
   but it passes 1000 only within ~1e-6 of the limit; above it the amplitude grows by 1 + sqrt(2*limit*dz)
   per step (RK4: 1 + 2.5*dz), past 1000 in 4000 steps from dz ~ 1e-6 (RK4: 1e-3, 0.04% of its limit). */
static int grows(motus_method method, double z) {
    return largest_amplitude(method, (motus_real)(z / OSC_OMEGA), 4000, 0) > 1000;
}

/* Bisection on z between a stable and an unstable value; returns w*h at the edge, h as rounded. */
static double measured_threshold(motus_method method, double lo, double hi) {
    int k;
    ENSURE(!grows(method, lo));
    ENSURE(grows(method, hi));
    for (k = 0; k < 40; ++k) {
        double mid = 0.5 * (lo + hi);
        if (grows(method, mid)) hi = mid;
        else lo = mid;
    }
    return (double)(motus_real)(hi / OSC_OMEGA) * OSC_OMEGA;
}

/* =================================================================================================
   Stability limits: measured against theory
   ================================================================================================= */
TEST(limits_table) {
    ENSURE(motus_method_stability_limit(MOTUS_SEMI_IMPLICIT_EULER) == 2);
    ENSURE(motus_method_stability_limit(MOTUS_POSITION_VERLET) == 2);
    ENSURE(motus_method_stability_limit(MOTUS_VELOCITY_VERLET) == 2);
    ENSURE(motus_method_stability_limit(MOTUS_LEAPFROG) == 2);
    ENSURE(motus_method_stability_limit(MOTUS_EXPLICIT_EULER) == 0);
    ENSURE(motus_method_stability_limit(MOTUS_MIDPOINT) == 0);
    ENSURE_NEAR(motus_method_stability_limit(MOTUS_RK4), 2 * sqrt(2.0), 2 * EPS);
    ENSURE(!motus_real_is_finite(motus_method_stability_limit(MOTUS_EXACT_LINEAR_DRAG)));
    ENSURE(motus_method_stability_limit(MOTUS_EXACT_LINEAR_DRAG) > 0);
    ENSURE(motus_method_stability_limit(MOTUS_METHOD_COUNT) == -1);
    ENSURE(motus_method_stability_limit((motus_method)-1) == -1);
    {
        /* Forest-Ruth from its trace (STABILITY LIMITS): three leapfrog maps S(s) = [[1 - s^2/2, s - s^3/4],
           [-s, 1 - s^2/2]] of s = theta*z, (1 - 2*theta)*z, theta*z; the limit is where the trace of the
           product is back at 2. Bisection in double on that closed form. */
        const double theta = 1 / (2 - cbrt(2.0));
        double lo = 1.4, hi = 1.7;
        int k;
        for (k = 0; k < 60; ++k) {
            double z = 0.5 * (lo + hi), a = theta * z, b = (1 - 2 * theta) * z;
            double P = 1 - a * a / 2, Q = a - a * a * a / 4, p = 1 - b * b / 2, q = b - b * b * b / 4;
            double trace = 2 * p * (P * P - a * Q) - 2 * P * (Q * b + a * q);
            if (trace < 2) lo = z;
            else hi = z;
        }
        /* The trace loses ~1e-15 near the root to cancellation: 1e-12 in double, rounding in float. */
        ENSURE_NEAR(motus_method_stability_limit(MOTUS_FOREST_RUTH), lo, fmax(1e-12, 2 * EPS));
    }
}

TEST(bisect_thresholds) {
    int m;
    printf("  %-20s %-12s %-12s %s\n", "method", "theory w*h", "measured", "off by");
    for (m = 0; m < MOTUS_METHOD_COUNT; ++m) {
        const double limit = (double)motus_method_stability_limit((motus_method)m);
        double measured;
        if (!has_finite_limit((motus_method)m)) continue;
        measured = measured_threshold((motus_method)m, 0.5 * limit, 1.5 * limit);
        printf("  %-20s %-12.7f %-12.7f %+.2e\n", motus_method_name((motus_method)m), limit, measured,
               (measured - limit) / limit);
        ENSURE_NEAR(measured, limit, 0.01 * limit);
    }
}

/* Explicit Euler and midpoint multiply the amplitude by exactly g(z) every step (their step is a rotation
   times g: see STABILITY LIMITS), so they grow at every z > 0. Float cannot see a growth below its
   rounding, so there the sweep starts where g - 1 is at least 1e-5. */
static void ensure_growth_everywhere(motus_method method, int quartic) {
    static const double zs[] = {1e-3, 3e-3, 1e-2, 3e-2, 0.1, 0.3, 0.5, 1, 1.5, 2, 2.5, 3, 5};
    int i;
    for (i = 0; i < (int)(sizeof zs / sizeof zs[0]); ++i) {
        const double z = zs[i];
        const motus_real h = (motus_real)(z / OSC_OMEGA);
        const double zr = (double)h * OSC_OMEGA; /* z as rounded */
        const double g = quartic ? sqrt(1 + zr * zr * zr * zr / 4) : sqrt(1 + zr * zr);
        /* Enough steps to grow by e^2 if that stays representable, at most 20000. */
        int steps = (int)fmin(20000, fmin(2 / log(g), 0.5 * log((double)REAL_MAX) / log(g)));
        oscillator o;
        double measured;
        int k;
        if (g - 1 < 1e-5 && EPS > 1e-10) continue; /* float */
        oscillator_init(&o, method, 0);
        if (steps < 1) steps = 1;
        for (k = 0; k < steps; ++k) ENSURE_EQ_INT(motus_stepper_step(&o.s.stepper, &o.particle, 1, &o.forces, h), MOTUS_OK);
        measured = pow(amplitude(&o.particle, OSC_OMEGA), 1.0 / steps);
        printf("  %-15s z = %-6g %5d steps: growth per step %.12f, theory %.12f, off by %.2e\n",
               motus_method_name(method), z, steps, measured, g, measured / g - 1);
        ENSURE(amplitude(&o.particle, OSC_OMEGA) > 1);
        /* Each step rounds ~6 times by eps/2 relative; averaged over the run, a few eps per step. */
        ENSURE_NEAR(measured / g, 1, 4 * EPS);
    }
}

TEST(explicit_euler_grows_at_every_dt) { ensure_growth_everywhere(MOTUS_EXPLICIT_EULER, 0); }
TEST(midpoint_grows_at_every_dt) { ensure_growth_everywhere(MOTUS_MIDPOINT, 1); }

TEST(exact_stepper_takes_no_spring) {
    /* Its limit is +Inf because it has no spring to lose: a spring is refused, as its step refuses it. */
    oscillator o;
    motus_real dt = 0;
    oscillator_init(&o, MOTUS_EXACT_LINEAR_DRAG, 0);
    ENSURE_EQ_INT(motus_stepper_step(&o.s.stepper, &o.particle, 1, &o.forces, MOTUS_R(0.1)), MOTUS_ERROR_UNSUPPORTED);
    ENSURE_EQ_INT(motus_stepper_max_stable_dt(&o.s.stepper, &o.particle, 1, &o.forces, &dt), MOTUS_ERROR_UNSUPPORTED);
    o.forces.spring_count = 0;
    o.forces.linear_drag = 1000;
    o.forces.gravity = motus_v2(0, -10);
    ENSURE_EQ_INT(motus_stepper_max_stable_dt(&o.s.stepper, &o.particle, 1, &o.forces, &dt), MOTUS_OK);
    ENSURE(!motus_real_is_finite(dt) && dt > 0);
    ENSURE_EQ_INT(motus_max_stable_dt(MOTUS_EXACT_LINEAR_DRAG, 1e6f, 1, &dt), MOTUS_OK);
    ENSURE(!motus_real_is_finite(dt) && dt > 0);
}

/* =================================================================================================
   The limit API: max stable dt, substep counts, bad input
   ================================================================================================= */
TEST(max_stable_dt_is_limit_over_omega) {
    int m;
    for (m = 0; m < MOTUS_METHOD_COUNT; ++m) {
        const motus_real limit = motus_method_stability_limit((motus_method)m);
        motus_real dt = -1;
        ENSURE_EQ_INT(motus_max_stable_dt((motus_method)m, 800, 2, &dt), MOTUS_OK); /* w = 20 */
        if (motus_real_is_finite(limit)) ENSURE_NEAR(dt, limit / 20, 2 * EPS * (double)limit / 20);
        else ENSURE(!motus_real_is_finite(dt) && dt > 0);
        ENSURE_EQ_INT(motus_max_stable_dt((motus_method)m, 0, 2, &dt), MOTUS_OK); /* no spring: no limit */
        ENSURE(!motus_real_is_finite(dt) && dt > 0);
    }
    {
        /* A spring between two particles: the reduced mass m1*m2/(m1 + m2), w^2 = k*(1/m1 + 1/m2). */
        motus_real dt;
        ENSURE_EQ_INT(motus_max_stable_dt(MOTUS_SEMI_IMPLICIT_EULER, 100, MOTUS_R(0.5) * 1 / MOTUS_R(1.5), &dt), MOTUS_OK);
        ENSURE_NEAR(dt, 2 / sqrt(100 * 3.0), 4 * EPS * dt);
    }
}

TEST(max_stable_dt_rejects_bad_input) {
    static const struct {
        int method;
        double stiffness, mass;
        motus_result expected;
    } cases[] = {
        {MOTUS_RK4, -1, 1, MOTUS_ERROR_INVALID_FORCES}, {MOTUS_RK4, 1, 0, MOTUS_ERROR_INVALID_MASS},
        {MOTUS_RK4, 1, -1, MOTUS_ERROR_INVALID_MASS},   {MOTUS_METHOD_COUNT, 1, 1, MOTUS_ERROR_UNSUPPORTED},
        {-1, 1, 1, MOTUS_ERROR_UNSUPPORTED},
    };
    motus_real dt = 42;
    int i;
    for (i = 0; i < (int)(sizeof cases / sizeof cases[0]); ++i)
        ENSURE_EQ_INT(motus_max_stable_dt((motus_method)cases[i].method, (motus_real)cases[i].stiffness,
                                          (motus_real)cases[i].mass, &dt), cases[i].expected);
    ENSURE_EQ_INT(motus_max_stable_dt(MOTUS_RK4, not_a_number(), 1, &dt), MOTUS_ERROR_NOT_FINITE);
    ENSURE_EQ_INT(motus_max_stable_dt(MOTUS_RK4, 1, not_a_number(), &dt), MOTUS_ERROR_NOT_FINITE);
    ENSURE_EQ_INT(motus_max_stable_dt(MOTUS_RK4, infinity(), 1, &dt), MOTUS_ERROR_NOT_FINITE);
    ENSURE_EQ_INT(motus_max_stable_dt(MOTUS_RK4, 1, infinity(), &dt), MOTUS_ERROR_NOT_FINITE);
    ENSURE_EQ_INT(motus_max_stable_dt(MOTUS_RK4, 1, 1, NULL), MOTUS_ERROR_NULL_POINTER);
    ENSURE(dt == 42); /* untouched */
}

/* The fewest n with dt/n < safety*max_dt, in motus_real as the substepped step computes it. */
static void ensure_minimal(motus_real dt, motus_real max_dt, motus_real safety, int n) {
    const motus_real limit = safety * max_dt;
    ENSURE(n >= 1);
    ENSURE(dt / (motus_real)n < limit);
    if (n > 1) ENSURE(!(dt / (motus_real)(n - 1) < limit));
}

TEST(substeps_for_is_minimal) {
    static const double dts[] = {1e-6, 1.0 / 144, 1.0 / 60, 1.0 / 30, 0.1, 0.5, 2};
    static const double max_dts[] = {1e-4, 0.001, 1.0 / 600, 0.0123, 1.0 / 60, 0.05, 1, 100};
    static const double safeties[] = {1, 0.9, 0.5, 0.1};
    int i, j, k, n;
    for (i = 0; i < (int)(sizeof dts / sizeof dts[0]); ++i)
        for (j = 0; j < (int)(sizeof max_dts / sizeof max_dts[0]); ++j)
            for (k = 0; k < (int)(sizeof safeties / sizeof safeties[0]); ++k) {
                const motus_real dt = (motus_real)dts[i], max_dt = (motus_real)max_dts[j];
                const motus_real safety = (motus_real)safeties[k];
                n = -1;
                ENSURE_EQ_INT(motus_substeps_for(dt, max_dt, safety, &n), MOTUS_OK);
                ensure_minimal(dt, max_dt, safety, n);
            }
    /* Exactly at the edge: dt/n == limit is not below it, so one more. */
    ENSURE_EQ_INT(motus_substeps_for(1, MOTUS_R(0.25), 1, &n), MOTUS_OK);
    ENSURE_EQ_INT(n, 5);
    ENSURE_EQ_INT(motus_substeps_for(1, infinity(), 1, &n), MOTUS_OK);
    ENSURE_EQ_INT(n, 1);
}

TEST(substeps_for_rejects_bad_input) {
    int n = 42;
    ENSURE_EQ_INT(motus_substeps_for(1, 0, 1, &n), MOTUS_ERROR_TOO_STIFF); /* explicit Euler on a spring */
    ENSURE_EQ_INT(motus_substeps_for(1, (motus_real)1e-12, 1, &n), MOTUS_ERROR_TOO_STIFF); /* > INT_MAX/2 */
    ENSURE_EQ_INT(motus_substeps_for(REAL_MAX, REAL_MIN, 1, &n), MOTUS_ERROR_TOO_STIFF); /* quotient overflows */
    ENSURE_EQ_INT(motus_substeps_for(0, 1, 1, &n), MOTUS_ERROR_INVALID_TIME_STEP);
    ENSURE_EQ_INT(motus_substeps_for(-1, 1, 1, &n), MOTUS_ERROR_INVALID_TIME_STEP);
    ENSURE_EQ_INT(motus_substeps_for(not_a_number(), 1, 1, &n), MOTUS_ERROR_INVALID_TIME_STEP);
    ENSURE_EQ_INT(motus_substeps_for(infinity(), 1, 1, &n), MOTUS_ERROR_INVALID_TIME_STEP);
    ENSURE_EQ_INT(motus_substeps_for(1, not_a_number(), 1, &n), MOTUS_ERROR_NOT_FINITE);
    ENSURE_EQ_INT(motus_substeps_for(1, -infinity(), 1, &n), MOTUS_ERROR_NOT_FINITE);
    ENSURE_EQ_INT(motus_substeps_for(1, -1, 1, &n), MOTUS_ERROR_INVALID_ARGUMENT);
    ENSURE_EQ_INT(motus_substeps_for(1, 1, not_a_number(), &n), MOTUS_ERROR_NOT_FINITE);
    ENSURE_EQ_INT(motus_substeps_for(1, 1, 0, &n), MOTUS_ERROR_INVALID_ARGUMENT);
    ENSURE_EQ_INT(motus_substeps_for(1, 1, MOTUS_R(1.01), &n), MOTUS_ERROR_INVALID_ARGUMENT);
    ENSURE_EQ_INT(motus_substeps_for(1, 1, -1, &n), MOTUS_ERROR_INVALID_ARGUMENT);
    ENSURE_EQ_INT(motus_substeps_for(1, 1, 1, NULL), MOTUS_ERROR_NULL_POINTER);
    ENSURE_EQ_INT(n, 42);
    ENSURE(strlen(motus_result_string(MOTUS_ERROR_TOO_STIFF)) > 20);
    ENSURE(strlen(motus_result_string(MOTUS_ERROR_INVALID_ARGUMENT)) > 20);
    ENSURE(strcmp(motus_result_string(MOTUS_ERROR_TOO_STIFF), motus_result_string(MOTUS_ERROR_INVALID_ARGUMENT)));
    ENSURE(strcmp(motus_result_string(MOTUS_RESULT_COUNT), "unknown motus_result value") == 0);
}

/* =================================================================================================
   Substepping
   ================================================================================================= */
TEST(stepper_max_stable_dt_bounds_the_springs) {
    /* A chain of 6 equal particles (1 kg) on 5 equal springs (k = 100) with its first end on an immovable
       particle: the Gershgorin bound is 4k/m (the chain's highest mode tends to it); one anchored spring
       gives k/m, one spring between two particles k*(1/m1 + 1/m2). */
    test_stepper s;
    motus_particle p[CAPACITY];
    motus_spring springs[CAPACITY];
    motus_forces f;
    motus_real dt = 0;
    int i;
    memset(&f, 0, sizeof f);
    memset(springs, 0, sizeof springs);
    stepper_init(&s, MOTUS_SEMI_IMPLICIT_EULER);
    ENSURE_EQ_INT(motus_particle_init_immovable(&p[0], motus_v2(0, 0)), MOTUS_OK);
    for (i = 1; i < 7; ++i) {
        ENSURE_EQ_INT(motus_particle_init(&p[i], motus_v2((motus_real)i, 0), 1), MOTUS_OK);
        springs[i - 1].a = i - 1, springs[i - 1].b = i, springs[i - 1].stiffness = 100;
    }
    f.springs = springs;
    f.spring_count = 6;
    ENSURE_EQ_INT(motus_stepper_max_stable_dt(&s.stepper, p, 7, &f, &dt), MOTUS_OK);
    ENSURE_NEAR(dt, 2 / sqrt(400.0), 4 * EPS);
    f.spring_count = 1; /* immovable 0 to 1: like an anchor */
    ENSURE_EQ_INT(motus_stepper_max_stable_dt(&s.stepper, p, 7, &f, &dt), MOTUS_OK);
    ENSURE_NEAR(dt, 2 / sqrt(100.0), 4 * EPS);
    f.springs = springs + 1; /* 1 to 2, both free: k*(1 + 1) */
    ENSURE_EQ_INT(motus_stepper_max_stable_dt(&s.stepper, p, 7, &f, &dt), MOTUS_OK);
    ENSURE_NEAR(dt, 2 / sqrt(200.0), 4 * EPS);
    /* Linear drag alone: g*h < 2 for semi-implicit Euler. */
    f.spring_count = 0;
    f.linear_drag = 40;
    ENSURE_EQ_INT(motus_stepper_max_stable_dt(&s.stepper, p, 7, &f, &dt), MOTUS_OK);
    ENSURE_NEAR(dt, 2 / 40.0, 4 * EPS);
    f.linear_drag = 0;
    ENSURE_EQ_INT(motus_stepper_max_stable_dt(&s.stepper, p, 7, &f, &dt), MOTUS_OK);
    ENSURE(!motus_real_is_finite(dt) && dt > 0);
    ENSURE_EQ_INT(motus_stepper_max_stable_dt(&s.stepper, p, 7, NULL, &dt), MOTUS_OK);
    ENSURE(!motus_real_is_finite(dt) && dt > 0);
}

TEST(stepper_max_stable_dt_rejects_bad_input) {
    test_stepper s;
    motus_particle p[2], before[2];
    motus_spring spring;
    motus_forces f;
    motus_real dt = 42;
    memset(&f, 0, sizeof f);
    memset(&spring, 0, sizeof spring);
    stepper_init(&s, MOTUS_RK4);
    ENSURE_EQ_INT(motus_particle_init(&p[0], motus_v2(0, 0), 1), MOTUS_OK);
    ENSURE_EQ_INT(motus_particle_init(&p[1], motus_v2(1, 0), 1), MOTUS_OK);
    spring.a = 0, spring.b = 1, spring.stiffness = 10;
    f.springs = &spring;
    f.spring_count = 1;
    memcpy(before, p, sizeof p);
    ENSURE_EQ_INT(motus_stepper_max_stable_dt(NULL, p, 2, &f, &dt), MOTUS_ERROR_NULL_POINTER);
    ENSURE_EQ_INT(motus_stepper_max_stable_dt(&s.stepper, NULL, 2, &f, &dt), MOTUS_ERROR_NULL_POINTER);
    ENSURE_EQ_INT(motus_stepper_max_stable_dt(&s.stepper, p, 2, &f, NULL), MOTUS_ERROR_NULL_POINTER);
    ENSURE_EQ_INT(motus_stepper_max_stable_dt(&s.stepper, p, -1, &f, &dt), MOTUS_ERROR_INVALID_COUNT);
    ENSURE_EQ_INT(motus_stepper_max_stable_dt(&s.stepper, p, CAPACITY + 1, &f, &dt), MOTUS_ERROR_INVALID_COUNT);
    ENSURE_EQ_INT(motus_stepper_max_stable_dt(&s.stepper, p, 1, &f, &dt), MOTUS_ERROR_INVALID_FORCES); /* b = 1 */
    spring.stiffness = -1;
    ENSURE_EQ_INT(motus_stepper_max_stable_dt(&s.stepper, p, 2, &f, &dt), MOTUS_ERROR_INVALID_FORCES);
    spring.stiffness = not_a_number();
    ENSURE_EQ_INT(motus_stepper_max_stable_dt(&s.stepper, p, 2, &f, &dt), MOTUS_ERROR_NOT_FINITE);
    spring.stiffness = 10;
    p[1].inverse_mass = -1;
    ENSURE_EQ_INT(motus_stepper_max_stable_dt(&s.stepper, p, 2, &f, &dt), MOTUS_ERROR_INVALID_MASS);
    p[1].inverse_mass = not_a_number();
    ENSURE_EQ_INT(motus_stepper_max_stable_dt(&s.stepper, p, 2, &f, &dt), MOTUS_ERROR_NOT_FINITE);
    p[1].inverse_mass = 1;
    f.quadratic_drag = 1;
    p[1].velocity = motus_v2(infinity(), 0);
    ENSURE_EQ_INT(motus_stepper_max_stable_dt(&s.stepper, p, 2, &f, &dt), MOTUS_ERROR_NOT_FINITE);
    p[1].velocity = motus_v2(0, 0);
    ENSURE(dt == 42);
    ENSURE(same_bytes(p, before, sizeof p));
    s.stepper.method = MOTUS_METHOD_COUNT;
    ENSURE_EQ_INT(motus_stepper_max_stable_dt(&s.stepper, p, 2, &f, &dt), MOTUS_ERROR_UNSUPPORTED);
}

/* A stiff spring at a game's dt: k = 1e5 N/m on 1 kg, w = 316 rad/s, w*dt = 5.3 at 60 Hz, beyond every
   method's limit. Unsubstepped it explodes; substepped (safety 0.9) it stays on its circle, and the count
   is the least that puts each substep under 0.9 of the limit. */
TEST(substepping_keeps_a_stiff_spring_bounded) {
    const motus_real dt = (motus_real)(1.0 / 60.0), k = 100000;
    const double omega = sqrt(1e5);
    int m;
    for (m = 0; m < MOTUS_METHOD_COUNT; ++m) {
        oscillator plain, sub;
        motus_real max_dt = 0;
        double largest_plain = 1, largest_sub = 1;
        int frame, n = 0, taken = 0, failed = 0;
        if (!has_finite_limit((motus_method)m)) continue;
        oscillator_init(&plain, (motus_method)m, 0);
        oscillator_init(&sub, (motus_method)m, 0);
        plain.spring.stiffness = sub.spring.stiffness = k;
        plain.particle.inverse_mass = sub.particle.inverse_mass = 1;
        ENSURE_EQ_INT(motus_stepper_max_stable_dt(&sub.s.stepper, &sub.particle, 1, &sub.forces, &max_dt), MOTUS_OK);
        ENSURE_NEAR(max_dt, (double)motus_method_stability_limit((motus_method)m) / omega, 4 * EPS * (double)max_dt);
        ENSURE_EQ_INT(motus_substeps_for(dt, max_dt, MOTUS_R(0.9), &n), MOTUS_OK);
        ensure_minimal(dt, max_dt, MOTUS_R(0.9), n);
        for (frame = 0; frame < 600; ++frame) { /* 10 s */
            if (!failed && motus_stepper_step(&plain.s.stepper, &plain.particle, 1, &plain.forces, dt) != MOTUS_OK)
                failed = 1, largest_plain = HUGE_VAL;
            if (!failed && amplitude(&plain.particle, omega) > largest_plain)
                largest_plain = amplitude(&plain.particle, omega);
            ENSURE_EQ_INT(motus_stepper_step_substepped(&sub.s.stepper, &sub.particle, 1, &sub.forces, dt,
                                                        MOTUS_R(0.9), 100, &taken), MOTUS_OK);
            ENSURE_EQ_INT(taken, n);
            if (amplitude(&sub.particle, omega) > largest_sub) largest_sub = amplitude(&sub.particle, omega);
        }
        printf("  %-20s w*dt = %.2f: %d substeps of w*h = %.3f (limit %.4f); largest amplitude %.3g without, "
               "%.4f with\n", motus_method_name((motus_method)m), omega * (double)dt, n, omega * (double)dt / n,
               (double)motus_method_stability_limit((motus_method)m), largest_plain, largest_sub);
        ENSURE(largest_plain > 1e6);
        /* Bounded, not growing. How far a symplectic method's amplitude wanders below the limit depends
           on z: semi-implicit Euler keeps x^2 + y^2 - z*x*y (y = v/w) fixed, an ellipse on which the
           amplitude reaches 1/sqrt(1 - z/2) from (1, 0): 2.87 at z = 1.757, at most 3.16 at safety 0.9. */
        ENSURE(largest_sub < 3.2);
        if (m == MOTUS_SEMI_IMPLICIT_EULER) {
            const double z = omega * (double)dt / n;
            ENSURE_NEAR(largest_sub, 1 / sqrt(1 - z / 2), 1e-3);
        }
    }
}

TEST(substepping_refuses_what_it_cannot_keep_stable) {
    int m;
    for (m = 0; m < MOTUS_METHOD_COUNT; ++m) {
        oscillator o;
        motus_particle before;
        motus_stepper stepper_before;
        int taken = 42;
        oscillator_init(&o, (motus_method)m, 0);
        o.spring.stiffness = 100000;
        o.particle.velocity = motus_v2(1, 2);
        before = o.particle;
        stepper_before = o.s.stepper;
        /* Explicit Euler and midpoint: no count is enough; the exact stepper: no spring; the others need 3
           or more at 60 Hz and are allowed 2. */
        ENSURE_EQ_INT(motus_stepper_step_substepped(&o.s.stepper, &o.particle, 1, &o.forces, (motus_real)(1.0 / 60.0),
                                                    MOTUS_R(0.9), 2, &taken),
                      m == MOTUS_EXACT_LINEAR_DRAG ? MOTUS_ERROR_UNSUPPORTED : MOTUS_ERROR_TOO_STIFF);
        ENSURE_EQ_INT(taken, 0);
        ENSURE(same_bytes(&o.particle, &before, sizeof before));
        ENSURE(same_bytes(&o.s.stepper, &stepper_before, sizeof stepper_before));
        /* Bad input: checked before the first substep, nothing written. */
        ENSURE_EQ_INT(motus_stepper_step_substepped(&o.s.stepper, &o.particle, 1, &o.forces, 0, 1, 10, &taken),
                      MOTUS_ERROR_INVALID_TIME_STEP);
        ENSURE_EQ_INT(motus_stepper_step_substepped(&o.s.stepper, &o.particle, 1, &o.forces, 1, 1, 0, &taken),
                      MOTUS_ERROR_INVALID_ARGUMENT);
        ENSURE_EQ_INT(motus_stepper_step_substepped(&o.s.stepper, &o.particle, 1, &o.forces, 1, 2, 10, &taken),
                      m == MOTUS_EXACT_LINEAR_DRAG ? MOTUS_ERROR_UNSUPPORTED : MOTUS_ERROR_INVALID_ARGUMENT);
        ENSURE_EQ_INT(motus_stepper_step_substepped(NULL, &o.particle, 1, &o.forces, 1, 1, 10, &taken),
                      MOTUS_ERROR_NULL_POINTER);
        ENSURE_EQ_INT(motus_stepper_step_substepped(&o.s.stepper, &o.particle, -1, &o.forces, 1, 1, 10, &taken),
                      MOTUS_ERROR_INVALID_COUNT);
        o.particle.position.x = not_a_number();
        before = o.particle;
        o.spring.stiffness = 1;
        ENSURE_EQ_INT(motus_stepper_step_substepped(&o.s.stepper, &o.particle, 1, &o.forces, (motus_real)(1.0 / 60.0),
                                                    1, 10, &taken),
                      m == MOTUS_EXACT_LINEAR_DRAG ? MOTUS_ERROR_UNSUPPORTED
                      : has_finite_limit((motus_method)m) ? MOTUS_ERROR_NOT_FINITE : MOTUS_ERROR_TOO_STIFF);
        ENSURE_EQ_INT(taken, 0);
        ENSURE(same_bytes(&o.particle, &before, sizeof before));
        ENSURE(same_bytes(&o.s.stepper, &stepper_before, sizeof stepper_before));
    }
}

/* Damping and drag lower the limit; the effective frequency of STABILITY LIMITS keeps each method stable
   at 0.99 of the dt it gives, over damping ratios g/w from 0.1 to 100, with the real stepper. For
   semi-implicit Euler the formula is exact, so 1.02 of it grows. */
TEST(damping_lowers_the_limit_and_stays_safe) {
    static const double ratios[] = {0.1, 0.5, 1, 2, 10, 100}; /* g/w */
    int m, i;
    for (m = 0; m < MOTUS_METHOD_COUNT; ++m) {
        if (!has_finite_limit((motus_method)m)) continue;
        for (i = 0; i < (int)(sizeof ratios / sizeof ratios[0]); ++i) {
            /* g = c/m with the oscillator's mass */
            const motus_real c = (motus_real)(ratios[i] * OSC_OMEGA * (double)OSC_MASS);
            oscillator o;
            motus_real max_dt = 0;
            double final;
            oscillator_init(&o, (motus_method)m, c);
            ENSURE_EQ_INT(motus_stepper_max_stable_dt(&o.s.stepper, &o.particle, 1, &o.forces, &max_dt), MOTUS_OK);
            ENSURE(max_dt < motus_method_stability_limit((motus_method)m) / (motus_real)OSC_OMEGA);
            final = final_amplitude((motus_method)m, MOTUS_R(0.99) * max_dt, 40000, c);
            /* Damped and stable: it decays (overdamped, slowly: the slow mode at the rate w^2/g). Unstable,
               the fast mode would grow by orders of magnitude in 40000 steps, as the 1.02 case shows. */
            if (!(final < 1))
                printf("  %s g/w = %g: amplitude %.3g after 40000 steps of 0.99 max dt\n",
                       motus_method_name((motus_method)m), ratios[i], final);
            ENSURE(final < 1);
            if (m == MOTUS_SEMI_IMPLICIT_EULER)
                ENSURE(final_amplitude((motus_method)m, MOTUS_R(1.02) * max_dt, 40000, c) > 1000);
        }
    }
}

/* =================================================================================================
   dt from 1e-7 s to 1 s
   =================================================================================================
   1000 steps of each dt, from rest at the origin (so no digits go to a large position; far from the origin
   is another test's business). Free fall under g = 9.81: semi-implicit Euler lands ahead of the exact
   -g*t^2/2 by g*t*h/2 (see motus_particle_step), explicit Euler behind by as much, every other method on it
   (second order and up integrate a constant acceleration exactly); what is left is rounding: n*k*eps of
   |y|. The oscillator (w = 1 rad/s, from x = 1): the error stays within the method's promise C*t*h^p (its
   order p) plus rounding, and the state finite, except where explicit Euler and midpoint grow, as they
   must, by their growth factor (in float, 1000 steps at h = 1 overflow: reported, state kept). */
static const double DTS[] = {1e-7, 1e-6, 1e-5, 1e-4, 1e-3, 1e-2, 1e-1, 1};

TEST(dt_extremes_free_fall) {
    const int steps = 1000;
    int m, i, k;
    for (m = 0; m < MOTUS_METHOD_COUNT; ++m) {
        double worst = 0;
        for (i = 0; i < (int)(sizeof DTS / sizeof DTS[0]); ++i) {
            const motus_real h = (motus_real)DTS[i];
            const double t = steps * (double)h, g = (double)MOTUS_R(9.81);
            double expected, error;
            test_stepper s;
            motus_particle p;
            motus_forces f;
            memset(&f, 0, sizeof f);
            f.gravity = motus_v2(0, MOTUS_R(-9.81));
            stepper_init(&s, (motus_method)m);
            ENSURE_EQ_INT(motus_particle_init(&p, motus_v2(0, 0), 1), MOTUS_OK);
            for (k = 0; k < steps; ++k) ENSURE_EQ_INT(motus_stepper_step(&s.stepper, &p, 1, &f, h), MOTUS_OK);
            expected = -g * t * t / 2;
            if (m == MOTUS_SEMI_IMPLICIT_EULER) expected -= g * t * (double)h / 2;
            if (m == MOTUS_EXPLICIT_EULER) expected += g * t * (double)h / 2;
            error = fabs((double)p.position.y - expected) / fabs(expected);
            if (error / (steps * EPS) > worst) worst = error / (steps * EPS);
            ENSURE(p.position.x == 0);
            ENSURE_NEAR(p.position.y, expected, 4 * steps * EPS * fabs(expected));
            ENSURE_NEAR(p.velocity.y, -g * t, 4 * steps * EPS * g * t);
        }
        printf("  %-20s free fall, dt 1e-7..1 s: relative error at most %.2f * n * eps\n",
               motus_method_name((motus_method)m), worst);
    }
}

TEST(dt_extremes_oscillator) {
    const int steps = 1000;
    int m, i, k;
    for (m = 0; m < MOTUS_EXACT_LINEAR_DRAG; ++m) {
        const int order = motus_method_order((motus_method)m);
        const int grows_always = motus_method_stability_limit((motus_method)m) == 0;
        printf("  %-20s", motus_method_name((motus_method)m));
        for (i = 0; i < (int)(sizeof DTS / sizeof DTS[0]); ++i) {
            const motus_real h = (motus_real)DTS[i];
            const double t = steps * (double)h;
            double worst = 0, promise = t * pow((double)h, order), rounding = 16 * steps * EPS;
            motus_result result = MOTUS_OK;
            oscillator o;
            oscillator_init(&o, (motus_method)m, 0);
            o.particle.inverse_mass = 1;
            o.spring.stiffness = 1; /* w = 1 */
            for (k = 1; k <= steps && result == MOTUS_OK; ++k) {
                motus_particle before = o.particle;
                result = motus_stepper_step(&o.s.stepper, &o.particle, 1, &o.forces, h);
                if (result != MOTUS_OK) {
                    /* Only a method that grows may overflow, and then the state is the one before. */
                    ENSURE(grows_always && EPS > 1e-10);
                    ENSURE_EQ_INT(result, MOTUS_ERROR_OVERFLOW);
                    ENSURE(same_bytes(&before, &o.particle, sizeof before));
                } else {
                    const double tk = k * (double)h;
                    const double ex = (double)o.particle.position.x - cos(tk), ev = (double)o.particle.velocity.x + sin(tk);
                    const double e = sqrt(ex * ex + ev * ev);
                    if (e > worst) worst = e;
                }
            }
            ENSURE(motus_particle_check(&o.particle) == MOTUS_OK);
            printf(" %8.1e", worst);
            if (grows_always && result != MOTUS_OK) continue;
            if (grows_always && promise > 0.1) {
                /* Past the asymptotic range: the amplitude is the growth factor to the n-th power. */
                const double z = (double)h, g = m == MOTUS_EXPLICIT_EULER ? sqrt(1 + z * z) : sqrt(1 + z * z * z * z / 4);
                ENSURE_NEAR(log(amplitude(&o.particle, 1)) / (steps * log(g)), 1, 1e-3);
            } else if (promise > 1) {
                ENSURE(amplitude(&o.particle, 1) < 3); /* stable, bounded (RK4 and Forest-Ruth decay or wobble) */
            } else {
                ENSURE(worst <= promise + rounding);
            }
        }
        printf("  (error, dt = 1e-7 .. 1)\n");
    }
}

/* =================================================================================================
   10^7 steps
   =================================================================================================
   The oscillator (w = 1 rad/s, from x = 1) at h = 0.1: 10^7 steps, 10^6 s, 159155 periods. The relative
   energy error |E - E0|/E0, E = (x^2 + v^2)/2, over the first and the last 10% of the run:
   - semi-implicit Euler keeps x^2 + v^2 - h*x*v fixed, on which E/E0 ranges over 1/(1 +- h/2): the error
     stays within (h/2)/(1 - h/2) = 5.263% forever (measured: 5.263% in the first and the last 10%);
   - velocity Verlet keeps x^2 + v^2/(1 - h^2/4) fixed: E/E0 in [1 - h^2/4, 1], error within 0.25%;
   - in float, rounding adds a little on top (measured: 1.2e-5 of E0 for velocity Verlet), no drift;
   - explicit Euler multiplies E by 1 + h^2 per step: 100 times larger within 463 steps, and in float it
     overflows (reported, state kept) long before the end.
   About 0.6 s per precision at -O2 (the two 10^7-step runs). */
static void long_run(motus_method method, double *first, double *last, double *final_energy) {
    const int steps = 10000000, window = steps / 10;
    oscillator o;
    int i;
    *first = *last = 0;
    oscillator_init(&o, method, 0);
    o.particle.inverse_mass = 1;
    o.spring.stiffness = 1;
    for (i = 0; i < steps; ++i) {
        double x, v, e;
        if (motus_stepper_step(&o.s.stepper, &o.particle, 1, &o.forces, MOTUS_R(0.1)) != MOTUS_OK) {
            ENSURE(!"step failed");
            break;
        }
        if (i >= window && i < steps - window) continue;
        x = (double)o.particle.position.x, v = (double)o.particle.velocity.x;
        e = fabs((x * x + v * v) - 1);
        if (i < window && e > *first) *first = e;
        if (i >= steps - window && e > *last) *last = e;
    }
    *final_energy = amplitude(&o.particle, 1);
    *final_energy *= *final_energy;
    printf("  %-20s 10^7 steps of w*h = 0.1: energy error first 10%% %.4g, last 10%% %.4g, final E/E0 %.6f\n",
           motus_method_name(method), *first, *last, *final_energy);
}

TEST(ten_million_steps) {
    double first, last, final_energy;
    long_run(MOTUS_SEMI_IMPLICIT_EULER, &first, &last, &final_energy);
    /* The wobble: within (h/2)/(1 - h/2) relative of E0 on the invariant ellipse. */
    ENSURE(first <= 0.05 / (1 - 0.05) + 1e-4);
    ENSURE(last <= 0.05 / (1 - 0.05) + 1e-4);
    ENSURE(first >= 0.05 / (1 - 0.05) - 1e-4); /* it does reach the edge of its ellipse */
    ENSURE(last <= first + 1e-4);
    long_run(MOTUS_VELOCITY_VERLET, &first, &last, &final_energy);
    ENSURE(first <= 0.01 / 4 + 1e-4);
    ENSURE(last <= 0.01 / 4 + 1e-4);
    ENSURE(last <= first + 1e-4);
    ENSURE_NEAR(final_energy, 1, 0.01 / 4 + 1e-4);
    {
        /* Explicit Euler: E grows by exactly 1 + h^2 per step (to rounding). */
        oscillator o;
        int i;
        motus_result result = MOTUS_OK;
        oscillator_init(&o, MOTUS_EXPLICIT_EULER, 0);
        o.particle.inverse_mass = 1;
        o.spring.stiffness = 1;
        for (i = 0; i < 463; ++i) ENSURE_EQ_INT(motus_stepper_step(&o.s.stepper, &o.particle, 1, &o.forces, MOTUS_R(0.1)), MOTUS_OK);
        ENSURE_NEAR(log(amplitude(&o.particle, 1)) * 2 / (463 * log(1 + (double)MOTUS_R(0.1) * (double)MOTUS_R(0.1))), 1, 1e-4);
        ENSURE(amplitude(&o.particle, 1) * amplitude(&o.particle, 1) > 100);
        for (i = 463; i < 10000000 && result == MOTUS_OK; ++i) {
            motus_particle before = o.particle;
            result = motus_stepper_step(&o.s.stepper, &o.particle, 1, &o.forces, MOTUS_R(0.1));
            if (result != MOTUS_OK) ENSURE(same_bytes(&before, &o.particle, sizeof before));
        }
        /* In float it stops at |x| ~ 2e19, where the spring's |d|^2 overflows, not x itself. */
        printf("  %-20s stopped at step %d: %s; |x| = %.3g, |v| = %.3g\n", "explicit_euler", i,
               motus_result_string(result), fabs((double)o.particle.position.x), fabs((double)o.particle.velocity.x));
        ENSURE_EQ_INT(result, MOTUS_ERROR_OVERFLOW);
        ENSURE(motus_particle_check(&o.particle) == MOTUS_OK);
    }
}

/* =================================================================================================
   Masses from 1e-20 to 1e20, and inverse mass 0
   ================================================================================================= */
TEST(masses_from_1e_minus_20_to_1e20) {
    /* Every mass in range is accepted, its inverse is the correctly rounded 1/m, and a force of m newtons
       gives 1 m/s^2: v = h after one step, to a few eps. */
    static const double masses[] = {1e-20, 1e-15, 1e-10, 1e-5, 1, 1e5, 1e10, 1e15, 1e20};
    int i;
    for (i = 0; i < (int)(sizeof masses / sizeof masses[0]); ++i) {
        const motus_real m = (motus_real)masses[i], h = MOTUS_R(0.125);
        motus_particle p;
        memset(&p, 0, sizeof p);
        ENSURE_EQ_INT(motus_particle_init(&p, motus_v2(1, 2), m), MOTUS_OK);
        ENSURE(p.inverse_mass == MOTUS_R(1.0) / m);
        ENSURE(p.inverse_mass >= (motus_real)REAL_MIN); /* normal: all its digits */
        ENSURE_NEAR(motus_particle_mass(&p) / m, 1, EPS);
        ENSURE_EQ_INT(motus_particle_add_force(&p, motus_v2(m, -m)), MOTUS_OK);
        ENSURE_EQ_INT(motus_particle_step(&p, h), MOTUS_OK);
        ENSURE_NEAR(p.velocity.x, h, 2 * EPS * (double)h);
        ENSURE_NEAR(p.velocity.y, -h, 2 * EPS * (double)h);
    }
}

TEST(masses_at_the_edges_of_the_format) {
    /* The limits are the format's, not 1e+-20: a mass whose inverse overflows is refused (INVALID_MASS);
       a mass so large that its inverse is subnormal is accepted, with fewer digits in the inverse.
       Float: 1/1e-38 = 1e38 fits, 1/1e-39 (a subnormal mass) does not; 1/3e38 = 3.3e-39 is subnormal
       (21 bits instead of 24). Double: the same at 1e-308 / 1e-309 and 1e308. */
#ifdef MOTUS_DOUBLE
    const motus_real tiny_ok = 1e-308, tiny_bad = 1e-309, huge = 1e308;
#else
    const motus_real tiny_ok = 1e-38f, tiny_bad = 1e-39f, huge = 3e38f;
#endif
    motus_particle p, before;
    double roundtrip;
    memset(&p, 0, sizeof p);
    ENSURE_EQ_INT(motus_particle_init(&p, motus_v2(0, 0), tiny_ok), MOTUS_OK);
    ENSURE(motus_real_is_finite(p.inverse_mass));
    before = p;
    ENSURE_EQ_INT(motus_particle_init(&p, motus_v2(0, 0), tiny_bad), MOTUS_ERROR_INVALID_MASS);
    ENSURE(same_bytes(&p, &before, sizeof p));
    ENSURE_EQ_INT(motus_particle_init(&p, motus_v2(0, 0), REAL_MAX), MOTUS_OK);
    ENSURE_EQ_INT(motus_particle_init(&p, motus_v2(0, 0), huge), MOTUS_OK);
    ENSURE(p.inverse_mass > 0 && p.inverse_mass < (motus_real)REAL_MIN); /* subnormal */
    roundtrip = fabs((double)motus_particle_mass(&p) / (double)huge - 1);
    printf("  mass %g: inverse %g is subnormal; 1/(1/m) is off by %.2g relative (eps %.2g)\n", (double)huge,
           (double)p.inverse_mass, roundtrip, EPS);
    ENSURE(roundtrip < 1e-5);
}

TEST(spring_between_masses_1e_minus_20_and_1e20) {
    /* A spring of k = 1e-20 N/m from a 1e-20 kg particle to a 1e20 kg one: w^2 = k*(1e20 + 1e-20) = 1, so
       the light one swings with period 2*pi and the heavy one stays put (its acceleration is 1e-40 m/s^2,
       below float's normal range: flushed or subnormal, and lost against its position either way). The
       stability bound sees the same w: max dt = 2/w for semi-implicit Euler. */
    test_stepper s;
    motus_particle p[2];
    motus_spring spring;
    motus_forces f;
    motus_real max_dt = 0;
    const motus_real h = MOTUS_R(0.001);
    double largest_error = 0;
    int k;
    memset(&f, 0, sizeof f);
    memset(&spring, 0, sizeof spring);
    stepper_init(&s, MOTUS_VELOCITY_VERLET);
    ENSURE_EQ_INT(motus_particle_init(&p[0], motus_v2(1, 0), (motus_real)1e-20), MOTUS_OK);
    ENSURE_EQ_INT(motus_particle_init(&p[1], motus_v2(0, 0), (motus_real)1e20), MOTUS_OK);
    spring.a = 0, spring.b = 1, spring.stiffness = (motus_real)1e-20;
    f.springs = &spring;
    f.spring_count = 1;
    ENSURE_EQ_INT(motus_stepper_max_stable_dt(&s.stepper, p, 2, &f, &max_dt), MOTUS_OK);
    ENSURE_NEAR(max_dt, 2, 8 * EPS);
    for (k = 1; k <= 6283; ++k) { /* one period */
        double e;
        ENSURE_EQ_INT(motus_stepper_step(&s.stepper, p, 2, &f, h), MOTUS_OK);
        e = fabs((double)p[0].position.x - cos(k * (double)h));
        if (e > largest_error) largest_error = e;
    }
    printf("  light end: largest error %.3g over a period; heavy end moved %.3g m\n", largest_error,
           (double)p[1].position.x);
    ENSURE(largest_error < 1e-5 + 1e4 * EPS); /* h^2/24 per radian of phase, plus rounding */
    ENSURE(fabs((double)p[1].position.x) < 1e-30);
    ENSURE(p[1].position.y == 0 && p[1].velocity.y == 0);
}

TEST(immovable_under_gravity_springs_and_drag) {
    /* Gravity is an acceleration, but an immovable particle gets none ("Forces: one model"): it stays where
       it is, bit for bit, in every method, with gravity, both drags, a stiff damped spring to a free
       particle, an attractor and an accumulated force on it. The spring pulls both ways: the free end
       swings about the immovable one. The exact stepper takes gravity and linear drag only. */
    int m, k;
    for (m = 0; m < MOTUS_METHOD_COUNT; ++m) {
        test_stepper s;
        motus_particle p[2], before;
        motus_spring spring;
        motus_forces f;
        motus_vec2 spring_force;
        memset(&f, 0, sizeof f);
        memset(&spring, 0, sizeof spring);
        stepper_init(&s, (motus_method)m);
        ENSURE_EQ_INT(motus_particle_init_immovable(&p[0], motus_v2(3, 4)), MOTUS_OK);
        ENSURE_EQ_INT(motus_particle_init(&p[1], motus_v2(5, 4), 2), MOTUS_OK);
        ENSURE_EQ_INT(motus_particle_add_force(&p[0], motus_v2(1e6f, -1e6f)), MOTUS_OK);
        f.gravity = motus_v2(0, MOTUS_R(-9.81));
        f.linear_drag = MOTUS_R(0.5);
        if (m != MOTUS_EXACT_LINEAR_DRAG) {
            f.quadratic_drag = MOTUS_R(0.1);
            f.attractor_strength = 10;
            f.attractor_position = motus_v2(-10, -10);
            spring.a = 0, spring.b = 1, spring.stiffness = 50, spring.damping = 1, spring.rest_length = 1;
            f.springs = &spring;
            f.spring_count = 1;
        }
        before = p[0];
        for (k = 0; k < 600; ++k)
            ENSURE_EQ_INT(motus_stepper_step(&s.stepper, p, 2, &f, (motus_real)(1.0 / 600.0)), MOTUS_OK);
        ENSURE(same_bytes(&p[0], &before, sizeof before));
        /* The free end fell and was held: within a few metres of the fixed one, below it. */
        spring_force = motus_vec2_sub(p[1].position, p[0].position);
        if (m != MOTUS_EXACT_LINEAR_DRAG) ENSURE(motus_vec2_length(spring_force) < 3 && p[1].position.y < 4);
        else ENSURE(p[1].position.y < 4 - 1);
        {
            /* motus_particle_step too: the force accumulates, the particle stays. */
            motus_particle q = before;
            ENSURE_EQ_INT(motus_particle_step(&q, MOTUS_R(0.5)), MOTUS_OK);
            ENSURE(same_bytes(&q, &before, sizeof q));
        }
    }
}

/* A chain of 6 particles (1 kg) on zero-length springs (k = 1e4 N/m) hanging from an immovable one: its
   highest mode has w^2 = 4k*sin^2(11*pi/26) = 3.88k (fixed-free chain of 6), above the 2k of any one
   spring. A step sized for one spring (0.95*limit/sqrt(2k)) blows the chain up; the Gershgorin bound
   (w^2 <= 4k) sizes it right, and substepping at 60 Hz (w*dt = 3.3) keeps it bounded. */
TEST(chain_needs_the_whole_bound) {
    int m;
    for (m = 0; m < MOTUS_METHOD_COUNT; ++m) {
        test_stepper s;
        motus_particle start[7], p[7];
        motus_spring springs[6];
        motus_forces f;
        motus_real max_dt = 0, naive;
        double largest = 0;
        int i, k, taken = 0;
        if (!has_finite_limit((motus_method)m)) continue;
        memset(&f, 0, sizeof f);
        memset(springs, 0, sizeof springs);
        ENSURE_EQ_INT(motus_particle_init_immovable(&start[0], motus_v2(0, 0)), MOTUS_OK);
        for (i = 1; i < 7; ++i) {
            /* Displaced in both axes with a sawtooth, so the highest mode is in the start. */
            ENSURE_EQ_INT(motus_particle_init(&start[i], motus_v2((motus_real)(i % 2), (motus_real)(-i)), 1), MOTUS_OK);
            springs[i - 1].a = i - 1, springs[i - 1].b = i, springs[i - 1].stiffness = 10000;
        }
        f.springs = springs;
        f.spring_count = 6;
        stepper_init(&s, (motus_method)m);
        ENSURE_EQ_INT(motus_stepper_max_stable_dt(&s.stepper, start, 7, &f, &max_dt), MOTUS_OK);
        ENSURE_NEAR(max_dt, (double)motus_method_stability_limit((motus_method)m) / 200, 4 * EPS);
        naive = MOTUS_R(0.95) * motus_method_stability_limit((motus_method)m) / MOTUS_SQRT(20000);
        memcpy(p, start, sizeof p);
        for (k = 0; k < 2000 && largest < 1e6; ++k) {
            if (motus_stepper_step(&s.stepper, p, 7, &f, naive) != MOTUS_OK) largest = HUGE_VAL;
            for (i = 1; i < 7; ++i) largest = fmax(largest, (double)motus_vec2_length(p[i].position));
        }
        ENSURE(largest >= 1e6); /* blown up */
        stepper_init(&s, (motus_method)m);
        memcpy(p, start, sizeof p);
        largest = 0;
        for (k = 0; k < 2000; ++k) {
            ENSURE_EQ_INT(motus_stepper_step(&s.stepper, p, 7, &f, MOTUS_R(0.95) * max_dt), MOTUS_OK);
            for (i = 1; i < 7; ++i) largest = fmax(largest, (double)motus_vec2_length(p[i].position));
        }
        ENSURE(largest < 100);
        stepper_init(&s, (motus_method)m);
        memcpy(p, start, sizeof p);
        largest = 0;
        for (k = 0; k < 600; ++k) {
            ENSURE_EQ_INT(motus_stepper_step_substepped(&s.stepper, p, 7, &f, (motus_real)(1.0 / 60.0), MOTUS_R(0.9),
                                                        16, &taken), MOTUS_OK);
            for (i = 1; i < 7; ++i) largest = fmax(largest, (double)motus_vec2_length(p[i].position));
        }
        printf("  %-20s chain: one-spring step blows up, bound %.4f s holds; at 60 Hz %d substeps, largest |x| %.2f\n",
               motus_method_name((motus_method)m), (double)max_dt, taken, largest);
        ENSURE(largest < 100);
    }
}

static const motus_test_case TESTS[] = {
    TEST_CASE(limits_table),
    TEST_CASE(bisect_thresholds),
    TEST_CASE(explicit_euler_grows_at_every_dt),
    TEST_CASE(midpoint_grows_at_every_dt),
    TEST_CASE(exact_stepper_takes_no_spring),
    TEST_CASE(max_stable_dt_is_limit_over_omega),
    TEST_CASE(max_stable_dt_rejects_bad_input),
    TEST_CASE(substeps_for_is_minimal),
    TEST_CASE(substeps_for_rejects_bad_input),
    TEST_CASE(stepper_max_stable_dt_bounds_the_springs),
    TEST_CASE(stepper_max_stable_dt_rejects_bad_input),
    TEST_CASE(substepping_keeps_a_stiff_spring_bounded),
    TEST_CASE(substepping_refuses_what_it_cannot_keep_stable),
    TEST_CASE(damping_lowers_the_limit_and_stays_safe),
    TEST_CASE(chain_needs_the_whole_bound),
    TEST_CASE(dt_extremes_free_fall),
    TEST_CASE(dt_extremes_oscillator),
    TEST_CASE(ten_million_steps),
    TEST_CASE(masses_from_1e_minus_20_to_1e20),
    TEST_CASE(masses_at_the_edges_of_the_format),
    TEST_CASE(spring_between_masses_1e_minus_20_and_1e20),
    TEST_CASE(immovable_under_gravity_springs_and_drag),
};

int main(int argc, char **argv) { return motus_test_main(argc, argv, TESTS, TEST_COUNT(TESTS)); }
