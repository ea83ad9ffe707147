#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Reference numbers for the LinuxCNC-pid feedforward check (PI + model-inverse FF1/FF2/FF3).

Independent of the C++ code; written from the specification only:
  plant   G(s) = k0 / (s^3 + a1 s^2 + a2 s), k0 = 77.8, a1 = 125.3, a2 = 3665 (Braga et al.,
          "lower base"), volts in, metres out; discretised exactly under ZOH with
          scipy.signal.tf2ss + cont2discrete(method='zoh'), Ts = 0.01 s, starting at rest.
  ref     cubic rest-to-rest r(t) = 600 (3 (t/130)^2 - 2 (t/130)^3) mm on [0, 130] s,
          sampled at k Ts, k = 0..13000 (13001 samples).
  loop    each sample: read y_mm(k Ts) (no quantisation), u(k) from LinuxCNC pid semantics
          (calc_pid, 2.8+): e = r - y, error_i += e Ts, cmd_d/cmd_dd/cmd_ddd by backward
          differences (at k = 0 previous command r_0, previous derivatives 0),
          u = P e + I error_i + FF1 cmd_d + FF2 cmd_dd + FF3 cmd_ddd, clipped to +-2.5 V
          (the script asserts no sample clips, so pid's anti-windup limit_state never acts),
          held over [k Ts, (k+1) Ts).
  gains   (mm units) P = 0.03, I = (2^4/k0) 0.001, FF1 = a2 0.001/k0, FF2 = a1 0.001/k0,
          FF3 = 0.001/k0.
Prints the RMSE of e over all 13001 samples (mm) for: 1 no FF; 2 FF from backward differences;
3 FF from the analytic derivatives of the cubic; 4 plant k0 x 1.1 (controller unchanged), with
and without FF; and the ratio case1/case2.

Run:  python3 tests/data/gen_pid_feedforward.py   (from the repository root; needs NumPy/SciPy,
      e.g. /usr/bin/python3 with Debian's python3-numpy and python3-scipy)
"""
import numpy as np
from scipy.signal import cont2discrete, tf2ss

K0, A1, A2 = 77.8, 125.3, 3665.0
TS, T0, TF, DIST = 0.01, 0.0, 130.0, 600.0
N = 13001
UMAX = 2.5
MM = 0.001  # metres per mm

P = 30.0 * MM
I = 2.0**4 / K0 * MM
FF = (A2 * MM / K0, A1 * MM / K0, MM / K0)

t = np.arange(N) * TS
tau = np.clip((t - T0) / (TF - T0), 0.0, 1.0)
r = DIST * (3 * tau**2 - 2 * tau**3)
inside = (t >= T0) & (t <= TF)
T = TF - T0
vel = np.where(inside, DIST * (6 * tau - 6 * tau**2) / T, 0.0)
acc = np.where(inside, DIST * (6 - 12 * tau) / T**2, 0.0)
jerk = np.where(inside, -12 * DIST / T**3, 0.0)


def plant(k0):
    A, B, C, D = tf2ss([k0], [1.0, A1, A2, 0.0])
    Ad, Bd, Cd, Dd, _ = cont2discrete((A, B, C, D), TS, method="zoh")
    assert np.allclose(Dd, 0.0)
    return Ad, Bd[:, 0], Cd[0]


def simulate(k0, ff=(0.0, 0.0, 0.0), analytic=False):
    Ad, Bd, Cd = plant(k0)
    x = np.zeros(Ad.shape[0])
    err_i = 0.0
    prev_cmd, prev_d, prev_dd = r[0], 0.0, 0.0
    e = np.empty(N)
    for k in range(N):
        y_mm = (Cd @ x) / MM
        e[k] = r[k] - y_mm
        err_i += e[k] * TS
        if analytic:
            cd, cdd, cddd = vel[k], acc[k], jerk[k]
        else:
            cd = (r[k] - prev_cmd) / TS
            cdd = (cd - prev_d) / TS
            cddd = (cdd - prev_dd) / TS
            prev_cmd, prev_d, prev_dd = r[k], cd, cdd
        u = P * e[k] + I * err_i + ff[0] * cd + ff[1] * cdd + ff[2] * cddd
        assert abs(u) <= UMAX, f"output clipped at k={k}: u={u}"
        x = Ad @ x + Bd * u
    return np.sqrt(np.mean(e**2))


if __name__ == "__main__":
    c1 = simulate(K0)
    c2 = simulate(K0, FF)
    c3 = simulate(K0, FF, analytic=True)
    c4ff = simulate(1.1 * K0, FF)
    c4no = simulate(1.1 * K0)
    print("(no sample clipped at +-2.5 V in any case)")
    print(f"1 no feedforward                      RMSE = {c1:.6g} mm")
    print(f"2 feedforward, backward differences   RMSE = {c2:.6g} mm")
    print(f"3 feedforward, analytic derivatives   RMSE = {c3:.6g} mm")
    print(f"4 plant k0 x 1.1, with feedforward    RMSE = {c4ff:.6g} mm")
    print(f"4 plant k0 x 1.1, no feedforward      RMSE = {c4no:.6g} mm")
    print(f"ratio case1/case2                     = {c1 / c2:.6g}")
