/* tradeoff_problems.h - the reference problems bench/tradeoff measures the integrators on, with their known
   answers: the closed forms of bench/problems.h (owned with tests/numeric.c), copied here with the force
   model as plain doubles (no motus type), so the bench builds whatever motus's API looks like; the motus side
   (tradeoff_motus.c) turns problem_forces into a motus_scene. One particle of mass 1 per problem (a batch is many copies);
   SI units; everything here is double, whatever motus_real is.

   problem                  force model                              known answer
   free_fall                gravity (0, -9.81)                       x0 + v0 t + g t^2/2
   gravity_linear_drag      gravity + linear drag k = 0.5/s          v_inf t + (v0 - v_inf)(1 - e^-kt)/k
   harmonic_oscillator      spring to the origin, k = 4 N/m          x0 cos wt + v0/w sin wt, w = 2
   damped_oscillator        the same spring + linear drag 0.4/s      underdamped closed form, zeta = 0.1
   kepler_circular          attractor mu = 1 at the origin, r = 1    circle, period 2 pi, E = -1/2, L = 1
   kepler_eccentric         attractor mu = 1, e = 0.5, a = 1         Kepler's equation, period 2 pi,
                                                                     E = -1/2, L = sqrt(3)/2
   projectile_quadratic_drag gravity + quadratic drag c = 0.05/m     none: a tight rk8pd reference (bench) */
#ifndef MOTUS_TRADEOFF_PROBLEMS_H
#define MOTUS_TRADEOFF_PROBLEMS_H

#include <math.h>
#include <string.h>

#define PROBLEM_PI 3.14159265358979323846

typedef struct problem_state {
    double x, y, vx, vy;
} problem_state;

/* The force model, per unit mass: gravity, linear drag k (a -= k v), quadratic drag c (a -= c |v| v), an
   attractor of strength mu at the origin (a -= mu r/|r|^3), a spring of stiffness k to an anchor at the
   origin, rest length 0 (a -= k x: the oscillators; motus steps it through its coupled path, one spring per
   particle). */
typedef struct problem_forces {
    double gravity_x, gravity_y, linear_drag, quadratic_drag, attractor_strength, spring_stiffness;
} problem_forces;

typedef struct problem {
    const char *name;
    problem_state start;
    double duration; /* seconds the error is measured over */
    problem_forces forces;
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
        p->forces.gravity_y = -PROBLEM_G;
        p->exact = problem_free_fall_exact;
        p->energy = problem_gravity_energy;
        break;
    case PROBLEM_GRAVITY_LINEAR_DRAG:
        p->name = "gravity_linear_drag";
        p->start.vx = 3, p->start.vy = 12;
        p->duration = 2;
        p->forces.gravity_y = -PROBLEM_G;
        p->forces.linear_drag = PROBLEM_DRAG;
        p->exact = problem_linear_drag_exact;
        break;
    case PROBLEM_HARMONIC_OSCILLATOR:
    case PROBLEM_DAMPED_OSCILLATOR:
        p->name = which == PROBLEM_HARMONIC_OSCILLATOR ? "harmonic_oscillator" : "damped_oscillator";
        p->start.x = 1, p->start.vy = 1;
        p->duration = 5;
        p->forces.spring_stiffness = PROBLEM_OMEGA * PROBLEM_OMEGA; /* to the origin, rest length 0 */
        if (which == PROBLEM_HARMONIC_OSCILLATOR) {
            p->exact = problem_oscillator_exact;
            p->energy = problem_oscillator_energy;
        } else {
            p->forces.linear_drag = PROBLEM_OSCILLATOR_DRAG;
            p->exact = problem_damped_oscillator_exact;
        }
        break;
    case PROBLEM_KEPLER_CIRCULAR:
        p->name = "kepler_circular";
        p->start.x = 1, p->start.vy = 1;
        p->duration = 2 * PROBLEM_PI;
        p->forces.attractor_strength = 1;
        p->exact = problem_kepler_circular_exact;
        p->energy = problem_kepler_energy;
        break;
    case PROBLEM_KEPLER_ECCENTRIC:
        p->name = "kepler_eccentric";
        p->start.x = 1 - PROBLEM_ECCENTRICITY;
        p->start.vy = sqrt((1 + PROBLEM_ECCENTRICITY) / (1 - PROBLEM_ECCENTRICITY)); /* vis-viva at periapsis */
        p->duration = 2 * PROBLEM_PI;
        p->forces.attractor_strength = 1;
        p->exact = problem_kepler_eccentric_exact;
        p->energy = problem_kepler_energy;
        break;
    case PROBLEM_PROJECTILE_QUADRATIC_DRAG:
        p->name = "projectile_quadratic_drag";
        p->start.vx = 20, p->start.vy = 20;
        p->duration = 3;
        p->forces.gravity_y = -PROBLEM_G;
        p->forces.quadratic_drag = PROBLEM_QUADRATIC_DRAG;
        break;
    default: return 0;
    }
    return 1;
}

#endif
