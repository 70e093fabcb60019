/* Contacts (issue 12): collisions between particles and walls they rest on, against closed forms.

   Head-on and glancing collisions against the 1D and 2D impulse formulas, restitution and its threshold,
   momentum kept to rounding and kinetic energy never growing in every contact pass (random scenes, no walls,
   no immovable particles), Newton's cradle, the broadphase against a brute-force O(N^2) search (random
   scenes, clusters, particles on cell borders, mixed radii, far from the origin), a ball at rest on the
   floor, a stack of ten at rest, a pile of 2,000 balls that settles, and bad input refused with nothing
   written. 2D and 3D in each; built in float and double. */
#define MOTUS_IMPLEMENTATION
#define MOTUS_STATIC
#include "motus.h"
#include "support/motus_test.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#ifdef MOTUS_DOUBLE
#define EPS DBL_EPSILON
#define REAL_MAX DBL_MAX
#else
#define EPS FLT_EPSILON
#define REAL_MAX FLT_MAX
#endif

enum { CAPACITY = 2048 };
typedef struct world {
    motus_scene scene;
    motus_state state;
    motus_real x[3][CAPACITY], v[3][CAPACITY], inverse_mass[CAPACITY], radius[CAPACITY];
    motus_contact_pair pairs[16 * CAPACITY];
    unsigned char scratch[CAPACITY * 1024];
} world;
static world W, BEFORE;

static uint32_t random_state = 1;
static uint32_t random_next(void) { return motus_test_xorshift32(&random_state); }
static double random_unit(void) { return (double)(random_next() >> 8) / 16777216.0; }
static motus_real random_real(double lo, double hi) { return (motus_real)(lo + (hi - lo) * random_unit()); }

/* A world of n particles in `dims`, at rest at the origin, contacts on with radius r, no walls. */
static void world_init(int dims, int n, motus_real r) {
    int d;
    memset(&W, 0, sizeof W);
    W.scene.contacts.enabled = 1;
    W.scene.contacts.radius = r;
    W.state.dimensions = dims;
    W.state.count = n;
    for (d = 0; d < dims; ++d) W.state.position[d] = W.x[d], W.state.velocity[d] = W.v[d];
}
static motus_result step(motus_real dt) {
    ENSURE(motus_scratch_size(&W.scene, &W.state) <= sizeof W.scratch);
    return motus_step(&W.scene, &W.state, dt, W.scratch, sizeof W.scratch);
}
static double mass_of(int i) {
    const motus_real w = W.state.inverse_mass ? W.inverse_mass[i] : 1;
    return 1.0 / (double)w;
}
static double kinetic_energy(void) {
    double e = 0;
    int i, d;
    for (i = 0; i < W.state.count; ++i)
        for (d = 0; d < W.state.dimensions; ++d) e += 0.5 * mass_of(i) * (double)W.v[d][i] * (double)W.v[d][i];
    return e;
}
static double momentum(int d) {
    double p = 0;
    int i;
    for (i = 0; i < W.state.count; ++i) p += mass_of(i) * (double)W.v[d][i];
    return p;
}
static int same_world(void) {
    return memcmp(W.x, BEFORE.x, sizeof W.x) == 0 && memcmp(W.v, BEFORE.v, sizeof W.v) == 0;
}

/* Two equal balls head-on: restitution 1 exchanges the velocities; restitution e leaves -e times the
   relative normal velocity; unequal masses match the 1D closed form
   v1' = v1 - (1 + e) m2/(m1 + m2) (v1 - v2), v2' = v2 + (1 + e) m1/(m1 + m2) (v1 - v2). */
TEST(head_on_matches_the_closed_form) {
    static const double restitutions[4] = {1, 0.5, 0.25, 0};
    static const double masses[3][2] = {{1, 1}, {1, 3}, {5, 0.5}};
    int dims, k, m, s;
    for (dims = 2; dims <= 3; ++dims)
        for (k = 0; k < 4; ++k)
            for (m = 0; m < 3; ++m) {
                const double e = restitutions[k], m1 = masses[m][0], m2 = masses[m][1];
                const double u1 = 2, u2 = -1, v1 = u1 - (1 + e) * m2 / (m1 + m2) * (u1 - u2);
                const double v2 = u2 + (1 + e) * m1 / (m1 + m2) * (u1 - u2);
                world_init(dims, 2, MOTUS_R(0.5));
                W.scene.contacts.restitution = (motus_real)e;
                W.state.inverse_mass = W.inverse_mass;
                W.inverse_mass[0] = (motus_real)(1 / m1), W.inverse_mass[1] = (motus_real)(1 / m2);
                W.x[0][0] = -2, W.x[0][1] = 2;
                W.v[0][0] = (motus_real)u1, W.v[0][1] = (motus_real)u2;
                for (s = 0; s < 200; ++s) ENSURE_EQ_INT(step(MOTUS_R(0.01)), MOTUS_OK);
                ENSURE_NEAR(W.v[0][0], v1, 16 * EPS * 4);
                ENSURE_NEAR(W.v[0][1], v2, 16 * EPS * 4);
                ENSURE_NEAR(momentum(0), m1 * u1 + m2 * u2, 64 * EPS * 10);
                ENSURE(W.v[1][0] == 0 && W.v[1][1] == 0);
                ENSURE(W.x[0][1] - W.x[0][0] >= 1 - 8 * EPS); /* apart again */
            }
}

/* A glancing hit of equal balls, restitution 1: along the line of centres at contact the normal components
   exchange, the tangential ones stay (the 2D closed form); the ball at rest leaves along that line. The
   solver acts on pairs within 1% of the radii's sum of touching (so that a pile's touching pairs hold), so
   the line of centres is that of up to 1% before touching: the velocities agree to 1e-2. */
TEST(glancing_hit_matches_the_closed_form) {
    int dims;
    for (dims = 2; dims <= 3; ++dims) {
        const double b = 0.6; /* impact parameter, < 2r = 1 */
        double nx, ny, un;
        int s;
        world_init(dims, 2, MOTUS_R(0.5));
        W.scene.contacts.restitution = 1;
        W.x[0][0] = -3, W.x[1][0] = 0;
        W.x[0][1] = 0, W.x[1][1] = (motus_real)b;
        W.v[0][0] = 1;
        /* at contact the centres are 1 apart: (dx, b) with dx = -sqrt(1 - b^2); the step lands on it up to
           the overlap of one step (speed 1 * h 1e-3), so the angle is within about 1e-3 */
        nx = sqrt(1 - b * b), ny = b;
        un = 1 * nx;
        for (s = 0; s < 6000; ++s) ENSURE_EQ_INT(step(MOTUS_R(0.001)), MOTUS_OK);
        ENSURE_NEAR(W.v[0][1] + 0.0, un * nx, 1e-2);
        ENSURE_NEAR(W.v[1][1] + 0.0, un * ny, 1e-2);
        ENSURE_NEAR(W.v[0][0] + 0.0, 1 - un * nx, 1e-2);
        ENSURE_NEAR(W.v[1][0] + 0.0, -un * ny, 1e-2);
        ENSURE_NEAR(momentum(0), 1, 64 * EPS);
        ENSURE_NEAR(momentum(1), 0, 64 * EPS);
        ENSURE_NEAR(kinetic_energy(), 0.5, 1e-3);
    }
}

/* Below the restitution threshold a contact does not bounce; above it, it does. */
TEST(restitution_threshold) {
    int dims;
    for (dims = 2; dims <= 3; ++dims) {
        int s;
        world_init(dims, 2, MOTUS_R(0.5));
        W.scene.contacts.restitution = 1;
        W.scene.contacts.restitution_threshold = MOTUS_R(0.5);
        W.x[0][0] = -1, W.x[0][1] = 1;
        W.v[0][0] = MOTUS_R(0.2), W.v[0][1] = MOTUS_R(-0.2); /* approach 0.4 < 0.5 */
        for (s = 0; s < 400; ++s) ENSURE_EQ_INT(step(MOTUS_R(0.01)), MOTUS_OK);
        ENSURE_NEAR(W.v[0][0], 0, 8 * EPS);
        ENSURE_NEAR(W.v[0][1], 0, 8 * EPS);
        W.v[0][0] = MOTUS_R(-0.3), W.v[0][1] = MOTUS_R(0.3); /* apart, then back at 0.6 > 0.5 */
        for (s = 0; s < 100; ++s) ENSURE_EQ_INT(step(MOTUS_R(0.01)), MOTUS_OK);
        W.v[0][0] = -W.v[0][0], W.v[0][1] = -W.v[0][1];
        for (s = 0; s < 400; ++s) ENSURE_EQ_INT(step(MOTUS_R(0.01)), MOTUS_OK);
        ENSURE_NEAR(W.v[0][0], -0.3, 16 * EPS);
        ENSURE_NEAR(W.v[0][1], 0.3, 16 * EPS);
    }
}

/* Random scenes without walls or immovable particles: every step (a contact pass per substep) keeps the
   momentum to rounding and never raises the kinetic energy (restitution <= 1, friction on). */
TEST(momentum_kept_and_energy_never_grows) {
    int dims, trial;
    random_state = 7;
    for (dims = 2; dims <= 3; ++dims)
        for (trial = 0; trial < 6; ++trial) {
            const int n = 300;
            const double side = dims == 2 ? 20 : 7;
            int i, d, s;
            world_init(dims, n, MOTUS_R(0.5));
            W.state.inverse_mass = W.inverse_mass;
            W.state.radius = trial % 2 ? W.radius : NULL;
            W.scene.contacts.restitution = (motus_real)(trial / 2) / 2;
            W.scene.contacts.friction = MOTUS_R(0.4);
            W.scene.substeps = 1 + trial % 3;
            for (i = 0; i < n; ++i) {
                W.inverse_mass[i] = random_real(0.2, 5);
                W.radius[i] = random_real(0.2, 0.7);
                for (d = 0; d < dims; ++d) W.x[d][i] = random_real(0, side), W.v[d][i] = random_real(-3, 3);
            }
            for (s = 0; s < 50; ++s) {
                double before_energy = kinetic_energy(), before_p[3], scale = 0;
                for (d = 0; d < dims; ++d) before_p[d] = momentum(d);
                for (i = 0; i < n; ++i)
                    for (d = 0; d < dims; ++d) scale += mass_of(i) * fabs((double)W.v[d][i]);
                ENSURE_EQ_INT(step(MOTUS_R(1.0) / 60), MOTUS_OK);
                for (d = 0; d < dims; ++d) ENSURE_NEAR(momentum(d), before_p[d], 64 * EPS * scale);
                ENSURE(kinetic_energy() <= before_energy * (1 + 64 * EPS));
            }
        }
}

/* Newton's cradle: five touching balls in a row, restitution 1; the first hits at 1 m/s and the last
   leaves at 1 m/s, the others at rest. */
TEST(newtons_cradle) {
    int dims;
    for (dims = 2; dims <= 3; ++dims) {
        int i, s;
        world_init(dims, 6, MOTUS_R(0.5));
        W.scene.contacts.restitution = 1;
        for (i = 0; i < 5; ++i) W.x[0][i + 1] = (motus_real)i; /* touching */
        W.x[0][0] = -3;
        W.v[0][0] = 1;
        for (s = 0; s < 300; ++s) ENSURE_EQ_INT(step(MOTUS_R(0.01)), MOTUS_OK);
        for (i = 0; i < 5; ++i) ENSURE_NEAR(W.v[0][i], 0, 64 * EPS);
        ENSURE_NEAR(W.v[0][5], 1, 64 * EPS);
        ENSURE_NEAR(momentum(0), 1, 64 * EPS);
    }
}

/* The broadphase finds exactly the pairs of a brute-force search (distance < 1.01 (r_a + r_b): in contact,
   as the solver counts it), on random scenes, clusters, particles on cell borders, mixed radii and far from
   the origin. */
static int brute_force_overlaps(int a, int b) {
    const motus_real ra = W.state.radius ? W.radius[a] : W.scene.contacts.radius;
    const motus_real rb = W.state.radius ? W.radius[b] : W.scene.contacts.radius;
    double d2 = 0, sum = ((double)ra + (double)rb) * (double)(MOTUS_R(1.0) + MOTUS_R(0.01));
    int d;
    for (d = 0; d < W.state.dimensions; ++d) {
        const double u = (double)W.x[d][b] - (double)W.x[d][a];
        d2 += u * u;
    }
    return d2 < sum * sum;
}
static int pair_order(const void *p, const void *q) {
    const motus_contact_pair *a = (const motus_contact_pair *)p, *b = (const motus_contact_pair *)q;
    return a->a != b->a ? (a->a > b->a) - (a->a < b->a) : (a->b > b->b) - (a->b < b->b);
}
static void check_broadphase(const char *what) {
    int found = -1, i, j, k = 0, n = W.state.count, borderline = 0;
    ENSURE_EQ_INT(motus_find_contacts(&W.scene, &W.state, W.scratch, sizeof W.scratch, W.pairs, 16 * CAPACITY, &found),
                  MOTUS_OK);
    ENSURE(found >= 0 && found <= 16 * CAPACITY);
    if (found > 16 * CAPACITY) return;
    for (i = 0; i < found; ++i) ENSURE(W.pairs[i].a < W.pairs[i].b);
    { /* the broadphase reads no velocity, force or mass: without them, the same pairs in the same order */
        static motus_contact_pair again[16 * CAPACITY];
        motus_state positions_only = W.state;
        int found_again = -1, d;
        for (d = 0; d < 3; ++d) positions_only.velocity[d] = NULL, positions_only.force[d] = NULL;
        positions_only.inverse_mass = NULL;
        ENSURE_EQ_INT(motus_find_contacts(&W.scene, &positions_only, W.scratch, sizeof W.scratch, again, 16 * CAPACITY,
                                          &found_again),
                      MOTUS_OK);
        ENSURE_EQ_INT(found_again, found);
        ENSURE(memcmp(again, W.pairs, sizeof again[0] * (size_t)found) == 0);
        positions_only.velocity[0] = W.v[0]; /* some velocities given, not all (the fuzzer's case) */
        found_again = -1;
        ENSURE_EQ_INT(motus_find_contacts(&W.scene, &positions_only, W.scratch, sizeof W.scratch, again, 16 * CAPACITY,
                                          &found_again),
                      MOTUS_OK);
        ENSURE_EQ_INT(found_again, found);
        positions_only.velocity[0] = W.x[1]; /* given, a velocity still may not be a position */
        ENSURE_EQ_INT(motus_find_contacts(&W.scene, &positions_only, W.scratch, sizeof W.scratch, again, 16 * CAPACITY,
                                          &found_again),
                      MOTUS_ERROR_ALIASING);
    }
    qsort(W.pairs, (size_t)found, sizeof W.pairs[0], pair_order);
    for (i = 0; i < n; ++i)
        for (j = i + 1; j < n; ++j)
            if (brute_force_overlaps(i, j)) {
                /* a pair within rounding of touching may fall either way in the header's float arithmetic */
                if (k < found && W.pairs[k].a == i && W.pairs[k].b == j) ++k;
                else ++borderline;
            }
    if (borderline != 0 || k != found) printf("  %s: %d pairs found, %d matched, %d missed\n", what, found, k, borderline);
    ENSURE(borderline == 0);
    ENSURE_EQ_INT(k, found);
}
TEST(broadphase_equals_brute_force) {
    int dims, kind;
    random_state = 11;
    for (dims = 2; dims <= 3; ++dims)
        for (kind = 0; kind < 7; ++kind) {
            const int n = kind == 1 ? 300 : 1500;
            int i, d;
            world_init(dims, n, MOTUS_R(0.5));
            for (i = 0; i < n; ++i) {
                for (d = 0; d < dims; ++d) {
                    double x = random_unit() * (dims == 2 ? 40 : 12);
                    if (kind == 1) x = random_unit() * 3; /* a cluster: many per cell */
                    if (kind == 2) x = floor(x / 1.125) * 1.125 + (random_next() & 1 ? 0 : 1.125 * 0.5); /* cells */
                    if (kind == 4) x = 3e5 + x; /* far from the origin */
                    if (kind == 5) x = -x;
                    if (kind == 6) x = 3e6 + x * 4; /* past 2^17 cells: the cells grow with the coordinates */
                    W.x[d][i] = (motus_real)x;
                }
                W.radius[i] = random_real(0.05, 1.0);
            }
            if (kind == 3 || kind == 5) W.state.radius = W.radius; /* mixed radii */
            check_broadphase(kind == 0 ? "random" : kind == 1 ? "cluster" : kind == 2 ? "cell borders" : kind == 3 ? "mixed radii" : kind == 4 ? "far" : kind == 5 ? "negative, mixed" : "very far");
        }
}

/* Two tables, one search: where the cells the particles span fit in the table, the header lays the cells
   out densely (a few runs of neighbouring buckets); one particle far away spreads them too wide and they are
   hashed. Both must list the same pairs in the same order: the cluster's pairs with one of its particles
   moved 10^6 m away along x (hashed) are its pairs without that particle's (dense), in order; and each
   list is the brute-force one. */
TEST(broadphase_dense_and_hashed_list_the_same_pairs) {
    static motus_contact_pair dense[16 * CAPACITY], hashed[16 * CAPACITY];
    int dims, mixed;
    random_state = 23;
    for (dims = 2; dims <= 3; ++dims)
        for (mixed = 0; mixed <= 1; ++mixed) {
            const int n = 1200, moved = 517;
            int i, d, found_dense = -1, found_hashed = -1, kept = 0;
            world_init(dims, n, MOTUS_R(0.5));
            for (i = 0; i < n; ++i) {
                for (d = 0; d < dims; ++d) W.x[d][i] = random_real(-9, dims == 2 ? 25 : 6);
                W.radius[i] = random_real(0.05, 1.0);
            }
            if (mixed) W.state.radius = W.radius;
            check_broadphase(mixed ? "dense, mixed radii" : "dense");
            ENSURE_EQ_INT(motus_find_contacts(&W.scene, &W.state, W.scratch, sizeof W.scratch, dense, 16 * CAPACITY,
                                              &found_dense),
                          MOTUS_OK);
            W.x[0][moved] = MOTUS_R(1e6);
            check_broadphase(mixed ? "hashed, mixed radii" : "hashed");
            ENSURE_EQ_INT(motus_find_contacts(&W.scene, &W.state, W.scratch, sizeof W.scratch, hashed, 16 * CAPACITY,
                                              &found_hashed),
                          MOTUS_OK);
            ENSURE(found_dense > n / 2 && found_hashed < found_dense);
            for (i = 0; i < found_dense && i < 16 * CAPACITY; ++i) {
                if (dense[i].a == moved || dense[i].b == moved) continue;
                ENSURE(kept < found_hashed && hashed[kept].a == dense[i].a && hashed[kept].b == dense[i].b);
                ++kept;
            }
            ENSURE_EQ_INT(kept, found_hashed);
        }
}

/* A ball dropped on the floor with restitution 0.5 comes to rest on it at floor + r: no hop. */
TEST(ball_rests_on_the_floor) {
    int dims;
    for (dims = 2; dims <= 3; ++dims) {
        int s;
        world_init(dims, 1, MOTUS_R(0.25));
        W.scene.gravity = motus_v3(0, -MOTUS_R(9.81), 0);
        W.scene.bounds_min = motus_v3(-10, 0, -10);
        W.scene.bounds_max = motus_v3(10, 10, 10);
        W.scene.restitution = MOTUS_R(0.5);
        W.x[1][0] = 3;
        for (s = 0; s < 600; ++s) ENSURE_EQ_INT(step(MOTUS_R(1.0) / 60), MOTUS_OK);
        for (s = 0; s < 60; ++s) {
            ENSURE_EQ_INT(step(MOTUS_R(1.0) / 60), MOTUS_OK);
            ENSURE(W.x[1][0] == MOTUS_R(0.25));
            ENSURE(W.v[1][0] == 0);
        }
    }
}

/* Ten balls of radius 0.5 dropped in a column onto the floor, 5% apart, and left 5 s (300 frames of 4
   substeps) to settle. */
static void settle_stack_of_ten(int dims) {
    int i, s;
    world_init(dims, 10, MOTUS_R(0.5));
    W.scene.gravity = motus_v3(0, -10, 0);
    W.scene.bounds_min = motus_v3(-5, 0, -5);
    W.scene.bounds_max = motus_v3(5, (motus_real)HUGE_VAL, 5);
    W.scene.substeps = 4;
    for (i = 0; i < 10; ++i) W.x[1][i] = MOTUS_R(0.5) + (motus_real)i * MOTUS_R(1.05);
    for (s = 0; s < 300; ++s) ENSURE_EQ_INT(step(MOTUS_R(1.0) / 60), MOTUS_OK);
}

/* Ten balls stacked on the floor rest, each on the one below, velocities 0. */
TEST(stack_of_ten_rests) {
    int dims;
    for (dims = 2; dims <= 3; ++dims) {
        int i;
        settle_stack_of_ten(dims);
        for (i = 0; i < 10; ++i) {
            ENSURE_NEAR(W.x[1][i], 0.5 + i, 32 * EPS * 10);
            ENSURE_NEAR(W.v[1][i], 0, 1e-6);
        }
    }
}

/* motus_find_contacts is for game logic (a sound when two balls hit): it lists the pairs the solver
   treats as in contact, which after a step sit at exactly r_a + r_b (the projection pushed the overlap
   out), not only those that still overlap. Head-on, restitution 0.5: the pair is listed after the step in
   which the velocities change, and not once the balls are apart; restitution 0: listed from then on
   (they move together). A resting stack of ten: its 9 pairs. */
TEST(contacts_are_listed_after_the_step_that_resolves_them) {
    int dims, k;
    for (dims = 2; dims <= 3; ++dims) {
        for (k = 0; k < 2; ++k) {
            const motus_real e = k == 0 ? MOTUS_R(0.5) : 0;
            int s, found = -1, hit = -1, listed = 0, listed_apart = 0;
            world_init(dims, 2, MOTUS_R(0.5));
            W.scene.contacts.restitution = e;
            W.x[0][0] = -2, W.x[0][1] = 2;
            W.v[0][0] = 2, W.v[0][1] = -1;
            for (s = 0; s < 120; ++s) {
                const motus_real before = W.v[0][0];
                ENSURE_EQ_INT(step(MOTUS_R(1.0) / 60), MOTUS_OK);
                ENSURE_EQ_INT(motus_find_contacts(&W.scene, &W.state, W.scratch, sizeof W.scratch, W.pairs, 4, &found),
                              MOTUS_OK);
                ENSURE(found == 0 || (found == 1 && W.pairs[0].a == 0 && W.pairs[0].b == 1));
                if (hit < 0 && W.v[0][0] != before) {
                    hit = s;
                    ENSURE_EQ_INT(found, 1); /* the step that resolved the collision left them touching */
                }
                if (found == 1) ++listed;
                if (found == 1 && W.x[0][1] - W.x[0][0] > MOTUS_R(1.01)) ++listed_apart;
            }
            ENSURE(hit > 0);
            ENSURE_EQ_INT(listed_apart, 0);
            /* and perhaps once before the hit: a step that ends within 1% of touching, approaching */
            if (e > 0) ENSURE(listed >= 1 && listed <= 3); /* apart at 0.75 m/s: past 1% within two frames */
            else ENSURE(listed == 120 - hit || listed == 121 - hit);
        }
    }
    for (dims = 2; dims <= 3; ++dims) {
        int i, found = -1;
        settle_stack_of_ten(dims);
        ENSURE_EQ_INT(motus_find_contacts(&W.scene, &W.state, W.scratch, sizeof W.scratch, W.pairs, 64, &found),
                      MOTUS_OK);
        ENSURE_EQ_INT(found, 9);
        qsort(W.pairs, (size_t)found, sizeof W.pairs[0], pair_order);
        for (i = 0; i < found && i < 9; ++i) ENSURE(W.pairs[i].a == i && W.pairs[i].b == i + 1);
    }
}

/* A ball resting in a V of two immovable balls (normals 60 degrees apart) stays at rest on them: the sweeps
   keep each contact's impulse over the pass. Clamping each increment instead threw it off the V at a quarter
   of the speed a substep of gravity gives (0.25*g*h: energy made at every substep). */
TEST(ball_in_a_v_is_not_thrown_off) {
    int dims;
    for (dims = 2; dims <= 3; ++dims) {
        const motus_real r = MOTUS_R(0.5), g = MOTUS_R(9.81), h = MOTUS_R(1.0) / 240;
        double speed = 0;
        int d, s;
        world_init(dims, 3, r);
        W.scene.gravity = motus_v3(0, -g, 0);
        W.scene.bounds_min = motus_v3(-5, 0, -5);
        W.scene.bounds_max = motus_v3(5, (motus_real)HUGE_VAL, 5);
        W.x[0][0] = -r, W.x[1][0] = r;
        W.x[0][1] = r, W.x[1][1] = r;
        W.x[0][2] = 0, W.x[1][2] = r + (motus_real)sqrt(3.0) * r; /* touching both */
        W.state.inverse_mass = W.inverse_mass;
        W.inverse_mass[0] = W.inverse_mass[1] = 0, W.inverse_mass[2] = 1;
        for (s = 0; s < 4; ++s) {
            ENSURE_EQ_INT(step(h), MOTUS_OK);
            speed = 0;
            for (d = 0; d < dims; ++d) speed += (double)W.v[d][2] * (double)W.v[d][2];
            speed = sqrt(speed);
            ENSURE(speed < 0.02 * (double)(g * h)); /* clamped increments: 0.25*g*h */
        }
        printf("  %dD: the top ball's speed after 4 substeps %.3g m/s (g*h = %.3g m/s)\n", dims, speed, (double)(g * h));
    }
}

/* A frictionless 2D pile 400 rows deep and 4 balls wide (hex-packed, touching) in a box 4,000 m from the
   origin (a float ulp of 4.9e-4 m there, more than a substep's fall at the top): it rests, overlapping by
   less than 1% of r, its top within 0.05 m of where it started after 15 frames (the packing eases a little
   under its weight: 9 mm in double, under 1 mm in float) and within 1 mm of that 15 frames later. Letting a
   ball fall into a gap of
   rounding size in the support sweep once made each substep's lifts feed the next: it blew up (overlaps of
   0.98 r) within four substeps in float. */
TEST(tall_pile_far_from_the_origin_rests) {
    const motus_real r = MOTUS_R(0.5), x0 = 4000, row = (motus_real)sqrt(3.0) * r;
    double largest = 0, top0 = 0, top1 = 0, top = 0;
    int i, q, j, n = 0, s;
    world_init(2, 0, r);
    for (j = 0; j < 400; ++j) {
        motus_real x;
        for (x = j % 2 ? 2 * r : r; x <= 4 - r; x += 2 * r, ++n) {
            W.x[0][n] = x0 + x;
            W.x[1][n] = r + (motus_real)j * row;
        }
    }
    ENSURE(n <= CAPACITY);
    W.state.count = n;
    W.scene.gravity = motus_v3(0, MOTUS_R(-9.81), 0);
    W.scene.bounds_min = motus_v3(x0, 0, 0);
    W.scene.bounds_max = motus_v3(x0 + 4, (motus_real)HUGE_VAL, 0);
    W.scene.substeps = 4;
    for (i = 0; i < n; ++i) top0 = (double)W.x[1][i] > top0 ? (double)W.x[1][i] : top0;
    for (s = 0; s < 15; ++s) ENSURE_EQ_INT(step(MOTUS_R(1.0) / 60), MOTUS_OK);
    for (i = 0; i < n; ++i) top1 = (double)W.x[1][i] > top1 ? (double)W.x[1][i] : top1;
    for (s = 0; s < 15; ++s) ENSURE_EQ_INT(step(MOTUS_R(1.0) / 60), MOTUS_OK);
    for (i = 0; i < n; ++i) {
        top = (double)W.x[1][i] > top ? (double)W.x[1][i] : top;
        for (q = i + 1; q < n && q < i + 9; ++q) { /* the rows are 4 and 3 balls long */
            const double dx = (double)W.x[0][q] - (double)W.x[0][i], dy = (double)W.x[1][q] - (double)W.x[1][i];
            const double overlap = 2 * (double)r - sqrt(dx * dx + dy * dy);
            if (overlap > largest) largest = overlap;
        }
    }
    printf("  %d balls, 120 substeps: largest overlap %.3g r, top %.5f m at 60 and %.5f m at 120 (from %.5f m)\n", n,
           largest / r, top1, top, top0);
    ENSURE(largest < 0.01 * r);
    ENSURE(fabs(top1 - top0) < 0.05);
    ENSURE(fabs(top - top1) < 1e-3);
}

/* 2,000 balls (r = 0.5, restitution 0.2, friction 0.3) dropped into a box under gravity 10: after 10 s the
   largest overlap is below 1% of r, the kinetic energy below 1e-4 of the potential energy they started
   with (above the floor), and every ball is inside the box. */
TEST(pile_of_2000_settles) {
    int dims;
    for (dims = 2; dims <= 3; ++dims) {
        const int n = 2000;
        const motus_real r = MOTUS_R(0.5), side = dims == 2 ? 40 : 12;
        const int per_row = (int)(side / (MOTUS_R(2.2) * r));
        double potential = 0, largest = 0;
        int i, d, s, found = 0;
        world_init(dims, n, r);
        random_state = 3;
        W.scene.gravity = motus_v3(0, -10, 0);
        W.scene.bounds_min = motus_v3(0, 0, 0);
        W.scene.bounds_max = motus_v3(side, (motus_real)HUGE_VAL, side);
        W.scene.restitution = W.scene.contacts.restitution = MOTUS_R(0.2);
        W.scene.contacts.friction = MOTUS_R(0.3);
        W.scene.substeps = 4;
        for (i = 0; i < n; ++i) {
            const int column = i % per_row, layer = i / per_row;
            W.x[0][i] = r * MOTUS_R(1.1) + (motus_real)column * MOTUS_R(2.2) * r + random_real(0, 0.1);
            if (dims == 2) {
                W.x[1][i] = r * MOTUS_R(1.1) + (motus_real)layer * MOTUS_R(2.2) * r + 5;
            } else {
                W.x[2][i] = r * MOTUS_R(1.1) + (motus_real)(layer % per_row) * MOTUS_R(2.2) * r;
                W.x[1][i] = r * MOTUS_R(1.1) + (motus_real)(layer / per_row) * MOTUS_R(2.2) * r + 5;
            }
            potential += 10.0 * ((double)W.x[1][i] - (double)r);
        }
        for (s = 0; s < 600; ++s) ENSURE_EQ_INT(step(MOTUS_R(1.0) / 60), MOTUS_OK);
        ENSURE_EQ_INT(motus_find_contacts(&W.scene, &W.state, W.scratch, sizeof W.scratch, W.pairs, 16 * CAPACITY, &found),
                      MOTUS_OK);
        for (i = 0; i < found; ++i) {
            double d2 = 0, overlap;
            for (d = 0; d < dims; ++d) {
                const double u = (double)W.x[d][W.pairs[i].b] - (double)W.x[d][W.pairs[i].a];
                d2 += u * u;
            }
            overlap = 2 * (double)r - sqrt(d2);
            if (overlap > largest) largest = overlap;
        }
        printf("  %dD: largest overlap %.3g r, kinetic / initial potential energy %.3g\n", dims, largest / r,
               kinetic_energy() / potential);
        ENSURE(largest < 0.01 * r);
        ENSURE(kinetic_energy() < 1e-4 * potential);
        for (i = 0; i < n; ++i)
            for (d = 0; d < dims; ++d) {
                ENSURE(W.x[d][i] >= r - 8 * EPS * side);
                if (d != 1) ENSURE(W.x[d][i] <= side - r + 8 * EPS * side);
            }
    }
}

/* Bad input: nothing written, the field named where a report is asked for. */
TEST(bad_input_is_refused) {
    motus_check_report report;
    int dims, found = 7;
    for (dims = 2; dims <= 3; ++dims) {
        world_init(dims, 4, MOTUS_R(0.5));
        W.x[0][1] = MOTUS_R(0.5), W.x[0][2] = 5, W.x[0][3] = 10;
        W.v[0][0] = 1;
        memcpy(&BEFORE, &W, sizeof W);
        W.scene.contacts.radius = -1;
        ENSURE_EQ_INT(step(MOTUS_R(0.1)), MOTUS_ERROR_INVALID_CONTACTS);
        ENSURE_EQ_INT(motus_scene_check(&W.scene, dims, 4, &report), MOTUS_ERROR_INVALID_CONTACTS);
        ENSURE(strcmp(report.field_name, "scene.contacts.radius") == 0);
        W.scene.contacts.radius = (motus_real)NAN;
        ENSURE_EQ_INT(step(MOTUS_R(0.1)), MOTUS_ERROR_NOT_FINITE);
        W.scene.contacts.radius = (motus_real)(REAL_MAX / 4);
        ENSURE_EQ_INT(step(MOTUS_R(0.1)), MOTUS_ERROR_INVALID_CONTACTS);
        W.scene.contacts.radius = MOTUS_R(0.5);
        W.scene.contacts.friction = -MOTUS_R(0.1);
        ENSURE_EQ_INT(motus_scene_check(&W.scene, dims, 4, &report), MOTUS_ERROR_INVALID_CONTACTS);
        ENSURE(strcmp(report.field_name, "scene.contacts.friction") == 0);
        W.scene.contacts.friction = 0;
        W.scene.contacts.restitution = MOTUS_R(1.5);
        ENSURE_EQ_INT(motus_scene_check(&W.scene, dims, 4, &report), MOTUS_ERROR_INVALID_RESTITUTION);
        ENSURE(strcmp(report.field_name, "scene.contacts.restitution") == 0);
        W.scene.contacts.restitution = 0;
        W.scene.contacts.restitution_threshold = -1;
        ENSURE_EQ_INT(step(MOTUS_R(0.1)), MOTUS_ERROR_INVALID_CONTACTS);
        W.scene.contacts.restitution_threshold = 0;
        W.scene.contacts.iterations = -1;
        ENSURE_EQ_INT(step(MOTUS_R(0.1)), MOTUS_ERROR_INVALID_CONTACTS);
        W.scene.contacts.iterations = 0;
        /* per-particle radii: negative, NaN; the state check names the particle */
        W.state.radius = W.radius;
        W.radius[0] = W.radius[1] = W.radius[3] = MOTUS_R(0.5);
        W.radius[2] = -MOTUS_R(0.5);
        ENSURE_EQ_INT(step(MOTUS_R(0.1)), MOTUS_ERROR_INVALID_CONTACTS);
        ENSURE_EQ_INT(motus_state_check(&W.scene, &W.state, 0, 4, &report), MOTUS_ERROR_INVALID_CONTACTS);
        ENSURE(report.index == 2 && report.field == MOTUS_FIELD_RADIUS && strcmp(report.field_name, "radius") == 0);
        W.radius[2] = (motus_real)NAN;
        ENSURE_EQ_INT(step(MOTUS_R(0.1)), MOTUS_ERROR_NOT_FINITE);
        ENSURE_EQ_INT(motus_find_contacts(&W.scene, &W.state, W.scratch, sizeof W.scratch, W.pairs, 8, &found),
                      MOTUS_ERROR_NOT_FINITE);
        /* an earlier particle's bad mass is named before a later one's NaN radius, as motus_state_check names
           it, at any dt (a fuzz finding: the radii were checked first) */
        {
            const motus_real *inverse_mass = W.state.inverse_mass, kept = W.inverse_mass[1];
            W.state.inverse_mass = W.inverse_mass;
            W.inverse_mass[1] = -1;
            ENSURE_EQ_INT(motus_state_check(&W.scene, &W.state, 0, 4, &report), MOTUS_ERROR_INVALID_MASS);
            ENSURE(report.index == 1);
            ENSURE_EQ_INT(step(MOTUS_R(0.1)), MOTUS_ERROR_INVALID_MASS);
            ENSURE_EQ_INT(step(0), MOTUS_ERROR_INVALID_MASS);
            W.inverse_mass[1] = kept;
            W.state.inverse_mass = inverse_mass;
        }
        W.radius[2] = MOTUS_R(0.5);
        /* scratch: too small, NULL, misaligned */
        ENSURE_EQ_INT(motus_step(&W.scene, &W.state, MOTUS_R(0.1), W.scratch, motus_scratch_size(&W.scene, &W.state) - 1),
                      MOTUS_ERROR_SCRATCH_TOO_SMALL);
        ENSURE_EQ_INT(motus_step(&W.scene, &W.state, MOTUS_R(0.1), NULL, 0), MOTUS_ERROR_SCRATCH_TOO_SMALL);
        ENSURE_EQ_INT(motus_step(&W.scene, &W.state, MOTUS_R(0.1), W.scratch + 1, sizeof W.scratch - 1),
                      MOTUS_ERROR_SCRATCH_TOO_SMALL);
        /* NaN position */
        W.x[1][3] = (motus_real)NAN;
        memcpy(BEFORE.x, W.x, sizeof W.x);
        ENSURE_EQ_INT(step(MOTUS_R(0.1)), MOTUS_ERROR_NOT_FINITE);
#ifdef MOTUS_CHECKED
        ENSURE(same_world());
#endif
        W.x[1][3] = 0;
        memcpy(BEFORE.x, W.x, sizeof W.x);
        memcpy(BEFORE.v, W.v, sizeof W.v);
        ENSURE(same_world());
        /* find_contacts arguments; the range API does not take contacts */
        ENSURE_EQ_INT(motus_find_contacts(&W.scene, &W.state, W.scratch, sizeof W.scratch, NULL, 8, &found),
                      MOTUS_ERROR_NULL_POINTER);
        ENSURE_EQ_INT(motus_find_contacts(&W.scene, &W.state, W.scratch, sizeof W.scratch, W.pairs, 8, NULL),
                      MOTUS_ERROR_NULL_POINTER);
        ENSURE_EQ_INT(motus_find_contacts(&W.scene, &W.state, W.scratch, sizeof W.scratch, W.pairs, -1, &found),
                      MOTUS_ERROR_INVALID_COUNT);
        ENSURE_EQ_INT(motus_find_contacts(&W.scene, &W.state, W.scratch, 4, W.pairs, 8, &found),
                      MOTUS_ERROR_SCRATCH_TOO_SMALL);
        ENSURE_EQ_INT(motus_step_range(&W.scene, &W.state, 0, 4, MOTUS_R(0.1)), MOTUS_ERROR_UNSUPPORTED);
        ENSURE(same_world());
        /* a capacity smaller than the pairs: the count is whole, only `capacity` written */
        ENSURE_EQ_INT(motus_find_contacts(&W.scene, &W.state, W.scratch, sizeof W.scratch, W.pairs, 0, &found), MOTUS_OK);
        ENSURE_EQ_INT(found, 1);
        /* a count whose scratch would overflow size_t */
        W.state.count = INT32_MAX;
        ENSURE(motus_scratch_size(&W.scene, &W.state) == (size_t)-1 ||
               motus_scratch_size(&W.scene, &W.state) > (size_t)INT32_MAX * 16);
        ENSURE_EQ_INT(motus_step(&W.scene, &W.state, MOTUS_R(0.1), W.scratch, sizeof W.scratch),
                      MOTUS_ERROR_SCRATCH_TOO_SMALL);
    }
}

/* Immovable particles are obstacles: a ball bounces off one that does not move. */
TEST(immovable_particles_are_obstacles) {
    int dims;
    for (dims = 2; dims <= 3; ++dims) {
        int s;
        world_init(dims, 2, MOTUS_R(0.5));
        W.state.inverse_mass = W.inverse_mass;
        W.inverse_mass[0] = 1, W.inverse_mass[1] = 0;
        W.scene.contacts.restitution = 1;
        W.x[0][0] = -3;
        W.v[0][0] = 2;
        for (s = 0; s < 300; ++s) ENSURE_EQ_INT(step(MOTUS_R(0.01)), MOTUS_OK);
        ENSURE_NEAR(W.v[0][0], -2, 16 * EPS);
        ENSURE(W.x[0][1] == 0 && W.v[0][1] == 0);
    }
}

/* Radii as an array of their own beside the particle structs (motus_state_of_particles: radius_stride 1,
   though the structs' stride is 7 or 10 reals), and at a stride of their own: each particle gets its own
   radius, read nowhere else (a radius read at the structs' stride ran past the array: ASan). Two balls of
   radii 1 and 3, 3.5 apart along x, overlap by 0.5: one step pushes them exactly 4 apart. */
TEST(radii_have_their_own_stride) {
    int dims;
    for (dims = 2; dims <= 3; ++dims) {
        motus_particle p2[2];
        motus_particle3 p3[2];
        motus_real *radii = (motus_real *)malloc(2 * sizeof *radii), spaced[5] = {1, -7, -7, -7, 3};
        motus_check_report report;
        int i, layout;
        ENSURE(radii != NULL);
        radii[0] = 1, radii[1] = 3;
        for (layout = 0; layout < 2; ++layout) {
            motus_real gap;
            world_init(dims, 2, 0);
            if (dims == 2) {
                for (i = 0; i < 2; ++i) ENSURE_EQ_INT(motus_particle_init(&p2[i], motus_v2(MOTUS_R(3.5) * (motus_real)i, 0), 1), MOTUS_OK);
                W.state = motus_state_of_particles(p2, 2);
            } else {
                for (i = 0; i < 2; ++i)
                    ENSURE_EQ_INT(motus_particle3_init(&p3[i], motus_v3(MOTUS_R(3.5) * (motus_real)i, 0, 0), 1), MOTUS_OK);
                W.state = motus_state_of_particles3(p3, 2);
            }
            ENSURE_EQ_INT(W.state.radius_stride, 1);
            W.state.radius = radii;
            if (layout == 1) W.state.radius = spaced, W.state.radius_stride = 4;
            ENSURE_EQ_INT(motus_state_check(&W.scene, &W.state, 0, 2, &report), MOTUS_OK);
            ENSURE_EQ_INT(step(MOTUS_R(0.01)), MOTUS_OK);
            gap = dims == 2 ? p2[1].position.x - p2[0].position.x : p3[1].position.x - p3[0].position.x;
            ENSURE_NEAR(gap, 4, 8 * EPS);
            /* a bad radius is named at its particle */
            if (layout == 1) spaced[4] = -1;
            else radii[1] = -1;
            ENSURE_EQ_INT(motus_state_check(&W.scene, &W.state, 0, 2, &report), MOTUS_ERROR_INVALID_CONTACTS);
            ENSURE(report.index == 1 && report.field == MOTUS_FIELD_RADIUS);
            ENSURE_EQ_INT(step(MOTUS_R(0.01)), MOTUS_ERROR_INVALID_CONTACTS);
            spaced[4] = 3, radii[1] = 3;
            W.state.radius_stride = -1;
            ENSURE_EQ_INT(motus_state_check(&W.scene, &W.state, 0, 2, &report), MOTUS_ERROR_INVALID_STRIDE);
            ENSURE(strcmp(report.field_name, "state.radius_stride") == 0);
        }
        free(radii);
    }
}

/* The largest overlap over every pair of the first n particles (brute force). */
static double largest_overlap(int n) {
    double largest = 0;
    int i, k, d;
    for (i = 0; i < n; ++i)
        for (k = i + 1; k < n; ++k) {
            const double sum = (double)(W.state.radius ? W.radius[i] + W.radius[k] : 2 * W.scene.contacts.radius);
            double d2 = 0;
            for (d = 0; d < W.state.dimensions; ++d) {
                const double u = (double)W.x[d][k] - (double)W.x[d][i];
                d2 += u * u;
            }
            if (sum - sqrt(d2) > largest) largest = sum - sqrt(d2);
        }
    return largest;
}

/* More balls in the floor's row than fit between the walls (what a frame hitch leaves when it presses a
   pile into its floor: every ball clamped to the floor's height, side by side): they rise into a second
   row, not press sideways for ever (100 balls where 79 fit kept overlaps of 0.8 r for 10 s). In 3D the row
   runs along x in a box one ball deep in z. */
TEST(overfull_row_rises) {
    int dims;
    for (dims = 2; dims <= 3; ++dims) {
        const int n = 100;
        int i, s;
        world_init(dims, n, 5);
        W.scene.gravity = motus_v3(0, -500, 0);
        W.scene.bounds_min = motus_v3(0, 0, 0);
        W.scene.bounds_max = motus_v3(800, (motus_real)HUGE_VAL, 10);
        for (i = 0; i < n; ++i) {
            W.x[0][i] = 5 + (motus_real)i * (MOTUS_R(790.0) / (motus_real)n);
            W.x[1][i] = 5;
            if (dims == 3) W.x[2][i] = 5;
        }
        for (s = 0; s < 600; ++s) ENSURE_EQ_INT(step(MOTUS_R(1.0) / 60), MOTUS_OK);
        printf("  %dD: largest overlap after 10 s %.3g r (it starts at 0.42 r)\n", dims, largest_overlap(n) / 5);
        ENSURE(largest_overlap(n) < 0.15 * 5);
    }
}

/* Particles far away change nothing near the origin: a ball dropped 0.06 m onto an immovable one lands as
   it does alone, bit for bit, beside one far particle, beside a far pair of touching ones, and beside a
   far one while 30 immovable ones in one spot overflow the pair list (a far coordinate set the rounding of
   every gap: it took 84 frames to land, not 6), and a pile with an immovable particle far above it settles (binned by height
   over the lowest to the highest, the pile shared a bin or two and lost its bottom-up order: overlaps of
   1.96 r). */
TEST(far_particle_changes_nothing_nearby) {
    int dims;
    for (dims = 2; dims <= 3; ++dims) {
        motus_real alone[60];
        const motus_real distance = sizeof(motus_real) == sizeof(float) ? MOTUS_R(1e6) : (motus_real)1e15;
        int far, s, i;
        for (far = 0; far <= 3; ++far) {
            /* 0: alone; 1: one far particle; 2: a far touching pair; 3: a far one and a crowd */
            const int count = far == 0 ? 2 : far == 1 ? 3 : far == 2 ? 4 : 33;
            world_init(dims, count, 1);
            W.state.inverse_mass = W.inverse_mass;
            for (i = 0; i < count; ++i) W.inverse_mass[i] = 0;
            W.inverse_mass[1] = 1;
            W.x[1][1] = MOTUS_R(2.06);
            W.x[0][2] = distance;
            if (far == 2) W.x[0][3] = distance + 2; /* touching particle 2 */
            for (i = 3; far == 3 && i < count; ++i) W.x[0][i] = -50; /* all in one spot */
            W.scene.gravity = motus_v3(0, -10, 0);
            W.scene.substeps = 4;
            for (s = 0; s < 60; ++s) {
                ENSURE_EQ_INT(step(MOTUS_R(1.0) / 60), MOTUS_OK);
                if (!far) alone[s] = W.x[1][1];
                else ENSURE(W.x[1][1] == alone[s]);
            }
            ENSURE(W.x[1][1] == 2 && W.v[1][1] == 0);
        }
        /* a pile of 400 in a box 20 balls wide, listed from the top row down, the immovable one 10^6 radii
           above it */
        {
            const int n = 400;
            world_init(dims, n + 1, MOTUS_R(0.5));
            W.state.inverse_mass = W.inverse_mass;
            W.scene.gravity = motus_v3(0, -10, 0);
            W.scene.bounds_min = motus_v3(0, 0, 0);
            W.scene.bounds_max = motus_v3(dims == 2 ? 20 : 5, (motus_real)HUGE_VAL, 4);
            W.scene.contacts.friction = MOTUS_R(0.3);
            W.scene.substeps = 4;
            for (i = 0; i < n; ++i) {
                const int per_row = dims == 2 ? 18 : 16, column = i % per_row, row = i / per_row;
                W.inverse_mass[i] = 1;
                W.x[0][i] = MOTUS_R(0.55) + (motus_real)(dims == 2 ? column : column % 4) * MOTUS_R(1.1);
                W.x[1][i] = MOTUS_R(0.55) + (motus_real)(n / per_row - row) * MOTUS_R(1.1); /* top row first */
                if (dims == 3) W.x[2][i] = MOTUS_R(0.55) + (motus_real)(column / 4) * MOTUS_R(0.9);
            }
            W.inverse_mass[n] = 0, W.x[0][n] = 2, W.x[1][n] = MOTUS_R(5e5), W.x[2][n] = 2;
            for (s = 0; s < 300; ++s) ENSURE_EQ_INT(step(MOTUS_R(1.0) / 60), MOTUS_OK);
            W.state.count = n; /* the pile's own kinetic energy (the immovable one has no mass to count) */
            printf("  %dD: a pile of %d with a particle 10^6 r above: largest overlap %.3g r, kinetic energy %.3g\n",
                   dims, n, largest_overlap(n) / 0.5, kinetic_energy());
            ENSURE(largest_overlap(n) < 0.01 * 0.5);
            ENSURE(kinetic_energy() < 1e-3);
        }
    }
}

/* Friction at any scale: a ball lands on the floor at (3s, -s) with friction 0.5 and leaves at 2.5s along
   the floor, s = 1 or 1e19 (float; 1e150 in double): at 1e19 the square of the sliding speed overflowed and
   friction was dropped. */
TEST(friction_at_any_scale) {
    int dims, big;
    for (dims = 2; dims <= 3; ++dims)
        for (big = 0; big <= 1; ++big) {
            const double scale = !big ? 1 : sizeof(motus_real) == sizeof(float) ? 1e19 : 1e150;
            world_init(dims, 1, 1);
            W.x[1][0] = 1;
            W.v[0][0] = (motus_real)(3 * scale), W.v[1][0] = (motus_real)-scale;
            W.scene.contacts.friction = MOTUS_R(0.5);
            W.scene.contacts.restitution_threshold = (motus_real)(10 * scale); /* no bounce */
            W.scene.bounds_min = motus_v3(-(motus_real)HUGE_VAL, 0, -(motus_real)HUGE_VAL);
            W.scene.bounds_max = motus_v3((motus_real)HUGE_VAL, (motus_real)HUGE_VAL, (motus_real)HUGE_VAL);
            ENSURE_EQ_INT(step((motus_real)(0.01 / scale)), MOTUS_OK);
            ENSURE_NEAR((double)W.v[0][0] / scale, 2.5, 1e-5);
            ENSURE(W.v[1][0] == 0);
        }
}

/* A head-on hit at speeds whose difference overflows (2e38 m/s each way in float, 1e308 in double: the
   approach speed is past the largest real, the velocities after it are not) bounces as at any speed: equal
   masses with restitution 1 exchange their velocities, with 1/2 they leave at half the approach speed. */
TEST(head_on_at_any_speed) {
    int dims, half;
    for (dims = 2; dims <= 3; ++dims)
        for (half = 0; half <= 1; ++half) {
            /* balls of radius 1e30 (1e300): a step of 1e-3 radius is a dt of a normal real */
            const int is_float = sizeof(motus_real) == sizeof(float);
            const double speed = is_float ? 2e38 : 1e308, e = half ? 0.5 : 1, radius = is_float ? 1e30 : 1e300;
            world_init(dims, 2, (motus_real)radius);
            W.x[0][1] = (motus_real)(1.999 * radius);
            W.v[0][0] = (motus_real)speed, W.v[0][1] = (motus_real)-speed;
            W.scene.contacts.restitution = (motus_real)e;
            ENSURE_EQ_INT(step((motus_real)(1e-4 * radius / speed)), MOTUS_OK);
            ENSURE_NEAR((double)W.v[0][0] / speed, -e, 1e-5);
            ENSURE_NEAR((double)W.v[0][1] / speed, e, 1e-5);
            ENSURE(W.v[1][0] == 0 && W.v[1][1] == 0);
        }
}

/* A count of 0 with contacts on needs no scratch and steps nothing; an axis of the bounds whose min and
   max are both 0 has no walls (the 2D bounds in a 3D scene leave z free). */
TEST(zero_means_nothing) {
    int dims, contacts;
    motus_contact_pair pair;
    int found = -1;
    world_init(2, 0, 1);
    ENSURE(motus_scratch_size(&W.scene, &W.state) == 0);
    ENSURE_EQ_INT(motus_step(&W.scene, &W.state, MOTUS_R(0.1), NULL, 0), MOTUS_OK);
    ENSURE_EQ_INT(motus_find_contacts(&W.scene, &W.state, NULL, 0, &pair, 1, &found), MOTUS_OK);
    ENSURE(found == 0);
    for (dims = 2; dims <= 3; ++dims)
        for (contacts = 0; contacts <= 1; ++contacts) {
            world_init(dims, 1, 1);
            W.scene.contacts.enabled = contacts;
            W.scene.bounds_max = motus_v3(10, 10, 0);
            W.x[0][0] = W.x[1][0] = 5;
            W.v[2][0] = 1;
            ENSURE_EQ_INT(step(1), MOTUS_OK);
            ENSURE(W.x[0][0] == 5 && W.x[1][0] == 5);
            if (dims == 3) ENSURE(W.x[2][0] == 1 && W.v[2][0] == 1);
        }
}

static const motus_test_case TESTS[] = {
    TEST_CASE(head_on_matches_the_closed_form),
    TEST_CASE(glancing_hit_matches_the_closed_form),
    TEST_CASE(restitution_threshold),
    TEST_CASE(momentum_kept_and_energy_never_grows),
    TEST_CASE(newtons_cradle),
    TEST_CASE(broadphase_equals_brute_force),
    TEST_CASE(broadphase_dense_and_hashed_list_the_same_pairs),
    TEST_CASE(ball_rests_on_the_floor),
    TEST_CASE(stack_of_ten_rests),
    TEST_CASE(contacts_are_listed_after_the_step_that_resolves_them),
    TEST_CASE(ball_in_a_v_is_not_thrown_off),
    TEST_CASE(tall_pile_far_from_the_origin_rests),
    TEST_CASE(pile_of_2000_settles),
    TEST_CASE(bad_input_is_refused),
    TEST_CASE(immovable_particles_are_obstacles),
    TEST_CASE(radii_have_their_own_stride),
    TEST_CASE(overfull_row_rises),
    TEST_CASE(far_particle_changes_nothing_nearby),
    TEST_CASE(friction_at_any_scale),
    TEST_CASE(head_on_at_any_speed),
    TEST_CASE(zero_means_nothing),
};

int main(int argc, char **argv) { return motus_test_main(argc, argv, TESTS, TEST_COUNT(TESTS)); }
