#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Builds the libFuzzer harnesses of tests/fuzz/ with clang (-DXYT_FUZZ=ON, in build-fuzz) and runs
# each for a bounded time:   scripts/fuzz.sh [seconds per harness, default 20]
# Starts from the committed corpus tests/fuzz/corpus/<harness>/ (read only); new inputs go to
# build-fuzz/corpus/<harness>/. A crash, a sanitizer report, a NaN in a valid result, a hang
# (> 10 s on one input) or more than 2 GB of memory stops that harness, and the script exits non-zero; the
# input is saved as build-fuzz/artifacts/<harness>/crash-*: fix the defect and commit the input
# to tests/fuzz/corpus/<harness>/ so that ctest replays it (replay_<harness>) from then on.
set -euo pipefail

seconds="${1:-20}"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${XYT_FUZZ_BUILD_DIR:-$root/build-fuzz}"
jobs="$(nproc 2>/dev/null || echo 2)"
harnesses=(fuzz_coefficients fuzz_design fuzz_session_loader fuzz_gcode_reader
           fuzz_delimited_reader fuzz_lvm_reader fuzz_mat_reader fuzz_accelerometer_log)
# XYT_FUZZ_HARNESSES="fuzz_lvm_reader fuzz_mat_reader" builds and runs only those.
if [ -n "${XYT_FUZZ_HARNESSES:-}" ]; then
    read -r -a harnesses <<< "$XYT_FUZZ_HARNESSES"
fi

cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DXYT_FUZZ=ON \
      -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++
cmake --build "$build" -j "$jobs" --target "${harnesses[@]}"

# The harnesses run side by side, one per core (each is single-threaded); each one's output is
# kept and printed in order when all are done, with the harnesses that failed named.
logs="$(mktemp -d)"
trap 'rm -rf "$logs"' EXIT
run_harness() {
    local h="$1"
    # XYT_FUZZ_RUNS=N (set by scripts/dev.sh test) makes the run reproducible: a fixed number of
    # inputs from a fixed seed, so CI cannot turn red on a random draw; the time stays a bound.
    local limits=(-max_total_time="$seconds")
    if [ -n "${XYT_FUZZ_RUNS:-}" ]; then
        limits+=(-runs="$XYT_FUZZ_RUNS" -seed=1)
    fi
    if "$build/tests/fuzz/$h" "${limits[@]}" -timeout=10 -rss_limit_mb=2048 \
        -artifact_prefix="$build/artifacts/$h/" -print_final_stats=1 \
        "$build/corpus/$h" "$root/tests/fuzz/corpus/$h" > "$logs/$h.log" 2>&1; then
        echo 0 > "$logs/$h.rc"
    else
        echo "$?" > "$logs/$h.rc"
    fi
}
for h in "${harnesses[@]}"; do
    mkdir -p "$build/corpus/$h" "$build/artifacts/$h"
    while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do wait -n || true; done
    run_harness "$h" &
done
wait
failed=()
for h in "${harnesses[@]}"; do
    echo "== $h: ${seconds} s"
    cat "$logs/$h.log"
    [ "$(cat "$logs/$h.rc" 2>/dev/null || echo missing)" = 0 ] || failed+=("$h")
done
if [ "${#failed[@]}" -gt 0 ]; then
    echo "fuzz: failed: ${failed[*]} (inputs that failed are in $build/artifacts/)" >&2
    exit 1
fi
echo "fuzz: every harness ran (${XYT_FUZZ_RUNS:-unbounded} inputs, at most ${seconds} s) without a failure"
