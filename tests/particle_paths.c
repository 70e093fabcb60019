/* particle_paths.c - the textbook calls on (x, y) pairs end where the same calls one component at a time end.

   On x86-64 under GCC or Clang, motus.h runs motus_particle_add_force, _step, _damp_per_step and _bounce (and
   their 3D twins) on (x, y) as one SSE pair (see "(x, y) as one pair" in motus.h); MOTUS_NO_SIMD turns the
   pairs off. This program is built from two units: this one with the pairs, and particle_paths_scalar.c
   (this file again, with MOTUS_NO_SIMD) without. Every case hands both the same particle and arguments and
   requires the same result code and the same bytes of the particle afterwards:
   - each call alone, on particles and arguments drawn from values at the edges of each test: 0, -0,
     subnormals, the rest speed and its neighbours, the top of the pairs' damping window (about 2^27 m/s),
     the largest real, +-Inf, NaN, and ordinary values (random exponents, both signs);
   - a game's loop: 64 particles, the five calls a frame, 2,000 frames, with walls they hit.
   Float and double; 2D and 3D. Skipped (77) where the header has no pairs (not x86-64, or not GCC/Clang). */
#ifdef PARTICLE_PATHS_SCALAR
#define MOTUS_NO_SIMD
#define PATHS(name) scalar_##name
#else
#define MOTUS_IMPLEMENTATION
#define PATHS(name) pair_##name
#endif
#include "motus.h"

#include <stdio.h>
#include <string.h>

enum { CLEAR, ADD_FORCE, STEP, DAMP, BOUNCE, CALLS };

/* One call on one particle: `a` is the force or the walls' minimum, `b` the walls' maximum, `s` dt, the
   damping or the restitution. */
motus_result PATHS(call2)(motus_particle *p, int call, motus_vec2 a, motus_vec2 b, motus_real s);
motus_result PATHS(call3)(motus_particle3 *p, int call, motus_vec3 a, motus_vec3 b, motus_real s);
motus_result PATHS(call2)(motus_particle *p, int call, motus_vec2 a, motus_vec2 b, motus_real s) {
    switch (call) {
    case CLEAR: return motus_particle_clear_forces(p);
    case ADD_FORCE: return motus_particle_add_force(p, a);
    case STEP: return motus_particle_step(p, s);
    case DAMP: return motus_particle_damp_per_step(p, s);
    default: return motus_particle_bounce(p, a, b, s);
    }
}
motus_result PATHS(call3)(motus_particle3 *p, int call, motus_vec3 a, motus_vec3 b, motus_real s) {
    switch (call) {
    case CLEAR: return motus_particle3_clear_forces(p);
    case ADD_FORCE: return motus_particle3_add_force(p, a);
    case STEP: return motus_particle3_step(p, s);
    case DAMP: return motus_particle3_damp_per_step(p, s);
    default: return motus_particle3_bounce(p, a, b, s);
    }
}

#ifndef PARTICLE_PATHS_SCALAR
#include <float.h>
#include <math.h>
#include <stdint.h>

motus_result scalar_call2(motus_particle *p, int call, motus_vec2 a, motus_vec2 b, motus_real s);
motus_result scalar_call3(motus_particle3 *p, int call, motus_vec3 a, motus_vec3 b, motus_real s);

static uint64_t seed = 0x9E3779B97F4A7C15ull;
static uint64_t next(void) { /* splitmix64 */
    uint64_t z = (seed += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}
static int below(int n) { return (int)(next() % (uint64_t)n); }

#ifdef MOTUS_DOUBLE
#define LARGEST DBL_MAX
#define SMALLEST_SUBNORMAL 4.9406564584124654e-324
#define WINDOW_TOP 2.2e8 /* about where the pairs' damping window ends (rest speed * 2^1024, doubled bits) */
#else
#define LARGEST FLT_MAX
#define SMALLEST_SUBNORMAL 1.40129846e-45f
#define WINDOW_TOP 2.7e8f
#endif

/* A value at an edge of some test, or an ordinary one. */
static motus_real edge(void) {
    const motus_real rest = (motus_real)(MOTUS_REST_SPEED);
    const motus_real values[] = {0, -0.0f, SMALLEST_SUBNORMAL, -SMALLEST_SUBNORMAL, rest, -rest,
                                 rest * (1 + MOTUS_REAL_EPSILON), rest * (1 - MOTUS_REAL_EPSILON), rest * 2,
                                 MOTUS_R(0.5), 1, -1, WINDOW_TOP, -WINDOW_TOP, WINDOW_TOP * 2, WINDOW_TOP / 2,
                                 (motus_real)LARGEST, -(motus_real)LARGEST, (motus_real)LARGEST / 2,
                                 (motus_real)INFINITY, -(motus_real)INFINITY, (motus_real)NAN};
    const int count = (int)(sizeof values / sizeof values[0]);
    if (below(3) == 0) return values[below(count)];
    {   /* ordinary: a random sign and mantissa, an exponent from 2^-20 to 2^20 (sometimes much wider) */
        const int wide = below(8) == 0;
        const double mantissa = 1 + (double)(next() >> 11) / 9007199254740992.0;
        const int exponent = wide ? below(240) - 120 : below(41) - 20;
        const double value = ldexp(mantissa, exponent) * (below(2) ? -1 : 1);
        return (motus_real)value;
    }
}
/* An argument of the call: mostly valid, sometimes an edge. */
static motus_real argument(int call) {
    if (below(4) == 0) return edge();
    switch (call) {
    case STEP: return (motus_real)(1.0 / (30 + below(200)));
    case DAMP: return (motus_real)((1 + below(1000)) * 1e-4);
    default: return (motus_real)(below(1001) * 1e-3); /* restitution */
    }
}
static motus_real inverse_mass(void) {
    if (below(4) == 0) return edge();
    return (motus_real)ldexp(1 + (double)below(1000) / 1000, below(21) - 10);
}
/* Walls: mostly valid and around the origin, sometimes an edge on either side. */
static void walls(motus_real *lo, motus_real *hi) {
    *lo = below(4) == 0 ? edge() : -(motus_real)(1 + below(1000));
    *hi = below(4) == 0 ? edge() : (motus_real)(1 + below(1000));
}

/* A velocity component that damping by `damping` brings to within a few ulps of the rest speed, either
   side, or one that was an edge already. */
static motus_real near_rest(motus_real damping) {
    const motus_real kept = 1 - damping, rest = (motus_real)(MOTUS_REST_SPEED);
    if (below(4) == 0 || !(kept > 0 && kept <= 1)) return edge();
    return rest / kept * (1 + (motus_real)(below(9) - 4) * MOTUS_REAL_EPSILON) * (below(2) ? -1 : 1);
}

static long failures = 0;
static void report(const char *what, int dims, int call, long index, motus_result pair, motus_result scalar) {
    static const char *const names[] = {"clear_forces", "add_force", "step", "damp_per_step", "bounce"};
    if (failures++ < 10)
        fprintf(stderr, "%s: %dD %s, case %ld: pairs returned %d, one component at a time %d; the particles differ "
                        "or the codes do\n",
                what, dims, names[call], index, (int)pair, (int)scalar);
}

static void calls_alone(long cases) {
    long i;
    for (i = 0; i < cases; ++i) {
        const int call = below(CALLS), dims = 2 + below(2);
        const motus_real s = argument(call);
        motus_vec3 a, b;
        motus_real lo[3], hi[3];
        int k;
        for (k = 0; k < 3; ++k) walls(&lo[k], &hi[k]);
        a = call == BOUNCE ? motus_v3(lo[0], lo[1], lo[2]) : motus_v3(edge(), edge(), edge());
        b = motus_v3(hi[0], hi[1], hi[2]);
        if (dims == 2) {
            motus_particle p, q;
            motus_result rp, rq;
            p.position = motus_v2(edge(), edge());
            p.velocity = motus_v2(edge(), edge());
            p.force = motus_v2(edge(), edge());
            p.inverse_mass = inverse_mass();
            if (call == DAMP && below(3) == 0) p.velocity = motus_v2(near_rest(s), near_rest(s));
            q = p;
            rp = pair_call2(&p, call, motus_v2(a.x, a.y), motus_v2(b.x, b.y), s);
            rq = scalar_call2(&q, call, motus_v2(a.x, a.y), motus_v2(b.x, b.y), s);
            if (rp != rq || memcmp(&p, &q, sizeof p) != 0) report("alone", 2, call, i, rp, rq);
        } else {
            motus_particle3 p, q;
            motus_result rp, rq;
            p.position = motus_v3(edge(), edge(), edge());
            p.velocity = motus_v3(edge(), edge(), edge());
            p.force = motus_v3(edge(), edge(), edge());
            p.inverse_mass = inverse_mass();
            if (call == DAMP && below(3) == 0) p.velocity = motus_v3(near_rest(s), near_rest(s), near_rest(s));
            q = p;
            rp = pair_call3(&p, call, a, b, s);
            rq = scalar_call3(&q, call, a, b, s);
            if (rp != rq || memcmp(&p, &q, sizeof p) != 0) report("alone", 3, call, i, rp, rq);
        }
    }
}

/* A game's frame, 64 particles for 2,000 frames: clear, add the weight (and, now and then, a kick), step,
   damp, bounce off walls they reach. */
static void game_loop(int dims) {
    enum { COUNT = 64, FRAMES = 2000 };
    static motus_particle a2[COUNT], b2[COUNT];
    static motus_particle3 a3[COUNT], b3[COUNT];
    const motus_real dt = MOTUS_R(1.0) / 60, damping = MOTUS_R(0.01), restitution = MOTUS_R(0.8);
    const motus_vec3 lo = motus_v3(-10, -10, -10), hi = motus_v3(10, 10, 10);
    long frame;
    int i, c;
    for (i = 0; i < COUNT; ++i) {
        const motus_real x = (motus_real)(i % 8) - 4, y = (motus_real)(i / 8) - 4, mass = (motus_real)(1 + i % 5);
        motus_particle_init(&a2[i], motus_v2(x, y), mass);
        motus_particle3_init(&a3[i], motus_v3(x, y, x * y / 4), mass);
        a2[i].velocity = motus_v2((motus_real)(i % 7) - 3, 0); /* a zero component, at rest along y */
        a3[i].velocity = motus_v3(0, (motus_real)(i % 5) - 2, (motus_real)(i % 3));
        b2[i] = a2[i];
        b3[i] = a3[i];
    }
    for (frame = 0; frame < FRAMES; ++frame) {
        for (i = 0; i < COUNT; ++i) {
            const motus_real mass = (motus_real)(1 + i % 5);
            const motus_vec3 weight = motus_v3(0, -MOTUS_R(9.81) * mass, 0);
            const motus_vec3 kick = (frame + i) % 97 == 0 ? motus_v3(400, 900, -300) : motus_v3(0, 0, 0);
            for (c = 0; c < CALLS; ++c) {
                const motus_vec3 arg = c == ADD_FORCE ? weight : lo;
                const motus_real s = c == STEP ? dt : c == DAMP ? damping : restitution;
                motus_result rp, rq;
                if (dims == 2) {
                    rp = pair_call2(&a2[i], c, motus_v2(arg.x, arg.y), motus_v2(hi.x, hi.y), s);
                    rq = scalar_call2(&b2[i], c, motus_v2(arg.x, arg.y), motus_v2(hi.x, hi.y), s);
                    if (c == ADD_FORCE) {
                        rp |= pair_call2(&a2[i], c, motus_v2(kick.x, kick.y), motus_v2(0, 0), 0);
                        rq |= scalar_call2(&b2[i], c, motus_v2(kick.x, kick.y), motus_v2(0, 0), 0);
                    }
                    if (rp != rq || memcmp(&a2[i], &b2[i], sizeof a2[i]) != 0) report("game loop", 2, c, frame, rp, rq);
                } else {
                    rp = pair_call3(&a3[i], c, arg, hi, s);
                    rq = scalar_call3(&b3[i], c, arg, hi, s);
                    if (c == ADD_FORCE) {
                        rp |= pair_call3(&a3[i], c, kick, hi, 0);
                        rq |= scalar_call3(&b3[i], c, kick, hi, 0);
                    }
                    if (rp != rq || memcmp(&a3[i], &b3[i], sizeof a3[i]) != 0) report("game loop", 3, c, frame, rp, rq);
                }
            }
        }
    }
}

int main(void) {
#ifndef MOTUS__PAIRS
    printf("skipped: this build of motus.h has no pairs (not x86-64, or not GCC or Clang)\n");
    return 77;
#else
    const long cases = 400000;
    calls_alone(cases);
    game_loop(2);
    game_loop(3);
    if (failures) {
        fprintf(stderr, "%ld cases where pairs and one component at a time differ\n", failures);
        return 1;
    }
    printf("%ld single calls (2D and 3D) and 2 game loops (64 particles, 2000 frames): pairs and one component at "
           "a time end in the same bytes with the same codes\n",
           cases);
    return 0;
#endif
}
#endif
