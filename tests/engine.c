/* The engine's kernels against each other and against the particle functions, bit for bit.

   For every method, 2D and 3D, and every combination of the scene's terms (gravity, linear drag, quadratic
   drag, attractor, tether, damping none / per step / per second, bounds with restitution, an accumulated force
   array or none, an inverse_mass array with immovable particles or scene.mass, 1 to 3 substeps), over
   random particles (-0 velocity and force components included, one particle on the attractor), the same
   scene is stepped five ways and every way must hold the same bits after every step:
     1. plain arrays (SoA) through motus_step;
     2. the same particles as motus_particle / motus_particle3 structs (motus_state_of_particles: strided);
     3. motus_step_range over random splits of [0, count), in a random order;
     4. a force_callback that adds nothing (the coupled staged path, scratch of motus_scratch_size);
     5. counts 1, 3, 7, 17, 33 and 1000, not multiples of any lane width (and each count's particles end
        where the same particles end in a 1000-particle state, and where each ends stepped alone).
   Also: motus_particle_step / motus_particle3_step equal a zeroed scene on accumulated forces (-0 and
   immovable included), step + bounce + damp equal a scene with bounds and damping, and springs through
   the coupled path equal a hand-written force callback with the same Hooke + damping formula.
   Built in float and double, with MOTUS_CHECKED, and at every lane width (MOTUS_NO_SIMD, 32-byte lanes,
   -mavx2, -march=native, clang): `motus_engine --dump` prints a digest of the end state of a fixed set of
   scenes, which must be the same in every build (compile.engine.agree.*, compile.engine.clang.*). */
#define MOTUS_IMPLEMENTATION
#define MOTUS_STATIC
#include "motus.h"
#include "support/motus_test.h"

#include <float.h>

#include <stdint.h>
#include <stdlib.h>

enum { MAX = 1000, STEPS = 5 };
static const int COUNTS[] = {1, 3, 7, 17, 33, 1000};
enum { COUNT_KINDS = (int)(sizeof COUNTS / sizeof COUNTS[0]) };

/* The scene's terms, one bit each (damping has three values: none, per step, per second). */
enum {
    T_GRAVITY = 1 << 0,
    T_LINEAR_DRAG = 1 << 1,
    T_QUADRATIC_DRAG = 1 << 2,
    T_ATTRACTOR = 1 << 3,
    T_BOUNDS = 1 << 4,
    T_FORCES = 1 << 5,
    T_MASS = 1 << 6,
    T_TETHER = 1 << 7,
    T_ALL = (1 << 8) - 1
};
enum { DAMP_NONE, DAMP_PER_STEP, DAMP_PER_SECOND, DAMP_KINDS };

/* ---- random numbers: xorshift32, the same sequence in every build ---- */
static uint32_t random_state = 1;
static uint32_t random_next(void) { return motus_test_xorshift32(&random_state); }
static void random_seed(uint32_t seed) { random_state = seed * 2654435761u + 12345u; if (!random_state) random_state = 1; }
static double random_unit(void) { return (double)(random_next() >> 8) / 16777216.0; }
static motus_real random_real(double lo, double hi) { return (motus_real)(lo + (hi - lo) * random_unit()); }
static int random_int(int n) { return (int)(random_next() % (uint32_t)n); }
/* A value in [lo, hi], or a zero of either sign one time in eight. */
static motus_real random_or_zero(double lo, double hi) {
    if (random_int(8) == 0) return random_int(2) ? -(motus_real)0 : (motus_real)0;
    return random_real(lo, hi);
}

/* Three values in x, y, z order (one statement each: the order of a call's arguments is unspecified, and
   GCC and Clang differ, so motus_v3(random(), random(), random()) would be another scene in a Clang build). */
static motus_vec3 random_vec3(double lo, double hi) {
    motus_vec3 v;
    v.x = random_real(lo, hi);
    v.y = random_real(lo, hi);
    v.z = random_real(lo, hi);
    return v;
}
static motus_vec3 random_vec3_or_zero(double lo, double hi) {
    motus_vec3 v;
    v.x = random_or_zero(lo, hi);
    v.y = random_or_zero(lo, hi);
    v.z = random_or_zero(lo, hi);
    return v;
}

/* ---- particles as plain arrays ---- */
typedef struct soa {
    motus_real x[3][MAX], v[3][MAX], f[3][MAX], w[MAX];
} soa;

static uint64_t bits_of(motus_real r) {
    uint64_t b = 0;
    memcpy(&b, &r, sizeof r);
    return b;
}

/* Random particles: positions partly outside the walls; with on_attractor (a state with inverse masses),
   one immovable particle at rest exactly on the attractor. */
static void fill_particles(soa *p, int count, const motus_scene *scene, int on_attractor) {
    const motus_real at[3] = {scene->attractor.x, scene->attractor.y, scene->attractor.z};
    int i, d;
    for (i = 0; i < count; ++i) {
        motus_real r2;
        do { /* not within 2.5 m of the attractor, whose pull there would make any method blow up */
            r2 = 0;
            for (d = 0; d < 3; ++d) {
                p->x[d][i] = random_real(-12, 12);
                if (d < 2) r2 += (p->x[d][i] - at[d]) * (p->x[d][i] - at[d]); /* in the plane: 2D and 3D */
            }
        } while (r2 < MOTUS_R(6.25));
        for (d = 0; d < 3; ++d) {
            p->v[d][i] = random_or_zero(-5, 5);
            p->f[d][i] = random_or_zero(-3, 3);
        }
        p->w[i] = random_int(6) == 0 ? 0 : random_real(0.25, 4);
    }
    if (count > 2 && on_attractor) { /* at rest there and immovable: the kernels' no-pull-at-the-centre case */
        for (d = 0; d < 3; ++d) p->x[d][count / 2] = at[d], p->v[d][count / 2] = 0;
        p->w[count / 2] = 0;
    }
}

static motus_state soa_state(soa *p, int dims, int count, unsigned terms) {
    motus_state s;
    int d;
    memset(&s, 0, sizeof s);
    s.dimensions = dims;
    s.count = count;
    for (d = 0; d < dims; ++d) {
        s.position[d] = p->x[d];
        s.velocity[d] = p->v[d];
        if (terms & T_FORCES) s.force[d] = p->f[d];
    }
    if (terms & T_MASS) s.inverse_mass = p->w;
    return s;
}

/* The same particles as structs, and back. */
static motus_particle P2[MAX];
static motus_particle3 P3[MAX];
static void to_structs(const soa *p, int dims, int count) {
    int i;
    for (i = 0; i < count; ++i)
        if (dims == 2) {
            P2[i].position = motus_v2(p->x[0][i], p->x[1][i]);
            P2[i].velocity = motus_v2(p->v[0][i], p->v[1][i]);
            P2[i].force = motus_v2(p->f[0][i], p->f[1][i]);
            P2[i].inverse_mass = p->w[i];
        } else {
            P3[i].position = motus_v3(p->x[0][i], p->x[1][i], p->x[2][i]);
            P3[i].velocity = motus_v3(p->v[0][i], p->v[1][i], p->v[2][i]);
            P3[i].force = motus_v3(p->f[0][i], p->f[1][i], p->f[2][i]);
            P3[i].inverse_mass = p->w[i];
        }
}
static void from_structs(soa *p, int dims, int count) {
    int i;
    for (i = 0; i < count; ++i)
        if (dims == 2) {
            p->x[0][i] = P2[i].position.x, p->x[1][i] = P2[i].position.y;
            p->v[0][i] = P2[i].velocity.x, p->v[1][i] = P2[i].velocity.y;
        } else {
            p->x[0][i] = P3[i].position.x, p->x[1][i] = P3[i].position.y, p->x[2][i] = P3[i].position.z;
            p->v[0][i] = P3[i].velocity.x, p->v[1][i] = P3[i].velocity.y, p->v[2][i] = P3[i].velocity.z;
        }
}
static motus_state struct_state(int dims, int count, unsigned terms) {
    motus_state s = dims == 2 ? motus_state_of_particles(P2, count) : motus_state_of_particles3(P3, count);
    int d;
    if (!(terms & T_FORCES))
        for (d = 0; d < 3; ++d) s.force[d] = NULL;
    if (!(terms & T_MASS)) s.inverse_mass = NULL;
    return s;
}

/* ---- comparisons ---- */
static int differences_printed, quiet;
/* Positions and velocities of particles [0, count) of b equal a's (offset: b's particle i is a's i + offset),
   bit for bit. Prints the first few differences. */
static int same_state(const soa *a, const soa *b, int dims, int count, int offset, const char *what, int step) {
    int i, d;
    for (d = 0; d < dims; ++d)
        for (i = 0; i < count; ++i) {
            const motus_real pairs[2][2] = {{a->x[d][i + offset], b->x[d][i]}, {a->v[d][i + offset], b->v[d][i]}};
            int k;
            for (k = 0; k < 2; ++k)
                if (bits_of(pairs[k][0]) != bits_of(pairs[k][1])) {
                    if (!quiet && differences_printed++ < 10)
                        fprintf(stderr, "%s, step %d: particle %d %s[%d] = %.9g (0x%llx), expected %.9g (0x%llx)\n",
                                what, step, i, k ? "velocity" : "position", d, (double)pairs[k][1],
                                (unsigned long long)bits_of(pairs[k][1]), (double)pairs[k][0],
                                (unsigned long long)bits_of(pairs[k][0]));
                    return 0;
                }
        }
    return 1;
}

/* ---- scenes ---- */
typedef struct setup {
    motus_method method;
    int dims, count, damping, substeps;
    unsigned terms;
    motus_real dt;
} setup;

static const char *describe(const setup *s) {
    static char text[160];
    snprintf(text, sizeof text, "%s %dD count %d terms 0x%02x damping %d substeps %d", motus_method_name(s->method),
             s->dims, s->count, s->terms, s->damping, s->substeps);
    return text;
}

static void make_scene(motus_scene *scene, const setup *s) {
    memset(scene, 0, sizeof *scene);
    scene->method = s->method;
    scene->substeps = s->substeps == 1 && random_int(2) ? 0 : s->substeps; /* 0 and 1: one step */
    /* beside the particles and the walls (|x| >= 13 m): a wall's mirror could otherwise put one next to it */
    scene->attractor = random_vec3(-5, 5);
    scene->attractor.x = (scene->attractor.x < 0 ? -13 : 13) + scene->attractor.x * MOTUS_R(0.6);
    if (s->terms & T_GRAVITY) scene->gravity = random_vec3(-10, 10);
    if (s->terms & T_LINEAR_DRAG) scene->linear_drag = random_real(0.05, 1);
    if (s->terms & T_QUADRATIC_DRAG) scene->quadratic_drag = random_real(0.01, 0.2);
    if (s->terms & T_ATTRACTOR) scene->attractor_strength = random_real(1, 50);
    if (s->terms & T_TETHER) {
        scene->tether = random_vec3(-5, 5);
        scene->tether_stiffness = random_real(0.5, 20);
    }
    if (s->damping == DAMP_PER_STEP) scene->damping_per_step = random_real(0, 0.1);
    if (s->damping == DAMP_PER_SECOND) scene->damping_per_second = random_real(0, 0.6);
    if (s->terms & T_BOUNDS) {
        scene->bounds_min = random_vec3(-11, -6);
        scene->bounds_max = random_vec3(6, 11);
        if (random_int(4) == 0) scene->bounds_max.y = (motus_real)HUGE_VAL; /* no wall on that side */
        if (random_int(4) == 0) scene->bounds_min.x = -(motus_real)HUGE_VAL;
        scene->restitution = random_int(5) == 0 ? (motus_real)random_int(2) : random_real(0, 1);
    }
    scene->mass = random_int(3) == 0 ? 0 : random_real(0.5, 3); /* used where there is no inverse_mass array */
}

/* A callback that adds nothing, but checks what it is handed. */
typedef struct noop_record {
    int dims, count, evaluations;
    long calls, bad;
} noop_record;
static void noop_callback(void *user_data, const motus_force_query *q) {
    noop_record *r = (noop_record *)user_data;
    int d, i;
    r->calls++;
    if (q->dimensions != r->dims || q->count != r->count || q->stage < 0 || q->stage >= r->evaluations ||
        !(q->time >= 0))
        r->bad++;
    for (d = 0; d < 3; ++d) {
        if ((d < r->dims) != (q->position[d] != NULL) || (d < r->dims) != (q->force[d] != NULL)) r->bad++;
        for (i = 0; d < r->dims && q->force[d] && i < q->count; ++i)
            if (q->force[d][i] != 0) r->bad++; /* forces start at zero */
    }
}

/* 3D, McLachlan's method: (2 + 5) * 3 reals a particle, + 11 for the checked copy; contacts: 64 reals and 44 ints a particle
   (two pair lists), and the table and bins */
static motus_real SCRATCH[(3 * 7 + 11 + 64 + 44 * 2) * MAX + 16384];
static soa A, B, C, D, E;

/* Splits [0, count) into 1..5 ranges (some may be empty) and steps them in a random order. */
static motus_result step_in_ranges(const motus_scene *scene, const motus_state *state, int count, motus_real dt) {
    int cuts[6], pieces = 1 + random_int(5), k, order[5], j;
    motus_result result = MOTUS_OK;
    cuts[0] = 0;
    cuts[pieces] = count;
    for (k = 1; k < pieces; ++k) cuts[k] = random_int(count + 1);
    for (k = 1; k < pieces; ++k) /* sort the inner cuts */
        for (j = k + 1; j < pieces; ++j)
            if (cuts[j] < cuts[k]) {
                const int t = cuts[j];
                cuts[j] = cuts[k];
                cuts[k] = t;
            }
    for (k = 0; k < pieces; ++k) order[k] = k;
    for (k = pieces - 1; k > 0; --k) {
        const int other = random_int(k + 1), t = order[k];
        order[k] = order[other];
        order[other] = t;
    }
    for (k = 0; k < pieces && result == MOTUS_OK; ++k)
        result = motus_step_range(scene, state, cuts[order[k]], cuts[order[k] + 1] - cuts[order[k]], dt);
    return result;
}

/* Steps one random scene STEPS times in every way; returns 1 if all agree after every step. */
static int paths_agree(const setup *s, uint32_t seed) {
    motus_scene scene, with_callback;
    motus_state sa, sb, sc, sd;
    noop_record record;
    size_t scratch_bytes, stage_length;
    int step, ok = 1, unsupported;
    char what[240];
    random_seed(seed);
    make_scene(&scene, s);
    fill_particles(&A, s->count, &scene, (s->terms & T_MASS) != 0);
    memcpy(&C, &A, sizeof A);
    memcpy(&D, &A, sizeof A);
    to_structs(&A, s->dims, s->count);
    sa = soa_state(&A, s->dims, s->count, s->terms);
    sb = struct_state(s->dims, s->count, s->terms);
    sc = soa_state(&C, s->dims, s->count, s->terms);
    sd = soa_state(&D, s->dims, s->count, s->terms);
    with_callback = scene;
    with_callback.force_callback = noop_callback;
    with_callback.user_data = &record;
    record.dims = s->dims, record.count = s->count, record.calls = 0, record.bad = 0;
    record.evaluations = motus_method_evaluations(s->method);
    scratch_bytes = motus_scratch_size(&with_callback, &sd);
    /* the stage arrays hold whole groups of lanes: the count rounded up to a multiple of MOTUS__LANES */
    stage_length = ((size_t)s->count + (size_t)MOTUS__LANES - 1) / (size_t)MOTUS__LANES * (size_t)MOTUS__LANES;
    ENSURE(scratch_bytes <= sizeof SCRATCH);
#ifdef MOTUS_CHECKED /* and a copy of the state to step (positions, velocities, forces, inverse masses) */
    ENSURE(scratch_bytes == (size_t)s->dims * (size_t)(2 + record.evaluations) * sizeof(motus_real) * stage_length +
                                (size_t)(3 * s->dims + 1) * sizeof(motus_real) * (size_t)s->count);
#else
    ENSURE(scratch_bytes == (size_t)s->dims * (size_t)(2 + record.evaluations) * sizeof(motus_real) * stage_length);
#endif
    /* the exact stepper takes no quadratic drag, attractor or callback */
    unsupported = s->method == MOTUS_EXACT_LINEAR_DRAG && (s->terms & (T_QUADRATIC_DRAG | T_ATTRACTOR | T_TETHER));
    if (unsupported) {
        ENSURE_EQ_INT(motus_step(&scene, &sa, s->dt, NULL, 0), MOTUS_ERROR_UNSUPPORTED);
        ENSURE_EQ_INT(motus_step_range(&scene, &sa, 0, s->count, s->dt), MOTUS_ERROR_UNSUPPORTED);
        return 1;
    }
    ENSURE_EQ_INT(motus_scene_check(&scene, s->dims, s->count, NULL), MOTUS_OK);
    for (step = 1; step <= STEPS && ok; ++step) {
        motus_result r1 = motus_step(&scene, &sa, s->dt, NULL, 0);
        motus_result r2 = motus_step(&scene, &sb, s->dt, NULL, 0);
        motus_result r3 = step_in_ranges(&scene, &sc, s->count, s->dt);
        motus_result r4 = motus_step(&with_callback, &sd, s->dt, SCRATCH, scratch_bytes);
        ENSURE_EQ_INT(r1, MOTUS_OK);
        ENSURE_EQ_INT(r2, MOTUS_OK);
        ENSURE_EQ_INT(r3, MOTUS_OK);
        if (s->method == MOTUS_EXACT_LINEAR_DRAG) ENSURE_EQ_INT(r4, MOTUS_ERROR_UNSUPPORTED);
        else ENSURE_EQ_INT(r4, MOTUS_OK);
        ok = r1 == MOTUS_OK && r2 == MOTUS_OK && r3 == MOTUS_OK;
        if (!ok) {
            motus_check_report report;
            fprintf(stderr, "%s, step %d: %s\n", describe(s), step, motus_result_string(r1));
            if (motus_state_check(&scene, &sa, 0, s->count, &report) != MOTUS_OK)
                fprintf(stderr, "  particle %d: %s[%d] (inverse mass %g)\n", report.index, report.field_name,
                        report.component, (double)A.w[report.index]);
        }
        from_structs(&B, s->dims, s->count);
        snprintf(what, sizeof what, "%s: structs (stride %d)", describe(s), (int)sb.stride);
        ok &= same_state(&A, &B, s->dims, s->count, 0, what, step);
        snprintf(what, sizeof what, "%s: ranges", describe(s));
        ok &= same_state(&A, &C, s->dims, s->count, 0, what, step);
        if (s->method != MOTUS_EXACT_LINEAR_DRAG) {
            snprintf(what, sizeof what, "%s: callback that adds nothing", describe(s));
            ok &= same_state(&A, &D, s->dims, s->count, 0, what, step);
        }
    }
    if (s->method != MOTUS_EXACT_LINEAR_DRAG && ok) {
        const int substeps = s->substeps > 1 ? s->substeps : 1;
        ENSURE_EQ_INT(record.calls, (long)STEPS * substeps * record.evaluations);
        ENSURE_EQ_INT(record.bad, 0);
    }
    ENSURE(ok);
    return ok;
}

/* Every combination of the terms, damping kinds and substeps, for one method in 2D and 3D. The counts
   cycle through 1, 3, 7, 17, 33 (coprime to the 3 substeps, so every pair occurs); every 16th scene also
   runs 1000 particles. */
static void every_combination(motus_method method) {
    const motus_real dt = (motus_real)(1.0 / 60.0);
    int dims, terms, damping, substeps, scenes = 0, failed = 0;
    for (dims = 2; dims <= 3; ++dims)
        for (terms = 0; terms <= T_ALL; ++terms)
            for (damping = 0; damping < DAMP_KINDS; ++damping)
                for (substeps = 1; substeps <= 3; ++substeps) {
                    setup s;
                    s.method = method, s.dims = dims, s.terms = (unsigned)terms, s.damping = damping;
                    s.substeps = substeps, s.dt = dt;
                    s.count = COUNTS[scenes % (COUNT_KINDS - 1)];
                    if (!paths_agree(&s, (uint32_t)scenes * 7919u + (uint32_t)method)) failed++;
                    if (scenes % 16 == 0) {
                        s.count = MAX;
                        if (!paths_agree(&s, (uint32_t)scenes * 7919u + 1u)) failed++;
                    }
                    scenes++;
                    if (failed > 3) return; /* enough to see the pattern */
                }
    printf("%s: %d scenes, every way the same bits after every step\n", motus_method_name(method), scenes);
}

TEST(paths_agree_semi_implicit_euler) { every_combination(MOTUS_SEMI_IMPLICIT_EULER); }
TEST(paths_agree_explicit_euler) { every_combination(MOTUS_EXPLICIT_EULER); }
TEST(paths_agree_position_verlet) { every_combination(MOTUS_POSITION_VERLET); }
TEST(paths_agree_velocity_verlet) { every_combination(MOTUS_VELOCITY_VERLET); }
TEST(paths_agree_leapfrog) { every_combination(MOTUS_LEAPFROG); }
TEST(paths_agree_midpoint) { every_combination(MOTUS_MIDPOINT); }
TEST(paths_agree_rk4) { every_combination(MOTUS_RK4); }
TEST(paths_agree_forest_ruth) { every_combination(MOTUS_FOREST_RUTH); }
TEST(paths_agree_mclachlan4) { every_combination(MOTUS_MCLACHLAN4); }
TEST(paths_agree_exact_linear_drag) { every_combination(MOTUS_EXACT_LINEAR_DRAG); }

/* Each count's particles end where the same particles end in a 1000-particle state, and where each one
   ends when stepped alone (a state of count 1 at its address): no lane, group or tail changes a bit. */
TEST(counts_do_not_change_results) {
    int method, dims, k, i, d, step, ok = 1;
    for (method = 0; method < MOTUS_METHOD_COUNT && ok; ++method)
        for (dims = 2; dims <= 3 && ok; ++dims) {
            setup s;
            motus_scene scene;
            motus_state full, part, alone;
            s.method = (motus_method)method, s.dims = dims, s.damping = DAMP_PER_SECOND, s.substeps = 2;
            s.terms = T_ALL, s.dt = (motus_real)(1.0 / 50.0), s.count = MAX;
            if (method == MOTUS_EXACT_LINEAR_DRAG) s.terms &= ~(unsigned)(T_QUADRATIC_DRAG | T_ATTRACTOR | T_TETHER);
            random_seed(1000u + (uint32_t)(method * 2 + dims));
            make_scene(&scene, &s);
            fill_particles(&D, MAX, &scene, 1); /* the start, kept */
            memcpy(&A, &D, sizeof D);
            full = soa_state(&A, dims, MAX, s.terms);
            for (step = 1; step <= STEPS; ++step) ENSURE_EQ_INT(motus_step(&scene, &full, s.dt, NULL, 0), MOTUS_OK);
            for (k = 0; k < COUNT_KINDS; ++k) {
                char what[240];
                memcpy(&B, &D, sizeof D);
                memcpy(&E, &D, sizeof D);
                part = soa_state(&B, dims, COUNTS[k], s.terms);
                for (step = 1; step <= STEPS; ++step) {
                    ENSURE_EQ_INT(motus_step(&scene, &part, s.dt, NULL, 0), MOTUS_OK);
                    if (COUNTS[k] > 33) continue;
                    for (i = 0; i < COUNTS[k]; ++i) { /* one at a time */
                        alone = soa_state(&E, dims, 1, s.terms);
                        for (d = 0; d < dims; ++d) {
                            alone.position[d] += i, alone.velocity[d] += i;
                            if (alone.force[d]) alone.force[d] += i;
                        }
                        if (alone.inverse_mass) alone.inverse_mass += i;
                        ENSURE_EQ_INT(motus_step(&scene, &alone, s.dt, NULL, 0), MOTUS_OK);
                    }
                    snprintf(what, sizeof what, "%s: one at a time", describe(&s));
                    ok &= same_state(&B, &E, dims, COUNTS[k], 0, what, step);
                }
                snprintf(what, sizeof what, "%s: count %d against the first of 1000", describe(&s), COUNTS[k]);
                ok &= same_state(&A, &B, dims, COUNTS[k], 0, what, STEPS);
                quiet = 1; /* and it did move */
                ok &= !same_state(&D, &B, dims, COUNTS[k], 0, "", STEPS);
                quiet = 0;
            }
        }
    ENSURE(ok);
}

/* ---- the particle functions ---- */
/* motus_particle_step (motus_particle3_step) on accumulated forces equals motus_step of a zeroed scene
   (semi-implicit Euler, no terms) over the same structs, bit for bit: -0 velocity and force components,
   immovable particles, forces changed every step, dt 0 a step of nothing. */
TEST(particle_step_equals_zeroed_scene) {
    enum { N = 37, PARTICLE_STEPS = 40 };
    static motus_particle a2[N], b2[N];
    static motus_particle3 a3[N], b3[N];
    motus_scene zero;
    int dims, i, step, negative_zeros = 0, immovable = 0, still_at_minus_zero = 0;
    memset(&zero, 0, sizeof zero);
    random_seed(77);
    for (dims = 2; dims <= 3; ++dims) {
        motus_state state = dims == 2 ? motus_state_of_particles(b2, N) : motus_state_of_particles3(b3, N);
        for (i = 0; i < N; ++i) {
            const motus_real w = i % 5 == 2 ? 0 : random_real(0.1, 10);
            motus_vec3 x = random_vec3(-50, 50);
            motus_vec3 v = random_vec3_or_zero(-5, 5);
            if (i == 2) x.x = x.z = v.x = v.z = -(motus_real)0; /* immovable (i % 5 == 2), at -0 drifting at -0 */
            if (dims == 2) {
                a2[i].position = motus_v2(x.x, x.y), a2[i].velocity = motus_v2(v.x, v.y), a2[i].inverse_mass = w;
            } else {
                a3[i].position = x, a3[i].velocity = v, a3[i].inverse_mass = w;
            }
            immovable += w == 0;
        }
        for (step = 0; step < PARTICLE_STEPS; ++step) {
            const motus_real dt = step % 13 == 5 ? 0 : random_real(0.001, 0.05);
            for (i = 0; i < N; ++i) {
                motus_vec3 f = random_vec3_or_zero(-20, 20);
                if (dims == 2) {
                    a2[i].force = motus_v2(f.x, f.y);
                    negative_zeros += bits_of(a2[i].velocity.x) == bits_of(-(motus_real)0);
                    still_at_minus_zero += a2[i].inverse_mass == 0 &&
                                           bits_of(a2[i].position.x) == bits_of(-(motus_real)0) &&
                                           bits_of(a2[i].velocity.x) == bits_of(-(motus_real)0);
                } else {
                    a3[i].force = f;
                    negative_zeros += bits_of(a3[i].velocity.z) == bits_of(-(motus_real)0);
                    still_at_minus_zero += a3[i].inverse_mass == 0 &&
                                           bits_of(a3[i].position.z) == bits_of(-(motus_real)0) &&
                                           bits_of(a3[i].velocity.z) == bits_of(-(motus_real)0);
                }
            }
            if (dims == 2) memcpy(b2, a2, sizeof a2);
            else memcpy(b3, a3, sizeof a3);
            for (i = 0; i < N; ++i)
                ENSURE_EQ_INT(dims == 2 ? motus_particle_step(&a2[i], dt) : motus_particle3_step(&a3[i], dt), MOTUS_OK);
            ENSURE_EQ_INT(motus_step(&zero, &state, dt, NULL, 0), MOTUS_OK);
            if (dims == 2) ENSURE(memcmp(a2, b2, sizeof a2) == 0);
            else ENSURE(memcmp(a3, b3, sizeof a3) == 0);
            if (dims == 2 ? memcmp(a2, b2, sizeof a2) != 0 : memcmp(a3, b3, sizeof a3) != 0) {
                fprintf(stderr, "%dD, step %d (dt %g): the particle functions and the scene differ\n", dims, step,
                        (double)dt);
                return;
            }
        }
    }
    printf("%d immovable particles, %d -0 velocity components seen, %d steps of an immovable one at x = -0, "
           "v = -0\n", immovable, negative_zeros, still_at_minus_zero);
    ENSURE(immovable > 0 && negative_zeros > 0 && still_at_minus_zero > 0); /* the cases this test is for did occur */
}

/* motus_particle_step, then motus_particle_bounce, then motus_particle_damp_per_step (per_second) equal a
   scene with only bounds and damping (the engine's order: method, walls, damping). */
TEST(particle_functions_equal_scene_with_bounds_and_damping) {
    enum { N = 29, PARTICLE_STEPS = 60 };
    static motus_particle a2[N], b2[N];
    static motus_particle3 a3[N], b3[N];
    int dims, kind, i, step, bounces = 0;
    random_seed(99);
    for (dims = 2; dims <= 3; ++dims)
        for (kind = DAMP_PER_STEP; kind <= DAMP_PER_SECOND; ++kind) {
            motus_scene scene;
            motus_state state = dims == 2 ? motus_state_of_particles(b2, N) : motus_state_of_particles3(b3, N);
            const motus_real dt = (motus_real)(1.0 / 30.0);
            memset(&scene, 0, sizeof scene);
            scene.bounds_min = motus_v3(-4, -3, -2);
            scene.bounds_max = motus_v3(4, 3, 2);
            scene.restitution = MOTUS_R(0.625);
            if (kind == DAMP_PER_STEP) scene.damping_per_step = MOTUS_R(0.02);
            else scene.damping_per_second = MOTUS_R(0.3);
            for (i = 0; i < N; ++i) {
                const motus_vec3 u = random_vec3(-1, 1), x = motus_v3(u.x * 4, u.y * 3, u.z * 2);
                const motus_vec3 v = random_vec3_or_zero(-30, 30);
                const motus_vec3 f = random_vec3_or_zero(-9, 9);
                const motus_real w = i % 7 == 3 ? 0 : random_real(0.5, 2);
                if (dims == 2) {
                    a2[i].position = motus_v2(x.x, x.y), a2[i].velocity = motus_v2(v.x, v.y);
                    a2[i].force = motus_v2(f.x, f.y), a2[i].inverse_mass = w;
                } else {
                    a3[i].position = x, a3[i].velocity = v, a3[i].force = f, a3[i].inverse_mass = w;
                }
            }
            memcpy(b2, a2, sizeof a2);
            memcpy(b3, a3, sizeof a3);
            for (step = 0; step < PARTICLE_STEPS; ++step) {
                for (i = 0; i < N; ++i)
                    if (dims == 2) {
                        const motus_vec2 v0 = a2[i].velocity;
                        ENSURE_EQ_INT(motus_particle_step(&a2[i], dt), MOTUS_OK);
                        ENSURE_EQ_INT(motus_particle_bounce(&a2[i], motus_v2(-4, -3), motus_v2(4, 3), scene.restitution),
                                      MOTUS_OK);
                        ENSURE_EQ_INT(kind == DAMP_PER_STEP ? motus_particle_damp_per_step(&a2[i], scene.damping_per_step)
                                                            : motus_particle_damp_per_second(&a2[i], scene.damping_per_second, dt),
                                      MOTUS_OK);
                        bounces += (a2[i].velocity.x < 0) != (v0.x < 0);
                    } else {
                        ENSURE_EQ_INT(motus_particle3_step(&a3[i], dt), MOTUS_OK);
                        ENSURE_EQ_INT(motus_particle3_bounce(&a3[i], scene.bounds_min, scene.bounds_max, scene.restitution),
                                      MOTUS_OK);
                        ENSURE_EQ_INT(kind == DAMP_PER_STEP ? motus_particle3_damp_per_step(&a3[i], scene.damping_per_step)
                                                            : motus_particle3_damp_per_second(&a3[i], scene.damping_per_second, dt),
                                      MOTUS_OK);
                    }
                ENSURE_EQ_INT(motus_step(&scene, &state, dt, NULL, 0), MOTUS_OK);
                if (dims == 2 ? memcmp(a2, b2, sizeof a2) != 0 : memcmp(a3, b3, sizeof a3) != 0) {
                    fprintf(stderr, "%dD damping kind %d, step %d: the particle functions and the scene differ\n", dims,
                            kind, step);
                    ENSURE(0);
                    return;
                }
            }
        }
    printf("%d bounces seen\n", bounces);
    ENSURE(bounces > 10);
}

/* ---- springs: the engine's against the same formula in a force callback ---- */
typedef struct spring_set {
    const motus_spring *springs;
    int count;
} spring_set;

/* motus_spring's formula, written as the engine evaluates it (length through d/max|d|, so that it cannot
   overflow where the force does not; -k*d without a square root for rest length 0 and no damping). */
static void spring_force(const motus_spring *s, const motus_real *d, const motus_real *relative, int dims,
                         motus_real *force) {
    motus_real scale = 0, u2 = 0, length, along = 0, magnitude, unit[3];
    int e;
    if (s->rest_length == 0 && s->damping == 0) {
        for (e = 0; e < dims; ++e) force[e] = d[e] * -s->stiffness;
        return;
    }
    for (e = 0; e < dims; ++e) {
        const motus_real m = d[e] < 0 ? -d[e] : d[e];
        if (m > scale) scale = m;
    }
    if (!(scale > 0)) {
        for (e = 0; e < dims; ++e) force[e] = d[e] * -s->stiffness + (scale - scale);
        return;
    }
    for (e = 0; e < dims; ++e) {
        unit[e] = d[e] / scale;
        u2 += unit[e] * unit[e];
    }
    u2 = MOTUS_SQRT(u2);
    length = scale * u2;
    for (e = 0; e < dims; ++e) {
        unit[e] = unit[e] / u2;
        along += relative[e] * unit[e];
    }
    magnitude = s->stiffness * (length - s->rest_length) + s->damping * along;
    for (e = 0; e < dims; ++e) force[e] = unit[e] * -magnitude;
}
static void springs_callback(void *user_data, const motus_force_query *q) {
    const spring_set *set = (const spring_set *)user_data;
    int k, d;
    for (k = 0; k < set->count; ++k) {
        const motus_spring *s = &set->springs[k];
        const motus_real anchor[3] = {s->anchor.x, s->anchor.y, s->anchor.z};
        motus_real dx[3], relative[3], f[3];
        for (d = 0; d < q->dimensions; ++d) {
            dx[d] = q->position[d][s->a] - (s->b < 0 ? anchor[d] : q->position[d][s->b]);
            relative[d] = q->velocity[d][s->a] - (s->b < 0 ? 0 : q->velocity[d][s->b]);
        }
        spring_force(s, dx, relative, q->dimensions, f);
        for (d = 0; d < q->dimensions; ++d) {
            q->force[d][s->a] += f[d];
            if (s->b >= 0) q->force[d][s->b] -= f[d];
        }
    }
}

/* Springs (between particles, to anchors, rest length 0 with and without damping, ends on immovable
   particles) with the scene's other terms: the engine's springs and the callback end in the same bits after
   every step, for every method that takes springs, 2D and 3D; and the springs did move the particles. */
TEST(springs_equal_a_force_callback) {
    enum { N = 41, SPRING_COUNT = 60 };
    static motus_spring springs[SPRING_COUNT];
    int method, dims, k, step, ok = 1, moved = 0, combos = 0;
    for (method = 0; method < MOTUS_EXACT_LINEAR_DRAG; ++method)
        for (dims = 2; dims <= 3; ++dims)
            for (k = 0; k < 4 && ok; ++k, ++combos) {
                static const unsigned term_sets[4] = {0, T_FORCES | T_MASS, T_GRAVITY | T_LINEAR_DRAG | T_BOUNDS | T_MASS,
                                                      T_ALL};
                setup s;
                motus_scene with_springs, with_callback, without;
                motus_state sa, sb, sc;
                spring_set set;
                size_t bytes;
                int j;
                char what[240];
                s.method = (motus_method)method, s.dims = dims, s.count = N, s.terms = term_sets[k];
                s.damping = k % 3, s.substeps = 1 + k % 3, s.dt = (motus_real)(1.0 / 120.0);
                random_seed(500u + (uint32_t)combos);
                make_scene(&with_springs, &s);
                fill_particles(&A, N, &with_springs, (s.terms & T_MASS) != 0);
                for (j = 0; j < SPRING_COUNT; ++j) {
                    motus_spring *sp = &springs[j];
                    memset(sp, 0, sizeof *sp);
                    sp->a = random_int(N);
                    sp->b = j % 6 == 0 ? -1 : random_int(N);
                    if (sp->b == sp->a) sp->b = (sp->a + 1) % N;
                    sp->anchor = random_vec3(-5, 5);
                    sp->rest_length = j % 4 == 1 ? 0 : random_real(0.5, 3);
                    sp->stiffness = random_real(1, 40);
                    sp->damping = j % 8 == 1 ? 0 : random_real(0, 0.5);
                }
                with_springs.springs = springs;
                with_springs.spring_count = SPRING_COUNT;
                with_callback = with_springs;
                with_callback.springs = NULL;
                with_callback.spring_count = 0;
                with_callback.force_callback = springs_callback;
                set.springs = springs, set.count = SPRING_COUNT;
                with_callback.user_data = &set;
                without = with_callback;
                without.force_callback = NULL;
                memcpy(&B, &A, sizeof A);
                memcpy(&C, &A, sizeof A);
                sa = soa_state(&A, dims, N, s.terms);
                sb = soa_state(&B, dims, N, s.terms);
                sc = soa_state(&C, dims, N, s.terms);
                bytes = motus_scratch_size(&with_springs, &sa);
                ENSURE(bytes == motus_scratch_size(&with_callback, &sb) && bytes <= sizeof SCRATCH);
                for (step = 1; step <= 2 * STEPS && ok; ++step) {
                    ENSURE_EQ_INT(motus_step(&with_springs, &sa, s.dt, SCRATCH, bytes), MOTUS_OK);
                    ENSURE_EQ_INT(motus_step(&with_callback, &sb, s.dt, SCRATCH, bytes), MOTUS_OK);
                    ENSURE_EQ_INT(motus_step(&without, &sc, s.dt, NULL, 0), MOTUS_OK);
                    snprintf(what, sizeof what, "%s: springs against the callback", describe(&s));
                    ok &= same_state(&A, &B, dims, N, 0, what, step);
                }
                quiet = 1;
                moved += !same_state(&A, &C, dims, N, 0, "", 0);
                quiet = 0;
            }
    ENSURE(ok);
    ENSURE_EQ_INT(moved, combos); /* the springs acted in every scene */
}

/* ---- --dump: a digest of the end state of a fixed set of scenes, for comparing builds ---- */
static uint64_t fnv1a(uint64_t hash, const void *data, size_t size) {
    const unsigned char *bytes = (const unsigned char *)data;
    size_t i;
    for (i = 0; i < size; ++i) hash = (hash ^ bytes[i]) * 1099511628211ull;
    return hash;
}
#ifdef MOTUS_DOUBLE
#define LARGEST DBL_MAX
#else
#define LARGEST FLT_MAX
#endif
static int dump(void) {
    static const unsigned term_sets[] = {0, T_GRAVITY | T_FORCES | T_MASS,
                                         T_ALL & ~(unsigned)(T_QUADRATIC_DRAG | T_ATTRACTOR | T_TETHER),
                                         T_ALL};
    static motus_spring springs[300];
    int method, dims, k, j, step, coupled, errors = 0, lines = 0;
    for (method = 0; method < MOTUS_METHOD_COUNT; ++method)
        for (dims = 2; dims <= 3; ++dims)
            for (k = 0; k < (int)(sizeof term_sets / sizeof term_sets[0]); ++k)
                for (coupled = 0; coupled <= 2; ++coupled) { /* 1: springs, 2: contacts */
                    setup s;
                    motus_scene scene;
                    motus_state state;
                    uint64_t hash = 14695981039346656037ull;
                    int d;
                    s.method = (motus_method)method, s.dims = dims, s.terms = term_sets[k], s.count = MAX;
                    s.damping = k % 3, s.substeps = 1 + k % 3, s.dt = (motus_real)(1.0 / 60.0);
                    if (method == MOTUS_EXACT_LINEAR_DRAG && (k == 3 || coupled)) continue;
                    random_seed(9000u + (uint32_t)(method * 64 + dims * 16 + k * 2 + coupled));
                    make_scene(&scene, &s);
                    fill_particles(&A, MAX, &scene, (s.terms & T_MASS) != 0);
                    state = soa_state(&A, dims, MAX, s.terms);
                    if (coupled == 2) {
                        scene.contacts.enabled = 1;
                        scene.contacts.radius = dims == 2 ? MOTUS_R(0.4) : MOTUS_R(0.6);
                        scene.contacts.restitution = MOTUS_R(0.5);
                        scene.contacts.friction = MOTUS_R(0.2);
                    } else if (coupled) {
                        for (j = 0; j < 300; ++j) {
                            memset(&springs[j], 0, sizeof springs[j]);
                            springs[j].a = random_int(MAX);
                            springs[j].b = j % 5 == 0 ? -1 : (springs[j].a + 1 + random_int(MAX - 1)) % MAX;
                            springs[j].rest_length = j % 3 == 0 ? 0 : random_real(0.5, 2);
                            springs[j].stiffness = random_real(1, 20);
                            springs[j].damping = random_real(0, 0.3);
                        }
                        scene.springs = springs;
                        scene.spring_count = 300;
                    }
                    for (step = 0; step < 8; ++step)
                        errors += motus_step(&scene, &state, s.dt, coupled ? SCRATCH : NULL,
                                             coupled ? sizeof SCRATCH : 0) != MOTUS_OK;
                    for (d = 0; d < dims; ++d) {
                        hash = fnv1a(hash, A.x[d], MAX * sizeof(motus_real));
                        hash = fnv1a(hash, A.v[d], MAX * sizeof(motus_real));
                    }
                    printf("%-20s %dD terms 0x%02x%s %016llx\n", motus_method_name(s.method), dims, s.terms,
                           coupled == 2 ? " contacts" : coupled ? " springs " : "         ", (unsigned long long)hash);
                    lines++;
                }
    /* The rescue (F*(1/m) past the largest real, see THE RESCUE in motus.h): every 7th particle pushed by
       largest/4 N on 0.01 kg, one step of 1 ms, every method. */
    for (method = 0; method < MOTUS_METHOD_COUNT; ++method)
        for (dims = 2; dims <= 3; ++dims) {
            setup s;
            motus_scene scene;
            motus_state state;
            uint64_t hash = 14695981039346656037ull;
            int d, i;
            s.method = (motus_method)method, s.dims = dims, s.terms = T_GRAVITY | T_FORCES | T_MASS, s.count = MAX;
            s.damping = 1, s.substeps = 1, s.dt = (motus_real)1e-3;
            random_seed(9900u + (uint32_t)(method * 4 + dims));
            make_scene(&scene, &s);
            fill_particles(&A, MAX, &scene, 1);
            for (i = 0; i < MAX; i += 7) A.f[i % dims][i] = (i % 2 ? -LARGEST : LARGEST) / 4, A.w[i] = 100;
            state = soa_state(&A, dims, MAX, s.terms);
            errors += motus_step(&scene, &state, s.dt, NULL, 0) != MOTUS_OK;
            for (d = 0; d < dims; ++d) {
                hash = fnv1a(hash, A.x[d], MAX * sizeof(motus_real));
                hash = fnv1a(hash, A.v[d], MAX * sizeof(motus_real));
            }
            printf("%-20s %dD rescue            %016llx\n", motus_method_name(s.method), dims, (unsigned long long)hash);
            lines++;
        }
    printf("%d scenes, %d steps that did not return MOTUS_OK\n", lines, errors);
    return errors != 0;
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
    TEST_CASE(counts_do_not_change_results),
    TEST_CASE(particle_step_equals_zeroed_scene),
    TEST_CASE(particle_functions_equal_scene_with_bounds_and_damping),
    TEST_CASE(springs_equal_a_force_callback),
};

int main(int argc, char **argv) {
    (void)motus_test_near;
    (void)motus_scene_max_stable_dt;
    if (argc > 1 && strcmp(argv[1], "--dump") == 0) return dump();
    return motus_test_main(argc, argv, TESTS, TEST_COUNT(TESTS));
}
