#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Reference data for tests/core/tst_diophantine.cpp and tests/core/tst_zpetc.cpp.

Independent of the C++ code: the Diophantine equation A F + B G = T is set up by stacking
convolution matrices built with numpy.convolve of unit vectors and solved with numpy.linalg.lstsq;
the closed loops are simulated with scipy.signal.lfilter on the closed-loop transfer functions
(not on the RST recursion the C++ code runs), the ZPETC factors come from numpy.roots.

Run:  /usr/bin/python3 tests/data/gen_pp_zpetc.py   (from the repository root)
Writes tests/data/pp_diophantine_random.json and tests/data/pp_zpetc_paper.csv.
"""
import json
import os

import numpy as np
from scipy.signal import lfilter

HERE = os.path.dirname(os.path.abspath(__file__))


def conv_matrix(p, cols, rows):
    """Column j holds p shifted by j (p(z^-1) * z^-j), built by convolving unit vectors."""
    m = np.zeros((rows, cols))
    for j in range(cols):
        e = np.zeros(j + 1)
        e[j] = 1.0
        c = np.convolve(p, e)
        m[: len(c), j] = c
    return m


def solve_diophantine(a, b, t):
    na, nb, nt = len(a) - 1, len(b) - 1, len(t) - 1
    nf = max(nb - 1, nt - na, 0)
    ng = na - 1
    rows = na + nf + 1
    m = np.hstack([conv_matrix(a, nf + 1, rows), conv_matrix(b, ng + 1, rows)])
    rhs = np.zeros(rows)
    rhs[: nt + 1] = t
    x, *_ = np.linalg.lstsq(m, rhs, rcond=None)
    return x[: nf + 1], x[nf + 1:]


def random_cases(rng, count):
    cases = []
    while len(cases) < count:
        na = int(rng.integers(1, 5))
        d = int(rng.integers(1, 3))
        nbp = int(rng.integers(0, 4))  # zeros of B
        poles = rng.uniform(-1.2, 1.2, na)
        zeros = rng.uniform(-2.5, 2.5, nbp)
        a = np.poly(poles)  # monic in z == monic in z^-1 read ascending
        b = np.concatenate([np.zeros(d), rng.uniform(0.02, 2.0) * np.atleast_1d(np.poly(zeros))])
        # Keep plants whose poles and zeros are well apart (a common factor has no solution).
        if nbp and min(abs(p - z) for p in poles for z in zeros) < 0.05:
            continue
        nt = int(rng.integers(1, na + len(b) - 1 + 1))
        t = np.poly(rng.uniform(-0.8, 0.8, nt))
        f, g = solve_diophantine(a, b, t)
        cases.append({"a": a.tolist(), "b": b.tolist(), "t": t.tolist(),
                      "f": f.tolist(), "g": g.tolist()})
    return cases


PAPER = {
    "x": ([1, -1.6580, 0.6583], [0, 0.0421, 0.0628, -0.0454], 0.0),
    "y": ([1, -1.4590, 0.4587], [0, 0.0352, 0.0599, -0.0067], np.pi / 2),
}


def paper_runs():
    ts, n, amp, w = 0.07, 898, 30.0, 0.1
    t_poly = np.array([1.0, -0.2])
    cols = {}
    for axis, (a, b, phase) in PAPER.items():
        b = np.array(b, float)
        kf = t_poly.sum() / b.sum()
        num = kf * b  # closed loop Kf B / T
        bc = num[1:]  # z^-1 Bc = Kf B, d = 1
        zeros = np.roots(bc)
        plus = [z for z in zeros if abs(z) < 0.95]
        minus = [z for z in zeros if abs(z) >= 0.95]
        bplus = np.real(np.poly(plus))
        bminus = bc[0] * np.real(np.poly(minus))
        s = len(minus)
        p = 1 + s
        ffnum = np.convolve(t_poly, bminus[::-1])
        ffden = bplus * bminus.sum() ** 2
        k = np.arange(n + p)
        r = amp * np.sin(w * k * ts + phase)
        for start in ("reference", "origin"):
            # 'reference': the reference extended backwards by r(0) for 400 samples; the slowest
            # mode (pole 0.53 of the feedforward) decays to 1e-110 over that span.
            pre = 400 if start == "reference" else 0
            rr = np.concatenate([np.full(pre, r[0]), r]) if pre else r.copy()
            y1 = lfilter(num, t_poly, rr)[pre:pre + n]
            uff = lfilter(ffnum, ffden, rr)  # u_ff at k = i - p reads r(i)
            y2 = lfilter(num, t_poly, uff)[pre + p:pre + p + n]
            cols[f"{axis}_{start}_y_feedback"] = y1
            cols[f"{axis}_{start}_y_zpetc"] = y2
        cols[f"{axis}_r"] = r[:n]
    return cols


def main():
    rng = np.random.default_rng(20261122)
    with open(os.path.join(HERE, "pp_diophantine_random.json"), "w") as fh:
        json.dump({"generator": "gen_pp_zpetc.py (numpy %s)" % np.__version__,
                   "cases": random_cases(rng, 40)}, fh, indent=1)
    cols = paper_runs()
    names = ["x_r", "y_r"] + sorted(c for c in cols if not c.endswith("_r"))
    with open(os.path.join(HERE, "pp_zpetc_paper.csv"), "w") as fh:
        fh.write("k," + ",".join(names) + "\n")
        for k in range(len(cols["x_r"])):
            fh.write(str(k) + "," + ",".join("%.17g" % cols[c][k] for c in names) + "\n")


if __name__ == "__main__":
    main()
