#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Runs the README's command-line examples with the xytune-cli of build folder $1 and writes each
# command's output (stdout and stderr, then its exit code) and every file it exported into
# folder $2. Two runs, before and after a refactoring, must give identical folders:
#   scripts/cli_examples.sh build-before out-before; ...; scripts/cli_examples.sh build out-after
#   diff -r out-before out-after
set -u
cli="$(cd "$1" && pwd)/app/xytune-cli"
mkdir -p "$2"
cd "$2"
run() { local name="$1"; shift; ( "$cli" "$@" 2>&1; echo "exit $?" ) > "$name.txt"; }
run gt_lower gt --preset lower-base --wn 2 --kp 30
run gt_upper gt --preset upper-base --wn 2 --kp 30
run gt_custom gt --k0 77.8 --a1 125.3 --a2 3665 --wn 2.5 --kp 40
run simulate_cubic simulate --preset lower-base --wn 2 --kp 30 --trajectory cubic --xf 600 --tf 130
run simulate_sine simulate --preset upper-base --wn 2 --kp 30 --trajectory sine --amplitude 25 --omega 0.2 --ramp-in 5
run report report
run pp_x pp --preset x-axis --t "1 -0.2"
run pp_y pp --preset y-axis --t "1 -0.2"
run zpetc_x zpetc --preset x-axis --t "1 -0.2" --amplitude 30 --omega 0.5
run contour contour --preset paper-zpetc
run rlocus_gt rlocus --gt-preset lower-base --wn 2 --kp 30
run rlocus_tf rlocus --num "1 2" --den "1 3 2 0"
run rlocus_z rlocus --num "0 0.0421 0.0628 -0.0454" --den "1 -1.658 0.6583" --ts 0.07
run sweep sweep --preset lower-base --wn 0.5:5:6 --kp 5:100:6 --log --trajectory cubic --xf 600 --tf 130 --max-overshoot 2
run bad_wn gt --preset lower-base --wn -1 --kp 30
rm -f session.json exported.*
run new new -o session.json
for f in json c m csv; do run "export_$f" export session.json --format "$f" -o "exported.$f"; done
