#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Reference run of the table with Coulomb friction under Braga et al.'s Guillemin-Truxal PI,
integrated independently of XY Tune: scipy.integrate.solve_ivp (DOP853, rtol 1e-12, atol 1e-15)
in each mode, with its own event location at the stick and slip instants.

The loop (tests/core/simulation/tst_table_dynamics.cpp, referenceRunWithCoulomb):
  plant   k0 / (s (s^2 + a1 s + a2)), lower base k0 = 77.8, a1 = 125.3, a2 = 3665 (m, V)
          split: pe = faster root of s^2 + a1 s + a2, pm = the slower, g = k0 / pe
          z' = pe (u - z),  v' = g (z - s Fc) - pm v (sliding s = +-1),  x' = v
          stuck: v = 0, x held, until |z| > Fc; sliding ends when v = 0, sticking if |z| <= Fc
  PI      u = kp e + ki I, I' = e, e = 0.001 r - x (metres), kp = 30 V/m, ki = wn^4 / k0, wn = 2
          (Braga et al. Eq. 16 with psi1 = wn^4 / (kp k0)), |u| <= 2.5 V never reached here
  r       5 sin(0.5 t) mm (a reversal every 6.3 s, where the table sticks), sampled every 10 ms
          and linear between samples, as simulateLoop takes a reference
  Fc      0.05 V, no Stribeck dip, no viscous term, no backlash, no deadband
Output: t, y (mm), every 0.5 s from 0 to 40 s; the number of stick/slip transitions on stderr.
Regenerate: /usr/bin/python3 tests/data/gen_table_friction.py > tests/data/table_friction_coulomb.csv
"""
import numpy as np
from scipy.integrate import solve_ivp

k0, a1, a2 = 77.8, 125.3, 3665.0
disc = a1 * a1 - 4.0 * a2
fast = 0.5 * (a1 + np.sqrt(disc))
pe, pm = fast, a2 / fast
g = k0 / pe
kp = 30.0
ki = 2.0 ** 4 / k0
fc = 0.05
unit = 0.001
dt = 0.01
end = 40.0
ts = np.arange(0.0, end + dt / 2, dt)
rs = 5.0 * np.sin(0.5 * ts)


def r(t):
    return np.interp(t, ts, rs)


def rhs(t, x, mode):
    z, v, pos, integ = x
    e = unit * r(t) - pos
    u = float(np.clip(kp * e + ki * integ, -2.5, 2.5))
    dz = pe * (u - z)
    if mode == 0:
        dv, dpos = 0.0, 0.0
    else:
        dv = g * (z - mode * fc) - pm * v
        dpos = v
    return [dz, dv, dpos, e]


def breakaway(t, x, mode):
    return abs(x[0]) - fc


def stop(t, x, mode):
    return mode * x[1]


breakaway.terminal = True
breakaway.direction = 1
stop.terminal = True
stop.direction = -1

out_t = np.arange(0.0, end + 1e-9, 0.5)
state = np.zeros(4)
mode = 0
t0 = 0.0
transitions = 0
values = []
while t0 < end:
    events = [breakaway] if mode == 0 else [stop]
    # The reference's corners every 10 ms: integrate sample by sample so no step crosses one.
    t1 = min(end, (np.floor(t0 / dt + 1e-9) + 1) * dt)
    sol = solve_ivp(rhs, (t0, t1), state, method="DOP853", rtol=1e-12, atol=1e-15,
                    events=events, args=(mode,), dense_output=True)
    t_end = sol.t[-1]
    for t in out_t:
        if t0 <= t <= t_end and (not values or t > values[-1][0]):
            values.append((t, sol.sol(t)[2] / unit))
    state = sol.y[:, -1].copy()
    if sol.status == 1:  # an event
        transitions += 1
        if mode == 0:
            mode = 1 if state[0] > 0 else -1
        else:
            state[1] = 0.0
            mode = 0 if abs(state[0]) <= fc else (1 if state[0] > 0 else -1)
    t0 = t_end
import sys
print("gen_table_friction.py: %d stick/slip transitions" % transitions, file=sys.stderr)
print("t,y")
for t, y in values:
    print("%.17g,%.17g" % (t, y))
