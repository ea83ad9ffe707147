#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Prints the unfinished messages of a catalogue as the skeleton of a batch for fill_ts.py.

    python3 translations/tools/dump_ts.py translations/xytune_pt_BR.ts [FIRST [COUNT]]
"""
import sys

import ts_catalogue as ts


def main(argv):
    if len(argv) < 2:
        print(__doc__)
        return 2
    first = int(argv[2]) if len(argv) > 2 else 0
    count = int(argv[3]) if len(argv) > 3 else 10**9
    seen = set()
    pending = []
    for context, message in ts.messages(ts.load(argv[1])):
        source = ts.source_of(message)
        if ts.state_of(message) == "unfinished" and source not in seen:
            seen.add(source)
            pending.append((context, source, ts.is_plural(message)))
    print("T = {")
    for context, source, plural in pending[first:first + count]:
        print("    # %s%s" % (context, " (plural)" if plural else ""))
        print("    %r: %s," % (source, "['', '']" if plural else "''"))
    print("}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
