// throughput.cpp - bench/throughput: ns per particle-step of motus_step (every method) against what a
// programmer would write instead, and against the memory bandwidth, for N = 4096 to 10^7 in 2D and 3D, float
// and double; and the textbook per-particle path (motus_particle_* on 5000 particles) against a plain loop.
//
//   throughput [--out DIR] [--sizes N,N,...] [--rounds R] [--seconds S] [--quick]     measure, this build
//              [--scenes S,S,...] [--dims 2|3] [--precision float|double] [--verbose]  (a part, for profiling)
//   throughput --report DIR                                                           tables of every build
//
// Measuring: for every N, dimension count and precision, every method of each scene (throughput.h): motus_step
// with each of the nine methods, the hand-written loop for exactly that scene (semi-implicit Euler), motus
// with walls no particle reaches; on gravity + damping also motus on 2 threads (OpenMP, one parallel region
// per step over motus_step_range), and the memory kernels (copy, triad and the in-place read-modify-write of
// the state: the bound); on gravity Boost.Odeint's symplectic_euler, velocity_verlet and runge_kutta4. At
// N = 5000 (THROUGHPUT_TEXTBOOK_COUNT) only the textbook per-particle path, its hand-written twin and motus.
// Each measurement times `steps` steps (as many as take at least S seconds, default 0.001; at least one),
// each step one call of a non-inlined function, by the CPU time of the thread (so that the time another
// process holds the core is not counted; the 2-thread runs by the wall clock, since a step lasts until its
// slower thread is done, and the thread ratios compare wall clocks on both sides). A scene's methods are
// timed in turn, round after round (default 9 rounds, at most 5 from N = 10^6), so that a slow moment of the machine
// lands on all of them; a round keeps the best of 3 measurements below N = 10^6 (interference only ever adds
// time), and the median over the rounds is reported. The state is reset to the scene's start
// whenever the scene changes and at least every 600 steps, so that no run drifts into subnormal numbers
// (the report counts any it finds). Writes DIR/BUILD.csv, DIR/BUILD.info (machine and flags) and
// DIR/BUILD_verify.csv (whether the methods computed the same thing), where BUILD is the name this binary
// was built with (native: -O3 -march=native; o2: -O2).
//
// Reporting: reads the files of every build found in DIR and writes DIR/throughput.md (also on stdout) with
// the machine, the targets of the issue as measured ratios, and a table of ns per particle-step against N per
// build, dimension count and precision; and DIR/plot/*.dat, the curves bench/plot_throughput.gp draws.
// scripts/throughput.sh builds both binaries, runs them and the report, and draws the figures.
#include "throughput.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <climits>
#include <cstring>
#include <ctime>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/utsname.h>
#ifdef __GLIBC__
#include <malloc.h>
#endif
#include <unistd.h>
#include <vector>

#ifndef THROUGHPUT_BUILD_NAME
#define THROUGHPUT_BUILD_NAME "unnamed"
#endif
#ifndef THROUGHPUT_BUILD_FLAGS
#define THROUGHPUT_BUILD_FLAGS "unknown flags"
#endif
#ifndef THROUGHPUT_HEADER_SHA256
#define THROUGHPUT_HEADER_SHA256 "unknown"
#endif

namespace {

const char *const scene_names[] = {"drift", "gravity", "gravity_damping", "gravity_linear_drag", "mass_forces",
                                   "springs", "attractor", "memory"};
const char *const scene_titles[] = {"drift only", "gravity", "gravity + damping", "gravity + linear drag",
                                    "per-particle mass + user forces", "springs (a chain of N, coupled)",
                                    "attractor (Kepler)", "memory bandwidth"};
const char *const method_names[] = {"motus", "hand", "general", "textbook", "motus_threads", "copy", "triad", "rmw",
                                    "rmw_threads", "odeint_symplectic_euler", "odeint_velocity_verlet",
                                    "odeint_runge_kutta4", "textbook_hand", "motus_explicit_euler",
                                    "motus_position_verlet", "motus_velocity_verlet", "motus_leapfrog",
                                    "motus_midpoint", "motus_rk4", "motus_forest_ruth", "motus_mclachlan4",
                                    "motus_exact_linear_drag", "textbook_engine"};
const char *const method_titles[] = {"motus semi_implicit_euler", "hand-written loop (semi-implicit Euler)",
                                     "motus semi_implicit_euler + walls nobody reaches",
                                     "textbook path: motus_particle_* per particle", "motus, 2 threads (step_range)",
                                     "copy (STREAM)", "triad (STREAM)", "in-place read-modify-write (the bound)",
                                     "in-place read-modify-write, 2 threads", "odeint symplectic_euler",
                                     "odeint velocity_verlet", "odeint runge_kutta4",
                                     "textbook path written by hand (same structs, same math)",
                                     "motus explicit_euler", "motus position_verlet", "motus velocity_verlet",
                                     "motus leapfrog", "motus midpoint", "motus rk4", "motus forest_ruth",
                                     "motus mclachlan4", "motus exact_linear_drag",
                                     "motus_step over the same structs (motus_state_of_particles)"};
const int reset_every = 600; // steps

int method_threads(int method) {
    return method == THROUGHPUT_MOTUS_THREADS || method == THROUGHPUT_RMW_THREADS ? 2 : 1;
}
bool is_odeint(int method) {
    return method == THROUGHPUT_ODEINT_SYMPLECTIC_EULER || method == THROUGHPUT_ODEINT_VELOCITY_VERLET ||
           method == THROUGHPUT_ODEINT_RUNGE_KUTTA4;
}
bool is_textbook(int method) { return throughput_on_structs(method) != 0; }
// Which arrays a method works on: methods of one layout take turns on one state.
int method_layout(int method) {
    switch (method) {
    case THROUGHPUT_TEXTBOOK:
    case THROUGHPUT_TEXTBOOK_HAND:
    case THROUGHPUT_TEXTBOOK_ENGINE: return 1;
    case THROUGHPUT_COPY:
    case THROUGHPUT_TRIAD: return 2;
    case THROUGHPUT_ODEINT_SYMPLECTIC_EULER: return 3;
    case THROUGHPUT_ODEINT_VELOCITY_VERLET: return 4;
    case THROUGHPUT_ODEINT_RUNGE_KUTTA4: return 5;
    default: return 0; // the x[], v[] arrays
    }
}
bool method_any_scene(int method) { // runs on whatever a layout holds
    return method == THROUGHPUT_RMW || method == THROUGHPUT_RMW_THREADS || method_layout(method) == 2;
}

double median(std::vector<double> v) {
    if (v.empty()) return NAN;
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// ---- one state: the C part in one precision, and odeint ------------------------------------------------
struct workset {
    int dims, n;
    bool single;
    void *c = nullptr, *odeint = nullptr;
    int layout_scene[6] = {-1, -1, -1, -1, -1, -1};
    long layout_steps[6] = {0, 0, 0, 0, 0, 0};

    workset(int dims_, int n_, bool single_) : dims(dims_), n(n_), single(single_) {
        c = single ? throughput_open_float(dims, n) : throughput_open_double(dims, n);
        odeint = throughput_odeint_open(dims, n, single);
    }
    ~workset() {
        if (c) (single ? throughput_close_float : throughput_close_double)(c);
        throughput_odeint_close(odeint);
    }
    bool ok() const { return c && odeint; }
    bool supported(int scene, int method) const {
        if (is_odeint(method)) return scene == THROUGHPUT_GRAVITY;
        return (single ? throughput_supported_float : throughput_supported_double)(c, scene, method) != 0;
    }
    void reset(int scene, int method) {
        if (is_odeint(method)) throughput_odeint_reset(odeint, method);
        else (single ? throughput_reset_float : throughput_reset_double)(c, scene, method);
        const int layout = method_layout(method);
        layout_scene[layout] = scene;
        layout_steps[layout] = 0;
        // Layouts that share memory: odeint's two steppers step one pair of vectors.
        const int sharing[6] = {-1, -1, -1, 4, 3, -1};
        if (sharing[layout] >= 0) layout_scene[sharing[layout]] = -1;
    }
    // Ready to run `steps` steps of (scene, method): resets only when the arrays hold another scene or have
    // run long enough since the last reset.
    void prepare(int scene, int method, int steps) {
        const int layout = method_layout(method);
        const bool other = layout_scene[layout] < 0 || (layout_scene[layout] != scene && !method_any_scene(method));
        if (other || layout_steps[layout] + steps > reset_every) reset(method_any_scene(method) && layout_scene[layout] >= 0 ? layout_scene[layout] : scene, method);
        if (!is_odeint(method)) (single ? throughput_configure_float : throughput_configure_double)(c, scene, method);
        layout_steps[layout] += steps;
    }
    int run(int scene, int method, int steps) {
        if (is_odeint(method)) return throughput_odeint_run(odeint, method, steps);
        return (single ? throughput_run_float : throughput_run_double)(c, scene, method, steps);
    }
    void read(int scene, int method, int i, double *out) const {
        if (is_odeint(method)) throughput_odeint_read(odeint, method, i, out);
        else (single ? throughput_read_float : throughput_read_double)(c, scene, method, i, out);
    }
    long subnormals(int scene, int method) const {
        if (is_odeint(method)) return throughput_odeint_subnormals(odeint, method);
        return (single ? throughput_subnormals_float : throughput_subnormals_double)(c, scene, method);
    }
};

int index_of(const char *const *names, int count, const std::string &name) {
    for (int i = 0; i < count; ++i)
        if (name == names[i]) return i;
    return -1;
}

// ---- options ---------------------------------------------------------------------------------------------
struct options {
    std::string out = "throughput-out";
    std::string report; // --report DIR
    std::vector<long> sizes = {4096, THROUGHPUT_TEXTBOOK_COUNT, 100000, 10000000};
    int rounds = 9;
    double seconds = 0.001;
    bool quick = false;
    std::vector<int> scenes;        // --scenes a,b: only these (for profiling); all when empty
    int dims = 0;                   // --dims 2|3; both when 0
    bool verbose = false;           // --verbose: every round's value on stderr
    std::string precision;          // --precision float|double; both when empty
};

[[noreturn]] void usage(const char *message) {
    std::fprintf(stderr,
                 "throughput: %s\nusage: throughput [--out DIR] [--sizes N,N,...] [--rounds R] [--seconds S] [--quick]\n"
                 "                  [--scenes S,S,...] [--dims 2|3] [--precision float|double] [--verbose]\n"
                 "       throughput --report DIR\n",
                 message);
    std::exit(2);
}

options parse(int argc, char **argv) {
    options o;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) usage(("missing value after " + a).c_str());
            return argv[++i];
        };
        if (a == "--out") o.out = value();
        else if (a == "--report") o.report = value();
        else if (a == "--rounds") o.rounds = std::max(1, std::atoi(value().c_str()));
        else if (a == "--seconds") o.seconds = std::max(1e-5, std::atof(value().c_str()));
        else if (a == "--quick") {
            o.quick = true;
            o.sizes = {4096, THROUGHPUT_TEXTBOOK_COUNT};
            o.rounds = 2;
            o.seconds = 0.0002;
        } else if (a == "--sizes") {
            o.sizes.clear();
            std::stringstream ss(value());
            std::string item;
            while (std::getline(ss, item, ','))
                if (!item.empty()) o.sizes.push_back(std::atol(item.c_str()));
            for (long n : o.sizes)
                if (n < 64 || n > 100000000) usage("sizes must be in [64, 1e8]");
        } else if (a == "--scenes") {
            std::stringstream ss(value());
            std::string item;
            while (std::getline(ss, item, ',')) {
                const int scene = index_of(scene_names, THROUGHPUT_SCENE_COUNT + 1, item);
                if (scene < 0) usage(("unknown scene " + item).c_str());
                o.scenes.push_back(scene);
            }
        } else if (a == "--verbose") {
            o.verbose = true;
        } else if (a == "--dims") {
            o.dims = std::atoi(value().c_str());
            if (o.dims != 2 && o.dims != 3) usage("--dims takes 2 or 3");
        } else if (a == "--precision") {
            o.precision = value();
            if (o.precision != "float" && o.precision != "double") usage("--precision takes float or double");
        } else usage(("unknown option " + a).c_str());
    }
    return o;
}

bool make_dir(const std::string &path) { return mkdir(path.c_str(), 0777) == 0 || errno == EEXIST; }

// ---- the machine ---------------------------------------------------------------------------------------
std::string read_line(const std::string &path) {
    std::ifstream in(path);
    std::string s;
    std::getline(in, s);
    return s;
}
std::string cpu_description() {
    std::ifstream in("/proc/cpuinfo");
    std::string line, model = "unknown CPU", family, number;
    while (std::getline(in, line)) {
        auto field = [&](const char *key, std::string &to) {
            if (line.compare(0, std::strlen(key), key) == 0 && to.empty()) {
                size_t colon = line.find(':');
                if (colon != std::string::npos) to = line.substr(colon + 2);
            }
        };
        std::string m;
        field("model name", m);
        if (!m.empty() && model == "unknown CPU") model = m;
        field("cpu family", family);
        field("model\t", number);
    }
    std::string d = model;
    if (!family.empty()) d += " (family " + family + ", model " + number + ")";
    d += ", " + std::to_string(sysconf(_SC_NPROCESSORS_ONLN)) + " logical CPUs";
    return d;
}
std::string cache_description() {
    std::string d;
    for (int i = 0; i < 8; ++i) {
        const std::string base = "/sys/devices/system/cpu/cpu0/cache/index" + std::to_string(i) + "/";
        const std::string level = read_line(base + "level"), type = read_line(base + "type"), size = read_line(base + "size");
        if (level.empty()) break;
        if (type == "Instruction") continue;
        if (!d.empty()) d += ", ";
        d += "L" + level + (type == "Data" ? "d" : "") + " " + size;
    }
    return d.empty() ? "unknown" : d + " (per core where private)";
}

// ---- measuring -----------------------------------------------------------------------------------------
struct result_row {
    std::string build;
    int dims = 0;
    std::string precision;
    int scene = 0, method = 0, threads = 1;
    long n = 0;
    int steps = 0, rounds = 0;
    double ns = NAN, ns_min = NAN, ns_max = NAN, gbps = NAN;
    long subnormals = 0;
    int error = 0;
    double ns_wall = NAN; // the median of the wall-clock values, for comparing 1 thread with 2
    std::vector<double> rounds_ns, rounds_wall; // every round's value
};

// Bytes a step moves per particle, counting each read and each write once (STREAM's convention): x and v
// read and written. The bandwidth the bound kernels reach is reported in these terms.
double state_bytes_per_particle(int dims, bool single) { return 2.0 * 2 * dims * (single ? 4 : 8); }

struct cell {
    int scene, method, steps = 1;
    std::vector<double> ns, ns_wall; // per round: by the thread's CPU time, by the wall clock
    long subnormals = 0;
    int error = 0;
};

// The groups of (scene, method) that take turns, round after round, in the order they are timed. Every
// target compares two members of one group, so that the two are measured back to back in every round.
typedef std::vector<std::pair<int, int> > group;
std::vector<group> groups() {
    const int basic[] = {THROUGHPUT_MOTUS, THROUGHPUT_HAND, THROUGHPUT_GENERAL,
                         THROUGHPUT_MOTUS_EXPLICIT_EULER, THROUGHPUT_MOTUS_POSITION_VERLET,
                         THROUGHPUT_MOTUS_VELOCITY_VERLET, THROUGHPUT_MOTUS_LEAPFROG, THROUGHPUT_MOTUS_MIDPOINT,
                         THROUGHPUT_MOTUS_RK4, THROUGHPUT_MOTUS_FOREST_RUTH, THROUGHPUT_MOTUS_MCLACHLAN4,
                         THROUGHPUT_MOTUS_EXACT_LINEAR_DRAG};
    std::vector<group> all;
    for (int scene : {THROUGHPUT_GRAVITY_DAMPING, THROUGHPUT_DRIFT, THROUGHPUT_GRAVITY, THROUGHPUT_GRAVITY_LINEAR_DRAG,
                      THROUGHPUT_MASS_FORCES, THROUGHPUT_SPRINGS, THROUGHPUT_ATTRACTOR}) {
        group g;
        for (int method : basic) g.push_back({scene, method});
        if (scene == THROUGHPUT_GRAVITY_DAMPING) {
            g.push_back({scene, THROUGHPUT_TEXTBOOK});
            g.push_back({scene, THROUGHPUT_TEXTBOOK_HAND});
            g.push_back({scene, THROUGHPUT_TEXTBOOK_ENGINE});
            g.push_back({scene, THROUGHPUT_MOTUS_THREADS});
            for (int method : {THROUGHPUT_RMW, THROUGHPUT_RMW_THREADS, THROUGHPUT_COPY, THROUGHPUT_TRIAD})
                g.push_back({THROUGHPUT_MEMORY, method}); // rmw adds 0 to the gravity + damping state
        }
        if (scene == THROUGHPUT_GRAVITY) {
            g.push_back({scene, THROUGHPUT_ODEINT_SYMPLECTIC_EULER});
            g.push_back({scene, THROUGHPUT_ODEINT_VELOCITY_VERLET});
            g.push_back({scene, THROUGHPUT_ODEINT_RUNGE_KUTTA4});
        }
        all.push_back(g);
    }
    return all;
}

struct timing {
    double wall, cpu; // seconds
};
timing time_run(workset &w, cell &c, int steps) {
    w.prepare(c.scene, c.method, steps);
    const double wall = throughput_seconds(), cpu = throughput_thread_seconds();
    const int error = w.run(c.scene, c.method, steps);
    const timing t = {throughput_seconds() - wall, throughput_thread_seconds() - cpu};
    if (error && !c.error) c.error = error;
    return t;
}

// Steps per measurement: at least `seconds` of stepping. The first runs are also the warm-up.
void calibrate(workset &w, cell &c, double seconds) {
    int steps = 1;
    double t = time_run(w, c, steps).wall;
    while (t < seconds / 4 && steps < (1 << 22)) {
        steps *= 4;
        t = time_run(w, c, steps).wall;
    }
    c.steps = std::max(1, (int)std::ceil(steps * seconds / std::max(t, 1e-9)));
    if (c.steps < steps && t < seconds) c.steps = steps;
}

void measure(const options &o, std::vector<result_row> &rows) {
    const std::string build = THROUGHPUT_BUILD_NAME;
    for (long n : o.sizes) {
        const double started = throughput_seconds();
        // The largest state first: the smaller ones then reuse its pages (freed memory stays in the process).
        for (int dims = 3; dims >= 2; --dims) {
            for (int single = 0; single <= 1; ++single) {
                if ((o.dims && dims != o.dims) || (!o.precision.empty() && (o.precision == "float") != (single != 0)))
                    continue;
                workset w(dims, (int)n, single != 0);
                if (!w.ok()) {
                    std::fprintf(stderr, "throughput: out of memory for N = %ld, %dD; skipped\n", n, dims);
                    continue;
                }
                const int rounds = n >= 1000000 ? std::min(o.rounds, 3) : o.rounds;
                const int best_of = n >= 1000000 ? 1 : 3;
                for (const group &g : groups()) {
                    std::vector<cell> cells;
                    for (const auto &member : g) {
                        if (!w.supported(member.first, member.second)) continue;
                        if (!o.scenes.empty() && std::find(o.scenes.begin(), o.scenes.end(), member.first) == o.scenes.end())
                            continue;
                        // The textbook path at N = 5000 only, and nothing else there but motus to compare with.
                        if (is_textbook(member.second) != (n == THROUGHPUT_TEXTBOOK_COUNT) &&
                            !(n == THROUGHPUT_TEXTBOOK_COUNT && member.first == THROUGHPUT_GRAVITY_DAMPING &&
                              member.second == THROUGHPUT_MOTUS))
                            continue;
                        cell c;
                        c.scene = member.first;
                        c.method = member.second;
                        cells.push_back(c);
                    }
                    for (cell &c : cells) calibrate(w, c, o.seconds);
                    // From N = 10^6 a round is one run of each cell, and the first cell of a round ran up to 3x
                    // slower than the same kernel later in the round (3D float at 10^7, gravity: motus 3.7 ns in
                    // the first round, 2.5 in the next, right after odeint's runge_kutta4 had freed 0.5 GB;
                    // explicit Euler 1.7 in the same round): one round first that is not recorded, and each
                    // round begins with a run of its first cell that is not recorded either.
                    // And each round starts at another cell, evenly around the group: at 10^7 the cells timed
                    // late in a round ran faster than those timed early (2D float, gravity + damping, native:
                    // from 0.98 ns for semi-implicit Euler, the first, down to 0.86-0.90 for the four-stage
                    // methods and the in-place bound, later; semi-implicit Euler alone: 0.80-0.83), so that a
                    // fixed order made the first cells look slower than the bound they were compared with.
                    const int warm_up = n >= 1000000 ? 1 : 0;
                    for (int round = -warm_up; round < rounds; ++round) {
                        const size_t count = cells.size(),
                                     start = round < 0 ? 0 : (size_t)round * count / (size_t)rounds;
                        if (warm_up && count) (void)time_run(w, cells[start], cells[start].steps);
                        for (size_t turn = 0; turn < count; ++turn) {
                            cell &c = cells[(start + turn) % count];
                            double wall = INFINITY, cpu = INFINITY;
                            for (int k = 0; k < best_of; ++k) {
                                const timing t = time_run(w, c, c.steps);
                                wall = std::min(wall, t.wall), cpu = std::min(cpu, t.cpu);
                            }
                            if (round < 0) continue;
                            const double per = 1e9 / ((double)c.steps * (double)n);
                            c.ns.push_back((method_threads(c.method) > 1 ? wall : cpu) * per);
                            c.ns_wall.push_back(wall * per);
                            if (o.verbose)
                                std::fprintf(stderr, "N %ld %dD %s %s/%s round %d: %.4g ns (wall %.4g)\n", n, dims,
                                             single ? "float" : "double", scene_names[c.scene], method_names[c.method],
                                             round, c.ns.back(), c.ns_wall.back());
                            if (round == rounds - 1) c.subnormals = w.subnormals(c.scene, c.method);
                        }
                    }
                    for (cell &c : cells) {
                        result_row r;
                        r.build = build;
                        r.dims = dims;
                        r.precision = single ? "float" : "double";
                        r.scene = c.scene;
                        r.method = c.method;
                        r.threads = method_threads(c.method);
                        r.n = n;
                        r.steps = c.steps;
                        r.rounds = rounds;
                        r.ns = median(c.ns);
                        r.ns_wall = median(c.ns_wall);
                        r.rounds_ns = c.ns;
                        r.rounds_wall = c.ns_wall;
                        r.ns_min = *std::min_element(c.ns.begin(), c.ns.end());
                        r.ns_max = *std::max_element(c.ns.begin(), c.ns.end());
                        r.gbps = state_bytes_per_particle(dims, single != 0) / r.ns;
                        r.subnormals = c.subnormals;
                        r.error = c.error;
                        rows.push_back(r);
                        if (c.subnormals)
                            std::fprintf(stderr, "throughput: %ld subnormal values after %s / %s at N = %ld (%dD %s)\n",
                                         c.subnormals, scene_names[c.scene], method_names[c.method], n, dims,
                                         single ? "float" : "double");
                        if (c.error)
                            std::fprintf(stderr, "throughput: %s / %s returned error %d at N = %ld\n",
                                         scene_names[c.scene], method_names[c.method], c.error, n);
                    }
                }
            }
        }
        std::fprintf(stderr, "[%s] N = %-9ld every method, 2D and 3D, float and double: %.1f s\n", build.c_str(), n,
                     throughput_seconds() - started);
    }
}

// Every method of a scene against motus after the same steps from the same start, on a size with a partial
// vector at the end: the largest difference relative to the largest value (0 = bit for bit).
struct check_row {
    int dims;
    std::string precision;
    int scene, method;
    double difference;
};
std::vector<check_row> verify() {
    const int n = 1013, steps = 60;
    std::vector<check_row> out;
    for (int dims = 2; dims <= 3; ++dims)
        for (int single = 1; single >= 0; --single) {
            workset w(dims, n, single != 0);
            if (!w.ok()) continue;
            // Against motus (semi-implicit Euler): the hand-written loop, the walls nobody reaches, 2 threads; the
            // textbook path (motus_particle_*) against its hand-written twin (it has walls the scene has not).
            for (int k = 0; k <= THROUGHPUT_SCENE_COUNT; ++k) {
                const bool textbook = k == THROUGHPUT_SCENE_COUNT;
                const int scene = textbook ? THROUGHPUT_GRAVITY_DAMPING : k;
                const int base = textbook ? THROUGHPUT_TEXTBOOK_HAND : THROUGHPUT_MOTUS;
                if (!w.supported(scene, base)) continue;
                std::vector<double> reference(2 * dims * (size_t)n);
                w.reset(scene, base);
                const int error = w.run(scene, base, steps);
                for (int i = 0; i < n; ++i) w.read(scene, base, i, &reference[2 * dims * (size_t)i]);
                const std::vector<int> others = textbook ? std::vector<int>{THROUGHPUT_TEXTBOOK, THROUGHPUT_TEXTBOOK_ENGINE}
                                                         : std::vector<int>{THROUGHPUT_HAND, THROUGHPUT_GENERAL,
                                                                            THROUGHPUT_MOTUS_THREADS};
                for (int method : others) {
                    if (!w.supported(scene, method)) continue;
                    w.reset(scene, method);
                    const int e = w.run(scene, method, steps);
                    double largest = 0, difference = 0, values[6];
                    for (int i = 0; i < n; ++i) {
                        w.read(scene, method, i, values);
                        for (int k = 0; k < 2 * dims; ++k) {
                            const double r = reference[2 * dims * (size_t)i + k];
                            largest = std::max(largest, std::fabs(r));
                            difference = std::max(difference, std::fabs(values[k] - r));
                            if (std::isnan(values[k]) != std::isnan(r)) difference = INFINITY;
                        }
                    }
                    out.push_back({dims, single ? "float" : "double", scene, method,
                                   (error || e) ? NAN : difference / std::max(largest, 1e-300)});
                }
            }
        }
    return out;
}

// The CPU time every process on the machine used, in seconds (all CPUs, from /proc/stat), and this one's.
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
    struct rusage u;
    if (getrusage(RUSAGE_SELF, &u) == 0)
        c.self = u.ru_utime.tv_sec + 1e-6 * u.ru_utime.tv_usec + u.ru_stime.tv_sec + 1e-6 * u.ru_stime.tv_usec;
    return c;
}

void write_info(const std::string &path) {
    std::ofstream f(path);
    struct utsname u;
    uname(&u);
    char date[64];
    const std::time_t now = std::time(nullptr);
    std::strftime(date, sizeof date, "%Y-%m-%d %H:%M", std::localtime(&now));
    std::string thp = read_line("/sys/kernel/mm/transparent_hugepage/enabled");
    f << "build: " << THROUGHPUT_BUILD_NAME << "\n";
    f << "flags: " << THROUGHPUT_BUILD_FLAGS << "\n";
#if defined(__clang__)
    f << "compiler: clang " << __clang_major__ << "." << __clang_minor__ << "." << __clang_patchlevel__ << "\n";
#elif defined(__GNUC__)
    f << "compiler: gcc " << __GNUC__ << "." << __GNUC_MINOR__ << "." << __GNUC_PATCHLEVEL__ << "\n";
#endif
    f << "cpu: " << cpu_description() << "\n";
    f << "caches: " << cache_description() << "\n";
    f << "system: " << u.sysname << " " << u.release << " " << u.machine << ", transparent huge pages " << thp << "\n";
    f << "simd: MOTUS_SIMD_BYTES " << throughput_simd_bytes_float() << " (float) / " << throughput_simd_bytes_double()
      << " (double), 0 = scalar\n";
    const char *spin = std::getenv("GOMP_SPINCOUNT"), *policy = std::getenv("OMP_WAIT_POLICY");
    f << "openmp: " << throughput_openmp() << ", OMP_WAIT_POLICY=" << (policy ? policy : "(unset)")
      << " GOMP_SPINCOUNT=" << (spin ? spin : "(unset)") << "\n";
    f << "header: motus.h sha256 " << THROUGHPUT_HEADER_SHA256 << "\n";
    f << "date: " << date << "\n";
}

int run_measure(const options &o) {
    if (!make_dir(o.out)) {
        std::fprintf(stderr, "throughput: cannot create %s\n", o.out.c_str());
        return 1;
    }
    const std::string build = THROUGHPUT_BUILD_NAME, base = o.out + "/" + build;
    const double started = throughput_seconds();
    write_info(base + ".info");
    std::vector<check_row> checks = verify();
    {
        std::ofstream f(base + "_verify.csv");
        f << "dims,precision,scene,method,relative_difference\n";
        for (const check_row &c : checks)
            f << c.dims << "," << c.precision << "," << scene_names[c.scene] << "," << method_names[c.method] << ","
              << c.difference << "\n";
    }
    std::vector<result_row> rows;
    const cpu_use before = cpu_now();
    const double measuring = throughput_seconds();
    measure(o, rows);
    const cpu_use after = cpu_now();
    const double wall = throughput_seconds() - measuring;
    {
        // How busy the other processes kept the machine: they share the cores, so they slow the 2-thread runs
        // most (a thread that waits for a core makes the whole step wait).
        std::ofstream info(base + ".info", std::ios::app);
        char line[256];
        std::snprintf(line, sizeof line,
                      "load: other processes used %.2f of the %ld CPUs on average during the %.0f s of measurement\n",
                      ((after.machine - before.machine) - (after.self - before.self)) / wall,
                      sysconf(_SC_NPROCESSORS_ONLN), wall);
        info << line;
    }
    std::ofstream f(base + ".csv");
    f << "build,dims,precision,scene,method,threads,n,steps,rounds,ns_median,ns_min,ns_max,gbps,subnormals,error,"
         "ns_wall_median,rounds_ns,rounds_wall\n";
    char line[512];
    auto joined = [](const std::vector<double> &v) {
        std::string s;
        char b[32];
        for (double x : v) {
            std::snprintf(b, sizeof b, "%.6g", x);
            s += (s.empty() ? "" : ";") + std::string(b);
        }
        return s;
    };
    for (const result_row &r : rows) {
        std::snprintf(line, sizeof line, "%s,%d,%s,%s,%s,%d,%ld,%d,%d,%.6g,%.6g,%.6g,%.4g,%ld,%d,%.6g,", r.build.c_str(),
                      r.dims, r.precision.c_str(), scene_names[r.scene], method_names[r.method], r.threads, r.n,
                      r.steps, r.rounds, r.ns, r.ns_min, r.ns_max, r.gbps, r.subnormals, r.error, r.ns_wall);
        f << line << joined(r.rounds_ns) << "," << joined(r.rounds_wall) << "\n";
    }
    std::fprintf(stderr, "[%s] measured in %.0f s: %s.csv\n", build.c_str(), throughput_seconds() - started, base.c_str());
    return f ? 0 : 1;
}

// ---- the report ------------------------------------------------------------------------------------------
struct results {
    std::vector<std::string> builds; // in the order they were found
    std::map<std::string, std::map<std::string, std::string> > info;
    std::vector<result_row> rows;
    std::map<std::string, std::vector<check_row> > checks;

    const result_row *find(const std::string &build, int dims, const std::string &precision, int scene, int method,
                           long n) const {
        for (const result_row &r : rows)
            if (r.build == build && r.dims == dims && r.precision == precision && r.scene == scene &&
                r.method == method && r.n == n)
                return &r;
        return nullptr;
    }
    double ns(const std::string &build, int dims, const std::string &precision, int scene, int method, long n) const {
        const result_row *r = find(build, dims, precision, scene, method, n);
        return r ? r->ns : NAN;
    }
    double wall(const std::string &build, int dims, const std::string &precision, int scene, int method, long n) const {
        const result_row *r = find(build, dims, precision, scene, method, n);
        return r ? r->ns_wall : NAN;
    }
    // a/b: the median over the rounds of the two times of one round (measured back to back), by the reported
    // clock or the wall clock; the ratio of the medians if the rounds do not pair up.
    double ratio(const std::string &build, int dims, const std::string &precision, int scene_a, int method_a,
                 int scene_b, int method_b, long n, bool wall_clock = false) const {
        const result_row *a = find(build, dims, precision, scene_a, method_a, n);
        const result_row *b = find(build, dims, precision, scene_b, method_b, n);
        if (!a || !b) return NAN;
        const std::vector<double> &ra = wall_clock ? a->rounds_wall : a->rounds_ns;
        const std::vector<double> &rb = wall_clock ? b->rounds_wall : b->rounds_ns;
        if (ra.empty() || ra.size() != rb.size()) return wall_clock ? a->ns_wall / b->ns_wall : a->ns / b->ns;
        std::vector<double> r;
        for (size_t i = 0; i < ra.size(); ++i) r.push_back(ra[i] / rb[i]);
        return median(r);
    }
    std::vector<long> sizes(const std::string &build) const {
        std::vector<long> s;
        for (const result_row &r : rows)
            if (r.build == build && std::find(s.begin(), s.end(), r.n) == s.end()) s.push_back(r.n);
        std::sort(s.begin(), s.end());
        return s;
    }
    bool has(const std::string &build) const { return std::find(builds.begin(), builds.end(), build) != builds.end(); }
};

std::vector<std::string> split_csv(const std::string &line) {
    std::vector<std::string> out;
    std::stringstream ss(line);
    std::string item;
    while (std::getline(ss, item, ',')) out.push_back(item);
    return out;
}

bool load(const std::string &dir, const std::string &build, results &res) {
    std::ifstream csv(dir + "/" + build + ".csv");
    if (!csv) return false;
    res.builds.push_back(build);
    std::string line;
    std::getline(csv, line);
    while (std::getline(csv, line)) {
        std::vector<std::string> v = split_csv(line);
        if (v.size() < 18) continue;
        result_row r;
        r.build = v[0];
        r.dims = std::atoi(v[1].c_str());
        r.precision = v[2];
        r.scene = index_of(scene_names, THROUGHPUT_SCENE_COUNT + 1, v[3]);
        r.method = index_of(method_names, THROUGHPUT_METHOD_COUNT, v[4]);
        r.threads = std::atoi(v[5].c_str());
        r.n = std::atol(v[6].c_str());
        r.steps = std::atoi(v[7].c_str());
        r.rounds = std::atoi(v[8].c_str());
        r.ns = std::atof(v[9].c_str());
        r.ns_min = std::atof(v[10].c_str());
        r.ns_max = std::atof(v[11].c_str());
        r.gbps = std::atof(v[12].c_str());
        r.subnormals = std::atol(v[13].c_str());
        r.error = std::atoi(v[14].c_str());
        r.ns_wall = std::atof(v[15].c_str());
        for (int column = 16; column <= 17; ++column) {
            std::stringstream values(v[column]);
            std::string item;
            while (std::getline(values, item, ';'))
                (column == 16 ? r.rounds_ns : r.rounds_wall).push_back(std::atof(item.c_str()));
        }
        if (r.scene >= 0 && r.method >= 0) res.rows.push_back(r);
    }
    std::ifstream info(dir + "/" + build + ".info");
    while (std::getline(info, line)) {
        const size_t colon = line.find(": ");
        if (colon != std::string::npos) res.info[build][line.substr(0, colon)] = line.substr(colon + 2);
    }
    std::ifstream verify(dir + "/" + build + "_verify.csv");
    std::getline(verify, line);
    while (std::getline(verify, line)) {
        std::vector<std::string> v = split_csv(line);
        if (v.size() < 5) continue;
        check_row c{std::atoi(v[0].c_str()), v[1], index_of(scene_names, THROUGHPUT_SCENE_COUNT, v[2]),
                    index_of(method_names, THROUGHPUT_METHOD_COUNT, v[3]), std::atof(v[4].c_str())};
        if (v[4] == "nan" || v[4] == "-nan") c.difference = NAN;
        if (c.scene >= 0 && c.method >= 0) res.checks[build].push_back(c);
    }
    return true;
}

std::string fmt(double v, int digits = 3) {
    if (!std::isfinite(v)) return "–";
    char b[32];
    if (v >= 100) std::snprintf(b, sizeof b, "%.0f", v);
    else std::snprintf(b, sizeof b, "%.*g", digits, v);
    return b;
}
std::string fmt_ratio(double v) {
    if (!std::isfinite(v)) return "–";
    char b[32];
    std::snprintf(b, sizeof b, v >= 10 ? "%.1fx" : "%.2fx", v);
    return b;
}
std::string fmt_n(long n) {
    if (n >= 1000000 && n % 1000000 == 0) return std::to_string(n / 1000000) + "M";
    char b[32];
    const double l = std::log10((double)n);
    if (std::fabs(l - std::round(l)) < 1e-3) std::snprintf(b, sizeof b, "10^%d", (int)std::round(l));
    else if (n >= 1000000) std::snprintf(b, sizeof b, "%.2gM", n / 1e6);
    else if (n >= 10000) std::snprintf(b, sizeof b, "%.3gk", n / 1e3);
    else std::snprintf(b, sizeof b, "%ld", n);
    return b;
}
std::string config_name(int dims, const std::string &precision) { return std::to_string(dims) + "D " + precision; }

struct target_row {
    std::string what, measured, required;
    int met; // 1 met, 0 not met, -1 not measured
    std::string note;
};

void report_targets(std::ostream &md, const results &res) {
    const std::string native = "native", o2 = "o2";
    const long cache_n = 4096, big_n = 10000000, threads_n = 100000;
    std::vector<target_row> targets;
    auto verdict = [](double value, double required, bool at_least) -> int {
        if (!std::isfinite(value)) return -1;
        return at_least ? value >= required : value <= required;
    };
    // 1: the textbook per-particle path (motus_particle_* on an array of motus_particle) against the plain loop
    // doing the same math over the same structs, in each build; and against motus_step on the SoA arrays.
    const long textbook_n = THROUGHPUT_TEXTBOOK_COUNT;
    for (const std::string &build : {o2, native}) {
        if (!res.has(build)) continue;
        for (int dims = 2; dims <= 3; ++dims)
            for (const char *precision : {"float", "double"}) {
                const double ratio = res.ratio(build, dims, precision, THROUGHPUT_GRAVITY_DAMPING, THROUGHPUT_TEXTBOOK,
                                               THROUGHPUT_GRAVITY_DAMPING, THROUGHPUT_TEXTBOOK_HAND, textbook_n);
                const double vs_motus = res.ratio(build, dims, precision, THROUGHPUT_GRAVITY_DAMPING,
                                                  THROUGHPUT_TEXTBOOK, THROUGHPUT_GRAVITY_DAMPING, THROUGHPUT_MOTUS,
                                                  textbook_n);
                const double engine = res.ratio(build, dims, precision, THROUGHPUT_GRAVITY_DAMPING,
                                                THROUGHPUT_TEXTBOOK_ENGINE, THROUGHPUT_GRAVITY_DAMPING,
                                                THROUGHPUT_TEXTBOOK_HAND, textbook_n);
                targets.push_back({"textbook path (motus_particle_clear_forces, _add_force, _step, _damp_per_step, "
                                   "_bounce) / plain loop, N = 5000, " + config_name(dims, precision) + ", " +
                                       res.info.at(build).at("flags"),
                                   fmt_ratio(ratio), "<= 1.5x", verdict(ratio, 1.5, false),
                                   "textbook path / motus_step (SoA, no walls): " + fmt_ratio(vs_motus)});
                targets.push_back({"motus_step over the same structs (motus_state_of_particles, same scene) / plain "
                                   "loop, N = 5000, " + config_name(dims, precision) + ", " +
                                       res.info.at(build).at("flags"),
                                   fmt_ratio(engine), "", -1, "the fast way through a game's own array"});
            }
    }
    // 3: each scene against its hand-written loop; and what walls nobody reaches cost (the kernel for any scene).
    if (res.has(native)) {
        for (long n : {cache_n, big_n}) {
            for (int scene = 0; scene < THROUGHPUT_SCENE_COUNT; ++scene) {
                double worst = 0, walls_cost_low = INFINITY, walls_cost_high = 0;
                std::string worst_at;
                for (int dims = 2; dims <= 3; ++dims)
                    for (const char *precision : {"float", "double"}) {
                        const double mh = res.ratio(native, dims, precision, scene, THROUGHPUT_MOTUS, scene, THROUGHPUT_HAND, n);
                        const double gm = res.ratio(native, dims, precision, scene, THROUGHPUT_GENERAL, scene, THROUGHPUT_MOTUS, n);
                        if (!std::isfinite(mh)) continue;
                        if (mh > worst) worst = mh, worst_at = config_name(dims, precision);
                        if (std::isfinite(gm)) walls_cost_low = std::min(walls_cost_low, gm), walls_cost_high = std::max(walls_cost_high, gm);
                    }
                if (worst == 0) continue;
                targets.push_back({std::string("motus / hand-written, ") + scene_titles[scene] + ", N = " + fmt_n(n) +
                                       " (worst of 2D/3D x float/double)",
                                   fmt_ratio(worst) + " (" + worst_at + ")", "", -1,
                                   "for context; motus + walls nobody reaches / motus: " + fmt_ratio(walls_cost_low) + " to " +
                                       fmt_ratio(walls_cost_high)});
            }
        }
    }
    if (res.has(o2)) { // for context: what gcc -O2 makes of the hand-written loops (no vectorisation in gcc 12)
        double low = INFINITY, high = 0;
        for (int scene = 0; scene < THROUGHPUT_SCENE_COUNT; ++scene)
            for (int dims = 2; dims <= 3; ++dims)
                for (const char *precision : {"float", "double"}) {
                    const double r = res.ratio(o2, dims, precision, scene, THROUGHPUT_MOTUS, scene, THROUGHPUT_HAND, cache_n);
                    if (std::isfinite(r)) low = std::min(low, r), high = std::max(high, r);
                }
        if (high > 0)
            targets.push_back({"motus / hand-written, every scene, N = 4096, -O2 (for context)",
                               fmt_ratio(low) + " to " + fmt_ratio(high), "", -1,
                               "gcc 12 at -O2 leaves plain loops scalar; motus's vector extensions do not need -O3"});
    }
    if (res.has(native)) {
        // 4: the bandwidth bound at 10^7 (issue 11, item 6): every method's uncoupled step (gravity + damping) reads
        // and writes x and v once, the bytes of the in-place bound; each must be within 1.15x of it.
        for (int method : {THROUGHPUT_MOTUS, THROUGHPUT_MOTUS_EXPLICIT_EULER, THROUGHPUT_MOTUS_POSITION_VERLET,
                           THROUGHPUT_MOTUS_VELOCITY_VERLET, THROUGHPUT_MOTUS_LEAPFROG, THROUGHPUT_MOTUS_MIDPOINT,
                           THROUGHPUT_MOTUS_RK4, THROUGHPUT_MOTUS_FOREST_RUTH, THROUGHPUT_MOTUS_MCLACHLAN4,
                           THROUGHPUT_MOTUS_EXACT_LINEAR_DRAG}) {
            double worst = 0;
            std::string worst_at, bounds;
            for (int dims = 2; dims <= 3; ++dims)
                for (const char *precision : {"float", "double"}) {
                    const double over = res.ratio(native, dims, precision, THROUGHPUT_GRAVITY_DAMPING, method,
                                                  THROUGHPUT_MEMORY, THROUGHPUT_RMW, big_n);
                    if (!std::isfinite(over)) continue;
                    if (over > worst) worst = over, worst_at = config_name(dims, precision);
                }
            if (worst == 0) continue;
            targets.push_back({std::string(method_titles[method]) + " / in-place bound, gravity + damping, N = 10^7, "
                                   "1 thread (worst of 2D/3D x float/double)",
                               fmt_ratio(worst) + " (" + worst_at + ")", "<= 1.15x", verdict(worst, 1.15, false),
                               "the bound: an in-place read-modify-write of x and v, one loop"});
        }
        // 5: two threads.
        for (long n : {threads_n, big_n})
            for (int dims = 2; dims <= 3; ++dims)
                for (const char *precision : {"float", "double"}) {
                    // Wall clock on both sides: a 2-thread step lasts until its slower thread is done.
                    const double speedup = res.ratio(native, dims, precision, THROUGHPUT_GRAVITY_DAMPING, THROUGHPUT_MOTUS,
                                                     THROUGHPUT_GRAVITY_DAMPING, THROUGHPUT_MOTUS_THREADS, n, true);
                    const double bound_speedup = res.ratio(native, dims, precision, THROUGHPUT_MEMORY, THROUGHPUT_RMW,
                                                           THROUGHPUT_MEMORY, THROUGHPUT_RMW_THREADS, n, true);
                    const bool official = n == threads_n;
                    targets.push_back({"2 threads / 1 thread, gravity + damping, N = " + fmt_n(n) + ", " +
                                           config_name(dims, precision) + (official ? "" : " (memory-bound: report)"),
                                       fmt_ratio(speedup), official ? ">= 1.80x" : "",
                                       official ? verdict(speedup, 1.8, true) : -1,
                                       "the bound on 2 threads: " + fmt_ratio(bound_speedup) + " over 1"});
                }
        // 6: odeint, each stepper against the motus method that does the same thing (issue 11, item 6): the
        // smallest speed-up over 2D/3D x float/double.
        struct peer_target {
            int peer, mine;
            double speedup;
            const char *what;
        };
        const peer_target peers[] = {
            {THROUGHPUT_ODEINT_SYMPLECTIC_EULER, THROUGHPUT_MOTUS, 2, "odeint symplectic_euler / motus semi_implicit_euler"},
            {THROUGHPUT_ODEINT_VELOCITY_VERLET, THROUGHPUT_MOTUS_VELOCITY_VERLET, 3,
             "odeint velocity_verlet / motus velocity_verlet"},
            {THROUGHPUT_ODEINT_RUNGE_KUTTA4, THROUGHPUT_MOTUS_RK4, 4, "odeint runge_kutta4 / motus rk4"}};
        for (const peer_target &pt : peers)
            for (long n : {cache_n, big_n}) {
                // The ceiling: no step that reads and writes its state once can beat the in-place bound, so
                // peer / bound is the most any such step could show; where it is below the target, the target
                // cannot be met in that configuration by any single-pass step, motus's or a hand-written one.
                double least = INFINITY, most = 0, ceiling_at_least = NAN;
                int configs = 0, configs_allowing = 0;
                std::string least_at;
                for (int dims = 2; dims <= 3; ++dims)
                    for (const char *precision : {"float", "double"}) {
                        const double r = res.ratio(native, dims, precision, THROUGHPUT_GRAVITY, pt.peer, THROUGHPUT_GRAVITY,
                                                   pt.mine, n);
                        const double ceiling = res.ratio(native, dims, precision, THROUGHPUT_GRAVITY, pt.peer,
                                                         THROUGHPUT_MEMORY, THROUGHPUT_RMW, n);
                        if (!std::isfinite(r)) continue;
                        if (r < least) least = r, least_at = config_name(dims, precision), ceiling_at_least = ceiling;
                        most = std::max(most, r);
                        if (std::isfinite(ceiling)) ++configs, configs_allowing += ceiling >= pt.speedup;
                    }
                if (!std::isfinite(least)) continue;
                std::string note = "largest: " + fmt_ratio(most);
                if (configs > 0)
                    note += "; odeint / the in-place bound (the most a single-pass step could show): " +
                            fmt_ratio(ceiling_at_least) + " in " + least_at + ", at least " + fmt_ratio(pt.speedup) +
                            " in " + std::to_string(configs_allowing) + " of " + std::to_string(configs) +
                            " configurations";
                targets.push_back({std::string(pt.what) + ", gravity, N = " + fmt_n(n) + " (least of 2D/3D x float/double)",
                                   fmt_ratio(least) + " (" + least_at + ")", ">= " + fmt_ratio(pt.speedup),
                                   verdict(least, pt.speedup, true), note});
            }
    }
    md << "## Targets\n\nRatios measured in one run on one machine (above): each is the median over the rounds of the "
          "ratio of the two methods' times in the same round, where they ran back to back (a slow moment of the "
          "machine then cancels out). \"native\" is -O3 -march=native, \"o2\" is -O2; every ratio compares two "
          "methods of the same build. The thread ratios compare wall clocks.\n\n";
    for (const std::string &build : res.builds) {
        auto it = res.info.at(build).find("load");
        if (it == res.info.at(build).end()) continue;
        const size_t used = it->second.find("used ");
        const double busy = used == std::string::npos ? 0 : std::atof(it->second.c_str() + used + 5);
        if (busy > 0.2)
            md << "**The machine was busy during the " << build << " run: other processes used " << fmt(busy, 2)
               << " CPUs on average.** They take turns with the bench on the cores, which spreads every "
                  "measurement and hits the 2-thread runs hardest (a step waits for its slower thread). Rerun "
                  "on an idle machine before trusting those ratios.\n\n";
    }
    md << "| target | measured | required | met | note |\n|---|---|---|---|---|\n";
    for (const target_row &t : targets)
        md << "| " << t.what << " | " << t.measured << " | " << t.required << " | "
           << (t.met < 0 ? (t.required.empty() ? "" : "not measured") : t.met ? "yes" : "**no**") << " | " << t.note << " |\n";
    md << "\n";
}

void report_tables(std::ostream &md, const results &res) {
    for (const std::string &build : res.builds) {
        const std::vector<long> sizes = res.sizes(build);
        for (int dims = 2; dims <= 3; ++dims)
            for (const char *precision : {"float", "double"}) {
                md << "### ns per particle-step, " << config_name(dims, precision) << ", build " << build << " ("
                   << res.info.at(build).at("flags") << ")\n\n| scene | method |";
                for (long n : sizes) md << " " << fmt_n(n) << " |";
                md << "\n|---|---|";
                for (size_t i = 0; i < sizes.size(); ++i) md << "---:|";
                md << "\n";
                for (const group &g : groups()) {
                    for (const auto &member : g) {
                        const int scene = member.first, method = member.second;
                        bool any = false;
                        for (long n : sizes) any |= res.find(build, dims, precision, scene, method, n) != nullptr;
                        if (!any) continue;
                        md << "| " << scene_titles[scene] << " | " << method_titles[method] << " |";
                        for (long n : sizes) {
                            const result_row *r = res.find(build, dims, precision, scene, method, n);
                            md << " " << (r ? fmt(r->ns) : "–") << (r && r->subnormals ? " (subnormal!)" : "")
                               << (r && r->error ? " (error!)" : "") << " |";
                        }
                        md << "\n";
                    }
                }
                md << "| memory | GB/s of the in-place bound (" << fmt(state_bytes_per_particle(dims, std::string(precision) == "float"))
                   << " B per particle-step) |";
                for (long n : sizes) {
                    const result_row *r = res.find(build, dims, precision, THROUGHPUT_MEMORY, THROUGHPUT_RMW, n);
                    md << " " << (r ? fmt(r->gbps) : "–") << " |";
                }
                md << "\n\n";
            }
    }
}

void report_checks(std::ostream &md, const results &res) {
    md << "## Do the methods compute the same thing?\n\nEvery method of a scene (hand-written loop, walls nobody reaches, "
          "textbook loop, 2 threads) against motus after 60 steps of 1013 particles from the same start: the largest "
          "difference relative to the largest value; 0 is bit for bit.\n\n";
    md << "| build | comparisons | bit for bit | the others |\n|---|---|---|---|\n";
    for (const std::string &build : res.builds) {
        auto it = res.checks.find(build);
        if (it == res.checks.end()) continue;
        int same = 0;
        std::string others;
        for (const check_row &c : it->second) {
            if (c.difference == 0) {
                ++same;
                continue;
            }
            others += (others.empty() ? "" : "; ") + config_name(c.dims, c.precision) + " " + scene_titles[c.scene] + ", " +
                      method_titles[c.method] + ": " + (std::isfinite(c.difference) ? fmt(c.difference, 2) : "**failed**");
        }
        md << "| " << build << " | " << it->second.size() << " | " << same << " | " << (others.empty() ? "none" : others)
           << " |\n";
    }
    md << "\n";
}

void write_plot_data(const std::string &dir, const results &res) {
    const std::string plot = dir + "/plot";
    make_dir(plot);
    std::map<std::string, std::vector<const result_row *> > curves;
    for (const result_row &r : res.rows) {
        const std::string name = r.build + "_" + std::to_string(r.dims) + "d_" + r.precision + "_" + scene_names[r.scene] +
                                 "_" + method_names[r.method];
        curves[name].push_back(&r);
    }
    for (auto &curve : curves) {
        std::sort(curve.second.begin(), curve.second.end(), [](const result_row *a, const result_row *b) { return a->n < b->n; });
        std::ofstream f(plot + "/" + curve.first + ".dat");
        f << "# N ns_median ns_min ns_max\n";
        for (const result_row *r : curve.second) f << r->n << " " << r->ns << " " << r->ns_min << " " << r->ns_max << "\n";
    }
    std::ofstream gp(plot + "/info.gp");
    for (const std::string &build : res.builds) {
        const auto &info = res.info.at(build);
        auto get = [&](const char *key) { auto it = info.find(key); return it == info.end() ? std::string("?") : it->second; };
        std::string load = get("load");
        const size_t used = load.find("used ");
        load = used == std::string::npos ? "" : "; other processes busy on " + load.substr(used + 5, load.find(" of") - used - 5) + " CPUs";
        gp << "machine_" << build << " = \"" << get("cpu") << "; " << get("compiler") << " " << get("flags") << load << "\"\n";
        gp << "has_" << build << " = 1\n";
    }
}

int run_report(const std::string &dir) {
    results res;
    for (const char *build : {"native", "o2"}) load(dir, build, res);
    if (res.builds.empty()) {
        std::fprintf(stderr, "throughput: no results in %s (native.csv, o2.csv)\n", dir.c_str());
        return 1;
    }
    std::ostringstream md;
    md << "# motus_step: throughput\n\n";
    for (const std::string &build : res.builds) {
        const auto &info = res.info.at(build);
        md << "- **" << build << "**: ";
        bool first = true;
        for (const char *key : {"flags", "compiler", "simd", "openmp", "load"}) {
            auto it = info.find(key);
            if (it == info.end()) continue;
            md << (first ? "" : "; ") << key << " " << it->second;
            first = false;
        }
        md << "\n";
    }
    const auto &info = res.info.at(res.builds[0]);
    for (const char *key : {"cpu", "caches", "system", "header", "date"}) {
        auto it = info.find(key);
        if (it != info.end()) md << "- " << key << ": " << it->second << "\n";
    }
    md << "\nns per particle-step: the time of a step of N particles divided by N (the CPU time of the thread; "
          "wall clock for 2 threads), the median over the rounds of the best of 3 measurements (1 from N = 10^6); "
          "each round starts at another method of its group, evenly around it. "
          "Arrays are 64-byte aligned (motus aligns its vector stores to the first position array). The bound is "
          "an in-place read-modify-write of the same x and v arrays (every value read and written once, one loop, "
          "one thread): no step that reads and writes its state can be faster. dt = 1/60 s; gravity (0.7, -9.81, "
          "0.4) m/s^2, damping 0.01 per step (v *= 0.99), linear drag 0.5 1/s, mass 2 kg (per-particle 0.5 to 4 kg "
          "in the mass scene); attractor mu = 1e5 m^3/s^2 at (500, 500, 500); springs: a chain of N, stiffness 50 "
          "N/m, rest length 1 m, damping 0.05 N s/m, 2D only (the hand loop is 2D), through motus's coupled path "
          "(scene.springs, scratch; the hand loop clears and sums the forces every step). Every motus row is one "
          "motus_step call per step over structure-of-arrays state (the fast path: every stage in registers, "
          "except the springs). \"walls nobody reaches\" adds bounds at +-1e30: the wall checks computed, the "
          "same motion. The textbook path is measured at N = 5000 only: an array of motus_particle (motus_particle3 "
          "in 3D) and, per particle, motus_particle_clear_forces, _add_force (the weight), _step, _damp_per_step "
          "and _bounce (walls at 0 and 1000 m, restitution 0.5), against a plain loop with the same math over the "
          "same structs. odeint runs the gravity scene (gravity + damping is not a Hamiltonian system); its "
          "symplectic_euler moves x first, motus's semi-implicit Euler v first: both order 1, the same work; its "
          "runge_kutta4 steps y = (x, v) as one std::vector.\n\n";
    long subnormal_cells = 0, error_cells = 0;
    for (const result_row &r : res.rows) subnormal_cells += r.subnormals != 0, error_cells += r.error != 0;
    md << "Subnormal numbers in the state after a measurement: " << (subnormal_cells ? std::to_string(subnormal_cells) + " measurements (marked below)" : std::string("none"))
       << ". Errors returned: " << (error_cells ? std::to_string(error_cells) : std::string("none")) << ".\n\n";
    report_targets(md, res);
    md << "## All measurements\n\n";
    report_tables(md, res);
    report_checks(md, res);
    const std::string text = md.str();
    std::fwrite(text.data(), 1, text.size(), stdout);
    std::ofstream(dir + "/throughput.md") << text;
    write_plot_data(dir, res);
    return 0;
}

} // namespace

int main(int argc, char **argv) {
    const options o = parse(argc, argv);
#ifdef __GLIBC__
    // Keep freed memory in the process: the arrays of one size are then the pages the previous size touched,
    // instead of fresh mappings the kernel must fault in and zero again (seconds at N = 10^7).
    mallopt(M_MMAP_MAX, 0);
    mallopt(M_TRIM_THRESHOLD, -1); // never give memory back (the value is read as the largest size_t)
#endif
    if (!o.report.empty()) return run_report(o.report);
    return run_measure(o);
}
