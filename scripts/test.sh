#!/usr/bin/env bash
# Usage: scripts/test.sh [ctest arguments...]
# Installs what is missing, builds everything in build/ and runs every test (unit, render, example,
# consumer, compile, determinism); then scripts/check-tools.sh runs the suite again under ASan + UBSan and
# under valgrind, and fuzzes the API for a bounded time. Extra arguments go to the first ctest only, e.g.
# `scripts/test.sh -L render`; with them, or with MOTUS_CHECK_TOOLS=0, the tool passes are skipped.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/deps.sh test
scripts/bootstrap-raylib.sh
jobs=$(nproc 2>/dev/null || echo 2)
start=$(date +%s)
# MOTUS_WERROR: warnings are errors here, in CI; a user's build (the option's default, OFF) only shows them.
cmake -S . -B build -DCMAKE_BUILD_TYPE=RelWithDebInfo -DMOTUS_BUILD_TESTS=ON -DMOTUS_BUILD_EXAMPLES=ON -DMOTUS_WERROR=ON
cmake --build build --parallel "$jobs"
(cd build && ctest --output-on-failure --parallel "$jobs" "$@")
echo "test: build + ctest took $(( $(date +%s) - start )) s"
if [ $# -gt 0 ] || [ "${MOTUS_CHECK_TOOLS:-1}" = 0 ]; then
    echo "test: sanitizer, valgrind and fuzz passes skipped (scripts/check-tools.sh runs them)"
    exit 0
fi
MOTUS_BUILD_DIR=build scripts/check-tools.sh
