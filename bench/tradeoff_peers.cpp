// tradeoff_peers.cpp - the reference problems solved by the libraries a user might pick instead of motus:
// Boost.Odeint (euler, symplectic_euler, velocity_verlet, runge_kutta4, symplectic_rkn_sb3a_mclachlan; in
// double and in float) and GSL odeiv2 (rk4, rk8pd; double only), on the same batch, force, start, duration
// and time steps as the motus side. Also the tight GSL rk8pd reference for the problem with no closed form.
//
// Each peer gets the form its documentation shows: odeint steppers over std::vector state (x, y, vx, vy of
// every particle for the first-order steppers; coordinates and momenta for the symplectic ones), GSL through
// gsl_odeiv2_driver_apply_fixed_step. The accelerations are written by hand for each problem, as a user of
// those libraries would write them, while motus evaluates its general force model (a motus_scene).
#define MOTUS_DOUBLE
#include "problems.h"
#include "tradeoff.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include <boost/numeric/odeint.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <type_traits>
#include <utility>
#include <vector>

namespace {

namespace odeint = boost::numeric::odeint;

// ---- accelerations, one functor per problem ----------------------------------------------------------
struct free_fall {
    static const bool uses_velocity = false;
    template <class T> void operator()(T, T, T, T, T &ax, T &ay) const {
        ax = 0;
        ay = T(-PROBLEM_G);
    }
};
struct gravity_linear_drag {
    static const bool uses_velocity = true;
    template <class T> void operator()(T, T, T vx, T vy, T &ax, T &ay) const {
        ax = -T(PROBLEM_DRAG) * vx;
        ay = T(-PROBLEM_G) - T(PROBLEM_DRAG) * vy;
    }
};
struct harmonic_oscillator {
    static const bool uses_velocity = false;
    template <class T> void operator()(T x, T y, T, T, T &ax, T &ay) const {
        const T k = T(PROBLEM_OMEGA * PROBLEM_OMEGA);
        ax = -k * x;
        ay = -k * y;
    }
};
struct damped_oscillator {
    static const bool uses_velocity = true;
    template <class T> void operator()(T x, T y, T vx, T vy, T &ax, T &ay) const {
        const T k = T(PROBLEM_OMEGA * PROBLEM_OMEGA), c = T(PROBLEM_OSCILLATOR_DRAG);
        ax = -k * x - c * vx;
        ay = -k * y - c * vy;
    }
};
struct kepler { // mu = 1, attractor at the origin
    static const bool uses_velocity = false;
    template <class T> void operator()(T x, T y, T, T, T &ax, T &ay) const {
        const T r2 = x * x + y * y, s = T(1) / (r2 * std::sqrt(r2));
        ax = -x * s;
        ay = -y * s;
    }
};
struct projectile_quadratic_drag {
    static const bool uses_velocity = true;
    template <class T> void operator()(T, T, T vx, T vy, T &ax, T &ay) const {
        const T c = T(PROBLEM_QUADRATIC_DRAG) * std::sqrt(vx * vx + vy * vy);
        ax = -c * vx;
        ay = T(-PROBLEM_G) - c * vy;
    }
};

// ---- the systems in the forms each stepper takes -------------------------------------------------------
// y' = f(y) over x, y, vx, vy of every particle, interleaved.
template <class T, class Accel> struct first_order_system {
    long *evaluations;
    void operator()(const std::vector<T> &s, std::vector<T> &d, T) const {
        ++*evaluations;
        const std::size_t n = s.size() / 4;
        for (std::size_t i = 0; i < n; ++i) {
            const T *in = &s[4 * i];
            T *out = &d[4 * i];
            out[0] = in[2];
            out[1] = in[3];
            Accel()(in[0], in[1], in[2], in[3], out[2], out[3]);
        }
    }
};
// dp/dt = a(q), dq/dt = p (mass 1): the one-function form of odeint's symplectic steppers.
template <class T, class Accel> struct momentum_system {
    long *evaluations;
    void operator()(const std::vector<T> &q, std::vector<T> &dpdt) const {
        ++*evaluations;
        const std::size_t n = q.size() / 2;
        for (std::size_t i = 0; i < n; ++i) Accel()(q[2 * i], q[2 * i + 1], T(0), T(0), dpdt[2 * i], dpdt[2 * i + 1]);
    }
};
// a(x, v, t): odeint's velocity_verlet. It evaluates a(x_{n+1}, v_n): velocity-dependent forces see the old v.
template <class T, class Accel> struct second_order_system {
    long *evaluations;
    void operator()(const std::vector<T> &x, const std::vector<T> &v, std::vector<T> &a, T) const {
        ++*evaluations;
        const std::size_t n = x.size() / 2;
        for (std::size_t i = 0; i < n; ++i)
            Accel()(x[2 * i], x[2 * i + 1], v[2 * i], v[2 * i + 1], a[2 * i], a[2 * i + 1]);
    }
};

// ---- solvers: reset to the problem's start, step, read a particle --------------------------------------
template <class T, class Accel, class Stepper> struct odeint_first_order {
    std::vector<T> y;
    Stepper stepper;
    first_order_system<T, Accel> system;
    T t;
    explicit odeint_first_order(long *evaluations) : t(0) { system.evaluations = evaluations; }
    void reset(const problem &p, int count) {
        y.assign(4 * (std::size_t)count, T(0));
        for (int i = 0; i < count; ++i) {
            y[4 * i] = T(p.start.x), y[4 * i + 1] = T(p.start.y);
            y[4 * i + 2] = T(p.start.vx), y[4 * i + 3] = T(p.start.vy);
        }
        t = 0; // euler and runge_kutta4 keep no state between steps but their buffers
    }
    bool step(T dt) {
        stepper.do_step(std::ref(system), y, t, dt);
        t += dt;
        return true;
    }
    bool steps(T dt, int n) {
        for (int i = 0; i < n; ++i) step(dt);
        return true;
    }
    void read(int i, double *out) const {
        for (int k = 0; k < 4; ++k) out[k] = y[4 * i + k];
    }
};

// Coordinates q = (x0, y0, x1, y1, ...) and velocities (= momenta, mass 1) p.
template <class T> struct split_state {
    std::vector<T> q, p;
    void reset(const problem &pr, int count) {
        q.assign(2 * (std::size_t)count, T(0));
        p.assign(2 * (std::size_t)count, T(0));
        for (int i = 0; i < count; ++i) {
            q[2 * i] = T(pr.start.x), q[2 * i + 1] = T(pr.start.y);
            p[2 * i] = T(pr.start.vx), p[2 * i + 1] = T(pr.start.vy);
        }
    }
    void read(int i, double *out) const {
        out[0] = q[2 * i], out[1] = q[2 * i + 1], out[2] = p[2 * i], out[3] = p[2 * i + 1];
    }
};

template <class T, class Accel, class Stepper> struct odeint_symplectic : split_state<T> {
    Stepper stepper;
    momentum_system<T, Accel> system;
    T t;
    explicit odeint_symplectic(long *evaluations) : t(0) { system.evaluations = evaluations; }
    void reset(const problem &p, int count) {
        split_state<T>::reset(p, count);
        t = 0; // the symplectic steppers keep no state between steps but their buffers
    }
    bool step(T dt) {
        stepper.do_step(std::ref(system), this->q, this->p, t, dt);
        t += dt;
        return true;
    }
    bool steps(T dt, int n) {
        for (int i = 0; i < n; ++i) step(dt);
        return true;
    }
};

template <class T, class Accel> struct odeint_verlet : split_state<T> {
    odeint::velocity_verlet<std::vector<T>, std::vector<T>, T> stepper;
    second_order_system<T, Accel> system;
    T t;
    explicit odeint_verlet(long *evaluations) : t(0) { system.evaluations = evaluations; }
    void reset(const problem &p, int count) {
        split_state<T>::reset(p, count);
        stepper.reset(); // the first step computes a(x_0, v_0); later steps reuse the last acceleration
        t = 0;
    }
    bool step(T dt) {
        stepper.do_step(std::ref(system), std::make_pair(std::ref(this->q), std::ref(this->p)), t, dt);
        t += dt;
        return true;
    }
    bool steps(T dt, int n) {
        for (int i = 0; i < n; ++i) step(dt);
        return true;
    }
};

template <class Accel> struct gsl_solver {
    const gsl_odeiv2_step_type *type;
    gsl_odeiv2_system system;
    gsl_odeiv2_driver *driver;
    std::vector<double> y;
    double t;
    long *evaluations;
    gsl_solver(const gsl_odeiv2_step_type *step_type, long *counter)
        : type(step_type), driver(NULL), t(0), evaluations(counter) {}
    ~gsl_solver() {
        if (driver) gsl_odeiv2_driver_free(driver);
    }
    static int rhs(double, const double *s, double *d, void *params) {
        gsl_solver *self = static_cast<gsl_solver *>(params);
        ++*self->evaluations;
        const std::size_t n = self->y.size() / 4;
        for (std::size_t i = 0; i < n; ++i) {
            const double *in = s + 4 * i;
            double *out = d + 4 * i;
            out[0] = in[2];
            out[1] = in[3];
            Accel()(in[0], in[1], in[2], in[3], out[2], out[3]);
        }
        return GSL_SUCCESS;
    }
    void reset(const problem &p, int count) {
        y.assign(4 * (std::size_t)count, 0.0);
        for (int i = 0; i < count; ++i) {
            y[4 * i] = p.start.x, y[4 * i + 1] = p.start.y, y[4 * i + 2] = p.start.vx, y[4 * i + 3] = p.start.vy;
        }
        if (driver) gsl_odeiv2_driver_free(driver);
        system.function = rhs;
        system.jacobian = NULL;
        system.dimension = y.size();
        system.params = this;
        // Tolerances are unused by the fixed-step driver call; hstart likewise.
        driver = gsl_odeiv2_driver_alloc_y_new(&system, type, 1e-3, 1e-6, 0.0);
        t = 0;
    }
    bool steps(double dt, int n) {
        return gsl_odeiv2_driver_apply_fixed_step(driver, &t, dt, (unsigned long)n, y.data()) == GSL_SUCCESS;
    }
    bool step(double dt) { return steps(dt, 1); }
    void read(int i, double *out) const {
        for (int k = 0; k < 4; ++k) out[k] = y[4 * i + k];
    }
};

// ---- jobs run on any solver ---------------------------------------------------------------------------
struct trajectory_job {
    const problem *p;
    double dt;
    int steps, count;
    double *trajectory, *evaluations;
    long counter;
    template <class Solver, class T> int run(Solver &s, T dt_t) {
        s.reset(*p, count);
        counter = 0;
        s.read(0, trajectory);
        int n = 1;
        for (; n <= steps; ++n) {
            if (!s.step(dt_t)) break;
            s.read(0, trajectory + 4 * n);
            const double *last = trajectory + 4 * n;
            if (!(std::isfinite(last[0]) && std::isfinite(last[1]) && std::isfinite(last[2]) && std::isfinite(last[3])))
                break;
        }
        const bool finished = n > steps;
        for (; n <= steps; ++n)
            for (int k = 0; k < 4; ++k) trajectory[4 * n + k] = NAN;
        if (!finished) return TRADEOFF_DIVERGED;
        double first[4], end[4];
        s.read(0, first);
        s.read(count - 1, end);
        if (std::memcmp(first, end, sizeof first) != 0) return TRADEOFF_BATCH_MISMATCH;
        *evaluations = steps > 0 ? (double)counter / steps : 0;
        return TRADEOFF_OK;
    }
};

struct timing_job {
    const problem *p;
    double dt;
    int steps, count, repetitions;
    double seconds;
    long counter;
    double result;
    // One timed run: reset (untimed), then `steps` steps. Seconds, or -1 if the peer reported a failure.
    template <class Solver, class T> double timed_run(Solver &s, T dt_t) {
        s.reset(*p, count);
        const double start = tradeoff_seconds();
        if (!s.steps(dt_t, steps)) return -1;
        return tradeoff_seconds() - start;
    }
    // As tradeoff_motus_time_*: one warm-up run, then `repetitions` repetitions of at least `seconds` each.
    template <class Solver, class T> int run(Solver &s, T dt_t) {
        double ns[64] = {0};
        if (repetitions > 64) repetitions = 64;
        result = NAN;
        const double warm_up = timed_run(s, dt_t);
        if (warm_up < 0) return TRADEOFF_DIVERGED;
        const int runs = std::max(1, (int)std::ceil(seconds / warm_up));
        for (int rep = 0; rep < repetitions; ++rep) {
            double total = 0;
            for (int run = 0; run < runs; ++run) {
                const double t = timed_run(s, dt_t);
                if (t < 0) return TRADEOFF_DIVERGED;
                total += t;
            }
            ns[rep] = total * 1e9 / ((double)steps * count * runs);
        }
        result = tradeoff_median(ns, repetitions);
        return TRADEOFF_OK;
    }
};

template <class T, class Accel, class Job> int run_peer(int peer, Job &job) {
    // Value (and so Time) is given as T: odeint's default is double even over float state.
    typedef std::vector<T> state;
    const T dt = T(job.dt);
    switch (peer) {
    case PEER_ODEINT_EULER: {
        odeint_first_order<T, Accel, odeint::euler<state, T> > s(&job.counter);
        return job.run(s, dt);
    }
    case PEER_ODEINT_SYMPLECTIC_EULER: {
        if (Accel::uses_velocity) return TRADEOFF_UNSUPPORTED; // q'' = f(q) only
        odeint_symplectic<T, Accel, odeint::symplectic_euler<state, state, T> > s(&job.counter);
        return job.run(s, dt);
    }
    case PEER_ODEINT_VELOCITY_VERLET: {
        odeint_verlet<T, Accel> s(&job.counter);
        return job.run(s, dt);
    }
    case PEER_ODEINT_RUNGE_KUTTA4: {
        odeint_first_order<T, Accel, odeint::runge_kutta4<state, T> > s(&job.counter);
        return job.run(s, dt);
    }
    case PEER_ODEINT_MCLACHLAN: {
        if (Accel::uses_velocity) return TRADEOFF_UNSUPPORTED;
        odeint_symplectic<T, Accel, odeint::symplectic_rkn_sb3a_mclachlan<state, state, T> > s(&job.counter);
        return job.run(s, dt);
    }
    case PEER_GSL_RK4:
    case PEER_GSL_RK8PD: {
        if (!std::is_same<T, double>::value) return TRADEOFF_UNSUPPORTED;
        gsl_solver<Accel> s(peer == PEER_GSL_RK4 ? gsl_odeiv2_step_rk4 : gsl_odeiv2_step_rk8pd, &job.counter);
        return job.run(s, job.dt);
    }
    default: return TRADEOFF_UNSUPPORTED;
    }
}

template <class T, class Job> int run_problem(int peer, int which, Job &job) {
    switch (which) {
    case PROBLEM_FREE_FALL: return run_peer<T, free_fall>(peer, job);
    case PROBLEM_GRAVITY_LINEAR_DRAG: return run_peer<T, gravity_linear_drag>(peer, job);
    case PROBLEM_HARMONIC_OSCILLATOR: return run_peer<T, harmonic_oscillator>(peer, job);
    case PROBLEM_DAMPED_OSCILLATOR: return run_peer<T, damped_oscillator>(peer, job);
    case PROBLEM_KEPLER_CIRCULAR:
    case PROBLEM_KEPLER_ECCENTRIC: return run_peer<T, kepler>(peer, job);
    case PROBLEM_PROJECTILE_QUADRATIC_DRAG: return run_peer<T, projectile_quadratic_drag>(peer, job);
    default: return TRADEOFF_UNSUPPORTED;
    }
}

template <class Job> int run_any(int peer, int single_precision, int which, Job &job) {
    gsl_set_error_handler_off(); // report failures through return codes, never abort()
    return single_precision ? run_problem<float>(peer, which, job) : run_problem<double>(peer, which, job);
}

// The reference: rk8pd with step control, stopped exactly at each sample time.
template <class Accel> struct reference_system {
    static int rhs(double, const double *s, double *d, void *) {
        d[0] = s[2];
        d[1] = s[3];
        Accel()(s[0], s[1], s[2], s[3], d[2], d[3]);
        return GSL_SUCCESS;
    }
    static int run(const problem &p, double dt, int steps, double tolerance, double *trajectory) {
        gsl_odeiv2_system system = {rhs, NULL, 4, NULL};
        gsl_odeiv2_driver *driver =
            gsl_odeiv2_driver_alloc_y_new(&system, gsl_odeiv2_step_rk8pd, 1e-4, tolerance, tolerance);
        double y[4] = {p.start.x, p.start.y, p.start.vx, p.start.vy}, t = 0;
        int status = GSL_SUCCESS;
        std::memcpy(trajectory, y, sizeof y);
        for (int n = 1; n <= steps && status == GSL_SUCCESS; ++n) {
            status = gsl_odeiv2_driver_apply(driver, &t, n * dt, y);
            std::memcpy(trajectory + 4 * n, y, sizeof y);
        }
        gsl_odeiv2_driver_free(driver);
        return status == GSL_SUCCESS ? TRADEOFF_OK : TRADEOFF_DIVERGED;
    }
};

} // namespace

extern "C" const char *tradeoff_peer_name(int peer) {
    static const char *const names[PEER_COUNT] = {"odeint euler", "odeint symplectic_euler",
                                                  "odeint velocity_verlet", "odeint runge_kutta4",
                                                  "odeint sb3a_mclachlan", "gsl rk4", "gsl rk8pd"};
    return peer >= 0 && peer < PEER_COUNT ? names[peer] : "?";
}

extern "C" int tradeoff_peer_order(int peer) {
    static const int orders[PEER_COUNT] = {1, 1, 2, 4, 4, 4, 8};
    return peer >= 0 && peer < PEER_COUNT ? orders[peer] : -1;
}

extern "C" int tradeoff_peer_trajectory(int peer, int single_precision, int which, double dt, int steps, int count,
                                        double *trajectory, double *evaluations) {
    problem p;
    if (!problem_get(which, &p)) return TRADEOFF_UNSUPPORTED;
    trajectory_job job = {&p, dt, steps, count, trajectory, evaluations, 0};
    *evaluations = 0;
    return run_any(peer, single_precision, which, job);
}

extern "C" double tradeoff_peer_time(int peer, int single_precision, int which, double dt, int steps, int count,
                                     int repetitions, double seconds) {
    problem p;
    if (!problem_get(which, &p)) return NAN;
    timing_job job = {&p, dt, steps, count, repetitions, seconds, 0, NAN};
    return run_any(peer, single_precision, which, job) == TRADEOFF_OK ? job.result : NAN;
}

extern "C" int tradeoff_reference(int which, double dt, int steps, double tolerance, double *trajectory) {
    problem p;
    if (!problem_get(which, &p)) return TRADEOFF_UNSUPPORTED;
    gsl_set_error_handler_off();
    switch (which) {
    case PROBLEM_FREE_FALL: return reference_system<free_fall>::run(p, dt, steps, tolerance, trajectory);
    case PROBLEM_GRAVITY_LINEAR_DRAG: return reference_system<gravity_linear_drag>::run(p, dt, steps, tolerance, trajectory);
    case PROBLEM_HARMONIC_OSCILLATOR: return reference_system<harmonic_oscillator>::run(p, dt, steps, tolerance, trajectory);
    case PROBLEM_DAMPED_OSCILLATOR: return reference_system<damped_oscillator>::run(p, dt, steps, tolerance, trajectory);
    case PROBLEM_KEPLER_CIRCULAR:
    case PROBLEM_KEPLER_ECCENTRIC: return reference_system<kepler>::run(p, dt, steps, tolerance, trajectory);
    case PROBLEM_PROJECTILE_QUADRATIC_DRAG:
        return reference_system<projectile_quadratic_drag>::run(p, dt, steps, tolerance, trajectory);
    default: return TRADEOFF_UNSUPPORTED;
    }
}
