/* Numeric tests: the integrators against the closed forms of bench/problems.h. No timing, only accuracy.
   Built in float and in double (MOTUS_DOUBLE), like unit.c. What each build can show:
   - Convergence orders are measured from the error at h, h/2, h/4, h/8. In double every method and problem
     is checked over three halvings in its asymptotic range. In float, rounding (about 1e-7 relative per
     operation, growing with the number of steps) swamps errors below ~1e-5, so the float build measures
     two halvings at coarser steps, and the 4th-order methods only on the oscillators, where their error
     at 25..100 steps per 5 s is still 1e-3..1e-6; their other problems run in double only.
   - Oracles, reversibility and the exact stepper have bounds written in units of the build's epsilon, so
     both builds run the same assertions.
   - Energy: Forest-Ruth's energy error (1e-5) is below float's rounding drift over 1e5 steps (~1e-4), so
     in float it gets a bound only, not the no-growth comparison. */
#include "motus.h"
#include "problems.h"
#include "support/motus_test.h"

#include <float.h>

#define EPS ((double)MOTUS_REAL_EPSILON)

/* A stepper for one particle with its scratch: 8 arrays is more than any method takes. */
typedef struct test_stepper {
    motus_stepper stepper;
    motus_vec2 scratch[8];
} test_stepper;

static void stepper_init(test_stepper *s, motus_method method, unsigned flags) {
    motus_stepper_desc desc;
    memset(&desc, 0, sizeof desc);
    desc.capacity = 1;
    desc.method = method;
    desc.scratch = s->scratch;
    desc.scratch_bytes = sizeof s->scratch;
    desc.flags = flags;
    ENSURE(motus_stepper_scratch_size(method, 1) <= sizeof s->scratch);
    ENSURE_EQ_INT(motus_stepper_init(&s->stepper, &desc), MOTUS_OK);
}

static double hypot4(double a, double b, double c, double d) { return sqrt(a * a + b * b + c * c + d * d); }

/* Euclidean distance in (x, y, vx, vy) between a particle and a closed-form state. */
static double state_error(const motus_particle *p, problem_state e) {
    problem_state s = problem_state_of(p);
    return hypot4(s.x - e.x, s.y - e.y, s.vx - e.vx, s.vy - e.vy);
}

/* =================================================================================================
   Convergence order
   =================================================================================================
   The error of a run is the largest state error over all its steps, not the error at the end: the Kepler
   problems last exactly one period, and at t = period the first-order term of semi-implicit Euler's
   error vanishes (measured: order 2.0 from the error at the end, 1.0 from the largest over the run). */
static double max_error_over_run(motus_method method, const problem *p, int steps) {
    test_stepper s;
    motus_particle particle = problem_particle(p);
    const motus_real h = (motus_real)(p->duration / steps);
    double worst = 0;
    int i;
    stepper_init(&s, method, 0);
    for (i = 1; i <= steps; ++i) {
        double error;
        if (motus_stepper_step(&s.stepper, &particle, 1, &p->forces, h) != MOTUS_OK) return HUGE_VAL;
        /* Compared at i*h with h as rounded to motus_real, so the step size itself is no error. */
        error = state_error(&particle, p->exact((double)i * (double)h));
        if (error > worst) worst = error;
    }
    return worst;
}

/* Measures log2(err(h)/err(h/2)) for `halvings` halvings from n0 steps and checks each within 0.15 of
   `expected`. Prints the measured orders (ctest -V shows them). */
static void ensure_order_from(motus_method method, int which, int n0, int halvings, double expected) {
    problem p;
    double previous;
    int k, n = n0;
    ENSURE(problem_get(which, &p));
    previous = max_error_over_run(method, &p, n);
    printf("  order %-20s %-20s n=%5d..%-6d", motus_method_name(method), p.name, n0, n0 << halvings);
    for (k = 0; k < halvings; ++k) {
        double error, order;
        n *= 2;
        error = max_error_over_run(method, &p, n);
        order = log2(previous / error);
        printf(" %.3f", order);
        if (!motus_test_near(order, expected, 0.15, "measured order", __FILE__, __LINE__))
            fprintf(stderr, "  %s on %s, %d -> %d steps: errors %.3g -> %.3g\n", motus_method_name(method), p.name,
                    n / 2, n, previous, error);
        previous = error;
    }
    printf(" (error %.2g)\n", previous);
}

/* n0: the coarsest run in double; float_n0: the same in float, 0 for "double only" (see the top). */
static void ensure_order_is(motus_method method, int which, int n0, int float_n0, double expected) {
#ifdef MOTUS_DOUBLE
    (void)float_n0;
    ensure_order_from(method, which, n0, 3, expected);
#else
    (void)n0;
    if (float_n0 > 0) ensure_order_from(method, which, float_n0, 2, expected);
#endif
}

/* The order motus_method_order reports, which is what the header tables. */
static void ensure_order(motus_method method, int which, int n0, int float_n0) {
    ensure_order_is(method, which, n0, float_n0, motus_method_order(method));
}

TEST(order_semi_implicit_euler) {
    ensure_order(MOTUS_SEMI_IMPLICIT_EULER, PROBLEM_HARMONIC_OSCILLATOR, 100, 100);
    ensure_order(MOTUS_SEMI_IMPLICIT_EULER, PROBLEM_KEPLER_CIRCULAR, 400, 400);
    ensure_order(MOTUS_SEMI_IMPLICIT_EULER, PROBLEM_KEPLER_ECCENTRIC, 800, 800);
    ensure_order(MOTUS_SEMI_IMPLICIT_EULER, PROBLEM_DAMPED_OSCILLATOR, 100, 100);
    ensure_order(MOTUS_SEMI_IMPLICIT_EULER, PROBLEM_GRAVITY_LINEAR_DRAG, 100, 100);
}

TEST(order_explicit_euler) {
    /* Its error constant on an orbit is large: the asymptotic range starts at thousands of steps. */
    ensure_order(MOTUS_EXPLICIT_EULER, PROBLEM_HARMONIC_OSCILLATOR, 400, 400);
    ensure_order(MOTUS_EXPLICIT_EULER, PROBLEM_KEPLER_CIRCULAR, 3200, 3200);
    ensure_order(MOTUS_EXPLICIT_EULER, PROBLEM_KEPLER_ECCENTRIC, 6400, 12800);
    ensure_order(MOTUS_EXPLICIT_EULER, PROBLEM_DAMPED_OSCILLATOR, 400, 400);
    ensure_order(MOTUS_EXPLICIT_EULER, PROBLEM_GRAVITY_LINEAR_DRAG, 100, 100);
}

TEST(order_position_verlet) {
    /* In float, Stormer's x_{n+1} = 2x_n - x_{n-1} + a h^2 accumulates rounding like N^2 (an error in
       x_n becomes a velocity error (x_n - x_{n-1})/h that persists), so float stays at coarse steps. */
    ensure_order(MOTUS_POSITION_VERLET, PROBLEM_HARMONIC_OSCILLATOR, 100, 50);
    ensure_order(MOTUS_POSITION_VERLET, PROBLEM_KEPLER_CIRCULAR, 100, 25);
    ensure_order(MOTUS_POSITION_VERLET, PROBLEM_KEPLER_ECCENTRIC, 200, 100);
}

TEST(order_position_verlet_drag_is_first_order) {
    /* Documented: forces that depend on velocity see (x_n - x_{n-1})/h, a first-order velocity. */
    ensure_order_is(MOTUS_POSITION_VERLET, PROBLEM_DAMPED_OSCILLATOR, 200, 50, 1);
    ensure_order_is(MOTUS_POSITION_VERLET, PROBLEM_GRAVITY_LINEAR_DRAG, 100, 25, 1);
}

TEST(order_velocity_verlet) {
    ensure_order(MOTUS_VELOCITY_VERLET, PROBLEM_HARMONIC_OSCILLATOR, 100, 100);
    ensure_order(MOTUS_VELOCITY_VERLET, PROBLEM_KEPLER_CIRCULAR, 100, 100);
    ensure_order(MOTUS_VELOCITY_VERLET, PROBLEM_KEPLER_ECCENTRIC, 200, 200);
    ensure_order(MOTUS_VELOCITY_VERLET, PROBLEM_DAMPED_OSCILLATOR, 100, 100);
    ensure_order(MOTUS_VELOCITY_VERLET, PROBLEM_GRAVITY_LINEAR_DRAG, 100, 25);
}

TEST(order_leapfrog) {
    ensure_order(MOTUS_LEAPFROG, PROBLEM_HARMONIC_OSCILLATOR, 100, 100);
    ensure_order(MOTUS_LEAPFROG, PROBLEM_KEPLER_CIRCULAR, 100, 100);
    ensure_order(MOTUS_LEAPFROG, PROBLEM_KEPLER_ECCENTRIC, 200, 200);
    ensure_order(MOTUS_LEAPFROG, PROBLEM_DAMPED_OSCILLATOR, 100, 100);
    ensure_order(MOTUS_LEAPFROG, PROBLEM_GRAVITY_LINEAR_DRAG, 100, 25);
}

TEST(order_midpoint) {
    ensure_order(MOTUS_MIDPOINT, PROBLEM_HARMONIC_OSCILLATOR, 100, 100);
    ensure_order(MOTUS_MIDPOINT, PROBLEM_KEPLER_CIRCULAR, 100, 50);
    ensure_order(MOTUS_MIDPOINT, PROBLEM_KEPLER_ECCENTRIC, 800, 400);
    ensure_order(MOTUS_MIDPOINT, PROBLEM_DAMPED_OSCILLATOR, 100, 100);
    ensure_order(MOTUS_MIDPOINT, PROBLEM_GRAVITY_LINEAR_DRAG, 100, 25);
}

TEST(order_rk4) {
    ensure_order(MOTUS_RK4, PROBLEM_HARMONIC_OSCILLATOR, 25, 25);
    ensure_order(MOTUS_RK4, PROBLEM_KEPLER_CIRCULAR, 400, 0);
    ensure_order(MOTUS_RK4, PROBLEM_KEPLER_ECCENTRIC, 800, 0);
    ensure_order(MOTUS_RK4, PROBLEM_DAMPED_OSCILLATOR, 25, 25);
    ensure_order(MOTUS_RK4, PROBLEM_GRAVITY_LINEAR_DRAG, 25, 0);
}

TEST(order_forest_ruth) {
    ensure_order(MOTUS_FOREST_RUTH, PROBLEM_HARMONIC_OSCILLATOR, 25, 25);
    ensure_order(MOTUS_FOREST_RUTH, PROBLEM_KEPLER_CIRCULAR, 100, 0);
    ensure_order(MOTUS_FOREST_RUTH, PROBLEM_KEPLER_ECCENTRIC, 200, 0);
}

TEST(order_forest_ruth_drag_is_first_order) {
    /* Documented: a kick with a velocity-dependent force is an explicit Euler step in v. */
    ensure_order_is(MOTUS_FOREST_RUTH, PROBLEM_DAMPED_OSCILLATOR, 100, 100, 1);
    ensure_order_is(MOTUS_FOREST_RUTH, PROBLEM_GRAVITY_LINEAR_DRAG, 100, 100, 1);
}

/* =================================================================================================
   Discrete oracles under constant acceleration
   =================================================================================================
   With a constant acceleration a, after steps of h the methods land exactly (in exact arithmetic) on
       explicit Euler        x0 + v0 t + a t (t - h)/2
       semi-implicit Euler   x0 + v0 t + a t (t + h)/2
       every other method    x0 + v0 t + a t^2/2       (order >= 2: exact on a quadratic in t)
   and all of them on v = v0 + a t. Two kinds of data:
   - Dyadic (h = 1/64 or 1/32, 1/128; a, v0, x0 small multiples of powers of two): every intermediate value
     fits in the mantissa, so a method whose coefficients are dyadic must match the oracle bit for bit.
     That is all of them but RK4 (h/6) and Forest-Ruth (irrational theta), which get the bound below.
   - Game-like (h = 1/60, g = -9.81, positions of a few hundred): rounding only. A step does at most
     k = 8 roundings of relative size eps/2 on values no larger than the running |x| and |v|*h; an error
     made in v at step i reaches x through the later steps as (n - i)*h*delta_v. Summed over n steps:
         |x_n - oracle| <= n*k*(eps/2)*(max|x| + max|v|*t),   |v_n - oracle| <= n*k*(eps/2)*max|v|.
     The oracle is evaluated in double with the h and the a that the method actually used (rounded to
     motus_real), so only the steps' own rounding is measured. */
typedef struct oracle_setup {
    const char *name;
    motus_vec2 x0, v0, gravity, force; /* force: accumulated on a particle of mass 2, added to gravity */
    motus_real h[3];                   /* step sizes, used in turn (all equal for a fixed step) */
    int steps;
    int dyadic; /* every value exactly representable: expect bit-exact results where the method allows */
} oracle_setup;

static int method_has_dyadic_coefficients(motus_method method) {
    return method != MOTUS_RK4 && method != MOTUS_FOREST_RUTH;
}

static double oracle_position(motus_method method, double x0, double v0, double a, double h, double t) {
    double offset = method == MOTUS_EXPLICIT_EULER ? -h : method == MOTUS_SEMI_IMPLICIT_EULER ? h : 0;
    return x0 + v0 * t + 0.5 * a * t * (t + offset);
}

/* Runs the setup with `method`; checks every step against the oracle (bit for bit when the data is dyadic
   and the method's coefficients are) and returns the largest error as a fraction of the bound. */
static double ensure_oracle(motus_method method, const oracle_setup *o) {
    const int bit_exact = o->dyadic && method_has_dyadic_coefficients(method);
    test_stepper s;
    motus_forces forces;
    motus_particle particle;
    motus_vec2 a;
    double t = 0, max_x = 0, max_v = 0, worst = 0;
    int i, mismatches = 0;
    memset(&forces, 0, sizeof forces);
    memset(&particle, 0, sizeof particle);
    forces.gravity = o->gravity;
    ENSURE_EQ_INT(motus_particle_init(&particle, o->x0, 2), MOTUS_OK);
    particle.velocity = o->v0;
    particle.force = o->force;
    /* The acceleration as the stepper forms it, F*(1/m) + g: rounded once, the same at every stage. */
    a = motus_vec2_add(motus_vec2_scale(o->force, particle.inverse_mass), o->gravity);
    stepper_init(&s, method, 0);
    for (i = 1; i <= o->steps; ++i) {
        const motus_real h = o->h[(i - 1) % 3];
        double x, y, vx, vy, error_x, error_v, bound_x, bound_v;
        if (motus_stepper_step(&s.stepper, &particle, 1, &forces, h) != MOTUS_OK) {
            ENSURE(!"step failed");
            return HUGE_VAL;
        }
        t += (double)h; /* exact in double: a sum of a few hundred values of motus_real */
        x = oracle_position(method, o->x0.x, o->v0.x, a.x, (double)h, t);
        y = oracle_position(method, o->x0.y, o->v0.y, a.y, (double)h, t);
        vx = o->v0.x + a.x * t;
        vy = o->v0.y + a.y * t;
        if (bit_exact && ((double)particle.position.x != x || (double)particle.position.y != y ||
                          (double)particle.velocity.x != vx || (double)particle.velocity.y != vy))
            mismatches++;
        if (sqrt(x * x + y * y) > max_x) max_x = sqrt(x * x + y * y);
        if (sqrt(vx * vx + vy * vy) > max_v) max_v = sqrt(vx * vx + vy * vy);
        bound_x = i * 8 * (EPS / 2) * (max_x + max_v * t);
        bound_v = i * 8 * (EPS / 2) * max_v;
        error_x = hypot(particle.position.x - x, particle.position.y - y) / bound_x;
        error_v = hypot(particle.velocity.x - vx, particle.velocity.y - vy) / bound_v;
        if (error_x > worst) worst = error_x;
        if (error_v > worst) worst = error_v;
    }
    printf("  oracle %-20s %-10s largest error %.3f of the bound%s\n", motus_method_name(method), o->name, worst,
           bit_exact ? (mismatches ? ", NOT bit-exact" : ", bit-exact") : "");
    if (bit_exact && mismatches)
        fprintf(stderr, "  %s, %s: %d steps off the oracle's bits\n", motus_method_name(method), o->name, mismatches);
    ENSURE(!bit_exact || mismatches == 0);
    if (!(worst <= 1))
        fprintf(stderr, "  %s, %s: error %.3g of the rounding bound\n", motus_method_name(method), o->name, worst);
    ENSURE(worst <= 1);
    return worst;
}

static const oracle_setup ORACLE_DYADIC = {
    "dyadic", {8, -4}, {3, 12}, {0, -8}, {3, 0}, {MOTUS_R(0.015625), MOTUS_R(0.015625), MOTUS_R(0.015625)}, 128, 1};
static const oracle_setup ORACLE_FREE_FALL = {
    "free_fall", {0, 0}, {3, 12}, {0, MOTUS_R(-9.81)}, {3, -1},
    {MOTUS_R(1.0) / 60, MOTUS_R(1.0) / 60, MOTUS_R(1.0) / 60}, 120, 0};
static const oracle_setup ORACLE_GAME = { /* pixels: 98.1 px/s^2 down, a key pushing right */
    "game", {400, 300}, {-20, 35}, {0, MOTUS_R(98.1)}, {100, 0},
    {MOTUS_R(1.0) / 60, MOTUS_R(1.0) / 60, MOTUS_R(1.0) / 60}, 600, 0};

static void ensure_oracles(motus_method method) {
    ensure_oracle(method, &ORACLE_DYADIC);
    ensure_oracle(method, &ORACLE_FREE_FALL);
    ensure_oracle(method, &ORACLE_GAME);
}

TEST(oracle_explicit_euler) { ensure_oracles(MOTUS_EXPLICIT_EULER); }
TEST(oracle_semi_implicit_euler) { ensure_oracles(MOTUS_SEMI_IMPLICIT_EULER); }
TEST(oracle_position_verlet) {
    /* Exact on dyadic data, but its rounding outgrows the bound: the stepper keeps x_{n-1} and forms
       x_n - x_{n-1} every step (Stormer's two-step form), so each rounding of x_n becomes a lasting velocity
       error of eps*|x|/h and the position error grows like n^2 (600 steps of the game setup: 16 times the
       bound in float, 0.9 px after 10 s; 69 times in double). Keeping the difference d_n = x_n - x_{n-1} as
       the step added it (the summed form, same method in exact arithmetic) stays within the bound. */
    ensure_oracles(MOTUS_POSITION_VERLET);
}
TEST(oracle_velocity_verlet) { ensure_oracles(MOTUS_VELOCITY_VERLET); }
TEST(oracle_leapfrog) { ensure_oracles(MOTUS_LEAPFROG); }
TEST(oracle_midpoint) { ensure_oracles(MOTUS_MIDPOINT); }
TEST(oracle_rk4) { ensure_oracles(MOTUS_RK4); }
TEST(oracle_forest_ruth) { ensure_oracles(MOTUS_FOREST_RUTH); }
TEST(oracle_exact_linear_drag) { ensure_oracles(MOTUS_EXACT_LINEAR_DRAG); }

TEST(oracle_varying_dt) {
    /* A game's dt changes from frame to frame. The one-step methods of order >= 2 stay exact under a
       constant acceleration whatever the sequence of steps. Position Verlet's x_{n+1} = 2x_n - x_{n-1} +
       a h^2 assumes the previous step had the same h; with h_{n-1} != h_n it is not even consistent
       (the drift x_n - x_{n-1} is the previous step's, not this one's). */
    static const oracle_setup varying = {
        "varying", {8, -4}, {3, 12}, {0, -8}, {3, 0}, {MOTUS_R(0.015625), MOTUS_R(0.03125), MOTUS_R(0.0078125)}, 60, 1};
    static const motus_method methods[] = {MOTUS_POSITION_VERLET, MOTUS_VELOCITY_VERLET, MOTUS_LEAPFROG,
                                           MOTUS_MIDPOINT,        MOTUS_RK4,             MOTUS_FOREST_RUTH,
                                           MOTUS_EXACT_LINEAR_DRAG};
    int i;
    for (i = 0; i < (int)(sizeof methods / sizeof methods[0]); ++i) ensure_oracle(methods[i], &varying);
}

/* =================================================================================================
   Time reversibility
   =================================================================================================
   Forward n steps, flip the velocities, n steps, flip back: a symmetric method (leapfrog, velocity Verlet,
   Forest-Ruth, for forces of position only) is back at the start up to rounding. Bound: a step adds into
   x and v at most k = 8 times (Forest-Ruth: 4 drifts, 3 kicks), each rounding by eps/2 relative to
   scale = max(|x| + |v|); on the oscillator and over a few orbits these errors add up about linearly,
   so the 2n steps leave at most 2n*k*(eps/2)*scale.
   Explicit Euler is not symmetric: it comes back off by O(h*t), hundreds of times that bound or more. */
static double reversal_error(motus_method method, int which, int steps, double *bound, const char **name) {
    test_stepper s;
    problem p;
    motus_particle particle, start;
    motus_real h;
    double scale = 0;
    int i, pass;
    ENSURE(problem_get(which, &p));
    particle = start = problem_particle(&p);
    h = (motus_real)(p.duration / 200);
    stepper_init(&s, method, 0);
    for (pass = 0; pass < 2; ++pass) {
        for (i = 0; i < steps; ++i) {
            double size;
            ENSURE_EQ_INT(motus_stepper_step(&s.stepper, &particle, 1, &p.forces, h), MOTUS_OK);
            size = hypot(particle.position.x, particle.position.y) + hypot(particle.velocity.x, particle.velocity.y);
            if (size > scale) scale = size;
        }
        particle.velocity = motus_vec2_scale(particle.velocity, -1);
        motus_stepper_reset(&s.stepper); /* velocities changed by hand */
    }
    *bound = 2.0 * steps * 8 * (EPS / 2) * scale;
    *name = p.name;
    return hypot4(particle.position.x - start.position.x, particle.position.y - start.position.y,
                  particle.velocity.x - start.velocity.x, particle.velocity.y - start.velocity.y);
}

static void ensure_reversible(motus_method method) {
    static const int problems[] = {PROBLEM_HARMONIC_OSCILLATOR, PROBLEM_KEPLER_ECCENTRIC};
    int i;
    for (i = 0; i < 2; ++i) {
        const char *name;
        double bound, error = reversal_error(method, problems[i], 1000, &bound, &name);
        printf("  reversal %-16s %-20s back within %.3g (bound %.3g)\n", motus_method_name(method), name, error, bound);
        ENSURE_NEAR(error, 0, bound);
    }
}

TEST(reversible_leapfrog) { ensure_reversible(MOTUS_LEAPFROG); }
TEST(reversible_velocity_verlet) { ensure_reversible(MOTUS_VELOCITY_VERLET); }
TEST(reversible_forest_ruth) { ensure_reversible(MOTUS_FOREST_RUTH); }

TEST(explicit_euler_is_not_reversible) {
    static const int problems[] = {PROBLEM_HARMONIC_OSCILLATOR, PROBLEM_KEPLER_ECCENTRIC};
    int i;
    for (i = 0; i < 2; ++i) {
        const char *name;
        double bound, error = reversal_error(MOTUS_EXPLICIT_EULER, problems[i], 1000, &bound, &name);
        printf("  reversal explicit_euler   %-20s off by %.3g (bound %.3g)\n", name, error, bound);
        ENSURE(error > 100 * bound);
        ENSURE(error > 0.1); /* not a rounding matter in either build */
    }
}

/* =================================================================================================
   Energy over long runs
   =================================================================================================
   kepler_eccentric (e = 0.5) for 10^5 steps of period/200 (500 orbits). The relative energy error
   |E - E0|/|E0| is recorded over the first orbit, the first 10% and the last 10% of the run. A symplectic
   method's error oscillates with the orbit but does not grow: its largest value in the last 10% is that of
   the first 10%. The bounds are the measured maxima with some room; what the test is about is the growth. */
typedef struct energy_record {
    double first_orbit, first, last, overall, final_signed;
} energy_record;

static energy_record kepler_energy(motus_method method) {
    const int steps = 100000, window = steps / 10;
    test_stepper s;
    problem p;
    motus_particle particle;
    energy_record r;
    double e0;
    int i;
    memset(&r, 0, sizeof r);
    ENSURE(problem_get(PROBLEM_KEPLER_ECCENTRIC, &p));
    particle = problem_particle(&p);
    e0 = p.energy(problem_state_of(&particle)); /* the start as rounded to motus_real */
    stepper_init(&s, method, 0);
    for (i = 0; i < steps; ++i) {
        double e;
        if (motus_stepper_step(&s.stepper, &particle, 1, &p.forces, (motus_real)(p.duration / 200)) != MOTUS_OK) {
            ENSURE(!"step failed");
            break;
        }
        e = fabs((p.energy(problem_state_of(&particle)) - e0) / e0);
        if (i < 200 && e > r.first_orbit) r.first_orbit = e;
        if (i < window && e > r.first) r.first = e;
        if (i >= steps - window && e > r.last) r.last = e;
        if (e > r.overall) r.overall = e;
    }
    r.final_signed = (p.energy(problem_state_of(&particle)) - e0) / e0;
    printf("  energy %-20s first orbit %.3g, first 10%% %.3g, last 10%% %.3g, max %.3g, final %+.3g\n",
           motus_method_name(method), r.first_orbit, r.first, r.last, r.overall, r.final_signed);
    return r;
}

TEST(energy_symplectic_bounded_kepler) {
    static const struct {
        motus_method method;
        double bound;
    } cases[] = {{MOTUS_SEMI_IMPLICIT_EULER, 0.06}, {MOTUS_POSITION_VERLET, 0.03}, {MOTUS_VELOCITY_VERLET, 0.003},
                 {MOTUS_LEAPFROG, 0.003},
#ifdef MOTUS_DOUBLE
                 {MOTUS_FOREST_RUTH, 1.2e-5},
#endif
    };
    int i;
    for (i = 0; i < (int)(sizeof cases / sizeof cases[0]); ++i) {
        energy_record r = kepler_energy(cases[i].method);
        ENSURE_NEAR(r.overall, 0, cases[i].bound);
        /* No growth: the last 10% no worse than the first 10%, up to 5% of wobble in the sampling. */
        if (!(r.last <= 1.05 * r.first))
            fprintf(stderr, "  %s energy error grows\n", motus_method_name(cases[i].method));
        ENSURE(r.last <= 1.05 * r.first);
    }
#ifndef MOTUS_DOUBLE
    {
        /* Float: Forest-Ruth's own error (1e-5) is below the rounding drift of 1e5 float steps; bound only. */
        energy_record r = kepler_energy(MOTUS_FOREST_RUTH);
        ENSURE_NEAR(r.overall, 0, 1e-3);
    }
#endif
}

TEST(energy_explicit_euler_grows_kepler) {
    /* At this step explicit Euler gains energy every orbit until the orbit opens (E > 0) and the body escapes. */
    energy_record r = kepler_energy(MOTUS_EXPLICIT_EULER);
    ENSURE(r.last > 2 * r.first_orbit);
    ENSURE(r.last > 10 * 0.06); /* ten times the worst symplectic method's bound */
    ENSURE(r.final_signed < -1);  /* E_final = E0*(1 + final_signed) > 0 with E0 < 0: unbound */
}

TEST(energy_rk4_and_midpoint_drift_kepler) {
    /* Not symplectic: the error grows steadily with time (RK4 gains energy, midpoint loses it). */
    energy_record rk4 = kepler_energy(MOTUS_RK4), midpoint = kepler_energy(MOTUS_MIDPOINT);
    ENSURE(rk4.last > 5 * rk4.first);
    ENSURE(midpoint.last > 5 * midpoint.first);
}

/* =================================================================================================
   The exact stepper
   =================================================================================================
   gravity_linear_drag has a closed form; MOTUS_EXACT_LINEAR_DRAG solves the same equation over each step,
   so it lands on the closed form at any dt, the whole 2 s in one step included. Rounding only. The
   stepper: each step computes decay, phi1, phi2 to a few eps and rounds x and v, at most k = 8 roundings
   of eps/2 relative to |x| and |v|*h: the same n*k*(eps/2)*(max|x| + max|v|*t) as the oracles. The
   closed form (double in both builds) has its own rounding: problem_linear_drag_exact forms 1 - e^-kt,
   which for small kt keeps only an absolute DBL_EPSILON of it, times |v0 - v_inf|/k (= 64 m) in x and
   |v0 - v_inf| in v; that is allowed for too (4 DBL_EPSILON of each). */
TEST(exact_stepper_matches_closed_form_at_any_dt) {
    static const double dts[] = {1e-3, 1.0 / 60, 0.1, 0.5, 2};
    const double k_drag = PROBLEM_DRAG, v_inf = PROBLEM_G / PROBLEM_DRAG;
    problem p;
    double reference_x, reference_v;
    int k;
    ENSURE(problem_get(PROBLEM_GRAVITY_LINEAR_DRAG, &p));
    reference_v = 4 * DBL_EPSILON * hypot(p.start.vx, p.start.vy + v_inf);
    reference_x = reference_v / k_drag;
    for (k = 0; k < 5; ++k) {
        test_stepper s;
        motus_particle particle = problem_particle(&p);
        const motus_real h = (motus_real)dts[k];
        const int steps = (int)floor(p.duration / dts[k] + 0.5);
        double max_x = 0, max_v = 0, worst = 0;
        int i;
        stepper_init(&s, MOTUS_EXACT_LINEAR_DRAG, 0);
        for (i = 1; i <= steps; ++i) {
            const double t = (double)i * (double)h;
            problem_state e;
            double bound_x, bound_v, error_x, error_v;
            ENSURE_EQ_INT(motus_stepper_step(&s.stepper, &particle, 1, &p.forces, h), MOTUS_OK);
            e = p.exact(t);
            if (hypot(e.x, e.y) > max_x) max_x = hypot(e.x, e.y);
            if (hypot(e.vx, e.vy) > max_v) max_v = hypot(e.vx, e.vy);
            bound_x = i * 8 * (EPS / 2) * (max_x + max_v * t) + reference_x;
            bound_v = i * 8 * (EPS / 2) * max_v + reference_v;
            error_x = hypot(particle.position.x - e.x, particle.position.y - e.y) / bound_x;
            error_v = hypot(particle.velocity.x - e.vx, particle.velocity.y - e.vy) / bound_v;
            if (error_x > worst) worst = error_x;
            if (error_v > worst) worst = error_v;
        }
        printf("  exact stepper dt = %-9g %4d steps: largest error %.3f of the bound, state error at 2 s %.3g\n",
               dts[k], steps, worst, state_error(&particle, p.exact((double)steps * (double)h)));
        ENSURE(worst <= 1);
        /* The clock too: time is the sum of the steps, rounded once per step. */
        ENSURE_NEAR(s.stepper.time, (double)steps * (double)h, steps * EPS * (double)steps * (double)h);
    }
}

static const motus_test_case TESTS[] = {
    TEST_CASE(order_semi_implicit_euler),
    TEST_CASE(order_explicit_euler),
    TEST_CASE(order_position_verlet),
    TEST_CASE(order_position_verlet_drag_is_first_order),
    TEST_CASE(order_velocity_verlet),
    TEST_CASE(order_leapfrog),
    TEST_CASE(order_midpoint),
    TEST_CASE(order_rk4),
    TEST_CASE(order_forest_ruth),
    TEST_CASE(order_forest_ruth_drag_is_first_order),
    TEST_CASE(oracle_explicit_euler),
    TEST_CASE(oracle_semi_implicit_euler),
    TEST_CASE(oracle_position_verlet),
    TEST_CASE(oracle_velocity_verlet),
    TEST_CASE(oracle_leapfrog),
    TEST_CASE(oracle_midpoint),
    TEST_CASE(oracle_rk4),
    TEST_CASE(oracle_forest_ruth),
    TEST_CASE(oracle_exact_linear_drag),
    TEST_CASE(oracle_varying_dt),
    TEST_CASE(reversible_leapfrog),
    TEST_CASE(reversible_velocity_verlet),
    TEST_CASE(reversible_forest_ruth),
    TEST_CASE(explicit_euler_is_not_reversible),
    TEST_CASE(energy_symplectic_bounded_kepler),
    TEST_CASE(energy_explicit_euler_grows_kepler),
    TEST_CASE(energy_rk4_and_midpoint_drift_kepler),
    TEST_CASE(exact_stepper_matches_closed_form_at_any_dt),
};

int main(int argc, char **argv) { return motus_test_main(argc, argv, TESTS, TEST_COUNT(TESTS)); }
