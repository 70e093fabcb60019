#!/usr/bin/env bash
# Usage: scripts/deps.sh [demo|test|bench]
# Installs the Debian 12 packages that the demo, the test suite or the benchmarks need and that are
# missing; installs nothing when all are present. As root it runs apt-get itself; otherwise through sudo.
set -euo pipefail

demo=(cmake make gcc pkg-config python3 libx11-dev libgl1-mesa-dri libglx-mesa0 xvfb xauth
      libxrandr2 libxcursor1 libxi6 libxinerama1 libxext6 libxrender1 libx11-xcb1)
# The tests also build the benchmarks (to keep them compiling) and run them once in their quick mode.
# scripts/check-tools.sh (run by scripts/test.sh): valgrind, and clang's sanitizer and libFuzzer runtimes.
test=("${demo[@]}" g++ clang tcc libosmesa6-dev libstb-dev xdotool libboost-dev libgsl-dev gnuplot-nox
      valgrind libclang-rt-14-dev libbox2d-dev libchipmunk-dev libbullet-dev)
# bench/collisions' peers: Box2D 2.4, Chipmunk 7, Bullet.
bench=(cmake make gcc g++ pkg-config libboost-dev libgsl-dev gnuplot-nox libbox2d-dev libchipmunk-dev libbullet-dev)

case "${1:-test}" in
    demo) wanted=("${demo[@]}") ;;
    test) wanted=("${test[@]}") ;;
    bench) wanted=("${bench[@]}") ;;
    *) echo "usage: $0 [demo|test|bench]" >&2; exit 2 ;;
esac
# raylib comes from PyPI wheels (scripts/bootstrap-raylib.sh), fetched with pip.
[ "${1:-test}" = bench ] || python3 -m pip --version >/dev/null 2>&1 || wanted+=(python3-pip)

missing=()
for package in "${wanted[@]}"; do
    dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing+=("$package")
done
if [ ${#missing[@]} -eq 0 ]; then
    echo "deps: all ${#wanted[@]} packages present"
    exit 0
fi

echo "deps: installing ${missing[*]}"
if ! command -v apt-get >/dev/null 2>&1; then
    echo "deps: no apt-get here; install the equivalents of: ${missing[*]}" >&2
    exit 1
fi
as_root=()
if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null 2>&1 || { echo "deps: run as root or install sudo (missing: ${missing[*]})" >&2; exit 1; }
    as_root=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
# Try with the package lists as they are; refresh them once if that fails (new machine, stale lists).
if ! "${as_root[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}" </dev/null; then
    "${as_root[@]}" apt-get update -q </dev/null
    "${as_root[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}" </dev/null
fi
