/* Bad input everywhere, byte for byte: every public function of motus.h given every bad input it can get
   (NaN, +Inf, -Inf in each real, zero and negative masses, dt <= 0 or not finite, NULL pointers, counts
   < 0, 0, INT_MAX, ranges past INT_MAX, absurd scratch sizes, unknown flags, broken force models and
   scenes), each call asserted for its result code and for the whole state (particles, stepper and its
   scratch, force model and springs, scene, batch arrays with guards) being byte for byte what it was.
   The state is one struct filled with a byte pattern first, then with valid values where a valid value is
   needed, so padding, unused arrays and the unused tail of the scratch are compared too.
   Also motus_particles_check / motus_batch_check_report (the first bad particle and field) and the
   messages. Built in float and double, and with MOTUS_CHECKED (input_checked.*), where the batch kernels
   find bad data before writing. */
#include "motus.h"
#include "support/motus_test.h"

#include <float.h>
#include <limits.h>
#include <stddef.h>
#include <stdint.h>

#ifdef MOTUS_DOUBLE
#define REAL_MAX DBL_MAX
#define REAL_MIN_NORMAL DBL_MIN
#else
#define REAL_MAX FLT_MAX
#define REAL_MIN_NORMAL FLT_MIN
#endif

enum { CAPACITY = 5, SPRINGS = 3, BN = 37, GUARD = 8, BSTRIDE = GUARD + BN + GUARD };
enum { BX = 0, BY, BVX, BVY, BFX, BFY, BMASS, BARRAYS };

static const motus_real DT = (motus_real)(1.0 / 60.0);
static motus_real not_a_number(void) { return (motus_real)NAN; }
static motus_real infinity(void) { return (motus_real)HUGE_VAL; }
static motus_real negative_zero(void) { return -(motus_real)0; }
/* The non-finite values every real input is tried with. */
static motus_real bad_real(int which) { return which == 0 ? not_a_number() : which == 1 ? infinity() : -infinity(); }
enum { BAD_REALS = 3 };

/* Everything a call could write. Pointers inside (stepper.scratch, forces.springs, batch arrays) point
   into the one global instance W, so a byte copy restores it exactly. The report comes last: the check
   functions write it whatever they return, so the state compared is everything before it. */
typedef struct world {
    motus_particle particles[CAPACITY];
    motus_stepper stepper;
    motus_vec2 scratch[8 * CAPACITY]; /* more than any method takes: the tail stays pattern */
    motus_stepper_desc desc;
    motus_forces forces;        /* every term (and, for the exact stepper, gravity and linear drag only) */
    motus_spring springs[SPRINGS];
    motus_scene scene;
    motus_batch batch;
    motus_real arrays[BARRAYS][BSTRIDE];
    motus_check_report report;
} world;

static world W, CLEAN, BEFORE;
static const unsigned char PATTERNS[2] = {0xA5, 0x5A};

static motus_real *barray(int which) { return W.arrays[which] + GUARD; }

static void setup_forces(motus_method method) {
    memset(&W.forces, 0, sizeof W.forces);
    W.forces.gravity = motus_v2(0, MOTUS_R(-9.81));
    W.forces.linear_drag = MOTUS_R(0.25);
    memset(W.springs, 0, sizeof W.springs);
    W.springs[0].a = 0, W.springs[0].b = 1, W.springs[0].rest_length = 1, W.springs[0].stiffness = 20;
    W.springs[0].damping = MOTUS_R(0.5);
    W.springs[1].a = 2, W.springs[1].b = -1, W.springs[1].anchor = motus_v2(4, 4), W.springs[1].stiffness = 10;
    W.springs[2].a = 4, W.springs[2].b = 3, W.springs[2].rest_length = 2, W.springs[2].stiffness = 5;
    if (method == MOTUS_EXACT_LINEAR_DRAG) return; /* the springs are there, the model does not use them */
    W.forces.quadratic_drag = MOTUS_R(0.01);
    W.forces.attractor_strength = 2;
    W.forces.attractor_position = motus_v2(0, -5);
    W.forces.springs = W.springs;
    W.forces.spring_count = SPRINGS;
}
/* The exact stepper's model with the springs hung on: checked (and refused) before UNSUPPORTED. */
static void use_springs(void) {
    W.forces.springs = W.springs;
    W.forces.spring_count = SPRINGS;
}

/* The pattern everywhere, then: four free particles and an immovable one, a stepper of `method` that has
   made one step (so position Verlet and reused forces have history to lose), a force model, a 2D scene
   with every feature and its batch of BN particles (z arrays NULL: a 2D scene does not read them). */
static void setup(unsigned char pattern, motus_method method) {
    int i;
    memset(&W, pattern, sizeof W);
    for (i = 0; i < CAPACITY; ++i) {
        motus_particle *p = &W.particles[i];
        p->position = motus_v2(MOTUS_R(1.5) * (motus_real)i - 2, MOTUS_R(0.75) * (motus_real)i + 1);
        p->velocity = motus_v2((motus_real)(i % 3) - 1, MOTUS_R(0.5) - (motus_real)i);
        p->force = motus_v2(MOTUS_R(0.25) * (motus_real)i, -MOTUS_R(0.125) * (motus_real)i);
        p->inverse_mass = i == CAPACITY - 1 ? 0 : MOTUS_R(1.0) / (motus_real)(i + 1);
    }
    setup_forces(method);
    W.desc.capacity = CAPACITY;
    W.desc.method = method;
    W.desc.scratch = W.scratch;
    W.desc.scratch_bytes = sizeof W.scratch;
    W.desc.flags = method == MOTUS_VELOCITY_VERLET || method == MOTUS_LEAPFROG ? MOTUS_STEPPER_REUSE_FORCES : 0;
    ENSURE_EQ_INT(motus_stepper_init(&W.stepper, &W.desc), MOTUS_OK);
    ENSURE_EQ_INT(motus_stepper_step(&W.stepper, W.particles, CAPACITY, &W.forces, DT), MOTUS_OK);

    memset(&W.scene, 0, sizeof W.scene);
    W.scene.has = MOTUS_HAS_GRAVITY | MOTUS_HAS_LINEAR_DRAG | MOTUS_HAS_DAMPING_PER_STEP | MOTUS_HAS_PARTICLE_MASS |
                  MOTUS_HAS_FORCES | MOTUS_HAS_QUADRATIC_DRAG | MOTUS_HAS_ATTRACTOR | MOTUS_HAS_BOUNDS;
    W.scene.method = MOTUS_SEMI_IMPLICIT_EULER;
    W.scene.gravity[1] = MOTUS_R(-9.81);
    W.scene.linear_drag = MOTUS_R(0.25);
    W.scene.quadratic_drag = MOTUS_R(0.01);
    W.scene.damping = MOTUS_R(0.99);
    W.scene.inverse_mass = 1;
    W.scene.attractor[0] = 3;
    W.scene.attractor_strength = 2;
    W.scene.bounds_min[0] = W.scene.bounds_min[1] = -100;
    W.scene.bounds_max[0] = W.scene.bounds_max[1] = 100;
    W.scene.restitution = MOTUS_R(0.5);
    memset(&W.batch, 0, sizeof W.batch);
    W.batch.dimensions = 2;
    W.batch.position[0] = barray(BX), W.batch.position[1] = barray(BY);
    W.batch.velocity[0] = barray(BVX), W.batch.velocity[1] = barray(BVY);
    W.batch.force[0] = barray(BFX), W.batch.force[1] = barray(BFY);
    W.batch.inverse_mass = barray(BMASS);
    for (i = 0; i < BN; ++i) {
        barray(BX)[i] = (motus_real)(i % 11) * 7 - 35, barray(BY)[i] = (motus_real)(i % 7) * 9 - 30;
        barray(BVX)[i] = (motus_real)(i % 5) - 2, barray(BVY)[i] = MOTUS_R(0.5) * (motus_real)(i % 3);
        barray(BFX)[i] = MOTUS_R(0.125) * (motus_real)i, barray(BFY)[i] = -1;
        barray(BMASS)[i] = i % 9 == 4 ? 0 : MOTUS_R(1.0) / (motus_real)(1 + i % 4);
    }
    memcpy(&CLEAN, &W, sizeof W);
}
static void restore(void) { memcpy(&W, &CLEAN, sizeof W); }

/* ---- the one assertion: result code, and the state byte for byte ---------------------------------------- */
/* The stepper's scratch is working memory: a step computes its new state there and writes it back only if
   it is good, so the arrays of that work change on a rejected step. What the stepper keeps between steps
   must not: position Verlet's last displacements and the kept acceleration (array 3 for those methods),
   and the scratch past what the method uses. */
static int scratch_changed(void) {
    const motus_method m = BEFORE.stepper.method;
    const size_t array = CAPACITY * sizeof(motus_vec2), used = motus_stepper_scratch_size(m, CAPACITY);
    const unsigned char *before = (const unsigned char *)BEFORE.scratch, *now = (const unsigned char *)W.scratch;
    const int keeps = m == MOTUS_POSITION_VERLET || m == MOTUS_VELOCITY_VERLET || m == MOTUS_LEAPFROG;
    if (keeps && memcmp(before + 3 * array, now + 3 * array, array) != 0) return 1;
    return memcmp(before + used, now + used, sizeof W.scratch - used) != 0;
}
static int state_changed(void) {
    const size_t scratch = offsetof(world, scratch), after = scratch + sizeof W.scratch;
    const unsigned char *before = (const unsigned char *)&BEFORE, *now = (const unsigned char *)&W;
    return memcmp(before, now, scratch) != 0 || scratch_changed() ||
           memcmp(before + after, now + after, offsetof(world, report) - after) != 0;
}

static void expect_at(motus_result got, motus_result expected, const char *call, const char *what, int line) {
    const int changed = state_changed();
    if (got != expected || changed) {
        fprintf(stderr, "%s:%d: %s [%s] (%s): ", __FILE__, line, call, what,
                motus_method_name(W.stepper.method) ? motus_method_name(W.stepper.method) : "?");
        if (got != expected)
            fprintf(stderr, "gave %d (%s), expected %d (%s)", (int)got, motus_result_string(got), (int)expected,
                    motus_result_string(expected));
        if (changed) fprintf(stderr, "%sthe state changed", got != expected ? "; " : "");
        fprintf(stderr, "\n");
        motus_test_failures++;
    }
}
/* Snapshot, call, then the code and every byte of the state. `what` names the case in a message. */
#define EXPECT(expected, what, call)                                                                          \
    do {                                                                                                      \
        motus_result expect_result_;                                                                          \
        memcpy(&BEFORE, &W, sizeof W);                                                                        \
        expect_result_ = (call);                                                                              \
        expect_at(expect_result_, expected, #call, what, __LINE__);                                           \
    } while (0)

/* The seven reals of a particle, by number, for loops over fields. */
static motus_real *particle_field(motus_particle *p, int k) {
    switch (k) {
    case 0: return &p->position.x;
    case 1: return &p->position.y;
    case 2: return &p->velocity.x;
    case 3: return &p->velocity.y;
    case 4: return &p->force.x;
    case 5: return &p->force.y;
    default: return &p->inverse_mass;
    }
}
static const char *const FIELD_NAMES[7] = {"position.x", "position.y", "velocity.x", "velocity.y",
                                           "force.x",    "force.y",    "inverse_mass"};
/* The time steps every stepping function must refuse. */
static motus_real bad_dt(int which) {
    switch (which) {
    case 0: return 0;
    case 1: return negative_zero();
    case 2: return -DT;
    case 3: return -REAL_MAX;
    default: return bad_real(which - 4);
    }
}
enum { BAD_DTS = 4 + BAD_REALS };

/* =================================================================================================
   Particle functions
   ================================================================================================= */
TEST(particle_init_rejects_everything_bad) {
    int pattern, b;
    for (pattern = 0; pattern < 2; ++pattern) {
        motus_particle *p = &W.particles[1];
        setup(PATTERNS[pattern], MOTUS_SEMI_IMPLICIT_EULER);
        EXPECT(MOTUS_ERROR_NULL_POINTER, "NULL", motus_particle_init(NULL, motus_v2(1, 2), 1));
        EXPECT(MOTUS_ERROR_NULL_POINTER, "NULL", motus_particle_init_immovable(NULL, motus_v2(1, 2)));
        for (b = 0; b < BAD_REALS; ++b) {
            EXPECT(MOTUS_ERROR_NOT_FINITE, "x", motus_particle_init(p, motus_v2(bad_real(b), 2), 1));
            EXPECT(MOTUS_ERROR_NOT_FINITE, "y", motus_particle_init(p, motus_v2(1, bad_real(b)), 1));
            EXPECT(MOTUS_ERROR_NOT_FINITE, "mass", motus_particle_init(p, motus_v2(1, 2), bad_real(b)));
            EXPECT(MOTUS_ERROR_NOT_FINITE, "x", motus_particle_init_immovable(p, motus_v2(bad_real(b), 2)));
            EXPECT(MOTUS_ERROR_NOT_FINITE, "y", motus_particle_init_immovable(p, motus_v2(1, bad_real(b))));
        }
        /* Non-finite before the mass's range: NaN position with mass 0 is NOT_FINITE. */
        EXPECT(MOTUS_ERROR_NOT_FINITE, "NaN x, mass 0", motus_particle_init(p, motus_v2(not_a_number(), 0), 0));
        EXPECT(MOTUS_ERROR_INVALID_MASS, "mass 0", motus_particle_init(p, motus_v2(1, 2), 0));
        EXPECT(MOTUS_ERROR_INVALID_MASS, "mass -0", motus_particle_init(p, motus_v2(1, 2), negative_zero()));
        EXPECT(MOTUS_ERROR_INVALID_MASS, "mass -1", motus_particle_init(p, motus_v2(1, 2), -1));
        EXPECT(MOTUS_ERROR_INVALID_MASS, "mass -max", motus_particle_init(p, motus_v2(1, 2), -REAL_MAX));
        EXPECT(MOTUS_ERROR_INVALID_MASS, "1/mass overflows",
               motus_particle_init(p, motus_v2(1, 2), REAL_MIN_NORMAL / 1024));
        /* The extremes that are fine: the largest mass (1/m subnormal, not 0) and the smallest normal one. */
        ENSURE_EQ_INT(motus_particle_init(p, motus_v2(1, 2), REAL_MAX), MOTUS_OK);
        ENSURE(p->inverse_mass > 0);
        ENSURE_EQ_INT(motus_particle_init(p, motus_v2(1, 2), REAL_MIN_NORMAL), MOTUS_OK);
        ENSURE_NEAR(motus_particle_mass(p), REAL_MIN_NORMAL, 0); /* 1/2^-126 (2^-1022) is exact both ways */
        /* Getters with no state: NaN for NULL. */
        ENSURE(motus_particle_mass(NULL) != motus_particle_mass(NULL));
    }
}

TEST(particle_check_and_forces_reject_everything_bad) {
    int pattern, k, b;
    for (pattern = 0; pattern < 2; ++pattern) {
        setup(PATTERNS[pattern], MOTUS_SEMI_IMPLICIT_EULER);
        EXPECT(MOTUS_ERROR_NULL_POINTER, "NULL", motus_particle_check(NULL));
        EXPECT(MOTUS_ERROR_NULL_POINTER, "NULL", motus_particle_add_force(NULL, motus_v2(1, 1)));
        EXPECT(MOTUS_ERROR_NULL_POINTER, "NULL", motus_particle_clear_forces(NULL));
        for (b = 0; b < BAD_REALS; ++b) {
            EXPECT(MOTUS_ERROR_NOT_FINITE, "fx", motus_particle_add_force(&W.particles[0], motus_v2(bad_real(b), 1)));
            EXPECT(MOTUS_ERROR_NOT_FINITE, "fy", motus_particle_add_force(&W.particles[0], motus_v2(1, bad_real(b))));
            for (k = 0; k < 7; ++k) {
                *particle_field(&W.particles[2], k) = bad_real(b);
                EXPECT(MOTUS_ERROR_NOT_FINITE, FIELD_NAMES[k], motus_particle_check(&W.particles[2]));
                /* add_force reads the accumulator only: a bad accumulator is refused, other fields are not
                   its business. */
                if (k == 4 || k == 5)
                    EXPECT(MOTUS_ERROR_NOT_FINITE, FIELD_NAMES[k], motus_particle_add_force(&W.particles[2], motus_v2(1, 1)));
                restore();
            }
        }
        W.particles[2].inverse_mass = MOTUS_R(-0.5);
        EXPECT(MOTUS_ERROR_INVALID_MASS, "inverse mass < 0", motus_particle_check(&W.particles[2]));
        restore();
        W.particles[2].force = motus_v2(REAL_MAX, -REAL_MAX);
        EXPECT(MOTUS_ERROR_OVERFLOW, "sum overflows", motus_particle_add_force(&W.particles[2], motus_v2(REAL_MAX, 0)));
        EXPECT(MOTUS_ERROR_OVERFLOW, "sum overflows", motus_particle_add_force(&W.particles[2], motus_v2(0, -REAL_MAX)));
        restore();
        ENSURE_EQ_INT(motus_particle_check(&W.particles[CAPACITY - 1]), MOTUS_OK); /* immovable is fine */
    }
}

/* The functions that step or damp one particle, each with a time step, a parameter, or both. */
enum { F_STEP, F_DRAG, F_DAMP_STEP, F_DAMP_SECOND, F_BOUNCE, PARTICLE_FUNCTIONS };
static const char *const PARTICLE_FUNCTION_NAMES[PARTICLE_FUNCTIONS] = {
    "motus_particle_step", "motus_particle_step_linear_drag", "motus_particle_damp_per_step",
    "motus_particle_damp_per_second", "motus_particle_bounce"};
static motus_result call_particle_function(int f, motus_particle *p, motus_real dt, motus_real parameter) {
    switch (f) {
    case F_STEP: return motus_particle_step(p, dt);
    case F_DRAG: return motus_particle_step_linear_drag(p, parameter, dt);
    case F_DAMP_STEP: return motus_particle_damp_per_step(p, parameter);
    case F_DAMP_SECOND: return motus_particle_damp_per_second(p, parameter, dt);
    default: return motus_particle_bounce(p, motus_v2(-100, -100), motus_v2(100, 100), parameter);
    }
}
/* Which particle fields each reads (bit k = field k of particle_field). */
static const int READS[PARTICLE_FUNCTIONS] = {0x7F, 0x7F, 0x0C, 0x0C, 0x0F};
static const int HAS_DT[PARTICLE_FUNCTIONS] = {1, 1, 0, 1, 0};

TEST(particle_steps_reject_everything_bad) {
    int pattern, f, k, b;
    const motus_real good_parameter = MOTUS_R(0.5);
    for (pattern = 0; pattern < 2; ++pattern)
        for (f = 0; f < PARTICLE_FUNCTIONS; ++f) {
            const char *what = PARTICLE_FUNCTION_NAMES[f];
            motus_particle *p = &W.particles[1];
            setup(PATTERNS[pattern], MOTUS_SEMI_IMPLICIT_EULER);
            EXPECT(MOTUS_ERROR_NULL_POINTER, what, call_particle_function(f, NULL, DT, good_parameter));
            if (HAS_DT[f])
                for (b = 0; b < BAD_DTS; ++b)
                    EXPECT(MOTUS_ERROR_INVALID_TIME_STEP, what, call_particle_function(f, p, bad_dt(b), good_parameter));
            /* Each field it reads, non-finite; fields it does not read are left to the functions that do. */
            for (k = 0; k < 7; ++k)
                for (b = 0; b < BAD_REALS; ++b) {
                    *particle_field(p, k) = bad_real(b);
                    if (READS[f] >> k & 1)
                        EXPECT(k == 6 && b == 2 && f <= F_DRAG ? MOTUS_ERROR_INVALID_MASS : MOTUS_ERROR_NOT_FINITE,
                               FIELD_NAMES[k], call_particle_function(f, p, DT, good_parameter));
                    else
                        ENSURE_EQ_INT(call_particle_function(f, p, DT, good_parameter), MOTUS_OK);
                    restore();
                }
            /* The parameter: a drag rate, a damping factor or a restitution. */
            for (b = 0; b < BAD_REALS; ++b) {
                const motus_result expected = f == F_STEP ? MOTUS_OK
                                              : f == F_DRAG || f == F_BOUNCE ? MOTUS_ERROR_NOT_FINITE
                                                                             : MOTUS_ERROR_INVALID_DAMPING;
                if (f == F_STEP) continue;
                EXPECT(expected, "parameter not finite", call_particle_function(f, p, DT, bad_real(b)));
            }
            if (f != F_STEP) {
                EXPECT(MOTUS_ERROR_INVALID_DAMPING, "parameter < 0", call_particle_function(f, p, DT, MOTUS_R(-0.25)));
                if (f != F_DRAG)
                    EXPECT(MOTUS_ERROR_INVALID_DAMPING, "parameter > 1", call_particle_function(f, p, DT, MOTUS_R(1.25)));
            }
            /* A negative mass, where the mass is read. */
            if (f <= F_DRAG) {
                p->inverse_mass = MOTUS_R(-0.5);
                EXPECT(MOTUS_ERROR_INVALID_MASS, "inverse mass < 0", call_particle_function(f, p, DT, good_parameter));
                restore();
                /* Finite inputs, a result past the largest real. */
                p->velocity = motus_v2(REAL_MAX / 2, 0);
                p->position = motus_v2(REAL_MAX / 2, 0);
                EXPECT(MOTUS_ERROR_OVERFLOW, "overflow", call_particle_function(f, p, 4, 0));
                restore();
                p->force = motus_v2(0, -REAL_MAX);
                EXPECT(MOTUS_ERROR_OVERFLOW, "overflow", call_particle_function(f, p, 8, 0));
                restore();
            }
        }
    /* bounce's own: a box with min > max in either axis, or a bad corner. */
    setup(PATTERNS[0], MOTUS_SEMI_IMPLICIT_EULER);
    EXPECT(MOTUS_ERROR_INVALID_SCENE, "min.x > max.x",
           motus_particle_bounce(&W.particles[0], motus_v2(1, 0), motus_v2(0, 1), MOTUS_R(0.5)));
    EXPECT(MOTUS_ERROR_INVALID_SCENE, "min.y > max.y",
           motus_particle_bounce(&W.particles[0], motus_v2(0, 1), motus_v2(1, 0), MOTUS_R(0.5)));
    for (b = 0; b < BAD_REALS; ++b) {
        EXPECT(MOTUS_ERROR_NOT_FINITE, "min", motus_particle_bounce(&W.particles[0], motus_v2(bad_real(b), 0), motus_v2(1, 1), 1));
        EXPECT(MOTUS_ERROR_NOT_FINITE, "min", motus_particle_bounce(&W.particles[0], motus_v2(0, bad_real(b)), motus_v2(1, 1), 1));
        EXPECT(MOTUS_ERROR_NOT_FINITE, "max", motus_particle_bounce(&W.particles[0], motus_v2(0, 0), motus_v2(bad_real(b), 1), 1));
        EXPECT(MOTUS_ERROR_NOT_FINITE, "max", motus_particle_bounce(&W.particles[0], motus_v2(0, 0), motus_v2(1, bad_real(b)), 1));
    }
    /* motus_damping_per_second_from_per_step has no state: NaN for arguments out of range. */
    for (b = 0; b < BAD_DTS; ++b) {
        motus_real r = motus_damping_per_second_from_per_step(MOTUS_R(0.99), bad_dt(b));
        ENSURE(r != r);
    }
    ENSURE(motus_damping_per_second_from_per_step(not_a_number(), 60) != motus_damping_per_second_from_per_step(not_a_number(), 60));
    ENSURE(motus_damping_per_second_from_per_step(MOTUS_R(1.5), 60) != motus_damping_per_second_from_per_step(MOTUS_R(1.5), 60));
}

/* =================================================================================================
   Force model and stepper
   ================================================================================================= */
/* One thing wrong with W.forces per case (or with the count it is checked for); MOTUS_RESULT_COUNT when
   the cases are done. */
static motus_result break_forces(int which, int *count, const char **what) {
    motus_forces *f = &W.forces;
    motus_spring *s = W.springs;
    const int bad = which % BAD_REALS;
    switch (which / BAD_REALS) {
    case 0: *what = "gravity.x"; f->gravity.x = bad_real(bad); return MOTUS_ERROR_NOT_FINITE;
    case 1: *what = "gravity.y"; f->gravity.y = bad_real(bad); return MOTUS_ERROR_NOT_FINITE;
    case 2: *what = "linear_drag"; f->linear_drag = bad_real(bad); return MOTUS_ERROR_NOT_FINITE;
    case 3: *what = "quadratic_drag"; f->quadratic_drag = bad_real(bad); return MOTUS_ERROR_NOT_FINITE;
    case 4: *what = "attractor_strength"; f->attractor_strength = bad_real(bad); return MOTUS_ERROR_NOT_FINITE;
    case 5: *what = "attractor_position.x"; f->attractor_position.x = bad_real(bad); return MOTUS_ERROR_NOT_FINITE;
    case 6: *what = "attractor_position.y"; f->attractor_position.y = bad_real(bad); return MOTUS_ERROR_NOT_FINITE;
    case 7: *what = "spring anchor.x"; s[1].anchor.x = bad_real(bad); return MOTUS_ERROR_NOT_FINITE;
    case 8: *what = "spring anchor.y"; s[1].anchor.y = bad_real(bad); return MOTUS_ERROR_NOT_FINITE;
    case 9: *what = "spring rest_length"; s[0].rest_length = bad_real(bad); return MOTUS_ERROR_NOT_FINITE;
    case 10: *what = "spring stiffness"; s[2].stiffness = bad_real(bad); return MOTUS_ERROR_NOT_FINITE;
    case 11: *what = "spring damping"; s[0].damping = bad_real(bad); return MOTUS_ERROR_NOT_FINITE;
    default: break;
    }
    switch (which - 12 * BAD_REALS) {
    case 0: *what = "linear_drag < 0"; f->linear_drag = MOTUS_R(-0.5); return MOTUS_ERROR_INVALID_FORCES;
    case 1: *what = "quadratic_drag < 0"; f->quadratic_drag = -REAL_MAX; return MOTUS_ERROR_INVALID_FORCES;
    case 2: *what = "attractor_strength < 0"; f->attractor_strength = -1; return MOTUS_ERROR_INVALID_FORCES;
    case 3: *what = "spring_count < 0"; f->spring_count = -1; return MOTUS_ERROR_INVALID_FORCES;
    case 4: *what = "spring_count INT_MIN"; f->spring_count = INT_MIN; return MOTUS_ERROR_INVALID_FORCES;
    case 5: *what = "springs NULL"; f->springs = NULL; return MOTUS_ERROR_INVALID_FORCES;
    case 6: *what = "spring a = count"; s[0].a = CAPACITY; return MOTUS_ERROR_INVALID_FORCES;
    case 7: *what = "spring a = -1"; s[0].a = -1; return MOTUS_ERROR_INVALID_FORCES;
    case 8: *what = "spring a = INT_MAX"; s[2].a = INT_MAX; return MOTUS_ERROR_INVALID_FORCES;
    case 9: *what = "spring b = count"; s[0].b = CAPACITY; return MOTUS_ERROR_INVALID_FORCES;
    case 10: *what = "spring b = -2"; s[2].b = -2; return MOTUS_ERROR_INVALID_FORCES;
    case 11: *what = "spring b = INT_MIN"; s[2].b = INT_MIN; return MOTUS_ERROR_INVALID_FORCES;
    case 12: *what = "spring a == b"; s[0].b = s[0].a; return MOTUS_ERROR_INVALID_FORCES;
    case 13: *what = "spring stiffness < 0"; s[1].stiffness = -1; return MOTUS_ERROR_INVALID_FORCES;
    case 14: *what = "spring damping < 0"; s[1].damping = MOTUS_R(-0.125); return MOTUS_ERROR_INVALID_FORCES;
    case 15: *what = "spring rest_length < 0"; s[2].rest_length = -2; return MOTUS_ERROR_INVALID_FORCES;
    case 16: *what = "count -1"; *count = -1; return MOTUS_ERROR_INVALID_COUNT;
    case 17: *what = "count INT_MIN"; *count = INT_MIN; return MOTUS_ERROR_INVALID_COUNT;
    default: return MOTUS_RESULT_COUNT;
    }
}

TEST(forces_check_rejects_everything_bad) {
    int pattern, which;
    for (pattern = 0; pattern < 2; ++pattern) {
        setup(PATTERNS[pattern], MOTUS_SEMI_IMPLICIT_EULER);
        EXPECT(MOTUS_ERROR_NULL_POINTER, "NULL", motus_forces_check(NULL, CAPACITY));
        EXPECT(MOTUS_OK, "valid", motus_forces_check(&W.forces, CAPACITY));
        EXPECT(MOTUS_OK, "count INT_MAX: every spring end is inside", motus_forces_check(&W.forces, INT_MAX));
        for (which = 0;; ++which) {
            const char *what = "";
            int count = CAPACITY;
            const motus_result expected = break_forces(which, &count, &what);
            if (expected == MOTUS_RESULT_COUNT) break;
            EXPECT(expected, what, motus_forces_check(&W.forces, count));
            restore();
        }
        /* No springs: NULL springs and count 0 are fine. */
        W.forces.springs = NULL, W.forces.spring_count = 0;
        EXPECT(MOTUS_OK, "no springs", motus_forces_check(&W.forces, 0));
        restore();
    }
}

TEST(method_queries_and_scratch_size_reject_bad_values) {
    const int bad_methods[4] = {-1, MOTUS_METHOD_COUNT, INT_MAX, INT_MIN};
    int i, m;
    for (i = 0; i < 4; ++i) {
        ENSURE(motus_method_name((motus_method)bad_methods[i]) == NULL);
        ENSURE_EQ_INT(motus_method_order((motus_method)bad_methods[i]), -1);
        ENSURE_EQ_INT(motus_method_evaluations((motus_method)bad_methods[i], 0), -1);
        ENSURE(motus_stepper_scratch_size((motus_method)bad_methods[i], 4) == 0);
    }
    for (m = 0; m < MOTUS_METHOD_COUNT; ++m) {
        const size_t one = motus_stepper_scratch_size((motus_method)m, 1);
        ENSURE(one > 0);
        ENSURE(motus_stepper_scratch_size((motus_method)m, -1) == 0);
        ENSURE(motus_stepper_scratch_size((motus_method)m, INT_MIN) == 0);
        ENSURE(motus_stepper_scratch_size((motus_method)m, 0) == 0); /* valid: nothing needed */
        /* INT_MAX particles: the exact size, or 0 where size_t cannot hold it (never a wrapped size). */
        if ((size_t)INT_MAX <= SIZE_MAX / one) ENSURE(motus_stepper_scratch_size((motus_method)m, INT_MAX) == (size_t)INT_MAX * one);
        else ENSURE(motus_stepper_scratch_size((motus_method)m, INT_MAX) == 0);
    }
}

/* One thing wrong with W.desc per case; the stepper it would initialise must stay as it was. */
static motus_result break_desc(int which, const char **what) {
    motus_stepper_desc *d = &W.desc;
    switch (which) {
    case 0: *what = "method -1"; d->method = (motus_method)-1; return MOTUS_ERROR_UNSUPPORTED;
    case 1: *what = "method COUNT"; d->method = MOTUS_METHOD_COUNT; return MOTUS_ERROR_UNSUPPORTED;
    case 2: *what = "capacity -1"; d->capacity = -1; return MOTUS_ERROR_INVALID_COUNT;
    case 3: *what = "capacity INT_MIN"; d->capacity = INT_MIN; return MOTUS_ERROR_INVALID_COUNT;
    case 4:
        *what = "capacity INT_MAX";
        d->capacity = INT_MAX; /* more than the memory given, or (32-bit size_t) than any memory */
        return motus_stepper_scratch_size(d->method, INT_MAX) == 0 ? MOTUS_ERROR_INVALID_COUNT
                                                                   : MOTUS_ERROR_SCRATCH_TOO_SMALL;
    case 5:
        *what = "scratch one byte short";
        d->scratch_bytes = motus_stepper_scratch_size(d->method, d->capacity) - 1;
        return MOTUS_ERROR_SCRATCH_TOO_SMALL;
    case 6: *what = "scratch_bytes 0"; d->scratch_bytes = 0; return MOTUS_ERROR_SCRATCH_TOO_SMALL;
    case 7: *what = "scratch NULL"; d->scratch = NULL; return MOTUS_ERROR_NULL_POINTER;
    case 8: *what = "unknown flag"; d->flags |= 2u; return MOTUS_ERROR_INVALID_DESC;
    case 9: *what = "a MOTUS_HAS_* bit as flags"; d->flags = MOTUS_HAS_BOUNDS; return MOTUS_ERROR_INVALID_DESC;
    case 10: *what = "all flags"; d->flags = ~0u; return MOTUS_ERROR_INVALID_DESC;
    case 11:
        *what = "scratch misaligned";
        d->scratch = (char *)W.scratch + 1;
        d->scratch_bytes = sizeof W.scratch - 1;
        return MOTUS_ERROR_INVALID_DESC;
    default: return MOTUS_RESULT_COUNT;
    }
}

TEST(stepper_init_rejects_everything_bad) {
    int pattern, m, which;
    for (pattern = 0; pattern < 2; ++pattern)
        for (m = 0; m < MOTUS_METHOD_COUNT; ++m) {
            setup(PATTERNS[pattern], (motus_method)m);
            EXPECT(MOTUS_ERROR_NULL_POINTER, "NULL stepper", motus_stepper_init(NULL, &W.desc));
            EXPECT(MOTUS_ERROR_NULL_POINTER, "NULL desc", motus_stepper_init(&W.stepper, NULL));
            for (which = 0;; ++which) {
                const char *what = "";
                const motus_result expected = break_desc(which, &what);
                if (expected == MOTUS_RESULT_COUNT) break;
                EXPECT(expected, what, motus_stepper_init(&W.stepper, &W.desc));
                restore();
            }
            /* Capacity 0 needs no memory: NULL scratch of 0 bytes is a valid (empty) stepper. */
            W.desc.capacity = 0, W.desc.scratch = NULL, W.desc.scratch_bytes = 0;
            ENSURE_EQ_INT(motus_stepper_init(&W.stepper, &W.desc), MOTUS_OK);
            motus_stepper_reset(NULL); /* a void function: NULL is ignored */
        }
}

/* Calls motus_stepper_step on W with the forces the method takes. */
static motus_result step_world(int count, motus_real dt) {
    return motus_stepper_step(&W.stepper, W.particles, count, &W.forces, dt);
}

TEST(stepper_step_rejects_everything_bad) {
    int pattern, m, which, b, i, k;
    for (pattern = 0; pattern < 2; ++pattern)
        for (m = 0; m < MOTUS_METHOD_COUNT; ++m) {
            setup(PATTERNS[pattern], (motus_method)m);
            EXPECT(MOTUS_ERROR_NULL_POINTER, "NULL stepper", motus_stepper_step(NULL, W.particles, CAPACITY, &W.forces, DT));
            EXPECT(MOTUS_ERROR_NULL_POINTER, "NULL particles", motus_stepper_step(&W.stepper, NULL, 1, &W.forces, DT));
            EXPECT(MOTUS_ERROR_INVALID_COUNT, "count -1", step_world(-1, DT));
            EXPECT(MOTUS_ERROR_INVALID_COUNT, "count INT_MIN", step_world(INT_MIN, DT));
            EXPECT(MOTUS_ERROR_INVALID_COUNT, "count > capacity", step_world(CAPACITY + 1, DT));
            EXPECT(MOTUS_ERROR_INVALID_COUNT, "count INT_MAX", step_world(INT_MAX, DT));
            for (b = 0; b < BAD_DTS; ++b) EXPECT(MOTUS_ERROR_INVALID_TIME_STEP, "bad dt", step_world(CAPACITY, bad_dt(b)));
            /* Every broken force model (the exact stepper's model has no springs, attractor or quadratic
               drag, but is checked all the same). */
            for (which = 0;; ++which) {
                const char *what = "";
                int count = CAPACITY;
                motus_result expected;
                if (m == MOTUS_EXACT_LINEAR_DRAG) use_springs();
                expected = break_forces(which, &count, &what);
                if (expected == MOTUS_RESULT_COUNT) break;
                EXPECT(expected, what, step_world(count, DT));
                restore();
            }
            restore();
            /* Every field of every particle: NaN, +Inf, -Inf; and a negative mass (-Inf is one too). */
            for (i = 0; i < CAPACITY; ++i)
                for (k = 0; k < 7; ++k)
                    for (b = 0; b < BAD_REALS; ++b) {
                        char what[64];
                        sprintf(what, "particle %d %s = %g", i, FIELD_NAMES[k], (double)bad_real(b));
                        *particle_field(&W.particles[i], k) = bad_real(b);
                        EXPECT(k == 6 && b == 2 ? MOTUS_ERROR_INVALID_MASS : MOTUS_ERROR_NOT_FINITE, what,
                               step_world(CAPACITY, DT));
                        restore();
                    }
            W.particles[3].inverse_mass = MOTUS_R(-0.5);
            EXPECT(MOTUS_ERROR_INVALID_MASS, "inverse mass < 0", step_world(CAPACITY, DT));
            restore();
            /* Finite, but the step would overflow. */
            W.particles[1].position = motus_v2(REAL_MAX / 2, 0);
            W.particles[1].velocity = motus_v2(REAL_MAX / 2, 0);
            EXPECT(MOTUS_ERROR_OVERFLOW, "overflow", step_world(CAPACITY, 4));
            restore();
            /* A stepper filled in by hand: no scratch, an unknown method. */
            W.stepper.scratch = NULL;
            EXPECT(MOTUS_ERROR_NULL_POINTER, "stepper without scratch", step_world(CAPACITY, DT));
            restore();
            W.stepper.method = MOTUS_METHOD_COUNT;
            EXPECT(MOTUS_ERROR_UNSUPPORTED, "corrupt method", step_world(CAPACITY, DT));
            restore();
            /* Forces the exact stepper cannot integrate. */
            if (m == MOTUS_EXACT_LINEAR_DRAG) {
                W.forces.quadratic_drag = 1;
                EXPECT(MOTUS_ERROR_UNSUPPORTED, "exact + quadratic drag", step_world(CAPACITY, DT));
                restore();
            }
        }
}

TEST(stepper_count_zero_steps_an_empty_world) {
    /* count 0: MOTUS_OK, particles untouched (may be NULL), the clock advances by dt and the stepper
       forgets its per-particle history, as for any change of count. */
    int pattern, m;
    for (pattern = 0; pattern < 2; ++pattern)
        for (m = 0; m < MOTUS_METHOD_COUNT; ++m) {
            motus_stepper expected;
            setup(PATTERNS[pattern], (motus_method)m);
            expected = W.stepper;
            expected.time += MOTUS_R(0.5);
            expected.history_count = m == MOTUS_POSITION_VERLET ? 0 : expected.history_count;
            expected.previous_dt = m == MOTUS_POSITION_VERLET ? MOTUS_R(0.5) : expected.previous_dt;
            expected.kept_acceleration_count =
                m == MOTUS_VELOCITY_VERLET || m == MOTUS_LEAPFROG ? 0 : expected.kept_acceleration_count;
            memcpy(&BEFORE, &W, sizeof W);
            if (m != MOTUS_EXACT_LINEAR_DRAG) /* springs need particles to hang on */
                ENSURE_EQ_INT(motus_stepper_step(&W.stepper, NULL, 0, &W.forces, MOTUS_R(0.5)), MOTUS_ERROR_INVALID_FORCES);
            W.forces.spring_count = 0;
            ENSURE_EQ_INT(motus_stepper_step(&W.stepper, NULL, 0, &W.forces, MOTUS_R(0.5)), MOTUS_OK);
            ENSURE(memcmp(BEFORE.particles, W.particles, sizeof W.particles) == 0);
            ENSURE(memcmp(BEFORE.scratch, W.scratch, sizeof W.scratch) == 0);
            ENSURE(memcmp(&expected, &W.stepper, sizeof expected) == 0);
        }
}

/* =================================================================================================
   Scenes and batches
   ================================================================================================= */
/* One thing wrong with W.scene or W.batch per case. */
static motus_result break_scene(int which, const char **what) {
    motus_scene *s = &W.scene;
    motus_batch *b = &W.batch;
    const int bad = which % BAD_REALS;
    switch (which / BAD_REALS) {
    case 0: *what = "gravity.x"; s->gravity[0] = bad_real(bad); return MOTUS_ERROR_NOT_FINITE;
    case 1: *what = "gravity.y"; s->gravity[1] = bad_real(bad); return MOTUS_ERROR_NOT_FINITE;
    case 2: *what = "linear_drag"; s->linear_drag = bad_real(bad); return MOTUS_ERROR_NOT_FINITE;
    case 3: *what = "quadratic_drag"; s->quadratic_drag = bad_real(bad); return MOTUS_ERROR_NOT_FINITE;
    case 4: *what = "attractor.x"; s->attractor[0] = bad_real(bad); return MOTUS_ERROR_NOT_FINITE;
    case 5: *what = "attractor.y"; s->attractor[1] = bad_real(bad); return MOTUS_ERROR_NOT_FINITE;
    case 6: *what = "attractor_strength"; s->attractor_strength = bad_real(bad); return MOTUS_ERROR_NOT_FINITE;
    case 7: *what = "bounds_min.y"; s->bounds_min[1] = bad_real(bad); return MOTUS_ERROR_NOT_FINITE;
    case 8: *what = "bounds_max.x"; s->bounds_max[0] = bad_real(bad); return MOTUS_ERROR_NOT_FINITE;
    case 9: *what = "restitution"; s->restitution = bad_real(bad); return MOTUS_ERROR_NOT_FINITE;
    case 10: *what = "damping (a fraction: NaN is out of range)"; s->damping = bad_real(bad); return MOTUS_ERROR_INVALID_DAMPING;
    case 11:
        *what = "uniform inverse_mass";
        s->has &= ~(unsigned)MOTUS_HAS_PARTICLE_MASS;
        s->inverse_mass = bad_real(bad);
        return MOTUS_ERROR_NOT_FINITE;
    default: break;
    }
    switch (which - 12 * BAD_REALS) {
    case 0: *what = "NULL x"; b->position[0] = NULL; return MOTUS_ERROR_NULL_POINTER;
    case 1: *what = "NULL y"; b->position[1] = NULL; return MOTUS_ERROR_NULL_POINTER;
    case 2: *what = "NULL vx"; b->velocity[0] = NULL; return MOTUS_ERROR_NULL_POINTER;
    case 3: *what = "NULL vy"; b->velocity[1] = NULL; return MOTUS_ERROR_NULL_POINTER;
    case 4: *what = "NULL fx"; b->force[0] = NULL; return MOTUS_ERROR_NULL_POINTER;
    case 5: *what = "NULL fy"; b->force[1] = NULL; return MOTUS_ERROR_NULL_POINTER;
    case 6: *what = "NULL inverse_mass"; b->inverse_mass = NULL; return MOTUS_ERROR_NULL_POINTER;
    case 7: *what = "3D without z arrays"; b->dimensions = 3; return MOTUS_ERROR_NULL_POINTER;
    case 8: *what = "dimensions 1"; b->dimensions = 1; return MOTUS_ERROR_INVALID_SCENE;
    case 9: *what = "dimensions 4"; b->dimensions = 4; return MOTUS_ERROR_INVALID_SCENE;
    case 10: *what = "dimensions INT_MIN"; b->dimensions = INT_MIN; return MOTUS_ERROR_INVALID_SCENE;
    case 11: *what = "unknown has bit"; s->has |= 1u << 20; return MOTUS_ERROR_INVALID_SCENE;
    case 12: *what = "both dampings"; s->has |= MOTUS_HAS_DAMPING_PER_SECOND; return MOTUS_ERROR_INVALID_SCENE;
    case 13: *what = "bounds min > max"; s->bounds_min[0] = 200; return MOTUS_ERROR_INVALID_SCENE;
    case 14: *what = "method RK4"; s->method = MOTUS_RK4; return MOTUS_ERROR_UNSUPPORTED;
    case 15: *what = "method -1"; s->method = (motus_method)-1; return MOTUS_ERROR_UNSUPPORTED;
    case 16: *what = "linear_drag < 0"; s->linear_drag = -1; return MOTUS_ERROR_INVALID_FORCES;
    case 17: *what = "quadratic_drag < 0"; s->quadratic_drag = -1; return MOTUS_ERROR_INVALID_FORCES;
    case 18: *what = "attractor_strength < 0"; s->attractor_strength = -1; return MOTUS_ERROR_INVALID_FORCES;
    case 19: *what = "damping < 0"; s->damping = MOTUS_R(-0.01); return MOTUS_ERROR_INVALID_DAMPING;
    case 20: *what = "damping > 1"; s->damping = MOTUS_R(1.01); return MOTUS_ERROR_INVALID_DAMPING;
    case 21: *what = "restitution > 1"; s->restitution = 2; return MOTUS_ERROR_INVALID_DAMPING;
    case 22:
        *what = "uniform inverse_mass < 0";
        s->has &= ~(unsigned)MOTUS_HAS_PARTICLE_MASS;
        s->inverse_mass = MOTUS_R(-0.5);
        return MOTUS_ERROR_INVALID_MASS;
    default: return MOTUS_RESULT_COUNT;
    }
}

TEST(scene_and_batch_reject_every_bad_scene) {
    /* The same broken scene gives the same result from every function that takes a scene, and none of
       them writes anything. */
    int pattern, which;
    for (pattern = 0; pattern < 2; ++pattern) {
        setup(PATTERNS[pattern], MOTUS_SEMI_IMPLICIT_EULER);
        EXPECT(MOTUS_ERROR_NULL_POINTER, "NULL scene", motus_scene_check(NULL, &W.batch));
        EXPECT(MOTUS_ERROR_NULL_POINTER, "NULL batch", motus_scene_check(&W.scene, NULL));
        EXPECT(MOTUS_ERROR_NULL_POINTER, "NULL scene", motus_batch_step(NULL, &W.batch, 0, BN, DT));
        EXPECT(MOTUS_ERROR_NULL_POINTER, "NULL batch", motus_batch_step(&W.scene, NULL, 0, BN, DT));
        EXPECT(MOTUS_ERROR_NULL_POINTER, "NULL scene", motus_batch_check(NULL, &W.batch, 0, BN, NULL, NULL));
        EXPECT(MOTUS_ERROR_NULL_POINTER, "NULL batch", motus_batch_check_report(&W.scene, NULL, 0, BN, &W.report));
        for (which = 0;; ++which) {
            const char *what = "";
            int index = -7;
            const char *field = "untouched";
            const motus_result expected = break_scene(which, &what);
            if (expected == MOTUS_RESULT_COUNT) break;
            EXPECT(expected, what, motus_scene_check(&W.scene, &W.batch));
            EXPECT(expected, what, motus_batch_step(&W.scene, &W.batch, 0, BN, DT));
            EXPECT(expected, what, motus_batch_step(&W.scene, &W.batch, 0, 0, DT));
            EXPECT(expected, what, motus_batch_check(&W.scene, &W.batch, 0, BN, &index, &field));
            ENSURE(index == -7 && strcmp(field, "untouched") == 0);
            EXPECT(expected, what, motus_batch_check_report(&W.scene, &W.batch, 0, BN, &W.report));
            ENSURE(W.report.index == -1 && W.report.field == MOTUS_FIELD_NONE);
            restore();
        }
    }
}

TEST(batch_rejects_bad_ranges_and_time_steps) {
    static const int ranges[][2] = {{-1, 1},      {INT_MIN, 1}, {0, -1},       {3, INT_MIN},
                                    {1, INT_MAX}, {INT_MAX, 1}, {INT_MAX, INT_MAX}, {-1, 0}};
    int pattern, r, b;
    for (pattern = 0; pattern < 2; ++pattern) {
        setup(PATTERNS[pattern], MOTUS_SEMI_IMPLICIT_EULER);
        for (r = 0; r < (int)(sizeof ranges / sizeof ranges[0]); ++r) {
            const int first = ranges[r][0], count = ranges[r][1];
            char what[64];
            sprintf(what, "first %d, count %d", first, count);
            EXPECT(MOTUS_ERROR_INVALID_COUNT, what, motus_batch_step(&W.scene, &W.batch, first, count, DT));
            EXPECT(MOTUS_ERROR_INVALID_COUNT, what, motus_batch_check(&W.scene, &W.batch, first, count, NULL, NULL));
            EXPECT(MOTUS_ERROR_INVALID_COUNT, what, motus_batch_check_report(&W.scene, &W.batch, first, count, &W.report));
            ENSURE(W.report.index == -1);
        }
        for (b = 0; b < BAD_DTS; ++b) {
            EXPECT(MOTUS_ERROR_INVALID_TIME_STEP, "bad dt", motus_batch_step(&W.scene, &W.batch, 0, BN, bad_dt(b)));
            EXPECT(MOTUS_ERROR_INVALID_TIME_STEP, "bad dt, empty range", motus_batch_step(&W.scene, &W.batch, 0, 0, bad_dt(b)));
        }
        /* Empty ranges are valid anywhere up to INT_MAX and write nothing. */
        EXPECT(MOTUS_OK, "empty", motus_batch_step(&W.scene, &W.batch, 0, 0, DT));
        EXPECT(MOTUS_OK, "empty at INT_MAX", motus_batch_step(&W.scene, &W.batch, INT_MAX, 0, DT));
        EXPECT(MOTUS_OK, "empty at INT_MAX", motus_batch_check(&W.scene, &W.batch, INT_MAX, 0, NULL, NULL));
    }
}

#ifndef MOTUS_CHECKED
/* The batch arrays a range [first, first + count) may write (release builds, bad data); nothing else. */
static int batch_outside_changed(int first, int count) {
    int a;
    if (memcmp(&BEFORE, &W, offsetof(world, arrays)) != 0) return 1;
    for (a = 0; a < BARRAYS; ++a) {
        const size_t size = sizeof(motus_real);
        if (memcmp(BEFORE.arrays[a], W.arrays[a], (size_t)(GUARD + first) * size) != 0 ||
            memcmp(BEFORE.arrays[a] + GUARD + first + count, W.arrays[a] + GUARD + first + count,
                   (size_t)(BSTRIDE - GUARD - first - count) * size) != 0)
            return 1;
    }
    return 0;
}
#endif

TEST(batch_bad_data) {
    /* A NaN, +Inf, -Inf in each array the scene reads, at a particle inside a range [5, 5 + 20), and a
       negative inverse mass. Checked build: the result of motus_batch_check, nothing written. Release:
       MOTUS_ERROR_NOT_FINITE with only the range written (a negative mass is not looked for). The
       report names the particle and the field either way. */
    static const motus_field fields[BARRAYS] = {MOTUS_FIELD_POSITION, MOTUS_FIELD_POSITION, MOTUS_FIELD_VELOCITY,
                                                MOTUS_FIELD_VELOCITY, MOTUS_FIELD_FORCE,    MOTUS_FIELD_FORCE,
                                                MOTUS_FIELD_INVERSE_MASS};
    const int first = 5, count = 20, at = 17;
    int pattern, a, b;
    for (pattern = 0; pattern < 2; ++pattern) {
        setup(PATTERNS[pattern], MOTUS_SEMI_IMPLICIT_EULER);
        for (a = 0; a < BARRAYS; ++a)
            for (b = 0; b <= BAD_REALS; ++b) {
                const int negative_mass = b == BAD_REALS;
                const motus_result expected = negative_mass ? MOTUS_ERROR_INVALID_MASS : MOTUS_ERROR_NOT_FINITE;
                int index = -1;
                const char *name = NULL;
                motus_result result;
                char what[64];
                if (negative_mass && a != BMASS) continue;
                barray(a)[at] = negative_mass ? MOTUS_R(-0.5) : bad_real(b);
                sprintf(what, "array %d [%d] = %g", a, at, (double)barray(a)[at]);
                EXPECT(expected, what, motus_batch_check(&W.scene, &W.batch, first, count, &index, &name));
                ENSURE_EQ_INT(index, at);
                EXPECT(expected, what, motus_batch_check_report(&W.scene, &W.batch, first, count, &W.report));
                ENSURE_EQ_INT(W.report.index, at);
                ENSURE_EQ_INT(W.report.field, fields[a]);
                ENSURE_EQ_INT(W.report.component, a == BMASS ? -1 : a % 2);
                ENSURE(name && strcmp(W.report.field_name, name) == 0);
                /* A range that does not hold the bad particle is fine. */
                EXPECT(MOTUS_OK, what, motus_batch_check_report(&W.scene, &W.batch, at + 1, BN - at - 1, &W.report));
                ENSURE(W.report.index == -1 && strcmp(W.report.field_name, "none") == 0);
#ifdef MOTUS_CHECKED
                EXPECT(expected, what, motus_batch_step(&W.scene, &W.batch, first, count, DT));
#else
                memcpy(&BEFORE, &W, sizeof W);
                result = motus_batch_step(&W.scene, &W.batch, first, count, DT);
                ENSURE_EQ_INT(result, negative_mass ? MOTUS_OK : MOTUS_ERROR_NOT_FINITE);
                ENSURE(!batch_outside_changed(first, count));
#endif
                (void)result;
                restore();
            }
    }
}

TEST(add_spring_forces_rejects_everything_bad) {
    int pattern, which, b, end;
    for (pattern = 0; pattern < 2; ++pattern) {
        setup(PATTERNS[pattern], MOTUS_SEMI_IMPLICIT_EULER);
        EXPECT(MOTUS_ERROR_NULL_POINTER, "NULL batch", motus_batch_add_spring_forces(NULL, BN, W.springs, SPRINGS));
        EXPECT(MOTUS_ERROR_INVALID_COUNT, "count -1", motus_batch_add_spring_forces(&W.batch, -1, W.springs, SPRINGS));
        EXPECT(MOTUS_ERROR_INVALID_COUNT, "count INT_MIN", motus_batch_add_spring_forces(&W.batch, INT_MIN, W.springs, 0));
        /* The force model's spring cases (the others do not apply: no gravity, drags or attractor here). */
        for (which = 7 * BAD_REALS;; ++which) {
            const char *what = "";
            int count = BN, spring_count = SPRINGS;
            const motus_spring *springs = W.springs;
            motus_result expected = break_forces(which, &count, &what);
            if (expected == MOTUS_RESULT_COUNT) break;
            if (which >= 12 * BAD_REALS && which < 12 * BAD_REALS + 3) { /* model-level terms */
                restore();
                continue;
            }
            if (W.forces.spring_count != SPRINGS) spring_count = W.forces.spring_count;
            if (W.forces.springs == NULL) springs = NULL;
            if (W.springs[0].a == CAPACITY) W.springs[0].a = BN; /* "a = count" for this batch's count */
            if (W.springs[0].b == CAPACITY) W.springs[0].b = BN;
            EXPECT(expected, what, motus_batch_add_spring_forces(&W.batch, count, springs, spring_count));
            restore();
        }
        W.batch.dimensions = 3;
        EXPECT(MOTUS_ERROR_UNSUPPORTED, "3D", motus_batch_add_spring_forces(&W.batch, BN, W.springs, SPRINGS));
        W.batch.dimensions = 5;
        EXPECT(MOTUS_ERROR_INVALID_SCENE, "dimensions 5", motus_batch_add_spring_forces(&W.batch, BN, W.springs, SPRINGS));
        W.batch.dimensions = 0;
        EXPECT(MOTUS_ERROR_INVALID_SCENE, "dimensions 0", motus_batch_add_spring_forces(&W.batch, BN, W.springs, SPRINGS));
        restore();
        W.batch.velocity[1] = NULL;
        EXPECT(MOTUS_ERROR_NULL_POINTER, "NULL vy", motus_batch_add_spring_forces(&W.batch, BN, W.springs, SPRINGS));
        restore();
        /* No springs: nothing is read, nothing needed. count 0 with springs: every end is out of range. */
        W.batch.position[0] = NULL;
        EXPECT(MOTUS_OK, "no springs", motus_batch_add_spring_forces(&W.batch, BN, NULL, 0));
        restore();
        EXPECT(MOTUS_ERROR_INVALID_FORCES, "count 0", motus_batch_add_spring_forces(&W.batch, 0, W.springs, SPRINGS));
        /* Bad data at a spring's end: a position, a velocity (with spring damping) or an end's force. */
        for (end = 0; end < 6; ++end)
            for (b = 0; b < BAD_REALS; ++b) {
                const int arrays[6] = {BX, BY, BVX, BVY, BFX, BFY};
                barray(arrays[end])[1] = bad_real(b); /* particle 1: end b of spring 0, which has damping */
#ifdef MOTUS_CHECKED
                EXPECT(MOTUS_ERROR_NOT_FINITE, "bad end", motus_batch_add_spring_forces(&W.batch, BN, W.springs, SPRINGS));
#else
                memcpy(&BEFORE, &W, sizeof W);
                ENSURE_EQ_INT(motus_batch_add_spring_forces(&W.batch, BN, W.springs, SPRINGS), MOTUS_ERROR_NOT_FINITE);
                ENSURE(memcmp(BEFORE.arrays, W.arrays, sizeof(motus_real) * BSTRIDE * BFX) == 0); /* x, v kept */
#endif
                restore();
            }
        /* Finite ends whose sum overflows. */
        barray(BFX)[0] = REAL_MAX;
        W.springs[0].stiffness = REAL_MAX;
        barray(BX)[0] = REAL_MAX / 2;
#ifdef MOTUS_CHECKED
        EXPECT(MOTUS_ERROR_NOT_FINITE, "overflow", motus_batch_add_spring_forces(&W.batch, BN, W.springs, SPRINGS));
#else
        ENSURE_EQ_INT(motus_batch_add_spring_forces(&W.batch, BN, W.springs, SPRINGS), MOTUS_ERROR_NOT_FINITE);
#endif
        restore();
    }
}

/* =================================================================================================
   motus_particles_check and the messages
   ================================================================================================= */
TEST(particles_check_finds_the_first_bad_particle_and_field) {
    int pattern, i, k, b;
    for (pattern = 0; pattern < 2; ++pattern) {
        setup(PATTERNS[pattern], MOTUS_SEMI_IMPLICIT_EULER);
        EXPECT(MOTUS_OK, "valid", motus_particles_check(W.particles, CAPACITY, &W.report));
        ENSURE(W.report.index == -1 && W.report.field == MOTUS_FIELD_NONE && W.report.component == -1);
        ENSURE(strcmp(W.report.field_name, "none") == 0);
        EXPECT(MOTUS_OK, "no report", motus_particles_check(W.particles, CAPACITY, NULL));
        /* count 0: valid, nothing read (NULL is fine). */
        EXPECT(MOTUS_OK, "count 0", motus_particles_check(NULL, 0, &W.report));
        EXPECT(MOTUS_ERROR_NULL_POINTER, "NULL", motus_particles_check(NULL, 1, &W.report));
        ENSURE(W.report.index == -1 && W.report.field_name != NULL); /* filled even then */
        EXPECT(MOTUS_ERROR_INVALID_COUNT, "count -1", motus_particles_check(W.particles, -1, &W.report));
        EXPECT(MOTUS_ERROR_INVALID_COUNT, "count INT_MIN", motus_particles_check(W.particles, INT_MIN, NULL));
        for (i = 0; i < CAPACITY; ++i)
            for (k = 0; k < 7; ++k)
                for (b = 0; b <= BAD_REALS; ++b) {
                    static const motus_field fields[7] = {MOTUS_FIELD_POSITION, MOTUS_FIELD_POSITION,
                                                          MOTUS_FIELD_VELOCITY, MOTUS_FIELD_VELOCITY,
                                                          MOTUS_FIELD_FORCE,    MOTUS_FIELD_FORCE,
                                                          MOTUS_FIELD_INVERSE_MASS};
                    motus_result expected;
                    if (b == BAD_REALS && k != 6) continue;
                    *particle_field(&W.particles[i], k) = b == BAD_REALS ? MOTUS_R(-0.5) : bad_real(b);
                    expected = motus_particle_check(&W.particles[i]);
                    ENSURE(expected != MOTUS_OK);
                    /* A later particle with another bad field does not hide the first. */
                    if (i + 1 < CAPACITY) W.particles[i + 1].position.x = not_a_number();
                    EXPECT(expected, FIELD_NAMES[k], motus_particles_check(W.particles, CAPACITY, &W.report));
                    ENSURE_EQ_INT(W.report.index, i);
                    ENSURE_EQ_INT(W.report.field, fields[k]);
                    ENSURE_EQ_INT(W.report.component, k == 6 ? -1 : k % 2);
                    ENSURE(strcmp(W.report.field_name, motus_field_name(fields[k])) == 0);
                    /* The range before it is fine. */
                    EXPECT(MOTUS_OK, FIELD_NAMES[k], motus_particles_check(W.particles, i, &W.report));
                    restore();
                }
        /* Two bad fields in one particle: the first in the documented order. */
        W.particles[2].inverse_mass = -1;
        W.particles[2].force.y = infinity();
        W.particles[2].velocity.y = not_a_number();
        EXPECT(MOTUS_ERROR_NOT_FINITE, "velocity before force and mass", motus_particles_check(W.particles, CAPACITY, &W.report));
        ENSURE(W.report.index == 2 && W.report.field == MOTUS_FIELD_VELOCITY && W.report.component == 1);
        restore();
    }
}

TEST(field_names_and_messages) {
    int i, j;
    ENSURE(strcmp(motus_field_name(MOTUS_FIELD_POSITION), "position") == 0);
    ENSURE(strcmp(motus_field_name(MOTUS_FIELD_INVERSE_MASS), "inverse_mass") == 0);
    ENSURE(motus_field_name(MOTUS_FIELD_COUNT) == NULL);
    ENSURE(motus_field_name((motus_field)-1) == NULL);
    for (i = 0; i < MOTUS_FIELD_COUNT; ++i) ENSURE(motus_field_name((motus_field)i) != NULL);
    /* Every code has its own sentence, long enough to say what was wrong and what is expected. */
    for (i = 1; i < MOTUS_RESULT_COUNT; ++i) {
        const char *message = motus_result_string((motus_result)i);
        ENSURE(message != NULL && strlen(message) >= 40);
        for (j = 0; j < i; ++j) ENSURE(strcmp(message, motus_result_string((motus_result)j)) != 0);
    }
    ENSURE(strcmp(motus_result_string((motus_result)-1), "unknown motus_result value") == 0);
    ENSURE(strcmp(motus_result_string(MOTUS_RESULT_COUNT), "unknown motus_result value") == 0);
}

static const motus_test_case TESTS[] = {
    TEST_CASE(particle_init_rejects_everything_bad),
    TEST_CASE(particle_check_and_forces_reject_everything_bad),
    TEST_CASE(particle_steps_reject_everything_bad),
    TEST_CASE(forces_check_rejects_everything_bad),
    TEST_CASE(method_queries_and_scratch_size_reject_bad_values),
    TEST_CASE(stepper_init_rejects_everything_bad),
    TEST_CASE(stepper_step_rejects_everything_bad),
    TEST_CASE(stepper_count_zero_steps_an_empty_world),
    TEST_CASE(scene_and_batch_reject_every_bad_scene),
    TEST_CASE(batch_rejects_bad_ranges_and_time_steps),
    TEST_CASE(batch_bad_data),
    TEST_CASE(add_spring_forces_rejects_everything_bad),
    TEST_CASE(particles_check_finds_the_first_bad_particle_and_field),
    TEST_CASE(field_names_and_messages),
};

int main(int argc, char **argv) { return motus_test_main(argc, argv, TESTS, TEST_COUNT(TESTS)); }
