// collisions.cpp - bench/collisions (issue 12, item 8): balls in a box, motus against what a game programmer
// would pick instead, in the same run and the same scene.
//   collisions [--out DIR] [--quick] [--sizes N,N,...] [--engines a,b,...] [--dims 2,3] [--scenes drop,pile]
//              [--cap S] [--run-cap S] [--run-limit S] [--substeps K] [--iterations K] [--blocks-along-x]
// Engines: motus (4 substeps a frame, or --substeps K; 4 iterations, or --iterations K), motus-1substep (motus
// at one step of dt a frame, the work a peer does a frame), motus-1x1 (one substep and one iteration: motus's
// lightest setting), box2d, chipmunk (2D), bullet (3D), brute (N <= 10^4).
// Scenes (collisions.h: every engine gets the same start, as doubles):
//   drop  N balls of radius r = 0.5 m on a jittered grid of spacing 2.2 r above the floor of a box open at the
//         top, each with a random velocity in [-1, 1] m/s per component (the same seed for every engine), fall
//         under g = 9.81 m/s^2: the lower rows land at once, the rest collide on the way down. Measured over
//         the first F(N) frames (F = 120, 60, 20, 6 at N = 10^3 .. 10^6: at 10^6 mostly the free fall above the
//         lowest rows, which flatters the largest N).
//   pile  the state a drop settles to, built directly: the N balls packed and touching, at rest on the floor
//         (hexagonal rows in 2D; hexagonal layers stacked A-B in 3D), then W(N) frames of warm-up (contacts
//         found, Box2D's and Bullet's warm starting filled) and M(N) measured frames. Settling 10^6 balls from a
//         drop would take the peers hours; a packed pile is the same load for every engine.
//   The box: 2D [0, W] x [0, +Inf), W = ceil(sqrt(2N)) diameters, so the pile is about half as high as wide;
//   3D [0, L] x [0, +Inf) x [0, L], L = ceil(cbrt(2N)) diameters. dt = 1/60 s, one engine call a frame.
// Measured per engine and N: the median wall time of the measured steps; the largest overlap (ball-ball or
// ball-wall, as a fraction of r) over every measured frame, found with a hash grid outside the timed step;
// kinetic energy / initial potential energy (above the resting height r) after the last frame.
// A peer is skipped at a size where one step takes more than --cap seconds (2): predicted linearly from the size
// below, or measured (the median of its steps after the first past one cap, or one step past two; the first,
// which finds every pair from scratch, may take 5). motus runs at every size; where its steps take more than
// 10 caps it stops there and reports the steps it made. A run stops early after --run-cap seconds (40) of
// stepping. Each run is a child process, killed (and reported skipped) after --run-limit seconds (150): a step
// that does not end costs that run only.
// 2 threads (issue 12, item 8: at least 1.6x one thread at N = 10^5): wherever N = 10^5 is among the sizes,
// motus runs twice more right after its row (motus_step on the calling thread, no parallel_for), with
// scene.parallel_for = motus_pool_for of tests/support/motus_pool.h, a pool of 1 thread and then of 2 (the
// CSV's threads column says 1 and 2, its note "parallel_for"), on the same start for the same frames. With
// parallel_for set the solver works in slabs (other bits than without, the same on any number of threads):
// the final positions and velocities of the 1- and 2-thread pool runs are compared bit for bit, and the report
// gives the speed-up of 2 threads over motus_step without parallel_for and over the 1-thread pool, the largest
// overlaps of both solvers, and how busy the machine was. The pool rows are in the tables and the CSV, not in
// the figure.
// --quick: N = 300 and 2000, a few frames: a smoke run in seconds (ctest bench.collisions_quick_run).
// --blocks-along-x: each start's balls stored in blocks 4.5 m wide along x (the same balls, another order in
// memory), so that the slabs of motus's 2 threads share no cache line (see the README's On 2 threads).
// Writes DIR/collisions.csv, DIR/collisions.md (also printed on stdout), DIR/plot/*.dat and DIR/plot/info.gp
// for bench/plot_collisions.gp; progress goes to stderr. scripts/collisions.sh runs it and draws the figure.
#include "collisions.h"

#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

struct options {
    std::string out = "collisions-out";
    bool quick = false;
    std::vector<int> sizes;
    std::vector<std::string> engines, scenes = {"drop", "pile"};
    std::vector<int> dims = {2, 3};
    double cap = 2.0, run_cap = 40.0, run_limit = 150.0;
    int substeps = 4; // motus's and the brute-force loop's substeps a frame (the peers take one step a frame)
    int iterations = 0; // motus's and the brute-force loop's solver sweeps a substep (0: motus's default, 4)
    bool blocks = false; // --blocks-along-x: the start's particles stored in blocks along x (see make_start)
};

struct frames {
    int warm, measured;
};

frames frames_for(const std::string &scene, int n, bool quick) {
    if (quick) return scene == "drop" ? frames{0, 10} : frames{3, 5};
    if (scene == "drop") return frames{0, n <= 1000 ? 120 : n <= 10000 ? 60 : n <= 100000 ? 20 : 6};
    return n <= 1000 ? frames{30, 60} : n <= 10000 ? frames{30, 30} : n <= 100000 ? frames{10, 15} : frames{3, 4};
}

// ---- the scenes -------------------------------------------------------------------------------------------
struct start {
    cb_scene scene{};
    std::vector<double> x[3], v[3];
    double pe0 = 0;
};

uint64_t splitmix(uint64_t &s) {
    uint64_t z = (s += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}
double uniform(uint64_t &s, double lo, double hi) { return lo + (hi - lo) * (double)(splitmix(s) >> 11) / 9007199254740992.0; }

void make_start(start &st, int dims, const std::string &scene, int n, int substeps, int iterations, bool blocks) {
    const double r = 0.5;
    cb_scene &s = st.scene;
    s = cb_scene{};
    s.dims = dims;
    s.n = n;
    s.r = r;
    s.g = 9.81;
    s.dt = 1.0 / 60;
    s.substeps = substeps;
    s.iterations = iterations;
    const int k = dims == 2 ? (int)std::ceil(std::sqrt(2.0 * n)) : (int)std::ceil(std::cbrt(2.0 * n));
    const double side = 2 * r * k;
    s.box_min[0] = s.box_min[1] = s.box_min[2] = 0;
    s.box_max[0] = side;
    s.box_max[1] = INFINITY;
    s.box_max[2] = dims == 3 ? side : 0;
    for (int c = 0; c < 3; ++c) {
        st.x[c].assign(c < dims ? (size_t)n : 0, 0.0);
        st.v[c].assign(c < dims ? (size_t)n : 0, 0.0);
    }
    int placed = 0;
    // Places ball `at`; the loops count with `placed += put(...)`, in sight of their conditions.
    auto put = [&](int at, double x, double y, double z) {
        st.x[0][at] = x;
        st.x[1][at] = y;
        if (dims == 3) st.x[2][at] = z;
        return 1;
    };
    const double eps = 1e-9 * side;
    if (scene == "pile") {
        const double row = std::sqrt(3.0) * r, layer = std::sqrt(8.0 / 3.0) * r;
        if (dims == 2) {
            for (int j = 0; placed < n; ++j)
                for (double x = j % 2 ? 2 * r : r; x <= side - r + eps && placed < n; x += 2 * r)
                    placed += put(placed, x, r + j * row, 0);
        } else {
            for (int l = 0; placed < n; ++l) {
                const double ox = l % 2 ? r : 0, oz = l % 2 ? row / 3 : 0;
                for (int j = 0; r + oz + j * row <= side - r + eps && placed < n; ++j) {
                    const double x0 = r + std::fmod((j % 2 ? r : 0) + ox, 2 * r);
                    for (double x = x0; x <= side - r + eps && placed < n; x += 2 * r)
                        placed += put(placed, x, r + l * layer, r + oz + j * row);
                }
            }
        }
    } else {
        uint64_t seed = 0x5eed0000u + (uint64_t)n * 7 + (uint64_t)dims;
        const double spacing = 2.2 * r, jitter = 0.04 * r, first = r + 0.05 * r;
        const int across = (int)std::floor((side - 2 * first) / spacing) + 1;
        for (int j = 0; placed < n; ++j)
            for (int a = 0; a < (dims == 3 ? across : 1) && placed < n; ++a)
                for (int i = 0; i < across && placed < n; ++i) {
                    // Drawn one statement at a time (the order of a call's arguments is up to the compiler:
                    // g++ drew them z first, clang x first), z, y, x: g++'s order, the published starts.
                    const double jz = uniform(seed, -jitter, jitter), jy = uniform(seed, -jitter, jitter),
                                 jx = uniform(seed, -jitter, jitter);
                    placed += put(placed, first + i * spacing + jx, first + j * spacing + jy, first + a * spacing + jz);
                }
        for (int c = 0; c < dims; ++c)
            for (int i = 0; i < n; ++i) st.v[c][i] = uniform(seed, -1, 1);
    }
    if (blocks) {
        // The same balls stored in blocks 4.5 m wide along x (about one of motus's slabs, 4 cells of 1.125 m),
        // in their order within a block: a memory layout in which the 2 threads' slabs share no cache line.
        std::vector<int> order(n);
        for (int i = 0; i < n; ++i) order[i] = i;
        std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
            return std::floor(st.x[0][a] / 4.5) < std::floor(st.x[0][b] / 4.5);
        });
        for (int c = 0; c < dims; ++c) {
            std::vector<double> x(n), v(n);
            for (int i = 0; i < n; ++i) x[i] = st.x[c][order[i]], v[i] = st.v[c][order[i]];
            st.x[c].swap(x);
            st.v[c].swap(v);
        }
    }
    st.pe0 = 0;
    for (int i = 0; i < n; ++i) st.pe0 += s.g * (st.x[1][i] - (s.box_min[1] + r));
    for (int c = 0; c < 3; ++c) {
        s.x[c] = c < dims ? st.x[c].data() : nullptr;
        s.v[c] = c < dims ? st.v[c].data() : nullptr;
    }
}

// ---- what the balls did -----------------------------------------------------------------------------------
struct overlap_grid {
    std::vector<uint32_t> key, start, order;
};

uint32_t cell_hash(int64_t ix, int64_t iy, int64_t iz, uint32_t mask) {
    return (uint32_t)(((uint64_t)ix * 73856093u) ^ ((uint64_t)iy * 19349663u) ^ ((uint64_t)iz * 83492791u)) & mask;
}

struct overlap_result {
    double largest = 0; // fraction of r, ball-ball or ball-wall
    int escaped = 0;    // outside the box by more than r, or not finite
};

// The largest overlap, found with a hash grid of cells one diameter wide (a hash collision only adds
// distance tests). Not timed.
overlap_result measure_overlap(const cb_scene &s, double *const x[3], overlap_grid &g) {
    overlap_result out;
    const int n = s.n, dims = s.dims;
    const double r = s.r, cell = 2 * r;
    uint32_t buckets = 1;
    while (buckets < 2u * (uint32_t)n) buckets <<= 1;
    const uint32_t mask = buckets - 1;
    g.key.assign((size_t)n, UINT32_MAX);
    g.start.assign((size_t)buckets + 1, 0);
    g.order.assign((size_t)n, 0);
    std::vector<int64_t> ci((size_t)n * 3);
    for (int i = 0; i < n; ++i) {
        bool finite = true;
        for (int c = 0; c < dims; ++c) finite = finite && std::isfinite(x[c][i]);
        bool outside = !finite;
        for (int c = 0; c < dims && finite; ++c) {
            if (x[c][i] < s.box_min[c] - r || x[c][i] > s.box_max[c] + r) outside = true;
            out.largest = std::max(out.largest, (s.box_min[c] + r - x[c][i]) / r);
            if (std::isfinite(s.box_max[c])) out.largest = std::max(out.largest, (x[c][i] - (s.box_max[c] - r)) / r);
        }
        if (outside) {
            ++out.escaped;
            continue;
        }
        for (int c = 0; c < 3; ++c) ci[3 * i + c] = c < dims ? (int64_t)std::floor(x[c][i] / cell) : 0;
        g.key[i] = cell_hash(ci[3 * i], ci[3 * i + 1], ci[3 * i + 2], mask);
        ++g.start[g.key[i] + 1];
    }
    for (uint32_t b = 0; b < buckets; ++b) g.start[b + 1] += g.start[b];
    {
        std::vector<uint32_t> fill(g.start.begin(), g.start.end() - 1);
        for (int i = 0; i < n; ++i)
            if (g.key[i] != UINT32_MAX) g.order[fill[g.key[i]]++] = (uint32_t)i;
    }
    double deepest = 0; // 2r - distance, largest
    const int reach_z = dims == 3 ? 1 : 0;
    for (int i = 0; i < n; ++i) {
        if (g.key[i] == UINT32_MAX) continue;
        uint32_t seen[27];
        int seen_count = 0;
        for (int dz = -reach_z; dz <= reach_z; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const uint32_t b = cell_hash(ci[3 * i] + dx, ci[3 * i + 1] + dy, ci[3 * i + 2] + dz, mask);
                    if (std::find(seen, seen + seen_count, b) != seen + seen_count) continue;
                    seen[seen_count++] = b;
                    for (uint32_t k = g.start[b]; k < g.start[b + 1]; ++k) {
                        const uint32_t j = g.order[k];
                        if ((int)j <= i) continue;
                        double d2 = 0;
                        for (int c = 0; c < dims; ++c) d2 += (x[c][j] - x[c][i]) * (x[c][j] - x[c][i]);
                        if (d2 < cell * cell) deepest = std::max(deepest, cell - std::sqrt(d2));
                    }
                }
    }
    out.largest = std::max(out.largest, deepest / r);
    return out;
}

double kinetic(const cb_scene &s, double *const v[3]) {
    double e = 0;
    for (int c = 0; c < s.dims; ++c)
        for (int i = 0; i < s.n; ++i) e += 0.5 * v[c][i] * v[c][i];
    return e;
}

// ---- runs -------------------------------------------------------------------------------------------------
struct row {
    std::string engine, scene;
    int dims = 0, n = 0, threads = 1;
    bool pool = false; // motus with scene.parallel_for (a pool of `threads`)
    double ms = NAN, overlap = NAN, ke = NAN;
    std::string note;
    int frames_done = 0;       // engine calls made, warm-up included
    std::vector<double> state; // asked for (keep_state): the final x[0..dims) then v[0..dims), as read
    bool skipped() const { return std::isnan(ms); }
};

// The 2-thread run of motus at one scene, against its 1-thread run.
struct thread_check {
    int dims = 0;
    std::string scene;
    std::string state; // the final states compared: "same bits", "**different bits** ...", "not compared ..."
    double others = NAN; // CPUs other processes used on average during the two runs
};

double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

std::string fmt(const char *format, double value) {
    char b[64];
    std::snprintf(b, sizeof b, format, value);
    return b;
}

std::string size_name(int n) {
    int e = 0;
    int m = n;
    while (m >= 10 && m % 10 == 0) {
        m /= 10;
        ++e;
    }
    if (m == 1 && e >= 3) return "10^" + std::to_string(e);
    return std::to_string(n);
}

// threads: cb_scene.threads (motus only: 0, no parallel_for; k, a pool of k); keep_state: the final state into
// out.state.
row run(const cb_engine &e, const start &st, const std::string &scene, const options &o, const row *smaller,
        int threads, bool keep_state) {
    cb_scene s = st.scene;
    s.threads = threads;
    row out;
    out.engine = e.name;
    out.scene = scene;
    out.dims = s.dims;
    out.n = s.n;
    out.threads = threads > 0 ? threads : 1;
    out.pool = threads > 0;
    if (e.max_n && s.n > e.max_n) {
        out.note = "skipped: O(N^2), run up to N = " + size_name(e.max_n);
        return out;
    }
    if (smaller && smaller->skipped()) {
        out.note = "skipped: skipped at N = " + size_name(smaller->n);
        return out;
    }
    // motus is what is measured (also at 1 substep): it runs at every size unless a step takes longer than 10
    // caps; a peer is skipped where its step would take longer than one cap (its own measured time at the size
    // below, scaled linearly) or does.
    const bool subject = std::string(e.name).rfind("motus", 0) == 0;
    const double cap = subject ? 10 * o.cap : o.cap;
    if (!subject && smaller && smaller->ms * 1e-3 * s.n / smaller->n > cap) {
        out.note = "skipped: predicted " + fmt("%.1f", smaller->ms * 1e-3 * s.n / smaller->n) + " s a step";
        return out;
    }
    const frames f = frames_for(scene, s.n, o.quick);
    const double setup_start = now();
    void *world = e.create(&s);
    const double setup = now() - setup_start;
    if (!world) {
        out.note = "failed: could not create the world";
        return out;
    }
    std::vector<double> xs[3], vs[3];
    double *x[3] = {nullptr, nullptr, nullptr}, *v[3] = {nullptr, nullptr, nullptr};
    for (int c = 0; c < s.dims; ++c) {
        xs[c].assign((size_t)s.n, 0.0);
        vs[c].assign((size_t)s.n, 0.0);
        x[c] = xs[c].data();
        v[c] = vs[c].data();
    }
    overlap_grid grid;
    std::vector<double> times, later;
    double stepping = 0, largest = 0;
    int escaped = 0, done = 0;
    bool failed = false, too_slow = false, stopped = false;
    for (int frame = 0; frame < f.warm + f.measured; ++frame) {
        const double t0 = now();
        if (e.step(world)) {
            failed = true;
            break;
        }
        const double t = now() - t0;
        stepping += t;
        ++done;
        // Too slow: the first step (which also finds every pair from scratch: Bullet 3 s at 10^5, then about
        // 1.5 s a step) past 5 caps, any later one past 2 caps, or the median of the later ones past one cap
        // after three of them (one slow step on a busy machine does not skip a peer).
        if (done > 1) later.push_back(t);
        std::vector<double> sorted_later(later);
        std::sort(sorted_later.begin(), sorted_later.end());
        if (t > (done == 1 ? 5 * cap : 2 * cap) || (sorted_later.size() >= 3 && sorted_later[sorted_later.size() / 2] > cap)) {
            too_slow = true;
            times.push_back(t);
            break;
        }
        if (frame >= f.warm) {
            times.push_back(t);
            e.read(world, x, v);
            const overlap_result ov = measure_overlap(s, x, grid);
            largest = std::max(largest, ov.largest);
            escaped = std::max(escaped, ov.escaped);
        }
        if (stepping > o.run_cap && frame + 1 < f.warm + f.measured && !times.empty()) {
            stopped = true;
            break;
        }
    }
    // motus over its cap: the steps it made are measured (the last one included), the run stops there.
    if (too_slow && subject) {
        e.read(world, x, v);
        const overlap_result ov = measure_overlap(s, x, grid);
        largest = std::max(largest, ov.largest);
        escaped = std::max(escaped, ov.escaped);
    }
    out.frames_done = done;
    if (!failed && (!too_slow || subject)) {
        e.read(world, x, v);
        out.ke = kinetic(s, v) / st.pe0;
        if (keep_state) {
            for (int c = 0; c < s.dims; ++c) out.state.insert(out.state.end(), xs[c].begin(), xs[c].end());
            for (int c = 0; c < s.dims; ++c) out.state.insert(out.state.end(), vs[c].begin(), vs[c].end());
        }
    }
    const double teardown_start = now();
    e.destroy(world);
    const double teardown = now() - teardown_start;
    if (failed) {
        out.note = "failed: the step returned an error at frame " + std::to_string(done);
        return out;
    }
    if (too_slow && !subject) {
        out.note = "skipped: steps of " + fmt("%.1f", times.back()) + " s";
        return out;
    }
    std::sort(times.begin(), times.end());
    const size_t m = times.size();
    out.ms = 1e3 * (m % 2 ? times[m / 2] : 0.5 * (times[m / 2 - 1] + times[m / 2]));
    out.overlap = largest;
    out.note = std::to_string(m) + " frames";
    if (f.warm) out.note += " after " + std::to_string(f.warm);
    if (stopped) out.note += " (stopped early: " + std::to_string(f.measured) + " planned)";
    if (too_slow)
        out.note += " (stopped: steps of " + fmt("%.1f", times.back()) + " s, over " + fmt("%.0f", cap) + " s; " +
                    std::to_string(done) + " of " + std::to_string(f.warm + f.measured) + " frames made)";
    out.note += "; setup " + fmt("%.2g", setup) + " s";
    if (teardown > 1) out.note += ", teardown " + fmt("%.2g", teardown) + " s";
    if (escaped) out.note += "; " + std::to_string(escaped) + " escaped";
    if (scene == "pile" && out.ke > 1) out.note += "; **the pile blew up** (kinetic energy above the start's potential)";
    return out;
}

// Each run in a child process: a step that never returns (a blown-up pile can put every ball in one cell) or
// a crash costs that run only. The child sends the row back through a pipe; past `limit` seconds it is killed.
// The row comes back as text (ms, overlap, KE, frames made, the number of state values, the note), a NUL, then
// the state values as raw doubles (the same machine: no conversion, the bits as read).
row run_isolated(const cb_engine &e, const start &st, const std::string &scene, const options &o, const row *smaller,
                 double limit, int threads, bool keep_state) {
    row out;
    out.engine = e.name;
    out.scene = scene;
    out.dims = st.scene.dims;
    out.n = st.scene.n;
    out.threads = threads > 0 ? threads : 1;
    out.pool = threads > 0;
    int fds[2];
    if (pipe(fds) != 0) return run(e, st, scene, o, smaller, threads, keep_state);
    std::fflush(nullptr);
    const pid_t child = fork();
    if (child < 0) {
        close(fds[0]);
        close(fds[1]);
        return run(e, st, scene, o, smaller, threads, keep_state);
    }
    if (child == 0) {
        close(fds[0]);
        const row r = run(e, st, scene, o, smaller, threads, keep_state);
        char text[1024];
        const int length = std::snprintf(text, sizeof text, "%.17g\n%.17g\n%.17g\n%d\n%zu\n%s", r.ms, r.overlap,
                                         r.ke, r.frames_done, r.state.size(), r.note.c_str());
        auto send = [&](const char *bytes, size_t count) {
            size_t written = 0;
            while (written < count) {
                const ssize_t w = write(fds[1], bytes + written, count - written);
                if (w <= 0) return;
                written += (size_t)w;
            }
        };
        send(text, (size_t)std::min(length, (int)sizeof text - 1));
        send("", 1);
        send((const char *)r.state.data(), sizeof(double) * r.state.size());
        close(fds[1]);
        _exit(0);
    }
    close(fds[1]);
    std::string text;
    const double deadline = now() + limit;
    bool killed = false;
    for (;;) {
        const double left = deadline - now();
        if (left <= 0) {
            kill(child, SIGKILL);
            killed = true;
            break;
        }
        struct pollfd p = {fds[0], POLLIN, 0};
        const int ready = poll(&p, 1, (int)std::min(left * 1000 + 1, 1000.0));
        if (ready < 0 && errno != EINTR) break;
        if (ready <= 0) continue;
        char buffer[1 << 16];
        const ssize_t got = read(fds[0], buffer, sizeof buffer);
        if (got <= 0) break;
        text.append(buffer, (size_t)got);
    }
    close(fds[0]);
    int status = 0;
    waitpid(child, &status, 0);
    if (killed) {
        out.note = "skipped: killed after " + fmt("%.0f", limit) + " s (a step that did not end)";
        return out;
    }
    const size_t head = std::min(text.find('\0'), text.size());
    std::istringstream in(text.substr(0, head));
    std::string ms, overlap, ke, frames_done, values;
    if (!std::getline(in, ms) || !std::getline(in, overlap) || !std::getline(in, ke) || !std::getline(in, frames_done) ||
        !std::getline(in, values)) {
        out.note = "failed: the run ended without a result (" +
                   (WIFSIGNALED(status) ? "signal " + std::to_string(WTERMSIG(status)) : std::string("no output")) + ")";
        return out;
    }
    out.ms = std::strtod(ms.c_str(), nullptr);
    out.overlap = std::strtod(overlap.c_str(), nullptr);
    out.ke = std::strtod(ke.c_str(), nullptr);
    out.frames_done = std::atoi(frames_done.c_str());
    std::getline(in, out.note, '\0');
    const size_t count = (size_t)std::strtoull(values.c_str(), nullptr, 10);
    if (count && text.size() - head - 1 == sizeof(double) * count) {
        out.state.resize(count);
        std::memcpy(out.state.data(), text.data() + head + 1, sizeof(double) * count);
    }
    return out;
}

// ---- machine -----------------------------------------------------------------------------------------------
struct cpu_use {
    double machine = NAN, self = NAN;
};
cpu_use cpu_now() {
    cpu_use c;
    std::ifstream stat("/proc/stat");
    std::string cpu;
    unsigned long long user, nice, system, idle, iowait, irq, softirq, steal;
    if (stat >> cpu >> user >> nice >> system >> idle >> iowait >> irq >> softirq >> steal && cpu == "cpu")
        c.machine = (double)(user + nice + system + irq + softirq + steal) / (double)sysconf(_SC_CLK_TCK);
    // this process and its runs (each run is a child process, counted once it has been waited for)
    struct rusage u, children;
    if (getrusage(RUSAGE_SELF, &u) == 0 && getrusage(RUSAGE_CHILDREN, &children) == 0)
        c.self = u.ru_utime.tv_sec + 1e-6 * u.ru_utime.tv_usec + u.ru_stime.tv_sec + 1e-6 * u.ru_stime.tv_usec +
                 children.ru_utime.tv_sec + 1e-6 * children.ru_utime.tv_usec + children.ru_stime.tv_sec +
                 1e-6 * children.ru_stime.tv_usec;
    return c;
}
std::string first_line(const char *path) {
    std::ifstream f(path);
    std::string line;
    std::getline(f, line);
    return line;
}
std::string cpu_model() {
    std::ifstream f("/proc/cpuinfo");
    std::string line;
    while (std::getline(f, line))
        if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
    return "unknown cpu";
}

// ---- output -------------------------------------------------------------------------------------------------
const row *find(const std::vector<row> &rows, const std::string &engine, int dims, const std::string &scene, int n,
               int threads = 1, bool pool = false) {
    for (const row &r : rows)
        if (r.engine == engine && r.dims == dims && r.scene == scene && r.n == n && r.threads == threads &&
            r.pool == pool)
            return &r;
    return nullptr;
}

// The 2-thread pool's final state against the 1-thread pool's, value by value, exactly (the bits of the doubles read back).
std::string compare_states(const row &one, const row &two) {
    if (one.skipped() || two.skipped()) return "not compared (a run did not finish)";
    if (one.frames_done != two.frames_done)
        return "not compared (" + std::to_string(one.frames_done) + " against " + std::to_string(two.frames_done) +
               " frames)";
    if (one.state.empty() || one.state.size() != two.state.size()) return "not compared (no final state read)";
    size_t differ = 0;
    double largest = 0;
    for (size_t i = 0; i < one.state.size(); ++i)
        if (std::memcmp(&one.state[i], &two.state[i], sizeof(double)) != 0) {
            ++differ;
            const double d = std::fabs(one.state[i] - two.state[i]);
            largest = std::isnan(d) ? d : std::max(largest, d);
        }
    if (!differ) return "same bits";
    return "**different bits**: " + std::to_string(differ) + " of " + std::to_string(one.state.size()) +
           " values, largest difference " + fmt("%.3g", largest);
}

std::string cell_ms(const row &r) { return r.skipped() ? "skipped" : fmt(r.ms < 1 ? "%.3f" : r.ms < 100 ? "%.2f" : "%.0f", r.ms); }

void write_outputs(const options &o, const std::vector<row> &rows, const std::vector<const cb_engine *> &engines,
                   const std::vector<thread_check> &checks, const std::string &machine_note,
                   const std::string &plot_note, bool have_motus) {
    std::ofstream csv(o.out + "/collisions.csv");
    csv << "engine,dims,scene,n,ms_per_step,max_overlap_over_r,ke_over_pe0,threads,note\n";
    for (const row &r : rows) {
        csv << r.engine << "," << r.dims << "," << r.scene << "," << r.n << ",";
        if (!r.skipped()) csv << fmt("%.6g", r.ms);
        csv << ",";
        if (!r.skipped()) csv << fmt("%.4g", r.overlap);
        csv << ",";
        if (!r.skipped() && std::isfinite(r.ke)) csv << fmt("%.4g", r.ke);
        std::string note = r.note;
        std::replace(note.begin(), note.end(), ',', ';');
        csv << "," << r.threads << "," << (r.pool ? "parallel_for; " : "") << note << "\n";
    }

    std::ostringstream md;
    md << "# bench/collisions: balls in a box (issue 12, item 8)\n\n";
    md << "Time per step is the median wall time of one engine call (one frame of 1/60 s); overlap is the largest "
          "ball-ball or ball-wall overlap over the measured frames, as a fraction of the radius r = 0.5 m; "
          "KE/PE0 is the kinetic energy after the last frame over the potential energy of the start above the "
          "resting height. *drop*: a jittered grid with random velocities falling into the box, from the "
          "release; *pile*: the balls packed and at rest on the floor (the state a drop settles to), after a "
          "warm-up. Same start for every engine; restitution 0, friction 0, no sleeping.\n\n";
    md << machine_note << "\n\n";
    for (int dims = 2; dims <= 3; ++dims) {
        md << "## " << dims << "D\n\n";
        md << "| engine | scene | N | ms / step | ns / particle-step | largest overlap / r | KE / PE0 | note |\n";
        md << "|---|---|---:|---:|---:|---:|---:|---|\n";
        for (const char *scene : {"drop", "pile"})
            for (const row &r : rows)
                if (r.dims == dims && r.scene == scene) {
                    const std::string name = r.engine == "motus" ? "**motus**" : r.engine;
                    md << "| " << (r.pool ? name + " (parallel_for, " + std::to_string(r.threads) + " thread" +
                                                  (r.threads > 1 ? "s)" : ")")
                                           : name)
                       << " | " << r.scene
                       << " | " << size_name(r.n) << " | " << cell_ms(r) << " | "
                       << (r.skipped() ? "" : fmt("%.0f", 1e6 * r.ms / r.n)) << " | "
                       << (r.skipped() ? "" : fmt("%.4f", r.overlap)) << " | "
                       << (r.skipped() || !std::isfinite(r.ke) ? "" : fmt("%.3g", r.ke)) << " | " << r.note
                       << " |\n";
                }
        md << "\n";
    }

    md << "## Targets (issue 12, item 8)\n\n";
    if (!have_motus) {
        md << "motus was not measured: this include/motus.h has no motus_contacts yet (bench/CMakeLists.txt builds "
              "the motus adapter once it has). The peers and the brute force ran.\n\n";
    } else {
        md << "At N = 10^4, motus against each peer: speed-up = the peer's time per step / motus's (target: at "
              "least 5x), and the largest overlap (target: motus's no worse).\n\n";
        for (const char *subject : {"motus", "motus-1substep", "motus-1x1"}) {
        if (std::string(subject) != "motus") {
            if (!find(rows, subject, 2, "drop", 10000) && !find(rows, subject, 2, "pile", 10000) &&
                !find(rows, subject, 3, "drop", 10000) && !find(rows, subject, 3, "pile", 10000))
                continue;
            md << (std::string(subject) == "motus-1substep"
                       ? "\nThe same at 1 substep a frame (motus-1substep: one step of dt a frame, the work a peer "
                         "does a frame; motus's default above takes 4):\n\n"
                       : "\nThe same at 1 substep a frame and 1 iteration (motus-1x1: motus's lightest setting; "
                         "a peer's speed-up target holds only where its overlap is no smaller):\n\n");
        }
        md << "| dims | scene | peer | peer ms | " << subject << " ms | speed-up | >= 5x | peer overlap | " << subject
           << " overlap | no worse |\n";
        md << "|---|---|---|---:|---:|---:|:-:|---:|---:|:-:|\n";
        for (int dims = 2; dims <= 3; ++dims)
            for (const char *scene : {"drop", "pile"}) {
                const row *m = find(rows, subject, dims, scene, 10000);
                for (const char *peer : {"box2d", "chipmunk", "bullet", "brute"}) {
                    const row *p = find(rows, peer, dims, scene, 10000);
                    if (!m || !p) continue;
                    if (m->skipped() || p->skipped()) {
                        md << "| " << dims << "D | " << scene << " | " << peer << " | " << cell_ms(*p) << " | "
                           << cell_ms(*m) << " | | | | | |\n";
                        continue;
                    }
                    const double up = p->ms / m->ms;
                    md << "| " << dims << "D | " << scene << " | " << peer << " | " << cell_ms(*p) << " | "
                       << cell_ms(*m) << " | " << fmt("%.2f", up) << "x | "
                       << (std::string(peer) == "brute" ? "(no target)" : up >= 5 ? "yes" : "**no**") << " | "
                       << fmt("%.4f", p->overlap) << " | " << fmt("%.4f", m->overlap) << " | "
                       << (m->overlap <= p->overlap ? "yes" : "**no**") << " |\n";
                }
            }
        }
        md << "\nmotus's time per particle-step from N = 10^4 to 10^6 (target: grows at most 1.5x):\n\n";
        md << "| dims | scene | ns at 10^4 | ns at 10^6 | growth | <= 1.5x |\n|---|---|---:|---:|---:|:-:|\n";
        for (int dims = 2; dims <= 3; ++dims)
            for (const char *scene : {"drop", "pile"}) {
                const row *a = find(rows, "motus", dims, scene, 10000), *b = find(rows, "motus", dims, scene, 1000000);
                if (!a || !b || a->skipped() || b->skipped()) continue;
                const double pa = 1e6 * a->ms / a->n, pb = 1e6 * b->ms / b->n;
                md << "| " << dims << "D | " << scene << " | " << fmt("%.0f", pa) << " | " << fmt("%.0f", pb) << " | "
                   << fmt("%.2f", pb / pa) << "x | " << (pb / pa <= 1.5 ? "yes" : "**no**") << " |\n";
            }
        md << "\n(The drop is measured over fewer frames at larger N, 6 at 10^6: mostly free fall above the lowest "
              "rows, cheaper per ball than the 60 frames at 10^4; the pile is the steadier comparison.)\n";
        md << "\nWhere a peer does better than motus (every size both ran):\n\n";
        int wins = 0;
        for (const row &p : rows) {
            if (p.engine.rfind("motus", 0) == 0 || p.skipped()) continue;
            const row *m = find(rows, "motus", p.dims, p.scene, p.n);
            if (!m || m->skipped()) continue;
            std::string what;
            if (p.ms < m->ms) what += "faster (" + cell_ms(p) + " against " + cell_ms(*m) + " ms a step)";
            if (p.overlap < m->overlap)
                what += (what.empty() ? "" : "; ") + std::string("smaller largest overlap (") + fmt("%.4f", p.overlap) +
                        " against " + fmt("%.4f", m->overlap) + ")";
            if (what.empty()) continue;
            md << "- " << p.engine << ", " << p.dims << "D " << p.scene << ", N = " << size_name(p.n) << ": " << what << "\n";
            ++wins;
        }
        if (!wins) md << "- nowhere\n";
        if (checks.empty()) {
            md << "\n2 threads against 1 at N = 10^5 (target: at least 1.6x): not measured in this run (N = 10^5 was "
                  "not among the sizes).\n\n";
        } else {
            const long cpus = sysconf(_SC_NPROCESSORS_ONLN);
            md << "\n2 threads against 1 at N = 10^5 (target: 2 threads at least 1.6x one thread): motus_step without "
                  "parallel_for (1 thread), then with scene.parallel_for = motus_pool_for of "
                  "tests/support/motus_pool.h, a pool of 1 thread (the calling one) and of 2, each right after the "
                  "other on the same start for the same frames. With parallel_for the solver works in slabs: the "
                  "final positions and velocities of the two pool runs are compared bit for bit (the same by design, "
                  "on any number of threads), and its largest overlap is given beside that of the solver without "
                  "slabs. Speed-up: the time per step without parallel_for / with 2 threads (in brackets: the "
                  "1-thread pool's / the 2 threads'). Others: the CPUs other processes used on average while the "
                  "three runs ran, of the machine's "
               << cpus << ".\n\n";
            md << "| dims | scene | 1 thread ms | pool of 1, ms | 2 threads ms | speed-up | >= 1.6x | 1 and 2 threads | "
                  "largest overlap / r, without slabs, in slabs | others, CPUs |\n";
            md << "|---|---|---:|---:|---:|---:|:-:|---|---|---:|\n";
            bool busy = false;
            for (const thread_check &c : checks) {
                const row *alone = find(rows, "motus", c.dims, c.scene, 100000, 1, false);
                const row *one = find(rows, "motus", c.dims, c.scene, 100000, 1, true);
                const row *two = find(rows, "motus", c.dims, c.scene, 100000, 2, true);
                if (!alone || !one || !two) continue;
                const bool all = !alone->skipped() && !one->skipped() && !two->skipped();
                const double up = all ? alone->ms / two->ms : NAN, up_pool = all ? one->ms / two->ms : NAN;
                md << "| " << c.dims << "D | " << c.scene << " | " << cell_ms(*alone) << " | " << cell_ms(*one) << " | "
                   << cell_ms(*two) << " | " << (all ? fmt("%.2f", up) + "x (" + fmt("%.2f", up_pool) + "x)" : "")
                   << " | " << (all ? (up >= 1.6 ? "yes" : "**no**") : "") << " | " << c.state << " | "
                   << (all ? fmt("%.2g", alone->overlap) + ", " + fmt("%.2g", two->overlap) : "") << " | "
                   << fmt("%.2f", c.others) << " |\n";
                busy = busy || c.others > 0.2;
            }
            if (cpus < 2)
                md << "\nThis machine has " << cpus << " CPU: the second thread has no core of its own, the "
                      "speed-ups say nothing about the target.\n";
            else if (busy)
                md << "\n**The machine was busy during some of these runs** (others above 0.2 CPUs): the second "
                      "thread shares a core with them, so those speed-ups understate what an idle machine gives.\n";
            md << "\n";
        }
    }
    md << "Engines:\n\n";
    for (const cb_engine *e : engines) md << "- " << e->name << ": " << e->describe() << "\n";
    std::ofstream(o.out + "/collisions.md") << md.str();
    std::fputs(md.str().c_str(), stdout);

    // gnuplot: one file per curve (N, ns per particle-step) and the list of curves.
    const std::string plot = o.out + "/plot";
    mkdir(plot.c_str(), 0777);
    std::map<std::string, std::string> lists;
    for (int dims = 2; dims <= 3; ++dims)
        for (const char *scene : {"drop", "pile"})
            for (const cb_engine *e : engines) {
                std::ostringstream dat;
                int points = 0;
                for (const row &r : rows)
                    if (r.engine == e->name && r.dims == dims && r.scene == scene && !r.pool && !r.skipped()) {
                        dat << r.n << " " << fmt("%.6g", 1e6 * r.ms / r.n) << "\n";
                        ++points;
                    }
                if (!points) continue;
                std::ofstream(plot + "/" + std::to_string(dims) + "d_" + scene + "_" + e->name + ".dat") << dat.str();
                std::string &list = lists[std::to_string(dims) + "d_" + scene];
                list += (list.empty() ? "" : " ") + std::string(e->name);
            }
    std::ofstream info(plot + "/info.gp");
    for (const char *key : {"2d_drop", "2d_pile", "3d_drop", "3d_pile"}) info << "curves_" << key << " = \"" << lists[key] << "\"\n";
    info << "machine = \"" << plot_note << "\"\n";
    info << "n_min = " << *std::min_element(o.sizes.begin(), o.sizes.end()) / 2 << "\n";
    info << "n_max = " << *std::max_element(o.sizes.begin(), o.sizes.end()) * 2 << "\n";
}

std::vector<std::string> split(const std::string &s) {
    std::vector<std::string> out;
    std::stringstream ss(s);
    std::string item;
    while (std::getline(ss, item, ','))
        if (!item.empty()) out.push_back(item);
    return out;
}

int usage() {
    std::fprintf(stderr, "usage: collisions [--out DIR] [--quick] [--sizes N,N,...] [--engines a,b,...] [--dims 2,3] "
                         "[--scenes drop,pile] [--cap S] [--run-cap S] [--run-limit S] [--substeps K] "
                         "[--iterations K] [--blocks-along-x]\n");
    return 2;
}

} // namespace

int main(int argc, char **argv) {
    options o;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        const bool has_value = i + 1 < argc;
        if (a == "--out" && has_value) o.out = argv[++i];
        else if (a == "--quick") o.quick = true;
        else if (a == "--sizes" && has_value)
            for (const std::string &n : split(argv[++i])) o.sizes.push_back((int)std::atof(n.c_str()));
        else if (a == "--engines" && has_value) o.engines = split(argv[++i]);
        else if (a == "--scenes" && has_value) o.scenes = split(argv[++i]);
        else if (a == "--dims" && has_value) {
            o.dims.clear();
            for (const std::string &d : split(argv[++i])) o.dims.push_back(std::atoi(d.c_str()));
        }
        else if (a == "--cap" && has_value) o.cap = std::atof(argv[++i]);
        else if (a == "--substeps" && has_value) o.substeps = std::atoi(argv[++i]);
        else if (a == "--iterations" && has_value) o.iterations = std::atoi(argv[++i]);
        else if (a == "--blocks-along-x") o.blocks = true;
        else if (a == "--run-cap" && has_value) o.run_cap = std::atof(argv[++i]);
        else if (a == "--run-limit" && has_value) o.run_limit = std::atof(argv[++i]);
        else return usage();
    }
    if (o.sizes.empty()) o.sizes = o.quick ? std::vector<int>{300, 2000} : std::vector<int>{1000, 10000, 100000, 1000000};
    std::sort(o.sizes.begin(), o.sizes.end());
    if (mkdir(o.out.c_str(), 0777) != 0 && errno != EEXIST) {
        std::fprintf(stderr, "collisions: cannot create %s\n", o.out.c_str());
        return 1;
    }
    std::vector<const cb_engine *> all = {
#ifdef CB_HAVE_MOTUS
        &cb_engine_motus,
        &cb_engine_motus_one_substep,
        &cb_engine_motus_light,
#endif
#ifdef CB_HAVE_BOX2D
        &cb_engine_box2d,
#endif
#ifdef CB_HAVE_CHIPMUNK
        &cb_engine_chipmunk,
#endif
#ifdef CB_HAVE_BULLET
        &cb_engine_bullet,
#endif
        &cb_engine_brute};
    bool have_motus = false;
    std::vector<const cb_engine *> engines;
    for (const cb_engine *e : all)
        if (o.engines.empty() || std::find(o.engines.begin(), o.engines.end(), e->name) != o.engines.end()) {
            engines.push_back(e);
            have_motus = have_motus || std::string(e->name) == "motus";
        }
    std::fprintf(stderr, "collisions: engines");
    for (const cb_engine *e : engines) std::fprintf(stderr, " %s", e->name);
    std::fprintf(stderr, "%s\n", have_motus ? "" : " (no motus: this motus.h has no motus_contacts)");

    // Chipmunk's Debian build prints a banner on stdout from cpSpaceNew: the engines write to stderr while
    // they run, stdout gets the report alone.
    std::fflush(stdout);
    const int report_fd = dup(1);
    dup2(2, 1);
    const std::string load_before = first_line("/proc/loadavg");
    const cpu_use before = cpu_now();
    const double started = now();
    std::vector<row> rows;
    std::vector<thread_check> checks;
    auto progress = [](const row &r) {
        const std::string name = r.pool ? r.engine + "/" + std::to_string(r.threads) + "t" : r.engine;
        std::fprintf(stderr, "collisions: %dD %-4s N = %-7d %-8s %10s ms/step  overlap %-8s  KE/PE0 %-9s %s\n", r.dims,
                     r.scene.c_str(), r.n, name.c_str(), cell_ms(r).c_str(),
                     r.skipped() ? "" : fmt("%.4f", r.overlap).c_str(), std::isfinite(r.ke) ? fmt("%.3g", r.ke).c_str() : "",
                     r.note.c_str());
    };
    for (int dims : o.dims)
        for (const std::string &scene_name : o.scenes)
            for (int n : o.sizes) {
                const char *scene = scene_name.c_str();
                start st;
                make_start(st, dims, scene, n, o.substeps, o.iterations, o.blocks);
                for (const cb_engine *e : engines) {
                    if (!(e->dims_mask & (1 << dims))) continue;
                    const row *smaller = nullptr;
                    for (const row &r : rows)
                        if (r.engine == e->name && r.dims == dims && r.scene == scene && !r.pool) smaller = &r;
                    // motus at 10^5: then again with 2 threads, at once, and the two final states compared.
                    const bool pair = std::string(e->name) == "motus" && n == 100000;
                    const cpu_use pair_before = pair ? cpu_now() : cpu_use{};
                    const double pair_started = now();
                    rows.push_back(run_isolated(*e, st, scene, o, smaller, o.run_limit, 0, false));
                    progress(rows.back());
                    if (!pair) continue;
                    rows.push_back(run_isolated(*e, st, scene, o, smaller, o.run_limit, 1, true));
                    progress(rows.back());
                    rows.push_back(run_isolated(*e, st, scene, o, smaller, o.run_limit, 2, true));
                    progress(rows.back());
                    const cpu_use pair_after = cpu_now();
                    row &alone = rows[rows.size() - 3], &one = rows[rows.size() - 2], &two = rows.back();
                    thread_check c;
                    c.dims = dims;
                    c.scene = scene;
                    c.state = compare_states(one, two);
                    c.others = ((pair_after.machine - pair_before.machine) - (pair_after.self - pair_before.self)) /
                               (now() - pair_started);
                    std::fprintf(stderr, "collisions: %dD %-4s N = %-7d 2 threads against 1: %.2fx (%.2fx against the "
                                 "1-thread pool), final state: %s\n", dims, scene, n, alone.ms / two.ms,
                                 one.ms / two.ms, c.state.c_str());
                    checks.push_back(c);
                    std::vector<double>().swap(one.state);
                    std::vector<double>().swap(two.state);
                }
            }
    const double wall = now() - started;
    const cpu_use after = cpu_now();
    const double others = ((after.machine - before.machine) - (after.self - before.self)) / wall;
    const long cpus = sysconf(_SC_NPROCESSORS_ONLN);
    auto three = [](const std::string &loadavg) {
        std::istringstream in(loadavg);
        std::string a, b, c;
        in >> a >> b >> c;
        return a + " " + b + " " + c;
    };
    std::string note = "Machine: " + cpu_model() + ", " + std::to_string(cpus) +
                       " CPUs; g++ -O2 (the peers: Debian's builds). During the " + fmt("%.0f", wall) +
                       " s of the run other processes used " + fmt("%.2f", others) + " of the " +
                       std::to_string(cpus) + " CPUs on average (load average 1/5/15 min before: " +
                       three(load_before) + "; after: " + three(first_line("/proc/loadavg")) + ").";
    if (others > 0.2) note = "**The machine was busy:** " + note + " Single-threaded times are still comparable run to run only roughly.";
    std::fflush(stdout);
    if (report_fd >= 0) dup2(report_fd, 1);
    const std::string plot_note = cpu_model() + ", " + std::to_string(cpus) + " CPUs, g++ -O2; other processes used " +
                                  fmt("%.2f", others) + " CPUs on average during the run";
    write_outputs(o, rows, engines, checks, note, plot_note, have_motus);
    return 0;
}
