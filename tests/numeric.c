/* Numeric tests: the integrators against the closed forms of bench/problems.h. No timing, only accuracy.
   Built in float and in double (MOTUS_DOUBLE). Every run goes through motus_step, the engine's kernels, on
   COPIES copies of one particle (more than any lane count, so both the whole vector groups and the tail
   run), in 2D and in 3D, by one of three paths:
   - arrays:    plain arrays (structure of arrays), no inverse-mass array (scene.mass), the fast kernels;
   - coupled:   the same with a force callback that adds nothing, so every stage is a pass over scratch;
   - particles: an array of motus_particle / motus_particle3 (motus_state_of_particles: the strided path).
   In 3D the problem's plane is put on the z and x axes (problem x -> z, problem y -> x, y stays 0), so the
   third component carries real data. paths_agree_* checks that the three paths end every problem in the
   same bits, in both dimensions, for every method; the other tests use the arrays path. The oscillators
   are tethered (scene.tether_stiffness, uncoupled); spring_to_an_anchor_off_the_origin poses them with a
   spring instead.
   What each build can show:
   - Convergence orders are measured from the error at h, h/2, h/4, h/8. In double every method and problem
     is checked over three halvings in its asymptotic range. In float, rounding (about 1e-7 relative per
     operation, growing with the number of steps) swamps errors below ~1e-5, so the float build measures
     two halvings at coarser steps, and the 4th-order methods only on the oscillators, where their error
     at 25..100 steps per 5 s is still 1e-3..1e-6; their other problems run in double only.
   - Oracles, reversibility and the exact stepper have bounds written in units of the build's epsilon, so
     both builds run the same assertions.
   - Energy: Forest-Ruth's energy error (1e-5) is below float's rounding drift over 1e5 steps (~1e-4), so
     in float it gets a bound only, not the no-growth comparison. */
#define MOTUS_IMPLEMENTATION
#include "motus.h"
#include "problems.h"
#include "support/motus_test.h"

#include <float.h>
#include <stdlib.h>

#define EPS ((double)MOTUS_REAL_EPSILON)
#define COPIES 17 /* > 16, the most lanes (float, 64-byte vectors): a whole group and a tail */

/* motus_method_name, never NULL (GCC's -Wformat-overflow sees the NULL for a bad method through the inlining). */
static const char *method_name(motus_method method) {
    const char *name = motus_method_name(method);
    return name ? name : "?";
}

static double hypot4(double a, double b, double c, double d) { return sqrt(a * a + b * b + c * c + d * d); }

/* =================================================================================================
   A run: COPIES copies of one particle, in 2D or 3D, through one path
   ================================================================================================= */
enum { PATH_ARRAYS, PATH_COUPLED, PATH_PARTICLES, PATH_COUNT };
static const char *const PATH_NAMES[PATH_COUNT] = {"arrays", "coupled", "particles"};

typedef struct run {
    int dims, path, ax, ay; /* ax, ay: the components that carry the problem's x and y */
    motus_scene scene;
    motus_spring springs[COPIES];
    motus_real x[3][COPIES], v[3][COPIES], f[3][COPIES];
    motus_particle p2[COPIES];
    motus_particle3 p3[COPIES];
    motus_state state;
    motus_real *scratch;
    size_t scratch_bytes;
} run;

static void nothing(void *user_data, const motus_force_query *query) {
    (void)user_data;
    (void)query;
}

/* The plane's vector in the run's components. */
static motus_vec3 embed(const run *r, motus_real x, motus_real y) {
    motus_real c[3] = {0, 0, 0};
    c[r->ax] = x;
    c[r->ay] = y;
    return motus_v3(c[0], c[1], c[2]);
}

/* `plane`: a scene in the plane (gravity.x/.y, drags, attractor at the origin, at most one spring, from
   particle 0 to an anchor: each copy gets its own). force: accumulated on each particle; mass: of each (the
   arrays paths put it in scene.mass, the particles path in each particle's inverse mass). */
static void run_open(run *r, const motus_scene *plane, motus_method method, int dims, int path, problem_state start,
                     motus_vec2 force, motus_real mass) {
    const int has_force = force.x != 0 || force.y != 0;
    int i, d;
    memset(r, 0, sizeof *r);
    r->dims = dims;
    r->path = path;
    r->ax = dims == 2 ? 0 : 2;
    r->ay = dims == 2 ? 1 : 0;
    r->scene = *plane;
    r->scene.method = method;
    r->scene.gravity = embed(r, plane->gravity.x, plane->gravity.y);
    r->scene.attractor = embed(r, plane->attractor.x, plane->attractor.y);
    r->scene.tether = embed(r, plane->tether.x, plane->tether.y);
    ENSURE(plane->spring_count <= 1);
    if (plane->spring_count == 1) {
        for (i = 0; i < COPIES; ++i) {
            r->springs[i] = plane->springs[0];
            r->springs[i].a = i;
            r->springs[i].anchor = embed(r, plane->springs[0].anchor.x, plane->springs[0].anchor.y);
        }
        r->scene.springs = r->springs;
        r->scene.spring_count = COPIES;
    }
    if (path == PATH_COUPLED) r->scene.force_callback = nothing;
    if (path == PATH_PARTICLES) {
        r->scene.mass = 0;
        for (i = 0; i < COPIES; ++i) {
            if (dims == 2) {
                ENSURE_EQ_INT(motus_particle_init(&r->p2[i], motus_v2((motus_real)start.x, (motus_real)start.y),
                                                  mass), MOTUS_OK);
                r->p2[i].velocity = motus_v2((motus_real)start.vx, (motus_real)start.vy);
                r->p2[i].force = force;
            } else {
                ENSURE_EQ_INT(motus_particle3_init(&r->p3[i], embed(r, (motus_real)start.x, (motus_real)start.y),
                                                   mass), MOTUS_OK);
                r->p3[i].velocity = embed(r, (motus_real)start.vx, (motus_real)start.vy);
                r->p3[i].force = embed(r, force.x, force.y);
            }
        }
        r->state = dims == 2 ? motus_state_of_particles(r->p2, COPIES) : motus_state_of_particles3(r->p3, COPIES);
    } else {
        const motus_vec3 x0 = embed(r, (motus_real)start.x, (motus_real)start.y);
        const motus_vec3 v0 = embed(r, (motus_real)start.vx, (motus_real)start.vy);
        const motus_vec3 f0 = embed(r, force.x, force.y);
        r->scene.mass = mass == 1 ? 0 : mass; /* 0: the default 1 kg */
        r->state.dimensions = dims;
        r->state.count = COPIES;
        for (i = 0; i < COPIES; ++i) {
            r->x[0][i] = x0.x, r->x[1][i] = x0.y, r->x[2][i] = x0.z;
            r->v[0][i] = v0.x, r->v[1][i] = v0.y, r->v[2][i] = v0.z;
            r->f[0][i] = f0.x, r->f[1][i] = f0.y, r->f[2][i] = f0.z;
        }
        for (d = 0; d < dims; ++d) {
            r->state.position[d] = r->x[d];
            r->state.velocity[d] = r->v[d];
            if (has_force) r->state.force[d] = r->f[d];
        }
    }
    r->scratch_bytes = motus_scratch_size(&r->scene, &r->state);
    ENSURE((r->scratch_bytes > 0) == (path == PATH_COUPLED || plane->spring_count > 0));
    if (r->scratch_bytes) r->scratch = (motus_real *)malloc(r->scratch_bytes);
}

static void run_close(run *r) {
    free(r->scratch);
    r->scratch = NULL;
}

static motus_result run_step(run *r, motus_real h) {
    return motus_step(&r->scene, &r->state, h, r->scratch, r->scratch_bytes);
}

static motus_real *component(const run *r, motus_real *const *arrays, int d, int i) {
    return arrays[d] + (ptrdiff_t)i * (r->state.stride ? r->state.stride : 1);
}

/* Particle i in the plane's coordinates. */
static problem_state run_get(const run *r, int i) {
    problem_state s;
    s.x = *component(r, r->state.position, r->ax, i);
    s.y = *component(r, r->state.position, r->ay, i);
    s.vx = *component(r, r->state.velocity, r->ax, i);
    s.vy = *component(r, r->state.velocity, r->ay, i);
    return s;
}

/* Every velocity times -1 (time reversal). */
static void run_flip(run *r) {
    int i, d;
    for (i = 0; i < COPIES; ++i)
        for (d = 0; d < r->dims; ++d) *component(r, r->state.velocity, d, i) = -*component(r, r->state.velocity, d, i);
}

/* Every component of every particle, in one array, for comparisons bit for bit. */
static void run_values(const run *r, motus_real *out /* 6 * COPIES */) {
    int i, d;
    for (i = 0; i < COPIES; ++i)
        for (d = 0; d < 3; ++d) {
            out[6 * i + d] = d < r->dims ? *component(r, r->state.position, d, i) : 0;
            out[6 * i + 3 + d] = d < r->dims ? *component(r, r->state.velocity, d, i) : 0;
        }
}

/* The copies all in the same bits (the vector groups and the tail compute alike). */
static int copies_agree(const run *r) {
    motus_real values[6 * COPIES];
    int i;
    run_values(r, values);
    for (i = 1; i < COPIES; ++i)
        if (memcmp(values, values + 6 * i, 6 * sizeof(motus_real)) != 0) return 0;
    return 1;
}

static void run_problem(run *r, const problem *p, motus_method method, int dims, int path) {
    run_open(r, &p->scene, method, dims, path, p->start, motus_v2(0, 0), 1);
}

/* Euclidean distance in (x, y, vx, vy) between particle 0 and a closed-form state. */
static double state_error(const run *r, problem_state e) {
    problem_state s = run_get(r, 0);
    return hypot4(s.x - e.x, s.y - e.y, s.vx - e.vx, s.vy - e.vy);
}

/* =================================================================================================
   The three paths agree bit for bit
   =================================================================================================
   Every method, every problem it takes, 2D and 3D: arrays, coupled (a callback that adds nothing) and
   particles (strided) end 300 steps in the same bits, every copy alike; plus an accumulated force on
   particles of 2 kg (scene.mass against each particle's inverse mass). */
/* The exact stepper takes gravity, linear drag and accumulated forces only: no tether, no callback (the
   coupled path). */
static int method_takes(motus_method method, const motus_scene *plane, int path) {
    return method != MOTUS_EXACT_LINEAR_DRAG || (plane->quadratic_drag == 0 && plane->attractor_strength == 0 &&
                                                 plane->tether_stiffness == 0 && plane->spring_count == 0 &&
                                                 path != PATH_COUPLED);
}

static void ensure_paths_agree(motus_method method) {
    int which, dims, path, step, agreed = 0;
    for (which = 0; which <= PROBLEM_COUNT; ++which) {
        problem p;
        motus_vec2 force = motus_v2(0, 0);
        motus_real mass = 1;
        const motus_real h = MOTUS_R(1.0) / 64;
        if (which < PROBLEM_COUNT) {
            ENSURE(problem_get(which, &p));
        } else { /* gravity, linear drag and an accumulated force on 2 kg */
            ENSURE(problem_get(PROBLEM_GRAVITY_LINEAR_DRAG, &p));
            p.name = "accumulated_force_2kg";
            force = motus_v2(3, MOTUS_R(-1.5));
            mass = 2;
        }
        if (!method_takes(method, &p.scene, PATH_ARRAYS)) continue;
        for (dims = 2; dims <= 3; ++dims) {
            motus_real reference[6 * COPIES], values[6 * COPIES];
            for (path = 0; path < PATH_COUNT; ++path) {
                run r;
                if (!method_takes(method, &p.scene, path)) continue;
                run_open(&r, &p.scene, method, dims, path, p.start, force, mass);
                for (step = 0; step < 300; ++step) ENSURE_EQ_INT(run_step(&r, h), MOTUS_OK);
                ENSURE(copies_agree(&r));
                run_values(&r, path == 0 ? reference : values);
                if (path > 0 && memcmp(reference, values, sizeof values) != 0) {
                    fprintf(stderr, "  %s, %s, %dD: the %s path ends elsewhere than the arrays path\n",
                            method_name(method), p.name, dims, PATH_NAMES[path]);
                    ENSURE(!"paths agree");
                } else if (path > 0) {
                    agreed++;
                }
                run_close(&r);
            }
        }
    }
    printf("  %-20s %d (problem, dimensions, path) runs equal to the arrays path bit for bit\n",
           method_name(method), agreed);
    ENSURE(agreed >= (method == MOTUS_EXACT_LINEAR_DRAG ? 3 * 2 : 8 * 2 * 2));
}

TEST(paths_agree_semi_implicit_euler) { ensure_paths_agree(MOTUS_SEMI_IMPLICIT_EULER); }
TEST(paths_agree_explicit_euler) { ensure_paths_agree(MOTUS_EXPLICIT_EULER); }
TEST(paths_agree_position_verlet) { ensure_paths_agree(MOTUS_POSITION_VERLET); }
TEST(paths_agree_velocity_verlet) { ensure_paths_agree(MOTUS_VELOCITY_VERLET); }
TEST(paths_agree_leapfrog) { ensure_paths_agree(MOTUS_LEAPFROG); }
TEST(paths_agree_midpoint) { ensure_paths_agree(MOTUS_MIDPOINT); }
TEST(paths_agree_rk4) { ensure_paths_agree(MOTUS_RK4); }
TEST(paths_agree_forest_ruth) { ensure_paths_agree(MOTUS_FOREST_RUTH); }
TEST(paths_agree_mclachlan4) { ensure_paths_agree(MOTUS_MCLACHLAN4); }
TEST(paths_agree_exact_linear_drag) { ensure_paths_agree(MOTUS_EXACT_LINEAR_DRAG); }

/* =================================================================================================
   Substeps
   =================================================================================================
   scene.substeps = n is n steps of dt/n (dt/n as motus_real rounds it), bit for bit, in every method,
   path and dimension; damping (fraction removed) applies once per motus_step, after the n substeps: equal
   to the n steps without damping, then motus_particle_damp_per_step / motus_particle3_damp_per_step on
   each particle. */
TEST(substeps_equal_steps_of_dt_over_n) {
    static const int problems[] = {PROBLEM_GRAVITY_LINEAR_DRAG, PROBLEM_KEPLER_ECCENTRIC, PROBLEM_DAMPED_OSCILLATOR};
    const motus_real dt = MOTUS_R(0.05);
    const int n = 5;
    int m, k, dims, path, frame, s, checked = 0;
    for (m = 0; m < MOTUS_METHOD_COUNT; ++m)
        for (k = 0; k < 3; ++k)
            for (dims = 2; dims <= 3; ++dims)
                for (path = 0; path < PATH_COUNT; ++path) {
                    problem p;
                    run sub, plain;
                    motus_real a[6 * COPIES], b[6 * COPIES];
                    ENSURE(problem_get(problems[k], &p));
                    if (!method_takes((motus_method)m, &p.scene, path)) continue;
                    run_problem(&sub, &p, (motus_method)m, dims, path);
                    run_problem(&plain, &p, (motus_method)m, dims, path);
                    sub.scene.substeps = n;
                    for (frame = 0; frame < 40; ++frame) {
                        ENSURE_EQ_INT(run_step(&sub, dt), MOTUS_OK);
                        for (s = 0; s < n; ++s) ENSURE_EQ_INT(run_step(&plain, dt / (motus_real)n), MOTUS_OK);
                    }
                    run_values(&sub, a);
                    run_values(&plain, b);
                    if (memcmp(a, b, sizeof a) != 0)
                        fprintf(stderr, "  %s, %s, %dD, %s: substeps differ from steps of dt/n\n",
                                method_name((motus_method)m), p.name, dims, PATH_NAMES[path]);
                    ENSURE(memcmp(a, b, sizeof a) == 0);
                    checked++;
                    if (path == PATH_PARTICLES) {
                        /* With damping: once per motus_step, after the substeps. */
                        int i;
                        sub.scene.damping_per_step = MOTUS_R(0.25);
                        for (frame = 0; frame < 10; ++frame) {
                            ENSURE_EQ_INT(run_step(&sub, dt), MOTUS_OK);
                            for (s = 0; s < n; ++s) ENSURE_EQ_INT(run_step(&plain, dt / (motus_real)n), MOTUS_OK);
                            for (i = 0; i < COPIES; ++i)
                                ENSURE_EQ_INT(dims == 2 ? motus_particle_damp_per_step(&plain.p2[i], MOTUS_R(0.25))
                                                        : motus_particle3_damp_per_step(&plain.p3[i], MOTUS_R(0.25)),
                                              MOTUS_OK);
                        }
                        run_values(&sub, a);
                        run_values(&plain, b);
                        ENSURE(memcmp(a, b, sizeof a) == 0);
                    }
                    run_close(&sub);
                    run_close(&plain);
                }
    printf("  %d (method, problem, dimensions, path) runs: substeps equal steps of dt/n bit for bit\n", checked);
    ENSURE(checked == 9 * 3 * 2 * 3 + 1 * 2 * 2); /* the exact stepper: one problem, no callback */
}

/* =================================================================================================
   Convergence order
   =================================================================================================
   The error of a run is the largest state error over all its steps, not the error at the end: the Kepler
   problems last exactly one period, and at t = period the first-order term of semi-implicit Euler's
   error vanishes (measured: order 2.0 from the error at the end, 1.0 from the largest over the run). */
static double max_error_over_run(motus_method method, const problem *p, int steps, int dims) {
    run r;
    const motus_real h = (motus_real)(p->duration / steps);
    double worst = 0;
    int i;
    run_problem(&r, p, method, dims, PATH_ARRAYS);
    for (i = 1; i <= steps; ++i) {
        double error;
        if (run_step(&r, h) != MOTUS_OK) {
            worst = HUGE_VAL;
            break;
        }
        /* Compared at i*h with h as rounded to motus_real, so the step size itself is no error. */
        error = state_error(&r, p->exact((double)i * (double)h));
        if (error > worst) worst = error;
    }
    ENSURE(copies_agree(&r));
    run_close(&r);
    return worst;
}

/* Measures log2(err(h)/err(h/2)) for `halvings` halvings from n0 steps, in 2D and in 3D, and checks each
   within 0.15 of `expected`. Prints the measured orders (ctest -V shows them). */
static void ensure_order_from(motus_method method, int which, int n0, int halvings, double expected) {
    problem p;
    int k, dims;
    ENSURE(problem_get(which, &p));
    for (dims = 2; dims <= 3; ++dims) {
        int n = n0;
        double previous = max_error_over_run(method, &p, n, dims);
        printf("  order %-20s %-20s %dD n=%5d..%-6d", method_name(method), p.name, dims, n0, n0 << halvings);
        for (k = 0; k < halvings; ++k) {
            double error, order;
            n *= 2;
            error = max_error_over_run(method, &p, n, dims);
            order = log2(previous / error);
            printf(" %.3f", order);
            if (!motus_test_near(order, expected, 0.15, "measured order", __FILE__, __LINE__))
                fprintf(stderr, "  %s on %s (%dD), %d -> %d steps: errors %.3g -> %.3g\n", method_name(method),
                        p.name, dims, n / 2, n, previous, error);
            previous = error;
        }
        printf(" (error %.2g)\n", previous);
    }
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

TEST(order_table) {
    /* The orders the tests below hold the methods to. */
    static const int orders[] = {1, 1, 2, 2, 2, 2, 4, 4, 4, 0};
    int m;
    for (m = 0; m < MOTUS_METHOD_COUNT; ++m) ENSURE_EQ_INT(motus_method_order((motus_method)m), orders[m]);
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
    /* Drift-kick-drift: self-starting, no history, so float runs the same steps as the other Verlets. */
    ensure_order(MOTUS_POSITION_VERLET, PROBLEM_HARMONIC_OSCILLATOR, 100, 100);
    ensure_order(MOTUS_POSITION_VERLET, PROBLEM_KEPLER_CIRCULAR, 100, 100);
    ensure_order(MOTUS_POSITION_VERLET, PROBLEM_KEPLER_ECCENTRIC, 200, 200);
}

TEST(order_position_verlet_drag_is_first_order) {
    /* Documented: the one kick sees the velocity at the start of the step, not at its middle. */
    ensure_order_is(MOTUS_POSITION_VERLET, PROBLEM_DAMPED_OSCILLATOR, 200, 100, 1);
    ensure_order_is(MOTUS_POSITION_VERLET, PROBLEM_GRAVITY_LINEAR_DRAG, 100, 100, 1);
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

/* McLachlan's error is ~440x Forest-Ruth's smaller on the oscillator (see >>methods): its runs start
   coarser, so that the error stays above float's rounding for the halvings measured. */
TEST(order_mclachlan4) {
    ensure_order(MOTUS_MCLACHLAN4, PROBLEM_HARMONIC_OSCILLATOR, 10, 10);
    ensure_order(MOTUS_MCLACHLAN4, PROBLEM_KEPLER_CIRCULAR, 50, 0);
    ensure_order(MOTUS_MCLACHLAN4, PROBLEM_KEPLER_ECCENTRIC, 100, 0);
}

TEST(order_mclachlan4_drag_is_first_order) {
    ensure_order_is(MOTUS_MCLACHLAN4, PROBLEM_DAMPED_OSCILLATOR, 100, 100, 1);
    ensure_order_is(MOTUS_MCLACHLAN4, PROBLEM_GRAVITY_LINEAR_DRAG, 100, 100, 1);
}

/* The oscillator's fixed end at (3, -2), with the start moved as much: the same motion, shifted. Posed by
   the tether (uncoupled: the fast kernels) or by an anchored spring (the coupled path). Every method the
   force allows, 2D and 3D: the error against the shifted closed form falls by 2^order per halving (within
   0.15 of the order; the 4th-order methods from 32 steps (McLachlan's from 8), where float's rounding, 2e-6 at these
   positions of 3 m, is 2% of the error). */
static void ensure_fixed_end_off_the_origin(int spring) {
    static const motus_method methods[] = {MOTUS_SEMI_IMPLICIT_EULER, MOTUS_POSITION_VERLET, MOTUS_VELOCITY_VERLET,
                                           MOTUS_LEAPFROG, MOTUS_MIDPOINT, MOTUS_RK4, MOTUS_FOREST_RUTH,
                                           MOTUS_MCLACHLAN4};
    static const int orders[] = {1, 2, 2, 2, 2, 4, 4, 4};
    int m, dims;
    for (m = 0; m < (int)(sizeof methods / sizeof methods[0]); ++m)
        for (dims = 2; dims <= 3; ++dims) {
            double errors[2];
            int k;
            for (k = 0; k < 2; ++k) {
                problem p;
                run r;
                /* McLachlan's error at 32 steps is near float's rounding (see order_mclachlan4) */
                const int steps = (methods[m] == MOTUS_MCLACHLAN4 ? 8 : orders[m] == 4 ? 32 : 200) << k;
                motus_real h;
                double worst = 0;
                int i;
                ENSURE(problem_get(PROBLEM_HARMONIC_OSCILLATOR, &p));
                if (spring) {
                    ENSURE(problem_use_spring(&p));
                    p.spring.anchor = motus_v3(3, -2, 0);
                } else {
                    p.scene.tether = motus_v3(3, -2, 0);
                }
                p.start.x += 3, p.start.y -= 2;
                h = (motus_real)(p.duration / steps);
                run_problem(&r, &p, methods[m], dims, PATH_ARRAYS);
                ENSURE((r.scratch_bytes > 0) == spring); /* the spring couples, the tether does not */
                for (i = 1; i <= steps; ++i) {
                    problem_state e = p.exact((double)i * (double)h);
                    ENSURE_EQ_INT(run_step(&r, h), MOTUS_OK);
                    e.x += 3, e.y -= 2;
                    worst = fmax(worst, state_error(&r, e));
                }
                errors[k] = worst;
                run_close(&r);
            }
            printf("  %s at (3, -2) %-20s %dD: errors %.3g -> %.3g, order %.3f\n", spring ? "spring" : "tether",
                   method_name(methods[m]), dims, errors[0], errors[1], log2(errors[0] / errors[1]));
            ENSURE_NEAR(log2(errors[0] / errors[1]), orders[m], 0.15);
        }
}
TEST(spring_to_an_anchor_off_the_origin) { ensure_fixed_end_off_the_origin(1); }
TEST(tether_off_the_origin) { ensure_fixed_end_off_the_origin(0); }

TEST(tether_and_anchored_spring_agree) {
    /* The same force two ways: k*(x - p) in the kernel's registers, and the spring's k*(|d| - 0)*d/|d| in a
       coupled pass. They round differently, so they agree to rounding, not bits: 1000 steps of RK4 and of
       velocity Verlet on the harmonic oscillator end within 200 eps (relative to the amplitude). */
    static const motus_method methods[] = {MOTUS_VELOCITY_VERLET, MOTUS_RK4};
    int m, dims;
    for (m = 0; m < 2; ++m)
        for (dims = 2; dims <= 3; ++dims) {
            problem p, q;
            run r, s;
            problem_state a, b;
            int i;
            ENSURE(problem_get(PROBLEM_HARMONIC_OSCILLATOR, &p));
            ENSURE(problem_get(PROBLEM_HARMONIC_OSCILLATOR, &q));
            ENSURE(problem_use_spring(&q));
            run_problem(&r, &p, methods[m], dims, PATH_ARRAYS);
            run_problem(&s, &q, methods[m], dims, PATH_ARRAYS);
            for (i = 0; i < 1000; ++i) {
                ENSURE_EQ_INT(run_step(&r, MOTUS_R(0.005)), MOTUS_OK);
                ENSURE_EQ_INT(run_step(&s, MOTUS_R(0.005)), MOTUS_OK);
            }
            a = run_get(&r, 0), b = run_get(&s, 0);
            printf("  tether vs spring %-16s %dD: %.3g eps apart\n", method_name(methods[m]), dims,
                   hypot4(a.x - b.x, a.y - b.y, a.vx - b.vx, a.vy - b.vy) / EPS);
            ENSURE(hypot4(a.x - b.x, a.y - b.y, a.vx - b.vx, a.vy - b.vy) <= 200 * EPS);
            run_close(&r);
            run_close(&s);
        }
}

/* =================================================================================================
   Discrete oracles under constant acceleration
   =================================================================================================
   With a constant acceleration a, after steps of h the methods land exactly (in exact arithmetic) on
       explicit Euler        x0 + v0 t + a t (t - h)/2
       semi-implicit Euler   x0 + v0 t + a t (t + h)/2
       every other method    x0 + v0 t + a t^2/2       (order >= 2, and the exact stepper: exact on a
                                                        quadratic in t)
   and all of them on v = v0 + a t. Two kinds of data:
   - Dyadic (h = 1/64 or 1/32, 1/128; a, v0, x0 small multiples of powers of two): every intermediate value
     fits in the mantissa, so a method whose coefficients are dyadic must match the oracle bit for bit.
     That is all of them but RK4 (h/6) and Forest-Ruth (irrational theta), which get the bound below.
   - Game-like (h = 1/60, g = -9.81, positions of a few hundred): rounding only. A step does at most
     k = 8 roundings of relative size eps/2 on values no larger than the running |x| and |v|*h; an error
     made in v at step i reaches x through the later steps as (n - i)*h*delta_v. Summed over n steps:
         |x_n - oracle| <= n*k*(eps/2)*(max|x| + max|v|*t),   |v_n - oracle| <= n*k*(eps/2)*max|v|.
     The oracle is evaluated in double with the h and the a that the method actually used (rounded to
     motus_real), so only the steps' own rounding is measured. Run in 2D and 3D. */
typedef struct oracle_setup {
    const char *name;
    motus_vec2 x0, v0, gravity, force; /* force: accumulated on a particle of mass 2, added to gravity */
    motus_real h[3];                   /* step sizes, used in turn (all equal for a fixed step) */
    int steps;
    int dyadic; /* every value exactly representable: expect bit-exact results where the method allows */
} oracle_setup;

static int method_has_dyadic_coefficients(motus_method method) {
    return method != MOTUS_RK4 && method != MOTUS_FOREST_RUTH && method != MOTUS_MCLACHLAN4 &&
           method != MOTUS_EXACT_LINEAR_DRAG;
}

static double oracle_position(motus_method method, double x0, double v0, double a, double h, double t) {
    double offset = method == MOTUS_EXPLICIT_EULER ? -h : method == MOTUS_SEMI_IMPLICIT_EULER ? h : 0;
    return x0 + v0 * t + 0.5 * a * t * (t + offset);
}

/* Runs the setup with `method`; checks every step against the oracle (bit for bit when the data is dyadic
   and the method's coefficients are) and returns the largest error as a fraction of the bound. */
static double ensure_oracle(motus_method method, const oracle_setup *o, int dims) {
    const int bit_exact = o->dyadic && method_has_dyadic_coefficients(method);
    motus_scene plane;
    problem_state start;
    run r;
    motus_vec2 a;
    double t = 0, max_x = 0, max_v = 0, worst = 0;
    int i, mismatches = 0;
    memset(&plane, 0, sizeof plane);
    plane.gravity = motus_v3(o->gravity.x, o->gravity.y, 0);
    start.x = o->x0.x, start.y = o->x0.y, start.vx = o->v0.x, start.vy = o->v0.y;
    run_open(&r, &plane, method, dims, PATH_ARRAYS, start, o->force, 2);
    /* The acceleration as the engine forms it, F*(1/m) + g: rounded once, the same at every stage. */
    a = motus_vec2_add(motus_vec2_scale(o->force, MOTUS_R(0.5)), o->gravity);
    for (i = 1; i <= o->steps; ++i) {
        const motus_real h = o->h[(i - 1) % 3];
        double x, y, vx, vy, error_x, error_v, bound_x, bound_v;
        problem_state s;
        if (run_step(&r, h) != MOTUS_OK) {
            ENSURE(!"step failed");
            worst = HUGE_VAL;
            break;
        }
        s = run_get(&r, 0);
        t += (double)h; /* exact in double: a sum of a few hundred values of motus_real */
        x = oracle_position(method, o->x0.x, o->v0.x, a.x, (double)h, t);
        y = oracle_position(method, o->x0.y, o->v0.y, a.y, (double)h, t);
        vx = o->v0.x + a.x * t;
        vy = o->v0.y + a.y * t;
        if (bit_exact && (s.x != x || s.y != y || s.vx != vx || s.vy != vy)) mismatches++;
        if (sqrt(x * x + y * y) > max_x) max_x = sqrt(x * x + y * y);
        if (sqrt(vx * vx + vy * vy) > max_v) max_v = sqrt(vx * vx + vy * vy);
        bound_x = i * 8 * (EPS / 2) * (max_x + max_v * t);
        bound_v = i * 8 * (EPS / 2) * max_v;
        error_x = hypot(s.x - x, s.y - y) / bound_x;
        error_v = hypot(s.vx - vx, s.vy - vy) / bound_v;
        if (error_x > worst) worst = error_x;
        if (error_v > worst) worst = error_v;
    }
    ENSURE(copies_agree(&r));
    run_close(&r);
    printf("  oracle %-20s %-10s %dD largest error %.3f of the bound%s\n", method_name(method), o->name, dims,
           worst, bit_exact ? (mismatches ? ", NOT bit-exact" : ", bit-exact") : "");
    if (bit_exact && mismatches)
        fprintf(stderr, "  %s, %s: %d steps off the oracle's bits\n", method_name(method), o->name, mismatches);
    ENSURE(!bit_exact || mismatches == 0);
    if (!(worst <= 1))
        fprintf(stderr, "  %s, %s: error %.3g of the rounding bound\n", method_name(method), o->name, worst);
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
    int dims;
    for (dims = 2; dims <= 3; ++dims) {
        ensure_oracle(method, &ORACLE_DYADIC, dims);
        ensure_oracle(method, &ORACLE_FREE_FALL, dims);
        ensure_oracle(method, &ORACLE_GAME, dims);
    }
}

TEST(oracle_explicit_euler) { ensure_oracles(MOTUS_EXPLICIT_EULER); }
TEST(oracle_semi_implicit_euler) { ensure_oracles(MOTUS_SEMI_IMPLICIT_EULER); }
TEST(oracle_position_verlet) {
    /* Drift-kick-drift keeps no x_{n-1}: its rounding stays within the one-step bound like the others'
       (the old two-step form outgrew it 16 times in float over the 600 game steps). */
    ensure_oracles(MOTUS_POSITION_VERLET);
}
TEST(oracle_velocity_verlet) { ensure_oracles(MOTUS_VELOCITY_VERLET); }
TEST(oracle_leapfrog) { ensure_oracles(MOTUS_LEAPFROG); }
TEST(oracle_midpoint) { ensure_oracles(MOTUS_MIDPOINT); }
TEST(oracle_rk4) { ensure_oracles(MOTUS_RK4); }
TEST(oracle_forest_ruth) { ensure_oracles(MOTUS_FOREST_RUTH); }
TEST(oracle_mclachlan4) { ensure_oracles(MOTUS_MCLACHLAN4); }
TEST(oracle_exact_linear_drag) { ensure_oracles(MOTUS_EXACT_LINEAR_DRAG); }

TEST(oracle_varying_dt) {
    /* A game's dt changes from frame to frame. The one-step methods of order >= 2 stay exact under a
       constant acceleration whatever the sequence of steps; position Verlet too, now that it is
       drift-kick-drift (it keeps no previous step). */
    static const oracle_setup varying = {
        "varying", {8, -4}, {3, 12}, {0, -8}, {3, 0}, {MOTUS_R(0.015625), MOTUS_R(0.03125), MOTUS_R(0.0078125)}, 60, 1};
    static const motus_method methods[] = {MOTUS_POSITION_VERLET, MOTUS_VELOCITY_VERLET, MOTUS_LEAPFROG,
                                           MOTUS_MIDPOINT,        MOTUS_RK4,             MOTUS_FOREST_RUTH,
                                           MOTUS_MCLACHLAN4,      MOTUS_EXACT_LINEAR_DRAG};
    int i, dims;
    for (i = 0; i < (int)(sizeof methods / sizeof methods[0]); ++i)
        for (dims = 2; dims <= 3; ++dims) ensure_oracle(methods[i], &varying, dims);
}

/* =================================================================================================
   Time reversibility
   =================================================================================================
   Forward n steps, flip the velocities, n steps, flip back: a symmetric method (leapfrog, velocity Verlet,
   position Verlet (drift-kick-drift), Forest-Ruth, for forces of position only) is back at the start up to
   rounding. Bound: a step adds into x and v at most k = 8 times (Forest-Ruth: 4 drifts, 3 kicks), each
   rounding by eps/2 relative to scale = max(|x| + |v|); on the oscillator and over a few orbits these
   errors add up about linearly, so the 2n steps leave at most 2n*k*(eps/2)*scale.
   Explicit Euler is not symmetric: it comes back off by O(h*t), hundreds of times that bound or more. */
static double reversal_error(motus_method method, int which, int steps, int dims, double *bound, const char **name) {
    problem p;
    run r;
    problem_state start, end;
    motus_real h;
    double scale = 0;
    int i, pass;
    ENSURE(problem_get(which, &p));
    run_problem(&r, &p, method, dims, PATH_ARRAYS);
    start = run_get(&r, 0);
    h = (motus_real)(p.duration / 200);
    for (pass = 0; pass < 2; ++pass) {
        for (i = 0; i < steps; ++i) {
            problem_state s;
            ENSURE_EQ_INT(run_step(&r, h), MOTUS_OK);
            s = run_get(&r, 0);
            if (hypot(s.x, s.y) + hypot(s.vx, s.vy) > scale) scale = hypot(s.x, s.y) + hypot(s.vx, s.vy);
        }
        run_flip(&r);
    }
    end = run_get(&r, 0);
    ENSURE(copies_agree(&r));
    run_close(&r);
    *bound = 2.0 * steps * 8 * (EPS / 2) * scale;
    *name = p.name;
    return hypot4(end.x - start.x, end.y - start.y, end.vx - start.vx, end.vy - start.vy);
}

static void ensure_reversible(motus_method method) {
    static const int problems[] = {PROBLEM_HARMONIC_OSCILLATOR, PROBLEM_KEPLER_ECCENTRIC};
    int i, dims;
    for (i = 0; i < 2; ++i)
        for (dims = 2; dims <= 3; ++dims) {
            const char *name;
            double bound, error = reversal_error(method, problems[i], 1000, dims, &bound, &name);
            printf("  reversal %-16s %-20s %dD back within %.3g (bound %.3g)\n", method_name(method), name, dims,
                   error, bound);
            ENSURE_NEAR(error, 0, bound);
        }
}

TEST(reversible_leapfrog) { ensure_reversible(MOTUS_LEAPFROG); }
TEST(reversible_velocity_verlet) { ensure_reversible(MOTUS_VELOCITY_VERLET); }
TEST(reversible_position_verlet) { ensure_reversible(MOTUS_POSITION_VERLET); }
TEST(reversible_forest_ruth) { ensure_reversible(MOTUS_FOREST_RUTH); }
TEST(reversible_mclachlan4) { ensure_reversible(MOTUS_MCLACHLAN4); }

TEST(explicit_euler_is_not_reversible) {
    static const int problems[] = {PROBLEM_HARMONIC_OSCILLATOR, PROBLEM_KEPLER_ECCENTRIC};
    int i;
    for (i = 0; i < 2; ++i) {
        const char *name;
        double bound, error = reversal_error(MOTUS_EXPLICIT_EULER, problems[i], 1000, 2, &bound, &name);
        printf("  reversal explicit_euler   %-20s off by %.3g (bound %.3g)\n", name, error, bound);
        ENSURE(error > 100 * bound);
        ENSURE(error > 0.1); /* not a rounding matter in either build */
    }
}

/* =================================================================================================
   Energy over long runs
   =================================================================================================
   A Kepler orbit of eccentricity e from periapsis (a = 1, mu = 1: E = -1/2), `steps` steps of h. The
   relative energy error |E - E0|/|E0| is recorded over the first orbit, the first 10% and the last 10% of
   the run. A symplectic method's error oscillates with the orbit but does not grow: its largest value in
   the last 10% is that of the first 10%. The bounds are the measured maxima with some room; what the test
   is about is the growth. Alternating 2D and 3D runs (by method). */
typedef struct energy_record {
    double first_orbit, first, last, overall, final_signed;
} energy_record;

static energy_record kepler_energy_of(motus_method method, double eccentricity, double h_double, int steps, int dims) {
    const int window = steps / 10, orbit = (int)(2 * PROBLEM_PI / h_double);
    const motus_real h = (motus_real)h_double;
    problem p;
    run r;
    energy_record rec;
    double e0;
    int i;
    memset(&rec, 0, sizeof rec);
    ENSURE(problem_get(PROBLEM_KEPLER_ECCENTRIC, &p));
    p.start.x = 1 - eccentricity;
    p.start.vy = sqrt((1 + eccentricity) / (1 - eccentricity)); /* vis-viva at periapsis */
    run_problem(&r, &p, method, dims, PATH_ARRAYS);
    e0 = p.energy(run_get(&r, 0)); /* the start as rounded to motus_real */
    for (i = 0; i < steps; ++i) {
        double e;
        if (run_step(&r, h) != MOTUS_OK) {
            ENSURE(!"step failed");
            break;
        }
        e = fabs((p.energy(run_get(&r, 0)) - e0) / e0);
        if (i < orbit && e > rec.first_orbit) rec.first_orbit = e;
        if (i < window && e > rec.first) rec.first = e;
        if (i >= steps - window && e > rec.last) rec.last = e;
        if (e > rec.overall) rec.overall = e;
    }
    rec.final_signed = (p.energy(run_get(&r, 0)) - e0) / e0;
    run_close(&r);
    printf("  energy %-20s e = %.1f h = %.4g %dD: first orbit %.3g, first 10%% %.3g, last 10%% %.3g, max %.3g, "
           "final %+.3g\n", method_name(method), eccentricity, h_double, dims, rec.first_orbit, rec.first,
           rec.last, rec.overall, rec.final_signed);
    return rec;
}

/* e = 0.5 for 10^5 steps of period/200 (500 orbits). */
static energy_record kepler_energy(motus_method method) {
    return kepler_energy_of(method, PROBLEM_ECCENTRICITY, 2 * PROBLEM_PI / 200, 100000, 2 + (int)method % 2);
}

TEST(energy_symplectic_bounded_kepler) {
    static const struct {
        motus_method method;
        double bound;
    } cases[] = {{MOTUS_SEMI_IMPLICIT_EULER, 0.06}, {MOTUS_POSITION_VERLET, 0.003}, {MOTUS_VELOCITY_VERLET, 0.003},
                 {MOTUS_LEAPFROG, 0.003},
#ifdef MOTUS_DOUBLE
                 {MOTUS_FOREST_RUTH, 1.2e-5}, {MOTUS_MCLACHLAN4, 1.2e-6},
#endif
    };
    int i;
    for (i = 0; i < (int)(sizeof cases / sizeof cases[0]); ++i) {
        energy_record r = kepler_energy(cases[i].method);
        ENSURE_NEAR(r.overall, 0, cases[i].bound);
        /* No growth: the last 10% no worse than the first 10%, up to 5% of wobble in the sampling. */
        if (!(r.last <= 1.05 * r.first))
            fprintf(stderr, "  %s energy error grows\n", method_name(cases[i].method));
        ENSURE(r.last <= 1.05 * r.first);
    }
#ifndef MOTUS_DOUBLE
    {
        /* Float: Forest-Ruth's own error (1e-5) is below the rounding drift of 1e5 float steps; bound only. */
        energy_record r = kepler_energy(MOTUS_FOREST_RUTH);
        ENSURE_NEAR(r.overall, 0, 1e-3);
        r = kepler_energy(MOTUS_MCLACHLAN4);
        ENSURE_NEAR(r.overall, 0, 1e-3);
    }
#endif
}

TEST(energy_position_verlet_as_velocity_verlet_kepler) {
    /* Issue 11: on a Kepler orbit of e = 0.6 at h = 0.01, 10^5 steps (159 orbits), the old two-step position
       Verlet's energy error was 4.9e-3, its velocity (x_{n+1} - x_{n-1})/2h out of step with its position.
       Drift-kick-drift reports the synchronised velocity: its error must be at most 1e-3 and no more than
       1.5 times velocity Verlet's (both are the same Stormer-Verlet map, split the other way round). In 2D
       and 3D. */
    int dims;
    for (dims = 2; dims <= 3; ++dims) {
        energy_record pv = kepler_energy_of(MOTUS_POSITION_VERLET, 0.6, 0.01, 100000, dims);
        energy_record vv = kepler_energy_of(MOTUS_VELOCITY_VERLET, 0.6, 0.01, 100000, dims);
        printf("  issue 11, %dD: position Verlet %.3g, velocity Verlet %.3g, ratio %.3f\n", dims, pv.overall,
               vv.overall, pv.overall / vv.overall);
        ENSURE(pv.overall <= 1e-3);
        ENSURE(pv.overall <= 1.5 * vv.overall);
        /* And it does not grow, beyond float's rounding: a random walk of about eps per step (measured in
           float: 1.45e-4 in the first 10%, 1.72e-4 in the last; in double 1.28e-4 in both). */
        ENSURE(pv.last <= 1.05 * pv.first + 2 * sqrt(100000.0) * EPS);
    }
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
   stepper: each step computes decay, c1, c2 to a few eps and rounds x and v, at most k = 8 roundings
   of eps/2 relative to |x| and |v|*h: the same n*k*(eps/2)*(max|x| + max|v|*t) as the oracles. The
   closed form (double in both builds) has its own rounding: problem_linear_drag_exact forms 1 - e^-kt,
   which for small kt keeps only an absolute DBL_EPSILON of it, times |v0 - v_inf|/k (= 64 m) in x and
   |v0 - v_inf| in v; that is allowed for too (4 DBL_EPSILON of each). 2D and 3D, every path. */
TEST(exact_stepper_matches_closed_form_at_any_dt) {
    static const double dts[] = {1e-3, 1.0 / 60, 0.1, 0.5, 2};
    const double k_drag = PROBLEM_DRAG, v_inf = PROBLEM_G / PROBLEM_DRAG;
    problem p;
    double reference_x, reference_v;
    int k, dims, path;
    ENSURE(problem_get(PROBLEM_GRAVITY_LINEAR_DRAG, &p));
    reference_v = 4 * DBL_EPSILON * hypot(p.start.vx, p.start.vy + v_inf);
    reference_x = reference_v / k_drag;
    for (k = 0; k < 5; ++k)
        for (dims = 2; dims <= 3; ++dims)
            for (path = 0; path < PATH_COUNT; ++path) {
                run r;
                const motus_real h = (motus_real)dts[k];
                const int steps = (int)floor(p.duration / dts[k] + 0.5);
                double max_x = 0, max_v = 0, worst = 0;
                int i;
                run_problem(&r, &p, MOTUS_EXACT_LINEAR_DRAG, dims, path);
                ENSURE_EQ_INT(r.scene.method, MOTUS_EXACT_LINEAR_DRAG);
                for (i = 1; i <= steps; ++i) {
                    const double t = (double)i * (double)h;
                    problem_state e, s;
                    double bound_x, bound_v, error_x, error_v;
                    ENSURE_EQ_INT(run_step(&r, h), path == PATH_COUPLED ? MOTUS_ERROR_UNSUPPORTED : MOTUS_OK);
                    if (path == PATH_COUPLED) break; /* the exact stepper takes no callback */
                    e = p.exact(t);
                    s = run_get(&r, 0);
                    if (hypot(e.x, e.y) > max_x) max_x = hypot(e.x, e.y);
                    if (hypot(e.vx, e.vy) > max_v) max_v = hypot(e.vx, e.vy);
                    bound_x = i * 8 * (EPS / 2) * (max_x + max_v * t) + reference_x;
                    bound_v = i * 8 * (EPS / 2) * max_v + reference_v;
                    error_x = hypot(s.x - e.x, s.y - e.y) / bound_x;
                    error_v = hypot(s.vx - e.vx, s.vy - e.vy) / bound_v;
                    if (error_x > worst) worst = error_x;
                    if (error_v > worst) worst = error_v;
                }
                if (path != PATH_COUPLED)
                    printf("  exact stepper dt = %-9g %4d steps %dD %-9s: largest error %.3f of the bound, state "
                           "error at 2 s %.3g\n", dts[k], steps, dims, PATH_NAMES[path], worst,
                           state_error(&r, p.exact((double)steps * (double)h)));
                ENSURE(worst <= 1);
                run_close(&r);
            }
}

static const motus_test_case TESTS[] = {
    TEST_CASE(paths_agree_semi_implicit_euler),
    TEST_CASE(paths_agree_explicit_euler),
    TEST_CASE(paths_agree_position_verlet),
    TEST_CASE(paths_agree_velocity_verlet),
    TEST_CASE(paths_agree_leapfrog),
    TEST_CASE(paths_agree_midpoint),
    TEST_CASE(paths_agree_rk4),
    TEST_CASE(paths_agree_forest_ruth),
    TEST_CASE(paths_agree_mclachlan4),
    TEST_CASE(paths_agree_exact_linear_drag),
    TEST_CASE(substeps_equal_steps_of_dt_over_n),
    TEST_CASE(order_table),
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
    TEST_CASE(order_mclachlan4),
    TEST_CASE(order_mclachlan4_drag_is_first_order),
    TEST_CASE(spring_to_an_anchor_off_the_origin),
    TEST_CASE(tether_off_the_origin),
    TEST_CASE(tether_and_anchored_spring_agree),
    TEST_CASE(oracle_explicit_euler),
    TEST_CASE(oracle_semi_implicit_euler),
    TEST_CASE(oracle_position_verlet),
    TEST_CASE(oracle_velocity_verlet),
    TEST_CASE(oracle_leapfrog),
    TEST_CASE(oracle_midpoint),
    TEST_CASE(oracle_rk4),
    TEST_CASE(oracle_forest_ruth),
    TEST_CASE(oracle_mclachlan4),
    TEST_CASE(oracle_exact_linear_drag),
    TEST_CASE(oracle_varying_dt),
    TEST_CASE(reversible_leapfrog),
    TEST_CASE(reversible_velocity_verlet),
    TEST_CASE(reversible_position_verlet),
    TEST_CASE(reversible_forest_ruth),
    TEST_CASE(reversible_mclachlan4),
    TEST_CASE(explicit_euler_is_not_reversible),
    TEST_CASE(energy_symplectic_bounded_kepler),
    TEST_CASE(energy_position_verlet_as_velocity_verlet_kepler),
    TEST_CASE(energy_explicit_euler_grows_kepler),
    TEST_CASE(energy_rk4_and_midpoint_drift_kepler),
    TEST_CASE(exact_stepper_matches_closed_form_at_any_dt),
};

int main(int argc, char **argv) { return motus_test_main(argc, argv, TESTS, TEST_COUNT(TESTS)); }
