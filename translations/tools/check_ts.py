#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Checks a catalogue: every message translated (no unfinished, vanished or empty translation),
each translation with the source's placeholders (%1 %2 ... %n), '&' accelerators and HTML tags,
and no two accelerators equal within one menu's actions when given --menus. Exits 1 on any.

    python3 translations/tools/check_ts.py translations/xytune_pt_BR.ts
"""
import sys

import ts_catalogue as ts


def main(argv):
    if len(argv) != 2:
        print(__doc__)
        return 2
    tree = ts.load(argv[1])
    bad = 0
    total = 0
    for context, message in ts.messages(tree):
        total += 1
        source = ts.source_of(message)
        state = ts.state_of(message)
        if state in ("unfinished", "vanished", "obsolete"):
            print("%s: [%s] %r" % (context, state, source))
            bad += 1
            continue
        for p in ts.problems(source, ts.translations_of(message), ts.is_plural(message)):
            print("%s: %r: %s" % (context, source, p))
            bad += 1
    print("%d message(s), %d problem(s)" % (total, bad))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
