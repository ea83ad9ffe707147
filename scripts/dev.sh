#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# XY Tune set-up: installs the Debian 12 packages that are missing, builds, then
#   scripts/dev.sh run    starts the workbench (or the headless report without a display)
#   scripts/dev.sh test   runs every test
#   scripts/dev.sh bench  builds and runs the benchmark program
set -euo pipefail

mode="${1:-run}"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${XYT_BUILD_DIR:-$root/build}"

packages=(build-essential cmake pkg-config qt6-base-dev libqcustomplot-dev libqcustomplot2.1-qt6
          libeigen3-dev libgl1-mesa-dev libxkbcommon-dev xvfb xauth)
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
