#!/bin/sh
# Usage: check.sh OUTPUT_DIR INCLUDE_DIR COMPILER [FLAGS...]
# Compiles unit_a.c and unit_b.c into one program with COMPILER and FLAGS, runs it. Exit 77 (skipped) when
# the compiler is not installed.
set -eu
out=$1 include=$2 compiler=$3
shift 3
here=$(cd "$(dirname "$0")" && pwd)
if ! command -v "$compiler" >/dev/null 2>&1; then
    echo "skipped: $compiler is not installed (scripts/deps.sh installs it)"
    exit 77
fi
mkdir -p "$(dirname "$out")"
echo "$compiler $* -I$include unit_a.c unit_b.c -lm"
"$compiler" "$@" -I"$include" "$here/unit_a.c" "$here/unit_b.c" -o "$out" -lm
"$out"
