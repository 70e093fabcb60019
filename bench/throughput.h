/* throughput.h - what the parts of bench/throughput say to each other.
   throughput_kernels.c  everything written in C: the motus calls, the hand-written loop of each scene, the
                         textbook loop, the memory-bandwidth kernels and the OpenMP split. Compiled twice in
                         each build: float (functions ending _float) and MOTUS_DOUBLE (ending _double);
   throughput_odeint.cpp Boost.Odeint's symplectic_euler, velocity_verlet and runge_kutta4 on the gravity scene;
   throughput.cpp        the sizes, the interleaved timing rounds, the CSV, and the report (tables, targets,
                         plot data) over the results of both builds.
   Only plain C types cross between them. A "work" is one state of N particles in 2D or 3D (one precision)
   that every method of one part steps in turn: reset it to a scene's start, run it `steps` steps. */
#ifndef THROUGHPUT_H
#define THROUGHPUT_H

#include <stddef.h>
#include <time.h>

#ifdef __cplusplus
extern "C" {
#endif

/* What the particles feel. Each is a motus_scene (the fields set) and a hand-written loop (semi-implicit
   Euler, the same math). */
enum {
    THROUGHPUT_DRIFT,              /* nothing: x += v*h                                       (zero scene) */
    THROUGHPUT_GRAVITY,            /* v += g*h; x += v*h                                      gravity */
    THROUGHPUT_GRAVITY_DAMPING,    /* then v *= 1 - 0.01 (the reference program's friction)   gravity, damping_per_step */
    THROUGHPUT_GRAVITY_LINEAR_DRAG,/* v += (g - k*v)*h                                        gravity, linear_drag */
    THROUGHPUT_MASS_FORCES,        /* v += F[i]*invmass[i]*h, user forces held constant       state.force, inverse_mass */
    THROUGHPUT_SPRINGS,            /* a chain of N springs: motus's coupled path (scratch)    springs (2D only) */
    THROUGHPUT_ATTRACTOR,          /* v -= mu*r/|r|^3*h, r from the attractor (a sun)         attractor */
    THROUGHPUT_SCENE_COUNT,
    THROUGHPUT_MEMORY = THROUGHPUT_SCENE_COUNT /* the bandwidth kernels: no scene */
};

/* How they are stepped. */
enum {
    THROUGHPUT_MOTUS,    /* motus_step over the structure-of-arrays state, semi-implicit Euler (the fast path:
                            every stage in registers; springs: the coupled path) */
    THROUGHPUT_HAND,     /* the plain loop a programmer writes for exactly that scene, restrict pointers */
    THROUGHPUT_GENERAL,  /* motus_step with walls no particle reaches (bounds at +-1e30): what the wall checks
                            cost, with the same result */
    THROUGHPUT_TEXTBOOK, /* gravity + damping + walls, the textbook per-particle path: an array of motus_particle
                            (motus_particle3 in 3D) and per particle motus_particle_clear_forces, _add_force
                            (the weight), _step, _damp_per_step, _bounce */
    THROUGHPUT_MOTUS_THREADS, /* motus, one OpenMP parallel region per step, [0, N) split in 2 motus_step_range */
    THROUGHPUT_COPY,     /* memory: dst[i] = src[i] over the bytes a step reads and writes */
    THROUGHPUT_TRIAD,    /* memory: a[i] = b[i] + s*c[i], same bytes */
    THROUGHPUT_RMW,      /* memory: the state arrays read and written in place: the bound of a step */
    THROUGHPUT_RMW_THREADS, /* the same on 2 threads */
    THROUGHPUT_ODEINT_SYMPLECTIC_EULER, /* gravity scene (throughput_odeint.cpp) */
    THROUGHPUT_ODEINT_VELOCITY_VERLET,
    THROUGHPUT_ODEINT_RUNGE_KUTTA4,
    THROUGHPUT_TEXTBOOK_HAND, /* the same math as THROUGHPUT_TEXTBOOK over the same structs, written out by hand */
    /* motus_step with the other methods (THROUGHPUT_MOTUS is semi-implicit Euler): MOTUS_EXPLICIT_EULER + k */
    THROUGHPUT_MOTUS_EXPLICIT_EULER,
    THROUGHPUT_MOTUS_POSITION_VERLET,
    THROUGHPUT_MOTUS_VELOCITY_VERLET,
    THROUGHPUT_MOTUS_LEAPFROG,
    THROUGHPUT_MOTUS_MIDPOINT,
    THROUGHPUT_MOTUS_RK4,
    THROUGHPUT_MOTUS_FOREST_RUTH,
    THROUGHPUT_MOTUS_MCLACHLAN4,
    THROUGHPUT_MOTUS_EXACT_LINEAR_DRAG,
    THROUGHPUT_TEXTBOOK_ENGINE, /* the textbook's scene (gravity, damping, walls) through motus_step over the same
                                   array of motus_particle (motus_state_of_particles: the engine reads the structs
                                   through a stride) */
    THROUGHPUT_METHOD_COUNT
};
/* The methods that step an array of motus_particle (motus_particle3) rather than the x[], v[] arrays. */
static inline int throughput_on_structs(int method) {
    return method == THROUGHPUT_TEXTBOOK || method == THROUGHPUT_TEXTBOOK_HAND || method == THROUGHPUT_TEXTBOOK_ENGINE;
}
/* The motus_method a bench method steps with, or -1 for one that is not motus_step. */
static inline int throughput_motus_method(int method) {
    if (method == THROUGHPUT_MOTUS || method == THROUGHPUT_GENERAL || method == THROUGHPUT_MOTUS_THREADS) return 0;
    if (method >= THROUGHPUT_MOTUS_EXPLICIT_EULER && method <= THROUGHPUT_MOTUS_EXACT_LINEAR_DRAG)
        return 1 + (method - THROUGHPUT_MOTUS_EXPLICIT_EULER);
    return -1;
}

/* The scene's constants (SI units; the reference program's damping and mass). */
#define THROUGHPUT_DT (1.0 / 60.0)
#define THROUGHPUT_GX 0.7 /* gravity has a component on every axis, so every velocity component tends to a */
#define THROUGHPUT_GY -9.81 /* terminal speed under damping or drag instead of decaying into subnormals */
#define THROUGHPUT_GZ 0.4
#define THROUGHPUT_DAMPING 0.01 /* the fraction removed per step (v *= 0.99) */
#define THROUGHPUT_LINEAR_DRAG 0.5
#define THROUGHPUT_INVERSE_MASS 0.5 /* mass 2, as the reference program's particle */
#define THROUGHPUT_SPRING_STIFFNESS 50.0
#define THROUGHPUT_SPRING_DAMPING 0.05
#define THROUGHPUT_SPRING_REST_LENGTH 1.0
#define THROUGHPUT_ATTRACTOR_AT 500.0       /* the attractor sits at (500, 500, 500), inside the start box */
#define THROUGHPUT_ATTRACTOR_STRENGTH 1.0e5 /* mu, m^3/s^2: about 1 m/s^2 at 300 m */
#define THROUGHPUT_BOUNDS 1000.0            /* the textbook's walls: [0, 1000) on every axis */
#define THROUGHPUT_RESTITUTION 0.5
#define THROUGHPUT_TEXTBOOK_COUNT 5000      /* the textbook per-particle path is compared at this N */

/* The start of particle i, deterministic: component c of 0..2 position, 3..5 velocity, 6..8 force,
   9 inverse mass; in [lo, hi). */
static inline double throughput_start(long i, int c) {
    unsigned long long h = (unsigned long long)i * 0x9E3779B97F4A7C15ull + (unsigned long long)(c + 1) * 0xC2B2AE3D27D4EB4Full;
    double u;
    h ^= h >> 29;
    h *= 0xBF58476D1CE4E5B9ull;
    h ^= h >> 32;
    u = (double)(h >> 11) * (1.0 / 9007199254740992.0);
    if (c < 3) return 1000.0 * u;      /* positions in [0, 1000) m */
    if (c < 6) return 10.0 * u - 5.0;  /* velocities in [-5, 5) m/s */
    if (c < 9) return 40.0 * u - 20.0; /* user forces in [-20, 20) N */
    return 0.25 + 1.75 * u;            /* inverse masses in [0.25, 2) 1/kg */
}

/* ---- the C part (throughput_kernels.c), once per precision -----------------------------------------
   open: allocates every array a method may need for n particles in `dims` dimensions (64-byte aligned),
   NULL if memory runs out. supported: 0 if the method does not exist for that scene (textbook is gravity +
   damping only, springs are 2D only, threads need OpenMP). configure: makes (scene, method) the current one
   without touching the arrays (motus, hand, general, threads and rmw share one set of x[], v[] arrays, so
   they can take turns on one scene's state). reset: configure, then write the scene's start into the
   arrays the method uses (untimed). run: `steps` steps, each one call of a non-inlined function; returns 0, or the
   first motus_result that was not MOTUS_OK. read: position and velocity of particle i (2*dims values).
   subnormals: how many of the values the method works on are subnormal (they make every step 10-100x
   slower; the starts and scenes are chosen so that it does not happen, and the report says if it did). */
void *throughput_open_float(int dims, int n);
void throughput_close_float(void *work);
int throughput_supported_float(const void *work, int scene, int method);
void throughput_configure_float(void *work, int scene, int method);
void throughput_reset_float(void *work, int scene, int method);
int throughput_run_float(void *work, int scene, int method, int steps);
void throughput_read_float(const void *work, int scene, int method, int i, double *out);
long throughput_subnormals_float(const void *work, int scene, int method);

void *throughput_open_double(int dims, int n);
void throughput_close_double(void *work);
int throughput_supported_double(const void *work, int scene, int method);
void throughput_configure_double(void *work, int scene, int method);
void throughput_reset_double(void *work, int scene, int method);
int throughput_run_double(void *work, int scene, int method, int steps);
void throughput_read_double(const void *work, int scene, int method, int i, double *out);
long throughput_subnormals_double(const void *work, int scene, int method);

/* Facts about the build the C part was compiled in: MOTUS_SIMD_BYTES, the OpenMP version (0 without). */
int throughput_simd_bytes_float(void);
int throughput_simd_bytes_double(void);
int throughput_openmp(void);

/* ---- the odeint part (throughput_odeint.cpp): the same calls for THROUGHPUT_ODEINT_* on THROUGHPUT_GRAVITY,
   single_precision choosing float or double. Both steppers work on one pair of vectors: reset when switching. */
void *throughput_odeint_open(int dims, int n, int single_precision);
void throughput_odeint_close(void *work);
void throughput_odeint_reset(void *work, int method);
int throughput_odeint_run(void *work, int method, int steps);
void throughput_odeint_read(const void *work, int method, int i, double *out);
long throughput_odeint_subnormals(const void *work, int method);

/* ---- shared helpers ---------------------------------------------------------------------------------- */
static inline double throughput_seconds(void) {
    struct timespec now;
    clock_gettime(CLOCK_MONOTONIC, &now);
    return (double)now.tv_sec + 1e-9 * (double)now.tv_nsec;
}
/* The CPU time of the calling thread: it stops while another process has the core. */
static inline double throughput_thread_seconds(void) {
    struct timespec now;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
    return (double)now.tv_sec + 1e-9 * (double)now.tv_nsec;
}

#ifdef __cplusplus
}
#endif

#endif
