/* tradeoff_motus.c - the motus side of bench/tradeoff: N copies of one reference problem in plain arrays
   (one per component: structure of arrays), stepped by motus_step under one motus_scene, as a game steps
   its particles. Every problem is uncoupled (gravity, drags, the attractor; the oscillators' tether to the
   origin) and takes motus's fast path: every stage in registers, one read and one write of the state per
   step. A problem posed with springs (problem_use_spring) would get one spring per copy, the coupled path
   (a pass per stage over scratch). Compiled twice by
   bench/CMakeLists.txt: in float (the default motus_real) and with MOTUS_DOUBLE; the public functions get
   the suffix _float or _double, and the engine is compiled static in each. */
#define _POSIX_C_SOURCE 200809L /* clock_gettime under -std=c99 */

#define MOTUS_IMPLEMENTATION
#define MOTUS_STATIC
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
    motus_real *x, *y, *vx, *vy;
    motus_spring *springs; /* a problem posed with a spring (problem_use_spring): one per copy, to its anchor */
    motus_scene scene;
    motus_state state;
    void *scratch;
    size_t scratch_bytes;
    int count;
    long evaluations; /* force-model stages, counted by batch_count_callback */
} batch;

/* Adds no force; counts the force-model evaluations a method makes (one call per stage). */
static void batch_count_callback(void *user_data, const motus_force_query *query) {
    (void)query;
    ++((batch *)user_data)->evaluations;
}

static void batch_close(batch *b) {
    free(b->x);
    free(b->y);
    free(b->vx);
    free(b->vy);
    free(b->springs);
    free(b->scratch);
}

/* 0 on failure. */
static int batch_open(batch *b, int which, int method, int count, int count_evaluations) {
    int i;
    memset(b, 0, sizeof *b);
    if (!problem_get(which, &b->problem) || count < 1) return 0;
    b->count = count;
    b->x = (motus_real *)malloc(sizeof(motus_real) * (size_t)count);
    b->y = (motus_real *)malloc(sizeof(motus_real) * (size_t)count);
    b->vx = (motus_real *)malloc(sizeof(motus_real) * (size_t)count);
    b->vy = (motus_real *)malloc(sizeof(motus_real) * (size_t)count);
    if (!b->x || !b->y || !b->vx || !b->vy) return 0;
    b->scene = b->problem.scene; /* the problem's forces (bench/problems.h) */
    b->scene.method = (motus_method)method;
    if (b->problem.scene.spring_count > 0) { /* each copy gets its own spring to the anchor */
        b->springs = (motus_spring *)malloc(sizeof(motus_spring) * (size_t)count);
        if (!b->springs) return 0;
        for (i = 0; i < count; ++i) {
            b->springs[i] = b->problem.spring;
            b->springs[i].a = i;
        }
        b->scene.springs = b->springs;
        b->scene.spring_count = count;
    }
    if (count_evaluations && method != MOTUS_EXACT_LINEAR_DRAG) {
        b->scene.force_callback = batch_count_callback;
        b->scene.user_data = b;
    }
    b->state.dimensions = 2;
    b->state.count = count;
    b->state.position[0] = b->x, b->state.position[1] = b->y;
    b->state.velocity[0] = b->vx, b->state.velocity[1] = b->vy;
    b->scratch_bytes = motus_scratch_size(&b->scene, &b->state);
    if (b->scratch_bytes == (size_t)-1) return 0;
    if (b->scratch_bytes) {
        b->scratch = malloc(b->scratch_bytes);
        if (!b->scratch) return 0;
    }
    return 1;
}

/* Every particle back at the start. */
static void batch_reset(batch *b) {
    const problem_state s = b->problem.start;
    int i;
    for (i = 0; i < b->count; ++i) {
        b->x[i] = (motus_real)s.x, b->y[i] = (motus_real)s.y;
        b->vx[i] = (motus_real)s.vx, b->vy[i] = (motus_real)s.vy;
    }
    b->evaluations = 0;
}

static motus_result batch_step(batch *b, double dt) {
    return motus_step(&b->scene, &b->state, (motus_real)dt, b->scratch, b->scratch_bytes);
}

static void batch_store(const batch *b, double *out) {
    out[0] = b->x[0], out[1] = b->y[0], out[2] = b->vx[0], out[3] = b->vy[0];
}

int TRADEOFF_NAME(tradeoff_motus_trajectory)(int method, int problem, double dt, int steps, int count,
                                             double *trajectory, double *evaluations) {
    batch b;
    int n, outcome = TRADEOFF_OK;
    *evaluations = 0;
    if (!batch_open(&b, problem, method, count, 1)) {
        batch_close(&b);
        return TRADEOFF_DIVERGED;
    }
    batch_reset(&b);
    batch_store(&b, trajectory);
    for (n = 1; n <= steps; ++n) {
        motus_result r = batch_step(&b, dt);
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
        const int last = count - 1;
        if (memcmp(&b.x[0], &b.x[last], sizeof *b.x) || memcmp(&b.y[0], &b.y[last], sizeof *b.y) ||
            memcmp(&b.vx[0], &b.vx[last], sizeof *b.vx) || memcmp(&b.vy[0], &b.vy[last], sizeof *b.vy))
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
    batch_reset(b);
    start = tradeoff_seconds();
    for (n = 0; n < steps; ++n)
        if (batch_step(b, dt) != MOTUS_OK) return -1;
    return tradeoff_seconds() - start;
}

double TRADEOFF_NAME(tradeoff_motus_time)(int method, int problem, double dt, int steps, int count, int repetitions,
                                          double seconds) {
    batch b;
    double ns[64] = {0}, warm_up;
    int rep, runs, run;
    if (repetitions > 64) repetitions = 64;
    if (!batch_open(&b, problem, method, count, 0)) {
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
