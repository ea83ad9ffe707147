#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
# Independent reference gains for tests/core/tst_root_locus.cpp, computed with numpy/scipy by a
# different method than the core: the stability-boundary gains by bracketing the sign change
# of the stability margin (max Re s, or max |z| - 1) of numpy.roots(D + K N) on a log grid of K
# and refining with scipy.optimize.brentq; the breakaway gains from numpy.roots of
# N D' - N' D. Regenerate: /usr/bin/python3 tests/data/gen_root_locus.py > tests/data/root_locus_reference.json
import json
import numpy as np
from scipy.optimize import brentq

def gt(k0, a1, a2, wn, kp):
    ki = wn ** 4 / k0  # kp * psi1, psi1 = wn^4 / (kp k0): Braga et al. Eq. 11, 16
    return [k0 * kp, k0 * ki], [1.0, a1, a2, 0.0, 0.0]

def zinv_to_z(b, a):
    n = max(len(b), len(a)) - 1
    return list(b) + [0.0] * (n + 1 - len(b)), list(a) + [0.0] * (n + 1 - len(a))

loops = []
num, den = [1.0], [1.0, 3.0, 2.0, 0.0]
loops.append(("type1", num, den, 0.0))
loops.append(("double_integrator_lead", [1.0, 1.0], [1.0, 10.0, 0.0, 0.0], 0.0))
loops.append(("z_double_pole_zero", [1.0, 0.5], [1.0, -1.0, 0.25], 0.1))
loops.append(("z_double_pole", [1.0], [1.0, -1.0, 0.25], 0.1))
# Patrick, Ishak and Adnan Eq. 1, x axis: B, A in ascending powers of z^-1, Ts = 0.07 s; in descending powers
# of z: multiply both by z^3 (pad to the same length).
b, a = zinv_to_z([0.0, 0.0421, 0.0628, -0.0454], [1.0, -1.6580, 0.6583])
loops.append(("arx_x_axis", b, a, 0.07))
loops.append(("gt_lower_base", *gt(77.8, 125.3, 3665.0, 2.0, 30.0), 0.0))
loops.append(("gt_upper_base", *gt(24.44, 68.18, 863.0, 1.0, 30.0), 0.0))

def char(num, den, k):
    n = np.zeros(len(den))
    n[len(den) - len(num):] = num
    return np.array(den) + k * n

def margin(num, den, ts, k):
    r = np.roots(char(num, den, k))
    return (np.max(np.abs(r)) - 1.0) if ts > 0 else np.max(r.real)

out = []
for name, num, den, ts in loops:
    ks = np.logspace(-6, 6, 20001)
    m = np.array([margin(num, den, ts, k) for k in ks])
    crossings = []
    for i in range(len(ks) - 1):
        if np.sign(m[i]) != np.sign(m[i + 1]) and m[i] != 0.0:
            kc = brentq(lambda k: margin(num, den, ts, k), ks[i], ks[i + 1], xtol=1e-14, rtol=1e-15)
            r = np.roots(char(num, den, kc))
            dist = np.abs(np.abs(r) - 1.0) if ts > 0 else np.abs(r.real)
            p = r[np.argmin(dist)]
            crossings.append({"k": kc, "re": float(p.real), "im": float(abs(p.imag))})
    nd = np.polysub(np.polymul(num, np.polyder(den)), np.polymul(np.polyder(num), den))
    breakaways = []
    for s in np.roots(nd):
        dv, nv = np.polyval(den, s), np.polyval(num, s)
        if abs(nv) == 0.0 or abs(dv) < 1e-10 * np.polyval(np.abs(den), abs(s)):
            continue
        k = -dv / nv
        if k.real > 0 and abs(k.imag) <= 1e-6 * abs(k):
            breakaways.append({"re": float(s.real), "im": float(s.imag), "k": float(k.real)})
    breakaways.sort(key=lambda f: f["k"])
    out.append({"name": name, "num": num, "den": den, "ts": ts,
                "crossings": crossings, "breakaways": breakaways})

print(json.dumps({"generator": "gen_root_locus.py", "numpy": np.__version__,
                  "scipy": __import__("scipy").__version__, "loops": out}, indent=1))
