/* motus.h - v0.1.0 - MIT licensed (see end of file) - particle integration for games, one C99 header.

   USAGE
   =====
   Copy this file into your project and include it. There is nothing to compile separately, nothing is
   allocated and there is no global state: every function is `static inline` and works on the data you pass.

       #include "motus.h"

       motus_particle ball;
       if (motus_particle_init(&ball, motus_v2(400, 300), 2) != MOTUS_OK) { ...bad mass... }

       // every frame:
       motus_particle_clear_forces(&ball);
       motus_particle_add_force(&ball, motus_v2(100, 0));    // push right
       motus_result r = motus_particle_step(&ball, dt);      // v += F/m*dt; x += v*dt
       motus_particle_damp_per_second(&ball, 0.55f, dt);     // keep 55% of the speed each second
       if (r != MOTUS_OK) fprintf(stderr, "motus: %s\n", motus_result_string(r));

   Three ways to step, from the textbook to the fastest:
   - motus_particle_step: one particle, semi-implicit Euler, the forces you added (the lines above);
   - motus_stepper_step: an array of motus_particle under a force model (gravity, drags, springs, an
     attractor, a callback) with any of nine integrators (see "Integrators");
   - motus_batch_step: arrays of components (x[], y[], vx[], ...) stepped by a kernel compiled for exactly
     the scene's features, vectorised, over a range a thread can own (see "Batch kernels").

   CONVENTIONS
   ===========
   - SI units: metres, seconds, kilograms, newtons. Nothing here cares what one unit is, so a game may use
     pixels for metres (the reference program does: one unit = one pixel).
   - The y axis points wherever you choose; motus never assumes "down". raylib's screen y grows downwards.
   - `motus_real` is float unless you define MOTUS_DOUBLE before including this header.
   - `motus_vec2` is two `motus_real`s, x then y, with no padding: in the float build it has the same layout as
     raylib's `Vector2` (checked at compile time by the tests), so an array of either converts to the other
     with one memcpy. Reading one through a pointer to the other would break C's aliasing rules.
   - A particle stores its inverse mass. Inverse mass 0 is an immovable particle: forces never move it.
   - Forces accumulate until you clear them. motus_particle_step does not clear them, so a force that is
     constant over many steps (gravity) may be added once; the reference program clears every frame.
   - Functions that can be handed bad input return a motus_result; on any result other than MOTUS_OK
     nothing was written (the batch kernels' release builds excepted, for bad particle data). A count of 0
     is valid and does nothing. motus_result_string turns a result into a sentence; what each build checks
     is under "Validation and messages", with motus_particles_check to find the first bad particle.
   - No compound literals in the header, so it also compiles as C++.

   CONFIGURATION
   =============
   Define these before including motus.h (all optional):
   - MOTUS_DOUBLE          (undefined)      motus_real is double instead of float.
   - MOTUS_API             (static inline)  storage class of every function. Keep internal linkage
                                            (`static` or `static inline`): the functions are defined here.
   - MOTUS_SQRT, MOTUS_EXP, MOTUS_EXPM1, MOTUS_POW
                           (<math.h>: sqrtf/expf/expm1f/powf, or the double ones with MOTUS_DOUBLE)
                           Define all four or none: they go together, as stb does with its hooks.
   - MOTUS_SIMD_BYTES      (64 with AVX-512, 32 with AVX, else 16)  vector width of the batch kernels.
                                            Wider than the target's registers works, but gcc and clang then
                                            warn -Wpsabi (harmless: the functions are inline).
   - MOTUS_NO_SIMD         (undefined)      batch kernels one particle at a time (the results are the same).
   - MOTUS_CHECKED         (undefined)      motus_batch_step checks every particle of its range, and
                                            motus_batch_add_spring_forces every spring, before writing
                                            anything (see "Validation and messages": release builds don't).
   - MOTUS_REST_SPEED      (1e-30f; 1e-300 with MOTUS_DOUBLE)  m/s: damping sets a velocity component
                                            whose magnitude falls below this to zero (see SUBNORMALS). 0
                                            turns the flush off.
   - MOTUS_CLOCK_DEFAULT_MAX_STEPS (8)      steps a motus_clock runs per frame when given 0.
   - MOTUS_ALLOW_FP_CONTRACT (undefined)    leave floating-point contraction to the compiler's flags. By
                                            default motus turns it off for its own code (see DETERMINISM):
                                            Clang: `#pragma STDC FP_CONTRACT OFF` between a float_control
                                            push and pop, free, your code keeps its own setting; GCC (which
                                            ignores the STDC pragma) in GNU modes on a target with FMA:
                                            `#pragma GCC optimize("fp-contract=off")` between push_options
                                            and pop_options. GCC then does not inline motus's functions into
                                            code built with other options, which costs a call per function;
                                            build with -ffp-contract=off to keep both the inlining and the
                                            determinism, or define this to keep the inlining and the FMAs.
   - MOTUS_ALLOW_FAST_MATH (undefined)      silence the message printed when motus is built with -ffast-math
                                            (or -ffinite-math-only): see DETERMINISM for what it breaks.

   DAMPING: PER STEP OR PER SECOND
   ===============================
   The reference program multiplies the velocity by 0.99 every frame. That is `motus_particle_damp_per_step`:
   simple, but the motion depends on the frame rate. At 60 frames a second 0.99 keeps 0.99^60 = 55% of the
   speed after one second, at 144 only 0.99^144 = 23%, at 30 it keeps 74%.
   `motus_particle_damp_per_second(p, retained_per_second, dt)` multiplies by retained_per_second^dt instead,
   so a second of motion keeps the same fraction at any rate. To carry a per-step factor over from a game that
   ran at a fixed rate, use motus_damping_per_second_from_per_step(0.99, 60) = 0.547.
   `motus_particle_step_linear_drag` goes one step further: it solves m*dv/dt = F - m*k*v exactly over the
   step (F held constant), so the position too is the same at 30, 60 or 144 steps a second, up to rounding.

   SUBNORMALS
   ===
   Damping multiplies a velocity by a factor < 1 every step, so a particle left alone slows down
   geometrically: with 0.99 a step, 1 m/s goes below FLT_MIN (1.2e-38) after some 8,700 steps and then
   never leaves the subnormal numbers: below 50 times the smallest one, 0.99*v rounds back to v.
   Arithmetic on subnormals takes a slow path on many x86 cores (a microcode assist: tens to hundreds of
   cycles per operation), and v*dt is subnormal too. motus_particle_damp_per_step / _per_second and the batch kernels' damping
   therefore set a velocity component whose magnitude is below MOTUS_REST_SPEED to zero (keeping its
   sign): 1e-30 m/s in float, a round number above FLT_MIN/1e-7 = 1.2e-31 so that v*dt stays a normal
   float for any dt >= 1e-7 s, and far below anything a game can see (1e-300 in double). bench/subnormal
   measures the cost with and without the flush.

   DETERMINISM
   ===========
   The same scene, stepped the same way, ends in the same state bit for bit whatever builds it: GCC or
   Clang, -O0 to -O3, with -march=native or without, as C or C++, with any MOTUS_SIMD_BYTES or
   MOTUS_NO_SIMD; and the three ways to step agree with each other on a scene they can all run (the batch
   kernels with motus_stepper_step followed by motus_particle_damp_per_step and motus_particle_bounce, and
   motus_particle_step where the forces are all accumulated ones). tests/determinism.c checks this with
   golden hashes of a 1000-particle scene, per method and per precision: 10^5 steps in the test build,
   10^4 (500 at -O0) in each build of the gcc/clang x -O0/-O2/-O3/-O3 -march=native x C/C++ matrix.
   This holds given:
   - IEEE-754 arithmetic on motus_real with no excess precision (FLT_EVAL_METHOD 0: SSE2 on x86, any
     arm64; not the x87 unit of 32-bit x86 builds without -msse2 -mfpmath=sse);
   - no contraction of a*b + c into one fused multiply-add, which rounds once instead of twice. GCC in
     its GNU modes (its default: no -std=c99/c11/c++NN) and Clang contract by default when the target has
     FMA (-march=native on any recent x86; always on arm64). motus turns contraction off for its own code
     (see MOTUS_ALLOW_FP_CONTRACT), except where a flag overrides the pragmas: -ffp-contract=fast given
     to Clang, or to GCC in an ISO mode (-std=c99 ... -ffp-contract=fast). -ffp-contract=off is the
     reliable, zero-cost way: it is what the tests build with. Other compilers: check their default
     (MSVC contracts under /fp:fast and, before Visual Studio 2022, sometimes under /fp:precise);
   - no -ffast-math, nor any of its parts (-ffinite-math-only, -fassociative-math, -freciprocal-math):
     they let the compiler reorder sums, replace divisions, and assume that NaN never happens, which
     removes motus's checks of a bad argument (`!(mass > 0)`), and linking with it flushes subnormals to
     zero for the whole program. motus prints a message when __FAST_MATH__ or __FINITE_MATH_ONLY__ is
     set (MOTUS_ALLOW_FAST_MATH silences it);
   - the same libm, for the few functions that call it. sqrt is exact (correctly rounded) everywhere, so
     springs with a rest length, quadratic drag and the attractor are deterministic. exp, expm1 and pow
     are not correctly rounded in every libm, so results that go through them may differ between glibc,
     musl, macOS and MSVC (and from a compiler that folds a call with constant arguments at build time):
     motus_particle_damp_per_second and motus_damping_per_second_from_per_step (pow), the batch kernels'
     MOTUS_HAS_DAMPING_PER_SECOND (pow, once per call), motus_particle_step_linear_drag and the stepper's
     MOTUS_EXACT_LINEAR_DRAG (exp; expm1 too when drag*dt >= 0.5). Every other method and function uses
     only + - * / and sqrt;
   - subnormals not flushed to zero (no -ffast-math, no FTZ/DAZ bits set by other code);
   - your own code (force callbacks, the forces you add) deterministic too: motus's pragmas cover only
     the header.
*/
#ifndef MOTUS_H
#define MOTUS_H

#define MOTUS_VERSION_MAJOR 0
#define MOTUS_VERSION_MINOR 1
#define MOTUS_VERSION_PATCH 0
#define MOTUS_VERSION_STRING "0.1.0"
/* One number that grows with every release: 10000*major + 100*minor + patch. */
#define MOTUS_VERSION (MOTUS_VERSION_MAJOR * 10000 + MOTUS_VERSION_MINOR * 100 + MOTUS_VERSION_PATCH)

#include <math.h>
#include <limits.h> /* INT_MAX */
#include <stddef.h> /* size_t, NULL */
#include <stdint.h> /* fixed-width integers for the bit-level finite check; no library code */
#include <string.h> /* memcpy (the bit-level check in C++), memset (motus_stepper_init) */

/* =================================================================================================
   Configuration
   ================================================================================================= */
/* Floating-point contraction off for the code of this header, restored at its end (see DETERMINISM and
   MOTUS_ALLOW_FP_CONTRACT). A fused a*b + c rounds once where the source rounds twice, so a build that
   contracts ends a long run in another state. Clang marks each operation, so what is inlined into your
   code keeps its setting (float_control push/pop since Clang 11). GCC ignores the STDC pragma; its
   optimize pragma works per function, and it contracts only in GNU modes (-ffp-contract=fast is their
   default; ISO modes mean off) and only with an FMA instruction (__FP_FAST_FMA), so it is used only then. */
#ifndef MOTUS_ALLOW_FP_CONTRACT
#if defined(__clang__) && ((defined(__apple_build_version__) && __clang_major__ >= 13) ||                  \
                           (!defined(__apple_build_version__) && __clang_major__ >= 11))
#define MOTUS__FP_CONTRACT_PRAGMA_CLANG
#pragma float_control(push)
#pragma STDC FP_CONTRACT OFF
#elif defined(__GNUC__) && !defined(__clang__) && !defined(__INTEL_COMPILER) && !defined(__STRICT_ANSI__) &&  \
    (defined(__FP_FAST_FMA) || defined(__FP_FAST_FMAF))
#define MOTUS__FP_CONTRACT_PRAGMA_GCC
#pragma GCC push_options
#pragma GCC optimize("fp-contract=off")
#endif
#endif

/* -ffast-math lets the compiler assume that no value is NaN or infinite (which removes the checks that
   reject a NaN argument), reorder sums and replace divisions (which changes results between builds), and
   flushes subnormals to zero for the whole program. A message, not #warning: #warning is an extension
   before C23, and -Wpedantic -Werror turns it into an error. */
#if (defined(__FAST_MATH__) || (defined(__FINITE_MATH_ONLY__) && __FINITE_MATH_ONLY__)) &&                   \
    !defined(MOTUS_ALLOW_FAST_MATH)
#pragma message("motus.h: built with -ffast-math (or -ffinite-math-only): its NaN checks may be optimised away and results differ between builds; see DETERMINISM in motus.h, or define MOTUS_ALLOW_FAST_MATH")
#endif

#ifndef MOTUS_API
#define MOTUS_API static inline
#endif

/* For the few per-particle helpers that must be inlined into their loops so that the compiler sees the
   constant flags they are called with and drops the work of force terms a scene does not use. */
#if defined(__GNUC__) || defined(__clang__)
#define MOTUS__INLINE static inline __attribute__((always_inline))
#else
#define MOTUS__INLINE static inline
#endif

#if defined(MOTUS_SQRT) || defined(MOTUS_EXP) || defined(MOTUS_EXPM1) || defined(MOTUS_POW)
#define MOTUS_SQRT_CUSTOM /* then the batch kernels call it too, lane by lane */
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

#ifdef __cplusplus
extern "C" {
#endif

/* =================================================================================================
   Types
   ================================================================================================= */
typedef struct motus_vec2 {
    motus_real x, y;
} motus_vec2;

typedef struct motus_particle {
    motus_vec2 position;
    motus_vec2 velocity;
    motus_vec2 force;        /* sum of the forces added since the last clear */
    motus_real inverse_mass; /* 1/mass; 0 = immovable */
} motus_particle;

typedef enum motus_result {
    MOTUS_OK = 0,
    MOTUS_ERROR_NULL_POINTER,      /* a pointer argument was NULL */
    MOTUS_ERROR_NOT_FINITE,        /* an input (argument or particle field) was NaN or infinite */
    MOTUS_ERROR_INVALID_MASS,      /* mass <= 0, or so small that 1/mass overflows; or inverse mass < 0 */
    MOTUS_ERROR_INVALID_TIME_STEP, /* dt <= 0, NaN or infinite */
    MOTUS_ERROR_INVALID_DAMPING,   /* a damping factor outside [0, 1], or a drag rate < 0 */
    MOTUS_ERROR_OVERFLOW,          /* finite inputs, but the result would not be finite */
    MOTUS_ERROR_INVALID_COUNT,     /* a particle count < 0, or more than the stepper was made for */
    MOTUS_ERROR_INVALID_FORCES,    /* a force model field out of range (negative drag, spring index, ...) */
    MOTUS_ERROR_SCRATCH_TOO_SMALL, /* the memory given to a stepper is smaller than it needs */
    MOTUS_ERROR_UNSUPPORTED,       /* the method cannot handle this force model (see motus_method) */
    MOTUS_ERROR_INVALID_SCENE,     /* a scene that contradicts itself or its batch (see motus_scene_check) */
    MOTUS_ERROR_TOO_STIFF,         /* more substeps needed than allowed, or no dt is stable for the method */
    MOTUS_ERROR_INVALID_ARGUMENT,  /* an argument out of its documented range (safety factor, substep cap) */
    MOTUS_ERROR_INVALID_DESC,      /* a desc with unknown flag bits, or scratch not aligned for motus_real */
    MOTUS_ERROR_INVALID_FRAME_TIME, /* a frame time < 0, NaN or infinite (motus_clock_advance) */
    MOTUS_RESULT_COUNT
} motus_result;

/* =================================================================================================
   Vector helpers (the few the step needs; raymath has the rest and shares the layout)
   ================================================================================================= */
MOTUS_API motus_vec2 motus_v2(motus_real x, motus_real y) {
    motus_vec2 v;
    v.x = x;
    v.y = y;
    return v;
}
MOTUS_API motus_vec2 motus_vec2_add(motus_vec2 a, motus_vec2 b) { return motus_v2(a.x + b.x, a.y + b.y); }
MOTUS_API motus_vec2 motus_vec2_sub(motus_vec2 a, motus_vec2 b) { return motus_v2(a.x - b.x, a.y - b.y); }
MOTUS_API motus_vec2 motus_vec2_scale(motus_vec2 v, motus_real s) { return motus_v2(v.x * s, v.y * s); }
MOTUS_API motus_real motus_vec2_dot(motus_vec2 a, motus_vec2 b) { return a.x * b.x + a.y * b.y; }
MOTUS_API motus_real motus_vec2_length(motus_vec2 v) { return MOTUS_SQRT(motus_vec2_dot(v, v)); }

/* True unless x is NaN or +-Inf. Reads the exponent bits instead of calling isfinite() so that the check
   survives -ffast-math, under which compilers assume NaN never happens and fold isfinite() to 1. C reads the
   bits through a union (defined behaviour since C99 TC3); C++ forbids that and gets memcpy, which compilers
   turn into a register move. */
MOTUS__INLINE motus__bits motus__real_bits(motus_real x) {
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
MOTUS_API int motus_real_is_finite(motus_real x) {
    return (motus__real_bits(x) & MOTUS__EXPONENT_MASK) != MOTUS__EXPONENT_MASK;
}
/* Bit tests that a loop can OR up without a compare per value:
   - the top bit of motus__not_finite_bits(x) is set iff x is NaN or +-Inf: the magnitude bits plus one unit
     of exponent carry into the sign position exactly when the exponent is all ones;
   - motus__negative_bits(x) is 1 iff x < 0 or x is a NaN with the sign bit (-0 is not negative). */
#define MOTUS__SIGN_BIT (~(MOTUS__EXPONENT_MASK | (MOTUS__EXPONENT_MASK >> 1)) & (MOTUS__EXPONENT_MASK << 1))
MOTUS__INLINE motus__bits motus__not_finite_bits(motus_real x) {
    return (motus__real_bits(x) & (motus__bits)~MOTUS__SIGN_BIT) + (MOTUS__EXPONENT_MASK & (motus__bits)~(MOTUS__EXPONENT_MASK << 1));
}
MOTUS__INLINE int motus__negative_bits(motus_real x) { return motus__real_bits(x) > MOTUS__SIGN_BIT; }
MOTUS_API int motus_vec2_is_finite(motus_vec2 v) { return motus_real_is_finite(v.x) && motus_real_is_finite(v.y); }

/* =================================================================================================
   Particle: create, forces, the textbook step, damping
   ================================================================================================= */

/* A particle at rest at `position` with no force. `mass` must be finite and > 0 (and large enough that
   1/mass is finite). For a particle that nothing moves, use motus_particle_init_immovable. */
MOTUS_API motus_result motus_particle_init(motus_particle *particle, motus_vec2 position, motus_real mass) {
    motus_real inverse_mass;
    if (!particle) return MOTUS_ERROR_NULL_POINTER;
    if (!motus_vec2_is_finite(position) || !motus_real_is_finite(mass)) return MOTUS_ERROR_NOT_FINITE;
    if (!(mass > 0)) return MOTUS_ERROR_INVALID_MASS;
    inverse_mass = MOTUS_R(1.0) / mass;
    if (!motus_real_is_finite(inverse_mass)) return MOTUS_ERROR_INVALID_MASS;
    particle->position = position;
    particle->velocity = motus_v2(0, 0);
    particle->force = motus_v2(0, 0);
    particle->inverse_mass = inverse_mass;
    return MOTUS_OK;
}

/* A particle with inverse mass 0: forces add up in `force` but never change its velocity or position. */
MOTUS_API motus_result motus_particle_init_immovable(motus_particle *particle, motus_vec2 position) {
    if (!particle) return MOTUS_ERROR_NULL_POINTER;
    if (!motus_vec2_is_finite(position)) return MOTUS_ERROR_NOT_FINITE;
    particle->position = position;
    particle->velocity = motus_v2(0, 0);
    particle->force = motus_v2(0, 0);
    particle->inverse_mass = 0;
    return MOTUS_OK;
}

/* The mass the particle was made with (rounded through 1/(1/m)); +Inf for an immovable particle, NaN for
   a NULL particle. */
MOTUS_API motus_real motus_particle_mass(const motus_particle *particle) {
    if (!particle) return (motus_real)NAN;
    if (particle->inverse_mass == 0) return (motus_real)HUGE_VAL;
    return MOTUS_R(1.0) / particle->inverse_mass;
}

/* MOTUS_OK if every field is finite and the inverse mass is >= 0. Use it on particles you filled by hand. */
MOTUS_API motus_result motus_particle_check(const motus_particle *particle) {
    if (!particle) return MOTUS_ERROR_NULL_POINTER;
    if (!motus_vec2_is_finite(particle->position) || !motus_vec2_is_finite(particle->velocity) ||
        !motus_vec2_is_finite(particle->force) || !motus_real_is_finite(particle->inverse_mass))
        return MOTUS_ERROR_NOT_FINITE;
    if (particle->inverse_mass < 0) return MOTUS_ERROR_INVALID_MASS;
    return MOTUS_OK;
}

/* Adds `force` to the accumulator. Rejects a non-finite force, and a sum that would overflow. */
MOTUS_API motus_result motus_particle_add_force(motus_particle *particle, motus_vec2 force) {
    motus_vec2 sum;
    if (!particle) return MOTUS_ERROR_NULL_POINTER;
    if (!motus_vec2_is_finite(force) || !motus_vec2_is_finite(particle->force)) return MOTUS_ERROR_NOT_FINITE;
    sum = motus_vec2_add(particle->force, force);
    if (!motus_vec2_is_finite(sum)) return MOTUS_ERROR_OVERFLOW;
    particle->force = sum;
    return MOTUS_OK;
}

MOTUS_API motus_result motus_particle_clear_forces(motus_particle *particle) {
    if (!particle) return MOTUS_ERROR_NULL_POINTER;
    particle->force = motus_v2(0, 0);
    return MOTUS_OK;
}

MOTUS_API int motus__is_positive_finite(motus_real x) { return motus_real_is_finite(x) && x > 0; }

/* Every stepper ends here: store the new state only if it is finite. Otherwise nothing is written, and the
   result says whether the particle came in broken (NaN/Inf in a field) or the step itself overflowed. */
MOTUS_API motus_result motus__commit_step(motus_particle *particle, motus_vec2 velocity, motus_vec2 position) {
    motus_result state;
    if (!motus_vec2_is_finite(velocity) || !motus_vec2_is_finite(position)) {
        state = motus_particle_check(particle);
        return state != MOTUS_OK ? state : MOTUS_ERROR_OVERFLOW;
    }
    particle->velocity = velocity;
    particle->position = position;
    return MOTUS_OK;
}

/* Semi-implicit (symplectic) Euler, the step the textbook teaches:
       v(t+dt) = v(t) + F * (1/m) * dt
       x(t+dt) = x(t) + v(t+dt) * dt        <- the *new* velocity: that is what makes it semi-implicit
   First order: under a constant acceleration a it lands at x0 + v0*t + a*t*(t + dt)/2 after time t, ahead
   of the exact x0 + v0*t + a*t^2/2 by a*dt*t/2. Unlike explicit Euler it keeps the energy of an orbit or a
   spring bounded; a spring of stiffness k stays stable while dt < 2*sqrt(m/k).
   Does not clear the force accumulator. */
MOTUS_API motus_result motus_particle_step(motus_particle *particle, motus_real dt) {
    motus_vec2 velocity, position;
    if (!particle) return MOTUS_ERROR_NULL_POINTER;
    if (!motus__is_positive_finite(dt)) return MOTUS_ERROR_INVALID_TIME_STEP;
    if (particle->inverse_mass < 0) return MOTUS_ERROR_INVALID_MASS;
    /* (F * 1/m) * dt, in this order, as the stepper's semi-implicit Euler does: the two agree bit for bit. */
    velocity = motus_vec2_add(particle->velocity, motus_vec2_scale(motus_vec2_scale(particle->force, particle->inverse_mass), dt));
    position = motus_vec2_add(particle->position, motus_vec2_scale(velocity, dt));
    return motus__commit_step(particle, velocity, position);
}

MOTUS_API int motus__damping_is_valid(motus_real factor) { return factor >= 0 && factor <= 1; } /* NaN fails */

/* A damped velocity: v*factor, each component below MOTUS_REST_SPEED in magnitude set to a zero of its sign
   so that it never lingers among the subnormals (see SUBNORMALS at the top). The batch kernels do the same
   lane by lane. */
MOTUS_API motus_vec2 motus__damp(motus_vec2 velocity, motus_real factor) {
    const motus_real rest = (motus_real)(MOTUS_REST_SPEED);
    motus_vec2 v = motus_vec2_scale(velocity, factor);
    if (v.x < rest && v.x > -rest) v.x = v.x * 0;
    if (v.y < rest && v.y > -rest) v.y = v.y * 0;
    return v;
}

/* v *= factor_per_step, as the reference program does with 0.99 each frame. Frame-rate dependent: see
   DAMPING at the top. factor_per_step must be in [0, 1]: 1 keeps all speed, 0 stops the particle; above 1,
   negative or NaN is MOTUS_ERROR_INVALID_DAMPING (damping that adds energy or flips the velocity is not
   damping). Speeds below MOTUS_REST_SPEED become 0 (see SUBNORMALS). */
MOTUS_API motus_result motus_particle_damp_per_step(motus_particle *particle, motus_real factor_per_step) {
    if (!particle) return MOTUS_ERROR_NULL_POINTER;
    if (!motus__damping_is_valid(factor_per_step)) return MOTUS_ERROR_INVALID_DAMPING;
    if (!motus_vec2_is_finite(particle->velocity)) return MOTUS_ERROR_NOT_FINITE;
    particle->velocity = motus__damp(particle->velocity, factor_per_step);
    return MOTUS_OK;
}

/* v *= retained_per_second^dt: after one second of steps the speed is retained_per_second times what it
   was, whatever dt was. retained_per_second must be in [0, 1] (0 stops the particle at any dt, 1 keeps all
   speed; the rest is MOTUS_ERROR_INVALID_DAMPING, as for damp_per_step). Equivalent to linear drag with
   rate k = -ln(retained_per_second) applied to the velocity alone. Speeds below MOTUS_REST_SPEED become 0. */
MOTUS_API motus_result motus_particle_damp_per_second(motus_particle *particle, motus_real retained_per_second,
                                                      motus_real dt) {
    if (!particle) return MOTUS_ERROR_NULL_POINTER;
    if (!motus__is_positive_finite(dt)) return MOTUS_ERROR_INVALID_TIME_STEP;
    if (!motus__damping_is_valid(retained_per_second)) return MOTUS_ERROR_INVALID_DAMPING;
    if (!motus_vec2_is_finite(particle->velocity)) return MOTUS_ERROR_NOT_FINITE;
    particle->velocity = motus__damp(particle->velocity, MOTUS_POW(retained_per_second, dt));
    return MOTUS_OK;
}

/* Keeps a particle inside the box [min, max]: past a wall its position is mirrored back inside and that
   velocity component is multiplied by -restitution (in [0, 1]; 1 keeps all speed); a particle that
   overshot by more than the box is then clamped to the wall. The batch kernels'
   bounds do the same, in the same order (after the step and the damping). */
MOTUS_API motus_result motus_particle_bounce(motus_particle *particle, motus_vec2 min, motus_vec2 max,
                                             motus_real restitution) {
    motus_real *position, *velocity;
    const motus_real lo[2] = {min.x, min.y}, hi[2] = {max.x, max.y};
    int d;
    if (!particle) return MOTUS_ERROR_NULL_POINTER;
    if (!motus_vec2_is_finite(min) || !motus_vec2_is_finite(max) || !motus_real_is_finite(restitution) ||
        !motus_vec2_is_finite(particle->position) || !motus_vec2_is_finite(particle->velocity))
        return MOTUS_ERROR_NOT_FINITE;
    if (!(min.x <= max.x) || !(min.y <= max.y)) return MOTUS_ERROR_INVALID_SCENE;
    if (!motus__damping_is_valid(restitution)) return MOTUS_ERROR_INVALID_DAMPING;
    for (d = 0; d < 2; ++d) {
        position = d == 0 ? &particle->position.x : &particle->position.y;
        velocity = d == 0 ? &particle->velocity.x : &particle->velocity.y;
        if (*position < lo[d]) {
            *position = lo[d] + (lo[d] - *position);
            *velocity = *velocity * -restitution;
        }
        if (*position > hi[d]) {
            *position = hi[d] - (*position - hi[d]);
            *velocity = *velocity * -restitution;
        }
        /* A particle that overshot by more than the box's width is still outside after one mirror. */
        if (*position < lo[d]) *position = lo[d];
        if (*position > hi[d]) *position = hi[d];
    }
    return MOTUS_OK;
}

/* The per-second fraction that a per-step factor amounts to at a fixed rate: factor^steps_per_second.
   motus_damping_per_second_from_per_step(0.99, 60) = 0.547. Returns NaN for arguments out of range. */
MOTUS_API motus_real motus_damping_per_second_from_per_step(motus_real factor_per_step, motus_real steps_per_second) {
    if (!motus__damping_is_valid(factor_per_step) || !motus__is_positive_finite(steps_per_second))
        return (motus_real)NAN;
    return MOTUS_POW(factor_per_step, steps_per_second);
}

/* The exact solution over one step of m*dv/dt = F - m*k*v, with F (the accumulator) held constant and
   drag rate k >= 0 (per second; k = -ln(retained_per_second)). With u = k*dt and a = F/m:
       v(dt) = v0*e^-u + a*dt*phi1(u)             phi1(u) = (1 - e^-u)/u
       x(dt) = x0 + v0*dt*phi1(u) + a*dt^2*phi2(u) phi2(u) = (u - 1 + e^-u)/u^2
   Exact at any dt, so the motion does not depend on the frame rate (only rounding does). k = 0 gives the
   exact constant-acceleration step x0 + v0*dt + a*dt^2/2. phi1 and phi2 lose digits to cancellation for
   small u, so there they come from their Taylor series. */
MOTUS_API void motus__drag_phi(motus_real u, motus_real *phi1, motus_real *phi2) {
    if (u < MOTUS_R(0.5)) {
        /* phi1 = sum (-u)^n/(n+1)!, phi2 = sum (-u)^n/(n+2)!; 15 terms leave a remainder below double
           rounding for u < 0.5. */
        motus_real term1 = 1, term2 = MOTUS_R(0.5), sum1 = 1, sum2 = MOTUS_R(0.5);
        int n;
        for (n = 1; n <= 14; ++n) {
            term1 *= -u / (motus_real)(n + 1);
            term2 *= -u / (motus_real)(n + 2);
            sum1 += term1;
            sum2 += term2;
        }
        *phi1 = sum1;
        *phi2 = sum2;
    } else {
        motus_real em1 = MOTUS_EXPM1(-u); /* e^-u - 1 without cancellation */
        *phi1 = -em1 / u;
        *phi2 = (u + em1) / (u * u);
    }
}

MOTUS_API motus_result motus_particle_step_linear_drag(motus_particle *particle, motus_real drag_per_second,
                                                       motus_real dt) {
    motus_real u, decay, phi1, phi2;
    motus_vec2 acceleration, velocity, position;
    if (!particle) return MOTUS_ERROR_NULL_POINTER;
    if (!motus__is_positive_finite(dt)) return MOTUS_ERROR_INVALID_TIME_STEP;
    if (!motus_real_is_finite(drag_per_second)) return MOTUS_ERROR_NOT_FINITE;
    if (!(drag_per_second >= 0)) return MOTUS_ERROR_INVALID_DAMPING;
    if (particle->inverse_mass < 0) return MOTUS_ERROR_INVALID_MASS;
    u = drag_per_second * dt;
    motus__drag_phi(u, &phi1, &phi2);
    decay = MOTUS_EXP(-u);
    acceleration = motus_vec2_scale(particle->force, particle->inverse_mass);
    velocity = motus_vec2_add(motus_vec2_scale(particle->velocity, decay), motus_vec2_scale(acceleration, dt * phi1));
    position = motus_vec2_add(particle->position,
                              motus_vec2_add(motus_vec2_scale(particle->velocity, dt * phi1),
                                             motus_vec2_scale(acceleration, dt * dt * phi2)));
    return motus__commit_step(particle, velocity, position);
}

/* Far from the origin a float position has few digits left for the motion: at x = 1e6 m one ulp is
   0.0625 m, so a step of 1 m/s * 1/60 s (0.017 m, under half an ulp) rounds away and the particle never
   moves. Two remedies: the double build (MOTUS_DOUBLE; ulp 1.2e-10 m at 1e6 m), or this step, which keeps
   what each position update rounded away in a carry the caller holds (one per particle, {0, 0} to start)
   and adds it back on the next step, so that small steps accumulate (Kahan's compensated summation, with
   Knuth's TwoSum for the exact rounding error of x + dx, any magnitudes):
       dx = v_new*dt + carry;  x' = fl(x + dx);  carry' = (x + dx) - x'   (exact: TwoSum)
   x + carry is then the position to about float precision squared; the stored position is within half
   an ulp of it. The velocity is motus_particle_step's, bit for bit; with carry {0, 0} the first position
   is too. Reset the carry to {0, 0} when the game moves the particle by hand. Needs IEEE arithmetic as
   written: -ffast-math may reassociate TwoSum into carry = 0. On any error neither the particle nor the
   carry is written. */
MOTUS_API motus_result motus_particle_step_compensated(motus_particle *particle, motus_vec2 *carry, motus_real dt) {
    motus_vec2 velocity, delta, sum, back, error;
    motus_result result;
    if (!particle || !carry) return MOTUS_ERROR_NULL_POINTER;
    if (!motus__is_positive_finite(dt)) return MOTUS_ERROR_INVALID_TIME_STEP;
    if (particle->inverse_mass < 0) return MOTUS_ERROR_INVALID_MASS;
    if (!motus_vec2_is_finite(*carry)) return MOTUS_ERROR_NOT_FINITE;
    velocity = motus_vec2_add(particle->velocity, motus_vec2_scale(motus_vec2_scale(particle->force, particle->inverse_mass), dt));
    delta = motus_vec2_add(motus_vec2_scale(velocity, dt), *carry);
    sum = motus_vec2_add(particle->position, delta);
    back = motus_vec2_sub(sum, particle->position);                             /* the part of delta that landed */
    error = motus_vec2_add(motus_vec2_sub(particle->position, motus_vec2_sub(sum, back)), /* TwoSum */
                           motus_vec2_sub(delta, back));
    /* A finite sum of finite terms has a finite TwoSum error: checking velocity and sum covers the carry. */
    result = motus__commit_step(particle, velocity, sum);
    if (result == MOTUS_OK) *carry = error;
    return result;
}

/* =================================================================================================
   Forces: one model for every method
   =================================================================================================
   A method that takes several stages evaluates the forces again at each stage, so every term is a function
   of the state (positions, velocities, time). Each term is off while its field is zero, so a zeroed
   motus_forces is "no forces". The particle's accumulated `force` is added at every stage as a force held
   constant over the step (a key held for the frame). Immovable particles (inverse mass 0) get no
   acceleration from any term. */

typedef struct motus_spring {
    int a;                  /* index of one end */
    int b;                  /* index of the other end, or -1: a spring from particle a to `anchor` */
    motus_vec2 anchor;      /* the fixed end when b == -1 */
    motus_real rest_length; /* m */
    motus_real stiffness;   /* k, N/m: Hooke's F = -k*(|d| - rest_length)*d/|d| */
    motus_real damping;     /* c, N*s/m, on the rate of stretch: F -= c*((v_a - v_b).d/|d|)*d/|d| */
} motus_spring;

/* Adds forces (newtons) to forces[0..count) for the state given; called at every stage of a step with the
   stage's positions, velocities and time. It must not keep the pointers. */
typedef void (*motus_force_callback)(void *user_data, int count, const motus_vec2 *positions,
                                     const motus_vec2 *velocities, motus_real time, motus_vec2 *forces);

typedef struct motus_forces {
    motus_vec2 gravity;            /* uniform acceleration, m/s^2 (e.g. {0, 9.81} with y down) */
    motus_real linear_drag;        /* k >= 0, 1/s: a -= k*v */
    motus_real quadratic_drag;     /* c >= 0, 1/m: a -= c*|v|*v */
    motus_real attractor_strength; /* mu = G*M >= 0, m^3/s^2: a -= mu*r/|r|^3, r from attractor_position */
    motus_vec2 attractor_position;
    const motus_spring *springs; /* spring_count springs, or NULL */
    int spring_count;
    motus_force_callback callback; /* or NULL */
    void *user_data;               /* handed to callback */
} motus_forces;

/* One spring's fields, for a loop over many: every step runs it, so it is bit operations with no branch or
   compare per field. Sets the sign bit of *not_finite if a field is NaN or Inf, and *out_of_range if an end
   is outside [0, count) (b may be -1) or both ends are one particle, or a parameter is negative (a NaN's
   sign does not matter: not finite is reported first). count >= 0. */
MOTUS__INLINE void motus__spring_check(const motus_spring *s, int count, motus__bits *not_finite, int *out_of_range) {
    *not_finite |= motus__not_finite_bits(s->anchor.x) | motus__not_finite_bits(s->anchor.y) |
                   motus__not_finite_bits(s->rest_length) | motus__not_finite_bits(s->stiffness) |
                   motus__not_finite_bits(s->damping);
    *out_of_range |= ((unsigned)s->a >= (unsigned)count) | ((unsigned)s->b + 1u > (unsigned)count) | (s->b == s->a) |
                     motus__negative_bits(s->rest_length) | motus__negative_bits(s->stiffness) |
                     motus__negative_bits(s->damping);
}

/* MOTUS_OK if the model can be used with `count` particles: finite fields, non-negative drags, stiffness,
   damping, rest lengths and attractor strength, spring ends in [0, count) (b may be -1). count < 0 is
   MOTUS_ERROR_INVALID_COUNT, as in motus_stepper_step. */
MOTUS_API motus_result motus_forces_check(const motus_forces *forces, int count) {
    motus__bits not_finite = 0;
    int i, out_of_range = 0;
    if (!forces) return MOTUS_ERROR_NULL_POINTER;
    if (count < 0) return MOTUS_ERROR_INVALID_COUNT;
    if (!motus_vec2_is_finite(forces->gravity) || !motus_real_is_finite(forces->linear_drag) ||
        !motus_real_is_finite(forces->quadratic_drag) || !motus_real_is_finite(forces->attractor_strength) ||
        !motus_vec2_is_finite(forces->attractor_position))
        return MOTUS_ERROR_NOT_FINITE;
    if (forces->linear_drag < 0 || forces->quadratic_drag < 0 || forces->attractor_strength < 0 ||
        forces->spring_count < 0 || (forces->spring_count > 0 && !forces->springs))
        return MOTUS_ERROR_INVALID_FORCES;
    for (i = 0; i < forces->spring_count; ++i) motus__spring_check(&forces->springs[i], count, &not_finite, &out_of_range);
    if (not_finite & MOTUS__SIGN_BIT) return MOTUS_ERROR_NOT_FINITE;
    return out_of_range ? MOTUS_ERROR_INVALID_FORCES : MOTUS_OK;
}

/* Nonzero if any component is NaN or infinite: bit operations only, so a loop can OR it up without a branch. */
MOTUS__INLINE int motus__vec2_not_finite(motus_vec2 v) {
    return (motus_real_is_finite(v.x) & motus_real_is_finite(v.y)) == 0;
}

/* Hooke with damping, without a square root unless the rest length needs one:
       F = -k*d + k*L*d/|d| - c*((v_a - v_b).d)/|d|^2 * d,     d = x_a - x_b
   which is -k*(|d| - L)*d/|d| - c*(stretch rate)*d/|d| written so that the common zero-length spring
   (and its damping) costs a multiply and a divide. */
MOTUS__INLINE motus_vec2 motus__spring_force(const motus_spring *s, motus_vec2 d, motus_vec2 relative_velocity) {
    motus_real d2 = motus_vec2_dot(d, d), along;
    motus_vec2 f = motus_vec2_scale(d, -s->stiffness);
    if (!(d2 > 0)) return f; /* both ends at one point: no direction to push along (or NaN: passed on) */
    along = -s->damping * motus_vec2_dot(relative_velocity, d) / d2;
    if (s->rest_length != 0) along += s->stiffness * s->rest_length / MOTUS_SQRT(d2);
    return motus_vec2_add(f, motus_vec2_scale(d, along));
}

/* One particle's acceleration from its summed force (newtons) and the per-particle terms. quadratic and
   attractor are constants where it is inlined, so unused terms cost nothing; gravity and linear drag are
   tested against zero, the same for every particle. An immovable particle gets 0 (or NaN if something it
   was given is NaN, so that the step reports it instead of hiding it). */
MOTUS__INLINE motus_vec2 motus__particle_acceleration(const motus_forces *f, motus_vec2 force, motus_real inverse_mass,
                                                      motus_vec2 x, motus_vec2 v, int quadratic, int attractor) {
    motus_vec2 a = motus_vec2_scale(force, inverse_mass);
    /* Terms that are off are skipped, not added as zero: adding +0 would turn a -0 into +0, and the
       batch kernels, which skip them, agree with this bit for bit. */
    if (f->gravity.x != 0 || f->gravity.y != 0) a = motus_vec2_add(a, f->gravity);
    if (f->linear_drag != 0) a = motus_vec2_sub(a, motus_vec2_scale(v, f->linear_drag));
    if (quadratic) a = motus_vec2_sub(a, motus_vec2_scale(v, f->quadratic_drag * motus_vec2_length(v)));
    if (attractor) {
        motus_vec2 r = motus_vec2_sub(x, f->attractor_position);
        motus_real r2 = motus_vec2_dot(r, r);
        if (r2 > 0) a = motus_vec2_sub(a, motus_vec2_scale(r, f->attractor_strength / (r2 * MOTUS_SQRT(r2))));
    }
    return motus_vec2_scale(a, (motus_real)(inverse_mass != 0));
}

/* Which of the costly per-particle terms are on: an index for the switches below. */
MOTUS_API int motus__terms(const motus_forces *f) {
    return (f->quadratic_drag != 0) | ((f->attractor_strength != 0) << 1);
}

/* Accelerations of every particle at the stage state (x, v, time). Springs and the callback couple
   particles, so their forces are summed first over the whole array; the rest is one pass. */
MOTUS_API void motus__accelerations(const motus_forces *forces, const motus_particle *particles, int count,
                                    const motus_vec2 *x, const motus_vec2 *v, motus_real time,
                                    motus_vec2 *acceleration) {
    int i;
    for (i = 0; i < count; ++i) acceleration[i] = particles[i].force;
    for (i = 0; i < forces->spring_count; ++i) {
        const motus_spring *s = &forces->springs[i];
        int anchored = s->b < 0;
        motus_vec2 d = motus_vec2_sub(x[s->a], anchored ? s->anchor : x[s->b]);
        motus_vec2 relative_velocity = anchored ? v[s->a] : motus_vec2_sub(v[s->a], v[s->b]);
        motus_vec2 f = motus__spring_force(s, d, relative_velocity);
        acceleration[s->a] = motus_vec2_add(acceleration[s->a], f);
        if (!anchored) acceleration[s->b] = motus_vec2_sub(acceleration[s->b], f);
    }
    if (forces->callback) forces->callback(forces->user_data, count, x, v, time, acceleration);
#define MOTUS__ACCELERATE(quadratic, attractor)                                                                  \
    for (i = 0; i < count; ++i)                                                                                \
        acceleration[i] = motus__particle_acceleration(forces, acceleration[i], particles[i].inverse_mass, x[i], \
                                                       v[i], quadratic, attractor);
    switch (motus__terms(forces)) {
    case 0: MOTUS__ACCELERATE(0, 0) break;
    case 1: MOTUS__ACCELERATE(1, 0) break;
    case 2: MOTUS__ACCELERATE(0, 1) break;
    default: MOTUS__ACCELERATE(1, 1) break;
    }
#undef MOTUS__ACCELERATE
}

/* =================================================================================================
   Integrators
   =================================================================================================
   All methods step a whole array of particles under one motus_forces through a motus_stepper, which owns
   nothing: the caller gives it memory (motus_stepper_scratch_size) once, and a step allocates nothing.
   A step is all or nothing: it computes the new state in that memory and writes it back only if every
   value is finite.

   h is the step, a(x, v, t) the acceleration the force model gives. "Evaluations" counts calls of the force
   model per step. Stability limits are for an undamped spring x'' = -w^2 x (w = sqrt(k/m)).

   method                 order  evals  symplectic  stable while   stores            velocity-dependent forces
   SEMI_IMPLICIT_EULER      1      1       yes      w*h < 2        -                 a(x_n, v_n)
     v += a(x, v)*h; x += v*h (new v). The textbook step and the default (method 0).
   EXPLICIT_EULER           1      1       no       never (*)      -                 a(x_n, v_n)
     x += v*h (old v); v += a*h. Energy grows every step: (*) the amplitude grows by sqrt(1 + (w*h)^2).
   POSITION_VERLET          2      1       yes      w*h < 2        previous x        (x_n - x_{n-1})/h: 1st order
     Stormer: x_{n+1} = 2x_n - x_{n-1} + a_n*h^2, in the time-corrected form for a step h after a step
     h_p: x_{n+1} = x_n + (x_n - x_{n-1})*h/h_p + a_n*h*(h + h_p)/2, so a varying dt stays second order.
     The stepper keeps each particle's last displacement x_n - x_{n-1} as it was added (re-forming it
     from two positions would add a rounding error per step that grows with the run). If the game
     moves particles or changes velocities by hand, call motus_stepper_reset. A particle without a
     last displacement (after a reset, or new at the end of the array) starts from its velocity:
     x_1 = x_0 + v_0*h + a_0*h^2/2. Reports
     v_{n+1} = (x_{n+1} - x_n)/h + a_n*h/2. Forces that depend on velocity see (x_n - x_{n-1})/h, a
     first-order velocity, so with drag the method is first order.
   VELOCITY_VERLET          2      2 (1)   yes      w*h < 2        -                 predicted v + a*h
     x += v*h + a*h^2/2; v += (a + a(x_new, v + a*h))*h/2.
   LEAPFROG                 2      2 (1)   yes      w*h < 2        -                 predicted v + a*h
     Kick-drift-kick: v += a*h/2; x += v*h; v += a(x_new)*h/2. The same map as velocity Verlet in exact
     arithmetic (it is velocity Verlet written with the half-step velocity); the two differ only in
     rounding. Time-reversible: flip the velocities, step as many times again, flip them back, and the
     particles are where they started (up to rounding).
   MIDPOINT                 2      2       no       never (**)     -                 at the stage
     Explicit midpoint RK2: y_mid = y + f(y)*h/2; y += f(y_mid)*h. (**) Like explicit Euler it adds
     energy to a spring every step, only less: the amplitude grows by sqrt(1 + (w*h)^4/4) per step.
   RK4                      4      4       no       w*h < 2.83     -                 at each stage
     Classic Runge-Kutta, stable while w*h < 2*sqrt(2). Energy drifts (a spring's decays) by O(h^4)
     per unit time, so it is not bounded over long runs.
   FOREST_RUTH              4      3       yes      w*h < 1.5734   -                 v at each kick: 1st order
     Forest-Ruth (Yoshida's 4th-order triple jump of leapfrog), theta = 1/(2 - 2^(1/3)):
     drift theta*h/2, kick theta*h, drift (1-theta)*h/2, kick (1-2*theta)*h, drift (1-theta)*h/2,
     kick theta*h, drift theta*h/2. Symplectic and 4th order for forces of position only; a kick with a
     velocity-dependent force is an explicit Euler step in v, which makes the whole method first order
     (use RK4 or the exact stepper for drag). Its large negative middle step is why its stability
     limit (1.5734) is lower than leapfrog's.
   EXACT_LINEAR_DRAG        exact  0       -        no spring (***) -                exact (linear drag)
     Solves v' = g + F/m - k*v over the step (see motus_particle_step_linear_drag). Only for gravity,
     linear drag and the accumulated force; other terms give MOTUS_ERROR_UNSUPPORTED. (***) It takes no
     spring, so it has no oscillator to lose; what it takes it solves exactly at any dt: its limit is +Inf.

   STABILITY LIMITS. On x'' = -w^2 x every method's step is a linear map of (x, v/w) that depends on
   z = w*h only; the amplitude does not grow while its eigenvalues stay on or inside the unit circle
   (motus_method_stability_limit gives the z where that stops, measured in tests/stability.c):
   - explicit Euler: (x, v/w) -> [[1, z], [-z, 1]] (x, v/w), a rotation times sqrt(1 + z^2): grows at any z > 0.
   - midpoint: I + z*J + z^2*J^2/2 with J^2 = -I, a rotation times |1 + iz - z^2/2| = sqrt(1 + z^4/4) > 1.
   - semi-implicit Euler, position Verlet, velocity Verlet, leapfrog: determinant 1, trace 2 - z^2, so the
     eigenvalues stay on the unit circle while |2 - z^2| < 2: z < 2. At z = 2 a double eigenvalue -1 makes
     the amplitude grow linearly, beyond it by (z^2 - 2 + z*sqrt(z^2 - 4))/2 per step.
   - RK4: R(iz) = 1 - z^2/2 + z^4/24 + i*(z - z^3/6), |R|^2 = 1 - z^6/72 + z^8/576 <= 1 iff z <= 2*sqrt(2).
   - Forest-Ruth: three leapfrog maps of theta*z, (1 - 2*theta)*z, theta*z; each has determinant 1, and
     the product's trace is 2 - u + u^2/12 + c*u^3 (u = z^2, c = 0.1295084). The rotation per step peaks
     at 0.977 rad (z = 1.185) and returns to 0 where the trace is back at 2: z^2 = (sqrt(1/144 + 4c) -
     1/12)/(2c), z = 1.5734019. Beyond it an eigenvalue is real and > 1.
   Damping shrinks the limits: a spring's damping c and the drags add a decay rate g to the oscillation,
   which pushes the eigenvalues off the imaginary axis, where the methods' limits differ (on the real
   axis, g*h < 2 for the Euler and Verlet family and midpoint, 2.7853 for RK4, 1.1682 for Forest-Ruth).
   The stepper's limit therefore uses an effective frequency
       w_eff = alpha*g/2 + sqrt((alpha*g/2)^2 + w^2),    stable while w_eff*h < limit
   with alpha = 1 for semi-implicit Euler, both Verlets and leapfrog (then it is exact: z^2 + 2*g*h < 4
   for semi-implicit Euler), alpha = 2.8284/2.7853 for RK4 (exact at both ends), and alpha = 2 for
   Forest-Ruth (1.79 is the least that holds over damping ratios 0..1e5, found numerically; its kicks are
   explicit Euler steps in v, and the middle one runs backwards). See motus_stepper_max_stable_dt.

   (1): with MOTUS_STEPPER_REUSE_FORCES, the acceleration computed at the end of a step is reused at the
   start of the next ("first same as last"). Only valid if nothing but the stepper changes positions,
   velocities and forces between steps and the forces do not depend on velocity; a game that adds input
   forces each frame should leave it off. */

typedef enum motus_method {
    MOTUS_SEMI_IMPLICIT_EULER = 0,
    MOTUS_EXPLICIT_EULER,
    MOTUS_POSITION_VERLET,
    MOTUS_VELOCITY_VERLET,
    MOTUS_LEAPFROG,
    MOTUS_MIDPOINT,
    MOTUS_RK4,
    MOTUS_FOREST_RUTH,
    MOTUS_EXACT_LINEAR_DRAG,
    MOTUS_METHOD_COUNT
} motus_method;

enum {
    MOTUS_STEPPER_REUSE_FORCES = 1 /* see (1) above */
};

/* Zero means default: `motus_stepper_desc desc = {0};` in C, `= {}` in C++, then set what you need. */
typedef struct motus_stepper_desc {
    int capacity;        /* most particles a step will be given */
    motus_method method; /* 0: semi-implicit Euler */
    void *scratch;       /* motus_stepper_scratch_size(method, capacity) bytes, aligned for motus_real */
    size_t scratch_bytes;
    unsigned flags; /* MOTUS_STEPPER_*; any other bit is MOTUS_ERROR_INVALID_DESC */
} motus_stepper_desc;

typedef struct motus_stepper {
    motus_method method;
    int capacity;
    unsigned flags;
    motus_vec2 *scratch;
    motus_real time;           /* seconds stepped since init: the callback's time */
    int history_count;         /* POSITION_VERLET: particles [0, history_count) have a last displacement */
    motus_real previous_dt;    /* POSITION_VERLET: the step that displacement was made with */
    int kept_acceleration_count; /* REUSE_FORCES: scratch holds a(x_n, v_n) of this many particles */
} motus_stepper;

/* Names, for tables and plots: "semi_implicit_euler", "rk4", ... NULL for a value out of range. */
MOTUS_API const char *motus_method_name(motus_method method) {
    switch (method) {
    case MOTUS_SEMI_IMPLICIT_EULER: return "semi_implicit_euler";
    case MOTUS_EXPLICIT_EULER: return "explicit_euler";
    case MOTUS_POSITION_VERLET: return "position_verlet";
    case MOTUS_VELOCITY_VERLET: return "velocity_verlet";
    case MOTUS_LEAPFROG: return "leapfrog";
    case MOTUS_MIDPOINT: return "midpoint";
    case MOTUS_RK4: return "rk4";
    case MOTUS_FOREST_RUTH: return "forest_ruth";
    case MOTUS_EXACT_LINEAR_DRAG: return "exact_linear_drag";
    case MOTUS_METHOD_COUNT: break;
    }
    return NULL;
}

/* Order of accuracy (0 for the exact stepper) and force evaluations per step, as tabled above. */
MOTUS_API int motus_method_order(motus_method method) {
    static const int order[MOTUS_METHOD_COUNT] = {1, 1, 2, 2, 2, 2, 4, 4, 0};
    return (unsigned)method < MOTUS_METHOD_COUNT ? order[method] : -1;
}
MOTUS_API int motus_method_evaluations(motus_method method, unsigned flags) {
    static const int evaluations[MOTUS_METHOD_COUNT] = {1, 1, 1, 2, 2, 2, 4, 3, 0};
    if ((unsigned)method >= MOTUS_METHOD_COUNT) return -1;
    if ((flags & MOTUS_STEPPER_REUSE_FORCES) && (method == MOTUS_VELOCITY_VERLET || method == MOTUS_LEAPFROG))
        return 1;
    return evaluations[method];
}

/* The largest w*h at which the method's amplitude on the undamped spring x'' = -w^2 x does not grow
   (see STABILITY LIMITS): 2 for semi-implicit Euler, both Verlets and leapfrog, 2*sqrt(2) for RK4,
   1.5734 for Forest-Ruth, 0 for explicit Euler and midpoint (they grow at every dt > 0), +Inf for the
   exact stepper (it takes no spring, and solves what it takes exactly). -1 for a value out of range, as
   motus_method_order. At the limit itself the symplectic methods grow linearly: stay below it. */
MOTUS_API motus_real motus_method_stability_limit(motus_method method) {
    switch (method) {
    case MOTUS_SEMI_IMPLICIT_EULER:
    case MOTUS_POSITION_VERLET:
    case MOTUS_VELOCITY_VERLET:
    case MOTUS_LEAPFROG: return 2;
    case MOTUS_EXPLICIT_EULER:
    case MOTUS_MIDPOINT: return 0;
    case MOTUS_RK4: return (motus_real)2.8284271247461900976;
    case MOTUS_FOREST_RUTH: return (motus_real)1.5734019474345367;
    case MOTUS_EXACT_LINEAR_DRAG: return (motus_real)HUGE_VAL;
    case MOTUS_METHOD_COUNT: break;
    }
    return -1;
}

/* The largest step for a method, given w^2 (stiffness over mass, summed as motus_stepper_max_stable_dt
   does) and a decay rate g (1/s) from damping and drag: limit/w_eff, w_eff as in STABILITY LIMITS.
   +Inf when nothing limits the step; 0 when no step is stable (or w_eff overflows). */
MOTUS_API motus_real motus__stable_dt(motus_method method, motus_real omega_squared, motus_real decay_rate) {
    const motus_real limit = motus_method_stability_limit(method);
    motus_real alpha = 1, half;
    if (!motus_real_is_finite(limit) || (omega_squared == 0 && decay_rate == 0)) return (motus_real)HUGE_VAL;
    if (limit == 0) /* explicit Euler and midpoint: no spring is stable; a pure decay is while g*h < 2 */
        return omega_squared > 0 ? 0 : 2 / decay_rate;
    if (method == MOTUS_RK4) alpha = (motus_real)(2.8284271247461900976 / 2.7852935634050);
    if (method == MOTUS_FOREST_RUTH) alpha = 2;
    half = MOTUS_R(0.5) * alpha * decay_rate;
    return limit / (half + MOTUS_SQRT(half * half + omega_squared));
}

/* The largest dt for which `method` keeps an undamped spring of `stiffness` (N/m) on a particle of `mass`
   (kg; to an anchor, or to an immovable particle) from growing: limit/w with w = sqrt(stiffness/mass).
   No safety margin: that is the edge itself (use a fraction of it, or motus_substeps_for with a safety
   factor). For a spring between two particles use the reduced mass m1*m2/(m1 + m2). Writes 0 for explicit
   Euler and midpoint (no dt is stable), +Inf for stiffness 0 or the exact stepper. Bad input (NaN or Inf,
   stiffness < 0, mass <= 0, a method out of range) returns a result and leaves *max_dt alone. */
MOTUS_API motus_result motus_max_stable_dt(motus_method method, motus_real stiffness, motus_real mass,
                                           motus_real *max_dt) {
    if (!max_dt) return MOTUS_ERROR_NULL_POINTER;
    if ((unsigned)method >= MOTUS_METHOD_COUNT) return MOTUS_ERROR_UNSUPPORTED;
    if (!motus_real_is_finite(stiffness) || !motus_real_is_finite(mass)) return MOTUS_ERROR_NOT_FINITE;
    if (!(mass > 0)) return MOTUS_ERROR_INVALID_MASS;
    if (stiffness < 0) return MOTUS_ERROR_INVALID_FORCES;
    *max_dt = motus__stable_dt(method, stiffness / mass, 0);
    return MOTUS_OK;
}

/* The fewest equal substeps n that bring dt/n below safety*max_stable_dt (strictly, in motus_real
   arithmetic: the substep motus_stepper_step_substepped takes). safety in (0, 1]. Below the limit a
   symplectic method is stable but its amplitude wanders over an ellipse that stretches as w*h nears the
   limit: semi-implicit Euler started at rest reaches 1/sqrt(1 - safety) times its start amplitude (3.2 at
   0.9, 1.4 at 0.5), so a margin buys smoothness too. max_stable_dt = +Inf gives 1.
   MOTUS_ERROR_TOO_STIFF if max_stable_dt is 0, or more than INT_MAX/2 substeps would be needed. */
MOTUS_API motus_result motus_substeps_for(motus_real dt, motus_real max_stable_dt, motus_real safety, int *substeps) {
    motus_real limit, quotient;
    int n;
    if (!substeps) return MOTUS_ERROR_NULL_POINTER;
    if (!motus__is_positive_finite(dt)) return MOTUS_ERROR_INVALID_TIME_STEP;
    if ((!motus_real_is_finite(max_stable_dt) && !(max_stable_dt > 0)) || !motus_real_is_finite(safety))
        return MOTUS_ERROR_NOT_FINITE; /* NaN or -Inf; +Inf means no limit */
    if (!(max_stable_dt >= 0) || !(safety > 0 && safety <= 1)) return MOTUS_ERROR_INVALID_ARGUMENT;
    if (!motus_real_is_finite(max_stable_dt)) {
        *substeps = 1;
        return MOTUS_OK;
    }
    limit = safety * max_stable_dt;
    quotient = dt / limit; /* +Inf when limit is 0 */
    if (!(quotient < (motus_real)(INT_MAX / 2))) return MOTUS_ERROR_TOO_STIFF;
    /* ceil(dt/limit) up to rounding; then settle on the least n with dt/n < limit as computed. */
    n = (int)quotient;
    if (n < 1) n = 1;
    while (!(dt / (motus_real)n < limit)) ++n;
    while (n > 1 && dt / (motus_real)(n - 1) < limit) --n;
    *substeps = n;
    return MOTUS_OK;
}

/* Scratch arrays per particle: [0] new x, [1] new v, [2] acceleration, then per method: RK stages, the
   previous positions (position Verlet) or the acceleration kept for the next step (reuse). */
MOTUS_API int motus__scratch_arrays(motus_method method) {
    switch (method) {
    case MOTUS_POSITION_VERLET: return 4;
    case MOTUS_VELOCITY_VERLET:
    case MOTUS_LEAPFROG: return 5;
    case MOTUS_MIDPOINT: return 5;
    case MOTUS_RK4: return 7;
    default: return 3;
    }
}

/* Bytes of memory a stepper for `capacity` particles needs; 0 for bad arguments. */
MOTUS_API size_t motus_stepper_scratch_size(motus_method method, int capacity) {
    if ((unsigned)method >= MOTUS_METHOD_COUNT || capacity < 0) return 0;
    if ((size_t)capacity > ((size_t)-1) / (sizeof(motus_vec2) * 8)) return 0; /* absurd sizes overflow */
    return (size_t)motus__scratch_arrays(method) * (size_t)capacity * sizeof(motus_vec2);
}

/* The alignment motus_real needs, in C99 (no _Alignof) and C++ alike. */
typedef struct motus__align_probe {
    char c;
    motus_real r;
} motus__align_probe;

MOTUS_API motus_result motus_stepper_init(motus_stepper *stepper, const motus_stepper_desc *desc) {
    size_t needed;
    if (!stepper || !desc) return MOTUS_ERROR_NULL_POINTER;
    if ((unsigned)desc->method >= MOTUS_METHOD_COUNT) return MOTUS_ERROR_UNSUPPORTED;
    if (desc->capacity < 0) return MOTUS_ERROR_INVALID_COUNT;
    needed = motus_stepper_scratch_size(desc->method, desc->capacity);
    if (needed == 0 && desc->capacity > 0) return MOTUS_ERROR_INVALID_COUNT;
    if (desc->scratch_bytes < needed) return MOTUS_ERROR_SCRATCH_TOO_SMALL;
    if (!desc->scratch && needed > 0) return MOTUS_ERROR_NULL_POINTER;
    /* A flag meant for something else (a MOTUS_HAS_* bit) would otherwise be ignored without a word; and
       scratch read as motus_vec2 at a misaligned address is undefined behaviour (a fault on some CPUs). */
    if ((desc->flags & ~(unsigned)MOTUS_STEPPER_REUSE_FORCES) ||
        (uintptr_t)desc->scratch % offsetof(motus__align_probe, r) != 0)
        return MOTUS_ERROR_INVALID_DESC;
    /* Padding too: a stepper saved, hashed or compared byte for byte (replays) holds no stale bytes. */
    memset(stepper, 0, sizeof *stepper);
    stepper->method = desc->method;
    stepper->capacity = desc->capacity;
    stepper->flags = desc->flags;
    stepper->scratch = (motus_vec2 *)desc->scratch;
    stepper->time = 0;
    stepper->history_count = 0;
    stepper->previous_dt = 0;
    stepper->kept_acceleration_count = 0;
    return MOTUS_OK;
}

/* Forget what the stepper remembers between steps (position Verlet's previous positions, a reused
   acceleration). Call it after moving particles or changing their velocities by hand. */
MOTUS_API void motus_stepper_reset(motus_stepper *stepper) {
    if (!stepper) return;
    stepper->history_count = 0;
    stepper->kept_acceleration_count = 0;
}

/* y_out = y + a*s, for the position and velocity halves of a stage. */
MOTUS_API void motus__axpy(int count, const motus_vec2 *y, const motus_vec2 *a, motus_real s, motus_vec2 *out) {
    int i;
    for (i = 0; i < count; ++i) out[i] = motus_vec2_add(y[i], motus_vec2_scale(a[i], s));
}

/* Copies particle positions (velocities) into an array, the state a stage starts from. */
MOTUS_API void motus__gather(const motus_particle *particles, int count, motus_vec2 *positions,
                             motus_vec2 *velocities) {
    int i;
    for (i = 0; i < count; ++i) {
        if (positions) positions[i] = particles[i].position;
        if (velocities) velocities[i] = particles[i].velocity;
    }
}

MOTUS_API motus_result motus__step_exact_drag(const motus_forces *forces, const motus_particle *particles,
                                              int count, motus_real h, motus_vec2 *x, motus_vec2 *v) {
    motus_real phi1, phi2, decay;
    int i;
    if (forces->quadratic_drag != 0 || forces->attractor_strength != 0 || forces->spring_count != 0 ||
        forces->callback)
        return MOTUS_ERROR_UNSUPPORTED;
    motus__drag_phi(forces->linear_drag * h, &phi1, &phi2);
    decay = MOTUS_EXP(-forces->linear_drag * h);
    for (i = 0; i < count; ++i) {
        const motus_particle *p = &particles[i];
        /* Nothing acts on an immovable particle, drag included: it keeps its velocity (decay 1, phi1 1). */
        const int movable = p->inverse_mass != 0;
        const motus_real particle_decay = movable ? decay : 1, particle_phi1 = movable ? phi1 : 1;
        motus_vec2 a = motus_vec2_scale(motus_vec2_add(motus_vec2_scale(p->force, p->inverse_mass), forces->gravity),
                                        (motus_real)movable);
        v[i] = motus_vec2_add(motus_vec2_scale(p->velocity, particle_decay), motus_vec2_scale(a, h * particle_phi1));
        x[i] = motus_vec2_add(p->position, motus_vec2_add(motus_vec2_scale(p->velocity, h * particle_phi1),
                                                          motus_vec2_scale(a, h * h * phi2)));
    }
    return MOTUS_OK;
}

/* Semi-implicit or explicit Euler in one pass over particles whose forces do not couple them (no springs,
   no callback): read, accelerate, write the new state to x, v. Returns nonzero if anything came out
   non-finite or a mass was negative. semi, quadratic and attractor are constants where it is inlined. */
MOTUS__INLINE int motus__euler_pass(const motus_forces *f, const motus_particle *particles, int count, motus_real h,
                                    motus_vec2 *x, motus_vec2 *v, int semi, int quadratic, int attractor) {
    motus_real check = 0;
    int i, negative_mass = 0;
    for (i = 0; i < count; ++i) {
        const motus_particle *p = &particles[i];
        motus_vec2 a = motus__particle_acceleration(f, p->force, p->inverse_mass, p->position, p->velocity,
                                                    quadratic, attractor);
        motus_vec2 velocity = motus_vec2_add(p->velocity, motus_vec2_scale(a, h));
        motus_vec2 position = motus_vec2_add(p->position, motus_vec2_scale(semi ? velocity : p->velocity, h));
        x[i] = position;
        v[i] = velocity;
        check += (position.x + position.y) + (velocity.x + velocity.y);
        negative_mass |= p->inverse_mass < 0;
    }
    return negative_mass | !motus_real_is_finite(check);
}

/* A sum of every new value is NaN or infinite if any value is, which costs far less than testing each
   one. It can also overflow with every value finite (positions near the float maximum): only then are the
   values tested one by one. Returns nonzero if the state really is not finite, or a mass is negative. */
MOTUS_API int motus__state_broken(const motus_particle *particles, int count, const motus_vec2 *x,
                                  const motus_vec2 *v, int suspicious) {
    int i, broken = 0;
    if (!suspicious) return 0;
    for (i = 0; i < count; ++i)
        broken |= motus__vec2_not_finite(x[i]) | motus__vec2_not_finite(v[i]) | (particles[i].inverse_mass < 0);
    return broken;
}

/* Why a step that produced a non-finite state (or met a negative mass) failed: a broken particle, or else
   an overflow of finite inputs (the force model was checked before the step). */
MOTUS_API motus_result motus__diagnose(const motus_particle *particles, int count) {
    motus_result result;
    int i;
    for (i = 0; i < count; ++i) {
        if (particles[i].inverse_mass < 0) return MOTUS_ERROR_INVALID_MASS; /* first, as motus_particle_step */
        result = motus_particle_check(&particles[i]);
        if (result != MOTUS_OK) return result;
    }
    return MOTUS_ERROR_OVERFLOW;
}

/* Advances particles[0..count) by dt under `forces` (NULL: no forces but the accumulated ones) with the
   stepper's method. On any result but MOTUS_OK nothing is written: not the particles, not the stepper nor
   what it keeps between steps (the rest of its scratch is working memory). count 0 is a step of nothing:
   particles may be NULL, the clock advances. */
MOTUS_API motus_result motus_stepper_step(motus_stepper *stepper, motus_particle *particles, int count,
                                          const motus_forces *forces, motus_real dt) {
    static const motus_forces no_forces = {{0, 0}, 0, 0, 0, {0, 0}, NULL, 0, NULL, NULL};
    motus_vec2 *x, *v, *a, no_scratch[1];
    const motus_real h = dt, t = stepper ? stepper->time : 0;
    motus_result result;
    int i, reuse, bad = 0, checked = 0, suspicious = 0;
    if (!stepper || (!particles && count > 0)) return MOTUS_ERROR_NULL_POINTER;
    if (!stepper->scratch && stepper->capacity > 0) return MOTUS_ERROR_NULL_POINTER; /* filled by hand */
    if (count < 0 || count > stepper->capacity) return MOTUS_ERROR_INVALID_COUNT;
    if (!motus__is_positive_finite(dt)) return MOTUS_ERROR_INVALID_TIME_STEP;
    /* The clock the callback sees must stay finite too (two steps of dt near the maximum overflow it). */
    if (!motus_real_is_finite(stepper->time + dt)) return MOTUS_ERROR_OVERFLOW;
    if (!forces) forces = &no_forces;
    /* The force model is checked up front (its springs index the arrays). The particles are not: a NaN or
       Inf in one, or a negative mass, makes the new state non-finite or trips `bad` below, and only then
       are they searched for the culprit. Nothing can hide: an immovable particle passes a NaN on, and a
       value a method does not read this step is checked where it is skipped. */
    result = motus_forces_check(forces, count);
    if (result != MOTUS_OK) return result;

    /* A stepper of capacity 0 may have no scratch, and NULL + 0 is undefined behaviour in C (C11 6.5.6;
       UBSan reports it): offsets from a local array instead. count is 0 then, so nothing reads it. */
    x = stepper->scratch ? stepper->scratch : no_scratch;
    v = x + stepper->capacity;
    a = v + stepper->capacity;
    reuse = (stepper->flags & MOTUS_STEPPER_REUSE_FORCES) && stepper->kept_acceleration_count == count;

    switch (stepper->method) {
    case MOTUS_SEMI_IMPLICIT_EULER:
    case MOTUS_EXPLICIT_EULER:
        if (forces->spring_count == 0 && !forces->callback) {
            const int semi = stepper->method == MOTUS_SEMI_IMPLICIT_EULER;
            switch (motus__terms(forces) * 2 + semi) {
            case 0: suspicious = motus__euler_pass(forces, particles, count, h, x, v, 0, 0, 0); break;
            case 1: suspicious = motus__euler_pass(forces, particles, count, h, x, v, 1, 0, 0); break;
            case 2: suspicious = motus__euler_pass(forces, particles, count, h, x, v, 0, 1, 0); break;
            case 3: suspicious = motus__euler_pass(forces, particles, count, h, x, v, 1, 1, 0); break;
            case 4: suspicious = motus__euler_pass(forces, particles, count, h, x, v, 0, 0, 1); break;
            case 5: suspicious = motus__euler_pass(forces, particles, count, h, x, v, 1, 0, 1); break;
            case 6: suspicious = motus__euler_pass(forces, particles, count, h, x, v, 0, 1, 1); break;
            default: suspicious = motus__euler_pass(forces, particles, count, h, x, v, 1, 1, 1); break;
            }
            checked = 1;
            break;
        }
        motus__gather(particles, count, x, v);
        motus__accelerations(forces, particles, count, x, v, t, a);
        for (i = 0; i < count; ++i) {
            motus_vec2 old_velocity = v[i];
            v[i] = motus_vec2_add(v[i], motus_vec2_scale(a[i], h));
            x[i] = motus_vec2_add(x[i], motus_vec2_scale(stepper->method == MOTUS_EXPLICIT_EULER ? old_velocity : v[i], h));
        }
        break;
    case MOTUS_POSITION_VERLET: {
        motus_vec2 *displacement = a + stepper->capacity; /* x_n - x_{n-1}, kept between steps */
        const int known = stepper->history_count < count ? stepper->history_count : count;
        const motus_real ratio = known > 0 ? h / stepper->previous_dt : 0;
        motus__gather(particles, count, x, v);
        /* The velocity forces see: the last displacement over its step, (x_n - x_{n-1})/h_p. */
        for (i = 0; i < known; ++i) {
            bad |= motus__vec2_not_finite(v[i]); /* the velocity given is replaced here: see that it was fine */
            v[i] = motus_vec2_scale(displacement[i], MOTUS_R(1.0) / stepper->previous_dt);
        }
        motus__accelerations(forces, particles, count, x, v, t, a);
        for (i = 0; i < count; ++i) {
            motus_vec2 step = i < known ? motus_vec2_add(motus_vec2_scale(displacement[i], ratio),
                                                         motus_vec2_scale(a[i], h * (h + stepper->previous_dt) * MOTUS_R(0.5)))
                                        : motus_vec2_add(motus_vec2_scale(particles[i].velocity, h),
                                                         motus_vec2_scale(a[i], MOTUS_R(0.5) * h * h));
            x[i] = motus_vec2_add(x[i], step);
            v[i] = motus_vec2_add(motus_vec2_scale(step, MOTUS_R(1.0) / h), motus_vec2_scale(a[i], MOTUS_R(0.5) * h));
            a[i] = step; /* the displacement to keep, once the step is accepted */
        }
        break;
    }
    case MOTUS_VELOCITY_VERLET:
    case MOTUS_LEAPFROG: {
        motus_vec2 *kept = a + stepper->capacity; /* a(x_n, v_n) from the last step (REUSE_FORCES) */
        motus_vec2 *predicted = kept + stepper->capacity; /* v_n + a_n*h, the velocity the end forces see */
        /* a_n: the kept one, or evaluated now into `a`, never into `kept`: a step that fails must leave the
           kept accelerations as they were (the next step may reuse them). */
        motus_vec2 *start = reuse ? kept : a;
        motus__gather(particles, count, x, v);
        if (!reuse) motus__accelerations(forces, particles, count, x, v, t, a);
        else /* the forces given are not evaluated this time: see that they were fine */
            for (i = 0; i < count; ++i) bad |= motus__vec2_not_finite(particles[i].force);
        if (stepper->method == MOTUS_VELOCITY_VERLET) {
            for (i = 0; i < count; ++i) {
                x[i] = motus_vec2_add(x[i], motus_vec2_add(motus_vec2_scale(v[i], h),
                                                           motus_vec2_scale(start[i], MOTUS_R(0.5) * h * h)));
                predicted[i] = motus_vec2_add(v[i], motus_vec2_scale(start[i], h));
                /* v_n stays in the particle (v is its copy), so v can hold a_n while `a` takes a_{n+1} */
                v[i] = start[i];
            }
            motus__accelerations(forces, particles, count, x, predicted, t + h, a);
            for (i = 0; i < count; ++i) {
                v[i] = motus_vec2_add(particles[i].velocity, motus_vec2_scale(motus_vec2_add(v[i], a[i]), MOTUS_R(0.5) * h));
            }
        } else {
            for (i = 0; i < count; ++i) {
                motus_vec2 half = motus_vec2_add(v[i], motus_vec2_scale(start[i], MOTUS_R(0.5) * h));
                x[i] = motus_vec2_add(x[i], motus_vec2_scale(half, h));
                v[i] = half;
                predicted[i] = motus_vec2_add(half, motus_vec2_scale(start[i], MOTUS_R(0.5) * h));
            }
            motus__accelerations(forces, particles, count, x, predicted, t + h, a);
            for (i = 0; i < count; ++i) {
                v[i] = motus_vec2_add(v[i], motus_vec2_scale(a[i], MOTUS_R(0.5) * h));
            }
        }
        break;
    }
    case MOTUS_MIDPOINT: {
        motus_vec2 *x_mid = a + stepper->capacity, *v_mid = x_mid + stepper->capacity;
        motus__gather(particles, count, x, v);
        motus__accelerations(forces, particles, count, x, v, t, a);
        motus__axpy(count, x, v, MOTUS_R(0.5) * h, x_mid);
        motus__axpy(count, v, a, MOTUS_R(0.5) * h, v_mid);
        motus__accelerations(forces, particles, count, x_mid, v_mid, t + MOTUS_R(0.5) * h, a);
        motus__axpy(count, x, v_mid, h, x);
        motus__axpy(count, v, a, h, v);
        break;
    }
    case MOTUS_RK4: {
        /* k1..k4 summed into dx, dv with weights 1, 2, 2, 1; the stage state in xs, vs. */
        motus_vec2 *xs = a + stepper->capacity, *vs = xs + stepper->capacity;
        motus_vec2 *dx = vs + stepper->capacity, *dv = dx + stepper->capacity;
        static const motus_real stage_c[3] = {MOTUS_R(0.5), MOTUS_R(0.5), MOTUS_R(1.0)};
        static const motus_real weight[3] = {MOTUS_R(2.0), MOTUS_R(2.0), MOTUS_R(1.0)};
        int stage;
        motus__gather(particles, count, x, v);
        motus__accelerations(forces, particles, count, x, v, t, a);
        for (i = 0; i < count; ++i) {
            dx[i] = v[i];
            dv[i] = a[i];
            vs[i] = v[i];
        }
        for (stage = 0; stage < 3; ++stage) {
            motus_real c = stage_c[stage] * h;
            for (i = 0; i < count; ++i) {
                motus_vec2 k_x = vs[i]; /* the previous stage's velocity is this stage's dx/dt slope */
                xs[i] = motus_vec2_add(x[i], motus_vec2_scale(k_x, c));
                vs[i] = motus_vec2_add(v[i], motus_vec2_scale(a[i], c));
            }
            motus__accelerations(forces, particles, count, xs, vs, t + c, a);
            for (i = 0; i < count; ++i) {
                dx[i] = motus_vec2_add(dx[i], motus_vec2_scale(vs[i], weight[stage]));
                dv[i] = motus_vec2_add(dv[i], motus_vec2_scale(a[i], weight[stage]));
            }
        }
        motus__axpy(count, x, dx, h / MOTUS_R(6.0), x);
        motus__axpy(count, v, dv, h / MOTUS_R(6.0), v);
        break;
    }
    case MOTUS_FOREST_RUTH: {
        /* theta = 1/(2 - 2^(1/3)) */
        const motus_real theta = (motus_real)1.3512071919596576340476878089715;
        const motus_real drift[4] = {theta * MOTUS_R(0.5), (1 - theta) * MOTUS_R(0.5), (1 - theta) * MOTUS_R(0.5),
                                     theta * MOTUS_R(0.5)};
        const motus_real kick[3] = {theta, 1 - 2 * theta, theta};
        motus_real stage_time = t;
        int stage;
        motus__gather(particles, count, x, v);
        for (stage = 0; stage < 3; ++stage) {
            motus__axpy(count, x, v, drift[stage] * h, x);
            stage_time += drift[stage] * h;
            motus__accelerations(forces, particles, count, x, v, stage_time, a);
            motus__axpy(count, v, a, kick[stage] * h, v);
        }
        motus__axpy(count, x, v, drift[3] * h, x);
        break;
    }
    case MOTUS_EXACT_LINEAR_DRAG:
        result = motus__step_exact_drag(forces, particles, count, h, x, v);
        if (result != MOTUS_OK) return result;
        break;
    default: return MOTUS_ERROR_UNSUPPORTED;
    }

    /* All or nothing: write back only a state that is finite everywhere (the fused Euler pass summed its
       values as it went). */
    if (!checked) {
        motus_real check = 0;
        int negative_mass = 0;
        for (i = 0; i < count; ++i) {
            check += (x[i].x + x[i].y) + (v[i].x + v[i].y);
            negative_mass |= particles[i].inverse_mass < 0;
        }
        suspicious = negative_mass | !motus_real_is_finite(check);
    }
    if (bad || motus__state_broken(particles, count, x, v, suspicious)) return motus__diagnose(particles, count);
    if (stepper->method == MOTUS_POSITION_VERLET) {
        motus_vec2 *displacement = a + stepper->capacity;
        for (i = 0; i < count; ++i) displacement[i] = a[i];
        stepper->history_count = count;
        stepper->previous_dt = h;
    }
    if (stepper->method == MOTUS_VELOCITY_VERLET || stepper->method == MOTUS_LEAPFROG) {
        motus_vec2 *kept = a + stepper->capacity;
        for (i = 0; i < count; ++i) kept[i] = a[i]; /* a(x_{n+1}): the next step's first evaluation */
        stepper->kept_acceleration_count = count;
    }
    for (i = 0; i < count; ++i) {
        particles[i].position = x[i];
        particles[i].velocity = v[i];
    }
    stepper->time += dt;
    return MOTUS_OK;
}

/* The largest dt with which motus_stepper_step keeps the springs and drags of `forces` on particles[0..count)
   from growing, for the stepper's method: limit/w_eff (see STABILITY LIMITS), with w and g bounded by
   Gershgorin's theorem on the columns of M^-1*K and M^-1*C (spring stiffness and damping matrices):
       w^2 <= max over movable j of  sum over j's springs s of k_s*(1/m_j + 1/m_other)
       g   <= linear_drag + 2*quadratic_drag*max|v_j| + max over movable j of  sum over s of c_s*(1/m_j + 1/m_other)
   1/m_other is 0 for an anchor or an immovable end. One spring: w^2 = k*(1/m1 + 1/m2) exactly; a long
   chain of equal springs: 4k/m, its highest mode. What it does not cover: a spring with rest length L
   squeezed below L/2 (sideways it then acts as a negative stiffness k*(L/|d| - 1) > k: a buckling, not
   an oscillation), the attractor and the callback. The damping rate g is combined with w as if they
   shared modes; for damping that does not, w_eff is an estimate. Quadratic drag is taken at the
   velocities given. Writes +Inf when nothing limits the step, 0 for explicit Euler or midpoint with a
   spring. Uses the first count elements of the stepper's scratch as work space (not its state: what it
   keeps between steps is untouched). Bad input returns a result and leaves *max_dt alone; the exact
   stepper with springs or other terms it cannot take returns MOTUS_ERROR_UNSUPPORTED, as its step does. */
MOTUS_API motus_result motus_stepper_max_stable_dt(motus_stepper *stepper, const motus_particle *particles, int count,
                                                   const motus_forces *forces, motus_real *max_dt) {
    motus_vec2 *sums; /* per particle: sum of k_s*(1/m_j + 1/m_other) in x, of c_s*(...) in y */
    motus_real omega_squared = 0, spring_decay = 0, fastest = 0, decay;
    motus_result result;
    int i;
    if (!stepper || !max_dt || (!particles && count > 0)) return MOTUS_ERROR_NULL_POINTER;
    if (count < 0 || count > stepper->capacity) return MOTUS_ERROR_INVALID_COUNT;
    if ((unsigned)stepper->method >= MOTUS_METHOD_COUNT) return MOTUS_ERROR_UNSUPPORTED;
    if (!forces) {
        *max_dt = (motus_real)HUGE_VAL;
        return MOTUS_OK;
    }
    result = motus_forces_check(forces, count);
    if (result != MOTUS_OK) return result;
    if (stepper->method == MOTUS_EXACT_LINEAR_DRAG) {
        if (forces->quadratic_drag != 0 || forces->attractor_strength != 0 || forces->spring_count != 0 ||
            forces->callback)
            return MOTUS_ERROR_UNSUPPORTED;
        *max_dt = (motus_real)HUGE_VAL;
        return MOTUS_OK;
    }
    for (i = 0; i < count; ++i) {
        if (!motus_real_is_finite(particles[i].inverse_mass)) return MOTUS_ERROR_NOT_FINITE;
        if (particles[i].inverse_mass < 0) return MOTUS_ERROR_INVALID_MASS;
    }
    if (forces->quadratic_drag != 0)
        for (i = 0; i < count; ++i) {
            motus_real speed = motus_vec2_length(particles[i].velocity);
            if (!motus_real_is_finite(speed)) return motus_vec2_is_finite(particles[i].velocity)
                                                         ? MOTUS_ERROR_OVERFLOW : MOTUS_ERROR_NOT_FINITE;
            if (speed > fastest) fastest = speed;
        }
    sums = stepper->scratch;
    for (i = 0; i < count; ++i) sums[i] = motus_v2(0, 0);
    for (i = 0; i < forces->spring_count; ++i) {
        const motus_spring *s = &forces->springs[i];
        const motus_real both = particles[s->a].inverse_mass + (s->b < 0 ? 0 : particles[s->b].inverse_mass);
        const motus_vec2 term = motus_v2(s->stiffness * both, s->damping * both);
        sums[s->a] = motus_vec2_add(sums[s->a], term);
        if (s->b >= 0) sums[s->b] = motus_vec2_add(sums[s->b], term);
    }
    for (i = 0; i < count; ++i) {
        if (particles[i].inverse_mass == 0) continue; /* nothing moves it: its column bounds no motion */
        if (sums[i].x > omega_squared) omega_squared = sums[i].x;
        if (sums[i].y > spring_decay) spring_decay = sums[i].y;
    }
    decay = forces->linear_drag + 2 * forces->quadratic_drag * fastest + spring_decay;
    *max_dt = motus__stable_dt(stepper->method, omega_squared, decay);
    return MOTUS_OK;
}

/* motus_stepper_step over dt in n equal substeps of dt/n, n the fewest that keep each below
   safety*motus_stepper_max_stable_dt (motus_substeps_for), at most max_substeps. *taken (may be NULL)
   gets the substeps completed. Everything is checked before the first substep, and a substep writes
   nothing unless it succeeds: so bad input, or a scene that needs more than max_substeps
   (MOTUS_ERROR_TOO_STIFF), leaves particles and stepper as they were, with *taken = 0. A later substep
   that overflows stops there, with the state of the substeps before it and *taken saying how many. The
   stepper's time grows by n roundings of dt/n, which may differ from dt in the last bit. */
MOTUS_API motus_result motus_stepper_step_substepped(motus_stepper *stepper, motus_particle *particles, int count,
                                                     const motus_forces *forces, motus_real dt, motus_real safety,
                                                     int max_substeps, int *taken) {
    motus_real max_dt = 0, h;
    motus_result result;
    int n = 0, i;
    if (taken) *taken = 0;
    if (!stepper || (!particles && count > 0)) return MOTUS_ERROR_NULL_POINTER;
    if (count < 0 || count > stepper->capacity) return MOTUS_ERROR_INVALID_COUNT;
    if (!motus__is_positive_finite(dt)) return MOTUS_ERROR_INVALID_TIME_STEP;
    if (max_substeps < 1) return MOTUS_ERROR_INVALID_ARGUMENT;
    result = motus_stepper_max_stable_dt(stepper, particles, count, forces, &max_dt);
    if (result != MOTUS_OK) return result;
    result = motus_substeps_for(dt, max_dt, safety, &n);
    if (result != MOTUS_OK) return result;
    if (n > max_substeps) return MOTUS_ERROR_TOO_STIFF;
    h = dt / (motus_real)n;
    for (i = 0; i < n; ++i) {
        result = motus_stepper_step(stepper, particles, count, forces, h);
        if (result != MOTUS_OK) return result;
        if (taken) *taken = i + 1;
    }
    return MOTUS_OK;
}

/* =================================================================================================
   Batch kernels: many particles in arrays, only the work the scene has
   =================================================================================================
   For thousands to millions of particles: one array per component (x[], y[], vx[], ...; "structure of
   arrays"), owned by the caller, stepped over a range [first, first + count) so that a job system or
   OpenMP can split the work: each particle's result does not depend on how the range is split.

   The scene says what it has (MOTUS_HAS_*); motus picks a kernel compiled for exactly that: arrays the
   scene does not have are never loaded (they may be NULL) and there is no per-particle test of a feature.
   Gravity, linear drag, damping, per-particle mass, accumulated forces and bounds have a kernel for each of
   their 64 combinations; quadratic drag, an attractor or explicit Euler switch to one general kernel that
   computes every term (the ones the scene lacks with neutral values). The particles are processed
   MOTUS_SIMD_BYTES at a time with the compiler's vector extensions (GCC, Clang), one at a time elsewhere;
   every lane does the same IEEE operations in the same order as motus_stepper_step followed by
   motus_particle_damp_per_step / _per_second and motus_particle_bounce, so the two agree bit for bit
   (in a build without floating-point contraction: see -ffp-contract=off), with one exception: a scene with
   nothing that changes velocities (no gravity, drag, damping, forces or bounds) does not write them, so a
   velocity of -0 stays -0 where the stepper's v + 0*h gives +0.

   Per particle and step, in this order (SI units; * is per component):
       a = F*inverse_mass + gravity - k*v - c*|v|*v - mu*r/|r|^3     (r from the attractor)
       v += a*h;  x += v*h           (semi-implicit Euler; explicit Euler moves x with the old v)
       v *= damping                  (per step), or damping^h (per second); |v| < MOTUS_REST_SPEED -> 0
       bounds: past a wall, x is mirrored back and v *= -restitution; then x is clamped into the box
   Springs couple particles, so they are not part of the per-range step: motus_batch_add_spring_forces
   adds their forces to the force arrays for the whole batch first (2D).

   Checks: the scene and the arguments are checked on every call (O(1)). The particle data is not read
   twice in release builds: the kernel sums what it writes, and a NaN or Inf in the new state makes the
   step return MOTUS_ERROR_NOT_FINITE after the range was written (overflow included: the inputs are gone,
   so the step cannot tell it from bad data). Define MOTUS_CHECKED to have every step check its range first
   (motus_batch_check) and write nothing on bad data, then run the step once without storing anything (a
   dry run) and return MOTUS_ERROR_OVERFLOW, again with nothing written, if a result would not be finite:
   a checked step reads its range three times. Or call motus_batch_check yourself where data comes in. */

enum {
    MOTUS_HAS_GRAVITY = 1u << 0,            /* scene.gravity */
    MOTUS_HAS_LINEAR_DRAG = 1u << 1,        /* scene.linear_drag */
    MOTUS_HAS_DAMPING_PER_STEP = 1u << 2,   /* scene.damping: v *= damping after each step */
    MOTUS_HAS_DAMPING_PER_SECOND = 1u << 3, /* scene.damping: v *= damping^dt after each step */
    MOTUS_HAS_PARTICLE_MASS = 1u << 4,      /* batch.inverse_mass[]; otherwise scene.inverse_mass for all */
    MOTUS_HAS_FORCES = 1u << 5,             /* batch.force[][]: accumulated forces, springs add to them */
    MOTUS_HAS_QUADRATIC_DRAG = 1u << 6,     /* scene.quadratic_drag */
    MOTUS_HAS_ATTRACTOR = 1u << 7,          /* scene.attractor, scene.attractor_strength */
    MOTUS_HAS_BOUNDS = 1u << 8              /* scene.bounds_min, bounds_max, restitution */
};
#define MOTUS__HAS_KNOWN ((1u << 9) - 1)

typedef struct motus_scene {
    unsigned has;                 /* MOTUS_HAS_* of what the scene has; other fields are ignored */
    motus_method method;          /* MOTUS_SEMI_IMPLICIT_EULER (0) or MOTUS_EXPLICIT_EULER */
    motus_real gravity[3];        /* uniform acceleration, m/s^2 (z unused in 2D) */
    motus_real linear_drag;       /* k >= 0, 1/s */
    motus_real quadratic_drag;    /* c >= 0, 1/m */
    motus_real damping;           /* in [0, 1]: velocity kept per step, or per second */
    motus_real inverse_mass;      /* >= 0, every particle's without MOTUS_HAS_PARTICLE_MASS (0: immovable) */
    motus_real attractor[3];      /* position */
    motus_real attractor_strength; /* mu = G*M >= 0, m^3/s^2 */
    motus_real bounds_min[3], bounds_max[3]; /* the box particles stay in */
    motus_real restitution;       /* in [0, 1]: speed kept through a bounce */
} motus_scene;

typedef struct motus_batch {
    int dimensions;             /* 2 or 3 */
    motus_real *position[3];    /* x[], y[] (, z[]) */
    motus_real *velocity[3];
    motus_real *force[3];         /* with MOTUS_HAS_FORCES, else unused (may be NULL) */
    motus_real *inverse_mass;     /* with MOTUS_HAS_PARTICLE_MASS, else unused (may be NULL) */
} motus_batch;

/* ---- lanes: a vector of motus_real where the compiler has vector extensions, one value elsewhere ---- */
#ifndef MOTUS_SIMD_BYTES
#if defined(__AVX512F__)
#define MOTUS_SIMD_BYTES 64
#elif defined(__AVX__)
#define MOTUS_SIMD_BYTES 32
#else
#define MOTUS_SIMD_BYTES 16 /* SSE2 and NEON: every x86-64 and arm64 */
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
/* The same, for loads and stores at any motus_real boundary; a vector of motus_real may alias the
   motus_real arrays it is read from (memcpy would alias everything and force pointer reloads). */
typedef motus_real motus__lane_unaligned __attribute__((vector_size(MOTUS_SIMD_BYTES), aligned(sizeof(motus_real))));
#define MOTUS__LANES ((int)(MOTUS_SIMD_BYTES / sizeof(motus_real)))
#if defined(__SSE2__) && !defined(MOTUS_SQRT_CUSTOM) && (MOTUS_SIMD_BYTES == 16 || (MOTUS_SIMD_BYTES == 32 && defined(__AVX__)) || (MOTUS_SIMD_BYTES == 64 && defined(__AVX512F__)))
#include <immintrin.h>
#ifdef MOTUS_DOUBLE
#if MOTUS_SIMD_BYTES == 16
#define MOTUS__X86_SQRT _mm_sqrt_pd
#define MOTUS__X86_VECTOR __m128d
#elif MOTUS_SIMD_BYTES == 32
#define MOTUS__X86_SQRT _mm256_sqrt_pd
#define MOTUS__X86_VECTOR __m256d
#else /* maskz: gcc 12's plain _mm512_sqrt_pd trips -Wmaybe-uninitialized in its own header */
#define MOTUS__X86_SQRT(x) _mm512_maskz_sqrt_pd((__mmask8)0xFF, x)
#define MOTUS__X86_VECTOR __m512d
#endif
#else
#if MOTUS_SIMD_BYTES == 16
#define MOTUS__X86_SQRT _mm_sqrt_ps
#define MOTUS__X86_VECTOR __m128
#elif MOTUS_SIMD_BYTES == 32
#define MOTUS__X86_SQRT _mm256_sqrt_ps
#define MOTUS__X86_VECTOR __m256
#else
#define MOTUS__X86_SQRT(x) _mm512_maskz_sqrt_ps((__mmask16)0xFFFF, x)
#define MOTUS__X86_VECTOR __m512
#endif
#endif
#endif
#else
#define MOTUS__VECTOR 0
typedef int motus__mask;
typedef motus_real motus__lane;
#define MOTUS__LANES 1
#endif

MOTUS__INLINE motus__lane motus__splat(motus_real value) {
#if MOTUS__VECTOR
    const motus__lane zero = {0};
    return value - zero; /* a broadcast; v - (+0) is v exactly, signed zeros included */
#else
    return value;
#endif
}
/* Loads n <= MOTUS__LANES values (the rest 0) from possibly unaligned memory; stores n back. */
MOTUS__INLINE motus__lane motus__load(const motus_real *from, int n) {
#if MOTUS__VECTOR
    motus__lane lanes = motus__splat(0);
    int i;
    if (n == MOTUS__LANES) return *(const motus__lane_unaligned *)from;
    for (i = 0; i < n; ++i) lanes[i] = from[i];
    return lanes;
#else
    (void)n;
    return *from;
#endif
}
MOTUS__INLINE void motus__store(motus_real *to, motus__lane lanes, int n) {
#if MOTUS__VECTOR
    int i;
    if (n == MOTUS__LANES) {
        *(motus__lane_unaligned *)to = lanes;
        return;
    }
    for (i = 0; i < n; ++i) to[i] = lanes[i];
#else
    (void)n;
    *to = lanes;
#endif
}
MOTUS__INLINE motus__lane motus__sqrt(motus__lane x) {
#if MOTUS__VECTOR && defined(MOTUS__X86_SQRT)
    /* The hardware's vector square root: correctly rounded, like sqrtf/sqrt, so the lanes agree with the
       scalar path bit for bit (a loop of sqrtf stays scalar while errno is on). */
    return (motus__lane)MOTUS__X86_SQRT((MOTUS__X86_VECTOR)x);
#elif MOTUS__VECTOR
    int i;
    for (i = 0; i < MOTUS__LANES; ++i) x[i] = MOTUS_SQRT(x[i]);
    return x;
#else
    return MOTUS_SQRT(x);
#endif
}
/* mask ? a : b, lane by lane, without a branch. */
MOTUS__INLINE motus__lane motus__select(motus__mask mask, motus__lane a, motus__lane b) {
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

/* The step's constants, worked out once per call. */
typedef struct motus__kernel_constants {
    motus_real h, gravity[3], linear_drag, quadratic_drag, damping, rest_speed, inverse_mass;
    motus_real attractor[3], attractor_strength, bounds_min[3], bounds_max[3], restitution;
    int semi_implicit, has_gravity, has_linear_drag;
} motus__kernel_constants;

/* Kernel flags: the first six choose among the 64 fast kernels; GENERAL adds every other term. */
#define MOTUS__K_GRAVITY 1
#define MOTUS__K_LINEAR_DRAG 2
#define MOTUS__K_DAMPING 4
#define MOTUS__K_MASS 8
#define MOTUS__K_FORCES 16
#define MOTUS__K_BOUNDS 32
#define MOTUS__K_GENERAL 64
#define MOTUS__K_CHANGES_VELOCITY \
    (MOTUS__K_GRAVITY | MOTUS__K_LINEAR_DRAG | MOTUS__K_DAMPING | MOTUS__K_FORCES | MOTUS__K_BOUNDS | MOTUS__K_GENERAL)
#define MOTUS__K_DRY 128 /* MOTUS_CHECKED's dry run: compute and check, store nothing */

/* The constants as lanes, made once per call so that the loop does not redo them (nor reload them: the
   arrays it stores to could alias a motus_real in memory, but not these locals). */
typedef struct motus__kernel_lanes {
    motus__lane h, gravity[3], linear_drag, quadratic_drag, damping, rest_speed, inverse_mass;
    motus__lane attractor[3], attractor_strength, bounds_min[3], bounds_max[3], bounce;
    motus__mask semi_implicit, has_quadratic_drag, has_attractor, has_gravity, has_linear_drag;
    motus__lane uniform_movable;
} motus__kernel_lanes;

/* Lane masks from a flag that is the same for every lane: all ones or all zeros. */
MOTUS__INLINE motus__mask motus__mask_if(int flag) {
    return motus__splat(flag ? MOTUS_R(1.0) : MOTUS_R(0.0)) != motus__splat(0);
}

/* The statements once per dimension with d a constant (the third only in 3D), so that x[d], v[d], a[d]
   become registers rather than arrays on the stack. */
#define MOTUS__EACH_DIM(...)                                                                                     \
    do {                                                                                                       \
        { const int d = 0; __VA_ARGS__ }                                                                       \
        { const int d = 1; __VA_ARGS__ }                                                                       \
        if (dims == 3) { const int d = 2; __VA_ARGS__ }                                                        \
    } while (0)

/* The arrays of a batch, copied into locals for the loop. */
typedef struct motus__arrays {
    motus_real *position[3], *velocity[3], *force[3], *inverse_mass;
} motus__arrays;

/* MOTUS__LANES particles starting at index i. dims and flags are constants where this is inlined:
   the compiler drops every term, load and store the scene does not have. Adds the new positions to
   check[]: a sum that is NaN or infinite if any new value is (a non-finite velocity always makes its
   position non-finite too), one sum per dimension so that the additions do not wait on each other. */
/* The dry run adds value - value: 0 where finite, NaN where not, a sum that cannot overflow on large finite
   values (it has no values to look at afterwards, as the step has). */
#define MOTUS__CHECK_ADD(sum, value) ((flags & MOTUS__K_DRY) ? (sum) + ((value) - (value)) : (sum) + (value))
MOTUS__INLINE void motus__batch_lanes(const motus__arrays *b, int i, const motus__kernel_lanes *k,
                                      const int dims, const int flags, motus__lane *check) {
    const int n = MOTUS__LANES;
    motus__lane x[3], v[3], a[3], inverse_mass;
    const motus__lane h = k->h, zero = motus__splat(0);
    inverse_mass = (flags & MOTUS__K_MASS) ? motus__load(b->inverse_mass + i, n) : k->inverse_mass;
    MOTUS__EACH_DIM(
        x[d] = motus__load(b->position[d] + i, n);
        v[d] = motus__load(b->velocity[d] + i, n);
        a[d] = (flags & MOTUS__K_FORCES) ? motus__load(b->force[d] + i, n) * inverse_mass : zero;
        if (flags & MOTUS__K_GRAVITY) a[d] = a[d] + k->gravity[d];
        if (flags & MOTUS__K_LINEAR_DRAG) a[d] = a[d] - v[d] * k->linear_drag;
    );
    if (flags & MOTUS__K_GENERAL) {
        /* Terms the scene lacks are selected away: added as zero they would turn -0 into +0, and multiplied
           by 0 an infinite intermediate into NaN. */
        motus__lane speed, r[3], r2, drag, pull;
        MOTUS__EACH_DIM(a[d] = motus__select(k->has_gravity, a[d] + k->gravity[d], a[d]);
                        a[d] = motus__select(k->has_linear_drag, a[d] - v[d] * k->linear_drag, a[d]););
        speed = v[0] * v[0] + v[1] * v[1];
        if (dims == 3) speed = speed + v[2] * v[2];
        drag = motus__select(k->has_quadratic_drag, k->quadratic_drag * motus__sqrt(speed), zero);
        MOTUS__EACH_DIM(a[d] = motus__select(k->has_quadratic_drag, a[d] - v[d] * drag, a[d]);
                        r[d] = x[d] - k->attractor[d];);
        r2 = r[0] * r[0] + r[1] * r[1];
        if (dims == 3) r2 = r2 + r[2] * r[2];
        /* mu/(r2*sqrt(r2)) where r2 > 0, else no pull (that lane's division by zero is discarded) */
        pull = motus__select((r2 > zero) & k->has_attractor, k->attractor_strength / (r2 * motus__sqrt(r2)), zero);
        MOTUS__EACH_DIM(a[d] = motus__select(k->has_attractor, a[d] - r[d] * pull, a[d]););
    }
    if (flags & MOTUS__K_MASS) { /* immovable particles: no acceleration (a NaN passes on) */
        motus__lane movable = motus__select(inverse_mass != zero, motus__splat(1), zero);
        MOTUS__EACH_DIM(a[d] = a[d] * movable;);
        MOTUS__EACH_DIM(check[d] = MOTUS__CHECK_ADD(check[d], inverse_mass);); /* a NaN mass shows even without forces */
    } else if (flags & MOTUS__K_GENERAL) { /* a uniform inverse mass of 0 comes here: nothing accelerates */
        MOTUS__EACH_DIM(a[d] = a[d] * k->uniform_movable;);
    }
    MOTUS__EACH_DIM(
        motus__lane old_velocity = v[d];
        v[d] = v[d] + a[d] * h;
        if (flags & MOTUS__K_GENERAL) /* explicit Euler moves with the old velocity */
            x[d] = x[d] + motus__select(k->semi_implicit, v[d], old_velocity) * h;
        else
            x[d] = x[d] + v[d] * h;
        if (flags & MOTUS__K_DAMPING) { /* as motus__damp: slow components to a zero of their sign */
            v[d] = v[d] * k->damping;
            v[d] = motus__select((v[d] < k->rest_speed) & (v[d] > -k->rest_speed), v[d] * zero, v[d]);
        }
        /* Checked before the bounds, whose clamp would turn an infinite position into the wall; explicit
           Euler's new velocity does not reach its position, so the general kernel adds it too. */
        check[d] = MOTUS__CHECK_ADD(check[d], x[d]);
        if (flags & MOTUS__K_GENERAL) check[d] = MOTUS__CHECK_ADD(check[d], v[d]);
        if (flags & MOTUS__K_BOUNDS) { /* as motus_particle_bounce: mirror, bounce, then clamp */
            motus__mask below = x[d] < k->bounds_min[d], above;
            /* Clamped only where the step left it finite: an infinite position must stay infinite for the
               check, but one the mirror itself overflows (walls near the maximum) is clamped, as
               motus_particle_bounce does. */
            const motus__mask finite = (motus__mask)(x[d] >= motus__splat(-MOTUS__REAL_MAX)) &
                                       (motus__mask)(x[d] <= motus__splat(MOTUS__REAL_MAX));
            x[d] = motus__select(below, k->bounds_min[d] + (k->bounds_min[d] - x[d]), x[d]);
            v[d] = motus__select(below, v[d] * k->bounce, v[d]);
            above = x[d] > k->bounds_max[d];
            x[d] = motus__select(above, k->bounds_max[d] - (x[d] - k->bounds_max[d]), x[d]);
            v[d] = motus__select(above, v[d] * k->bounce, v[d]);
            x[d] = motus__select((x[d] < k->bounds_min[d]) & finite, k->bounds_min[d], x[d]);
            x[d] = motus__select((x[d] > k->bounds_max[d]) & finite, k->bounds_max[d], x[d]);
        }
        if (!(flags & MOTUS__K_DRY)) {
            motus__store(b->position[d] + i, x[d], n);
            /* A kernel with nothing that changes velocities (drift, or masses with no force) does not store
               them: a third less memory traffic. The stepper's v + 0 would turn a -0 into +0; that is all. */
            if (flags & MOTUS__K_CHANGES_VELOCITY) motus__store(b->velocity[d] + i, v[d], n);
        }
    );
}

/* n < MOTUS__LANES particles at index i of `arrays`, copied into the buffers of `partial` (zero padded) when
   `in`, or back (positions and velocities) when not. */
MOTUS_API void motus__partial_copy(const motus__arrays *arrays, int i, const motus__arrays *partial, int n, int dims,
                                   int flags, int in) {
    int j, d;
    for (j = 0; j < MOTUS__LANES; ++j) {
        const int inside = j < n;
        for (d = 0; d < dims; ++d) {
            if (in) {
                partial->position[d][j] = inside ? arrays->position[d][i + j] : 0;
                partial->velocity[d][j] = inside ? arrays->velocity[d][i + j] : 0;
                if (flags & MOTUS__K_FORCES) partial->force[d][j] = inside ? arrays->force[d][i + j] : 0;
            } else if (inside) {
                arrays->position[d][i + j] = partial->position[d][j];
                arrays->velocity[d][i + j] = partial->velocity[d][j];
            }
        }
        if (in && (flags & MOTUS__K_MASS)) partial->inverse_mass[j] = inside ? arrays->inverse_mass[i + j] : 0;
    }
}

/* The range in whole vectors, then one partial vector for the rest. Returns nonzero if the sum of the new
   state is not finite (then motus__batch_state_broken looks closer). */
MOTUS__INLINE int motus__batch_range(const motus_batch *batch, int first, int count, const motus__kernel_constants *c,
                                     const int dims, const int flags) {
    motus__kernel_lanes k;
    motus__arrays arrays, partial;
    motus_real buffer[10][MOTUS__LANES];
    motus__lane check[3];
    motus_real sum = 0;
    int i = first, end = first + count, lane, d, head, whole_end, part, part_start[2], part_length[2];
    k.h = motus__splat(c->h);
    k.linear_drag = motus__splat(c->linear_drag);
    k.quadratic_drag = motus__splat(c->quadratic_drag);
    k.damping = motus__splat(c->damping);
    k.rest_speed = motus__splat(c->rest_speed);
    k.inverse_mass = motus__splat(c->inverse_mass);
    k.attractor_strength = motus__splat(c->attractor_strength);
    k.bounce = motus__splat(-c->restitution);
    k.semi_implicit = motus__mask_if(c->semi_implicit);
    k.has_quadratic_drag = motus__mask_if(c->quadratic_drag != 0);
    k.has_attractor = motus__mask_if(c->attractor_strength != 0);
    k.has_gravity = motus__mask_if(c->has_gravity);
    k.has_linear_drag = motus__mask_if(c->has_linear_drag);
    k.uniform_movable = motus__splat(c->inverse_mass != 0 ? MOTUS_R(1.0) : MOTUS_R(0.0));
    arrays.inverse_mass = batch->inverse_mass;
    for (d = 0; d < 3; ++d) {
        arrays.position[d] = batch->position[d];
        arrays.velocity[d] = batch->velocity[d];
        arrays.force[d] = batch->force[d];
        k.gravity[d] = motus__splat(c->gravity[d]);
        k.attractor[d] = motus__splat(c->attractor[d]);
        k.bounds_min[d] = motus__splat(c->bounds_min[d]);
        k.bounds_max[d] = motus__splat(c->bounds_max[d]);
        partial.position[d] = buffer[d];
        partial.velocity[d] = buffer[3 + d];
        partial.force[d] = buffer[6 + d];
    }
    partial.inverse_mass = buffer[9];
    check[0] = check[1] = check[2] = motus__splat(0);
    head = MOTUS__VECTOR ? (int)(((uintptr_t)0 - (uintptr_t)(arrays.position[0] + i)) % MOTUS_SIMD_BYTES / sizeof(motus_real)) : 0;
    /* Whole vectors in place, starting on a vector boundary of the first position array (stores that
       straddle cache lines cost up to twice as much); then the partial vectors at either end, through a
       zero-padded copy, from one place so that each kernel's body is compiled twice, not three times. */
    if (!(head > 0 && head < end - i)) head = 0;
    whole_end = i + head + (end - i - head) / MOTUS__LANES * MOTUS__LANES;
    for (i += head; i < whole_end; i += MOTUS__LANES) motus__batch_lanes(&arrays, i, &k, dims, flags, check);
    part_start[0] = first;
    part_length[0] = head;
    part_start[1] = whole_end;
    part_length[1] = end - whole_end;
    for (part = 0; part < 2; ++part) {
        if (part_length[part] == 0) continue;
        motus__partial_copy(&arrays, part_start[part], &partial, part_length[part], dims, flags, 1);
        motus__batch_lanes(&partial, 0, &k, dims, flags, check);
        if (!(flags & MOTUS__K_DRY))
            motus__partial_copy(&arrays, part_start[part], &partial, part_length[part], dims, flags, 0);
    }
    check[0] = check[0] + check[1] + check[2];
#if MOTUS__VECTOR
    for (lane = 0; lane < MOTUS__LANES; ++lane) sum += check[0][lane];
#else
    (void)lane;
    sum = check[0];
#endif
    return !motus_real_is_finite(sum);
}

#define MOTUS__KERNEL_CASE(dims, flags)                                                                          \
    case (flags): return motus__batch_range(b, first, count, k, dims, flags);
#define MOTUS__KERNEL_CASES_8(dims, base)                                                                        \
    MOTUS__KERNEL_CASE(dims, (base) + 0) MOTUS__KERNEL_CASE(dims, (base) + 1) MOTUS__KERNEL_CASE(dims, (base) + 2)  \
    MOTUS__KERNEL_CASE(dims, (base) + 3) MOTUS__KERNEL_CASE(dims, (base) + 4) MOTUS__KERNEL_CASE(dims, (base) + 5)  \
    MOTUS__KERNEL_CASE(dims, (base) + 6) MOTUS__KERNEL_CASE(dims, (base) + 7)
#define MOTUS__GENERAL (MOTUS__K_GENERAL | MOTUS__K_DAMPING | MOTUS__K_BOUNDS)
/* One function per dimension count, each with its 68 kernels: the 64 fast ones and the general one for the
   4 combinations of the two optional arrays. */
#define MOTUS__KERNEL_DISPATCH(name, dims)                                                                       \
    MOTUS_API int name(const motus_batch *b, int first, int count, const motus__kernel_constants *k, int flags) {  \
        switch (flags) {                                                                                         \
            MOTUS__KERNEL_CASES_8(dims, 0)                                                                       \
            MOTUS__KERNEL_CASES_8(dims, 8)                                                                       \
            MOTUS__KERNEL_CASES_8(dims, 16)                                                                      \
            MOTUS__KERNEL_CASES_8(dims, 24)                                                                      \
            MOTUS__KERNEL_CASES_8(dims, 32)                                                                      \
            MOTUS__KERNEL_CASES_8(dims, 40)                                                                      \
            MOTUS__KERNEL_CASES_8(dims, 48)                                                                      \
            MOTUS__KERNEL_CASES_8(dims, 56)                                                                      \
            MOTUS__KERNEL_CASE(dims, MOTUS__GENERAL)                                                             \
            MOTUS__KERNEL_CASE(dims, MOTUS__GENERAL | MOTUS__K_MASS)                                             \
            MOTUS__KERNEL_CASE(dims, MOTUS__GENERAL | MOTUS__K_FORCES)                                           \
            MOTUS__KERNEL_CASE(dims, MOTUS__GENERAL | MOTUS__K_MASS | MOTUS__K_FORCES)                           \
        default: return -1;                                                                                      \
        }                                                                                                        \
    }
MOTUS__KERNEL_DISPATCH(motus__batch_dispatch2, 2)
MOTUS__KERNEL_DISPATCH(motus__batch_dispatch3, 3)
#undef MOTUS__KERNEL_DISPATCH
#ifdef MOTUS_CHECKED
/* The step without its stores, through the general kernel: it computes every term with neutral values for
   what the scene lacks, so it gives the values any kernel gives. Nonzero if one would not be finite. Only
   checked builds compile these 8 kernels. */
MOTUS_API int motus__batch_dry_run(const motus_batch *b, int first, int count, const motus__kernel_constants *k,
                                   int flags) {
    const int dry = MOTUS__GENERAL | MOTUS__K_DRY;
    switch ((flags & (MOTUS__K_MASS | MOTUS__K_FORCES)) + (b->dimensions == 3 ? 1 : 0)) {
    case 0: return motus__batch_range(b, first, count, k, 2, dry);
    case 1: return motus__batch_range(b, first, count, k, 3, dry);
    case MOTUS__K_MASS: return motus__batch_range(b, first, count, k, 2, dry | MOTUS__K_MASS);
    case MOTUS__K_MASS + 1: return motus__batch_range(b, first, count, k, 3, dry | MOTUS__K_MASS);
    case MOTUS__K_FORCES: return motus__batch_range(b, first, count, k, 2, dry | MOTUS__K_FORCES);
    case MOTUS__K_FORCES + 1: return motus__batch_range(b, first, count, k, 3, dry | MOTUS__K_FORCES);
    case MOTUS__K_MASS + MOTUS__K_FORCES: return motus__batch_range(b, first, count, k, 2, dry | MOTUS__K_MASS | MOTUS__K_FORCES);
    default: return motus__batch_range(b, first, count, k, 3, dry | MOTUS__K_MASS | MOTUS__K_FORCES);
    }
}
#endif
#undef MOTUS__KERNEL_CASES_8
#undef MOTUS__KERNEL_CASE

MOTUS_API int motus__scene_damping_flags(unsigned has) {
    return (int)(has & (MOTUS_HAS_DAMPING_PER_STEP | MOTUS_HAS_DAMPING_PER_SECOND));
}

/* Checks the scene against the batch: known features, a supported method, the arrays it needs, parameters
   in range. O(1); run by every step. */
MOTUS_API motus_result motus_scene_check(const motus_scene *scene, const motus_batch *batch) {
    const unsigned has = scene ? scene->has : 0;
    int d, dims;
    if (!scene || !batch) return MOTUS_ERROR_NULL_POINTER;
    dims = batch->dimensions;
    if ((has & ~MOTUS__HAS_KNOWN) || (dims != 2 && dims != 3) ||
        motus__scene_damping_flags(has) == (MOTUS_HAS_DAMPING_PER_STEP | MOTUS_HAS_DAMPING_PER_SECOND))
        return MOTUS_ERROR_INVALID_SCENE;
    if (scene->method != MOTUS_SEMI_IMPLICIT_EULER && scene->method != MOTUS_EXPLICIT_EULER)
        return MOTUS_ERROR_UNSUPPORTED;
    for (d = 0; d < dims; ++d) {
        if (!batch->position[d] || !batch->velocity[d]) return MOTUS_ERROR_NULL_POINTER;
        if ((has & MOTUS_HAS_FORCES) && !batch->force[d]) return MOTUS_ERROR_NULL_POINTER;
        if ((has & MOTUS_HAS_GRAVITY) && !motus_real_is_finite(scene->gravity[d])) return MOTUS_ERROR_NOT_FINITE;
        if ((has & MOTUS_HAS_ATTRACTOR) && !motus_real_is_finite(scene->attractor[d])) return MOTUS_ERROR_NOT_FINITE;
        if (has & MOTUS_HAS_BOUNDS) {
            if (!motus_real_is_finite(scene->bounds_min[d]) || !motus_real_is_finite(scene->bounds_max[d]))
                return MOTUS_ERROR_NOT_FINITE;
            if (!(scene->bounds_min[d] <= scene->bounds_max[d])) return MOTUS_ERROR_INVALID_SCENE;
        }
    }
    if ((has & MOTUS_HAS_PARTICLE_MASS) && !batch->inverse_mass) return MOTUS_ERROR_NULL_POINTER;
    if (!(has & MOTUS_HAS_PARTICLE_MASS)) {
        if (!motus_real_is_finite(scene->inverse_mass)) return MOTUS_ERROR_NOT_FINITE;
        if (scene->inverse_mass < 0) return MOTUS_ERROR_INVALID_MASS;
    }
    if (((has & MOTUS_HAS_LINEAR_DRAG) && !motus_real_is_finite(scene->linear_drag)) ||
        ((has & MOTUS_HAS_QUADRATIC_DRAG) && !motus_real_is_finite(scene->quadratic_drag)) ||
        ((has & MOTUS_HAS_ATTRACTOR) && !motus_real_is_finite(scene->attractor_strength)))
        return MOTUS_ERROR_NOT_FINITE;
    if (((has & MOTUS_HAS_LINEAR_DRAG) && scene->linear_drag < 0) ||
        ((has & MOTUS_HAS_QUADRATIC_DRAG) && scene->quadratic_drag < 0) ||
        ((has & MOTUS_HAS_ATTRACTOR) && scene->attractor_strength < 0))
        return MOTUS_ERROR_INVALID_FORCES;
    if (motus__scene_damping_flags(has) && !motus__damping_is_valid(scene->damping)) return MOTUS_ERROR_INVALID_DAMPING;
    if ((has & MOTUS_HAS_BOUNDS) && !motus_real_is_finite(scene->restitution)) return MOTUS_ERROR_NOT_FINITE;
    if ((has & MOTUS_HAS_BOUNDS) && !motus__damping_is_valid(scene->restitution)) return MOTUS_ERROR_INVALID_DAMPING;
    return MOTUS_OK;
}

/* The first particle in [first, first + count) with a NaN or Inf in a field the scene uses, or a negative
   inverse mass: MOTUS_OK, or the result with *bad_index and *bad_field ("position", "velocity", "force",
   "inverse_mass") set. Either output pointer may be NULL. Reads the range once. */
MOTUS_API motus_result motus_batch_check(const motus_scene *scene, const motus_batch *batch, int first, int count,
                                         int *bad_index, const char **bad_field) {
    motus_result result = motus_scene_check(scene, batch);
    int i, d;
    if (result != MOTUS_OK) return result;
    if (first < 0 || count < 0 || count > INT_MAX - first) return MOTUS_ERROR_INVALID_COUNT;
    for (i = first; i < first + count; ++i) {
        const char *field = NULL;
        if ((scene->has & MOTUS_HAS_PARTICLE_MASS) && !motus_real_is_finite(batch->inverse_mass[i])) field = "inverse_mass";
        for (d = 0; d < batch->dimensions && !field; ++d) {
            if (!motus_real_is_finite(batch->position[d][i])) field = "position";
            else if (!motus_real_is_finite(batch->velocity[d][i])) field = "velocity";
            else if ((scene->has & MOTUS_HAS_FORCES) && !motus_real_is_finite(batch->force[d][i])) field = "force";
        }
        result = field ? MOTUS_ERROR_NOT_FINITE : MOTUS_OK;
        if (!field && (scene->has & MOTUS_HAS_PARTICLE_MASS) && batch->inverse_mass[i] < 0) {
            field = "inverse_mass";
            result = MOTUS_ERROR_INVALID_MASS;
        }
        if (field) {
            if (bad_index) *bad_index = i;
            if (bad_field) *bad_field = field;
            return result;
        }
    }
    return MOTUS_OK;
}

/* Steps particles [first, first + count) of `batch` by dt through `scene` (see the top of this section).
   Thread-safe for ranges that do not overlap. Release builds: on MOTUS_ERROR_NOT_FINITE the range was
   written (the data had NaN/Inf, or overflowed); with MOTUS_CHECKED, bad data (MOTUS_ERROR_NOT_FINITE) and
   overflow (MOTUS_ERROR_OVERFLOW) are found first and nothing is written. Every other error is found before
   anything is written. */
MOTUS_API motus_result motus_batch_step(const motus_scene *scene, const motus_batch *batch, int first, int count,
                                        motus_real dt) {
    motus__kernel_constants k;
    motus_result result = motus_scene_check(scene, batch);
    const unsigned has = scene ? scene->has : 0;
    int flags = 0, d, broken;
    if (result != MOTUS_OK) return result;
    if (first < 0 || count < 0 || count > INT_MAX - first) return MOTUS_ERROR_INVALID_COUNT;
    if (!motus__is_positive_finite(dt)) return MOTUS_ERROR_INVALID_TIME_STEP;
#ifdef MOTUS_CHECKED
    result = motus_batch_check(scene, batch, first, count, NULL, NULL);
    if (result != MOTUS_OK) return result;
#endif
    if (count == 0) return MOTUS_OK;

    /* Neutral values for what the scene lacks: the general kernel computes every term. */
    k.h = dt;
    k.linear_drag = k.quadratic_drag = k.attractor_strength = k.restitution = 0;
    k.damping = 1;
    k.rest_speed = 0; /* no flush without damping (the general kernel always "damps", by 1) */
    k.semi_implicit = scene->method == MOTUS_SEMI_IMPLICIT_EULER;
    k.has_gravity = k.has_linear_drag = 0;
    k.inverse_mass = (has & MOTUS_HAS_PARTICLE_MASS) ? 0 : scene->inverse_mass;
    for (d = 0; d < 3; ++d) {
        k.gravity[d] = k.attractor[d] = 0;
        k.bounds_min[d] = -(motus_real)HUGE_VAL;
        k.bounds_max[d] = (motus_real)HUGE_VAL;
    }
    /* Gravity and linear drag count as on only when not zero, as in motus_stepper_step. */
    if (has & MOTUS_HAS_GRAVITY)
        for (d = 0; d < batch->dimensions; ++d) {
            k.gravity[d] = scene->gravity[d];
            k.has_gravity |= scene->gravity[d] != 0;
        }
    if (has & MOTUS_HAS_LINEAR_DRAG) {
        k.linear_drag = scene->linear_drag;
        k.has_linear_drag = scene->linear_drag != 0;
    }
    if (has & MOTUS_HAS_QUADRATIC_DRAG) k.quadratic_drag = scene->quadratic_drag;
    if (has & MOTUS_HAS_ATTRACTOR) {
        for (d = 0; d < batch->dimensions; ++d) k.attractor[d] = scene->attractor[d];
        k.attractor_strength = scene->attractor_strength;
    }
    if (has & MOTUS_HAS_DAMPING_PER_STEP) k.damping = scene->damping;
    if (has & MOTUS_HAS_DAMPING_PER_SECOND) k.damping = MOTUS_POW(scene->damping, dt); /* as damp_per_second */
    if (motus__scene_damping_flags(has)) k.rest_speed = (motus_real)(MOTUS_REST_SPEED);
    if (has & MOTUS_HAS_BOUNDS) {
        for (d = 0; d < batch->dimensions; ++d) {
            k.bounds_min[d] = scene->bounds_min[d];
            k.bounds_max[d] = scene->bounds_max[d];
        }
        k.restitution = scene->restitution;
    }

    if (k.has_gravity) flags |= MOTUS__K_GRAVITY;
    if (k.has_linear_drag) flags |= MOTUS__K_LINEAR_DRAG;
    if (motus__scene_damping_flags(has)) flags |= MOTUS__K_DAMPING;
    if (has & MOTUS_HAS_PARTICLE_MASS) flags |= MOTUS__K_MASS;
    if (has & MOTUS_HAS_FORCES) flags |= MOTUS__K_FORCES;
    if (has & MOTUS_HAS_BOUNDS) flags |= MOTUS__K_BOUNDS;
    if ((has & (MOTUS_HAS_QUADRATIC_DRAG | MOTUS_HAS_ATTRACTOR)) || !k.semi_implicit ||
        (!(has & MOTUS_HAS_PARTICLE_MASS) && scene->inverse_mass == 0))
        flags = (flags & (MOTUS__K_MASS | MOTUS__K_FORCES)) | MOTUS__GENERAL; /* gravity, drag: by mask */

#ifdef MOTUS_CHECKED
    /* The range was checked finite above: a non-finite result can only be an overflow. Find it before
       writing anything. */
    if (motus__batch_dry_run(batch, first, count, &k, flags)) return MOTUS_ERROR_OVERFLOW;
#endif
    broken = batch->dimensions == 2 ? motus__batch_dispatch2(batch, first, count, &k, flags)
                                    : motus__batch_dispatch3(batch, first, count, &k, flags);
    if (broken < 0) return MOTUS_ERROR_UNSUPPORTED; /* cannot happen: every flag combination has a kernel */
    if (broken) { /* the sum overflowed or a value is not finite: look at each one */
        int i;
        for (i = first; i < first + count; ++i) {
            if ((has & MOTUS_HAS_PARTICLE_MASS) && !motus_real_is_finite(batch->inverse_mass[i]))
                return MOTUS_ERROR_NOT_FINITE;
            for (d = 0; d < batch->dimensions; ++d)
                if (!motus_real_is_finite(batch->position[d][i]) || !motus_real_is_finite(batch->velocity[d][i]))
                    return MOTUS_ERROR_NOT_FINITE;
        }
    }
    return MOTUS_OK;
}

/* springs[0, n) checked as motus_forces_check(count) checks them, several springs a vector: where a spring is
   a whole number of words of motus__bits (7 of 4 bytes in float, 6 of 8 in double: ints first, then reals),
   L springs are W vectors of L words whose field pattern repeats every W vectors; lane masks pick the tests
   each word gets. The last springs go one at a time. count >= 0. */
#if MOTUS__VECTOR && defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
#define MOTUS__SPRINGS_VECTOR 1
typedef motus__bits motus__words __attribute__((vector_size(MOTUS_SIMD_BYTES), aligned(sizeof(int)), may_alias));
#else
#define MOTUS__SPRINGS_VECTOR 0
#endif
MOTUS_API motus_result motus__springs_check(const motus_spring *springs, int n, int count) {
    motus__bits not_finite = 0;
    int out_of_range = 0, i = 0;
#if MOTUS__SPRINGS_VECTOR
    enum { WORDS = (int)(sizeof(motus_spring) / sizeof(motus__bits)), INTS = (int)(2 * sizeof(int) / sizeof(motus__bits)) };
    const int layout_ok = sizeof(motus_spring) == WORDS * sizeof(motus__bits) && offsetof(motus_spring, anchor) == 2 * sizeof(int) &&
                          offsetof(motus_spring, damping) == sizeof(motus_spring) - sizeof(motus_real);
    if (layout_ok && n > MOTUS__LANES) {
        const motus__bits *words = (const motus__bits *)(const void *)springs;
        motus__words real_field[WORDS], negative_field[WORDS], index_field[WORDS], nf, bad;
        int v, lane;
        for (v = 0; v < WORDS; ++v)
            for (lane = 0; lane < MOTUS__LANES; ++lane) {
                const int field = (v * MOTUS__LANES + lane) % WORDS; /* word index within its spring */
                real_field[v][lane] = field >= INTS ? ~(motus__bits)0 : 0;
                negative_field[v][lane] = field >= WORDS - 3 ? ~(motus__bits)0 : 0; /* rest length, stiffness, damping */
                index_field[v][lane] = field == 0 ? ~(motus__bits)0 : 0;
            }
        nf = bad = real_field[0] ^ real_field[0];
        /* A block reads one word past its last spring (b beside a, in float): stop a spring early. */
        for (; i + MOTUS__LANES < n; i += MOTUS__LANES) {
            const motus__bits *block = words + (size_t)i * WORDS;
            for (v = 0; v < WORDS; ++v) {
                const motus__words w = *(const motus__words *)(const void *)(block + v * MOTUS__LANES);
                nf |= ((w & (motus__bits)~MOTUS__SIGN_BIT) + (MOTUS__EXPONENT_MASK & (motus__bits)~(MOTUS__EXPONENT_MASK << 1))) & real_field[v];
                bad |= (motus__words)(w > MOTUS__SIGN_BIT) & negative_field[v];
#ifdef MOTUS_DOUBLE /* a and b share word 0: a the low half, b the high half (little-endian) */
                {
                    const motus__words a = w & 0xFFFFFFFFu, b = w >> 32;
                    bad |= (motus__words)((a >= (motus__bits)count) | (((b + 1) & 0xFFFFFFFFu) > (motus__bits)count) | (a == b)) &
                           index_field[v];
                }
#else /* a in word 0, b in word 1: the next word */
                {
                    const motus__words b = *(const motus__words *)(const void *)(block + v * MOTUS__LANES + 1);
                    bad |= (motus__words)((w >= (motus__bits)count) | (b + 1 > (motus__bits)count) | (w == b)) & index_field[v];
                }
#endif
            }
        }
        for (lane = 0; lane < MOTUS__LANES; ++lane) {
            not_finite |= nf[lane];
            out_of_range |= bad[lane] != 0;
        }
    }
#endif
    for (; i < n; ++i) motus__spring_check(&springs[i], count, &not_finite, &out_of_range);
    if (not_finite & MOTUS__SIGN_BIT) return MOTUS_ERROR_NOT_FINITE;
    return out_of_range ? MOTUS_ERROR_INVALID_FORCES : MOTUS_OK;
}

/* The force spring `s` puts on its first end (the second gets its opposite), from the batch's state. */
MOTUS__INLINE motus_vec2 motus__batch_spring_force(const motus_batch *batch, const motus_spring *s) {
    const int a = s->a, b = s->b, anchored = b < 0;
    motus_vec2 xa = motus_v2(batch->position[0][a], batch->position[1][a]);
    motus_vec2 va = motus_v2(batch->velocity[0][a], batch->velocity[1][a]);
    motus_vec2 d = motus_vec2_sub(xa, anchored ? s->anchor : motus_v2(batch->position[0][b], batch->position[1][b]));
    motus_vec2 relative = anchored ? va : motus_vec2_sub(va, motus_v2(batch->velocity[0][b], batch->velocity[1][b]));
    return motus__spring_force(s, d, relative);
}

#ifdef MOTUS_CHECKED
MOTUS__INLINE motus_real motus__abs(motus_real x) { return x < 0 ? -x : x; }

/* Checked builds: would adding the springs' forces make a force not finite? Writes nothing. Each spring's
   force and each force it adds to must be finite; then no running sum may overflow. A bound settles that
   in one pass: B starts at the largest |force| the springs touch and adds |f| of every spring in order.
   Rounding is monotonic, so each particle's running sum, summed in that order, never exceeds B in
   magnitude: if B is finite, nothing overflows. Only when B is not (forces within a few springs' worth
   of the largest real) is each touched particle's sum replayed exactly, in O(spring_count^2). */
static motus_result motus__batch_springs_would_overflow(const motus_batch *batch, const motus_spring *springs,
                                                        int spring_count) {
    motus_real bound[2] = {0, 0};
    int i, j, c, end;
    for (i = 0; i < spring_count; ++i)
        for (end = 0; end < 2; ++end) {
            const int p = end ? springs[i].b : springs[i].a;
            for (c = 0; c < 2 && p >= 0; ++c) {
                const motus_real force = batch->force[c][p];
                if (!motus_real_is_finite(force)) return MOTUS_ERROR_NOT_FINITE;
                if (motus__abs(force) > bound[c]) bound[c] = motus__abs(force);
            }
        }
    for (i = 0; i < spring_count; ++i) {
        const motus_vec2 f = motus__batch_spring_force(batch, &springs[i]);
        if (!motus_vec2_is_finite(f)) return MOTUS_ERROR_NOT_FINITE;
        bound[0] += motus__abs(f.x);
        bound[1] += motus__abs(f.y);
    }
    if (motus_real_is_finite(bound[0]) && motus_real_is_finite(bound[1])) return MOTUS_OK;
    /* Exact: for each particle, at the first spring that touches it, replay its sum (springs have a != b). */
    for (i = 0; i < spring_count; ++i)
        for (end = 0; end < 2; ++end) {
            const int p = end ? springs[i].b : springs[i].a;
            int seen_before = 0;
            motus_real sum[2];
            if (p < 0) continue;
            for (j = 0; j < i && !seen_before; ++j) seen_before = springs[j].a == p || springs[j].b == p;
            if (seen_before) continue;
            sum[0] = batch->force[0][p];
            sum[1] = batch->force[1][p];
            for (j = i; j < spring_count; ++j) {
                motus_vec2 f;
                if (springs[j].a != p && springs[j].b != p) continue;
                f = motus__batch_spring_force(batch, &springs[j]);
                if (springs[j].a == p) { sum[0] += f.x; sum[1] += f.y; }
                else { sum[0] -= f.x; sum[1] -= f.y; } /* the second end gets -f */
                if (!motus_real_is_finite(sum[0]) || !motus_real_is_finite(sum[1])) return MOTUS_ERROR_NOT_FINITE;
            }
        }
    return MOTUS_OK;
}
#endif

/* Adds the forces of `springs` (see motus_spring) to the force arrays of a 2D batch of `count` particles,
   as motus_stepper_step sums them; call it once per step for the whole batch, before stepping its ranges.
   Like motus_batch_step, a release build reads the data once: a NaN or Inf among the spring ends, or a sum
   that overflows, gives MOTUS_ERROR_NOT_FINITE after the forces were added. With MOTUS_CHECKED a spring
   whose force or end forces are not finite, or a sum that would overflow, is found first, and nothing is
   written. */
MOTUS_API motus_result motus_batch_add_spring_forces(const motus_batch *batch, int count, const motus_spring *springs,
                                                     int spring_count) {
    motus_result result;
    motus__bits not_finite = 0;
    int i;
    if (!batch) return MOTUS_ERROR_NULL_POINTER;
    if (count < 0) return MOTUS_ERROR_INVALID_COUNT;
    if (batch->dimensions != 2 && batch->dimensions != 3) return MOTUS_ERROR_INVALID_SCENE;
    if (batch->dimensions != 2) return MOTUS_ERROR_UNSUPPORTED;
    if (spring_count > 0 && (!batch->position[0] || !batch->position[1] || !batch->velocity[0] ||
                             !batch->velocity[1] || !batch->force[0] || !batch->force[1]))
        return MOTUS_ERROR_NULL_POINTER;
    if (spring_count < 0 || (spring_count > 0 && !springs)) return MOTUS_ERROR_INVALID_FORCES;
    result = motus__springs_check(springs, spring_count, count); /* as motus_forces_check, faster */
    if (result != MOTUS_OK) return result;
#ifdef MOTUS_CHECKED
    result = motus__batch_springs_would_overflow(batch, springs, spring_count);
    if (result != MOTUS_OK) return result;
#endif
    for (i = 0; i < spring_count; ++i) {
        const motus_spring *s = &springs[i];
        const int a = s->a, b = s->b;
        const motus_vec2 f = motus__batch_spring_force(batch, s);
        batch->force[0][a] += f.x;
        batch->force[1][a] += f.y;
        not_finite |= motus__not_finite_bits(batch->force[0][a]) | motus__not_finite_bits(batch->force[1][a]);
        if (b >= 0) {
            batch->force[0][b] -= f.x;
            batch->force[1][b] -= f.y;
            not_finite |= motus__not_finite_bits(batch->force[0][b]) | motus__not_finite_bits(batch->force[1][b]);
        }
    }
    /* Every force written (a NaN or Inf the arrays held, a spring's, or a sum that overflowed), tested by bit
       operations that the loop ORs up. */
    return (not_finite & MOTUS__SIGN_BIT) ? MOTUS_ERROR_NOT_FINITE : MOTUS_OK;
}

/* =================================================================================================
   Fixed-step clock: the game loop's accumulator
   =================================================================================================
   Frames take whatever time they take; the simulation should not (see DAMPING at the top). The clock turns
   each frame's duration into a whole number of steps of one fixed dt and carries the rest over to the next
   frame (G. Fiedler, "Fix your timestep", 2004):

       motus_clock clock;
       motus_clock_init(&clock, MOTUS_R(1.0) / 60, 0);        // dt 1/60 s, at most 8 steps a frame
       // every frame:
       int steps, i;
       motus_clock_advance(&clock, frame_seconds, &steps);
       for (i = 0; i < steps; ++i) { previous = p.position; ...forces...; motus_particle_step(&p, clock.fixed_dt); }
       draw(motus_vec2_lerp(previous, p.position, motus_clock_alpha(&clock)));

   The same inputs stepped through the clock give the same states at any frame rate: only the number of
   steps per frame changes, never their dt. Drawing the state interpolated by alpha between the last two
   steps hides the beat between frame rate and step rate, at the cost of showing the past by < 1 step.

   Spiral of death: a long frame (a 2 s hitch: loading, a breakpoint, a dragged window) asks for many
   steps, which make the next frame long too. The clock runs at most max_steps_per_frame steps and drops
   the whole steps beyond that (the fraction of a step left over is kept, so alpha stays smooth): the game
   slows down instead of launching everything. The fields steps_dropped_* and time_dropped_* report it.

   The accumulator counts integer ticks, 2^32 to a step, rather than seconds in a motus_real: a frame of
   exactly dt (or k*dt) is exactly 2^32 (k*2^32) ticks, so a 60 Hz game with dt 1/60 takes exactly one step
   every frame for ever, with no comparison of two nearly equal reals; adding and subtracting ticks is
   exact, so the leftover never drifts over a long run (a float accumulator of seconds rounds at every
   frame, and a double one still decides "one step or none" by comparing two sums that differ by rounding);
   the float and double builds count the same. Each frame is rounded once to the nearest tick, computed in
   double: 2^-33 of a step at most. alpha = leftover / 2^32 is in [0, 1) by construction. */

/* Steps a frame may run when motus_clock_init is given 0: 8 steps of 1/60 s cover frames up to 133 ms
   (7.5 frames a second) before time is dropped. */
#ifndef MOTUS_CLOCK_DEFAULT_MAX_STEPS
#define MOTUS_CLOCK_DEFAULT_MAX_STEPS 8
#endif
#define MOTUS__CLOCK_TICKS_PER_STEP 4294967296.0 /* 2^32 */
#define MOTUS__CLOCK_TICK_MASK 0xFFFFFFFFu

typedef struct motus_clock {
    motus_real fixed_dt;                 /* s, the dt of every step */
    int max_steps_per_frame;             /* the cap against the spiral of death */
    uint64_t accumulator;                /* ticks not stepped yet: < 2^32 (one step) between frames */
    uint64_t steps_total;                /* steps run since init: simulated time = steps_total * fixed_dt */
    uint64_t steps_dropped_last_frame;   /* whole steps the cap dropped in the last advance */
    uint64_t steps_dropped_total;        /* since init */
    motus_real time_dropped_last_frame;  /* s, dropped in the last advance */
    double time_dropped_total;           /* s, since init; a double so that a float build's sum holds */
} motus_clock;

/* fixed_dt must be finite and > 0; max_steps_per_frame >= 0, where 0 means MOTUS_CLOCK_DEFAULT_MAX_STEPS. */
MOTUS_API motus_result motus_clock_init(motus_clock *clock, motus_real fixed_dt, int max_steps_per_frame) {
    if (!clock) return MOTUS_ERROR_NULL_POINTER;
    if (!motus__is_positive_finite(fixed_dt)) return MOTUS_ERROR_INVALID_TIME_STEP;
    if (max_steps_per_frame < 0) return MOTUS_ERROR_INVALID_COUNT;
    clock->fixed_dt = fixed_dt;
    clock->max_steps_per_frame = max_steps_per_frame ? max_steps_per_frame : MOTUS_CLOCK_DEFAULT_MAX_STEPS;
    clock->accumulator = 0;
    clock->steps_total = 0;
    clock->steps_dropped_last_frame = 0;
    clock->steps_dropped_total = 0;
    clock->time_dropped_last_frame = 0;
    clock->time_dropped_total = 0;
    return MOTUS_OK;
}

/* Adds a frame that lasted frame_seconds (finite and >= 0; 0 runs no step) and sets *steps_to_run to the
   fixed steps to run now, at most max_steps_per_frame. A negative, NaN or infinite frame time returns
   MOTUS_ERROR_INVALID_FRAME_TIME with the clock left as it was and *steps_to_run 0, so that a loop which
   ignores the result runs nothing. A clock that motus_clock_init did not make is MOTUS_ERROR_INVALID_COUNT. */
MOTUS_API motus_result motus_clock_advance(motus_clock *clock, motus_real frame_seconds, int *steps_to_run) {
    double frame_steps, dt;
    uint64_t ticks, steps, cap, dropped = 0;
    motus_real time_dropped = 0;
    if (!clock || !steps_to_run) return MOTUS_ERROR_NULL_POINTER;
    *steps_to_run = 0;
    if (!motus_real_is_finite(frame_seconds) || frame_seconds < 0) return MOTUS_ERROR_INVALID_FRAME_TIME;
    if (!motus__is_positive_finite(clock->fixed_dt) || clock->max_steps_per_frame <= 0 ||
        clock->accumulator > MOTUS__CLOCK_TICK_MASK)
        return MOTUS_ERROR_INVALID_COUNT;
    dt = (double)clock->fixed_dt;
    cap = (uint64_t)clock->max_steps_per_frame;
    frame_steps = (double)frame_seconds / dt;
    if (frame_steps < 2147483648.0) { /* < 2^31 steps: the ticks fit in 64 bits, counted exactly */
        ticks = clock->accumulator + (uint64_t)(frame_steps * MOTUS__CLOCK_TICKS_PER_STEP + 0.5);
        steps = ticks >> 32;
        clock->accumulator = ticks & MOTUS__CLOCK_TICK_MASK;
        if (steps > cap) {
            dropped = steps - cap;
            time_dropped = (motus_real)((double)dropped * dt);
            steps = cap;
        }
    } else { /* a frame of 2^31 steps or more (cap <= INT_MAX < 2^31): a fraction of a step is noise */
        steps = cap;
        dropped = frame_steps < 1.8e19 ? (uint64_t)frame_steps - cap : ~(uint64_t)0;
        time_dropped = (motus_real)((double)frame_seconds - (double)cap * dt);
    }
    clock->steps_dropped_last_frame = dropped;
    clock->steps_dropped_total += dropped;
    clock->time_dropped_last_frame = time_dropped;
    clock->time_dropped_total += (double)time_dropped;
    clock->steps_total += steps;
    *steps_to_run = (int)steps;
    return MOTUS_OK;
}

/* How far the clock is between the last step run and the next one, in [0, 1): the weight of the newest
   state when drawing, position = lerp(before the last step, after it, alpha). 0 for a NULL clock. */
MOTUS_API motus_real motus_clock_alpha(const motus_clock *clock) {
    motus_real alpha;
    if (!clock || clock->accumulator > MOTUS__CLOCK_TICK_MASK) return 0;
    alpha = (motus_real)((double)clock->accumulator / MOTUS__CLOCK_TICKS_PER_STEP);
    /* In float a leftover within 2^-25 of a step rounds up to 1: keep alpha below 1 as promised. */
    return alpha < 1 ? alpha : 1 - MOTUS_REAL_EPSILON / 2;
}

/* Simulated seconds since init: steps_total * fixed_dt, in double (exact up to 2^53 steps' rounding). */
MOTUS_API double motus_clock_time(const motus_clock *clock) {
    if (!clock) return 0;
    return (double)clock->steps_total * (double)clock->fixed_dt;
}

/* a + (b - a)*t: t = 0 gives a exactly; for drawing a state between two steps with t = motus_clock_alpha. */
MOTUS_API motus_vec2 motus_vec2_lerp(motus_vec2 a, motus_vec2 b, motus_real t) {
    return motus_vec2_add(a, motus_vec2_scale(motus_vec2_sub(b, a), t));
}

/* =================================================================================================
   Validation and messages
   =================================================================================================
   BAD INPUT: WHAT EACH BUILD CHECKS
   Every function that can be handed bad input returns a motus_result, and checks the arguments it takes
   and the data it reads before anything is written. The rules, the same for every function:
   - NULL where memory is needed: MOTUS_ERROR_NULL_POINTER. Memory is not needed for a count of 0
     (particles, springs) nor for batch arrays the scene does not have.
   - A count of 0 is valid: MOTUS_OK and nothing written. motus_stepper_step with count 0 is a step of an
     empty world: its clock still advances by dt, and (as on any change of count) it forgets the last
     displacements of position Verlet and a kept acceleration.
   - count < 0, first < 0, first + count past INT_MAX, count above a stepper's capacity, a force model
     used with count < 0: MOTUS_ERROR_INVALID_COUNT. motus cannot know how long your arrays are: a range
     inside INT_MAX but past the end of an array is yours to avoid.
   - dt not finite or not > 0 (-0 included): MOTUS_ERROR_INVALID_TIME_STEP, before anything else is read.
   - NaN or Inf in an argument, a force model, a scene or a particle field the function reads:
     MOTUS_ERROR_NOT_FINITE. A damping factor is a fraction, so a NaN one is out of its range [0, 1]:
     MOTUS_ERROR_INVALID_DAMPING (a NaN restitution or drag rate is MOTUS_ERROR_NOT_FINITE).
   - mass <= 0 or 1/mass infinite, inverse mass < 0: MOTUS_ERROR_INVALID_MASS. An inverse mass of -Inf is
     both; motus_particle_check and the batch checks say NOT_FINITE, the steps say INVALID_MASS.
   - Finite inputs whose result is not finite (a huge force, a huge dt): MOTUS_ERROR_OVERFLOW. So is a
     NaN or Inf that a force callback returned: the inputs motus can see were finite.
   - Unknown bits in motus_stepper_desc.flags, or scratch not aligned for motus_real:
     MOTUS_ERROR_INVALID_DESC; unknown MOTUS_HAS_* bits in a scene: MOTUS_ERROR_INVALID_SCENE.
   On any result but MOTUS_OK nothing was written (particles, the stepper and what it keeps between steps,
   force arrays), in every build, with one exception: bad particle data in the batch kernels' release
   builds. A stepper's scratch is working memory: a step computes there before it decides, so only the
   part kept between steps (position Verlet's displacements, a kept acceleration) is sure to stay.

   Release builds check all of the above. The particle functions and motus_stepper_step are all or
   nothing at no extra pass over the data: the new state is computed aside, summed (a NaN or Inf makes the
   sum so), and written only if the sum is finite; only a sum that is not finite has its values looked at
   one by one, to name the cause. The batch kernels check the scene and the arguments (O(1)) but read the
   particle data once: a NaN or Inf in it, or an overflow, makes motus_batch_step and
   motus_batch_add_spring_forces return MOTUS_ERROR_NOT_FINITE after they wrote, and a negative
   batch.inverse_mass[i] is not looked for.
   Checked builds (define MOTUS_CHECKED) find bad batch data first: motus_batch_step runs
   motus_batch_check over its range, motus_batch_add_spring_forces computes every spring force first and
   makes sure that no particle's sum of them overflows, and on bad data nothing is written (a negative
   inverse mass is then MOTUS_ERROR_INVALID_MASS).
   Either build: call motus_particles_check or motus_batch_check_report where data comes in (a file, the
   network, an editor) to learn which particle and which field is bad. */

MOTUS_API const char *motus_result_string(motus_result result) {
    switch (result) {
    case MOTUS_OK: return "ok";
    case MOTUS_ERROR_NULL_POINTER:
        return "a pointer argument was NULL, or an array that the count or the scene needs; pass valid memory";
    case MOTUS_ERROR_NOT_FINITE:
        return "an input was NaN or infinite (an argument, a particle field, a force or scene value); all must be "
               "finite";
    case MOTUS_ERROR_INVALID_MASS:
        return "mass must be finite and > 0, with 1/mass finite; inverse mass must be >= 0 (0 = immovable)";
    case MOTUS_ERROR_INVALID_TIME_STEP: return "time step dt must be finite and > 0 seconds (not 0, negative, NaN or Inf)";
    case MOTUS_ERROR_INVALID_DAMPING:
        return "damping factor or restitution must be in [0, 1] (NaN is not), drag rate must be >= 0";
    case MOTUS_ERROR_OVERFLOW:
        return "the inputs were finite but the result would not be (overflow, or NaN from a force callback); "
               "nothing was written: use a smaller dt or smaller forces";
    case MOTUS_ERROR_INVALID_COUNT:
        return "count or range out of bounds: count and first must be >= 0, first + count <= INT_MAX, count at "
               "most the stepper's capacity";
    case MOTUS_ERROR_INVALID_FORCES:
        return "force model out of range: drags, attractor strength, stiffness, spring damping and rest length "
               "must be >= 0; spring ends in [0, count) with b = -1 for an anchor and a != b; springs not NULL";
    case MOTUS_ERROR_SCRATCH_TOO_SMALL:
        return "stepper memory too small: give at least motus_stepper_scratch_size(method, capacity) bytes";
    case MOTUS_ERROR_INVALID_SCENE:
        return "scene invalid: unknown MOTUS_HAS_* bit, both damping flags, dimensions not 2 or 3, or bounds "
               "min > max";
    case MOTUS_ERROR_UNSUPPORTED:
        return "unsupported: the exact stepper takes gravity and linear drag only, a batch semi-implicit or "
               "explicit Euler and springs in 2D only; or the method value is unknown";
    case MOTUS_ERROR_TOO_STIFF:
        return "springs too stiff for this dt: more substeps needed than allowed, or the method (explicit Euler, "
               "midpoint) is unstable on a spring at any dt";
    case MOTUS_ERROR_INVALID_ARGUMENT:
        return "argument out of range: a safety factor must be in (0, 1], a substep cap >= 1, a step limit >= 0";
    case MOTUS_ERROR_INVALID_DESC:
        return "stepper desc invalid: flags may only have MOTUS_STEPPER_* bits, scratch must be aligned for "
               "motus_real";
    case MOTUS_ERROR_INVALID_FRAME_TIME: return "frame time must be finite and >= 0 seconds; the clock was left as it was";
    case MOTUS_RESULT_COUNT: break;
    }
    return "unknown motus_result value";
}

/* The fields a check can find bad, in particles and in batches. */
typedef enum motus_field {
    MOTUS_FIELD_NONE = 0,
    MOTUS_FIELD_POSITION,
    MOTUS_FIELD_VELOCITY,
    MOTUS_FIELD_FORCE,
    MOTUS_FIELD_INVERSE_MASS,
    MOTUS_FIELD_COUNT
} motus_field;

/* "position", "velocity", "force", "inverse_mass" (the names motus_batch_check reports), "none" for
   MOTUS_FIELD_NONE, NULL for a value out of range. */
MOTUS_API const char *motus_field_name(motus_field field) {
    switch (field) {
    case MOTUS_FIELD_NONE: return "none";
    case MOTUS_FIELD_POSITION: return "position";
    case MOTUS_FIELD_VELOCITY: return "velocity";
    case MOTUS_FIELD_FORCE: return "force";
    case MOTUS_FIELD_INVERSE_MASS: return "inverse_mass";
    case MOTUS_FIELD_COUNT: break;
    }
    return NULL;
}

/* Where a check found the first bad particle. Filled by every call that is given one, whatever the result:
   index -1 and MOTUS_FIELD_NONE unless a particle is bad, so that it can be printed without a test. */
typedef struct motus_check_report {
    int index;              /* the first bad particle (its index in the array, or in the batch), or -1 */
    motus_field field;      /* which of its fields */
    int component;          /* 0 for x, 1 for y, 2 for z; -1 for the inverse mass and for none */
    const char *field_name; /* motus_field_name(field), never NULL */
} motus_check_report;

MOTUS_API void motus__report(motus_check_report *report, int index, motus_field field, int component) {
    if (!report) return;
    report->index = index;
    report->field = field;
    report->component = component;
    report->field_name = motus_field_name(field);
}

/* The first of particles[0..count) that motus_particle_check rejects, and its first bad field, in the
   order position x, y, velocity x, y, force x, y, inverse mass (not finite), then a negative inverse mass.
   Returns motus_particle_check's result for that particle: MOTUS_ERROR_NOT_FINITE or
   MOTUS_ERROR_INVALID_MASS; MOTUS_OK if all are fine (count 0 included: particles may then be NULL).
   `report` may be NULL. Reads each particle once; writes nothing but *report. */
MOTUS_API motus_result motus_particles_check(const motus_particle *particles, int count, motus_check_report *report) {
    int i, k;
    motus__report(report, -1, MOTUS_FIELD_NONE, -1);
    if (!particles && count > 0) return MOTUS_ERROR_NULL_POINTER;
    if (count < 0) return MOTUS_ERROR_INVALID_COUNT;
    for (i = 0; i < count; ++i) {
        const motus_particle *p = &particles[i];
        const motus_real values[6] = {p->position.x, p->position.y, p->velocity.x,
                                      p->velocity.y, p->force.x,    p->force.y};
        /* One combined test per particle: the loop that finds the field runs only for a bad particle. */
        if (motus_particle_check(p) == MOTUS_OK) continue;
        for (k = 0; k < 6; ++k)
            if (!motus_real_is_finite(values[k])) {
                motus__report(report, i, (motus_field)(MOTUS_FIELD_POSITION + k / 2), k % 2);
                return MOTUS_ERROR_NOT_FINITE;
            }
        motus__report(report, i, MOTUS_FIELD_INVERSE_MASS, -1);
        return motus_real_is_finite(p->inverse_mass) ? MOTUS_ERROR_INVALID_MASS : MOTUS_ERROR_NOT_FINITE;
    }
    return MOTUS_OK;
}

/* motus_batch_check with a motus_check_report: the same result and the same particle and field (same
   name), and the component. Fields in motus_batch_check's order: the inverse mass (not finite), then per
   dimension position, velocity, force, then a negative inverse mass. A result about the scene or the range
   leaves index -1. */
MOTUS_API motus_result motus_batch_check_report(const motus_scene *scene, const motus_batch *batch, int first,
                                                int count, motus_check_report *report) {
    int index = -1, d;
    motus_result result;
    motus__report(report, -1, MOTUS_FIELD_NONE, -1);
    result = motus_batch_check(scene, batch, first, count, &index, NULL);
    if (index < 0 || !report) return result;
    /* motus_batch_check found particle `index` bad: which field, in its order (O(1)). */
    if ((scene->has & MOTUS_HAS_PARTICLE_MASS) && !motus_real_is_finite(batch->inverse_mass[index])) {
        motus__report(report, index, MOTUS_FIELD_INVERSE_MASS, -1);
        return result;
    }
    for (d = 0; d < batch->dimensions; ++d) {
        motus_field field = MOTUS_FIELD_NONE;
        if (!motus_real_is_finite(batch->position[d][index])) field = MOTUS_FIELD_POSITION;
        else if (!motus_real_is_finite(batch->velocity[d][index])) field = MOTUS_FIELD_VELOCITY;
        else if ((scene->has & MOTUS_HAS_FORCES) && !motus_real_is_finite(batch->force[d][index]))
            field = MOTUS_FIELD_FORCE;
        if (field != MOTUS_FIELD_NONE) {
            motus__report(report, index, field, d);
            return result;
        }
    }
    motus__report(report, index, MOTUS_FIELD_INVERSE_MASS, -1); /* finite but negative */
    return result;
}

#ifdef __cplusplus
} /* extern "C" */
#endif

/* The contraction setting of the code that includes this header, back as it was (see Configuration). */
#if defined(MOTUS__FP_CONTRACT_PRAGMA_CLANG)
#pragma float_control(pop)
#elif defined(MOTUS__FP_CONTRACT_PRAGMA_GCC)
#pragma GCC pop_options
#endif

#endif /* MOTUS_H */

/*
------------------------------------------------------------------------------
MIT License

Copyright (c) 2026 the motus developers

Permission is hereby granted, free of charge, to any person obtaining a copy of
this software and associated documentation files (the "Software"), to deal in
the Software without restriction, including without limitation the rights to
use, copy, modify, merge, publish, distribute, sublicense, and/or sell copies
of the Software, and to permit persons to whom the Software is furnished to do
so, subject to the following conditions:

The above copyright notice and this permission notice shall be included in all
copies or substantial portions of the Software.

THE SOFTWARE IS PROVIDED "AS IS", WITHOUT WARRANTY OF ANY KIND, EXPRESS OR
IMPLIED, INCLUDING BUT NOT LIMITED TO THE WARRANTIES OF MERCHANTABILITY,
FITNESS FOR A PARTICULAR PURPOSE AND NONINFRINGEMENT. IN NO EVENT SHALL THE
AUTHORS OR COPYRIGHT HOLDERS BE LIABLE FOR ANY CLAIM, DAMAGES OR OTHER
LIABILITY, WHETHER IN AN ACTION OF CONTRACT, TORT OR OTHERWISE, ARISING FROM,
OUT OF OR IN CONNECTION WITH THE SOFTWARE OR THE USE OR OTHER DEALINGS IN THE
SOFTWARE.
------------------------------------------------------------------------------
*/
