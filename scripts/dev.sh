#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# XY Tune set-up: installs the Debian 12 packages that are missing, builds, then
#   scripts/dev.sh run    starts the workbench (or the headless report without a display)
#   scripts/dev.sh test   runs every test: the format check, the normal build, then one clang build with
#                         AddressSanitizer + UndefinedBehaviorSanitizer and libFuzzer coverage
#                         (build-fuzz) in which the core, file-format and presenter suites and
#                         a GUI smoke test run again (any sanitizer report fails) and each
#                         libFuzzer harness runs on 8000 inputs from a fixed seed
#   scripts/dev.sh bench  builds and runs the benchmark program
set -euo pipefail

mode="${1:-run}"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${XYT_BUILD_DIR:-$root/build}"

packages=(build-essential cmake pkg-config qt6-base-dev libqcustomplot-dev libqcustomplot2.1-qt6
          libeigen3-dev libmatio-dev libgl1-mesa-dev libxkbcommon-dev xvfb xauth
          clang libclang-rt-14-dev clang-format-14 ninja-build
          dpkg-dev file appstream desktop-file-utils groff-base poppler-utils lintian
          qt6-tools-dev qt6-tools-dev-tools qt6-l10n-tools qt6-translations-l10n)
missing=()
for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ "${#missing[@]}" -gt 0 ]; then
    echo "Installing missing Debian packages: ${missing[*]}"
    sudo_cmd=()
    [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
    "${sudo_cmd[@]}" apt-get update -q
    DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

jobs="$(nproc 2>/dev/null || echo 2)"
# The committed .clang-format holds for every source: checked first, it costs a second.
if [ "$mode" = test ]; then bash "$root/scripts/check_format.sh"; fi
# Ninja for a new build directory (it schedules the ~500 steps better than make's recursive
# makefiles); a directory configured before keeps the generator it has, as CMake requires.
generator_for() { [ -f "$1/CMakeCache.txt" ] || echo "-GNinja"; }
# -g1 (line tables and function names: what a backtrace needs) rather than -g: full debug
# information is about a fifth of what the optimized core and widget files cost to compile.
# For a debugger's view of locals, configure a Debug build of your own.
cmake -S "$root" -B "$build" $(generator_for "$build") -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG" "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG"
cmake --build "$build" -j "$jobs"

case "$mode" in
    run)
        if [ -x "$build/app/xytune" ] && [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]; then
            exec "$build/app/xytune"
        fi
        if [ -x "$build/app/xytune" ]; then
            echo "No display found (DISPLAY and WAYLAND_DISPLAY are unset): printing the headless report instead." >&2
        fi
        exec "$build/app/xytune-cli" report
        ;;
    test)
        ctest --test-dir "$build" --output-on-failure -j "$jobs"

        # One instrumented build for two jobs: clang with AddressSanitizer + UBSan and libFuzzer's
        # coverage instrumentation (-DXYT_FUZZ=ON, in build-fuzz). What sanitizing can find runs
        # again in it: the core, file-format and presenter suites, the job runner with its
        # views and one GUI smoke test (tests/ui/CMakeLists.txt says which), then each libFuzzer
        # harness; not the programs or their CLI suites (tests/CMakeLists.txt says why). Line tables are
        # all the debug information a sanitizer report needs (and build much faster than -g).
        # -O2, not the -O1 AddressSanitizer's documentation suggests: measured from fresh clones,
        # -O1 made this stage slower (18 + 4 min against 15.5 + 3), the instrumented sweeps
        # running longer than the build saved.
        # -fno-sanitize-recover=all (CMakeLists.txt) makes every UBSan report fatal;
        # halt_on_error does the same for ASan, and a leak report makes the process exit
        # non-zero, so any report fails its test.
        fuzz_build="${XYT_FUZZ_BUILD_DIR:-$root/build-fuzz}"
        sanitizer_env=(ASAN_OPTIONS="halt_on_error=1:abort_on_error=1:detect_leaks=1:strict_init_order=1:check_initialization_order=1:detect_stack_use_after_return=1"
                       UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1")
        cmake -S "$root" -B "$fuzz_build" $(generator_for "$fuzz_build") \
              -DCMAKE_BUILD_TYPE=RelWithDebInfo -DXYT_FUZZ=ON \
              -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
              "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -gline-tables-only -DNDEBUG" \
              "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O2 -gline-tables-only -DNDEBUG"
        cmake --build "$fuzz_build" -j "$jobs"
        env "${sanitizer_env[@]}" ctest --test-dir "$fuzz_build" --output-on-failure -j "$jobs"

        # Every fuzz harness on a fixed seed and input count: reproducible, so a red run is a
        # real regression (open-ended exploration: scripts/fuzz.sh SECONDS without XYT_FUZZ_RUNS).
        XYT_FUZZ_RUNS=8000 XYT_FUZZ_BUILD_DIR="$fuzz_build" bash "$root/scripts/fuzz.sh" 120
        ;;
    bench)
        cmake --build "$build" --target xytune-bench -j "$jobs"
        exec "$build/app/xytune-bench"
        ;;
    *)
        echo "usage: scripts/dev.sh run|test|bench" >&2
        exit 2
        ;;
esac
