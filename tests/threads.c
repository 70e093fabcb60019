/* Threads (issue 12, item 4): motus_step with scene.parallel_for on scenes with contacts.

   The passes a step hands out (the method, the pair search, the sort, the sweeps in slabs, the last wall
   projection and check) must give the same bits however the tasks are split and in whatever order they
   run: against the calling thread alone, through a pool of 2 and of 3 threads, one task at a time in
   reverse, and in a shuffled order with ranges of random lengths, after every frame of a pile of 5,000
   balls falling into a box (more than MOTUS_CONTACT_SLAB_MIN_COUNT: the sweeps run in slabs), and the bits
   of a step without parallel_for below that count. A pile of 6,000 that settles in slabs (every overlap below 1% of the radius, kinetic energy below 1e-4 of the
   potential energy it fell from, nothing out of the box), and bad data refused the same way with threads.
   2D and 3D; built in float and in double with MOTUS_CHECKED. tests/CMakeLists.txt also runs the first
   test under ThreadSanitizer. */
#define _POSIX_C_SOURCE 200809L
#define MOTUS_IMPLEMENTATION
#define MOTUS_STATIC
#include "motus.h"
#define MOTUS_POOL_IMPLEMENTATION
#include "support/motus_pool.h"
#include "support/motus_test.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#ifdef MOTUS_DOUBLE
#define EPS DBL_EPSILON
#else
#define EPS FLT_EPSILON
#endif

typedef struct world {
    motus_scene scene;
    motus_state state;
    motus_real *x[3], *v[3];
    void *scratch;
    size_t scratch_bytes;
    int n, dims;
    motus_real r, side;
} world;

static uint32_t random_state = 1;
static uint32_t random_next(void) { return motus_test_xorshift32(&random_state); }
static double random_unit(void) { return (double)(random_next() >> 8) / 16777216.0; }

/* n balls of radius 0.5 in a box `side` wide (and deep, in 3D), open at the top, gravity -10 along y;
   restitution 0.2 and friction 0.3 (walls too), 4 substeps a frame. Scattered (packed = 0): in rows 0.1 r
   apart, moving sideways at up to 2 m/s, so that the columns break up. Packed: rows offset by half a
   spacing (each ball above the gap between two below, or four in 3D), 0.2 r apart, as in a pile at rest:
   every ball rests on a V of supports, across the slab borders too. Stored along x fastest, then z, then
   up; with WORLD_DEPTH_FASTEST (3D) along z fastest, then x: the slabs are then across x (motus cuts them
   across the axis that keeps a cache line's particles nearer one slab), else across z. */
enum { WORLD_PACKED = 1, WORLD_DEPTH_FASTEST = 2 };
static void world_init(world *w, int dims, int n, motus_real side, uint32_t seed, int flags) {
    const int packed = flags & WORLD_PACKED;
    const motus_real r = MOTUS_R(0.5), spacing = MOTUS_R(2.2) * r;
    /* packed rows: neighbours in the rows above and below are `spacing` apart too */
    const motus_real row = packed ? (dims == 2 ? MOTUS_R(0.8660254) : MOTUS_R(0.70710678)) * spacing : spacing;
    const int per_row = (int)(side / spacing) - (packed ? 1 : 0);
    int i, d;
    memset(w, 0, sizeof *w);
    w->n = n, w->dims = dims, w->r = r, w->side = side;
    w->scene.gravity = motus_v3(0, -10, 0);
    w->scene.bounds_min = motus_v3(0, 0, 0);
    w->scene.bounds_max = motus_v3(side, (motus_real)HUGE_VAL, side);
    w->scene.restitution = w->scene.contacts.restitution = MOTUS_R(0.2);
    w->scene.contacts.enabled = 1;
    w->scene.contacts.radius = r;
    w->scene.contacts.friction = MOTUS_R(0.3);
    w->scene.substeps = 4;
    w->state.dimensions = dims;
    w->state.count = n;
    for (d = 0; d < dims; ++d) {
        w->x[d] = (motus_real *)calloc((size_t)n, sizeof(motus_real));
        w->v[d] = (motus_real *)calloc((size_t)n, sizeof(motus_real));
        ENSURE(w->x[d] && w->v[d]);
        w->state.position[d] = w->x[d], w->state.velocity[d] = w->v[d];
    }
    random_state = seed;
    for (i = 0; i < n; ++i) {
        const int fastest = i % per_row, layer = i / per_row;
        const int height = dims == 2 ? layer : layer / per_row, next = dims == 2 ? 0 : layer % per_row;
        const int column = flags & WORLD_DEPTH_FASTEST ? next : fastest;
        const int depth = flags & WORLD_DEPTH_FASTEST ? fastest : next;
        const motus_real shift = packed && (height & 1) ? spacing / 2 : 0;
        w->x[0][i] = r * MOTUS_R(1.1) + (motus_real)column * spacing + shift;
        w->x[1][i] = r * MOTUS_R(1.1) + (motus_real)height * row;
        if (dims == 3) w->x[2][i] = r * MOTUS_R(1.1) + (motus_real)depth * spacing + shift;
        if (!packed) {
            w->x[0][i] += (motus_real)(0.1 * random_unit());
            w->v[0][i] = (motus_real)(4 * random_unit() - 2);
            if (dims == 3) w->v[2][i] = (motus_real)(4 * random_unit() - 2);
        }
    }
    w->scratch_bytes = motus_scratch_size(&w->scene, &w->state);
    w->scratch = malloc(w->scratch_bytes);
    ENSURE(w->scratch != NULL);
}
static void world_free(world *w) {
    int d;
    for (d = 0; d < w->dims; ++d) free(w->x[d]), free(w->v[d]);
    free(w->scratch);
}
static int same_state(const world *a, const world *b) {
    int d, same = 1;
    for (d = 0; d < a->dims; ++d)
        same &= memcmp(a->x[d], b->x[d], (size_t)a->n * sizeof(motus_real)) == 0 &&
                memcmp(a->v[d], b->v[d], (size_t)a->n * sizeof(motus_real)) == 0;
    return same;
}

/* Runners that split differently: one task at a time from the last, and ranges of random lengths in a
   shuffled order. Each counts the calls with more than one task. */
typedef struct runner {
    int shared_calls, largest;
    uint32_t seed;
} runner;
static void in_order_for(void *context, motus_task_function task, void *task_context, int task_count) {
    (void)context;
    task(task_context, 0, task_count);
}
static void reverse_for(void *context, motus_task_function task, void *task_context, int task_count) {
    runner *r = (runner *)context;
    int t;
    if (task_count > 1) ++r->shared_calls;
    if (task_count > r->largest) r->largest = task_count;
    for (t = task_count - 1; t >= 0; --t) task(task_context, t, 1);
}
static void shuffled_for(void *context, motus_task_function task, void *task_context, int task_count) {
    runner *r = (runner *)context;
    int first[256], count[256], ranges = 0, t = 0, k;
    if (task_count > 1) ++r->shared_calls;
    if (task_count > r->largest) r->largest = task_count;
    while (t < task_count && ranges < 255) {
        r->seed = r->seed * 1664525u + 1013904223u;
        first[ranges] = t;
        count[ranges] = 1 + (int)((r->seed >> 16) % 3);
        if (count[ranges] > task_count - t) count[ranges] = task_count - t;
        t += count[ranges++];
    }
    if (t < task_count) first[ranges] = t, count[ranges++] = task_count - t;
    for (k = ranges - 1; k > 0; --k) { /* Fisher-Yates */
        int j, swap;
        r->seed = r->seed * 1664525u + 1013904223u;
        j = (int)((r->seed >> 16) % (uint32_t)(k + 1));
        swap = first[k], first[k] = first[j], first[j] = swap;
        swap = count[k], count[k] = count[j], count[j] = swap;
    }
    for (k = 0; k < ranges; ++k) task(task_context, first[k], count[k]);
}

/* The same bits after every frame, however the tasks are split and run: against one call of all the tasks
   in order on the calling thread, through pools of 2 and 3 threads, in reverse, shuffled. The slabs are
   in use: without parallel_for the bits differ. In 3D twice: the slabs across z, then across x. */
TEST(same_bits_however_split) {
    int setup;
    for (setup = 0; setup < 3; ++setup) {
        const int dims = setup == 0 ? 2 : 3, flags = setup == 2 ? WORLD_DEPTH_FASTEST : 0;
        enum { WAYS = 5 };
        world w[WAYS], alone;
        motus_pool pool2, pool3;
        runner reverse = {0, 0, 1}, shuffled = {0, 0, 7};
        /* MOTUS_THREADS_FRAMES: fewer frames (the ThreadSanitizer run) */
        const int n = 5000, frames = getenv("MOTUS_THREADS_FRAMES") ? atoi(getenv("MOTUS_THREADS_FRAMES")) : 30;
        int k, frame, differ = 0;
        ENSURE_EQ_INT(motus_pool_start(&pool2, 2), 0);
        ENSURE_EQ_INT(motus_pool_start(&pool3, 3), 0);
        for (k = 0; k < WAYS; ++k) world_init(&w[k], dims, n, dims == 2 ? 100 : 24, 11, flags);
        world_init(&alone, dims, n, dims == 2 ? 100 : 24, 11, flags);
        w[0].scene.parallel_for = in_order_for;
        w[1].scene.parallel_for = motus_pool_for, w[1].scene.parallel_context = &pool2;
        w[2].scene.parallel_for = motus_pool_for, w[2].scene.parallel_context = &pool3;
        w[3].scene.parallel_for = reverse_for, w[3].scene.parallel_context = &reverse;
        w[4].scene.parallel_for = shuffled_for, w[4].scene.parallel_context = &shuffled;
        for (frame = 0; frame < frames; ++frame) {
            for (k = 0; k < WAYS; ++k)
                ENSURE_EQ_INT(motus_step(&w[k].scene, &w[k].state, MOTUS_R(1.0) / 60, w[k].scratch, w[k].scratch_bytes),
                              MOTUS_OK);
            ENSURE_EQ_INT(motus_step(&alone.scene, &alone.state, MOTUS_R(1.0) / 60, alone.scratch, alone.scratch_bytes),
                          MOTUS_OK);
            for (k = 1; k < WAYS; ++k)
                if (!same_state(&w[0], &w[k])) {
                    if (!differ) fprintf(stderr, "  %dD: way %d differs from one thread at frame %d\n", dims, k, frame);
                    differ = 1;
                }
        }
        ENSURE(!differ);
        ENSURE(!same_state(&w[0], &alone)); /* the slabs' order */
        /* the work was handed out: several tasks per call (the pair search of 5,000 particles in tasks of
           2,048, the sweeps in at least 4 slabs), in most calls */
        printf("  %dD%s: %d calls with more than one task, up to %d tasks\n", dims, flags ? " (z fastest)" : "", shuffled.shared_calls, shuffled.largest);
        ENSURE(shuffled.largest >= 3);
        ENSURE(shuffled.shared_calls >= frames * 4 * 10);
        ENSURE_EQ_INT(reverse.shared_calls, shuffled.shared_calls);
        motus_pool_stop(&pool2);
        motus_pool_stop(&pool3);
        for (k = 0; k < WAYS; ++k) world_free(&w[k]);
        world_free(&alone);
    }
}

/* Below MOTUS_CONTACT_SLAB_MIN_COUNT (4,096) there are no slabs: the tasks (two of 2,048 in the method's
   pass, the grid's scans and the pair search) give the bits of a step without parallel_for. */
TEST(same_bits_as_one_thread_below_the_slabs) {
    int dims;
    for (dims = 2; dims <= 3; ++dims) {
        world threaded, alone;
        motus_pool pool;
        runner shuffled = {0, 0, 3};
        int frame, differ = 0;
        ENSURE_EQ_INT(motus_pool_start(&pool, 2), 0);
        world_init(&threaded, dims, 4000, dims == 2 ? 100 : 24, 13, 0);
        world_init(&alone, dims, 4000, dims == 2 ? 100 : 24, 13, 0);
        threaded.scene.parallel_for = shuffled_for, threaded.scene.parallel_context = &shuffled;
        for (frame = 0; frame < 30; ++frame) {
            ENSURE_EQ_INT(motus_step(&threaded.scene, &threaded.state, MOTUS_R(1.0) / 60, threaded.scratch,
                                     threaded.scratch_bytes), MOTUS_OK);
            ENSURE_EQ_INT(motus_step(&alone.scene, &alone.state, MOTUS_R(1.0) / 60, alone.scratch, alone.scratch_bytes),
                          MOTUS_OK);
            differ |= !same_state(&threaded, &alone);
        }
        ENSURE(!differ);
        ENSURE(shuffled.largest >= 2);
        motus_pool_stop(&pool);
        world_free(&threaded), world_free(&alone);
    }
}

/* A pile of 6,000 settles in slabs, stepped by 2 threads. */
TEST(pile_settles_in_slabs) {
    int dims;
    for (dims = 2; dims <= 3; ++dims) {
        world w;
        motus_pool pool;
        const int n = 6000;
        double potential = 0, kinetic = 0, largest = 0;
        motus_contact_pair *pairs;
        int i, d, s, found = 0, capacity = 16 * n;
        ENSURE_EQ_INT(motus_pool_start(&pool, 2), 0);
        world_init(&w, dims, n, dims == 2 ? 100 : 24, 3, WORLD_PACKED);
        w.scene.parallel_for = motus_pool_for, w.scene.parallel_context = &pool;
        /* the energy it starts with: its height above the floor, and its sideways speed */
        for (i = 0; i < n; ++i) {
            potential += 10.0 * ((double)w.x[1][i] - (double)w.r);
            for (d = 0; d < dims; ++d) potential += 0.5 * (double)w.v[d][i] * (double)w.v[d][i];
        }
        for (s = 0; s < 600; ++s)
            ENSURE_EQ_INT(motus_step(&w.scene, &w.state, MOTUS_R(1.0) / 60, w.scratch, w.scratch_bytes), MOTUS_OK);
        pairs = (motus_contact_pair *)malloc(sizeof *pairs * (size_t)capacity);
        ENSURE(pairs != NULL);
        ENSURE_EQ_INT(motus_find_contacts(&w.scene, &w.state, w.scratch, w.scratch_bytes, pairs, capacity, &found),
                      MOTUS_OK);
        for (i = 0; i < found && i < capacity; ++i) {
            double d2 = 0, overlap;
            for (d = 0; d < dims; ++d) {
                const double u = (double)w.x[d][pairs[i].b] - (double)w.x[d][pairs[i].a];
                d2 += u * u;
            }
            overlap = 2 * (double)w.r - sqrt(d2);
            if (overlap > largest) largest = overlap;
        }
        for (i = 0; i < n; ++i)
            for (d = 0; d < dims; ++d) kinetic += 0.5 * (double)w.v[d][i] * (double)w.v[d][i];
        printf("  %dD: largest overlap %.3g r, kinetic / initial energy %.3g\n", dims, largest / w.r,
               kinetic / potential);
        ENSURE_NEAR(largest / w.r, 0, 0.01);
        ENSURE(kinetic < 1e-4 * potential); /* 1e-5 measured, 2e-5 without slabs (README) */
        for (i = 0; i < n; ++i)
            for (d = 0; d < dims; ++d) {
                ENSURE(w.x[d][i] >= w.r - 8 * EPS * w.side);
                if (d != 1) ENSURE(w.x[d][i] <= w.side - w.r + 8 * EPS * w.side);
            }
        free(pairs);
        motus_pool_stop(&pool);
        world_free(&w);
    }
}

/* Bad data: the same result with and without threads, and (checked build) nothing written. */
TEST(bad_data_refused_the_same_way) {
    int dims;
    for (dims = 2; dims <= 3; ++dims) {
        world one, two, before;
        motus_pool pool;
        motus_result alone, threaded;
        ENSURE_EQ_INT(motus_pool_start(&pool, 2), 0);
        world_init(&one, dims, 5000, dims == 2 ? 100 : 24, 5, 0);
        world_init(&two, dims, 5000, dims == 2 ? 100 : 24, 5, 0);
        world_init(&before, dims, 5000, dims == 2 ? 100 : 24, 5, 0);
        two.scene.parallel_for = motus_pool_for, two.scene.parallel_context = &pool;
        one.v[0][4321] = two.v[0][4321] = before.v[0][4321] = (motus_real)NAN;
        alone = motus_step(&one.scene, &one.state, MOTUS_R(1.0) / 60, one.scratch, one.scratch_bytes);
        threaded = motus_step(&two.scene, &two.state, MOTUS_R(1.0) / 60, two.scratch, two.scratch_bytes);
        ENSURE_EQ_INT(alone, MOTUS_ERROR_NOT_FINITE);
        ENSURE_EQ_INT(threaded, alone);
#ifdef MOTUS_CHECKED
        ENSURE(same_state(&two, &before));
#endif
        ENSURE(same_state(&one, &two)); /* whatever was written, the same */
        /* a NaN position, in another task's part */
        one.v[0][4321] = two.v[0][4321] = 0;
        one.x[1][17] = two.x[1][17] = (motus_real)NAN;
        alone = motus_step(&one.scene, &one.state, MOTUS_R(1.0) / 60, one.scratch, one.scratch_bytes);
        threaded = motus_step(&two.scene, &two.state, MOTUS_R(1.0) / 60, two.scratch, two.scratch_bytes);
        ENSURE_EQ_INT(alone, MOTUS_ERROR_NOT_FINITE);
        ENSURE_EQ_INT(threaded, alone);
        ENSURE(same_state(&one, &two));
        motus_pool_stop(&pool);
        world_free(&one), world_free(&two), world_free(&before);
    }
}

static const motus_test_case TESTS[] = {
    TEST_CASE(same_bits_however_split),
    TEST_CASE(same_bits_as_one_thread_below_the_slabs),
    TEST_CASE(pile_settles_in_slabs),
    TEST_CASE(bad_data_refused_the_same_way),
};

int main(int argc, char **argv) { return motus_test_main(argc, argv, TESTS, TEST_COUNT(TESTS)); }
