/* collisions_chipmunk.c - Chipmunk 7 (Debian libchipmunk-dev) on the 2D scenes of bench/collisions: one
   cpSpace with its spatial hash (cpSpaceUseSpatialHash: cells of one ball diameter, 10 cells a ball as
   Chipmunk's manual advises), a body of 1 kg with one cpCircleShape per ball (elasticity 0, friction 0), the
   box as three segments on the static body (floor and the two sides, taller than the start), the default 10
   iterations, sleeping off (Chipmunk's default). The collision slop is set to 0.005 m, Box2D's linear slop (1%
   of the radius): Chipmunk's default of 0.1 is meant for pixel units and would let balls of 0.5 m overlap by
   20% of their radius on purpose. Chipmunk computes in double (cpFloat, Debian's build). */
#include "collisions.h"

#include <chipmunk/chipmunk.h>

#include <stdio.h>
#include <stdlib.h>

typedef struct chipmunk_world {
    cpSpace *space;
    cpBody **bodies;
    cpShape **shapes;
    cpShape *walls[3];
    int n;
    double dt;
} chipmunk_world;

/* The space is freed first, then the bodies and shapes: cpSpaceRemoveBody searches its array linearly, so
   removing 10^6 balls one by one would take O(N^2). */
static void chipmunk_destroy(void *world) {
    chipmunk_world *w = (chipmunk_world *)world;
    if (!w) return;
    if (w->space) cpSpaceFree(w->space);
    for (int i = 0; i < w->n; ++i) {
        if (w->shapes && w->shapes[i]) cpShapeFree(w->shapes[i]);
        if (w->bodies && w->bodies[i]) cpBodyFree(w->bodies[i]);
    }
    for (int k = 0; k < 3; ++k)
        if (w->walls[k]) cpShapeFree(w->walls[k]);
    free(w->bodies);
    free(w->shapes);
    free(w);
}

/* Debian's library is built without NDEBUG: cpSpaceNew prints "Debug Enabled" and the assertions stay in.
   bench/CMakeLists.txt finds that banner in the library and defines CB_CHIPMUNK_DEBUG. */
#ifdef CB_CHIPMUNK_DEBUG
static const int chipmunk_debug = 1;
#else
static const int chipmunk_debug = 0;
#endif

static void *chipmunk_create(const cb_scene *s) {
    if (s->dims != 2) return NULL;
    chipmunk_world *w = (chipmunk_world *)calloc(1, sizeof *w);
    if (!w) return NULL;
    w->dt = s->dt;
    w->space = cpSpaceNew();
    w->bodies = (cpBody **)calloc((size_t)s->n, sizeof *w->bodies);
    w->shapes = (cpShape **)calloc((size_t)s->n, sizeof *w->shapes);
    if (!w->space || !w->bodies || !w->shapes) {
        chipmunk_destroy(w);
        return NULL;
    }
    w->n = s->n;
    cpSpaceSetGravity(w->space, cpv(0, -s->g));
    cpSpaceSetCollisionSlop(w->space, 0.005);
    cpSpaceUseSpatialHash(w->space, 2 * s->r, 10 * s->n);
    double top = s->box_min[1];
    for (int i = 0; i < s->n; ++i)
        if (s->x[1][i] > top) top = s->x[1][i];
    top += 10 * s->r;
    const cpVect corners[4] = {cpv(s->box_min[0], top), cpv(s->box_min[0], s->box_min[1]),
                               cpv(s->box_max[0], s->box_min[1]), cpv(s->box_max[0], top)};
    for (int k = 0; k < 3; ++k) {
        w->walls[k] = cpSegmentShapeNew(cpSpaceGetStaticBody(w->space), corners[k], corners[k + 1], 0);
        cpShapeSetElasticity(w->walls[k], 0);
        cpShapeSetFriction(w->walls[k], 0);
        cpSpaceAddShape(w->space, w->walls[k]);
    }
    const cpFloat moment = cpMomentForCircle(1, 0, s->r, cpvzero);
    for (int i = 0; i < s->n; ++i) {
        cpBody *body = cpSpaceAddBody(w->space, cpBodyNew(1, moment));
        cpBodySetPosition(body, cpv(s->x[0][i], s->x[1][i]));
        cpBodySetVelocity(body, cpv(s->v[0][i], s->v[1][i]));
        w->bodies[i] = body;
        cpShape *shape = cpSpaceAddShape(w->space, cpCircleShapeNew(body, s->r, cpvzero));
        cpShapeSetElasticity(shape, 0);
        cpShapeSetFriction(shape, 0);
        w->shapes[i] = shape;
    }
    return w;
}

static int chipmunk_step(void *world) {
    chipmunk_world *w = (chipmunk_world *)world;
    cpSpaceStep(w->space, w->dt);
    return 0;
}

static void chipmunk_read(void *world, double *x[3], double *v[3]) {
    const chipmunk_world *w = (const chipmunk_world *)world;
    for (int i = 0; i < w->n; ++i) {
        const cpVect p = cpBodyGetPosition(w->bodies[i]), u = cpBodyGetVelocity(w->bodies[i]);
        x[0][i] = p.x;
        x[1][i] = p.y;
        v[0][i] = u.x;
        v[1][i] = u.y;
    }
}

static const char *chipmunk_describe(void) {
    static char text[200];
    snprintf(text, sizeof text,
             "Chipmunk %s, %s%s; cpSpaceStep(dt), 10 iterations; spatial hash (cell 2r, 10N cells); collision slop "
             "0.005 m (default 0.1); sleeping off",
             cpVersionString, CP_USE_DOUBLES ? "double" : "float",
             chipmunk_debug ? ", a debug build (Debian's: its assertions run in the step)" : "");
    return text;
}

const cb_engine cb_engine_chipmunk = {"chipmunk", 1 << 2, 0, chipmunk_create, chipmunk_step, chipmunk_read,
                                      chipmunk_destroy, chipmunk_describe};
