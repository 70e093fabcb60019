/* collisions_brute.c - the brute-force peer of bench/collisions: the pair loop a user would write, with the
   plain contact model of COLLISIONS.md, every pair tested instead of a grid. Each substep of dt/substeps:
   semi-implicit Euler under gravity; the touching pairs found by testing all N(N-1)/2 (once per substep, as a
   broadphase would); `iterations` Gauss-Seidel sweeps of velocity impulses along the normal (restitution 0:
   the approach speed removed, equal masses), the walls as contacts at the ball's radius; then `iterations`
   sweeps of position projection (split impulse: positions only, no velocity change, so no energy added).
   Float, like motus's default motus_real; the same substeps and iterations as motus. motus's own solver has
   more since (pairs kept within 1.1 times the radii's sum, a support sweep that carries a pile's weight:
   motus.h >>contacts); the loop keeps the plain model. Capped at N = 10^4 by the driver (10^8 pair tests per
   substep at 10^5). */
#include "collisions.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct brute {
    int dims, n, substeps, iterations;
    float r, g, h;
    float lo[3], hi[3];
    float *x[3], *v[3];
    int *pairs; /* 2 ints a contact */
    size_t pair_count, pair_capacity;
} brute;

static void brute_destroy(void *world) {
    brute *b = (brute *)world;
    if (!b) return;
    for (int c = 0; c < 3; ++c) {
        free(b->x[c]);
        free(b->v[c]);
    }
    free(b->pairs);
    free(b);
}

static void *brute_create(const cb_scene *s) {
    brute *b = (brute *)calloc(1, sizeof *b);
    if (!b) return NULL;
    b->dims = s->dims;
    b->n = s->n;
    b->substeps = s->substeps > 0 ? s->substeps : 1;
    b->iterations = s->iterations > 0 ? s->iterations : 4;
    b->r = (float)s->r;
    b->g = (float)s->g;
    b->h = (float)(s->dt / b->substeps);
    for (int c = 0; c < s->dims; ++c) {
        b->lo[c] = (float)s->box_min[c];
        b->hi[c] = (float)s->box_max[c]; /* +Inf stays +Inf */
        b->x[c] = (float *)malloc(sizeof(float) * (size_t)s->n);
        b->v[c] = (float *)malloc(sizeof(float) * (size_t)s->n);
        if (!b->x[c] || !b->v[c]) {
            brute_destroy(b);
            return NULL;
        }
        for (int i = 0; i < s->n; ++i) {
            b->x[c][i] = (float)s->x[c][i];
            b->v[c][i] = (float)s->v[c][i];
        }
    }
    b->pair_capacity = (size_t)s->n * 8 + 64;
    b->pairs = (int *)malloc(sizeof(int) * 2 * b->pair_capacity);
    if (!b->pairs) {
        brute_destroy(b);
        return NULL;
    }
    return b;
}

/* All pairs closer than 2r; grows the list (rarely: it starts at 8 contacts a ball). */
static int brute_find_pairs(brute *b) {
    const float reach = 2 * b->r, reach2 = reach * reach;
    const int n = b->n, dims = b->dims;
    const float *x = b->x[0], *y = b->x[1], *z = dims == 3 ? b->x[2] : NULL;
    b->pair_count = 0;
    for (int i = 0; i < n; ++i) {
        const float xi = x[i], yi = y[i], zi = z ? z[i] : 0;
        for (int j = i + 1; j < n; ++j) {
            const float dx = x[j] - xi, dy = y[j] - yi, dz = z ? z[j] - zi : 0;
            if (dx * dx + dy * dy + dz * dz < reach2) {
                if (b->pair_count == b->pair_capacity) {
                    size_t capacity = b->pair_capacity * 2;
                    int *grown = (int *)realloc(b->pairs, sizeof(int) * 2 * capacity);
                    if (!grown) return 1;
                    b->pairs = grown;
                    b->pair_capacity = capacity;
                }
                b->pairs[2 * b->pair_count] = i;
                b->pairs[2 * b->pair_count + 1] = j;
                ++b->pair_count;
            }
        }
    }
    return 0;
}

static int brute_step(void *world) {
    brute *b = (brute *)world;
    const int n = b->n, dims = b->dims;
    const float h = b->h, r = b->r, reach = 2 * r;
    for (int sub = 0; sub < b->substeps; ++sub) {
        /* integrate: semi-implicit Euler */
        for (int i = 0; i < n; ++i) b->v[1][i] -= b->g * h;
        for (int c = 0; c < dims; ++c)
            for (int i = 0; i < n; ++i) b->x[c][i] += b->v[c][i] * h;
        if (brute_find_pairs(b)) return 1;
        /* velocity: remove the approach speed along each normal (restitution 0, equal masses) */
        for (int it = 0; it < b->iterations; ++it) {
            for (size_t k = 0; k < b->pair_count; ++k) {
                const int i = b->pairs[2 * k], j = b->pairs[2 * k + 1];
                float d[3] = {0, 0, 0}, d2 = 0;
                for (int c = 0; c < dims; ++c) {
                    d[c] = b->x[c][j] - b->x[c][i];
                    d2 += d[c] * d[c];
                }
                if (d2 <= 0) continue;
                const float inv = 1 / sqrtf(d2);
                float vn = 0;
                for (int c = 0; c < dims; ++c) vn += (b->v[c][j] - b->v[c][i]) * d[c] * inv;
                if (vn >= 0) continue;
                const float impulse = -0.5f * vn; /* (1 + e) * -vn / (w_i + w_j), e = 0, w = 1 */
                for (int c = 0; c < dims; ++c) {
                    b->v[c][i] -= impulse * d[c] * inv;
                    b->v[c][j] += impulse * d[c] * inv;
                }
            }
            for (int c = 0; c < dims; ++c)
                for (int i = 0; i < n; ++i) {
                    if (b->x[c][i] < b->lo[c] + r && b->v[c][i] < 0) b->v[c][i] = 0;
                    if (b->x[c][i] > b->hi[c] - r && b->v[c][i] > 0) b->v[c][i] = 0;
                }
        }
        /* position: project the overlaps away, half to each ball; the walls clamp */
        for (int it = 0; it < b->iterations; ++it) {
            for (size_t k = 0; k < b->pair_count; ++k) {
                const int i = b->pairs[2 * k], j = b->pairs[2 * k + 1];
                float d[3] = {0, 0, 0}, d2 = 0;
                for (int c = 0; c < dims; ++c) {
                    d[c] = b->x[c][j] - b->x[c][i];
                    d2 += d[c] * d[c];
                }
                if (d2 >= reach * reach || d2 <= 0) continue;
                const float dist = sqrtf(d2), push = 0.5f * (reach - dist) / dist;
                for (int c = 0; c < dims; ++c) {
                    b->x[c][i] -= push * d[c];
                    b->x[c][j] += push * d[c];
                }
            }
            for (int c = 0; c < dims; ++c)
                for (int i = 0; i < n; ++i) {
                    if (b->x[c][i] < b->lo[c] + r) b->x[c][i] = b->lo[c] + r;
                    if (b->x[c][i] > b->hi[c] - r) b->x[c][i] = b->hi[c] - r;
                }
        }
    }
    return 0;
}

static void brute_read(void *world, double *x[3], double *v[3]) {
    const brute *b = (const brute *)world;
    for (int c = 0; c < b->dims; ++c)
        for (int i = 0; i < b->n; ++i) {
            x[c][i] = b->x[c][i];
            v[c][i] = b->v[c][i];
        }
}

static const char *brute_describe(void) {
    return "all N(N-1)/2 pairs tested once a substep; float; the plain model of COLLISIONS.md (Gauss-Seidel "
           "velocity impulses on touching pairs, then position projection; no contact reach or support sweep, "
           "which motus's solver has), motus's substeps (4, or --substeps K) and iterations (4)";
}

const cb_engine cb_engine_brute = {"brute", (1 << 2) | (1 << 3), 10000, brute_create, brute_step, brute_read,
                                   brute_destroy, brute_describe};
