#!/usr/bin/env bash
# Usage: scripts/check-tools.sh [asan] [valgrind] [fuzz]      (no argument: all three, in that order)
# The test suite under the tools that find what tests miss. scripts/test.sh runs it after the normal suite.
#   asan      configures build-asan/ with clang and MOTUS_SANITIZE=ON (AddressSanitizer + UndefinedBehavior-
#             Sanitizer, any finding aborts), builds every test, example and benchmark and runs the ctest
#             suite there. Leaks inside OSMesa (not motus, not raylib) are suppressed: tests/support/lsan.supp.
#   valgrind  runs the suite of the normal tree (build/, built by scripts/test.sh; built here if missing)
#             under valgrind memcheck through `ctest -T memcheck`: any error or definitely lost block fails
#             the test.
#   fuzz      builds tests/fuzz/fuzz_motus.c with clang -fsanitize=fuzzer,address,undefined (float, and double
#             with MOTUS_CHECKED) and runs each for MOTUS_FUZZ_SECONDS (default 60) from tests/fuzz/corpus/.
# What each pass leaves out, and why: the *_exclude patterns below (README.md, "Tests").
# Environment: MOTUS_BUILD_DIR (build), MOTUS_ASAN_BUILD_DIR (build-asan), MOTUS_FUZZ_BUILD_DIR (build-fuzz),
# MOTUS_FUZZ_SECONDS (60), MOTUS_JOBS (nproc).
# Warnings are errors in every build here (-DMOTUS_WERROR=ON, -Werror for the fuzz harness), as in
# scripts/test.sh: this is CI's script.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
jobs=${MOTUS_JOBS:-$(nproc 2>/dev/null || echo 2)}
build=${MOTUS_BUILD_DIR:-build}
asan_build=${MOTUS_ASAN_BUILD_DIR:-build-asan}
fuzz_build=${MOTUS_FUZZ_BUILD_DIR:-build-fuzz}
fuzz_seconds=${MOTUS_FUZZ_SECONDS:-60}
parts=("$@")
[ ${#parts[@]} -gt 0 ] || parts=(asan valgrind fuzz)

# Tests the ASan tree does not run (a regular expression for ctest -E): they build their own programs at
# test time, without the sanitizers, to check compilers and flags, not memory:
# - determinism.matrix.*, determinism.contracted.*: determinism.c rebuilt by gcc and clang in 18 modes; the
#   sanitized determinism.{float,double}.* run the same source, golden hashes included.
# - compile.{gcc,clang,g++,clang++,tcc}.*, compile.fast_math_message.*, compile.flags.*: the warning
#   matrix, the -ffast-math message and the engine compiled at other flags (the programs they run, the unit
#   tests run sanitized; compile.flags runs nothing).
# - consumer.*: CMake consumer projects built against the installed package, which carries no sanitizer.
# - threads.tsan: tests/threads.c rebuilt with ThreadSanitizer, which does not mix with ASan (the normal
#   tree runs it).
# - threads.*.pile_settles_in_slabs: 600 frames of 6,000 balls to check that the pile comes to rest (its
#   physics; 190 s under ASan on a Zen 3, the longest test of the pass, 90-100 s natively). Its code runs
#   sanitized in threads.*.same_bits_however_split (5,000 balls in slabs on 2 and 3 threads) and in
#   contacts.*.pile_of_2000_settles (a deep pile); the normal tree checks that it settles.
asan_exclude='^(determinism\.(matrix|contracted)\.|compile\.(gcc|clang|g\+\+|clang\+\+|tcc|fast_math_message|flags)\.|consumer\.|threads\.tsan$|threads\.[a-z_]+\.pile_settles_in_slabs$)'
# Tests valgrind does not run (ctest -E), each for a reason:
# - compile.engine.native.*, compile.engine.agree.*, compile.engine.clang.*, bench.throughput_quick_run: they
#   run -march=native binaries, which on an AVX-512 machine use instructions valgrind cannot decode (SIGILL).
#   The same kernels at 16 and 32 bytes (compile.engine.nosimd/simd32/avx2.*) run under valgrind, and the
#   AVX-512 ones under ASan.
# - determinism.*: 10^5 steps of 1000 particles per method (20 s of CPU per precision, hours under valgrind),
#   and the matrix rebuilds them 18 times; the engine code they hash runs under valgrind in the unit.*,
#   numeric.* and compile.engine.* tests, and the golden-hash tests themselves run under ASan.
# - consumer.*: the command is CMake (ctest --build-and-test); valgrind would check CMake, not motus.
# - example.*: raylib programs in Xvfb with GLX on llvmpipe: under valgrind a frame takes longer than the key
#   tests' timing allows, and what it reports is Mesa's; they run under ASan instead.
# - compile.flags.*: the engine compiled (not run) at six flag sets: gcc's work, not motus's.
# - compile.*.quiet.*: the header compiled (-fsyntax-only, nothing run) under extra warnings: the same.
# - compile.engine.*: engine.c rebuilt at every lane width (and -march=native, which valgrind cannot decode
#   on an AVX-512 machine): 4-25 s each natively, half an hour under valgrind; the default build's engine.*
#   runs under valgrind and ASan (the widths are checked for identical bits in the normal tree only).
# - engine*.paths_agree_*, stability.*.ten_million_steps: the heaviest runs of code the lighter tests cover
#   (2,304 scenes per method; 10^7 steps); they run under ASan. bench.*: the benchmarks' quick mode, run in
#   build/ only (not sanitized either). contacts.*.pile_of_2000_settles: 2,400 contact passes over 2,000
#   balls per dimension (10 s natively, most of an hour under valgrind); the contact code runs under valgrind
#   in the other contacts.* tests and the pile itself under ASan. threads.*: thousands of balls per step on 2
#   and 3 threads (valgrind runs one thread at a time: about an hour); they run under ASan, and under
#   ThreadSanitizer in the normal tree (threads.tsan).
# - render.*, but for three: OSMesa's llvmpipe under valgrind takes 30-120 s a test (760 s of CPU for the ten
#   float ones on a Zen 3), and what it checks there is mostly Mesa's rasteriser. Every render test draws through
#   the same harness (tests/support/motus_canvas.c, from render.c or render_contacts.c): three run it under
#   valgrind, one per kind of motus call (render.wsad_directions the 2D particle and
#   render.projectile_3d_drawn_in_the_xy_plane the 3D one, from render.c; render.head_on_between_two_frames a
#   contact step, from render_contacts.c); the same calls run under valgrind in the unit.*,
#   numeric.* and contacts.* tests; all render tests run natively and under ASan.
# Script-driven tests (compile.gcc.* ...) run with --trace-children: valgrind follows the programs the script
# starts from the build tree and skips system programs (compilers, shells' tools) by the skip patterns.
valgrind_exclude='^(compile\.(engine|flags)\.|compile\.[a-z+]+\.quiet\.|determinism\.|consumer\.|example\.|bench\.|engine(_checked)?\.(float|double)\.paths_agree_|stability\.(float|double)\.ten_million_steps$|contacts\.[a-z_]+\.pile_of_2000_settles$|threads\.|render\.(double\.|canvas_centroid_accuracy$|from_rest_under_constant_force$|constant_velocity_without_force$|twice_the_mass_half_the_displacement$|damping_per_step_matches_linear_drag$|exact_drag_is_frame_rate_independent$|head_on_equal_masses_exchange_velocities$|head_on_restitution_half_on_a_diagonal$))'
valgrind_options="--error-exitcode=1 --trace-children=yes --trace-children-skip=/usr/*,/bin/*,/sbin/* --leak-check=full --show-leak-kinds=definite --errors-for-leak-kinds=definite \
--track-origins=yes --num-callers=30 --suppressions=$root/tests/support/valgrind.supp"

elapsed() { echo "check-tools: $1 took $(( $(date +%s) - $2 )) s"; }

run_asan() {
    local start
    start=$(date +%s)
    # clang: GCC 12 with UBSan takes minutes per unit that includes the engine's kernels, clang seconds.
    # No benchmarks (CI time: each of their programs compiles the engine; their quick runs are in build/).
    CC=${MOTUS_ASAN_CC:-clang} CXX=${MOTUS_ASAN_CXX:-clang++} \
    cmake -S . -B "$asan_build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DMOTUS_SANITIZE=ON \
          -DMOTUS_BUILD_TESTS=ON -DMOTUS_BUILD_EXAMPLES=ON -DMOTUS_BUILD_BENCH=OFF -DMOTUS_WERROR=ON
    cmake --build "$asan_build" --parallel "$jobs"
    (cd "$asan_build" && ctest --output-on-failure --parallel "$jobs" -E "$asan_exclude")
    elapsed "asan (build + ctest)" "$start"
}

run_valgrind() {
    local start
    start=$(date +%s)
    command -v valgrind >/dev/null 2>&1 || { echo "check-tools: valgrind is not installed (scripts/deps.sh test)" >&2; exit 1; }
    if [ ! -f "$build/CTestTestfile.cmake" ]; then
        cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DMOTUS_BUILD_TESTS=ON -DMOTUS_BUILD_EXAMPLES=ON \
              -DMOTUS_WERROR=ON
        cmake --build "$build" --parallel "$jobs"
    fi
    (cd "$build" && ctest -T memcheck --output-on-failure --parallel "$jobs" -E "$valgrind_exclude" \
        --overwrite MemoryCheckCommand="$(command -v valgrind)" \
        --overwrite MemoryCheckCommandOptions="$valgrind_options")
    elapsed "valgrind (ctest -T memcheck)" "$start"
}

run_fuzz() {
    local start variant flags binary work
    start=$(date +%s)
    command -v clang >/dev/null 2>&1 || { echo "check-tools: clang is not installed (scripts/deps.sh test)" >&2; exit 1; }
    mkdir -p "$fuzz_build"
    for variant in float double_checked; do
        flags=()
        [ "$variant" = double_checked ] && flags=(-DMOTUS_DOUBLE -DMOTUS_CHECKED)
        binary="$fuzz_build/fuzz_motus_$variant"
        echo "check-tools: clang -fsanitize=fuzzer,address,undefined ${flags[*]} tests/fuzz/fuzz_motus.c"
        clang -std=c99 -g -O1 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer \
              -ffp-contract=off -Wall -Wextra -Wpedantic -Werror "${flags[@]}" -Iinclude tests/fuzz/fuzz_motus.c \
              -o "$binary" -lm
        # New inputs go to a scratch directory, never into the committed corpus; a crash leaves its input in
        # $fuzz_build/crash-* (replay it: $binary that-file).
        work="$fuzz_build/corpus_$variant"
        mkdir -p "$work"
        # libFuzzer prints a line per new input (thousands): they go to a log, which is shown if it fails.
        if ! "$binary" -max_total_time="$fuzz_seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
                       -artifact_prefix="$fuzz_build/$variant-" "$work" tests/fuzz/corpus >"$fuzz_build/$variant.log" 2>&1
        then
            grep -v -E '^#[0-9]+[[:space:]]+(NEW|REDUCE|pulse)' "$fuzz_build/$variant.log" | tail -n 80 >&2 || true
            echo "check-tools: fuzz $variant failed; full log: $fuzz_build/$variant.log" >&2
            exit 1
        fi
        grep -E '^(#[0-9]+[[:space:]]+DONE|Done|stat::|INFO: seed corpus)' "$fuzz_build/$variant.log" || true
    done
    elapsed "fuzz (2 builds, 2 x $fuzz_seconds s)" "$start"
}

for part in "${parts[@]}"; do
    case "$part" in
        asan) run_asan ;;
        valgrind) run_valgrind ;;
        fuzz) run_fuzz ;;
        *) echo "usage: $0 [asan] [valgrind] [fuzz]" >&2; exit 2 ;;
    esac
done
