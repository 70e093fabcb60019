// collisions_bullet.cpp - Bullet (Debian libbullet-dev, single precision) on the 3D scenes of bench/collisions:
// btDiscreteDynamicsWorld with btDbvtBroadphase, btDefaultCollisionConfiguration and the sequential-impulse
// solver (default 10 iterations, split impulse as Bullet sets it by default), one shared btSphereShape, a body
// of 1 kg per ball (friction, rolling friction and restitution 0, deactivation off: motus has no sleeping, so
// both step every ball every frame), the box as five static btBoxShape bodies (floor and four sides, taller
// than the start), stepSimulation(dt, 0): exactly one internal step of dt a frame.
#include "collisions.h"

#include <btBulletDynamicsCommon.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <new>
#include <vector>

namespace {

// The shapes and bodies are declared first so that they outlive the world: ~btCollisionWorld frees their
// broadphase proxies itself (removing 10^5 bodies one by one would search linearly each time: O(N^2)).
struct bullet_world {
    std::unique_ptr<btSphereShape> sphere;
    std::vector<std::unique_ptr<btBoxShape>> wall_shapes;
    std::vector<std::unique_ptr<btRigidBody>> bodies; // the walls first, then the balls
    btDefaultCollisionConfiguration configuration;
    btCollisionDispatcher dispatcher{&configuration};
    btDbvtBroadphase broadphase;
    btSequentialImpulseConstraintSolver solver;
    btDiscreteDynamicsWorld world{&dispatcher, &broadphase, &solver, &configuration};
    int walls = 0;
    btScalar dt = 0;
};

void add_wall(bullet_world *w, btVector3 half, btVector3 centre) {
    w->wall_shapes.emplace_back(new btBoxShape(half));
    btRigidBody::btRigidBodyConstructionInfo info(0, nullptr, w->wall_shapes.back().get());
    info.m_startWorldTransform.setIdentity();
    info.m_startWorldTransform.setOrigin(centre);
    info.m_friction = 0;
    info.m_restitution = 0;
    w->bodies.emplace_back(new btRigidBody(info));
    w->world.addRigidBody(w->bodies.back().get());
    ++w->walls;
}

void *bullet_create(const cb_scene *s) {
    if (s->dims != 3) return nullptr;
    bullet_world *w = new (std::nothrow) bullet_world;
    if (!w) return nullptr;
    w->world.setGravity(btVector3(0, (btScalar)-s->g, 0));
    w->dt = (btScalar)s->dt;
    double top = s->box_min[1];
    for (int i = 0; i < s->n; ++i) top = std::fmax(top, s->x[1][i]);
    top += 10 * s->r;
    const double x0 = s->box_min[0], x1 = s->box_max[0], y0 = s->box_min[1], z0 = s->box_min[2],
                 z1 = s->box_max[2], t = 1; // wall thickness, m
    const double cx = (x0 + x1) / 2, cz = (z0 + z1) / 2, hx = (x1 - x0) / 2 + t, hz = (z1 - z0) / 2 + t,
                 hy = (top - y0) / 2, cy = (top + y0) / 2;
    add_wall(w, btVector3(hx, t / 2, hz), btVector3(cx, y0 - t / 2, cz)); // floor
    add_wall(w, btVector3(t / 2, hy, hz), btVector3(x0 - t / 2, cy, cz));
    add_wall(w, btVector3(t / 2, hy, hz), btVector3(x1 + t / 2, cy, cz));
    add_wall(w, btVector3(hx, hy, t / 2), btVector3(cx, cy, z0 - t / 2));
    add_wall(w, btVector3(hx, hy, t / 2), btVector3(cx, cy, z1 + t / 2));
    w->sphere.reset(new btSphereShape((btScalar)s->r));
    btVector3 inertia(0, 0, 0);
    w->sphere->calculateLocalInertia(1, inertia);
    w->bodies.reserve(w->bodies.size() + (size_t)s->n);
    for (int i = 0; i < s->n; ++i) {
        btRigidBody::btRigidBodyConstructionInfo info(1, nullptr, w->sphere.get(), inertia);
        info.m_startWorldTransform.setIdentity();
        info.m_startWorldTransform.setOrigin(btVector3(s->x[0][i], s->x[1][i], s->x[2][i]));
        info.m_friction = 0;
        info.m_rollingFriction = 0;
        info.m_restitution = 0;
        btRigidBody *body = new btRigidBody(info);
        body->setLinearVelocity(btVector3(s->v[0][i], s->v[1][i], s->v[2][i]));
        body->setActivationState(DISABLE_DEACTIVATION);
        w->bodies.emplace_back(body);
        w->world.addRigidBody(body);
    }
    return w;
}

int bullet_step(void *world) {
    bullet_world *w = (bullet_world *)world;
    w->world.stepSimulation(w->dt, 0);
    return 0;
}

void bullet_read(void *world, double *x[3], double *v[3]) {
    const bullet_world *w = (const bullet_world *)world;
    for (size_t i = (size_t)w->walls; i < w->bodies.size(); ++i) {
        const btVector3 &p = w->bodies[i]->getCenterOfMassPosition(), &u = w->bodies[i]->getLinearVelocity();
        const size_t k = i - (size_t)w->walls;
        for (int c = 0; c < 3; ++c) {
            x[c][k] = p[c];
            v[c][k] = u[c];
        }
    }
}

// The pairs first, one by one from the end (hashed: O(1) each): ~btCollisionWorld then frees each body's
// proxy, which scans every remaining pair; with the pairs still there that is O(N * pairs), minutes at 10^5.
void bullet_destroy(void *world) {
    bullet_world *w = (bullet_world *)world;
    btOverlappingPairCache *cache = w->world.getPairCache();
    btBroadphasePairArray &pairs = cache->getOverlappingPairArray();
    while (pairs.size() > 0) {
        btBroadphasePair &last = pairs[pairs.size() - 1];
        cache->removeOverlappingPair(last.m_pProxy0, last.m_pProxy1, &w->dispatcher);
    }
    delete w;
}

const char *bullet_describe() {
    static char text[200];
    std::snprintf(text, sizeof text,
                  "Bullet %d.%02d, %s; btDbvtBroadphase, sequential impulse (default 10 iterations, split impulse); "
                  "stepSimulation(dt, 0); deactivation off; static boxes for the walls",
                  btGetVersion() / 100, btGetVersion() % 100, sizeof(btScalar) == 8 ? "double" : "float");
    return text;
}

} // namespace

extern "C" const cb_engine cb_engine_bullet = {"bullet", 1 << 3, 0, bullet_create, bullet_step, bullet_read,
                                               bullet_destroy, bullet_describe};
