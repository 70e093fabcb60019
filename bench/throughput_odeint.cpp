// throughput_odeint.cpp - Boost.Odeint on the gravity scene of bench/throughput: symplectic_euler (order 1,
// the peer of motus's semi-implicit Euler), velocity_verlet (order 2, the peer of motus's velocity_verlet)
// and runge_kutta4 (the peer of motus's rk4), in float or double.
//
// The state is the one motus steps, in the form odeint's documentation shows for its symplectic steppers:
// coordinates and momenta as two std::vector<T> (unit mass: the momentum is the velocity), one component
// after the other (x[0..N), y[0..N) (, z[0..N))), the same order as motus's arrays. The system is the one
// function dp/dt = f(q) = g, written as a user of odeint writes it. Gravity + damping is not a conservative
// system and cannot be given to these steppers, so the comparison is on gravity alone. runge_kutta4 takes the
// first-order form y' = f(y) over one vector y = (x, v) (positions then velocities, one component after the
// other), as its documentation shows.
//
// Note that odeint's symplectic_euler moves the position first (q += p*dt, then p += f(q)*dt), motus's
// semi-implicit Euler the velocity first; both are the first-order symplectic Euler, with the same work.
#include "throughput.h"

#include <boost/numeric/odeint.hpp>

#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

#if defined(__GNUC__) && !defined(__clang__)
#define KERNEL __attribute__((noipa))
#elif defined(__clang__)
#define KERNEL __attribute__((noinline))
#else
#define KERNEL
#endif

namespace {

namespace odeint = boost::numeric::odeint;

template <class T> struct gravity_momentum { // dp/dt = g for every particle
    T g[3];
    int dims;
    std::size_t n;
    void operator()(const std::vector<T> &, std::vector<T> &dpdt) const {
        for (int d = 0; d < dims; ++d) {
            const T gd = g[d];
            for (std::size_t i = 0; i < n; ++i) dpdt[d * n + i] = gd;
        }
    }
};
template <class T> struct gravity_acceleration { // a(x, v, t) = g, velocity_verlet's form
    T g[3];
    int dims;
    std::size_t n;
    void operator()(const std::vector<T> &, const std::vector<T> &, std::vector<T> &a, T) const {
        for (int d = 0; d < dims; ++d) {
            const T gd = g[d];
            for (std::size_t i = 0; i < n; ++i) a[d * n + i] = gd;
        }
    }
};

template <class T> struct gravity_first_order { // y = (x, v): x' = v, v' = g
    T g[3];
    int dims;
    std::size_t n;
    void operator()(const std::vector<T> &y, std::vector<T> &dydt, T) const {
        const std::size_t half = (std::size_t)dims * n;
        for (std::size_t i = 0; i < half; ++i) dydt[i] = y[half + i];
        for (int d = 0; d < dims; ++d) {
            const T gd = g[d];
            for (std::size_t i = 0; i < n; ++i) dydt[half + d * n + i] = gd;
        }
    }
};

template <class T> struct odeint_work {
    typedef std::vector<T> state;
    int dims;
    std::size_t n;
    T dt;
    state q, p; // coordinates and momenta (velocities): both symplectic steppers step these
    state y;    // runge_kutta4's (x, v), allocated on its first reset
    gravity_momentum<T> momentum;
    gravity_acceleration<T> acceleration;
    gravity_first_order<T> first_order;
    odeint::symplectic_euler<state, state, T> euler;
    odeint::velocity_verlet<state, state, T> verlet;
    odeint::runge_kutta4<state, T> rk4;

    odeint_work(int dims_, std::size_t n_) : dims(dims_), n(n_), dt(T(THROUGHPUT_DT)) {
        const T g[3] = {T(THROUGHPUT_GX), T(THROUGHPUT_GY), T(THROUGHPUT_GZ)};
        for (int d = 0; d < 3; ++d) momentum.g[d] = acceleration.g[d] = first_order.g[d] = g[d];
        momentum.dims = acceleration.dims = first_order.dims = dims;
        momentum.n = acceleration.n = first_order.n = n;
        q.resize(dims * n), p.resize(dims * n);
    }
    void reset(int method) {
        if (method == THROUGHPUT_ODEINT_RUNGE_KUTTA4) {
            const std::size_t half = (std::size_t)dims * n;
            y.resize(2 * half);
            for (int d = 0; d < dims; ++d)
                for (std::size_t i = 0; i < n; ++i) {
                    y[d * n + i] = T(throughput_start((long)i, d));
                    y[half + d * n + i] = T(throughput_start((long)i, 3 + d));
                }
            return;
        }
        for (int d = 0; d < dims; ++d)
            for (std::size_t i = 0; i < n; ++i) {
                q[d * n + i] = T(throughput_start((long)i, d));
                p[d * n + i] = T(throughput_start((long)i, 3 + d));
            }
        if (method == THROUGHPUT_ODEINT_VELOCITY_VERLET) verlet.reset(); // a(x_0) again on the next step
    }
};

// One step each, never inlined into the repetition loop (see throughput_kernels.c).
template <class T> KERNEL void euler_step(odeint_work<T> &w) { w.euler.do_step(w.momentum, w.q, w.p, T(0), w.dt); }
template <class T> KERNEL void rk4_step(odeint_work<T> &w) { w.rk4.do_step(w.first_order, w.y, T(0), w.dt); }
template <class T> KERNEL void verlet_step(odeint_work<T> &w) {
    w.verlet.do_step(w.acceleration, std::make_pair(std::ref(w.q), std::ref(w.p)), T(0), w.dt);
}

struct any_work {
    bool single;
    odeint_work<float> *f;
    odeint_work<double> *d;
};

template <class T> int run(odeint_work<T> &w, int method, int steps) {
    if (method == THROUGHPUT_ODEINT_SYMPLECTIC_EULER)
        for (int s = 0; s < steps; ++s) euler_step(w);
    else if (method == THROUGHPUT_ODEINT_VELOCITY_VERLET)
        for (int s = 0; s < steps; ++s) verlet_step(w);
    else if (method == THROUGHPUT_ODEINT_RUNGE_KUTTA4)
        for (int s = 0; s < steps; ++s) rk4_step(w);
    else
        return 1;
    return 0;
}
template <class T> void read(const odeint_work<T> &w, int method, int i, double *out) {
    if (method == THROUGHPUT_ODEINT_RUNGE_KUTTA4) {
        const std::size_t half = (std::size_t)w.dims * w.n;
        for (int d = 0; d < w.dims; ++d) {
            out[d] = w.y[d * w.n + i];
            out[w.dims + d] = w.y[half + d * w.n + i];
        }
        return;
    }
    for (int d = 0; d < w.dims; ++d) {
        out[d] = w.q[d * w.n + i];
        out[w.dims + d] = w.p[d * w.n + i];
    }
}
template <class T> long subnormals(const odeint_work<T> &w, int method) {
    long found = 0;
    if (method == THROUGHPUT_ODEINT_RUNGE_KUTTA4) {
        for (std::size_t i = 0; i < w.y.size(); ++i) found += std::fpclassify(w.y[i]) == FP_SUBNORMAL;
        return found;
    }
    for (std::size_t i = 0; i < w.q.size(); ++i)
        found += (std::fpclassify(w.q[i]) == FP_SUBNORMAL) + (std::fpclassify(w.p[i]) == FP_SUBNORMAL);
    return found;
}

} // namespace

void *throughput_odeint_open(int dims, int n, int single_precision) {
    any_work *w = new any_work();
    w->single = single_precision != 0;
    w->f = nullptr;
    w->d = nullptr;
    try {
        if (w->single) w->f = new odeint_work<float>(dims, (std::size_t)n);
        else w->d = new odeint_work<double>(dims, (std::size_t)n);
    } catch (...) {
        delete w;
        return nullptr;
    }
    return w;
}
void throughput_odeint_close(void *work) {
    any_work *w = static_cast<any_work *>(work);
    if (!w) return;
    delete w->f;
    delete w->d;
    delete w;
}
void throughput_odeint_reset(void *work, int method) {
    any_work *w = static_cast<any_work *>(work);
    if (w->single) w->f->reset(method);
    else w->d->reset(method);
}
int throughput_odeint_run(void *work, int method, int steps) {
    any_work *w = static_cast<any_work *>(work);
    return w->single ? run(*w->f, method, steps) : run(*w->d, method, steps);
}
void throughput_odeint_read(const void *work, int method, int i, double *out) {
    const any_work *w = static_cast<const any_work *>(work);
    if (w->single) read(*w->f, method, i, out);
    else read(*w->d, method, i, out);
}
long throughput_odeint_subnormals(const void *work, int method) {
    const any_work *w = static_cast<const any_work *>(work);
    return w->single ? subnormals(*w->f, method) : subnormals(*w->d, method);
}
