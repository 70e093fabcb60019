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

#if defined(MOTUS_SQRT) || defined(MOTUS_EXP) || defined(MOTUS_EXPM1) || defined(MOTUS_POW)
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
    velocity = motus_vec2_add(particle->velocity, motus_vec2_scale(particle->force, particle->inverse_mass * dt));
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
