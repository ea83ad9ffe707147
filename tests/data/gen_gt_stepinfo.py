#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Step-response figures of the two Guillemin-Truxal closed loops of Braga et al., with scipy.

Octave's control package 3.4 has no stepinfo, so this computes them independently of the C++
code: the unit step response is written in closed form from the partial fractions of T(s)/s
(scipy.signal.residue), the last exit from the 2 % band is bracketed on a 1e6-point grid and
refined with scipy.optimize.brentq, the peak with scipy.optimize.minimize_scalar.

Regenerate (from this folder):  /usr/bin/python3 gen_gt_stepinfo.py > gt_stepinfo.csv
"""
import numpy as np
from scipy import optimize, signal

DESIGNS = [  # name, k0, a1, a2, wn, kp (Braga et al. Sec. 3.1 and 3.2)
    ("lower-base", 77.8, 125.3, 3665.0, 2.0, 30.0),
    ("upper-base", 24.44, 68.18, 863.0, 1.0, 30.0),
]
BAND = 0.02


def step_response(num, den):
    """y(t) of the unit step response, from the residues of num / (den * s)."""
    r, p, k = signal.residue(num, np.polymul(den, [1.0, 0.0]))
    assert len(k) == 0 and len(set(np.round(p, 9))) == len(p), "simple poles only"

    def y(t):
        return np.real(np.exp(np.multiply.outer(t, p)) @ r)

    return y, np.roots(den)


print("system,final_value,settling_time,overshoot_pct,peak_time")
for name, k0, a1, a2, wn, kp in DESIGNS:
    ki = kp * wn**4 / (kp * k0)
    num = np.polymul([kp, ki], [k0])                      # Gc G numerator
    den_ol = np.polymul([1.0, 0.0], [1.0, a1, a2, 0.0])  # Gc G denominator
    den = np.polyadd(den_ol, num)                         # unity feedback
    y, poles = step_response(num, den)
    final = num[-1] / den[-1]
    horizon = 12.0 / min(-poles.real)
    t = np.linspace(0.0, horizon, 1_000_001)
    yt = y(t)
    outside = np.nonzero(np.abs(yt - final) > BAND * abs(final))[0]
    last = outside[-1]
    target = final + np.sign(yt[last] - final) * BAND * abs(final)
    settling = optimize.brentq(lambda x: float(y(x)) - target, t[last], t[last + 1], xtol=1e-14)
    ipeak = int(np.argmax(yt))
    lo, hi = t[max(ipeak - 1, 0)], t[min(ipeak + 1, len(t) - 1)]
    peak = optimize.minimize_scalar(lambda x: -float(y(x)), bounds=(lo, hi), method="bounded",
                                    options={"xatol": 1e-12})
    overshoot = max(0.0, (-peak.fun - final) / abs(final) * 100.0)
    print(f"{name},{final:.17g},{settling:.17g},{overshoot:.17g},{peak.x:.17g}")
