#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Reference contour errors of Koren's cross-coupled contouring controller (CCC) on a full
circle, computed independently of XY Tune (numpy/scipy only; no XY Tune code is called).

The run (what `xytune-cli contour --gcode` does with "F90\\nG3 X0 Y0 I-25 J0\\n"):
  path     a counter-clockwise circle of radius R = 25 mm about (-25, 0), from (0, 0) back to
           (0, 0); length L = 2 pi R
  feed     trapezoidal: 100 mm/s^2 up to 1.5 mm/s (F90), cruise, 100 mm/s^2 down to rest at L;
           s(t) in closed form; samples t_k = k dt, dt = 1 ms, k = 0 .. ceil(T/dt), the last one
           (past T) holding the end of the path, s = L
  axes     Braga et al.'s bases, G(s) = k0 / (s (s^2 + a1 s + a2)) in metres per volt, under the
           continuous PI C(s) = kp + ki / s (V/m), unity feedback, the reference in mm scaled by
           0.001 into the loop and the output scaled back by 1 / 0.001:
             x: lower base k0 77.8, a1 125.3, a2 3665, kp 30, ki = 2^4 / 77.8 (wn 2)
             y: upper base k0 24.44, a1 68.18, a2 863, kp 30, ki = 1^4 / 24.44 (wn 1)
           both at rest at the origin; actuator limit +-2.5 V, never reached here (checked)
  hold     between samples the reference is linear (first-order hold), the coupling's voltage v
           (added to the PI's output at the plant input) is held (zero-order hold); each closed
           loop is discretized exactly at dt with scipy.linalg.expm of an augmented matrix
  law      at sample k: e = r - y per axis (mm), theta = s / R + pi / 2, kappa = +1 / R;
             linear:   eps = -ex sin theta + ey cos theta,  (Cx, Cy) = (-sin theta, cos theta)
             circular: tau = ex cos theta + ey sin theta,
                       eps = -ex sin theta + ey cos theta + kappa tau^2 / 2,
                       (Cx, Cy) = (-sin theta + kappa tau cos theta, cos theta + kappa tau sin theta)
           I+ = I + dt eps, u_c = kp_c eps + ki_c I+, v = (Cx u_c, Cy u_c), I = I+; then both
           axes advance over [t_k, t_k+1] with v held
  error    the radial deviation |hypot(x + 25, y) - 25| (mm) of every sample; max and RMS over
           all samples
Output: tests/data/cross_coupling_circle.csv (next to this script), one row per case:
  estimate,kp,ki,max_contour_error_mm,rms_contour_error_mm (repr, full double precision);
  a summary (samples, duration, largest |u|, largest turn per sample) on stderr.
Regenerate (from the repository root): /usr/bin/python3 tests/data/gen_cross_coupling.py
"""
import math
import os
import sys

import numpy as np
from scipy.linalg import expm

DT = 0.001
UNIT = 0.001  # model units (m) per mm
UMAX = 2.5
R = 25.0
CX, CY = -25.0, 0.0
FEED = 90.0 / 60.0  # mm/s
ACCEL = 100.0  # mm/s^2
KAPPA = 1.0 / R
CORNER_TURN = 0.1  # rad

LOWER = dict(k0=77.8, a1=125.3, a2=3665.0, kp=30.0, ki=2.0 ** 4 / 77.8)
UPPER = dict(k0=24.44, a1=68.18, a2=863.0, kp=30.0, ki=1.0 ** 4 / 24.44)

CASES = [
    ("none", 0.0, 0.0),
    ("circular", 0.1, 0.0),
    ("circular", 0.1, 1.0),
    ("linear", 0.1, 0.0),
    ("linear", 0.1, 1.0),
]


def profile():
    """Arc length s_k (mm) at t_k = k dt of the trapezoidal feed profile, and its duration."""
    length = 2.0 * math.pi * R
    t_ramp = FEED / ACCEL
    s_ramp = 0.5 * ACCEL * t_ramp ** 2
    assert 2.0 * s_ramp < length, "the profile reaches its feed"
    t_cruise = (length - 2.0 * s_ramp) / FEED
    total = 2.0 * t_ramp + t_cruise
    n = int(math.ceil(total / DT)) + 1  # k = 0 .. ceil(T/dt): the last sample is at or past T

    def s_of(t):
        if t >= total:
            return length
        if t <= t_ramp:
            return 0.5 * ACCEL * t * t
        if t <= t_ramp + t_cruise:
            return s_ramp + FEED * (t - t_ramp)
        return length - 0.5 * ACCEL * (total - t) ** 2

    s = np.array([s_of(k * DT) for k in range(n)])
    return s, total


def discretize(p):
    """Exact discretization at DT of one axis' closed loop, states (y, y', y'', integral of e)
    in model units, inputs r (model units, first-order hold) and v (V, zero-order hold).
    Returns Phi, Gr0, Gr1 (x+ = Phi x + Gr0 r_k + Gr1 r_k+1 + Gv v_k), Gv."""
    k0, a1, a2, kp, ki = p["k0"], p["a1"], p["a2"], p["kp"], p["ki"]
    # u = kp (r - y) + ki z + v;  y''' = -a2 y' - a1 y'' + k0 u;  z' = r - y
    a = np.array([[0.0, 1.0, 0.0, 0.0],
                  [0.0, 0.0, 1.0, 0.0],
                  [-k0 * kp, -a2, -a1, k0 * ki],
                  [-1.0, 0.0, 0.0, 0.0]])
    b_r = np.array([0.0, 0.0, k0 * kp, 1.0])
    b_v = np.array([0.0, 0.0, k0, 0.0])
    # augmented states (x, r, r', v): r' = (r_k+1 - r_k) / DT and v constant over the step
    m = np.zeros((7, 7))
    m[:4, :4] = a
    m[:4, 4] = b_r
    m[:4, 6] = b_v
    m[4, 5] = 1.0
    e = expm(m * DT)
    phi = e[:4, :4]
    g_r = e[:4, 4]
    g_rd = e[:4, 5] / DT
    g_v = e[:4, 6]
    return phi, g_r - g_rd, g_rd, g_v


def command(p, x, r):
    """The PI's output (V) at a sample, before the coupling's voltage."""
    return p["kp"] * (r - x[0]) + p["ki"] * x[3]


def run(estimate, kp_c, ki_c, s, loops):
    theta = s / R + math.pi / 2.0
    rx = CX + R * np.cos(s / R)
    ry = CY + R * np.sin(s / R)
    (phx, g0x, g1x, gvx), (phy, g0y, g1y, gvy) = loops
    n = len(s)
    xs = np.zeros(4)
    ys = np.zeros(4)
    integral = 0.0
    err = np.empty(n)
    umax = 0.0
    for k in range(n):
        px = xs[0] / UNIT
        py = ys[0] / UNIT
        err[k] = abs(math.hypot(px - CX, py - CY) - R)
        if k == n - 1:
            break
        ex = rx[k] - px
        ey = ry[k] - py
        th = theta[k]
        if k > 0:
            assert abs(th - theta[k - 1]) <= CORNER_TURN
        sn, cs = math.sin(th), math.cos(th)
        if estimate == "none":
            vx = vy = 0.0
        else:
            eps = -ex * sn + ey * cs
            gx, gy = -sn, cs
            if estimate == "circular":
                tau = ex * cs + ey * sn
                eps += KAPPA * tau * tau / 2.0
                gx += KAPPA * tau * cs
                gy += KAPPA * tau * sn
            integral_next = integral + DT * eps
            uc = kp_c * eps + ki_c * integral_next
            vx, vy = gx * uc, gy * uc
            integral = integral_next
        ux = command(LOWER, xs, UNIT * rx[k]) + vx
        uy = command(UPPER, ys, UNIT * ry[k]) + vy
        umax = max(umax, abs(ux), abs(uy))
        xs = phx @ xs + g0x * (UNIT * rx[k]) + g1x * (UNIT * rx[k + 1]) + gvx * vx
        ys = phy @ ys + g0y * (UNIT * ry[k]) + g1y * (UNIT * ry[k + 1]) + gvy * vy
    assert umax < UMAX, "the actuator limit is reached: the clip would have to be modelled"
    return float(err.max()), float(math.sqrt(np.mean(err * err))), umax


def main():
    s, total = profile()
    turn = float(np.max(np.abs(np.diff(s / R))))
    loops = (discretize(LOWER), discretize(UPPER))
    rows = ["estimate,kp,ki,max_contour_error_mm,rms_contour_error_mm"]
    print("samples %d, duration %r s, last s %r mm (L %r), largest turn per sample %.3g rad"
          % (len(s), total, float(s[-1]), 2.0 * math.pi * R, turn), file=sys.stderr)
    for estimate, kp_c, ki_c in CASES:
        mx, rms, umax = run(estimate, kp_c, ki_c, s, loops)
        rows.append("%s,%r,%r,%r,%r" % (estimate, kp_c, ki_c, mx, rms))
        print("%-8s kp %g ki %g: max %.10g mm, rms %.10g mm, largest |u| %.4g V"
              % (estimate, kp_c, ki_c, mx, rms, umax), file=sys.stderr)
    out = os.path.join(os.path.dirname(os.path.abspath(__file__)), "cross_coupling_circle.csv")
    with open(out, "w", newline="\n") as f:
        f.write("\n".join(rows) + "\n")


if __name__ == "__main__":
    main()
