/* tradeoff.h - what the three parts of bench/tradeoff say to each other.
   tradeoff_motus.c  the motus side, compiled twice: once in float (functions ending _float) and once with
                     MOTUS_DOUBLE (ending _double);
   tradeoff_peers.cpp the same problems solved by Boost.Odeint and GSL odeiv2, and the tight GSL reference;
   tradeoff.cpp       the sweep, the errors, the analysis and every output file.
   Only plain C types cross between them: each part includes motus.h with its own motus_real.

   A "trajectory" is x, y, vx, vy of particle 0 of the batch at step 0 (the start), 1, ..., steps: 4*(steps+1)
   doubles. Every run also checks that the last particle of the batch ended exactly where particle 0 did. */
#ifndef TRADEOFF_H
#define TRADEOFF_H

#include <math.h> /* NAN */
#include <time.h>

#ifdef __cplusplus
extern "C" {
#endif

enum {
    TRADEOFF_OK = 0,
    TRADEOFF_UNSUPPORTED, /* the method cannot express this problem (a velocity-dependent force, ...) */
    TRADEOFF_DIVERGED,    /* the run stopped: a step failed or left a non-finite state; the rest is NaN */
    TRADEOFF_BATCH_MISMATCH /* the particles of the batch did not all end in the same place: a bug */
};

/* ---- motus (tradeoff_motus.c) ----------------------------------------------------------------------
   method: a motus_method value. *evaluations receives the force-model stages per step the run made,
   counted through a force callback that adds nothing (0 for the exact stepper, which takes no callback).
   The callback puts the accuracy runs on motus's coupled path, which gives the same bits as the fast path
   (motus.h >>determinism); the timed runs have no callback. */
int tradeoff_motus_trajectory_float(int method, int problem, double dt, int steps, int count, double *trajectory,
                                    double *evaluations);
int tradeoff_motus_trajectory_double(int method, int problem, double dt, int steps, int count, double *trajectory,
                                     double *evaluations);
/* Wall time per particle-step in ns: the median over `repetitions` timed repetitions, after one untimed
   warm-up run, of a batch of `count` particles reset to the start and stepped `steps` times. A repetition
   repeats that run (resetting untimed in between) until it has timed at least `seconds` seconds, so short
   problems are not measured at the timer's resolution. NaN if a run did not finish. */
double tradeoff_motus_time_float(int method, int problem, double dt, int steps, int count, int repetitions,
                                 double seconds);
double tradeoff_motus_time_double(int method, int problem, double dt, int steps, int count, int repetitions,
                                  double seconds);

/* ---- peers (tradeoff_peers.cpp) --------------------------------------------------------------------- */
enum {
    PEER_ODEINT_EULER,
    PEER_ODEINT_SYMPLECTIC_EULER,
    PEER_ODEINT_VELOCITY_VERLET,
    PEER_ODEINT_RUNGE_KUTTA4,
    PEER_ODEINT_MCLACHLAN,
    PEER_GSL_RK4,
    PEER_GSL_RK8PD,
    PEER_COUNT
};
const char *tradeoff_peer_name(int peer);
int tradeoff_peer_order(int peer);
/* single_precision: odeint in float (GSL is double only: TRADEOFF_UNSUPPORTED). */
int tradeoff_peer_trajectory(int peer, int single_precision, int problem, double dt, int steps, int count,
                             double *trajectory, double *evaluations);
double tradeoff_peer_time(int peer, int single_precision, int problem, double dt, int steps, int count,
                          int repetitions, double seconds);
/* The answer for problems without a closed form: GSL rk8pd with step control at absolute and relative
   tolerance `tolerance`, stopped exactly at every t = n*dt. */
int tradeoff_reference(int problem, double dt, int steps, double tolerance, double *trajectory);

/* ---- shared helpers ---------------------------------------------------------------------------------- */
static inline double tradeoff_seconds(void) {
    struct timespec now;
    clock_gettime(CLOCK_MONOTONIC, &now);
    return (double)now.tv_sec + 1e-9 * (double)now.tv_nsec;
}

/* Median of values[0..n), n <= 64; sorts a copy. */
static inline double tradeoff_median(const double *values, int n) {
    double sorted[64];
    int i, j;
    if (n <= 0) return NAN;
    if (n > 64) n = 64;
    for (i = 0; i < n; ++i) {
        double v = values[i];
        for (j = i; j > 0 && sorted[j - 1] > v; --j) sorted[j] = sorted[j - 1];
        sorted[j] = v;
    }
    return n % 2 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
}

#ifdef __cplusplus
}
#endif

#endif
