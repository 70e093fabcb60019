/* Bad input everywhere, byte for byte: every public function of motus.h given every bad input it can get
   (NaN, +Inf, -Inf in each real, -0 where it matters, zero and negative masses, dt < 0 or not finite, NULL
   pointers, counts < 0 and INT_MAX, ranges past INT_MAX, negative strides, aliased arrays, scratch too
   small or misaligned, every broken scene field), each call asserted for its result code and for the whole
   world (2D and 3D particles, carries, springs, scene, state and its arrays with guards, scratch, clock,
   outputs) being byte for byte what it was, and the force callback not called.
   The world is one struct filled with a byte pattern first, then with valid values where a valid value is
   needed, so padding, unused arrays and the unused tail of the scratch are compared too.
   motus_step on bad particle data: release builds write and return MOTUS_ERROR_NOT_FINITE (documented),
   so only the code is asserted; MOTUS_CHECKED builds (input_checked.*) find the data first and write
   nothing. Also motus_state_check / motus_particles_check / motus_particles3_check (the first bad particle,
   field and component) and the messages. Built in float and double, and with MOTUS_CHECKED. */
#define MOTUS_IMPLEMENTATION
#include "motus.h"
#include "support/motus_test.h"

#include <float.h>
#include <limits.h>
#include <stddef.h>
#include <stdint.h>

#ifdef MOTUS_DOUBLE
#define REAL_MAX DBL_MAX
#define REAL_MIN_NORMAL DBL_MIN
#define REAL_TRUE_MIN 4.9406564584124654e-324
#else
#define REAL_MAX FLT_MAX
#define REAL_MIN_NORMAL FLT_MIN
#define REAL_TRUE_MIN 1.40129846e-45f
#endif

enum { CAPACITY = 5, SPRINGS = 3, BN = 37, GUARD = 8, BSTRIDE = GUARD + BN + GUARD };
enum { BX = 0, BY, BZ, BVX, BVY, BVZ, BFX, BFY, BFZ, BMASS, BARRAYS };
#ifdef MOTUS_CHECKED /* checked builds step coupled scenes on a copy of the state in scratch */
#define CHECKED_COPY_REALS (3 * 3 + 1)
#else
#define CHECKED_COPY_REALS 0
#endif
/* the coupled stage arrays are rounded up to whole groups of lanes (at most 16) */
enum { SCRATCH_REALS = (3 * (2 + MOTUS__MAX_EVALUATIONS) + CHECKED_COPY_REALS) * (BN + 16) + 64 };

static const motus_real DT = (motus_real)(1.0 / 60.0);
static motus_real not_a_number(void) { return (motus_real)NAN; }
static motus_real infinity(void) { return (motus_real)HUGE_VAL; }
static motus_real negative_zero(void) { return -(motus_real)0; }
/* The non-finite values every real input is tried with. */
static motus_real bad_real(int which) { return which == 0 ? not_a_number() : which == 1 ? infinity() : -infinity(); }
enum { BAD_REALS = 3 };

/* Everything a call could write. Pointers inside (scene.springs, state arrays) point into the one global
   instance W, so a byte copy restores it exactly. The report comes last: the check functions write it
   whatever they return, so the state compared is everything before it. */
typedef struct world {
    motus_particle particles[CAPACITY];
    motus_particle3 particles3[CAPACITY];
    motus_vec2 carry;
    motus_vec3 carry3;
    motus_spring springs[SPRINGS];
    motus_scene scene;
    motus_state state;
    motus_real arrays[BARRAYS][BSTRIDE];
    motus_real scratch[SCRATCH_REALS];
    motus_clock clock;
    motus_real max_dt;
    int substeps;
    motus_check_report report;
} world;

static world W, CLEAN, BEFORE;
static const unsigned char PATTERNS[2] = {0xA5, 0x5A};
static unsigned long CALLBACK_CALLS;

static motus_real *barray(int which) { return W.arrays[which] + GUARD; }

/* Pulls every particle towards the origin: a callback that the scene calls at every stage. */
static void world_callback(void *user_data, const motus_force_query *query) {
    int d, i;
    (void)user_data;
    ++CALLBACK_CALLS;
    for (d = 0; d < query->dimensions; ++d)
        for (i = 0; i < query->count; ++i) query->force[d][i] += MOTUS_R(-0.5) * query->position[d][i];
}

/* A scene with every term, springs and the callback, for `method` (the exact stepper takes only gravity,
   linear drag, damping and bounds). */
static void setup_scene(motus_method method) {
    motus_scene *s = &W.scene;
    memset(s, 0, sizeof *s);
    memset(W.springs, 0, sizeof W.springs);
    W.springs[0].a = 0, W.springs[0].b = 1, W.springs[0].rest_length = 1, W.springs[0].stiffness = 20;
    W.springs[0].damping = MOTUS_R(0.5);
    W.springs[1].a = 2, W.springs[1].b = -1, W.springs[1].anchor = motus_v3(4, 4, 4), W.springs[1].stiffness = 10;
    W.springs[2].a = BN - 1, W.springs[2].b = BN - 2, W.springs[2].rest_length = 2, W.springs[2].stiffness = 5;
    s->method = method;
    s->gravity = motus_v3(0, MOTUS_R(-9.81), 1);
    s->linear_drag = MOTUS_R(0.25);
    s->damping_per_step = MOTUS_R(0.01);
    s->bounds_min = motus_v3(-100, -100, -100);
    s->bounds_max = motus_v3(100, 100, 100);
    s->restitution = MOTUS_R(0.5);
    if (method == MOTUS_EXACT_LINEAR_DRAG) return;
    s->quadratic_drag = MOTUS_R(0.01);
    s->attractor = motus_v3(3, 0, -1);
    s->attractor_strength = 2;
    s->tether = motus_v3(-1, 2, MOTUS_R(0.5));
    s->tether_stiffness = MOTUS_R(1.5);
    s->springs = W.springs;
    s->spring_count = SPRINGS;
    s->force_callback = world_callback;
}
static void uncouple(void) {
    W.scene.springs = NULL;
    W.scene.spring_count = 0;
    W.scene.force_callback = NULL;
}

/* The pattern everywhere, then: four free particles and an immovable one in 2D and 3D, the scene, a 3D
   state of BN particles over guarded arrays, a clock. */
static void setup(unsigned char pattern, motus_method method) {
    int i, d;
    memset(&W, pattern, sizeof W);
    for (i = 0; i < CAPACITY; ++i) {
        motus_particle *p = &W.particles[i];
        motus_particle3 *q = &W.particles3[i];
        p->position = motus_v2(MOTUS_R(1.5) * (motus_real)i - 2, MOTUS_R(0.75) * (motus_real)i + 1);
        p->velocity = motus_v2((motus_real)(i % 3) - 1, MOTUS_R(0.5) - (motus_real)i);
        p->force = motus_v2(MOTUS_R(0.25) * (motus_real)i + 1, -MOTUS_R(0.125) * (motus_real)i);
        p->inverse_mass = i == CAPACITY - 1 ? 0 : MOTUS_R(1.0) / (motus_real)(i + 1);
        q->position = motus_v3(p->position.x, p->position.y, (motus_real)i - 3);
        q->velocity = motus_v3(p->velocity.x, p->velocity.y, MOTUS_R(0.25) * (motus_real)i);
        q->force = motus_v3(p->force.x, p->force.y, 2);
        q->inverse_mass = p->inverse_mass;
    }
    W.carry = motus_v2(MOTUS_R(1e-3), MOTUS_R(-2e-3));
    W.carry3 = motus_v3(MOTUS_R(1e-3), 0, MOTUS_R(-2e-3));
    setup_scene(method);
    memset(&W.state, 0, sizeof W.state);
    W.state.dimensions = 3;
    W.state.count = BN;
    for (d = 0; d < 3; ++d) {
        W.state.position[d] = barray(BX + d);
        W.state.velocity[d] = barray(BVX + d);
        W.state.force[d] = barray(BFX + d);
    }
    W.state.inverse_mass = barray(BMASS);
    for (i = 0; i < BN; ++i) {
        barray(BX)[i] = (motus_real)(i % 11) * 7 - 35, barray(BY)[i] = (motus_real)(i % 7) * 9 - 30;
        barray(BZ)[i] = (motus_real)(i % 5) * 3 - 7;
        barray(BVX)[i] = (motus_real)(i % 5) - 2, barray(BVY)[i] = MOTUS_R(0.5) * (motus_real)(i % 3);
        barray(BVZ)[i] = MOTUS_R(-0.25) * (motus_real)(i % 4);
        barray(BFX)[i] = MOTUS_R(0.125) * (motus_real)i, barray(BFY)[i] = -1, barray(BFZ)[i] = 3;
        barray(BMASS)[i] = i % 9 == 4 ? 0 : MOTUS_R(1.0) / (motus_real)(1 + i % 4);
    }
    ENSURE_EQ_INT(motus_clock_init(&W.clock, DT, 4), MOTUS_OK);
    W.max_dt = MOTUS_R(-7.0);
    W.substeps = -7;
    memcpy(&CLEAN, &W, sizeof W);
}
static void restore(void) { memcpy(&W, &CLEAN, sizeof W); }

/* ---- the one assertion: result code, the world byte for byte, no callback --------------------------------- */
static int state_changed(void) { return memcmp(&BEFORE, &W, offsetof(world, report)) != 0; }

static void expect_at(motus_result got, motus_result expected, unsigned long calls, const char *call,
                      const char *what, int line) {
    const int changed = state_changed(), called = CALLBACK_CALLS != calls;
    if (got != expected || changed || called) {
        fprintf(stderr, "%s:%d: %s [%s] (%s): ", __FILE__, line, call, what,
                motus_method_name(W.scene.method) ? motus_method_name(W.scene.method) : "?");
        if (got != expected)
            fprintf(stderr, "gave %d (%s), expected %d (%s)", (int)got, motus_result_string(got), (int)expected,
                    motus_result_string(expected));
        if (changed) fprintf(stderr, "%sthe world changed", got != expected ? "; " : "");
        if (called) fprintf(stderr, "; the callback was called");
        fprintf(stderr, "\n");
        motus_test_failures++;
    }
}
/* Snapshot, call, then the code and every byte of the world. `what` names the case in a message. */
#define EXPECT(expected, what, call)                                                                          \
    do {                                                                                                      \
        motus_result expect_result_;                                                                          \
        unsigned long expect_calls_ = CALLBACK_CALLS;                                                         \
        memcpy(&BEFORE, &W, sizeof W);                                                                        \
        expect_result_ = (call);                                                                              \
        expect_at(expect_result_, expected, expect_calls_, #call, what, __LINE__);                            \
    } while (0)

/* The reals of a particle, by number: 2D has 7 (x y, vx vy, fx fy, inverse mass), 3D has 10. */
static motus_real *field_of(int dims, int index, int k) {
    return dims == 2 ? &W.particles[index].position.x + k : &W.particles3[index].position.x + k;
}
static int field_count(int dims) { return 3 * dims + 1; }
static motus_field field_kind(int dims, int k) {
    return k == 3 * dims ? MOTUS_FIELD_INVERSE_MASS : (motus_field)(MOTUS_FIELD_POSITION + k / dims);
}
/* The time steps every stepping function must refuse. */
static motus_real bad_dt(int which) {
    switch (which) {
    case 0: return -DT;
    case 1: return -REAL_MAX;
    case 2: return -REAL_TRUE_MIN;
    default: return bad_real(which - 3);
    }
}
enum { BAD_DTS = 3 + BAD_REALS };

/* =================================================================================================
   Particle functions, 2D and 3D
   ================================================================================================= */
TEST(particle_init_rejects_everything_bad) {
    int pattern, b;
    for (pattern = 0; pattern < 2; ++pattern) {
        motus_particle *p = &W.particles[1];
        motus_particle3 *q = &W.particles3[1];
        setup(PATTERNS[pattern], MOTUS_SEMI_IMPLICIT_EULER);
        EXPECT(MOTUS_ERROR_NULL_POINTER, "NULL", motus_particle_init(NULL, motus_v2(1, 2), 1));
        EXPECT(MOTUS_ERROR_NULL_POINTER, "NULL", motus_particle_init_immovable(NULL, motus_v2(1, 2)));
        EXPECT(MOTUS_ERROR_NULL_POINTER, "NULL", motus_particle3_init(NULL, motus_v3(1, 2, 3), 1));
        EXPECT(MOTUS_ERROR_NULL_POINTER, "NULL", motus_particle3_init_immovable(NULL, motus_v3(1, 2, 3)));
        for (b = 0; b < BAD_REALS; ++b) {
            EXPECT(MOTUS_ERROR_NOT_FINITE, "x", motus_particle_init(p, motus_v2(bad_real(b), 2), 1));
            EXPECT(MOTUS_ERROR_NOT_FINITE, "y", motus_particle_init(p, motus_v2(1, bad_real(b)), 1));
            EXPECT(MOTUS_ERROR_NOT_FINITE, "mass", motus_particle_init(p, motus_v2(1, 2), bad_real(b)));
            EXPECT(MOTUS_ERROR_NOT_FINITE, "x", motus_particle_init_immovable(p, motus_v2(bad_real(b), 2)));
            EXPECT(MOTUS_ERROR_NOT_FINITE, "y", motus_particle_init_immovable(p, motus_v2(1, bad_real(b))));
            EXPECT(MOTUS_ERROR_NOT_FINITE, "z", motus_particle3_init(q, motus_v3(1, 2, bad_real(b)), 1));
            EXPECT(MOTUS_ERROR_NOT_FINITE, "mass", motus_particle3_init(q, motus_v3(1, 2, 3), bad_real(b)));
            EXPECT(MOTUS_ERROR_NOT_FINITE, "z", motus_particle3_init_immovable(q, motus_v3(1, 2, bad_real(b))));
        }
        /* Non-finite before the mass's range: NaN position with mass 0 is NOT_FINITE. */
        EXPECT(MOTUS_ERROR_NOT_FINITE, "NaN x, mass 0", motus_particle_init(p, motus_v2(not_a_number(), 0), 0));
        EXPECT(MOTUS_ERROR_INVALID_MASS, "mass 0", motus_particle_init(p, motus_v2(1, 2), 0));
        EXPECT(MOTUS_ERROR_INVALID_MASS, "mass -0", motus_particle_init(p, motus_v2(1, 2), negative_zero()));
        EXPECT(MOTUS_ERROR_INVALID_MASS, "mass -0", motus_particle3_init(q, motus_v3(1, 2, 3), negative_zero()));
        EXPECT(MOTUS_ERROR_INVALID_MASS, "mass -1", motus_particle_init(p, motus_v2(1, 2), -1));
        EXPECT(MOTUS_ERROR_INVALID_MASS, "mass -max", motus_particle3_init(q, motus_v3(1, 2, 3), -REAL_MAX));
        EXPECT(MOTUS_ERROR_INVALID_MASS, "1/mass overflows",
               motus_particle_init(p, motus_v2(1, 2), REAL_MIN_NORMAL / 1024));
        EXPECT(MOTUS_ERROR_INVALID_MASS, "1/mass overflows",
               motus_particle3_init(q, motus_v3(1, 2, 3), REAL_TRUE_MIN));
        /* The extremes that are fine: the largest mass (1/m subnormal, not 0) and the smallest normal one. */
        ENSURE_EQ_INT(motus_particle_init(p, motus_v2(1, 2), REAL_MAX), MOTUS_OK);
        ENSURE(p->inverse_mass > 0);
        ENSURE_EQ_INT(motus_particle3_init(q, motus_v3(1, 2, 3), REAL_MIN_NORMAL), MOTUS_OK);
        ENSURE_NEAR(motus_particle3_mass(q), REAL_MIN_NORMAL, 0); /* 1/2^-126 (2^-1022) is exact both ways */
        ENSURE(motus_particle_mass(NULL) != motus_particle_mass(NULL));
    }
}

/* The particle functions with a particle argument, by number. */
enum { F_STEP, F_COMPENSATED, F_DAMP_STEP, F_DAMP_SECOND, F_BOUNCE, F_ADD_FORCE, F_CHECK, F_CLEAR, PARTICLE_FUNCTIONS };
static const char *const PARTICLE_FUNCTION_NAMES[PARTICLE_FUNCTIONS] = {
    "step", "step_compensated", "damp_per_step", "damp_per_second", "bounce", "add_force", "check", "clear_forces"};
/* Which field groups each reads: 1 position, 2 velocity, 4 force, 8 inverse mass. */
static const int READS[PARTICLE_FUNCTIONS] = {15, 15, 2, 2, 3, 4, 15, 0};
static const int HAS_DT[PARTICLE_FUNCTIONS] = {1, 1, 0, 1, 0, 0, 0, 0};
static int group_of(int dims, int k) { return k == 3 * dims ? 8 : 1 << (k / dims); }

/* Calls function f in 2D or 3D on particle `index` (-1: NULL) with dt and a parameter (a damping, a
   restitution, a force component). */
static motus_result call_particle_function(int f, int dims, int index, motus_real dt, motus_real parameter) {
    if (dims == 2) {
        motus_particle *p = index < 0 ? NULL : &W.particles[index];
        switch (f) {
        case F_STEP: return motus_particle_step(p, dt);
        case F_COMPENSATED: return motus_particle_step_compensated(p, &W.carry, dt);
        case F_DAMP_STEP: return motus_particle_damp_per_step(p, parameter);
        case F_DAMP_SECOND: return motus_particle_damp_per_second(p, parameter, dt);
        case F_BOUNCE: return motus_particle_bounce(p, motus_v2(-100, -100), motus_v2(100, 100), parameter);
        case F_ADD_FORCE: return motus_particle_add_force(p, motus_v2(parameter, 1));
        case F_CHECK: return motus_particle_check(p);
        default: return motus_particle_clear_forces(p);
        }
    } else {
        motus_particle3 *p = index < 0 ? NULL : &W.particles3[index];
        switch (f) {
        case F_STEP: return motus_particle3_step(p, dt);
        case F_COMPENSATED: return motus_particle3_step_compensated(p, &W.carry3, dt);
        case F_DAMP_STEP: return motus_particle3_damp_per_step(p, parameter);
        case F_DAMP_SECOND: return motus_particle3_damp_per_second(p, parameter, dt);
        case F_BOUNCE: return motus_particle3_bounce(p, motus_v3(-100, -100, -100), motus_v3(100, 100, 100), parameter);
        case F_ADD_FORCE: return motus_particle3_add_force(p, motus_v3(1, 1, parameter));
        case F_CHECK: return motus_particle3_check(p);
        default: return motus_particle3_clear_forces(p);
        }
    }
}

TEST(particle_functions_reject_everything_bad) {
    int pattern, f, k, b, dims;
    const motus_real good = MOTUS_R(0.5);
    for (pattern = 0; pattern < 2; ++pattern)
        for (dims = 2; dims <= 3; ++dims)
            for (f = 0; f < PARTICLE_FUNCTIONS; ++f) {
                char what[96];
                sprintf(what, "%dD %s", dims, PARTICLE_FUNCTION_NAMES[f]);
                setup(PATTERNS[pattern], MOTUS_SEMI_IMPLICIT_EULER);
                EXPECT(MOTUS_ERROR_NULL_POINTER, what, call_particle_function(f, dims, -1, DT, good));
                if (HAS_DT[f]) {
                    for (b = 0; b < BAD_DTS; ++b)
                        EXPECT(MOTUS_ERROR_INVALID_TIME_STEP, what, call_particle_function(f, dims, 1, bad_dt(b), good));
                    /* dt 0 and -0: a valid step of nothing. */
                    EXPECT(MOTUS_OK, what, call_particle_function(f, dims, 1, 0, good));
                    EXPECT(MOTUS_OK, what, call_particle_function(f, dims, 1, negative_zero(), good));
                }
                /* Each field it reads, not finite; fields it does not read are left to the functions that do. */
                for (k = 0; k < field_count(dims); ++k)
                    for (b = 0; b < BAD_REALS; ++b) {
                        const int mass = k == 3 * dims;
                        *field_of(dims, 1, k) = bad_real(b);
                        sprintf(what, "%dD %s, field %d = %g", dims, PARTICLE_FUNCTION_NAMES[f], k, (double)bad_real(b));
                        if (READS[f] & group_of(dims, k))
                            EXPECT(mass && b == 2 && f <= F_COMPENSATED ? MOTUS_ERROR_INVALID_MASS : MOTUS_ERROR_NOT_FINITE,
                                   what, call_particle_function(f, dims, 1, DT, good));
                        else
                            ENSURE_EQ_INT(call_particle_function(f, dims, 1, DT, good), MOTUS_OK);
                        restore();
                    }
                /* The parameter: a damping fraction, a restitution, a force. */
                sprintf(what, "%dD %s, parameter", dims, PARTICLE_FUNCTION_NAMES[f]);
                if (f == F_DAMP_STEP || f == F_DAMP_SECOND) {
                    for (b = 0; b < BAD_REALS; ++b)
                        EXPECT(MOTUS_ERROR_INVALID_DAMPING, what, call_particle_function(f, dims, 1, DT, bad_real(b)));
                    EXPECT(MOTUS_ERROR_INVALID_DAMPING, what, call_particle_function(f, dims, 1, DT, MOTUS_R(-0.25)));
                    EXPECT(MOTUS_ERROR_INVALID_DAMPING, what, call_particle_function(f, dims, 1, DT, -REAL_TRUE_MIN));
                    EXPECT(MOTUS_ERROR_INVALID_DAMPING, what, call_particle_function(f, dims, 1, DT, MOTUS_R(1.25)));
                    ENSURE_EQ_INT(call_particle_function(f, dims, 1, DT, negative_zero()), MOTUS_OK); /* -0 is 0 */
                } else if (f == F_BOUNCE) {
                    for (b = 0; b < BAD_REALS; ++b)
                        EXPECT(MOTUS_ERROR_NOT_FINITE, what, call_particle_function(f, dims, 1, DT, bad_real(b)));
                    EXPECT(MOTUS_ERROR_INVALID_RESTITUTION, what, call_particle_function(f, dims, 1, DT, MOTUS_R(-0.25)));
                    EXPECT(MOTUS_ERROR_INVALID_RESTITUTION, what, call_particle_function(f, dims, 1, DT, MOTUS_R(1.25)));
                } else if (f == F_ADD_FORCE) {
                    for (b = 0; b < BAD_REALS; ++b)
                        EXPECT(MOTUS_ERROR_NOT_FINITE, what, call_particle_function(f, dims, 1, DT, bad_real(b)));
                    /* The component the parameter is added to: force.x in 2D, force.z in 3D. */
                    *field_of(dims, 1, dims == 2 ? 2 * dims : 3 * dims - 1) = -REAL_MAX;
                    EXPECT(MOTUS_ERROR_OVERFLOW, what, call_particle_function(f, dims, 1, DT, -REAL_MAX));
                    restore();
                }
                if (f == F_STEP || f == F_COMPENSATED || f == F_CHECK) {
                    /* A negative mass; -0 is not negative (immovable). */
                    *field_of(dims, 1, 3 * dims) = MOTUS_R(-0.5);
                    EXPECT(MOTUS_ERROR_INVALID_MASS, "inverse mass < 0", call_particle_function(f, dims, 1, DT, good));
                    *field_of(dims, 1, 3 * dims) = negative_zero();
                    ENSURE_EQ_INT(call_particle_function(f, dims, 1, DT, good), MOTUS_OK);
                    restore();
                }
                if (f == F_STEP || f == F_COMPENSATED) {
                    /* Finite inputs, a result past the largest real: the position, then the velocity. */
                    *field_of(dims, 1, 0) = *field_of(dims, 1, dims) = REAL_MAX / 2;
                    EXPECT(MOTUS_ERROR_OVERFLOW, "position overflow", call_particle_function(f, dims, 1, 4, good));
                    restore();
                    *field_of(dims, 1, 3 * dims - 1) = -REAL_MAX;
                    EXPECT(MOTUS_ERROR_OVERFLOW, "velocity overflow", call_particle_function(f, dims, 1, 8, good));
                    restore();
                }
                if (f == F_COMPENSATED) { /* a bad carry */
                    for (b = 0; b < BAD_REALS; ++b) {
                        W.carry.y = bad_real(b), W.carry3.z = bad_real(b);
                        EXPECT(MOTUS_ERROR_NOT_FINITE, "carry", call_particle_function(f, dims, 1, DT, good));
                        restore();
                    }
                    EXPECT(MOTUS_ERROR_NULL_POINTER, "NULL carry",
                           dims == 2 ? motus_particle_step_compensated(&W.particles[1], NULL, DT)
                                     : motus_particle3_step_compensated(&W.particles3[1], NULL, DT));
                }
            }
}

TEST(particle_bounce_rejects_bad_boxes) {
    int b, pattern;
    for (pattern = 0; pattern < 2; ++pattern) {
        motus_particle *p = &W.particles[0];
        motus_particle3 *q = &W.particles3[0];
        setup(PATTERNS[pattern], MOTUS_SEMI_IMPLICIT_EULER);
        EXPECT(MOTUS_ERROR_INVALID_BOUNDS, "min.x > max.x", motus_particle_bounce(p, motus_v2(1, 0), motus_v2(0, 1), 1));
        EXPECT(MOTUS_ERROR_INVALID_BOUNDS, "min.y > max.y", motus_particle_bounce(p, motus_v2(0, 1), motus_v2(1, 0), 1));
        EXPECT(MOTUS_ERROR_INVALID_BOUNDS, "min.z > max.z",
               motus_particle3_bounce(q, motus_v3(0, 0, 1), motus_v3(1, 1, 0), 1));
        EXPECT(MOTUS_ERROR_INVALID_BOUNDS, "+Inf > -Inf",
               motus_particle3_bounce(q, motus_v3(infinity(), 0, 0), motus_v3(-infinity(), 1, 1), 1));
        for (b = 0; b < BAD_REALS; ++b) {
            const motus_real r = bad_real(b);
            if (b == 0) { /* NaN walls; infinite ones are no wall */
                EXPECT(MOTUS_ERROR_NOT_FINITE, "min", motus_particle_bounce(p, motus_v2(r, 0), motus_v2(1, 1), 1));
                EXPECT(MOTUS_ERROR_NOT_FINITE, "max", motus_particle_bounce(p, motus_v2(0, 0), motus_v2(1, r), 1));
                EXPECT(MOTUS_ERROR_NOT_FINITE, "min.z", motus_particle3_bounce(q, motus_v3(0, 0, r), motus_v3(1, 1, 1), 1));
                EXPECT(MOTUS_ERROR_NOT_FINITE, "max.z", motus_particle3_bounce(q, motus_v3(0, 0, 0), motus_v3(1, 1, r), 1));
            }
        }
    }
}

/* =================================================================================================
   Method queries, stable dt and substeps: outputs written only on MOTUS_OK
   ================================================================================================= */
TEST(method_functions_reject_everything_bad) {
    const int bad_methods[4] = {-1, MOTUS_METHOD_COUNT, INT_MAX, INT_MIN};
    int i, b, pattern;
    for (pattern = 0; pattern < 2; ++pattern) {
        setup(PATTERNS[pattern], MOTUS_SEMI_IMPLICIT_EULER);
        for (i = 0; i < 4; ++i) {
            const motus_method m = (motus_method)bad_methods[i];
            ENSURE(motus_method_name(m) == NULL);
            ENSURE_EQ_INT(motus_method_order(m), -1);
            ENSURE_EQ_INT(motus_method_evaluations(m), -1);
            ENSURE(motus_method_stability_limit(m) == -1);
            EXPECT(MOTUS_ERROR_INVALID_METHOD, "method", motus_max_stable_dt(m, 1, 1, &W.max_dt));
        }
        EXPECT(MOTUS_ERROR_NULL_POINTER, "NULL", motus_max_stable_dt(MOTUS_RK4, 1, 1, NULL));
        for (b = 0; b < BAD_REALS; ++b) {
            EXPECT(MOTUS_ERROR_NOT_FINITE, "stiffness", motus_max_stable_dt(MOTUS_RK4, bad_real(b), 1, &W.max_dt));
            EXPECT(MOTUS_ERROR_NOT_FINITE, "mass", motus_max_stable_dt(MOTUS_RK4, 1, bad_real(b), &W.max_dt));
            EXPECT(MOTUS_ERROR_INVALID_TIME_STEP, "dt", motus_substeps_for(bad_dt(3 + b), 1, 1, &W.substeps));
            EXPECT(b == 0 ? MOTUS_ERROR_NOT_FINITE : MOTUS_ERROR_INVALID_ARGUMENT, "safety",
                   motus_substeps_for(1, 1, bad_real(b), &W.substeps));
        }
        EXPECT(MOTUS_ERROR_NOT_FINITE, "stable dt NaN", motus_substeps_for(1, not_a_number(), 1, &W.substeps));
        EXPECT(MOTUS_ERROR_INVALID_ARGUMENT, "stable dt -Inf", motus_substeps_for(1, -infinity(), 1, &W.substeps));
        EXPECT(MOTUS_ERROR_INVALID_MASS, "mass 0", motus_max_stable_dt(MOTUS_RK4, 1, 0, &W.max_dt));
        EXPECT(MOTUS_ERROR_INVALID_MASS, "mass -0", motus_max_stable_dt(MOTUS_RK4, 1, negative_zero(), &W.max_dt));
        EXPECT(MOTUS_ERROR_INVALID_MASS, "mass < 0", motus_max_stable_dt(MOTUS_RK4, 1, -REAL_MAX, &W.max_dt));
        EXPECT(MOTUS_ERROR_INVALID_SPRING, "stiffness < 0", motus_max_stable_dt(MOTUS_RK4, -REAL_TRUE_MIN, 1, &W.max_dt));
        EXPECT(MOTUS_ERROR_NULL_POINTER, "NULL", motus_substeps_for(1, 1, 1, NULL));
        for (b = 0; b < 3; ++b)
            EXPECT(MOTUS_ERROR_INVALID_TIME_STEP, "dt < 0", motus_substeps_for(bad_dt(b), 1, 1, &W.substeps));
        EXPECT(MOTUS_ERROR_INVALID_ARGUMENT, "stable dt < 0", motus_substeps_for(1, -1, 1, &W.substeps));
        EXPECT(MOTUS_ERROR_INVALID_ARGUMENT, "safety 0", motus_substeps_for(1, 1, 0, &W.substeps));
        EXPECT(MOTUS_ERROR_INVALID_ARGUMENT, "safety -0", motus_substeps_for(1, 1, negative_zero(), &W.substeps));
        EXPECT(MOTUS_ERROR_INVALID_ARGUMENT, "safety > 1", motus_substeps_for(1, 1, 1 + MOTUS_REAL_EPSILON, &W.substeps));
        EXPECT(MOTUS_ERROR_TOO_STIFF, "stable dt -0", motus_substeps_for(1, negative_zero(), 1, &W.substeps));
        EXPECT(MOTUS_ERROR_TOO_STIFF, "stable dt 0", motus_substeps_for(1, 0, 1, &W.substeps));
        EXPECT(MOTUS_ERROR_TOO_STIFF, "2^30 substeps", motus_substeps_for(REAL_MAX, 1, 1, &W.substeps));
        EXPECT(MOTUS_ERROR_TOO_STIFF, "2^30 substeps", motus_substeps_for(1, REAL_TRUE_MIN * 4, 1, &W.substeps));
    }
}

/* =================================================================================================
   The clock
   ================================================================================================= */
TEST(clock_rejects_everything_bad) {
    int pattern, b;
    int steps = 0;
    for (pattern = 0; pattern < 2; ++pattern) {
        setup(PATTERNS[pattern], MOTUS_SEMI_IMPLICIT_EULER);
        ENSURE_EQ_INT(motus_clock_advance(&W.clock, DT * MOTUS_R(2.5), &steps), MOTUS_OK);
        memcpy(&CLEAN, &W, sizeof W);
        EXPECT(MOTUS_ERROR_NULL_POINTER, "NULL", motus_clock_init(NULL, DT, 1));
        EXPECT(MOTUS_ERROR_INVALID_CLOCK, "max steps < 0", motus_clock_init(&W.clock, DT, -1));
        EXPECT(MOTUS_ERROR_INVALID_CLOCK, "max steps INT_MIN", motus_clock_init(&W.clock, DT, INT_MIN));
        EXPECT(MOTUS_ERROR_INVALID_TIME_STEP, "dt 0", motus_clock_init(&W.clock, 0, 1));
        EXPECT(MOTUS_ERROR_INVALID_TIME_STEP, "dt -0", motus_clock_init(&W.clock, negative_zero(), 1));
        for (b = 0; b < BAD_DTS; ++b) {
            EXPECT(MOTUS_ERROR_INVALID_TIME_STEP, "dt", motus_clock_init(&W.clock, bad_dt(b), 1));
            EXPECT(MOTUS_ERROR_INVALID_FRAME_TIME, "frame", motus_clock_advance(&W.clock, bad_dt(b), &steps));
            ENSURE_EQ_INT(steps, 0); /* a loop that ignores the result runs nothing */
        }
        EXPECT(MOTUS_ERROR_NULL_POINTER, "NULL", motus_clock_advance(NULL, DT, &W.substeps));
        EXPECT(MOTUS_ERROR_NULL_POINTER, "NULL", motus_clock_advance(&W.clock, DT, NULL));
        /* A corrupt clock: refused, not divided by zero. */
        W.clock.fixed_dt = 0;
        memcpy(&CLEAN, &W, sizeof W);
        EXPECT(MOTUS_ERROR_INVALID_CLOCK, "fixed_dt 0", motus_clock_advance(&W.clock, DT, &steps));
        W.clock.fixed_dt = DT, W.clock.max_steps_per_frame = 0;
        EXPECT(MOTUS_ERROR_INVALID_CLOCK, "cap 0", motus_clock_advance(&W.clock, DT, &steps));
        W.clock.max_steps_per_frame = 4, W.clock.accumulator = (uint64_t)1 << 40;
        EXPECT(MOTUS_ERROR_INVALID_CLOCK, "accumulator past a step", motus_clock_advance(&W.clock, DT, &steps));
        ENSURE(motus_clock_alpha(&W.clock) == 0);
    }
}

/* =================================================================================================
   The engine: scenes
   ================================================================================================= */
/* One thing wrong with W.scene per case; MOTUS_RESULT_COUNT when the cases are done. */
static motus_result break_scene(int which, const char **what) {
    motus_scene *s = &W.scene;
    motus_spring *sp = W.springs;
    const int bad = which % BAD_REALS;
    switch (which / BAD_REALS) {
    case 0: *what = "gravity.x"; s->gravity.x = bad_real(bad); return MOTUS_ERROR_NOT_FINITE;
    case 1: *what = "gravity.z"; s->gravity.z = bad_real(bad); return MOTUS_ERROR_NOT_FINITE;
    case 2: *what = "linear_drag"; s->linear_drag = bad_real(bad); return MOTUS_ERROR_NOT_FINITE;
    case 3: *what = "quadratic_drag"; s->quadratic_drag = bad_real(bad); return MOTUS_ERROR_NOT_FINITE;
    case 4: *what = "attractor.y"; s->attractor.y = bad_real(bad); return MOTUS_ERROR_NOT_FINITE;
    case 5: *what = "attractor.z"; s->attractor.z = bad_real(bad); return MOTUS_ERROR_NOT_FINITE;
    case 6: *what = "attractor_strength"; s->attractor_strength = bad_real(bad); return MOTUS_ERROR_NOT_FINITE;
    case 7: *what = "restitution"; s->restitution = bad_real(bad); return MOTUS_ERROR_NOT_FINITE;
    case 8: *what = "mass"; s->mass = bad_real(bad); return MOTUS_ERROR_NOT_FINITE;
    case 9: *what = "damping_per_step (a fraction)"; s->damping_per_step = bad_real(bad); return MOTUS_ERROR_INVALID_DAMPING;
    case 10:
        *what = "damping_per_second (a fraction)";
        s->damping_per_step = 0, s->damping_per_second = bad_real(bad);
        return MOTUS_ERROR_INVALID_DAMPING;
    case 11: *what = "spring anchor.z"; sp[1].anchor.z = bad_real(bad); return MOTUS_ERROR_NOT_FINITE;
    case 12: *what = "spring rest_length"; sp[0].rest_length = bad_real(bad); return MOTUS_ERROR_NOT_FINITE;
    case 13: *what = "spring stiffness"; sp[2].stiffness = bad_real(bad); return MOTUS_ERROR_NOT_FINITE;
    case 14: *what = "spring damping"; sp[0].damping = bad_real(bad); return MOTUS_ERROR_NOT_FINITE;
    case 15: *what = "tether.y"; s->tether.y = bad_real(bad); return MOTUS_ERROR_NOT_FINITE;
    case 16: *what = "tether_stiffness"; s->tether_stiffness = bad_real(bad); return MOTUS_ERROR_NOT_FINITE;
    default: break;
    }
    switch (which - 17 * BAD_REALS) {
    case 0: *what = "bounds_min.y NaN"; s->bounds_min.y = not_a_number(); return MOTUS_ERROR_NOT_FINITE;
    case 1: *what = "bounds_max.z NaN"; s->bounds_max.z = not_a_number(); return MOTUS_ERROR_NOT_FINITE;
    case 2: *what = "bounds min > max"; s->bounds_min.x = 200; return MOTUS_ERROR_INVALID_BOUNDS;
    case 3: *what = "bounds +Inf > -Inf"; s->bounds_min.z = infinity(), s->bounds_max.z = -infinity(); return MOTUS_ERROR_INVALID_BOUNDS;
    case 4: *what = "method -1"; s->method = (motus_method)-1; return MOTUS_ERROR_INVALID_METHOD;
    case 5: *what = "method COUNT"; s->method = MOTUS_METHOD_COUNT; return MOTUS_ERROR_INVALID_METHOD;
    case 6: *what = "method INT_MAX"; s->method = (motus_method)INT_MAX; return MOTUS_ERROR_INVALID_METHOD;
    case 7: *what = "substeps -1"; s->substeps = -1; return MOTUS_ERROR_INVALID_SUBSTEPS;
    case 8: *what = "substeps INT_MIN"; s->substeps = INT_MIN; return MOTUS_ERROR_INVALID_SUBSTEPS;
    case 9: *what = "linear_drag < 0"; s->linear_drag = -REAL_TRUE_MIN; return MOTUS_ERROR_INVALID_DRAG;
    case 10: *what = "quadratic_drag < 0"; s->quadratic_drag = -1; return MOTUS_ERROR_INVALID_DRAG;
    case 11: *what = "attractor_strength < 0"; s->attractor_strength = -1; return MOTUS_ERROR_INVALID_ATTRACTOR;
    case 12: *what = "damping_per_step < 0"; s->damping_per_step = MOTUS_R(-0.01); return MOTUS_ERROR_INVALID_DAMPING;
    case 13: *what = "damping_per_step > 1"; s->damping_per_step = MOTUS_R(1.01); return MOTUS_ERROR_INVALID_DAMPING;
    case 14: *what = "both dampings"; s->damping_per_second = MOTUS_R(0.5); return MOTUS_ERROR_INVALID_DAMPING;
    case 15: *what = "restitution > 1"; s->restitution = 2; return MOTUS_ERROR_INVALID_RESTITUTION;
    case 16: *what = "restitution < 0"; s->restitution = -REAL_TRUE_MIN; return MOTUS_ERROR_INVALID_RESTITUTION;
    case 17: *what = "mass < 0"; s->mass = MOTUS_R(-0.5); return MOTUS_ERROR_INVALID_MASS;
    case 18: *what = "1/mass overflows"; s->mass = REAL_TRUE_MIN; return MOTUS_ERROR_INVALID_MASS;
    case 19: *what = "spring_count < 0"; s->spring_count = -1; return MOTUS_ERROR_INVALID_SPRING;
    case 20: *what = "spring_count INT_MIN"; s->spring_count = INT_MIN; return MOTUS_ERROR_INVALID_SPRING;
    case 21: *what = "springs NULL"; s->springs = NULL; return MOTUS_ERROR_NULL_POINTER;
    case 22: *what = "spring a = count"; sp[0].a = BN; return MOTUS_ERROR_INVALID_SPRING;
    case 23: *what = "spring a = -1"; sp[0].a = -1; return MOTUS_ERROR_INVALID_SPRING;
    case 24: *what = "spring a = INT_MAX"; sp[2].a = INT_MAX; return MOTUS_ERROR_INVALID_SPRING;
    case 25: *what = "spring a = INT_MIN"; sp[2].a = INT_MIN; return MOTUS_ERROR_INVALID_SPRING;
    case 26: *what = "spring b = count"; sp[0].b = BN; return MOTUS_ERROR_INVALID_SPRING;
    case 27: *what = "spring b = -2"; sp[2].b = -2; return MOTUS_ERROR_INVALID_SPRING;
    case 28: *what = "spring b = INT_MIN"; sp[2].b = INT_MIN; return MOTUS_ERROR_INVALID_SPRING;
    case 29: *what = "spring a == b"; sp[0].b = sp[0].a; return MOTUS_ERROR_INVALID_SPRING;
    case 30: *what = "spring stiffness < 0"; sp[1].stiffness = -1; return MOTUS_ERROR_INVALID_SPRING;
    case 31: *what = "spring damping < 0"; sp[1].damping = MOTUS_R(-0.125); return MOTUS_ERROR_INVALID_SPRING;
    case 32: *what = "spring rest_length < 0"; sp[2].rest_length = -2; return MOTUS_ERROR_INVALID_SPRING;
    case 33: *what = "exact + quadratic drag"; s->method = MOTUS_EXACT_LINEAR_DRAG; return MOTUS_ERROR_UNSUPPORTED;
    case 34:
        *what = "exact + attractor";
        s->method = MOTUS_EXACT_LINEAR_DRAG, s->quadratic_drag = 0;
        return MOTUS_ERROR_UNSUPPORTED;
    case 35:
        *what = "exact + springs";
        s->method = MOTUS_EXACT_LINEAR_DRAG, s->quadratic_drag = 0, s->attractor_strength = 0;
        s->force_callback = NULL, s->tether_stiffness = 0;
        return MOTUS_ERROR_UNSUPPORTED;
    case 36:
        *what = "exact + callback";
        s->method = MOTUS_EXACT_LINEAR_DRAG, s->quadratic_drag = 0, s->attractor_strength = 0;
        s->springs = NULL, s->spring_count = 0, s->tether_stiffness = 0;
        return MOTUS_ERROR_UNSUPPORTED;
    case 37:
        *what = "exact + tether";
        s->method = MOTUS_EXACT_LINEAR_DRAG, s->quadratic_drag = 0, s->attractor_strength = 0;
        s->springs = NULL, s->spring_count = 0, s->force_callback = NULL;
        return MOTUS_ERROR_UNSUPPORTED;
    case 38: *what = "tether_stiffness < 0"; s->tether_stiffness = -REAL_TRUE_MIN; return MOTUS_ERROR_INVALID_TETHER;
    default: return MOTUS_RESULT_COUNT;
    }
}

TEST(every_bad_scene_is_refused_by_every_function) {
    /* The same broken scene gives the same result from every function that takes a scene, and none of
       them writes anything or calls the callback. */
    int pattern, which;
    for (pattern = 0; pattern < 2; ++pattern) {
        setup(PATTERNS[pattern], MOTUS_RK4);
        EXPECT(MOTUS_ERROR_NULL_POINTER, "NULL scene", motus_scene_check(NULL, 3, BN, &W.report));
        EXPECT(MOTUS_ERROR_NULL_POINTER, "NULL scene", motus_step(NULL, &W.state, DT, W.scratch, sizeof W.scratch));
        EXPECT(MOTUS_ERROR_NULL_POINTER, "NULL scene", motus_step_range(NULL, &W.state, 0, BN, DT));
        EXPECT(MOTUS_ERROR_NULL_POINTER, "NULL scene",
               motus_scene_max_stable_dt(NULL, &W.state, &W.max_dt, W.scratch, sizeof W.scratch));
        EXPECT(MOTUS_ERROR_NULL_POINTER, "NULL max_dt",
               motus_scene_max_stable_dt(&W.scene, &W.state, NULL, W.scratch, sizeof W.scratch));
        ENSURE(motus_scratch_size(NULL, &W.state) == 0);
        for (which = 0;; ++which) {
            const char *what = "";
            const motus_result expected = break_scene(which, &what);
            if (expected == MOTUS_RESULT_COUNT) break;
            EXPECT(expected, what, motus_scene_check(&W.scene, 3, BN, &W.report));
            ENSURE(W.report.field_name != NULL && strncmp(W.report.field_name, "scene", 5) == 0);
            EXPECT(expected, what, motus_scene_check(&W.scene, 3, BN, NULL));
            EXPECT(expected, what, motus_step(&W.scene, &W.state, DT, W.scratch, sizeof W.scratch));
            EXPECT(expected, what, motus_step(&W.scene, &W.state, 0, W.scratch, sizeof W.scratch));
            EXPECT(expected, what, motus_step_range(&W.scene, &W.state, 0, BN, DT));
            EXPECT(expected, what, motus_step_range(&W.scene, &W.state, 0, 0, DT));
            EXPECT(expected, what, motus_scene_max_stable_dt(&W.scene, &W.state, &W.max_dt, W.scratch, sizeof W.scratch));
            restore();
        }
        ENSURE(which == 17 * BAD_REALS + 39);
    }
}

TEST(scene_walls_at_infinity) {
    /* bounds_min = bounds_max = +Inf (or both -Inf) passes min <= max. Every finite position is below the
       +Inf wall, so it is "mirrored" to +Inf. Whatever the engine decides (refuse the scene, or treat the wall
       as none), MOTUS_OK must not come with an infinite position.
       HEADER BUG: motus_scene_check accepts it and motus__walls writes x = lo + (lo - x) = +Inf after the
       check sum is taken, so motus_step returns MOTUS_OK with infinite positions (release and checked). */
    int side, d;
    for (side = 0; side < 2; ++side) {
        motus_result r;
        int finite = 1, i;
        setup(PATTERNS[0], MOTUS_SEMI_IMPLICIT_EULER);
        uncouple();
        W.scene.bounds_min.y = W.scene.bounds_max.y = side ? -infinity() : infinity();
        r = motus_step(&W.scene, &W.state, DT, NULL, 0);
        for (d = 0; d < 3; ++d)
            for (i = 0; i < BN; ++i) finite &= motus_real_is_finite(W.state.position[d][i]);
        ENSURE(r != MOTUS_OK || finite);
    }
}

/* =================================================================================================
   The engine: state shapes, time steps, scratch, ranges
   ================================================================================================= */
/* One thing wrong with W.state per case (its shape, not its data). */
static motus_result break_state(int which, const char **what) {
    motus_state *s = &W.state;
    switch (which) {
    case 0: *what = "dimensions 1"; s->dimensions = 1; return MOTUS_ERROR_INVALID_DIMENSIONS;
    case 1: *what = "dimensions 4"; s->dimensions = 4; return MOTUS_ERROR_INVALID_DIMENSIONS;
    case 2: *what = "dimensions -1"; s->dimensions = -1; return MOTUS_ERROR_INVALID_DIMENSIONS;
    case 3: *what = "dimensions INT_MIN"; s->dimensions = INT_MIN; return MOTUS_ERROR_INVALID_DIMENSIONS;
    case 4: *what = "count -1"; s->count = -1; return MOTUS_ERROR_INVALID_COUNT;
    case 5: *what = "count INT_MIN"; s->count = INT_MIN; return MOTUS_ERROR_INVALID_COUNT;
    case 6: *what = "stride -1"; s->stride = -1; return MOTUS_ERROR_INVALID_STRIDE;
    case 7: *what = "stride INT_MIN"; s->stride = INT_MIN; return MOTUS_ERROR_INVALID_STRIDE;
    case 8: *what = "count and stride INT_MAX"; s->count = INT_MAX, s->stride = INT_MAX; return MOTUS_ERROR_INVALID_COUNT;
    case 9: *what = "NULL x"; s->position[0] = NULL; return MOTUS_ERROR_NULL_POINTER;
    case 10: *what = "NULL y"; s->position[1] = NULL; return MOTUS_ERROR_NULL_POINTER;
    case 11: *what = "NULL z"; s->position[2] = NULL; return MOTUS_ERROR_NULL_POINTER;
    case 12: *what = "NULL vx"; s->velocity[0] = NULL; return MOTUS_ERROR_NULL_POINTER;
    case 13: *what = "NULL vy"; s->velocity[1] = NULL; return MOTUS_ERROR_NULL_POINTER;
    case 14: *what = "NULL vz"; s->velocity[2] = NULL; return MOTUS_ERROR_NULL_POINTER;
    case 15: *what = "position == velocity"; s->velocity[0] = s->position[0]; return MOTUS_ERROR_ALIASING;
    case 16: *what = "x == vz"; s->velocity[2] = s->position[0]; return MOTUS_ERROR_ALIASING;
    case 17: *what = "x == y"; s->position[1] = s->position[0]; return MOTUS_ERROR_ALIASING;
    case 18: *what = "vy == vz"; s->velocity[2] = s->velocity[1]; return MOTUS_ERROR_ALIASING;
    case 19: *what = "z == vx"; s->position[2] = s->velocity[0]; return MOTUS_ERROR_ALIASING;
    default: return MOTUS_RESULT_COUNT;
    }
}

TEST(every_bad_state_shape_is_refused) {
    int pattern, which, coupled;
    for (pattern = 0; pattern < 2; ++pattern)
        for (coupled = 0; coupled < 2; ++coupled) {
            setup(PATTERNS[pattern], MOTUS_LEAPFROG);
            if (!coupled) uncouple(), memcpy(&CLEAN, &W, sizeof W);
            EXPECT(MOTUS_ERROR_NULL_POINTER, "NULL state", motus_step(&W.scene, NULL, DT, W.scratch, sizeof W.scratch));
            EXPECT(MOTUS_ERROR_NULL_POINTER, "NULL state", motus_step_range(&W.scene, NULL, 0, 1, DT));
            EXPECT(MOTUS_ERROR_NULL_POINTER, "NULL state", motus_state_check(&W.scene, NULL, 0, 1, &W.report));
            EXPECT(MOTUS_ERROR_NULL_POINTER, "NULL state",
                   motus_scene_max_stable_dt(&W.scene, NULL, &W.max_dt, W.scratch, sizeof W.scratch));
            ENSURE(motus_scratch_size(&W.scene, NULL) == 0);
            for (which = 0;; ++which) {
                const char *what = "";
                const motus_result expected = break_state(which, &what);
                if (expected == MOTUS_RESULT_COUNT) break;
                EXPECT(expected, what, motus_step(&W.scene, &W.state, DT, W.scratch, sizeof W.scratch));
                EXPECT(expected, what, motus_step(&W.scene, &W.state, 0, W.scratch, sizeof W.scratch));
                EXPECT(expected, what, motus_step_range(&W.scene, &W.state, 0, 1, DT));
                EXPECT(expected, what, motus_state_check(&W.scene, &W.state, 0, 1, &W.report));
                ENSURE(W.report.index == -1 && W.report.field_name != NULL);
                EXPECT(expected, what, motus_scene_max_stable_dt(&W.scene, &W.state, &W.max_dt, W.scratch, sizeof W.scratch));
                restore();
            }
            ENSURE(which == 20);
            /* A 2D state does not read z: NULL or aliased z arrays are fine, nothing in them is written. */
            W.state.dimensions = 2;
            W.state.position[2] = NULL, W.state.velocity[2] = W.state.position[0], W.state.force[2] = NULL;
            ENSURE_EQ_INT(motus_state_check(&W.scene, &W.state, 0, BN, &W.report), MOTUS_OK);
            ENSURE_EQ_INT(motus_step(&W.scene, &W.state, DT, W.scratch, sizeof W.scratch), MOTUS_OK);
            ENSURE(memcmp(CLEAN.arrays[BZ], W.arrays[BZ], sizeof W.arrays[BZ]) == 0);
            ENSURE(memcmp(CLEAN.arrays[BVZ], W.arrays[BVZ], sizeof W.arrays[BVZ]) == 0);
            ENSURE(memcmp(CLEAN.arrays[BX], W.arrays[BX], sizeof W.arrays[BX]) != 0); /* it did step */
            restore();
        }
}

TEST(bad_time_steps_and_dt_zero) {
    int pattern, m, b, coupled;
    for (pattern = 0; pattern < 2; ++pattern)
        for (m = 0; m < MOTUS_METHOD_COUNT; ++m)
            for (coupled = 0; coupled < 2; ++coupled) {
                setup(PATTERNS[pattern], (motus_method)m);
                if (!coupled) uncouple(), memcpy(&CLEAN, &W, sizeof W);
                for (b = 0; b < BAD_DTS; ++b) {
                    EXPECT(MOTUS_ERROR_INVALID_TIME_STEP, "bad dt", motus_step(&W.scene, &W.state, bad_dt(b), W.scratch, sizeof W.scratch));
                    EXPECT(MOTUS_ERROR_INVALID_TIME_STEP, "bad dt",
                           motus_step_range(&W.scene, &W.state, 0, BN, bad_dt(b)));
                    EXPECT(MOTUS_ERROR_INVALID_TIME_STEP, "bad dt, empty range", motus_step_range(&W.scene, &W.state, 3, 0, bad_dt(b)));
                }
                /* dt 0 and -0: a valid step of nothing; bad data in the state is still reported. */
                EXPECT(MOTUS_OK, "dt 0", motus_step(&W.scene, &W.state, 0, W.scratch, sizeof W.scratch));
                EXPECT(MOTUS_OK, "dt -0", motus_step(&W.scene, &W.state, negative_zero(), W.scratch, sizeof W.scratch));
                if (!coupled) EXPECT(MOTUS_OK, "dt 0", motus_step_range(&W.scene, &W.state, 0, BN, 0));
                barray(BVX)[3] = not_a_number();
                memcpy(&CLEAN, &W, sizeof W);
                EXPECT(MOTUS_ERROR_NOT_FINITE, "dt 0, NaN velocity", motus_step(&W.scene, &W.state, 0, W.scratch, sizeof W.scratch));
                if (!coupled)
                    EXPECT(MOTUS_ERROR_NOT_FINITE, "dt 0, NaN velocity", motus_step_range(&W.scene, &W.state, 0, BN, 0));
            }
}

TEST(scratch_too_small_or_misaligned) {
    int pattern, m;
    for (pattern = 0; pattern < 2; ++pattern)
        for (m = 0; m < MOTUS_EXACT_LINEAR_DRAG; ++m) {
            size_t needed;
            setup(PATTERNS[pattern], (motus_method)m);
            needed = motus_scratch_size(&W.scene, &W.state);
            /* the stage arrays hold whole groups of lanes; the checked copy one value a particle */
            ENSURE(needed == ((size_t)3 * (size_t)(2 + motus_method_evaluations((motus_method)m)) *
                                  (size_t)((BN + MOTUS__LANES - 1) / MOTUS__LANES * MOTUS__LANES) +
                              (size_t)CHECKED_COPY_REALS * BN) * sizeof(motus_real));
            ENSURE(needed <= sizeof W.scratch);
            EXPECT(MOTUS_ERROR_SCRATCH_TOO_SMALL, "NULL", motus_step(&W.scene, &W.state, DT, NULL, 0));
            EXPECT(MOTUS_ERROR_SCRATCH_TOO_SMALL, "NULL, bytes enough", motus_step(&W.scene, &W.state, DT, NULL, needed));
            EXPECT(MOTUS_ERROR_SCRATCH_TOO_SMALL, "one byte short", motus_step(&W.scene, &W.state, DT, W.scratch, needed - 1));
            EXPECT(MOTUS_ERROR_SCRATCH_TOO_SMALL, "0 bytes", motus_step(&W.scene, &W.state, DT, W.scratch, 0));
            EXPECT(MOTUS_ERROR_SCRATCH_TOO_SMALL, "misaligned",
                   motus_step(&W.scene, &W.state, DT, (char *)W.scratch + 1, sizeof W.scratch - 1));
            EXPECT(MOTUS_ERROR_SCRATCH_TOO_SMALL, "dt 0, NULL", motus_step(&W.scene, &W.state, 0, NULL, 0));
            /* INT_MAX particles: the scratch size says so (never a wrapped size), the step refuses before
               it reads a particle. */
            W.state.count = INT_MAX;
            ENSURE(motus_scratch_size(&W.scene, &W.state) == (size_t)-1 ||
                   motus_scratch_size(&W.scene, &W.state) ==
                       ((size_t)3 * (size_t)(2 + motus_method_evaluations((motus_method)m)) *
                            (((size_t)INT_MAX + (size_t)MOTUS__LANES - 1) / (size_t)MOTUS__LANES * (size_t)MOTUS__LANES) +
                        (size_t)CHECKED_COPY_REALS * (size_t)INT_MAX) * sizeof(motus_real));
            EXPECT(MOTUS_ERROR_SCRATCH_TOO_SMALL, "count INT_MAX", motus_step(&W.scene, &W.state, DT, W.scratch, sizeof W.scratch));
            EXPECT(MOTUS_ERROR_SCRATCH_TOO_SMALL, "count INT_MAX",
                   motus_scene_max_stable_dt(&W.scene, &W.state, &W.max_dt, W.scratch, sizeof W.scratch));
            restore();
            /* max_stable_dt's own scratch: 2 reals a particle. */
            EXPECT(MOTUS_ERROR_SCRATCH_TOO_SMALL, "stable dt, NULL",
                   motus_scene_max_stable_dt(&W.scene, &W.state, &W.max_dt, NULL, sizeof W.scratch));
            EXPECT(MOTUS_ERROR_SCRATCH_TOO_SMALL, "stable dt, short",
                   motus_scene_max_stable_dt(&W.scene, &W.state, &W.max_dt, W.scratch, 2 * BN * sizeof(motus_real) - 1));
            EXPECT(MOTUS_ERROR_SCRATCH_TOO_SMALL, "stable dt, misaligned",
                   motus_scene_max_stable_dt(&W.scene, &W.state, &W.max_dt, (char *)W.scratch + 2, sizeof W.scratch - 2));
            /* Uncoupled scenes need none. */
            uncouple();
            ENSURE(motus_scratch_size(&W.scene, &W.state) == 0);
            ENSURE_EQ_INT(motus_step(&W.scene, &W.state, DT, NULL, 0), MOTUS_OK);
        }
    /* The scratch size of arguments that are not a state. */
    setup(PATTERNS[0], MOTUS_RK4);
    W.scene.method = MOTUS_METHOD_COUNT;
    ENSURE(motus_scratch_size(&W.scene, &W.state) == 0);
    W.scene.method = MOTUS_RK4, W.state.count = -1;
    ENSURE(motus_scratch_size(&W.scene, &W.state) == 0);
}

TEST(ranges_and_counts) {
    static const int ranges[][2] = {{-1, 1},      {INT_MIN, 1}, {0, -1},           {3, INT_MIN}, {1, INT_MAX},
                                    {INT_MAX, 1}, {INT_MAX, INT_MAX}, {-1, 0}, {BN, 1}, {BN + 1, 0}, {0, BN + 1}};
    int pattern, r;
    for (pattern = 0; pattern < 2; ++pattern) {
        setup(PATTERNS[pattern], MOTUS_MIDPOINT);
        EXPECT(MOTUS_ERROR_UNSUPPORTED, "coupled", motus_step_range(&W.scene, &W.state, 0, BN, DT));
        EXPECT(MOTUS_ERROR_UNSUPPORTED, "coupled, empty", motus_step_range(&W.scene, &W.state, 0, 0, DT));
        W.scene.springs = NULL, W.scene.spring_count = 0;
        EXPECT(MOTUS_ERROR_UNSUPPORTED, "callback", motus_step_range(&W.scene, &W.state, 0, BN, DT));
        uncouple();
        memcpy(&CLEAN, &W, sizeof W);
        for (r = 0; r < (int)(sizeof ranges / sizeof ranges[0]); ++r) {
            const int first = ranges[r][0], count = ranges[r][1];
            char what[64];
            sprintf(what, "first %d, count %d", first, count);
            EXPECT(MOTUS_ERROR_INVALID_COUNT, what, motus_step_range(&W.scene, &W.state, first, count, DT));
            EXPECT(MOTUS_ERROR_INVALID_COUNT, what, motus_state_check(&W.scene, &W.state, first, count, &W.report));
            ENSURE(W.report.index == -1);
        }
        /* Empty ranges are valid anywhere up to the count and write nothing. */
        EXPECT(MOTUS_OK, "empty", motus_step_range(&W.scene, &W.state, 0, 0, DT));
        EXPECT(MOTUS_OK, "empty at the end", motus_step_range(&W.scene, &W.state, BN, 0, DT));
        EXPECT(MOTUS_OK, "empty at the end", motus_state_check(&W.scene, &W.state, BN, 0, &W.report));
        /* count 0: no particles to read (NULL arrays are fine), springs have no end to hang on. */
        W.state.count = 0;
        W.state.position[0] = W.state.velocity[1] = NULL;
        memcpy(&CLEAN, &W, sizeof W);
        EXPECT(MOTUS_OK, "count 0", motus_step(&W.scene, &W.state, DT, NULL, 0));
        EXPECT(MOTUS_OK, "count 0", motus_state_check(&W.scene, &W.state, 0, 0, &W.report));
        ENSURE_EQ_INT(motus_scene_max_stable_dt(&W.scene, &W.state, &W.max_dt, NULL, 0), MOTUS_OK);
        ENSURE(W.max_dt > 0);
        restore();
        setup_scene(MOTUS_MIDPOINT);
        memcpy(&CLEAN, &W, sizeof W);
        EXPECT(MOTUS_ERROR_INVALID_SPRING, "count 0 with springs", motus_step(&W.scene, &W.state, DT, W.scratch, sizeof W.scratch));
        W.scene.springs = NULL, W.scene.spring_count = 0; /* the callback alone: nothing to call it for */
        EXPECT(MOTUS_OK, "count 0, callback", motus_step(&W.scene, &W.state, DT, NULL, 0));
    }
}

/* =================================================================================================
   The engine: bad particle data
   ================================================================================================= */
static const motus_field ARRAY_FIELDS[BARRAYS] = {
    MOTUS_FIELD_POSITION, MOTUS_FIELD_POSITION, MOTUS_FIELD_POSITION, MOTUS_FIELD_VELOCITY, MOTUS_FIELD_VELOCITY,
    MOTUS_FIELD_VELOCITY, MOTUS_FIELD_FORCE,    MOTUS_FIELD_FORCE,    MOTUS_FIELD_FORCE,    MOTUS_FIELD_INVERSE_MASS};

/* motus_step on bad data in [0, BN): MOTUS_CHECKED finds it first and writes nothing; release builds write and
   return MOTUS_ERROR_NOT_FINITE (a negative finite inverse mass is not looked for there). */
static void expect_bad_data(motus_result expected, const char *what, int line) {
    motus_result r;
    unsigned long calls = CALLBACK_CALLS;
    memcpy(&BEFORE, &W, sizeof W);
    r = motus_step(&W.scene, &W.state, DT, W.scratch, sizeof W.scratch);
#ifdef MOTUS_CHECKED
    expect_at(r, expected, calls, "motus_step", what, line);
#else
    (void)calls;
    if (expected == MOTUS_ERROR_INVALID_MASS ? !(r == MOTUS_OK || r == expected) : r != MOTUS_ERROR_NOT_FINITE) {
        fprintf(stderr, "%s:%d: motus_step [%s] (%s): gave %d (%s)\n", __FILE__, line, what,
                motus_method_name(W.scene.method), (int)r, motus_result_string(r));
        motus_test_failures++;
    }
#endif
    memcpy(&W, &BEFORE, sizeof W);
    if (!W.scene.springs && !W.scene.force_callback) { /* the range API, on a range holding the bad particle */
        memcpy(&BEFORE, &W, sizeof W);
        r = motus_step_range(&W.scene, &W.state, 10, BN - 10, DT);
#ifdef MOTUS_CHECKED
        expect_at(r, expected, CALLBACK_CALLS, "motus_step_range", what, line);
#else
        if (expected == MOTUS_ERROR_INVALID_MASS ? !(r == MOTUS_OK || r == expected) : r != MOTUS_ERROR_NOT_FINITE) {
            fprintf(stderr, "%s:%d: motus_step_range [%s]: gave %d\n", __FILE__, line, what, (int)r);
            motus_test_failures++;
        }
        /* Release: only the range was written, nothing outside it. */
        {
            int a;
            for (a = 0; a < BARRAYS; ++a)
                if (memcmp(BEFORE.arrays[a], W.arrays[a], (GUARD + 10) * sizeof(motus_real)) != 0 ||
                    memcmp(BEFORE.arrays[a] + GUARD + BN, W.arrays[a] + GUARD + BN, GUARD * sizeof(motus_real)) != 0) {
                    fprintf(stderr, "%s:%d: motus_step_range [%s] wrote outside its range\n", __FILE__, line, what);
                    motus_test_failures++;
                }
        }
#endif
        memcpy(&W, &BEFORE, sizeof W);
    }
}

TEST(bad_particle_data) {
    /* A NaN, +Inf, -Inf in each array the scene reads, at particle `at` (in a whole vector or the last
       partial one), and a negative inverse mass; every method, coupled and not. motus_state_check names the
       particle, field and component; motus_step as expect_bad_data says. */
    static const int ats[2] = {17, BN - 1};
    int pattern, m, a, b, coupled, t;
    for (pattern = 0; pattern < 2; ++pattern)
        for (m = 0; m < MOTUS_METHOD_COUNT; ++m)
            for (coupled = 0; coupled < 2; ++coupled) {
                if (coupled && m == MOTUS_EXACT_LINEAR_DRAG) continue;
                setup(PATTERNS[pattern], (motus_method)m);
                if (!coupled) uncouple(), memcpy(&CLEAN, &W, sizeof W);
                for (t = 0; t < 2; ++t)
                    for (a = 0; a < BARRAYS; ++a)
                        for (b = 0; b <= BAD_REALS; ++b) {
                            const int at = ats[t], negative_mass = b == BAD_REALS;
                            const motus_result expected = negative_mass ? MOTUS_ERROR_INVALID_MASS : MOTUS_ERROR_NOT_FINITE;
                            char what[96];
                            if (negative_mass && a != BMASS) continue;
                            if (barray(BMASS)[at] == 0 && a >= BFX && a <= BFZ) continue; /* see immovable_bad_force */
                            barray(a)[at] = negative_mass ? MOTUS_R(-0.5) : bad_real(b);
                            sprintf(what, "%s array %d [%d] = %g", coupled ? "coupled" : "uncoupled", a, at, (double)barray(a)[at]);
                            memcpy(&CLEAN, &W, sizeof W);
                            EXPECT(expected, what, motus_state_check(&W.scene, &W.state, 0, BN, &W.report));
                            ENSURE_EQ_INT(W.report.index, at);
                            ENSURE_EQ_INT(W.report.field, ARRAY_FIELDS[a]);
                            ENSURE_EQ_INT(W.report.component, a == BMASS ? -1 : (a - BX) % 3);
                            ENSURE(W.report.field_name && strcmp(W.report.field_name, motus_field_name(ARRAY_FIELDS[a])) == 0);
                            /* A range that does not hold the bad particle is fine. */
                            EXPECT(MOTUS_OK, what, motus_state_check(&W.scene, &W.state, 0, at, &W.report));
                            ENSURE(W.report.index == -1 && strcmp(W.report.field_name, "none") == 0);
                            expect_bad_data(expected, what, __LINE__);
                            setup(PATTERNS[pattern], (motus_method)m);
                            if (!coupled) uncouple(), memcpy(&CLEAN, &W, sizeof W);
                        }
            }
}

TEST(state_check_order_and_unread_fields) {
    int pattern;
    for (pattern = 0; pattern < 2; ++pattern) {
        setup(PATTERNS[pattern], MOTUS_RK4);
        /* Two bad particles: the first is named. Two bad fields in one: position, velocity, force, mass. */
        barray(BMASS)[9] = -1, barray(BFZ)[9] = infinity(), barray(BVY)[9] = not_a_number();
        barray(BX)[20] = not_a_number();
        memcpy(&CLEAN, &W, sizeof W);
        EXPECT(MOTUS_ERROR_NOT_FINITE, "velocity first", motus_state_check(&W.scene, &W.state, 0, BN, &W.report));
        ENSURE(W.report.index == 9 && W.report.field == MOTUS_FIELD_VELOCITY && W.report.component == 1);
        EXPECT(MOTUS_ERROR_NOT_FINITE, "from 10", motus_state_check(&W.scene, &W.state, 10, BN - 10, &W.report));
        ENSURE(W.report.index == 20 && W.report.field == MOTUS_FIELD_POSITION && W.report.component == 0);
        EXPECT(MOTUS_ERROR_NOT_FINITE, "no report", motus_state_check(&W.scene, &W.state, 0, BN, NULL));
        EXPECT(MOTUS_ERROR_NOT_FINITE, "scene NULL (not read)", motus_state_check(NULL, &W.state, 0, BN, &W.report));
        barray(BVY)[9] = 1;
        EXPECT(MOTUS_ERROR_NOT_FINITE, "force before mass", motus_state_check(&W.scene, &W.state, 0, 10, &W.report));
        ENSURE(W.report.index == 9 && W.report.field == MOTUS_FIELD_FORCE && W.report.component == 2);
        barray(BFZ)[9] = 1;
        EXPECT(MOTUS_ERROR_INVALID_MASS, "mass", motus_state_check(&W.scene, &W.state, 0, 10, &W.report));
        ENSURE(W.report.index == 9 && W.report.field == MOTUS_FIELD_INVERSE_MASS && W.report.component == -1);
        setup(PATTERNS[pattern], MOTUS_RK4);
        /* Arrays the state does not have are not read: no forces, no masses (scene.mass), z in 2D. */
        W.state.force[0] = W.state.force[1] = W.state.force[2] = NULL;
        W.state.inverse_mass = NULL;
        barray(BFX)[3] = not_a_number(), barray(BMASS)[3] = -1;
        memcpy(&CLEAN, &W, sizeof W);
        EXPECT(MOTUS_OK, "no force, no mass arrays", motus_state_check(&W.scene, &W.state, 0, BN, &W.report));
        W.state.dimensions = 2;
        barray(BZ)[5] = infinity(), barray(BVZ)[6] = not_a_number();
        memcpy(&CLEAN, &W, sizeof W);
        EXPECT(MOTUS_OK, "2D: z not read", motus_state_check(&W.scene, &W.state, 0, BN, &W.report));
        ENSURE_EQ_INT(motus_step(&W.scene, &W.state, DT, W.scratch, sizeof W.scratch), MOTUS_OK);
        ENSURE(barray(BZ)[5] == infinity());
    }
}

TEST(immovable_bad_force) {
    /* A NaN force on an immovable particle: its acceleration is 0 whatever the force, but the data is bad,
       as motus_particle_check and motus_state_check say. HEADER BUG: (release builds) motus_step selects the
       acceleration of an immovable particle to 0 before the check sum sees the NaN, so it returns MOTUS_OK;
       so does motus_particle_step (motus__step sets v back to the old velocity before its finite check). */
    int pattern, m;
    for (pattern = 0; pattern < 2; ++pattern)
        for (m = 0; m < MOTUS_METHOD_COUNT; ++m) {
            motus_particle alone;
            setup(PATTERNS[pattern], (motus_method)m);
            uncouple();
            ENSURE(barray(BMASS)[13] == 0); /* inside the range expect_bad_data steps */
            barray(BFY)[13] = not_a_number();
            memcpy(&CLEAN, &W, sizeof W);
            EXPECT(MOTUS_ERROR_NOT_FINITE, "immovable, NaN force", motus_state_check(&W.scene, &W.state, 0, BN, &W.report));
            expect_bad_data(MOTUS_ERROR_NOT_FINITE, "immovable, NaN force", __LINE__);
            alone = W.particles[CAPACITY - 1];
            alone.force.x = not_a_number();
            ENSURE_EQ_INT(motus_particle_check(&alone), MOTUS_ERROR_NOT_FINITE);
            if (m == 0) ENSURE_EQ_INT(motus_particle_step(&alone, DT), MOTUS_ERROR_NOT_FINITE);
        }
}

TEST(bad_data_reaching_other_particles) {
    /* An Inf position in particle 1 reaches particle 0 through a spring or the callback: the step must
       still say MOTUS_ERROR_NOT_FINITE (not OVERFLOW: the input was bad), with nothing written when checked. */
    int m, coupling;
    for (m = 0; m < MOTUS_EXACT_LINEAR_DRAG; ++m)
        for (coupling = 0; coupling < 2; ++coupling) {
            setup(PATTERNS[0], (motus_method)m);
            if (coupling == 0) W.scene.force_callback = NULL;
            else W.scene.springs = NULL, W.scene.spring_count = 0;
            barray(BY)[1] = infinity();
            memcpy(&CLEAN, &W, sizeof W);
            expect_bad_data(MOTUS_ERROR_NOT_FINITE, coupling ? "Inf position, callback" : "Inf position, spring", __LINE__);
        }
}

TEST(overflow_with_finite_data) {
    /* Finite data, a step past the largest real: MOTUS_CHECKED says MOTUS_ERROR_OVERFLOW and writes nothing
       (coupled scenes too); release builds write and say MOTUS_ERROR_NOT_FINITE. Every method; the overflow
       in a position, and in a velocity (F/m). */
    int pattern, m, coupled, which;
    for (pattern = 0; pattern < 2; ++pattern)
        for (m = 0; m < MOTUS_METHOD_COUNT; ++m)
            for (coupled = 0; coupled < 2; ++coupled)
                for (which = 0; which < 2; ++which) {
                    motus_result r;
                    unsigned long calls;
                    if (coupled && m == MOTUS_EXACT_LINEAR_DRAG) continue;
                    setup(PATTERNS[pattern], (motus_method)m);
                    if (!coupled) uncouple();
                    W.scene.linear_drag = W.scene.quadratic_drag = 0; /* drag would slow it down enough */
                    W.scene.bounds_min = W.scene.bounds_max = motus_v3(0, 0, 0);
                    if (which == 0) barray(BX)[22] = barray(BVX)[22] = REAL_MAX / 2;
                    else barray(BFZ)[22] = -REAL_MAX, barray(BMASS)[22] = 4;
                    memcpy(&CLEAN, &W, sizeof W);
                    ENSURE_EQ_INT(motus_state_check(&W.scene, &W.state, 0, BN, NULL), MOTUS_OK);
                    memcpy(&BEFORE, &W, sizeof W);
                    calls = CALLBACK_CALLS;
                    r = motus_step(&W.scene, &W.state, 8, W.scratch, sizeof W.scratch);
#ifdef MOTUS_CHECKED
                    /* HEADER BUG: (coupled scenes) the checked build checks the data of a coupled scene but makes no
                       dry run, so an overflow there writes and returns MOTUS_ERROR_NOT_FINITE. (The scratch
                       is working memory: it may change.) */
                    memcpy(W.scratch, BEFORE.scratch, sizeof W.scratch);
                    (void)calls;
                    expect_at(r, MOTUS_ERROR_OVERFLOW, CALLBACK_CALLS, coupled ? "motus_step, coupled" : "motus_step",
                              which ? "velocity overflow" : "position overflow", __LINE__);
#else
                    (void)calls;
                    if (r != MOTUS_ERROR_NOT_FINITE) {
                        fprintf(stderr, "%s:%d: %s %s: gave %d\n", __FILE__, __LINE__, motus_method_name((motus_method)m),
                                which ? "velocity overflow" : "position overflow", (int)r);
                        motus_test_failures++;
                    }
#endif
                }
}

TEST(attractor_at_the_origin_with_a_partial_vector) {
    /* (b) An attractor at the origin, particles near it, counts 1..2*MOTUS__LANES+1 (never only whole
       vectors): the lanes past the count must not be phantom particles at the origin, where the pull is a
       division by zero (NaN, Inf) that the check sum (and MOTUS_CHECKED's dry run) would report. Every method
       but the exact one, 2D and 3D, plain arrays and strided structs; and a particle exactly at the
       attractor feels no pull. */
    int m, dims, count, strided;
    for (dims = 2; dims <= 3; ++dims)
        for (m = 0; m < MOTUS_EXACT_LINEAR_DRAG; ++m)
            for (strided = 0; strided < 2; ++strided)
                for (count = 1; count <= 2 * MOTUS__LANES + 1; ++count) {
                    motus_particle3 p3[2 * 16 + 1];
                    motus_particle p2[2 * 16 + 1];
                    motus_real x[3][2 * 16 + 1], v[3][2 * 16 + 1];
                    motus_scene scene;
                    motus_state state;
                    motus_result r;
                    int i, d;
                    memset(&scene, 0, sizeof scene);
                    memset(&state, 0, sizeof state);
                    scene.method = (motus_method)m;
                    scene.attractor_strength = MOTUS_R(1e-6); /* weak: no step overshoots the origin */
                    for (i = 0; i < count; ++i) {
                        for (d = 0; d < 3; ++d) {
                            x[d][i] = MOTUS_R(0.001) * (motus_real)(i + 1) * (d == 1 ? -1 : 1);
                            v[d][i] = 0;
                        }
                        motus_particle3_init(&p3[i], motus_v3(x[0][i], x[1][i], x[2][i]), 1);
                        motus_particle_init(&p2[i], motus_v2(x[0][i], x[1][i]), 1);
                    }
                    if (strided) state = dims == 3 ? motus_state_of_particles3(p3, count) : motus_state_of_particles(p2, count);
                    else {
                        state.dimensions = dims;
                        state.count = count;
                        for (d = 0; d < dims; ++d) state.position[d] = x[d], state.velocity[d] = v[d];
                    }
                    r = motus_step(&scene, &state, MOTUS_R(1e-4), NULL, 0);
                    if (r != MOTUS_OK) {
                        fprintf(stderr, "  %s, %dD, %s, count %d: %s\n", motus_method_name((motus_method)m), dims,
                                strided ? "structs" : "arrays", count, motus_result_string(r));
                        motus_test_failures++;
                    }
                    /* Pulled towards the origin. */
                    if (!(strided ? (dims == 3 ? p3[count - 1].velocity.x < 0 : p2[count - 1].velocity.x < 0)
                                  : v[0][count - 1] < 0)) {
                        fprintf(stderr, "  %s, %dD, %s, count %d: not pulled (vx %g)\n", motus_method_name((motus_method)m),
                                dims, strided ? "structs" : "arrays", count,
                                strided ? (dims == 3 ? (double)p3[count - 1].velocity.x : (double)p2[count - 1].velocity.x)
                                        : (double)v[0][count - 1]);
                        motus_test_failures++;
                    }
                }
    /* A particle exactly at the attractor: no pull, no NaN. */
    {
        motus_real x[2] = {0, 1}, y[2] = {0, 0}, vx[2] = {0, 0}, vy[2] = {0, 0};
        motus_scene scene;
        motus_state state;
        memset(&scene, 0, sizeof scene);
        memset(&state, 0, sizeof state);
        scene.attractor_strength = 1;
        state.count = 2;
        state.position[0] = x, state.position[1] = y, state.velocity[0] = vx, state.velocity[1] = vy;
        ENSURE_EQ_INT(motus_step(&scene, &state, MOTUS_R(0.01), NULL, 0), MOTUS_OK);
        ENSURE(x[0] == 0 && vx[0] == 0 && vy[0] == 0 && vx[1] < 0);
    }
}

TEST(tether_names_its_fields_and_takes_signed_zeros) {
    /* The report names the tether's field; a stiffness of -0 is no tether (not negative), and a tether at
       -0 pulls as one at +0: the same bits. */
    motus_real x[2] = {1, -2}, y[2] = {3, MOTUS_R(0.5)}, vx[2] = {0, 1}, vy[2] = {0, 0};
    motus_real x2[2] = {1, -2}, y2[2] = {3, MOTUS_R(0.5)}, vx2[2] = {0, 1}, vy2[2] = {0, 0};
    motus_check_report report;
    motus_scene scene;
    motus_state state, other;
    memset(&scene, 0, sizeof scene);
    memset(&state, 0, sizeof state);
    state.count = 2;
    state.position[0] = x, state.position[1] = y, state.velocity[0] = vx, state.velocity[1] = vy;
    other = state;
    other.position[0] = x2, other.position[1] = y2, other.velocity[0] = vx2, other.velocity[1] = vy2;
    scene.tether.y = not_a_number();
    scene.tether_stiffness = 2;
    ENSURE_EQ_INT(motus_scene_check(&scene, 2, 2, &report), MOTUS_ERROR_NOT_FINITE);
    ENSURE(strcmp(report.field_name, "scene.tether.y") == 0);
    scene.tether.y = 0;
    scene.tether.z = infinity(); /* z is not read in 2D */
    ENSURE_EQ_INT(motus_scene_check(&scene, 2, 2, &report), MOTUS_OK);
    ENSURE_EQ_INT(motus_scene_check(&scene, 3, 2, &report), MOTUS_ERROR_NOT_FINITE);
    ENSURE(strcmp(report.field_name, "scene.tether.z") == 0);
    scene.tether.z = 0;
    scene.tether_stiffness = -1;
    ENSURE_EQ_INT(motus_step(&scene, &state, MOTUS_R(0.1), NULL, 0), MOTUS_ERROR_INVALID_TETHER);
    ENSURE_EQ_INT(motus_scene_check(&scene, 2, 2, &report), MOTUS_ERROR_INVALID_TETHER);
    ENSURE(strcmp(report.field_name, "scene.tether_stiffness") == 0);
    ENSURE(x[0] == 1 && vx[1] == 1); /* nothing written */
    scene.tether_stiffness = -MOTUS_R(0.0);
    ENSURE_EQ_INT(motus_step(&scene, &state, MOTUS_R(0.1), NULL, 0), MOTUS_OK);
    ENSURE(vx[0] == 0 && vy[0] == 0 && x[1] == -2 + MOTUS_R(0.1)); /* no pull */
    scene.tether_stiffness = 2;
    scene.tether = motus_v3(MOTUS_R(0.0), MOTUS_R(0.0), 0);
    ENSURE_EQ_INT(motus_step(&scene, &state, MOTUS_R(0.1), NULL, 0), MOTUS_OK);
    scene.tether = motus_v3(-MOTUS_R(0.0), -MOTUS_R(0.0), 0);
    ENSURE_EQ_INT(motus_step(&scene, &other, MOTUS_R(0.0), NULL, 0), MOTUS_OK);
    scene.tether_stiffness = -MOTUS_R(0.0);
    ENSURE_EQ_INT(motus_step(&scene, &other, MOTUS_R(0.1), NULL, 0), MOTUS_OK);
    scene.tether_stiffness = 2;
    ENSURE_EQ_INT(motus_step(&scene, &other, MOTUS_R(0.1), NULL, 0), MOTUS_OK);
    ENSURE(memcmp(x, x2, sizeof x) == 0 && memcmp(y, y2, sizeof y) == 0);
    ENSURE(memcmp(vx, vx2, sizeof vx) == 0 && memcmp(vy, vy2, sizeof vy) == 0);
    ENSURE(vx[0] < 0 && vy[0] < 0); /* pulled towards the origin */
}

/* =================================================================================================
   motus_particles_check / motus_particles3_check and the messages
   ================================================================================================= */
TEST(particles_check_finds_the_first_bad_particle_and_field) {
    int pattern, i, k, b, dims;
    for (pattern = 0; pattern < 2; ++pattern)
        for (dims = 2; dims <= 3; ++dims) {
#define CHECK_PARTICLES(n, report)                                                                            \
    (dims == 2 ? motus_particles_check(W.particles, n, report) : motus_particles3_check(W.particles3, n, report))
            setup(PATTERNS[pattern], MOTUS_SEMI_IMPLICIT_EULER);
            EXPECT(MOTUS_OK, "valid", CHECK_PARTICLES(CAPACITY, &W.report));
            ENSURE(W.report.index == -1 && W.report.field == MOTUS_FIELD_NONE && W.report.component == -1);
            ENSURE(strcmp(W.report.field_name, "none") == 0);
            EXPECT(MOTUS_OK, "no report", CHECK_PARTICLES(CAPACITY, NULL));
            EXPECT(MOTUS_OK, "count 0", motus_particles_check(NULL, 0, &W.report));
            EXPECT(MOTUS_OK, "count 0", motus_particles3_check(NULL, 0, &W.report));
            EXPECT(MOTUS_ERROR_NULL_POINTER, "NULL", motus_particles_check(NULL, 1, &W.report));
            ENSURE(W.report.index == -1 && W.report.field_name != NULL); /* filled even then */
            EXPECT(MOTUS_ERROR_NULL_POINTER, "NULL", motus_particles3_check(NULL, INT_MAX, &W.report));
            EXPECT(MOTUS_ERROR_INVALID_COUNT, "count -1", CHECK_PARTICLES(-1, &W.report));
            EXPECT(MOTUS_ERROR_INVALID_COUNT, "count INT_MIN", CHECK_PARTICLES(INT_MIN, NULL));
            for (i = 0; i < CAPACITY; ++i)
                for (k = 0; k < field_count(dims); ++k)
                    for (b = 0; b <= BAD_REALS; ++b) {
                        const motus_field field = field_kind(dims, k);
                        motus_result expected;
                        char what[64];
                        if (b == BAD_REALS && field != MOTUS_FIELD_INVERSE_MASS) continue;
                        *field_of(dims, i, k) = b == BAD_REALS ? MOTUS_R(-0.5) : bad_real(b);
                        expected = dims == 2 ? motus_particle_check(&W.particles[i]) : motus_particle3_check(&W.particles3[i]);
                        ENSURE(expected != MOTUS_OK);
                        /* A later particle with another bad field does not hide the first. */
                        if (i + 1 < CAPACITY) *field_of(dims, i + 1, 0) = not_a_number();
                        sprintf(what, "%dD particle %d field %d", dims, i, k);
                        memcpy(&CLEAN, &W, sizeof W);
                        EXPECT(expected, what, CHECK_PARTICLES(CAPACITY, &W.report));
                        ENSURE_EQ_INT(W.report.index, i);
                        ENSURE_EQ_INT(W.report.field, field);
                        ENSURE_EQ_INT(W.report.component, field == MOTUS_FIELD_INVERSE_MASS ? -1 : k % dims);
                        ENSURE(strcmp(W.report.field_name, motus_field_name(field)) == 0);
                        /* The range before it is fine. */
                        EXPECT(MOTUS_OK, what, CHECK_PARTICLES(i, &W.report));
                        setup(PATTERNS[pattern], MOTUS_SEMI_IMPLICIT_EULER);
                    }
            /* Two bad fields in one particle: the first in the documented order. */
            *field_of(dims, 2, 3 * dims) = -1;
            *field_of(dims, 2, 3 * dims - 1) = infinity();
            *field_of(dims, 2, dims + 1) = not_a_number();
            memcpy(&CLEAN, &W, sizeof W);
            EXPECT(MOTUS_ERROR_NOT_FINITE, "velocity before force and mass", CHECK_PARTICLES(CAPACITY, &W.report));
            ENSURE(W.report.index == 2 && W.report.field == MOTUS_FIELD_VELOCITY && W.report.component == 1);
#undef CHECK_PARTICLES
        }
}

TEST(field_names_and_messages) {
    int i, j;
    ENSURE(strcmp(motus_field_name(MOTUS_FIELD_POSITION), "position") == 0);
    ENSURE(strcmp(motus_field_name(MOTUS_FIELD_INVERSE_MASS), "inverse_mass") == 0);
    ENSURE(strcmp(motus_field_name(MOTUS_FIELD_COUNT), "unknown motus_field value") == 0); /* never NULL */
    ENSURE(strcmp(motus_field_name((motus_field)-1), "unknown motus_field value") == 0);
    for (i = 0; i < MOTUS_FIELD_COUNT; ++i) ENSURE(motus_field_name((motus_field)i) != NULL);
    /* Every code has its own sentence, long enough to say what was wrong and what is expected. */
    for (i = 1; i < MOTUS_RESULT_COUNT; ++i) {
        const char *message = motus_result_string((motus_result)i);
        ENSURE(message != NULL && strlen(message) >= 20);
        for (j = 0; j < i; ++j) ENSURE(strcmp(message, motus_result_string((motus_result)j)) != 0);
    }
    ENSURE(strcmp(motus_result_string((motus_result)-1), "unknown motus_result value") == 0);
    ENSURE(strcmp(motus_result_string(MOTUS_RESULT_COUNT), "unknown motus_result value") == 0);
    ENSURE(strcmp(motus_result_string((motus_result)INT_MAX), "unknown motus_result value") == 0);
}

static const motus_test_case TESTS[] = {
    TEST_CASE(particle_init_rejects_everything_bad),
    TEST_CASE(particle_functions_reject_everything_bad),
    TEST_CASE(particle_bounce_rejects_bad_boxes),
    TEST_CASE(method_functions_reject_everything_bad),
    TEST_CASE(clock_rejects_everything_bad),
    TEST_CASE(every_bad_scene_is_refused_by_every_function),
    TEST_CASE(scene_walls_at_infinity),
    TEST_CASE(every_bad_state_shape_is_refused),
    TEST_CASE(bad_time_steps_and_dt_zero),
    TEST_CASE(scratch_too_small_or_misaligned),
    TEST_CASE(ranges_and_counts),
    TEST_CASE(bad_particle_data),
    TEST_CASE(state_check_order_and_unread_fields),
    TEST_CASE(immovable_bad_force),
    TEST_CASE(bad_data_reaching_other_particles),
    TEST_CASE(overflow_with_finite_data),
    TEST_CASE(attractor_at_the_origin_with_a_partial_vector),
    TEST_CASE(tether_names_its_fields_and_takes_signed_zeros),
    TEST_CASE(particles_check_finds_the_first_bad_particle_and_field),
    TEST_CASE(field_names_and_messages),
};

int main(int argc, char **argv) { return motus_test_main(argc, argv, TESTS, TEST_COUNT(TESTS)); }
