#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Fails (exit 1) naming each C/C++ source that the committed .clang-format would change.
# The architecture fixtures are excluded: they are inputs the checks must refuse, kept as written.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
    mapfile -t files < <(git ls-files '*.cpp' '*.h' '*.c' | grep -v '^tests/architecture/fixture')
else
    mapfile -t files < <(find app core ui tests \( -name '*.cpp' -o -name '*.h' -o -name '*.c' \) \
                         -not -path 'tests/architecture/fixture*' | sort)
fi
if ! clang-format-14 --dry-run -Werror "${files[@]}"; then
    echo "clang-format: the files above differ from .clang-format (fix: clang-format-14 -i FILE)" >&2
    exit 1
fi
echo "clang-format: ${#files[@]} files follow .clang-format"
