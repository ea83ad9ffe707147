#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Reference data for core/design/shaper_recommendation (tests/core/design/
tst_shaper_recommendation.cpp): an independent NumPy re-implementation of Klipper's input shaper
formulas and of its automatic shaper choice.

Sources, re-typed here from their equations and rules (no code of XY Tune is used):
  - the shapers: Klipper's klippy/extras/shaper_defs.py in its closed forms (the 2020-2021
    version: ZV, ZVD and MZV, EI, 2-hump and 3-hump EI for a vibration tolerance of 1/20); ZVDD,
    which Klipper does not ship, from Singer and Seering 1990 (amplitudes 1, 3K, 3K^2, K^3 at
    0, td/2, td, 3td/2);
  - klippy/extras/shaper_calibrate.py: _estimate_shaper, _estimate_remaining_vibrations,
    _get_shaper_smoothing, _bisect, find_shaper_max_accel, fit_shaper, find_best_shaper and
    CalibrationData.normalize_to_frequencies.

The spectrum: Klipper's frequency bins for a log at 3200 Hz (Welch segments of
M = 2048 samples: rfftfreq(2048, 1/3200), 1.5625 Hz apart), kept up to 300 Hz so the 200 Hz
cut is exercised, and a fixed synthetic PSD: two Lorentzian peaks (42 Hz, half-width 2.5 Hz,
height 1; 67 Hz, half-width 4 Hz, height 0.45) on a floor of 0.01.

Run:  /usr/bin/python3 tests/data/gen_input_shapers.py > tests/data/input_shapers_klipper.json
"""
import json
import math

import numpy as np

V_TOL = 1.0 / 20.0  # SHAPER_VIBRATION_REDUCTION = 20
NAMES = ["zv", "mzv", "zvd", "zvdd", "ei", "2hump_ei", "3hump_ei"]
KLIPPER_MIN_FREQ = {"zv": 21.0, "mzv": 23.0, "zvd": 29.0, "ei": 29.0, "2hump_ei": 39.0,
                    "3hump_ei": 48.0}
AUTOTUNE = ["zv", "mzv", "ei", "2hump_ei", "3hump_ei"]


def shaper(name, f, zeta):
    """(A, T), amplitudes not normalized, as shaper_defs.py returns them."""
    df = math.sqrt(1.0 - zeta ** 2)
    K = math.exp(-zeta * math.pi / df)
    td = 1.0 / (f * df)
    if name == "zv":
        return [1.0, K], [0.0, 0.5 * td]
    if name == "zvd":
        return [1.0, 2.0 * K, K ** 2], [0.0, 0.5 * td, td]
    if name == "zvdd":
        return [1.0, 3.0 * K, 3.0 * K ** 2, K ** 3], [0.0, 0.5 * td, td, 1.5 * td]
    if name == "mzv":
        Km = math.exp(-0.75 * zeta * math.pi / df)
        a1 = 1.0 - 1.0 / math.sqrt(2.0)
        return [a1, (math.sqrt(2.0) - 1.0) * Km, a1 * Km ** 2], [0.0, 0.375 * td, 0.75 * td]
    if name == "ei":
        a1 = 0.25 * (1.0 + V_TOL)
        return [a1, 0.5 * (1.0 - V_TOL) * K, a1 * K ** 2], [0.0, 0.5 * td, td]
    if name == "2hump_ei":
        V2 = V_TOL ** 2
        X = (V2 * (math.sqrt(1.0 - V2) + 1.0)) ** (1.0 / 3.0)
        a1 = (3.0 * X * X + 2.0 * X + 3.0 * V2) / (16.0 * X)
        a2 = (0.5 - a1) * K
        return [a1, a2, a2 * K, a1 * K ** 3], [0.0, 0.5 * td, td, 1.5 * td]
    if name == "3hump_ei":
        a1 = 0.0625 * (1.0 + 3.0 * V_TOL + 2.0 * math.sqrt(2.0 * (V_TOL + 1.0) * V_TOL))
        a2 = 0.25 * (1.0 - V_TOL) * K
        a3 = (0.5 * (1.0 + V_TOL) - 2.0 * a1) * K ** 2
        return ([a1, a2, a3, a2 * K ** 2, a1 * K ** 4],
                [0.0, 0.5 * td, td, 1.5 * td, 2.0 * td])
    raise ValueError(name)


def estimate_shaper(A, T, dr, freqs):
    A = np.asarray(A)
    T = np.asarray(T)
    w = 2.0 * np.pi * freqs
    wd = w * math.sqrt(1.0 - dr ** 2)
    W = A[None, :] * np.exp(-(dr * w)[:, None] * (T[-1] - T)[None, :])
    S = (W * np.sin(wd[:, None] * T[None, :])).sum(axis=1)
    C = (W * np.cos(wd[:, None] * T[None, :])).sum(axis=1)
    return np.sqrt(S ** 2 + C ** 2) / A.sum()


def remaining(A, T, dr, freqs, psd):
    vals = estimate_shaper(A, T, dr, freqs)
    thr = psd.max() / 20.0
    return np.maximum(vals * psd - thr, 0.0).sum() / np.maximum(psd - thr, 0.0).sum(), vals


def smoothing(A, T, accel=5000.0, scv=5.0):
    D = sum(A)
    ts = sum(a * t for a, t in zip(A, T)) / D
    o90 = sum(a * (scv + 0.5 * accel * (t - ts)) * (t - ts) for a, t in zip(A, T) if t >= ts)
    o180 = sum(a * 0.5 * accel * (t - ts) ** 2 for a, t in zip(A, T))
    return max(o90 * math.sqrt(2.0) / D, o180 / D)


def max_accel(A, T, scv=5.0):
    ok = lambda acc: smoothing(A, T, acc, scv) <= 0.12
    left = right = 1.0
    if not ok(1e-9):
        return 0.0
    while not ok(left):
        right = left
        left *= 0.5
    if right == left:
        while ok(right):
            right *= 2.0
    while right - left > 1e-8:
        mid = (left + right) * 0.5
        if ok(mid):
            left = mid
        else:
            right = mid
    return left


def fit(name, freqs, psd, fmin, fmax, step, zeta, test_drs, scv, max_smoothing, max_vibr):
    test_freqs = np.arange(fmin, fmax, step)
    max_freq = max(200.0, test_freqs.max())
    keep = freqs <= max_freq
    f, p = freqs[keep], psd[keep]
    best = None
    results = []
    for tf in test_freqs[::-1]:
        A, T = shaper(name, tf, zeta)
        sm = smoothing(A, T, scv=scv)
        if max_smoothing and sm > max_smoothing and best:
            return [best] + results
        vib = 0.0
        for dr in test_drs:
            v, _ = remaining(A, T, dr, f, p)
            vib = max(vib, v)
        score = sm * (vib ** 1.5 + vib * 0.2 + 0.01)
        results.append(dict(name=name, freq=float(tf), vibrs=float(vib), smoothing=sm,
                            score=float(score)))
        if best is None or best["vibrs"] > results[-1]["vibrs"]:
            best = results[-1]
    selected = best
    for r in results[::-1]:
        if r["vibrs"] < best["vibrs"] * 1.1 + 0.0005 and (
                r["score"] < selected["score"] or
                (max_vibr is not None and best["vibrs"] > max_vibr)):
            selected = r
    return [selected] + results


def find_best(names, freqs, psd, fmin, fmax, step, zeta, test_drs, scv, max_smoothing,
              max_vibr, klipper_min):
    best = None
    all_shapers = []
    for name in names:
        start = min(KLIPPER_MIN_FREQ[name], fmax - 1e-7) if klipper_min and \
            name in KLIPPER_MIN_FREQ else fmin
        res = fit(name, freqs, psd, start, fmax, step, zeta, test_drs, scv, max_smoothing,
                  max_vibr)
        sh, results = res[0], res[1:]
        if (best is None or sh["score"] * 1.2 < best["score"] or
                (sh["score"] * 1.05 < best["score"] and sh["smoothing"] * 1.1 < best["smoothing"])
                or (max_vibr is not None and best["vibrs"] > max_vibr and
                    sh["vibrs"] < best["vibrs"])):
            best = sh
        for s in results[::-1]:
            if s["vibrs"] < best["vibrs"] and s["smoothing"] < best["smoothing"]:
                best = sh = s
        A, T = shaper(name, sh["freq"], zeta)
        sh = dict(sh, max_accel=max_accel(A, T, scv), candidates=len(results))
        all_shapers.append(sh)
    if best["name"] == "zv":
        for s in all_shapers:
            if s["name"] != "zv" and s["vibrs"] * 1.1 < best["vibrs"]:
                best = s
                break
    return {"recommended": best["name"], "fits": all_shapers}


def main():
    freqs = np.fft.rfftfreq(2048, 1.0 / 3200.0)
    freqs = freqs[freqs <= 300.0]
    psd = (1.0 / (1.0 + ((freqs - 42.0) / 2.5) ** 2) +
           0.45 / (1.0 + ((freqs - 67.0) / 4.0) ** 2) + 0.01)
    cut = freqs <= 200.0
    out = {"spectrum": {"frequency": freqs.tolist(), "power": psd.tolist()}}

    # Klipper's normalize_to_frequencies of that spectrum.
    norm = psd / (freqs + 0.1)
    low = freqs < 10.0
    norm[low] *= np.exp(-(10.0 / (freqs[low] + 0.1)) ** 2 + 1.0)
    out["normalized_power"] = norm.tolist()

    # Each shaper at 40 Hz, zeta 0.1; its smoothing, max accel and remaining vibration over a
    # range of test damping ratios (spectrum cut at 200 Hz as fit_shaper does).
    drs = [0.0, 0.05, 0.075, 0.1, 0.15, 0.2]
    shapers = {}
    for name in NAMES:
        A, T = shaper(name, 40.0, 0.1)
        shapers[name] = {
            "amplitudes_raw": A, "amplitudes": (np.asarray(A) / sum(A)).tolist(), "times": T,
            "smoothing": smoothing(A, T), "smoothing_accel_3000_scv_8": smoothing(A, T, 3000.0, 8.0),
            "max_accel": max_accel(A, T), "max_accel_scv_8": max_accel(A, T, 8.0),
            "test_damping_ratios": drs,
            "remaining_vibrations": [float(remaining(A, T, dr, freqs[cut], psd[cut])[0])
                                     for dr in drs],
        }
    out["shapers_40hz_zeta_0p1"] = shapers

    drs3 = [0.075, 0.1, 0.15]
    out["recommendation_default"] = dict(
        options="all seven, 10..200 Hz step 0.2, zeta 0.1, test 0.075/0.1/0.15, scv 5",
        **find_best(NAMES, freqs, psd, 10.0, 200.0, 0.2, 0.1, drs3, 5.0, None, None, False))
    out["recommendation_klipper"] = dict(
        options="Klipper's autotune shapers from their min_freq to 200 Hz step 0.2, "
                "max_smoothing 0.1",
        **find_best(AUTOTUNE, freqs, psd, 10.0, 200.0, 0.2, 0.1, drs3, 5.0, 0.1, None, True))
    out["recommendation_max_vibrations"] = dict(
        options="all seven, 10..200 Hz step 0.2, max_vibrations 0.01",
        **find_best(NAMES, freqs, psd, 10.0, 200.0, 0.2, 0.1, drs3, 5.0, None, 0.01, False))
    print(json.dumps(out, indent=1))


if __name__ == "__main__":
    main()
