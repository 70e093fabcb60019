#!/bin/sh
# Usage: pkgconfig.sh PREFIX OUTPUT_DIR CC [FLAGS...]
# A Makefile-style consumer: compiler flags from `pkg-config motus` of an installed motus; main.c and engine.c
# (the unit with MOTUS_IMPLEMENTATION) linked into one program. FLAGS go after -Wall -Wextra
# (tests/CMakeLists.txt passes -Werror there with MOTUS_WERROR).
set -eu
prefix=$1 out=$2 cc=$3
shift 3
here=$(cd "$(dirname "$0")" && pwd)
export PKG_CONFIG_PATH="$prefix/share/pkgconfig"
pkg-config --exists --print-errors "motus >= 0.1"
echo "pkg-config motus: version $(pkg-config --modversion motus), flags $(pkg-config --cflags --libs motus)"
mkdir -p "$out"
# shellcheck disable=SC2046
"$cc" -std=c99 -Wall -Wextra "$@" $(pkg-config --cflags motus) "$here/main.c" "$here/engine.c" -o "$out/consumer" \
    $(pkg-config --libs motus)
"$out/consumer"
