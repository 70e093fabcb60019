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

/* The engine, static in each of the two precisions of one program. */
#define MOTUS_IMPLEMENTATION
#define MOTUS_STATIC
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

/* ---- the textbook per-particle path ---------------------------------------------------------------
   What a game written from the textbook does every frame to each of its motus_particle: clear the forces,
   add the weight, step (semi-implicit Euler), damp, bounce off the walls; against the same math written out
   by hand over the same structs. The results are summed so that no call can be dropped. Both loops take
   the walls as the same two numbers (lo, hi on every axis): as motus_vec2 arguments of the loop's function,
   GCC keeps each in an integer register across the loop (the calls' rare paths would clobber a vector one)
   and unpacks it every particle, which costs the calls about 0.7 ns a particle (2D float, gcc 12 -O2) and
   measures the caller's argument passing, not motus. */
static KERNEL int textbook_step2(motus_particle *particles, int n, motus_vec2 weight, motus_real damping, real lo,
                                 real hi, motus_real restitution, real dt) {
    int i, bad = 0;
    for (i = 0; i < n; ++i) {
        motus_particle *p = &particles[i];
        bad |= motus_particle_clear_forces(p);
        bad |= motus_particle_add_force(p, weight);
        bad |= motus_particle_step(p, dt);
        bad |= motus_particle_damp_per_step(p, damping);
        bad |= motus_particle_bounce(p, motus_v2(lo, lo), motus_v2(hi, hi), restitution);
    }
    return bad;
}
static KERNEL int textbook_step3(motus_particle3 *particles, int n, motus_vec3 weight, motus_real damping, real lo,
                                 real hi, motus_real restitution, real dt) {
    int i, bad = 0;
    for (i = 0; i < n; ++i) {
        motus_particle3 *p = &particles[i];
        bad |= motus_particle3_clear_forces(p);
        bad |= motus_particle3_add_force(p, weight);
        bad |= motus_particle3_step(p, dt);
        bad |= motus_particle3_damp_per_step(p, damping);
        bad |= motus_particle3_bounce(p, motus_v3(lo, lo, lo), motus_v3(hi, hi, hi), restitution);
    }
    return bad;
}
/* One wall pair, as motus_particle_bounce: mirror back inside, reverse and scale that velocity component. */
static inline void hand_wall(real *x, real *v, real lo, real hi, real bounce) {
    if (*x < lo) *x = lo + (lo - *x), *v = *v * bounce;
    if (*x > hi) *x = hi - (*x - hi), *v = *v * bounce;
    if (*x < lo) *x = lo;
    if (*x > hi) *x = hi;
}
static KERNEL void textbook_hand2(motus_particle *particles, int n, motus_vec2 weight, real kept, real lo, real hi,
                                  real bounce, real dt) {
    int i;
    for (i = 0; i < n; ++i) {
        motus_particle *p = &particles[i];
        p->force.x = 0 + weight.x, p->force.y = 0 + weight.y;
        p->velocity.x = p->velocity.x + p->force.x * p->inverse_mass * dt;
        p->velocity.y = p->velocity.y + p->force.y * p->inverse_mass * dt;
        p->position.x = p->position.x + p->velocity.x * dt;
        p->position.y = p->position.y + p->velocity.y * dt;
        p->velocity.x = p->velocity.x * kept, p->velocity.y = p->velocity.y * kept;
        hand_wall(&p->position.x, &p->velocity.x, lo, hi, bounce);
        hand_wall(&p->position.y, &p->velocity.y, lo, hi, bounce);
    }
}
static KERNEL void textbook_hand3(motus_particle3 *particles, int n, motus_vec3 weight, real kept, real lo, real hi,
                                  real bounce, real dt) {
    int i;
    for (i = 0; i < n; ++i) {
        motus_particle3 *p = &particles[i];
        p->force.x = 0 + weight.x, p->force.y = 0 + weight.y, p->force.z = 0 + weight.z;
        p->velocity.x = p->velocity.x + p->force.x * p->inverse_mass * dt;
        p->velocity.y = p->velocity.y + p->force.y * p->inverse_mass * dt;
        p->velocity.z = p->velocity.z + p->force.z * p->inverse_mass * dt;
        p->position.x = p->position.x + p->velocity.x * dt;
        p->position.y = p->position.y + p->velocity.y * dt;
        p->position.z = p->position.z + p->velocity.z * dt;
        p->velocity.x = p->velocity.x * kept, p->velocity.y = p->velocity.y * kept, p->velocity.z = p->velocity.z * kept;
        hand_wall(&p->position.x, &p->velocity.x, lo, hi, bounce);
        hand_wall(&p->position.y, &p->velocity.y, lo, hi, bounce);
        hand_wall(&p->position.z, &p->velocity.z, lo, hi, bounce);
    }
}

/* ---- the hand-written loops: exactly the scene, the operations in motus's order ------------------------
   Per particle (semi-implicit Euler): a = F*inverse_mass + g - k*v; v += a*h; x += v*h; v *= 1 - damping
   (kept). A term the scene lacks is simply not written. */
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
                                         real *restrict vy, real gx, real gy, real kept, real h) {
    int i;
    for (i = 0; i < n; ++i) {
        const real ux = vx[i] + gx * h, uy = vy[i] + gy * h;
        x[i] = x[i] + ux * h;
        y[i] = y[i] + uy * h;
        vx[i] = ux * kept;
        vy[i] = uy * kept;
    }
}
static KERNEL void hand_gravity_damping3(int n, real *restrict x, real *restrict y, real *restrict z,
                                         real *restrict vx, real *restrict vy, real *restrict vz, real gx, real gy,
                                         real gz, real kept, real h) {
    int i;
    for (i = 0; i < n; ++i) {
        const real ux = vx[i] + gx * h, uy = vy[i] + gy * h, uz = vz[i] + gz * h;
        x[i] = x[i] + ux * h;
        y[i] = y[i] + uy * h;
        z[i] = z[i] + uz * h;
        vx[i] = ux * kept;
        vy[i] = uy * kept;
        vz[i] = uz * kept;
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

/* a = -mu*r/|r|^3, r = x - c. */
static KERNEL void hand_attractor2(int n, real *restrict x, real *restrict y, real *restrict vx, real *restrict vy,
                                   real c, real mu, real h) {
    int i;
    for (i = 0; i < n; ++i) {
        const real dx = x[i] - c, dy = y[i] - c, r2 = dx * dx + dy * dy, s = mu / (r2 * MOTUS_SQRT(r2));
        const real ux = vx[i] - dx * s * h, uy = vy[i] - dy * s * h;
        x[i] = x[i] + ux * h;
        y[i] = y[i] + uy * h;
        vx[i] = ux;
        vy[i] = uy;
    }
}
static KERNEL void hand_attractor3(int n, real *restrict x, real *restrict y, real *restrict z, real *restrict vx,
                                   real *restrict vy, real *restrict vz, real c, real mu, real h) {
    int i;
    for (i = 0; i < n; ++i) {
        const real dx = x[i] - c, dy = y[i] - c, dz = z[i] - c, r2 = dx * dx + dy * dy + dz * dz;
        const real s = mu / (r2 * MOTUS_SQRT(r2));
        const real ux = vx[i] - dx * s * h, uy = vy[i] - dy * s * h, uz = vz[i] - dz * s * h;
        x[i] = x[i] + ux * h;
        y[i] = y[i] + uy * h;
        z[i] = z[i] + uz * h;
        vx[i] = ux;
        vy[i] = uy;
        vz[i] = uz;
    }
}

/* Springs: clear the forces, sum every spring's Hooke + damping force into both ends (the formula of
   motus.h's spring, written the plain way), then the semi-implicit Euler step with a uniform inverse mass. */
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
static KERNEL motus_result step_motus(const motus_scene *scene, const motus_state *state, real dt, void *scratch,
                                      size_t scratch_bytes) {
    return motus_step(scene, state, dt, scratch, scratch_bytes);
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
static KERNEL motus_result motus_threads_step(const motus_scene *scene, const motus_state *state, int n, real dt) {
    motus_result result = MOTUS_OK;
#ifdef _OPENMP
#pragma omp parallel num_threads(2)
    {
        int first, count;
        motus_result mine;
        thread_range(n, omp_get_thread_num(), omp_get_num_threads(), &first, &count);
        mine = motus_step_range(scene, state, first, count, dt);
        if (mine != MOTUS_OK) {
#pragma omp critical(throughput_result)
            result = mine;
        }
    }
#else
    (void)scene, (void)state, (void)n, (void)dt;
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
    void *textbook;     /* n motus_particle or motus_particle3 */
    real *scratch;      /* 2*S values: copy source and destination; the three triad arrays */
    size_t state_count; /* S = 2*dims*n */
    motus_spring *springs; /* n springs: a chain hung from an anchor (2D) */
    motus_scene scene;  /* of the current scene and method */
    motus_state state;
    void *motus_scratch; /* motus_scratch_size() bytes for the springs (malloc, grown when a method needs more) */
    size_t motus_scratch_bytes;
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
    free(w->motus_scratch);
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
    ok &= (w->textbook = work_alloc(w, (dims == 2 ? sizeof(motus_particle) : sizeof(motus_particle3)) * count)) != NULL;
    ok &= (w->scratch = (real *)work_alloc(w, sizeof(real) * 2 * w->state_count)) != NULL;
    if (dims == 2) {
        ok &= (w->springs = (motus_spring *)work_alloc(w, sizeof(motus_spring) * count)) != NULL;
        if (ok) {
            int i;
            for (i = 0; i < n; ++i) {
                motus_spring *s = &w->springs[i];
                s->a = i;
                s->b = i - 1; /* spring 0 hangs particle 0 from the anchor */
                s->anchor = motus_v3((real)-THROUGHPUT_SPRING_REST_LENGTH, 0, 0);
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
    const int integrator = throughput_motus_method(method);
    if (method == THROUGHPUT_MOTUS_THREADS) {
#ifdef _OPENMP
        return scene == THROUGHPUT_GRAVITY_DAMPING;
#else
        return 0;
#endif
    }
    if (integrator >= 0 || method == THROUGHPUT_HAND) {
        if (scene >= THROUGHPUT_SCENE_COUNT || (scene == THROUGHPUT_SPRINGS && w->dims != 2)) return 0;
        /* The exact stepper takes no spring and no attractor (MOTUS_ERROR_UNSUPPORTED). */
        return integrator != MOTUS_EXACT_LINEAR_DRAG || (scene != THROUGHPUT_SPRINGS && scene != THROUGHPUT_ATTRACTOR);
    }
    switch (method) {
    case THROUGHPUT_TEXTBOOK:
    case THROUGHPUT_TEXTBOOK_HAND:
    case THROUGHPUT_TEXTBOOK_ENGINE: return scene == THROUGHPUT_GRAVITY_DAMPING;
#ifdef _OPENMP
    case THROUGHPUT_RMW_THREADS: return scene == THROUGHPUT_MEMORY;
#endif
    case THROUGHPUT_COPY:
    case THROUGHPUT_TRIAD:
    case THROUGHPUT_RMW: return scene == THROUGHPUT_MEMORY;
    default: return 0;
    }
}

/* The motus scene and state of (scene, method); nothing in the arrays changes. */
void NAME(throughput_configure)(void *opaque, int scene, int method) {
    work *w = (work *)opaque;
    const int integrator = throughput_motus_method(method);
    int d;
    memset(&w->scene, 0, sizeof w->scene);
    w->scene.method = (motus_method)(integrator > 0 ? integrator : 0);
    w->scene.mass = (real)(1.0 / THROUGHPUT_INVERSE_MASS);
    if (scene != THROUGHPUT_DRIFT && scene != THROUGHPUT_MASS_FORCES && scene != THROUGHPUT_SPRINGS &&
        scene != THROUGHPUT_ATTRACTOR)
        w->scene.gravity = motus_v3((real)THROUGHPUT_GX, (real)THROUGHPUT_GY, (real)THROUGHPUT_GZ);
    if (scene == THROUGHPUT_GRAVITY_DAMPING) w->scene.damping_per_step = (real)THROUGHPUT_DAMPING;
    if (scene == THROUGHPUT_GRAVITY_LINEAR_DRAG) w->scene.linear_drag = (real)THROUGHPUT_LINEAR_DRAG;
    if (scene == THROUGHPUT_ATTRACTOR) {
        const real c = (real)THROUGHPUT_ATTRACTOR_AT;
        w->scene.attractor = motus_v3(c, c, c);
        w->scene.attractor_strength = (real)THROUGHPUT_ATTRACTOR_STRENGTH;
    }
    if (scene == THROUGHPUT_SPRINGS && w->springs) {
        w->scene.springs = w->springs;
        w->scene.spring_count = w->n;
    }
    if (method == THROUGHPUT_GENERAL) { /* walls no particle reaches: the wall checks run, nothing bounces */
        w->scene.bounds_min = motus_v3((real)-1e30, (real)-1e30, (real)-1e30);
        w->scene.bounds_max = motus_v3((real)1e30, (real)1e30, (real)1e30);
        w->scene.restitution = 1;
    }
    memset(&w->state, 0, sizeof w->state);
    w->state.dimensions = w->dims;
    w->state.count = w->n;
    for (d = 0; d < w->dims; ++d) {
        w->state.position[d] = w->position[d];
        w->state.velocity[d] = w->velocity[d];
        if (scene == THROUGHPUT_MASS_FORCES) w->state.force[d] = w->force[d];
    }
    if (scene == THROUGHPUT_MASS_FORCES) w->state.inverse_mass = w->inverse_mass;
    if (method == THROUGHPUT_TEXTBOOK_ENGINE) { /* the textbook's walls, over its structs */
        const real lo = 0, hi = (real)THROUGHPUT_BOUNDS;
        w->scene.bounds_min = motus_v3(lo, lo, w->dims == 3 ? lo : 0);
        w->scene.bounds_max = motus_v3(hi, hi, w->dims == 3 ? hi : 0);
        w->scene.restitution = (real)THROUGHPUT_RESTITUTION;
        w->state = w->dims == 2 ? motus_state_of_particles((motus_particle *)w->textbook, w->n)
                                : motus_state_of_particles3((motus_particle3 *)w->textbook, w->n);
    }
    if (integrator >= 0) {
        const size_t bytes = motus_scratch_size(&w->scene, &w->state);
        if (bytes != (size_t)-1 && bytes > w->motus_scratch_bytes) {
            void *grown = NULL;
            if (posix_memalign(&grown, 64, bytes) == 0) {
                free(w->motus_scratch);
                w->motus_scratch = grown;
                w->motus_scratch_bytes = bytes;
            }
        }
    }
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
    if (throughput_on_structs(method)) {
        const real mass = (real)(1.0 / THROUGHPUT_INVERSE_MASS);
        for (i = 0; i < n; ++i) {
            if (dims == 2) {
                motus_particle *p = (motus_particle *)w->textbook + i;
                memset(p, 0, sizeof *p);
                motus_particle_init(p, motus_v2((real)throughput_start(i, 0), (real)throughput_start(i, 1)), mass);
                p->velocity = motus_v2((real)throughput_start(i, 3), (real)throughput_start(i, 4));
            } else {
                motus_particle3 *p = (motus_particle3 *)w->textbook + i;
                memset(p, 0, sizeof *p);
                motus_particle3_init(p, motus_v3((real)throughput_start(i, 0), (real)throughput_start(i, 1),
                                                 (real)throughput_start(i, 2)), mass);
                p->velocity = motus_v3((real)throughput_start(i, 3), (real)throughput_start(i, 4), (real)throughput_start(i, 5));
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
    const real damping = (real)THROUGHPUT_DAMPING, kept = 1 - damping, drag = (real)THROUGHPUT_LINEAR_DRAG;
    const real inverse_mass = (real)THROUGHPUT_INVERSE_MASS, mass = 1 / inverse_mass;
    const real c = (real)THROUGHPUT_ATTRACTOR_AT, mu = (real)THROUGHPUT_ATTRACTOR_STRENGTH;
    const real lo = 0, hi = (real)THROUGHPUT_BOUNDS, restitution = (real)THROUGHPUT_RESTITUTION;
    real *const *x = w->position, *const *v = w->velocity, *const *f = w->force;
    const int three = w->dims == 3;
    int s, failed = 0;
    if ((throughput_motus_method(method) >= 0 && method != THROUGHPUT_MOTUS_THREADS) || method == THROUGHPUT_TEXTBOOK_ENGINE) {
        REPEAT_MOTUS(step_motus(&w->scene, &w->state, h, w->motus_scratch, w->motus_scratch_bytes));
        return failed;
    }
    switch (method) {
    case THROUGHPUT_MOTUS_THREADS: REPEAT_MOTUS(motus_threads_step(&w->scene, &w->state, n, h)); break;
    case THROUGHPUT_TEXTBOOK:
        if (three)
            REPEAT_MOTUS(textbook_step3((motus_particle3 *)w->textbook, n, motus_v3(g[0] * mass, g[1] * mass, g[2] * mass),
                                        damping, lo, hi, restitution, h));
        else
            REPEAT_MOTUS(textbook_step2((motus_particle *)w->textbook, n, motus_v2(g[0] * mass, g[1] * mass), damping,
                                        lo, hi, restitution, h));
        break;
    case THROUGHPUT_TEXTBOOK_HAND:
        if (three)
            REPEAT(textbook_hand3((motus_particle3 *)w->textbook, n, motus_v3(g[0] * mass, g[1] * mass, g[2] * mass),
                                  kept, lo, hi, -restitution, h));
        else
            REPEAT(textbook_hand2((motus_particle *)w->textbook, n, motus_v2(g[0] * mass, g[1] * mass), kept, lo, hi,
                                  -restitution, h));
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
            if (three) REPEAT(hand_gravity_damping3(n, x[0], x[1], x[2], v[0], v[1], v[2], g[0], g[1], g[2], kept, h));
            else REPEAT(hand_gravity_damping2(n, x[0], x[1], v[0], v[1], g[0], g[1], kept, h));
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
        case THROUGHPUT_ATTRACTOR:
            if (three) REPEAT(hand_attractor3(n, x[0], x[1], x[2], v[0], v[1], v[2], c, mu, h));
            else REPEAT(hand_attractor2(n, x[0], x[1], v[0], v[1], c, mu, h));
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
    if (throughput_on_structs(method)) {
        if (w->dims == 2) {
            const motus_particle *p = (const motus_particle *)w->textbook + i;
            out[0] = p->position.x, out[1] = p->position.y, out[2] = p->velocity.x, out[3] = p->velocity.y;
        } else {
            const motus_particle3 *p = (const motus_particle3 *)w->textbook + i;
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
    if (throughput_on_structs(method)) {
        const size_t values = (w->dims == 2 ? sizeof(motus_particle) : sizeof(motus_particle3)) / sizeof(real);
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
