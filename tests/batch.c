/* Unit tests of the batch kernels (motus_batch_step, motus_batch_check, motus_scene_check,
   motus_batch_add_spring_forces): bit-identical to the single-particle path (motus_stepper_step, then
   motus_particle_damp_per_step / _per_second, then motus_particle_bounce) for every scene; independent of
   how the range is split; 3D against closed forms; unused arrays NULL; every error path with the arrays
   left byte for byte as they were; bad data, overflow, bounds, damping, immovable particles.
   Built in float and double, with MOTUS_CHECKED (bad data found first, nothing written), and in the extra
   modes of the compile matrix (scalar fallback, 32-byte lanes, -O3 -march=native): `motus_batch --dump`
   prints a hash of the final state of every scene so that those builds can be compared bit for bit. */
#include "motus.h"
#include "support/motus_test.h"

#include <float.h>
#include <limits.h>
#include <stdint.h>

#ifdef MOTUS_DOUBLE
#define REAL_MAX DBL_MAX
#else
#define REAL_MAX FLT_MAX
#endif

#define EPS ((double)MOTUS_REAL_EPSILON)
#define ALL_HAS (MOTUS_HAS_GRAVITY | MOTUS_HAS_LINEAR_DRAG | MOTUS_HAS_DAMPING_PER_STEP | MOTUS_HAS_PARTICLE_MASS | \
                 MOTUS_HAS_FORCES | MOTUS_HAS_QUADRATIC_DRAG | MOTUS_HAS_ATTRACTOR | MOTUS_HAS_BOUNDS)
#define BOTH_DAMPINGS (MOTUS_HAS_DAMPING_PER_STEP | MOTUS_HAS_DAMPING_PER_SECOND)
/* Scene features that change velocities; a semi-implicit scene without any (drift, masses) keeps them. */
#define VELOCITY_CHANGERS (MOTUS__HAS_KNOWN & ~MOTUS_HAS_PARTICLE_MASS)

/* N particles: not a multiple of any vector width, so every kernel runs whole vectors and a partial one. */
enum { N = 301, STEPS = 50, GUARD = 16, STRIDE = GUARD + N + GUARD, SPRINGS = 100 };
enum { POSITION = 0, VELOCITY = 3, FORCE = 6, INVERSE_MASS = 9, ARRAYS = 10 };

static const motus_real DT = (motus_real)(1.0 / 60.0);
static const motus_real GUARD_VALUE = (motus_real)-7777.0; /* around every array: no step may change it */

static motus_real not_a_number(void) { return (motus_real)NAN; }
static motus_real infinity(void) { return (motus_real)HUGE_VAL; }
static motus_real negative_zero(void) { return -(motus_real)0; }

static int same_bytes(const void *a, const void *b, size_t size) { return memcmp(a, b, size) == 0; }

/* The bits of a value, for messages: two values that print alike may still differ (-0 and +0). */
static unsigned long long bits_of(motus_real value) {
#ifdef MOTUS_DOUBLE
    uint64_t bits;
#else
    uint32_t bits;
#endif
    memcpy(&bits, &value, sizeof bits);
    return (unsigned long long)bits;
}

/* A 32-bit LCG: the same sequence on every platform and in every build. */
static uint32_t random_state = 1;
static double random_unit(void) {
    random_state = random_state * 1664525u + 1013904223u;
    return (double)(random_state >> 8) / 16777216.0;
}
static motus_real random_real(double lo, double hi) { return (motus_real)(lo + (hi - lo) * random_unit()); }
static int random_int(int n) { return (int)(random_unit() * n); }

/* =================================================================================================
   A batch in test memory: ten arrays (x, y, z, vx, vy, vz, fx, fy, fz, inverse mass), each with GUARD
   values before and after its N particles (and `offset` more before, to start the arrays off a vector
   boundary).
   ================================================================================================= */
typedef struct test_batch {
    motus_batch batch;
    int dims, offset, null_unused;
    unsigned has;
    motus_real memory[ARRAYS][STRIDE + GUARD];
} test_batch;

static motus_real *array_of(test_batch *t, int which) { return t->memory[which] + GUARD + t->offset; }

/* Whether the scene reads array `which` (the position, velocity, force or inverse-mass array of a dimension). */
static int array_used(const test_batch *t, int which) {
    if (which == INVERSE_MASS) return (t->has & MOTUS_HAS_PARTICLE_MASS) != 0;
    if (which % 3 >= t->dims) return 0;
    if (which >= FORCE) return (t->has & MOTUS_HAS_FORCES) != 0;
    return 1;
}

/* Points the batch at the arrays the scene reads. The others are NULL (null_unused), or point at arrays
   that fill_random fills with NaN, which a kernel that read them would spread into the state. */
static void bind(test_batch *t, int dims, unsigned has, int null_unused, int offset) {
    int d;
    memset(&t->batch, 0, sizeof t->batch);
    t->dims = dims, t->has = has, t->null_unused = null_unused, t->offset = offset;
    t->batch.dimensions = dims;
    for (d = 0; d < 3; ++d) {
        t->batch.position[d] = !null_unused || array_used(t, POSITION + d) ? array_of(t, POSITION + d) : NULL;
        t->batch.velocity[d] = !null_unused || array_used(t, VELOCITY + d) ? array_of(t, VELOCITY + d) : NULL;
        t->batch.force[d] = !null_unused || array_used(t, FORCE + d) ? array_of(t, FORCE + d) : NULL;
    }
    t->batch.inverse_mass = !null_unused || array_used(t, INVERSE_MASS) ? array_of(t, INVERSE_MASS) : NULL;
}

/* The scene every test starts from: every parameter valid and distinct, whatever `has` says. */
static void make_scene(motus_scene *s, unsigned has, motus_method method) {
    memset(s, 0, sizeof *s);
    s->has = has;
    s->method = method;
    s->gravity[0] = MOTUS_R(0.5), s->gravity[1] = MOTUS_R(-9.81), s->gravity[2] = MOTUS_R(1.25);
    s->linear_drag = MOTUS_R(0.3);
    s->quadratic_drag = MOTUS_R(0.02);
    s->damping = (has & MOTUS_HAS_DAMPING_PER_SECOND) ? MOTUS_R(0.5) : MOTUS_R(0.98);
    s->inverse_mass = MOTUS_R(0.5);
    s->attractor[0] = 1, s->attractor[1] = 2, s->attractor[2] = MOTUS_R(0.5);
    s->attractor_strength = MOTUS_R(0.2);
    s->bounds_min[0] = -8, s->bounds_min[1] = -6, s->bounds_min[2] = -5;
    s->bounds_max[0] = 8, s->bounds_max[1] = 7, s->bounds_max[2] = 5;
    s->restitution = MOTUS_R(0.7);
}

/* Random state for every particle, with the awkward cases at fixed indices: every 7th immovable
   (inverse mass 0), signed zeros in velocities and forces, an immovable particle on the attractor (when the
   scene can hold one there) and one on a wall, at rest. Arrays the scene does not read are NaN; the guards are GUARD_VALUE. */
static void fill_random(test_batch *t, const motus_scene *s, uint32_t seed) {
    int a, i, d;
    random_state = seed;
    for (a = 0; a < ARRAYS; ++a)
        for (i = 0; i < STRIDE + GUARD; ++i) t->memory[a][i] = GUARD_VALUE;
    for (i = 0; i < N; ++i) {
        for (d = 0; d < 3; ++d) {
            array_of(t, POSITION + d)[i] = random_real(-6, 6);
            array_of(t, VELOCITY + d)[i] = random_real(-4, 4);
            array_of(t, FORCE + d)[i] = random_real(-10, 10);
        }
        array_of(t, INVERSE_MASS)[i] = i % 7 == 0 ? 0 : random_real(0.2, 2);
        if (i % 11 == 4) {
            array_of(t, VELOCITY + 0)[i] = negative_zero(), array_of(t, VELOCITY + 1)[i] = 0;
            array_of(t, VELOCITY + 2)[i] = negative_zero();
        }
        if (i % 13 == 6) array_of(t, FORCE + 0)[i] = negative_zero(), array_of(t, FORCE + 1)[i] = 0;
    }
    for (d = 0; d < 3; ++d) {
        /* Only where it cannot move (a free particle there would be flung out at any speed). */
        if ((t->has & MOTUS_HAS_PARTICLE_MASS) || s->inverse_mass == 0)
            array_of(t, POSITION + d)[14] = s->attractor[d], array_of(t, VELOCITY + d)[14] = 0;
        array_of(t, VELOCITY + d)[28] = 0;
        array_of(t, VELOCITY + d)[35] = negative_zero(), array_of(t, FORCE + d)[35] = negative_zero();
    }
    array_of(t, POSITION + 0)[28] = s->bounds_max[0];
    for (a = 0; a < ARRAYS; ++a)
        if (!array_used(t, a))
            for (i = 0; i < N; ++i) array_of(t, a)[i] = not_a_number();
}

/* Every value outside the N particles is still GUARD_VALUE: no store went past either end. */
static int guards_intact(test_batch *t) {
    int a, i;
    for (a = 0; a < ARRAYS; ++a)
        for (i = 0; i < STRIDE + GUARD; ++i) {
            const int inside = i >= GUARD + t->offset && i < GUARD + t->offset + N;
            if (!inside && !same_bytes(&t->memory[a][i], &GUARD_VALUE, sizeof GUARD_VALUE)) return 0;
        }
    return 1;
}

/* Differences printed so far: the first few say enough. */
static int differences_printed;

/* The position and velocity arrays of the scene's dimensions of two batches are byte for byte equal;
   otherwise prints the first difference (of the first 20 calls that find one), and says when the two
   differ only in the signs of zeros. In a 3D batch compared with a 2D one, only x and y are compared. */
static int same_state_except(test_batch *a, test_batch *b, const char *what, int velocity_zero_signs_may_differ) {
    int which, i;
    for (which = 0; which < 6; ++which) {
        if (which % 3 >= a->dims || which % 3 >= b->dims) continue;
        for (i = 0; i < N; ++i) {
            const motus_real u = array_of(a, which)[i], v = array_of(b, which)[i];
            if (velocity_zero_signs_may_differ && which >= 3 && u == 0 && v == 0) continue;
            if (!same_bytes(&u, &v, sizeof u)) {
                if (++differences_printed > 20) return 0;
                fprintf(stderr, "%s: %s[%d][%d] = %.9g (0x%llx), expected %.9g (0x%llx)%s\n", what,
                        which < 3 ? "position" : "velocity", which % 3, i, (double)u, bits_of(u), (double)v,
                        bits_of(v), u == 0 && v == 0 ? ": signs of zero differ" : "");
                return 0;
            }
        }
    }
    return 1;
}
static int same_state(test_batch *a, test_batch *b, const char *what) { return same_state_except(a, b, what, 0); }

/* A set of springs over N particles: between particles (some of them immovable), to anchors, with and
   without rest length and damping. */
static void make_springs(motus_spring springs[SPRINGS]) {
    int j;
    random_state = 99;
    memset(springs, 0, sizeof(motus_spring) * SPRINGS);
    for (j = 0; j < SPRINGS; ++j) {
        motus_spring *s = &springs[j];
        s->a = (j * 7) % N;
        s->b = j % 5 == 4 ? -1 : (j * 13 + 5) % N;
        if (s->b == s->a) s->b = -1;
        s->anchor.x = random_real(-3, 3); /* one statement each: argument order is unspecified */
        s->anchor.y = random_real(-3, 3);
        s->rest_length = j % 4 == 0 ? 0 : random_real(0.5, 2);
        s->stiffness = random_real(1, 20);
        s->damping = j % 3 == 0 ? 0 : random_real(0.1, 0.5);
    }
}

/* =================================================================================================
   The single-particle path: what a user of motus_particle / motus_stepper_step writes for a scene
   ================================================================================================= */
static motus_vec2 scene_vec2(const motus_real v[3]) { return motus_v2(v[0], v[1]); }

static void scene_forces(const motus_scene *s, const motus_spring *springs, int spring_count, motus_forces *f) {
    memset(f, 0, sizeof *f);
    if (s->has & MOTUS_HAS_GRAVITY) f->gravity = scene_vec2(s->gravity);
    if (s->has & MOTUS_HAS_LINEAR_DRAG) f->linear_drag = s->linear_drag;
    if (s->has & MOTUS_HAS_QUADRATIC_DRAG) f->quadratic_drag = s->quadratic_drag;
    if (s->has & MOTUS_HAS_ATTRACTOR) {
        f->attractor_strength = s->attractor_strength;
        f->attractor_position = scene_vec2(s->attractor);
    }
    f->springs = springs;
    f->spring_count = spring_count;
}

/* The particles of a 2D batch, with the force array's values (or none) and its masses (or the scene's). */
static void to_particles(test_batch *t, const motus_scene *s, motus_particle p[N]) {
    int i;
    for (i = 0; i < N; ++i) {
        p[i].position = motus_v2(array_of(t, POSITION)[i], array_of(t, POSITION + 1)[i]);
        p[i].velocity = motus_v2(array_of(t, VELOCITY)[i], array_of(t, VELOCITY + 1)[i]);
        p[i].force = (s->has & MOTUS_HAS_FORCES) ? motus_v2(array_of(t, FORCE)[i], array_of(t, FORCE + 1)[i])
                                                 : motus_v2(0, 0);
        p[i].inverse_mass = (s->has & MOTUS_HAS_PARTICLE_MASS) ? array_of(t, INVERSE_MASS)[i] : s->inverse_mass;
    }
}

/* Writes particles into the position and velocity arrays of a 2D test batch, to compare them. */
static void from_particles(test_batch *t, const motus_particle p[N]) {
    int i;
    for (i = 0; i < N; ++i) {
        array_of(t, POSITION)[i] = p[i].position.x, array_of(t, POSITION + 1)[i] = p[i].position.y;
        array_of(t, VELOCITY)[i] = p[i].velocity.x, array_of(t, VELOCITY + 1)[i] = p[i].velocity.y;
    }
}

static motus_vec2 stepper_scratch[3 * N]; /* semi-implicit and explicit Euler take 3 arrays */

static motus_result init_stepper(motus_stepper *stepper, motus_method method) {
    motus_stepper_desc desc;
    memset(&desc, 0, sizeof desc);
    desc.capacity = N;
    desc.method = method;
    desc.scratch = stepper_scratch;
    desc.scratch_bytes = sizeof stepper_scratch;
    return motus_stepper_init(stepper, &desc);
}

/* One step of the single-particle path: the forces of the step (the ones given each step, as the batch's
   force arrays are re-set each step), the stepper, then damping and bounds per particle. */
static motus_result single_step(const motus_scene *s, motus_stepper *stepper, motus_particle p[N],
                                const motus_vec2 base_force[N], const motus_spring *springs, int spring_count,
                                motus_real dt) {
    motus_forces forces;
    motus_result result = MOTUS_OK;
    int i;
    scene_forces(s, springs, spring_count, &forces);
    for (i = 0; i < N; ++i) p[i].force = base_force[i];
    result = motus_stepper_step(stepper, p, N, &forces, dt);
    if (result != MOTUS_OK) return result;
    for (i = 0; i < N && result == MOTUS_OK; ++i) {
        if (s->has & MOTUS_HAS_DAMPING_PER_STEP) result = motus_particle_damp_per_step(&p[i], s->damping);
        if (s->has & MOTUS_HAS_DAMPING_PER_SECOND) result = motus_particle_damp_per_second(&p[i], s->damping, dt);
        if (result == MOTUS_OK && (s->has & MOTUS_HAS_BOUNDS))
            result = motus_particle_bounce(&p[i], scene_vec2(s->bounds_min), scene_vec2(s->bounds_max), s->restitution);
    }
    return result;
}

/* One step of the batch path: force arrays re-set to the step's forces, springs added, the whole range. */
static motus_result batch_step(const motus_scene *s, test_batch *t, const motus_vec2 base_force[N],
                               const motus_spring *springs, int spring_count, motus_real dt) {
    int i;
    if (s->has & MOTUS_HAS_FORCES) {
        for (i = 0; i < N; ++i) array_of(t, FORCE)[i] = base_force[i].x, array_of(t, FORCE + 1)[i] = base_force[i].y;
        if (spring_count > 0) {
            motus_result result = motus_batch_add_spring_forces(&t->batch, N, springs, spring_count);
            if (result != MOTUS_OK) return result;
        }
    }
    return motus_batch_step(s, &t->batch, 0, N, dt);
}

/* STEPS steps of a random 2D scene through both paths, compared byte for byte after every step. */
static int batch_equals_single(unsigned has, motus_method method, int with_springs, motus_real uniform_inverse_mass) {
    static test_batch t, expected;
    static motus_particle p[N];
    static motus_vec2 base_force[N];
    static motus_spring springs[SPRINGS];
    static motus_real mass_before[N], velocity_before[2][N];
    motus_stepper stepper;
    int changes_no_velocity;
    motus_scene s;
    char what[160];
    int i, step, ok = 1;
    const int spring_count = with_springs ? SPRINGS : 0;
    make_scene(&s, has, method);
    s.inverse_mass = uniform_inverse_mass;
    bind(&t, 2, has, 0, 0);
    bind(&expected, 2, has, 0, 0);
    fill_random(&t, &s, 1000 + has * 2 + (unsigned)method);
    make_springs(springs);
    to_particles(&t, &s, p);
    for (i = 0; i < N; ++i) base_force[i] = p[i].force;
    memcpy(mass_before, array_of(&t, INVERSE_MASS), sizeof mass_before);
    ENSURE_EQ_INT(init_stepper(&stepper, method), MOTUS_OK);
    /* The one documented difference: a fast kernel with nothing that changes velocities does not store them,
       so a velocity of -0 stays -0 where the stepper's v + 0*h makes it +0. Everything else, bit for bit. */
    changes_no_velocity = !(has & VELOCITY_CHANGERS) && method == MOTUS_SEMI_IMPLICIT_EULER &&
                          ((has & MOTUS_HAS_PARTICLE_MASS) || uniform_inverse_mass != 0);
    memcpy(velocity_before[0], array_of(&t, VELOCITY), sizeof velocity_before[0]);
    memcpy(velocity_before[1], array_of(&t, VELOCITY + 1), sizeof velocity_before[1]);
    for (step = 0; step < STEPS && ok; ++step) {
        motus_result batch_result = batch_step(&s, &t, base_force, springs, spring_count, DT);
        motus_result single_result = single_step(&s, &stepper, p, base_force, springs, spring_count, DT);
        sprintf(what, "has 0x%03x, %s, %s, uniform inverse mass %g, step %d", has, motus_method_name(method),
                with_springs ? "springs" : "no springs", (double)uniform_inverse_mass, step);
        from_particles(&expected, p);
        if (batch_result != MOTUS_OK || single_result != MOTUS_OK) {
            fprintf(stderr, "%s: batch %s, single %s\n", what, motus_result_string(batch_result),
                    motus_result_string(single_result));
            ok = 0;
        } else if (!same_state_except(&t, &expected, what, changes_no_velocity)) {
            ok = 0;
        } else if (changes_no_velocity && (!same_bytes(velocity_before[0], array_of(&t, VELOCITY), sizeof velocity_before[0]) ||
                                           !same_bytes(velocity_before[1], array_of(&t, VELOCITY + 1), sizeof velocity_before[1]))) {
            fprintf(stderr, "%s: a kernel that changes no velocity wrote the velocities\n", what);
            ok = 0;
        } else if (!guards_intact(&t) || !same_bytes(mass_before, array_of(&t, INVERSE_MASS), sizeof mass_before)) {
            fprintf(stderr, "%s: guards or masses changed\n", what);
            ok = 0;
        }
    }
    return ok;
}

/* =================================================================================================
   batch equals single particle: every scene, both methods
   ================================================================================================= */
TEST(batch_equals_single_particle) {
    /* Every valid combination of the 9 MOTUS_HAS_* flags (not both dampings) x semi-implicit and explicit
       Euler, 2D, N particles, STEPS steps, byte for byte after every step. Scenes with forces run with and
       without springs; scenes without per-particle masses with a uniform inverse mass of 0.5 and of 0. */
    unsigned has;
    int method, with_springs, uniform, combinations = 0, runs = 0, failed = 0;
    for (has = 0; has <= MOTUS__HAS_KNOWN; ++has) {
        if ((has & BOTH_DAMPINGS) == BOTH_DAMPINGS) continue;
        combinations++;
        for (method = 0; method < 2; ++method)
            for (with_springs = 0; with_springs < 2; ++with_springs)
                for (uniform = 0; uniform < 2; ++uniform) {
                    if (with_springs && !(has & MOTUS_HAS_FORCES)) continue;
                    if (uniform && (has & MOTUS_HAS_PARTICLE_MASS)) continue;
                    runs++;
                    failed += !batch_equals_single(has, (motus_method)method, with_springs,
                                                   uniform ? 0 : MOTUS_R(0.5));
                }
    }
    printf("%d flag combinations, %d runs, %d differ\n", combinations, runs, failed);
    ENSURE_EQ_INT(combinations, 384);
    ENSURE_EQ_INT(failed, 0);
}

/* =================================================================================================
   Range splits
   ================================================================================================= */
typedef struct range {
    int first, count;
} range;

/* STEPS steps, each stepping the ranges in the order given. */
static void step_ranges(const motus_scene *s, test_batch *t, const range *ranges, int range_count) {
    int step, r;
    for (step = 0; step < STEPS; ++step)
        for (r = 0; r < range_count; ++r)
            ENSURE_EQ_INT(motus_batch_step(s, &t->batch, ranges[r].first, ranges[r].count, DT), MOTUS_OK);
}

TEST(range_split_does_not_change_results) {
    /* The same scene stepped as one range, as [0, k) + [k, N) in both orders for k at and around vector
       widths (k = 0 and k = N included), as many small ranges in a shuffled order, one particle at a time
       backwards, and with the arrays starting 1..5 values off a vector boundary: identical bit for bit. */
    static const unsigned scenes[] = {
        0,
        MOTUS_HAS_GRAVITY | MOTUS_HAS_DAMPING_PER_STEP,
        MOTUS_HAS_GRAVITY | MOTUS_HAS_LINEAR_DRAG | MOTUS_HAS_DAMPING_PER_SECOND | MOTUS_HAS_PARTICLE_MASS |
            MOTUS_HAS_FORCES,
        ALL_HAS,
        ALL_HAS ^ BOTH_DAMPINGS,
    };
    static const int cuts[] = {0, 1, 2, 3, 5, 7, 8, 9, 13, 15, 16, 17, 31, 32, 33, 63, 64, 65, 150, N - 1, N};
    static test_batch reference, t;
    range ranges[N + 1];
    int scene, dims, method, c, order, offset, count, i;
    char what[128];
    for (scene = 0; scene < (int)(sizeof scenes / sizeof scenes[0]); ++scene)
        for (dims = 2; dims <= 3; ++dims)
            for (method = 0; method < 2; ++method) {
                motus_scene s;
                make_scene(&s, scenes[scene], (motus_method)method);
                bind(&reference, dims, s.has, 1, 0);
                fill_random(&reference, &s, 7 + (unsigned)scene);
                bind(&t, dims, s.has, 1, 0);
                ranges[0].first = 0, ranges[0].count = N;
                step_ranges(&s, &reference, ranges, 1);
                ENSURE(guards_intact(&reference));
                for (c = 0; c < (int)(sizeof cuts / sizeof cuts[0]); ++c)
                    for (order = 0; order < 2; ++order) {
                        fill_random(&t, &s, 7 + (unsigned)scene);
                        ranges[order].first = 0, ranges[order].count = cuts[c];
                        ranges[1 - order].first = cuts[c], ranges[1 - order].count = N - cuts[c];
                        step_ranges(&s, &t, ranges, 2);
                        sprintf(what, "has 0x%03x, %dD, method %d, split at %d, order %d", s.has, dims, method,
                                cuts[c], order);
                        ENSURE(same_state(&t, &reference, what));
                        ENSURE(guards_intact(&t));
                    }
                /* Small ranges (0 to 19 particles, empty ones included), shuffled. */
                fill_random(&t, &s, 7 + (unsigned)scene);
                random_state = 12345;
                for (count = 0, i = 0; i < N; ++count) {
                    int size = random_int(20);
                    if (size > N - i) size = N - i;
                    ranges[count].first = i, ranges[count].count = size;
                    i += size;
                }
                for (i = count - 1; i > 0; --i) {
                    int j = random_int(i + 1);
                    range swap = ranges[i];
                    ranges[i] = ranges[j], ranges[j] = swap;
                }
                step_ranges(&s, &t, ranges, count);
                sprintf(what, "has 0x%03x, %dD, method %d, %d shuffled ranges", s.has, dims, method, count);
                ENSURE(same_state(&t, &reference, what));
                ENSURE(guards_intact(&t));
                /* One particle at a time, last first. */
                fill_random(&t, &s, 7 + (unsigned)scene);
                for (i = 0; i < N; ++i) ranges[i].first = N - 1 - i, ranges[i].count = 1;
                step_ranges(&s, &t, ranges, N);
                sprintf(what, "has 0x%03x, %dD, method %d, one at a time", s.has, dims, method);
                ENSURE(same_state(&t, &reference, what));
                /* The arrays off a vector boundary (the kernel peels a partial vector first). */
                for (offset = 1; offset <= 5; ++offset) {
                    bind(&t, dims, s.has, 1, offset);
                    fill_random(&t, &s, 7 + (unsigned)scene);
                    ranges[0].first = 0, ranges[0].count = 100;
                    ranges[1].first = 100, ranges[1].count = N - 100;
                    step_ranges(&s, &t, ranges, 2);
                    sprintf(what, "has 0x%03x, %dD, method %d, arrays offset by %d", s.has, dims, method, offset);
                    ENSURE(same_state(&t, &reference, what));
                    ENSURE(guards_intact(&t));
                }
            }
}

TEST(step_writes_only_its_range) {
    /* Stepping [first, first + count) leaves every other particle, and the memory around the arrays,
       byte for byte as it was: no vector load/store of a partial vector spills over. */
    static const int firsts[] = {0, 1, 3, 7, 8, 16, 17, 100, N - 1};
    static const int counts[] = {0, 1, 2, 3, 7, 8, 9, 15, 16, 17, 33, 64, 65};
    static test_batch t, before;
    int f, c, dims, offset, i, a;
    motus_scene s;
    make_scene(&s, ALL_HAS, MOTUS_SEMI_IMPLICIT_EULER);
    for (dims = 2; dims <= 3; ++dims)
        for (offset = 0; offset < 3; ++offset)
            for (f = 0; f < (int)(sizeof firsts / sizeof firsts[0]); ++f)
                for (c = 0; c < (int)(sizeof counts / sizeof counts[0]); ++c) {
                    const int first = firsts[f], count = counts[c];
                    if (first + count > N) continue;
                    bind(&t, dims, s.has, 0, offset);
                    fill_random(&t, &s, 5);
                    memcpy(&before, &t, sizeof t);
                    ENSURE_EQ_INT(motus_batch_step(&s, &t.batch, first, count, DT), MOTUS_OK);
                    ENSURE(guards_intact(&t));
                    for (a = 0; a < ARRAYS; ++a)
                        for (i = 0; i < N; ++i) {
                            const int stepped = i >= first && i < first + count && a < FORCE && a % 3 < dims;
                            const int same = same_bytes(&t.memory[a][GUARD + offset + i],
                                                        &before.memory[a][GUARD + offset + i], sizeof(motus_real));
                            if (!stepped && !same) {
                                fprintf(stderr, "%dD [%d, %d): array %d particle %d changed\n", dims, first,
                                        first + count, a, i);
                                motus_test_failures++;
                            }
                            /* A moving particle (every 7th is immovable, and may sit still) moved. */
                            if (stepped && a == VELOCITY + 1 && i % 7 != 0 && same) {
                                fprintf(stderr, "%dD [%d, %d): particle %d not stepped\n", dims, first, first + count, i);
                                motus_test_failures++;
                            }
                        }
                }
}

/* =================================================================================================
   3D
   ================================================================================================= */
TEST(three_d_with_zero_z_equals_two_d) {
    /* Every scene and method: a 3D batch whose z components are all +0 (and the scene's z gravity and
       attractor 0) gives the 2D batch's x and y bit for bit, and its z stays +0. */
    static test_batch two, three;
    static motus_real zeros[N];
    unsigned has;
    int method, step, d;
    char what[96];
    memset(zeros, 0, sizeof zeros);
    for (has = 0; has <= MOTUS__HAS_KNOWN; ++has) {
        if ((has & BOTH_DAMPINGS) == BOTH_DAMPINGS) continue;
        for (method = 0; method < 2; ++method) {
            motus_scene s;
            make_scene(&s, has, (motus_method)method);
            s.gravity[2] = 0, s.attractor[2] = 0;
            bind(&two, 2, has, 1, 0);
            bind(&three, 3, has, 1, 0);
            fill_random(&two, &s, 77 + has);
            fill_random(&three, &s, 77 + has);
            for (d = POSITION + 2; d < ARRAYS; d += 3) memset(array_of(&three, d), 0, sizeof zeros);
            for (step = 0; step < STEPS; ++step) {
                ENSURE_EQ_INT(motus_batch_step(&s, &two.batch, 0, N, DT), MOTUS_OK);
                ENSURE_EQ_INT(motus_batch_step(&s, &three.batch, 0, N, DT), MOTUS_OK);
            }
            sprintf(what, "has 0x%03x, %s", has, motus_method_name((motus_method)method));
            ENSURE(same_state(&three, &two, what));
            ENSURE(same_bytes(array_of(&three, POSITION + 2), zeros, sizeof zeros));
            ENSURE(same_bytes(array_of(&three, VELOCITY + 2), zeros, sizeof zeros));
        }
    }
}

/* Far enough from the oracle to be more than rounding: n steps of a few operations on values of the
   scale given, each rounded. */
static double rounding_tolerance(int steps, double scale) { return 8.0 * steps * EPS * scale; }

TEST(three_d_matches_closed_forms) {
    /* Motion in all three axes, per-particle masses and forces.
       - Constant acceleration a = F/m + g: semi-implicit Euler lands at x0 + v0*t + a*t*(t + h)/2 after
         time t = n*h, explicit Euler at x0 + v0*t + a*t*(t - h)/2, both with v = v0 + a*t.
       - With linear drag k, semi-implicit Euler is the linear map v' = v*(1 - k*h) + a*h: with q = 1 - k*h
         and v_inf = a/k, v_n = v_inf + (v0 - v_inf)*q^n and x_n = x0 + h*(n*v_inf + (v0 - v_inf)*q*(1 - q^n)/(1 - q)). */
    static test_batch t;
    static motus_real x0[3][N], v0[3][N];
    enum { STEPS_3D = 120 };
    const double h = (double)DT;
    int drag, method, i, d, step;
    for (drag = 0; drag < 2; ++drag)
        for (method = 0; method < 2; ++method) {
            motus_scene s;
            if (drag && method) continue; /* the drag oracle is for semi-implicit Euler */
            make_scene(&s, MOTUS_HAS_GRAVITY | MOTUS_HAS_PARTICLE_MASS | MOTUS_HAS_FORCES |
                               (drag ? MOTUS_HAS_LINEAR_DRAG : 0u), (motus_method)method);
            s.gravity[0] = MOTUS_R(1.5), s.gravity[1] = MOTUS_R(-9.81), s.gravity[2] = 4;
            bind(&t, 3, s.has, 1, 0);
            fill_random(&t, &s, 31);
            for (d = 0; d < 3; ++d) {
                memcpy(x0[d], array_of(&t, POSITION + d), sizeof x0[d]);
                memcpy(v0[d], array_of(&t, VELOCITY + d), sizeof v0[d]);
            }
            for (step = 0; step < STEPS_3D; ++step) ENSURE_EQ_INT(motus_batch_step(&s, &t.batch, 0, N, DT), MOTUS_OK);
            for (i = 0; i < N; ++i)
                for (d = 0; d < 3; ++d) {
                    const double im = (double)array_of(&t, INVERSE_MASS)[i];
                    const double a = im != 0 ? (double)array_of(&t, FORCE + d)[i] * im + (double)s.gravity[d] : 0;
                    const double time = STEPS_3D * h, x_0 = (double)x0[d][i], v_0 = (double)v0[d][i];
                    const double scale = fabs(x_0) + fabs(v_0) * time + fabs(a) * time * time + 1;
                    double x, v;
                    if (!drag || im == 0) {
                        x = x_0 + v_0 * time + 0.5 * a * time * (method == 0 ? time + h : time - h);
                        v = v_0 + a * time;
                    } else {
                        const double k = (double)s.linear_drag, q = 1 - k * h, v_inf = a / k;
                        const double qn = pow(q, STEPS_3D);
                        v = v_inf + (v_0 - v_inf) * qn;
                        x = x_0 + h * (STEPS_3D * v_inf + (v_0 - v_inf) * q * (1 - qn) / (1 - q));
                    }
                    if (!ENSURE_NEAR(array_of(&t, POSITION + d)[i], x, rounding_tolerance(STEPS_3D, scale)) ||
                        !ENSURE_NEAR(array_of(&t, VELOCITY + d)[i], v, rounding_tolerance(STEPS_3D, scale))) {
                        fprintf(stderr, "  particle %d, axis %d, drag %d, method %d\n", i, d, drag, method);
                        return;
                    }
                }
        }
}

/* =================================================================================================
   Unused arrays
   ================================================================================================= */
TEST(unused_arrays_may_be_null) {
    /* Every scene, both methods, 2D and 3D: force and inverse-mass arrays NULL when the scene does not
       declare them, and the z arrays NULL in 2D. Checked, stepped (a whole range and a split one) and
       springs added (none) without error, with the same state as a batch whose unused arrays are NaN. */
    static test_batch with_null, with_nan;
    unsigned has;
    int method, dims, step;
    char what[96];
    for (has = 0; has <= MOTUS__HAS_KNOWN; ++has) {
        if ((has & BOTH_DAMPINGS) == BOTH_DAMPINGS) continue;
        for (dims = 2; dims <= 3; ++dims)
            for (method = 0; method < 2; ++method) {
                motus_scene s;
                int index = -1;
                const char *field = NULL;
                make_scene(&s, has, (motus_method)method);
                bind(&with_null, dims, has, 1, 0);
                bind(&with_nan, dims, has, 0, 0);
                fill_random(&with_null, &s, 3);
                fill_random(&with_nan, &s, 3);
                ENSURE_EQ_INT(motus_scene_check(&s, &with_null.batch), MOTUS_OK);
                ENSURE_EQ_INT(motus_batch_check(&s, &with_null.batch, 0, N, &index, &field), MOTUS_OK);
                if (dims == 2 && !(has & MOTUS_HAS_FORCES))
                    ENSURE_EQ_INT(motus_batch_add_spring_forces(&with_null.batch, N, NULL, 0), MOTUS_OK);
                for (step = 0; step < 10; ++step) {
                    ENSURE_EQ_INT(motus_batch_step(&s, &with_null.batch, 0, 37, DT), MOTUS_OK);
                    ENSURE_EQ_INT(motus_batch_step(&s, &with_null.batch, 37, N - 37, DT), MOTUS_OK);
                    ENSURE_EQ_INT(motus_batch_step(&s, &with_nan.batch, 0, N, DT), MOTUS_OK);
                }
                sprintf(what, "has 0x%03x, %dD, %s", has, dims, motus_method_name((motus_method)method));
                ENSURE(same_state(&with_null, &with_nan, what));
                ENSURE(guards_intact(&with_null));
            }
    }
}

/* =================================================================================================
   Scene and argument validation: every error, nothing written
   ================================================================================================= */

/* Calls motus_scene_check, motus_batch_check and motus_batch_step on the scene and batch and expects
   `expected` from each, with every array of `t` byte for byte as it was and batch_check's outputs
   untouched. dt and the range are valid here. */
static void ensure_scene_rejected_at(const motus_scene *scene, const motus_batch *batch, test_batch *t,
                                     motus_result expected, const char *what, int line) {
    static test_batch before;
    motus_result results[3];
    int index = -7, k;
    const char *field = "untouched";
    static const char *const names[3] = {"motus_scene_check", "motus_batch_check", "motus_batch_step"};
    memcpy(&before, t, sizeof *t);
    results[0] = motus_scene_check(scene, batch);
    results[1] = motus_batch_check(scene, batch, 0, N, &index, &field);
    results[2] = motus_batch_step(scene, batch, 0, N, DT);
    for (k = 0; k < 3; ++k)
        if (results[k] != expected) {
            fprintf(stderr, "%s:%d: %s: %s gave %d (%s), expected %d (%s)\n", __FILE__, line, what, names[k],
                    (int)results[k], motus_result_string(results[k]), (int)expected, motus_result_string(expected));
            motus_test_failures++;
        }
    if (!same_bytes(before.memory, t->memory, sizeof t->memory)) {
        fprintf(stderr, "%s:%d: %s: arrays changed\n", __FILE__, line, what);
        motus_test_failures++;
    }
    if (index != -7 || strcmp(field, "untouched") != 0) {
        fprintf(stderr, "%s:%d: %s: motus_batch_check wrote its outputs\n", __FILE__, line, what);
        motus_test_failures++;
    }
}
#define ENSURE_SCENE_REJECTED(scene, batch, t, expected, what) \
    ensure_scene_rejected_at(scene, batch, t, expected, what, __LINE__)

/* motus_batch_step (and motus_batch_check, which takes no dt) on a valid scene with a bad range or dt. */
static void ensure_step_rejected_at(const motus_scene *scene, test_batch *t, int first, int count, motus_real dt,
                                    motus_result expected, int check_too, const char *what, int line) {
    static test_batch before;
    motus_result result;
    int index = -7;
    const char *field = "untouched";
    memcpy(&before, t, sizeof *t);
    result = motus_batch_step(scene, &t->batch, first, count, dt);
    if (result != expected) {
        fprintf(stderr, "%s:%d: %s: motus_batch_step gave %d (%s), expected %d (%s)\n", __FILE__, line, what,
                (int)result, motus_result_string(result), (int)expected, motus_result_string(expected));
        motus_test_failures++;
    }
    if (check_too) {
        result = motus_batch_check(scene, &t->batch, first, count, &index, &field);
        if (result != expected || index != -7 || strcmp(field, "untouched") != 0) {
            fprintf(stderr, "%s:%d: %s: motus_batch_check gave %d (%s), expected %d (%s), outputs %s\n", __FILE__,
                    line, what, (int)result, motus_result_string(result), (int)expected,
                    motus_result_string(expected), index != -7 ? "written" : "untouched");
            motus_test_failures++;
        }
    }
    if (!same_bytes(before.memory, t->memory, sizeof t->memory)) {
        fprintf(stderr, "%s:%d: %s: arrays changed\n", __FILE__, line, what);
        motus_test_failures++;
    }
}
#define ENSURE_STEP_REJECTED(scene, t, first, count, dt, expected, check_too, what) \
    ensure_step_rejected_at(scene, t, first, count, dt, expected, check_too, what, __LINE__)

/* A valid scene with everything, damping per step, and its 2D batch with every array. */
static void valid_setup(motus_scene *s, test_batch *t, int dims) {
    make_scene(s, ALL_HAS, MOTUS_SEMI_IMPLICIT_EULER);
    bind(t, dims, ALL_HAS, 0, 0);
    fill_random(t, s, 11);
    ENSURE_EQ_INT(motus_scene_check(s, &t->batch), MOTUS_OK);
}

TEST(scene_check_rejects_bad_scenes) {
    static test_batch t;
    static const int bad_dims[] = {0, 1, 4, -1, INT_MIN, INT_MAX};
    static const motus_method unsupported[] = {MOTUS_POSITION_VERLET, MOTUS_VELOCITY_VERLET, MOTUS_LEAPFROG,
                                               MOTUS_MIDPOINT, MOTUS_RK4, MOTUS_FOREST_RUTH,
                                               MOTUS_EXACT_LINEAR_DRAG, MOTUS_METHOD_COUNT, (motus_method)-1};
    motus_scene s, bad;
    motus_batch b;
    int i, d, dims;
    char what[96];
    valid_setup(&s, &t, 2);
    ENSURE_SCENE_REJECTED(NULL, &t.batch, &t, MOTUS_ERROR_NULL_POINTER, "NULL scene");
    ENSURE_SCENE_REJECTED(&s, NULL, &t, MOTUS_ERROR_NULL_POINTER, "NULL batch");
    ENSURE_EQ_INT(motus_batch_check(NULL, NULL, 0, 0, NULL, NULL), MOTUS_ERROR_NULL_POINTER);
    ENSURE_EQ_INT(motus_batch_step(NULL, NULL, 0, 0, DT), MOTUS_ERROR_NULL_POINTER);

    /* Unknown has bits, both dampings, dimensions, methods. */
    for (i = 9; i < 32; ++i) {
        bad = s, bad.has |= 1u << i;
        sprintf(what, "unknown has bit %d", i);
        ENSURE_SCENE_REJECTED(&bad, &t.batch, &t, MOTUS_ERROR_INVALID_SCENE, what);
    }
    bad = s, bad.has |= BOTH_DAMPINGS;
    ENSURE_SCENE_REJECTED(&bad, &t.batch, &t, MOTUS_ERROR_INVALID_SCENE, "both dampings");
    bad.has = BOTH_DAMPINGS;
    ENSURE_SCENE_REJECTED(&bad, &t.batch, &t, MOTUS_ERROR_INVALID_SCENE, "both dampings, nothing else");
    for (i = 0; i < (int)(sizeof bad_dims / sizeof bad_dims[0]); ++i) {
        b = t.batch, b.dimensions = bad_dims[i];
        sprintf(what, "dimensions %d", bad_dims[i]);
        ENSURE_SCENE_REJECTED(&s, &b, &t, MOTUS_ERROR_INVALID_SCENE, what);
    }
    for (i = 0; i < (int)(sizeof unsupported / sizeof unsupported[0]); ++i) {
        bad = s, bad.method = unsupported[i];
        sprintf(what, "method %d", (int)unsupported[i]);
        ENSURE_SCENE_REJECTED(&bad, &t.batch, &t, MOTUS_ERROR_UNSUPPORTED, what);
    }

    /* Arrays the scene needs, in 2D and 3D. */
    for (dims = 2; dims <= 3; ++dims) {
        valid_setup(&s, &t, dims);
        for (d = 0; d < dims; ++d) {
            b = t.batch, b.position[d] = NULL;
            sprintf(what, "%dD, position[%d] NULL", dims, d);
            ENSURE_SCENE_REJECTED(&s, &b, &t, MOTUS_ERROR_NULL_POINTER, what);
            b = t.batch, b.velocity[d] = NULL;
            sprintf(what, "%dD, velocity[%d] NULL", dims, d);
            ENSURE_SCENE_REJECTED(&s, &b, &t, MOTUS_ERROR_NULL_POINTER, what);
            b = t.batch, b.force[d] = NULL;
            sprintf(what, "%dD, force[%d] NULL with MOTUS_HAS_FORCES", dims, d);
            ENSURE_SCENE_REJECTED(&s, &b, &t, MOTUS_ERROR_NULL_POINTER, what);
        }
        b = t.batch, b.inverse_mass = NULL;
        ENSURE_SCENE_REJECTED(&s, &b, &t, MOTUS_ERROR_NULL_POINTER, "inverse_mass NULL with MOTUS_HAS_PARTICLE_MASS");
    }

    /* Parameters: NaN or Inf, out of range, in 2D and 3D (the z parameters count in 3D only). */
    for (dims = 2; dims <= 3; ++dims) {
        valid_setup(&s, &t, dims);
        for (d = 0; d < dims; ++d) {
            bad = s, bad.gravity[d] = d % 2 ? infinity() : not_a_number();
            sprintf(what, "%dD, gravity[%d] not finite", dims, d);
            ENSURE_SCENE_REJECTED(&bad, &t.batch, &t, MOTUS_ERROR_NOT_FINITE, what);
            bad = s, bad.attractor[d] = d % 2 ? not_a_number() : -infinity();
            sprintf(what, "%dD, attractor[%d] not finite", dims, d);
            ENSURE_SCENE_REJECTED(&bad, &t.batch, &t, MOTUS_ERROR_NOT_FINITE, what);
            bad = s, bad.bounds_min[d] = not_a_number();
            sprintf(what, "%dD, bounds_min[%d] NaN", dims, d);
            ENSURE_SCENE_REJECTED(&bad, &t.batch, &t, MOTUS_ERROR_NOT_FINITE, what);
            bad = s, bad.bounds_max[d] = infinity();
            sprintf(what, "%dD, bounds_max[%d] +Inf", dims, d);
            ENSURE_SCENE_REJECTED(&bad, &t.batch, &t, MOTUS_ERROR_NOT_FINITE, what);
            bad = s, bad.bounds_min[d] = -infinity();
            sprintf(what, "%dD, bounds_min[%d] -Inf", dims, d);
            ENSURE_SCENE_REJECTED(&bad, &t.batch, &t, MOTUS_ERROR_NOT_FINITE, what);
            bad = s, bad.bounds_min[d] = bad.bounds_max[d] + MOTUS_R(0.5);
            sprintf(what, "%dD, bounds_min[%d] > bounds_max[%d]", dims, d, d);
            ENSURE_SCENE_REJECTED(&bad, &t.batch, &t, MOTUS_ERROR_INVALID_SCENE, what);
        }
    }
    valid_setup(&s, &t, 2);
    bad = s, bad.linear_drag = not_a_number();
    ENSURE_SCENE_REJECTED(&bad, &t.batch, &t, MOTUS_ERROR_NOT_FINITE, "linear drag NaN");
    bad = s, bad.linear_drag = infinity();
    ENSURE_SCENE_REJECTED(&bad, &t.batch, &t, MOTUS_ERROR_NOT_FINITE, "linear drag +Inf");
    bad = s, bad.linear_drag = MOTUS_R(-0.1);
    ENSURE_SCENE_REJECTED(&bad, &t.batch, &t, MOTUS_ERROR_INVALID_FORCES, "linear drag < 0");
    bad = s, bad.quadratic_drag = -infinity();
    ENSURE_SCENE_REJECTED(&bad, &t.batch, &t, MOTUS_ERROR_NOT_FINITE, "quadratic drag -Inf");
    bad = s, bad.quadratic_drag = MOTUS_R(-1e-30);
    ENSURE_SCENE_REJECTED(&bad, &t.batch, &t, MOTUS_ERROR_INVALID_FORCES, "quadratic drag < 0");
    bad = s, bad.attractor_strength = not_a_number();
    ENSURE_SCENE_REJECTED(&bad, &t.batch, &t, MOTUS_ERROR_NOT_FINITE, "attractor strength NaN");
    bad = s, bad.attractor_strength = -1;
    ENSURE_SCENE_REJECTED(&bad, &t.batch, &t, MOTUS_ERROR_INVALID_FORCES, "attractor strength < 0");
    bad = s, bad.damping = MOTUS_R(-0.01);
    ENSURE_SCENE_REJECTED(&bad, &t.batch, &t, MOTUS_ERROR_INVALID_DAMPING, "damping per step < 0");
    bad = s, bad.damping = MOTUS_R(1.01);
    ENSURE_SCENE_REJECTED(&bad, &t.batch, &t, MOTUS_ERROR_INVALID_DAMPING, "damping per step > 1");
    bad = s, bad.has ^= BOTH_DAMPINGS, bad.damping = 2;
    ENSURE_SCENE_REJECTED(&bad, &t.batch, &t, MOTUS_ERROR_INVALID_DAMPING, "damping per second > 1");
    bad = s, bad.has ^= BOTH_DAMPINGS, bad.damping = -1;
    ENSURE_SCENE_REJECTED(&bad, &t.batch, &t, MOTUS_ERROR_INVALID_DAMPING, "damping per second < 0");
    bad = s, bad.restitution = MOTUS_R(-0.5);
    ENSURE_SCENE_REJECTED(&bad, &t.batch, &t, MOTUS_ERROR_INVALID_DAMPING, "restitution < 0");
    bad = s, bad.restitution = MOTUS_R(1.5);
    ENSURE_SCENE_REJECTED(&bad, &t.batch, &t, MOTUS_ERROR_INVALID_DAMPING, "restitution > 1");
    /* The uniform inverse mass, without MOTUS_HAS_PARTICLE_MASS. */
    bad = s, bad.has &= ~(unsigned)MOTUS_HAS_PARTICLE_MASS, bad.inverse_mass = not_a_number();
    ENSURE_SCENE_REJECTED(&bad, &t.batch, &t, MOTUS_ERROR_NOT_FINITE, "uniform inverse mass NaN");
    bad.inverse_mass = infinity();
    ENSURE_SCENE_REJECTED(&bad, &t.batch, &t, MOTUS_ERROR_NOT_FINITE, "uniform inverse mass +Inf");
    bad.inverse_mass = MOTUS_R(-0.5);
    ENSURE_SCENE_REJECTED(&bad, &t.batch, &t, MOTUS_ERROR_INVALID_MASS, "uniform inverse mass < 0");
    bad.inverse_mass = -infinity();
    ENSURE_SCENE_REJECTED(&bad, &t.batch, &t, MOTUS_ERROR_NOT_FINITE, "uniform inverse mass -Inf");
}

TEST(scene_errors_match_the_particle_functions) {
    /* A NaN or Inf damping or restitution is reported as the particle function that does the same work
       reports it, so that a game switching layouts sees the same error: damping as
       motus_particle_damp_per_step / _per_second, restitution as motus_particle_bounce. */
    static test_batch t;
    motus_real (*const values[2])(void) = {not_a_number, infinity};
    motus_scene s, bad;
    motus_particle p;
    int i;
    char what[96];
    valid_setup(&s, &t, 2);
    ENSURE_EQ_INT(motus_particle_init(&p, motus_v2(0, 0), 1), MOTUS_OK);
    for (i = 0; i < 2; ++i) {
        const motus_real value = values[i]();
        bad = s, bad.damping = value;
        sprintf(what, "damping per step %g", (double)value);
        ENSURE_SCENE_REJECTED(&bad, &t.batch, &t, motus_particle_damp_per_step(&p, value), what);
        bad.has ^= BOTH_DAMPINGS;
        sprintf(what, "damping per second %g", (double)value);
        ENSURE_SCENE_REJECTED(&bad, &t.batch, &t, motus_particle_damp_per_second(&p, value, DT), what);
        bad = s, bad.restitution = value;
        sprintf(what, "restitution %g", (double)value);
        ENSURE_SCENE_REJECTED(&bad, &t.batch, &t,
                              motus_particle_bounce(&p, motus_v2(-1, -1), motus_v2(1, 1), value), what);
    }
}

TEST(scene_ignores_what_it_does_not_have) {
    /* Fields of features the scene does not declare are never read: NaN, negative or contradictory values
       there are fine, and so are the z parameters of a 2D scene. */
    static test_batch t, reference;
    motus_scene s, clean;
    int step;
    make_scene(&s, MOTUS_HAS_GRAVITY, MOTUS_SEMI_IMPLICIT_EULER);
    clean = s;
    bind(&t, 2, s.has, 1, 0);
    bind(&reference, 2, s.has, 1, 0);
    fill_random(&t, &clean, 4);
    fill_random(&reference, &clean, 4);
    s.gravity[2] = not_a_number();
    s.linear_drag = -1, s.quadratic_drag = not_a_number(), s.damping = 7;
    s.attractor[0] = infinity(), s.attractor_strength = -3;
    s.bounds_min[0] = 5, s.bounds_max[0] = -5, s.bounds_min[1] = not_a_number(), s.restitution = not_a_number();
    ENSURE_EQ_INT(motus_scene_check(&s, &t.batch), MOTUS_OK);
    for (step = 0; step < 5; ++step) {
        ENSURE_EQ_INT(motus_batch_step(&s, &t.batch, 0, N, DT), MOTUS_OK);
        ENSURE_EQ_INT(motus_batch_step(&clean, &reference.batch, 0, N, DT), MOTUS_OK);
    }
    ENSURE(same_state(&t, &reference, "unused fields broken"));
    /* With per-particle masses the uniform one is not read either; a 2D scene ignores z bounds. */
    make_scene(&s, MOTUS_HAS_PARTICLE_MASS | MOTUS_HAS_BOUNDS, MOTUS_SEMI_IMPLICIT_EULER);
    bind(&t, 2, s.has, 1, 0);
    fill_random(&t, &s, 4);
    s.inverse_mass = -infinity();
    s.bounds_min[2] = 1, s.bounds_max[2] = -1, s.gravity[0] = not_a_number();
    ENSURE_EQ_INT(motus_scene_check(&s, &t.batch), MOTUS_OK);
    ENSURE_EQ_INT(motus_batch_step(&s, &t.batch, 0, N, DT), MOTUS_OK);
    /* Accepted edges: bounds of zero width, damping and restitution 0 and 1, drags of -0. */
    make_scene(&s, ALL_HAS, MOTUS_EXPLICIT_EULER);
    s.bounds_min[0] = s.bounds_max[0] = 1, s.damping = 0, s.restitution = 1;
    s.linear_drag = negative_zero(), s.quadratic_drag = negative_zero(), s.attractor_strength = 0;
    bind(&t, 2, s.has, 1, 0);
    fill_random(&t, &s, 4);
    ENSURE_EQ_INT(motus_scene_check(&s, &t.batch), MOTUS_OK);
    ENSURE_EQ_INT(motus_batch_step(&s, &t.batch, 0, N, DT), MOTUS_OK);
    s.damping = 1, s.restitution = 0;
    ENSURE_EQ_INT(motus_batch_step(&s, &t.batch, 0, N, DT), MOTUS_OK);
}

TEST(step_rejects_bad_ranges_and_time_steps) {
    static test_batch t;
    motus_scene s;
    int dims;
    for (dims = 2; dims <= 3; ++dims) {
        valid_setup(&s, &t, dims);
        ENSURE_STEP_REJECTED(&s, &t, -1, 1, DT, MOTUS_ERROR_INVALID_COUNT, 1, "first -1");
        ENSURE_STEP_REJECTED(&s, &t, INT_MIN, 1, DT, MOTUS_ERROR_INVALID_COUNT, 1, "first INT_MIN");
        ENSURE_STEP_REJECTED(&s, &t, 0, -1, DT, MOTUS_ERROR_INVALID_COUNT, 1, "count -1");
        ENSURE_STEP_REJECTED(&s, &t, 5, INT_MIN, DT, MOTUS_ERROR_INVALID_COUNT, 1, "count INT_MIN");
        ENSURE_STEP_REJECTED(&s, &t, 1, INT_MAX, DT, MOTUS_ERROR_INVALID_COUNT, 1, "first + count overflows");
        ENSURE_STEP_REJECTED(&s, &t, INT_MAX, 1, DT, MOTUS_ERROR_INVALID_COUNT, 1, "first INT_MAX, count 1");
        ENSURE_STEP_REJECTED(&s, &t, INT_MAX, INT_MAX, DT, MOTUS_ERROR_INVALID_COUNT, 1, "both INT_MAX");
        ENSURE_STEP_REJECTED(&s, &t, 0, N, 0, MOTUS_ERROR_INVALID_TIME_STEP, 0, "dt 0");
        ENSURE_STEP_REJECTED(&s, &t, 0, N, negative_zero(), MOTUS_ERROR_INVALID_TIME_STEP, 0, "dt -0");
        ENSURE_STEP_REJECTED(&s, &t, 0, N, -DT, MOTUS_ERROR_INVALID_TIME_STEP, 0, "dt < 0");
        ENSURE_STEP_REJECTED(&s, &t, 0, N, not_a_number(), MOTUS_ERROR_INVALID_TIME_STEP, 0, "dt NaN");
        ENSURE_STEP_REJECTED(&s, &t, 0, N, infinity(), MOTUS_ERROR_INVALID_TIME_STEP, 0, "dt +Inf");
        ENSURE_STEP_REJECTED(&s, &t, 0, N, -infinity(), MOTUS_ERROR_INVALID_TIME_STEP, 0, "dt -Inf");
        /* Empty ranges are fine anywhere, even at INT_MAX, and write nothing. */
        ENSURE_STEP_REJECTED(&s, &t, 0, 0, DT, MOTUS_OK, 1, "empty range");
        ENSURE_STEP_REJECTED(&s, &t, N, 0, DT, MOTUS_OK, 1, "empty range at the end");
        ENSURE_STEP_REJECTED(&s, &t, INT_MAX, 0, DT, MOTUS_OK, 1, "empty range at INT_MAX");
    }
}

/* One bad argument of motus_batch_add_spring_forces per case: a spring, a batch field or a count. */
static motus_result break_spring_call(int which, motus_batch *b, motus_spring bad[3], const motus_spring **springs,
                                      int *count, int *spring_count, const char **what) {
    switch (which) {
    case 0: *what = "NULL fy"; b->force[1] = NULL; return MOTUS_ERROR_NULL_POINTER;
    case 1: *what = "NULL y"; b->position[1] = NULL; return MOTUS_ERROR_NULL_POINTER;
    case 2: *what = "NULL vx"; b->velocity[0] = NULL; return MOTUS_ERROR_NULL_POINTER;
    case 3: *what = "NULL fx"; b->force[0] = NULL; return MOTUS_ERROR_NULL_POINTER;
    case 4: *what = "3D batch"; b->dimensions = 3; return MOTUS_ERROR_UNSUPPORTED;
    case 5: *what = "NULL springs"; *springs = NULL; return MOTUS_ERROR_INVALID_FORCES;
    case 6: *what = "spring count < 0"; *spring_count = -1; return MOTUS_ERROR_INVALID_FORCES;
    case 7: *what = "end a = count"; bad[1].a = N; return MOTUS_ERROR_INVALID_FORCES;
    case 8: *what = "end a = -1"; bad[1].a = -1; return MOTUS_ERROR_INVALID_FORCES;
    case 9: *what = "end b = count"; bad[2].b = N; return MOTUS_ERROR_INVALID_FORCES;
    case 10: *what = "end b = -2"; bad[0].b = -2; return MOTUS_ERROR_INVALID_FORCES;
    case 11: *what = "a == b"; bad[0].b = 0; return MOTUS_ERROR_INVALID_FORCES;
    case 12: *what = "stiffness < 0"; bad[2].stiffness = -1; return MOTUS_ERROR_INVALID_FORCES;
    case 13: *what = "stiffness NaN"; bad[2].stiffness = not_a_number(); return MOTUS_ERROR_NOT_FINITE;
    case 14: *what = "anchor Inf"; bad[1].anchor.y = infinity(); return MOTUS_ERROR_NOT_FINITE;
    case 15: *what = "rest length < 0"; bad[0].rest_length = -1; return MOTUS_ERROR_INVALID_FORCES;
    case 16: *what = "rest length NaN"; bad[0].rest_length = not_a_number(); return MOTUS_ERROR_NOT_FINITE;
    case 17: *what = "damping < 0"; bad[0].damping = MOTUS_R(-0.5); return MOTUS_ERROR_INVALID_FORCES;
    case 18: *what = "damping -Inf"; bad[0].damping = -infinity(); return MOTUS_ERROR_NOT_FINITE;
    /* A particle count < 0 is MOTUS_ERROR_INVALID_COUNT ("a particle count < 0"), as in motus_stepper_step,
       with or without springs. */
    case 19: *what = "count < 0, no springs"; *count = -1, *spring_count = 0; return MOTUS_ERROR_INVALID_COUNT;
    case 20: *what = "count < 0, springs"; *count = -1; return MOTUS_ERROR_INVALID_COUNT;
    default: return MOTUS_RESULT_COUNT;
    }
}

TEST(add_spring_forces_rejects_bad_arguments) {
    /* Every error of motus_batch_add_spring_forces, with the force arrays (and all others) unchanged. */
    static test_batch t, before;
    motus_spring springs[3], bad[3];
    motus_batch b;
    motus_scene s;
    int which;
    valid_setup(&s, &t, 2);
    memset(springs, 0, sizeof springs);
    springs[0].a = 0, springs[0].b = 1, springs[0].rest_length = 1, springs[0].stiffness = 5;
    springs[1].a = 2, springs[1].b = -1, springs[1].anchor = motus_v2(1, 1), springs[1].stiffness = 3;
    springs[2].a = N - 1, springs[2].b = 7, springs[2].damping = 1, springs[2].stiffness = 1;
    memcpy(&before, &t, sizeof t);
    ENSURE_EQ_INT(motus_batch_add_spring_forces(&t.batch, N, springs, 3), MOTUS_OK);
    ENSURE(!same_bytes(before.memory[FORCE], t.memory[FORCE], sizeof t.memory[FORCE]));
    ENSURE(same_bytes(before.memory[POSITION], t.memory[POSITION], sizeof t.memory[POSITION]));
    ENSURE(guards_intact(&t));
    ENSURE_EQ_INT(motus_batch_add_spring_forces(NULL, N, springs, 3), MOTUS_ERROR_NULL_POINTER);
    for (which = 0;; ++which) {
        const motus_spring *given = bad;
        const char *what = "";
        int count = N, spring_count = 3;
        motus_result expected, result;
        b = t.batch;
        memcpy(bad, springs, sizeof bad);
        expected = break_spring_call(which, &b, bad, &given, &count, &spring_count, &what);
        if (expected == MOTUS_RESULT_COUNT) break;
        memcpy(&before, &t, sizeof t);
        result = motus_batch_add_spring_forces(&b, count, given, spring_count);
        if (result != expected) {
            fprintf(stderr, "%s: gave %d (%s), expected %d (%s)\n", what, (int)result, motus_result_string(result),
                    (int)expected, motus_result_string(expected));
            motus_test_failures++;
        }
        if (!same_bytes(before.memory, t.memory, sizeof t.memory)) {
            fprintf(stderr, "%s: arrays changed\n", what);
            motus_test_failures++;
        }
    }
    /* No springs: nothing to read, so no arrays are needed, and NULL springs are fine. */
    memset(&b, 0, sizeof b);
    b.dimensions = 2;
    ENSURE_EQ_INT(motus_batch_add_spring_forces(&b, N, NULL, 0), MOTUS_OK);
    ENSURE_EQ_INT(motus_batch_add_spring_forces(&b, 0, NULL, 0), MOTUS_OK);
}

TEST(add_spring_forces_equals_the_stepper_springs) {
    /* The forces motus_batch_add_spring_forces adds, for springs sharing particles, are the ones the
       stepper applies: one semi-implicit step of a unit-mass batch with springs only equals the stepper's. */
    static test_batch t, expected;
    static motus_particle p[N];
    static motus_vec2 base_force[N];
    static motus_spring springs[SPRINGS];
    motus_stepper stepper;
    motus_scene s;
    int i, step;
    make_scene(&s, MOTUS_HAS_FORCES | MOTUS_HAS_PARTICLE_MASS, MOTUS_SEMI_IMPLICIT_EULER);
    bind(&t, 2, s.has, 1, 0);
    bind(&expected, 2, s.has, 1, 0);
    fill_random(&t, &s, 8);
    make_springs(springs);
    to_particles(&t, &s, p);
    for (i = 0; i < N; ++i) base_force[i] = motus_v2(0, 0);
    ENSURE_EQ_INT(init_stepper(&stepper, MOTUS_SEMI_IMPLICIT_EULER), MOTUS_OK);
    for (step = 0; step < 3; ++step) {
        ENSURE_EQ_INT(batch_step(&s, &t, base_force, springs, SPRINGS, DT), MOTUS_OK);
        ENSURE_EQ_INT(single_step(&s, &stepper, p, base_force, springs, SPRINGS, DT), MOTUS_OK);
    }
    from_particles(&expected, p);
    ENSURE(same_state(&t, &expected, "springs only"));
    /* Forces add up: twice the springs into the same arrays is twice the force (exactly, for this sum). */
    for (i = 0; i < N; ++i) array_of(&t, FORCE)[i] = 0, array_of(&t, FORCE + 1)[i] = 0;
    ENSURE_EQ_INT(motus_batch_add_spring_forces(&t.batch, N, springs, 1), MOTUS_OK);
    {
        const motus_real once = array_of(&t, FORCE)[springs[0].a];
        ENSURE(once != 0);
        ENSURE_EQ_INT(motus_batch_add_spring_forces(&t.batch, N, springs, 1), MOTUS_OK);
        ENSURE(array_of(&t, FORCE)[springs[0].a] == 2 * once);
        ENSURE(array_of(&t, FORCE)[springs[0].b] == -2 * once);
    }
}

/* =================================================================================================
   Bad data
   ================================================================================================= */
TEST(batch_check_finds_the_first_bad_particle) {
    static test_batch t, before;
    static const char *const names[3] = {"position", "velocity", "force"};
    motus_scene s;
    int dims, kind, d, v, index;
    const char *field;
    char what[96];
    for (dims = 2; dims <= 3; ++dims) {
        valid_setup(&s, &t, dims);
        index = -7, field = "untouched";
        ENSURE_EQ_INT(motus_batch_check(&s, &t.batch, 0, N, &index, &field), MOTUS_OK);
        ENSURE(index == -7 && strcmp(field, "untouched") == 0); /* outputs written only on an error */
        /* NaN, +Inf, -Inf in each field of each dimension. */
        for (kind = 0; kind < 3; ++kind)
            for (d = 0; d < dims; ++d)
                for (v = 0; v < 3; ++v) {
                    const motus_real value = v == 0 ? not_a_number() : v == 1 ? infinity() : -infinity();
                    fill_random(&t, &s, 11);
                    array_of(&t, POSITION + 3 * kind + d)[123] = value;
                    memcpy(&before, &t, sizeof t);
                    index = -7, field = NULL;
                    sprintf(what, "%dD, %s[%d][123] = %g", dims, names[kind], d, (double)value);
                    ENSURE_EQ_INT(motus_batch_check(&s, &t.batch, 0, N, &index, &field), MOTUS_ERROR_NOT_FINITE);
                    ENSURE_EQ_INT(index, 123);
                    if (!field || strcmp(field, names[kind]) != 0)
                        fprintf(stderr, "%s: field %s\n", what, field ? field : "NULL"), motus_test_failures++;
                    ENSURE(same_bytes(before.memory, t.memory, sizeof t.memory));
                    /* Outside the range: not seen. Either output may be NULL. */
                    ENSURE_EQ_INT(motus_batch_check(&s, &t.batch, 0, 123, &index, &field), MOTUS_OK);
                    ENSURE_EQ_INT(motus_batch_check(&s, &t.batch, 124, N - 124, &index, &field), MOTUS_OK);
                    ENSURE_EQ_INT(motus_batch_check(&s, &t.batch, 123, 1, NULL, NULL), MOTUS_ERROR_NOT_FINITE);
                }
        /* The inverse mass: not finite, or negative (-Inf is both: not finite first, as the stepper). */
        for (v = 0; v < 5; ++v) {
            static const motus_result expected[5] = {MOTUS_ERROR_NOT_FINITE, MOTUS_ERROR_NOT_FINITE,
                                                     MOTUS_ERROR_NOT_FINITE, MOTUS_ERROR_INVALID_MASS,
                                                     MOTUS_ERROR_INVALID_MASS};
            const motus_real values[5] = {not_a_number(), infinity(), -infinity(), MOTUS_R(-0.5), -REAL_MAX};
            fill_random(&t, &s, 11);
            array_of(&t, INVERSE_MASS)[200] = values[v];
            index = -7, field = NULL;
            ENSURE_EQ_INT(motus_batch_check(&s, &t.batch, 0, N, &index, &field), expected[v]);
            ENSURE_EQ_INT(index, 200);
            ENSURE(field && strcmp(field, "inverse_mass") == 0);
        }
        /* The first of several bad particles. -0 is not a negative mass. */
        fill_random(&t, &s, 11);
        array_of(&t, INVERSE_MASS)[10] = negative_zero();
        array_of(&t, POSITION + dims - 1)[250] = not_a_number();
        array_of(&t, INVERSE_MASS)[170] = -1;
        array_of(&t, FORCE + 1)[160] = infinity();
        ENSURE_EQ_INT(motus_batch_check(&s, &t.batch, 0, N, &index, &field), MOTUS_ERROR_NOT_FINITE);
        ENSURE(index == 160 && strcmp(field, "force") == 0);
        ENSURE_EQ_INT(motus_batch_check(&s, &t.batch, 161, N - 161, &index, &field), MOTUS_ERROR_INVALID_MASS);
        ENSURE(index == 170 && strcmp(field, "inverse_mass") == 0);
        ENSURE_EQ_INT(motus_batch_check(&s, &t.batch, 171, N - 171, &index, &field), MOTUS_ERROR_NOT_FINITE);
        ENSURE(index == 250 && strcmp(field, "position") == 0);
        /* Fields the scene does not read are not checked. */
        s.has &= ~(unsigned)(MOTUS_HAS_FORCES | MOTUS_HAS_PARTICLE_MASS);
        ENSURE_EQ_INT(motus_batch_check(&s, &t.batch, 0, 250, &index, &field), MOTUS_OK);
    }
    /* In 2D the z arrays are not read. */
    valid_setup(&s, &t, 2);
    array_of(&t, POSITION + 2)[5] = not_a_number(), array_of(&t, VELOCITY + 2)[6] = infinity();
    array_of(&t, FORCE + 2)[7] = not_a_number();
    ENSURE_EQ_INT(motus_batch_check(&s, &t.batch, 0, N, NULL, NULL), MOTUS_OK);
}

/* Scenes for the bad-data tests: fast kernels and the general one, with and without the optional arrays. */
static const unsigned BAD_DATA_SCENES[] = {
    0,
    MOTUS_HAS_GRAVITY,
    MOTUS_HAS_FORCES,
    MOTUS_HAS_PARTICLE_MASS,
    MOTUS_HAS_GRAVITY | MOTUS_HAS_PARTICLE_MASS | MOTUS_HAS_DAMPING_PER_STEP,
    MOTUS_HAS_GRAVITY | MOTUS_HAS_LINEAR_DRAG | MOTUS_HAS_PARTICLE_MASS | MOTUS_HAS_FORCES,
    MOTUS_HAS_BOUNDS,
    MOTUS_HAS_BOUNDS | MOTUS_HAS_PARTICLE_MASS | MOTUS_HAS_DAMPING_PER_SECOND,
    ALL_HAS,
};

TEST(step_on_bad_data) {
    /* A NaN or Inf in any array the scene reads (at particle 123, and at the last particle, which is in
       the partial vector), in 2D and 3D, both methods.
       Release build: motus_batch_step returns MOTUS_ERROR_NOT_FINITE and has written the range; every
       other particle is exactly what a clean step gives it.
       MOTUS_CHECKED: the result is motus_batch_check's, and nothing is written. A negative inverse mass is
       MOTUS_ERROR_INVALID_MASS there (a release build does not look for it). */
    static test_batch t, clean, before;
    int scene, dims, method, which, v, at, i, a;
    char what[128];
    for (scene = 0; scene < (int)(sizeof BAD_DATA_SCENES / sizeof BAD_DATA_SCENES[0]); ++scene)
        for (dims = 2; dims <= 3; ++dims)
            for (method = 0; method < 2; ++method)
                for (which = 0; which < ARRAYS; ++which)
                    for (v = 0; v < 4; ++v)
                        for (at = 0; at < 2; ++at) {
                            const int bad = at ? N - 1 : 123;
                            const motus_real value = v == 0   ? not_a_number()
                                                     : v == 1 ? infinity()
                                                     : v == 2 ? -infinity()
                                                              : MOTUS_R(-0.5);
                            motus_scene s;
                            motus_result result;
                            make_scene(&s, BAD_DATA_SCENES[scene], (motus_method)method);
                            bind(&t, dims, s.has, 1, 0);
                            bind(&clean, dims, s.has, 1, 0);
                            if (!array_used(&t, which) || (v == 3 && which != INVERSE_MASS)) continue;
                            fill_random(&t, &s, 21);
                            fill_random(&clean, &s, 21);
                            ENSURE_EQ_INT(motus_batch_step(&s, &clean.batch, 0, N, DT), MOTUS_OK);
                            array_of(&t, which)[bad] = value;
                            memcpy(&before, &t, sizeof t);
                            result = motus_batch_step(&s, &t.batch, 0, N, DT);
                            sprintf(what, "has 0x%03x, %dD, %s, array %d [%d] = %g", s.has, dims,
                                    motus_method_name((motus_method)method), which, bad, (double)value);
#ifdef MOTUS_CHECKED
                            {
                                const motus_result expected = motus_batch_check(&s, &t.batch, 0, N, NULL, NULL);
                                if (result != expected || expected == MOTUS_OK ||
                                    !same_bytes(before.memory, t.memory, sizeof t.memory)) {
                                    fprintf(stderr, "%s: gave %s, check %s, %s\n", what, motus_result_string(result),
                                            motus_result_string(expected),
                                            same_bytes(before.memory, t.memory, sizeof t.memory) ? "nothing written"
                                                                                                 : "arrays written");
                                    motus_test_failures++;
                                }
                            }
#else
                            if (v == 3) continue; /* a negative mass is not looked for in release builds */
                            if (result != MOTUS_ERROR_NOT_FINITE) {
                                fprintf(stderr, "%s: gave %d (%s), expected MOTUS_ERROR_NOT_FINITE\n", what,
                                        (int)result, motus_result_string(result));
                                motus_test_failures++;
                            }
                            /* The range was written: the other particles are stepped as usual. */
                            for (a = 0; a < 6; ++a) {
                                if (a % 3 >= dims) continue;
                                for (i = 0; i < N; ++i)
                                    if (i != bad && !same_bytes(&array_of(&t, a)[i], &array_of(&clean, a)[i],
                                                                sizeof(motus_real))) {
                                        fprintf(stderr, "%s: particle %d not stepped as usual\n", what, i);
                                        motus_test_failures++;
                                        i = N, a = 6;
                                    }
                            }
#endif
                        }
    (void)i, (void)a;
}

/* MOTUS_ERROR_NOT_FINITE after writing the range in release builds; with MOTUS_CHECKED the dry run finds the
   overflow first: MOTUS_ERROR_OVERFLOW, and every array is as it was. */
#ifdef MOTUS_CHECKED
#define OVERFLOW_RESULT MOTUS_ERROR_OVERFLOW
#else
#define OVERFLOW_RESULT MOTUS_ERROR_NOT_FINITE
#endif
static void ensure_overflow_reported(const motus_scene *s, test_batch *t) {
    static motus_real saved[ARRAYS][STRIDE + GUARD];
    memcpy(saved, t->memory, sizeof saved);
    ENSURE_EQ_INT(motus_batch_check(s, &t->batch, 0, N, NULL, NULL), MOTUS_OK);
    ENSURE_EQ_INT(motus_batch_step(s, &t->batch, 0, N, 1), OVERFLOW_RESULT);
#ifdef MOTUS_CHECKED
    ENSURE(memcmp(saved, t->memory, sizeof saved) == 0);
#endif
}

TEST(overflow_is_not_finite) {
    /* Every input finite, but the new state is not: MOTUS_ERROR_NOT_FINITE in release builds,
       MOTUS_ERROR_OVERFLOW with nothing written in checked ones. Position overflow (x + v*h), and velocity
       overflow (v + F*(1/m)*h), in the whole-vector part and in the partial vector, both methods (explicit
       Euler moves x with the old velocity, so there an infinite new velocity leaves x finite), with and
       without bounds and damping (the checked build's dry run goes through the general kernel). */
    static test_batch t;
    motus_scene s;
    int dims, at, method, extra;
    for (extra = 0; extra < 2; ++extra)
    for (method = 0; method < 2; ++method)
    for (dims = 2; dims <= 3; ++dims)
        for (at = 0; at < 2; ++at) {
            const int i = at ? N - 1 : 64;
            make_scene(&s, MOTUS_HAS_PARTICLE_MASS | MOTUS_HAS_FORCES |
                           (extra ? MOTUS_HAS_BOUNDS | MOTUS_HAS_DAMPING_PER_STEP : 0u), (motus_method)method);
            bind(&t, dims, s.has, 1, 0);
            fill_random(&t, &s, 2);
            array_of(&t, POSITION + dims - 1)[i] = REAL_MAX * MOTUS_R(0.75);
            array_of(&t, VELOCITY + dims - 1)[i] = REAL_MAX * MOTUS_R(0.75);
            ensure_overflow_reported(&s, &t);
            fill_random(&t, &s, 2);
            array_of(&t, FORCE)[i] = REAL_MAX;
            array_of(&t, INVERSE_MASS)[i] = 4;
            ensure_overflow_reported(&s, &t);
        }
}

TEST(finite_sum_overflow_is_not_an_error) {
    /* The kernel sums the new positions to find NaN and Inf at little cost; with positions near the
       largest finite value that sum overflows while every value is finite. That is not an error: the
       step looks at the values one by one and returns MOTUS_OK, with the state as stepped. Every particle
       at +0.9*max (the sum is +Inf), alternately +-0.9*max (lane sums of +Inf and -Inf make NaN), and
       both at once with a real NaN (an error after all). */
    static test_batch t;
    const motus_real big = REAL_MAX * MOTUS_R(0.9);
    motus_scene s;
    int dims, pattern, i, d, general;
    for (general = 0; general < 2; ++general)
        for (dims = 2; dims <= 3; ++dims)
            for (pattern = 0; pattern < 3; ++pattern) {
                make_scene(&s, general ? MOTUS_HAS_BOUNDS : 0u, MOTUS_SEMI_IMPLICIT_EULER);
                for (d = 0; d < 3; ++d) s.bounds_min[d] = -REAL_MAX, s.bounds_max[d] = REAL_MAX;
                bind(&t, dims, s.has, 1, 0);
                fill_random(&t, &s, 2);
                for (i = 0; i < N; ++i)
                    for (d = 0; d < dims; ++d) {
                        array_of(&t, POSITION + d)[i] = pattern == 0 || (i / 3 + d) % 2 ? big : -big;
                        array_of(&t, VELOCITY + d)[i] = 0;
                    }
                if (pattern == 2) array_of(&t, VELOCITY + 1)[N - 2] = not_a_number();
                ENSURE_EQ_INT(motus_batch_step(&s, &t.batch, 0, N, DT),
                              pattern == 2 ? MOTUS_ERROR_NOT_FINITE : MOTUS_OK);
                if (pattern == 2) continue;
                for (i = 0; i < N; ++i)
                    for (d = 0; d < dims; ++d) ENSURE(array_of(&t, POSITION + d)[i] == (pattern == 0 || (i / 3 + d) % 2 ? big : -big));
            }
    /* The brief's example: two particles at +3e38 (float) or 1e308 (double), at rest. */
    make_scene(&s, MOTUS_HAS_GRAVITY, MOTUS_SEMI_IMPLICIT_EULER);
    bind(&t, 2, s.has, 1, 0);
    fill_random(&t, &s, 2);
    array_of(&t, POSITION)[0] = array_of(&t, POSITION)[1] = REAL_MAX * MOTUS_R(0.88);
    array_of(&t, VELOCITY)[0] = array_of(&t, VELOCITY)[1] = 0;
    ENSURE_EQ_INT(motus_batch_step(&s, &t.batch, 0, 2, DT), MOTUS_OK);
    ENSURE(array_of(&t, POSITION)[0] == REAL_MAX * MOTUS_R(0.88));
}

TEST(spring_force_sums_that_overflow) {
    /* Every spring force finite, but two of them (0.6 of the largest real each) add up past it on one
       particle: MOTUS_ERROR_NOT_FINITE, after writing in release builds, with nothing written in checked
       ones (the fuzzer found a checked build writing here). Summed at a spring's first end, at its second
       end, and, as controls, the same two forces cancelling on one particle and landing on two particles:
       MOTUS_OK and exactly the forces of the single springs (the checked build's bound overflows there and
       it replays each particle's sum). */
    static test_batch t;
    static motus_real saved[ARRAYS][STRIDE + GUARD];
    const motus_real k = REAL_MAX * MOTUS_R(0.6);
    motus_spring springs[2];
    motus_scene s;
    int c, i;
    for (c = 0; c < 4; ++c) {
        make_scene(&s, MOTUS_HAS_FORCES, MOTUS_SEMI_IMPLICIT_EULER);
        bind(&t, 2, s.has, 1, 0);
        fill_random(&t, &s, 3);
        for (i = 0; i < 8; ++i) array_of(&t, POSITION)[i] = 0, array_of(&t, POSITION + 1)[i] = 0;
        for (i = 0; i < N; ++i) array_of(&t, FORCE)[i] = 0, array_of(&t, FORCE + 1)[i] = 0;
        memset(springs, 0, sizeof springs);
        springs[0].stiffness = springs[1].stiffness = k; /* rest length 0, no damping: F = -k*d */
        springs[0].b = springs[1].b = -1;
        array_of(&t, POSITION)[1] = 1;                       /* d = (1, 0) from an anchor at 0: F = -k */
        springs[0].a = 1;
        springs[1].a = c == 2 ? 1 : c == 3 ? 2 : 1;
        if (c == 2) springs[1].anchor.x = 2;                 /* d = (-1, 0): +k, cancelling */
        if (c == 3) array_of(&t, POSITION)[2] = 1;           /* the same force on particle 2 */
        if (c == 1) {                                        /* +k twice on particle 3, a second end */
            springs[0].a = 4, springs[0].b = 3;              /* x4 - x3 = 1: particle 3 gets +k */
            array_of(&t, POSITION)[4] = 1;
            springs[1].a = 3, springs[1].anchor.x = 1;       /* d = (-1, 0): +k */
        }
        memcpy(saved, t.memory, sizeof saved);
        if (c < 2) {
            ENSURE_EQ_INT(motus_batch_add_spring_forces(&t.batch, N, springs, 2), MOTUS_ERROR_NOT_FINITE);
#ifdef MOTUS_CHECKED
            ENSURE(memcmp(saved, t.memory, sizeof saved) == 0);
#else
            ENSURE(array_of(&t, FORCE)[c == 0 ? 1 : 3] == (c == 0 ? -infinity() : infinity()));
#endif
            continue;
        }
        ENSURE_EQ_INT(motus_batch_add_spring_forces(&t.batch, N, springs, 2), MOTUS_OK);
        ENSURE(array_of(&t, FORCE)[1] == (c == 2 ? 0 : -k));
        ENSURE(array_of(&t, FORCE)[2] == (c == 2 ? 0 : -k));
        ENSURE(array_of(&t, FORCE + 1)[1] == 0 && array_of(&t, FORCE + 1)[2] == 0);
    }
}

/* =================================================================================================
   Bounds, damping, immovable particles
   ================================================================================================= */
TEST(bounds_mirror_and_bounce) {
    /* Box [-1, 1] in every axis, no forces, h = 1/8 (all values below exact in binary). Per axis:
       x = 0.75, v = 5 ends at 1.375: mirrored to 0.625 with v = -5*restitution; the same at the lower wall;
       x = 0.5, v = 4 lands exactly on the wall at 1: stays there, v unchanged; at rest on a wall: stays;
       inside: no bounce. Restitution 0, 0.5 and 1, 2D and 3D; 2D equal bit for bit to motus_particle_bounce. */
    static const double x0[6] = {0.75, -0.75, 0.5, 1, -1, 0}, v0[6] = {5, -5, 4, 0, 0, 1};
    static const double x1[6] = {0.625, -0.625, 1, 1, -1, 0.125};
    static const int bounces[6] = {1, 1, 0, 0, 0, 0};
    static const motus_real restitutions[3] = {0, MOTUS_R(0.5), 1};
    static test_batch t;
    const motus_real h = MOTUS_R(0.125);
    motus_scene s;
    int dims, r, i, d;
    for (dims = 2; dims <= 3; ++dims)
        for (r = 0; r < 3; ++r) {
            make_scene(&s, MOTUS_HAS_BOUNDS, MOTUS_SEMI_IMPLICIT_EULER);
            for (d = 0; d < 3; ++d) s.bounds_min[d] = -1, s.bounds_max[d] = 1;
            s.restitution = restitutions[r];
            bind(&t, dims, s.has, 1, 0);
            fill_random(&t, &s, 3);
            /* Particle i has case i in x, case i+1 in y, case i+2 in z (mod 6). */
            for (i = 0; i < N; ++i)
                for (d = 0; d < 3; ++d) {
                    array_of(&t, POSITION + d)[i] = (motus_real)x0[(i + d) % 6];
                    array_of(&t, VELOCITY + d)[i] = (motus_real)v0[(i + d) % 6];
                }
            ENSURE_EQ_INT(motus_batch_step(&s, &t.batch, 0, N, h), MOTUS_OK);
            for (i = 0; i < N; ++i)
                for (d = 0; d < dims; ++d) {
                    const int c = (i + d) % 6;
                    const motus_real x = array_of(&t, POSITION + d)[i], v = array_of(&t, VELOCITY + d)[i];
                    const double expected_v = bounces[c] ? -v0[c] * (double)restitutions[r] : v0[c];
                    if (x != (motus_real)x1[c] || v != (motus_real)expected_v) {
                        fprintf(stderr, "%dD, restitution %g, particle %d axis %d: x %g v %g, expected %g %g\n", dims,
                                (double)restitutions[r], i, d, (double)x, (double)v, x1[c], expected_v);
                        motus_test_failures++;
                    }
                    if (dims == 2 && d == 0) {
                        motus_particle p;
                        memset(&p, 0, sizeof p);
                        p.position = motus_v2((motus_real)x0[c], (motus_real)x0[(c + 1) % 6]);
                        p.velocity = motus_v2((motus_real)v0[c], (motus_real)v0[(c + 1) % 6]);
                        p.inverse_mass = s.inverse_mass;
                        ENSURE_EQ_INT(motus_particle_step(&p, h), MOTUS_OK);
                        ENSURE_EQ_INT(motus_particle_bounce(&p, motus_v2(-1, -1), motus_v2(1, 1), s.restitution),
                                      MOTUS_OK);
                        ENSURE(same_bytes(&p.position.x, &array_of(&t, POSITION)[i], sizeof(motus_real)));
                        ENSURE(same_bytes(&p.position.y, &array_of(&t, POSITION + 1)[i], sizeof(motus_real)));
                        ENSURE(same_bytes(&p.velocity.x, &array_of(&t, VELOCITY)[i], sizeof(motus_real)));
                        ENSURE(same_bytes(&p.velocity.y, &array_of(&t, VELOCITY + 1)[i], sizeof(motus_real)));
                    }
                }
        }
}

TEST(bounds_keep_particles_inside) {
    /* Gravity, an attractor and random starts inside the box: after many steps every particle is still
       inside (a particle can leave only by more than the box width in one step). */
    static test_batch t;
    motus_scene s;
    int dims, step, i, d;
    for (dims = 2; dims <= 3; ++dims) {
        make_scene(&s, MOTUS_HAS_GRAVITY | MOTUS_HAS_ATTRACTOR | MOTUS_HAS_BOUNDS | MOTUS_HAS_DAMPING_PER_STEP,
                   MOTUS_SEMI_IMPLICIT_EULER);
        bind(&t, dims, s.has, 1, 0);
        fill_random(&t, &s, 6);
        for (step = 0; step < 600; ++step) ENSURE_EQ_INT(motus_batch_step(&s, &t.batch, 0, N, DT), MOTUS_OK);
        for (i = 0; i < N; ++i)
            for (d = 0; d < dims; ++d) {
                const motus_real x = array_of(&t, POSITION + d)[i];
                if (!(x >= s.bounds_min[d] && x <= s.bounds_max[d])) {
                    fprintf(stderr, "%dD particle %d axis %d at %g\n", dims, i, d, (double)x);
                    motus_test_failures++;
                }
            }
    }
}

TEST(damping_per_second_is_rate_independent) {
    /* No forces, damping per second 0.25: after one second at 30, 60 or 144 steps a second every velocity
       is 0.25 of what it was (up to rounding), bit for bit what motus_particle_damp_per_second gives
       step by step. Damping per step 0.99 instead keeps 0.99^30, 0.99^60, 0.99^144: the rate matters. */
    static const int rates[3] = {30, 60, 144};
    static test_batch t;
    static motus_real v0[N];
    motus_scene s;
    int r, per_second, i, step;
    for (per_second = 0; per_second < 2; ++per_second)
        for (r = 0; r < 3; ++r) {
            const motus_real h = MOTUS_R(1.0) / (motus_real)rates[r];
            const double kept = per_second ? 0.25 : pow(0.99, rates[r]);
            make_scene(&s, per_second ? MOTUS_HAS_DAMPING_PER_SECOND : MOTUS_HAS_DAMPING_PER_STEP,
                       MOTUS_SEMI_IMPLICIT_EULER);
            s.damping = per_second ? MOTUS_R(0.25) : MOTUS_R(0.99);
            bind(&t, 2, s.has, 1, 0);
            fill_random(&t, &s, 9);
            memcpy(v0, array_of(&t, VELOCITY), sizeof v0);
            for (step = 0; step < rates[r]; ++step) ENSURE_EQ_INT(motus_batch_step(&s, &t.batch, 0, N, h), MOTUS_OK);
            for (i = 0; i < N; ++i) {
                motus_particle p;
                const motus_real v = array_of(&t, VELOCITY)[i];
                if (!ENSURE_NEAR(v, (double)v0[i] * kept, 4 * rates[r] * EPS * fabs((double)v0[i]))) {
                    fprintf(stderr, "  %d steps a second, particle %d\n", rates[r], i);
                    break;
                }
                ENSURE_EQ_INT(motus_particle_init(&p, motus_v2(0, 0), 1), MOTUS_OK);
                p.velocity = motus_v2(v0[i], 0);
                for (step = 0; step < rates[r]; ++step) {
                    ENSURE_EQ_INT(motus_particle_step(&p, h), MOTUS_OK);
                    if (per_second) ENSURE_EQ_INT(motus_particle_damp_per_second(&p, s.damping, h), MOTUS_OK);
                    else ENSURE_EQ_INT(motus_particle_damp_per_step(&p, s.damping), MOTUS_OK);
                }
                ENSURE(same_bytes(&p.velocity.x, &v, sizeof v));
            }
        }
}

TEST(immovable_particles_move_kinematically) {
    /* Inverse mass 0 (in the array, or the scene's uniform one): gravity, drags, the attractor, springs
       and forces do nothing; the velocity stays as it was and the position advances by v*h each step, bit
       for bit, as motus_stepper_step moves an immovable particle. Both methods, 2D and 3D. (The velocity is
       compared as a number: adding a zero acceleration turns a -0 into +0, in the stepper too; the signs
       of zeros are compared with the stepper's in batch_equals_single_particle.) */
    static test_batch t;
    static motus_real x0[3][N], v0[3][N];
    motus_scene s;
    int dims, method, uniform, i, d, step, checked = 0;
    for (uniform = 0; uniform < 2; ++uniform)
        for (dims = 2; dims <= 3; ++dims)
            for (method = 0; method < 2; ++method) {
                make_scene(&s, MOTUS_HAS_GRAVITY | MOTUS_HAS_LINEAR_DRAG | MOTUS_HAS_QUADRATIC_DRAG |
                                   MOTUS_HAS_ATTRACTOR | MOTUS_HAS_FORCES | (uniform ? 0u : MOTUS_HAS_PARTICLE_MASS),
                           (motus_method)method);
                s.inverse_mass = 0;
                bind(&t, dims, s.has, 1, 0);
                fill_random(&t, &s, 13);
                for (d = 0; d < dims; ++d) {
                    memcpy(x0[d], array_of(&t, POSITION + d), sizeof x0[d]);
                    memcpy(v0[d], array_of(&t, VELOCITY + d), sizeof v0[d]);
                }
                for (step = 0; step < STEPS; ++step) {
                    ENSURE_EQ_INT(motus_batch_step(&s, &t.batch, 0, N, DT), MOTUS_OK);
                    for (i = 0; i < N; ++i)
                        for (d = 0; d < dims; ++d) x0[d][i] = x0[d][i] + v0[d][i] * DT;
                }
                for (i = 0; i < N; ++i) {
                    if (!uniform && array_of(&t, INVERSE_MASS)[i] != 0) continue;
                    checked++;
                    for (d = 0; d < dims; ++d)
                        if (array_of(&t, VELOCITY + d)[i] != v0[d][i] ||
                            !same_bytes(&array_of(&t, POSITION + d)[i], &x0[d][i], sizeof(motus_real))) {
                            fprintf(stderr, "%s, %dD, %s: immovable particle %d axis %d: x %g v %g (0x%llx), expected "
                                            "%g %g (0x%llx)\n",
                                    uniform ? "uniform" : "array", dims, motus_method_name((motus_method)method), i, d,
                                    (double)array_of(&t, POSITION + d)[i], (double)array_of(&t, VELOCITY + d)[i],
                                    bits_of(array_of(&t, VELOCITY + d)[i]), (double)x0[d][i], (double)v0[d][i],
                                    bits_of(v0[d][i]));
                            motus_test_failures++;
                        }
                }
            }
    ENSURE(checked > 4 * N);
}

/* =================================================================================================
   --dump: a hash of the final state of every scene, for comparing builds
   ================================================================================================= */
static uint64_t fnv1a(uint64_t hash, const void *data, size_t size) {
    const unsigned char *bytes = (const unsigned char *)data;
    size_t i;
    for (i = 0; i < size; ++i) hash = (hash ^ bytes[i]) * 1099511628211ull;
    return hash;
}

/* Every scene, both methods, 2D (with and without springs) and 3D, 20 steps as two ranges split off a
   vector boundary: one line per scene with a hash of every position and velocity bit, then the raw bits
   of one scene's state. Builds with other vector widths or the scalar fallback must print the same. */
static int dump(void) {
    static test_batch t;
    static motus_spring springs[SPRINGS];
    static motus_vec2 base_force[N];
    unsigned has;
    int dims, method, with_springs, step, a, i;
    make_springs(springs);
    for (dims = 2; dims <= 3; ++dims)
        for (has = 0; has <= MOTUS__HAS_KNOWN; ++has) {
            if ((has & BOTH_DAMPINGS) == BOTH_DAMPINGS) continue;
            for (method = 0; method < 2; ++method)
                for (with_springs = 0; with_springs < 2; ++with_springs) {
                    motus_scene s;
                    uint64_t hash = 14695981039346656037ull;
                    int bad = 0;
                    if (with_springs && (dims == 3 || !(has & MOTUS_HAS_FORCES))) continue;
                    make_scene(&s, has, (motus_method)method);
                    bind(&t, dims, has, 1, 0);
                    fill_random(&t, &s, 500 + has);
                    for (i = 0; i < N; ++i)
                        base_force[i] = motus_v2(array_of(&t, FORCE)[i], array_of(&t, FORCE + 1)[i]);
                    for (step = 0; step < 20; ++step) {
                        if (with_springs) {
                            for (i = 0; i < N; ++i)
                                array_of(&t, FORCE)[i] = base_force[i].x, array_of(&t, FORCE + 1)[i] = base_force[i].y;
                            bad |= motus_batch_add_spring_forces(&t.batch, N, springs, SPRINGS) != MOTUS_OK;
                        }
                        bad |= motus_batch_step(&s, &t.batch, 0, 37, DT) != MOTUS_OK;
                        bad |= motus_batch_step(&s, &t.batch, 37, N - 37, DT) != MOTUS_OK;
                    }
                    for (a = 0; a < 6; ++a)
                        if (a % 3 < dims) hash = fnv1a(hash, array_of(&t, a), N * sizeof(motus_real));
                    printf("%dD has=0x%03x method=%d springs=%d %s %016llx\n", dims, has, method, with_springs,
                           bad ? "ERROR" : "ok", (unsigned long long)hash);
                }
        }
    {
        motus_scene s;
        make_scene(&s, ALL_HAS, MOTUS_SEMI_IMPLICIT_EULER);
        bind(&t, 3, s.has, 1, 0);
        fill_random(&t, &s, 42);
        for (step = 0; step < 20; ++step) motus_batch_step(&s, &t.batch, 0, N, DT);
        for (i = 0; i < 40; ++i) {
            printf("3D all particle %2d:", i);
            for (a = 0; a < 6; ++a) printf(" %0*llx", (int)(2 * sizeof(motus_real)), bits_of(array_of(&t, a)[i]));
            printf("\n");
        }
    }
    return 0;
}

/* motus_batch_add_spring_forces checks its springs several at a time (motus__springs_check): it must give
   motus_forces_check's result for every array length around the vector block sizes and every bad field at
   every position, including the last spring (which the vector blocks leave to the scalar loop). */
TEST(spring_check_agrees_with_forces_check) {
    static motus_spring springs[160];
    const int count = 50;
    int n, position, bad, checked = 0, disagree = 0;
    for (n = 0; n <= 70; ++n)
        for (position = -1; position < n; ++position)
            for (bad = 0; bad < 16; ++bad) {
                motus_forces forces;
                motus_result expected, got;
                int i;
                if (position < 0 && bad > 0) break;
                for (i = 0; i < n; ++i) {
                    motus_spring *s = &springs[i];
                    s->a = (i * 7) % count;
                    s->b = i % 3 == 0 ? -1 : (s->a + 1 + i % (count - 1)) % count;
                    s->anchor.x = random_real(-3, 3);
                    s->anchor.y = random_real(-3, 3);
                    s->rest_length = i % 2 ? 0 : random_real(0, 2);
                    s->stiffness = random_real(0, 100);
                    s->damping = i % 5 ? MOTUS_R(0.0) : negative_zero();
                }
                if (position >= 0) {
                    motus_spring *s = &springs[position];
                    switch (bad) {
                    case 0: s->a = -1; break;
                    case 1: s->a = count; break;
                    case 2: s->b = -2; break;
                    case 3: s->b = count; break;
                    case 4: s->b = s->a; break;
                    case 5: s->anchor.x = not_a_number(); break;
                    case 6: s->anchor.y = infinity(); break;
                    case 7: s->rest_length = -infinity(); break;
                    case 8: s->stiffness = not_a_number(); break;
                    case 9: s->damping = infinity(); break;
                    case 10: s->rest_length = MOTUS_R(-1e-30); break;
                    case 11: s->stiffness = -REAL_MAX; break;
                    case 12: s->damping = MOTUS_R(-0.5); break;
                    case 13: s->a = INT_MAX; break;
                    case 14: s->b = INT_MAX; break;
                    default: s->b = INT_MIN; break;
                    }
                }
                memset(&forces, 0, sizeof forces);
                forces.springs = springs;
                forces.spring_count = n;
                expected = motus_forces_check(&forces, count);
                got = motus__springs_check(springs, n, count);
                checked++;
                if (got != expected) {
                    if (disagree++ < 10)
                        fprintf(stderr, "n %d, bad field %d at %d: %s, motus_forces_check %s\n", n, bad, position,
                                motus_result_string(got), motus_result_string(expected));
                }
                if (position >= 0) ENSURE(expected != MOTUS_OK);
            }
    printf("%d spring arrays checked both ways, %d disagree\n", checked, disagree);
    ENSURE_EQ_INT(disagree, 0);
}

static const motus_test_case TESTS[] = {
    TEST_CASE(batch_equals_single_particle),
    TEST_CASE(range_split_does_not_change_results),
    TEST_CASE(step_writes_only_its_range),
    TEST_CASE(three_d_with_zero_z_equals_two_d),
    TEST_CASE(three_d_matches_closed_forms),
    TEST_CASE(unused_arrays_may_be_null),
    TEST_CASE(scene_check_rejects_bad_scenes),
    TEST_CASE(scene_errors_match_the_particle_functions),
    TEST_CASE(scene_ignores_what_it_does_not_have),
    TEST_CASE(step_rejects_bad_ranges_and_time_steps),
    TEST_CASE(add_spring_forces_rejects_bad_arguments),
    TEST_CASE(add_spring_forces_equals_the_stepper_springs),
    TEST_CASE(spring_force_sums_that_overflow),
    TEST_CASE(batch_check_finds_the_first_bad_particle),
    TEST_CASE(step_on_bad_data),
    TEST_CASE(overflow_is_not_finite),
    TEST_CASE(finite_sum_overflow_is_not_an_error),
    TEST_CASE(bounds_mirror_and_bounce),
    TEST_CASE(bounds_keep_particles_inside),
    TEST_CASE(damping_per_second_is_rate_independent),
    TEST_CASE(immovable_particles_move_kinematically),
    TEST_CASE(spring_check_agrees_with_forces_check),
};

int main(int argc, char **argv) {
    if (argc > 1 && strcmp(argv[1], "--dump") == 0) return dump();
    return motus_test_main(argc, argv, TESTS, TEST_COUNT(TESTS));
}

