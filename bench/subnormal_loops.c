/* subnormal_loops.c - the timed loops of bench/subnormal. Compiled twice by bench/CMakeLists.txt, in float
   and with MOTUS_DOUBLE; the public functions get the suffix _float or _double.

   Four loops, each a damped particle coasting (no force; v *= 0.99 each step at dt 1/60):
   - old particle: a copy of the loop before the flush (semi-implicit Euler, then v *= 0.99);
   - new particle: motus_particle_step + motus_particle_damp_per_step(0.01) (which flushes |v| < MOTUS_REST_SPEED);
   - old batch: a copy of what the batch kernel computed for this scene before the flush, on the SoA arrays
     (v += a*h with a = 0; x += v*h; v *= damping), which gcc vectorises;
   - new batch: motus_step over the SoA arrays, scene.damping_per_step = 0.01 (the engine compiled here,
     static, in each precision). */
#define _POSIX_C_SOURCE 200809L /* clock_gettime under -std=c99 */

#define MOTUS_IMPLEMENTATION
#define MOTUS_STATIC
#include "motus.h"
#include "subnormal.h"

#include <float.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#ifdef MOTUS_DOUBLE
#define NAME(name) name##_double
#define REAL_MIN_NORMAL DBL_MIN
#else
#define NAME(name) name##_float
#define REAL_MIN_NORMAL FLT_MIN
#endif

#if defined(__GNUC__) && !defined(__clang__)
#define KERNEL __attribute__((noipa)) /* one real call per step: no loop interchange across steps */
#else
#define KERNEL __attribute__((noinline))
#endif

static const motus_real DAMPING = MOTUS_R(0.01); /* the fraction removed per step */
static const motus_real KEPT = MOTUS_R(0.99);    /* what the old loops multiply by */

typedef struct arrays {
    motus_real *x, *y, *vx, *vy;
    motus_particle *particles;
    int n;
} arrays;

KERNEL static void old_particle_step(motus_particle *p, int n, motus_real dt) {
    int i;
    for (i = 0; i < n; ++i) { /* motus_particle_step and the old motus_particle_damp_per_step, inlined */
        motus_vec2 v = motus_vec2_add(p[i].velocity, motus_vec2_scale(motus_vec2_scale(p[i].force, p[i].inverse_mass), dt));
        p[i].position = motus_vec2_add(p[i].position, motus_vec2_scale(v, dt));
        p[i].velocity = motus_vec2_scale(v, KEPT);
    }
}
KERNEL static void new_particle_step(motus_particle *p, int n, motus_real dt) {
    int i;
    for (i = 0; i < n; ++i) {
        motus_particle_step(&p[i], dt);
        motus_particle_damp_per_step(&p[i], DAMPING);
    }
}
KERNEL static void old_batch_step(motus_real *restrict x, motus_real *restrict y, motus_real *restrict vx,
                                  motus_real *restrict vy, int n, motus_real h, motus_real damping) {
    const motus_real a = 0; /* the kernel's zero acceleration without forces */
    int i;
    for (i = 0; i < n; ++i) {
        motus_real u = vx[i] + a * h, w = vy[i] + a * h;
        x[i] = x[i] + u * h;
        y[i] = y[i] + w * h;
        vx[i] = u * damping;
        vy[i] = w * damping;
    }
}
KERNEL static void new_batch_step(const motus_scene *scene, const motus_state *state, motus_real h) {
    motus_step(scene, state, h, NULL, 0);
}

static void fill(arrays *a, int subnormal) {
    int i;
    srand(7);
    for (i = 0; i < a->n; ++i) {
        /* Subnormal: between REAL_MIN/16 and REAL_MIN/2; normal: 1 to 2 m/s. Random signs. */
        motus_real r = (motus_real)rand() / (motus_real)RAND_MAX, s = (rand() & 1) ? 1 : -1;
        motus_real speed = subnormal ? REAL_MIN_NORMAL * (MOTUS_R(0.0625) + r * MOTUS_R(0.4375)) : 1 + r;
        a->x[i] = a->y[i] = (motus_real)(i % 800);
        a->vx[i] = s * speed;
        a->vy[i] = -s * speed * MOTUS_R(0.5);
        motus_particle_init(&a->particles[i], motus_v2(a->x[i], a->y[i]), 1);
        a->particles[i].velocity = motus_v2(a->vx[i], a->vy[i]);
    }
}

static double seconds(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

double NAME(subnormal_measure)(int loop, int subnormal, int particles, int steps, int repetitions) {
    const motus_real dt = MOTUS_R(1.0) / 60;
    arrays a;
    motus_scene scene;
    motus_state state;
    double best = 1e300;
    int rep, step;
    a.n = particles;
    a.x = (motus_real *)malloc(sizeof(motus_real) * (size_t)particles * 4);
    a.particles = (motus_particle *)malloc(sizeof(motus_particle) * (size_t)particles);
    if (!a.x || !a.particles) return -1;
    a.y = a.x + particles, a.vx = a.y + particles, a.vy = a.vx + particles;
    memset(&scene, 0, sizeof scene);
    scene.damping_per_step = DAMPING; /* mass 1 kg (scene.mass 0) */
    memset(&state, 0, sizeof state);
    state.dimensions = 2;
    state.count = particles;
    state.position[0] = a.x, state.position[1] = a.y, state.velocity[0] = a.vx, state.velocity[1] = a.vy;
    for (rep = 0; rep < repetitions; ++rep) {
        double start, elapsed;
        fill(&a, subnormal);
        start = seconds();
        for (step = 0; step < steps; ++step) {
            switch (loop) {
            case LOOP_OLD_PARTICLE: old_particle_step(a.particles, particles, dt); break;
            case LOOP_NEW_PARTICLE: new_particle_step(a.particles, particles, dt); break;
            case LOOP_OLD_BATCH: old_batch_step(a.x, a.y, a.vx, a.vy, particles, dt, KEPT); break;
            default: new_batch_step(&scene, &state, dt); break;
            }
        }
        elapsed = seconds() - start;
        if (elapsed < best) best = elapsed;
    }
    free(a.x);
    free(a.particles);
    return best * 1e9 / ((double)particles * (double)steps);
}
