/* Determinism: golden hashes of a 1000-particle scene after 500, 10^4 and 10^5 steps, in float and in double
   (MOTUS_DOUBLE), 2D and 3D: every method through motus_step (no coupling: all stages in registers), the
   coupled path (springs: staged passes over scratch) for four methods, collisions (scene.contacts) in 2D and
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
    {"mclachlan4_2d", SCENE, MOTUS_MCLACHLAN4, 2, -1, 0},
    {"mclachlan4_3d", SCENE, MOTUS_MCLACHLAN4, 3, -1, 0},
    {"springs_mclachlan4_3d", SPRUNG, MOTUS_MCLACHLAN4, 3, -1, 0},
};
enum { PATH_COUNT = (int)(sizeof PATHS / sizeof PATHS[0]) };

/* Golden hashes at each of CHECKPOINTS, in the order of PATHS (x86-64, glibc 2.36). A twin's are its
   twin's. */
#ifdef MOTUS_DOUBLE
static const uint64_t GOLDEN[CHECKPOINT_COUNT][PATH_COUNT] = {
    {0xfbb22b9649f62ef1ull, 0xc1548c3e4087447cull, 0xb979f3069ba296e4ull,
     0xc047b8c5a77f31f2ull, 0x643cea1748cc6a70ull, 0xe034eda2bfb8ed6bull,
     0xdba0d8596dc83679ull, 0x5ab3481429661807ull, 0x3e134e02c3c61641ull,
     0x579c53dea7587181ull, 0xbd04d092bca708e4ull, 0x977a4a1727f7931cull,
     0x84a7dc1e87798184ull, 0x056e55f60af5080aull, 0x64c3fe97e1b9a682ull,
     0x1edb51a7559a1d0cull, 0x02afc855782a0c8eull, 0xd13c7d386208ed02ull,
     0xdba0d8596dc83679ull, 0x02afc855782a0c8eull, 0xe92ced589f3ea6daull,
     0x93324c91a20a336bull, 0xade999666acf4247ull, 0xde71c3df7501793cull,
     0x17f1fec8edddedecull, 0xde8ff5e9699dbfb1ull, 0x6c1e7671ee55c571ull,
     0x6c1e7671ee55c571ull, 0x1c6673fe7180dac5ull, 0x1c6673fe7180dac5ull,
     0xe89c593f25af95aeull, 0xcc07443f3d4a6c98ull, 0x65f9b32af0a7ab93ull,
     0xde0f71625c9d3defull, 0xe4ebf2f716882bc8ull, 0x912be44f43d786c2ull,
     0xc64fb821a23c5194ull},
    {0x8945b4e71c0a8d0cull, 0xd83e2144df916ab5ull, 0xc6121038ffdf15f1ull,
     0xabaa0e06bfc1751aull, 0x7f8c99ea6517cd76ull, 0x96d0ed997918c7f1ull,
     0x65769c67a6913a8full, 0xd5ab24093f2c3478ull, 0x0ce5a4294f32a2cfull,
     0x0e6dcd5996f9a0aeull, 0x8d3bd2d59193fd8dull, 0x896e21c2ba11215full,
     0x3d58bde07d47a982ull, 0x66eb0f08abd3932full, 0x1a0a9d2a1b92defaull,
     0x25d93476c022bbadull, 0x4bb1873aa826a73dull, 0x9fa36d0c2669452bull,
     0x65769c67a6913a8full, 0x4bb1873aa826a73dull, 0x247bf9177a2ae191ull,
     0x62355399565773e0ull, 0xe9a8418e935570b5ull, 0x51c15d888a3ad3c6ull,
     0xcf30fb1a0df359f9ull, 0x22177bfd10445c35ull, 0x5798c5eba60367f8ull,
     0x5798c5eba60367f8ull, 0xab16cf8b206d2a81ull, 0xab16cf8b206d2a81ull,
     0x5b19dbcaf2dce5a1ull, 0xb96eef99104a31edull, 0xe577d2eda982a7a9ull,
     0x4be316d40da61f6aull, 0x44acb4a6f9e51580ull, 0x9459f4df7a015e79ull,
     0x8c930046e8eec78dull},
    {0x32ad5fb480e59999ull, 0x7e26e0f8bc717557ull, 0x62f5624ec346d59cull,
     0x61e81fbc467dd1c4ull, 0xedd838f7c3344cfeull, 0x6858a3503e4826c8ull,
     0xc6fffcc4ccd4c1baull, 0x797d1cdbce8609fdull, 0x71fa7738cfbb0554ull,
     0x8fc452137dc31571ull, 0x34df69a602505cf1ull, 0x3f9000ddff02abf7ull,
     0x78cdba8c46c7795aull, 0xcf0e6b443bc752fbull, 0xeab6eb28ebeeba5bull,
     0xe6605423ce9ef5c2ull, 0x87565cd4dbb0d640ull, 0x96cbfc91c5591f0dull,
     0xc6fffcc4ccd4c1baull, 0x87565cd4dbb0d640ull, 0xafe5e08e05e0e88dull,
     0x0b46829734b0f11dull, 0x0eedee280606e435ull, 0x530888c359d1eacdull,
     0x02e8eb2c327825d1ull, 0xe7b49b41ff39a8e3ull, 0x2620d062a3fa7931ull,
     0x2620d062a3fa7931ull, 0x0c088d445822724eull, 0x0c088d445822724eull,
     0xaa95a29a3d518901ull, 0x482a4452b2473daaull, 0xd3154247a1679bf5ull,
     0x46e344b7fe656bf2ull, 0x748d53133fe808a4ull, 0x0b6e126903f7673full,
     0xe8b4ca89341e3e0dull},
    {0xcaac3c15e9edfb32ull, 0x56e8875806143938ull, 0x2d62e52cee1da5cfull,
     0xd738880d23028d42ull, 0x52dbbf44f3ba83e4ull, 0x1156ca711f1aa5b9ull,
     0x37a05348c5aeb97eull, 0xccbe2ec67d285a1bull, 0xe34827ae41cd7195ull,
     0xe32ef99f5abb6177ull, 0x1d771942b47a00f2ull, 0xe2d8737a78421686ull,
     0x101e19eb6a5d5365ull, 0xadddb1103d844288ull, 0xbb5247e59781aeb9ull,
     0xb644dad5525e6394ull, 0xdb1838371b06b396ull, 0xc657eb519a79f2e0ull,
     0x37a05348c5aeb97eull, 0xdb1838371b06b396ull, 0x9412c793baacc00cull,
     0x3f53c8ff7f2b4855ull, 0xa4553b23d31a788eull, 0x8d5f9b311177f8f6ull,
     0x95fde5a58bd4f40aull, 0xa3002f6a3aee21acull, 0x4591d91e0487cfa3ull,
     0x4591d91e0487cfa3ull, 0x70f200851a682d37ull, 0x70f200851a682d37ull,
     0x1fed87454f584fdaull, 0xc006e4237470f4a6ull, 0x163a3fb61c5ba119ull,
     0xb63040ed6994a753ull, 0x4e029db153440cf4ull, 0x467cee8550df575eull,
     0x3f2249c76b5e8e80ull},
};
static const uint64_t GLIBC_EXP_BITS = 0x3fefddf00bbd0dacull;
#else
static const uint64_t GOLDEN[CHECKPOINT_COUNT][PATH_COUNT] = {
    {0x26458f018a8fb0d5ull, 0x394a36fb0dcaa16bull, 0x54c7c26c0ad856b9ull,
     0x1a197c70397e9a61ull, 0x771aaeec0f9993deull, 0xc7a2cf2a234229f9ull,
     0x411fec1c21c29f09ull, 0xf1bb7b99f27502aeull, 0xf3a1cbee9f8177c2ull,
     0xfd1ddd7bd83e2681ull, 0xdfe83f6658a750bbull, 0xfbfdd78a869a3de4ull,
     0x256faa558051505dull, 0x509d8836e1b9e66eull, 0xbdb6df2d7cc4e778ull,
     0x29231d4bbe78c316ull, 0x4a01bf72011383e2ull, 0xfd9ec5a74ef5eb65ull,
     0x411fec1c21c29f09ull, 0x4a01bf72011383e2ull, 0xf0ccac626e774725ull,
     0x9183ab8bed084cb1ull, 0xe80c9ad5554d866aull, 0xa9df7f6eac077383ull,
     0x4529983feae93fd9ull, 0x1b3e9043125caa8full, 0x0060f97004c70802ull,
     0x0060f97004c70802ull, 0x470f9db34b62298aull, 0x470f9db34b62298aull,
     0xdc562c9259901a1eull, 0x90a847dc294c4f96ull, 0x954f3215973adf2bull,
     0xa0b4de94de9deab7ull, 0x932cb5e30a58db19ull, 0x144bfbca6e0ba5e9ull,
     0x9bfeec4cd63bca9cull},
    {0xa9699f9bf63378a9ull, 0x8e23ee6306c3b84cull, 0x3ff7d32329bc434bull,
     0xd933d296f08a1c38ull, 0x07e594b2daab1ff7ull, 0x4352f15f621c5acbull,
     0xa9dded00d1bc5888ull, 0xae19db8079288669ull, 0x9076df96d8cb2158ull,
     0xbe37a2234dc05465ull, 0x2c5f051b5b8b8bf1ull, 0xad5e624d87be64ceull,
     0xe2c71e86a8b8124eull, 0x8964fe7f35b2cf69ull, 0xc6526b2f920891ddull,
     0x67d9da6ba7378166ull, 0x65a3d9c53b856adcull, 0x45956fcdf10e3b00ull,
     0xa9dded00d1bc5888ull, 0x65a3d9c53b856adcull, 0x24735134ff090518ull,
     0x3753f7fd19ad8d36ull, 0xd72d04be336be4a3ull, 0x2002ac53789f9cccull,
     0x95923911b00c5da6ull, 0xe145202074b76362ull, 0x6c0bb31aa9774eefull,
     0x6c0bb31aa9774eefull, 0xf4280c86e7d1bc30ull, 0xf4280c86e7d1bc30ull,
     0xd50960c1171efacbull, 0xa90d931f2c375b67ull, 0xdba97a8dd8dd8154ull,
     0x01ad25a95c59e353ull, 0x74a9833be50b723full, 0xee3f7be2437a8c8cull,
     0x40f973cfcdba9b39ull},
    {0x26fe7afb9bcaa3c6ull, 0xc24e0cf22bc54297ull, 0xc20f0d574bdf4b29ull,
     0x867a66b8d9777103ull, 0xd57a4adbb8771695ull, 0xcff56eada3d5bcd9ull,
     0x78a9a43a7e58f097ull, 0x3a3a3eecdfd37a53ull, 0x0910c24fa5046cebull,
     0x108d52793ccd44aaull, 0x94225ec50135fe15ull, 0xcc00fa4896cf92ddull,
     0x2ca6656d6246a0edull, 0x41a096070df701c6ull, 0x9e652d92e6fba51dull,
     0x2675d934a1df9efcull, 0x51bde0a01acd57ceull, 0x4e1d28010f4e980eull,
     0x78a9a43a7e58f097ull, 0x51bde0a01acd57ceull, 0x458deb372e58d105ull,
     0x94c5892db4c7faeaull, 0x66ce77207297be73ull, 0x841b69438ac47ea3ull,
     0x9cda1068409fa412ull, 0x452ea470a44bb72cull, 0x37a4643247a7bb8full,
     0x37a4643247a7bb8full, 0xd82c85ee89ec0ab6ull, 0xd82c85ee89ec0ab6ull,
     0xbea4f74aae067775ull, 0x9df8189be9e29305ull, 0x342625883a94a3f1ull,
     0x75c57e1be3a27e0dull, 0xc9e073d0ac8d79dbull, 0x0316f3040200eef8ull,
     0xc5f4a3d6659853deull},
    {0x674416b57ac02639ull, 0xbaba6bb5916fca03ull, 0x3893db7d2f5e056cull,
     0xc316fede9b4fa608ull, 0x5767b6fc27c49743ull, 0xb7c8c6fda5dcda38ull,
     0xfd3987dac5cd95f3ull, 0xdc8fa856587594fdull, 0x9c0552570a3b05bdull,
     0x896bd3f540062836ull, 0x1898d2736e6c14beull, 0xed859be5f9ecef3full,
     0x936da8400965e2a1ull, 0xac164d8c0ea8d802ull, 0x538ca0262c3dcc41ull,
     0x438b74672181b9baull, 0x848c0577c4d9aa73ull, 0xfd1ff30ab5d63d00ull,
     0xfd3987dac5cd95f3ull, 0x848c0577c4d9aa73ull, 0x927755bb32831161ull,
     0x61e00be0cd54098cull, 0xb619f7c6e27ede1bull, 0x58394fad8c260d22ull,
     0x72c40a4df68021deull, 0xf4263d32eb415bfbull, 0x4a7fa2d0dc5ae660ull,
     0x4a7fa2d0dc5ae660ull, 0x10a49eaecb4a9da9ull, 0x10a49eaecb4a9da9ull,
     0xa72db5620c7a71ebull, 0x0e022f3cd5ffced7ull, 0x9204f324baa36301ull,
     0xc8a60426459d556cull, 0x17049c7d15b59ad0ull, 0xc0ed0653b4291e18ull,
     0x6e9effa36ead19fbull},
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
/* McLachlan's method (added after the tables above: its own paths), uncoupled and on the springs. */
TEST(mclachlan4) {
    ensure_golden_2d_3d("mclachlan4");
    ensure_golden("springs_mclachlan4_3d");
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
    TEST_CASE(mclachlan4),
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
