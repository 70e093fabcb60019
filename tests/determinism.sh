#!/bin/sh
# Usage: determinism.sh OUTPUT SOURCE INCLUDE_DIR STEPS EXPECT COMPILER [FLAGS...]
# Builds SOURCE (tests/determinism.c) with COMPILER and FLAGS, runs `OUTPUT --matrix STEPS` and checks it:
# EXPECT=golden: every path ends on its golden hash (and on its twin's); EXPECT=differs: the build must NOT
# print the golden hashes (a build with contraction allowed: proves the test sees what the pragmas prevent).
# Exit 77 (skipped) when the compiler is not installed.
set -eu
out=$1 source=$2 include=$3 steps=$4 expect=$5 compiler=$6
shift 6
if ! command -v "$compiler" >/dev/null 2>&1; then
    echo "skipped: $compiler is not installed (scripts/deps.sh installs it)"
    exit 77
fi
mkdir -p "$(dirname "$out")"
echo "$compiler $* -I$include $source"
"$compiler" "$@" -I"$include" -I"$(dirname "$source")" "$source" -o "$out" -lm
status=0
"$out" --matrix "$steps" > "$out.txt" || status=$?
cat "$out.txt"
case $expect in
golden) exit $status ;;
differs)
    if [ $status -eq 0 ]; then
        echo "this build was expected to end in another state (contraction allowed), but printed the golden hashes"
        exit 1
    fi
    grep -c DIFFERS "$out.txt" | sed 's/$/ paths end in another state, as expected/'
    exit 0 ;;
*) echo "EXPECT must be golden or differs"; exit 2 ;;
esac
