// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace xyt {

/// The sampling of an excitation signal: u[k] is applied over [k Ts, (k+1) Ts), k = 0..n-1.
struct ExcitationTiming {
    double tsSeconds = 0.01;
    /// n = duration / Ts samples (rounded when within 1e-9 relative of a whole number, else up).
    double durationSeconds = 10.0;
    /// |u| <= umax checked when given (V); the paper's amplifier range is +-2.5 V.
    std::optional<double> umaxVolts;
};

/// A sampled command signal (V) and what it is.
struct ExcitationSignal {
    std::vector<double> u;
    double tsSeconds = 0.0;
    std::string description; ///< e.g. "square wave: amplitude 1 V, period 2 s, offset 0 V"
    /// A synthetic experiment's measured position y[k] (mm) at k Ts (simulateExperiment); empty
    /// for a command alone. The writers add it as the column "y" when present.
    std::vector<double> y;
};

/// The most samples an excitation may have: 10^7 (over 27 hours at 10 ms).
inline constexpr std::size_t kMaxExcitationSamples = 10'000'000;

/// u(t) = offset + amplitude for t mod period < period / 2, offset - amplitude otherwise.
struct SquareWave {
    double amplitudeVolts = 1.0;
    double periodSeconds = 1.0;
    double offsetVolts = 0.0;
};

/**
 * Maximal-length pseudo-random binary sequence: a Fibonacci LFSR of registerLength bits
 * (2..31) with the taps of kPrbsTaps (a primitive polynomial of that degree, so the sequence
 * repeats every 2^n - 1 bits and holds 2^(n-1) ones and 2^(n-1) - 1 zeros), started from all
 * ones; each bit b is held clockSamples samples as u = offset + amplitude (b = 1) or
 * offset - amplitude (b = 0).
 */
struct Prbs {
    double amplitudeVolts = 1.0;
    int clockSamples = 1;
    int registerLength = 10;
    double offsetVolts = 0.0;
};

/// Linear sweep: u(t) = offset + amplitude sin(2 pi (f0 t + (f1 - f0) t^2 / (2 T))), T the
/// duration; the instantaneous frequency goes from f0 (t = 0) to f1 (t = T), Hz.
struct Chirp {
    double amplitudeVolts = 1.0;
    double f0Hz = 0.1;
    double f1Hz = 1.0;
    double offsetVolts = 0.0;
};

/**
 * The taps of the maximal-length LFSR of each register length n = 2..31 (1-based bit numbers,
 * n first; Xilinx XAPP052 "Efficient Shift Registers, LFSR Counters, and Long Pseudo-Random
 * Sequence Generators", table 3). Bit 1 receives the XOR of the tapped bits, bit n is output.
 */
std::vector<int> prbsTaps(int registerLength);

/// The first @p count bits (0/1) of the maximal-length sequence (Prbs's LFSR, one bit per step).
std::vector<std::uint8_t> prbsBits(int registerLength, std::size_t count);

/// @throws InvalidInput naming the field ("amplitude", "period", "ts", "duration", "umax",
///         "offset"): not finite, not > 0 where a size is meant, |offset| + amplitude > umax, more
///         than kMaxExcitationSamples samples.
ExcitationSignal squareWave(const SquareWave& wave, const ExcitationTiming& timing);
/// @throws InvalidInput as squareWave, plus "clock" (< 1), "register" (not 2..31).
ExcitationSignal prbs(const Prbs& prbs, const ExcitationTiming& timing);
/// @throws InvalidInput as squareWave, plus "f0", "f1" (< 0, not finite, or above the Nyquist
///         frequency 1 / (2 Ts)).
ExcitationSignal chirp(const Chirp& chirp, const ExcitationTiming& timing);

/// CSV text: header "t,u" ("t,u,y" with a response), one row per sample (t = k Ts), numbers as
/// %.17g (read back exactly).
std::string excitationCsvText(const ExcitationSignal& signal);
/**
 * LVM text (LabVIEW Measurement 2.0: tab separators, decimal point, X_Columns One, one segment
 * whose header states Delta_X = Ts and X0 = 0; columns X_Value (t, s) and u (V), and y (mm) with a
 * response; the Description tag holds the signal's description; no date or time so the file
 * depends on the signal only), numbers as %.17g.
 */
std::string excitationLvmText(const ExcitationSignal& signal);
/**
 * Writes the signal to @p path as CSV (".csv") or LVM (".lvm"), atomically
 * (core/io/file_io.h writeFileAtomically: an existing file is replaced only when every byte is
 * on disk).
 * @throws InvalidInput "output" for any other extension; FileError when the write fails.
 */
void writeExcitation(const std::string& path, const ExcitationSignal& signal);

} // namespace xyt
