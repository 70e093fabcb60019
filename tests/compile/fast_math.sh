#!/bin/sh
# Usage: fast_math.sh INCLUDE_DIR COMPILER
# motus.h prints a message when built with -ffast-math or -ffinite-math-only, none when MOTUS_ALLOW_FAST_MATH
# is defined and none in a normal build; the message does not fail -Wall -Wextra -Wpedantic -Werror.
# Exit 77 (skipped) when the compiler is not installed.
set -u
include=$1 compiler=$2
if ! command -v "$compiler" >/dev/null 2>&1; then
    echo "skipped: $compiler is not installed"
    exit 77
fi
failed=0
check() { # expected-count flags...
    expected=$1
    shift
    log=$(printf '#include "motus.h"\nint main(void) { return motus_real_is_finite(1) ? 0 : 1; }\n' |
        "$compiler" -x c -std=c99 -Wall -Wextra -Wpedantic -Werror -I"$include" "$@" -fsyntax-only - 2>&1)
    status=$?
    count=$(printf '%s\n' "$log" | grep -cE 'motus\.h:[0-9]+:[0-9]+: .*motus\.h: built with -ffast-math')
    if [ $status -ne 0 ] || [ "$count" -ne "$expected" ]; then
        echo "FAILED: $compiler $*: exit $status, $count messages (expected $expected):"
        printf '%s\n' "$log"
        failed=1
    else
        echo "ok: $compiler $*: $count message(s)"
        [ "$count" -gt 0 ] && printf '%s\n' "$log" | grep -E 'motus\.h:[0-9]+:[0-9]+: ' | head -1
    fi
}
check 1 -ffast-math
check 1 -ffinite-math-only
check 1 -O2 -ffast-math -DMOTUS_DOUBLE
check 0 -ffast-math -DMOTUS_ALLOW_FAST_MATH
check 0
check 0 -O2
exit $failed
