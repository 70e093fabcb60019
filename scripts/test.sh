#!/usr/bin/env bash
# Usage: scripts/test.sh [ctest arguments...]
# Installs what is missing, builds everything in build/ and runs every test (unit, render, example,
# consumer, compile). Extra arguments go to ctest, e.g. `scripts/test.sh -L render`.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/deps.sh test
scripts/bootstrap-raylib.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=RelWithDebInfo -DMOTUS_BUILD_TESTS=ON -DMOTUS_BUILD_EXAMPLES=ON
cmake --build build --parallel "$(nproc 2>/dev/null || echo 2)"
cd build
ctest --output-on-failure --parallel "$(nproc 2>/dev/null || echo 2)" "$@"
