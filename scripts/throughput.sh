#!/usr/bin/env bash
# Usage: scripts/throughput.sh [throughput options...]
# Measures ns per particle-step of motus_step (every method, over structure-of-arrays state) for N = 4096,
# 10^5 and 10^7, in 2D and 3D, float and double, on the scenes drift, gravity, gravity + damping, gravity +
# linear drag, mass + forces, springs (coupled) and attractor, side by side with a hand-written loop for each
# scene, the memory bandwidth (copy, triad and the in-place bound), Boost.Odeint (symplectic_euler,
# velocity_verlet, runge_kutta4 on gravity) and 2 threads over motus_step_range; and at N = 5000 the textbook
# per-particle path (motus_particle_* on an array of motus_particle) against a plain loop doing the same math
# (bench/throughput.cpp says how). It installs the Debian 12 packages it needs and are missing (compilers,
# CMake, the Boost headers, gnuplot), builds the two binaries of the `throughput` target in build-bench/
# (throughput_native: -O3 -march=native; throughput_o2: -O2, no -march), runs both one after the other,
# merges their results and writes into build-bench/throughput/:
#   native.csv, o2.csv            every measurement (median, min, max over the rounds)
#   native.info, o2.info          the machine, compiler, flags, and how busy other processes kept it
#   native_verify.csv, o2_verify.csv  whether every method computed what motus did
#   throughput.md                 the targets as measured ratios, and every table (also printed on stdout)
#   throughput.png, throughput_scenes.png, throughput_o2.png
# and copies the figures to docs/throughput*.png for the README. About 7 minutes on 2 cores; run it on an
# otherwise idle machine (the report says how busy it was: other processes slow the 2-thread runs most).
# Options go to both programs: --quick (a smoke run in seconds), --sizes N,N,... , --scenes S,S,...,
# --dims 2|3, --precision float|double (a run with any of these leaves docs/ as it was), --rounds R (9),
# --seconds S (0.001 per measurement). CC=clang CXX=clang++ THROUGHPUT_BUILD_DIR=build-clang measures a
# Clang build (--sizes 5000: only the textbook calls).
# THROUGHPUT_BUILD_DIR and THROUGHPUT_OUT override the two directories. OpenMP's idle threads spin for at
# most GOMP_SPINCOUNT=10000 turns (set it to override): libgomp's default keeps a core busy for milliseconds
# after each 2-thread step, which slows whatever is measured next on a 2-core machine.
set -euo pipefail
cd "$(dirname "$0")/.."

scripts/deps.sh bench >&2
gnuplot -e "set terminal pngcairo" </dev/null 2>/dev/null ||
    { echo "throughput: this gnuplot has no pngcairo terminal (Debian's gnuplot-nox has it)" >&2; exit 1; }

build=${THROUGHPUT_BUILD_DIR:-build-bench}
out=${THROUGHPUT_OUT:-$build/throughput}
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DMOTUS_BUILD_BENCH=ON -DMOTUS_BUILD_TESTS=OFF \
      -DMOTUS_BUILD_EXAMPLES=OFF -DMOTUS_INSTALL=OFF >&2
if ! cmake --build "$build" --target throughput --parallel "$(nproc 2>/dev/null || echo 2)" >&2; then
    echo "throughput: the target did not build; see above (bench/CMakeLists.txt skips it without Boost)" >&2
    exit 1
fi

mkdir -p "$out"
out=$(cd "$out" && pwd)
rm -f "$out"/native.csv "$out"/o2.csv "$out"/native.info "$out"/o2.info "$out"/*_verify.csv
export GOMP_SPINCOUNT=${GOMP_SPINCOUNT:-10000}
ran=0
for binary in throughput_native throughput_o2; do
    if [ -x "$build/bench/$binary" ]; then
        "$build/bench/$binary" --out "$out" "$@" </dev/null
        ran=1
    fi
done
[ "$ran" -eq 1 ] || { echo "throughput: no binary in $build/bench" >&2; exit 1; }
reporter=$build/bench/throughput_native
[ -x "$reporter" ] || reporter=$build/bench/throughput_o2
"$reporter" --report "$out" </dev/null
# Only a full run (no --quick, nor a choice of sizes, scenes, dimensions or precision) redraws docs/; the
# figures of a run without some of the data they draw are not drawn.
partial=0
for argument in "$@"; do
    case $argument in --quick | --sizes* | --scenes* | --dims* | --precision*) partial=1 ;; esac
done
if ! gnuplot -e "out='$out'" bench/plot_throughput.gp </dev/null 2>"$out/gnuplot.log"; then
    [ "$partial" -eq 1 ] || { cat "$out/gnuplot.log" >&2; exit 1; }
    echo "throughput: no figures for this partial run (see $out/gnuplot.log)" >&2
fi
if [ "$partial" -eq 0 ]; then
    for figure in throughput throughput_scenes throughput_o2; do
        if [ -f "$out/$figure.png" ]; then cp "$out/$figure.png" "docs/$figure.png"; fi
    done
    echo "throughput: results in $out; figures copied to docs/throughput{,_scenes,_o2}.png" >&2
else
    echo "throughput: results in $out (a partial run: docs/ left as it was)" >&2
fi
