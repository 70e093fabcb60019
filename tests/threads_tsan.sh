#!/bin/sh
# Usage: threads_tsan.sh OUTPUT SOURCE INCLUDE_DIR COMPILER [FLAGS...]
# Builds SOURCE (tests/threads.c) with COMPILER -fsanitize=thread and runs its bit-identity test: any data
# race between the tasks motus hands to scene.parallel_for (or in tests/support/motus_pool.h) fails it.
# Exit 77 (skipped) when the compiler is not installed.
set -eu
out=$1 source=$2 include=$3 compiler=$4
shift 4
if ! command -v "$compiler" >/dev/null 2>&1; then
    echo "skipped: $compiler is not installed (scripts/deps.sh installs it)"
    exit 77
fi
mkdir -p "$(dirname "$out")"
echo "$compiler -fsanitize=thread $* -I$include $source"
"$compiler" -fsanitize=thread -g "$@" -I"$include" -I"$(dirname "$source")" "$source" -o "$out" -lm -lpthread
MOTUS_THREADS_FRAMES=6 TSAN_OPTIONS="halt_on_error=1 exitcode=66" "$out" same_bits_however_split
