/* tradeoff_motus.c - the motus side of bench/tradeoff: a batch of copies of one reference problem stepped
   by one motus_stepper, as a game would. Compiled twice by bench/CMakeLists.txt: in float (the default
   motus_real) and with MOTUS_DOUBLE; the public functions get the suffix _float or _double. */
#define _POSIX_C_SOURCE 200809L /* clock_gettime under -std=c99 */

#include "motus.h"
#include "problems.h"
#include "tradeoff.h"

#include <stdlib.h>

#ifdef MOTUS_DOUBLE
#define TRADEOFF_NAME(name) name##_double
#else
#define TRADEOFF_NAME(name) name##_float
#endif

typedef struct batch {
    problem problem;
    motus_particle *particles;
    motus_spring *springs; /* one spring per particle for the oscillators: each copy has its own anchor spring */
    motus_forces forces;
    motus_stepper_desc desc;
    motus_stepper stepper;
    int count;
    long evaluations; /* force-model calls, counted by batch_count_callback */
} batch;

/* Adds no force; counts the force-model evaluations a method makes. */
static void batch_count_callback(void *user_data, int count, const motus_vec2 *positions,
                                 const motus_vec2 *velocities, motus_real time, motus_vec2 *forces) {
    (void)count, (void)positions, (void)velocities, (void)time, (void)forces;
    ++((batch *)user_data)->evaluations;
}

static void batch_close(batch *b) {
    free(b->particles);
    free(b->springs);
    free(b->desc.scratch);
}

/* 0 on failure to allocate. */
static int batch_open(batch *b, int which, int method, unsigned flags, int count, int count_evaluations) {
    int i;
    memset(b, 0, sizeof *b);
    if (!problem_get(which, &b->problem) || count < 1) return 0;
    b->count = count;
    b->particles = (motus_particle *)malloc(sizeof(motus_particle) * (size_t)count);
    b->forces = b->problem.forces;
    if (b->problem.forces.spring_count > 0) {
        b->springs = (motus_spring *)malloc(sizeof(motus_spring) * (size_t)count);
        if (!b->springs) return 0;
        for (i = 0; i < count; ++i) {
            b->springs[i] = b->problem.spring;
            b->springs[i].a = i;
        }
        b->forces.springs = b->springs;
        b->forces.spring_count = count;
    }
    if (count_evaluations && method != MOTUS_EXACT_LINEAR_DRAG) {
        b->forces.callback = batch_count_callback;
        b->forces.user_data = b;
    }
    b->desc.capacity = count;
    b->desc.method = (motus_method)method;
    b->desc.flags = flags;
    b->desc.scratch_bytes = motus_stepper_scratch_size((motus_method)method, count);
    b->desc.scratch = malloc(b->desc.scratch_bytes ? b->desc.scratch_bytes : 1);
    return b->particles && b->desc.scratch;
}

/* Every particle back at the start, the stepper new. */
static motus_result batch_reset(batch *b) {
    int i;
    motus_particle start = problem_particle(&b->problem);
    for (i = 0; i < b->count; ++i) b->particles[i] = start;
    b->evaluations = 0;
    return motus_stepper_init(&b->stepper, &b->desc);
}

static void batch_store(const batch *b, double *out) {
    problem_state s = problem_state_of(&b->particles[0]);
    out[0] = s.x, out[1] = s.y, out[2] = s.vx, out[3] = s.vy;
}

int TRADEOFF_NAME(tradeoff_motus_trajectory)(int method, unsigned flags, int problem, double dt, int steps,
                                             int count, double *trajectory, double *evaluations) {
    batch b;
    int n, outcome = TRADEOFF_OK;
    *evaluations = 0;
    if (!batch_open(&b, problem, method, flags, count, 1) || batch_reset(&b) != MOTUS_OK) {
        batch_close(&b);
        return TRADEOFF_DIVERGED;
    }
    batch_store(&b, trajectory);
    for (n = 1; n <= steps; ++n) {
        motus_result r = motus_stepper_step(&b.stepper, b.particles, count, &b.forces, (motus_real)dt);
        if (r == MOTUS_ERROR_UNSUPPORTED) {
            outcome = TRADEOFF_UNSUPPORTED;
            break;
        }
        if (r != MOTUS_OK) {
            outcome = TRADEOFF_DIVERGED;
            break;
        }
        batch_store(&b, trajectory + 4 * n);
    }
    for (; n <= steps; ++n) trajectory[4 * n] = trajectory[4 * n + 1] = trajectory[4 * n + 2] = trajectory[4 * n + 3] = NAN;
    if (outcome == TRADEOFF_OK) {
        const motus_particle *first = &b.particles[0], *last = &b.particles[count - 1];
        if (memcmp(&first->position, &last->position, sizeof first->position) != 0 ||
            memcmp(&first->velocity, &last->velocity, sizeof first->velocity) != 0)
            outcome = TRADEOFF_BATCH_MISMATCH;
        *evaluations = steps > 0 ? (double)b.evaluations / steps : 0;
    }
    batch_close(&b);
    return outcome;
}

/* One timed run: reset (untimed), then `steps` steps. Seconds, or a negative number if a step failed. */
static double batch_timed_run(batch *b, double dt, int steps) {
    double start;
    int n;
    if (batch_reset(b) != MOTUS_OK) return -1;
    start = tradeoff_seconds();
    for (n = 0; n < steps; ++n)
        if (motus_stepper_step(&b->stepper, b->particles, b->count, &b->forces, (motus_real)dt) != MOTUS_OK) return -1;
    return tradeoff_seconds() - start;
}

double TRADEOFF_NAME(tradeoff_motus_time)(int method, unsigned flags, int problem, double dt, int steps, int count,
                                          int repetitions, double seconds) {
    batch b;
    double ns[64] = {0}, warm_up;
    int rep, runs, run;
    if (repetitions > 64) repetitions = 64;
    if (!batch_open(&b, problem, method, flags, count, 0)) {
        batch_close(&b);
        return NAN;
    }
    warm_up = batch_timed_run(&b, dt, steps);
    runs = warm_up > 0 ? (int)ceil(seconds / warm_up) : 1;
    if (runs < 1) runs = 1;
    for (rep = 0; rep < repetitions && warm_up >= 0; ++rep) {
        double total = 0;
        for (run = 0; run < runs; ++run) {
            double t = batch_timed_run(&b, dt, steps);
            if (t < 0) break;
            total += t;
        }
        if (run < runs) break;
        ns[rep] = total * 1e9 / ((double)steps * count * runs);
    }
    batch_close(&b);
    return rep < repetitions ? NAN : tradeoff_median(ns, repetitions);
}
