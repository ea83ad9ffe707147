#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
# Independent reference spectra for tests/core/identification/tst_spectral_estimate.cpp and
# tst_accelerometer_log.cpp, computed with scipy.signal (welch, csd, coherence; pocketfft, not
# the core's Eigen FFT). Fixed seed. Regenerate (from the repository root):
#   /usr/bin/python3 tests/data/gen_spectral_estimate.py
# which writes tests/data/spectral_estimate_scipy.json and tests/data/klipper_accel_raw.csv.
import json
import os

import numpy as np
from scipy import signal

here = os.path.dirname(os.path.abspath(__file__))
rng = np.random.default_rng(20261126)


def floats(a):
    return [float(repr_v) for repr_v in np.asarray(a, dtype=float)]


# 1. A record through a second-order filter with output noise: Welch PSD, CSD, coherence and
#    H1 with a periodic Hann window, nperseg 64, half overlap, constant detrend, density.
n, ts = 700, 0.002
u = rng.standard_normal(n) + 0.3
b, a = [0.05, 0.04], [1.0, -1.6, 0.69]
y = signal.lfilter(b, a, u) + 0.05 * rng.standard_normal(n) - 1.2
fs = 1.0 / ts
common = dict(fs=fs, window="hann", nperseg=64, noverlap=32, detrend="constant",
              scaling="density")
f, puu = signal.welch(u, **common)
_, pyy = signal.welch(y, **common)
_, puy = signal.csd(u, y, **common)  # scipy: conj(U) Y
_, coh = signal.coherence(u, y, fs=fs, window="hann", nperseg=64, noverlap=32,
                             detrend="constant")
h = puy / puu
hann = {
    "ts": ts, "segment": 64, "u": floats(u), "y": floats(y), "frequency": floats(f),
    "puu": floats(puu), "pyy": floats(pyy), "puy_re": floats(puy.real),
    "puy_im": floats(puy.imag), "coherence": floats(coh), "magnitude": floats(np.abs(h)),
    "phase_rad": floats(np.unwrap(np.angle(h))),
}

# 2. An odd segment (no Nyquist bin): PSD of u with nperseg 45, noverlap 22.
f45, p45 = signal.welch(u, fs=fs, window="hann", nperseg=45, noverlap=22, detrend="constant",
                        scaling="density")
odd = {"segment": 45, "frequency": floats(f45), "psd": floats(p45)}

# 3. A Klipper-style raw accelerometer log: ~400 Hz with 0.5 % timing jitter, times and values
#    printed "%.6f" as Klipper writes them; then Klipper's spectra, as shaper_calibrate.py
#    documents them: fs = N / (t_last - t_first), nfft = 1 << int(fs * 0.5 - 1).bit_length(),
#    the symmetric numpy.kaiser(nfft, 6) window, half overlap, segment means removed, density
#    scaling with the one-sided doubling except at 0 Hz and Nyquist: scipy.signal.welch with that
#    window array.
m = 1100
t = 12.5 + np.arange(m) / 400.0 + rng.uniform(-1.25e-5, 1.25e-5, m)
ax = 800.0 * np.sin(2 * np.pi * 47.0 * t) + 60.0 * rng.standard_normal(m)
ay = 300.0 * np.sin(2 * np.pi * 81.3 * t + 0.4) + 60.0 * rng.standard_normal(m) - 40.0
az = 9810.0 + 30.0 * rng.standard_normal(m)
csv = os.path.join(here, "klipper_accel_raw.csv")
with open(csv, "w") as fh:
    fh.write("#time,accel_x,accel_y,accel_z\n")
    for row in zip(t, ax, ay, az):
        fh.write("%.6f,%.6f,%.6f,%.6f\n" % row)
data = np.loadtxt(csv, comments="#", delimiter=",")
N = data.shape[0]
T = data[-1, 0] - data[0, 0]
fs_k = N / T
nfft = 1 << int(fs_k * 0.5 - 1).bit_length()
window = np.kaiser(nfft, 6.0)
spectra = []
for col in (1, 2, 3):
    fk, pk = signal.welch(data[:, col], fs=fs_k, window=window, nperseg=nfft,
                          noverlap=nfft // 2, detrend="constant", scaling="density")
    spectra.append(pk)
klipper = {
    "file": "klipper_accel_raw.csv", "samples": int(N), "sampling_hz": fs_k, "segment": nfft,
    "frequency": floats(fk), "psd_x": floats(spectra[0]), "psd_y": floats(spectra[1]),
    "psd_z": floats(spectra[2]), "psd_sum": floats(spectra[0] + spectra[1] + spectra[2]),
}

out = {
    "tool": "scipy %s, numpy %s" % (__import__("scipy").__version__, np.__version__),
    "hann": hann, "odd": odd, "klipper": klipper,
}
with open(os.path.join(here, "spectral_estimate_scipy.json"), "w") as fh:
    json.dump(out, fh, indent=0)
    fh.write("\n")
