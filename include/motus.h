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
   - Functions that can be handed bad input return a motus_result; on any result other than MOTUS_OK the
     particle is left exactly as it was. motus_result_string turns a result into a sentence.
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
   - MOTUS_CHECKED         (undefined)      motus_batch_step checks every particle of its range before
                                            writing anything (see "Batch kernels": release builds don't).

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
#ifdef __cplusplus
#include <string.h> /* memcpy, for the same check in C++ */
#endif

/* =================================================================================================
   Configuration
   ================================================================================================= */
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
MOTUS_API int motus_real_is_finite(motus_real x) {
#ifdef __cplusplus
    motus__bits bits;
    memcpy(&bits, &x, sizeof bits);
#else
    union {
        motus_real real;
        motus__bits bits;
    } pun;
    motus__bits bits;
    pun.real = x;
    bits = pun.bits;
#endif
    return (bits & MOTUS__EXPONENT_MASK) != MOTUS__EXPONENT_MASK;
}
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

/* v *= factor_per_step, as the reference program does with 0.99 each frame. Frame-rate dependent: see
   DAMPING at the top. factor_per_step must be in [0, 1]: 1 keeps all speed, 0 stops the particle. */
MOTUS_API motus_result motus_particle_damp_per_step(motus_particle *particle, motus_real factor_per_step) {
    if (!particle) return MOTUS_ERROR_NULL_POINTER;
    if (!motus__damping_is_valid(factor_per_step)) return MOTUS_ERROR_INVALID_DAMPING;
    if (!motus_vec2_is_finite(particle->velocity)) return MOTUS_ERROR_NOT_FINITE;
    particle->velocity = motus_vec2_scale(particle->velocity, factor_per_step);
    return MOTUS_OK;
}

/* v *= retained_per_second^dt: after one second of steps the speed is retained_per_second times what it
   was, whatever dt was. retained_per_second must be in [0, 1]. Equivalent to linear drag with rate
   k = -ln(retained_per_second) applied to the velocity alone. */
MOTUS_API motus_result motus_particle_damp_per_second(motus_particle *particle, motus_real retained_per_second,
                                                      motus_real dt) {
    if (!particle) return MOTUS_ERROR_NULL_POINTER;
    if (!motus__is_positive_finite(dt)) return MOTUS_ERROR_INVALID_TIME_STEP;
    if (!motus__damping_is_valid(retained_per_second)) return MOTUS_ERROR_INVALID_DAMPING;
    if (!motus_vec2_is_finite(particle->velocity)) return MOTUS_ERROR_NOT_FINITE;
    particle->velocity = motus_vec2_scale(particle->velocity, MOTUS_POW(retained_per_second, dt));
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

/* MOTUS_OK if the model can be used with `count` particles: finite fields, non-negative drags, stiffness,
   damping, rest lengths and attractor strength, spring ends in [0, count) (b may be -1). */
MOTUS_API motus_result motus_forces_check(const motus_forces *forces, int count) {
    int i, not_finite = 0, out_of_range = 0;
    if (!forces) return MOTUS_ERROR_NULL_POINTER;
    if (!motus_vec2_is_finite(forces->gravity) || !motus_real_is_finite(forces->linear_drag) ||
        !motus_real_is_finite(forces->quadratic_drag) || !motus_real_is_finite(forces->attractor_strength) ||
        !motus_vec2_is_finite(forces->attractor_position))
        return MOTUS_ERROR_NOT_FINITE;
    if (forces->linear_drag < 0 || forces->quadratic_drag < 0 || forces->attractor_strength < 0 ||
        forces->spring_count < 0 || (forces->spring_count > 0 && !forces->springs))
        return MOTUS_ERROR_INVALID_FORCES;
    /* Every step runs this, so one combined test per spring rather than a branch per field. */
    for (i = 0; i < forces->spring_count; ++i) {
        const motus_spring *s = &forces->springs[i];
        not_finite |= (motus_vec2_is_finite(s->anchor) & motus_real_is_finite(s->rest_length) &
                       motus_real_is_finite(s->stiffness) & motus_real_is_finite(s->damping)) == 0;
        out_of_range |= (s->a < 0) | (s->a >= count) | (s->b < -1) | (s->b >= count) | (s->b == s->a) |
                        (s->rest_length < 0) | (s->stiffness < 0) | (s->damping < 0);
    }
    if (not_finite) return MOTUS_ERROR_NOT_FINITE;
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
   FOREST_RUTH              4      3       yes      w*h < 1.57     -                 v at each kick: 1st order
     Forest-Ruth (Yoshida's 4th-order triple jump of leapfrog), theta = 1/(2 - 2^(1/3)):
     drift theta*h/2, kick theta*h, drift (1-theta)*h/2, kick (1-2*theta)*h, drift (1-theta)*h/2,
     kick theta*h, drift theta*h/2. Symplectic and 4th order for forces of position only; a kick with a
     velocity-dependent force is an explicit Euler step in v, which makes the whole method first order
     (use RK4 or the exact stepper for drag). Its large negative middle step is why its stability
     limit (1.57) is lower than leapfrog's.
   EXACT_LINEAR_DRAG        exact  0       -        always         -                 exact (linear drag)
     Solves v' = g + F/m - k*v over the step (see motus_particle_step_linear_drag). Only for gravity,
     linear drag and the accumulated force; other terms give MOTUS_ERROR_UNSUPPORTED.

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
    unsigned flags; /* MOTUS_STEPPER_* */
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

MOTUS_API motus_result motus_stepper_init(motus_stepper *stepper, const motus_stepper_desc *desc) {
    size_t needed;
    if (!stepper || !desc) return MOTUS_ERROR_NULL_POINTER;
    if ((unsigned)desc->method >= MOTUS_METHOD_COUNT) return MOTUS_ERROR_UNSUPPORTED;
    if (desc->capacity < 0) return MOTUS_ERROR_INVALID_COUNT;
    needed = motus_stepper_scratch_size(desc->method, desc->capacity);
    if (needed == 0 && desc->capacity > 0) return MOTUS_ERROR_INVALID_COUNT;
    if (desc->scratch_bytes < needed) return MOTUS_ERROR_SCRATCH_TOO_SMALL;
    if (!desc->scratch && needed > 0) return MOTUS_ERROR_NULL_POINTER;
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
   stepper's method. On any result but MOTUS_OK nothing is written: not the particles, not the stepper. */
MOTUS_API motus_result motus_stepper_step(motus_stepper *stepper, motus_particle *particles, int count,
                                          const motus_forces *forces, motus_real dt) {
    static const motus_forces no_forces = {{0, 0}, 0, 0, 0, {0, 0}, NULL, 0, NULL, NULL};
    motus_vec2 *x, *v, *a, no_scratch[1];
    const motus_real h = dt, t = stepper ? stepper->time : 0;
    motus_result result;
    int i, reuse, bad = 0, checked = 0, suspicious = 0;
    if (!stepper || (!particles && count > 0)) return MOTUS_ERROR_NULL_POINTER;
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
   (in a build without floating-point contraction: see -ffp-contract=off).

   Per particle and step, in this order (SI units; * is per component):
       a = F*inverse_mass + gravity - k*v - c*|v|*v - mu*r/|r|^3     (r from the attractor)
       v += a*h;  x += v*h           (semi-implicit Euler; explicit Euler moves x with the old v)
       v *= damping                  (per step), or damping^h (per second)
       bounds: past a wall, x is mirrored back and v *= -restitution; then x is clamped into the box
   Springs couple particles, so they are not part of the per-range step: motus_batch_add_spring_forces
   adds their forces to the force arrays for the whole batch first (2D).

   Checks: the scene and the arguments are checked on every call (O(1)). The particle data is not read
   twice in release builds: the kernel sums what it writes, and a NaN or Inf in the new state makes the
   step return MOTUS_ERROR_NOT_FINITE after the range was written. Define MOTUS_CHECKED to have every step
   check its range first (motus_batch_check) and write nothing on bad data; or call motus_batch_check
   yourself where data comes in. */

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
    motus_real h, gravity[3], linear_drag, quadratic_drag, damping, inverse_mass;
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

/* The constants as lanes, made once per call so that the loop does not redo them (nor reload them: the
   arrays it stores to could alias a motus_real in memory, but not these locals). */
typedef struct motus__kernel_lanes {
    motus__lane h, gravity[3], linear_drag, quadratic_drag, damping, inverse_mass;
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
        MOTUS__EACH_DIM(check[d] = check[d] + inverse_mass;); /* a NaN mass shows even without forces */
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
        if (flags & MOTUS__K_DAMPING) v[d] = v[d] * k->damping;
        /* Checked before the bounds, whose clamp would turn an infinite position into the wall; explicit
           Euler's new velocity does not reach its position, so the general kernel adds it too. */
        check[d] = check[d] + x[d];
        if (flags & MOTUS__K_GENERAL) check[d] = check[d] + v[d];
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
        motus__store(b->position[d] + i, x[d], n);
        motus__store(b->velocity[d] + i, v[d], n);
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
   written (the data had NaN/Inf, or overflowed); with MOTUS_CHECKED, bad data is found first and nothing is
   written. Every other error is found before anything is written. */
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

/* Adds the forces of `springs` (see motus_spring) to the force arrays of a 2D batch of `count` particles,
   as motus_stepper_step sums them; call it once per step for the whole batch, before stepping its ranges. */
MOTUS_API motus_result motus_batch_add_spring_forces(const motus_batch *batch, int count, const motus_spring *springs,
                                                     int spring_count) {
    motus_forces model = {{0, 0}, 0, 0, 0, {0, 0}, NULL, 0, NULL, NULL};
    motus_result result;
    int i;
    if (!batch) return MOTUS_ERROR_NULL_POINTER;
    if (count < 0) return MOTUS_ERROR_INVALID_COUNT;
    if (batch->dimensions != 2) return MOTUS_ERROR_UNSUPPORTED;
    if (spring_count > 0 && (!batch->position[0] || !batch->position[1] || !batch->velocity[0] ||
                             !batch->velocity[1] || !batch->force[0] || !batch->force[1]))
        return MOTUS_ERROR_NULL_POINTER;
    model.springs = springs;
    model.spring_count = spring_count;
    result = motus_forces_check(&model, count);
    if (result != MOTUS_OK) return result;
    for (i = 0; i < spring_count; ++i) {
        const motus_spring *s = &springs[i];
        const int a = s->a, b = s->b, anchored = b < 0;
        motus_vec2 xa = motus_v2(batch->position[0][a], batch->position[1][a]);
        motus_vec2 va = motus_v2(batch->velocity[0][a], batch->velocity[1][a]);
        motus_vec2 d = motus_vec2_sub(xa, anchored ? s->anchor : motus_v2(batch->position[0][b], batch->position[1][b]));
        motus_vec2 relative = anchored ? va : motus_vec2_sub(va, motus_v2(batch->velocity[0][b], batch->velocity[1][b]));
        motus_vec2 f = motus__spring_force(s, d, relative);
        batch->force[0][a] += f.x;
        batch->force[1][a] += f.y;
        if (!anchored) {
            batch->force[0][b] -= f.x;
            batch->force[1][b] -= f.y;
        }
    }
    return MOTUS_OK;
}

/* =================================================================================================
   Validation and messages
   ================================================================================================= */
MOTUS_API const char *motus_result_string(motus_result result) {
    switch (result) {
    case MOTUS_OK: return "ok";
    case MOTUS_ERROR_NULL_POINTER: return "a pointer argument was NULL";
    case MOTUS_ERROR_NOT_FINITE: return "an input was NaN or infinite (argument or particle field)";
    case MOTUS_ERROR_INVALID_MASS: return "mass must be finite and > 0 (inverse mass >= 0; 0 = immovable)";
    case MOTUS_ERROR_INVALID_TIME_STEP: return "time step must be finite and > 0 seconds";
    case MOTUS_ERROR_INVALID_DAMPING: return "damping factor must be in [0, 1] and drag rate >= 0";
    case MOTUS_ERROR_OVERFLOW: return "the result would overflow to infinity; state left unchanged";
    case MOTUS_ERROR_INVALID_COUNT: return "particle count must be >= 0 and at most the stepper's capacity";
    case MOTUS_ERROR_INVALID_FORCES:
        return "force model out of range: drags and attractor strength >= 0, spring indices valid, all finite";
    case MOTUS_ERROR_SCRATCH_TOO_SMALL: return "stepper memory too small: see motus_stepper_scratch_size()";
    case MOTUS_ERROR_INVALID_SCENE:
        return "scene invalid: unknown MOTUS_HAS_* bit, both dampings, dimensions not 2 or 3, or bounds min > max";
    case MOTUS_ERROR_UNSUPPORTED:
        return "this method cannot integrate these forces (the exact stepper takes gravity and linear drag only)";
    case MOTUS_RESULT_COUNT: break;
    }
    return "unknown motus_result value";
}

#ifdef __cplusplus
} /* extern "C" */
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
