#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Makes the documentation's screenshots from the program itself:
#   scripts/make_screenshots.sh BUILD_DIR OUT_DIR [LIST]
# runs BUILD_DIR/app/xytune --screenshot OUT_DIR/<name>.png --size <size> --tab "<tab>" <session>
# for each line "name | tab | size | session" of LIST (docs/screenshots.txt by default; '#' starts
# a comment; sessions are relative to the repository root). Exits 1 naming every shot that could
# not be made (a tab renamed, a session that no longer loads). To refresh the committed images:
#   scripts/make_screenshots.sh build docs/images
set -u
if [ $# -lt 2 ]; then
    echo "usage: $0 BUILD_DIR OUT_DIR [LIST]" >&2
    exit 2
fi
root="$(cd "$(dirname "$0")/.." && pwd)"
xytune="$(cd "$1" && pwd)/app/xytune"
mkdir -p "$2"
out="$(cd "$2" && pwd)"
list="${3:-$root/docs/screenshots.txt}"
if [ ! -x "$xytune" ]; then
    echo "$0: no program $xytune" >&2
    exit 2
fi
trim() { local s="$1"; s="${s#"${s%%[![:space:]]*}"}"; printf '%s' "${s%"${s##*[![:space:]]}"}"; }
failed=0
made=0
while IFS='|' read -r name tab size session; do
    name="$(trim "$name")"
    [ -z "$name" ] || [ "${name:0:1}" = "#" ] && continue
    tab="$(trim "$tab")"
    size="$(trim "$size")"
    session="$(trim "$session")"
    if ! (cd "$root" && QT_QPA_PLATFORM=offscreen "$xytune" --screenshot "$out/$name.png" \
              --size "$size" --tab "$tab" "$session" > /dev/null); then
        echo "$0: $name: could not be made (tab '$tab', session $session)" >&2
        failed=$((failed + 1))
        continue
    fi
    made=$((made + 1))
done < "$list"
echo "$made screenshot(s) in $out"
[ "$failed" -eq 0 ] || { echo "$0: $failed screenshot(s) failed" >&2; exit 1; }
