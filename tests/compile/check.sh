#!/bin/sh
# Usage: check.sh OUTPUT_DIR INCLUDE_DIR TEST_CODE_WERROR COMPILER [FLAGS...]
# Compiles unit_a.c and unit_b.c into one program with COMPILER and FLAGS, runs it. Exit 77 (skipped) when
# the compiler is not installed.
# FLAGS carry -Werror: what the test asserts is that motus.h compiles without a warning. Only the header may
# fail that assertion, not the test's own code: when the -Werror build stops, the sources are compiled again
# without -Werror and the diagnostics read. Any diagnostic that points into motus.h (a warning there, or a
# note in one of its macros or declarations) fails the test. Warnings in unit_a.c and unit_b.c alone fail it
# only when TEST_CODE_WERROR is 1 (MOTUS_WERROR=ON, as in CI); with 0 they are printed and the program, built
# without -Werror, runs.
set -eu
out=$1 include=$2 test_code_werror=$3 compiler=$4
shift 4
here=$(cd "$(dirname "$0")" && pwd)
if ! command -v "$compiler" >/dev/null 2>&1; then
    echo "skipped: $compiler is not installed (scripts/deps.sh installs it)"
    exit 77
fi
mkdir -p "$(dirname "$out")"
echo "$compiler $* -I$include unit_a.c unit_b.c -lm"
if ! "$compiler" "$@" -I"$include" "$here/unit_a.c" "$here/unit_b.c" -o "$out" -lm; then
    for arg do
        shift
        [ "$arg" = -Werror ] || set -- "$@" "$arg"
    done
    echo "check: the build failed; again without -Werror, to see whether motus.h or the test code warns:"
    echo "$compiler $* -I$include unit_a.c unit_b.c -lm"
    status=0
    log=$("$compiler" "$@" -I"$include" "$here/unit_a.c" "$here/unit_b.c" -o "$out" -lm 2>&1) || status=$?
    printf '%s\n' "$log"
    if [ $status -ne 0 ]; then
        echo "FAILED: the build fails without -Werror too"
        exit 1
    fi
    if printf '%s\n' "$log" | grep -qE 'motus\.h:[0-9]+'; then
        echo "FAILED: motus.h warns (the diagnostics above that point into it)"
        exit 1
    fi
    if [ "$test_code_werror" = 1 ]; then
        echo "FAILED: the warnings are in the test code (unit_a.c, unit_b.c), not in motus.h; MOTUS_WERROR=ON" \
             "makes them errors"
        exit 1
    fi
    echo "check: the warnings are in the test code (unit_a.c, unit_b.c), not in motus.h: not a failure of" \
         "the header (MOTUS_WERROR=ON would make them one); running the program built without -Werror"
fi
"$out"
