#!/usr/bin/env bash
# bootstrap-raylib.sh -- lay out a prebuilt raylib in a local prefix for the
# motus raylib example.
#
# Usage: scripts/bootstrap-raylib.sh [--force] [PREFIX]
#
#   PREFIX   install prefix (default: <repo>/.deps/raylib, which is git-ignored)
#   --force  reinstall even if PREFIX already holds raylib
#
# raylib is not packaged by Debian 12, so this script takes the static
# libraries that PyPI ships inside binary wheels:
#   comma-deps-raylib  -> raylib 6.0 headers + libraylib_desktop.a (GLFW/X11)
#                         + libraylib_headless.a (EGL surfaceless, no X needed)
#   comma-deps-imgui   -> libglfw3.a (GLFW 3.4) + GLFW headers
# The wheels say Requires-Python >= 3.12 but contain no Python-version-specific
# code we use, so they are fetched with `pip download --python-version 3.12`.
#
# Resulting layout:
#   PREFIX/include/{raylib.h,raymath.h,rlgl.h,GLFW/glfw3.h,GLFW/glfw3native.h}
#   PREFIX/lib/libraylib.a            (the desktop/GLFW build; bundles GLFW 3.4)
#   PREFIX/lib/libraylib_headless.a   (optional extra; link -lEGL -lGLESv2 -lm)
#   PREFIX/lib/libglfw3.a
#   PREFIX/share/motus-raylib/SOURCE.txt  (which wheels it came from)
#
# Environment:
#   PYTHON                      python interpreter with pip (default: python3)
#   MOTUS_RAYLIB_WHEEL_VERSION  comma-deps-raylib version (default pinned below;
#                               set to empty for the newest)
#   MOTUS_GLFW_WHEEL_VERSION    comma-deps-imgui version (same rules)
#   MOTUS_BOOTSTRAP_GLFW        set to 0 to skip the GLFW wheel (libraylib.a
#                               already bundles GLFW; libglfw3.a is optional)
#
# The system libraries needed to link are NOT installed here (apt is left to
# the caller): libX11 (Debian: libx11-dev) and, at run time, an OpenGL driver
# (Debian: libgl1 + libgl1-mesa-dri).  Link line for the desktop build:
#   -Iinclude lib/libraylib.a -lX11 -lm   (+ -lpthread -ldl on glibc < 2.34)

set -euo pipefail

say()  { printf 'bootstrap-raylib: %s\n' "$*"; }
warn() { printf 'bootstrap-raylib: warning: %s\n' "$*" >&2; }
die()  { printf 'bootstrap-raylib: error: %s\n' "$*" >&2; exit 1; }

usage() { sed -n '2,/^$/{s/^# \{0,1\}//;p}' "$0"; }

script_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo_root=$(cd "$script_dir/.." && pwd)

force=0
prefix=""
while [ $# -gt 0 ]; do
    case "$1" in
        -h|--help) usage; exit 0 ;;
        -f|--force) force=1 ;;
        --) shift; [ $# -gt 0 ] && { prefix=$1; shift; }; break ;;
        -*) die "unknown option '$1' (see --help)" ;;
        *) [ -z "$prefix" ] || die "more than one PREFIX given ('$prefix', '$1')"
           prefix=$1 ;;
    esac
    shift
done
[ $# -eq 0 ] || die "unexpected arguments: $*"
prefix=${prefix:-$repo_root/.deps/raylib}

PYTHON=${PYTHON:-python3}
raylib_version=${MOTUS_RAYLIB_WHEEL_VERSION-6.0.0.1.post104}
glfw_version=${MOTUS_GLFW_WHEEL_VERSION-1.92.7.post104}
want_glfw=${MOTUS_BOOTSTRAP_GLFW:-1}

# ---------------------------------------------------------------------------
# Hints about system libraries (never fatal, never installs anything).
x11_hint() {
    local multiarch="" d
    multiarch=$( (gcc -print-multiarch || cc -print-multiarch) 2>/dev/null || true)
    for d in ${multiarch:+/usr/lib/$multiarch} /usr/lib64 /usr/lib /usr/local/lib; do
        [ -e "$d/libX11.so" ] && return 0
    done
    warn "libX11.so (X11 development library) not found; linking the raylib"
    warn "example needs it. On Debian/Ubuntu: apt-get install -y libx11-dev"
}

# ---------------------------------------------------------------------------
# Idempotency.
if [ "$force" -eq 0 ] && [ -f "$prefix/lib/libraylib.a" ] && [ -f "$prefix/include/raylib.h" ]; then
    say "raylib already present in $prefix (nothing to do; use --force to reinstall)"
    x11_hint
    exit 0
fi

case "$(uname -s)" in
    Linux) ;;
    *) die "the PyPI raylib wheels are Linux-only; on $(uname -s) install raylib yourself and pass -DMOTUS_RAYLIB_PREFIX=... to CMake" ;;
esac

command -v "$PYTHON" >/dev/null 2>&1 || die "'$PYTHON' not found (set PYTHON=/path/to/python3)"
"$PYTHON" -m pip --version >/dev/null 2>&1 \
    || die "'$PYTHON -m pip' does not work; install pip (Debian: apt-get install -y python3-pip)"

work=$(mktemp -d "${TMPDIR:-/tmp}/motus-raylib.XXXXXX")
cleanup() { rm -rf "$work"; }
trap cleanup EXIT

# fetch DIST VERSION DEST: download one wheel and unpack it into DEST.
fetch() {
    local dist=$1 version=$2 dest=$3 spec wheel
    spec=$dist${version:+==$version}
    say "downloading $spec (binary wheel, via $PYTHON -m pip)"
    mkdir -p "$work/dl-$dist"
    if ! "$PYTHON" -m pip download --no-deps --only-binary=:all: \
            --python-version 3.12 --no-input --disable-pip-version-check \
            --progress-bar off -d "$work/dl-$dist" "$spec" >"$work/pip-$dist.log" 2>&1; then
        cat "$work/pip-$dist.log" >&2
        die "pip could not download $spec (is PyPI reachable? is this x86_64/aarch64 Linux with glibc >= 2.28?)"
    fi
    wheel=$(find "$work/dl-$dist" -maxdepth 1 -name '*.whl' | head -n 1)
    [ -n "$wheel" ] || die "pip reported success but no wheel for $spec is in $work/dl-$dist"
    say "  got $(basename "$wheel")"
    mkdir -p "$dest"
    "$PYTHON" -m zipfile -e "$wheel" "$dest" || die "could not unpack $(basename "$wheel")"
    printf '%s  %s\n' "$(basename "$wheel")" \
        "$( (sha256sum "$wheel" 2>/dev/null || true) | cut -d' ' -f1)" >>"$work/SOURCE.txt"
}

# find_one DIR PATH-PATTERN WHAT: print the single file matching the pattern.
find_one() {
    local hit
    hit=$(find "$1" -type f -path "$2" | head -n 1)
    [ -n "$hit" ] || die "$3 not found in the wheel (looked for '$2'); the wheel layout changed?"
    printf '%s\n' "$hit"
}

: >"$work/SOURCE.txt"
fetch comma-deps-raylib "$raylib_version" "$work/raylib"
ray_h=$(find_one "$work/raylib" '*/raylib/install/include/raylib.h' raylib.h)
ray_inc=$(dirname "$ray_h")
ray_lib=$(find_one "$work/raylib" '*/raylib/install/lib/libraylib_desktop.a' libraylib_desktop.a)
ray_headless=$(find "$work/raylib" -type f -path '*/raylib/install/lib/libraylib_headless.a' | head -n 1)

glfw_lib=""
if [ "$want_glfw" != 0 ]; then
    fetch comma-deps-imgui "$glfw_version" "$work/imgui"
    glfw_lib=$(find_one "$work/imgui" '*/imgui/install/lib/libglfw3.a' libglfw3.a)
    glfw_inc=$(dirname "$(find_one "$work/imgui" '*/imgui/install/include/GLFW/glfw3.h' GLFW/glfw3.h)")
fi

# ---------------------------------------------------------------------------
# Install.  libraylib.a is written last (atomically) because it is the marker
# the idempotency check and CMake look for.
mkdir -p "$prefix/include" "$prefix/lib" "$prefix/share/motus-raylib" \
    || die "cannot create $prefix"
prefix=$(cd "$prefix" && pwd)
rm -f "$prefix/lib/libraylib.a"

for h in raylib.h raymath.h rlgl.h; do
    [ -f "$ray_inc/$h" ] || die "$h missing from the raylib wheel"
    install -m 0644 "$ray_inc/$h" "$prefix/include/$h"
done
say "installed headers raylib.h raymath.h rlgl.h -> $prefix/include"

if [ -n "$glfw_lib" ]; then
    mkdir -p "$prefix/include/GLFW"
    install -m 0644 "$glfw_inc"/*.h "$prefix/include/GLFW/"
    install -m 0644 "$glfw_lib" "$prefix/lib/libglfw3.a"
    say "installed libglfw3.a (+ GLFW headers) -> $prefix/lib"
fi
if [ -n "$ray_headless" ]; then
    install -m 0644 "$ray_headless" "$prefix/lib/libraylib_headless.a"
    say "installed libraylib_headless.a -> $prefix/lib"
fi
install -m 0644 "$work/SOURCE.txt" "$prefix/share/motus-raylib/SOURCE.txt"
install -m 0644 "$ray_lib" "$prefix/lib/libraylib.a.tmp"
mv -f "$prefix/lib/libraylib.a.tmp" "$prefix/lib/libraylib.a"
say "installed libraylib.a (raylib $(sed -n 's/^#define RAYLIB_VERSION  *"\(.*\)".*/\1/p' "$prefix/include/raylib.h"), desktop/GLFW build) -> $prefix/lib"

# ---------------------------------------------------------------------------
# Smoke-link a tiny program (informational only; needs a C compiler + libX11).
x11_hint
cc_bin=${CC:-cc}
if command -v "$cc_bin" >/dev/null 2>&1; then
    # InitWindow is referenced behind a run-time condition so the whole
    # platform layer gets linked without the program ever opening a window.
    printf '#include "raylib.h"\nint main(int argc, char **argv) { (void)argv; if (argc > 99) InitWindow(8, 8, ""); return 0; }\n' >"$work/t.c"
    if "$cc_bin" "$work/t.c" -I"$prefix/include" "$prefix/lib/libraylib.a" \
            -lX11 -lm -lpthread -ldl -o "$work/t" >"$work/link.log" 2>&1; then
        say "link check OK: cc prog.c -I$prefix/include $prefix/lib/libraylib.a -lX11 -lm -lpthread -ldl"
    else
        warn "link check failed (the install itself is complete):"
        sed 's/^/    /' "$work/link.log" >&2
    fi
else
    say "no C compiler ('$cc_bin') found; skipped the link check"
fi
say "done. Configure motus with -DMOTUS_RAYLIB_PREFIX=$prefix (the default when PREFIX is <repo>/.deps/raylib)"
