#!/bin/sh
# Usage: quiet.sh INCLUDE_DIR COMPILER [FLAGS...]
# The warnings motus.h keeps off over its own lines (MOTUS__QUIET_BEGIN: -Wfloat-equal, -Wswitch-enum, -Wpadded,
# with Clang -Wcomma and -Wused-but-marked-unused, and in C++ -Wold-style-cast, -Wuseless-cast,
# -Wzero-as-null-pointer-constant, -Wreserved-identifier and -Wreserved-macro-identifier), which a game's build may turn
# on: the header with its implementation must compile under FLAGS (they carry -Werror) with no warning, and
# the same warning in the including file's own code, after the header, must still be reported (the pragma
# is popped, not left on for the game). Exit 77 (skipped) when the compiler is not installed.
set -eu
include=$1 compiler=$2
shift 2
if ! command -v "$compiler" >/dev/null 2>&1; then
    echo "skipped: $compiler is not installed (scripts/deps.sh installs it)"
    exit 77
fi
dir=$(mktemp -d)
finish() { rm -rf "$dir"; exit "$1"; } # not a trap: dash's trap leaks its string under valgrind
cat >"$dir/quiet.c" <<'UNIT'
#define MOTUS_IMPLEMENTATION
#include "motus.h"
#ifdef QUIET_GAME_CODE
int quiet_game_code(motus_real a) { return a == motus_particle3_mass(NULL); } /* -Wfloat-equal */
#endif
int quiet_unit(void) { return MOTUS_VERSION; }
UNIT
echo "$compiler $* -I$include -fsyntax-only quiet.c"
"$compiler" "$@" -I"$include" -fsyntax-only "$dir/quiet.c" || finish 1
echo "again with a float == in the unit's own code: it must be reported"
if "$compiler" "$@" -DQUIET_GAME_CODE -I"$include" -fsyntax-only "$dir/quiet.c" 2>"$dir/log"; then
    echo "FAILED: the unit's own a == b compiled without a warning: the header left -Wfloat-equal off"
    finish 1
fi
cat "$dir/log"
grep -q 'quiet\.c:4:.*float-equal' "$dir/log" || { echo "FAILED: no -Wfloat-equal on the unit's line 4"; finish 1; }
echo ok
finish 0
