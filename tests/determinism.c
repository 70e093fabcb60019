/* Determinism: golden hashes of a 1000-particle scene after 500, 10^4 and 10^5 steps, in float and in double
   (MOTUS_DOUBLE), 2D and 3D: every method through motus_step (no coupling: all stages in registers), the
   coupled path (springs: staged passes over scratch) for three methods, collisions (scene.contacts) in 2D and
   3D, and a motus_particle_step loop; and
   the paths that run the same scene agree bit for bit (twins: a particle loop = the scene it equals, a range
   split = the whole, structs = plain arrays). The hash is FNV-1a 64 of every position and velocity bit,
   particle by particle (x, y[, z], vx, vy[, vz]), as this little-endian host stores them.

   Each TEST(name) runs its paths for 10^4 steps (CI time: the springs paths cost most) and compares the
   hashes after 500, 2000 and 10^4 of the
   steps (CHECKPOINTS) with the golden values below. `determinism --matrix STEPS` runs every path for STEPS (one
   of CHECKPOINTS), prints one line per path and exits nonzero on any difference from the golden hashes or
   between twins: tests/determinism.sh builds this file with gcc and clang at -O0/-O2/-O3/-O3 -march=native
   as C and as C++ and runs that, so every build must print the golden hashes. For CI time (the family's
   budget is about 5 minutes on 2 cores) the -O0 builds run 500 steps, -O2 and -O3 2000, -O3 -march=native
   10^4 (the springs paths, staged over scratch, cost most); the full 10^5 runs in the build CMake makes (-ffp-contract=off, C99). The matrix builds use each compiler's
   default language mode and contraction setting (GNU C/C++, FMA contracted where allowed): what they
   check is that motus.h turns contraction off itself. `determinism --golden` prints the tables.

   The scene: 250 chains of 4 particles (masses 0.5, 1, 2, 4 kg; every 97th particle immovable but moving),
   gravity, linear drag, a little quadratic drag, a weak attractor below the box (its pull: a square root
   and a division per particle), a per-particle force that changes every step (a game's input: values from
   a table, exact in float), damping per step and walls with restitution. The exact stepper runs it without
   quadratic drag and attractor (it takes neither). The coupled paths add springs along the chains (rest
   length 0.5 m: the square-root path) and from the first particle of every 5th chain to an anchor (rest
   length 0, every other one undamped: the -k*d path). The particle paths run what motus_particle_step can:
   no gravity or drag term, the weight is part of the accumulated force (m*g is exact for these masses),
   then motus_particle_bounce and motus_particle_damp_per_step; its twin is the scene with only walls and
   damping over the same structs. The contacts paths run the scene (no springs) with balls of 0.2 m that
   collide with each other and the walls (restitution 0.75, friction 0.3) and pile up on the floor.

   Parameters reach the code through volatile reads, as run-time values do in a game: otherwise an
   optimising build may fold exp(-k*h) at compile time (correctly rounded, by MPFR) where -O0 calls libm.
   Only the exact stepper calls libm here (exp, once per step); if this libm's exp gives other bits than
   glibc's for that argument, its golden hashes are not compared (reported, not failed). */
#define MOTUS_IMPLEMENTATION
#define MOTUS_STATIC
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
    SPLIT = 333, /* the range path steps two ranges, split off a vector boundary */
    CONTACT_SCRATCH_REALS = 128 * COUNT
};
enum { CHECKPOINT_COUNT = 4 };
static const long CHECKPOINTS[CHECKPOINT_COUNT] = {500, 2000, 10000, 100000};
#define FULL_STEPS 10000L /* the test build (the 10^5 column: `determinism --golden`, which runs them all) */

/* ---- the paths ---------------------------------------------------------------------------------- */
enum {
    SCENE,    /* motus_step over plain arrays, no coupling */
    RANGES,   /* motus_step_range over [0, SPLIT) and [SPLIT, COUNT) */
    STRUCTS,  /* motus_step over motus_particle / motus_particle3 structs */
    SPRUNG,   /* motus_step with the springs: the coupled path */
    PARTICLE, /* motus_particle_step + bounce + damp_per_step, weight in the force */
    PARTICLE_SCENE, /* the scene PARTICLE equals: walls and damping only, over the structs */
    CONTACTS, /* motus_step with collisions (scene.contacts): the broadphase, the solver, the support sweeps */
    TETHERED  /* SCENE with every particle tethered to a point (scene.tether: uncoupled, in registers) */
};
typedef struct path {
    const char *name;
    int kind;
    motus_method method;
    int dims;
    int twin;      /* index of the path that must end in the same state, or -1 */
    int uses_libm; /* exp: golden hashes depend on the libm */
} path;

static const path PATHS[] = {
    {"semi_implicit_euler_2d", SCENE, MOTUS_SEMI_IMPLICIT_EULER, 2, -1, 0},
    {"explicit_euler_2d", SCENE, MOTUS_EXPLICIT_EULER, 2, -1, 0},
    {"position_verlet_2d", SCENE, MOTUS_POSITION_VERLET, 2, -1, 0},
    {"velocity_verlet_2d", SCENE, MOTUS_VELOCITY_VERLET, 2, -1, 0},
    {"leapfrog_2d", SCENE, MOTUS_LEAPFROG, 2, -1, 0},
    {"midpoint_2d", SCENE, MOTUS_MIDPOINT, 2, -1, 0},
    {"rk4_2d", SCENE, MOTUS_RK4, 2, -1, 0},
    {"forest_ruth_2d", SCENE, MOTUS_FOREST_RUTH, 2, -1, 0},
    {"exact_linear_drag_2d", SCENE, MOTUS_EXACT_LINEAR_DRAG, 2, -1, 1},
    {"semi_implicit_euler_3d", SCENE, MOTUS_SEMI_IMPLICIT_EULER, 3, -1, 0},
    {"explicit_euler_3d", SCENE, MOTUS_EXPLICIT_EULER, 3, -1, 0},
    {"position_verlet_3d", SCENE, MOTUS_POSITION_VERLET, 3, -1, 0},
    {"velocity_verlet_3d", SCENE, MOTUS_VELOCITY_VERLET, 3, -1, 0},
    {"leapfrog_3d", SCENE, MOTUS_LEAPFROG, 3, -1, 0},
    {"midpoint_3d", SCENE, MOTUS_MIDPOINT, 3, -1, 0},
    {"rk4_3d", SCENE, MOTUS_RK4, 3, -1, 0},
    {"forest_ruth_3d", SCENE, MOTUS_FOREST_RUTH, 3, -1, 0},
    {"exact_linear_drag_3d", SCENE, MOTUS_EXACT_LINEAR_DRAG, 3, -1, 1},
    {"rk4_2d_ranges", RANGES, MOTUS_RK4, 2, 6, 0},
    {"forest_ruth_3d_structs", STRUCTS, MOTUS_FOREST_RUTH, 3, 16, 0},
    {"springs_semi_implicit_euler_2d", SPRUNG, MOTUS_SEMI_IMPLICIT_EULER, 2, -1, 0},
    {"springs_velocity_verlet_2d", SPRUNG, MOTUS_VELOCITY_VERLET, 2, -1, 0},
    {"springs_rk4_2d", SPRUNG, MOTUS_RK4, 2, -1, 0},
    {"springs_semi_implicit_euler_3d", SPRUNG, MOTUS_SEMI_IMPLICIT_EULER, 3, -1, 0},
    {"springs_velocity_verlet_3d", SPRUNG, MOTUS_VELOCITY_VERLET, 3, -1, 0},
    {"springs_rk4_3d", SPRUNG, MOTUS_RK4, 3, -1, 0},
    {"particle_step_2d", PARTICLE, MOTUS_SEMI_IMPLICIT_EULER, 2, -1, 0},
    {"particle_scene_2d", PARTICLE_SCENE, MOTUS_SEMI_IMPLICIT_EULER, 2, 26, 0},
    {"particle_step_3d", PARTICLE, MOTUS_SEMI_IMPLICIT_EULER, 3, -1, 0},
    {"particle_scene_3d", PARTICLE_SCENE, MOTUS_SEMI_IMPLICIT_EULER, 3, 28, 0},
    {"contacts_semi_implicit_euler_2d", CONTACTS, MOTUS_SEMI_IMPLICIT_EULER, 2, -1, 0},
    {"contacts_rk4_3d", CONTACTS, MOTUS_RK4, 3, -1, 0},
    {"tether_velocity_verlet_2d", TETHERED, MOTUS_VELOCITY_VERLET, 2, -1, 0},
    {"tether_forest_ruth_3d", TETHERED, MOTUS_FOREST_RUTH, 3, -1, 0},
};
enum { PATH_COUNT = (int)(sizeof PATHS / sizeof PATHS[0]) };

/* Golden hashes at each of CHECKPOINTS, in the order of PATHS (x86-64, glibc 2.36). A twin's are its
   twin's. */
#ifdef MOTUS_DOUBLE
static const uint64_t GOLDEN[CHECKPOINT_COUNT][PATH_COUNT] = {
    {0x2245a287bde1fc73ull, 0xfa0a2eb21c1dfaf0ull, 0xfe41dbd94426a201ull,
     0x7380254776523e2bull, 0xb3f1271ef07e108eull, 0xc3ed9cf5ce18e346ull,
     0x8e4ada53759451bbull, 0x7076ed7014316bc1ull, 0x3e134e02c3c61641ull,
     0xc5af7ba49c15a8f0ull, 0x3f8f8899566b2616ull, 0x5bd033439c4ea200ull,
     0x14666d2870fd8a4aull, 0xe9482f86af429fefull, 0xfb7950342dc797feull,
     0x592a7c1ef7374af6ull, 0x4380d7305b8a5c41ull, 0xd13c7d386208ed02ull,
     0x8e4ada53759451bbull, 0x4380d7305b8a5c41ull, 0x314b2a916a3c437bull,
     0x07c206bf4f727d0full, 0x01f7c280cf091412ull, 0x4f4d749254348d15ull,
     0x1e91685c47e47dceull, 0xe44131956f4800d1ull, 0x6c1e7671ee55c571ull,
     0x6c1e7671ee55c571ull, 0x1c6673fe7180dac5ull, 0x1c6673fe7180dac5ull,
     0x47c6ab461aa6c5d7ull, 0x8f4fe46b1c0b013eull, 0xedae4340a7291455ull,
     0x178bd1e262ae1f2bull},
    {0x748e753ba4ed629cull, 0x6816935358de3b6dull, 0x71b20d7285871b20ull,
     0xecdf3291c65fc07eull, 0x977a493f2b2f6e74ull, 0x17126869b47e02c6ull,
     0xb0fa032b1e0cd1adull, 0xcc2219e5d531748full, 0x0ce5a4294f32a2cfull,
     0x17b25bec552cbd87ull, 0x0669b5f5a53e754cull, 0xf3359cce9daaf243ull,
     0x50f9b87922060c9eull, 0x0c4d5093d4b57eb1ull, 0xccdec54d59e85783ull,
     0x917ec9e77b48f8e5ull, 0x1cf4cda6e3226254ull, 0x9fa36d0c2669452bull,
     0xb0fa032b1e0cd1adull, 0x1cf4cda6e3226254ull, 0x7e6d0057c5e6fe94ull,
     0x5f5454182569d60aull, 0x2531474a79e5c7b6ull, 0x35355f9e06a620d9ull,
     0x3f3208dd0295c0a2ull, 0xedfe01a00a2be911ull, 0x5798c5eba60367f8ull,
     0x5798c5eba60367f8ull, 0xab16cf8b206d2a81ull, 0xab16cf8b206d2a81ull,
     0xc6cf19dbdc584473ull, 0x3162310b7083983aull, 0x5c0ead12adb1484cull,
     0xdf1e88f1e573d22aull},
    {0x029ccf80dfacde26ull, 0xfdc8cda66a43e154ull, 0x55497e4ff73992b6ull,
     0x09a83519ea5e98f1ull, 0x0b3dc95aa583d300ull, 0xc431de9956c98cd4ull,
     0x718a25864c7a1d9dull, 0x56fdbe7c2dd4ecc7ull, 0x71fa7738cfbb0554ull,
     0xc9dc19990448fbe8ull, 0x5dd7a2eff65af57bull, 0x116d936150fe7428ull,
     0x72673d6675adbe8cull, 0x5c69830750eec87eull, 0x22201bc3d412f74dull,
     0x7de3417c665451cbull, 0x2e57b90271da5365ull, 0x96cbfc91c5591f0dull,
     0x718a25864c7a1d9dull, 0x2e57b90271da5365ull, 0x6903a41d7b2d02f8ull,
     0x49a6324200e10188ull, 0x97810bd194ccbd98ull, 0xaf6cd258eb7c18f4ull,
     0x51d9d55c9dfb8f06ull, 0x7cc41993bfd4ee1eull, 0x2620d062a3fa7931ull,
     0x2620d062a3fa7931ull, 0x0c088d445822724eull, 0x0c088d445822724eull,
     0xadd2a4e1ccdb4adfull, 0x756d4629383d0283ull, 0xc7076aa4db710196ull,
     0x6935cf542fada8bdull},
    {0x32aecd662021863full, 0x4ae1b00113eac12full, 0xd809808f21d04146ull,
     0x0f8b0e811b9cf209ull, 0x366da2862db4797cull, 0x9c728cb0a2d440f4ull,
     0xbe5c87f57af65c20ull, 0x7f7e2edc6bcb1fe9ull, 0xe34827ae41cd7195ull,
     0x80ad1c459fc6bd52ull, 0x94eab7cf3b3a6511ull, 0xe8c8c69c53389e1cull,
     0x2e1128b08e86071bull, 0xed27c2a95e140e5dull, 0xa9a9633d95d55764ull,
     0x2878fd90489af1dbull, 0x3c09f3743e4ec9dfull, 0xc657eb519a79f2e0ull,
     0xbe5c87f57af65c20ull, 0x3c09f3743e4ec9dfull, 0x6085dda4665cc327ull,
     0x16235fe6baa381acull, 0x9acb38a07088d818ull, 0xb2cbad9d8d7e1b20ull,
     0x4b403eaeacc5f1c8ull, 0xa20f8a01e4b73535ull, 0x4591d91e0487cfa3ull,
     0x4591d91e0487cfa3ull, 0x70f200851a682d37ull, 0x70f200851a682d37ull,
     0x4197ea8f9a271e23ull, 0x9f58d38e240f9b1dull, 0x234b8fbe01f1e2b1ull,
     0xc841341cfaf60664ull},
};
static const uint64_t GLIBC_EXP_BITS = 0x3fefddf00bbd0dacull;
#else
static const uint64_t GOLDEN[CHECKPOINT_COUNT][PATH_COUNT] = {
    {0x89af05b76df8ff89ull, 0xe0582ec43a5593b9ull, 0xb8013ea57bbc2401ull,
     0x4758f461c4e8359cull, 0x95804f1ffba4f370ull, 0x38b88560e7d1c7bcull,
     0x061339b7b249b16dull, 0x2f3c7cbd8e1f5473ull, 0xf3a1cbee9f8177c2ull,
     0xa7aede07fb0fcbedull, 0x3f99375d096646e3ull, 0xd54b897116b6c120ull,
     0x0c406d778f2f2d7bull, 0xd955aedc3232a083ull, 0xe2a328da84fe598bull,
     0xc1e95ca28d7f0fc0ull, 0x707d3dec07740166ull, 0xfd9ec5a74ef5eb65ull,
     0x061339b7b249b16dull, 0x707d3dec07740166ull, 0x1ba625d5bd114e58ull,
     0xaaebb6f961b9debaull, 0xd0bf4724f3b3bdf8ull, 0x6bc36789aac1dbadull,
     0xb17da7df79c75525ull, 0xdf60b31e1dc7165eull, 0x0060f97004c70802ull,
     0x0060f97004c70802ull, 0x470f9db34b62298aull, 0x470f9db34b62298aull,
     0x07aaaf524ea017a8ull, 0x3c1d99b27dc051d5ull, 0x21da8edbac091937ull,
     0xb63ebc709146c29eull},
    {0xfb25b7111e792068ull, 0x09fa7d5b46451f04ull, 0xcec758f6ab3d856eull,
     0xe28d3efe37f92a35ull, 0xa8898454fcef8513ull, 0xac50b691d0695095ull,
     0xdec28211a496d744ull, 0x995b596f9340fff6ull, 0x9076df96d8cb2158ull,
     0x18a23d87b2d79357ull, 0x37f66b46658a4180ull, 0xea33737c6ddf66abull,
     0x5eefb4e552a147d7ull, 0x0276b667ab27ff87ull, 0xe110a98c9f83a929ull,
     0x1248d783a42b6effull, 0x265348067bd88102ull, 0x45956fcdf10e3b00ull,
     0xdec28211a496d744ull, 0x265348067bd88102ull, 0x1571aaf0f4cce359ull,
     0x6a8a999e2849b4ecull, 0xbae139b160154323ull, 0xb75a63ff8e369b62ull,
     0xc6f0645152868b4eull, 0xfb1896760da6a75full, 0x6c0bb31aa9774eefull,
     0x6c0bb31aa9774eefull, 0xf4280c86e7d1bc30ull, 0xf4280c86e7d1bc30ull,
     0xf6507e4f6c38051eull, 0xf4575a9366d940d2ull, 0x31e6732079b846aeull,
     0x5827b53efce3a3e9ull},
    {0x394caae1e0a22c41ull, 0x514fde2e0177ac00ull, 0x256a490635bce549ull,
     0xbe602355ecabd32bull, 0x6ffa5db4f308848eull, 0x1f4948ea7a162766ull,
     0x31cb015a6a1c2c13ull, 0xe5896052957af91dull, 0x0910c24fa5046cebull,
     0xc5d8e69951f5f0ebull, 0x91e307cdcc452b14ull, 0x6c1c1eec790318caull,
     0xc00438652e941b62ull, 0x38c79ee8f8a67b92ull, 0x0937a4878b7a94d4ull,
     0xb8058256a071dc35ull, 0x9ac27062417614a9ull, 0x4e1d28010f4e980eull,
     0x31cb015a6a1c2c13ull, 0x9ac27062417614a9ull, 0x0cff139611f5596dull,
     0x8216bf7475acbae8ull, 0x8d7e1cf3b8f198e3ull, 0x8af1b0a07c909da8ull,
     0xdd2e1cb0918e3df0ull, 0xb90647ad52c37956ull, 0x37a4643247a7bb8full,
     0x37a4643247a7bb8full, 0xd82c85ee89ec0ab6ull, 0xd82c85ee89ec0ab6ull,
     0x40c80b3da366477cull, 0x9280cd9db435dc76ull, 0x7351d48dab1cd491ull,
     0xb422f703b9c1a298ull},
    {0x2d2d2d9b893c1b5dull, 0x5cabe8a1b89c2ef2ull, 0xd5d2c626930120aaull,
     0xe2c9b5452b5d74bfull, 0xc9d78cabca9354afull, 0xdbf1b442375307a0ull,
     0x71f3a9626392dfdcull, 0xb9fd3724f928aa88ull, 0x9c0552570a3b05bdull,
     0x01007566d6395fc7ull, 0x55dd9e2cab88b057ull, 0x7aed19ffe33aae14ull,
     0xe18476d2d7ac442cull, 0xd5349b9376615213ull, 0x526daa4912ece1a0ull,
     0xa240eef195904b72ull, 0x0576ccdc14e374afull, 0xfd1ff30ab5d63d00ull,
     0x71f3a9626392dfdcull, 0x0576ccdc14e374afull, 0xd6ab5b496fbacbe0ull,
     0x3f75cce652564852ull, 0x844987068c0039c7ull, 0x6d1d31dbd2b062fdull,
     0x3efadf68f89418b2ull, 0x083d726ad0ac8f6full, 0x4a7fa2d0dc5ae660ull,
     0x4a7fa2d0dc5ae660ull, 0x10a49eaecb4a9da9ull, 0x10a49eaecb4a9da9ull,
     0x9bada946d1c89ea7ull, 0xf547c7f20b2f80dbull, 0x6c807ea58d509359ull,
     0x72c9aa6ff59df249ull},
};
static const uint64_t GLIBC_EXP_BITS = 0x3f7eef80ull;
#endif

/* ---- the scene ------------------------------------------------------------------------------------ */
typedef struct parameters {
    motus_real h, gravity, linear_drag, quadratic_drag, attractor_y, attractor_strength, stiffness,
        spring_damping, damping, restitution, radius, friction, tether_stiffness;
    motus_vec3 bounds_min, bounds_max, tether;
} parameters;

/* A value the compiler cannot see: the scene's numbers arrive at run time, as in a game. */
static motus_real at_run_time(double value) {
    volatile double hidden = value;
    return (motus_real)hidden;
}

static parameters scene_parameters(void) {
    parameters p;
    p.h = at_run_time(1.0 / 60.0);
    p.gravity = at_run_time(-9.75); /* times 0.5, 1, 2, 4 kg: exact weights for the particle paths */
    p.linear_drag = at_run_time(0.25);
    p.quadratic_drag = at_run_time(0.01);
    p.attractor_y = at_run_time(-60.0); /* below the box: a smooth pull everywhere in it */
    p.attractor_strength = at_run_time(2000.0);
    p.stiffness = at_run_time(20.0);
    p.spring_damping = at_run_time(1.0);
    p.damping = at_run_time(0.0005); /* the fraction removed each step */
    p.restitution = at_run_time(0.75);
    p.radius = at_run_time(0.2);
    p.friction = at_run_time(0.3);
    p.tether_stiffness = at_run_time(3.0);
    p.tether = motus_v3(at_run_time(1.5), at_run_time(-2.0), at_run_time(0.5));
    p.bounds_min = motus_v3(at_run_time(-20.0), at_run_time(-15.0), at_run_time(-10.0));
    p.bounds_max = motus_v3(at_run_time(20.0), at_run_time(15.0), at_run_time(10.0));
    return p;
}

/* Everything a run touches, static: about 0.8 MB in float, 1.5 MB in double (mostly the contacts' scratch). */
typedef struct world {
    motus_particle particles[COUNT];
    motus_particle3 particles3[COUNT];
    motus_real x[3][COUNT], v[3][COUNT], f[3][COUNT], inverse_mass[COUNT];
    motus_real weight[COUNT];
    motus_spring springs[SPRINGS];
    /* 3D, RK4 with springs: (2 + 4 evaluations) * 3 reals a particle; contacts need more (the grid, the pairs) */
    motus_real scratch[CONTACT_SCRATCH_REALS];
    motus_real kick[KICKS];
} world;
static world W;

/* Multiples of 1/4 in [-2, 2]: exact in float, so the forces are the same bits in every build. */
static void make_kicks(void) {
    int j;
    for (j = 0; j < KICKS; ++j) W.kick[j] = (motus_real)((j * 37) % 17 - 8) * MOTUS_R(0.25);
}
static motus_real kick(long step, int i, int d) {
    static const int a[3] = {13, 5, 3}, b[3] = {7, 11, 17};
    return W.kick[(step * a[d] + i * b[d]) & (KICKS - 1)];
}

/* The initial state, in every layout. Values are small multiples of powers of two: exact in float. */
static void make_world(const parameters *p) {
    static const motus_real inverse_masses[4] = {2, 1, MOTUS_R(0.5), MOTUS_R(0.25)};
    int c, j, i, d, s = 0;
    memset(&W.particles, 0, sizeof W.particles);
    memset(&W.particles3, 0, sizeof W.particles3);
    memset(W.springs, 0, sizeof W.springs);
    memset(W.f, 0, sizeof W.f);
    make_kicks();
    for (c = 0; c < CHAINS; ++c)
        for (j = 0; j < CHAIN; ++j) {
            motus_real x[3], v[3], w;
            i = c * CHAIN + j;
            x[0] = (motus_real)(c % 25) * MOTUS_R(1.5) - 18 + (motus_real)j * MOTUS_R(0.5);
            x[1] = (motus_real)(c / 25) * MOTUS_R(2.5) - 12;
            x[2] = (motus_real)(c % 7) * MOTUS_R(2.5) - MOTUS_R(7.5);
            v[0] = (motus_real)((i * 5) % 9 - 4) * MOTUS_R(0.125);
            v[1] = (motus_real)((i * 3) % 7 - 3) * MOTUS_R(0.25);
            v[2] = (motus_real)((i * 7) % 5 - 2) * MOTUS_R(0.25);
            w = inverse_masses[(i * 7) % 4];
            if (i % 97 == 13) { /* immovable, but moving: it bounces around the box and pulls its chain */
                w = 0;
                v[0] = 3, v[1] = MOTUS_R(1.5), v[2] = MOTUS_R(0.5);
            }
            /* m*g, exact: -4.875, -9.75, -19.5 or -39 N (nothing for an immovable particle) */
            W.weight[i] = w != 0 ? p->gravity / w : 0;
            for (d = 0; d < 3; ++d) W.x[d][i] = x[d], W.v[d][i] = v[d];
            W.inverse_mass[i] = w;
            W.particles[i].position = motus_v2(x[0], x[1]);
            W.particles[i].velocity = motus_v2(v[0], v[1]);
            W.particles[i].inverse_mass = w;
            W.particles3[i].position = motus_v3(x[0], x[1], x[2]);
            W.particles3[i].velocity = motus_v3(v[0], v[1], v[2]);
            W.particles3[i].inverse_mass = w;
            if (j > 0) {
                W.springs[s].a = i - 1, W.springs[s].b = i;
                W.springs[s].rest_length = MOTUS_R(0.5);
                W.springs[s].stiffness = p->stiffness, W.springs[s].damping = p->spring_damping;
                ++s;
            }
        }
    for (c = 0; c < CHAINS; c += 5) {
        i = c * CHAIN;
        W.springs[s].a = i, W.springs[s].b = -1;
        W.springs[s].anchor = motus_v3(W.x[0][i], W.x[1][i] + 2, W.x[2][i]);
        W.springs[s].stiffness = p->stiffness;
        W.springs[s].damping = (c / 5) % 2 ? p->spring_damping : 0; /* rest length 0, undamped: -k*d */
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

static int in_structs(int kind) { return kind == STRUCTS || kind == PARTICLE || kind == PARTICLE_SCENE; }

static uint64_t hash_state(const path *run) {
    uint64_t hash = 14695981039346656037ull;
    int i, d;
    for (i = 0; i < COUNT; ++i) {
        motus_real state[6];
        if (!in_structs(run->kind))
            for (d = 0; d < run->dims; ++d) state[d] = W.x[d][i], state[run->dims + d] = W.v[d][i];
        else if (run->dims == 2) {
            const motus_particle *q = &W.particles[i];
            state[0] = q->position.x, state[1] = q->position.y, state[2] = q->velocity.x, state[3] = q->velocity.y;
        } else {
            const motus_particle3 *q = &W.particles3[i];
            state[0] = q->position.x, state[1] = q->position.y, state[2] = q->position.z;
            state[3] = q->velocity.x, state[4] = q->velocity.y, state[5] = q->velocity.z;
        }
        hash = fnv1a(hash, state, (size_t)(2 * run->dims) * sizeof(motus_real));
    }
    return hash;
}

/* ---- the runs --------------------------------------------------------------------------------------- */
/* The forces a game adds this step: the kick, and on the particle paths the weight. */
static void set_forces(const path *run, long step) {
    const int weight = run->kind == PARTICLE || run->kind == PARTICLE_SCENE;
    int i, d;
    for (i = 0; i < COUNT; ++i) {
        motus_real f[3];
        for (d = 0; d < 3; ++d) f[d] = kick(step, i, d);
        if (weight) f[1] = f[1] + W.weight[i];
        if (!in_structs(run->kind))
            for (d = 0; d < 3; ++d) W.f[d][i] = f[d];
        else if (run->dims == 2)
            W.particles[i].force = motus_v2(f[0], f[1]);
        else
            W.particles3[i].force = motus_v3(f[0], f[1], f[2]);
    }
}

static void make_scene(const path *run, const parameters *p, motus_scene *scene) {
    memset(scene, 0, sizeof *scene);
    scene->method = run->method;
    scene->damping_per_step = p->damping;
    scene->bounds_min = p->bounds_min;
    scene->bounds_max = p->bounds_max;
    scene->restitution = p->restitution;
    if (run->kind == PARTICLE_SCENE) return; /* walls and damping only: what the particle functions do */
    scene->gravity = motus_v3(0, p->gravity, 0);
    scene->linear_drag = p->linear_drag;
    if (run->method != MOTUS_EXACT_LINEAR_DRAG) {
        scene->quadratic_drag = p->quadratic_drag;
        scene->attractor = motus_v3(0, p->attractor_y, 0);
        scene->attractor_strength = p->attractor_strength;
    }
    if (run->kind == CONTACTS) { /* balls of 0.2 m: the chains' links (0.5 m apart) start clear of each other */
        scene->contacts.enabled = 1;
        scene->contacts.radius = p->radius;
        scene->contacts.restitution = p->restitution;
        scene->contacts.friction = p->friction;
    }
    if (run->kind == TETHERED) {
        scene->tether = p->tether;
        scene->tether_stiffness = p->tether_stiffness;
    }
    if (run->kind == SPRUNG) {
        scene->springs = W.springs;
        scene->spring_count = SPRINGS;
    }
}

/* Runs `run` from the initial state for `steps` steps; the hash at each of CHECKPOINTS reached (0 for
   the others). Returns the number of calls that did not return MOTUS_OK (0 expected). */
static long run_path(const path *run, long steps, uint64_t hashes[CHECKPOINT_COUNT]) {
    const parameters p = scene_parameters();
    const motus_vec2 lo2 = motus_v2(p.bounds_min.x, p.bounds_min.y), hi2 = motus_v2(p.bounds_max.x, p.bounds_max.y);
    motus_scene scene;
    motus_state state;
    size_t scratch_bytes;
    long step, errors = 0;
    int i, d, c;
    make_world(&p);
    make_scene(run, &p, &scene);
    if (in_structs(run->kind))
        state = run->dims == 2 ? motus_state_of_particles(W.particles, COUNT) : motus_state_of_particles3(W.particles3, COUNT);
    else {
        memset(&state, 0, sizeof state);
        state.dimensions = run->dims;
        state.count = COUNT;
        for (d = 0; d < run->dims; ++d) state.position[d] = W.x[d], state.velocity[d] = W.v[d], state.force[d] = W.f[d];
        state.inverse_mass = W.inverse_mass;
    }
    scratch_bytes = motus_scratch_size(&scene, &state);
    if (scratch_bytes > sizeof W.scratch) return steps;

    for (c = 0; c < CHECKPOINT_COUNT; ++c) hashes[c] = 0;
    for (step = 0; step < steps; ++step) {
        set_forces(run, step);
        if (run->kind == RANGES) {
            errors += motus_step_range(&scene, &state, 0, SPLIT, p.h) != MOTUS_OK;
            errors += motus_step_range(&scene, &state, SPLIT, COUNT - SPLIT, p.h) != MOTUS_OK;
        } else if (run->kind == PARTICLE) {
            for (i = 0; i < COUNT; ++i)
                if (run->dims == 2) {
                    errors += motus_particle_step(&W.particles[i], p.h) != MOTUS_OK;
                    errors += motus_particle_bounce(&W.particles[i], lo2, hi2, p.restitution) != MOTUS_OK;
                    errors += motus_particle_damp_per_step(&W.particles[i], p.damping) != MOTUS_OK;
                } else {
                    errors += motus_particle3_step(&W.particles3[i], p.h) != MOTUS_OK;
                    errors += motus_particle3_bounce(&W.particles3[i], p.bounds_min, p.bounds_max, p.restitution) != MOTUS_OK;
                    errors += motus_particle3_damp_per_step(&W.particles3[i], p.damping) != MOTUS_OK;
                }
        } else {
            errors += motus_step(&scene, &state, p.h, scratch_bytes ? W.scratch : NULL, scratch_bytes) != MOTUS_OK;
        }
        for (c = 0; c < CHECKPOINT_COUNT; ++c)
            if (step + 1 == CHECKPOINTS[c]) hashes[c] = hash_state(run);
    }
    return errors;
}

/* 0 if this libm's exp gives glibc's bits for the exact stepper's exp(-k*h). */
static int libm_differs(void) {
    const parameters p = scene_parameters();
    motus_real e = MOTUS_EXP(-(p.linear_drag * p.h));
    uint64_t bits = 0;
    memcpy(&bits, &e, sizeof e);
    return bits != GLIBC_EXP_BITS;
}

static int path_index(const char *name) {
    int i;
    for (i = 0; i < PATH_COUNT; ++i)
        if (strcmp(PATHS[i].name, name) == 0) return i;
    fprintf(stderr, "no path %s\n", name);
    exit(2);
}

/* One path for FULL_STEPS against the golden hashes (a twin's are its twin's). */
static void ensure_golden(const char *name) {
    const int index = path_index(name);
    const path *run = &PATHS[index];
    uint64_t hashes[CHECKPOINT_COUNT];
    const int compared = !(run->uses_libm && libm_differs());
    int c;
    ENSURE_EQ_INT(run_path(run, FULL_STEPS, hashes), 0);
    for (c = 0; c < CHECKPOINT_COUNT && CHECKPOINTS[c] <= FULL_STEPS; ++c) {
        printf("%-32s after %6ld steps %016llx %s\n", name, CHECKPOINTS[c], (unsigned long long)hashes[c],
               !compared ? "(not compared: this libm's exp differs from glibc's)"
               : hashes[c] == GOLDEN[c][index] ? "ok" : "DIFFERS");
        if (compared && hashes[c] != GOLDEN[c][index]) {
            fprintf(stderr, "%s after %ld steps: expected %016llx\n", name, CHECKPOINTS[c],
                    (unsigned long long)GOLDEN[c][index]);
            motus_test_failures++;
        }
    }
}
static void ensure_golden_2d_3d(const char *method) {
    char name[64];
    snprintf(name, sizeof name, "%s_2d", method);
    ensure_golden(name);
    snprintf(name, sizeof name, "%s_3d", method);
    ensure_golden(name);
}

TEST(semi_implicit_euler) { ensure_golden_2d_3d("semi_implicit_euler"); }
TEST(explicit_euler) { ensure_golden_2d_3d("explicit_euler"); }
TEST(position_verlet) { ensure_golden_2d_3d("position_verlet"); }
TEST(velocity_verlet) { ensure_golden_2d_3d("velocity_verlet"); }
TEST(leapfrog) { ensure_golden_2d_3d("leapfrog"); }
TEST(midpoint) { ensure_golden_2d_3d("midpoint"); }
TEST(rk4) { ensure_golden_2d_3d("rk4"); }
TEST(forest_ruth) { ensure_golden_2d_3d("forest_ruth"); }
TEST(exact_linear_drag) { ensure_golden_2d_3d("exact_linear_drag"); }
/* A range split and the structs end where the whole plain arrays end (same golden hashes). */
TEST(ranges_and_structs_equal_arrays) {
    ensure_golden("rk4_2d_ranges");
    ensure_golden("forest_ruth_3d_structs");
}
TEST(springs_semi_implicit_euler) { ensure_golden_2d_3d("springs_semi_implicit_euler"); }
TEST(springs_velocity_verlet) { ensure_golden_2d_3d("springs_velocity_verlet"); }
TEST(springs_rk4) { ensure_golden_2d_3d("springs_rk4"); }
/* motus_particle_step + bounce + damp ends where the scene with walls and damping ends. */
TEST(particle_step_equals_scene) {
    ensure_golden_2d_3d("particle_step");
    ensure_golden_2d_3d("particle_scene");
}
/* Collisions (issue 12: the pair order depends on the data only): a 2D scene by semi-implicit Euler and a
   3D one by RK4, the balls falling into piles on the floor. */
TEST(contacts) {
    ensure_golden("contacts_semi_implicit_euler_2d");
    ensure_golden("contacts_rk4_3d");
}
/* The tether (a term added after the tables above were first made: its own paths). */
TEST(tether) {
    ensure_golden("tether_velocity_verlet_2d");
    ensure_golden("tether_forest_ruth_3d");
}

/* The golden table itself: a twin has its twin's hashes, the hashes are distinct otherwise (a scene that
   came to rest, or a path that ignored its method or its springs, would repeat one) and from one
   checkpoint to the next; and the scene stays in the box and keeps moving. */
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
    for (i = 0; i < 2; ++i) { /* a 2D path, and a 3D one with springs */
        const path *run = &PATHS[path_index(i == 0 ? "semi_implicit_euler_2d" : "springs_rk4_3d")];
        fastest = 0;
        ENSURE_EQ_INT(run_path(run, CHECKPOINTS[2], hashes), 0);
        for (j = 0; j < COUNT; ++j) {
            motus_real speed2 = 0;
            for (k = 0; k < run->dims; ++k) {
                const motus_real lo[3] = {-20, -15, -10}, hi[3] = {20, 15, 10};
                ENSURE(W.x[k][j] >= lo[k] && W.x[k][j] <= hi[k]);
                speed2 += W.v[k][j] * W.v[k][j];
            }
            if (speed2 > fastest) fastest = speed2;
        }
        fastest = MOTUS_SQRT(fastest);
        printf("%s after %ld steps: fastest particle %.3g m/s\n", run->name, CHECKPOINTS[2], (double)fastest);
        ENSURE(fastest > MOTUS_R(0.1) && fastest < 100); /* the kicks keep it moving */
    }
}

/* --matrix STEPS: every path, one line each, compared with the golden hashes for that length. */
static int matrix(long steps) {
    uint64_t hash[PATH_COUNT];
    int i, which = -1, failed = 0, libm = libm_differs();
    for (i = 0; i < CHECKPOINT_COUNT; ++i)
        if (steps == CHECKPOINTS[i]) which = i;
    if (which < 0) {
        fprintf(stderr, "--matrix takes %ld, %ld, %ld or %ld steps\n", CHECKPOINTS[0], CHECKPOINTS[1], CHECKPOINTS[2],
                CHECKPOINTS[3]);
        return 2;
    }
    printf("%ld steps (FLT_EVAL_METHOD %d)\n", steps, (int)FLT_EVAL_METHOD);
    for (i = 0; i < PATH_COUNT; ++i) {
        uint64_t hashes[CHECKPOINT_COUNT], end;
        const long errors = run_path(&PATHS[i], steps, hashes);
        const int compared = !(PATHS[i].uses_libm && libm);
        end = hashes[which];
        hash[i] = end;
        printf("%-32s %016llx %s\n", PATHS[i].name, (unsigned long long)end,
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
    motus_real e = MOTUS_EXP(-(p.linear_drag * p.h));
    uint64_t bits = 0;
    long errors = 0;
    int i, c;
    for (i = 0; i < PATH_COUNT; ++i) errors += run_path(&PATHS[i], CHECKPOINTS[CHECKPOINT_COUNT - 1], table[i]);
    printf("static const uint64_t GOLDEN[CHECKPOINT_COUNT][PATH_COUNT] = {\n");
    for (c = 0; c < CHECKPOINT_COUNT; ++c) {
        printf("    {");
        for (i = 0; i < PATH_COUNT; ++i)
            printf("%s0x%016llxull", i == 0 ? "" : i % 3 == 0 ? ",\n     " : ", ", (unsigned long long)table[i][c]);
        printf("},\n");
    }
    memcpy(&bits, &e, sizeof e);
    printf("};\nstatic const uint64_t GLIBC_EXP_BITS = 0x%llxull;\n", (unsigned long long)bits);
    if (errors) fprintf(stderr, "%ld calls did not return MOTUS_OK\n", errors);
    return errors != 0;
}

/* --golden-path NAME: one path's column of the tables (a new path, without rerunning the others). */
static int print_golden_path(const char *name) {
    uint64_t hashes[CHECKPOINT_COUNT];
    const long errors = run_path(&PATHS[path_index(name)], CHECKPOINTS[CHECKPOINT_COUNT - 1], hashes);
    int c;
    for (c = 0; c < CHECKPOINT_COUNT; ++c)
        printf("%s after %ld steps: 0x%016llxull\n", name, CHECKPOINTS[c], (unsigned long long)hashes[c]);
    if (errors) fprintf(stderr, "%ld calls did not return MOTUS_OK\n", errors);
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
    TEST_CASE(ranges_and_structs_equal_arrays),
    TEST_CASE(springs_semi_implicit_euler),
    TEST_CASE(springs_velocity_verlet),
    TEST_CASE(springs_rk4),
    TEST_CASE(particle_step_equals_scene),
    TEST_CASE(contacts),
    TEST_CASE(tether),
    TEST_CASE(golden_table_is_consistent),
};

int main(int argc, char **argv) {
    (void)motus_test_near; /* hashes are compared exactly here */
    (void)motus_state_check;
    (void)motus_scene_max_stable_dt;
    if (argc > 2 && strcmp(argv[1], "--matrix") == 0) return matrix(strtol(argv[2], NULL, 10));
    if (argc > 1 && strcmp(argv[1], "--golden") == 0) return print_golden();
    if (argc > 2 && strcmp(argv[1], "--golden-path") == 0) return print_golden_path(argv[2]);
    return motus_test_main(argc, argv, TESTS, TEST_COUNT(TESTS));
}
