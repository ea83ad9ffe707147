#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# XY Tune set-up: installs the Debian 12 packages that are missing, builds, then
#   scripts/dev.sh run    starts the workbench (or the headless report without a display)
#   scripts/dev.sh test   runs every test: the normal build, then the whole suite again in an
#                         AddressSanitizer + UndefinedBehaviorSanitizer build (build-asan; any
#                         sanitizer report fails), then each libFuzzer harness on 8000
#                         inputs from a fixed seed (scripts/fuzz.sh, clang build in build-fuzz)
#   scripts/dev.sh bench  builds and runs the benchmark program
set -euo pipefail

mode="${1:-run}"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${XYT_BUILD_DIR:-$root/build}"

packages=(build-essential cmake pkg-config qt6-base-dev libqcustomplot-dev libqcustomplot2.1-qt6
          libeigen3-dev libgl1-mesa-dev libxkbcommon-dev xvfb xauth
          clang libclang-rt-14-dev)
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
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo
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

        # The same suite, GUI tests included (offscreen), instrumented with ASan + UBSan.
        # RelWithDebInfo rather than Debug: unoptimized Eigen under ASan makes the sweep and
        # simulation tests many times slower without finding more. -fno-sanitize-recover=all
        # (CMakeLists.txt) makes every UBSan report fatal; halt_on_error does the same for ASan,
        # and a leak report makes the process exit non-zero, so any report fails its test.
        asan_build="${XYT_ASAN_BUILD_DIR:-$root/build-asan}"
        cmake -S "$root" -B "$asan_build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DXYT_SANITIZE=ON
        cmake --build "$asan_build" -j "$jobs"
        ASAN_OPTIONS="halt_on_error=1:abort_on_error=1:detect_leaks=1:strict_init_order=1:check_initialization_order=1:detect_stack_use_after_return=1" \
        UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1" \
            ctest --test-dir "$asan_build" --output-on-failure -j "$jobs"

        # Every fuzz harness for a short, bounded time (a crash fails the run).
        if command -v clang++ >/dev/null 2>&1; then
            # A fixed seed and input count: reproducible, so a red run is a real regression.
            # Open-ended exploration: scripts/fuzz.sh SECONDS without XYT_FUZZ_RUNS.
            XYT_FUZZ_RUNS=8000 bash "$root/scripts/fuzz.sh" 120
        else
            echo "clang++ not found: skipping the libFuzzer runs (the corpora were replayed by ctest)" >&2
        fi
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
