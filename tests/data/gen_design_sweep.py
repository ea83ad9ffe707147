#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
# Reference step figures of Guillemin-Truxal closed loops G_R (Braga et al. Eq. 7) of the lower
# base (Eq. 2), from the analytic step response y(t) = 1 + sum_i r_i e^{p_i t},
# r_i = N(p_i) / (p_i D'(p_i)) (distinct poles), independent of XY Tune's discretization.
# Settling time (2 % band): last crossing of |y - 1| = 0.02, bracketed on a dense log-spaced
# grid and solved with scipy.optimize.brentq. Overshoot: max of y on the dense grid, refined by
# scipy.optimize.minimize_scalar around the best sample.
# Run: /usr/bin/python3 tests/data/gen_design_sweep.py > tests/data/design_sweep_step.csv
import numpy as np
from scipy.optimize import brentq, minimize_scalar

K0, A1, A2 = 77.8, 125.3, 3665.0


def figures(wn, kp):
    k, w = kp * K0, wn ** 4
    p = np.roots([1.0, A1, A2, k, w])
    r = (k * p + w) / (p * (4 * p ** 3 + 3 * A1 * p ** 2 + 2 * A2 * p + k))

    def y(t):
        return 1.0 + np.real(np.exp(np.multiply.outer(t, p)) @ r)

    slow = min(-p.real)
    t = np.concatenate([[0.0], np.geomspace(1e-4, 40.0 / slow, 400001)])
    ys = y(t)
    outside = np.nonzero(np.abs(ys - 1.0) > 0.02)[0]
    k_last = outside[-1]
    g = lambda s: abs(y(np.array([s]))[0] - 1.0) - 0.02
    settling = brentq(g, t[k_last], t[k_last + 1], xtol=1e-14, rtol=1e-15)
    i = int(np.argmax(ys))
    lo, hi = t[max(i - 1, 0)], t[min(i + 1, len(t) - 1)]
    res = minimize_scalar(lambda s: -y(np.array([s]))[0], bounds=(lo, hi), method="bounded",
                          options={"xatol": 1e-12 * hi})
    peak = max(-res.fun, ys[i])
    return settling, (peak - 1.0) * 100.0


print("wn,kp,settling_time,overshoot_pct")
for wn, kp in [(2.0, 30.0), (0.5, 30.0), (0.2, 30.0), (1.0, 10.0), (5.0, 100.0), (0.1, 1.0)]:
    s, o = figures(wn, kp)
    print(f"{wn},{kp},{s:.12g},{o:.12g}")
