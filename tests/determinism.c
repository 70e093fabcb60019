/* Determinism: golden hashes of a 1000-particle scene after 10^5 steps, for every method of motus_stepper,
   for the batch kernels and for motus_particle_step, in float and in double (MOTUS_DOUBLE); and the
   paths that can run the same scene agree bit for bit (batch = stepper + damp + bounce; motus_particle_step
   = batch). The hash is FNV-1a 64 of every position and velocity bit, particle by particle (x, y, vx, vy),
   as this little-endian host stores them.

   Each TEST(name) runs one path for 10^5 steps and compares the hashes after 500, 10^4 and 10^5 steps
   (CHECKPOINTS) with the golden values below. `determinism --matrix STEPS` runs every path for STEPS (one
   of CHECKPOINTS), prints one line per path and exits nonzero on any difference from the golden hashes or
   between twins: tests/determinism.sh builds this file with gcc and clang at -O0/-O2/-O3/-O3 -march=native
   as C and as C++ and runs that, so every build must print the golden hashes. For CI time (the family's
   budget is about 5 minutes on 2 cores) the -O0 builds run 500 steps and the optimised ones 10^4; the full
   10^5 runs in the build CMake makes (-ffp-contract=off, C99). The matrix builds use each compiler's
   default language mode and contraction setting (GNU C/C++, FMA contracted where allowed): what they
   check is that motus.h turns contraction off itself.

   The scene ("A"): 250 chains of 4 particles (masses 0.5, 1, 2, 4 kg; every 97th particle immovable but
   moving), springs along the chains (rest length 0.5 m: the square-root path) and from the first particle
   of every 5th chain to an anchor (rest length 0: the other path), gravity, linear drag, a per-particle
   force that changes every step (a game's input: values from a table, exact in float), then
   motus_particle_damp_per_step and motus_particle_bounce in a box. Spring damping c > k*h keeps explicit
   Euler and midpoint stable for 10^5 steps. The exact stepper runs it without the springs (it takes only
   gravity and linear drag). Scene "B" is what motus_particle_step can run: no gravity or drag term, the
   weight is part of the accumulated force (m*g is exact for these masses).

   Parameters reach the code through volatile reads, as run-time values do in a game: otherwise an
   optimising build may fold exp(-k*h) at compile time (correctly rounded, by MPFR) where -O0 calls libm.
   Only the exact stepper calls libm here (exp, once per step); if this libm's exp gives other bits than
   glibc's for that argument, its golden hashes are not compared (reported, not failed). */
#include "motus.h"
#include "support/motus_test.h"

#include <float.h>
#include <stdint.h>
#include <stdlib.h>

enum {
    COUNT = 1000,
    CHAIN = 4,
    CHAINS = COUNT / CHAIN,
    CHAIN_SPRINGS = CHAINS * (CHAIN - 1),
    ANCHORED = CHAINS / 5,
    SPRINGS = CHAIN_SPRINGS + ANCHORED,
    KICKS = 64,
    SPLIT = 333 /* the batch steps two ranges, split off a vector boundary */
};
enum { CHECKPOINT_COUNT = 3 };
static const long CHECKPOINTS[CHECKPOINT_COUNT] = {500, 10000, 100000};
#define FULL_STEPS 100000L

/* ---- the paths ---------------------------------------------------------------------------------- */
enum { STEPPER, BATCH, PARTICLE };
typedef struct path {
    const char *name;
    int kind;             /* STEPPER (motus_stepper_step), BATCH (motus_batch_step), PARTICLE (motus_particle_step) */
    motus_method method;  /* the stepper's, or the batch scene's */
    int scene_b;          /* weight in the force instead of a gravity term; no drag term */
    int twin;             /* index of the path that must end in the same state, or -1 */
    int uses_libm;        /* exp: golden hashes depend on the libm */
} path;

static const path PATHS[] = {
    {"semi_implicit_euler", STEPPER, MOTUS_SEMI_IMPLICIT_EULER, 0, -1, 0},
    {"explicit_euler", STEPPER, MOTUS_EXPLICIT_EULER, 0, -1, 0},
    {"position_verlet", STEPPER, MOTUS_POSITION_VERLET, 0, -1, 0},
    {"velocity_verlet", STEPPER, MOTUS_VELOCITY_VERLET, 0, -1, 0},
    {"leapfrog", STEPPER, MOTUS_LEAPFROG, 0, -1, 0},
    {"midpoint", STEPPER, MOTUS_MIDPOINT, 0, -1, 0},
    {"rk4", STEPPER, MOTUS_RK4, 0, -1, 0},
    {"forest_ruth", STEPPER, MOTUS_FOREST_RUTH, 0, -1, 0},
    {"exact_linear_drag", STEPPER, MOTUS_EXACT_LINEAR_DRAG, 0, -1, 1},
    {"batch_semi_implicit_euler", BATCH, MOTUS_SEMI_IMPLICIT_EULER, 0, 0, 0},
    {"batch_explicit_euler", BATCH, MOTUS_EXPLICIT_EULER, 0, 1, 0},
    {"particle_step_b", PARTICLE, MOTUS_SEMI_IMPLICIT_EULER, 1, -1, 0},
    {"batch_semi_implicit_euler_b", BATCH, MOTUS_SEMI_IMPLICIT_EULER, 1, 11, 0},
};
enum { PATH_COUNT = (int)(sizeof PATHS / sizeof PATHS[0]) };

/* Golden hashes at each of CHECKPOINTS, in the order of PATHS (x86-64, glibc 2.36). A twin's are its
   twin's. */
#ifdef MOTUS_DOUBLE
static const uint64_t GOLDEN[CHECKPOINT_COUNT][PATH_COUNT] = {
    {0xdd7d82b897b3a268ull, 0x96fb6ce029693d40ull, 0xdee894ae3af97768ull,
     0x9494bc4c34baa192ull, 0x2f1e5f4596f07c38ull, 0x30b46e33404ba3a2ull,
     0xfc542b9415d06796ull, 0x03ee960ce359f8daull, 0xa307f9647abbf9eeull,
     0xdd7d82b897b3a268ull, 0x96fb6ce029693d40ull, 0xd17ac9fb9de6e8cdull,
     0xd17ac9fb9de6e8cdull},
    {0x9d938966c242f8e2ull, 0x44f78183940c1cdcull, 0xcd49d017eaa6612bull,
     0x1b71cb1085676dfcull, 0x932c507782e91efdull, 0x49c355f53d5bc9c2ull,
     0xf9e769a102eea22aull, 0x384c720d0ece1f6bull, 0x50c39028b93614c5ull,
     0x9d938966c242f8e2ull, 0x44f78183940c1cdcull, 0x20817ea90239a9d6ull,
     0x20817ea90239a9d6ull},
    {0x063f507631d191faull, 0xeb0ba746ef71a002ull, 0xaf13c2950027e043ull,
     0x5af6f9632db67c3cull, 0xd8cd93469158fdd8ull, 0xb79d025ba002915eull,
     0xea98e6b9e41172b8ull, 0x2faf76dd509a5bfdull, 0x15cd2766c2ab71edull,
     0x063f507631d191faull, 0xeb0ba746ef71a002ull, 0x2a0fff2096d6f3f4ull,
     0x2a0fff2096d6f3f4ull},
};
static const uint64_t GLIBC_EXP_BITS = 0x3fefddf00bbd0dacull; /* the bits of exp(-drag*h) */
#else
static const uint64_t GOLDEN[CHECKPOINT_COUNT][PATH_COUNT] = {
    {0x49aa54a95ce145e8ull, 0xfa4541f74edda31dull, 0x5079d76934c7b5afull,
     0x06d137b1212ba138ull, 0x7ed92514785e0821ull, 0xe4cc9a2472a8a912ull,
     0x376c4c8d8ca75e17ull, 0x0980374a852e2f45ull, 0x7aaf8018e4b6c91full,
     0x49aa54a95ce145e8ull, 0xfa4541f74edda31dull, 0x80f8b8027b460227ull,
     0x80f8b8027b460227ull},
    {0x0dd112947b8c2f7cull, 0xa64547c43cdfa1dfull, 0x5f4d41af6589a1e6ull,
     0x2db46882448be4c7ull, 0x4a4ec45a32c5d7a9ull, 0x538a38612ad434cdull,
     0x3adaa98ac01d28c3ull, 0x8db105dc67cd3cf7ull, 0x6b6e5adcf9eea3b3ull,
     0x0dd112947b8c2f7cull, 0xa64547c43cdfa1dfull, 0xccd2331d0686bcb3ull,
     0xccd2331d0686bcb3ull},
    {0x4fc242e166f0ab30ull, 0xb992cdbd352fc1eeull, 0xc54b6e71dcdc3fa7ull,
     0x531538b259d79a29ull, 0x8ff1e56839696075ull, 0x647f40756fda2fe5ull,
     0x1758d702bb143f85ull, 0x2de9f033b615db32ull, 0x6f19cef7e4421f5full,
     0x4fc242e166f0ab30ull, 0xb992cdbd352fc1eeull, 0x9a9c253a087200d0ull,
     0x9a9c253a087200d0ull},
};
static const uint64_t GLIBC_EXP_BITS = 0x3f7eef80ull;
#endif

/* ---- the scene ------------------------------------------------------------------------------------ */
typedef struct parameters {
    motus_real h, gravity, linear_drag, stiffness, spring_damping, damping, restitution;
    motus_vec2 bounds_min, bounds_max;
} parameters;

/* A value the compiler cannot see: the scene's numbers arrive at run time, as in a game. */
static motus_real at_run_time(double value) {
    volatile double hidden = value;
    return (motus_real)hidden;
}

static parameters scene_parameters(void) {
    parameters p;
    p.h = at_run_time(1.0 / 60.0);
    p.gravity = at_run_time(-9.75); /* times 0.5, 1, 2, 4 kg: exact weights for scene B */
    p.linear_drag = at_run_time(0.25);
    p.stiffness = at_run_time(20.0);
    p.spring_damping = at_run_time(1.0); /* > stiffness*h = 0.33: explicit Euler stable on every spring mode */
    p.damping = at_run_time(0.9995);
    p.restitution = at_run_time(0.75);
    p.bounds_min = motus_v2(at_run_time(-20.0), at_run_time(-15.0));
    p.bounds_max = motus_v2(at_run_time(20.0), at_run_time(15.0));
    return p;
}

/* Everything a run touches, static: about 200 KB. */
typedef struct world {
    motus_particle particles[COUNT];
    motus_real x[2][COUNT], v[2][COUNT], f[2][COUNT], inverse_mass[COUNT];
    motus_real weight[COUNT];
    motus_spring springs[SPRINGS];
    motus_vec2 scratch[7 * COUNT];
    motus_real kick[KICKS];
} world;
static world W;

/* Multiples of 1/4 in [-2, 2]: exact in float, so the forces are the same bits in every build. */
static void make_kicks(void) {
    int j;
    for (j = 0; j < KICKS; ++j) W.kick[j] = (motus_real)((j * 37) % 17 - 8) * MOTUS_R(0.25);
}
static motus_real kick_x(long step, int i) { return W.kick[(step * 13 + i * 7) & (KICKS - 1)]; }
static motus_real kick_y(long step, int i) { return W.kick[(step * 5 + i * 11) & (KICKS - 1)]; }

/* The initial state, in both layouts. Values are small multiples of powers of two: exact in float. */
static void make_world(const parameters *p) {
    static const motus_real inverse_masses[4] = {2, 1, MOTUS_R(0.5), MOTUS_R(0.25)};
    int c, j, i, s = 0;
    memset(&W.particles, 0, sizeof W.particles);
    memset(W.springs, 0, sizeof W.springs);
    make_kicks();
    for (c = 0; c < CHAINS; ++c)
        for (j = 0; j < CHAIN; ++j) {
            motus_particle *q;
            i = c * CHAIN + j;
            q = &W.particles[i];
            q->position = motus_v2((motus_real)(c % 25) * MOTUS_R(1.5) - 18 + (motus_real)j * MOTUS_R(0.5),
                                   (motus_real)(c / 25) * MOTUS_R(2.5) - 12);
            q->velocity = motus_v2((motus_real)((i * 5) % 9 - 4) * MOTUS_R(0.125), (motus_real)((i * 3) % 7 - 3) * MOTUS_R(0.25));
            q->inverse_mass = inverse_masses[(i * 7) % 4];
            if (i % 97 == 13) { /* immovable, but moving: it bounces around the box and pulls its chain */
                q->inverse_mass = 0;
                q->velocity = motus_v2(3, MOTUS_R(1.5));
            }
            /* m*g, exact: -4.875, -9.75, -19.5 or -39 N (nothing for an immovable particle) */
            W.weight[i] = q->inverse_mass != 0 ? p->gravity / q->inverse_mass : 0;
            W.x[0][i] = q->position.x, W.x[1][i] = q->position.y;
            W.v[0][i] = q->velocity.x, W.v[1][i] = q->velocity.y;
            W.inverse_mass[i] = q->inverse_mass;
            if (j > 0) {
                W.springs[s].a = i - 1, W.springs[s].b = i;
                W.springs[s].rest_length = MOTUS_R(0.5);
                W.springs[s].stiffness = p->stiffness, W.springs[s].damping = p->spring_damping;
                ++s;
            }
        }
    for (c = 0; c < CHAINS; c += 5) {
        const motus_particle *q = &W.particles[c * CHAIN];
        W.springs[s].a = c * CHAIN, W.springs[s].b = -1;
        W.springs[s].anchor = motus_v2(q->position.x, q->position.y + 2);
        W.springs[s].stiffness = p->stiffness, W.springs[s].damping = p->spring_damping;
        ++s;
    }
}

/* ---- the hash --------------------------------------------------------------------------------------- */
static uint64_t fnv1a(uint64_t hash, const void *data, size_t size) {
    const unsigned char *bytes = (const unsigned char *)data;
    size_t i;
    for (i = 0; i < size; ++i) hash = (hash ^ bytes[i]) * 1099511628211ull;
    return hash;
}

static uint64_t hash_state(int kind) {
    uint64_t hash = 14695981039346656037ull;
    int i;
    for (i = 0; i < COUNT; ++i) {
        motus_real state[4];
        if (kind == BATCH) {
            state[0] = W.x[0][i], state[1] = W.x[1][i], state[2] = W.v[0][i], state[3] = W.v[1][i];
        } else {
            const motus_particle *q = &W.particles[i];
            state[0] = q->position.x, state[1] = q->position.y, state[2] = q->velocity.x, state[3] = q->velocity.y;
        }
        hash = fnv1a(hash, state, sizeof state);
    }
    return hash;
}

/* ---- the runs --------------------------------------------------------------------------------------- */
/* The forces a game adds this step: the kick, and in scene B the weight. */
static void set_force_arrays(long step, int scene_b) {
    int i;
    for (i = 0; i < COUNT; ++i) {
        W.f[0][i] = kick_x(step, i);
        W.f[1][i] = scene_b ? kick_y(step, i) + W.weight[i] : kick_y(step, i);
    }
}

/* Runs `path` from the initial state for `steps` steps; the hash at each of CHECKPOINTS reached (0 for
   the others). Returns the number of calls that did not return MOTUS_OK (0 expected). */
static long run_path(const path *run, long steps, uint64_t hashes[CHECKPOINT_COUNT]) {
    const parameters p = scene_parameters();
    motus_stepper stepper;
    motus_stepper_desc desc;
    motus_forces forces;
    motus_scene scene;
    motus_batch batch;
    long step, errors = 0;
    int i, d, c;
    make_world(&p);
    memset(&stepper, 0, sizeof stepper);
    memset(&desc, 0, sizeof desc);
    memset(&forces, 0, sizeof forces);
    memset(&scene, 0, sizeof scene);
    memset(&batch, 0, sizeof batch);
    desc.capacity = COUNT;
    desc.method = run->method;
    desc.scratch = W.scratch;
    desc.scratch_bytes = sizeof W.scratch;
    if (run->kind == STEPPER && motus_stepper_init(&stepper, &desc) != MOTUS_OK) return steps;
    forces.gravity = motus_v2(0, p.gravity);
    forces.linear_drag = p.linear_drag;
    if (run->method != MOTUS_EXACT_LINEAR_DRAG) {
        forces.springs = W.springs;
        forces.spring_count = SPRINGS;
    }
    scene.has = MOTUS_HAS_FORCES | MOTUS_HAS_PARTICLE_MASS | MOTUS_HAS_DAMPING_PER_STEP | MOTUS_HAS_BOUNDS;
    if (!run->scene_b) scene.has |= MOTUS_HAS_GRAVITY | MOTUS_HAS_LINEAR_DRAG;
    scene.method = run->method;
    scene.gravity[1] = p.gravity;
    scene.linear_drag = p.linear_drag;
    scene.damping = p.damping;
    scene.bounds_min[0] = p.bounds_min.x, scene.bounds_min[1] = p.bounds_min.y;
    scene.bounds_max[0] = p.bounds_max.x, scene.bounds_max[1] = p.bounds_max.y;
    scene.restitution = p.restitution;
    batch.dimensions = 2;
    for (d = 0; d < 2; ++d) batch.position[d] = W.x[d], batch.velocity[d] = W.v[d], batch.force[d] = W.f[d];
    batch.inverse_mass = W.inverse_mass;

    for (c = 0; c < CHECKPOINT_COUNT; ++c) hashes[c] = 0;
    for (step = 0; step < steps; ++step) {
        if (run->kind == STEPPER) {
            for (i = 0; i < COUNT; ++i) W.particles[i].force = motus_v2(kick_x(step, i), kick_y(step, i));
            errors += motus_stepper_step(&stepper, W.particles, COUNT, &forces, p.h) != MOTUS_OK;
        } else if (run->kind == BATCH) {
            set_force_arrays(step, run->scene_b);
            errors += motus_batch_add_spring_forces(&batch, COUNT, W.springs, SPRINGS) != MOTUS_OK;
            errors += motus_batch_step(&scene, &batch, 0, SPLIT, p.h) != MOTUS_OK;
            errors += motus_batch_step(&scene, &batch, SPLIT, COUNT - SPLIT, p.h) != MOTUS_OK;
        } else { /* the springs are summed by the batch function, on a copy of the state in arrays */
            for (i = 0; i < COUNT; ++i) {
                W.x[0][i] = W.particles[i].position.x, W.x[1][i] = W.particles[i].position.y;
                W.v[0][i] = W.particles[i].velocity.x, W.v[1][i] = W.particles[i].velocity.y;
            }
            set_force_arrays(step, 1);
            errors += motus_batch_add_spring_forces(&batch, COUNT, W.springs, SPRINGS) != MOTUS_OK;
            for (i = 0; i < COUNT; ++i) {
                W.particles[i].force = motus_v2(W.f[0][i], W.f[1][i]);
                errors += motus_particle_step(&W.particles[i], p.h) != MOTUS_OK;
            }
        }
        if (run->kind != BATCH)
            for (i = 0; i < COUNT; ++i) {
                errors += motus_particle_damp_per_step(&W.particles[i], p.damping) != MOTUS_OK;
                errors += motus_particle_bounce(&W.particles[i], p.bounds_min, p.bounds_max, p.restitution) != MOTUS_OK;
            }
        for (c = 0; c < CHECKPOINT_COUNT; ++c)
            if (step + 1 == CHECKPOINTS[c]) hashes[c] = hash_state(run->kind);
    }
    return errors;
}

/* 0 if this libm's exp gives glibc's bits for the exact stepper's exp(-k*h). --exp-bits prints them. */
static int libm_differs(void) {
    const parameters p = scene_parameters();
    motus_real e = MOTUS_EXP(-p.linear_drag * p.h);
    uint64_t bits = 0;
    memcpy(&bits, &e, sizeof e);
    return bits != GLIBC_EXP_BITS;
}

static int path_index(const char *name) {
    int i;
    for (i = 0; i < PATH_COUNT; ++i)
        if (strcmp(PATHS[i].name, name) == 0) return i;
    return -1;
}

/* One path for FULL_STEPS against the golden hashes (and its twin's, which are the same). */
static void ensure_golden(const char *name) {
    const int index = path_index(name);
    const path *run = &PATHS[index];
    uint64_t hashes[CHECKPOINT_COUNT];
    const int compared = !(run->uses_libm && libm_differs());
    int c;
    ENSURE_EQ_INT(run_path(run, FULL_STEPS, hashes), 0);
    for (c = 0; c < CHECKPOINT_COUNT; ++c) {
        printf("%-28s after %6ld steps %016llx %s\n", name, CHECKPOINTS[c], (unsigned long long)hashes[c],
               !compared ? "(not compared: this libm's exp differs from glibc's)"
               : hashes[c] == GOLDEN[c][index] ? "ok" : "DIFFERS");
        if (compared && hashes[c] != GOLDEN[c][index]) {
            fprintf(stderr, "%s after %ld steps: expected %016llx\n", name, CHECKPOINTS[c],
                    (unsigned long long)GOLDEN[c][index]);
            motus_test_failures++;
        }
    }
}

TEST(semi_implicit_euler) { ensure_golden("semi_implicit_euler"); }
TEST(explicit_euler) { ensure_golden("explicit_euler"); }
TEST(position_verlet) { ensure_golden("position_verlet"); }
TEST(velocity_verlet) { ensure_golden("velocity_verlet"); }
TEST(leapfrog) { ensure_golden("leapfrog"); }
TEST(midpoint) { ensure_golden("midpoint"); }
TEST(rk4) { ensure_golden("rk4"); }
TEST(forest_ruth) { ensure_golden("forest_ruth"); }
TEST(exact_linear_drag) { ensure_golden("exact_linear_drag"); }
/* The batch kernels end where motus_stepper_step + damp + bounce end (same golden hashes). */
TEST(batch_semi_implicit_euler) { ensure_golden("batch_semi_implicit_euler"); }
TEST(batch_explicit_euler) { ensure_golden("batch_explicit_euler"); }
/* motus_particle_step ends where the batch kernel ends on scene B (both compared to the same hashes). */
TEST(particle_step_equals_batch) {
    ensure_golden("particle_step_b");
    ensure_golden("batch_semi_implicit_euler_b");
}

/* The golden table itself: a twin has its twin's hashes, the hashes are distinct otherwise (a scene that
   came to rest, or a path that ignored its method, would repeat one) and from one checkpoint to the next;
   and the scene stays in the box and keeps moving. */
TEST(golden_table_is_consistent) {
    int i, j, k;
    uint64_t hashes[CHECKPOINT_COUNT];
    motus_real fastest = 0;
    for (i = 0; i < PATH_COUNT; ++i) {
        if (PATHS[i].twin >= 0)
            for (k = 0; k < CHECKPOINT_COUNT; ++k) ENSURE(GOLDEN[k][i] == GOLDEN[k][PATHS[i].twin]);
        for (j = 0; j < i; ++j)
            if (PATHS[i].twin != j)
                for (k = 0; k < CHECKPOINT_COUNT; ++k) ENSURE(GOLDEN[k][i] != GOLDEN[k][j]);
        for (k = 1; k < CHECKPOINT_COUNT; ++k) ENSURE(GOLDEN[k][i] != GOLDEN[k - 1][i]); /* still changing */
    }
    ENSURE_EQ_INT(run_path(&PATHS[0], CHECKPOINTS[1], hashes), 0);
    for (i = 0; i < COUNT; ++i) {
        const motus_particle *q = &W.particles[i];
        motus_real speed = motus_vec2_length(q->velocity);
        ENSURE(q->position.x >= -20 && q->position.x <= 20 && q->position.y >= -15 && q->position.y <= 15);
        if (speed > fastest) fastest = speed;
    }
    printf("semi-implicit Euler after %ld steps: fastest particle %.3g m/s\n", CHECKPOINTS[1], (double)fastest);
    ENSURE(fastest > MOTUS_R(0.1) && fastest < 100); /* about 0.5 m/s: the kicks keep it moving */
}

/* --matrix STEPS: every path, one line each, compared with the golden hashes for that length. */
static int matrix(long steps) {
    uint64_t hash[PATH_COUNT];
    int i, which = -1, failed = 0, libm = libm_differs();
    for (i = 0; i < CHECKPOINT_COUNT; ++i)
        if (steps == CHECKPOINTS[i]) which = i;
    if (which < 0) {
        fprintf(stderr, "--matrix takes %ld, %ld or %ld steps\n", CHECKPOINTS[0], CHECKPOINTS[1], CHECKPOINTS[2]);
        return 2;
    }
    printf("%ld steps (FLT_EVAL_METHOD %d)\n", steps, (int)FLT_EVAL_METHOD);
    for (i = 0; i < PATH_COUNT; ++i) {
        uint64_t hashes[CHECKPOINT_COUNT], end;
        long errors = run_path(&PATHS[i], steps, hashes);
        end = hashes[which];
        const int compared = !(PATHS[i].uses_libm && libm);
        hash[i] = end;
        printf("%-28s %016llx %s\n", PATHS[i].name, (unsigned long long)end,
               errors ? "ERRORS" : !compared ? "(libm differs: not compared)" : end == GOLDEN[which][i] ? "ok" : "DIFFERS");
        failed |= errors != 0 || (compared && end != GOLDEN[which][i]);
        if (PATHS[i].twin >= 0 && hash[PATHS[i].twin] != end) {
            printf("  differs from %s\n", PATHS[PATHS[i].twin].name);
            failed = 1;
        }
    }
    return failed;
}

/* --golden: the tables above, from this build (to update them after a deliberate change of results). */
static int print_golden(void) {
    static uint64_t table[PATH_COUNT][CHECKPOINT_COUNT];
    const parameters p = scene_parameters();
    motus_real e = MOTUS_EXP(-p.linear_drag * p.h);
    uint64_t bits = 0;
    long errors = 0;
    int i, c;
    for (i = 0; i < PATH_COUNT; ++i) errors += run_path(&PATHS[i], FULL_STEPS, table[i]);
    printf("static const uint64_t GOLDEN[CHECKPOINT_COUNT][PATH_COUNT] = {\n");
    for (c = 0; c < CHECKPOINT_COUNT; ++c) {
        printf("    {");
        for (i = 0; i < PATH_COUNT; ++i)
            printf("%s0x%016llxull", i == 0 ? "" : i % 3 == 0 ? ",\n     " : ", ", (unsigned long long)table[i][c]);
        printf("},\n");
    }
    memcpy(&bits, &e, sizeof e);
    printf("};\nstatic const uint64_t GLIBC_EXP_BITS = 0x%llxull;\n", (unsigned long long)bits);
    return errors != 0;
}

static const motus_test_case TESTS[] = {
    TEST_CASE(semi_implicit_euler),
    TEST_CASE(explicit_euler),
    TEST_CASE(position_verlet),
    TEST_CASE(velocity_verlet),
    TEST_CASE(leapfrog),
    TEST_CASE(midpoint),
    TEST_CASE(rk4),
    TEST_CASE(forest_ruth),
    TEST_CASE(exact_linear_drag),
    TEST_CASE(batch_semi_implicit_euler),
    TEST_CASE(batch_explicit_euler),
    TEST_CASE(particle_step_equals_batch),
    TEST_CASE(golden_table_is_consistent),
};

int main(int argc, char **argv) {
    (void)motus_test_near; /* hashes are compared exactly here */
    if (argc > 2 && strcmp(argv[1], "--matrix") == 0) return matrix(strtol(argv[2], NULL, 10));
    if (argc > 1 && strcmp(argv[1], "--golden") == 0) return print_golden();
    return motus_test_main(argc, argv, TESTS, TEST_COUNT(TESTS));
}
