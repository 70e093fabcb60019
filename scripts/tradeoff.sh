#!/usr/bin/env bash
# Usage: scripts/tradeoff.sh [tradeoff options...]
# Measures every motus integrator (motus_step over structure-of-arrays state: the fast path for gravity, drags,
# the attractor and the oscillators' tether) against Boost.Odeint and GSL on the
# reference problems of bench/problems.h, and draws the figures. Timed twice: a batch of N = 4096
# particles (the figures in docs/) and N = 1 (one particle: every step pays the per-call overhead, of motus's
# call as of the peers'), each with its own report. It installs the Debian 12 packages it needs and are missing (compilers, CMake, the
# Boost headers, GSL, gnuplot), builds the `tradeoff` target in build-bench/ (Release, -O2, no -march=native
# so that the numbers hold for any x86-64; configure with -DMOTUS_BENCH_NATIVE=ON to change that), runs it
# and writes into build-bench/tradeoff/ (N = 4096) and build-bench/tradeoff/n1/ (N = 1):
#   tradeoff.csv         every method x precision x problem x dt: error, energy error, evaluations, ns, cost
#   tradeoff_ratios.csv  the cost ratio motus/peer at every error level both cover
#   tradeoff.md          the tables (also printed on stdout; progress goes to stderr)
#   work_precision.png, convergence.png, kepler_energy.png
# and copies the N = 4096 figures to docs/tradeoff_*.png for the README. About 4 minutes on 2 cores.
# Options go to the program: --quick (a smoke run in seconds; its figures are not copied to docs/),
# --repetitions R (9), --seconds S (0.02), --orbits K (1000); --particles N replaces the two runs by one at N.
# TRADEOFF_BUILD_DIR and TRADEOFF_OUT override the two directories.
set -euo pipefail
cd "$(dirname "$0")/.."

scripts/deps.sh bench >&2
gnuplot -e "set terminal pngcairo" </dev/null 2>/dev/null ||
    { echo "tradeoff: this gnuplot has no pngcairo terminal (Debian's gnuplot-nox has it)" >&2; exit 1; }

build=${TRADEOFF_BUILD_DIR:-build-bench}
out=${TRADEOFF_OUT:-$build/tradeoff}
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DMOTUS_BUILD_BENCH=ON -DMOTUS_BUILD_TESTS=OFF \
      -DMOTUS_BUILD_EXAMPLES=OFF -DMOTUS_INSTALL=OFF >&2
if ! cmake --build "$build" --target tradeoff --parallel "$(nproc 2>/dev/null || echo 2)" >&2; then
    echo "tradeoff: the target did not build; see above (bench/CMakeLists.txt skips it without Boost or GSL)" >&2
    exit 1
fi

mkdir -p "$out"
out=$(cd "$out" && pwd)
quick=0 particles_given=0
for argument in "$@"; do
    [ "$argument" = "--quick" ] && quick=1
    [ "$argument" = "--particles" ] && particles_given=1
done
if [ "$particles_given" -eq 1 ]; then
    "$build/bench/tradeoff" --out "$out" "$@" </dev/null
    gnuplot -e "out='$out'" bench/plot_tradeoff.gp </dev/null
else
    "$build/bench/tradeoff" --out "$out" --particles 4096 "$@" </dev/null
    gnuplot -e "out='$out'" bench/plot_tradeoff.gp </dev/null
    mkdir -p "$out/n1"
    "$build/bench/tradeoff" --out "$out/n1" --particles 1 "$@" </dev/null >"$out/n1/stdout.md"
    gnuplot -e "out='$out/n1'" bench/plot_tradeoff.gp </dev/null
    echo "tradeoff: N = 1 (one particle per call) in $out/n1/tradeoff.md" >&2
fi

if [ "$quick" -eq 0 ]; then
    for figure in work_precision convergence kepler_energy; do
        cp "$out/$figure.png" "docs/tradeoff_$figure.png"
    done
    echo "tradeoff: results in $out; figures copied to docs/tradeoff_{work_precision,convergence,kepler_energy}.png" >&2
else
    echo "tradeoff: results in $out (quick run: docs/ left as it was)" >&2
fi
