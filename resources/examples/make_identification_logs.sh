#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Makes the two SYNTHETIC experiment logs of resources/examples with XY Tune's own
# simulation: they are not measurements. Usage: make_identification_logs.sh path/to/xytune-cli
#  - synthetic_lower_base_square_10ms.lvm: Braga et al.'s lower base (k0 = 77.8 m/(V s^3) = 77 800
#    mm/(V s^3), a1 = 125.3, a2 = 3665) under a +-2.5 V square wave of 0.5 s period, logged at
#    10 ms for 20 s as LabVIEW would, with 0.02 mm rms white measurement noise (seed 1);
#  - synthetic_x_axis_prbs_70ms.csv: Patrick, Ishak and Adnan's x-axis ARX(2,3,1) model (A = 1 - 1.658 z^-1 +
#    0.6583 z^-2, B = 0.0421 z^-1 + 0.0628 z^-2 - 0.0454 z^-3) under a +-2 V PRBS (10-bit
#    register, one sample per bit) at 70 ms for 1023 samples, 0.05 mm rms noise (seed 2).
set -euo pipefail
cli="${1:?usage: make_identification_logs.sh path/to/xytune-cli}"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
"$cli" new -o "$tmp/guillemin_truxal.json" >/dev/null
# Patrick, Ishak and Adnan's axis: the same session with the x axis on pole placement (its default model).
sed '0,/"method": "guillemin-truxal"/s//"method": "pole-placement-zpetc"/' "$tmp/guillemin_truxal.json" > "$tmp/pole_placement.json"
"$cli" excite --signal square --ts 0.01 --duration 20 --amplitude 2.5 --period 0.5 \
    --respond "$tmp/guillemin_truxal.json" --axis x --noise-std 0.02 --seed 1 \
    -o "$here/synthetic_lower_base_square_10ms.lvm" >/dev/null
"$cli" excite --signal prbs --ts 0.07 --duration 71.61 --amplitude 2 --clock 1 --register 10 \
    --respond "$tmp/pole_placement.json" --axis x --noise-std 0.05 --seed 2 \
    -o "$here/synthetic_x_axis_prbs_70ms.csv" >/dev/null
echo "wrote $here/synthetic_lower_base_square_10ms.lvm and $here/synthetic_x_axis_prbs_70ms.csv"
