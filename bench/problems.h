/* problems.h - the reference problems the integrators are measured on, with their known answers.
   Shared by bench/tradeoff and tests/numeric.c. One particle of mass 1 per problem (a batch is many copies);
   SI units; everything here is double, whatever motus_real is. Each problem carries the motus_scene that
   poses it (method left at 0, semi-implicit Euler: set scene.method before stepping). The oscillators'
   scene tethers the particle to the origin (scene.tether_stiffness: no coupling, no scratch);
   problem_use_spring() poses them instead with an anchored spring, which couples (scratch needed).

   problem                  force model                              known answer
   free_fall                gravity (0, -9.81)                       x0 + v0 t + g t^2/2
   gravity_linear_drag      gravity + linear drag k = 0.5/s          v_inf t + (v0 - v_inf)(1 - e^-kt)/k
   harmonic_oscillator      tether to the origin, k = 4 N/m          x0 cos wt + v0/w sin wt, w = 2
   damped_oscillator        the same tether + linear drag 0.4/s      underdamped closed form, zeta = 0.1
   kepler_circular          attractor mu = 1 at the origin, r = 1    circle, period 2 pi, E = -1/2, L = 1
   kepler_eccentric         attractor mu = 1, e = 0.5, a = 1         Kepler's equation, period 2 pi,
                                                                     E = -1/2, L = sqrt(3)/2
   projectile_quadratic_drag gravity + quadratic drag c = 0.05/m     none: a tight rk8pd reference (bench) */
#ifndef MOTUS_PROBLEMS_H
#define MOTUS_PROBLEMS_H

#include "motus.h"

#include <math.h>
#include <string.h>

#define PROBLEM_PI 3.14159265358979323846

typedef struct problem_state {
    double x, y, vx, vy;
} problem_state;

typedef struct problem {
    const char *name;
    problem_state start;
    double duration; /* seconds the error is measured over */
    motus_scene scene;   /* the forces; scene.method is 0 (set yours); scene.mass 0 = 1 kg */
    motus_spring spring; /* the oscillators' tether as a spring (problem_use_spring): scene.springs then points
                            here, so pass problems by pointer */
    /* The exact state at time t, or NULL where there is no closed form. */
    problem_state (*exact)(double t);
    /* Total energy per unit mass (kinetic + potential), or NULL where energy is not conserved. */
    double (*energy)(problem_state s);
} problem;

enum {
    PROBLEM_FREE_FALL,
    PROBLEM_GRAVITY_LINEAR_DRAG,
    PROBLEM_HARMONIC_OSCILLATOR,
    PROBLEM_DAMPED_OSCILLATOR,
    PROBLEM_KEPLER_CIRCULAR,
    PROBLEM_KEPLER_ECCENTRIC,
    PROBLEM_PROJECTILE_QUADRATIC_DRAG,
    PROBLEM_COUNT
};

#define PROBLEM_G 9.81
#define PROBLEM_DRAG 0.5
#define PROBLEM_OMEGA 2.0
#define PROBLEM_OSCILLATOR_DRAG 0.4
#define PROBLEM_QUADRATIC_DRAG 0.05
#define PROBLEM_ECCENTRICITY 0.5

static inline problem_state problem_free_fall_exact(double t) {
    problem_state s;
    s.x = 3 * t;
    s.y = 12 * t - 0.5 * PROBLEM_G * t * t;
    s.vx = 3;
    s.vy = 12 - PROBLEM_G * t;
    return s;
}
static inline double problem_gravity_energy(problem_state s) { return 0.5 * (s.vx * s.vx + s.vy * s.vy) + PROBLEM_G * s.y; }

/* v' = g - k v per axis: v = v_inf + (v0 - v_inf) e^-kt, x = v_inf t + (v0 - v_inf)(1 - e^-kt)/k. */
static inline problem_state problem_linear_drag_exact(double t) {
    const double k = PROBLEM_DRAG, decay = exp(-k * t), lost = -expm1(-k * t), vx_inf = 0, vy_inf = -PROBLEM_G / k;
    problem_state s;
    s.x = vx_inf * t + (3 - vx_inf) * lost / k;
    s.y = vy_inf * t + (12 - vy_inf) * lost / k;
    s.vx = vx_inf + (3 - vx_inf) * decay;
    s.vy = vy_inf + (12 - vy_inf) * decay;
    return s;
}

/* Isotropic oscillator from (1, 0) with velocity (0, 1): an ellipse with semi-axes 1 and 1/2. */
static inline problem_state problem_oscillator_exact(double t) {
    const double w = PROBLEM_OMEGA;
    problem_state s;
    s.x = cos(w * t);
    s.y = sin(w * t) / w;
    s.vx = -w * sin(w * t);
    s.vy = cos(w * t);
    return s;
}
static inline double problem_oscillator_energy(problem_state s) {
    return 0.5 * (s.vx * s.vx + s.vy * s.vy) + 0.5 * PROBLEM_OMEGA * PROBLEM_OMEGA * (s.x * s.x + s.y * s.y);
}

/* x'' + 2 zeta w x' + w^2 x = 0 per axis, with 2 zeta w = 0.4: x = e^(-gt)(A cos(wd t) + B sin(wd t)). */
static inline problem_state problem_damped_oscillator_exact(double t) {
    const double w = PROBLEM_OMEGA, g = 0.5 * PROBLEM_OSCILLATOR_DRAG, wd = sqrt(w * w - g * g), e = exp(-g * t);
    const double c = cos(wd * t), sn = sin(wd * t);
    /* x: x0 = 1, v0 = 0 -> A = 1, B = g/wd. y: y0 = 0, v0 = 1 -> A = 0, B = 1/wd. */
    problem_state s;
    s.x = e * (c + g / wd * sn);
    s.vx = e * (-g * (c + g / wd * sn) + (-wd * sn + g * c));
    s.y = e * sn / wd;
    s.vy = e * (-g * sn / wd + c);
    return s;
}

static inline problem_state problem_kepler_circular_exact(double t) {
    problem_state s;
    s.x = cos(t);
    s.y = sin(t);
    s.vx = -sin(t);
    s.vy = cos(t);
    return s;
}
static inline double problem_kepler_energy(problem_state s) {
    return 0.5 * (s.vx * s.vx + s.vy * s.vy) - 1.0 / sqrt(s.x * s.x + s.y * s.y);
}
/* Angular momentum per unit mass, conserved by the central force. */
static inline double problem_angular_momentum(problem_state s) { return s.x * s.vy - s.y * s.vx; }

/* Ellipse a = 1, e = 0.5, starting at periapsis (0.5, 0) moving +y: mean anomaly M = t, Kepler's equation
   E - e sin E = M solved by Newton's method to rounding. */
static inline problem_state problem_kepler_eccentric_exact(double t) {
    const double e = PROBLEM_ECCENTRICITY, b = sqrt(1 - e * e);
    double m = fmod(t, 2 * PROBLEM_PI), E = m, r;
    int i;
    problem_state s;
    for (i = 0; i < 50; ++i) {
        double step = (E - e * sin(E) - m) / (1 - e * cos(E));
        E -= step;
        if (fabs(step) < 1e-16) break;
    }
    r = 1 - e * cos(E);
    s.x = cos(E) - e;
    s.y = b * sin(E);
    s.vx = -sin(E) / r; /* dE/dt = n/r with mean motion n = 1 */
    s.vy = b * cos(E) / r;
    return s;
}

/* Fills *p with problem `which` (PROBLEM_*). Returns 0 for an unknown index. */
static inline int problem_get(int which, problem *p) {
    memset(p, 0, sizeof *p);
    switch (which) {
    case PROBLEM_FREE_FALL:
        p->name = "free_fall";
        p->start.vx = 3, p->start.vy = 12;
        p->duration = 2;
        p->scene.gravity = motus_v3(0, (motus_real)-PROBLEM_G, 0);
        p->exact = problem_free_fall_exact;
        p->energy = problem_gravity_energy;
        break;
    case PROBLEM_GRAVITY_LINEAR_DRAG:
        p->name = "gravity_linear_drag";
        p->start.vx = 3, p->start.vy = 12;
        p->duration = 2;
        p->scene.gravity = motus_v3(0, (motus_real)-PROBLEM_G, 0);
        p->scene.linear_drag = (motus_real)PROBLEM_DRAG;
        p->exact = problem_linear_drag_exact;
        break;
    case PROBLEM_HARMONIC_OSCILLATOR:
    case PROBLEM_DAMPED_OSCILLATOR:
        p->name = which == PROBLEM_HARMONIC_OSCILLATOR ? "harmonic_oscillator" : "damped_oscillator";
        p->start.x = 1, p->start.vy = 1;
        p->duration = 5;
        p->spring.a = 0;
        p->spring.b = -1; /* to the anchor at the origin, rest length 0: F = -k x */
        p->spring.stiffness = (motus_real)(PROBLEM_OMEGA * PROBLEM_OMEGA);
        p->scene.tether_stiffness = p->spring.stiffness; /* tether at the origin: F = -k x */
        if (which == PROBLEM_HARMONIC_OSCILLATOR) {
            p->exact = problem_oscillator_exact;
            p->energy = problem_oscillator_energy;
        } else {
            p->scene.linear_drag = (motus_real)PROBLEM_OSCILLATOR_DRAG;
            p->exact = problem_damped_oscillator_exact;
        }
        break;
    case PROBLEM_KEPLER_CIRCULAR:
        p->name = "kepler_circular";
        p->start.x = 1, p->start.vy = 1;
        p->duration = 2 * PROBLEM_PI;
        p->scene.attractor_strength = 1;
        p->exact = problem_kepler_circular_exact;
        p->energy = problem_kepler_energy;
        break;
    case PROBLEM_KEPLER_ECCENTRIC:
        p->name = "kepler_eccentric";
        p->start.x = 1 - PROBLEM_ECCENTRICITY;
        p->start.vy = sqrt((1 + PROBLEM_ECCENTRICITY) / (1 - PROBLEM_ECCENTRICITY)); /* vis-viva at periapsis */
        p->duration = 2 * PROBLEM_PI;
        p->scene.attractor_strength = 1;
        p->exact = problem_kepler_eccentric_exact;
        p->energy = problem_kepler_energy;
        break;
    case PROBLEM_PROJECTILE_QUADRATIC_DRAG:
        p->name = "projectile_quadratic_drag";
        p->start.vx = 20, p->start.vy = 20;
        p->duration = 3;
        p->scene.gravity = motus_v3(0, (motus_real)-PROBLEM_G, 0);
        p->scene.quadratic_drag = (motus_real)PROBLEM_QUADRATIC_DRAG;
        break;
    default: return 0;
    }
    return 1;
}

/* A particle of mass 1 at the problem's start (2D; problem_particle3: in the plane z = 0). */
static inline motus_particle problem_particle(const problem *p) {
    motus_particle particle;
    /* Zeroed first: mass 1 never fails, but GCC 12 under -fsanitize=address cannot see that and warns
       -Wmaybe-uninitialized on the path where init returns an error without writing. */
    memset(&particle, 0, sizeof particle);
    motus_particle_init(&particle, motus_v2((motus_real)p->start.x, (motus_real)p->start.y), 1);
    particle.velocity = motus_v2((motus_real)p->start.vx, (motus_real)p->start.vy);
    return particle;
}

static inline motus_particle3 problem_particle3(const problem *p) {
    motus_particle3 particle;
    memset(&particle, 0, sizeof particle);
    motus_particle3_init(&particle, motus_v3((motus_real)p->start.x, (motus_real)p->start.y, 0), 1);
    particle.velocity = motus_v3((motus_real)p->start.vx, (motus_real)p->start.vy, 0);
    return particle;
}

/* An oscillator posed with an anchored spring (the same force, k*(x - anchor), through the coupled path)
   instead of the tether; its anchor is p->spring.anchor. 0 for the other problems. */
static inline int problem_use_spring(problem *p) {
    if (p->spring.stiffness == 0) return 0;
    p->scene.tether_stiffness = 0;
    p->scene.springs = &p->spring;
    p->scene.spring_count = 1;
    return 1;
}

/* 1 if the problem's scene couples particles (a spring): motus_step needs scratch, motus_step_range refuses it. */
static inline int problem_needs_scratch(const problem *p) {
    return p->scene.spring_count > 0 || p->scene.force_callback != NULL;
}

static inline problem_state problem_state_of(const motus_particle *particle) {
    problem_state s;
    s.x = particle->position.x, s.y = particle->position.y;
    s.vx = particle->velocity.x, s.vy = particle->velocity.y;
    return s;
}

static inline problem_state problem_state_of3(const motus_particle3 *particle) {
    problem_state s;
    s.x = particle->position.x, s.y = particle->position.y;
    s.vx = particle->velocity.x, s.vy = particle->velocity.y;
    return s;
}

#endif
