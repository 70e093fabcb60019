// collisions_box2d.cpp - Box2D 2.4 (Debian libbox2d-dev) on the scenes of bench/collisions: one b2World, a
// dynamic body with one b2CircleShape fixture per ball (density 1/(pi r^2): 1 kg, friction 0, restitution 0),
// the box as three two-sided b2EdgeShapes on one static body (floor and the two sides, taller than the
// start), sleeping off (motus has no sleeping: both step every ball every frame; Box2D's sleeping would make a
// pile at rest nearly free), World::Step(dt, 8, 3): Box2D's recommended 8 velocity and 3 position iterations.
// Box2D's b2_linearSlop (0.005 m) is the overlap it leaves on purpose: 1% of the 0.5 m radius.
#include "collisions.h"

#include <box2d/box2d.h>

#include <cmath>
#include <cstdio>
#include <new>
#include <vector>

namespace {

struct box2d_world {
    b2World world{b2Vec2(0, 0)};
    std::vector<b2Body *> bodies;
    float dt = 0;
};

void *box2d_create(const cb_scene *s) {
    if (s->dims != 2) return nullptr;
    box2d_world *w = new (std::nothrow) box2d_world;
    if (!w) return nullptr;
    w->world.SetGravity(b2Vec2(0, (float)-s->g));
    w->world.SetAllowSleeping(false);
    w->dt = (float)s->dt;
    double top = s->box_min[1];
    for (int i = 0; i < s->n; ++i) top = std::fmax(top, s->x[1][i]);
    top += 10 * s->r;
    b2BodyDef ground_def;
    b2Body *ground = w->world.CreateBody(&ground_def);
    const float x0 = (float)s->box_min[0], x1 = (float)s->box_max[0], y0 = (float)s->box_min[1], y1 = (float)top;
    const b2Vec2 corners[4] = {b2Vec2(x0, y1), b2Vec2(x0, y0), b2Vec2(x1, y0), b2Vec2(x1, y1)};
    for (int k = 0; k < 3; ++k) {
        b2EdgeShape edge;
        edge.SetTwoSided(corners[k], corners[k + 1]);
        b2FixtureDef fd;
        fd.shape = &edge;
        fd.friction = 0;
        fd.restitution = 0;
        ground->CreateFixture(&fd);
    }
    b2CircleShape circle;
    circle.m_radius = (float)s->r;
    b2FixtureDef fd;
    fd.shape = &circle;
    fd.density = (float)(1 / (M_PI * s->r * s->r));
    fd.friction = 0;
    fd.restitution = 0;
    w->bodies.reserve((size_t)s->n);
    for (int i = 0; i < s->n; ++i) {
        b2BodyDef bd;
        bd.type = b2_dynamicBody;
        bd.allowSleep = false;
        bd.position.Set((float)s->x[0][i], (float)s->x[1][i]);
        bd.linearVelocity.Set((float)s->v[0][i], (float)s->v[1][i]);
        b2Body *body = w->world.CreateBody(&bd);
        body->CreateFixture(&fd);
        w->bodies.push_back(body);
    }
    return w;
}

int box2d_step(void *world) {
    box2d_world *w = (box2d_world *)world;
    w->world.Step(w->dt, 8, 3);
    return 0;
}

void box2d_read(void *world, double *x[3], double *v[3]) {
    const box2d_world *w = (const box2d_world *)world;
    for (size_t i = 0; i < w->bodies.size(); ++i) {
        const b2Vec2 p = w->bodies[i]->GetPosition(), u = w->bodies[i]->GetLinearVelocity();
        x[0][i] = p.x;
        x[1][i] = p.y;
        v[0][i] = u.x;
        v[1][i] = u.y;
    }
}

void box2d_destroy(void *world) { delete (box2d_world *)world; }

const char *box2d_describe() {
    static char text[160];
    std::snprintf(text, sizeof text,
                  "Box2D %d.%d.%d, float; Step(dt, 8, 3); b2_linearSlop %g m; sleeping off; edges for the walls",
                  b2_version.major, b2_version.minor, b2_version.revision, (double)b2_linearSlop);
    return text;
}

} // namespace

extern "C" const cb_engine cb_engine_box2d = {"box2d", 1 << 2, 0, box2d_create, box2d_step, box2d_read,
                                              box2d_destroy, box2d_describe};
