/* collisions.h - what the parts of bench/collisions say to each other (issue 12, item 8).
   collisions.cpp           the scenes, the timing, the overlap and energy measurements, every output file;
   collisions_motus.c       motus_step with scene.contacts (built only when include/motus.h has motus_contacts);
   collisions_brute.c       a brute-force pair loop with the plain contact model of COLLISIONS.md (integrate,
                            then Gauss-Seidel velocity impulses, then position projection): O(N^2);
   collisions_box2d.cpp     Box2D 2.4 circles (Debian libbox2d-dev);
   collisions_chipmunk.c    Chipmunk 7 circles (libchipmunk-dev);
   collisions_bullet.cpp    Bullet spheres, 3D (libbullet-dev).
   Only plain C types cross between them. Every engine sees the same scene: N balls of radius r and mass 1 kg,
   y up, gravity -g along y, a box [box_min, box_max] open at the top (box_max[1] = +Inf), restitution 0 and
   friction 0 everywhere (walls too), one call per frame of dt = 1/60 s. */
#ifndef COLLISIONS_H
#define COLLISIONS_H

#ifdef __cplusplus
extern "C" {
#endif

typedef struct cb_scene {
    int dims;              /* 2 or 3 */
    int n;                 /* balls */
    double r;              /* radius, m */
    double g;              /* m/s^2, acts along -y */
    double dt;             /* s per frame (per step call) */
    int substeps;          /* motus and brute force: substeps per frame */
    int iterations;        /* motus and brute force: solver sweeps per substep */
    int threads;           /* motus: threads of scene.parallel_for (tests/support/motus_pool.h); 0: none, the
                              calling thread alone. The peers ignore it (they run on one thread). */
    double box_min[3], box_max[3]; /* walls; box_max[1] is +Inf (open top); [2] unused in 2D */
    const double *x[3], *v[3];     /* the start: positions and velocities, [2] NULL in 2D */
} cb_scene;

/* An engine: create builds its world from the scene (untimed), step advances one frame (timed; returns 0,
   or nonzero on an error), read copies positions and velocities out as doubles (untimed), destroy frees. */
typedef struct cb_engine {
    const char *name;      /* the CSV's engine column */
    int dims_mask;         /* bit 2: 2D, bit 3: 3D */
    int max_n;             /* 0: no cap; the brute force stops at 10^4 */
    void *(*create)(const cb_scene *scene);
    int (*step)(void *world);
    void (*read)(void *world, double *x[3], double *v[3]);
    void (*destroy)(void *world);
    const char *(*describe)(void); /* settings for the report: version, iterations, slop ... */
} cb_engine;

extern const cb_engine cb_engine_brute;
#ifdef CB_HAVE_MOTUS
extern const cb_engine cb_engine_motus;
extern const cb_engine cb_engine_motus_one_substep; /* "motus-1substep": motus at 1 substep a frame */
extern const cb_engine cb_engine_motus_light;       /* "motus-1x1": 1 substep a frame, 1 iteration */
#endif
#ifdef CB_HAVE_BOX2D
extern const cb_engine cb_engine_box2d;
#endif
#ifdef CB_HAVE_CHIPMUNK
extern const cb_engine cb_engine_chipmunk;
#endif
#ifdef CB_HAVE_BULLET
extern const cb_engine cb_engine_bullet;
#endif

#ifdef __cplusplus
}
#endif

#endif
