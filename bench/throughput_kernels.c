/* throughput_kernels.c - the C side of bench/throughput: every timed loop that is not odeint's.
   Compiled twice in each build by bench/CMakeLists.txt, in float (the default motus_real) and with
   MOTUS_DOUBLE; the public functions get the suffix _float or _double (see throughput.h).

   Every timed step is one call of a function the compiler may neither inline nor specialise (KERNEL), made
   from the repetition loop in throughput_run. Inlined, gcc -O3 interchanges the repetition loop with the
   particle loop and a "step" then reads memory once for many steps: a loop that looks 5x faster than memory
   allows. The scene's numbers reach every kernel as run-time values, as they would in a game.

   Arrays: one per component (x[], y[], vx[], ...), each 64-byte aligned (posix_memalign), so that motus,
   which aligns its vector stores to the first position array, finds every array aligned the same way. */
#define _POSIX_C_SOURCE 200809L /* posix_memalign, clock_gettime under -std=c99 */

#include "motus.h"
#include "throughput.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#ifdef _OPENMP
#include <omp.h>
#endif

#ifdef MOTUS_DOUBLE
#define NAME(name) name##_double
#else
#define NAME(name) name##_float
#endif

/* noipa: no inlining, no cloning, no constants propagated from the call site (gcc >= 8). */
#if defined(__GNUC__) && !defined(__clang__)
#define KERNEL __attribute__((noipa))
/* A copy loop would otherwise become a call to memcpy, which streams large copies past the cache with
   non-temporal stores: a different experiment from the one the step makes. */
#define NO_MEMCPY __attribute__((optimize("no-tree-loop-distribute-patterns")))
#elif defined(__clang__)
#define KERNEL __attribute__((noinline))
#define NO_MEMCPY
#else
#define KERNEL
#define NO_MEMCPY
#endif

typedef motus_real real;

/* ---- the reference program's particle, as the textbook writes it ---------------------------------- */
typedef struct vec2 {
    real x, y;
} vec2;
typedef struct vec3 {
    real x, y, z;
} vec3;
typedef struct particle2 {
    vec2 force, velocity, position;
    real mass;
} particle2;
typedef struct particle3 {
    vec3 force, velocity, position;
    real mass;
} particle3;

static inline vec2 v2(real x, real y) {
    vec2 v;
    v.x = x, v.y = y;
    return v;
}
static inline vec2 v2_add(vec2 a, vec2 b) { return v2(a.x + b.x, a.y + b.y); }
static inline vec2 v2_scale(vec2 a, real s) { return v2(a.x * s, a.y * s); }
static inline vec2 v2_div(vec2 a, real s) { return v2(a.x / s, a.y / s); }
static inline vec3 v3(real x, real y, real z) {
    vec3 v;
    v.x = x, v.y = y, v.z = z;
    return v;
}
static inline vec3 v3_add(vec3 a, vec3 b) { return v3(a.x + b.x, a.y + b.y, a.z + b.z); }
static inline vec3 v3_scale(vec3 a, real s) { return v3(a.x * s, a.y * s, a.z * s); }
static inline vec3 v3_div(vec3 a, real s) { return v3(a.x / s, a.y / s, a.z / s); }

/* The reference program's frame with gravity: clear the force, add the weight m*g, v += F/m*dt,
   x += v*dt, v *= DAMPING. */
static KERNEL void textbook_step2(particle2 *particles, int n, vec2 gravity, real damping, real dt) {
    int i;
    for (i = 0; i < n; ++i) {
        particle2 *p = &particles[i];
        p->force = v2(0, 0);
        p->force = v2_add(p->force, v2_scale(gravity, p->mass));
        p->velocity = v2_add(p->velocity, v2_scale(v2_div(p->force, p->mass), dt));
        p->position = v2_add(p->position, v2_scale(p->velocity, dt));
        p->velocity = v2_scale(p->velocity, damping);
    }
}
static KERNEL void textbook_step3(particle3 *particles, int n, vec3 gravity, real damping, real dt) {
    int i;
    for (i = 0; i < n; ++i) {
        particle3 *p = &particles[i];
        p->force = v3(0, 0, 0);
        p->force = v3_add(p->force, v3_scale(gravity, p->mass));
        p->velocity = v3_add(p->velocity, v3_scale(v3_div(p->force, p->mass), dt));
        p->position = v3_add(p->position, v3_scale(p->velocity, dt));
        p->velocity = v3_scale(p->velocity, damping);
    }
}

/* ---- the hand-written loops: exactly the scene, the operations in motus's order ------------------------
   Per particle (see motus.h, "Batch kernels"): a = F*inverse_mass + g - k*v; v += a*h; x += v*h;
   v *= damping. A term the scene lacks is simply not written. */
static KERNEL void hand_drift2(int n, real *restrict x, real *restrict y, const real *restrict vx,
                               const real *restrict vy, real h) {
    int i;
    for (i = 0; i < n; ++i) {
        x[i] = x[i] + vx[i] * h;
        y[i] = y[i] + vy[i] * h;
    }
}
static KERNEL void hand_drift3(int n, real *restrict x, real *restrict y, real *restrict z, const real *restrict vx,
                               const real *restrict vy, const real *restrict vz, real h) {
    int i;
    for (i = 0; i < n; ++i) {
        x[i] = x[i] + vx[i] * h;
        y[i] = y[i] + vy[i] * h;
        z[i] = z[i] + vz[i] * h;
    }
}

static KERNEL void hand_gravity2(int n, real *restrict x, real *restrict y, real *restrict vx, real *restrict vy,
                                 real gx, real gy, real h) {
    int i;
    for (i = 0; i < n; ++i) {
        const real ux = vx[i] + gx * h, uy = vy[i] + gy * h;
        x[i] = x[i] + ux * h;
        y[i] = y[i] + uy * h;
        vx[i] = ux;
        vy[i] = uy;
    }
}
static KERNEL void hand_gravity3(int n, real *restrict x, real *restrict y, real *restrict z, real *restrict vx,
                                 real *restrict vy, real *restrict vz, real gx, real gy, real gz, real h) {
    int i;
    for (i = 0; i < n; ++i) {
        const real ux = vx[i] + gx * h, uy = vy[i] + gy * h, uz = vz[i] + gz * h;
        x[i] = x[i] + ux * h;
        y[i] = y[i] + uy * h;
        z[i] = z[i] + uz * h;
        vx[i] = ux;
        vy[i] = uy;
        vz[i] = uz;
    }
}

static KERNEL void hand_gravity_damping2(int n, real *restrict x, real *restrict y, real *restrict vx,
                                         real *restrict vy, real gx, real gy, real damping, real h) {
    int i;
    for (i = 0; i < n; ++i) {
        const real ux = vx[i] + gx * h, uy = vy[i] + gy * h;
        x[i] = x[i] + ux * h;
        y[i] = y[i] + uy * h;
        vx[i] = ux * damping;
        vy[i] = uy * damping;
    }
}
static KERNEL void hand_gravity_damping3(int n, real *restrict x, real *restrict y, real *restrict z,
                                         real *restrict vx, real *restrict vy, real *restrict vz, real gx, real gy,
                                         real gz, real damping, real h) {
    int i;
    for (i = 0; i < n; ++i) {
        const real ux = vx[i] + gx * h, uy = vy[i] + gy * h, uz = vz[i] + gz * h;
        x[i] = x[i] + ux * h;
        y[i] = y[i] + uy * h;
        z[i] = z[i] + uz * h;
        vx[i] = ux * damping;
        vy[i] = uy * damping;
        vz[i] = uz * damping;
    }
}

static KERNEL void hand_gravity_drag2(int n, real *restrict x, real *restrict y, real *restrict vx,
                                      real *restrict vy, real gx, real gy, real k, real h) {
    int i;
    for (i = 0; i < n; ++i) {
        const real ux = vx[i] + (gx - vx[i] * k) * h, uy = vy[i] + (gy - vy[i] * k) * h;
        x[i] = x[i] + ux * h;
        y[i] = y[i] + uy * h;
        vx[i] = ux;
        vy[i] = uy;
    }
}
static KERNEL void hand_gravity_drag3(int n, real *restrict x, real *restrict y, real *restrict z,
                                      real *restrict vx, real *restrict vy, real *restrict vz, real gx, real gy,
                                      real gz, real k, real h) {
    int i;
    for (i = 0; i < n; ++i) {
        const real ux = vx[i] + (gx - vx[i] * k) * h, uy = vy[i] + (gy - vy[i] * k) * h,
                   uz = vz[i] + (gz - vz[i] * k) * h;
        x[i] = x[i] + ux * h;
        y[i] = y[i] + uy * h;
        z[i] = z[i] + uz * h;
        vx[i] = ux;
        vy[i] = uy;
        vz[i] = uz;
    }
}

static KERNEL void hand_mass_forces2(int n, real *restrict x, real *restrict y, real *restrict vx, real *restrict vy,
                                     const real *restrict fx, const real *restrict fy,
                                     const real *restrict inverse_mass, real h) {
    int i;
    for (i = 0; i < n; ++i) {
        const real w = inverse_mass[i];
        const real ux = vx[i] + fx[i] * w * h, uy = vy[i] + fy[i] * w * h;
        x[i] = x[i] + ux * h;
        y[i] = y[i] + uy * h;
        vx[i] = ux;
        vy[i] = uy;
    }
}
static KERNEL void hand_mass_forces3(int n, real *restrict x, real *restrict y, real *restrict z, real *restrict vx,
                                     real *restrict vy, real *restrict vz, const real *restrict fx,
                                     const real *restrict fy, const real *restrict fz,
                                     const real *restrict inverse_mass, real h) {
    int i;
    for (i = 0; i < n; ++i) {
        const real w = inverse_mass[i];
        const real ux = vx[i] + fx[i] * w * h, uy = vy[i] + fy[i] * w * h, uz = vz[i] + fz[i] * w * h;
        x[i] = x[i] + ux * h;
        y[i] = y[i] + uy * h;
        z[i] = z[i] + uz * h;
        vx[i] = ux;
        vy[i] = uy;
        vz[i] = uz;
    }
}

/* Springs: clear the forces, sum every spring's Hooke + damping force into both ends (the formula of
   motus__spring_force, same operations), then the semi-implicit Euler step with a uniform inverse mass. */
static KERNEL void hand_springs2(int n, const motus_spring *restrict springs, int spring_count, real *restrict x,
                                 real *restrict y, real *restrict vx, real *restrict vy, real *restrict fx,
                                 real *restrict fy, real inverse_mass, real h) {
    int i;
    memset(fx, 0, sizeof(real) * (size_t)n);
    memset(fy, 0, sizeof(real) * (size_t)n);
    for (i = 0; i < spring_count; ++i) {
        const motus_spring *s = &springs[i];
        const int a = s->a, b = s->b;
        real dx, dy, rx, ry, d2, f_x, f_y;
        if (b < 0) {
            dx = x[a] - s->anchor.x, dy = y[a] - s->anchor.y;
            rx = vx[a], ry = vy[a];
        } else {
            dx = x[a] - x[b], dy = y[a] - y[b];
            rx = vx[a] - vx[b], ry = vy[a] - vy[b];
        }
        d2 = dx * dx + dy * dy;
        f_x = dx * -s->stiffness, f_y = dy * -s->stiffness;
        if (d2 > 0) {
            real along = -s->damping * (rx * dx + ry * dy) / d2;
            if (s->rest_length != 0) along += s->stiffness * s->rest_length / MOTUS_SQRT(d2);
            f_x = f_x + dx * along, f_y = f_y + dy * along;
        }
        fx[a] += f_x, fy[a] += f_y;
        if (b >= 0) fx[b] -= f_x, fy[b] -= f_y;
    }
    for (i = 0; i < n; ++i) {
        const real ux = vx[i] + fx[i] * inverse_mass * h, uy = vy[i] + fy[i] * inverse_mass * h;
        x[i] = x[i] + ux * h;
        y[i] = y[i] + uy * h;
        vx[i] = ux;
        vy[i] = uy;
    }
}

/* ---- motus ---------------------------------------------------------------------------------------- */
static KERNEL motus_result motus_step(const motus_scene *scene, const motus_batch *batch, int n, real dt) {
    return motus_batch_step(scene, batch, 0, n, dt);
}

/* The user's part of a spring step (clear the forces) and motus's two calls. */
static KERNEL motus_result motus_springs_step(const motus_scene *scene, const motus_batch *batch, int n,
                                              const motus_spring *springs, int spring_count, real dt) {
    motus_result result;
    memset(batch->force[0], 0, sizeof(real) * (size_t)n);
    memset(batch->force[1], 0, sizeof(real) * (size_t)n);
    result = motus_batch_add_spring_forces(batch, n, springs, spring_count);
    if (result != MOTUS_OK) return result;
    return motus_batch_step(scene, batch, 0, n, dt);
}

#ifdef _OPENMP
/* Thread t of `threads` gets [*first, *first + *count): the boundaries on multiples of 64 particles, so
   that no cache line (nor vector) is written by both threads. */
static void thread_range(int n, int t, int threads, int *first, int *count) {
    int chunk = (n / threads + 63) & ~63, end;
    *first = t * chunk < n ? t * chunk : n;
    end = *first + chunk < n && t < threads - 1 ? *first + chunk : n;
    *count = end - *first;
}
#endif

/* One OpenMP parallel region per step, as a game hands a frame's work to its threads: each thread steps
   its range through the range API. */
static KERNEL motus_result motus_threads_step(const motus_scene *scene, const motus_batch *batch, int n, real dt) {
    motus_result result = MOTUS_OK;
#ifdef _OPENMP
#pragma omp parallel num_threads(2)
    {
        int first, count;
        motus_result mine;
        thread_range(n, omp_get_thread_num(), omp_get_num_threads(), &first, &count);
        mine = motus_batch_step(scene, batch, first, count, dt);
        if (mine != MOTUS_OK) {
#pragma omp critical(throughput_result)
            result = mine;
        }
    }
#else
    (void)scene, (void)batch, (void)n, (void)dt;
    result = MOTUS_ERROR_UNSUPPORTED;
#endif
    return result;
}

/* ---- memory bandwidth ----------------------------------------------------------------------------
   Each kernel moves the bytes a step moves: a step reads and writes its state, S = 2*dims*N values (x and
   v), 2*S counting reads and writes as STREAM does. copy: S values into S others; triad: three arrays of
   2*S/3; rmw: the state arrays themselves, each value read and written back in place, the fastest a step
   can be (no extra write-allocate: the lines it writes are the lines it read). */
static KERNEL NO_MEMCPY void copy_kernel(real *restrict to, const real *restrict from, size_t count) {
    size_t i;
    for (i = 0; i < count; ++i) to[i] = from[i];
}
static KERNEL void triad_kernel(real *restrict a, const real *restrict b, const real *restrict c, real s,
                                size_t count) {
    size_t i;
    for (i = 0; i < count; ++i) a[i] = b[i] + s * c[i];
}
static KERNEL void rmw2(int first, int end, real *restrict x, real *restrict y, real *restrict vx, real *restrict vy,
                        real s) {
    int i;
    for (i = first; i < end; ++i) {
        x[i] = x[i] + s;
        y[i] = y[i] + s;
        vx[i] = vx[i] + s;
        vy[i] = vy[i] + s;
    }
}
static KERNEL void rmw3(int first, int end, real *restrict x, real *restrict y, real *restrict z, real *restrict vx,
                        real *restrict vy, real *restrict vz, real s) {
    int i;
    for (i = first; i < end; ++i) {
        x[i] = x[i] + s;
        y[i] = y[i] + s;
        z[i] = z[i] + s;
        vx[i] = vx[i] + s;
        vy[i] = vy[i] + s;
        vz[i] = vz[i] + s;
    }
}
static KERNEL void rmw_threads(int dims, int n, real *const *position, real *const *velocity, real s) {
#ifdef _OPENMP
#pragma omp parallel num_threads(2)
    {
        int first, count;
        thread_range(n, omp_get_thread_num(), omp_get_num_threads(), &first, &count);
        if (dims == 2) rmw2(first, first + count, position[0], position[1], velocity[0], velocity[1], s);
        else rmw3(first, first + count, position[0], position[1], position[2], velocity[0], velocity[1], velocity[2], s);
    }
#else
    (void)dims, (void)n, (void)position, (void)velocity, (void)s;
#endif
}

/* ---- the work: every array of one (N, dims), and what the current method needs ------------------------ */
typedef struct work {
    int dims, n;
    real *position[3], *velocity[3], *force[3], *inverse_mass;
    void *textbook;     /* n particle2 or particle3 */
    real *scratch;      /* 2*S values: copy source and destination; the three triad arrays */
    size_t state_count; /* S = 2*dims*n */
    motus_spring *springs; /* n springs: a chain hung from an anchor (2D) */
    motus_scene scene;  /* of the current scene and method */
    motus_batch batch;
    real dt, zero;      /* zero: a run-time 0 the memory kernels add, so the compiler cannot drop the work */
    void *blocks[16];
    int block_count;
} work;

static void *work_alloc(work *w, size_t bytes) {
    void *p = NULL;
    bytes = (bytes + 63) / 64 * 64;
    if (w->block_count >= 16 || posix_memalign(&p, 64, bytes ? bytes : 64) != 0) return NULL;
    w->blocks[w->block_count++] = p;
    return p;
}

void NAME(throughput_close)(void *opaque) {
    work *w = (work *)opaque;
    int i;
    if (!w) return;
    for (i = 0; i < w->block_count; ++i) free(w->blocks[i]);
    free(w);
}

void *NAME(throughput_open)(int dims, int n) {
    work *w;
    const size_t count = (size_t)n;
    int d, ok = 1;
    if ((dims != 2 && dims != 3) || n < 1) return NULL;
    w = (work *)calloc(1, sizeof *w);
    if (!w) return NULL;
    w->dims = dims;
    w->n = n;
    w->dt = (real)THROUGHPUT_DT;
    w->zero = 0;
    w->state_count = 2 * (size_t)dims * count;
    for (d = 0; d < dims; ++d) {
        ok &= (w->position[d] = (real *)work_alloc(w, sizeof(real) * count)) != NULL;
        ok &= (w->velocity[d] = (real *)work_alloc(w, sizeof(real) * count)) != NULL;
        ok &= (w->force[d] = (real *)work_alloc(w, sizeof(real) * count)) != NULL;
    }
    ok &= (w->inverse_mass = (real *)work_alloc(w, sizeof(real) * count)) != NULL;
    ok &= (w->textbook = work_alloc(w, (dims == 2 ? sizeof(particle2) : sizeof(particle3)) * count)) != NULL;
    ok &= (w->scratch = (real *)work_alloc(w, sizeof(real) * 2 * w->state_count)) != NULL;
    if (dims == 2) {
        ok &= (w->springs = (motus_spring *)work_alloc(w, sizeof(motus_spring) * count)) != NULL;
        if (ok) {
            int i;
            for (i = 0; i < n; ++i) {
                motus_spring *s = &w->springs[i];
                s->a = i;
                s->b = i - 1; /* spring 0 hangs particle 0 from the anchor */
                s->anchor = motus_v2((real)-THROUGHPUT_SPRING_REST_LENGTH, 0);
                s->rest_length = (real)THROUGHPUT_SPRING_REST_LENGTH;
                s->stiffness = (real)THROUGHPUT_SPRING_STIFFNESS;
                s->damping = (real)THROUGHPUT_SPRING_DAMPING;
            }
        }
    }
    if (!ok) {
        NAME(throughput_close)(w);
        return NULL;
    }
    return w;
}

int NAME(throughput_supported)(const void *opaque, int scene, int method) {
    const work *w = (const work *)opaque;
    switch (method) {
    case THROUGHPUT_MOTUS:
    case THROUGHPUT_HAND:
    case THROUGHPUT_GENERAL: return scene < THROUGHPUT_SCENE_COUNT && (scene != THROUGHPUT_SPRINGS || w->dims == 2);
    case THROUGHPUT_TEXTBOOK: return scene == THROUGHPUT_GRAVITY_DAMPING;
#ifdef _OPENMP
    case THROUGHPUT_MOTUS_THREADS: return scene == THROUGHPUT_GRAVITY_DAMPING;
    case THROUGHPUT_RMW_THREADS: return scene == THROUGHPUT_MEMORY;
#endif
    case THROUGHPUT_COPY:
    case THROUGHPUT_TRIAD:
    case THROUGHPUT_RMW: return scene == THROUGHPUT_MEMORY;
    default: return 0;
    }
}

static unsigned scene_has(int scene) {
    switch (scene) {
    case THROUGHPUT_GRAVITY: return MOTUS_HAS_GRAVITY;
    case THROUGHPUT_GRAVITY_DAMPING: return MOTUS_HAS_GRAVITY | MOTUS_HAS_DAMPING_PER_STEP;
    case THROUGHPUT_GRAVITY_LINEAR_DRAG: return MOTUS_HAS_GRAVITY | MOTUS_HAS_LINEAR_DRAG;
    case THROUGHPUT_MASS_FORCES: return MOTUS_HAS_PARTICLE_MASS | MOTUS_HAS_FORCES;
    case THROUGHPUT_SPRINGS: return MOTUS_HAS_FORCES;
    default: return 0;
    }
}

/* The motus scene and batch of (scene, method); nothing in the arrays changes. */
void NAME(throughput_configure)(void *opaque, int scene, int method) {
    work *w = (work *)opaque;
    int d;
    memset(&w->scene, 0, sizeof w->scene);
    w->scene.has = scene_has(scene);
    w->scene.method = MOTUS_SEMI_IMPLICIT_EULER;
    w->scene.gravity[0] = (real)THROUGHPUT_GX;
    w->scene.gravity[1] = (real)THROUGHPUT_GY;
    w->scene.gravity[2] = (real)THROUGHPUT_GZ;
    w->scene.linear_drag = (real)THROUGHPUT_LINEAR_DRAG;
    w->scene.damping = (real)THROUGHPUT_DAMPING;
    w->scene.inverse_mass = (real)THROUGHPUT_INVERSE_MASS;
    if (method == THROUGHPUT_GENERAL) {
        /* Every feature on, with values that change nothing: quadratic drag 0, an attractor of strength 0
           and walls no particle reaches. Quadratic drag and the attractor make motus pick its general kernel,
           which computes every term; the motion is the scene's. */
        w->scene.has |= MOTUS_HAS_QUADRATIC_DRAG | MOTUS_HAS_ATTRACTOR | MOTUS_HAS_BOUNDS;
        w->scene.quadratic_drag = 0;
        w->scene.attractor_strength = 0;
        for (d = 0; d < 3; ++d) {
            w->scene.bounds_min[d] = (real)-1e30;
            w->scene.bounds_max[d] = (real)1e30;
        }
        w->scene.restitution = 1;
    }
    memset(&w->batch, 0, sizeof w->batch);
    w->batch.dimensions = w->dims;
    for (d = 0; d < w->dims; ++d) {
        w->batch.position[d] = w->position[d];
        w->batch.velocity[d] = w->velocity[d];
        if (w->scene.has & MOTUS_HAS_FORCES) w->batch.force[d] = w->force[d];
    }
    if (w->scene.has & MOTUS_HAS_PARTICLE_MASS) w->batch.inverse_mass = w->inverse_mass;
}

void NAME(throughput_reset)(void *opaque, int scene, int method) {
    work *w = (work *)opaque;
    const int dims = w->dims, n = w->n;
    int i, d;
    NAME(throughput_configure)(w, scene, method);
    if (method == THROUGHPUT_COPY || method == THROUGHPUT_TRIAD) {
        for (i = 0; (size_t)i < 2 * w->state_count; ++i) w->scratch[i] = (real)(1 + (i & 1023));
        return;
    }
    if (method == THROUGHPUT_TEXTBOOK) {
        const real mass = (real)(1.0 / THROUGHPUT_INVERSE_MASS);
        for (i = 0; i < n; ++i) {
            if (dims == 2) {
                particle2 *p = (particle2 *)w->textbook + i;
                p->force = v2(0, 0);
                p->position = v2((real)throughput_start(i, 0), (real)throughput_start(i, 1));
                p->velocity = v2((real)throughput_start(i, 3), (real)throughput_start(i, 4));
                p->mass = mass;
            } else {
                particle3 *p = (particle3 *)w->textbook + i;
                p->force = v3(0, 0, 0);
                p->position = v3((real)throughput_start(i, 0), (real)throughput_start(i, 1), (real)throughput_start(i, 2));
                p->velocity = v3((real)throughput_start(i, 3), (real)throughput_start(i, 4), (real)throughput_start(i, 5));
                p->mass = mass;
            }
        }
        return;
    }
    for (i = 0; i < n; ++i) {
        if (scene == THROUGHPUT_SPRINGS) { /* the chain along x, each spring stretched or squeezed a little */
            w->position[0][i] = (real)(THROUGHPUT_SPRING_REST_LENGTH * (i + 0.2 * (throughput_start(i, 0) / 1000 - 0.5)));
            w->position[1][i] = (real)(0.2 * (throughput_start(i, 1) / 1000 - 0.5));
            w->velocity[0][i] = (real)(0.1 * throughput_start(i, 3));
            w->velocity[1][i] = (real)(0.1 * throughput_start(i, 4));
            continue;
        }
        for (d = 0; d < dims; ++d) {
            w->position[d][i] = (real)throughput_start(i, d);
            w->velocity[d][i] = (real)throughput_start(i, 3 + d);
        }
        if (scene == THROUGHPUT_MASS_FORCES) {
            for (d = 0; d < dims; ++d) w->force[d][i] = (real)throughput_start(i, 6 + d);
            w->inverse_mass[i] = (real)throughput_start(i, 9);
        }
    }
}

#define REPEAT(call)                                                                                             \
    do {                                                                                                       \
        for (s = 0; s < steps; ++s) call;                                                                      \
    } while (0)
#define REPEAT_MOTUS(call)                                                                                       \
    do {                                                                                                       \
        for (s = 0; s < steps; ++s) {                                                                          \
            motus_result r = call;                                                                             \
            if (r != MOTUS_OK) failed = r;                                                                     \
        }                                                                                                      \
    } while (0)

int NAME(throughput_run)(void *opaque, int scene, int method, int steps) {
    work *w = (work *)opaque;
    const int n = w->n;
    const real h = w->dt, g[3] = {(real)THROUGHPUT_GX, (real)THROUGHPUT_GY, (real)THROUGHPUT_GZ};
    const real damping = w->scene.damping, drag = w->scene.linear_drag, inverse_mass = w->scene.inverse_mass;
    real *const *x = w->position, *const *v = w->velocity, *const *f = w->force;
    const int three = w->dims == 3;
    int s, failed = 0;
    switch (method) {
    case THROUGHPUT_MOTUS:
    case THROUGHPUT_GENERAL:
        if (scene == THROUGHPUT_SPRINGS) REPEAT_MOTUS(motus_springs_step(&w->scene, &w->batch, n, w->springs, n, h));
        else REPEAT_MOTUS(motus_step(&w->scene, &w->batch, n, h));
        break;
    case THROUGHPUT_MOTUS_THREADS: REPEAT_MOTUS(motus_threads_step(&w->scene, &w->batch, n, h)); break;
    case THROUGHPUT_TEXTBOOK:
        if (three) REPEAT(textbook_step3((particle3 *)w->textbook, n, v3(g[0], g[1], g[2]), damping, h));
        else REPEAT(textbook_step2((particle2 *)w->textbook, n, v2(g[0], g[1]), damping, h));
        break;
    case THROUGHPUT_HAND:
        switch (scene) {
        case THROUGHPUT_DRIFT:
            if (three) REPEAT(hand_drift3(n, x[0], x[1], x[2], v[0], v[1], v[2], h));
            else REPEAT(hand_drift2(n, x[0], x[1], v[0], v[1], h));
            break;
        case THROUGHPUT_GRAVITY:
            if (three) REPEAT(hand_gravity3(n, x[0], x[1], x[2], v[0], v[1], v[2], g[0], g[1], g[2], h));
            else REPEAT(hand_gravity2(n, x[0], x[1], v[0], v[1], g[0], g[1], h));
            break;
        case THROUGHPUT_GRAVITY_DAMPING:
            if (three) REPEAT(hand_gravity_damping3(n, x[0], x[1], x[2], v[0], v[1], v[2], g[0], g[1], g[2], damping, h));
            else REPEAT(hand_gravity_damping2(n, x[0], x[1], v[0], v[1], g[0], g[1], damping, h));
            break;
        case THROUGHPUT_GRAVITY_LINEAR_DRAG:
            if (three) REPEAT(hand_gravity_drag3(n, x[0], x[1], x[2], v[0], v[1], v[2], g[0], g[1], g[2], drag, h));
            else REPEAT(hand_gravity_drag2(n, x[0], x[1], v[0], v[1], g[0], g[1], drag, h));
            break;
        case THROUGHPUT_MASS_FORCES:
            if (three)
                REPEAT(hand_mass_forces3(n, x[0], x[1], x[2], v[0], v[1], v[2], f[0], f[1], f[2], w->inverse_mass, h));
            else REPEAT(hand_mass_forces2(n, x[0], x[1], v[0], v[1], f[0], f[1], w->inverse_mass, h));
            break;
        case THROUGHPUT_SPRINGS:
            REPEAT(hand_springs2(n, w->springs, n, x[0], x[1], v[0], v[1], f[0], f[1], inverse_mass, h));
            break;
        default: return MOTUS_ERROR_UNSUPPORTED;
        }
        break;
    case THROUGHPUT_COPY: REPEAT(copy_kernel(w->scratch + w->state_count, w->scratch, w->state_count)); break;
    case THROUGHPUT_TRIAD: {
        const size_t third = (2 * w->state_count) / 3;
        REPEAT(triad_kernel(w->scratch, w->scratch + third, w->scratch + 2 * third, w->zero, third));
        break;
    }
    case THROUGHPUT_RMW:
        if (three) REPEAT(rmw3(0, n, x[0], x[1], x[2], v[0], v[1], v[2], w->zero));
        else REPEAT(rmw2(0, n, x[0], x[1], v[0], v[1], w->zero));
        break;
    case THROUGHPUT_RMW_THREADS: REPEAT(rmw_threads(w->dims, n, x, v, w->zero)); break;
    default: return MOTUS_ERROR_UNSUPPORTED;
    }
    return failed;
}

void NAME(throughput_read)(const void *opaque, int scene, int method, int i, double *out) {
    const work *w = (const work *)opaque;
    int d;
    (void)scene;
    if (method == THROUGHPUT_TEXTBOOK) {
        if (w->dims == 2) {
            const particle2 *p = (const particle2 *)w->textbook + i;
            out[0] = p->position.x, out[1] = p->position.y, out[2] = p->velocity.x, out[3] = p->velocity.y;
        } else {
            const particle3 *p = (const particle3 *)w->textbook + i;
            out[0] = p->position.x, out[1] = p->position.y, out[2] = p->position.z;
            out[3] = p->velocity.x, out[4] = p->velocity.y, out[5] = p->velocity.z;
        }
        return;
    }
    for (d = 0; d < w->dims; ++d) {
        out[d] = w->position[d][i];
        out[w->dims + d] = w->velocity[d][i];
    }
}

static long count_subnormals(const real *values, size_t count) {
    long found = 0;
    size_t i;
    for (i = 0; i < count; ++i) found += fpclassify(values[i]) == FP_SUBNORMAL;
    return found;
}

long NAME(throughput_subnormals)(const void *opaque, int scene, int method) {
    const work *w = (const work *)opaque;
    long found = 0;
    int d;
    (void)scene;
    if (method == THROUGHPUT_COPY || method == THROUGHPUT_TRIAD) return count_subnormals(w->scratch, 2 * w->state_count);
    if (method == THROUGHPUT_TEXTBOOK) {
        const size_t values = (w->dims == 2 ? sizeof(particle2) : sizeof(particle3)) / sizeof(real);
        return count_subnormals((const real *)w->textbook, values * (size_t)w->n);
    }
    for (d = 0; d < w->dims; ++d) {
        found += count_subnormals(w->position[d], (size_t)w->n);
        found += count_subnormals(w->velocity[d], (size_t)w->n);
        if (scene == THROUGHPUT_SPRINGS || scene == THROUGHPUT_MASS_FORCES) found += count_subnormals(w->force[d], (size_t)w->n);
    }
    return found;
}

int NAME(throughput_simd_bytes)(void) {
#if MOTUS__VECTOR
    return MOTUS_SIMD_BYTES;
#else
    return 0;
#endif
}

#ifndef MOTUS_DOUBLE
int throughput_openmp(void) {
#ifdef _OPENMP
    return _OPENMP;
#else
    return 0;
#endif
}
#endif
