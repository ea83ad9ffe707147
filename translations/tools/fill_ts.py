#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Fills translations into a catalogue from a batch file, then reports what is left.

    python3 translations/tools/fill_ts.py translations/xytune_pt_BR.ts BATCH.py [BATCH.py ...]

A batch file is Python defining T, a dict from source text to its translation (a string, or for
a %n message the list of plural forms); a key (context, source) applies to that context only
and wins over a plain key. A message is filled when a key matches and its translation shows no
problem (check_ts.py's checks); a problem is printed and the message left as it was.
"""
import runpy
import sys

import ts_catalogue as ts


def main(argv):
    if len(argv) < 3:
        print(__doc__)
        return 2
    table = {}
    for batch in argv[2:]:
        table.update(runpy.run_path(batch)["T"])
    tree = ts.load(argv[1])
    filled = rejected = left = 0
    for context, message in ts.messages(tree):
        source = ts.source_of(message)
        value = table.get((context, source), table.get(source))
        if value is None:
            if ts.state_of(message) == "unfinished":
                left += 1
            continue
        forms = list(value) if isinstance(value, (list, tuple)) else [value]
        if ts.is_plural(message) and len(forms) == 1:
            forms = forms * 2
        issues = ts.problems(source, forms, ts.is_plural(message))
        if issues:
            for p in issues:
                print("REJECTED %s: %r: %s" % (context, source, p))
            rejected += 1
            continue
        ts.set_translation(message, forms if ts.is_plural(message) else forms[0])
        filled += 1
    ts.save(tree, argv[1])
    print("filled %d, rejected %d, still unfinished %d" % (filled, rejected, left))
    return 1 if rejected else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
