#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Writes the seed inputs of tests/fuzz/corpus/fuzz_design/ (paper designs encoded in the byte
format that tests/fuzz/fuzz_support.h FuzzInput decodes). Plain Python 3, no packages:
    python3 tests/fuzz/make_seeds.py
Crash-regression inputs found by libFuzzer are committed next to these files, not made here."""
import math
import os
import struct

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus", "fuzz_design")


def number(v):
    """FuzzInput::number: kind byte (>= 16; kind % 25 = e + 12; bit 7 = sign), then the
    mantissa m in [1, 10) as 1 + 9 w / 65536, w little-endian."""
    if v == 0.0:
        return bytes([0])
    e = math.floor(math.log10(abs(v)))
    m = abs(v) / 10.0 ** e
    w = min(65535, round((m - 1.0) / 9.0 * 65536.0))
    base = 128 if v < 0 else 0
    kind = next(k for k in range(base, base + 128) if k >= 16 and k % 25 == e + 12)
    return bytes([kind]) + struct.pack("<H", w)


def within(f):
    """FuzzInput::within(lo, hi): the fraction f of the range as a 16-bit word."""
    return struct.pack("<H", round(f * 65535))


def count(n, lo, hi=None):
    """FuzzInput::integer(lo, hi): n - lo as one byte, or as a word when hi - lo >= 256."""
    if hi is not None and hi - lo >= 256:
        return struct.pack("<H", n - lo)
    return bytes([n - lo])


def coefficients(values, lo):
    return count(len(values), lo) + b"".join(number(v) for v in values)


def gt(k0, a1, a2, wn, kp, dt_fraction, steps, saturate):
    # mode 0; plant, wn, kp; dt within(1e-4, 0.5); steps integer(1, 400); xf within(-1000, 1000);
    # saturation flag + umax within(1e-3, 100); unit flag; locus maxPoints integer(10, 2000)
    s = bytes([0]) + b"".join(number(v) for v in (k0, a1, a2, wn, kp))
    s += within(dt_fraction) + count(steps, 1, 400) + within(0.8)
    s += bytes([1]) + within(0.025) if saturate else bytes([0])
    return s + bytes([1]) + count(1000, 10, 2000)


def pp(a, b_after_delay, t_tail, ts, diophantine_only=False):
    # mode 1; a (1..6); delay (1..3) and b (1..6); "no delay" selector; t tail (0..5);
    # Diophantine-only selector; ts; margin selector; grid points; amplitude, omega, duration
    s = bytes([1]) + coefficients(a, 1) + count(1, 1) + coefficients(b_after_delay, 1)
    s += bytes([1]) + coefficients(t_tail, 0)
    s += bytes([0 if diophantine_only else 1])
    s += number(ts) + bytes([1]) + count(20, 2) + within(0.03) + within(0.01) + count(200, 0, 300)
    return s + bytes([1])


def locus(den, num, ts):
    # mode 2; den (1..7) and num (1..7) ascending (s or z); continuous flag or ts; maxPoints
    s = bytes([2]) + coefficients(den, 1) + coefficients(num, 1)
    s += bytes([1]) if ts == 0 else bytes([0]) + number(ts)
    return s + count(1000, 10, 2000) + bytes([1, 1])


SEEDS = {
    # Braga et al.'s lower and upper base at their design points
    "gt_lower_base": gt(77.8, 125.3, 3665.0, 2.0, 30.0, 0.02, 300, True),
    "gt_upper_base": gt(24.44, 68.18, 863.0, 2.0, 30.0, 0.02, 300, False),
    "gt_unstable_choice": gt(77.8, 125.3, 3665.0, 50.0, 0.5, 0.1, 100, True),
    # Patrick, Ishak and Adnan's x axis: A, B after the delay, T = 1 - 0.2 z^-1, Ts = 70 ms
    "pp_paper_x_axis": pp([1.0, -1.6580, 0.6583], [0.0421, 0.0628, -0.0454], [-0.2], 0.07),
    "pp_paper_diophantine": pp([1.0, -1.6580, 0.6583], [0.0421, 0.0628, -0.0454], [-0.2], 0.07,
                               diophantine_only=True),
    "pp_common_factor": pp([1.0, -0.5], [1.0, -0.5], [-0.2], 0.07),
    # loops for the root locus: 1/(s(s+2)(s+5)) and a discrete one
    "locus_third_order": locus([0.0, 10.0, 7.0, 1.0], [1.0], 0.0),
    "locus_discrete": locus([0.5, -1.5, 1.0], [0.2, 1.0], 0.1),
}

os.makedirs(OUT, exist_ok=True)
for name, data in SEEDS.items():
    with open(os.path.join(OUT, name), "wb") as f:
        f.write(data)
print(f"wrote {len(SEEDS)} seeds to {OUT}")
