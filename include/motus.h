/* motus.h - v0.2.0 - MIT licensed (see end of file) - particle integration for games, one C99 header.

   TABLE OF CONTENTS (search for the tag)
   =================
   >>usage           two ways in: the textbook particle, and a scene stepped over arrays
   >>conventions     units, axes, float or double, errors, immovable particles
   >>config          macros you may define, with their defaults
   >>types           motus_vec2/3, motus_particle/3, motus_result, motus_method, motus_scene, motus_state
   >>declarations    every function motus has, in one list
   >>methods         the ten integrators: order, cost, stability, what they do with velocity forces
   >>contacts        collisions and resting contacts: the broadphase, the solver, what it costs and keeps
   >>determinism     what is bit-for-bit reproducible, and under which conditions
   >>inline          the small functions, defined in every unit (vectors, particles, clock, messages)
   >>implementation  the engine (kernels, checks, stability), compiled where MOTUS_IMPLEMENTATION is defined

   >>usage
   =======
   The textbook step on one particle needs nothing but the include (every particle function is inline):

       #include "motus.h"

       motus_particle ball;
       motus_particle_init(&ball, motus_v2(400, 300), 2);          // at the centre, 2 kg
       // every frame:
       motus_particle_clear_forces(&ball);
       motus_particle_add_force(&ball, motus_v2(100, 0));          // push right (N)
       motus_particle_step(&ball, dt);                              // v += F/m*dt; x += v*dt
       motus_particle_damp_per_step(&ball, 0.01f);                  // v *= 0.99, as the reference

   A scene over many particles, with any integrator, in 2D or 3D: in exactly one C or C++ file write

       #define MOTUS_IMPLEMENTATION
       #include "motus.h"

   and include motus.h anywhere else as usual. Then:

       motus_scene scene = {0};                        // zero: no forces, semi-implicit Euler, 1 kg each
                                                       // (C++: motus_scene scene{};)
       scene.gravity = motus_v3(0, 9.81f, 0);
       scene.method = MOTUS_RK4;
       motus_state state = motus_state_of_particles(balls, count);   // your motus_particle array, or:
       // state.dimensions = 3; state.count = n; state.position[0] = x; ... (one array per component)
       motus_result r = motus_step(&scene, &state, dt, NULL, 0);
       if (r != MOTUS_OK) fprintf(stderr, "motus: %s\n", motus_result_string(r));   // <stdio.h>

   Forces that couple particles (springs, a callback) and collisions need working memory:
   motus_scratch_size() bytes, yours, passed to motus_step. motus allocates nothing and keeps no global
   state. Balls that collide and pile up on the floor of a box (see >>contacts):

       scene.contacts.enabled = 1;
       scene.contacts.radius = 8;                      // or state.radius: one per particle
       scene.contacts.friction = 0.3f;
       scene.bounds_min = motus_v3(0, 0, 0);           // the walls they rest against
       scene.bounds_max = motus_v3(800, 600, 0);
       size_t bytes = motus_scratch_size(&scene, &state);
       void *scratch = malloc(bytes);                  // <stdlib.h>; once, not every frame
       motus_step(&scene, &state, dt, scratch, bytes);

   >>conventions
   =============
   - SI units: metres, seconds, kilograms, newtons. Nothing here cares what one unit is, so a game may use
     pixels for metres (the reference program does).
   - The y axis points wherever you choose; motus never assumes "down" (raylib's screen y grows downwards).
   - `motus_real` is float unless you define MOTUS_DOUBLE before every include of this header.
   - motus_vec2 and motus_vec3 are plain structs of motus_real (x, y[, z]) with raylib's Vector2 / Vector3
     layout in the float build: copy field by field, or memcpy arrays of them (a cast between the two
     types breaks C's aliasing rules).
   - A particle stores its inverse mass. Inverse mass 0 is an immovable particle: no force, drag, damping,
     spring or collision with another particle changes its velocity. It still moves with the velocity it
     has (a platform you slide); give it velocity 0 for a fixed anchor or obstacle. The walls of
     scene.bounds hold every particle, immovable ones too: one placed across a wall is put inside it, and
     one that slides into a wall bounces off it as any particle does (scene.restitution; 0 stops it
     there). Keep obstacles inside the bounds.
   - Forces accumulate until you clear them. The step does not clear them: a constant force may be added once.
   - Every function that can be handed bad input returns a motus_result; on any result other than MOTUS_OK
     nothing was written, with one exception: without MOTUS_CHECKED (>>config), motus_step (and
     motus_step_range) on particle data that is NaN or Inf, or that overflows, has written the step when
     it returns MOTUS_ERROR_NOT_FINITE (it finds out while it writes, to stay a single pass; a particle
     whose force or inverse mass is NaN or Inf, or whose F*(1/m) or a term's acceleration (tether,
     attractor, quadratic drag) overflows and cannot be rescued (THE RESCUE), is found before and left as
     it was, except in scenes with springs or a callback), and it
     does not look for a negative inverse mass (motus_state_check and MOTUS_CHECKED do). dt == 0 is a
     valid step of nothing (NaN or Inf in the state is still reported); a count of 0 is valid and does
     nothing.
     motus_result_string() turns a result into a sentence, motus_scene_check() names the scene field at
     fault, motus_state_check() the particle and field.
   - A step whose F*(1/m) passes the largest real while its result fits (a huge force on a light particle
     over a short dt) is taken: the particle is stepped again in scaled units (THE RESCUE, in >>inline).
     Other such intermediates are reported as an overflow (README, "what is scaled").
   - Zero means default in every description: a zeroed motus_scene is a valid scene with no forces.
   - No compound literals in the header, so it also compiles as C++.

   >>config
   ========
   Define these before including motus.h (all optional):
   - MOTUS_DOUBLE          (undefined)   motus_real is double instead of float (define it everywhere).
   - MOTUS_IMPLEMENTATION  (undefined)   compile the engine in this unit (exactly one unit per program).
   - MOTUS_STATIC          (undefined)   with MOTUS_IMPLEMENTATION: the engine's functions are `static`, for a
                                         program of one unit (no link-time names).
   - MOTUS_API             (extern, or static with MOTUS_STATIC)  linkage of the engine's functions.
   - MOTUS_SQRT, MOTUS_EXP, MOTUS_EXPM1, MOTUS_POW  (<math.h>)  define all four or none.
   - MOTUS_SIMD_BYTES      (64 with AVX-512, 32 with AVX, else 16)  lane width of the kernels.
   - MOTUS_NO_SIMD         (undefined)   kernels one particle at a time, and the textbook calls one component
                                         at a time (same results, bit for bit).
   - MOTUS_CHECKED         (undefined)   motus_step checks every particle first and runs the step once without
                                         storing before it writes: bad data or an overflow writes nothing.
   - MOTUS_REST_SPEED      (1e-30f; 1e-300 with MOTUS_DOUBLE)  m/s: damping sets a velocity component below
                                         this to zero (subnormals are slow on many x86 cores). 0: no flush.
   - MOTUS_CLOCK_DEFAULT_MAX_STEPS (8)   steps a motus_clock runs per frame when given 0.
   - MOTUS_CONTACT_SUPPORT_SWEEPS (1)    0: contacts without the support sweeps (plain Gauss-Seidel; for
                                         comparison, see >>contacts: deep piles then need many iterations).
   - MOTUS_CONTACT_SLAB_MIN_COUNT (4096) particles from which a contact pass with scene.parallel_for solves
                                         in slabs that threads can share, where 4 or more slabs fit across
                                         the scene (see THREADS in >>contacts).
   - MOTUS_ALLOW_FP_CONTRACT (undefined) leave a*b + c contraction to your compiler flags (see >>determinism).
   - MOTUS_ALLOW_FAST_MATH (undefined)   silence the message printed under -ffast-math.
*/
#ifndef MOTUS_H
#define MOTUS_H

#define MOTUS_VERSION_MAJOR 0
#define MOTUS_VERSION_MINOR 2
#define MOTUS_VERSION_PATCH 0
#define MOTUS_VERSION_STRING "0.2.0"
#define MOTUS_VERSION (MOTUS_VERSION_MAJOR * 10000 + MOTUS_VERSION_MINOR * 100 + MOTUS_VERSION_PATCH)

#include <math.h>
#include <stddef.h> /* size_t, NULL */
#include <stdint.h> /* fixed-width integers: the bit-level finite check, the clock's ticks */
#include <string.h> /* memcpy (the bit-level check in C++) */

/* Warnings that motus's own code sets off by design, off for the header's lines alone (your code keeps
   them): -Wfloat-equal (exact comparisons are meant: a dt of 0, a mass of 0, signed zeros, the bits two
   paths must agree on), -Wswitch-enum (a switch on a method names some and sends the rest to a default),
   -Wpadded (the structs' layout is the API's), with Clang -Wcomma (a for loop that steps two indices) and
   -Wused-but-marked-unused (the static API of MOTUS_STATIC), and in C++ what C99 code cannot avoid: C
   casts (-Wold-style-cast), casts to motus_real that are ones only in double (-Wuseless-cast), 0 for a null
   pointer (-Wzero-as-null-pointer-constant), and motus__ names (a double underscore is reserved in C++,
   -Wreserved-identifier; the prefix is the stb and sokol convention for a header's internals). */
#if defined(__clang__)
/* the lines up to the push below define macros with motus__ names too */
#pragma clang diagnostic push
#pragma clang diagnostic ignored "-Wunknown-warning-option" /* Clang before 13: no -Wreserved-* */
#pragma clang diagnostic ignored "-Wreserved-macro-identifier"
#define MOTUS__QUIET_CXX _Pragma("clang diagnostic ignored \"-Wold-style-cast\"") \
    _Pragma("clang diagnostic ignored \"-Wzero-as-null-pointer-constant\"") \
    _Pragma("clang diagnostic ignored \"-Wreserved-identifier\"") \
    _Pragma("clang diagnostic ignored \"-Wreserved-macro-identifier\"")
#define MOTUS__QUIET_BEGIN _Pragma("clang diagnostic push") _Pragma("clang diagnostic ignored \"-Wfloat-equal\"") \
    _Pragma("clang diagnostic ignored \"-Wswitch-enum\"") _Pragma("clang diagnostic ignored \"-Wpadded\"") \
    _Pragma("clang diagnostic ignored \"-Wcomma\"") _Pragma("clang diagnostic ignored \"-Wused-but-marked-unused\"") \
    _Pragma("clang diagnostic ignored \"-Wunknown-warning-option\"") MOTUS__QUIET_LANGUAGE
#define MOTUS__QUIET_END _Pragma("clang diagnostic pop")
#elif defined(__GNUC__)
#define MOTUS__QUIET_CXX _Pragma("GCC diagnostic ignored \"-Wold-style-cast\"") \
    _Pragma("GCC diagnostic ignored \"-Wuseless-cast\"") _Pragma("GCC diagnostic ignored \"-Wzero-as-null-pointer-constant\"")
#define MOTUS__QUIET_BEGIN _Pragma("GCC diagnostic push") _Pragma("GCC diagnostic ignored \"-Wfloat-equal\"") \
    _Pragma("GCC diagnostic ignored \"-Wswitch-enum\"") _Pragma("GCC diagnostic ignored \"-Wpadded\"") \
    MOTUS__QUIET_LANGUAGE
#define MOTUS__QUIET_END _Pragma("GCC diagnostic pop")
#else
#define MOTUS__QUIET_CXX
#define MOTUS__QUIET_BEGIN
#define MOTUS__QUIET_END
#endif
#ifdef __cplusplus
#define MOTUS__QUIET_LANGUAGE MOTUS__QUIET_CXX
#else
#define MOTUS__QUIET_LANGUAGE
#endif
#if defined(__clang__)
#pragma clang diagnostic pop
#endif
MOTUS__QUIET_BEGIN

/* >>config ====================================================================================== */
#if defined(MOTUS_STATIC) && (defined(__GNUC__) || defined(__clang__))
#define MOTUS__API_DEFAULT static __attribute__((unused)) /* a one-file program calls only some */
#elif defined(MOTUS_STATIC)
#define MOTUS__API_DEFAULT static
#else
#define MOTUS__API_DEFAULT extern
#endif
#ifndef MOTUS_API
#define MOTUS_API MOTUS__API_DEFAULT
#endif
/* The small functions: defined in every unit, inlined where they are called. */
#define MOTUS_DEF static inline

#if (defined(__FAST_MATH__) || (defined(__FINITE_MATH_ONLY__) && __FINITE_MATH_ONLY__)) &&                   \
    !defined(MOTUS_ALLOW_FAST_MATH)
#pragma message("motus.h: built with -ffast-math (or -ffinite-math-only): its NaN checks may be optimised away and results differ between builds; see >>determinism in motus.h, or define MOTUS_ALLOW_FAST_MATH")
#endif

#if defined(MOTUS_SQRT) || defined(MOTUS_EXP) || defined(MOTUS_EXPM1) || defined(MOTUS_POW)
#define MOTUS_SQRT_CUSTOM
#if !defined(MOTUS_SQRT) || !defined(MOTUS_EXP) || !defined(MOTUS_EXPM1) || !defined(MOTUS_POW)
#error "motus.h: define all of MOTUS_SQRT, MOTUS_EXP, MOTUS_EXPM1 and MOTUS_POW, or none of them"
#endif
#endif

#ifdef MOTUS_DOUBLE
typedef double motus_real;
typedef uint64_t motus__bits;
#define MOTUS_R(literal) (literal)
#define MOTUS__EXPONENT_MASK 0x7FF0000000000000ull
#define MOTUS_REAL_EPSILON 2.2204460492503131e-16
#define MOTUS__REAL_MAX 1.7976931348623157e308
#define MOTUS__REAL_MIN_NORMAL 2.2250738585072014e-308
#ifndef MOTUS_SQRT
#define MOTUS_SQRT(x) sqrt(x)
#define MOTUS_EXP(x) exp(x)
#define MOTUS_EXPM1(x) expm1(x)
#define MOTUS_POW(x, y) pow(x, y)
#endif
#else
typedef float motus_real;
typedef uint32_t motus__bits;
#define MOTUS_R(literal) (literal##f)
#define MOTUS__EXPONENT_MASK 0x7F800000u
#define MOTUS_REAL_EPSILON 1.1920929e-7f
#define MOTUS__REAL_MAX 3.40282347e38f
#define MOTUS__REAL_MIN_NORMAL 1.17549435e-38f
#ifndef MOTUS_SQRT
#define MOTUS_SQRT(x) sqrtf(x)
#define MOTUS_EXP(x) expf(x)
#define MOTUS_EXPM1(x) expm1f(x)
#define MOTUS_POW(x, y) powf(x, y)
#endif
#endif

#ifndef MOTUS_REST_SPEED
#ifdef MOTUS_DOUBLE
#define MOTUS_REST_SPEED 1e-300
#else
#define MOTUS_REST_SPEED 1e-30f
#endif
#endif
#ifndef MOTUS_CLOCK_DEFAULT_MAX_STEPS
#define MOTUS_CLOCK_DEFAULT_MAX_STEPS 8
#endif

/* Contraction of a*b + c into one fused multiply-add rounds once where the source rounds twice, so a build
   that contracts ends a long run elsewhere (see >>determinism). GCC contracts by default in its GNU modes
   when the target has FMA; Clang when the target has FMA, unless told otherwise. motus keeps its results
   independent of that without slowing your code down:
   - the inline functions (compiled into your code, with your flags) pass each product that feeds an add
     through MOTUS__ROUND, an empty asm that makes the product a value the compiler must hold, so it
     cannot fuse it; free, and it does not stop inlining (GCC's optimize pragma did);
   - the engine (one unit) is compiled under `#pragma STDC FP_CONTRACT OFF` (Clang) or
     `#pragma GCC optimize("fp-contract=off")` (GCC), which costs nothing there. */
/* Strict ISO modes too: GCC does not contract there by default, but -std=c99 -ffp-contract=fast does. */
#if !defined(MOTUS_ALLOW_FP_CONTRACT) && (defined(__GNUC__) || defined(__clang__)) && \
    (defined(__FP_FAST_FMA) || defined(__FP_FAST_FMAF) || defined(__FMA__) || defined(__aarch64__))
#if defined(__x86_64__) || defined(__i386__)
#define MOTUS__ROUND_CONSTRAINT "+x"
#elif defined(__aarch64__) || defined(__arm__)
#define MOTUS__ROUND_CONSTRAINT "+w"
#endif
#endif
#if defined(__clang__) && !defined(MOTUS_ALLOW_FP_CONTRACT) && (defined(__FMA__) || defined(__aarch64__))
/* Clang with -std=c99 and FMA still contracts (its default is "on" within a statement). */
#if !defined(MOTUS__ROUND_CONSTRAINT) && (defined(__x86_64__) || defined(__i386__))
#define MOTUS__ROUND_CONSTRAINT "+x"
#elif !defined(MOTUS__ROUND_CONSTRAINT) && defined(__aarch64__)
#define MOTUS__ROUND_CONSTRAINT "+w"
#endif
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* >>types ======================================================================================= */
typedef struct motus_vec2 {
    motus_real x, y;
} motus_vec2;

typedef struct motus_vec3 {
    motus_real x, y, z;
} motus_vec3;

/* One particle of a game's own array, in 2D; motus_particle3 is the same in 3D. The engine steps arrays of
   either (motus_state_of_particles), so a game can keep its particles in these structs. */
typedef struct motus_particle {
    motus_vec2 position;     /* m */
    motus_vec2 velocity;     /* m/s */
    motus_vec2 force;        /* N: sum of the forces added since the last clear */
    motus_real inverse_mass; /* 1/kg; 0 = immovable */
} motus_particle;

typedef struct motus_particle3 {
    motus_vec3 position, velocity, force;
    motus_real inverse_mass;
} motus_particle3;

/* Results: one table, so that the enum and the sentences cannot drift apart. */
#define MOTUS__RESULTS(X)                                                                                        \
    X(MOTUS_OK, "ok")                                                                                            \
    X(MOTUS_ERROR_NULL_POINTER, "a pointer argument was NULL, or an array the count or the scene needs")          \
    X(MOTUS_ERROR_NOT_FINITE, "an input was NaN or infinite (an argument, a particle field, a scene value); "     \
                              "all must be finite")                                                              \
    X(MOTUS_ERROR_INVALID_MASS, "mass must be finite and > 0 with 1/mass finite; an inverse mass must be >= 0 "   \
                                "(0 = immovable)")                                                               \
    X(MOTUS_ERROR_INVALID_TIME_STEP, "dt must be finite and >= 0 seconds (0 steps nothing); a clock's fixed_dt " \
                                     "must be > 0")                                                              \
    X(MOTUS_ERROR_INVALID_DAMPING, "damping (per step or per second) must be in [0, 1], and not both set")       \
    X(MOTUS_ERROR_INVALID_DRAG, "linear and quadratic drag must be >= 0")                                        \
    X(MOTUS_ERROR_INVALID_ATTRACTOR, "attractor strength must be >= 0")                                          \
    X(MOTUS_ERROR_INVALID_TETHER, "tether stiffness must be >= 0")                                               \
    X(MOTUS_ERROR_INVALID_BOUNDS, "bounds: each component of bounds_min must be <= that of bounds_max")          \
    X(MOTUS_ERROR_INVALID_RESTITUTION, "restitution must be in [0, 1]")                                          \
    X(MOTUS_ERROR_INVALID_SPRING, "a spring's ends must be in [0, count) (b = -1: anchored) and differ; its "     \
                                  "rest length, stiffness and damping >= 0; springs not NULL when counted")      \
    X(MOTUS_ERROR_INVALID_CONTACTS, "contacts: a radius must be >= 0 and at most the largest real / 8; friction "  \
                                    "and the restitution threshold >= 0; iterations >= 0")                       \
    X(MOTUS_ERROR_INVALID_METHOD, "method must be one of motus_method")                                          \
    X(MOTUS_ERROR_INVALID_SUBSTEPS, "substeps must be >= 0 (0 and 1 both mean one step)")                        \
    X(MOTUS_ERROR_INVALID_DIMENSIONS, "dimensions must be 2 or 3 (0 means 2)")                                   \
    X(MOTUS_ERROR_INVALID_COUNT, "a count must be >= 0: state.count, first and count within the state, a "        \
                                 "capacity; or too many pairs to count in an int")                               \
    X(MOTUS_ERROR_INVALID_STRIDE, "stride must be >= 0 (0 means 1: plain arrays)")                                \
    X(MOTUS_ERROR_ALIASING, "two state arrays that motus writes (position, velocity) start at the same address") \
    X(MOTUS_ERROR_SCRATCH_TOO_SMALL, "scratch too small or not aligned: give motus_scratch_size() bytes, aligned " \
                                     "for motus_real")                                                           \
    X(MOTUS_ERROR_UNSUPPORTED, "unsupported combination: motus_step_range takes no springs, callback or "       \
                               "contacts (use motus_step); the exact stepper takes no attractor, tether, "       \
                               "quadratic drag, springs or callback")                                           \
    X(MOTUS_ERROR_OVERFLOW, "the inputs were finite but the result would not be (overflow, or a callback's NaN); " \
                            "use a smaller dt or smaller forces")                                                \
    X(MOTUS_ERROR_TOO_STIFF, "too stiff for this dt: more substeps needed than allowed, or the method is "        \
                             "unstable on a spring at any dt (explicit Euler, midpoint)")                        \
    X(MOTUS_ERROR_INVALID_ARGUMENT, "argument out of range: a safety factor must be in (0, 1], a stable step "    \
                                    ">= 0")                                                                      \
    X(MOTUS_ERROR_INVALID_FRAME_TIME, "frame time must be finite and >= 0 seconds; the clock was left as it was") \
    X(MOTUS_ERROR_INVALID_CLOCK, "clock: max_steps_per_frame must be >= 0 (0 means the default), and a clock "     \
                                 "must be set up by motus_clock_init before it advances (a zeroed one is not)")

#define MOTUS__RESULT_ENUM(name, text) name,
typedef enum motus_result { MOTUS__RESULTS(MOTUS__RESULT_ENUM) MOTUS_RESULT_COUNT } motus_result;
#undef MOTUS__RESULT_ENUM

/* The integrators (see >>methods). One row each: name, order, force evaluations per step, stability limit
   (w*h on an undamped spring; 0 = unstable at any dt, -1 = no spring taken). */
#define MOTUS__METHODS(X)                                                                                        \
    X(MOTUS_SEMI_IMPLICIT_EULER, "semi_implicit_euler", 1, 1, 2.0)                                               \
    X(MOTUS_EXPLICIT_EULER, "explicit_euler", 1, 1, 0.0)                                                         \
    X(MOTUS_POSITION_VERLET, "position_verlet", 2, 1, 2.0)                                                       \
    X(MOTUS_VELOCITY_VERLET, "velocity_verlet", 2, 2, 2.0)                                                       \
    X(MOTUS_LEAPFROG, "leapfrog", 2, 2, 2.0)                                                                     \
    X(MOTUS_MIDPOINT, "midpoint", 2, 2, 0.0)                                                                     \
    X(MOTUS_RK4, "rk4", 4, 4, 2.8284271247461900976)                                                             \
    X(MOTUS_FOREST_RUTH, "forest_ruth", 4, 3, 1.5734019474345367)                                                \
    X(MOTUS_MCLACHLAN4, "mclachlan4", 4, 5, 2.9218392391961706)                                                  \
    X(MOTUS_EXACT_LINEAR_DRAG, "exact_linear_drag", 0, 0, -1.0)
#define MOTUS__METHOD_ENUM(name, text, order, evaluations, limit) name,
typedef enum motus_method { MOTUS__METHODS(MOTUS__METHOD_ENUM) MOTUS_METHOD_COUNT } motus_method;
#undef MOTUS__METHOD_ENUM
#define MOTUS__MAX_EVALUATIONS 5

/* A spring between particles a and b, or from a to a fixed `anchor` (b = -1). The same in 2D and 3D (z is
   ignored in 2D). Hooke with damping on the rate of stretch:
       F_a = -(k*(|d| - L) + c*((v_a - v_b).d/|d|)) * d/|d|,  d = x_a - x_b;  F_b = -F_a
   With rest length L = 0 this is F_a = -k*d - c*((v_a - v_b).d/|d|^2)*d: without damping (c = 0), no
   square root. */
typedef struct motus_spring {
    int a, b;
    motus_vec3 anchor;      /* the fixed end when b == -1 */
    motus_real rest_length; /* L >= 0, m */
    motus_real stiffness;   /* k >= 0, N/m */
    motus_real damping;     /* c >= 0, N*s/m */
} motus_spring;

/* What a force callback is handed at each stage of a step: the stage's state of every particle, as plain
   arrays (index 0 is the state's first particle), and where to add its forces. */
typedef struct motus_force_query {
    int dimensions, count;
    int stage;                          /* 0 .. evaluations-1 */
    motus_real time;                    /* s since the start of this call's step (substep), at this stage */
    const motus_real *position[3];      /* m, per component; [2] NULL in 2D */
    const motus_real *velocity[3];      /* m/s */
    motus_real *force[3];               /* N: add yours here; they start at zero */
} motus_force_query;
typedef void (*motus_force_callback)(void *user_data, const motus_force_query *query);

/* Collisions between particles, and walls they rest on (see >>contacts). Zero: off. */
typedef struct motus_contacts {
    int enabled;                      /* 1: particles with a radius collide, and the bounds are walls they
                                         rest against at their radius; 0: particles pass through one another
                                         and the bounds mirror points (as without contacts) */
    motus_real radius;                /* m >= 0: every particle's radius when state.radius is NULL (0 and no
                                         state.radius: points, which never touch: nothing collides) */
    motus_real restitution;           /* in [0, 1]: share of the normal approach speed kept in a particle
                                         collision (the walls use scene.restitution) */
    motus_real restitution_threshold; /* m/s >= 0: slower approaches do not bounce (Box2D's threshold). 0:
                                         4*|gravity|*h, a few substeps of falling, so that what rests rests */
    motus_real friction;              /* >= 0: Coulomb coefficient on the tangential relative velocity */
    int iterations;                   /* Gauss-Seidel sweeps per substep (0: 4); more: stiffer piles */
} motus_contacts;
typedef struct motus_contact_pair {
    int a, b; /* particle indices, a < b */
} motus_contact_pair;

/* Your threads (Box2D v3's task callbacks, reduced to one). motus_step hands the parts of a contact pass
   that can run at once to scene.parallel_for: run task(task_context, first, count) over the tasks
   [0, task_count), in ranges split however you like, on whatever threads, and return when all have run.
   The tasks of one call touch disjoint particles, so the result is the same bits however they are split,
   in any order, on any number of threads. From 4,096 particles (MOTUS_CONTACT_SLAB_MIN_COUNT), in a scene
   wide enough for 4 slabs across it, the solver then works in slabs, which gives other bits than without
   parallel_for (see THREADS in >>contacts). */
typedef void (*motus_task_function)(void *task_context, int first, int count);
typedef void (*motus_parallel_for)(void *parallel_context, motus_task_function task, void *task_context,
                                   int task_count);

/* Everything that acts on the particles, and how to step them. Zero means default (sokol's descs, Box2D's
   definitions): `motus_scene scene = {0};` (C) or `motus_scene scene{};` (C++) is semi-implicit Euler with
   no forces and particles of 1 kg; set what the scene has. Every term that is zero costs nothing. */
typedef struct motus_scene {
    motus_method method;            /* 0: MOTUS_SEMI_IMPLICIT_EULER */
    int substeps;                   /* each motus_step is this many steps of dt/substeps (0, 1: one) */
    motus_vec3 gravity;             /* m/s^2, a uniform acceleration (z ignored in 2D) */
    motus_real linear_drag;         /* k >= 0, 1/s: a -= k*v */
    motus_real quadratic_drag;      /* c >= 0, 1/m: a -= c*|v|*v */
    motus_real damping_per_step;    /* in [0, 1]: the fraction of velocity removed once each motus_step
                                       (0.01: v *= 0.99 a step, the reference program); frame-rate dependent */
    motus_real damping_per_second;  /* in [0, 1]: the fraction removed per second, v *= (1 - d)^dt; the
                                       same motion at any frame rate. At most one of the two is set. */
    motus_vec3 attractor;           /* position of an inverse-square attractor (a sun), m */
    motus_real attractor_strength;  /* mu = G*M >= 0, m^3/s^2: a -= mu*r/|r|^3, r from the attractor */
    motus_vec3 tether;              /* the fixed end of every particle's tether, m */
    motus_real tether_stiffness;    /* k >= 0, N/m: F -= k*(x - tether), a spring of rest length 0 from each
                                       particle to one point (an oscillator; particles that follow the
                                       mouse). Unlike scene.springs it couples nothing: no scratch, every
                                       stage in registers. Damp it with linear_drag */
    motus_vec3 bounds_min, bounds_max; /* a box the particles stay in; an axis whose min and max are both 0
                                       has no walls (all six 0: no box). A component may be -Inf/+Inf: no
                                       wall on that side */
    motus_real restitution;         /* in [0, 1]: the share of normal speed kept through a wall bounce */
    motus_real mass;                /* kg of every particle when the state has no inverse_mass array (0: 1) */
    const motus_spring *springs;    /* spring_count springs (they couple particles: scratch needed) */
    int spring_count;
    motus_force_callback force_callback; /* your forces, at every stage (couples: scratch needed) */
    void *user_data;                /* handed to force_callback */
    motus_contacts contacts;        /* collisions and resting contacts (off while zero) */
    motus_parallel_for parallel_for; /* NULL: motus_step runs on the calling thread; else it hands the
                                       independent parts of a step with contacts to your threads (the
                                       same bits on any number of them; see THREADS in >>contacts) */
    void *parallel_context;         /* handed to parallel_for */
} motus_scene;

/* Where the particles are: one array per component (structure of arrays), or pointers into your own
   structs with a stride. motus writes position and velocity and reads the rest: the arrays it reads must not
   share memory with those it writes (a position array that starts where a velocity array does, or another
   position array, is refused; other overlaps are not looked for, and a radius, mass or force that is also
   a position changes during the step). Zero means default. */
typedef struct motus_state {
    int dimensions;              /* 2 or 3 (0: 2) */
    int count;                   /* particles */
    int stride;                  /* motus_reals from one particle's value to the next (0: 1, plain arrays) */
    motus_real *position[3];     /* x, y (, z) */
    motus_real *velocity[3];
    const motus_real *force[3];  /* accumulated forces, N, held over the step; NULL: none */
    const motus_real *inverse_mass; /* 1/kg per particle (0: immovable); NULL: every particle has scene.mass */
    const motus_real *radius;    /* m per particle, for contacts; NULL: every particle has scene.contacts.radius */
    int radius_stride;           /* motus_reals from one radius to the next (0: stride, as the other arrays);
                                    motus_state_of_particles sets 1: motus_particle has no radius, so the radii
                                    are an array of their own */
} motus_state;

/* Where a check found the first bad particle or field. */
typedef enum motus_field {
    MOTUS_FIELD_NONE = 0,
    MOTUS_FIELD_POSITION,
    MOTUS_FIELD_VELOCITY,
    MOTUS_FIELD_FORCE,
    MOTUS_FIELD_INVERSE_MASS,
    MOTUS_FIELD_RADIUS,
    MOTUS_FIELD_COUNT
} motus_field;
typedef struct motus_check_report {
    int index;              /* the first bad particle (its index in the state), or -1 */
    motus_field field;
    int component;          /* 0 x, 1 y, 2 z; -1 for the inverse mass and for none */
    const char *field_name; /* "position", "velocity", "force", "inverse_mass", "radius", "none"; or the scene's field
                               ("scene.gravity.y", ...) when the scene is at fault. Never NULL. */
} motus_check_report;

/* The fixed-step clock (see motus_clock_advance). */
typedef struct motus_clock {
    motus_real fixed_dt;               /* s, the dt of every step */
    int max_steps_per_frame;           /* the cap against the spiral of death */
    uint64_t accumulator;              /* ticks not stepped yet: < 2^32 (one step) between frames */
    uint64_t steps_total;              /* steps run since init */
    uint64_t steps_dropped_last_frame; /* whole steps the cap dropped in the last advance */
    uint64_t steps_dropped_total;      /* since init (saturates at 2^64 - 1) */
    motus_real time_dropped_last_frame; /* s */
    double time_dropped_total;         /* s, since init */
} motus_clock;

/* >>declarations ================================================================================
   Vectors (inline): motus_v2, motus_v3, motus_vec2_add/sub/scale/dot/length/lerp/is_finite and the same for
   motus_vec3; motus_real_is_finite.
   Particles (inline; the same with motus_particle3_ and motus_vec3 in 3D): */
MOTUS_DEF motus_result motus_particle_init(motus_particle *particle, motus_vec2 position, motus_real mass);
MOTUS_DEF motus_result motus_particle_init_immovable(motus_particle *particle, motus_vec2 position);
MOTUS_DEF motus_real motus_particle_mass(const motus_particle *particle);   /* +Inf immovable, NaN for NULL */
MOTUS_DEF motus_result motus_particle_check(const motus_particle *particle);
MOTUS_DEF motus_result motus_particle_add_force(motus_particle *particle, motus_vec2 force);
MOTUS_DEF motus_result motus_particle_clear_forces(motus_particle *particle);
MOTUS_DEF motus_result motus_particle_step(motus_particle *particle, motus_real dt); /* semi-implicit Euler */
MOTUS_DEF motus_result motus_particle_step_compensated(motus_particle *particle, motus_vec2 *carry, motus_real dt);
MOTUS_DEF motus_result motus_particle_damp_per_step(motus_particle *particle, motus_real damping);
MOTUS_DEF motus_result motus_particle_damp_per_second(motus_particle *particle, motus_real damping_per_second,
                                                      motus_real dt);
MOTUS_DEF motus_result motus_particle_bounce(motus_particle *particle, motus_vec2 bounds_min, motus_vec2 bounds_max,
                                             motus_real restitution);
MOTUS_DEF motus_result motus_particle3_init(motus_particle3 *particle, motus_vec3 position, motus_real mass);
MOTUS_DEF motus_result motus_particle3_init_immovable(motus_particle3 *particle, motus_vec3 position);
MOTUS_DEF motus_real motus_particle3_mass(const motus_particle3 *particle);
MOTUS_DEF motus_result motus_particle3_check(const motus_particle3 *particle);
MOTUS_DEF motus_result motus_particle3_add_force(motus_particle3 *particle, motus_vec3 force);
MOTUS_DEF motus_result motus_particle3_clear_forces(motus_particle3 *particle);
MOTUS_DEF motus_result motus_particle3_step(motus_particle3 *particle, motus_real dt);
MOTUS_DEF motus_result motus_particle3_step_compensated(motus_particle3 *particle, motus_vec3 *carry, motus_real dt);
MOTUS_DEF motus_result motus_particle3_damp_per_step(motus_particle3 *particle, motus_real damping);
MOTUS_DEF motus_result motus_particle3_damp_per_second(motus_particle3 *particle, motus_real damping_per_second,
                                                       motus_real dt);
MOTUS_DEF motus_result motus_particle3_bounce(motus_particle3 *particle, motus_vec3 bounds_min, motus_vec3 bounds_max,
                                              motus_real restitution);
MOTUS_DEF motus_real motus_damping_per_second_from_per_step(motus_real damping_per_step, motus_real steps_per_second);
/* States over your arrays of particles (inline): */
MOTUS_DEF motus_state motus_state_of_particles(motus_particle *particles, int count);
MOTUS_DEF motus_state motus_state_of_particles3(motus_particle3 *particles, int count);

/* Methods (inline): name ("rk4"), order (0: exact), force evaluations per step, stability limit (see
   >>methods); NULL / -1 for a value out of range. */
MOTUS_DEF const char *motus_method_name(motus_method method);
MOTUS_DEF int motus_method_order(motus_method method);
MOTUS_DEF int motus_method_evaluations(motus_method method);
MOTUS_DEF motus_real motus_method_stability_limit(motus_method method);
MOTUS_DEF motus_result motus_max_stable_dt(motus_method method, motus_real stiffness, motus_real mass,
                                           motus_real *max_dt);
MOTUS_DEF motus_result motus_substeps_for(motus_real dt, motus_real max_stable_dt, motus_real safety, int *substeps);

/* The engine (compiled where MOTUS_IMPLEMENTATION is defined): */
/* Advances every particle of `state` by dt under `scene`: scene.substeps steps of dt/substeps, each by
   scene.method with the bounds after it, then the damping. With contacts on, each substep is the method,
   then the contacts and walls; the damping comes with the last substep's method, before its contacts (a
   bounce then leaves at the restitution's speed, undamped). scratch: motus_scratch_size() bytes for a
   scene with springs, a callback or contacts, else NULL/0. */
MOTUS_API motus_result motus_step(const motus_scene *scene, const motus_state *state, motus_real dt, void *scratch,
                                  size_t scratch_bytes);
/* The same over particles [first, first + count) only, for a scene whose forces do not couple particles
   (no springs, no callback): each particle's result does not depend on how a range is split, so threads
   can each step their own range. */
MOTUS_API motus_result motus_step_range(const motus_scene *scene, const motus_state *state, int first, int count,
                                        motus_real dt);
/* Bytes of scratch motus_step needs for this scene and state (0: none); (size_t)-1 if the sizes overflow. */
MOTUS_API size_t motus_scratch_size(const motus_scene *scene, const motus_state *state);
/* MOTUS_OK if the scene is valid for a state of `dimensions` (0: 2) and `count` particles (for the spring
   ends); otherwise the result, with the field at fault in report->field_name ("scene.damping_per_step"). */
MOTUS_API motus_result motus_scene_check(const motus_scene *scene, int dimensions, int count,
                                         motus_check_report *report);
/* The first bad particle of [first, first + count): a NaN or Inf in what the scene reads, or a negative
   inverse mass. report (may be NULL) says which particle, field and component. */
MOTUS_API motus_result motus_state_check(const motus_scene *scene, const motus_state *state, int first, int count,
                                         motus_check_report *report);
/* The pairs of particles in contact now: overlapping or within 1% of the sum of their radii of touching
   (distance < 1.01 * (r_a + r_b), the solver's own tolerance: after a step pushes an overlap out, two balls
   that collided or rest on each other sit at exactly r_a + r_b, and they are listed), each once with a < b, in
   the order the broadphase finds them (the particles from the bottom up, each with its neighbours in its
   half of the cells around it; the solver then sorts them by their upper particle): *found gets their
   number, the first `capacity` are written to pairs. scratch as for motus_step with contacts on. The
   broadphase of the step, for game logic and tests. It reads positions and radii only: state.velocity,
   force and inverse_mass may be NULL. */
MOTUS_API motus_result motus_find_contacts(const motus_scene *scene, const motus_state *state, void *scratch,
                                           size_t scratch_bytes, motus_contact_pair *pairs, int capacity, int *found);
/* The largest dt the scene's springs and drags allow for its method (Gershgorin bound, see >>methods);
   +Inf when nothing limits it. scratch as for motus_step. Where w^2 = k*(1/m), summed over a particle's
   springs, or the damping rate passes the largest real, the rates are scaled, not refused: a tether of
   1e30 N/m on 1e-10 kg in float (w^2 = 1e40/s^2) gets its 2e-20 s. MOTUS_ERROR_OVERFLOW (and *max_dt
   untouched) only where a speed |v| itself does. */
MOTUS_API motus_result motus_scene_max_stable_dt(const motus_scene *scene, const motus_state *state,
                                                 motus_real *max_dt, void *scratch, size_t scratch_bytes);

/* Clock and messages (inline): */
MOTUS_DEF motus_result motus_clock_init(motus_clock *clock, motus_real fixed_dt, int max_steps_per_frame);
MOTUS_DEF motus_result motus_clock_advance(motus_clock *clock, motus_real frame_seconds, int *steps_to_run);
MOTUS_DEF motus_real motus_clock_alpha(const motus_clock *clock);
MOTUS_DEF double motus_clock_time(const motus_clock *clock);
MOTUS_DEF const char *motus_result_string(motus_result result);
MOTUS_DEF const char *motus_field_name(motus_field field);
MOTUS_DEF motus_result motus_particles_check(const motus_particle *particles, int count, motus_check_report *report);
MOTUS_DEF motus_result motus_particles3_check(const motus_particle3 *particles, int count,
                                              motus_check_report *report);

/* >>methods
   =========
   method               order  evals  symplectic  stable on a spring   with drag (velocity forces)
   SEMI_IMPLICIT_EULER  1      1      yes         w*h < 2              1st order
     v += a(x, v)*h; x += v*h. The textbook step (motus_particle_step is this method, bit for bit).
   EXPLICIT_EULER       1      1      no          never                1st order
     x += v*h; v += a(x, v)*h. Adds energy to every oscillation: (x, v/w) grows by sqrt(1 + (w*h)^2).
   POSITION_VERLET      2      1      yes         w*h < 2              1st order
     Drift-kick-drift (Stormer-Verlet in position form): x_m = x + v*h/2; v += a(x_m, v)*h; x = x_m + v*h/2.
     Self-starting and its velocity is the synchronised one: on a Kepler orbit its energy error is
     velocity Verlet's, not the 8x of the old x_{n+1} - x_n form that needed the last step kept.
   VELOCITY_VERLET      2      2      yes         w*h < 2              2nd order (v predicted to the end)
     x += v*h + a0*h^2/2; v += a0*h/2 + a(x_new, v + a0*h)*h/2.
   LEAPFROG             2      2      yes         w*h < 2              2nd order
     Kick-drift-kick: v += a0*h/2; x += v*h; v += a(x_new, v + a0*h/2)*h/2. Velocity Verlet's map written
     with the half-step velocity; they differ in rounding only. Time-reversible.
   MIDPOINT             2      2      no          never                2nd order
     Explicit midpoint RK2; grows a spring's amplitude by sqrt(1 + (w*h)^4/4) per step.
   RK4                  4      4      no          w*h < 2*sqrt(2)      4th order
     Classic Runge-Kutta, its sums formed as odeint's: x += v1*h/6 + v2*h/3 + v3*h/3 + v4*h/6 with the
     stages' velocities, v likewise with their accelerations. Energy drifts by O(h^4) per unit time.
   FOREST_RUTH          4      3      yes         w*h < 1.5734         1st order (a kick is Euler in v)
     Yoshida's triple jump of leapfrog, theta = 1/(2 - 2^(1/3)): D(th/2) K(th) D((1-th)/2) K(1-2th)
     D((1-th)/2) K(th) D(th/2). 4th order for forces of position only.
   MCLACHLAN4           4      5      yes         w*h < 2.9218         1st order (a kick is Euler in v)
     McLachlan's symmetric composition (SIAM J. Sci. Comput. 16, 1995; odeint's symplectic_rkn_sb3a_mclachlan):
     D(a1) K(b1) D(a2) K(b2) D(a3) K(b3) D(a3) K(b2) D(a2) K(b1) D(a1), a1 = 0.405189, a2 = -0.287144,
     a3 = 1/2 - a1 - a2, b1 = -3/73, b2 = 17/59, b3 = 1 - 2*(b1 + b2). Two evaluations more than Forest-Ruth
     and, on a spring at the same dt, an error about 440 times smaller: about 50 times smaller at equal cost.
     4th order for forces of position only.
   EXACT_LINEAR_DRAG    exact  0      -           takes no spring      exact
     Solves v' = g + F/m - k*v over the step: v = v0*e^-u + a*c1, x = x0 + v0*c1 + a*c2 with u = k*h,
     c1 = (1 - e^-u)/k, c2 = (h - c1)/k (series for small u). Exact at any dt. Only gravity, linear drag,
     accumulated forces, damping and bounds (and contacts, which act after each substep): anything else is
     MOTUS_ERROR_UNSUPPORTED.
   STABILITY: on x'' = -w^2 x each method's step is a linear map of (x, v/w) that depends on z = w*h; the
   limits above are where its eigenvalues leave the unit circle (semi-implicit Euler and the Verlets: trace
   2 - z^2, |trace| < 2; RK4: |R(iz)|^2 = 1 - z^6/72 + z^8/576 <= 1; Forest-Ruth: trace 2 - u + u^2/12 +
   c*u^3, u = z^2, c = 0.1295084; McLachlan: the trace of its eleven maps first reaches -2 at 2.9218, and
   is back inside from 3.30 to 4.65, a window the limit does not count). Damping g (drags, spring damping)
   moves the eigenvalues off the axis: w_eff = alpha*g/2 + sqrt((alpha*g/2)^2 + w^2) must stay below the
   limit over h, alpha = 1 (Euler and Verlet family, exact for semi-implicit Euler; McLachlan, which needs
   0.82), 2.8284/2.7853 (RK4), 2 (Forest-Ruth, which needs 1.79).
   motus_scene_max_stable_dt bounds w^2 by Gershgorin on M^-1*K: max over movable j of sum over j's springs
   of k*(1/m_j + 1/m_other), plus the tether's k/m_j.
   COUPLING: forces that do not couple particles (gravity, drags, the attractor, the tether, accumulated
   forces, damping, bounds) are evaluated in registers, particle by particle, all stages of the method at once: one read
   and one write of the state per motus_step whatever the order and the substeps. Springs and the callback
   couple particles: each stage then is a pass over the particles that records the stage's state in
   scratch, then the callback and the springs add the stage's forces, then the next stage; the last pass
   stores the result. The same code runs both ways, so a scene gives the same bits with or without a
   callback that adds nothing.

   >>contacts
   ==========
   With scene.contacts.enabled each particle is a disc (2D) or a ball (3D) of its radius (state.radius, or
   contacts.radius for all), and every substep is the method, then a contact pass:
   - Broadphase: a spatial hash of cells 2.25 times the largest radius (no world box: cell numbers are
     formed in double, so that rounding never skips a cell, and clamped at 2^29, where the particles beyond
     share the edge cells; one particle flung far away costs nothing), the particles counting-sorted by
     bucket into scratch (O(N), no allocation); each particle looks at its own cell and the half of the
     3^d - 1 around it that come after it (each pair is met once). Where the cells the particles span fit
     in the table (2 buckets a particle), the buckets are those cells laid out densely, so that the cells a
     particle looks at are 2 runs of neighbouring buckets in 2D (5 in 3D) instead of 5 (14) hashed
     lookups; the same cells in the same order either way, so the same pairs and bits. The pairs nearer
     than 1.1 times the sum of their radii are listed in scratch (4 per particle in 2D, 8 in 3D; past that,
     the rest are searched again at each sweep, same order). The solver's order is the heights' (a radix
     sort of heights in 1/64ths of the largest radius, ties in index order), so a particle far above or
     below a pile changes nothing in it.
   - Solver: sequential impulses (projected Gauss-Seidel: Catto, "Iterative Dynamics with Temporal
     Coherence", GDC 2005; Box2D) over `iterations` sweeps of velocities: a pair within 1% of touching
     that approaches at vn < 0 gets the mass-weighted impulse that leaves -restitution*vn, or 0 below the
     restitution threshold (Box2D's rule, so that what rests does not hop); then Coulomb friction up to
     friction times that impulse. A resting contact keeps its impulse over the sweeps of a pass and only
     the total is clamped at 0 (a ball in a V of two others is not thrown off it); a bounce is never
     taken back. Nothing is kept between passes (no warm starting). Then as many sweeps of positions:
     each overlap removed along the normal by inverse-mass shares, without touching velocities (split
     impulse / Box2D v2's non-linear Gauss-Seidel position pass: the overlap goes without adding energy).
     The walls of the bounds are contacts with an immovable plane at the particle's radius, same rules.
   - Piles: pairs are visited from the bottom up (a counting sort on height against gravity), and each
     phase ends with a support sweep (shock propagation: Guendelman, Bridson and Fedkiw, "Nonconvex rigid
     bodies with stacking", SIGGRAPH 2003): a particle resting on a wall, an immovable particle, or one
     resting on those counts as immovable for the particle above it (within 60 degrees of up), still
     whichever way it moves; in the position sweep the upper one is lifted straight up out of it. A
     particle's supports are solved together, a few passes with the impulse on each kept, and a gap within
     4 ulps of the largest coordinate counts as touching there (a float pile 700 rows deep at 1,400 m blew
     up otherwise). One sweep then carries a pile's whole weight, where plain Gauss-Seidel needs about as
     many sweeps as the pile has rows: a 2,000-ball pile settles to overlaps of 3.4e-5 r and a kinetic
     energy of 1e-20 of what it fell from (tests/contacts.c). Why not Box2D v3's soft step (Catto's
     Solver2D comparison ranks it best for rigid bodies): it relies on warm starting, i.e. contact
     impulses kept from the last step, and motus keeps no state between calls.
   - What it keeps: every impulse is equal and opposite (momentum kept to rounding) except where a wall or
     an immovable particle takes it; with restitution <= 1 the kinetic energy never grows (a sweep's
     impulse brings one pair's approach to -e times itself, or takes back part of an earlier one to stop a
     separation, friction never reverses sliding, positions move without velocity). So contacts do not
     lower any method's stable dt. A contact is resolved at the end of the substep in which it begins:
     across a collision every method is first order in time (between collisions each keeps its order). A
     particle that moves more than its radius in a substep can pass through a thin one: keep |v|*h below
     the radius (substeps).
   - Deterministic: the order depends on the data only (heights, indices, cells), never on threads.
   - Particles at exactly one point have no line of centres: they are pushed apart along +x, and pair by
     pair the first push sets the line for the rest, so a burst spawned at one point spreads into a row.
     Spawn them a few % of a radius apart (random offsets) and they spread out in every direction.
   - Radii may differ by up to about 1e20 in float (1e150 in double): distances are formed in units of the
     largest radius, and beyond that the squared distances of the smallest pairs underflow (they are then
     missed, or pushed apart along x). Velocities may be anything finite: where a component passes the
     largest real / 64, the velocity sweeps run on velocities scaled down by a power of two, so that an
     approach speed that overflows (2e38 m/s head-on in float) bounces as at any speed. An impulse (a
     momentum) past the largest real is not scaled: it is reported (MOTUS_ERROR_NOT_FINITE, or
     MOTUS_ERROR_OVERFLOW with MOTUS_CHECKED), e.g. 1e36 m/s head-on between 1,000 kg balls in float.
   - Cost per substep: O(N + pairs * iterations); motus_find_contacts gives the pairs in contact (within
     1% of touching, as the solver counts them) for game logic. Memory: the scratch (motus_scratch_size),
     and about 19 KB of stack for the pass's job (the tasks' tables; mind it on a fiber's small stack).
   - THREADS: with scene.parallel_for set, motus_step hands it the method's pass, the grid's scans and the
     pair search in tasks of 2,048 particles or more (each task lists its pairs into its own part of the
     list, and a stable sort joins them as one thread would have: the same bits as without parallel_for),
     and, from 4,096 particles, the sweeps in slabs: the cells across an axis that is not up (x under
     gravity along -y in 2D; in 3D x or z, whichever keeps the particles of a cache line of the arrays
     closer to one slab, so that two threads write apart in memory: particles stored roughly in order
     along one horizontal axis, e.g. spawned row by row, or sorted now and then, and the slabs follow)
     are cut into slabs as wide to a cell, at least 16 cells in 2D and 4 in 3D, as many as fit up to 64,
     rounded down to a multiple of 12 (4 or 8 below 12): each colour has an even number of slabs, which 2,
     3, 4 or 6 threads share evenly. A pair belongs to the slab of its upper particle (its supports are
     then all in one task); each sweep solves the even slabs at once, then the odd ones. A pair's cells
     are at most one apart and a slab is at least 4 cells wide, so a slab's task touches only its own
     particles and the edge cells of its neighbours: the tasks of one call share no particle, and the
     bits do not depend on how the tasks are split, in what order they run, or on how many threads (Box2D
     v3 colours its constraint graph for the same reason; two colours of slabs are enough for particles).
     tests/threads.c checks it through pools of 2 and 3 threads and odd splits (in 3D with slabs across x
     and across z), also under ThreadSanitizer.
     What the slabs cost: the order is no longer bottom-up across a slab border (a support in the odd slab
     beside an even one is solved after it; the support sweep takes it as resting, else a ball on the
     border was pushed off its V), so a step with parallel_for gives other bits than one without, and deep
     2D piles rest less tightly: largest overlap 4.9e-4 r against 6.1e-5 r in a 2D pile of 10^5 balls
     (224 rows; 1.2e-3 r against 1.3e-3 r in 3D); a 6,000-ball pile settles alike (with 4-cell slabs in
     2D: 5.5e-4 r there, hence 16). Below 4,096 particles there are no slabs and the bits are the same with
     or without parallel_for. The hash table's counting sort and the heights' radix sort stay on the
     calling thread.
     motus_step_range refuses a scene with contacts: a contact pass needs all the particles.

   >>determinism
   =============
   The same scene, stepped the same way, ends in the same state bit for bit whatever builds it: GCC or
   Clang, -O0 to -O3, with -march=native or not, as C or C++, at any MOTUS_SIMD_BYTES or MOTUS_NO_SIMD, over
   plain arrays or your structs, whole or split in ranges; motus_particle_step equals the semi-implicit
   Euler scene on accumulated forces. tests/determinism.c checks it with golden hashes. This holds given
   IEEE-754 arithmetic with no excess precision (SSE2 or arm64, not x87); no contraction of a*b + c into an
   FMA that motus did not prevent (it prevents it in its own code, see >>config); no -ffast-math or its
   parts; subnormals not flushed; the same libm for the few calls that use it (sqrt is exact everywhere;
   pow for damping_per_second, once per step; exp and expm1 for the exact stepper, once per step).
*/

/* >>inline ====================================================================================== */

/* A product that must round before it is added (see >>config). */
#ifdef MOTUS__ROUND_CONSTRAINT
MOTUS_DEF motus_real motus__round(motus_real x) {
    __asm__("" : MOTUS__ROUND_CONSTRAINT(x));
    return x;
}
#define MOTUS__ROUND(x) motus__round(x)
#else
#define MOTUS__ROUND(x) (x)
#endif

MOTUS_DEF motus_vec2 motus_v2(motus_real x, motus_real y) {
    motus_vec2 v;
    v.x = x;
    v.y = y;
    return v;
}
/* The vectors' arithmetic writes through a pointer (motus__*_into), so that tcc can run it without
   returning a 3D vector: see "TCC" below. */
MOTUS_DEF motus_vec3 *motus__v3_into(motus_vec3 *to, motus_real x, motus_real y, motus_real z) {
    to->x = x;
    to->y = y;
    to->z = z;
    return to;
}
MOTUS_DEF motus_vec3 *motus__vec3_add_into(motus_vec3 *to, motus_vec3 a, motus_vec3 b) {
    return motus__v3_into(to, a.x + b.x, a.y + b.y, a.z + b.z);
}
MOTUS_DEF motus_vec3 *motus__vec3_sub_into(motus_vec3 *to, motus_vec3 a, motus_vec3 b) {
    return motus__v3_into(to, a.x - b.x, a.y - b.y, a.z - b.z);
}
MOTUS_DEF motus_vec3 *motus__vec3_scale_into(motus_vec3 *to, motus_vec3 v, motus_real s) {
    return motus__v3_into(to, v.x * s, v.y * s, v.z * s);
}
MOTUS_DEF motus_vec3 *motus__vec3_lerp_into(motus_vec3 *to, motus_vec3 a, motus_vec3 b, motus_real t) {
    return motus__v3_into(to, a.x + MOTUS__ROUND((b.x - a.x) * t), a.y + MOTUS__ROUND((b.y - a.y) * t),
                          a.z + MOTUS__ROUND((b.z - a.z) * t));
}
MOTUS_DEF motus_vec3 motus_v3(motus_real x, motus_real y, motus_real z) {
    motus_vec3 v;
    return *motus__v3_into(&v, x, y, z);
}
MOTUS_DEF motus_vec2 motus_vec2_add(motus_vec2 a, motus_vec2 b) { return motus_v2(a.x + b.x, a.y + b.y); }
MOTUS_DEF motus_vec2 motus_vec2_sub(motus_vec2 a, motus_vec2 b) { return motus_v2(a.x - b.x, a.y - b.y); }
MOTUS_DEF motus_vec2 motus_vec2_scale(motus_vec2 v, motus_real s) { return motus_v2(v.x * s, v.y * s); }
MOTUS_DEF motus_real motus_vec2_dot(motus_vec2 a, motus_vec2 b) {
    return MOTUS__ROUND(a.x * b.x) + MOTUS__ROUND(a.y * b.y);
}
MOTUS_DEF motus_real motus_vec2_length(motus_vec2 v) { return MOTUS_SQRT(motus_vec2_dot(v, v)); }
/* a + (b - a)*t: t = 0 gives a exactly; for drawing between two steps with t = motus_clock_alpha. */
MOTUS_DEF motus_vec2 motus_vec2_lerp(motus_vec2 a, motus_vec2 b, motus_real t) {
    return motus_v2(a.x + MOTUS__ROUND((b.x - a.x) * t), a.y + MOTUS__ROUND((b.y - a.y) * t));
}
MOTUS_DEF motus_vec3 motus_vec3_add(motus_vec3 a, motus_vec3 b) {
    motus_vec3 sum;
    return *motus__vec3_add_into(&sum, a, b);
}
MOTUS_DEF motus_vec3 motus_vec3_sub(motus_vec3 a, motus_vec3 b) {
    motus_vec3 difference;
    return *motus__vec3_sub_into(&difference, a, b);
}
MOTUS_DEF motus_vec3 motus_vec3_scale(motus_vec3 v, motus_real s) {
    motus_vec3 scaled;
    return *motus__vec3_scale_into(&scaled, v, s);
}
MOTUS_DEF motus_real motus_vec3_dot(motus_vec3 a, motus_vec3 b) {
    return MOTUS__ROUND(a.x * b.x) + MOTUS__ROUND(a.y * b.y) + MOTUS__ROUND(a.z * b.z);
}
MOTUS_DEF motus_real motus_vec3_length(motus_vec3 v) { return MOTUS_SQRT(motus_vec3_dot(v, v)); }
MOTUS_DEF motus_vec3 motus_vec3_lerp(motus_vec3 a, motus_vec3 b, motus_real t) {
    motus_vec3 between;
    return *motus__vec3_lerp_into(&between, a, b, t);
}

/* True unless x is NaN or +-Inf. Reads the exponent bits, so that the check survives -ffast-math (under
   which isfinite() folds to 1). C reads the bits through a union; C++ through memcpy (a register move). */
MOTUS_DEF motus__bits motus__real_bits(motus_real x) {
#ifdef __cplusplus
    motus__bits bits;
    memcpy(&bits, &x, sizeof bits);
    return bits;
#else
    union {
        motus_real real;
        motus__bits bits;
    } pun;
    pun.real = x;
    return pun.bits;
#endif
}
MOTUS_DEF int motus_real_is_finite(motus_real x) {
    return (motus__real_bits(x) & MOTUS__EXPONENT_MASK) != MOTUS__EXPONENT_MASK;
}
MOTUS_DEF motus__bits motus__sign_bit(void) { return (motus__bits)~(MOTUS__EXPONENT_MASK | (MOTUS__EXPONENT_MASK >> 1)) & (motus__bits)(MOTUS__EXPONENT_MASK << 1); }
MOTUS_DEF int motus_vec2_is_finite(motus_vec2 v) { return motus_real_is_finite(v.x) & motus_real_is_finite(v.y); }
MOTUS_DEF int motus_vec3_is_finite(motus_vec3 v) {
    return motus_real_is_finite(v.x) & motus_real_is_finite(v.y) & motus_real_is_finite(v.z);
}
/* x > 0 and finite; dt >= 0 and finite (a -0 dt is a step of nothing, as +0). */
MOTUS_DEF int motus__positive_finite(motus_real x) { return motus_real_is_finite(x) && x > 0; }
MOTUS_DEF int motus__dt_valid(motus_real dt) { return motus_real_is_finite(dt) && dt >= 0; }
MOTUS_DEF int motus__fraction_valid(motus_real x) { return x >= 0 && x <= 1; } /* NaN fails */

/* ---- particles: written once on motus_vec3; the 2D functions run them with z = 0 ---- */
MOTUS_DEF motus_vec3 motus__v3_of(motus_vec2 v) { return motus_v3(v.x, v.y, 0); }
#if defined(__TINYC__) && !defined(MOTUS_DOUBLE)
/* TCC: tcc 0.9.27 (Debian 12's) stores a returned 12-byte struct, a float motus_vec3, with two 8-byte
   moves into a 12-byte temporary: 4 bytes past it, over whatever the frame keeps there. In the README's
   3D loop, motus_particle3_bounce(&ball, motus_v3(-5, 0, -5), motus_v3(5, 20, 5), 0.8f) overwrote the
   loop's counter and the loop never ended (tests/compile/unit_b.c). Under tcc the functions that return
   one are macros that return none: each writes the vector into a compound literal of the caller's block
   through its motus__*_into, which the function calls too, and reads it back, evaluating each argument
   once, as the call does: the same arithmetic, the same bits. */
#define MOTUS__V3_TEMPORARY (&(motus_vec3){0, 0, 0})
#define motus_v3(x, y, z) (*motus__v3_into(MOTUS__V3_TEMPORARY, (x), (y), (z)))
#define motus_vec3_add(a, b) (*motus__vec3_add_into(MOTUS__V3_TEMPORARY, (a), (b)))
#define motus_vec3_sub(a, b) (*motus__vec3_sub_into(MOTUS__V3_TEMPORARY, (a), (b)))
#define motus_vec3_scale(v, s) (*motus__vec3_scale_into(MOTUS__V3_TEMPORARY, (v), (s)))
#define motus_vec3_lerp(a, b, t) (*motus__vec3_lerp_into(MOTUS__V3_TEMPORARY, (a), (b), (t)))
#define motus__v3_of(v) motus_v3((v).x, (v).y, 0)
#endif
MOTUS_DEF motus_vec2 motus__v2_of(motus_vec3 v) { return motus_v2(v.x, v.y); }

MOTUS_DEF motus_result motus__init(motus_vec3 position, motus_real mass, motus_real *inverse_mass) {
    if (!motus_vec3_is_finite(position) || !motus_real_is_finite(mass)) return MOTUS_ERROR_NOT_FINITE;
    if (!(mass > 0)) return MOTUS_ERROR_INVALID_MASS;
    *inverse_mass = MOTUS_R(1.0) / mass;
    return motus_real_is_finite(*inverse_mass) ? MOTUS_OK : MOTUS_ERROR_INVALID_MASS;
}
MOTUS_DEF motus_result motus__check(motus_vec3 position, motus_vec3 velocity, motus_vec3 force, motus_real inverse_mass) {
    if (!(motus_vec3_is_finite(position) & motus_vec3_is_finite(velocity) & motus_vec3_is_finite(force) &
          motus_real_is_finite(inverse_mass)))
        return MOTUS_ERROR_NOT_FINITE;
    return inverse_mass < 0 ? MOTUS_ERROR_INVALID_MASS : MOTUS_OK;
}
/* Semi-implicit Euler, the step the textbook teaches:
       v(t+dt) = v(t) + F*(1/m)*dt;   x(t+dt) = x(t) + v(t+dt)*dt      <- the new velocity
   First order: under a constant acceleration a it lands at x0 + v0*t + a*t*(t + dt)/2 after time t. It
   keeps the energy of an orbit or a spring bounded; a spring of stiffness k is stable while dt < 2*sqrt(m/k).
   Writes *velocity and *position only if both come out finite. */
MOTUS_DEF int motus__finite_in(motus_vec3 v, int dims) {
    return dims == 3 ? motus_vec3_is_finite(v) : motus_real_is_finite(v.x) & motus_real_is_finite(v.y);
}
/* The velocity of the step, one component: v + ((F*(1/m) + 0) - v*0)*dt (see motus__step why the zeros). */
MOTUS_DEF motus_real motus__kick(motus_real v, motus_real force, motus_real inverse_mass, motus_real dt) {
    return v + MOTUS__ROUND(((MOTUS__ROUND(force * inverse_mass) + 0) - MOTUS__ROUND(v * 0)) * dt);
}
/* THE RESCUE. A step whose inputs are finite can overflow where its result does not: F*(1/m) past the
   largest real while a*dt is not (1e38 N on 0.01 kg for 1 ms in float). A particle whose F*(1/m) is not
   finite is stepped again in time units of 2^-s seconds: velocities times 2^-s, accelerations times 2^-2s
   (F*(1/m) as (F*2^-s)*((1/m)*2^-s), gravity, the tether's and the attractor's strengths likewise), drag
   rates times 2^-s, h times 2^s, and the velocity times 2^s at the end. A power of two scales exactly, so
   where nothing under- or overflows this is the same computation, rounding for rounding; it is tried at
   s = 4, 16 and 64 (in double also 256 and 512), and the first s at which the step is finite is kept: the
   smallest that brings the large values in range, so that the small ones (a gravity of 1e-30 beside the
   force that overflowed) keep their digits. Where no s gives a finite step, the result itself does not
   fit: OVERFLOW. The engine takes the same steps (motus__group_rescue): the paths agree bit for bit.
   The triggers: F*(1/m) not finite, tested where the forces are loaded; and a term whose textbook formula
   is out of range at a stage (a tether's k*dx*(1/m) not finite, a quadratic drag's |v|^2 past
   largest/(4c), an attractor's |r|^3 or pull past the largest real), which stops the kernel at that group
   (see motus__acceleration): each particle of it is then stepped alone by the general kernel, which scales
   what it can (x - tether, |v|^2, |r|^3), and one whose step is still not finite with finite inputs is
   rescued as above. The fast kernels can afford these tests and not one of their results (see the
   kernel); the general kernel makes the same tests in a scene without coupling, so that the paths agree.
   Not rescued: a sum of terms that each fit (g + F/m past the largest real), springs and the callback
   (they couple particles). The methods' sums are formed so that they overflow only where the step does
   (RK4's and velocity Verlet's add changes of x and v, each a*h or v*h). */
/* Out of line and cold: what the common paths below reach only for rare input (see there). */
#if defined(__GNUC__) || defined(__clang__)
#define MOTUS__RARE static __attribute__((noinline, cold, unused))
#define MOTUS__LIKELY(x) __builtin_expect(!!(x), 1)
#else
#define MOTUS__RARE static
#define MOTUS__LIKELY(x) (x)
#endif
#ifdef MOTUS_DOUBLE
#define MOTUS__RESCUE_LEVELS 5
#else
#define MOTUS__RESCUE_LEVELS 3
#endif
/* 2^-s at a level of the rescue: 0.5 squared 2, 4, 6, 8 or 9 times (s = 4, 16, 64, 256, 512), exact. */
MOTUS_DEF motus_real motus__rescue_down(int level) {
    motus_real down = MOTUS_R(0.5);
    int squarings = level < 3 ? 2 * level + 2 : level + 5;
    while (squarings-- > 0) down *= down;
    return down;
}
MOTUS__RARE motus_result motus__step_rescaled(motus_vec3 *position, motus_vec3 *velocity, motus_vec3 force,
                                         motus_real inverse_mass, motus_real dt, int dims) {
    int level;
    for (level = 0; level < MOTUS__RESCUE_LEVELS; ++level) {
        const motus_real down = motus__rescue_down(level), up = MOTUS_R(1.0) / down, h = dt * up;
        const motus_real scaled_inverse_mass = inverse_mass * down;
        motus_vec3 v = motus_v3(velocity->x * down, velocity->y * down, velocity->z * down), x;
        if (inverse_mass != 0) {
            v.x = motus__kick(v.x, force.x * down, scaled_inverse_mass, h);
            v.y = motus__kick(v.y, force.y * down, scaled_inverse_mass, h);
            v.z = dims == 3 ? motus__kick(v.z, force.z * down, scaled_inverse_mass, h) : 0;
        }
        x.x = position->x + MOTUS__ROUND(v.x * h);
        x.y = position->y + MOTUS__ROUND(v.y * h);
        x.z = dims == 3 ? position->z + MOTUS__ROUND(v.z * h) : 0;
        v = motus_v3(v.x * up, v.y * up, v.z * up);
        if (inverse_mass == 0) v = *velocity;
        if (motus__finite_in(x, dims) & motus__finite_in(v, dims)) {
            *velocity = v;
            *position = x;
            return MOTUS_OK;
        }
    }
    return MOTUS_ERROR_OVERFLOW;
}
MOTUS_DEF motus_result motus__step(motus_vec3 *position, motus_vec3 *velocity, motus_vec3 force,
                                   motus_real inverse_mass, motus_real dt, int dims) {
    motus_vec3 v, x;
    if (!motus__dt_valid(dt)) return MOTUS_ERROR_INVALID_TIME_STEP;
    if (inverse_mass < 0) return MOTUS_ERROR_INVALID_MASS;
    /* a step of nothing, as motus_step's: the state stays bit for bit, and bad data is still reported */
    if (dt == 0) return motus__check(*position, *velocity, force, inverse_mass);
    /* a = (F*(1/m) + g) - k*v with g = 0 and k = 0, as the engine computes it for a scene without gravity
       and drag (adding a zero and subtracting a v*0 change nothing but the sign of a zero), so that the two
       agree bit for bit, signed zeros included. */
    v.x = motus__kick(velocity->x, force.x, inverse_mass, dt);
    v.y = motus__kick(velocity->y, force.y, inverse_mass, dt);
    v.z = dims == 3 ? motus__kick(velocity->z, force.z, inverse_mass, dt) : 0;
    if (inverse_mass == 0) v = *velocity; /* immovable: forces do not change its velocity */
    x.x = position->x + MOTUS__ROUND(v.x * dt);
    x.y = position->y + MOTUS__ROUND(v.y * dt);
    x.z = dims == 3 ? position->z + MOTUS__ROUND(v.z * dt) : 0;
    /* x = position + v*dt is NaN or Inf whenever v is, so x tells for the state; the force is looked at
       too, since an immovable particle does not read it (its NaN must still be reported, as the engine's). */
    if (!(motus__finite_in(x, dims) & motus__finite_in(force, dims))) {
        motus_result state = motus__check(*position, *velocity, force, inverse_mass);
        if (state != MOTUS_OK) return state;
        /* F*(1/m) past the largest real: THE RESCUE */
        if (!motus__finite_in(motus_v3(force.x * inverse_mass, force.y * inverse_mass, force.z * inverse_mass), dims))
            return motus__step_rescaled(position, velocity, force, inverse_mass, dt, dims);
        return MOTUS_ERROR_OVERFLOW;
    }
    *velocity = v;
    *position = x;
    return MOTUS_OK;
}
/* Kahan-compensated position update for far from the origin in float: the carry keeps what each update
   rounded away (Knuth's TwoSum, exact) and adds it back next step. The velocity is motus__step's. */
MOTUS_DEF motus_result motus__step_compensated(motus_vec3 *position, motus_vec3 *velocity, motus_vec3 force,
                                               motus_real inverse_mass, motus_vec3 *carry, motus_real dt, int dims) {
    motus_vec3 x = *position, v = *velocity, delta, sum, back, error;
    motus_result result;
    if (!motus__dt_valid(dt)) return MOTUS_ERROR_INVALID_TIME_STEP;
    if (!motus_vec3_is_finite(*carry)) return MOTUS_ERROR_NOT_FINITE;
    result = motus__step(&x, &v, force, inverse_mass, dt, dims);
    if (result != MOTUS_OK || dt == 0) return result;
    delta = motus_v3(MOTUS__ROUND(v.x * dt) + carry->x, MOTUS__ROUND(v.y * dt) + carry->y,
                     MOTUS__ROUND(v.z * dt) + carry->z);
    sum = motus_vec3_add(*position, delta);
    back = motus_vec3_sub(sum, *position);
    error = motus_vec3_add(motus_vec3_sub(*position, motus_vec3_sub(sum, back)), motus_vec3_sub(delta, back));
    if (!motus__finite_in(sum, dims)) return MOTUS_ERROR_OVERFLOW;
    *velocity = v;
    *position = sum;
    *carry = error;
    return MOTUS_OK;
}
/* v*kept, each component below MOTUS_REST_SPEED set to a zero of its sign (subnormals are slow). */
MOTUS_DEF motus_real motus__damp(motus_real v, motus_real kept) {
    const motus__bits rest = motus__real_bits((motus_real)(MOTUS_REST_SPEED));
    v = v * kept;
    /* |v| < rest compared as magnitude bits (monotonic for non-negative reals): no branch */
    return v * (motus_real)((motus__real_bits(v) & ~motus__sign_bit()) >= rest);
}
MOTUS_DEF motus_result motus__damp3(motus_vec3 *velocity, motus_real inverse_mass, motus_real kept, int dims) {
    if (!motus__finite_in(*velocity, dims)) return MOTUS_ERROR_NOT_FINITE;
    /* immovable: damping does not act on it; no damping (0, or dt 0): no change, not even the flush */
    if (inverse_mass == 0 || kept == 1) return MOTUS_OK;
    velocity->x = motus__damp(velocity->x, kept);
    velocity->y = motus__damp(velocity->y, kept);
    if (dims == 3) velocity->z = motus__damp(velocity->z, kept);
    return MOTUS_OK;
}
/* The kept factor of damping_per_second over dt: (1 - d)^dt. */
MOTUS_DEF motus_real motus__kept_per_second(motus_real damping_per_second, motus_real dt) {
    return damping_per_second == 0 ? MOTUS_R(1.0) : MOTUS_POW(MOTUS_R(1.0) - damping_per_second, dt);
}
/* One wall pair: past a wall the position is mirrored back inside and that velocity component multiplied
   by -restitution; one that overshot by more than the box is clamped to the wall. */
MOTUS_DEF void motus__bounce1(motus_real *x, motus_real *v, motus_real lo, motus_real hi, motus_real bounce) {
    if (*x < lo) {
        *x = lo + (lo - *x);
        *v = *v * bounce;
        if (!(*x <= MOTUS__REAL_MAX)) *x = lo; /* the mirror overflowed (a wall near the largest real) */
    }
    if (*x > hi) {
        *x = hi - (*x - hi);
        *v = *v * bounce;
        if (!(*x >= -MOTUS__REAL_MAX)) *x = hi;
    }
    if (*x < lo) *x = lo;
    if (*x > hi) *x = hi;
}
MOTUS_DEF motus_result motus__bounce(motus_vec3 *x, motus_vec3 *v, motus_vec3 lo, motus_vec3 hi, motus_real restitution,
                                     int dims) {
    motus_vec3 nx = *x, nv = *v;
    if (!motus_real_is_finite(restitution) || !motus__finite_in(*x, dims) || !motus__finite_in(*v, dims))
        return MOTUS_ERROR_NOT_FINITE;
    if (lo.x != lo.x || lo.y != lo.y || lo.z != lo.z || hi.x != hi.x || hi.y != hi.y || hi.z != hi.z)
        return MOTUS_ERROR_NOT_FINITE; /* NaN walls; infinite ones mean no wall */
    /* min <= max, and a wall at infinity only where it means "no wall": min may be -Inf, max +Inf */
    if (!(lo.x <= hi.x && lo.y <= hi.y && lo.z <= hi.z) || lo.x > MOTUS__REAL_MAX || lo.y > MOTUS__REAL_MAX ||
        lo.z > MOTUS__REAL_MAX || hi.x < -MOTUS__REAL_MAX || hi.y < -MOTUS__REAL_MAX || hi.z < -MOTUS__REAL_MAX)
        return MOTUS_ERROR_INVALID_BOUNDS;
    if (!motus__fraction_valid(restitution)) return MOTUS_ERROR_INVALID_RESTITUTION;
    motus__bounce1(&nx.x, &nv.x, lo.x, hi.x, -restitution);
    motus__bounce1(&nx.y, &nv.y, lo.y, hi.y, -restitution);
    if (dims == 3) motus__bounce1(&nx.z, &nv.z, lo.z, hi.z, -restitution);
    *x = nx;
    *v = nv;
    return MOTUS_OK;
}

/* ---- the common path of the textbook calls ----
   A game calls these on every particle every frame, so each does the common case first: compute, test
   with a short chain of predictable branches, store; anything else (a rejection, an immovable particle, a
   step of nothing, a particle at or past a wall) goes to the full function, out of line and marked cold
   (MOTUS__RARE), which says why and writes nothing on a rejection.
   Both paths compute the same bits. What keeps the common path short (the benchmark's loop of the five
   calls, 2D float, gcc 12 -O2: 88 instructions a particle; 161 in the first version; the same loop written
   by hand without a check: 42):
   - the rare path takes the particle and the call's own numbers, never a vector by value: every vector
     register is a call's to overwrite, so a vector kept for a call in the caller's loop was held packed in
     an integer register and unpacked every particle;
   - `&&`, not `&`: a chain of well-predicted branches is fewer instructions than booleans combined;
   - an argument that is the same for every particle (dt, damping, restitution) is tested on its bits:
     compilers move integer work out of the caller's loop, not floating-point work (it may raise a flag),
     so what is left a particle is one compare;
   - one finiteness test on the sum of the components (x + y is finite only if both are; a sum that
     overflows goes to the rare path, which finds the components fine);
   - each check reads what the arithmetic already has (the doubled bits of a damped velocity component
     say in one compare that it is finite and not below the rest speed);
   - the stores go through MOTUS__OPAQUE_POINTER (below);
   - on x86-64 with GCC or Clang, x and y go as one pair ("(x, y) as one pair", below). */
/* A value the compiler must take as it is. A call reads what the call before it wrote a moment ago (the
   step reads the force add_force wrote, damping the velocity the step wrote); a vectoriser (GCC's, on at
   -O2 since GCC 12; Clang's) loads two neighbours as one pair, which the CPU cannot forward from two
   separate stores: a stall a particle (the 3D calls 2x slower with GCC -O2, the 2D ones in double 3x with
   Clang -O2). Read through this, each value is a load of its own. */
#if (defined(__GNUC__) || defined(__clang__)) && defined(__x86_64__)
#define MOTUS__OPAQUE(x) __asm__("" : "+x"(x))
#elif (defined(__GNUC__) || defined(__clang__)) && defined(__aarch64__)
#define MOTUS__OPAQUE(x) __asm__("" : "+w"(x))
#else
#define MOTUS__OPAQUE(x) (void)0
#endif
/* The same where only Clang needs it: Clang pairs the force's components in the step, GCC does not, and
   there the barrier costs GCC 5-10% (it then keeps the step's arithmetic scalar). */
#if defined(__clang__)
#define MOTUS__OPAQUE_CLANG(x) MOTUS__OPAQUE(x)
#else
#define MOTUS__OPAQUE_CLANG(x) (void)0
#endif
/* A copy of a pointer that the compiler cannot see is the same pointer. The common paths store the x (and
   z) components through such a copy and y through the original: GCC's SLP vectoriser (on at -O2) otherwise
   packs the adjacent stores into one vector store, builds that vector with shuffles, and unpacks it again
   for the checks (the textbook calls, 2D float, gcc 12 -O2: 5.0 against 3.8 ns a particle). */
#if defined(__GNUC__) || defined(__clang__)
#define MOTUS__OPAQUE_POINTER(p) __asm__("" : "+r"(p))
#else
#define MOTUS__OPAQUE_POINTER(p) (void)0
#endif
/* The walls leave a particle strictly inside them alone: lo < x < hi also says x is finite and the walls
   are valid there (not NaN, lo < hi, lo below the largest real, hi above its negative). */
MOTUS_DEF int motus__inside(motus_real x, motus_real lo, motus_real hi) { return lo < x && x < hi; }
/* |x| as bits: monotonic in |x|, below MOTUS__EXPONENT_MASK exactly when x is finite. */
MOTUS_DEF motus__bits motus__magnitude_bits(motus_real x) { return motus__real_bits(x) & ~motus__sign_bit(); }
/* x in [+0, 1], read from its bits (a -0 or a NaN is not: the rare path takes those). */
MOTUS_DEF int motus__unit_bits(motus_real x) { return motus__real_bits(x) <= motus__real_bits(MOTUS_R(1.0)); }
/* x in (0, largest finite], read from its bits: one unsigned compare (+0, -0, negatives, Inf and NaN are
   not). dt is the same for every particle, so the caller's loop computes most of it once; and the step and
   damping test 1/m with it alike, so that after a step the compiler drops damping's test. */
MOTUS_DEF int motus__positive_bits(motus_real x) {
    return (motus__bits)(motus__real_bits(x) - 1u) < (motus__bits)(MOTUS__EXPONENT_MASK - 1u);
}
/* damping in [1e-6, 1], from its bits: then 1 - damping is in [0, 1) (something to damp, and not more than
   all of it). Smaller dampings, and every invalid one, go to the rare path. */
MOTUS_DEF int motus__damping_bits(motus_real damping) {
    const motus__bits least = motus__real_bits((motus_real)1e-6);
    return (motus__bits)(motus__real_bits(damping) - least) <= (motus__bits)(motus__real_bits(MOTUS_R(1.0)) - least);
}
/* A damped component that damping neither flushed (|v| >= MOTUS_REST_SPEED) nor found non-finite: one
   unsigned compare on the magnitude's bits, doubled so that the sign falls out (x86: one lea). */
MOTUS_DEF int motus__moving_bits(motus_real v) {
    const motus__bits rest = motus__real_bits((motus_real)(MOTUS_REST_SPEED)) << 1;
    return (motus__bits)((motus__real_bits(v) << 1) - rest) < (motus__bits)((MOTUS__EXPONENT_MASK << 1) - rest);
}
/* The velocity of the common step, one component, without motus__kick's "- v*0": for a finite v that is
   subtracting a zero from F/m + 0, which is never -0, so it changes nothing; for a v that is NaN or Inf
   the position comes out NaN or Inf either way and the step is rejected. */
MOTUS_DEF motus_real motus__kick_finite(motus_real v, motus_real force, motus_real inverse_mass, motus_real dt) {
    return v + MOTUS__ROUND((MOTUS__ROUND(force * inverse_mass) + 0) * dt);
}
/* A damped velocity component, with its magnitude bits: below MOTUS_REST_SPEED a zero of its sign, as
   motus__damp. */
MOTUS_DEF motus_real motus__rest_flush(motus_real damped, motus__bits magnitude) {
    return magnitude >= motus__real_bits((motus_real)(MOTUS_REST_SPEED)) ? damped : damped * 0;
}
/* Why a sum of forces is not finite: a term was not, or the sum overflowed. */
MOTUS__RARE motus_result motus__add_force_error(motus_vec3 old, motus_vec3 force, int dims) {
    return (motus__finite_in(force, dims) & motus__finite_in(old, dims)) ? MOTUS_ERROR_OVERFLOW
                                                                         : MOTUS_ERROR_NOT_FINITE;
}
/* The rare paths: the full functions on the particle. The 2D ones run the 3D code on a copy with z = 0.
   add_force's common path tests the sum of the components: a sum that overflowed while each component is
   finite comes here, and is stored. */
MOTUS__RARE motus_result motus__particle3_add_force_rare(motus_particle3 *particle, motus_real x, motus_real y,
                                                         motus_real z) {
    const motus_vec3 sum = motus_vec3_add(particle->force, motus_v3(x, y, z));
    if (!motus__finite_in(sum, 3)) return motus__add_force_error(particle->force, motus_v3(x, y, z), 3);
    particle->force = sum;
    return MOTUS_OK;
}
MOTUS__RARE motus_result motus__particle3_step_rare(motus_particle3 *particle, motus_real dt) {
    return motus__step(&particle->position, &particle->velocity, particle->force, particle->inverse_mass, dt, 3);
}
MOTUS__RARE motus_result motus__particle3_damp_rare(motus_particle3 *particle, motus_real damping) {
    if (!motus__fraction_valid(damping)) return MOTUS_ERROR_INVALID_DAMPING;
    return motus__damp3(&particle->velocity, particle->inverse_mass, MOTUS_R(1.0) - damping, 3);
}
MOTUS__RARE motus_result motus__particle3_bounce_rare(motus_particle3 *particle, motus_real min_x, motus_real min_y,
                                                      motus_real min_z, motus_real max_x, motus_real max_y,
                                                      motus_real max_z, motus_real restitution) {
    return motus__bounce(&particle->position, &particle->velocity, motus_v3(min_x, min_y, min_z),
                         motus_v3(max_x, max_y, max_z), restitution, 3);
}
MOTUS_DEF motus_particle3 motus__particle3_of(const motus_particle *particle) {
    motus_particle3 p;
    p.position = motus__v3_of(particle->position);
    p.velocity = motus__v3_of(particle->velocity);
    p.force = motus__v3_of(particle->force);
    p.inverse_mass = particle->inverse_mass;
    return p;
}
/* Writes the copy's position and velocity back if the result is MOTUS_OK. */
MOTUS_DEF motus_result motus__particle_store(motus_particle *particle, const motus_particle3 *p, motus_result result) {
    if (result == MOTUS_OK) {
        particle->position = motus__v2_of(p->position);
        particle->velocity = motus__v2_of(p->velocity);
    }
    return result;
}
MOTUS__RARE motus_result motus__particle_add_force_rare(motus_particle *particle, motus_real x, motus_real y) {
    const motus_vec2 sum = motus_vec2_add(particle->force, motus_v2(x, y));
    if (!motus_vec2_is_finite(sum)) return motus__add_force_error(motus__v3_of(particle->force), motus_v3(x, y, 0), 2);
    particle->force = sum;
    return MOTUS_OK;
}
MOTUS__RARE motus_result motus__particle_step_rare(motus_particle *particle, motus_real dt) {
    motus_particle3 p = motus__particle3_of(particle);
    motus_result result = motus__particle3_step_rare(&p, dt);
    if (dt == 0) return result; /* a step of nothing writes nothing */
    return motus__particle_store(particle, &p, result);
}
MOTUS__RARE motus_result motus__particle_damp_rare(motus_particle *particle, motus_real damping) {
    motus_particle3 p = motus__particle3_of(particle);
    return motus__particle_store(particle, &p, motus__particle3_damp_rare(&p, damping));
}
MOTUS__RARE motus_result motus__particle_bounce_rare(motus_particle *particle, motus_real min_x, motus_real min_y,
                                                     motus_real max_x, motus_real max_y, motus_real restitution) {
    motus_particle3 p = motus__particle3_of(particle);
    return motus__particle_store(particle, &p,
                                 motus__particle3_bounce_rare(&p, min_x, min_y, 0, max_x, max_y, 0, restitution));
}

/* ---- (x, y) as one pair ----
   On x86-64 under GCC or Clang the textbook calls (clear_forces, add_force, step, damp_per_step, bounce;
   in 3D with z beside the pair) load, compute, test and store x and y as one pair (16 bytes of doubles, 8
   of floats, in an SSE register), as GCC compiles a loop written by hand. The five calls on 5,000
   particles, gcc 12 -O2: 3.1 ns a particle in 2D double where one component at a time took 3.8 (the hand
   loop: 2.1-2.4), and 1.2-1.4 times the hand loop in every configuration where it was 1.4-1.8
   (docs/performance-notes.md). The lanes compute what the components did, bit for bit
   (tests/particle_paths.c). The tests:
   - finite: x*0 is a zero where x is finite and NaN where it is not, and a NaN is not equal to itself;
   - moving (damping): (bits << 1) - (the rest speed's bits << 1) has its sign bit clear in each lane for
     MOTUS_REST_SPEED <= |v| < about 2^27 m/s (the window is half the doubled bits' range); anything else,
     a faster particle too, takes the full test (every speed does if MOTUS_REST_SPEED is above 1 m/s);
   - inside the walls: lo < x + v*0 < hi, which also says that v is finite.
   Every call stores a pair where it loads one, so each load is forwarded from one store. Code of yours
   that writes one component and then calls a function that loads the pair makes the CPU wait for the
   store (some 10 cycles, not a wrong result). MOTUS_NO_SIMD turns the pairs off; so does -O0, where each
   helper below would be a call (the five calls took 2.6 times as long in double). */
#if (defined(__GNUC__) || defined(__clang__)) && defined(__x86_64__) && defined(__SSE2__) && \
    defined(__OPTIMIZE__) && !defined(MOTUS_NO_SIMD)
#define MOTUS__PAIRS 1
typedef motus_real motus__pair __attribute__((vector_size(2 * sizeof(motus_real))));
typedef motus__bits motus__pair_bits __attribute__((vector_size(2 * sizeof(motus_real))));
MOTUS_DEF motus__pair motus__pair_of(motus_real x, motus_real y) {
    motus__pair pair = {x, y};
    return pair;
}
MOTUS_DEF motus__pair motus__pair_load(const void *vector) {
    motus__pair pair;
    memcpy(&pair, vector, sizeof pair);
    return pair;
}
MOTUS_DEF void motus__pair_store(void *vector, motus__pair pair) { memcpy(vector, &pair, sizeof pair); }
/* Zeros to store as one pair. In double from a register: GCC -Og writes a constant pair as two 8-byte
   stores, and the one 16-byte load that follows cannot be forwarded from them (the five calls 2.4 times as
   slow). */
MOTUS_DEF motus__pair motus__pair_zeros(void) {
    motus__pair zeros = {0, 0};
#ifdef MOTUS_DOUBLE
    MOTUS__OPAQUE(zeros);
#endif
    return zeros;
}
MOTUS_DEF motus__pair_bits motus__pair_bits_of(motus__pair pair) {
    motus__pair_bits bits;
    memcpy(&bits, &pair, sizeof bits);
    return bits;
}
/* A product that must round before it is added, as MOTUS__ROUND. */
MOTUS_DEF motus__pair motus__pair_round(motus__pair x) {
#if defined(MOTUS__ROUND_CONSTRAINT) && (defined(MOTUS_DOUBLE) || !defined(__clang__))
    __asm__("" : MOTUS__ROUND_CONSTRAINT(x));
#elif defined(MOTUS__ROUND_CONSTRAINT)
    double held; /* Clang gives no SSE register to an 8-byte vector in an asm; it does to a double */
    memcpy(&held, &x, sizeof held);
    __asm__("" : MOTUS__ROUND_CONSTRAINT(held));
    memcpy(&x, &held, sizeof x);
#endif
    return x;
}
#ifdef MOTUS_DOUBLE
/* Both lanes' sign bits set (a comparison's mask: all of it true), or both clear. */
MOTUS_DEF int motus__pair_all(motus__pair_bits mask) {
    motus__pair lanes;
    memcpy(&lanes, &mask, sizeof lanes);
    return __builtin_ia32_movmskpd(lanes) == 3;
}
MOTUS_DEF int motus__pair_signs_clear(motus__pair_bits bits) {
    motus__pair lanes;
    memcpy(&lanes, &bits, sizeof lanes);
    return __builtin_ia32_movmskpd(lanes) == 0;
}
#define MOTUS__PAIR_LEAST_REST 1e-300
#else
MOTUS_DEF int motus__pair_all(motus__pair_bits mask) {
    uint64_t lanes;
    memcpy(&lanes, &mask, sizeof lanes);
    return lanes == ~(uint64_t)0;
}
MOTUS_DEF int motus__pair_signs_clear(motus__pair_bits bits) {
    uint64_t lanes;
    memcpy(&lanes, &bits, sizeof lanes);
    return (lanes & 0x8000000080000000ull) == 0;
}
#define MOTUS__PAIR_LEAST_REST 1e-30f
#endif
MOTUS_DEF int motus__pair_finite(motus__pair x) {
    const motus__pair zeros = x * motus__pair_of(0, 0);
    return motus__pair_all((motus__pair_bits)(zeros == zeros));
}
MOTUS_DEF int motus__pair_moving(motus__pair v) {
    /* A rest speed below the default (0: flush nothing) would put the window's top below 2 m/s: the speeds
       between it and the default take the full test. One above 1 m/s would put Inf and NaN inside the
       window: then every speed does. */
    const motus__bits rest = (motus__bits)(motus__real_bits((motus_real)(MOTUS_REST_SPEED)) << 1),
                      least = (motus__bits)(motus__real_bits(MOTUS__PAIR_LEAST_REST) << 1),
                      most = (motus__bits)(motus__real_bits(1) << 1), start = rest > least ? rest : least;
    const motus__pair_bits window = {start, start};
    return start <= most && motus__pair_signs_clear((motus__pair_bits_of(v) << 1) - window);
}
/* lo < x < hi in both lanes. In double each comparison's mask goes through MOTUS__OPAQUE before the `&`:
   GCC 12 otherwise rebuilds the masks lane by lane in general registers (see motus__any_sse2_doubles). */
MOTUS_DEF int motus__pair_inside(motus__pair x, motus__pair lo, motus__pair hi) {
    motus__pair_bits above = (motus__pair_bits)(lo < x), below = (motus__pair_bits)(x < hi);
#ifdef MOTUS_DOUBLE
    MOTUS__OPAQUE(above);
    MOTUS__OPAQUE(below);
#endif
    return motus__pair_all(above & below);
}
#endif

/* ---- the 2D particle functions ---- */
/* A particle at rest at `position` with no force; mass finite and > 0 with 1/mass finite. */
MOTUS_DEF motus_result motus_particle_init(motus_particle *particle, motus_vec2 position, motus_real mass) {
    motus_real inverse_mass = 0;
    motus_result result;
    if (!particle) return MOTUS_ERROR_NULL_POINTER;
    result = motus__init(motus__v3_of(position), mass, &inverse_mass);
    if (result != MOTUS_OK) return result;
    particle->position = position;
    particle->velocity = motus_v2(0, 0);
    particle->force = motus_v2(0, 0);
    particle->inverse_mass = inverse_mass;
    return MOTUS_OK;
}
/* Inverse mass 0: forces, drag and damping never change its velocity (see >>conventions). */
MOTUS_DEF motus_result motus_particle_init_immovable(motus_particle *particle, motus_vec2 position) {
    if (!particle) return MOTUS_ERROR_NULL_POINTER;
    if (!motus_vec2_is_finite(position)) return MOTUS_ERROR_NOT_FINITE;
    particle->position = position;
    particle->velocity = motus_v2(0, 0);
    particle->force = motus_v2(0, 0);
    particle->inverse_mass = 0;
    return MOTUS_OK;
}
MOTUS_DEF motus_real motus_particle_mass(const motus_particle *particle) {
    if (!particle) return (motus_real)NAN;
    return particle->inverse_mass == 0 ? (motus_real)HUGE_VAL : MOTUS_R(1.0) / particle->inverse_mass;
}
MOTUS_DEF motus_result motus_particle_check(const motus_particle *particle) {
    if (!particle) return MOTUS_ERROR_NULL_POINTER;
    return motus__check(motus__v3_of(particle->position), motus__v3_of(particle->velocity),
                        motus__v3_of(particle->force), particle->inverse_mass);
}
/* Adds `force` to the accumulator; rejects a non-finite force and a sum that would overflow. */
MOTUS_DEF motus_result motus_particle_add_force(motus_particle *particle, motus_vec2 force) {
#ifdef MOTUS__PAIRS
    motus__pair sum;
    if (!particle) return MOTUS_ERROR_NULL_POINTER;
    sum = motus__pair_load(&particle->force) + motus__pair_of(force.x, force.y);
    if (MOTUS__LIKELY(motus__pair_finite(sum))) {
        motus__pair_store(&particle->force, sum);
        return MOTUS_OK;
    }
#else
    motus_real x, y;
    if (!particle) return MOTUS_ERROR_NULL_POINTER;
    x = particle->force.x;
    y = particle->force.y;
    MOTUS__OPAQUE_CLANG(x); /* each a load of its own, see MOTUS__OPAQUE */
    MOTUS__OPAQUE_CLANG(y);
    /* A NaN or Inf among the terms makes the sum so; and x + y is finite only if both are: one test, and
       the cause only on failure. */
    x = x + force.x;
    y = y + force.y;
    if (MOTUS__LIKELY(motus_real_is_finite(x + y))) {
        particle->force.x = x;
        particle->force.y = y;
        return MOTUS_OK;
    }
#endif
    return motus__particle_add_force_rare(particle, force.x, force.y);
}
MOTUS_DEF motus_result motus_particle_clear_forces(motus_particle *particle) {
    if (!particle) return MOTUS_ERROR_NULL_POINTER;
#ifdef MOTUS__PAIRS
    motus__pair_store(&particle->force, motus__pair_zeros()); /* one store, for add_force's one load */
#else
    particle->force = motus_v2(0, 0);
#endif
    return MOTUS_OK;
}
/* Semi-implicit Euler with the accumulated force (see motus__step). Does not clear the force. */
MOTUS_DEF motus_result motus_particle_step(motus_particle *particle, motus_real dt) {
#ifdef MOTUS__PAIRS
    motus__pair h, force, v, x;
    motus_real im;
    if (!particle) return MOTUS_ERROR_NULL_POINTER;
    /* The common case: a movable particle, dt > 0, a finite result. A finite x then says that v, F, 1/m
       and dt were finite and nothing overflowed (a NaN or Inf anywhere makes x so). */
    im = particle->inverse_mass;
    h = motus__pair_of(dt, dt);
    force = motus__pair_round(motus__pair_load(&particle->force) * motus__pair_of(im, im));
    v = motus__pair_load(&particle->velocity) + motus__pair_round((force + motus__pair_of(0, 0)) * h);
    x = motus__pair_load(&particle->position) + motus__pair_round(v * h);
    if (MOTUS__LIKELY(motus__positive_bits(dt) && motus__positive_bits(im) && motus__pair_finite(x))) {
        motus__pair_store(&particle->velocity, v);
        motus__pair_store(&particle->position, x);
        return MOTUS_OK;
    }
#else
    motus_real im, fx, fy, vx, vy, xx, xy;
    if (!particle) return MOTUS_ERROR_NULL_POINTER;
    /* The common case: a movable particle, dt > 0, a finite result. A finite x then says that v, F, 1/m
       and dt were finite and nothing overflowed (a NaN or Inf anywhere makes x so). */
    im = particle->inverse_mass;
    fx = particle->force.x;
    fy = particle->force.y;
    MOTUS__OPAQUE(im); /* 1/m and the force each a load of its own: see MOTUS__OPAQUE */
    MOTUS__OPAQUE_CLANG(fx);
    MOTUS__OPAQUE_CLANG(fy);
    vx = motus__kick_finite(particle->velocity.x, fx, im, dt);
    vy = motus__kick_finite(particle->velocity.y, fy, im, dt);
    xx = particle->position.x + MOTUS__ROUND(vx * dt);
    xy = particle->position.y + MOTUS__ROUND(vy * dt);
    if (MOTUS__LIKELY(motus__positive_bits(dt) && motus__positive_bits(particle->inverse_mass) &&
                      motus_real_is_finite(xx + xy))) {
        motus_particle *out = particle; /* see MOTUS__OPAQUE_POINTER */
        MOTUS__OPAQUE_POINTER(out);
        out->velocity.x = vx;
        particle->velocity.y = vy;
        out->position.x = xx;
        particle->position.y = xy;
        return MOTUS_OK;
    }
#endif
    return motus__particle_step_rare(particle, dt);
}
/* motus_particle_step that keeps, in *carry ({0, 0} to start), what the position update rounded away, so
   that small steps far from the origin still add up (float at x = 1e6 m has an ulp of 0.0625 m). */
MOTUS_DEF motus_result motus_particle_step_compensated(motus_particle *particle, motus_vec2 *carry, motus_real dt) {
    motus_vec3 x, v, c;
    motus_result result;
    if (!particle || !carry) return MOTUS_ERROR_NULL_POINTER;
    x = motus__v3_of(particle->position);
    v = motus__v3_of(particle->velocity);
    c = motus__v3_of(*carry);
    result = motus__step_compensated(&x, &v, motus__v3_of(particle->force), particle->inverse_mass, &c, dt, 2);
    if (result == MOTUS_OK && dt != 0) {
        particle->position = motus__v2_of(x);
        particle->velocity = motus__v2_of(v);
        *carry = motus__v2_of(c);
    }
    return result;
}
/* v *= 1 - damping: the fraction `damping` of the velocity is removed (0.01: the reference's v *= 0.99).
   Frame-rate dependent; damp_per_second is not. damping in [0, 1]. */
MOTUS_DEF motus_result motus_particle_damp_per_step(motus_particle *particle, motus_real damping) {
    if (!particle) return MOTUS_ERROR_NULL_POINTER;
    /* 1/m > 0 as the step tests it, so that after a step the compiler drops this test */
    if (MOTUS__LIKELY(motus__damping_bits(damping) && motus__positive_bits(particle->inverse_mass))) {
        const motus_real kept = MOTUS_R(1.0) - damping;
#ifdef MOTUS__PAIRS
        const motus__pair damped = motus__pair_load(&particle->velocity) * motus__pair_of(kept, kept);
        motus_real x = damped[0], y = damped[1];
        motus__bits mx, my;
        if (MOTUS__LIKELY(motus__pair_moving(damped))) {
            motus__pair_store(&particle->velocity, damped);
            return MOTUS_OK;
        }
#else
        /* each component a load of its own: Clang -O3 -march=native otherwise loads the two as one pair right
           after the step's two stores, which the CPU cannot forward (a stall a particle: 2.2x slower) */
        motus_real x = particle->velocity.x, y = particle->velocity.y;
        motus__bits mx, my;
        MOTUS__OPAQUE(x);
        MOTUS__OPAQUE(y);
        x = x * kept;
        y = y * kept;
        if (MOTUS__LIKELY(motus__moving_bits(x) && motus__moving_bits(y))) {
            motus_particle *out = particle;
            MOTUS__OPAQUE_POINTER(out);
            out->velocity.x = x;
            particle->velocity.y = y;
            return MOTUS_OK;
        }
#endif
        mx = motus__magnitude_bits(x);
        my = motus__magnitude_bits(y);
        /* finite after damping <=> finite before (kept < 1, and Inf*0 is NaN) */
        if (MOTUS__LIKELY(mx < MOTUS__EXPONENT_MASK && my < MOTUS__EXPONENT_MASK)) {
            particle->velocity.x = motus__rest_flush(x, mx);
            particle->velocity.y = motus__rest_flush(y, my);
            return MOTUS_OK;
        }
    }
    return motus__particle_damp_rare(particle, damping);
}
/* v *= (1 - damping_per_second)^dt: after one second of steps the fraction damping_per_second of the speed
   is gone, whatever dt was. */
MOTUS_DEF motus_result motus_particle_damp_per_second(motus_particle *particle, motus_real damping_per_second,
                                                      motus_real dt) {
    motus_vec3 v;
    motus_result result;
    if (!particle) return MOTUS_ERROR_NULL_POINTER;
    if (!motus__dt_valid(dt)) return MOTUS_ERROR_INVALID_TIME_STEP;
    if (!motus__fraction_valid(damping_per_second)) return MOTUS_ERROR_INVALID_DAMPING;
    v = motus__v3_of(particle->velocity);
    result = motus__damp3(&v, particle->inverse_mass, motus__kept_per_second(damping_per_second, dt), 2);
    if (result == MOTUS_OK) particle->velocity = motus__v2_of(v);
    return result;
}
/* Keeps the particle inside [bounds_min, bounds_max] (an infinite bound is no wall), as the scene's bounds. */
MOTUS_DEF motus_result motus_particle_bounce(motus_particle *particle, motus_vec2 bounds_min, motus_vec2 bounds_max,
                                             motus_real restitution) {
    if (!particle) return MOTUS_ERROR_NULL_POINTER;
#ifdef MOTUS__PAIRS
    /* x + v*0 is x where v is finite and NaN where it is not: one test of both */
    if (MOTUS__LIKELY(motus__unit_bits(restitution) &&
                      motus__pair_inside(motus__pair_load(&particle->position) +
                                             motus__pair_load(&particle->velocity) * motus__pair_of(0, 0),
                                         motus__pair_of(bounds_min.x, bounds_min.y),
                                         motus__pair_of(bounds_max.x, bounds_max.y))))
        return MOTUS_OK;
    return motus__particle_bounce_rare(particle, bounds_min.x, bounds_min.y, bounds_max.x, bounds_max.y, restitution);
#else
    if (MOTUS__LIKELY(motus__unit_bits(restitution) && motus__inside(particle->position.x, bounds_min.x, bounds_max.x) &&
                      motus__inside(particle->position.y, bounds_min.y, bounds_max.y) &&
                      motus_real_is_finite(particle->velocity.x + particle->velocity.y)))
        return MOTUS_OK; /* nothing to bounce off, nothing to report */
    return motus__particle_bounce_rare(particle, bounds_min.x, bounds_min.y, bounds_max.x, bounds_max.y, restitution);
#endif
}

/* ---- the 3D particle functions: the same, on motus_vec3 ---- */
MOTUS_DEF motus_result motus_particle3_init(motus_particle3 *particle, motus_vec3 position, motus_real mass) {
    motus_real inverse_mass = 0;
    motus_result result;
    if (!particle) return MOTUS_ERROR_NULL_POINTER;
    result = motus__init(position, mass, &inverse_mass);
    if (result != MOTUS_OK) return result;
    particle->position = position;
    particle->velocity = particle->force = motus_v3(0, 0, 0);
    particle->inverse_mass = inverse_mass;
    return MOTUS_OK;
}
MOTUS_DEF motus_result motus_particle3_init_immovable(motus_particle3 *particle, motus_vec3 position) {
    if (!particle) return MOTUS_ERROR_NULL_POINTER;
    if (!motus_vec3_is_finite(position)) return MOTUS_ERROR_NOT_FINITE;
    particle->position = position;
    particle->velocity = particle->force = motus_v3(0, 0, 0);
    particle->inverse_mass = 0;
    return MOTUS_OK;
}
MOTUS_DEF motus_real motus_particle3_mass(const motus_particle3 *particle) {
    if (!particle) return (motus_real)NAN;
    return particle->inverse_mass == 0 ? (motus_real)HUGE_VAL : MOTUS_R(1.0) / particle->inverse_mass;
}
MOTUS_DEF motus_result motus_particle3_check(const motus_particle3 *particle) {
    if (!particle) return MOTUS_ERROR_NULL_POINTER;
    return motus__check(particle->position, particle->velocity, particle->force, particle->inverse_mass);
}
MOTUS_DEF motus_result motus_particle3_add_force(motus_particle3 *particle, motus_vec3 force) {
#ifdef MOTUS__PAIRS
    motus__pair sum;
    motus_real z;
    if (!particle) return MOTUS_ERROR_NULL_POINTER;
    sum = motus__pair_load(&particle->force) + motus__pair_of(force.x, force.y);
    z = particle->force.z + force.z;
    /* x + z and y + z are finite only if all three are (a sum that overflows takes the full test) */
    if (MOTUS__LIKELY(motus__pair_finite(sum + motus__pair_of(z, z)))) {
        motus__pair_store(&particle->force, sum);
        particle->force.z = z;
        return MOTUS_OK;
    }
#else
    motus_real x, y, z;
    if (!particle) return MOTUS_ERROR_NULL_POINTER;
    x = particle->force.x;
    y = particle->force.y;
    z = particle->force.z;
    MOTUS__OPAQUE_CLANG(x);
    MOTUS__OPAQUE_CLANG(y);
    MOTUS__OPAQUE_CLANG(z);
    x = x + force.x;
    y = y + force.y;
    z = z + force.z;
    if (MOTUS__LIKELY(motus_real_is_finite(x + y + z))) {
        particle->force.x = x;
        particle->force.y = y;
        particle->force.z = z;
        return MOTUS_OK;
    }
#endif
    return motus__particle3_add_force_rare(particle, force.x, force.y, force.z);
}
MOTUS_DEF motus_result motus_particle3_clear_forces(motus_particle3 *particle) {
    if (!particle) return MOTUS_ERROR_NULL_POINTER;
#ifdef MOTUS__PAIRS
    motus__pair_store(&particle->force, motus__pair_zeros());
    particle->force.z = 0;
#else
    particle->force = motus_v3(0, 0, 0);
#endif
    return MOTUS_OK;
}
MOTUS_DEF motus_result motus_particle3_step(motus_particle3 *particle, motus_real dt) {
#ifdef MOTUS__PAIRS
    motus__pair h, force, v, x;
    motus_real im, vz, xz;
    if (!particle) return MOTUS_ERROR_NULL_POINTER;
    im = particle->inverse_mass; /* the common case, as motus_particle_step; z beside the pair */
    h = motus__pair_of(dt, dt);
    force = motus__pair_round(motus__pair_load(&particle->force) * motus__pair_of(im, im));
    v = motus__pair_load(&particle->velocity) + motus__pair_round((force + motus__pair_of(0, 0)) * h);
    x = motus__pair_load(&particle->position) + motus__pair_round(v * h);
    vz = motus__kick_finite(particle->velocity.z, particle->force.z, im, dt);
    xz = particle->position.z + MOTUS__ROUND(vz * dt);
    if (MOTUS__LIKELY(motus__positive_bits(dt) && motus__positive_bits(im) &&
                      motus__pair_finite(x + motus__pair_of(xz, xz)))) {
        motus__pair_store(&particle->velocity, v);
        particle->velocity.z = vz;
        motus__pair_store(&particle->position, x);
        particle->position.z = xz;
        return MOTUS_OK;
    }
#else
    motus_real im, fx, fy, fz, vx, vy, vz, xx, xy, xz;
    if (!particle) return MOTUS_ERROR_NULL_POINTER;
    im = particle->inverse_mass; /* the common case, as motus_particle_step */
    fx = particle->force.x;
    fy = particle->force.y;
    fz = particle->force.z;
    MOTUS__OPAQUE(im);
    MOTUS__OPAQUE_CLANG(fx);
    MOTUS__OPAQUE_CLANG(fy);
    MOTUS__OPAQUE_CLANG(fz);
    vx = motus__kick_finite(particle->velocity.x, fx, im, dt);
    vy = motus__kick_finite(particle->velocity.y, fy, im, dt);
    vz = motus__kick_finite(particle->velocity.z, fz, im, dt);
    xx = particle->position.x + MOTUS__ROUND(vx * dt);
    xy = particle->position.y + MOTUS__ROUND(vy * dt);
    xz = particle->position.z + MOTUS__ROUND(vz * dt);
    if (MOTUS__LIKELY(motus__positive_bits(dt) && motus__positive_bits(particle->inverse_mass) &&
                      motus_real_is_finite(xx + xy + xz))) {
        motus_particle3 *out = particle;
        MOTUS__OPAQUE_POINTER(out);
        out->velocity.x = vx;
        particle->velocity.y = vy;
        out->velocity.z = vz;
        out->position.x = xx;
        particle->position.y = xy;
        out->position.z = xz;
        return MOTUS_OK;
    }
#endif
    return motus__particle3_step_rare(particle, dt);
}
MOTUS_DEF motus_result motus_particle3_step_compensated(motus_particle3 *particle, motus_vec3 *carry, motus_real dt) {
    if (!particle || !carry) return MOTUS_ERROR_NULL_POINTER;
    return motus__step_compensated(&particle->position, &particle->velocity, particle->force, particle->inverse_mass,
                                   carry, dt, 3);
}
MOTUS_DEF motus_result motus_particle3_damp_per_step(motus_particle3 *particle, motus_real damping) {
    if (!particle) return MOTUS_ERROR_NULL_POINTER;
    if (MOTUS__LIKELY(motus__damping_bits(damping) && motus__positive_bits(particle->inverse_mass))) {
        const motus_real kept = MOTUS_R(1.0) - damping;
#ifdef MOTUS__PAIRS
        const motus__pair damped = motus__pair_load(&particle->velocity) * motus__pair_of(kept, kept);
        motus_real x = damped[0], y = damped[1], z = particle->velocity.z * kept;
        motus__bits mx, my, mz;
        if (MOTUS__LIKELY(motus__pair_moving(damped) && motus__moving_bits(z))) {
            motus__pair_store(&particle->velocity, damped);
            particle->velocity.z = z;
            return MOTUS_OK;
        }
#else
        motus_real x = particle->velocity.x, y = particle->velocity.y, z = particle->velocity.z;
        motus__bits mx, my, mz;
        MOTUS__OPAQUE(x); /* as in motus_particle_damp_per_step */
        MOTUS__OPAQUE(y);
        MOTUS__OPAQUE(z);
        x = x * kept;
        y = y * kept;
        z = z * kept;
        if (MOTUS__LIKELY(motus__moving_bits(x) && motus__moving_bits(y) && motus__moving_bits(z))) {
            motus_particle3 *out = particle;
            MOTUS__OPAQUE_POINTER(out);
            out->velocity.x = x;
            particle->velocity.y = y;
            out->velocity.z = z;
            return MOTUS_OK;
        }
#endif
        mx = motus__magnitude_bits(x);
        my = motus__magnitude_bits(y);
        mz = motus__magnitude_bits(z);
        if (MOTUS__LIKELY(mx < MOTUS__EXPONENT_MASK && my < MOTUS__EXPONENT_MASK && mz < MOTUS__EXPONENT_MASK)) {
            particle->velocity.x = motus__rest_flush(x, mx);
            particle->velocity.y = motus__rest_flush(y, my);
            particle->velocity.z = motus__rest_flush(z, mz);
            return MOTUS_OK;
        }
    }
    return motus__particle3_damp_rare(particle, damping);
}
MOTUS_DEF motus_result motus_particle3_damp_per_second(motus_particle3 *particle, motus_real damping_per_second,
                                                       motus_real dt) {
    if (!particle) return MOTUS_ERROR_NULL_POINTER;
    if (!motus__dt_valid(dt)) return MOTUS_ERROR_INVALID_TIME_STEP;
    if (!motus__fraction_valid(damping_per_second)) return MOTUS_ERROR_INVALID_DAMPING;
    return motus__damp3(&particle->velocity, particle->inverse_mass, motus__kept_per_second(damping_per_second, dt), 3);
}
MOTUS_DEF motus_result motus_particle3_bounce(motus_particle3 *particle, motus_vec3 bounds_min, motus_vec3 bounds_max,
                                              motus_real restitution) {
    if (!particle) return MOTUS_ERROR_NULL_POINTER;
#ifdef MOTUS__PAIRS
    if (MOTUS__LIKELY(motus__unit_bits(restitution) &&
                      motus__pair_inside(motus__pair_load(&particle->position) +
                                             motus__pair_load(&particle->velocity) * motus__pair_of(0, 0),
                                         motus__pair_of(bounds_min.x, bounds_min.y),
                                         motus__pair_of(bounds_max.x, bounds_max.y)) &&
                      motus__inside(particle->position.z + particle->velocity.z * 0, bounds_min.z, bounds_max.z)))
        return MOTUS_OK;
#else
    if (MOTUS__LIKELY(motus__unit_bits(restitution) && motus__inside(particle->position.x, bounds_min.x, bounds_max.x) &&
                      motus__inside(particle->position.y, bounds_min.y, bounds_max.y) &&
                      motus__inside(particle->position.z, bounds_min.z, bounds_max.z) &&
                      motus_real_is_finite(particle->velocity.x + particle->velocity.y + particle->velocity.z)))
        return MOTUS_OK;
#endif
    return motus__particle3_bounce_rare(particle, bounds_min.x, bounds_min.y, bounds_min.z, bounds_max.x, bounds_max.y,
                                        bounds_max.z, restitution);
}

/* The damping per second that a per-step damping amounts to at a fixed rate: 1 - (1 - d)^rate. The
   reference program's 0.01 a step (v *= 0.99) at 60 steps a second is 0.453 per second. NaN for arguments
   out of range. */
MOTUS_DEF motus_real motus_damping_per_second_from_per_step(motus_real damping_per_step, motus_real steps_per_second) {
    if (!motus__fraction_valid(damping_per_step) || !motus__positive_finite(steps_per_second)) return (motus_real)NAN;
    return MOTUS_R(1.0) - MOTUS_POW(MOTUS_R(1.0) - damping_per_step, steps_per_second);
}

/* ---- states over arrays of particles: the engine reads your structs through a stride ---- */
MOTUS_DEF motus_state motus_state_of_particles(motus_particle *particles, int count) {
    motus_state s;
    memset(&s, 0, sizeof s);
    s.dimensions = 2;
    s.count = particles ? count : 0;
    s.stride = (int)(sizeof(motus_particle) / sizeof(motus_real));
    s.radius_stride = 1; /* state.radius: an array of its own */
    if (!particles) return s;
    s.position[0] = &particles->position.x;
    s.position[1] = &particles->position.y;
    s.velocity[0] = &particles->velocity.x;
    s.velocity[1] = &particles->velocity.y;
    s.force[0] = &particles->force.x;
    s.force[1] = &particles->force.y;
    s.inverse_mass = &particles->inverse_mass;
    return s;
}
MOTUS_DEF motus_state motus_state_of_particles3(motus_particle3 *particles, int count) {
    motus_state s;
    memset(&s, 0, sizeof s);
    s.dimensions = 3;
    s.count = particles ? count : 0;
    s.stride = (int)(sizeof(motus_particle3) / sizeof(motus_real));
    s.radius_stride = 1;
    if (!particles) return s;
    s.position[0] = &particles->position.x;
    s.position[1] = &particles->position.y;
    s.position[2] = &particles->position.z;
    s.velocity[0] = &particles->velocity.x;
    s.velocity[1] = &particles->velocity.y;
    s.velocity[2] = &particles->velocity.z;
    s.force[0] = &particles->force.x;
    s.force[1] = &particles->force.y;
    s.force[2] = &particles->force.z;
    s.inverse_mass = &particles->inverse_mass;
    return s;
}

/* ---- methods ---- */
MOTUS_DEF const char *motus_method_name(motus_method method) {
#define MOTUS__ROW(name, text, order, evaluations, limit) text,
    static const char *const names[MOTUS_METHOD_COUNT] = {MOTUS__METHODS(MOTUS__ROW)};
#undef MOTUS__ROW
    return (unsigned)method < MOTUS_METHOD_COUNT ? names[method] : NULL;
}
MOTUS_DEF int motus_method_order(motus_method method) {
#define MOTUS__ROW(name, text, order, evaluations, limit) order,
    static const int orders[MOTUS_METHOD_COUNT] = {MOTUS__METHODS(MOTUS__ROW)};
#undef MOTUS__ROW
    return (unsigned)method < MOTUS_METHOD_COUNT ? orders[method] : -1;
}
MOTUS_DEF int motus_method_evaluations(motus_method method) {
#define MOTUS__ROW(name, text, order, evaluations, limit) evaluations,
    static const int counts[MOTUS_METHOD_COUNT] = {MOTUS__METHODS(MOTUS__ROW)};
#undef MOTUS__ROW
    return (unsigned)method < MOTUS_METHOD_COUNT ? counts[method] : -1;
}
/* The largest w*h at which the method's amplitude on x'' = -w^2 x does not grow: 2 for semi-implicit
   Euler and the Verlets, 2*sqrt(2) for RK4, 1.5734 for Forest-Ruth, 2.9218 for McLachlan's method, 0 for
   explicit Euler and midpoint
   (they grow at every dt), +Inf for the exact stepper (it takes no spring); -1 out of range. */
MOTUS_DEF motus_real motus_method_stability_limit(motus_method method) {
#define MOTUS__ROW(name, text, order, evaluations, limit) (motus_real)(limit),
    static const motus_real limits[MOTUS_METHOD_COUNT] = {MOTUS__METHODS(MOTUS__ROW)};
#undef MOTUS__ROW
    if ((unsigned)method >= MOTUS_METHOD_COUNT) return -1;
    return limits[method] < 0 ? (motus_real)HUGE_VAL : limits[method];
}
/* limit/w_eff (see >>methods), from w^2 and half the decay rate (both finite, >= 0); +Inf when nothing
   limits; 0 when no step is stable. Where (alpha*c/2)^2 + w^2 overflows, the root is formed in units of
   the larger of alpha*c/2 and w, so that a representable dt is not lost to it (a linear drag of 1e20/s in
   float: 2e-20 s, not 0). */
MOTUS_DEF motus_real motus__stable_dt(motus_method method, motus_real omega_squared, motus_real half_decay) {
    const motus_real limit = motus_method_stability_limit(method);
    motus_real alpha = 1, half, sum, omega, larger;
    if (!motus_real_is_finite(limit) || (omega_squared == 0 && half_decay == 0)) return (motus_real)HUGE_VAL;
    if (limit == 0) return omega_squared > 0 ? 0 : 1 / half_decay;
    if (method == MOTUS_RK4) alpha = (motus_real)(2.8284271247461900976 / 2.7852935634050);
    if (method == MOTUS_FOREST_RUTH) alpha = 2;
    half = alpha * half_decay;
    /* alpha*c/2 itself past the largest real (alpha <= 2): the same dt from rates a quarter as large, a
       quarter of it (powers of two: nothing rounds unless the dt is subnormal) */
    if (!motus_real_is_finite(half)) return motus__stable_dt(method, omega_squared / 16, half_decay / 4) / 4;
    sum = MOTUS__ROUND(half * half) + omega_squared;
    if (motus_real_is_finite(sum)) return limit / (half + MOTUS_SQRT(sum));
    omega = MOTUS_SQRT(omega_squared);
    larger = half > omega ? half : omega;
    half = half / larger, omega = omega / larger;
    return limit / larger / (half + MOTUS_SQRT(MOTUS__ROUND(half * half) + MOTUS__ROUND(omega * omega)));
}
/* The largest dt at which `method` keeps an undamped spring of `stiffness` (N/m) on `mass` (kg) from
   growing: limit*sqrt(mass/stiffness). No safety margin. 0 for explicit Euler and midpoint, +Inf for
   stiffness 0 or the exact stepper. For a spring between two particles use the reduced mass. */
MOTUS_DEF motus_result motus_max_stable_dt(motus_method method, motus_real stiffness, motus_real mass,
                                           motus_real *max_dt) {
    if (!max_dt) return MOTUS_ERROR_NULL_POINTER;
    if ((unsigned)method >= MOTUS_METHOD_COUNT) return MOTUS_ERROR_INVALID_METHOD;
    if (!motus_real_is_finite(stiffness) || !motus_real_is_finite(mass)) return MOTUS_ERROR_NOT_FINITE;
    if (!(mass > 0)) return MOTUS_ERROR_INVALID_MASS;
    if (motus__real_bits(stiffness) > motus__real_bits((motus_real)-0.0) - 1 && stiffness != 0)
        return MOTUS_ERROR_INVALID_SPRING; /* negative */
    if (stiffness == 0) {
        *max_dt = (motus_real)HUGE_VAL;
        return MOTUS_OK;
    }
    /* limit*sqrt(m)/sqrt(k): k/m itself may underflow or overflow where the answer does not (stiffness
       1e-30 N/m on 1e30 kg is a finite 2e30 s for semi-implicit Euler). */
    {
        const motus_real limit = motus_method_stability_limit(method);
        /* limit 0 (explicit Euler, midpoint): 0 at any stiffness, not 0 * Inf when the root ratio overflows */
        *max_dt = !motus_real_is_finite(limit) || limit == 0 ? limit : limit * (MOTUS_SQRT(mass) / MOTUS_SQRT(stiffness));
    }
    return MOTUS_OK;
}
/* The fewest equal substeps n with dt/n < safety*max_stable_dt (as computed in motus_real). safety in
   (0, 1]. max_stable_dt +Inf gives 1; 0 (or -0) is MOTUS_ERROR_TOO_STIFF, as is needing more than 2^30.
   A dt so small that dt/n would round to 0 (subnormal) gets the largest n that keeps dt/n > 0. */
MOTUS_DEF motus_result motus_substeps_for(motus_real dt, motus_real max_stable_dt, motus_real safety, int *substeps) {
    motus_real limit, quotient;
    int n;
    if (!substeps) return MOTUS_ERROR_NULL_POINTER;
    if (!motus__dt_valid(dt)) return MOTUS_ERROR_INVALID_TIME_STEP;
    if (max_stable_dt != max_stable_dt || safety != safety) return MOTUS_ERROR_NOT_FINITE;
    if (!(max_stable_dt >= 0) || !(safety > 0 && safety <= 1)) return MOTUS_ERROR_INVALID_ARGUMENT;
    if (!motus_real_is_finite(max_stable_dt) || dt == 0) {
        *substeps = 1;
        return MOTUS_OK;
    }
    limit = safety * max_stable_dt;
    if (!(limit > 0)) return MOTUS_ERROR_TOO_STIFF; /* -0 and 0 alike, before any conversion */
    quotient = dt / limit;
    if (!(quotient < (motus_real)1073741824.0)) return MOTUS_ERROR_TOO_STIFF;
    n = (int)quotient;
    if (n < 1) n = 1;
    while (!(dt / (motus_real)n < limit)) ++n;
    while (n > 1 && dt / (motus_real)(n - 1) < limit) --n;
    while (n > 1 && !(dt / (motus_real)n > 0)) --n;
    *substeps = n;
    return MOTUS_OK;
}

/* ---- clock: the game loop's accumulator ----
   Frames take whatever time they take; the simulation should not. The clock turns each frame's duration
   into a whole number of steps of one fixed dt and carries the rest to the next frame (G. Fiedler, "Fix
   your timestep", 2004):
       motus_clock_advance(&clock, GetFrameTime(), &steps);
       for (i = 0; i < steps; ++i) { previous[k] = p[k].position...; step with clock.fixed_dt; }
       draw(motus_vec2_lerp(previous, current, motus_clock_alpha(&clock)));
   Interpolating between the last two steps hides the beat between frame and step rates; it draws the
   state of up to one step ago (alpha*dt behind the newest state), the price of never guessing ahead. A
   game that cannot afford it steps once more and extrapolates instead, which overshoots at collisions.
   The accumulator counts ticks, 2^32 to a step: a frame of exactly dt is exactly one step for ever. At
   most max_steps_per_frame steps run per frame; whole steps beyond are dropped and counted. */
#define MOTUS__CLOCK_TICKS_PER_STEP 4294967296.0 /* 2^32 */
#define MOTUS__CLOCK_TICK_MASK 0xFFFFFFFFu
MOTUS_DEF motus_result motus_clock_init(motus_clock *clock, motus_real fixed_dt, int max_steps_per_frame) {
    if (!clock) return MOTUS_ERROR_NULL_POINTER;
    if (!motus__positive_finite(fixed_dt)) return MOTUS_ERROR_INVALID_TIME_STEP;
    if (max_steps_per_frame < 0) return MOTUS_ERROR_INVALID_CLOCK;
    memset(clock, 0, sizeof *clock);
    clock->fixed_dt = fixed_dt;
    clock->max_steps_per_frame = max_steps_per_frame ? max_steps_per_frame : MOTUS_CLOCK_DEFAULT_MAX_STEPS;
    return MOTUS_OK;
}
MOTUS_DEF uint64_t motus__saturating_add(uint64_t a, uint64_t b) { return a + b < a ? ~(uint64_t)0 : a + b; }
/* Adds a frame of frame_seconds (finite, >= 0) and sets *steps_to_run. A bad frame time leaves the clock as
   it was with *steps_to_run = 0. */
MOTUS_DEF motus_result motus_clock_advance(motus_clock *clock, motus_real frame_seconds, int *steps_to_run) {
    double frame_steps, dt;
    uint64_t ticks, steps, cap, dropped = 0;
    motus_real time_dropped = 0;
    if (!clock || !steps_to_run) return MOTUS_ERROR_NULL_POINTER;
    *steps_to_run = 0;
    if (!motus_real_is_finite(frame_seconds) || frame_seconds < 0) return MOTUS_ERROR_INVALID_FRAME_TIME;
    if (!motus__positive_finite(clock->fixed_dt) || clock->max_steps_per_frame <= 0 ||
        clock->accumulator > MOTUS__CLOCK_TICK_MASK)
        return MOTUS_ERROR_INVALID_CLOCK; /* never initialised (zeroed), or corrupted: not divided by zero */
    dt = (double)clock->fixed_dt;
    cap = (uint64_t)clock->max_steps_per_frame;
    frame_steps = (double)frame_seconds / dt;
    if (frame_steps < 2147483648.0) { /* < 2^31 steps: the ticks fit in 64 bits */
        ticks = clock->accumulator + (uint64_t)(frame_steps * MOTUS__CLOCK_TICKS_PER_STEP + 0.5);
        steps = ticks >> 32;
        clock->accumulator = ticks & MOTUS__CLOCK_TICK_MASK;
        if (steps > cap) {
            dropped = steps - cap;
            time_dropped = (motus_real)((double)dropped * dt);
            steps = cap;
        }
    } else {
        steps = cap;
        dropped = frame_steps < 1.8e19 ? (uint64_t)frame_steps - cap : ~(uint64_t)0;
        time_dropped = (motus_real)((double)frame_seconds - (double)cap * dt);
    }
    clock->steps_dropped_last_frame = dropped;
    clock->steps_dropped_total = motus__saturating_add(clock->steps_dropped_total, dropped);
    clock->time_dropped_last_frame = time_dropped;
    clock->time_dropped_total += (double)time_dropped;
    clock->steps_total = motus__saturating_add(clock->steps_total, steps);
    *steps_to_run = (int)steps;
    return MOTUS_OK;
}
/* Where the clock is between the last step and the next, in [0, 1). */
MOTUS_DEF motus_real motus_clock_alpha(const motus_clock *clock) {
    motus_real alpha;
    if (!clock || clock->accumulator > MOTUS__CLOCK_TICK_MASK) return 0;
    alpha = (motus_real)((double)clock->accumulator / MOTUS__CLOCK_TICKS_PER_STEP);
    return alpha < 1 ? alpha : 1 - MOTUS_REAL_EPSILON / 2;
}
MOTUS_DEF double motus_clock_time(const motus_clock *clock) {
    return clock ? (double)clock->steps_total * (double)clock->fixed_dt : 0;
}

/* ---- messages and checks ---- */
MOTUS_DEF const char *motus_result_string(motus_result result) {
#define MOTUS__RESULT_TEXT(name, text) text,
    static const char *const texts[MOTUS_RESULT_COUNT] = {MOTUS__RESULTS(MOTUS__RESULT_TEXT)};
#undef MOTUS__RESULT_TEXT
    return (unsigned)result < MOTUS_RESULT_COUNT ? texts[result] : "unknown motus_result value";
}
MOTUS_DEF const char *motus_field_name(motus_field field) {
    static const char *const names[MOTUS_FIELD_COUNT] = {"none", "position", "velocity", "force", "inverse_mass",
                                                                  "radius"};
    return (unsigned)field < MOTUS_FIELD_COUNT ? names[field] : "unknown motus_field value";
}
MOTUS_DEF void motus__report(motus_check_report *report, int index, motus_field field, int component) {
    if (!report) return;
    report->index = index;
    report->field = field;
    report->component = component;
    report->field_name = motus_field_name(field);
}
/* The first bad particle: fields in the order position, velocity, force (x, y, z each), inverse mass. */
MOTUS_DEF motus_result motus__particles_check(const motus_real *base, int stride, int dims, int count,
                                              motus_check_report *report) {
    int i, k;
    motus__report(report, -1, MOTUS_FIELD_NONE, -1);
    if (!base && count > 0) return MOTUS_ERROR_NULL_POINTER;
    if (count < 0) return MOTUS_ERROR_INVALID_COUNT;
    for (i = 0; i < count; ++i) {
        const motus_real *p = base + (size_t)i * (size_t)stride;
        for (k = 0; k < 3 * dims; ++k)
            if (!motus_real_is_finite(p[k])) {
                motus__report(report, i, (motus_field)(MOTUS_FIELD_POSITION + k / dims), k % dims);
                return MOTUS_ERROR_NOT_FINITE;
            }
        if (!motus_real_is_finite(p[3 * dims]) || p[3 * dims] < 0) {
            motus__report(report, i, MOTUS_FIELD_INVERSE_MASS, -1);
            return motus_real_is_finite(p[3 * dims]) ? MOTUS_ERROR_INVALID_MASS : MOTUS_ERROR_NOT_FINITE;
        }
    }
    return MOTUS_OK;
}
MOTUS_DEF motus_result motus_particles_check(const motus_particle *particles, int count, motus_check_report *report) {
    return motus__particles_check(particles ? &particles->position.x : NULL,
                                  (int)(sizeof(motus_particle) / sizeof(motus_real)), 2, count, report);
}
MOTUS_DEF motus_result motus_particles3_check(const motus_particle3 *particles, int count, motus_check_report *report) {
    return motus__particles_check(particles ? &particles->position.x : NULL,
                                  (int)(sizeof(motus_particle3) / sizeof(motus_real)), 3, count, report);
}

#ifdef __cplusplus
} /* extern "C" */
#endif
MOTUS__QUIET_END
#endif /* MOTUS_H */

/* >>implementation ============================================================================== */
#if defined(MOTUS_IMPLEMENTATION) && !defined(MOTUS__IMPLEMENTED)
MOTUS__QUIET_BEGIN
#define MOTUS__IMPLEMENTED
/* The engine, compiled once per program. Contraction off for all of it (see >>config): its functions are
   called from your code, never inlined into it, so the pragma costs nothing. */
#ifndef MOTUS_ALLOW_FP_CONTRACT
#if defined(__clang__)
#pragma float_control(push)
#pragma STDC FP_CONTRACT OFF
#define MOTUS__ENGINE_PRAGMA_CLANG
#elif defined(__GNUC__) && (defined(__FP_FAST_FMA) || defined(__FP_FAST_FMAF))
#pragma GCC push_options
#pragma GCC optimize("fp-contract=off")
#define MOTUS__ENGINE_PRAGMA_GCC
#endif
#endif
/* GCC 12 stops with an internal compiler error in its partial redundancy elimination (-ftree-partial-pre,
   on at -O3) on the selects of double lanes when the target lacks SSE4.1's 64-bit compares (plain x86-64):
   that one pass is off for the engine there, so that double runs in vector lanes at every -O level (one
   particle at a time it took 2.7x float's time at -O2). */
#if defined(MOTUS_DOUBLE) && defined(__GNUC__) && !defined(__clang__) && defined(__SSE2__) && !defined(__SSE4_1__)
#ifndef MOTUS__ENGINE_PRAGMA_GCC
#pragma GCC push_options
#define MOTUS__ENGINE_PRAGMA_GCC
#endif
#pragma GCC optimize("no-tree-partial-pre")
#endif
/* GCC's second instruction scheduling (after register allocation) off for the engine on x86, where an
   out-of-order core reorders by itself: the unit compiled in 2.84-2.88 s where it took 2.99-3.15 (gcc 12
   -O2, Zen 4, best of 5, two sessions of runs), and the kernels ran as fast (2D and 3D, float and double, -O2 and -O3 -march=native: each
   within 3%). Scheduling moves no arithmetic: the golden hashes hold. (The "expensive optimizations" were
   worth as much compile time, but without them some kernels ran 5-16% slower: kept.) */
#if defined(__GNUC__) && !defined(__clang__) && defined(__OPTIMIZE__) && (defined(__x86_64__) || defined(__i386__))
#ifndef MOTUS__ENGINE_PRAGMA_GCC
#pragma GCC push_options
#define MOTUS__ENGINE_PRAGMA_GCC
#endif
#pragma GCC optimize("no-schedule-insns2")
#endif

#include <limits.h> /* INT_MAX */

#ifdef __cplusplus
extern "C" {
#endif

/* An unoptimised build (GCC and Clang's -O0, where __OPTIMIZE__ is not defined) compiles only the general
   kernel: it gives the same bits as the fast ones, a debugger steps through one function and each method's
   own, and the unit compiles in a fraction of the time. */
#if defined(__GNUC__) && !defined(__OPTIMIZE__)
#define MOTUS__FAST_KERNELS 0
#else
#define MOTUS__FAST_KERNELS 1
#endif

#if defined(__GNUC__) || defined(__clang__)
#define MOTUS__KI static inline __attribute__((always_inline))
#define MOTUS__PREFETCH(p) __builtin_prefetch((p), 1, 3)
#else
#define MOTUS__KI static inline
#define MOTUS__PREFETCH(p) ((void)(p))
#endif
/* The fast kernels ask for the x and v they will read and write MOTUS__PREFETCH_AHEAD particles ahead, in a
   call over at least MOTUS__PREFETCH_FROM particles (below that the state is in cache and the requests
   would only cost). Why: RK4 and Forest-Ruth keep a group of particles in registers for many dependent
   operations, so the out-of-order window held too few loads in flight to keep memory busy: at 10^7
   particles RK4 ran 1.17-1.23x the in-place bandwidth bound (x and v read and written once) where a
   hand-written Euler loop runs 1.01-1.09x; with the requests, every method 0.96-1.11x. */
#ifndef MOTUS__PREFETCH_AHEAD
#define MOTUS__PREFETCH_AHEAD 256
#endif
#ifndef MOTUS__PREFETCH_FROM
#define MOTUS__PREFETCH_FROM 16384
#endif

/* ---- lanes: a vector of motus_real where the compiler has vector extensions, one value elsewhere ---- */
#ifndef MOTUS_SIMD_BYTES
#if defined(__AVX512F__)
#define MOTUS_SIMD_BYTES 64
#elif defined(__AVX__)
#define MOTUS_SIMD_BYTES 32
#else
#define MOTUS_SIMD_BYTES 16
#endif
#endif
#if (defined(__GNUC__) || defined(__clang__)) && !defined(MOTUS_NO_SIMD) && MOTUS_SIMD_BYTES > 0
#define MOTUS__VECTOR 1
#ifdef MOTUS_DOUBLE
typedef int64_t motus__mask __attribute__((vector_size(MOTUS_SIMD_BYTES)));
#else
typedef int32_t motus__mask __attribute__((vector_size(MOTUS_SIMD_BYTES)));
#endif
typedef motus_real motus__lane __attribute__((vector_size(MOTUS_SIMD_BYTES)));
typedef motus_real motus__lane_unaligned __attribute__((vector_size(MOTUS_SIMD_BYTES), aligned(sizeof(motus_real))));
#define MOTUS__LANES ((int)(MOTUS_SIMD_BYTES / sizeof(motus_real)))
#ifdef MOTUS_DOUBLE /* the same, for #if */
#define MOTUS__LANES_PP (MOTUS_SIMD_BYTES / 8)
#else
#define MOTUS__LANES_PP (MOTUS_SIMD_BYTES / 4)
#endif
/* The hardware's vector square root, correctly rounded like sqrtf/sqrt. Through the compilers' builtins
   (GCC and Clang name them alike) rather than <immintrin.h>, which takes longer to parse than the engine
   to compile at 16 and 32 bytes; AVX-512 builds include the header. */
#if defined(__SSE2__) && !defined(MOTUS_SQRT_CUSTOM)
#if MOTUS_SIMD_BYTES == 16 && defined(MOTUS_DOUBLE)
#define MOTUS__VECTOR_SQRT(x) __builtin_ia32_sqrtpd(x)
#elif MOTUS_SIMD_BYTES == 16
#define MOTUS__VECTOR_SQRT(x) __builtin_ia32_sqrtps(x)
#elif MOTUS_SIMD_BYTES == 32 && defined(__AVX__) && defined(MOTUS_DOUBLE)
#define MOTUS__VECTOR_SQRT(x) __builtin_ia32_sqrtpd256(x)
#elif MOTUS_SIMD_BYTES == 32 && defined(__AVX__)
#define MOTUS__VECTOR_SQRT(x) __builtin_ia32_sqrtps256(x)
#elif MOTUS_SIMD_BYTES == 64 && defined(__AVX512F__)
#include <immintrin.h>
#ifdef MOTUS_DOUBLE /* maskz: gcc 12's plain _mm512_sqrt_pd trips -Wmaybe-uninitialized in its own header */
#define MOTUS__VECTOR_SQRT(x) (motus__lane) _mm512_maskz_sqrt_pd((__mmask8)0xFF, (__m512d)(x))
#else
#define MOTUS__VECTOR_SQRT(x) (motus__lane) _mm512_maskz_sqrt_ps((__mmask16)0xFFFF, (__m512)(x))
#endif
#endif
#endif
/* Whether any lane of a mask (each lane all ones or all zeros, as comparisons make them) is set: one
   instruction that gathers the lanes' top bits, where the portable loop moves each lane to a general
   register (a tether's step 1.3-1.5x faster with -march=native). In GCC's 16-byte doubles without SSE4.1
   (no 64-bit integer comparison) the mask goes through MOTUS__MASK_BARRIER first: without it GCC rebuilt
   the mask lane by lane (to a general register, and, neg, back) before the gather, 13% slower than the
   loop, and the same before every or of two masks (motus__either). */
#if defined(__SSE2__) && MOTUS_SIMD_BYTES == 16 &&                                                              \
    !(defined(__GNUC__) && !defined(__clang__) && !defined(__SSE4_1__) && defined(MOTUS_DOUBLE))
typedef char motus__mask_bytes __attribute__((vector_size(16)));
#define MOTUS__VECTOR_ANY(mask) (__builtin_ia32_pmovmskb128((motus__mask_bytes)(mask)) != 0)
#elif defined(__SSE2__) && MOTUS_SIMD_BYTES == 16 && defined(MOTUS_DOUBLE)
typedef double motus__mask_doubles __attribute__((vector_size(16)));
#define MOTUS__VECTOR_ANY(mask) motus__any_sse2_doubles(mask)
#elif defined(__AVX__) && MOTUS_SIMD_BYTES == 32
typedef float motus__mask_bytes __attribute__((vector_size(32)));
#define MOTUS__VECTOR_ANY(mask) (__builtin_ia32_movmskps256((motus__mask_bytes)(mask)) != 0)
#elif defined(__AVX512F__) && MOTUS_SIMD_BYTES == 64
#include <immintrin.h>
#define MOTUS__VECTOR_ANY(mask) (_mm512_test_epi32_mask((__m512i)(mask), (__m512i)(mask)) != 0)
#endif
#else
#define MOTUS__VECTOR 0
typedef int motus__mask;
typedef motus_real motus__lane;
#define MOTUS__LANES 1
#endif

/* GCC 12 on x86 with SSE2 and no SSE4.1 (x86-64's default target) in double stops with an internal compiler
   error (gimple-isel.cc:281, gimple_expand_vec_cond_expr) when jump threading leaves a comparison mask
   merged from several paths (a PHI) as the condition of the blends that motus__select becomes: the kernels
   for any scene hit it at -O2 -funsafe-math-optimizations, and with small changes to the kernels at plain
   -O2 and -O3. Through an empty asm, the particles' mask is a plain integer vector to the compiler, and
   motus__select stays the and/andnot/or it is written as (what SSE2 does for a blend anyway). */
#if MOTUS__VECTOR && defined(__GNUC__) && !defined(__clang__) && defined(__SSE2__) && !defined(__SSE4_1__) && \
    defined(MOTUS_DOUBLE) && MOTUS_SIMD_BYTES == 16
#define MOTUS__MASK_BARRIER(mask) __asm__("" : "+x"(mask))
#else
#define MOTUS__MASK_BARRIER(mask) (void)0
#endif

MOTUS__KI motus__lane motus__splat(motus_real value) {
#if MOTUS__VECTOR
    const motus__lane zero = {0};
    return value - zero; /* a broadcast; v - (+0) is v exactly, signed zeros included */
#else
    return value;
#endif
}
/* n <= MOTUS__LANES values, `stride` reals apart; lanes past n repeat the last value, so that they compute
   what a real particle computes (zeros would be phantom particles at the origin, where an attractor may
   sit). */
MOTUS__KI motus__lane motus__load(const motus_real *from, ptrdiff_t stride, int n) {
#if MOTUS__VECTOR
    if (stride == 1 && n == MOTUS__LANES) return *(const motus__lane_unaligned *)from;
    {
        /* Built from its values, not lane by lane: lane stores go through memory at -O2, and the vector
           read back after four (or more) small stores waits for them (a store-forwarding stall that made a
           strided step over motus_particle structs 4x slower). */
#define MOTUS__AT(l) from[(ptrdiff_t)((l) < n ? (l) : n - 1) * stride]
#if MOTUS__LANES_PP == 2
        const motus__lane lanes = {MOTUS__AT(0), MOTUS__AT(1)};
#elif MOTUS__LANES_PP == 4
        const motus__lane lanes = {MOTUS__AT(0), MOTUS__AT(1), MOTUS__AT(2), MOTUS__AT(3)};
#elif MOTUS__LANES_PP == 8
        const motus__lane lanes = {MOTUS__AT(0), MOTUS__AT(1), MOTUS__AT(2), MOTUS__AT(3),
                                   MOTUS__AT(4), MOTUS__AT(5), MOTUS__AT(6), MOTUS__AT(7)};
#else
        motus__lane lanes = motus__splat(0);
        int l;
        for (l = 0; l < MOTUS__LANES; ++l) lanes[l] = MOTUS__AT(l);
#endif
#undef MOTUS__AT
        return lanes;
    }
#else
    (void)n;
    (void)stride;
    return *from;
#endif
}
MOTUS__KI void motus__store(motus_real *to, motus__lane lanes, ptrdiff_t stride, int n) {
#if MOTUS__VECTOR
    int l;
    if (stride == 1 && n == MOTUS__LANES) {
        *(motus__lane_unaligned *)to = lanes;
        return;
    }
    for (l = 0; l < n; ++l) to[l * stride] = lanes[l];
#else
    (void)n;
    (void)stride;
    *to = lanes;
#endif
}
MOTUS__KI motus__lane motus__sqrt(motus__lane x) {
#if MOTUS__VECTOR && defined(MOTUS__VECTOR_SQRT)
    return MOTUS__VECTOR_SQRT(x);
#elif MOTUS__VECTOR
    int l;
    for (l = 0; l < MOTUS__LANES; ++l) x[l] = MOTUS_SQRT(x[l]);
    return x;
#else
    return MOTUS_SQRT(x);
#endif
}
/* mask ? a : b, lane by lane, without a branch. */
MOTUS__KI motus__lane motus__select(motus__mask mask, motus__lane a, motus__lane b) {
#if MOTUS__VECTOR
    motus__mask bits_a, bits_b, chosen;
    motus__lane result;
    __builtin_memcpy(&bits_a, &a, sizeof a);
    __builtin_memcpy(&bits_b, &b, sizeof b);
    chosen = (mask & bits_a) | (~mask & bits_b);
    __builtin_memcpy(&result, &chosen, sizeof result);
    return result;
#else
    return mask ? a : b;
#endif
}
#if defined(MOTUS__VECTOR_ANY) && defined(__SSE2__) && MOTUS_SIMD_BYTES == 16 && defined(MOTUS_DOUBLE) && \
    defined(__GNUC__) && !defined(__clang__) && !defined(__SSE4_1__)
MOTUS__KI int motus__any_sse2_doubles(motus__mask mask) {
    MOTUS__MASK_BARRIER(mask);
    return __builtin_ia32_movmskpd((motus__mask_doubles)mask) != 0;
}
#endif
/* a | b for two comparisons' masks. Through MOTUS__MASK_BARRIER where GCC (16-byte doubles, SSE2 without
   SSE4.1) would otherwise rebuild each mask lane by lane (a move to a general register, and, neg, and back)
   before the or. */
MOTUS__KI motus__mask motus__either(motus__mask a, motus__mask b) {
    MOTUS__MASK_BARRIER(a);
    MOTUS__MASK_BARRIER(b);
    return a | b;
}
/* Whether any lane of the mask is set. */
MOTUS__KI int motus__any(motus__mask mask) {
#if defined(MOTUS__VECTOR_ANY)
    return MOTUS__VECTOR_ANY(mask);
#elif MOTUS__VECTOR
    int l, any = 0;
    for (l = 0; l < MOTUS__LANES; ++l) any |= mask[l] != 0;
    return any;
#else
    return mask != 0;
#endif
}
/* A lane mask as reals: -1 (vectors) or 1 (scalars) where set, 0 where not. */
MOTUS__KI motus__lane motus__mask_as_lane(motus__mask mask) {
#if MOTUS__VECTOR
    return __builtin_convertvector(mask, motus__lane);
#else
    return (motus_real)mask;
#endif
}
MOTUS__KI motus_real motus__lane_sum(motus__lane x) {
#if MOTUS__VECTOR
    motus_real sum = 0;
    int l;
    for (l = 0; l < MOTUS__LANES; ++l) sum += x[l];
    return sum;
#else
    return x;
#endif
}

/* The statements once per dimension with d a constant (the third only in 3D). A loop over d would keep the
   lane arrays in memory at -O2 (GCC unrolls such loops only after it has decided what lives in registers). */
#define MOTUS__EACH_D(...)                                                                                       \
    do {                                                                                                         \
        { const int d = 0; __VA_ARGS__ }                                                                         \
        { const int d = 1; __VA_ARGS__ }                                                                         \
        if (dims == 3) { const int d = 2; __VA_ARGS__ }                                                          \
    } while (0)

/* ---- the job: the scene and the state as the kernels read them, made once per call ---- */
enum {
    MOTUS__T_GRAVITY = 1 << 0,
    MOTUS__T_LINEAR_DRAG = 1 << 1,
    MOTUS__T_QUADRATIC_DRAG = 1 << 2,
    MOTUS__T_ATTRACTOR = 1 << 3,
    MOTUS__T_FORCES = 1 << 4,   /* state.force[] */
    MOTUS__T_MASS = 1 << 5,     /* state.inverse_mass[] */
    MOTUS__T_DAMPING = 1 << 6,
    MOTUS__T_BOUNDS = 1 << 7,
    MOTUS__T_COUPLED = 1 << 8,  /* springs or a callback: stage forces in scratch */
    MOTUS__T_DRY = 1 << 9,      /* MOTUS_CHECKED's run that stores nothing */
    MOTUS__T_TETHER = 1 << 10
};
/* The terms a kernel sees, by `shape` (a constant where the kernel is compiled):
   - MOTUS__SHAPE_ANY, the general kernel (any stride, coupling, the dry run): every term read from the job
     at run time, gravity and linear drag always computed as a = (F/m + g) - k*v (g = 0, k = 0 when off);
   - MOTUS__SHAPE_ALL, the fast kernel for any scene: the same, over plain arrays, without coupling, and
     with the tether, the attractor and quadratic drag in their textbook formulas, inline (a group out of
     their range stops the kernel and goes to the general one, which scales them: see motus__acceleration);
   - the terms of the common scenes (gravity, linear drag, damping, any of them or none): a fast kernel for
     them, with nothing to test at run time but whether there is drag (a predictable branch a stage) and
     damping (one a step), and no work for what the scene lacks. A kernel of its own for each cost 54
     kernels to compile where there are 36 (0.35 s more for the engine unit with gcc -O2) for no speed
     that one run could tell apart (gravity alone at N = 4096, within 3% at -O2 and -O3). They give
     the bits the others give (g is stored as g + 0, so a = g here is (0 + g) - v*0 there, exactly). Not
     even a test for walls: a call in the loop, taken or not, costs these kernels 5% in float and 60% in
     double at -O2 (every vector register is the caller's to save), so scenes with walls run the kernel for
     any scene, whose walls skip the groups that reach none.
   Terms tested at run time cost a predictable branch per group of particles; gravity and drag computed at
   0 cost two operations. */
#define MOTUS__SHAPE_ANY 0x80000000u
#define MOTUS__SHAPE_ALL 0x40000000u
#define MOTUS__SHAPE_GRAVITY ((unsigned)(MOTUS__T_GRAVITY | MOTUS__T_LINEAR_DRAG | MOTUS__T_DAMPING))
#define MOTUS__EXACT_SHAPE(shape) ((shape) != MOTUS__SHAPE_ANY && (shape) != MOTUS__SHAPE_ALL)
/* Whether a kernel stops at a group with a term out of range (see motus__acceleration): a fast kernel
   always; the general kernel in a scene without coupling, except in the rescue's own runs. Both then stop
   on the same tests of the same values, and the group goes to motus__group_rescue: the paths agree. */
#define MOTUS__MAY_STOP(j, coupled) (!(coupled) || (!((j)->terms & MOTUS__T_COUPLED) && !(j)->rescuing))
#define MOTUS__TERMS(j, shape)                                                                                   \
    ((shape) == MOTUS__SHAPE_ANY   ? (j)->terms                                                                  \
     : (shape) == MOTUS__SHAPE_ALL ? ((j)->terms & ~(unsigned)(MOTUS__T_COUPLED | MOTUS__T_DRY))                 \
                                   : (shape))

typedef struct motus__job {
    unsigned terms;
    motus_method method; /* for the general kernel, which runs every method */
    int dims, substeps, record_stage, apply_damping, apply_drag;
    motus_real substep_dt; /* h as a number, for the callback's stage times */
    ptrdiff_t stride;
    motus_real *x[3], *v[3];
    const motus_real *f[3], *inverse_mass;
    /* scene terms */
    motus__lane gravity[3], linear_drag, quadratic_drag, attractor[3], attractor_strength, uniform_inverse_mass;
    motus__lane tether[3], tether_stiffness;
    motus__lane kept, rest_speed, bounds_min[3], bounds_max[3], bounce, largest;
    motus__lane drag_speed2_limit; /* |v|^2 past it: quadratic drag's textbook formula may overflow (see below) */
    /* step constants: h and the fractions of it the methods use */
    motus__lane h, half_h, half_h2, third_h, sixth_h;
    /* the splittings (Forest-Ruth, McLachlan): D(drift[0]) K(kick[0]) ... K(kick[kicks-1]) D(drift[kicks]) */
    motus__lane drift[MOTUS__MAX_EVALUATIONS + 1], kick[MOTUS__MAX_EVALUATIONS];
    int kicks;
    motus__lane exact_decay, exact_c1, exact_c2;
    /* coupled: the recorded stage state and the stage forces, plain arrays over the whole state */
    motus_real *stage_x[3], *stage_v[3];
    const motus_real *stage_force[MOTUS__MAX_EVALUATIONS][3];
    int rescuing; /* a job in the rescue's units (motus__group_rescue): no rescue in it */
} motus__job;

/* The terms with a square root and a division, whole, with the scaling that keeps them right at every
   scale: out of line, called by the general kernel. The fast kernels inline only their textbook formulas
   and hand a group out of those formulas' range to the general kernel (see motus__acceleration). */
/* The lanes where the attractor's textbook pull mu/|r|^3 is out of its range: |r|^3 past the largest real
   or below the smallest normal one, or the pull past the largest real. The one test of both the fast kernels
   (which stop there) and motus__costly_terms (which scales those lanes), so that both stop at the same
   groups. */
MOTUS__KI motus__mask motus__pull_out_of_range(motus__lane cube, motus__lane pull, motus__lane largest) {
    return motus__either(motus__either((motus__mask)(cube > largest),
                                       (motus__mask)(cube < motus__splat((motus_real)MOTUS__REAL_MIN_NORMAL))),
                         (motus__mask)(pull > largest));
}
/* max |c_d| over the components, the unit in which the costly terms below scale what would overflow */
MOTUS__KI motus__lane motus__largest_magnitude(const motus__lane *c, const int dims) {
    const motus__lane zero = motus__splat(0);
    motus__lane largest = motus__select(c[0] < zero, -c[0], c[0]);
    int d;
    for (d = 1; d < dims; ++d) {
        const motus__lane m = motus__select(c[d] < zero, -c[d], c[d]);
        largest = motus__select(m > largest, m, largest);
    }
    return largest;
}
MOTUS__KI int motus__costly_terms(const motus__job *j, const motus__lane *x, const motus__lane *v, motus__lane *a,
                                  const int dims, const int may_stop) {
    const unsigned t = j->terms;
    const motus__lane zero = motus__splat(0);
    int d;
    if (t & MOTUS__T_QUADRATIC_DRAG) {
        motus__lane speed2 = v[0] * v[0] + v[1] * v[1], speed, drag;
        motus__mask overflowed;
        if (dims == 3) speed2 = speed2 + v[2] * v[2];
        /* the fast kernels' test (see motus__acceleration), on the same value: the general kernel stops where
           they do (MOTUS__MAY_STOP) */
        if (may_stop && motus__any((motus__mask)(speed2 > j->drag_speed2_limit))) return 1;
        speed = motus__sqrt(speed2);
        /* |v|^2 overflows from |v| = 1.8e19 m/s in float, where c*|v|*v may not (a small c): there |v| is
           s*sqrt(sum (v_d/s)^2) with s = max|v_d|, as for the attractor below. Only the lanes that overflowed
           take it (a NaN or infinite v is not one: it stays as it was), so the other bits do not change. */
        overflowed = (motus__mask)(speed2 > j->largest) & (motus__mask)(v[0] - v[0] == zero) &
                     (motus__mask)(v[1] - v[1] == zero);
        if (dims == 3) overflowed = overflowed & (motus__mask)(v[2] - v[2] == zero);
        if (motus__any(overflowed)) {
            motus__lane largest = motus__largest_magnitude(v, dims), sum = zero;
            largest = motus__select(overflowed, largest, motus__splat(1)); /* > 0 where it is used */
            for (d = 0; d < dims; ++d) sum = sum + (v[d] / largest) * (v[d] / largest);
            speed = motus__select(overflowed, largest * motus__sqrt(sum), speed);
        }
        drag = j->quadratic_drag * speed;
        for (d = 0; d < dims; ++d) a[d] = a[d] - v[d] * drag;
    }
    if (t & MOTUS__T_ATTRACTOR) {
        /* a = -mu*r/|r|^3: pull = mu/(r^2*|r|), the textbook formula, where r^2*|r| is a normal real and the
           pull finite; the chain to the pull is then one division and one root long (the scaled form below
           is one of each longer, and this term's time is that chain's latency: Kepler orbits 1.4-1.5x faster
           with semi-implicit Euler and RK4 at -O2 on Zen 4, in float and in double). */
        motus__lane r[3], r2, cube, pull;
        motus__mask scaled;
        for (d = 0; d < dims; ++d) r[d] = x[d] - j->attractor[d];
        r2 = r[0] * r[0] + r[1] * r[1];
        if (dims == 3) r2 = r2 + r[2] * r[2];
        cube = r2 * motus__sqrt(r2);
        pull = j->attractor_strength / cube;
        /* Elsewhere (a NaN is neither: it stays NaN): r^2 overflows from |r| = 1.8e19 m in float and r^2*|r|
           from 7e12 m, where the pull is still representable; below the smallest normal real they have lost
           their digits (and at the attractor itself they are 0); mu/|r|^3 overflows for mu near the largest
           real at under 1 m, where mu*r/|r|^3 may not. Those lanes take mu*u/(s^2*|u|^3) with s = max|r_d|
           and u = r/s (|u| in [1, sqrt(3)]), which forms neither r^2 nor |r|^3. */
        scaled = motus__pull_out_of_range(cube, pull, j->largest);
        if (may_stop && motus__any(scaled)) return 1; /* the fast kernels' test, as above */
        if (motus__any(scaled)) {
            motus__lane s, inverse_s, u2, u[3], scaled_pull;
            motus__mask at_centre;
            s = motus__largest_magnitude(r, dims);
            at_centre = s == zero; /* no pull at the attractor itself */
            inverse_s = motus__splat(1) / motus__select(at_centre, motus__splat(1), s);
            u2 = zero;
            for (d = 0; d < dims; ++d) {
                u[d] = r[d] * inverse_s;
                u2 = u2 + u[d] * u[d];
            }
            scaled_pull = j->attractor_strength * inverse_s * inverse_s / (u2 * motus__sqrt(u2));
            /* mu*(1/s)^2 overflows for mu near the largest real and s < 1 where the pull may not (|u|^3 up to
               5.2 divides it): there (mu/|u|^3)*(1/s)*(1/s), each product no larger than the pull. The pull
               is the largest component of the acceleration (that of u is 1), so a pull that overflows is an
               acceleration that does. */
            scaled_pull = motus__select((motus__mask)(scaled_pull > j->largest) & (motus__mask)(u2 - u2 == zero),
                                        j->attractor_strength / (u2 * motus__sqrt(u2)) * inverse_s * inverse_s,
                                        scaled_pull);
            pull = motus__select(scaled, motus__select(at_centre, zero, scaled_pull), pull);
            for (d = 0; d < dims; ++d) r[d] = motus__select(scaled, u[d], r[d]); /* that pull acts on u */
        }
        for (d = 0; d < dims; ++d) a[d] = a[d] - r[d] * pull;
    }
    return 0;
}
#if defined(__GNUC__) || defined(__clang__)
#define MOTUS__NOINLINE __attribute__((noinline))
#else
#define MOTUS__NOINLINE
#endif
static MOTUS__NOINLINE int motus__costly_terms_2(const motus__job *j, const motus__lane *x, const motus__lane *v,
                                                 motus__lane *a, int may_stop) {
    return motus__costly_terms(j, x, v, a, 2, may_stop);
}
static MOTUS__NOINLINE int motus__costly_terms_3(const motus__job *j, const motus__lane *x, const motus__lane *v,
                                                 motus__lane *a, int may_stop) {
    return motus__costly_terms(j, x, v, a, 3, may_stop);
}

/* The tether's pull where x - tether overflowed (both beyond half the largest real, on opposite sides):
   formed from halves, (((x/2 - tether/2)*k)*(1/m))*2, which overflows only if the pull itself does. */
static MOTUS__NOINLINE void motus__tether_far(const motus__job *j, const motus__lane *x,
                                             const motus__lane *inverse_mass, motus__lane *pull, int dims) {
    const motus__lane zero = motus__splat(0), half = motus__splat(MOTUS_R(0.5)), two = motus__splat(2);
    int d;
    for (d = 0; d < dims; ++d) {
        const motus__lane offset = x[d] - j->tether[d];
        const motus__lane scaled = (((x[d] * half - j->tether[d] * half) * j->tether_stiffness) * *inverse_mass) * two;
        pull[d] = motus__select((motus__mask)(offset - offset != zero), scaled, pull[d]);
    }
}

/* The acceleration at a stage, from the terms that do not couple particles, plus the stage's coupled force
   (springs, callback) when there is one. base = F*(1/m) of the accumulated force, or 0. Terms that are
   off are skipped, not added as zero (which would turn a -0 into +0): the same bits whatever path. */
MOTUS__KI int motus__acceleration(const motus__job *j, const motus__lane *x, const motus__lane *v,
                                  const motus__lane *base, motus__lane inverse_mass, motus__mask movable,
                                  motus__lane *a, const int dims, const int coupled, const unsigned shape, int stage,
                                  int i) {
    const unsigned t = MOTUS__TERMS(j, shape);
    const motus__lane zero = motus__splat(0);
    /* F/m + g, then - k*v where there is linear drag. Without it, nothing is subtracted: (F/m + g) - v*0 is
       F/m + g for every finite v, since F/m + g is never -0 (g is stored as g + 0). */
    MOTUS__EACH_D(a[d] = MOTUS__EXACT_SHAPE(shape) ? j->gravity[d] : base[d] + j->gravity[d];);
    if ((t & MOTUS__T_LINEAR_DRAG) && j->apply_drag) MOTUS__EACH_D(a[d] = a[d] - v[d] * j->linear_drag;);
    if (t & MOTUS__T_TETHER) { /* a -= (k*(x - tether))*(1/m): the force, then as an accumulated force */
        /* zeros: 0, or NaN where a pull overflowed (or is NaN); offset_zeros the same for x - tether */
        motus__lane pull[3], zeros = zero, offset_zeros = zero;
        MOTUS__EACH_D(
            const motus__lane offset = x[d] - j->tether[d];
            pull[d] = (offset * j->tether_stiffness) * inverse_mass;
            zeros = zeros + (pull[d] - pull[d]);
            if (coupled) offset_zeros = offset_zeros + (offset - offset);
        );
        /* stop (see below): the pull, or x - tether, past the largest real. One comparison of a sum of
           zeros, not one a component: their masks' or cost GCC a lane-by-lane rebuild in double. */
        if (MOTUS__MAY_STOP(j, coupled) && motus__any((motus__mask)(zeros != zero))) return 1;
        if (coupled && motus__any((motus__mask)(offset_zeros != zero))) {
            /* the general kernel: out of line, through copies (see below) */
            motus__lane x_copy[3], pull_copy[3], inverse_mass_copy = inverse_mass;
            MOTUS__EACH_D(
                x_copy[d] = x[d];
                pull_copy[d] = pull[d];
            );
            motus__tether_far(j, x_copy, &inverse_mass_copy, pull_copy, dims);
            MOTUS__EACH_D(pull[d] = pull_copy[d];);
        }
        MOTUS__EACH_D(a[d] = a[d] - pull[d];);
    }
    if (!coupled && (t & (MOTUS__T_QUADRATIC_DRAG | MOTUS__T_ATTRACTOR))) {
        /* A fast kernel: the textbook formulas of motus__costly_terms, inline and in its order, the same
           operations and so the same bits. A group with a lane out of their range (where motus__costly_terms
           scales) stops: the kernel hands it to the general kernel, which makes the call. No call in a fast
           kernel's loop: a call, taken or not, makes GCC keep the loop's constants in memory, not in
           registers (the call may use every vector register). */
        const motus__lane largest = j->largest;
        motus__lane r[3], r2, cube, pull, speed2, drag;
        if (t & MOTUS__T_QUADRATIC_DRAG) {
            speed2 = v[0] * v[0] + v[1] * v[1];
            if (dims == 3) speed2 = speed2 + v[2] * v[2];
            if (motus__any((motus__mask)(speed2 > j->drag_speed2_limit))) return 1;
            drag = j->quadratic_drag * motus__sqrt(speed2);
            MOTUS__EACH_D(a[d] = a[d] - v[d] * drag;);
        }
        if (t & MOTUS__T_ATTRACTOR) {
            MOTUS__EACH_D(r[d] = x[d] - j->attractor[d];);
            r2 = r[0] * r[0] + r[1] * r[1];
            if (dims == 3) r2 = r2 + r[2] * r[2];
            cube = r2 * motus__sqrt(r2);
            pull = j->attractor_strength / cube;
            if (motus__any(motus__pull_out_of_range(cube, pull, largest))) return 1;
            MOTUS__EACH_D(a[d] = a[d] - r[d] * pull;);
        }
    } else if (t & (MOTUS__T_QUADRATIC_DRAG | MOTUS__T_ATTRACTOR)) {
        /* Copies go to the call, so that x, v and a themselves never have their address taken and stay in
           registers on the paths that do not make it. */
        motus__lane x_copy[3], v_copy[3], a_copy[3];
        MOTUS__EACH_D(
            x_copy[d] = x[d];
            v_copy[d] = v[d];
            a_copy[d] = a[d];
    );
        /* in a scene without coupling, the general kernel stops where a fast kernel would (MOTUS__MAY_STOP) */
        if (dims == 2 ? motus__costly_terms_2(j, x_copy, v_copy, a_copy, MOTUS__MAY_STOP(j, coupled))
                      : motus__costly_terms_3(j, x_copy, v_copy, a_copy, MOTUS__MAY_STOP(j, coupled)))
            return 1;
        MOTUS__EACH_D(a[d] = a_copy[d];);
    }
    if (coupled && (t & MOTUS__T_COUPLED))
        MOTUS__EACH_D(if (j->stage_force[stage][d]) /* whole groups (see motus__layout) */
                          a[d] = a[d] + motus__load(j->stage_force[stage][d] + i, 1, MOTUS__LANES) * inverse_mass;);
    if (t & MOTUS__T_MASS) { /* immovable: no acceleration (a NaN still shows in the check) */
        /* -0, not +0: v + (-0)*h is v for every v, -0 included (+0 turned a -0 velocity into +0, and then
           a position at -0 into +0 where motus_particle_step's drift x + v*dt keeps it -0) */
        const motus__lane no_acceleration = motus__splat(-MOTUS_R(0.0));
        MOTUS__EACH_D(a[d] = motus__select(movable, a[d], no_acceleration););
    }
    return 0;
}

/* One evaluation of the forces at stage `stage`. In a pass that records that stage (coupled scenes), the
   stage's state is stored for the springs and the callback instead, and the method stops there: returns 1. */
MOTUS__KI int motus__evaluate(const motus__job *j, int stage, const motus__lane *x, const motus__lane *v,
                              const motus__lane *base, motus__lane inverse_mass, motus__mask movable, motus__lane *a,
                              const int dims, const int coupled, const unsigned shape, int i, int n) {
    if (coupled && j->record_stage == stage) {
        MOTUS__EACH_D(if (j->stage_x[d]) {
                motus__store(j->stage_x[d] + i, x[d], 1, MOTUS__LANES); /* whole groups (motus__layout) */
                motus__store(j->stage_v[d] + i, v[d], 1, MOTUS__LANES);
            });
        return 1;
    }
    (void)n;
    return motus__acceleration(j, x, v, base, inverse_mass, movable, a, dims, coupled, shape, stage, i);
}
#define MOTUS__EVALUATE(stage, xs, vs, a)                                                                        \
    if (motus__evaluate(j, stage, xs, vs, base, inverse_mass, movable, a, dims, coupled, shape, i, n)) return 1

/* ---- the methods, one function each (see >>methods for the formulas, orders and limits) ----
   x, v: the state, updated in place; each returns 1 if it stopped at a recorded stage. */
#define MOTUS__METHOD_ARGS                                                                                       \
    const motus__job *j, motus__lane *x, motus__lane *v, const motus__lane *base, motus__lane inverse_mass,      \
        motus__mask movable, const int dims, const int coupled, const unsigned shape, int i, int n
MOTUS__KI int motus__semi_implicit_euler(MOTUS__METHOD_ARGS) {
    motus__lane a[3];
    MOTUS__EVALUATE(0, x, v, a);
    MOTUS__EACH_D(
        v[d] = v[d] + a[d] * j->h;
        x[d] = x[d] + v[d] * j->h;
    );
    return 0;
}
MOTUS__KI int motus__explicit_euler(MOTUS__METHOD_ARGS) {
    motus__lane a[3];
    MOTUS__EVALUATE(0, x, v, a);
    MOTUS__EACH_D(
        x[d] = x[d] + v[d] * j->h;
        v[d] = v[d] + a[d] * j->h;
    );
    return 0;
}
MOTUS__KI int motus__position_verlet(MOTUS__METHOD_ARGS) {
    motus__lane a[3];
    MOTUS__EACH_D(x[d] = x[d] + v[d] * j->half_h;);
    MOTUS__EVALUATE(0, x, v, a);
    MOTUS__EACH_D(
        v[d] = v[d] + a[d] * j->h;
        x[d] = x[d] + v[d] * j->half_h;
    );
    return 0;
}
/* The velocity's change is formed as a0*(h/2) + a1*(h/2): a0 + a1 overflows where the accelerations pass
   half the largest real and the step does not (the same for RK4's sums below). */
MOTUS__KI int motus__velocity_verlet(MOTUS__METHOD_ARGS) {
    motus__lane a0[3], a1[3], predicted[3];
    MOTUS__EVALUATE(0, x, v, a0);
    MOTUS__EACH_D(
        x[d] = x[d] + v[d] * j->h + a0[d] * j->half_h2;
        predicted[d] = v[d] + a0[d] * j->h;
    );
    MOTUS__EVALUATE(1, x, predicted, a1);
    MOTUS__EACH_D(v[d] = v[d] + (a0[d] * j->half_h + a1[d] * j->half_h););
    return 0;
}
MOTUS__KI int motus__leapfrog(MOTUS__METHOD_ARGS) {
    motus__lane a0[3], a1[3], predicted[3];
    MOTUS__EVALUATE(0, x, v, a0);
    MOTUS__EACH_D(
        v[d] = v[d] + a0[d] * j->half_h;
        x[d] = x[d] + v[d] * j->h;
        predicted[d] = v[d] + a0[d] * j->half_h;
    );
    MOTUS__EVALUATE(1, x, predicted, a1);
    MOTUS__EACH_D(v[d] = v[d] + a1[d] * j->half_h;);
    return 0;
}
MOTUS__KI int motus__midpoint(MOTUS__METHOD_ARGS) {
    motus__lane a0[3], a1[3], xm[3], vm[3];
    MOTUS__EVALUATE(0, x, v, a0);
    MOTUS__EACH_D(
        xm[d] = x[d] + v[d] * j->half_h;
        vm[d] = v[d] + a0[d] * j->half_h;
    );
    MOTUS__EVALUATE(1, xm, vm, a1);
    MOTUS__EACH_D(
        x[d] = x[d] + vm[d] * j->h;
        v[d] = v[d] + a1[d] * j->h;
    );
    return 0;
}
/* The weighted sum as odeint's rk4 forms it, x + h/6*k1 + h/3*k2 + h/3*k3 + h/6*k4: each term a change of
   x or v, so no sum passes the largest real unless the step does (k1 + 2*k2 + 2*k3 + k4 overflowed in
   float for velocities past 6.8e37 m/s, where the step itself fits). */
MOTUS__KI int motus__rk4(MOTUS__METHOD_ARGS) {
    motus__lane a[3], xs[3], vs[3], dx[3], dv[3];
    MOTUS__EVALUATE(0, x, v, a);
    MOTUS__EACH_D( /* k1 = (v, a1); v*h/6 is added at the next stage, where it is needed (v is kept anyway) */
        dv[d] = a[d] * j->sixth_h;
        xs[d] = x[d] + v[d] * j->half_h;
        vs[d] = v[d] + a[d] * j->half_h;
    );
    MOTUS__EVALUATE(1, xs, vs, a);
    MOTUS__EACH_D( /* k2 = (vs, a2) */
        dx[d] = v[d] * j->sixth_h + vs[d] * j->third_h;
        dv[d] = dv[d] + a[d] * j->third_h;
        xs[d] = x[d] + vs[d] * j->half_h;
        vs[d] = v[d] + a[d] * j->half_h;
    );
    MOTUS__EVALUATE(2, xs, vs, a);
    MOTUS__EACH_D( /* k3 */
        dx[d] = dx[d] + vs[d] * j->third_h;
        dv[d] = dv[d] + a[d] * j->third_h;
        xs[d] = x[d] + vs[d] * j->h;
        vs[d] = v[d] + a[d] * j->h;
    );
    MOTUS__EVALUATE(3, xs, vs, a);
    MOTUS__EACH_D( /* k4 */
        x[d] = x[d] + (dx[d] + vs[d] * j->sixth_h);
        v[d] = v[d] + (dv[d] + a[d] * j->sixth_h);
    );
    return 0;
}
/* Forest-Ruth and McLachlan's method: symmetric splittings, drift-kick-...-kick-drift, one loop over the
   job's coefficients (so both run the same kernels, and each stage's code is compiled once). */
MOTUS__KI int motus__splitting(MOTUS__METHOD_ARGS) {
    motus__lane a[3];
    int stage;
    for (stage = 0; stage < j->kicks; ++stage) {
        MOTUS__EACH_D(x[d] = x[d] + v[d] * j->drift[stage];);
        MOTUS__EVALUATE(stage, x, v, a);
        MOTUS__EACH_D(v[d] = v[d] + a[d] * j->kick[stage];);
    }
    MOTUS__EACH_D(x[d] = x[d] + v[d] * j->drift[stage];);
    return 0;
}
/* v = v0*e^-u + a*c1, x = x0 + v0*c1 + a*c2 (see >>methods): gravity and the accumulated force make a, the
   linear drag is in the coefficients. */
MOTUS__KI int motus__exact_linear_drag(MOTUS__METHOD_ARGS) {
    const motus__lane zero = motus__splat(0);
    const unsigned t = MOTUS__TERMS(j, shape);
    (void)coupled;
    (void)i;
    (void)n;
    (void)inverse_mass;
    MOTUS__EACH_D(
        motus__lane a = MOTUS__EXACT_SHAPE(shape) ? j->gravity[d] : base[d] + j->gravity[d];
        const motus__lane v0 = v[d];
        if (t & MOTUS__T_MASS) a = motus__select(movable, a, zero);
        v[d] = v0 * j->exact_decay + a * j->exact_c1;
        x[d] = x[d] + v0 * j->exact_c1 + a * j->exact_c2;
        if (t & MOTUS__T_MASS) { /* immovable: drag does not act either; it drifts */
            v[d] = motus__select(movable, v[d], v0);
            x[d] = motus__select(movable, x[d], x[d] - v0 * j->exact_c1 + v0 * j->h);
        }
    );
    return 0;
}

/* The walls of axis d: past one, the position is mirrored back inside and that velocity component multiplied
   by -restitution; a particle that overshot by more than the box is clamped to the wall (as
   motus_particle_bounce). Only where the position is finite: an overflow must stay visible to the check. */
MOTUS__KI void motus__walls_axis(const motus__job *j, motus__lane *x_in, motus__lane *v_in, int d) {
    const motus__lane lo = j->bounds_min[d], hi = j->bounds_max[d];
    motus__lane x = *x_in, v = *v_in, mirrored;
    const motus__mask finite = (motus__mask)(x >= motus__splat(-MOTUS__REAL_MAX)) &
                               (motus__mask)(x <= motus__splat(MOTUS__REAL_MAX));
    motus__mask below = x < lo, above;
    mirrored = lo + (lo - x);
    mirrored = motus__select(mirrored <= j->largest, mirrored, lo); /* the mirror overflowed */
    x = motus__select(below, mirrored, x);
    v = motus__select(below, v * j->bounce, v);
    above = x > hi;
    mirrored = hi - (x - hi);
    mirrored = motus__select(mirrored >= -j->largest, mirrored, hi);
    x = motus__select(above, mirrored, x);
    v = motus__select(above, v * j->bounce, v);
    x = motus__select((x < lo) & finite, lo, x);
    x = motus__select((x > hi) & finite, hi, x);
    *x_in = x;
    *v_in = v;
}
/* The walls of every axis. An axis's walls change nothing unless a lane is past one of them (a NaN is past
   none): most groups of most steps pay two compares an axis, and a pile on the floor pays for the floor
   only. Out of line, as the costly terms, and called only for a group with a lane past a wall. Tried and
   not kept: the walls inline in the kernels for gravity, so that a scene with walls need not run the
   kernel for any scene: such scenes ran 1.6-2.5x faster at -O2 (1.1-1.5x native), but the unit took 1 s
   longer to compile (a third more) with kernels of their own, or gravity alone ran 11-36% slower at -O2
   with the walls tested at run time. */
MOTUS__KI void motus__walls(const motus__job *j, motus__lane *x, motus__lane *v, const int dims) {
    MOTUS__EACH_D(
        if (motus__any(motus__either((motus__mask)(x[d] < j->bounds_min[d]), (motus__mask)(x[d] > j->bounds_max[d]))))
            motus__walls_axis(j, &x[d], &v[d], d);
    );
}
static MOTUS__NOINLINE void motus__walls_2(const motus__job *j, motus__lane *x, motus__lane *v) { motus__walls(j, x, v, 2); }
static MOTUS__NOINLINE void motus__walls_3(const motus__job *j, motus__lane *x, motus__lane *v) { motus__walls(j, x, v, 3); }

/* MOTUS__LANES particles (n of them real) from index i, as registers: loaded, stepped by every substep's
   method and walls, damped, checked, stored. dims and contiguous are constants where these are inlined, so
   the compiler drops what they exclude. The general kernel runs with dims 3 and reads j->dims: a 2D state's
   z is 0 in, discarded out, and every x and y operation is the one a 2D kernel does (adding a +0 square to
   a sum of squares, or a 0 to a max of magnitudes, changes no bit), so the two agree bit for bit. */
typedef struct motus__group {
    motus__lane x[3], v[3], base[3], force[3], v_start[3], inverse_mass;
    motus__mask movable;
    ptrdiff_t stride, at;
    int n;
} motus__group;
#define MOTUS__AXIS(d) (contiguous || (d) < j->dims) /* a component the state has */
MOTUS__KI void motus__group_load(const motus__job *j, motus__group *g, int i, int n, const int dims,
                                 const int contiguous, const unsigned shape) {
    const unsigned t = MOTUS__TERMS(j, shape);
    const motus__lane zero = motus__splat(0);
    g->n = n;
    g->stride = contiguous ? 1 : j->stride;
    g->at = (ptrdiff_t)i * g->stride;
    g->inverse_mass = (t & MOTUS__T_MASS) ? motus__load(j->inverse_mass + g->at, g->stride, n) : j->uniform_inverse_mass;
    g->movable = g->inverse_mass != zero;
    MOTUS__MASK_BARRIER(g->movable);
    MOTUS__EACH_D(
        const int axis = MOTUS__AXIS(d);
        g->x[d] = axis ? motus__load(j->x[d] + g->at, g->stride, n) : zero;
        g->v[d] = axis ? motus__load(j->v[d] + g->at, g->stride, n) : zero;
        g->force[d] = (axis && (t & MOTUS__T_FORCES)) ? motus__load(j->f[d] + g->at, g->stride, n) : zero;
        g->base[d] = g->force[d] * g->inverse_mass;
    );
}
/* The inputs the step may not show in its results: a NaN or Inf force on an immovable particle (its
   acceleration is 0 whatever the force), an inverse mass that is NaN, or negative. */
/* Whether a lane's F*(1/m) is not finite: b - b is 0 for a finite b and NaN for the rest, and a sum of such
   zeros cannot overflow. */
MOTUS__KI int motus__base_overflowed(const motus__lane *base, const int dims) {
    motus__lane zeros = (base[0] - base[0]) + (base[1] - base[1]);
    if (dims == 3) zeros = zeros + (base[2] - base[2]);
    return motus__any((motus__mask)(zeros != zeros));
}
MOTUS__KI void motus__group_check_inputs(const motus__job *j, const motus__group *g, motus__lane *check,
                                         const int dims, const unsigned shape) {
    const unsigned t = MOTUS__TERMS(j, shape);
    motus__lane bad = motus__splat(0);
    if (t & MOTUS__T_MASS) bad = g->inverse_mass - g->inverse_mass; /* NaN for a NaN or infinite one */
    if (t & MOTUS__T_FORCES) MOTUS__EACH_D(bad = bad * g->force[d];); /* 0 times it: NaN unless finite */
    if (t & (MOTUS__T_MASS | MOTUS__T_FORCES)) check[0] = check[0] + bad;
}
/* After a substep's method: immovable velocities back as they were, the check sum, the walls. The check is
   made before the walls, whose clamp would turn an infinite position into the wall. */
MOTUS__KI void motus__group_substep_end(const motus__job *j, motus__group *g, motus__lane *check, const int dims,
                                        const unsigned shape) {
    const unsigned t = MOTUS__TERMS(j, shape);
    if (t & MOTUS__T_MASS) /* nothing changed an immovable particle's velocity, not even a -0 into +0 */
        MOTUS__EACH_D(g->v[d] = motus__select(g->movable, g->v[d], g->v_start[d]););
    /* x - x is 0 for a finite x and NaN for the rest, and 0 times a value is 0 for a finite value and NaN
       for the rest: ((x0 - x0)*v0)*x1*v1... is 0 exactly when every value is finite, and the sum of such
       products cannot overflow, so a check that is not finite means a value that is not (a sum of the
       values themselves overflows near the largest real; a product of them too). A chain of products: a
       third fewer operations than a sum of differences, x - x and v - v each, and half of them on the
       multiplier, which on Zen 4 has pipes of its own: steps in cache there up to a third faster (16 of
       27 cells measured 7-33% faster, the rest within 5%). */
    {
        motus__lane zeros = (g->x[0] - g->x[0]) * g->v[0];
        MOTUS__EACH_D(if (d > 0) zeros = (zeros * g->x[d]) * g->v[d];);
        check[0] = check[0] + zeros;
    }
    if (t & MOTUS__T_BOUNDS) {
        /* Only a group with a lane past a wall (a NaN is past none) makes the call: out of line, through
           copies, as the costly terms. */
        motus__mask past =
            motus__either((motus__mask)(g->x[0] < j->bounds_min[0]), (motus__mask)(g->x[0] > j->bounds_max[0]));
        MOTUS__EACH_D(
            if (d > 0) past = motus__either(motus__either(past, (motus__mask)(g->x[d] < j->bounds_min[d])),
                                            (motus__mask)(g->x[d] > j->bounds_max[d]));
        );
        if (motus__any(past)) {
            motus__lane x_copy[3], v_copy[3];
            MOTUS__EACH_D(
                x_copy[d] = g->x[d];
                v_copy[d] = g->v[d];
            );
            if (dims == 2) motus__walls_2(j, x_copy, v_copy);
            else motus__walls_3(j, x_copy, v_copy);
            MOTUS__EACH_D(
                g->x[d] = x_copy[d];
                g->v[d] = v_copy[d];
            );
        }
    }
}
/* The damping (once per motus_step, after the last substep), then the stores. */
MOTUS__KI void motus__group_finish(const motus__job *j, motus__group *g, const int dims, const int contiguous,
                                   const unsigned shape) {
    const unsigned t = MOTUS__TERMS(j, shape);
    const motus__lane zero = motus__splat(0);
    if ((t & MOTUS__T_DAMPING) && j->apply_damping)
        MOTUS__EACH_D( /* as motus__damp: slow components to a zero of their sign */
            motus__lane damped = g->v[d] * j->kept;
            damped = motus__select((damped < j->rest_speed) & (damped > -j->rest_speed), damped * zero, damped);
            g->v[d] = (t & MOTUS__T_MASS) ? motus__select(g->movable, damped, g->v[d]) : damped;
    );
    if (t & MOTUS__T_DRY) return;
    MOTUS__EACH_D(if (MOTUS__AXIS(d)) {
            motus__store(j->x[d] + g->at, g->x[d], g->stride, g->n);
            motus__store(j->v[d] + g->at, g->v[d], g->stride, g->n);
        });
}
#undef MOTUS__AXIS

/* A kernel: particles [first, end) in groups of MOTUS__LANES, each through `method` (a name: the macro
   makes one group function per method, so that a fast kernel holds only its own method's code). Returns
   nonzero if the new state's check sum is not finite. Fast kernels (plain arrays, no coupling) take whole
   groups with plain vector loads and hand the rest to the general kernel. */
#define MOTUS__KERNEL_OF(method)                                                                                 \
    MOTUS__KI long long motus__kernel_##method(const motus__job *job, int first, int end, const int dims,        \
                                         const int contiguous, const int coupled, const unsigned shape) {        \
        /* A local copy: the state arrays the kernel stores to could alias the job's reals in memory, which      \
           would make the compiler reload every constant after every store; they cannot alias a local. */        \
        const motus__job local = *job, *j = &local;                                                              \
        motus__lane check = motus__splat(0); /* 0, or NaN once a value is not finite */                          \
        motus__group g;                                                                                          \
        int i, s, broken = 0, end_here = end, prefetch_end;                                                      \
        if (contiguous) end_here = first + (end - first) / MOTUS__LANES * MOTUS__LANES;                          \
        prefetch_end = contiguous && end_here - first >= MOTUS__PREFETCH_FROM ? end_here - MOTUS__PREFETCH_AHEAD \
                                                                               : first;                          \
        for (i = first; i < end_here; i += MOTUS__LANES) {                                                       \
            const int n = contiguous ? MOTUS__LANES : (end - i < MOTUS__LANES ? end - i : MOTUS__LANES);         \
            if (i < prefetch_end) {                                                                              \
                const int ahead = i + MOTUS__PREFETCH_AHEAD;                                                     \
                MOTUS__EACH_D(MOTUS__PREFETCH(j->x[d] + ahead); MOTUS__PREFETCH(j->v[d] + ahead);                \
                              if (MOTUS__TERMS(j, shape) & MOTUS__T_FORCES) MOTUS__PREFETCH(j->f[d] + ahead););  \
                if (MOTUS__TERMS(j, shape) & MOTUS__T_MASS) MOTUS__PREFETCH(j->inverse_mass + ahead);            \
            }                                                                                                    \
            motus__group_load(j, &g, i, n, dims, contiguous, shape);                                             \
            /* F*(1/m) not finite (past the largest real, or F or 1/m not finite): the group is left to          \
               motus__group_rescue (THE RESCUE), after this loop; a call in it, taken or not, would cost the     \
               loop every vector register the call may use. Tested on the loads: a test of the results,          \
               which come last, cost RK4 20% (Zen 3). Not in a coupled scene (its passes take whole groups). */  \
            if ((MOTUS__TERMS(j, shape) & (MOTUS__T_FORCES | MOTUS__T_MASS)) &&                                  \
                !(MOTUS__TERMS(j, shape) & MOTUS__T_COUPLED) && motus__base_overflowed(g.base, dims))            \
                break;                                                                                           \
            if (!contiguous) motus__group_check_inputs(j, &g, &check, dims, shape); /* the fast: in the test */  \
            for (s = 0; s < j->substeps; ++s) {                                                                  \
                MOTUS__EACH_D(g.v_start[d] = g.v[d];);                                                           \
                if (motus__##method(j, g.x, g.v, g.base, g.inverse_mass, g.movable, dims, coupled, shape, i, n)) \
                    break;                                                                                       \
                motus__group_substep_end(j, &g, &check, dims, shape);                                            \
            }                                                                                                    \
            if (s == j->substeps) motus__group_finish(j, &g, dims, contiguous, shape);                           \
            else if (MOTUS__MAY_STOP(j, coupled)) break; /* a term out of range: to motus__group_rescue */      \
        }                                                                                                        \
        if (i < end_here) /* stopped: the group at i for motus__group_rescue */                                  \
            return MOTUS__STOPPED_AT(i) | !motus_real_is_finite(motus__lane_sum(check));                         \
        /* job, not j: given the local copy's address, a callee that stores through pointers made GCC reload     \
           the copy's constants in the loop, every group (10-30% slower on Zen 3) */                             \
        if (end_here < end) broken = motus__general(job, end_here, end);                                         \
        return broken | !motus_real_is_finite(motus__lane_sum(check));                                           \
    }                                                                                                            \
    MOTUS__FASTS(method)
#if MOTUS__FAST_KERNELS
#define MOTUS__FASTS(method)                                                                                     \
    MOTUS__FAST(method, 2, 0, MOTUS__SHAPE_ALL) MOTUS__FAST(method, 2, 1, MOTUS__SHAPE_GRAVITY)                   \
    MOTUS__FAST(method, 3, 0, MOTUS__SHAPE_ALL) MOTUS__FAST(method, 3, 1, MOTUS__SHAPE_GRAVITY)
#define MOTUS__FAST(method, dims, index, shape)                                                                  \
    static MOTUS__NOINLINE long long motus__fast_body##dims##_##index##_##method(const motus__job *j, int first, \
                                                                                 int end) {                     \
        return motus__kernel_##method(j, first, end, dims, 1, 0, shape);                                         \
    }                                                                                                            \
    static int motus__fast##dims##_##index##_##method(const motus__job *j, int first, int end) {                 \
        return motus__fast_loop(j, first, end, motus__fast_body##dims##_##index##_##method);                     \
    }
#else
#define MOTUS__FASTS(method)
#endif
/* The general kernel (any stride, coupling, the dry run, the fast kernels' last partial group) runs every
   method: one kernel whose group of particles goes through the scene's method by a switch, a predictable
   jump per group next to strided loads. Its loads, stores, walls and checks are then compiled once, not
   once per method, and the unit compiles faster. The same code, inlined the same way, as the fast
   kernels: the same bits. */
MOTUS__KI int motus__any_method(MOTUS__METHOD_ARGS) {
#define MOTUS__CALL(name) motus__##name(j, x, v, base, inverse_mass, movable, dims, coupled, shape, i, n)
    switch (j->method) {
    case MOTUS_EXPLICIT_EULER: return MOTUS__CALL(explicit_euler);
    case MOTUS_POSITION_VERLET: return MOTUS__CALL(position_verlet);
    case MOTUS_VELOCITY_VERLET: return MOTUS__CALL(velocity_verlet);
    case MOTUS_LEAPFROG: return MOTUS__CALL(leapfrog);
    case MOTUS_MIDPOINT: return MOTUS__CALL(midpoint);
    case MOTUS_RK4: return MOTUS__CALL(rk4);
    case MOTUS_FOREST_RUTH:
    case MOTUS_MCLACHLAN4: return MOTUS__CALL(splitting);
    case MOTUS_EXACT_LINEAR_DRAG: return MOTUS__CALL(exact_linear_drag);
    default: return MOTUS__CALL(semi_implicit_euler);
    }
#undef MOTUS__CALL
}
static MOTUS__NOINLINE int motus__general(const motus__job *j, int first, int end);
static MOTUS__NOINLINE int motus__group_rescue(const motus__job *j, int first, int n);
/* A kernel's result: bit 0, a value not finite; from bit 1 up, 1 + the index of the group it stopped at. */
#define MOTUS__STOPPED_AT(i) (((long long)(i) + 1) * 2)
#if MOTUS__FAST_KERNELS
/* A fast kernel from first to end: where it stops at a group (one whose F*(1/m) is not finite, or with a
   lane out of the range of the textbook formulas it inlines: see motus__acceleration), motus__group_rescue
   takes that group and the kernel goes on after it. A loop of calls, out of the kernel, so that no call to
   the rescue is compiled into the kernel's loop. */
static MOTUS__NOINLINE int motus__fast_loop(const motus__job *j, int first, int end,
                                          long long (*body)(const motus__job *, int, int)) {
    int broken = 0;
    long long result;
    for (;;) {
        result = body(j, first, end);
        broken |= (int)(result & 1);
        if (result < 2) return broken;
        first = (int)(result / 2 - 1);
        broken |= motus__group_rescue(j, first, MOTUS__LANES);
        first += MOTUS__LANES;
    }
}
#endif
MOTUS__KERNEL_OF(semi_implicit_euler)
MOTUS__KERNEL_OF(explicit_euler)
MOTUS__KERNEL_OF(position_verlet)
MOTUS__KERNEL_OF(velocity_verlet)
MOTUS__KERNEL_OF(leapfrog)
MOTUS__KERNEL_OF(midpoint)
MOTUS__KERNEL_OF(rk4)
MOTUS__KERNEL_OF(splitting)
MOTUS__KERNEL_OF(exact_linear_drag)
#undef MOTUS__FASTS
#define MOTUS__FASTS(method)
MOTUS__KERNEL_OF(any_method)
static MOTUS__NOINLINE long long motus__general_body(const motus__job *j, int first, int end) {
    return motus__kernel_any_method(j, first, end, 3, 0, 1, MOTUS__SHAPE_ANY);
}
static MOTUS__NOINLINE int motus__general(const motus__job *j, int first, int end) {
    int broken = 0;
    long long result;
    for (;;) { /* as motus__fast_loop */
        result = motus__general_body(j, first, end);
        broken |= (int)(result & 1);
        if (result < 2) return broken;
        first = (int)(result / 2 - 1);
        broken |= motus__group_rescue(j, first, end - first < MOTUS__LANES ? end - first : MOTUS__LANES);
        first += MOTUS__LANES;
    }
}
/* The rescue (see THE RESCUE, by motus__step_rescaled) of the group [first, first + n) a kernel stopped
   at: each particle alone. One whose F*(1/m) is finite takes its step in the general kernel, as in any
   group (its lane computes what it computes alone; the general kernel scales the terms the fast kernel
   does not), without stopping; where that step is not finite and its inputs are, the particle is put back
   as it was and taken as the next. One whose F*(1/m) is not, with finite inputs, is stepped on a
   copy by the general kernel with the job in time units of 2^-s s (1/m, the tether's strength and drag
   rates times 2^-s; the force, gravity and the attractor's strength times 2^-2s; the times 2^s; the
   velocity in and out), at each s in turn until its step is finite, then damped and stored as the kernel
   would. Alone, so its result does not depend on the particles beside it: the same at every SIMD width.
   One whose inputs are not finite, or whose step is not finite at any s, is not written: nonzero. */
static MOTUS__NOINLINE int motus__group_rescue(const motus__job *j, int first, int n) {
    motus_real one_x[3], one_v[3], one_force[3], one_inverse_mass, lane[MOTUS__LANES];
    const int dims = j->dims, damp = (j->terms & MOTUS__T_DAMPING) && j->apply_damping;
    int level, k, d, stage, broken = 0;
    motus_real uniform_inverse_mass, kept;
    motus__job scaled;
    motus__store(lane, j->uniform_inverse_mass, 1, MOTUS__LANES);
    uniform_inverse_mass = lane[0];
    motus__store(lane, j->kept, 1, MOTUS__LANES);
    kept = lane[0];
    for (k = 0; k < n; ++k) {
        const ptrdiff_t at = (ptrdiff_t)(first + k) * j->stride;
        const motus_real inverse_mass = j->inverse_mass ? j->inverse_mass[at] : uniform_inverse_mass;
        int finite = motus_real_is_finite(inverse_mass), overflowed = 0, done = 0;
        for (d = 0; d < dims; ++d) {
            const motus_real force = j->f[0] ? j->f[d][at] : 0;
            finite &= motus_real_is_finite(j->x[d][at]) & motus_real_is_finite(j->v[d][at]) & motus_real_is_finite(force);
            overflowed |= !motus_real_is_finite(force * inverse_mass);
        }
        if (j->rescuing) finite = 0; /* not again, in the rescue's own run */
        if (!overflowed) {
            /* Its F*(1/m) is finite: the general kernel steps it as it is, without stopping (a job marked
               as the rescue's). If that is not finite while its inputs are (a tether's k*dx*(1/m), an
               attractor's pull or a quadratic drag past the largest real), it is put back as it was and
               rescued as below; else that is its step. */
            motus_real saved_x[3], saved_v[3];
            int unscaled_broken;
            for (d = 0; d < dims; ++d) {
                saved_x[d] = j->x[d][at];
                saved_v[d] = j->v[d][at];
            }
            scaled = *j;
            scaled.rescuing = 1;
            unscaled_broken = motus__general(&scaled, first + k, first + k + 1);
            if (!unscaled_broken || !finite) {
                broken |= unscaled_broken;
                continue;
            }
            if (!(j->terms & MOTUS__T_DRY))
                for (d = 0; d < dims; ++d) {
                    j->x[d][at] = saved_x[d];
                    j->v[d][at] = saved_v[d];
                }
        }
        for (level = 0; finite && level < MOTUS__RESCUE_LEVELS && !done; ++level) {
            const motus_real down = motus__rescue_down(level), up = MOTUS_R(1.0) / down;
            const motus__lane down_lane = motus__splat(down), up_lane = motus__splat(up);
            scaled = *j;
            scaled.rescuing = 1;
            /* damping after, in m/s (its rest speed in these units could underflow); stored here */
            scaled.terms &= ~(unsigned)(MOTUS__T_DRY | MOTUS__T_DAMPING);
            scaled.apply_damping = 0;
            scaled.stride = 1;
            for (d = 0; d < 3; ++d) {
                scaled.gravity[d] = (j->gravity[d] * down_lane) * down_lane; /* accelerations: 2^-2s */
                scaled.x[d] = d < dims ? &one_x[d] : NULL;
                scaled.v[d] = d < dims ? &one_v[d] : NULL;
                scaled.f[d] = d < dims && j->f[0] ? &one_force[d] : NULL;
            }
            scaled.inverse_mass = j->inverse_mass ? &one_inverse_mass : NULL;
            scaled.uniform_inverse_mass = j->uniform_inverse_mass * down_lane; /* F*(1/m): (F 2^-s)(1/m 2^-s) */
            scaled.linear_drag = j->linear_drag * down_lane; /* rates: 2^-s */
            scaled.attractor_strength = (j->attractor_strength * down_lane) * down_lane;
            scaled.tether_stiffness = j->tether_stiffness * down_lane; /* k*dx*(1/m): the other 2^-s in 1/m */
            scaled.h = j->h * up_lane; /* times: 2^s */
            scaled.half_h = j->half_h * up_lane;
            scaled.half_h2 = (scaled.h * scaled.h) * motus__splat(MOTUS_R(0.5)); /* as motus__job_init: h^2 may underflow */
            scaled.third_h = j->third_h * up_lane;
            scaled.sixth_h = j->sixth_h * up_lane;
            scaled.substep_dt = j->substep_dt * up;
            for (stage = 0; stage <= j->kicks; ++stage) {
                scaled.drift[stage] = j->drift[stage] * up_lane;
                if (stage < j->kicks) scaled.kick[stage] = j->kick[stage] * up_lane;
            }
            scaled.exact_c1 = j->exact_c1 * up_lane; /* (1 - e^-kh)/k: a time */
            scaled.exact_c2 = (j->exact_c2 * up_lane) * up_lane; /* (h - c1)/k: a time squared */
            for (d = 0; d < dims; ++d) {
                one_x[d] = j->x[d][at];
                one_v[d] = j->v[d][at] * down;
                if (j->f[0]) one_force[d] = j->f[d][at] * down;
            }
            one_inverse_mass = inverse_mass * down;
            if (motus__general(&scaled, 0, 1) != 0) continue;
            done = 1;
            for (d = 0; d < dims; ++d) {
                one_v[d] = one_v[d] * up;
                done &= motus_real_is_finite(one_v[d]);
                if (damp) one_v[d] = motus__damp(one_v[d], kept); /* motus__group_finish's, one lane */
            }
        }
        if (!done) {
            broken = 1;
            continue;
        }
        if (!(j->terms & MOTUS__T_DRY))
            for (d = 0; d < dims; ++d) {
                j->x[d][at] = one_x[d];
                j->v[d][at] = one_v[d];
            }
    }
    return broken;
}

/* The kernel for a method: fast for 2D or 3D plain arrays without coupling, else general. In the order of
   motus_method (MOTUS__METHODS). */
typedef int (*motus__kernel_function)(const motus__job *j, int first, int end);
static motus__kernel_function motus__kernel_for(motus_method method, int dims, unsigned terms, int general) {
#if MOTUS__FAST_KERNELS
#define MOTUS__ROW(name)                                                                                         \
    {motus__fast2_0_##name, motus__fast2_1_##name, motus__fast3_0_##name, motus__fast3_1_##name, motus__general},
    static const motus__kernel_function kernels[MOTUS_METHOD_COUNT][5] = {
        MOTUS__ROW(semi_implicit_euler) MOTUS__ROW(explicit_euler) MOTUS__ROW(position_verlet)
        MOTUS__ROW(velocity_verlet) MOTUS__ROW(leapfrog) MOTUS__ROW(midpoint) MOTUS__ROW(rk4)
        MOTUS__ROW(splitting) MOTUS__ROW(splitting) MOTUS__ROW(exact_linear_drag)};
#undef MOTUS__ROW
    /* Drift (no term) takes the gravity kernel with g = 0: adding +0 to +0 changes nothing. */
    /* drag and damping: tested in the kernel */
    const unsigned exact = terms | MOTUS__T_GRAVITY | MOTUS__T_LINEAR_DRAG | MOTUS__T_DAMPING;
    return kernels[method][general ? 4 : (dims - 2) * 2 + (exact == MOTUS__SHAPE_GRAVITY)];
#else
    (void)method;
    (void)dims;
    (void)terms;
    (void)general;
    return motus__general;
#endif
}

/* ---- checks ---- */
static int motus__negative(motus_real x) { return x < 0; } /* -0 is not negative; NaN is caught before */
static motus_result motus__scene_fail(motus_check_report *report, motus_result result, const char *field, int index) {
    if (report) {
        report->index = index;
        report->field = MOTUS_FIELD_NONE;
        report->component = -1;
        report->field_name = field;
    }
    return result;
}
/* The walls of scene.bounds, axis by axis: an axis whose min and max are both 0 has none (zero means off,
   per axis: the 2D line bounds_max = (800, 600, 0) in a 3D scene leaves z free, where a wall pair at
   [0, 0] flattened every particle onto z = 0). */
static void motus__walls_of(const motus_scene *scene, motus_real *lo, motus_real *hi) {
    int d;
    lo[0] = scene->bounds_min.x, lo[1] = scene->bounds_min.y, lo[2] = scene->bounds_min.z;
    hi[0] = scene->bounds_max.x, hi[1] = scene->bounds_max.y, hi[2] = scene->bounds_max.z;
    for (d = 0; d < 3; ++d)
        if (lo[d] == 0 && hi[d] == 0) lo[d] = -(motus_real)HUGE_VAL, hi[d] = (motus_real)HUGE_VAL;
}
static int motus__bounds_on(const motus_scene *scene, int dims) {
    const motus_real lo[3] = {scene->bounds_min.x, scene->bounds_min.y, scene->bounds_min.z};
    const motus_real hi[3] = {scene->bounds_max.x, scene->bounds_max.y, scene->bounds_max.z};
    int d, on = 0;
    for (d = 0; d < dims; ++d) on |= (lo[d] != 0) | (hi[d] != 0);
    return on;
}
static int motus__coupled(const motus_scene *scene) { return scene->spring_count > 0 || scene->force_callback; }
static int motus__radius_valid(motus_real r) { return motus_real_is_finite(r) && r >= 0 && r <= MOTUS__REAL_MAX / 8; }

MOTUS_API motus_result motus_scene_check(const motus_scene *scene, int dimensions, int count,
                                         motus_check_report *report) {
    static const char *const gravity[3] = {"scene.gravity.x", "scene.gravity.y", "scene.gravity.z"};
    static const char *const attractor[3] = {"scene.attractor.x", "scene.attractor.y", "scene.attractor.z"};
    static const char *const tether_names[3] = {"scene.tether.x", "scene.tether.y", "scene.tether.z"};
    static const char *const lo_names[3] = {"scene.bounds_min.x", "scene.bounds_min.y", "scene.bounds_min.z"};
    static const char *const hi_names[3] = {"scene.bounds_max.x", "scene.bounds_max.y", "scene.bounds_max.z"};
    motus_real g[3], at[3], tether[3], lo[3], hi[3];
    int d, k, dims = dimensions == 0 ? 2 : dimensions;
    motus__report(report, -1, MOTUS_FIELD_NONE, -1);
    if (!scene) return motus__scene_fail(report, MOTUS_ERROR_NULL_POINTER, "scene", -1);
    if (dims != 2 && dims != 3) return motus__scene_fail(report, MOTUS_ERROR_INVALID_DIMENSIONS, "dimensions", -1);
    if (count < 0) return motus__scene_fail(report, MOTUS_ERROR_INVALID_COUNT, "count", -1);
    if ((unsigned)scene->method >= MOTUS_METHOD_COUNT)
        return motus__scene_fail(report, MOTUS_ERROR_INVALID_METHOD, "scene.method", -1);
    if (scene->substeps < 0) return motus__scene_fail(report, MOTUS_ERROR_INVALID_SUBSTEPS, "scene.substeps", -1);
    g[0] = scene->gravity.x, g[1] = scene->gravity.y, g[2] = scene->gravity.z;
    at[0] = scene->attractor.x, at[1] = scene->attractor.y, at[2] = scene->attractor.z;
    tether[0] = scene->tether.x, tether[1] = scene->tether.y, tether[2] = scene->tether.z;
    lo[0] = scene->bounds_min.x, lo[1] = scene->bounds_min.y, lo[2] = scene->bounds_min.z;
    hi[0] = scene->bounds_max.x, hi[1] = scene->bounds_max.y, hi[2] = scene->bounds_max.z;
    for (d = 0; d < dims; ++d)
        if (!motus_real_is_finite(g[d])) return motus__scene_fail(report, MOTUS_ERROR_NOT_FINITE, gravity[d], -1);
    if (!motus_real_is_finite(scene->linear_drag))
        return motus__scene_fail(report, MOTUS_ERROR_NOT_FINITE, "scene.linear_drag", -1);
    if (motus__negative(scene->linear_drag))
        return motus__scene_fail(report, MOTUS_ERROR_INVALID_DRAG, "scene.linear_drag", -1);
    if (!motus_real_is_finite(scene->quadratic_drag))
        return motus__scene_fail(report, MOTUS_ERROR_NOT_FINITE, "scene.quadratic_drag", -1);
    if (motus__negative(scene->quadratic_drag))
        return motus__scene_fail(report, MOTUS_ERROR_INVALID_DRAG, "scene.quadratic_drag", -1);
    if (!motus__fraction_valid(scene->damping_per_step))
        return motus__scene_fail(report, MOTUS_ERROR_INVALID_DAMPING, "scene.damping_per_step", -1);
    if (!motus__fraction_valid(scene->damping_per_second))
        return motus__scene_fail(report, MOTUS_ERROR_INVALID_DAMPING, "scene.damping_per_second", -1);
    if (scene->damping_per_step != 0 && scene->damping_per_second != 0)
        return motus__scene_fail(report, MOTUS_ERROR_INVALID_DAMPING, "scene.damping_per_second (and damping_per_step: set one)", -1);
    for (d = 0; d < dims; ++d)
        if (!motus_real_is_finite(at[d])) return motus__scene_fail(report, MOTUS_ERROR_NOT_FINITE, attractor[d], -1);
    if (!motus_real_is_finite(scene->attractor_strength))
        return motus__scene_fail(report, MOTUS_ERROR_NOT_FINITE, "scene.attractor_strength", -1);
    if (motus__negative(scene->attractor_strength))
        return motus__scene_fail(report, MOTUS_ERROR_INVALID_ATTRACTOR, "scene.attractor_strength", -1);
    for (d = 0; d < dims; ++d)
        if (!motus_real_is_finite(tether[d]))
            return motus__scene_fail(report, MOTUS_ERROR_NOT_FINITE, tether_names[d], -1);
    if (!motus_real_is_finite(scene->tether_stiffness))
        return motus__scene_fail(report, MOTUS_ERROR_NOT_FINITE, "scene.tether_stiffness", -1);
    if (motus__negative(scene->tether_stiffness))
        return motus__scene_fail(report, MOTUS_ERROR_INVALID_TETHER, "scene.tether_stiffness", -1);
    for (d = 0; d < dims; ++d) {
        if (lo[d] != lo[d]) return motus__scene_fail(report, MOTUS_ERROR_NOT_FINITE, lo_names[d], -1);
        if (hi[d] != hi[d]) return motus__scene_fail(report, MOTUS_ERROR_NOT_FINITE, hi_names[d], -1);
        if (!(lo[d] <= hi[d]) || lo[d] > MOTUS__REAL_MAX)
            return motus__scene_fail(report, MOTUS_ERROR_INVALID_BOUNDS, lo_names[d], -1);
        if (hi[d] < -MOTUS__REAL_MAX) return motus__scene_fail(report, MOTUS_ERROR_INVALID_BOUNDS, hi_names[d], -1);
    }
    if (!motus_real_is_finite(scene->restitution))
        return motus__scene_fail(report, MOTUS_ERROR_NOT_FINITE, "scene.restitution", -1);
    if (!motus__fraction_valid(scene->restitution))
        return motus__scene_fail(report, MOTUS_ERROR_INVALID_RESTITUTION, "scene.restitution", -1);
    if (!motus_real_is_finite(scene->mass)) return motus__scene_fail(report, MOTUS_ERROR_NOT_FINITE, "scene.mass", -1);
    if (scene->mass < 0 || (scene->mass > 0 && !motus_real_is_finite(MOTUS_R(1.0) / scene->mass)))
        return motus__scene_fail(report, MOTUS_ERROR_INVALID_MASS, "scene.mass", -1);
    if (scene->spring_count < 0)
        return motus__scene_fail(report, MOTUS_ERROR_INVALID_SPRING, "scene.spring_count", -1);
    if (scene->spring_count > 0 && !scene->springs)
        return motus__scene_fail(report, MOTUS_ERROR_NULL_POINTER, "scene.springs", -1);
    for (k = 0; k < scene->spring_count; ++k) {
        const motus_spring *s = &scene->springs[k];
        const motus_real anchor[3] = {s->anchor.x, s->anchor.y, s->anchor.z};
        if ((unsigned)s->a >= (unsigned)count)
            return motus__scene_fail(report, MOTUS_ERROR_INVALID_SPRING, "scene.springs[index].a", k);
        if (s->b < -1 || s->b >= count)
            return motus__scene_fail(report, MOTUS_ERROR_INVALID_SPRING, "scene.springs[index].b", k);
        if (s->a == s->b) return motus__scene_fail(report, MOTUS_ERROR_INVALID_SPRING, "scene.springs[index].b", k);
        for (d = 0; d < dims; ++d)
            if (s->b < 0 && !motus_real_is_finite(anchor[d]))
                return motus__scene_fail(report, MOTUS_ERROR_NOT_FINITE, "scene.springs[index].anchor", k);
        if (!motus_real_is_finite(s->rest_length))
            return motus__scene_fail(report, MOTUS_ERROR_NOT_FINITE, "scene.springs[index].rest_length", k);
        if (!motus_real_is_finite(s->stiffness))
            return motus__scene_fail(report, MOTUS_ERROR_NOT_FINITE, "scene.springs[index].stiffness", k);
        if (!motus_real_is_finite(s->damping))
            return motus__scene_fail(report, MOTUS_ERROR_NOT_FINITE, "scene.springs[index].damping", k);
        if (motus__negative(s->rest_length))
            return motus__scene_fail(report, MOTUS_ERROR_INVALID_SPRING, "scene.springs[index].rest_length", k);
        if (motus__negative(s->stiffness))
            return motus__scene_fail(report, MOTUS_ERROR_INVALID_SPRING, "scene.springs[index].stiffness", k);
        if (motus__negative(s->damping))
            return motus__scene_fail(report, MOTUS_ERROR_INVALID_SPRING, "scene.springs[index].damping", k);
    }
    if (scene->method == MOTUS_EXACT_LINEAR_DRAG &&
        (scene->quadratic_drag != 0 || scene->attractor_strength != 0 || scene->tether_stiffness != 0 ||
         motus__coupled(scene)))
        return motus__scene_fail(report, MOTUS_ERROR_UNSUPPORTED, "scene.method", -1);
    {
        const motus_contacts *c = &scene->contacts;
        if (!motus_real_is_finite(c->radius))
            return motus__scene_fail(report, MOTUS_ERROR_NOT_FINITE, "scene.contacts.radius", -1);
        if (motus__negative(c->radius) || c->radius > MOTUS__REAL_MAX / 8)
            return motus__scene_fail(report, MOTUS_ERROR_INVALID_CONTACTS, "scene.contacts.radius", -1);
        if (!motus_real_is_finite(c->restitution))
            return motus__scene_fail(report, MOTUS_ERROR_NOT_FINITE, "scene.contacts.restitution", -1);
        if (!motus__fraction_valid(c->restitution))
            return motus__scene_fail(report, MOTUS_ERROR_INVALID_RESTITUTION, "scene.contacts.restitution", -1);
        if (!motus_real_is_finite(c->restitution_threshold))
            return motus__scene_fail(report, MOTUS_ERROR_NOT_FINITE, "scene.contacts.restitution_threshold", -1);
        if (motus__negative(c->restitution_threshold))
            return motus__scene_fail(report, MOTUS_ERROR_INVALID_CONTACTS, "scene.contacts.restitution_threshold", -1);
        if (!motus_real_is_finite(c->friction))
            return motus__scene_fail(report, MOTUS_ERROR_NOT_FINITE, "scene.contacts.friction", -1);
        if (motus__negative(c->friction))
            return motus__scene_fail(report, MOTUS_ERROR_INVALID_CONTACTS, "scene.contacts.friction", -1);
        if (c->iterations < 0)
            return motus__scene_fail(report, MOTUS_ERROR_INVALID_CONTACTS, "scene.contacts.iterations", -1);
    }
    return MOTUS_OK;
}

/* The state's shape (not its data): O(1). */
/* velocities: 1 where the caller reads them (every step); 0 for the broadphase alone, where they may be NULL. */
static motus_result motus__state_shape(const motus_state *state, int *dims, motus_check_report *report, int velocities) {
    int d, e;
    if (!state) return motus__scene_fail(report, MOTUS_ERROR_NULL_POINTER, "state", -1);
    *dims = state->dimensions == 0 ? 2 : state->dimensions;
    if (*dims != 2 && *dims != 3) return motus__scene_fail(report, MOTUS_ERROR_INVALID_DIMENSIONS, "state.dimensions", -1);
    if (state->count < 0) return motus__scene_fail(report, MOTUS_ERROR_INVALID_COUNT, "state.count", -1);
    if (state->stride < 0) return motus__scene_fail(report, MOTUS_ERROR_INVALID_STRIDE, "state.stride", -1);
    if (state->radius_stride < 0)
        return motus__scene_fail(report, MOTUS_ERROR_INVALID_STRIDE, "state.radius_stride", -1);
    if (state->count == 0) return MOTUS_OK;
    for (d = 0; d < *dims; ++d) {
        if (!state->position[d]) return motus__scene_fail(report, MOTUS_ERROR_NULL_POINTER, "state.position", -1);
        if (!state->velocity[d] && velocities)
            return motus__scene_fail(report, MOTUS_ERROR_NULL_POINTER, "state.velocity", -1);
        /* forces: all of the state's components, or none */
        if (!state->force[d] != !state->force[0])
            return motus__scene_fail(report, MOTUS_ERROR_NULL_POINTER, "state.force", -1);
    }
    /* The stride times the count must be an offset C can form. */
    if (state->stride > 1 && (size_t)(state->count - 1) > (size_t)PTRDIFF_MAX / (size_t)state->stride / sizeof(motus_real))
        return motus__scene_fail(report, MOTUS_ERROR_INVALID_COUNT, "state.count", -1);
    if (state->radius_stride > 1 &&
        (size_t)(state->count - 1) > (size_t)PTRDIFF_MAX / (size_t)state->radius_stride / sizeof(motus_real))
        return motus__scene_fail(report, MOTUS_ERROR_INVALID_COUNT, "state.count", -1);
    for (d = 0; d < *dims; ++d)
        for (e = 0; e < *dims; ++e)
            if ((state->velocity[e] && state->position[d] == state->velocity[e]) ||
                (d != e && (state->position[d] == state->position[e] ||
                            (state->velocity[d] && state->velocity[d] == state->velocity[e]))))
                return motus__scene_fail(report, MOTUS_ERROR_ALIASING, "state.position/velocity", -1);
    return MOTUS_OK;
}

/* The radii's stride: their own, else the state's (0: 1). */
static ptrdiff_t motus__radius_stride(const motus_state *state) {
    const int stride = state->radius_stride != 0 ? state->radius_stride : state->stride;
    return stride == 0 ? 1 : stride;
}

static motus_result motus__state_check(const motus_scene *scene, const motus_state *state, int first, int count,
                                       motus_check_report *report, int velocities) {
    motus_result result;
    int dims = 2, i, d, forces, radii;
    ptrdiff_t stride, radius_stride;
    motus__report(report, -1, MOTUS_FIELD_NONE, -1);
    result = motus__state_shape(state, &dims, report, velocities);
    if (result != MOTUS_OK) return result;
    radius_stride = motus__radius_stride(state);
    /* the radii are data only where the scene collides */
    radii = scene && scene->contacts.enabled && state->radius;
    if (first < 0 || count < 0 || first > state->count || count > state->count - first)
        return motus__scene_fail(report, MOTUS_ERROR_INVALID_COUNT, "first/count", -1);
    stride = state->stride == 0 ? 1 : state->stride;
    forces = state->force[0] != NULL;
    for (i = first; i < first + count; ++i) {
        const ptrdiff_t at = (ptrdiff_t)i * stride;
        for (d = 0; d < dims; ++d)
            if (!motus_real_is_finite(state->position[d][at])) {
                motus__report(report, i, MOTUS_FIELD_POSITION, d);
                return MOTUS_ERROR_NOT_FINITE;
            }
        for (d = 0; d < dims && velocities; ++d)
            if (!motus_real_is_finite(state->velocity[d][at])) {
                motus__report(report, i, MOTUS_FIELD_VELOCITY, d);
                return MOTUS_ERROR_NOT_FINITE;
            }
        for (d = 0; d < dims && forces; ++d)
            if (state->force[d] && !motus_real_is_finite(state->force[d][at])) {
                motus__report(report, i, MOTUS_FIELD_FORCE, d);
                return MOTUS_ERROR_NOT_FINITE;
            }
        if (state->inverse_mass && (!motus_real_is_finite(state->inverse_mass[at]) || state->inverse_mass[at] < 0)) {
            motus__report(report, i, MOTUS_FIELD_INVERSE_MASS, -1);
            return motus_real_is_finite(state->inverse_mass[at]) ? MOTUS_ERROR_INVALID_MASS : MOTUS_ERROR_NOT_FINITE;
        }
        if (radii && !motus__radius_valid(state->radius[(ptrdiff_t)i * radius_stride])) {
            motus__report(report, i, MOTUS_FIELD_RADIUS, -1);
            return motus_real_is_finite(state->radius[(ptrdiff_t)i * radius_stride]) ? MOTUS_ERROR_INVALID_CONTACTS
                                                                                     : MOTUS_ERROR_NOT_FINITE;
        }
    }
    return MOTUS_OK;
}
MOTUS_API motus_result motus_state_check(const motus_scene *scene, const motus_state *state, int first, int count,
                                         motus_check_report *report) {
    return motus__state_check(scene, state, first, count, report, 1);
}

/* Tasks (see THREADS in >>contacts): particles are handed out MOTUS__TASK_MIN or more at a time, in at most
   MOTUS__TASKS tasks; a pass over MOTUS_CONTACT_SLAB_MIN_COUNT particles or more is solved in slabs at
   least MOTUS__SLAB_CELLS_2D (3D) cells wide, at most MOTUS__SLABS of them, at least 4. All depend on the
   data only. */
#define MOTUS__TASKS 32
#ifndef MOTUS__TASK_MIN /* internal; tests/fuzz makes them small to reach the tasks with few particles */
#define MOTUS__TASK_MIN 2048
#endif
#ifndef MOTUS_CONTACT_SLAB_MIN_COUNT
#define MOTUS_CONTACT_SLAB_MIN_COUNT 4096
#endif
#ifndef MOTUS__SLAB_CELLS_2D /* at least 2: a particle then never touches both neighbouring slabs */
#define MOTUS__SLAB_CELLS_2D 16
#define MOTUS__SLAB_CELLS_3D 4
#endif
#define MOTUS__SLABS 64
/* Where each part of the scratch goes, in bytes: the coupled stages, the checked build's copy of the state,
   the contacts' grid and pair list. 0 if the sizes overflow a size_t. */
typedef struct motus__layout {
    size_t coupled, copy, contacts, total;
    size_t table_size, pair_capacity; /* the contacts' hash table (a power of two) and pair list */
    size_t stage_length; /* reals in each coupled stage array: the count rounded up to whole groups of lanes */
} motus__layout;
static int motus__layout_of(const motus_scene *scene, const motus_state *state, motus__layout *l) {
    const size_t n = (size_t)state->count, real = sizeof(motus_real), index = sizeof(int);
    /* no particles: no memory (a count of 0 is a valid step of nothing, scratch or not) */
    const int dims = state->dimensions == 3 ? 3 : 2, contacts = scene->contacts.enabled != 0 && n > 0;
    size_t per_particle = 0;
    memset(l, 0, sizeof *l);
    /* Whole groups, so that the general kernel reads and writes its last, partial group of a stage as it
       does every other: one vector load or store, where n lanes one by one made it twice the code. */
    l->stage_length = n + (size_t)(MOTUS__LANES - 1) - (n + (size_t)(MOTUS__LANES - 1)) % (size_t)MOTUS__LANES;
    if (motus__coupled(scene))
        /* stage positions and velocities, and each evaluation's coupled forces */
        l->coupled = (size_t)dims * (size_t)(2 + motus_method_evaluations(scene->method)) * real;
#ifdef MOTUS_CHECKED
    /* checked builds step a copy of the state (positions, velocities, forces, inverse masses, radii) so
       that an overflow in any substep leaves the state as it was */
    if (motus__coupled(scene) || contacts) l->copy = (size_t)(3 * dims + 1 + contacts) * real;
#endif
    if (contacts) {
        /* a pair list of 4 (2D) or 8 (3D) pairs per particle (2 ints, and the normal and depth: 4 reals),
           and a second one to sort it into;
           each particle's cell (dims ints), the particles sorted by bucket (1), by height (1) and their rank
           in that order (1), whether it is supported (1), the particles near a wall (1), its rank by slab
           then height (1) and its slab's task (1), the bins of the slabs' sorts (3, + MOTUS__SLABS + 1; the
           height keys and the height sort's spare before); the table (2 per particle, a power of two, + 1) */
        const size_t pairs = dims == 3 ? 8 : 4;
        l->table_size = 1;
        while (l->table_size < 2 * n && l->table_size < ((size_t)1 << 30)) l->table_size *= 2;
        l->pair_capacity = pairs * n;
        l->contacts = 2 * pairs * 4 * real + ((size_t)dims + 10 + 2 * 2 * pairs) * index; /* pair lists: 2 */
    }
    per_particle = l->coupled + l->copy + l->contacts;
    if (n > 0 && per_particle > ((size_t)-1 - 4 * index) / 2 / l->stage_length) return 0;
    l->coupled *= l->stage_length, l->copy *= n, l->contacts *= n;
    if (contacts) l->contacts += (l->table_size + 1 + MOTUS__SLABS + 1) * index;
    l->total = l->coupled + l->copy + l->contacts;
    return 1;
}
MOTUS_API size_t motus_scratch_size(const motus_scene *scene, const motus_state *state) {
    motus__layout layout;
    if (!scene || !state || (unsigned)scene->method >= MOTUS_METHOD_COUNT || state->count < 0) return 0;
    if (!motus__layout_of(scene, state, &layout)) return (size_t)-1;
    return layout.total;
}

/* ---- the step ---- */
typedef struct motus__align_probe {
    char c;
    motus_real r;
} motus__align_probe;

/* A splitting's drifts and kicks as fractions of the substep (see >>methods); returns the number of kicks.
   Forest-Ruth: Yoshida's triple jump of leapfrog, theta = 1/(2 - 2^(1/3)). McLachlan (1995), the symmetric
   composition with five kicks that odeint calls symplectic_rkn_sb3a_mclachlan: drifts a1, a2, a3, a3, a2,
   a1 with a3 = 1/2 - a1 - a2, kicks b1, b2, b3, b2, b1 with b1 = -3/73, b2 = 17/59, b3 = 1 - 2*(b1 + b2). */
static int motus__splitting_fractions(motus_method method, motus_real *drift, motus_real *kick) {
    if (method == MOTUS_FOREST_RUTH) {
        const motus_real theta = (motus_real)1.3512071919596576340476878089715;
        drift[0] = drift[3] = theta * MOTUS_R(0.5);
        drift[1] = drift[2] = (1 - theta) * MOTUS_R(0.5);
        kick[0] = kick[2] = theta;
        kick[1] = 1 - 2 * theta;
        return 3;
    }
    drift[0] = drift[5] = (motus_real)0.40518861839525227722;
    drift[1] = drift[4] = (motus_real)-0.28714404081652408900;
    drift[2] = drift[3] = (motus_real)0.38195542242127181178;
    kick[0] = kick[4] = (motus_real)(-3.0 / 73.0);
    kick[1] = kick[3] = (motus_real)(17.0 / 59.0);
    kick[2] = (motus_real)(2179.0 / 4307.0);
    return 5;
}

/* The job for this scene and state; *h the substep, *substeps their number. */
static void motus__job_init(motus__job *j, const motus_scene *scene, const motus_state *state, int dims, motus_real dt) {
    const motus_real g[3] = {scene->gravity.x, scene->gravity.y, scene->gravity.z};
    const motus_real at[3] = {scene->attractor.x, scene->attractor.y, scene->attractor.z};
    const motus_real tether[3] = {scene->tether.x, scene->tether.y, scene->tether.z};
    motus_real lo[3], hi[3];
    motus_real h, kept = 1;
    int d, n = scene->substeps > 1 ? scene->substeps : 1;
    memset(j, 0, sizeof *j);
    motus__walls_of(scene, lo, hi);
    /* a subnormal dt split so finely that dt/n rounds to 0 would step nothing: fewer substeps */
    while (n > 1 && !(dt / (motus_real)n > 0)) --n;
    h = dt / (motus_real)n;
    j->dims = dims;
    j->method = scene->method;
    j->substeps = n;
    j->record_stage = -1;
    j->stride = state->stride == 0 ? 1 : state->stride;
    for (d = 0; d < dims; ++d) {
        j->x[d] = state->position[d];
        j->v[d] = state->velocity[d];
        j->f[d] = state->force[d];
        j->gravity[d] = motus__splat(g[d] + 0); /* -0 as +0: every kernel then adds the same zero */
        j->attractor[d] = motus__splat(at[d]);
        j->tether[d] = motus__splat(tether[d] + 0); /* -0 as +0: x - tether then has one sign of zero */
        j->bounds_min[d] = motus__splat(lo[d]);
        j->bounds_max[d] = motus__splat(hi[d]);
        if (g[d] != 0) j->terms |= MOTUS__T_GRAVITY;
    }
    j->inverse_mass = state->inverse_mass;
    if (state->force[0]) j->terms |= MOTUS__T_FORCES;
    if (state->inverse_mass) j->terms |= MOTUS__T_MASS;
    if (scene->linear_drag != 0) j->terms |= MOTUS__T_LINEAR_DRAG;
    if (scene->quadratic_drag != 0) j->terms |= MOTUS__T_QUADRATIC_DRAG;
    if (scene->attractor_strength != 0) j->terms |= MOTUS__T_ATTRACTOR;
    if (scene->tether_stiffness != 0) j->terms |= MOTUS__T_TETHER;
    if (scene->damping_per_step != 0) kept = MOTUS_R(1.0) - scene->damping_per_step;
    if (scene->damping_per_second != 0) kept = motus__kept_per_second(scene->damping_per_second, dt);
    if (scene->damping_per_step != 0 || scene->damping_per_second != 0) j->terms |= MOTUS__T_DAMPING;
    j->apply_damping = (j->terms & MOTUS__T_DAMPING) != 0; /* the kernels for gravity test it (see shape) */
    j->apply_drag = (j->terms & MOTUS__T_LINEAR_DRAG) != 0; /* and this */
    if (motus__bounds_on(scene, dims)) j->terms |= MOTUS__T_BOUNDS;
    if (motus__coupled(scene)) j->terms |= MOTUS__T_COUPLED;
    j->linear_drag = motus__splat(scene->linear_drag);
    j->quadratic_drag = motus__splat(scene->quadratic_drag);
    j->attractor_strength = motus__splat(scene->attractor_strength);
    j->tether_stiffness = motus__splat(scene->tether_stiffness);
    j->uniform_inverse_mass = motus__splat(scene->mass > 0 ? MOTUS_R(1.0) / scene->mass : MOTUS_R(1.0));
    j->kept = motus__splat(kept);
    j->rest_speed = motus__splat((motus_real)(MOTUS_REST_SPEED));
    j->bounce = motus__splat(-scene->restitution);
    j->largest = motus__splat(MOTUS__REAL_MAX);
    /* c*|v|*v is at most c*|v|^2: below a quarter of the largest real for |v|^2 below this (a margin for
       the roundings of the square root and the products), and |v|^2 itself below the largest real */
    j->drag_speed2_limit = motus__splat(scene->quadratic_drag * 4 > 1 ? MOTUS__REAL_MAX / (scene->quadratic_drag * 4)
                                                                     : MOTUS__REAL_MAX);
    j->h = motus__splat(h);
    j->substep_dt = h;
    j->half_h = motus__splat(h * MOTUS_R(0.5));
    j->half_h2 = motus__splat(h * h * MOTUS_R(0.5));
    j->third_h = motus__splat(h / MOTUS_R(3.0));
    j->sixth_h = motus__splat(h / MOTUS_R(6.0));
    if (scene->method == MOTUS_FOREST_RUTH || scene->method == MOTUS_MCLACHLAN4) {
        motus_real drift[MOTUS__MAX_EVALUATIONS + 1], kick[MOTUS__MAX_EVALUATIONS];
        j->kicks = motus__splitting_fractions(scene->method, drift, kick);
        for (d = 0; d < j->kicks; ++d) {
            j->drift[d] = motus__splat(drift[d] * h);
            j->kick[d] = motus__splat(kick[d] * h);
        }
        j->drift[j->kicks] = motus__splat(drift[j->kicks] * h);
    }
    if (scene->method == MOTUS_EXACT_LINEAR_DRAG) {
        /* c1 = (1 - e^-u)/k and c2 = (h - c1)/k with u = k*h, formed from k and h so that neither u nor
           u^2 can overflow when the result does not (drag 1e38/s over 1e20 s is a particle at rest after
           moving a/k^2); a series where u is small and h - c1 cancels. */
        const motus_real k = scene->linear_drag, u = k * h;
        motus_real decay = 1, c1 = h, c2 = h * h * MOTUS_R(0.5);
        if (k > 0 && u < MOTUS_R(0.5)) {
            /* c1 = h*sum (-u)^m/(m+1)!, c2 = h^2*sum (-u)^m/(m+2)!: 15 terms are below double rounding */
            motus_real term1 = 1, term2 = MOTUS_R(0.5), sum1 = 1, sum2 = MOTUS_R(0.5);
            int m;
            for (m = 1; m <= 14; ++m) {
                term1 *= -u / (motus_real)(m + 1);
                term2 *= -u / (motus_real)(m + 2);
                sum1 += term1;
                sum2 += term2;
            }
            decay = MOTUS_EXP(-u);
            c1 = h * sum1;
            c2 = h * h * sum2;
            if (!motus_real_is_finite(c2)) c2 = h * (h * sum2);
        } else if (k > 0) {
            decay = motus_real_is_finite(u) ? MOTUS_EXP(-u) : 0;
            c1 = (motus_real_is_finite(u) ? -MOTUS_EXPM1(-u) : 1) / k;
            c2 = (h - c1) / k;
        }
        j->exact_decay = motus__splat(decay);
        j->exact_c1 = motus__splat(c1);
        j->exact_c2 = motus__splat(c2);
    }
}

/* Stage times as fractions of the substep, for the callback. */
static motus_real motus__stage_time(motus_method method, int stage) {
    const motus_real theta = (motus_real)1.3512071919596576340476878089715;
    switch (method) {
    case MOTUS_POSITION_VERLET: return MOTUS_R(0.5);
    case MOTUS_VELOCITY_VERLET:
    case MOTUS_LEAPFROG: return (motus_real)stage;
    case MOTUS_MIDPOINT: return MOTUS_R(0.5) * (motus_real)stage;
    case MOTUS_RK4: return stage == 0 ? 0 : stage == 3 ? MOTUS_R(1.0) : MOTUS_R(0.5);
    case MOTUS_FOREST_RUTH: return stage == 0 ? theta * MOTUS_R(0.5) : stage == 1 ? MOTUS_R(0.5) : 1 - theta * MOTUS_R(0.5);
    case MOTUS_MCLACHLAN4: { /* the drifts' sums (see motus__splitting_fractions) */
        static const motus_real times[5] = {(motus_real)0.40518861839525227722, (motus_real)0.11804457757872818822,
                                            MOTUS_R(0.5), (motus_real)0.88195542242127181178,
                                            (motus_real)0.59481138160474772278};
        return times[stage];
    }
    default: return 0;
    }
}

/* A spring's force on its end a, from the recorded stage state (see motus_spring). The length is formed
   from d/s, s = max|d_i|, so that it does not overflow where the force does not (k = L = 1e20 at rest). */
MOTUS__KI void motus__spring_force(const motus_spring *s, const motus_real *dx, const motus_real *relative,
                                  const int dims, motus_real *force) {
    motus_real scale = 0, u2 = 0, length, along = 0, magnitude, unit[3];
    if (s->rest_length == 0 && s->damping == 0) { /* -k*d: no square root */
        MOTUS__EACH_D(force[d] = dx[d] * -s->stiffness;);
        return;
    }
    MOTUS__EACH_D(
        const motus_real m = dx[d] < 0 ? -dx[d] : dx[d];
        if (m > scale) scale = m;
    );
    if (!(scale > 0)) { /* both ends at one point: no direction to push along (or NaN: passed on) */
        MOTUS__EACH_D(force[d] = dx[d] * -s->stiffness + (scale - scale););
        return;
    }
    MOTUS__EACH_D(
        unit[d] = dx[d] / scale;
        u2 += unit[d] * unit[d];
    );
    u2 = MOTUS_SQRT(u2);
    length = scale * u2;
    MOTUS__EACH_D(
        unit[d] = unit[d] / u2;
        along += relative[d] * unit[d];
    );
    magnitude = s->stiffness * (length - s->rest_length) + s->damping * along;
    MOTUS__EACH_D(force[d] = unit[d] * -magnitude;);
}

/* The springs' forces of one stage, added to force[]. Inlined with dims a constant (2 or 3): with dims
   known only at run time the small arrays went through the stack, and two 4-byte stores read back as one
   8-byte load cannot be forwarded (2.5x slower: 30 ns a spring in 2D float, -O3 -march=native). */
MOTUS__KI void motus__add_spring_forces(const motus__job *j, const motus_scene *scene, motus_real *const *force,
                                        const int dims) {
    int k;
    for (k = 0; k < scene->spring_count; ++k) {
        const motus_spring *s = &scene->springs[k];
        const motus_real anchor[3] = {s->anchor.x, s->anchor.y, s->anchor.z};
        motus_real dx[3], relative[3], f[3];
        MOTUS__EACH_D(
            dx[d] = j->stage_x[d][s->a] - (s->b < 0 ? anchor[d] : j->stage_x[d][s->b]);
            relative[d] = j->stage_v[d][s->a] - (s->b < 0 ? 0 : j->stage_v[d][s->b]);
        );
        motus__spring_force(s, dx, relative, dims, f);
        MOTUS__EACH_D(
            force[d][s->a] += f[d];
            if (s->b >= 0) force[d][s->b] -= f[d];
        );
    }
}

/* The coupled forces of one stage into stage_force[stage]: zero, the callback, then the springs. */
static void motus__stage_forces(const motus__job *j, const motus_scene *scene, int dims, int count, int length,
                                int stage, motus_real time) {
    motus_real *force[3] = {NULL, NULL, NULL};
    int d;
    /* -0, not +0: adding -0 changes no value (x + -0 is x, -0 included), so a stage with no coupled force
       gives the bits of a scene without coupling. */
    for (d = 0; d < dims; ++d) {
        int i;
        force[d] = (motus_real *)(uintptr_t)j->stage_force[stage][d];
        for (i = 0; i < count; ++i) force[d][i] = -MOTUS_R(0.0);
    }
    if (scene->force_callback) {
        motus_force_query query;
        memset(&query, 0, sizeof query);
        query.dimensions = dims;
        query.count = count;
        query.stage = stage;
        query.time = time;
        for (d = 0; d < dims; ++d) {
            query.position[d] = j->stage_x[d];
            query.velocity[d] = j->stage_v[d];
            query.force[d] = force[d];
        }
        scene->force_callback(scene->user_data, &query);
    }
    if (dims == 2) motus__add_spring_forces(j, scene, force, 2);
    else motus__add_spring_forces(j, scene, force, 3);
    /* The lanes past the last particle compute that particle again (as motus__load's repeated lanes do):
       they get its force, so that they overflow only where it does. */
    for (d = 0; d < dims; ++d) {
        int i;
        for (i = count; i < length; ++i) force[d][i] = force[d][count - 1];
    }
}

/* The checks every step makes before it reads a particle: O(1), or O(springs). */
static motus_result motus__step_checks(const motus_scene *scene, const motus_state *state, motus_real dt, int *dims,
                                       int velocities) {
    motus_result result;
    if (!scene) return MOTUS_ERROR_NULL_POINTER;
    result = motus__state_shape(state, dims, NULL, velocities);
    if (result != MOTUS_OK) return result;
    if (!motus__dt_valid(dt)) return MOTUS_ERROR_INVALID_TIME_STEP;
    return motus_scene_check(scene, *dims, state->count, NULL);
}

/* Runs the kernel over [first, end), after the checked build's look at the data. */
static motus_result motus__run(motus__job *j, const motus_scene *scene, const motus_state *state, int dims, int first,
                               int end) {
    /* fewer particles than a group of lanes: straight to the general kernel, which takes partial groups */
    const int fast = j->stride == 1 && !(j->terms & MOTUS__T_COUPLED) && end - first >= MOTUS__LANES;
    const motus__kernel_function kernel = motus__kernel_for(scene->method, dims, j->terms, !fast);
#ifdef MOTUS_CHECKED
    motus_result result = motus_state_check(scene, state, first, end - first, NULL);
    if (result != MOTUS_OK) return result;
    j->terms |= MOTUS__T_DRY;
    if (motus__kernel_for(scene->method, dims, 0, 1)(j, first, end)) return MOTUS_ERROR_OVERFLOW;
    j->terms &= ~(unsigned)MOTUS__T_DRY;
#else
    (void)state;
#endif
    return kernel(j, first, end) ? MOTUS_ERROR_NOT_FINITE : MOTUS_OK;
}

MOTUS_API motus_result motus_step_range(const motus_scene *scene, const motus_state *state, int first, int count,
                                        motus_real dt) {
    motus__job job;
    motus_result result;
    int dims = 2;
    result = motus__step_checks(scene, state, dt, &dims, 1);
    if (result != MOTUS_OK) return result;
    if (first < 0 || count < 0 || first > state->count || count > state->count - first) return MOTUS_ERROR_INVALID_COUNT;
    if (motus__coupled(scene) || scene->contacts.enabled) return MOTUS_ERROR_UNSUPPORTED;
    if (count == 0) return MOTUS_OK;
    if (dt == 0) return motus_state_check(scene, state, first, count, NULL); /* nothing moves; bad data is reported */
    motus__job_init(&job, scene, state, dims, dt);
    return motus__run(&job, scene, state, dims, first, first + count);
}

/* ---- contacts (see >>contacts) ---- */
/* Cell numbers beyond this are clamped to it: differences of two fit an int, and so does a neighbour's. */
#define MOTUS__CELL_LIMIT (1 << 29)
#ifndef MOTUS_CONTACT_SUPPORT_SWEEPS
#define MOTUS_CONTACT_SUPPORT_SWEEPS 1
#endif
/* task over [0, task_count) on the scene's threads, or here (one task: no hand-over) */
static void motus__for(const motus_scene *scene, motus_task_function task, void *task_context, int task_count) {
    if (task_count <= 0) return;
    if (scene->parallel_for && task_count > 1) scene->parallel_for(scene->parallel_context, task, task_context, task_count);
    else task(task_context, 0, task_count);
}
/* How many particles a task takes (from 64 up, a multiple of 64: whole groups of lanes), and how many tasks. */
static int motus__task_size(int count, int *tasks) {
    int size = count / MOTUS__TASKS + 1;
    if (size < MOTUS__TASK_MIN) size = MOTUS__TASK_MIN;
    if (size >= 64) size = (size + 63) / 64 * 64;
    *tasks = count / size + (count % size != 0);
    return size;
}
typedef struct motus__contact_job {
    int dims, count, iterations, walls, grid, listed;
    ptrdiff_t stride, radius_stride;
    motus_real *x[3], *v[3];
    const motus_real *inverse_mass, *radius;
    motus_real uniform_inverse_mass, uniform_radius;
    motus_real restitution, wall_restitution, threshold, friction, h;
    motus_real lo[3], hi[3];
    motus_real inverse_cell, scale, inverse_scale; /* cell = 1/inverse_cell; scale: a power of two, radii ~ 1 */
    int *cell[3], *sorted, *table, *order, *rank, *supported, *near_wall, near_walls, shock, up_axis, weighed;
    int *slab_rank, *sort_bins; /* rank by slab, then height (rank when there are no slabs); sort bins */
    int half[14][3], half_count; /* the own cell, then the cells after it in (up, other axes) order */
    motus_real *geometry; /* per listed pair: the normal and the depth when it was listed */
    motus_real *impulse; /* per listed pair: its impulse so far in the velocity sweeps (the sort's spare buffer) */
    motus_contact_pair *pairs_sorted;
    motus_real *geometry_sorted;
    motus_real up_sign;
    unsigned mask;
    motus_contact_pair *pairs;
    size_t pair_capacity, pair_count;
    /* Listing in tasks: the particles in the solver's order, task_size at a time, each task's pairs in its
       own part of the list (pairs_per_particle per particle), task_found[t] of them, task_pairs[t][s] of
       them in slab task s */
    int pairs_per_particle, tasks, task_size;
    size_t task_found[MOTUS__TASKS];
    size_t task_pairs[MOTUS__TASKS][MOTUS__SLABS];
    /* Slabs (see THREADS in >>contacts): cell c across slab_axis is in slab (c - slab_low) * slabs /
       slab_extent (all as wide to a cell); task_of[i], the task of particle i's slab; the sorted
       pairs of the even slabs' tasks, then the odd ones', slab_start[] apart; the particles of task t are
       slab_first[t] .. slab_first[t + 1] - 1 in slab_rank */
    int slab_axis, slab_low, slab_extent, slabs, even_slabs, *task_of;
    size_t slab_start[MOTUS__SLABS + 1];
    int slab_first[MOTUS__SLABS + 1], wall_start[MOTUS__SLABS + 1]; /* near_wall by slab task */
    unsigned char failed[MOTUS__TASKS];
    /* the grid's scans in tasks: the largest radius; the lowest and highest cell across slab_axis; the
       particles near a wall; the largest velocity component */
    motus_real task_largest_radius[MOTUS__TASKS], task_largest_velocity[MOTUS__TASKS];
    /* the velocity sweeps run on velocities times this power of two (1 but where a velocity component is
       above the largest real / 64: there an approach speed, or an impulse of (1 + e) times it, would
       overflow where the velocities after it do not); h and the threshold are scaled to match */
    motus_real velocity_scale;
    int task_cells[MOTUS__TASKS][2][3], task_near[MOTUS__TASKS]; /* per task: the lowest and highest cells */
    /* The table over a dense grid, where the cells the particles span (and one more each side) are no more
       than its buckets: bucket = sum over d of (cell[d] - dense_low[d]) * dense_stride[d], the first axis
       of the half neighbourhood fastest, so that its cells come as runs of neighbouring buckets (2 runs in
       2D and 5 in 3D, where the hash looks up 5 and 14 buckets) and no bucket holds two cells. The cells are
       visited in the same order either way: the same pairs, in the same order. */
    int dense, dense_low[3], run_count;
    ptrdiff_t dense_stride[3], run_start[14];
    int run_length[14];
    motus_real largest_radius;
    uint32_t *height_key; /* per particle, its height as a key (motus__height_key), in the sort bins */
    double height_scale;  /* keys per metre of height: 64 / the largest radius */
} motus__contact_job;
enum { MOTUS__PAIRS_RECORD, MOTUS__PAIRS_VELOCITY, MOTUS__PAIRS_POSITION };
/* The solver keeps the pairs nearer than MOTUS__REACH times their radii's sum: a pile whose balls touch
   after one projection (a gap of a rounding) stays in the list, so a push travels up a column within a
   pass. Impulses act within MOTUS__TOUCH (of the radii's sum) of touching; projections on overlaps only. */
#define MOTUS__REACH MOTUS_R(1.1)
#define MOTUS__TOUCH MOTUS_R(0.01)
#define MOTUS__SUPPORT_PASSES 4
#define MOTUS__DEEP MOTUS_R(0.025) /* of the radii's sum: a deep overlap (see motus__pair_position) */
#define MOTUS__LEVEL MOTUS_R(0.25) /* the up component below which a deep pair is side by side */
#define MOTUS__SUPPORT_GROUP 16 /* supports of one particle solved with kept impulses (more: each pass clamped) */
#define MOTUS__SUPPORT_SLOP (1024 * MOTUS_REAL_EPSILON) /* of the radii's sum: see motus__support_slop */
#define MOTUS__TOUCH_SUPPORT MOTUS_R(0.05) /* a ball in a random pile touches one support and may miss the next by a few % */

static motus_real motus__contact_w(const motus__contact_job *j, int i) {
    return j->inverse_mass ? j->inverse_mass[(ptrdiff_t)i * j->stride] : j->uniform_inverse_mass;
}
static motus_real motus__contact_r(const motus__contact_job *j, int i) {
    return j->radius ? j->radius[(ptrdiff_t)i * j->radius_stride] : j->uniform_radius;
}
/* A bucket of the hash table for a cell (the cells are unbounded: no world box). */
static unsigned motus__cell_hash(int x, int y, int z, unsigned mask) {
    unsigned h = (unsigned)x * 73856093u ^ (unsigned)y * 19349663u ^ (unsigned)z * 83492791u;
    h ^= h >> 16;
    h *= 0x7feb352du;
    h ^= h >> 15;
    return h & mask;
}
/* The bucket of a cell: on the dense grid or hashed (see dense in motus__contact_job). */
static unsigned motus__bucket(const motus__contact_job *j, int x, int y, int z) {
    if (j->dense)
        return (unsigned)((x - j->dense_low[0]) * j->dense_stride[0] + (y - j->dense_low[1]) * j->dense_stride[1] +
                          (z - j->dense_low[2]) * j->dense_stride[2]);
    return motus__cell_hash(x, y, z, j->mask);
}
/* The cell number of coordinate x: floor(x / cell), formed in double (in float too: a cell number up to
   2^29 then has an ulp of 2^-23 cell, so touching particles, less than 2.2/2.25 of a cell apart, never
   round two cells apart), clamped to +-MOTUS__CELL_LIMIT. Clamped, the particles beyond share the edge
   cells (found as pairs where they are near, as any): one particle flung far away no longer makes the
   cells as wide as its distance over the limit, which put a pile of 10^5 into one cell (O(N^2): a step of
   15.6 s for one particle at 1e8 m). */
static int motus__cell_of(motus_real x, motus_real inverse_cell) {
    double q = (double)x * (double)inverse_cell;
    int t;
    if (q > (double)MOTUS__CELL_LIMIT) q = (double)MOTUS__CELL_LIMIT;
    if (q < -(double)MOTUS__CELL_LIMIT) q = -(double)MOTUS__CELL_LIMIT;
    t = (int)q;
    return (double)t > q ? t - 1 : t;
}

/* Particle i's slab (0 .. slabs - 1): its cell's place in the extent, in slabs (integers: exact; the cells
   below 2^30 apart, times 64 slabs at most). */
static int motus__slab_of(const motus__contact_job *j, int i) {
    return (int)((int64_t)(j->cell[j->slab_axis][i] - j->slab_low) * j->slabs / j->slab_extent);
}
/* The particles of task t: [*from, *to). */
static void motus__task_range(const motus__contact_job *j, int t, int *from, int *to) {
    *from = t * j->task_size;
    *to = j->count - *from < j->task_size ? j->count : *from + j->task_size;
}
static void motus__scan_task(void *context, int first, int count) {
    motus__contact_job *j = (motus__contact_job *)context;
    int t, i, from, to;
    for (t = first; t < first + count; ++t) {
        motus_real largest_radius = 0, largest_velocity = 0;
        int d;
        motus__task_range(j, t, &from, &to);
        for (i = from; i < to; ++i) {
            const motus_real r = motus__contact_r(j, i);
            if (r > largest_radius) largest_radius = r;
        }
        for (d = 0; d < j->dims; ++d)
            for (i = from; i < to && j->v[d]; ++i) { /* NULL in motus_find_contacts: not read */
                const motus_real v = j->v[d][(ptrdiff_t)i * j->stride], m = v < 0 ? -v : v;
                if (m > largest_velocity) largest_velocity = m;
            }
        j->task_largest_radius[t] = largest_radius;
        j->task_largest_velocity[t] = largest_velocity;
    }
}
/* A height as an unsigned key in the same order: in steps of 1/64 of the largest radius (heights closer
   than that tie, and keep their index order: a settled row, level to rounding, stays in the order of its
   particles in memory, which an exact order of heights broke: 17% more time a step on a 3D pile of 10^4),
   clamped to 32 bits. */
static uint32_t motus__height_key(const motus__contact_job *j, motus_real height) {
    double q = (double)height * j->height_scale;
    if (q > 2147483647.0) q = 2147483647.0;
    if (q < -2147483648.0) q = -2147483648.0;
    return (uint32_t)((int64_t)q + (int64_t)2147483648LL); /* truncated: monotonic, as the order needs */
}
static void motus__cells_task(void *context, int first, int count) {
    motus__contact_job *j = (motus__contact_job *)context;
    int t, i, d, from, to;
    for (t = first; t < first + count; ++t) {
        int near_walls = 0, cell_low[3] = {INT_MAX, INT_MAX, INT_MAX}, cell_high[3] = {INT_MIN, INT_MIN, INT_MIN};
        int *near_wall;
        motus__task_range(j, t, &from, &to);
        near_wall = j->near_wall + from;
        for (i = from; j->walls && i < to; ++i) {
            const motus_real reach = motus__contact_r(j, i) + 4 * j->largest_radius;
            int close_to_wall = 0;
            for (d = 0; d < j->dims; ++d) {
                const motus_real x = j->x[d][(ptrdiff_t)i * j->stride];
                close_to_wall |= (x - j->lo[d] < reach) | (j->hi[d] - x < reach); /* Inf - x: never near; overflow: Inf */
            }
            if (close_to_wall) near_wall[near_walls++] = i;
        }
        j->task_near[t] = near_walls;
        for (i = from; j->grid && i < to; ++i) {
            int k[3] = {0, 0, 0};
            for (d = 0; d < j->dims; ++d)
                k[d] = j->cell[d][i] = motus__cell_of(j->x[d][(ptrdiff_t)i * j->stride], j->inverse_cell);
            j->rank[i] = (int)motus__cell_hash(k[0], k[1], k[2], j->mask); /* the bucket, for now */
            j->height_key[i] = motus__height_key(j, j->up_sign * j->x[j->up_axis][(ptrdiff_t)i * j->stride]);
            for (d = 0; d < 3; ++d) {
                if (k[d] < cell_low[d]) cell_low[d] = k[d];
                if (k[d] > cell_high[d]) cell_high[d] = k[d];
            }
        }
        for (d = 0; d < 3; ++d) j->task_cells[t][0][d] = cell_low[d], j->task_cells[t][1][d] = cell_high[d];
    }
}
/* Each particle's bucket on the dense grid (in rank, for now). */
static void motus__dense_task(void *context, int first, int count) {
    motus__contact_job *j = (motus__contact_job *)context;
    int t, i, from, to;
    for (t = first; t < first + count; ++t) {
        motus__task_range(j, t, &from, &to);
        for (i = from; i < to; ++i)
            j->rank[i] = (int)motus__bucket(j, j->cell[0][i], j->cell[1][i], j->dims == 3 ? j->cell[2][i] : 0);
    }
}
static void motus__slabs_task(void *context, int first, int count) {
    motus__contact_job *j = (motus__contact_job *)context;
    int t, i, from, to;
    for (t = first; t < first + count; ++t) {
        motus__task_range(j, t, &from, &to);
        for (i = from; i < to; ++i) {
            const int s = motus__slab_of(j, i);
            j->task_of[i] = (s & 1) ? j->even_slabs + s / 2 : s / 2;
        }
    }
}
/* The particles from the bottom up (order), ties in index order: a stable LSD radix sort of the height
   keys, a byte a pass (a pass whose byte all keys share is skipped: a pile's keys share their top
   bytes). Steps of a fixed height whatever the spread of the heights: binned over the lowest to the
   highest, one particle far above a pile put the whole pile in a bin or two, in index order, and the
   support sweep no longer went from the bottom up (a settled pile of 2,000 with an immovable particle
   10^6 px above it blew up: overlaps of 1.96 r). */
static void motus__height_order(motus__contact_job *j, int *spare) {
    /* the keys move with their particles (the scatter then reads both in order); their spare: after the
       particles' spare. The four bytes' counts in one pass over the keys, in index order. */
    uint32_t *keys = j->height_key, *keys_to = (uint32_t *)(void *)(spare + j->count), *swap_keys;
    int *from = j->order, *to = spare, *swap, i, pass, byte, start[4][257];
    for (pass = 0; pass < 4; ++pass)
        for (byte = 0; byte <= 256; ++byte) start[pass][byte] = 0;
    for (i = 0; i < j->count; ++i) {
        const uint32_t key = keys[i];
        from[i] = i;
        ++start[0][(key & 255u) + 1], ++start[1][((key >> 8) & 255u) + 1];
        ++start[2][((key >> 16) & 255u) + 1], ++start[3][(key >> 24) + 1];
    }
    for (pass = 0; pass < 4; ++pass) {
        int *next = start[pass];
        const int shift = 8 * pass;
        if (next[((keys[0] >> shift) & 255u) + 1] == j->count) continue; /* one byte for all */
        for (byte = 0; byte < 256; ++byte) next[byte + 1] += next[byte];
        for (i = 0; i < j->count; ++i) {
            const int k = next[(keys[i] >> shift) & 255u]++;
            to[k] = from[i], keys_to[k] = keys[i];
        }
        swap = from, from = to, to = swap;
        swap_keys = keys, keys = keys_to, keys_to = swap_keys;
    }
    if (from != j->order) memcpy(j->order, from, sizeof(int) * (size_t)j->count);
}
static void motus__ranks_task(void *context, int first, int count) {
    motus__contact_job *j = (motus__contact_job *)context;
    int t, k, from, to;
    for (t = first; t < first + count; ++t) {
        motus__task_range(j, t, &from, &to);
        for (k = from; k < to; ++k) j->rank[j->order[k]] = k;
    }
}

/* The slab task a particle's own slab is solved in. */
static int motus__particle_task(const motus__contact_job *j, int i) { return j->task_of[i]; }

/* The job of a contact pass over the state, and the grid of its positions: cells of 2.25 times the largest
   radius (so that touching particles are in the same or neighbouring cells, with room for rounding; cell
   numbers by motus__cell_of); the particles counting-sorted by bucket into the scratch, in index order
   within one. */
static void motus__contact_job_init(motus__contact_job *j, const motus_scene *scene, const motus_state *state,
                                    int dims, motus_real h, void *memory, const motus__layout *l) {
    const motus_contacts *c = &scene->contacts;
    const motus_real g[3] = {scene->gravity.x, scene->gravity.y, scene->gravity.z};
    motus_real lo[3], hi[3];
    motus_real largest_radius = 0, cell, g_max = 0, g_sum = 0;
    motus_real *reals = (motus_real *)(void *)((char *)memory + l->coupled + l->copy);
    int *ints = (int *)(void *)(reals + 2 * 4 * l->pair_capacity);
    int i, d, t, count = state->count, low[3], high[3];
    memset(j, 0, sizeof *j);
    motus__walls_of(scene, lo, hi);
    j->dims = dims;
    j->count = count;
    j->stride = state->stride == 0 ? 1 : state->stride;
    for (d = 0; d < dims; ++d) {
        j->x[d] = state->position[d];
        j->v[d] = state->velocity[d];
        j->lo[d] = lo[d];
        j->hi[d] = hi[d];
    }
    j->inverse_mass = state->inverse_mass;
    j->radius = state->radius;
    j->radius_stride = motus__radius_stride(state);
    j->uniform_inverse_mass = scene->mass > 0 ? MOTUS_R(1.0) / scene->mass : MOTUS_R(1.0);
    j->uniform_radius = c->radius;
    j->restitution = c->restitution;
    j->wall_restitution = scene->restitution;
    j->friction = c->friction;
    j->iterations = c->iterations > 0 ? c->iterations : 4;
    j->walls = motus__bounds_on(scene, dims);
    /* |g| without squaring g (it may be near the largest real) */
    for (d = 0; d < dims; ++d) g_max = (g[d] < 0 ? -g[d] : g[d]) > g_max ? (g[d] < 0 ? -g[d] : g[d]) : g_max;
    for (d = 0; d < dims && g_max > 0; ++d) g_sum += (g[d] / g_max) * (g[d] / g_max);
    j->h = h;
    j->threshold = c->restitution_threshold > 0 ? c->restitution_threshold : 4 * (g_max * MOTUS_SQRT(g_sum)) * h;
    /* the solver's up: against gravity (y without gravity) */
    {
        int axis = 1;
        for (d = 0; d < dims; ++d)
            if ((g[d] < 0 ? -g[d] : g[d]) > (g[axis] < 0 ? -g[axis] : g[axis])) axis = d;
        j->up_axis = axis, j->up_sign = g[axis] > 0 ? -1 : 1;
        j->weighed = g[axis] != 0;
        j->slab_axis = axis == 0 ? 1 : 0;
    }
    for (d = 0; d < dims; ++d) j->cell[d] = ints, ints += count;
    j->sorted = ints, ints += count;
    j->table = ints, ints += l->table_size + 1;
    j->order = ints, ints += count;
    j->rank = ints, ints += count;
    j->supported = ints, ints += count;
    j->near_wall = ints, ints += count;
    j->slab_rank = ints, ints += count;
    j->task_of = ints, ints += count;
    j->sort_bins = ints, ints += 3 * count + MOTUS__SLABS + 1;
    j->height_key = (uint32_t *)(void *)j->sort_bins; /* free until the pairs are sorted; then 2 counts of spare */
    j->pairs = (motus_contact_pair *)(void *)ints;
    j->pairs_sorted = j->pairs + l->pair_capacity;
    j->geometry = reals;
    j->geometry_sorted = reals + 4 * l->pair_capacity;
    j->pair_capacity = l->pair_capacity;
    j->pairs_per_particle = count > 0 ? (int)(l->pair_capacity / (size_t)count) : 0;
    j->task_size = motus__task_size(count, &j->tasks);
    j->slabs = j->even_slabs = 1;
    j->slab_first[1] = count;
    j->mask = (unsigned)(l->table_size - 1);
    /* the largest radius (per task, then the largest of those) */
    motus__for(scene, motus__scan_task, j, j->tasks);
    j->velocity_scale = 1;
    for (t = 0; t < j->tasks; ++t) {
        if (j->task_largest_radius[t] > largest_radius) largest_radius = j->task_largest_radius[t];
        while (j->task_largest_velocity[t] * j->velocity_scale > (motus_real)MOTUS__REAL_MAX / 64 &&
               j->task_largest_velocity[t] <= (motus_real)MOTUS__REAL_MAX)
            j->velocity_scale *= MOTUS_R(0.5);
    }
    j->largest_radius = largest_radius;
    j->grid = largest_radius > 0 && count > 1;
    if (j->grid) {
        cell = largest_radius * MOTUS_R(2.25); /* > 2 * MOTUS__REACH: room for rounding */
        if (cell < 4 / (motus_real)MOTUS__REAL_MAX) cell = 4 / (motus_real)MOTUS__REAL_MAX;
        j->inverse_cell = 1 / cell;
        j->height_scale = 64 / (double)largest_radius;
        if (!(j->height_scale <= 1e308)) j->height_scale = 1e308; /* a subnormal radius in double */
        /* distances in units where the largest pair of radii is about 1: neither their squares nor those of
           the gaps between touching particles overflow or underflow (a power of two: exact) */
        j->scale = 1;
        while (j->scale * largest_radius > 2 && j->scale > 4 / (motus_real)MOTUS__REAL_MAX) j->scale *= MOTUS_R(0.5);
        while (j->scale * largest_radius < MOTUS_R(0.25) && j->scale < (motus_real)MOTUS__REAL_MAX / 4) j->scale *= 2;
        j->inverse_scale = 1 / j->scale;
    }
    /* the particles within their radius and two of the largest diameters of a wall (the sweeps look at
       these; the last projection onto the walls looks at all), each task's into its own part of near_wall,
       then one after the other; with the grid, each particle's cell and bucket (in rank, for now), and the
       lowest and highest heights and slab cells */
    motus__for(scene, motus__cells_task, j, j->tasks);
    j->near_walls = 0;
    for (t = 0; t < j->tasks; ++t) {
        const int *from = j->near_wall + t * j->task_size;
        for (i = 0; i < j->task_near[t]; ++i) j->near_wall[j->near_walls + i] = from[i];
        j->near_walls += j->task_near[t];
    }
    j->wall_start[1] = j->near_walls;
    if (!j->grid) {
        for (i = 0; i < count; ++i) j->order[i] = j->rank[i] = i; /* index order */
        return;
    }
    /* the lowest and highest cell on each axis, over the tasks: the dense grid's span and the slabs' */
    for (d = 0; d < 3; ++d) {
        low[d] = j->task_cells[0][0][d], high[d] = j->task_cells[0][1][d];
        for (t = 1; t < j->tasks; ++t) {
            if (j->task_cells[t][0][d] < low[d]) low[d] = j->task_cells[t][0][d];
            if (j->task_cells[t][1][d] > high[d]) high[d] = j->task_cells[t][1][d];
        }
    }
    {
        /* the dense grid where it fits in the table: the cells spanned, one more each side (the neighbours
           of the outermost), the first axis of the half neighbourhood fastest (see motus__contact_job) */
        const int axis = j->up_axis, first = axis == 0 ? 1 : 0, second = 3 - axis - first;
        const int by[3] = {first, second, axis};
        double cells = 1;
        int k;
        for (k = 0; k < 3; ++k) {
            d = by[k];
            j->dense_stride[d] = (ptrdiff_t)cells;
            j->dense_low[d] = d < dims ? low[d] - 1 : 0; /* cell numbers: within +-2^29 */
            cells *= d < dims ? (double)high[d] - (double)low[d] + 3 : 1;
        }
        j->dense = cells <= (double)l->table_size;
        if (j->dense) motus__for(scene, motus__dense_task, j, j->tasks);
    }
    /* the particles counting-sorted by bucket, in index order within one; table[b] runs one bucket ahead
       in the scatter, and is shifted back after */
    for (i = 0; i <= (int)l->table_size; ++i) j->table[i] = 0;
    for (i = 0; i < count; ++i) ++j->table[j->rank[i] + 1];
    for (i = 0; i < (int)l->table_size; ++i) j->table[i + 1] += j->table[i];
    for (i = 0; i < count; ++i) j->sorted[j->table[j->rank[i]]++] = i;
    for (i = (int)l->table_size; i > 0; --i) j->table[i] = j->table[i - 1];
    j->table[0] = 0;
    /* The solver's order: from the bottom up (motus__height_order), ties in index order. A pile's floor
       contacts then come before the rows they carry, so one sweep carries a push up the whole pile. */
    {
        const int axis = j->up_axis, first = axis == 0 ? 1 : 0, second = 3 - axis - first;
        int o[3], k;
        j->half_count = 0;
        for (o[axis] = 0; o[axis] <= 1; ++o[axis])
            for (o[second] = dims == 3 ? -1 : 0; o[second] <= (dims == 3 ? 1 : 0); ++o[second])
                for (o[first] = -1; o[first] <= 1; ++o[first]) {
                    if (o[axis] == 0 && (o[second] < 0 || (o[second] == 0 && o[first] < 0))) continue;
                    j->half[j->half_count][0] = o[0], j->half[j->half_count][1] = o[1];
                    j->half[j->half_count][2] = o[2], ++j->half_count;
                }
        /* on the dense grid, the half neighbourhood as runs of neighbouring buckets */
        j->run_count = 0;
        for (k = 0; j->dense && k < j->half_count; ++k) {
            const ptrdiff_t at = j->half[k][0] * j->dense_stride[0] + j->half[k][1] * j->dense_stride[1] +
                                 j->half[k][2] * j->dense_stride[2];
            if (j->run_count > 0 && j->run_start[j->run_count - 1] + j->run_length[j->run_count - 1] == at) {
                ++j->run_length[j->run_count - 1];
            } else {
                j->run_start[j->run_count] = at, j->run_length[j->run_count] = 1, ++j->run_count;
            }
        }
        /* The slabs: across an axis that is not up, so that a pile's columns stay in one slab; as many as
           are at least MOTUS__SLAB_CELLS_2D (3D) cells wide, at most MOTUS__SLABS, rounded down to a multiple
           of 12 (from 12 up; else of 4), all as wide to a cell. Each colour then has an even number of slabs
           of about one weight, which 2, 3, 4 or 6 threads share evenly (13 slabs of 4 cells, the last of
           one, had 2 threads take 4 and 3 of the 7 even ones: 1.59x one thread on a 3D pile). In 3D, of the
           two axes across up, the one along which fewer particles are two slabs or more from the particle
           a cache line before them in the array (the first on a tie): the threads then write apart in
           memory. Across x, a 3D drop of 10^5 balls stored x fastest, then z, had the 16 balls of a 64-byte
           line of x or v in about four slabs, two threads wrote the same lines, and ran 1.43x one thread;
           across z, 1.76-1.80x. The same balls stored in blocks along x as wide as a slab: across x 1.82x,
           across z 1.67x (a count of the slab borders between array neighbours had chosen z there). */
        if (count >= MOTUS_CONTACT_SLAB_MIN_COUNT && scene->parallel_for) {
            const int least = dims == 3 ? MOTUS__SLAB_CELLS_3D : MOTUS__SLAB_CELLS_2D;
            size_t fewest_far = 0;
            int a;
            for (a = 0; a < dims; ++a) {
                int extent, slabs;
                size_t far_apart = 0; /* particles two slabs or more from the one a line before */
                if (a == j->up_axis) continue;
                extent = high[a] - low[a] + 1; /* cell numbers: below 2^29 in magnitude */
                slabs = extent / least < MOTUS__SLABS ? extent / least : MOTUS__SLABS;
                slabs = slabs >= 12 ? slabs / 12 * 12 : slabs / 4 * 4;
                if (slabs < 4) continue;
                if (dims == 3) {
                    /* the particles a 64-byte line apart in the array that are two slabs or more apart:
                       slabs one apart are of two colours and never solved at once, slabs two apart may be,
                       on two threads, which then write the same lines (a heuristic, in doubles: no division
                       a particle, the same count on every build) */
                    const int *cell_of = j->cell[a], apart = (int)(64 / sizeof(motus_real));
                    const double per_cell = (double)slabs / extent;
                    for (i = apart; i < count; ++i) {
                        const int slab = (int)((double)(cell_of[i] - low[a]) * per_cell);
                        const int before = (int)((double)(cell_of[i - apart] - low[a]) * per_cell);
                        far_apart += slab - before >= 2 || before - slab >= 2;
                    }
                }
                if (j->slabs > 1 && far_apart >= fewest_far) continue;
                fewest_far = far_apart;
                j->slab_axis = a, j->slabs = slabs, j->even_slabs = slabs / 2;
                j->slab_low = low[a], j->slab_extent = extent;
            }
        }
        if (j->slabs > 1) motus__for(scene, motus__slabs_task, j, j->tasks); /* each particle's slab's task */
        motus__height_order(j, (int *)(void *)(j->height_key + count));
        motus__for(scene, motus__ranks_task, j, j->tasks); /* rank[order[k]] = k */
    }
    if (j->slabs > 1) {
        /* the rank by slab task, then height: a stable counting sort of the height order by task */
        int *first = j->slab_first, s;
        for (s = 0; s <= j->slabs; ++s) first[s] = 0;
        for (i = 0; i < count; ++i) ++first[j->task_of[i] + 1];
        for (s = 0; s < j->slabs; ++s) first[s + 1] += first[s];
        {
            int next[MOTUS__SLABS];
            for (s = 0; s < j->slabs; ++s) next[s] = first[s];
            for (i = 0; i < count; ++i) {
                const int q = j->order[i];
                j->slab_rank[q] = next[j->task_of[q]]++;
            }
        }
        {
            /* the particles near a wall by slab task (a wall contact touches its particle only) */
            int *start = j->wall_start, *sorted_walls = j->sort_bins;
            for (t = 0; t <= j->slabs; ++t) start[t] = 0;
            for (i = 0; i < j->near_walls; ++i) ++start[motus__particle_task(j, j->near_wall[i]) + 1];
            for (t = 0; t < j->slabs; ++t) start[t + 1] += start[t];
            for (i = 0; i < j->near_walls; ++i) sorted_walls[start[motus__particle_task(j, j->near_wall[i])]++] = j->near_wall[i];
            for (t = j->slabs; t > 0; --t) start[t] = start[t - 1];
            start[0] = 0;
            for (i = 0; i < j->near_walls; ++i) j->near_wall[i] = sorted_walls[i];
        }
    } else {
        j->slab_rank = j->rank;
    }
}
/* The task of a pair: that of its upper particle's slab, so that a particle's supports are solved together
   (split between two tasks, a ball in a V of two supports on a slab border was thrown off one, and a 2D
   pile of 6,000 never came to rest: 1.5% overlaps). A pair's cells are at most one apart, so its lower
   particle is in the same slab or on the edge of a neighbour. */
static int motus__pair_task(const motus__contact_job *j, int upper) {
    return j->slabs <= 1 ? 0 : motus__particle_task(j, upper);
}

/* Are a and b nearer than `reach` times the sum of their radii (1: overlapping)? If so, the unit normal from
   a to b and the depth (m; negative: the gap between them). Coincident centres get the normal +x. With
   `overlapping`, only a pair that overlaps (depth > 0) is one: the projection's test, before the normal's
   divisions, which it then spares the pairs it leaves alone (a drop of 10^4 at 1 substep: 1-2% of a step
   in 2D, 7-9% in 3D). */
MOTUS__KI int motus__overlap_in(const motus__contact_job *j, int dims, int a, int b, motus_real reach, int overlapping,
                                motus_real *normal, motus_real *depth) {
    const ptrdiff_t pa = (ptrdiff_t)a * j->stride, pb = (ptrdiff_t)b * j->stride;
    const motus_real sum = (motus__contact_r(j, a) + motus__contact_r(j, b)) * j->scale, touching_at = sum * reach;
    motus_real u[3] = {0, 0, 0}, d2 = 0, distance;
    int d;
    for (d = 0; d < dims; ++d) {
        u[d] = (j->x[d][pb] - j->x[d][pa]) * j->scale; /* Inf when far apart: no contact */
        d2 += u[d] * u[d];
    }
    if (!(d2 < touching_at * touching_at)) return 0;
    distance = MOTUS_SQRT(d2);
    *depth = (sum - distance) * j->inverse_scale;
    if (overlapping && !(*depth > 0)) return 0;
    for (d = 0; d < dims; ++d) normal[d] = distance > 0 ? u[d] / distance : (motus_real)(d == 0);
    return 1;
}

/* |t| from t2 = t.t, or, where t2 overflowed, from t over its largest component (a sliding speed of 1e19
   m/s in float is representable; its square is not, and friction was dropped). t has 3 components, those
   past the scene's dimensions 0 (which add nothing); a loop over all 3 also spares gcc -mavx512f -O2 a
   false "t may be used uninitialized". */
static motus_real motus__length_scaled(const motus_real t[3], motus_real t2) {
    motus_real largest = 0, sum = 0;
    int d;
    if (t2 <= (motus_real)MOTUS__REAL_MAX) return MOTUS_SQRT(t2);
    for (d = 0; d < 3; ++d) largest = (t[d] < 0 ? -t[d] : t[d]) > largest ? (t[d] < 0 ? -t[d] : t[d]) : largest;
    if (!(largest > 0) || !(largest <= (motus_real)MOTUS__REAL_MAX)) return t2; /* NaN or Inf: as it was */
    for (d = 0; d < 3; ++d) sum += (t[d] / largest) * (t[d] / largest);
    return largest * MOTUS_SQRT(sum);
}
/* In the support sweep a gap up to this is a contact (no approach allowed): 4 ulps of the pair's largest
   coordinate (6.7e-4 m at 1,414 m in float), and at least 4 ulps of 256 radii's sums (MOTUS__SUPPORT_SLOP
   of the sum: 1.2e-4 in float, 2.3e-13 in double), as if the pair stood a pile's width from the origin.
   - The rounding: letting a particle fall into a gap of rounding size against a support taken as still
     fed the rounding of each row's lift back into the next substep's gaps, and a float pile 700 rows deep
     at x = 1,400 m (ulp 1.2e-4 m) blew up within three substeps.
   - The slop: with the rounding alone, tiny near the origin, the rows of a float pile there fell into gaps
     of 1e-6 m and were lifted back at every substep (a 2D pile of 10^5 in slabs: kinetic energy 1.1e-8 of
     the potential it fell from, its bottom corner's slabs 50% slower a pair; 4e-11 with the slop). What it
     costs: a ball may rest up to that slop above its support (1e-4 of a diameter in float). A slop of 1e-4
     of the sum in double let a 400-row pile grow 1 cm in a second, a gap held at every row.
   - The pair's own coordinates, not the scene's: one particle or pair flung far away made every gap below
     4 ulps of its coordinate a contact (a ball 0.06 m above another took 84 frames to land, not 6, beside
     a pair at x = 1e6 m in float). */
static motus_real motus__support_slop(const motus__contact_job *j, int a, int b, motus_real sum) {
    motus_real largest = 0, rounding;
    int d;
    for (d = 0; d < j->dims; ++d) {
        const motus_real xa = j->x[d][(ptrdiff_t)a * j->stride], xb = j->x[d][(ptrdiff_t)b * j->stride];
        const motus_real ma = xa < 0 ? -xa : xa, mb = xb < 0 ? -xb : xb;
        if (ma > largest) largest = ma;
        if (mb > largest) largest = mb;
    }
    rounding = largest * (4 * MOTUS_REAL_EPSILON);
    return rounding > MOTUS__SUPPORT_SLOP * sum ? rounding : MOTUS__SUPPORT_SLOP * sum;
}
/* In the support sweep, is a (below b, in the next slab) solved after b? Its support is not known yet when
   b is solved: it is taken as supported (a pile rests on its neighbours; taken as unsupported, a ball on a
   slab border rested on one support of its V and was pushed sideways off it, at every substep, and a 2D
   pile of 6,000 never came to rest). */
static int motus__solved_later(const motus__contact_job *j, int a, int b) {
    int ta, tb;
    if (j->slabs <= 1) return 0;
    ta = motus__particle_task(j, a), tb = motus__particle_task(j, b);
    return tb < j->even_slabs && ta >= j->even_slabs;
}
/* One contact's velocity: the normal impulse that turns the approach speed vn < 0 into -e*vn (0 below the
   threshold), mass-weighted, then Coulomb friction up to friction times that impulse, never past a
   tangential stop. Applied to the current velocities (Gauss-Seidel), so a chain (Newton's cradle) passes
   the momentum through in one sweep. Equal and opposite: momentum is kept to rounding; with e <= 1 the
   kinetic energy does not grow. */
MOTUS__KI void motus__pair_velocity(motus__contact_job *j, int dims, int a, int b, const motus_real *n, motus_real depth,
                                    motus_real *accumulated, int *moved) {
    const ptrdiff_t pa = (ptrdiff_t)a * j->stride, pb = (ptrdiff_t)b * j->stride;
    const motus_real wb = motus__contact_w(j, b), gap = -depth;
    const motus_real sum = motus__contact_r(j, a) + motus__contact_r(j, b);
    motus_real wa = motus__contact_w(j, a), w = wa + wb;
    motus_real vn = 0, target, allowed, impulse, t[3] = {0, 0, 0}, t2 = 0, tangential, friction;
    int d, fast;
    if (w == 0) return; /* two immovable particles */
    /* the support sweep acts only on a particle resting on a support (see below): most pairs end here */
    if (j->shock && (!(j->supported[a] || motus__solved_later(j, a, b)) || wb == 0 ||
                     !(n[j->up_axis] * j->up_sign > MOTUS_R(0.5))))
        return;
    for (d = 0; d < dims; ++d) vn += (j->v[d][pb] - j->v[d][pa]) * n[d];
    /* A fast approach (faster than the threshold) is a collision once they touch or overlap: it bounces with
       the approach speed it has then. A slow one is a resting contact: within a few % of touching (a pile's
       supports), or closing its gap within this substep, it may approach only as fast as closes the gap
       by the substep's end (a speculative contact: it lands, and nothing hovers). */
    fast = vn < -j->threshold && !j->shock;
    if (fast ? !(gap <= 0) : (gap > (j->shock ? MOTUS__TOUCH_SUPPORT : MOTUS__TOUCH) * sum && !(gap <= -vn * j->h)))
        return;
    if (j->shock) {
        /* the last sweep: a particle resting on a support (a wall, an immovable particle, or a particle that
           rests on one) within 60 degrees of up is a support for the one above it (a neighbour in the same
           row is not: n.up > 1/2 parts them clearly, 0.87 against 0 in a packed 2D pile, 0.82 against 0 in
           3D): the impulse moves only the upper one. The support is taken as still whichever way it moves
           (the sweeps before dealt with that): the support sweep only stops, it never throws (energy is not
           made). Relative to a support still sinking, an error left in one row would be passed on to every
           row above it and add up: a 10^5-ball frictionless 2D pile sank through itself. */
        motus_real support = 0;
        j->supported[b] = 1;
        wa = 0, w = wb;
        for (d = 0; d < dims; ++d) support += j->v[d][pa] * n[d];
        vn += support; /* vn as against a still support */
    }
    /* In the support sweep a gap within motus__support_slop is a contact (no approach allowed); larger gaps
       close as in the other sweeps. (After the support test: most pairs of a support sweep end there.) */
    allowed = gap > 0 && (!j->shock || gap > motus__support_slop(j, a, b, sum)) ? -gap / j->h : 0;
    target = fast ? -j->restitution * vn : allowed;
    if (accumulated && *accumulated >= 0 && !fast) {
        /* A resting contact keeps the impulse it has had in this pass, and its total is clamped at 0, not
           each increment (projected Gauss-Seidel with accumulated impulses: Catto 2005). Clamped increments
           leave a ball in a V of two supports 60 degrees apart thrown off them at a quarter of the speed the
           substep's gravity gave it (0.0102 m/s at 9.81 m/s^2 and h = 1/240 s): a resting pile made energy
           at every substep (a 2D pile 700 rows deep rose 0.1 m in 100 substeps). What is taken back only
           stops a separation (vn down to 0, never an approach made): the kinetic energy still never grows. */
        if (!(vn < allowed) && !(*accumulated > 0 && vn > 0)) return; /* nothing to give or take back */
        impulse = (target - vn) / w;
        if (impulse < 0) impulse = vn > 0 ? -vn / w : 0;
        if (*accumulated + impulse < 0) impulse = -*accumulated;
        *accumulated += impulse;
        *moved = 1;
        if (impulse == 0) return;
    } else {
        if (!(vn < allowed)) return; /* separating, or resting */
        impulse = (target - vn) / w;
        /* a collision's bounce is never taken back: the pair takes only increments from now on */
        if (accumulated && fast) *accumulated = -1;
    }
    *moved = 1;
    for (d = 0; d < dims; ++d) {
        j->v[d][pa] -= impulse * wa * n[d];
        j->v[d][pb] += impulse * wb * n[d];
    }
    if (j->friction == 0 || !(impulse > 0)) return; /* friction up to friction times an impulse given */
    /* the tangential part of the relative velocity: r - (r.n)n, with r.n summed over the components */
    {
        motus_real rn = 0;
        for (d = 0; d < dims; ++d) rn += (j->v[d][pb] - j->v[d][pa]) * n[d];
        for (d = 0; d < dims; ++d) t[d] = (j->v[d][pb] - j->v[d][pa]) - rn * n[d], t2 += t[d] * t[d];
    }
    tangential = motus__length_scaled(t, t2);
    if (!(tangential > 0)) return;
    friction = tangential / w; /* the impulse that stops the sliding */
    if (friction > j->friction * impulse) friction = j->friction * impulse;
    for (d = 0; d < dims; ++d) {
        const motus_real direction = t[d] / tangential;
        j->v[d][pa] += friction * wa * direction;
        j->v[d][pb] -= friction * wb * direction;
    }
}
/* One contact's position: each pushed out along the normal by its share (inverse mass) of the depth. A
   projection, not a velocity (split impulse): it removes the overlap without adding energy. In the support
   sweep only a particle on its support (within 60 degrees of up) moves, and straight up, by depth / n.up
   (at most twice the depth): pushed along the normal instead, a ball against a side wall is pushed into it
   and the sideways errors grow from row to row up the wall (a 10^5-ball frictionless 2D pile blew up). */
MOTUS__KI void motus__pair_position(motus__contact_job *j, int dims, int a, int b, const motus_real *n, motus_real depth,
                                    int *moved) {
    const ptrdiff_t pa = (ptrdiff_t)a * j->stride, pb = (ptrdiff_t)b * j->stride;
    /* the support sweep: only where b rests on a (the pairs side by side were dealt with by the sweeps before) */
    const int carried = j->shock && n[j->up_axis] * j->up_sign > MOTUS_R(0.5);
    const motus_real wb = motus__contact_w(j, b), wa = carried && wb > 0 ? 0 : motus__contact_w(j, a), w = wa + wb;
    int d;
    if (w == 0 || (j->shock && !carried)) return;
    *moved = 1;
    if (carried && wb > 0) {
        j->x[j->up_axis][pb] += j->up_sign * depth / (n[j->up_axis] * j->up_sign);
        return;
    }
    if (j->weighed && !j->shock && depth > MOTUS__DEEP * (motus__contact_r(j, a) + motus__contact_r(j, b))) {
        /* Deep and level (side by side, within 14 degrees): pushed apart along a normal tilted up to b, the
           upper in the solver's order (height, then index). Straight sideways, a row with more balls than
           fit between the walls (a frame hitch of 0.2 s pressed a settled pile into its floor: every ball
           clamped to the floor's height) only pressed sideways for ever: 100 balls where 79 fit still
           overlapped by 0.8 r after 10 s. Tilted, b rises onto its neighbours and the row heals. Above
           MOTUS__DEEP only (5% of r for equal balls): the overlaps a pile rests with (< 1e-3 r) never reach
           it, and a game's pile of mixed radii (the sandbox's, about 5% r at most) is tilted only where
           deepest (at 1%, the sandbox pile's largest overlap grew by a fifth). */
        const motus_real up = n[j->up_axis] * j->up_sign;
        if (up < MOTUS__LEVEL && up > -MOTUS__LEVEL) {
            motus_real tilted[3], length2 = 0, length;
            for (d = 0; d < dims; ++d) tilted[d] = d == j->up_axis ? j->up_sign * MOTUS__LEVEL : n[d], length2 += tilted[d] * tilted[d];
            length = MOTUS_SQRT(length2);
            for (d = 0; d < dims; ++d) {
                j->x[d][pa] -= depth * (wa / w) * (tilted[d] / length);
                j->x[d][pb] += depth * (wb / w) * (tilted[d] / length);
            }
            return;
        }
    }
    for (d = 0; d < dims; ++d) {
        j->x[d][pa] -= depth * (wa / w) * n[d];
        j->x[d][pb] += depth * (wb / w) * n[d];
    }
}
/* The walls of the bounds as contacts at the particle's radius: the same impulse, threshold and friction
   as between particles (the wall immovable), and the same projection. Walls act on immovable particles
   too, as the bounds do without contacts. Returns whether it moved the particle (or may have). */
static int motus__wall_contacts(motus__contact_job *j, int i, int action) {
    const ptrdiff_t p = (ptrdiff_t)i * j->stride;
    const motus_real r = motus__contact_r(j, i);
    int d, e, moved = 0;
    for (d = 0; d < j->dims; ++d) {
        motus_real *x = &j->x[d][p], *v = &j->v[d][p], low = j->lo[d] + r, high = j->hi[d] - r;
        if (!(low <= (motus_real)MOTUS__REAL_MAX)) low = (motus_real)MOTUS__REAL_MAX;
        if (!(high >= -(motus_real)MOTUS__REAL_MAX)) high = -(motus_real)MOTUS__REAL_MAX;
        if (low > high) low = high = j->lo[d] * MOTUS_R(0.5) + j->hi[d] * MOTUS_R(0.5); /* narrower than the ball */
        if (action == MOTUS__PAIRS_POSITION) {
            if (*x < low) *x = low, moved = 1;
            if (*x > high) *x = high, moved = 1;
            continue;
        }
        for (e = -1; e <= 1; e += 2) {
            /* e = -1: the low wall (normal +d), e = +1: the high wall (normal -d) */
            const motus_real vn = e < 0 ? *v : -*v; /* along the wall's normal */
            motus_real target, change, t2 = 0, tangential, keep, t[3] = {0, 0, 0};
            int k;
            /* touching counts (the projection leaves a ball exactly against the wall; see the support sweep
               in motus__sweep_listed) */
            if (!(e < 0 ? *x <= low : *x >= high)) continue;
            j->supported[i] = 1;
            if (!(vn < 0)) continue;
            target = vn < -j->threshold ? -j->wall_restitution * vn : 0;
            change = target - vn;
            *v = e < 0 ? target : -target;
            moved = 1;
            if (j->friction == 0) continue;
            for (k = 0; k < j->dims; ++k)
                if (k != d) t[k] = j->v[k][p], t2 += t[k] * t[k];
            tangential = motus__length_scaled(t, t2);
            if (!(tangential > 0)) continue;
            keep = tangential > j->friction * change ? 1 - j->friction * change / tangential : 0;
            for (k = 0; k < j->dims; ++k)
                if (k != d) j->v[k][p] *= keep;
        }
    }
    return moved;
}

/* Does particle i touch (or pass) a wall of the bounds? */
static int motus__against_wall(const motus__contact_job *j, int i) {
    const ptrdiff_t p = (ptrdiff_t)i * j->stride;
    const motus_real r = motus__contact_r(j, i);
    int d;
    for (d = 0; d < j->dims; ++d)
        if (j->x[d][p] - j->lo[d] <= r || j->hi[d] - j->x[d][p] <= r) return 1;
    return 0;
}
/* A near pair in a phase: impulses where they touch or will (see motus__pair_velocity), projection where
   they overlap. */
MOTUS__KI void motus__pair_solve_in(motus__contact_job *j, int dims, int a, int b, int phase, const motus_real *n,
                                    motus_real depth, motus_real *accumulated, int *moved) {
    if (phase == MOTUS__PAIRS_VELOCITY) {
        motus__pair_velocity(j, dims, a, b, n, depth, accumulated, moved);
    } else if (depth > 0) {
        motus__pair_position(j, dims, a, b, n, depth, moved);
    }
}

/* Particle i's contacts in its half of the neighbourhood: its own cell's particles after it (index order),
   and the cells after its own in (up, then the other axes) order: 4 cells of 8 in 2D, 13 of 26 in 3D, so
   that each pair is met once, from one of its two particles. On the dense grid these cells are runs of
   neighbouring buckets (the first starts with the own cell); hashed, one bucket each, which may hold other
   cells too (and be some other neighbour's bucket as well): only that cell's particles. Either way the
   same cells in the same order, each cell's particles in index order. The pair is given lower particle
   first (in the solver's order), with the normal from it to the other. Records them (up to room) or solves
   them; returns how many there were. dims a constant (motus__pairs_of_2, _3). */
MOTUS__KI size_t motus__pairs_of_in(motus__contact_job *j, int dims, int i, int action, motus_real reach,
                                    motus_contact_pair *out, motus_real *geometry_out, size_t room) {
    const int c0 = j->cell[0][i], c1 = j->cell[1][i], c2 = dims == 3 ? j->cell[2][i] : 0;
    const int runs = j->dense ? j->run_count : j->half_count;
    const ptrdiff_t own = j->dense ? (ptrdiff_t)motus__bucket(j, c0, c1, c2) : 0;
    int cell;
    size_t found = 0;
    for (cell = 0; cell < runs; ++cell) {
        /* dense: run `cell` of buckets from b; hashed: half-neighbour `cell` (t0, t1, t2), in bucket b */
        int t0 = 0, t1 = 0, t2 = 0, own_end, other, end;
        ptrdiff_t b;
        if (j->dense) {
            b = own + j->run_start[cell];
            end = j->table[b + j->run_length[cell]];
        } else {
            t0 = c0 + j->half[cell][0], t1 = c1 + j->half[cell][1], t2 = c2 + j->half[cell][2];
            b = (ptrdiff_t)motus__cell_hash(t0, t1, t2, j->mask);
            end = j->table[b + 1];
        }
        own_end = cell > 0 ? 0 : j->table[b + 1]; /* the own cell's particles end here */
        for (other = j->table[b]; other < end; ++other) {
            const int q = j->sorted[other];
            motus_real n[3] = {0, 0, 0}, depth;
            int lower, upper, d;
            if ((other < own_end && q <= i) ||
                (!j->dense && (j->cell[0][q] != t0 || j->cell[1][q] != t1 || (dims == 3 && j->cell[2][q] != t2))) ||
                !motus__overlap_in(j, dims, i, q, reach, 0, n, &depth))
                continue;
            lower = i, upper = q;
            if (j->rank[q] < j->rank[i]) {
                lower = q, upper = i;
                for (d = 0; d < 3; ++d) n[d] = -n[d];
            }
            if (action == MOTUS__PAIRS_RECORD) {
                if (found < room) {
                    out[found].a = lower, out[found].b = upper;
                    if (geometry_out) {
                        motus_real *g = geometry_out + 4 * found;
                        g[0] = n[0], g[1] = n[1], g[2] = dims == 3 ? n[2] : 0, g[3] = depth;
                    }
                }
            } else {
                int moved = 0;
                motus__pair_solve_in(j, dims, lower, upper, action, n, depth, NULL, &moved);
            }
            ++found;
        }
    }
    return found;
}
static MOTUS__NOINLINE size_t motus__pairs_of_2(motus__contact_job *j, int i, int action, motus_real reach,
                                                motus_contact_pair *out, motus_real *geometry_out, size_t room) {
    return motus__pairs_of_in(j, 2, i, action, reach, out, geometry_out, room);
}
static MOTUS__NOINLINE size_t motus__pairs_of_3(motus__contact_job *j, int i, int action, motus_real reach,
                                                motus_contact_pair *out, motus_real *geometry_out, size_t room) {
    return motus__pairs_of_in(j, 3, i, action, reach, out, geometry_out, room);
}
static size_t motus__pairs_of(motus__contact_job *j, int i, int action, motus_real reach, motus_contact_pair *out,
                              motus_real *geometry_out, size_t room) {
    return j->dims == 3 ? motus__pairs_of_3(j, i, action, reach, out, geometry_out, room)
                        : motus__pairs_of_2(j, i, action, reach, out, geometry_out, room);
}

/* The list sorted for the sweeps: by slab task (the even slabs' tasks first), then by the rank of the
   upper particle (by slab, then height), stable. Each particle's supports then come together, after the
   supports of its supports, so one support sweep carries a pile from the floor up (within a slab). Two
   passes, each in tasks: each listing task scatters its pairs to its place in each slab task's part (the
   offsets worked out here), then each slab task counting-sorts its part by rank into the list, with bins
   over the ranks of its slab and the two beside it (a pair's particles are in neighbouring slabs). */
static size_t motus__task_base(const motus__contact_job *j, int t) {
    return (size_t)t * (size_t)j->task_size * (size_t)j->pairs_per_particle;
}
static void motus__scatter_task(void *context, int first, int count) {
    motus__contact_job *j = (motus__contact_job *)context;
    int t, d;
    size_t k;
    for (t = first; t < first + count; ++t) {
        const size_t base = motus__task_base(j, t);
        size_t *next = j->task_pairs[t];
        for (k = base; k < base + j->task_found[t]; ++k) {
            const size_t to = next[motus__pair_task(j, j->pairs[k].b)]++;
            j->pairs_sorted[to] = j->pairs[k];
            for (d = 0; d < 4; ++d) j->geometry_sorted[4 * to + (size_t)d] = j->geometry[4 * k + (size_t)d];
        }
    }
}
typedef struct motus__sort_context {
    motus__contact_job *job;
    size_t bins_at[MOTUS__SLABS];
} motus__sort_context;
static void motus__rank_bounds(const motus__contact_job *j, int task, int *low, int *high) {
    *low = j->slab_first[task];
    *high = j->slab_first[task + 1];
}
static void motus__slab_sort_task(void *context, int first, int count) {
    const motus__sort_context *c = (const motus__sort_context *)context;
    motus__contact_job *j = c->job;
    int t, i, d, low, high;
    size_t k;
    for (t = first; t < first + count; ++t) {
        const size_t from = j->slab_start[t], to = j->slab_start[t + 1];
        int *bins = j->sort_bins + c->bins_at[t];
        motus__rank_bounds(j, t, &low, &high);
        for (i = 0; i <= high - low; ++i) bins[i] = 0;
        for (k = from; k < to; ++k) ++bins[j->slab_rank[j->pairs_sorted[k].b] - low + 1];
        for (i = 0; i < high - low; ++i) bins[i + 1] += bins[i];
        for (k = from; k < to; ++k) {
            const size_t at = from + (size_t)bins[j->slab_rank[j->pairs_sorted[k].b] - low]++;
            j->pairs[at] = j->pairs_sorted[k];
            for (d = 0; d < 4; ++d) j->geometry[4 * at + (size_t)d] = j->geometry_sorted[4 * k + (size_t)d];
        }
    }
}
static void motus__sort_pairs(const motus_scene *scene, motus__contact_job *j) {
    motus__sort_context context;
    size_t total = 0, bins = 0;
    int t, s, low, high;
    for (s = 0; s < j->slabs; ++s) {
        j->slab_start[s] = total;
        for (t = 0; t < j->tasks; ++t) {
            const size_t n = j->task_pairs[t][s];
            j->task_pairs[t][s] = total;
            total += n;
        }
        motus__rank_bounds(j, s, &low, &high);
        context.bins_at[s] = bins;
        bins += (size_t)(high - low) + 1; /* at most 3 * count + slabs in all */
    }
    j->slab_start[j->slabs] = j->pair_count = total;
    context.job = j;
    motus__for(scene, motus__scatter_task, j, j->tasks);
    motus__for(scene, motus__slab_sort_task, &context, j->slabs);
}

/* One sweep of a phase over the listed pairs, with dims a constant (motus__sweep_listed_2, _3: the pair
   solves without a loop over a run-time dims; the same operations in the same order, so the same bits). */
MOTUS__KI void motus__sweep_listed(motus__contact_job *j, int phase, int dims, size_t first, size_t last) {
    size_t k, end;
    motus_real accumulated[MOTUS__SUPPORT_GROUP];
    for (k = first; k < last; k = end) {
        size_t m;
        int local, group, walled, several;
        /* the support sweep: a particle's supports together, a few times (a ball in a V of two), with the
           impulse on each kept over the passes (see motus__pair_velocity) */
        for (end = k + 1; j->shock && end < last && j->pairs[end].b == j->pairs[k].b;) ++end;
        /* and in the velocity sweep a wall the particle touches is one of its supports: solved before the
           pairs only, the wall's stop was undone by the support's push (a ball in the corner of a side wall
           and a support below it slid into the wall at every substep, the projection put it back and its
           support lifted it, a little more each row up the wall: a frictionless 2D pile 590 rows deep at 1
           substep of 1/60 s gave way within three frames) */
        walled = j->shock && phase == MOTUS__PAIRS_VELOCITY && j->walls && motus__against_wall(j, j->pairs[k].b);
        several = j->shock && (end > k + 1 || walled);
        group = several && end - k <= MOTUS__SUPPORT_GROUP;
        for (m = 0; group && m < end - k; ++m) accumulated[m] = 0;
        for (local = 0; local < (several ? MOTUS__SUPPORT_PASSES : 1); ++local) {
            int moved = 0;
            for (m = k; m < end; ++m) {
                motus_real n[3], depth;
                const int a = j->pairs[m].a, b = j->pairs[m].b;
                if (phase == MOTUS__PAIRS_VELOCITY) {
                    /* positions do not move in this phase: the normal and depth of the listing hold */
                    const motus_real *g = j->geometry + 4 * m;
                    n[0] = g[0], n[1] = g[1], n[2] = g[2];
                    motus__pair_solve_in(j, dims, a, b, phase, n, g[3],
                                         group ? &accumulated[m - k] : j->shock ? NULL : j->impulse + m, &moved);
                } else if (motus__overlap_in(j, dims, a, b, MOTUS__REACH, 1, n, &depth)) {
                    motus__pair_solve_in(j, dims, a, b, phase, n, depth, NULL, &moved);
                }
            }
            if (walled) moved |= motus__wall_contacts(j, j->pairs[k].b, phase);
            /* a pass that moved nothing leaves everything its next pass reads as it was: the passes left
               would do the same nothing (a drop of 10^4 at 1 substep: 8% less time a step in 2D, 14% in 3D) */
            if (!moved) break;
        }
    }
}
static MOTUS__NOINLINE void motus__sweep_listed_2(motus__contact_job *j, int phase, size_t first, size_t last) {
    motus__sweep_listed(j, phase, 2, first, last);
}
static MOTUS__NOINLINE void motus__sweep_listed_3(motus__contact_job *j, int phase, size_t first, size_t last) {
    motus__sweep_listed(j, phase, 3, first, last);
}
/* A sweep over slabs: task t is the t-th of the even slabs' tasks, or of the odd ones' (from `first_task`). */
typedef struct motus__sweep_context {
    motus__contact_job *job;
    int phase, first_task;
} motus__sweep_context;
static void motus__sweep_task(void *context, int first, int count) {
    const motus__sweep_context *c = (const motus__sweep_context *)context;
    motus__contact_job *j = c->job;
    int t, i;
    for (t = c->first_task + first; t < c->first_task + first + count; ++t) {
        const size_t from = (size_t)j->slab_start[t], to = (size_t)j->slab_start[t + 1];
        /* velocities (and the support sweep): the walls first; positions: the walls last */
        for (i = j->wall_start[t]; (c->phase == MOTUS__PAIRS_VELOCITY || j->shock) && i < j->wall_start[t + 1]; ++i)
            motus__wall_contacts(j, j->near_wall[i], c->phase);
        if (j->dims == 3) motus__sweep_listed_3(j, c->phase, from, to);
        else motus__sweep_listed_2(j, c->phase, from, to);
        for (i = j->wall_start[t]; c->phase == MOTUS__PAIRS_POSITION && !j->shock && i < j->wall_start[t + 1]; ++i)
            motus__wall_contacts(j, j->near_wall[i], c->phase);
    }
}
/* Particles in tasks: the supports reset (immovable ones support), or the last projection onto the walls
   and the check that all came out finite. */
typedef struct motus__particles_context {
    motus__contact_job *job;
    int finish;
} motus__particles_context;
static void motus__particles_task(void *context, int first, int count) {
    const motus__particles_context *c = (const motus__particles_context *)context;
    motus__contact_job *j = c->job;
    int t, i, d;
    for (t = first; t < first + count; ++t) {
        const int from = t * j->task_size, to = j->count - from < j->task_size ? j->count : from + j->task_size;
        int bad = 0;
        if (!c->finish) {
            for (i = from; i < to; ++i) j->supported[i] = motus__contact_w(j, i) == 0;
            continue;
        }
        for (i = from; j->walls && i < to; ++i) motus__wall_contacts(j, i, MOTUS__PAIRS_POSITION); /* none leaves */
        for (i = from; i < to; ++i)
            for (d = 0; d < j->dims; ++d)
                bad |= !motus_real_is_finite(j->x[d][(ptrdiff_t)i * j->stride]) ||
                       !motus_real_is_finite(j->v[d][(ptrdiff_t)i * j->stride]);
        j->failed[t] = (unsigned char)bad;
    }
}
/* The listing of task t's particles into its part of the list; task_found[t] past its room: it ran out. */
static void motus__record_task(void *context, int first, int count) {
    motus__contact_job *j = (motus__contact_job *)context;
    int t, k;
    for (t = first; t < first + count; ++t) {
        const int from = t * j->task_size, to = j->count - from < j->task_size ? j->count : from + j->task_size;
        const size_t base = motus__task_base(j, t), room = (size_t)(to - from) * (size_t)j->pairs_per_particle;
        size_t found = 0;
        for (k = from; k < to && found <= room; ++k)
            found += motus__pairs_of(j, j->order[k], MOTUS__PAIRS_RECORD, MOTUS__REACH, j->pairs + base + found,
                                     j->geometry + 4 * (base + found), room - found);
        j->task_found[t] = found;
        for (k = 0; k < j->slabs; ++k) j->task_pairs[t][k] = 0;
        for (k = 0; found <= room && k < (int)found; ++k)
            ++j->task_pairs[t][motus__pair_task(j, j->pairs[base + (size_t)k].b)];
    }
}

/* Velocities, h and the threshold for the velocity sweeps at a scale (see velocity_scale): powers of two,
   exact but where a component goes subnormal. `by` multiplies the velocities and the threshold and divides h. */
static void motus__scale_velocities(motus__contact_job *j, motus_real by) {
    int i, d;
    for (d = 0; d < j->dims; ++d)
        for (i = 0; i < j->count; ++i) j->v[d][(ptrdiff_t)i * j->stride] *= by;
    j->threshold *= by;
    j->h /= by;
}
/* One contact pass after a substep of h: the pairs recorded (as many particles' worth as the list holds;
   the rest are searched again at each sweep, in the same order), then `iterations` sweeps of velocity
   impulses over the pairs and walls, then as many of position projection. */
static motus_result motus__contacts_pass(const motus_scene *scene, const motus_state *state, int dims, motus_real h,
                                         void *memory, const motus__layout *l) {
    motus__contact_job job, *j = &job;
    int i, sweep, phase, t, overflow = 0;
    size_t k;
    motus__contact_job_init(j, scene, state, dims, h, memory, l);
    j->listed = 0;
    if (j->grid) {
        /* each task lists its particles' pairs into its own part of the list */
        motus__for(scene, motus__record_task, j, j->tasks);
        for (t = 0; t < j->tasks; ++t)
            overflow |= j->task_found[t] > (size_t)(j->count - t * j->task_size < j->task_size ? j->count - t * j->task_size
                                                                                                : j->task_size) *
                                               (size_t)j->pairs_per_particle;
        if (!overflow) {
            j->listed = j->count;
        } else {
            /* a crowded part ran out of room: list into the whole list, one particle after another, and
               leave the rest to be searched at every sweep; no slabs */
            for (k = 0; k < (size_t)j->count; ++k) {
                const size_t room = j->pair_capacity - j->pair_count;
                const size_t found = motus__pairs_of(j, j->order[k], MOTUS__PAIRS_RECORD, MOTUS__REACH,
                                                     j->pairs + j->pair_count, j->geometry + 4 * j->pair_count, room);
                if (found > room) break; /* this particle's pairs and the rest: searched at every sweep */
                j->pair_count += found;
                j->listed = (int)k + 1;
            }
            for (t = 0; t < j->tasks; ++t) j->task_found[t] = j->task_pairs[t][0] = 0;
            j->task_found[0] = j->task_pairs[0][0] = j->pair_count;
            j->slabs = j->even_slabs = 1;
            j->slab_rank = j->rank, j->slab_first[1] = j->count;
            j->wall_start[0] = 0, j->wall_start[1] = j->near_walls;
        }
        if (j->listed == j->count) motus__sort_pairs(scene, j);
    }
    /* the impulses of the listed pairs, kept over the velocity sweeps (see motus__pair_velocity), in the
       sort's spare buffer (free once sorted, or never sorted) */
    j->impulse = j->geometry_sorted;
    for (k = 0; k < j->pair_count; ++k) j->impulse[k] = 0;
    /* Velocities: the walls first (a pile's floor stops its bottom row before the rows above meet it).
       Positions: the walls last (nothing leaves the box). Each phase ends with one more sweep that carries
       a pile's weight (shock propagation, Guendelman, Bridson and Fedkiw 2003): walls first, then each pair
       from the bottom up with its lower particle counted immovable, so the rows above do not push the rows
       below back into the floor. For velocities only where the lower one is supported (a wall, an
       immovable particle, or one resting on them): in free space every impulse stays equal and opposite. */
    if (j->velocity_scale != 1) motus__scale_velocities(j, j->velocity_scale);
    for (phase = MOTUS__PAIRS_VELOCITY; phase <= MOTUS__PAIRS_POSITION; ++phase)
        for (sweep = 0; sweep < j->iterations + (MOTUS_CONTACT_SUPPORT_SWEEPS != 0); ++sweep) {
            j->shock = sweep == j->iterations;
            if (phase == MOTUS__PAIRS_POSITION && sweep == 0 && j->velocity_scale != 1)
                motus__scale_velocities(j, 1 / j->velocity_scale); /* back (Inf: reported) */
            if (j->shock && phase == MOTUS__PAIRS_VELOCITY) {
                motus__particles_context context;
                context.job = j, context.finish = 0;
                motus__for(scene, motus__particles_task, &context, j->tasks);
            }
            if (j->listed == j->count && j->grid) {
                /* the even slabs at once, then the odd ones (with the pairs across); one slab: all */
                motus__sweep_context context;
                context.job = j, context.phase = phase, context.first_task = 0;
                motus__for(scene, motus__sweep_task, &context, j->even_slabs);
                context.first_task = j->even_slabs;
                motus__for(scene, motus__sweep_task, &context, j->slabs - j->even_slabs);
                continue;
            }
            for (i = 0; (phase == MOTUS__PAIRS_VELOCITY || j->shock) && i < j->near_walls; ++i)
                motus__wall_contacts(j, j->near_wall[i], phase);
            if (dims == 3) {
                motus__sweep_listed_3(j, phase, 0, j->pair_count);
            } else {
                motus__sweep_listed_2(j, phase, 0, j->pair_count);
            }
            for (i = j->listed; j->grid && i < j->count; ++i)
                (void)motus__pairs_of(j, j->order[i], phase, MOTUS__REACH, NULL, NULL, 0);
            for (i = 0; phase == MOTUS__PAIRS_POSITION && !j->shock && i < j->near_walls; ++i)
                motus__wall_contacts(j, j->near_wall[i], phase);
        }
    {
        motus__particles_context context;
        context.job = j, context.finish = 1;
        motus__for(scene, motus__particles_task, &context, j->tasks);
        for (t = 0; t < j->tasks; ++t)
            if (j->failed[t]) return MOTUS_ERROR_NOT_FINITE;
    }
    return MOTUS_OK;
}

/* The method over tasks of particles (each particle's result is its own: any split gives the same bits). */
typedef struct motus__kernel_context {
    const motus__job *job;
    motus__kernel_function kernel;
    int count, task_size;
    unsigned char failed[MOTUS__TASKS];
} motus__kernel_context;
static void motus__kernel_task(void *context, int first, int count) {
    motus__kernel_context *c = (motus__kernel_context *)context;
    int t;
    for (t = first; t < first + count; ++t) {
        const int from = t * c->task_size, to = c->count - from < c->task_size ? c->count : from + c->task_size;
        c->failed[t] = (unsigned char)(c->kernel(c->job, from, to) != 0);
    }
}

/* The substeps one at a time, for a scene with springs, a callback or contacts: for each, where coupled, a
   recording pass per stage (the stage state into scratch, then the callback and the springs add that
   stage's forces); the pass that stores; then, with contacts, the contact pass. */
static motus_result motus__step_substeps(const motus_scene *scene, const motus_state *state, int dims, motus_real dt,
                                         motus_real *memory, const motus__layout *layout) {
    const int count = state->count, coupled = motus__coupled(scene), contacts = scene->contacts.enabled != 0;
    const int evaluations = motus_method_evaluations(scene->method);
    motus__kernel_function kernel;
    motus__job job;
    int d, stage, substep, substeps;
    motus__job_init(&job, scene, state, dims, dt);
    if (contacts) job.terms &= ~(unsigned)MOTUS__T_BOUNDS; /* the walls are contacts */
    kernel = motus__kernel_for(scene->method, dims, coupled ? 0 : job.terms,
                               coupled || job.stride != 1 || count < MOTUS__LANES);
    for (d = 0; d < dims && coupled; ++d) {
        job.stage_x[d] = memory + (size_t)d * layout->stage_length;
        job.stage_v[d] = memory + (size_t)(dims + d) * layout->stage_length;
        for (stage = 0; stage < evaluations; ++stage)
            job.stage_force[stage][d] = memory + (size_t)((2 + stage) * dims + d) * layout->stage_length;
    }
    substeps = job.substeps;
    job.substeps = 1;
    for (substep = 0; substep < substeps; ++substep) {
        const motus_real h = job.substep_dt;
        for (stage = 0; stage < evaluations && coupled; ++stage) {
            job.record_stage = stage;
            (void)kernel(&job, 0, count);
            motus__stage_forces(&job, scene, dims, count, (int)layout->stage_length, stage,
                                motus__stage_time(scene->method, stage) * h);
        }
        job.record_stage = -1;
        job.apply_damping = substep == substeps - 1 && (job.terms & MOTUS__T_DAMPING);
        if (coupled || !scene->parallel_for) {
            if (kernel(&job, 0, count)) return MOTUS_ERROR_NOT_FINITE;
        } else {
            motus__kernel_context context;
            int t, tasks, failed = 0;
            context.job = &job, context.kernel = kernel, context.count = count;
            context.task_size = motus__task_size(count, &tasks);
            motus__for(scene, motus__kernel_task, &context, tasks);
            for (t = 0; t < tasks; ++t) failed |= context.failed[t];
            if (failed) return MOTUS_ERROR_NOT_FINITE;
        }
        if (contacts) {
            const motus_result result = motus__contacts_pass(scene, state, dims, h, memory, layout);
            if (result != MOTUS_OK) return result;
        }
    }
    return MOTUS_OK;
}

/* The radii, before anything is written (a contact pass reads them at every substep). A bad one hands over to
   the full check, so that the error named is the first in particle order, as motus_state_check names it (an
   earlier particle's bad mass before a later one's bad radius). */
static motus_result motus__radii_check(const motus_scene *scene, const motus_state *state) {
    const ptrdiff_t stride = motus__radius_stride(state);
    int i;
    for (i = 0; i < state->count && state->radius; ++i)
        if (!motus__radius_valid(state->radius[(ptrdiff_t)i * stride]))
            return motus_state_check(scene, state, 0, state->count, NULL);
    return MOTUS_OK;
}

MOTUS_API motus_result motus_step(const motus_scene *scene, const motus_state *state, motus_real dt, void *scratch,
                                  size_t scratch_bytes) {
    motus__job job;
    motus__layout layout;
    motus_result result;
    motus_real *memory = (motus_real *)scratch;
    int dims = 2, count;
    result = motus__step_checks(scene, state, dt, &dims, 1);
    if (result != MOTUS_OK) return result;
    count = state->count;
    if (!motus__coupled(scene) && !scene->contacts.enabled) {
        if (count == 0) return MOTUS_OK;
        if (dt == 0) return motus_state_check(scene, state, 0, count, NULL); /* nothing moves; bad data is reported */
        motus__job_init(&job, scene, state, dims, dt);
        return motus__run(&job, scene, state, dims, 0, count);
    }
    /* Coupled or colliding: substep by substep over caller memory (see COUPLING in >>methods, >>contacts). */
    if (!motus__layout_of(scene, state, &layout) || scratch_bytes < layout.total || (!scratch && count > 0) ||
        (uintptr_t)scratch % offsetof(motus__align_probe, r) != 0)
        return MOTUS_ERROR_SCRATCH_TOO_SMALL;
    if (count == 0) return MOTUS_OK;
    if (scene->contacts.enabled) {
        result = motus__radii_check(scene, state);
        if (result != MOTUS_OK) return result;
    }
    if (dt == 0) return motus_state_check(scene, state, 0, count, NULL);
#ifdef MOTUS_CHECKED
    {
        /* Checked: the data first, then every substep on a copy in scratch, written back only if it all
           came out finite, so that an overflow leaves the state as it was. */
        motus_state copy = *state;
        const ptrdiff_t stride = state->stride == 0 ? 1 : state->stride;
        motus_real *next = (motus_real *)(void *)((char *)scratch + layout.coupled);
        int i, d;
        result = motus_state_check(scene, state, 0, count, NULL);
        if (result != MOTUS_OK) return result;
        copy.stride = copy.radius_stride = 1;
        for (d = 0; d < dims; ++d) {
            copy.position[d] = next, next += count;
            copy.velocity[d] = next, next += count;
            copy.force[d] = state->force[d] ? next : NULL, next += count;
            for (i = 0; i < count; ++i) {
                copy.position[d][i] = state->position[d][(ptrdiff_t)i * stride];
                copy.velocity[d][i] = state->velocity[d][(ptrdiff_t)i * stride];
                if (state->force[d]) next[i - count] = state->force[d][(ptrdiff_t)i * stride];
            }
        }
        if (state->inverse_mass) {
            for (i = 0; i < count; ++i) next[i] = state->inverse_mass[(ptrdiff_t)i * stride];
            copy.inverse_mass = next;
        }
        next += count;
        if (state->radius && scene->contacts.enabled) {
            const ptrdiff_t radius_stride = motus__radius_stride(state);
            for (i = 0; i < count; ++i) next[i] = state->radius[(ptrdiff_t)i * radius_stride];
            copy.radius = next;
        }
        result = motus__step_substeps(scene, &copy, dims, dt, memory, &layout);
        if (result != MOTUS_OK) return MOTUS_ERROR_OVERFLOW; /* the data was checked: only an overflow is left */
        for (d = 0; d < dims; ++d)
            for (i = 0; i < count; ++i) {
                state->position[d][(ptrdiff_t)i * stride] = copy.position[d][i];
                state->velocity[d][(ptrdiff_t)i * stride] = copy.velocity[d][i];
            }
        return MOTUS_OK;
    }
#else
    return motus__step_substeps(scene, state, dims, dt, memory, &layout);
#endif
}

/* The broadphase alone, on the positions as they are. */
MOTUS_API motus_result motus_find_contacts(const motus_scene *scene, const motus_state *state, void *scratch,
                                           size_t scratch_bytes, motus_contact_pair *pairs, int capacity, int *found) {
    motus__layout layout;
    motus__contact_job job;
    motus_result result;
    size_t total = 0;
    int dims = 2, i;
    if (!found || (capacity > 0 && !pairs)) return MOTUS_ERROR_NULL_POINTER;
    if (capacity < 0) return MOTUS_ERROR_INVALID_COUNT;
    result = motus__step_checks(scene, state, 0, &dims, 0); /* velocities are not read: they may be NULL */
    if (result != MOTUS_OK) return result;
    {
        motus_scene colliding = *scene; /* the layout of a scene with contacts on, whatever this one says */
        colliding.contacts.enabled = 1;
        if (!motus__layout_of(&colliding, state, &layout) || scratch_bytes < layout.total ||
            (!scratch && state->count > 0) || (uintptr_t)scratch % offsetof(motus__align_probe, r) != 0)
            return MOTUS_ERROR_SCRATCH_TOO_SMALL;
        result = motus__state_check(&colliding, state, 0, state->count, NULL, 0); /* the radii too */
        if (result != MOTUS_OK) return result;
        if (state->count == 0) { /* no particles, no pairs (and no scratch needed) */
            *found = 0;
            return MOTUS_OK;
        }
        motus__contact_job_init(&job, &colliding, state, dims, 0, scratch, &layout);
    }
    for (i = 0; job.grid && i < state->count; ++i) {
        const size_t room = total < (size_t)capacity ? (size_t)capacity - total : 0;
        const size_t from = total;
        size_t k;
        total += motus__pairs_of(&job, job.order[i], MOTUS__PAIRS_RECORD, 1 + MOTUS__TOUCH,
                                 room > 0 ? pairs + total : NULL, NULL, room);
        if (total > (size_t)INT_MAX) return MOTUS_ERROR_INVALID_COUNT;
        for (k = from; k < total && k < (size_t)capacity; ++k)
            if (pairs[k].a > pairs[k].b) {
                const int swap = pairs[k].a;
                pairs[k].a = pairs[k].b, pairs[k].b = swap;
            }
    }
    *found = (int)total;
    return MOTUS_OK;
}

MOTUS_API motus_result motus_scene_max_stable_dt(const motus_scene *scene, const motus_state *state,
                                                 motus_real *max_dt, void *scratch, size_t scratch_bytes) {
    motus_real omega_squared = 0, spring_decay = 0, fastest = 0, half_decay, *sums = (motus_real *)scratch;
    motus_real fastest_half = 0; /* where some |v| passes the largest real (it is then the fastest): |v|/2 */
    motus_result result;
    ptrdiff_t stride;
    int dims = 2, i, d, k, count;
    if (!max_dt) return MOTUS_ERROR_NULL_POINTER;
    result = motus__step_checks(scene, state, 0, &dims, 1);
    if (result != MOTUS_OK) return result;
    count = state->count;
    stride = state->stride == 0 ? 1 : state->stride;
    if (scene->method == MOTUS_EXACT_LINEAR_DRAG) {
        *max_dt = (motus_real)HUGE_VAL;
        return MOTUS_OK;
    }
    if (scene->spring_count > 0 &&
        (scratch_bytes < 2 * (size_t)count * sizeof(motus_real) || !scratch ||
         (uintptr_t)scratch % offsetof(motus__align_probe, r) != 0))
        return MOTUS_ERROR_SCRATCH_TOO_SMALL;
    for (i = 0; i < count && state->inverse_mass; ++i) {
        const motus_real w = state->inverse_mass[(ptrdiff_t)i * stride];
        if (!motus_real_is_finite(w)) return MOTUS_ERROR_NOT_FINITE;
        if (w < 0) return MOTUS_ERROR_INVALID_MASS;
    }
    if (scene->quadratic_drag != 0)
        for (i = 0; i < count; ++i) {
            motus_real speed2 = 0, speed, largest = 0;
            for (d = 0; d < dims; ++d) {
                const motus_real v = state->velocity[d][(ptrdiff_t)i * stride];
                if (!motus_real_is_finite(v)) return MOTUS_ERROR_NOT_FINITE;
                speed2 += v * v;
                if ((v < 0 ? -v : v) > largest) largest = v < 0 ? -v : v;
            }
            speed = MOTUS_SQRT(speed2);
            if (!motus_real_is_finite(speed)) { /* |v|^2 overflowed: |v| in units of its largest component */
                speed2 = 0;
                for (d = 0; d < dims; ++d) {
                    const motus_real u = state->velocity[d][(ptrdiff_t)i * stride] / largest;
                    speed2 += u * u;
                }
                speed = largest * MOTUS_SQRT(speed2);
                if (!motus_real_is_finite(speed)) { /* |v| itself (up to sqrt(3) of the largest real): its half */
                    const motus_real half = largest * (MOTUS_R(0.5) * MOTUS_SQRT(speed2));
                    if (half > fastest_half) fastest_half = half;
                    continue;
                }
            }
            if (speed > fastest) fastest = speed;
        }
    /* The rates in units of 1/q, q a power of two: w^2*q^2 (each factor of k*(1/m) times q) and the half
       decay rate times q, so that a dt is answered wherever it is representable. q = 1 unless a product or
       a sum overflowed (then the same bits as unscaled); each retry takes q a quarter of the exponent range
       lower (2^-32 in float), which products of reals up to the largest and sums over a particle's springs
       cannot outrun in three retries: a tether of 1e30 N/m on 1e-10 kg in float has w^2 = 1e40, past the
       largest real, and its dt is 2e-20 s. The dt is then dt(scaled rates)*q. */
    {
#ifdef MOTUS_DOUBLE
        const motus_real scale_step = 8.6361685550944446e-78; /* 2^-256 */
#else
        const motus_real scale_step = 2.32830644e-10f; /* 2^-32 */
#endif
        const motus_real uniform = scene->mass > 0 ? MOTUS_R(1.0) / scene->mass : MOTUS_R(1.0);
        const int springs = scene->spring_count > 0;
        motus_real q = 1, dt;
#define MOTUS__W(p) (state->inverse_mass ? state->inverse_mass[(ptrdiff_t)(p) * stride] : uniform)
        for (;;) {
            omega_squared = 0, spring_decay = 0;
            if (springs || scene->tether_stiffness != 0) {
                for (i = 0; springs && i < 2 * count; ++i) sums[i] = 0;
                for (k = 0; k < scene->spring_count; ++k) {
                    const motus_spring *s = &scene->springs[k];
                    const motus_real both = MOTUS__W(s->a) + (s->b < 0 ? 0 : MOTUS__W(s->b));
                    const motus_real stiffness = (s->stiffness * q) * (both * q), damping = (s->damping * q) * both;
                    sums[2 * s->a] += stiffness;
                    sums[2 * s->a + 1] += damping;
                    if (s->b >= 0) {
                        sums[2 * s->b] += stiffness;
                        sums[2 * s->b + 1] += damping;
                    }
                }
                for (i = 0; i < count; ++i) {
                    /* the tether is a spring to a fixed end: k*(1/m) on the diagonal only */
                    const motus_real row = (springs ? sums[2 * i] : 0) + (scene->tether_stiffness * q) * (MOTUS__W(i) * q);
                    if (MOTUS__W(i) == 0) continue; /* nothing moves it: its column bounds no motion */
                    if (row > omega_squared) omega_squared = row;
                    if (springs && sums[2 * i + 1] > spring_decay) spring_decay = sums[2 * i + 1];
                }
            }
            /* Half the decay rate: quadratic drag's rate at the fastest speed is 2*c*|v|, so its half is c*|v|
               (the halves are exact: the same bits as halving the sum, without its overflow). */
            half_decay = MOTUS_R(0.5) * (scene->linear_drag * q) +
                         (fastest_half > 0 ? ((scene->quadratic_drag * q) * 2) * fastest_half
                                           : (scene->quadratic_drag * q) * fastest) +
                         MOTUS_R(0.5) * spring_decay;
            if (motus_real_is_finite(omega_squared) && motus_real_is_finite(half_decay)) break;
            q = q * scale_step;
            if (q == 0) return MOTUS_ERROR_OVERFLOW; /* not reached by finite inputs (see above) */
        }
#undef MOTUS__W
        dt = motus__stable_dt(scene->method, omega_squared, half_decay);
        /* a dt below the smallest subnormal real: not representable, refused (not answered with 0, which
           means that no step is stable) */
        if (dt > 0 && dt * q == 0) return MOTUS_ERROR_OVERFLOW;
        *max_dt = dt * q;
    }
    return MOTUS_OK;
}

#ifdef __cplusplus
} /* extern "C" */
#endif

#if defined(MOTUS__ENGINE_PRAGMA_CLANG)
#pragma float_control(pop)
#elif defined(MOTUS__ENGINE_PRAGMA_GCC)
#pragma GCC pop_options
#endif
MOTUS__QUIET_END
#endif /* MOTUS_IMPLEMENTATION */

/*
   MIT License

   Copyright (c) 2026 the motus developers

   Permission is hereby granted, free of charge, to any person obtaining a copy
   of this software and associated documentation files (the "Software"), to deal
   in the Software without restriction, including without limitation the rights
   to use, copy, modify, merge, publish, distribute, sublicense, and/or sell
   copies of the Software, and to permit persons to whom the Software is
   furnished to do so, subject to the following conditions:

   The above copyright notice and this permission notice shall be included in all
   copies or substantial portions of the Software.

   THE SOFTWARE IS PROVIDED "AS IS", WITHOUT WARRANTY OF ANY KIND, EXPRESS OR
   IMPLIED, INCLUDING BUT NOT LIMITED TO THE WARRANTIES OF MERCHANTABILITY,
   FITNESS FOR A PARTICULAR PURPOSE AND NONINFRINGEMENT. IN NO EVENT SHALL THE
   AUTHORS OR COPYRIGHT HOLDERS BE LIABLE FOR ANY CLAIM, DAMAGES OR OTHER
   LIABILITY, WHETHER IN AN ACTION OF CONTRACT, TORT OR OTHERWISE, ARISING FROM,
   OUT OF OR IN CONNECTION WITH THE SOFTWARE OR THE USE OR OTHER DEALINGS IN THE
   SOFTWARE.
*/
