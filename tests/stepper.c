/* Unit tests of the force model and the steppers: every error path of motus_forces_check,
   motus_stepper_init and motus_stepper_step (with the state left byte for byte as it was), the scratch
   arithmetic, and the properties that hold exactly: bit-identical agreements, immovable particles, stage
   times, force reuse, reset and the clock. Accuracy against closed forms is in numeric.c.
   Built in float and in double (MOTUS_DOUBLE). */
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
#define CAPACITY 4

static const motus_real DT = (motus_real)(1.0 / 60.0);

static motus_real not_a_number(void) { return (motus_real)NAN; }
static motus_real infinity(void) { return (motus_real)HUGE_VAL; }

/* A stepper with its own scratch: 8 arrays of CAPACITY is more than any method takes. stepper.scratch
   points into it, so a copy must point its own stepper.scratch at its own array. */
typedef struct test_stepper {
    motus_stepper stepper;
    motus_vec2 scratch[8 * CAPACITY];
} test_stepper;

static motus_result init_stepper(test_stepper *s, motus_method method, unsigned flags) {
    motus_stepper_desc desc;
    memset(s, 0, sizeof *s);
    memset(&desc, 0, sizeof desc);
    desc.capacity = CAPACITY;
    desc.method = method;
    desc.scratch = s->scratch;
    desc.scratch_bytes = sizeof s->scratch;
    desc.flags = flags;
    return motus_stepper_init(&s->stepper, &desc);
}

/* Four particles with distinct values in every field: three free ones of masses 1, 3, 2 and an
   immovable one. */
static void sample_particles(motus_particle p[CAPACITY]) {
    memset(p, 0, sizeof(motus_particle) * CAPACITY);
    motus_particle_init(&p[0], motus_v2(1, 0), 1);
    p[0].velocity = motus_v2(0, 1);
    p[0].force = motus_v2(MOTUS_R(0.5), MOTUS_R(-0.25));
    motus_particle_init(&p[1], motus_v2(-2, 1), 3);
    p[1].velocity = motus_v2(MOTUS_R(0.5), 0);
    motus_particle_init(&p[2], motus_v2(3, 2), 2);
    p[2].velocity = motus_v2(-1, MOTUS_R(0.25));
    motus_particle_init_immovable(&p[3], motus_v2(0, 3));
}

/* A force model and its springs together (forces.springs points into it: pass by pointer). */
typedef struct test_forces {
    motus_forces forces;
    motus_spring springs[3];
} test_forces;

/* Every term on: gravity, both drags, an attractor, a spring 0-1, one from 2 to an anchor, one from the
   immovable 3 to 0. */
static void full_forces(test_forces *f) {
    memset(f, 0, sizeof *f);
    f->forces.gravity = motus_v2(0, MOTUS_R(-9.81));
    f->forces.linear_drag = MOTUS_R(0.1);
    f->forces.quadratic_drag = MOTUS_R(0.01);
    f->forces.attractor_strength = 2;
    f->forces.attractor_position = motus_v2(0, -5);
    f->springs[0].a = 0, f->springs[0].b = 1;
    f->springs[0].rest_length = 1, f->springs[0].stiffness = 20, f->springs[0].damping = MOTUS_R(0.5);
    f->springs[1].a = 2, f->springs[1].b = -1, f->springs[1].anchor = motus_v2(4, 4);
    f->springs[1].rest_length = MOTUS_R(0.5), f->springs[1].stiffness = 10;
    f->springs[2].a = 3, f->springs[2].b = 0;
    f->springs[2].rest_length = 2, f->springs[2].stiffness = 5, f->springs[2].damping = MOTUS_R(0.25);
    f->forces.springs = f->springs;
    f->forces.spring_count = 3;
}

/* What the exact stepper takes: gravity, linear drag (and the accumulated force). */
static void simple_forces(test_forces *f) {
    memset(f, 0, sizeof *f);
    f->forces.gravity = motus_v2(0, MOTUS_R(-9.81));
    f->forces.linear_drag = MOTUS_R(0.3);
}

static void forces_for(motus_method method, test_forces *f) {
    if (method == MOTUS_EXACT_LINEAR_DRAG) simple_forces(f);
    else full_forces(f);
}

static int same_bytes(const void *a, const void *b, size_t size) { return memcmp(a, b, size) == 0; }

/* Steps and expects `expected`, with the particles (all CAPACITY of them) and the stepper struct byte for
   byte as they were. */
static void ensure_rejected_at(motus_stepper *stepper, motus_particle *particles, int count, const motus_forces *forces,
                               motus_real dt, motus_result expected, const char *what, int line) {
    motus_particle particles_before[CAPACITY];
    motus_stepper stepper_before;
    motus_result result;
    /* motus_method_name is NULL for a method out of range (stepper_rejects_corrupt_method): never pass NULL
       to %s (undefined; GCC 12 -O3 sees it: -Wformat-overflow). */
    const char *name = stepper ? motus_method_name(stepper->method) : "(no stepper)";
    const char *method = name ? name : "(method out of range)";
    if (particles) memcpy(particles_before, particles, sizeof particles_before);
    if (stepper) memcpy(&stepper_before, stepper, sizeof stepper_before);
    result = motus_stepper_step(stepper, particles, count, forces, dt);
    if (result != expected) {
        fprintf(stderr, "%s:%d: %s, %s: got %d (%s), expected %d (%s)\n", __FILE__, line, method, what, (int)result,
                motus_result_string(result), (int)expected, motus_result_string(expected));
        motus_test_failures++;
    }
    if (particles && !same_bytes(particles_before, particles, sizeof particles_before)) {
        fprintf(stderr, "%s:%d: %s, %s: particles changed\n", __FILE__, line, method, what);
        motus_test_failures++;
    }
    if (stepper && !same_bytes(&stepper_before, stepper, sizeof stepper_before)) {
        fprintf(stderr, "%s:%d: %s, %s: stepper changed\n", __FILE__, line, method, what);
        motus_test_failures++;
    }
}
#define ENSURE_REJECTED(stepper, particles, count, forces, dt, expected, what)                                  \
    ensure_rejected_at(stepper, particles, count, forces, dt, expected, what, __LINE__)

/* =================================================================================================
   Names, orders, evaluations, scratch size
   ================================================================================================= */
TEST(method_names) {
    int i, j;
    for (i = 0; i < MOTUS_METHOD_COUNT; ++i) {
        const char *name = motus_method_name((motus_method)i);
        ENSURE(name != NULL && strlen(name) > 2);
        for (j = 0; j < i; ++j) ENSURE(strcmp(name, motus_method_name((motus_method)j)) != 0);
    }
    ENSURE(strcmp(motus_method_name(MOTUS_SEMI_IMPLICIT_EULER), "semi_implicit_euler") == 0);
    ENSURE(strcmp(motus_method_name(MOTUS_RK4), "rk4") == 0);
    ENSURE(strcmp(motus_method_name(MOTUS_EXACT_LINEAR_DRAG), "exact_linear_drag") == 0);
    ENSURE(motus_method_name(MOTUS_METHOD_COUNT) == NULL);
    ENSURE(motus_method_name((motus_method)-1) == NULL);
}

TEST(method_orders_and_evaluations) {
    static const int order[MOTUS_METHOD_COUNT] = {1, 1, 2, 2, 2, 2, 4, 4, 0};
    static const int evaluations[MOTUS_METHOD_COUNT] = {1, 1, 1, 2, 2, 2, 4, 3, 0};
    int i;
    for (i = 0; i < MOTUS_METHOD_COUNT; ++i) {
        const motus_method m = (motus_method)i;
        const int reusing = m == MOTUS_VELOCITY_VERLET || m == MOTUS_LEAPFROG;
        ENSURE_EQ_INT(motus_method_order(m), order[i]);
        ENSURE_EQ_INT(motus_method_evaluations(m, 0), evaluations[i]);
        /* Only the two methods that end where the next step starts can reuse the last evaluation. */
        ENSURE_EQ_INT(motus_method_evaluations(m, MOTUS_STEPPER_REUSE_FORCES), reusing ? 1 : evaluations[i]);
    }
    ENSURE_EQ_INT(motus_method_order(MOTUS_METHOD_COUNT), -1);
    ENSURE_EQ_INT(motus_method_order((motus_method)-1), -1);
    ENSURE_EQ_INT(motus_method_evaluations(MOTUS_METHOD_COUNT, 0), -1);
    ENSURE_EQ_INT(motus_method_evaluations((motus_method)-1, MOTUS_STEPPER_REUSE_FORCES), -1);
}

TEST(scratch_size_arithmetic) {
    int i;
    for (i = 0; i < MOTUS_METHOD_COUNT; ++i) {
        const motus_method m = (motus_method)i;
        const size_t one = motus_stepper_scratch_size(m, 1);
        /* At least new x, new v and an acceleration per particle, whole vectors, linear in the capacity. */
        ENSURE(one >= 3 * sizeof(motus_vec2));
        ENSURE(one % sizeof(motus_vec2) == 0);
        ENSURE(motus_stepper_scratch_size(m, 10) == 10 * one);
        ENSURE(motus_stepper_scratch_size(m, 1000) == 1000 * one);
        ENSURE(motus_stepper_scratch_size(m, 0) == 0);
        ENSURE(motus_stepper_scratch_size(m, -1) == 0);
        ENSURE(motus_stepper_scratch_size(m, INT_MIN) == 0);
        /* The largest capacity: the exact product when it fits in size_t, else 0 (never a wrapped size).
           With a 64-bit size_t every int capacity fits; with a 32-bit one this is the overflow path. */
        if ((size_t)INT_MAX <= SIZE_MAX / one) ENSURE(motus_stepper_scratch_size(m, INT_MAX) == (size_t)INT_MAX * one);
        else ENSURE(motus_stepper_scratch_size(m, INT_MAX) == 0);
    }
    /* RK4 keeps the most: four stages' worth. */
    ENSURE(motus_stepper_scratch_size(MOTUS_RK4, 1) > motus_stepper_scratch_size(MOTUS_SEMI_IMPLICIT_EULER, 1));
    ENSURE(motus_stepper_scratch_size(MOTUS_METHOD_COUNT, 1) == 0);
    ENSURE(motus_stepper_scratch_size((motus_method)-1, 1) == 0);
}

TEST(scratch_size_is_enough) {
    /* Each method stepped with exactly motus_stepper_scratch_size bytes, followed by guard bytes that must
       stay untouched; with count < capacity too (the arrays are laid out by capacity). */
    enum { GUARD = 16 };
    int i, count;
    for (i = 0; i < MOTUS_METHOD_COUNT; ++i) {
        for (count = CAPACITY; count >= CAPACITY - 1; --count) {
            const motus_method m = (motus_method)i;
            const size_t bytes = motus_stepper_scratch_size(m, CAPACITY);
            motus_vec2 memory[8 * CAPACITY + GUARD];
            unsigned char guard[GUARD * sizeof(motus_vec2)];
            motus_stepper stepper;
            motus_stepper_desc desc;
            motus_particle p[CAPACITY];
            test_forces f;
            int k;
            memset(memory, 0xA5, sizeof memory);
            memcpy(guard, (unsigned char *)memory + bytes, sizeof guard);
            memset(&desc, 0, sizeof desc);
            desc.capacity = CAPACITY;
            desc.method = m;
            desc.scratch = memory;
            desc.scratch_bytes = bytes;
            desc.flags = MOTUS_STEPPER_REUSE_FORCES;
            ENSURE_EQ_INT(motus_stepper_init(&stepper, &desc), MOTUS_OK);
            sample_particles(p);
            forces_for(m, &f);
            if (count < CAPACITY && f.forces.spring_count > 2) f.forces.spring_count = 2; /* 2 joins particle 3 */
            for (k = 0; k < 5; ++k) ENSURE_EQ_INT(motus_stepper_step(&stepper, p, count, &f.forces, DT), MOTUS_OK);
            ENSURE(same_bytes(guard, (unsigned char *)memory + bytes, sizeof guard));
        }
    }
}

/* =================================================================================================
   motus_stepper_init
   ================================================================================================= */
TEST(stepper_init_sets_fields) {
    test_stepper s;
    int i;
    for (i = 0; i < MOTUS_METHOD_COUNT; ++i) {
        ENSURE_EQ_INT(init_stepper(&s, (motus_method)i, MOTUS_STEPPER_REUSE_FORCES), MOTUS_OK);
        ENSURE_EQ_INT(s.stepper.method, i);
        ENSURE_EQ_INT(s.stepper.capacity, CAPACITY);
        ENSURE_EQ_INT(s.stepper.flags, MOTUS_STEPPER_REUSE_FORCES);
        ENSURE(s.stepper.scratch == s.scratch);
        ENSURE(s.stepper.time == 0);
    }
}

TEST(stepper_desc_zero_is_default) {
    /* A zeroed desc is valid: semi-implicit Euler for no particles, no memory needed. */
    motus_stepper stepper;
    motus_stepper_desc desc;
    motus_particle p[CAPACITY];
    memset(&desc, 0, sizeof desc);
    sample_particles(p);
    ENSURE_EQ_INT(motus_stepper_init(&stepper, &desc), MOTUS_OK);
    ENSURE_EQ_INT(stepper.method, MOTUS_SEMI_IMPLICIT_EULER);
    ENSURE_EQ_INT(stepper.capacity, 0);
    ENSURE_EQ_INT(motus_stepper_step(&stepper, NULL, 0, NULL, DT), MOTUS_OK);
    ENSURE_REJECTED(&stepper, p, 1, NULL, DT, MOTUS_ERROR_INVALID_COUNT, "one particle, capacity 0");
}

TEST(stepper_init_rejects_bad_desc) {
    test_stepper s;
    motus_stepper before;
    motus_stepper_desc desc;
    int i;
    for (i = 0; i < MOTUS_METHOD_COUNT; ++i) {
        const motus_method m = (motus_method)i;
        const size_t needed = motus_stepper_scratch_size(m, CAPACITY);
        ENSURE_EQ_INT(init_stepper(&s, MOTUS_RK4, 0), MOTUS_OK); /* a valid stepper, to see nothing changes */
        memcpy(&before, &s.stepper, sizeof before);
        memset(&desc, 0, sizeof desc);
        desc.capacity = CAPACITY;
        desc.method = m;
        desc.scratch = s.scratch;
        desc.scratch_bytes = needed;
        ENSURE_EQ_INT(motus_stepper_init(NULL, &desc), MOTUS_ERROR_NULL_POINTER);
        ENSURE_EQ_INT(motus_stepper_init(&s.stepper, NULL), MOTUS_ERROR_NULL_POINTER);
        desc.scratch_bytes = needed - 1;
        ENSURE_EQ_INT(motus_stepper_init(&s.stepper, &desc), MOTUS_ERROR_SCRATCH_TOO_SMALL);
        desc.scratch_bytes = 0;
        ENSURE_EQ_INT(motus_stepper_init(&s.stepper, &desc), MOTUS_ERROR_SCRATCH_TOO_SMALL);
        desc.scratch_bytes = needed;
        desc.scratch = NULL;
        ENSURE_EQ_INT(motus_stepper_init(&s.stepper, &desc), MOTUS_ERROR_NULL_POINTER);
        desc.scratch = s.scratch;
        desc.capacity = -1;
        ENSURE_EQ_INT(motus_stepper_init(&s.stepper, &desc), MOTUS_ERROR_INVALID_COUNT);
        desc.capacity = INT_MIN;
        ENSURE_EQ_INT(motus_stepper_init(&s.stepper, &desc), MOTUS_ERROR_INVALID_COUNT);
        desc.capacity = INT_MAX; /* more than the memory given, or (32-bit size_t) more than memory can be */
        ENSURE_EQ_INT(motus_stepper_init(&s.stepper, &desc), motus_stepper_scratch_size(m, INT_MAX) == 0
                                                                 ? MOTUS_ERROR_INVALID_COUNT
                                                                 : MOTUS_ERROR_SCRATCH_TOO_SMALL);
        ENSURE(same_bytes(&before, &s.stepper, sizeof before));
    }
    memset(&desc, 0, sizeof desc);
    desc.method = MOTUS_METHOD_COUNT;
    ENSURE_EQ_INT(motus_stepper_init(&s.stepper, &desc), MOTUS_ERROR_UNSUPPORTED);
    desc.method = (motus_method)-1;
    ENSURE_EQ_INT(motus_stepper_init(&s.stepper, &desc), MOTUS_ERROR_UNSUPPORTED);
    ENSURE(same_bytes(&before, &s.stepper, sizeof before));
}

/* =================================================================================================
   motus_forces_check, and the same checks through motus_stepper_step
   ================================================================================================= */

/* Applies break number `which` to a full force model (4 particles) and returns the result it must give,
   or -1 past the last. The springs broken are the last one, so every spring is seen to be checked. */
static int break_forces(test_forces *f, int which) {
    motus_spring *s = &f->springs[2];
    full_forces(f);
    switch (which) {
    case 0: f->forces.gravity.x = not_a_number(); return MOTUS_ERROR_NOT_FINITE;
    case 1: f->forces.gravity.y = -infinity(); return MOTUS_ERROR_NOT_FINITE;
    case 2: f->forces.linear_drag = infinity(); return MOTUS_ERROR_NOT_FINITE;
    case 3: f->forces.linear_drag = MOTUS_R(-0.1); return MOTUS_ERROR_INVALID_FORCES;
    case 4: f->forces.quadratic_drag = not_a_number(); return MOTUS_ERROR_NOT_FINITE;
    case 5: f->forces.quadratic_drag = -1; return MOTUS_ERROR_INVALID_FORCES;
    case 6: f->forces.attractor_strength = infinity(); return MOTUS_ERROR_NOT_FINITE;
    case 7: f->forces.attractor_strength = -1; return MOTUS_ERROR_INVALID_FORCES;
    case 8: f->forces.attractor_position.y = not_a_number(); return MOTUS_ERROR_NOT_FINITE;
    case 9: f->forces.spring_count = -1; return MOTUS_ERROR_INVALID_FORCES;
    case 10: f->forces.springs = NULL; return MOTUS_ERROR_INVALID_FORCES;
    case 11: s->a = -1; return MOTUS_ERROR_INVALID_FORCES;
    case 12: s->a = CAPACITY; return MOTUS_ERROR_INVALID_FORCES;
    case 13: s->b = -2; return MOTUS_ERROR_INVALID_FORCES;
    case 14: s->b = CAPACITY; return MOTUS_ERROR_INVALID_FORCES;
    case 15: s->b = s->a; return MOTUS_ERROR_INVALID_FORCES;
    case 16: s->rest_length = -1; return MOTUS_ERROR_INVALID_FORCES;
    case 17: s->stiffness = -1; return MOTUS_ERROR_INVALID_FORCES;
    case 18: s->damping = MOTUS_R(-0.5); return MOTUS_ERROR_INVALID_FORCES;
    case 19: s->anchor.x = infinity(); return MOTUS_ERROR_NOT_FINITE;
    case 20: s->rest_length = not_a_number(); return MOTUS_ERROR_NOT_FINITE;
    case 21: s->stiffness = infinity(); return MOTUS_ERROR_NOT_FINITE;
    case 22: s->damping = not_a_number(); return MOTUS_ERROR_NOT_FINITE;
    default: return -1;
    }
}

TEST(forces_check_accepts_valid_models) {
    test_forces f;
    motus_forces zero;
    memset(&zero, 0, sizeof zero);
    ENSURE_EQ_INT(motus_forces_check(&zero, 0), MOTUS_OK); /* zeroed: no forces */
    ENSURE_EQ_INT(motus_forces_check(&zero, CAPACITY), MOTUS_OK);
    full_forces(&f);
    ENSURE_EQ_INT(motus_forces_check(&f.forces, CAPACITY), MOTUS_OK);
    /* Spring ends are checked against the count given: spring 2 joins particle 3 and 0. */
    ENSURE_EQ_INT(motus_forces_check(&f.forces, CAPACITY - 1), MOTUS_ERROR_INVALID_FORCES);
    f.forces.spring_count = 2; /* the springs past spring_count are not looked at */
    ENSURE_EQ_INT(motus_forces_check(&f.forces, CAPACITY - 1), MOTUS_OK);
    f.forces.spring_count = 0;
    f.forces.springs = NULL;
    ENSURE_EQ_INT(motus_forces_check(&f.forces, 0), MOTUS_OK);
    /* Zero stiffness, damping, rest length, drags and strength are all valid: off. */
    simple_forces(&f);
    f.forces.linear_drag = 0;
    ENSURE_EQ_INT(motus_forces_check(&f.forces, 1), MOTUS_OK);
}

TEST(forces_check_rejects_bad_models) {
    test_forces f;
    int which, expected;
    ENSURE_EQ_INT(motus_forces_check(NULL, 1), MOTUS_ERROR_NULL_POINTER);
    for (which = 0; (expected = break_forces(&f, which)) >= 0; ++which) {
        motus_result result = motus_forces_check(&f.forces, CAPACITY);
        if (result != (motus_result)expected)
            fprintf(stderr, "  break %d: got %d, expected %d\n", which, (int)result, expected);
        ENSURE_EQ_INT(result, expected);
    }
    ENSURE_EQ_INT(which, 23);
}

TEST(stepper_rejects_bad_forces) {
    /* Every method, every broken field: the check's result, nothing written. */
    int i, which, expected;
    for (i = 0; i < MOTUS_METHOD_COUNT; ++i) {
        test_stepper s;
        motus_particle p[CAPACITY];
        test_forces f;
        ENSURE_EQ_INT(init_stepper(&s, (motus_method)i, 0), MOTUS_OK);
        sample_particles(p);
        for (which = 0; (expected = break_forces(&f, which)) >= 0; ++which)
            ENSURE_REJECTED(&s.stepper, p, CAPACITY, &f.forces, DT, (motus_result)expected, "broken force model");
    }
}

/* =================================================================================================
   motus_stepper_step: bad arguments and bad particles
   ================================================================================================= */
TEST(stepper_rejects_bad_arguments) {
    int i;
    for (i = 0; i < MOTUS_METHOD_COUNT; ++i) {
        test_stepper s;
        motus_particle p[CAPACITY];
        test_forces f;
        ENSURE_EQ_INT(init_stepper(&s, (motus_method)i, MOTUS_STEPPER_REUSE_FORCES), MOTUS_OK);
        sample_particles(p);
        forces_for((motus_method)i, &f);
        /* One good step first, so the stepper has history to lose (position Verlet, reuse). */
        ENSURE_EQ_INT(motus_stepper_step(&s.stepper, p, CAPACITY, &f.forces, DT), MOTUS_OK);
        ENSURE_REJECTED(NULL, p, CAPACITY, &f.forces, DT, MOTUS_ERROR_NULL_POINTER, "NULL stepper");
        ENSURE_REJECTED(&s.stepper, NULL, 1, &f.forces, DT, MOTUS_ERROR_NULL_POINTER, "NULL particles");
        ENSURE_REJECTED(&s.stepper, p, -1, &f.forces, DT, MOTUS_ERROR_INVALID_COUNT, "count -1");
        ENSURE_REJECTED(&s.stepper, p, INT_MIN, &f.forces, DT, MOTUS_ERROR_INVALID_COUNT, "count INT_MIN");
        ENSURE_REJECTED(&s.stepper, p, CAPACITY + 1, &f.forces, DT, MOTUS_ERROR_INVALID_COUNT, "count > capacity");
        ENSURE_REJECTED(&s.stepper, p, CAPACITY, &f.forces, 0, MOTUS_ERROR_INVALID_TIME_STEP, "dt 0");
        ENSURE_REJECTED(&s.stepper, p, CAPACITY, &f.forces, MOTUS_R(-0.0), MOTUS_ERROR_INVALID_TIME_STEP, "dt -0");
        ENSURE_REJECTED(&s.stepper, p, CAPACITY, &f.forces, -DT, MOTUS_ERROR_INVALID_TIME_STEP, "dt < 0");
        ENSURE_REJECTED(&s.stepper, p, CAPACITY, &f.forces, not_a_number(), MOTUS_ERROR_INVALID_TIME_STEP, "dt NaN");
        ENSURE_REJECTED(&s.stepper, p, CAPACITY, &f.forces, infinity(), MOTUS_ERROR_INVALID_TIME_STEP, "dt +Inf");
        ENSURE_REJECTED(&s.stepper, p, CAPACITY, &f.forces, -infinity(), MOTUS_ERROR_INVALID_TIME_STEP, "dt -Inf");
    }
}

TEST(stepper_accepts_no_particles) {
    /* count 0 is a step of nothing: particles may be NULL, the clock still advances. */
    int i;
    for (i = 0; i < MOTUS_METHOD_COUNT; ++i) {
        test_stepper s;
        ENSURE_EQ_INT(init_stepper(&s, (motus_method)i, 0), MOTUS_OK);
        ENSURE_EQ_INT(motus_stepper_step(&s.stepper, NULL, 0, NULL, MOTUS_R(0.5)), MOTUS_OK);
        ENSURE(s.stepper.time == MOTUS_R(0.5));
    }
}

TEST(stepper_rejects_broken_particles) {
    /* A NaN or Inf in any field of a free particle, or a negative inverse mass: reported, nothing written,
       for every method. The particles are not tied to each other here, and the stepper is new (see
       stepper_rejects_every_non_finite_input for the other cases). */
    int i, field;
    for (i = 0; i < MOTUS_METHOD_COUNT; ++i) {
        for (field = 0; field < 9; ++field) {
            test_stepper s;
            motus_particle p[CAPACITY];
            motus_real *fields[7];
            test_forces f;
            char what[64];
            ENSURE_EQ_INT(init_stepper(&s, (motus_method)i, 0), MOTUS_OK);
            sample_particles(p);
            simple_forces(&f);
            f.forces.attractor_strength = i == MOTUS_EXACT_LINEAR_DRAG ? 0 : 1;
            fields[0] = &p[1].position.x, fields[1] = &p[1].position.y, fields[2] = &p[1].velocity.x;
            fields[3] = &p[1].velocity.y, fields[4] = &p[1].force.x, fields[5] = &p[1].force.y;
            fields[6] = &p[1].inverse_mass;
            if (field < 7) {
                *fields[field] = field % 2 ? not_a_number() : (field == 6 ? infinity() : -infinity());
                sprintf(what, "particle 1 field %d not finite", field);
                ENSURE_REJECTED(&s.stepper, p, CAPACITY, &f.forces, DT, MOTUS_ERROR_NOT_FINITE, what);
            } else {
                /* Negative, finite or not, is a bad mass first, as in motus_particle_step. */
                p[1].inverse_mass = field == 7 ? MOTUS_R(-0.5) : -infinity();
                ENSURE_REJECTED(&s.stepper, p, CAPACITY, &f.forces, DT, MOTUS_ERROR_INVALID_MASS, "inverse mass < 0");
            }
        }
    }
}

static void spreading_callback(void *user_data, int count, const motus_vec2 *x, const motus_vec2 *v, motus_real time,
                               motus_vec2 *forces) {
    /* Every particle pulled towards the centroid: a callback that couples all particles. */
    motus_vec2 sum = motus_v2(0, 0), centroid;
    int i;
    (void)user_data, (void)v, (void)time;
    for (i = 0; i < count; ++i) sum = motus_vec2_add(sum, x[i]);
    centroid = motus_vec2_scale(sum, MOTUS_R(1.0) / (motus_real)count);
    for (i = 0; i < count; ++i) forces[i] = motus_vec2_add(forces[i], motus_vec2_sub(centroid, x[i]));
}

TEST(stepper_rejects_every_non_finite_input) {
    /* motus_stepper_step finds bad particles by looking for non-finite values in the new state, and then
       checks only the first particle whose new state is not finite. Three inputs slip through that:
       - a NaN force on an immovable particle: its acceleration is set to 0, so nothing turns NaN, and the
         step succeeds (motus_particle_step, the same step for one particle, says MOTUS_ERROR_NOT_FINITE);
       - a NaN velocity given to position Verlet once it has history: the velocity is not read, the step
         succeeds and overwrites it;
       - an Inf position in particle 1 that reaches particle 0 through a spring or a callback: particle 0
         is the first non-finite one, its own fields are fine, so the result is MOTUS_ERROR_OVERFLOW
         ("finite inputs, but the result would not be finite").
       All three should be MOTUS_ERROR_NOT_FINITE, with nothing written. */
    int i, coupling;
    for (i = 0; i < MOTUS_METHOD_COUNT; ++i) {
        test_stepper s;
        motus_particle p[CAPACITY], alone;
        ENSURE_EQ_INT(init_stepper(&s, (motus_method)i, 0), MOTUS_OK);
        sample_particles(p);
        p[3].force.x = not_a_number();
        alone = p[3];
        ENSURE_EQ_INT(motus_particle_step(&alone, DT), MOTUS_ERROR_NOT_FINITE);
        ENSURE_REJECTED(&s.stepper, p, CAPACITY, NULL, DT, MOTUS_ERROR_NOT_FINITE, "NaN force, immovable particle");
    }
    {
        test_stepper s;
        motus_particle p[CAPACITY];
        ENSURE_EQ_INT(init_stepper(&s, MOTUS_POSITION_VERLET, 0), MOTUS_OK);
        sample_particles(p);
        ENSURE_EQ_INT(motus_stepper_step(&s.stepper, p, CAPACITY, NULL, DT), MOTUS_OK);
        p[1].velocity.x = not_a_number();
        ENSURE_REJECTED(&s.stepper, p, CAPACITY, NULL, DT, MOTUS_ERROR_NOT_FINITE, "NaN velocity, with history");
    }
    for (i = 0; i < MOTUS_METHOD_COUNT; ++i) {
        if (i == MOTUS_EXACT_LINEAR_DRAG) continue; /* takes neither springs nor callbacks */
        for (coupling = 0; coupling < 2; ++coupling) {
            test_stepper s;
            motus_particle p[CAPACITY];
            motus_forces forces;
            motus_spring spring;
            ENSURE_EQ_INT(init_stepper(&s, (motus_method)i, 0), MOTUS_OK);
            sample_particles(p);
            memset(&forces, 0, sizeof forces);
            memset(&spring, 0, sizeof spring);
            spring.a = 0, spring.b = 1, spring.stiffness = 10, spring.rest_length = 1;
            if (coupling == 0) forces.springs = &spring, forces.spring_count = 1;
            else forces.callback = spreading_callback;
            p[1].position.y = infinity();
            ENSURE_REJECTED(&s.stepper, p, CAPACITY, &forces, DT, MOTUS_ERROR_NOT_FINITE,
                            coupling ? "Inf position, callback coupling" : "Inf position, spring to particle 0");
        }
    }
}

TEST(stepper_reports_overflow_all_or_nothing) {
    /* Particle 0 steps fine, particle 1 overflows: nothing is written, not even particle 0. */
    int i;
    for (i = 0; i < MOTUS_METHOD_COUNT; ++i) {
        test_stepper s;
        motus_particle p[CAPACITY];
        test_forces f;
        ENSURE_EQ_INT(init_stepper(&s, (motus_method)i, 0), MOTUS_OK);
        sample_particles(p);
        simple_forces(&f);
        f.forces.linear_drag = 0; /* drag would slow the particle down enough not to overflow */
        ENSURE_EQ_INT(motus_stepper_step(&s.stepper, p, CAPACITY, &f.forces, DT), MOTUS_OK);
        p[1].position = motus_v2(REAL_MAX, 0);
        p[1].velocity = motus_v2(REAL_MAX / 2, 0);
        motus_stepper_reset(&s.stepper); /* particles set by hand: position Verlet restarts from the velocity */
        ENSURE_REJECTED(&s.stepper, p, CAPACITY, &f.forces, 4, MOTUS_ERROR_OVERFLOW, "position overflow");
        sample_particles(p);
        p[2].force = motus_v2(0, REAL_MAX); /* finite, but F*(1/m) is not */
        p[2].inverse_mass = 4;
        ENSURE_REJECTED(&s.stepper, p, CAPACITY, &f.forces, 8, MOTUS_ERROR_OVERFLOW, "velocity overflow");
    }
}

TEST(exact_stepper_rejects_unsupported_forces) {
    int term;
    for (term = 0; term < 4; ++term) {
        test_stepper exact, other;
        motus_particle p[CAPACITY];
        test_forces f;
        simple_forces(&f);
        if (term == 0) { /* a spring */
            full_forces(&f);
            f.forces.quadratic_drag = 0, f.forces.attractor_strength = 0;
        } else if (term == 1) {
            f.forces.attractor_strength = 1;
        } else if (term == 2) {
            f.forces.quadratic_drag = MOTUS_R(0.01);
        } else {
            f.forces.callback = spreading_callback;
        }
        ENSURE_EQ_INT(init_stepper(&exact, MOTUS_EXACT_LINEAR_DRAG, 0), MOTUS_OK);
        sample_particles(p);
        ENSURE_REJECTED(&exact.stepper, p, CAPACITY, &f.forces, DT, MOTUS_ERROR_UNSUPPORTED, "unsupported term");
        /* The same model is fine for the other methods. */
        ENSURE_EQ_INT(init_stepper(&other, MOTUS_RK4, 0), MOTUS_OK);
        ENSURE_EQ_INT(motus_stepper_step(&other.stepper, p, CAPACITY, &f.forces, DT), MOTUS_OK);
    }
}

TEST(stepper_rejects_corrupt_method) {
    test_stepper s;
    motus_particle p[CAPACITY];
    ENSURE_EQ_INT(init_stepper(&s, MOTUS_LEAPFROG, 0), MOTUS_OK);
    sample_particles(p);
    s.stepper.method = MOTUS_METHOD_COUNT;
    ENSURE_REJECTED(&s.stepper, p, CAPACITY, NULL, DT, MOTUS_ERROR_UNSUPPORTED, "method out of range");
}

TEST(reuse_forces_survives_a_rejected_step) {
    /* With MOTUS_STEPPER_REUSE_FORCES the stepper keeps the last acceleration in its scratch. A step that
       is rejected must not replace it: "on any result but MOTUS_OK nothing is written: not the particles,
       not the stepper". After a rejected step the next good step must be the one a twin stepper, that
       never saw the rejected step, takes. */
    static const motus_method methods[2] = {MOTUS_VELOCITY_VERLET, MOTUS_LEAPFROG};
    int i, k;
    for (i = 0; i < 2; ++i) {
        test_stepper s, twin;
        motus_particle p[CAPACITY], q[CAPACITY];
        test_forces f;
        full_forces(&f);
        f.forces.linear_drag = 0, f.forces.quadratic_drag = 0; /* position-only forces: reuse is valid */
        f.springs[0].damping = 0, f.springs[2].damping = 0;
        ENSURE_EQ_INT(init_stepper(&s, methods[i], MOTUS_STEPPER_REUSE_FORCES), MOTUS_OK);
        ENSURE_EQ_INT(init_stepper(&twin, methods[i], MOTUS_STEPPER_REUSE_FORCES), MOTUS_OK);
        sample_particles(p);
        sample_particles(q);
        for (k = 0; k < 3; ++k) {
            ENSURE_EQ_INT(motus_stepper_step(&s.stepper, p, CAPACITY, &f.forces, DT), MOTUS_OK);
            ENSURE_EQ_INT(motus_stepper_step(&twin.stepper, q, CAPACITY, &f.forces, DT), MOTUS_OK);
        }
        ENSURE_REJECTED(&s.stepper, p, CAPACITY, &f.forces, REAL_MAX / 4, MOTUS_ERROR_OVERFLOW, "huge dt");
        ENSURE_EQ_INT(motus_stepper_step(&s.stepper, p, CAPACITY, &f.forces, DT), MOTUS_OK);
        ENSURE_EQ_INT(motus_stepper_step(&twin.stepper, q, CAPACITY, &f.forces, DT), MOTUS_OK);
        if (!same_bytes(p, q, sizeof p))
            fprintf(stderr, "  %s: the rejected step changed the next one\n", motus_method_name(methods[i]));
        ENSURE(same_bytes(p, q, sizeof p));
    }
}

/* =================================================================================================
   Agreements that hold bit for bit
   ================================================================================================= */
TEST(semi_implicit_euler_matches_particle_step) {
    /* The stepper's semi-implicit Euler does the operations of motus_particle_step in the same order:
       with no forces but the accumulated ones (NULL or a zeroed model) the two agree bit for bit. */
    int model, k, j;
    for (model = 0; model < 2; ++model) {
        test_stepper s;
        motus_particle p[CAPACITY], q[CAPACITY];
        motus_forces zero;
        memset(&zero, 0, sizeof zero);
        ENSURE_EQ_INT(init_stepper(&s, MOTUS_SEMI_IMPLICIT_EULER, 0), MOTUS_OK);
        sample_particles(p);
        sample_particles(q);
        for (k = 0; k < 200; ++k) {
            const motus_real dt = k < 100 ? DT : MOTUS_R(0.1);
            if (k == 100) /* a different dt and force halfway */
                for (j = 0; j < CAPACITY; ++j) p[j].force = q[j].force = motus_v2(MOTUS_R(-1.5), MOTUS_R(3.25));
            ENSURE_EQ_INT(motus_stepper_step(&s.stepper, p, CAPACITY, model ? &zero : NULL, dt), MOTUS_OK);
            for (j = 0; j < CAPACITY; ++j) ENSURE_EQ_INT(motus_particle_step(&q[j], dt), MOTUS_OK);
        }
        ENSURE(same_bytes(p, q, sizeof p));
        ENSURE(p[0].position.x != 1); /* it did move */
    }
}

TEST(exact_stepper_matches_particle_step_linear_drag) {
    /* Gravity off, linear drag k: the exact stepper is motus_particle_step_linear_drag, bit for bit. */
    test_stepper s;
    motus_particle p[CAPACITY], q[CAPACITY];
    motus_forces drag;
    int k, j;
    memset(&drag, 0, sizeof drag);
    drag.linear_drag = MOTUS_R(0.7);
    ENSURE_EQ_INT(init_stepper(&s, MOTUS_EXACT_LINEAR_DRAG, 0), MOTUS_OK);
    sample_particles(p);
    sample_particles(q);
    for (k = 0; k < 100; ++k) {
        const motus_real dt = k % 2 ? DT : MOTUS_R(1.5); /* both branches of phi: u below and above 0.5 */
        ENSURE_EQ_INT(motus_stepper_step(&s.stepper, p, CAPACITY, &drag, dt), MOTUS_OK);
        for (j = 0; j < CAPACITY; ++j)
            ENSURE_EQ_INT(motus_particle_step_linear_drag(&q[j], drag.linear_drag, dt), MOTUS_OK);
    }
    ENSURE(same_bytes(p, q, sizeof p));
}

/* Records what the force model is called with, and adds `push` (newtons) to every particle. */
typedef struct recorder {
    int calls;
    int count_seen;
    motus_real times[16];
    motus_vec2 first_position; /* particle 0's position at the first call */
    motus_vec2 push;
} recorder;

static void recording_callback(void *user_data, int count, const motus_vec2 *x, const motus_vec2 *v, motus_real time,
                               motus_vec2 *forces) {
    recorder *r = (recorder *)user_data;
    int i;
    (void)v;
    if (r->calls < 16) r->times[r->calls] = time;
    if (r->calls == 0) r->first_position = x[0];
    r->count_seen = count;
    r->calls++;
    for (i = 0; i < count; ++i) forces[i] = motus_vec2_add(forces[i], r->push);
}

static void recorder_forces(motus_forces *forces, recorder *r, motus_vec2 push) {
    memset(r, 0, sizeof *r);
    memset(forces, 0, sizeof *forces);
    r->push = push;
    forces->gravity = motus_v2(0, -10);
    forces->callback = recording_callback;
    forces->user_data = r;
}

TEST(callback_forces_are_applied) {
    /* A callback adding F is the same as F in the accumulator, bit for bit, for every method that takes
       callbacks: both are newtons added before the division by mass. And it does something. */
    const motus_vec2 push = motus_v2(MOTUS_R(2.5), MOTUS_R(-1.25));
    int i, j, k;
    for (i = 0; i < MOTUS_METHOD_COUNT; ++i) {
        test_stepper a, b, c;
        motus_particle with_callback[CAPACITY], with_force[CAPACITY], without[CAPACITY];
        motus_forces callback_model, plain;
        recorder r;
        if (i == MOTUS_EXACT_LINEAR_DRAG) continue;
        recorder_forces(&callback_model, &r, push);
        memset(&plain, 0, sizeof plain);
        plain.gravity = callback_model.gravity;
        ENSURE_EQ_INT(init_stepper(&a, (motus_method)i, 0), MOTUS_OK);
        ENSURE_EQ_INT(init_stepper(&b, (motus_method)i, 0), MOTUS_OK);
        ENSURE_EQ_INT(init_stepper(&c, (motus_method)i, 0), MOTUS_OK);
        sample_particles(with_callback);
        for (j = 0; j < CAPACITY; ++j) with_callback[j].force = motus_v2(0, 0);
        memcpy(without, with_callback, sizeof without);
        memcpy(with_force, with_callback, sizeof with_force);
        for (j = 0; j < CAPACITY; ++j) with_force[j].force = push;
        for (k = 0; k < 50; ++k) {
            ENSURE_EQ_INT(motus_stepper_step(&a.stepper, with_callback, CAPACITY, &callback_model, DT), MOTUS_OK);
            ENSURE_EQ_INT(motus_stepper_step(&b.stepper, with_force, CAPACITY, &plain, DT), MOTUS_OK);
            ENSURE_EQ_INT(motus_stepper_step(&c.stepper, without, CAPACITY, &plain, DT), MOTUS_OK);
        }
        for (j = 0; j < CAPACITY; ++j) {
            ENSURE(same_bytes(&with_callback[j].position, &with_force[j].position, sizeof(motus_vec2)));
            ENSURE(same_bytes(&with_callback[j].velocity, &with_force[j].velocity, sizeof(motus_vec2)));
        }
        ENSURE(with_callback[0].position.x != without[0].position.x);
        ENSURE(r.calls >= 50);
    }
}

TEST(callback_receives_stage_times) {
    /* Second step of h = 0.25 from t = 0.25: each method evaluates the forces at its stage times. */
    const double t = 0.25, h = 0.25, theta = 1.3512071919596576340476878089715;
    const double forest_ruth[3] = {t + theta * h / 2, t + h / 2, t + (1 - theta / 2) * h};
    int i, flags;
    for (i = 0; i < MOTUS_METHOD_COUNT; ++i) {
        for (flags = 0; flags <= MOTUS_STEPPER_REUSE_FORCES; ++flags) {
            const motus_method m = (motus_method)i;
            const int reusing = flags && (m == MOTUS_VELOCITY_VERLET || m == MOTUS_LEAPFROG);
            double expected[4];
            int stages = 0, k;
            test_stepper s;
            motus_particle p[CAPACITY];
            motus_forces forces;
            recorder r;
            motus_vec2 start;
            if (m == MOTUS_EXACT_LINEAR_DRAG) continue;
            switch (m) {
            case MOTUS_SEMI_IMPLICIT_EULER:
            case MOTUS_EXPLICIT_EULER:
            case MOTUS_POSITION_VERLET: expected[stages++] = t; break;
            case MOTUS_VELOCITY_VERLET:
            case MOTUS_LEAPFROG:
                if (!reusing) expected[stages++] = t;
                expected[stages++] = t + h;
                break;
            case MOTUS_MIDPOINT:
                expected[stages++] = t;
                expected[stages++] = t + h / 2;
                break;
            case MOTUS_RK4:
                expected[stages++] = t, expected[stages++] = t + h / 2;
                expected[stages++] = t + h / 2, expected[stages++] = t + h;
                break;
            case MOTUS_FOREST_RUTH:
                for (k = 0; k < 3; ++k) expected[stages++] = forest_ruth[k];
                break;
            default: break;
            }
            ENSURE_EQ_INT(init_stepper(&s, m, (unsigned)flags), MOTUS_OK);
            sample_particles(p);
            recorder_forces(&forces, &r, motus_v2(1, 0));
            ENSURE_EQ_INT(motus_stepper_step(&s.stepper, p, CAPACITY, &forces, (motus_real)h), MOTUS_OK);
            r.calls = 0;
            start = p[0].position;
            ENSURE_EQ_INT(motus_stepper_step(&s.stepper, p, CAPACITY, &forces, (motus_real)h), MOTUS_OK);
            if (r.calls != stages) fprintf(stderr, "  %s flags %d: %d calls\n", motus_method_name(m), flags, r.calls);
            ENSURE_EQ_INT(r.calls, stages);
            for (k = 0; k < stages && k < r.calls; ++k) ENSURE_NEAR(r.times[k], expected[k], 4 * EPS);
            ENSURE_EQ_INT(r.count_seen, CAPACITY);
            /* The first evaluation sees the state the step starts from (Forest-Ruth drifts first). */
            if (m != MOTUS_FOREST_RUTH && !reusing) ENSURE(same_bytes(&r.first_position, &start, sizeof start));
        }
    }
}

TEST(evaluations_match_callback_calls) {
    /* motus_method_evaluations is what a step costs: the callback is called that many times per step
       (with reuse, from the second step on; the first has nothing to reuse). */
    int i, flags, k;
    for (i = 0; i < MOTUS_METHOD_COUNT; ++i) {
        for (flags = 0; flags <= MOTUS_STEPPER_REUSE_FORCES; ++flags) {
            const motus_method m = (motus_method)i;
            test_stepper s;
            motus_particle p[CAPACITY];
            motus_forces forces;
            recorder r;
            if (m == MOTUS_EXACT_LINEAR_DRAG) continue;
            ENSURE_EQ_INT(init_stepper(&s, m, (unsigned)flags), MOTUS_OK);
            sample_particles(p);
            recorder_forces(&forces, &r, motus_v2(0, 1));
            ENSURE_EQ_INT(motus_stepper_step(&s.stepper, p, CAPACITY, &forces, DT), MOTUS_OK);
            ENSURE_EQ_INT(r.calls, motus_method_evaluations(m, 0));
            r.calls = 0;
            for (k = 0; k < 10; ++k) ENSURE_EQ_INT(motus_stepper_step(&s.stepper, p, CAPACITY, &forces, DT), MOTUS_OK);
            ENSURE_EQ_INT(r.calls, 10 * motus_method_evaluations(m, (unsigned)flags));
        }
    }
}

TEST(reuse_forces_gives_the_same_result) {
    /* For forces of position only (gravity, springs without damping, the attractor, a constant callback)
       reusing the last evaluation changes nothing, bit for bit: it is the same a(x_n) either way. */
    static const motus_method methods[2] = {MOTUS_VELOCITY_VERLET, MOTUS_LEAPFROG};
    int i, k;
    for (i = 0; i < 2; ++i) {
        test_stepper reusing, plain;
        motus_particle p[CAPACITY], q[CAPACITY];
        test_forces f;
        recorder r;
        full_forces(&f);
        f.forces.linear_drag = 0, f.forces.quadratic_drag = 0;
        f.springs[0].damping = 0, f.springs[2].damping = 0;
        memset(&r, 0, sizeof r);
        r.push = motus_v2(MOTUS_R(0.75), 0);
        f.forces.callback = recording_callback;
        f.forces.user_data = &r;
        ENSURE_EQ_INT(init_stepper(&reusing, methods[i], MOTUS_STEPPER_REUSE_FORCES), MOTUS_OK);
        ENSURE_EQ_INT(init_stepper(&plain, methods[i], 0), MOTUS_OK);
        sample_particles(p);
        sample_particles(q);
        for (k = 0; k < 100; ++k) {
            ENSURE_EQ_INT(motus_stepper_step(&reusing.stepper, p, CAPACITY, &f.forces, DT), MOTUS_OK);
            ENSURE_EQ_INT(motus_stepper_step(&plain.stepper, q, CAPACITY, &f.forces, DT), MOTUS_OK);
        }
        ENSURE(same_bytes(p, q, sizeof p));
        ENSURE(reusing.stepper.time == plain.stepper.time);
    }
}

TEST(reuse_forces_recomputes_when_the_count_changes) {
    /* The kept accelerations cover the particles of the last step only: a step over more particles must
       evaluate again, or the new ones would start from whatever the scratch held. */
    test_stepper reusing, plain;
    motus_particle p[CAPACITY], q[CAPACITY];
    motus_forces f;
    memset(&f, 0, sizeof f);
    f.gravity = motus_v2(0, -10);
    f.attractor_strength = 1;
    ENSURE_EQ_INT(init_stepper(&reusing, MOTUS_VELOCITY_VERLET, MOTUS_STEPPER_REUSE_FORCES), MOTUS_OK);
    ENSURE_EQ_INT(init_stepper(&plain, MOTUS_VELOCITY_VERLET, 0), MOTUS_OK);
    sample_particles(p);
    sample_particles(q);
    ENSURE_EQ_INT(motus_stepper_step(&reusing.stepper, p, 1, &f, DT), MOTUS_OK);
    ENSURE_EQ_INT(motus_stepper_step(&plain.stepper, q, 1, &f, DT), MOTUS_OK);
    ENSURE_EQ_INT(motus_stepper_step(&reusing.stepper, p, CAPACITY, &f, DT), MOTUS_OK);
    ENSURE_EQ_INT(motus_stepper_step(&plain.stepper, q, CAPACITY, &f, DT), MOTUS_OK);
    ENSURE(same_bytes(p, q, sizeof p));
}

/* =================================================================================================
   Physics that holds exactly or to rounding
   ================================================================================================= */
TEST(immovable_particles_do_not_move) {
    /* Particle 3 is immovable, on a spring to particle 0, under gravity, drag and the attractor, with a
       large accumulated force: it stays where it is, at rest, in every method. */
    int i, k;
    for (i = 0; i < MOTUS_METHOD_COUNT; ++i) {
        test_stepper s;
        motus_particle p[CAPACITY], before;
        test_forces f;
        ENSURE_EQ_INT(init_stepper(&s, (motus_method)i, 0), MOTUS_OK);
        sample_particles(p);
        forces_for((motus_method)i, &f);
        p[3].force = motus_v2(1e6f, -1e6f);
        before = p[3];
        for (k = 0; k < 100; ++k) ENSURE_EQ_INT(motus_stepper_step(&s.stepper, p, CAPACITY, &f.forces, DT), MOTUS_OK);
        ENSURE(same_bytes(&p[3], &before, sizeof before));
        ENSURE(p[0].position.x != 1); /* the others did move */
    }
}

TEST(immovable_particle_keeps_its_velocity_in_every_method) {
    /* An immovable particle given a velocity by hand (a moving platform) gets no acceleration from any
       term ("Forces: one model"), so it moves at that velocity: x0 + v*t. motus_particle_step and eight
       of the nine methods do so; all nine should agree. */
    int i, k;
    for (i = 0; i < MOTUS_METHOD_COUNT; ++i) {
        test_stepper s;
        motus_particle p[CAPACITY];
        test_forces f;
        ENSURE_EQ_INT(init_stepper(&s, (motus_method)i, 0), MOTUS_OK);
        sample_particles(p);
        simple_forces(&f); /* every method takes gravity and linear drag */
        p[3].velocity = motus_v2(3, -1);
        for (k = 0; k < 8; ++k)
            ENSURE_EQ_INT(motus_stepper_step(&s.stepper, p, CAPACITY, &f.forces, MOTUS_R(0.25)), MOTUS_OK);
        /* Rounding: RK4's h/6 and Forest-Ruth's theta are not dyadic; 8 steps of a few eps of |x| <= 6. */
        if (!motus_test_near(p[3].position.x, 6, 8 * 4 * EPS * 6, "immovable x", __FILE__, __LINE__) ||
            !motus_test_near(p[3].position.y, 1, 8 * 4 * EPS * 6, "immovable y", __FILE__, __LINE__))
            fprintf(stderr, "  %s: immovable particle at (%g, %g), expected (6, 1)\n",
                    motus_method_name((motus_method)i), (double)p[3].position.x, (double)p[3].position.y);
        ENSURE(p[3].velocity.x == 3 && p[3].velocity.y == -1);
    }
}

TEST(spring_conserves_momentum_and_pulls_together) {
    /* Two free particles (1 kg, 3 kg) on a stretched spring, moving apart, nothing else. The spring's forces
       are equal and opposite, so the total momentum stays what it was, to rounding; and they are pulled
       together. Rounding bound per step: k = 8 roundings of eps/2 on each m*v, and for position Verlet
       (whose velocity is (x_{n+1} - x_n)/h) on m*|x|/h; summed over the steps. */
    const int steps = 300;
    int i, k;
    for (i = 0; i < MOTUS_EXACT_LINEAR_DRAG; ++i) {
        test_stepper s;
        motus_particle p[2];
        motus_forces forces;
        motus_spring spring;
        const double h = (double)DT;
        double m0, m1, px0, py0, scale = 0, worst = 0, gap_start, gap;
        memset(p, 0, sizeof p);
        motus_particle_init(&p[0], motus_v2(0, 0), 1);
        motus_particle_init(&p[1], motus_v2(3, 0), 3);
        p[0].velocity = motus_v2(MOTUS_R(-0.2), MOTUS_R(0.1));
        p[1].velocity = motus_v2(MOTUS_R(0.3), MOTUS_R(0.4));
        memset(&forces, 0, sizeof forces);
        memset(&spring, 0, sizeof spring);
        spring.a = 0, spring.b = 1, spring.rest_length = 1, spring.stiffness = 50, spring.damping = MOTUS_R(0.5);
        forces.springs = &spring;
        forces.spring_count = 1;
        m0 = motus_particle_mass(&p[0]);
        m1 = motus_particle_mass(&p[1]);
        px0 = m0 * p[0].velocity.x + m1 * p[1].velocity.x;
        py0 = m0 * p[0].velocity.y + m1 * p[1].velocity.y;
        gap_start = hypot(p[1].position.x - p[0].position.x, p[1].position.y - p[0].position.y);
        ENSURE_EQ_INT(init_stepper(&s, (motus_method)i, 0), MOTUS_OK);
        for (k = 1; k <= steps; ++k) {
            double error, size;
            ENSURE_EQ_INT(motus_stepper_step(&s.stepper, p, 2, &forces, DT), MOTUS_OK);
            if (k == 10) {
                gap = hypot(p[1].position.x - p[0].position.x, p[1].position.y - p[0].position.y);
                ENSURE(gap < gap_start - 0.5);
            }
            size = m0 * (hypot(p[0].velocity.x, p[0].velocity.y) + hypot(p[0].position.x, p[0].position.y) / h) +
                   m1 * (hypot(p[1].velocity.x, p[1].velocity.y) + hypot(p[1].position.x, p[1].position.y) / h);
            if (size > scale) scale = size;
            error = hypot(m0 * p[0].velocity.x + m1 * p[1].velocity.x - px0,
                          m0 * p[0].velocity.y + m1 * p[1].velocity.y - py0);
            if (error / (k * 8 * (EPS / 2) * scale) > worst) worst = error / (k * 8 * (EPS / 2) * scale);
        }
        printf("  momentum %-20s largest drift %.3g of the rounding bound\n", motus_method_name((motus_method)i),
               worst);
        ENSURE(worst <= 1);
    }
}

/* =================================================================================================
   Reset and the clock
   ================================================================================================= */
TEST(reset_restarts_position_verlet) {
    /* Position Verlet steps from its stored previous positions, so a velocity set by hand is ignored until
       motus_stepper_reset; after it, the next step starts from the particle's velocity, exactly as a new
       stepper does. */
    test_stepper s, stale, fresh;
    motus_particle p[CAPACITY], q[CAPACITY], r[CAPACITY];
    test_forces f;
    int k;
    full_forces(&f);
    ENSURE_EQ_INT(init_stepper(&s, MOTUS_POSITION_VERLET, 0), MOTUS_OK);
    ENSURE_EQ_INT(init_stepper(&fresh, MOTUS_POSITION_VERLET, 0), MOTUS_OK);
    sample_particles(p);
    for (k = 0; k < 5; ++k) ENSURE_EQ_INT(motus_stepper_step(&s.stepper, p, CAPACITY, &f.forces, DT), MOTUS_OK);
    p[0].velocity = motus_v2(5, 5);
    p[2].velocity = motus_v2(-5, 0);
    memcpy(q, p, sizeof p);
    memcpy(r, p, sizeof p);
    memcpy(&stale, &s, sizeof s);
    stale.stepper.scratch = stale.scratch; /* the copy's own memory, with the same history */
    motus_stepper_reset(&s.stepper);
    ENSURE_EQ_INT(motus_stepper_step(&s.stepper, p, CAPACITY, &f.forces, DT), MOTUS_OK);
    ENSURE_EQ_INT(motus_stepper_step(&fresh.stepper, q, CAPACITY, &f.forces, DT), MOTUS_OK);
    ENSURE_EQ_INT(motus_stepper_step(&stale.stepper, r, CAPACITY, &f.forces, DT), MOTUS_OK);
    ENSURE(same_bytes(p, q, sizeof p));
    ENSURE(p[0].position.x != r[0].position.x); /* without the reset the new velocity was ignored */
    motus_stepper_reset(NULL);                  /* harmless */
}

TEST(reset_restarts_reused_forces) {
    /* With MOTUS_STEPPER_REUSE_FORCES the stepper keeps a(x_n); a particle moved by hand needs a reset,
       after which the step is the one a new stepper takes. */
    static const motus_method methods[2] = {MOTUS_VELOCITY_VERLET, MOTUS_LEAPFROG};
    int i;
    for (i = 0; i < 2; ++i) {
        test_stepper s, stale, fresh;
        motus_particle p[CAPACITY], q[CAPACITY], r[CAPACITY];
        test_forces f;
        full_forces(&f);
        f.forces.linear_drag = 0, f.forces.quadratic_drag = 0;
        f.springs[0].damping = 0, f.springs[2].damping = 0;
        ENSURE_EQ_INT(init_stepper(&s, methods[i], MOTUS_STEPPER_REUSE_FORCES), MOTUS_OK);
        ENSURE_EQ_INT(init_stepper(&fresh, methods[i], MOTUS_STEPPER_REUSE_FORCES), MOTUS_OK);
        sample_particles(p);
        ENSURE_EQ_INT(motus_stepper_step(&s.stepper, p, CAPACITY, &f.forces, DT), MOTUS_OK);
        p[0].position = motus_v2(-3, 2); /* teleported */
        memcpy(q, p, sizeof p);
        memcpy(r, p, sizeof p);
        memcpy(&stale, &s, sizeof s);
        stale.stepper.scratch = stale.scratch;
        motus_stepper_reset(&s.stepper);
        ENSURE_EQ_INT(motus_stepper_step(&s.stepper, p, CAPACITY, &f.forces, DT), MOTUS_OK);
        ENSURE_EQ_INT(motus_stepper_step(&fresh.stepper, q, CAPACITY, &f.forces, DT), MOTUS_OK);
        ENSURE_EQ_INT(motus_stepper_step(&stale.stepper, r, CAPACITY, &f.forces, DT), MOTUS_OK);
        ENSURE(same_bytes(p, q, sizeof p));
        ENSURE(p[0].velocity.x != r[0].velocity.x); /* without the reset the old acceleration was used */
    }
}

TEST(position_verlet_new_particles_start_from_their_velocity) {
    /* A game adds particles: the stepper was stepping 1, now it steps 2. Position Verlet has no previous
       position for the new one, so its first step must start from its velocity, as after a reset (a
       particle at rest with no force stays at rest). Stepping from the stale scratch instead moves it by
       whatever the memory held. */
    test_stepper s;
    motus_particle p[CAPACITY];
    int k;
    ENSURE_EQ_INT(init_stepper(&s, MOTUS_POSITION_VERLET, 0), MOTUS_OK);
    sample_particles(p);
    p[1].velocity = motus_v2(0, 0);
    p[1].force = motus_v2(0, 0);
    for (k = 0; k < 3; ++k) ENSURE_EQ_INT(motus_stepper_step(&s.stepper, p, 1, NULL, DT), MOTUS_OK);
    ENSURE_EQ_INT(motus_stepper_step(&s.stepper, p, 2, NULL, DT), MOTUS_OK);
    if (!(p[1].position.x == -2 && p[1].position.y == 1))
        fprintf(stderr, "  new particle at rest moved from (-2, 1) to (%g, %g)\n", (double)p[1].position.x,
                (double)p[1].position.y);
    ENSURE(p[1].position.x == -2 && p[1].position.y == 1);
    ENSURE(p[1].velocity.x == 0 && p[1].velocity.y == 0);
}

TEST(stepper_time_advances_by_dt) {
    int i;
    for (i = 0; i < MOTUS_METHOD_COUNT; ++i) {
        test_stepper s;
        motus_particle p[CAPACITY];
        test_forces f;
        ENSURE_EQ_INT(init_stepper(&s, (motus_method)i, 0), MOTUS_OK);
        sample_particles(p);
        forces_for((motus_method)i, &f);
        ENSURE(s.stepper.time == 0);
        ENSURE_EQ_INT(motus_stepper_step(&s.stepper, p, CAPACITY, &f.forces, MOTUS_R(0.25)), MOTUS_OK);
        ENSURE(s.stepper.time == MOTUS_R(0.25));
        ENSURE_EQ_INT(motus_stepper_step(&s.stepper, p, CAPACITY, &f.forces, MOTUS_R(0.5)), MOTUS_OK);
        ENSURE_EQ_INT(motus_stepper_step(&s.stepper, p, CAPACITY, &f.forces, MOTUS_R(0.125)), MOTUS_OK);
        ENSURE(s.stepper.time == MOTUS_R(0.875));
        /* A rejected step is not a step. */
        ENSURE_REJECTED(&s.stepper, p, CAPACITY, &f.forces, 0, MOTUS_ERROR_INVALID_TIME_STEP, "dt 0");
        ENSURE(s.stepper.time == MOTUS_R(0.875));
    }
}

static const motus_test_case TESTS[] = {
    TEST_CASE(method_names),
    TEST_CASE(method_orders_and_evaluations),
    TEST_CASE(scratch_size_arithmetic),
    TEST_CASE(scratch_size_is_enough),
    TEST_CASE(stepper_init_sets_fields),
    TEST_CASE(stepper_desc_zero_is_default),
    TEST_CASE(stepper_init_rejects_bad_desc),
    TEST_CASE(forces_check_accepts_valid_models),
    TEST_CASE(forces_check_rejects_bad_models),
    TEST_CASE(stepper_rejects_bad_forces),
    TEST_CASE(stepper_rejects_bad_arguments),
    TEST_CASE(stepper_accepts_no_particles),
    TEST_CASE(stepper_rejects_broken_particles),
    TEST_CASE(stepper_rejects_every_non_finite_input),
    TEST_CASE(stepper_reports_overflow_all_or_nothing),
    TEST_CASE(exact_stepper_rejects_unsupported_forces),
    TEST_CASE(stepper_rejects_corrupt_method),
    TEST_CASE(reuse_forces_survives_a_rejected_step),
    TEST_CASE(semi_implicit_euler_matches_particle_step),
    TEST_CASE(exact_stepper_matches_particle_step_linear_drag),
    TEST_CASE(callback_forces_are_applied),
    TEST_CASE(callback_receives_stage_times),
    TEST_CASE(evaluations_match_callback_calls),
    TEST_CASE(reuse_forces_gives_the_same_result),
    TEST_CASE(reuse_forces_recomputes_when_the_count_changes),
    TEST_CASE(immovable_particles_do_not_move),
    TEST_CASE(immovable_particle_keeps_its_velocity_in_every_method),
    TEST_CASE(spring_conserves_momentum_and_pulls_together),
    TEST_CASE(reset_restarts_position_verlet),
    TEST_CASE(reset_restarts_reused_forces),
    TEST_CASE(position_verlet_new_particles_start_from_their_velocity),
    TEST_CASE(stepper_time_advances_by_dt),
};

int main(int argc, char **argv) { return motus_test_main(argc, argv, TESTS, TEST_COUNT(TESTS)); }
