#!/usr/bin/env bash
# Usage: scripts/collisions.sh [collisions options...]      QUICK=1 scripts/collisions.sh: a smoke run in seconds
# Balls in a box (issue 12, item 8): N = 10^3 .. 10^6 balls of one radius falling into a box open at the top
# ("drop") and packed at rest on its floor ("pile"), in 2D and 3D, stepped by motus_step with contacts and, in
# the same run on the same start, by what a game programmer would pick instead: Box2D 2.4 circles, Chipmunk 7
# circles (2D), Bullet spheres (3D), and a brute-force pair loop with motus's contact model (N <= 10^4); motus
# also at 1 substep a frame ("motus-1substep": one step of dt a frame, as the peers step) and at 1 substep and
# 1 iteration ("motus-1x1": its lightest setting). Per
# engine and N: time per step (median), the largest overlap as a fraction of the radius, the kinetic energy
# over the initial potential energy (bench/collisions.cpp says exactly how). It installs the Debian 12 packages
# it needs and are missing (compilers, CMake, libbox2d-dev, libchipmunk-dev, libbullet-dev, gnuplot), builds
# the `collisions` target in build-bench/ (-O2, no -march: the peers are Debian's -O2 builds), runs it and
# writes into build-bench/collisions/:
#   collisions.csv   engine,dims,scene,n,ms_per_step,max_overlap_over_r,ke_over_pe0,threads,note (note
#                    "parallel_for": motus again at N = 10^5 with scene.parallel_for, a pool of 1 and 2 threads
#                    of tests/support/motus_pool.h)
#   collisions.md    the tables, the targets of item 8 as measured (2 threads against 1 at 10^5, with the final
#                    states of 1 and 2 threads compared bit for bit), the machine and how busy it was (also
#                    printed on stdout; progress goes to stderr)
#   collisions.png   ns per particle-step against N, one line per engine (2D, 3D; drop, pile)
# and copies the figure to docs/collisions.png for the README. About 6 minutes on 2 cores; run it on an
# otherwise idle machine (the report says how busy it was). A peer is skipped at a size where one step would
# take more than 2 s (--cap S), and the table says so. QUICK=1 (or --quick): N = 300 and 2000, a few frames,
# docs/ left as it was. Other options go to the program: --sizes N,N,... --engines motus,box2d,... --cap S.
# COLLISIONS_BUILD_DIR and COLLISIONS_OUT override the two directories.
set -euo pipefail
cd "$(dirname "$0")/.."

scripts/deps.sh bench >&2
gnuplot -e "set terminal pngcairo" </dev/null 2>/dev/null ||
    { echo "collisions: this gnuplot has no pngcairo terminal (Debian's gnuplot-nox has it)" >&2; exit 1; }

build=${COLLISIONS_BUILD_DIR:-build-bench}
out=${COLLISIONS_OUT:-$build/collisions}
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DMOTUS_BUILD_BENCH=ON -DMOTUS_BUILD_TESTS=OFF \
      -DMOTUS_BUILD_EXAMPLES=OFF -DMOTUS_INSTALL=OFF >&2
# -j2 at most: the machine's 2 cores are shared.
if ! cmake --build "$build" --target collisions --parallel 2 >&2; then
    echo "collisions: the target did not build; see above" >&2
    exit 1
fi

quick=0
[ "${QUICK:-0}" = 1 ] && quick=1
for argument in "$@"; do [ "$argument" = "--quick" ] && quick=1; done
arguments=("$@")
[ "$quick" -eq 1 ] && arguments+=(--quick)

mkdir -p "$out"
out=$(cd "$out" && pwd)
rm -rf "$out/plot" "$out/collisions.csv" "$out/collisions.md" "$out/collisions.png"
start=$(date +%s)
"$build/bench/collisions" --out "$out" "${arguments[@]}" </dev/null
packages=$(dpkg-query -W -f='${Package} ${Version}; ' libbox2d-dev libchipmunk-dev libbullet-dev 2>/dev/null || true)
printf '\nDebian packages: %s run time %s s (build excluded).\n' "$packages" "$(( $(date +%s) - start ))" |
    tee -a "$out/collisions.md"
gnuplot -e "out='$out'" bench/plot_collisions.gp </dev/null

if [ "$quick" -eq 0 ]; then
    cp "$out/collisions.png" docs/collisions.png
    echo "collisions: results in $out; figure copied to docs/collisions.png" >&2
else
    echo "collisions: results in $out (quick run: docs/ left as it was)" >&2
fi
