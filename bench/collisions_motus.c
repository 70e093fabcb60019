/* collisions_motus.c - motus on the scenes of bench/collisions: motus_step with scene.contacts on (radius r,
   restitution 0, friction 0, the default iterations), the box as scene.bounds (open top: bounds_max.y = +Inf;
   walls with restitution 0 are contact walls at the radius), 4 substeps a frame, the state as plain arrays of
   motus_real (float, the default), scratch of motus_scratch_size() allocated once in create (untimed). With
   cb_scene.threads >= 1, scene.parallel_for is motus_pool_for of tests/support/motus_pool.h with a pool of that
   many threads (the calling one included), started in create and stopped in destroy (both untimed).
   bench/CMakeLists.txt builds this file only when include/motus.h declares motus_contacts (CB_HAVE_MOTUS). */
#define MOTUS_IMPLEMENTATION
#define MOTUS_STATIC
#include "motus.h"
#include "collisions.h"
#define MOTUS_POOL_IMPLEMENTATION
#include "motus_pool.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

typedef struct motus_world {
    motus_scene scene;
    motus_state state;
    motus_real *arrays[6];
    void *scratch;
    size_t scratch_bytes;
    motus_real dt;
    int n, dims;
    motus_pool pool;
    int pool_started;
} motus_world;

static void motus_world_destroy(void *world) {
    motus_world *w = (motus_world *)world;
    if (!w) return;
    if (w->pool_started) motus_pool_stop(&w->pool);
    for (int k = 0; k < 6; ++k) free(w->arrays[k]);
    free(w->scratch);
    free(w);
}

static void *motus_world_create(const cb_scene *s) {
    motus_world *w = (motus_world *)calloc(1, sizeof *w);
    if (!w) return NULL;
    w->n = s->n;
    w->dims = s->dims;
    w->dt = (motus_real)s->dt;
    motus_scene *scene = &w->scene;
    scene->substeps = s->substeps;
    scene->gravity.y = (motus_real)-s->g;
    scene->bounds_min.x = (motus_real)s->box_min[0];
    scene->bounds_min.y = (motus_real)s->box_min[1];
    scene->bounds_max.x = (motus_real)s->box_max[0];
    scene->bounds_max.y = (motus_real)INFINITY;
    if (s->dims == 3) {
        scene->bounds_min.z = (motus_real)s->box_min[2];
        scene->bounds_max.z = (motus_real)s->box_max[2];
    }
    scene->restitution = 0;
    scene->contacts.enabled = 1;
    scene->contacts.radius = (motus_real)s->r;
    scene->contacts.restitution = 0;
    scene->contacts.friction = 0;
    scene->contacts.iterations = s->iterations > 0 ? s->iterations : 0; /* 0: the default (4) */
    motus_state *state = &w->state;
    state->dimensions = s->dims;
    state->count = s->n;
    for (int c = 0; c < s->dims; ++c) {
        w->arrays[c] = (motus_real *)malloc(sizeof(motus_real) * (size_t)s->n);
        w->arrays[3 + c] = (motus_real *)malloc(sizeof(motus_real) * (size_t)s->n);
        if (!w->arrays[c] || !w->arrays[3 + c]) {
            motus_world_destroy(w);
            return NULL;
        }
        for (int i = 0; i < s->n; ++i) {
            w->arrays[c][i] = (motus_real)s->x[c][i];
            w->arrays[3 + c][i] = (motus_real)s->v[c][i];
        }
        state->position[c] = w->arrays[c];
        state->velocity[c] = w->arrays[3 + c];
    }
    w->scratch_bytes = motus_scratch_size(scene, state);
    w->scratch = malloc(w->scratch_bytes ? w->scratch_bytes : 1);
    if (!w->scratch) {
        motus_world_destroy(w);
        return NULL;
    }
    if (s->threads >= 1) {
        if (motus_pool_start(&w->pool, s->threads) != 0) {
            fprintf(stderr, "collisions: motus_pool_start(%d threads) failed\n", s->threads);
            motus_world_destroy(w);
            return NULL;
        }
        w->pool_started = 1;
        scene->parallel_for = motus_pool_for;
        scene->parallel_context = &w->pool;
    }
    return w;
}

static int motus_world_step(void *world) {
    motus_world *w = (motus_world *)world;
    const motus_result result = motus_step(&w->scene, &w->state, w->dt, w->scratch, w->scratch_bytes);
    if (result != MOTUS_OK) {
        fprintf(stderr, "collisions: motus_step: %s\n", motus_result_string(result));
        return 1;
    }
    return 0;
}

static void motus_world_read(void *world, double *x[3], double *v[3]) {
    const motus_world *w = (const motus_world *)world;
    for (int c = 0; c < w->dims; ++c)
        for (int i = 0; i < w->n; ++i) {
            x[c][i] = w->arrays[c][i];
            v[c][i] = w->arrays[3 + c][i];
        }
}

static const char *motus_world_describe(void) {
    static char text[400];
    snprintf(text, sizeof text, "motus %s, %s; motus_step, 4 substeps a frame (or --substeps K), contacts.iterations default (4, or --iterations K), "
             "friction 0, restitution 0; the calling thread alone, and at N = 10^5 also with scene.parallel_for "
             "= motus_pool_for of tests/support/motus_pool.h, 1 and 2 threads", MOTUS_VERSION_STRING,
             sizeof(motus_real) == 8 ? "double" : "float");
    return text;
}

const cb_engine cb_engine_motus = {"motus", (1 << 2) | (1 << 3), 0, motus_world_create, motus_world_step,
                                   motus_world_read, motus_world_destroy, motus_world_describe};

/* motus at one substep a frame: one step of dt, the work a peer does a frame (at a larger overlap than 4
   substeps give); the calling thread alone. */
static void *motus_one_substep_create(const cb_scene *s) {
    cb_scene one = *s;
    one.substeps = 1;
    one.threads = 0;
    return motus_world_create(&one);
}
static const char *motus_one_substep_describe(void) {
    return "motus as above at 1 substep a frame (one step of dt a frame, as the peers step), the calling thread "
           "alone";
}
const cb_engine cb_engine_motus_one_substep = {"motus-1substep", (1 << 2) | (1 << 3), 0, motus_one_substep_create,
                                               motus_world_step, motus_world_read, motus_world_destroy,
                                               motus_one_substep_describe};

/* motus at its lightest setting a game would pick for speed: one substep a frame and one iteration (one
   velocity sweep and one position sweep, each followed by its support sweep); the calling thread alone. */
static void *motus_light_create(const cb_scene *s) {
    cb_scene light = *s;
    light.substeps = 1;
    light.iterations = 1;
    light.threads = 0;
    return motus_world_create(&light);
}
static const char *motus_light_describe(void) {
    return "motus as above at 1 substep a frame and contacts.iterations = 1, the calling thread alone";
}
const cb_engine cb_engine_motus_light = {"motus-1x1", (1 << 2) | (1 << 3), 0, motus_light_create, motus_world_step,
                                         motus_world_read, motus_world_destroy, motus_light_describe};
