// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/identification/spectral_estimate.h"

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace xyt {

/// The largest relative deviation of one sample interval from the log's mean interval
/// (t_last - t_first) / (N - 1). Klipper prints times as "%.6f" (1 us), so at the fastest
/// accelerometer rates (3.2 kHz ADXL345, 312.5 us; even 10 kHz, 100 us) rounding moves an
/// interval by at most 2 us, 0.6 % (2 %), and its clock synchronisation drifts by parts per
/// million; a lost sample doubles an interval (+100 %), a reversal or a repeated time is
/// refused anyway. 25 % lies far from both.
inline constexpr double kAccelerometerIntervalTolerance = 0.25;

/// The largest acceleration accepted, mm/s^2: 1e9 is 100 000 g, far beyond any accelerometer
/// (the ADXL345 saturates at 16 g, 157 000 mm/s^2); it keeps the spectra far from overflow.
inline constexpr double kMaxAccelerometerMmPerS2 = 1e9;

/// The fewest rows a log must hold: two half-overlapping Welch segments of the smallest
/// segment Klipper chooses would need more; this only refuses logs too short to be a
/// measurement before the spectra refuse them with the segment length.
inline constexpr std::size_t kMinAccelerometerSamples = 16;

/**
 * A raw accelerometer log as Klipper writes it (ACCELEROMETER_MEASURE, TEST_RESONANCES with
 * OUTPUT=raw_data: /tmp/raw_data_*.csv, the file scripts/calibrate_shaper.py reads): a header
 * line "#time,accel_x,accel_y,accel_z", then one "%.6f,%.6f,%.6f,%.6f" row per sample: the
 * time in s and the accelerations in mm/s^2.
 */
struct AccelerometerLog {
    std::string fileName;
    std::vector<double> timeSeconds;
    std::vector<double> x, y, z; ///< mm/s^2
    /// The mean sample interval (t_last - t_first) / (N - 1), s.
    double meanIntervalSeconds = 0.0;
    /// Klipper's sampling frequency N / (t_last - t_first) (shaper_calibrate.py
    /// calc_freq_response; it counts N samples over N - 1 intervals, a bias of 1/N), Hz.
    double klipperSamplingHz = 0.0;
    std::size_t size() const { return timeSeconds.size(); }
};

/**
 * Reads a Klipper accelerometer log.
 *   - Lines end at LF, CRLF or CR (TextLines); blank lines are skipped; lines starting with "##"
 *     before the header (the statistics line older Klipper versions wrote) are skipped.
 *   - The header is the first other line: '#' then comma-separated names, which must include
 *     time, accel_x, accel_y and accel_z (any order, other columns ignored; names trimmed).
 *   - Every later line that starts with '#' is a comment (numpy.loadtxt(comments='#'), as
 *     calibrate_shaper.py reads it); every other line holds exactly as many comma-separated
 *     numbers as the header names.
 *   - Accelerations are at most kMaxAccelerometerMmPerS2 in magnitude; the mean interval is an
 *     accepted sample time (requireSampleTime: 1 ns to 10 000 s).
 *   - Times increase strictly; each interval is within kAccelerometerIntervalTolerance of the
 *     mean interval.
 *   - Memory: at most kMaxExperimentBytes of text; the rows are counted first and 32 bytes a
 *     row reserved, so no number in the file drives an allocation.
 * @throws InvalidInput whose field is "<file>: line N" (", column C (name)" for a cell): no
 *         header ("line 1: no header ..."), a missing column ("line 1: no accel_y column"), a
 *         field that is not a number or an acceleration beyond the bound, too few or too many
 * fields, a time not after the one before, an interval off the mean by more than the tolerance (a
 * gap), fewer than kMinAccelerometerSamples rows, more than kMaxExperimentBytes bytes.
 */
AccelerometerLog readAccelerometerLog(std::string_view text, const std::string& fileName);

/// readAccelerometerLog on the file at @p path (readExperimentFile: at most
/// kMaxExperimentBytes). @throws FileError when the file cannot be read.
AccelerometerLog readAccelerometerLogFile(const std::string& path);

/// Klipper's analysis window, s (shaper_calibrate.py WINDOW_T_SEC).
inline constexpr double kKlipperWindowSeconds = 0.5;
/// Klipper's Kaiser window parameter (shaper_calibrate.py _psd: numpy.kaiser(nfft, 6.)).
inline constexpr double kKlipperKaiserBeta = 6.0;

/// The segment length Klipper's shaper_calibrate.py calc_freq_response uses at sampling rate
/// @p samplingHz: the power of two M = 2^b with b the bit length of floor(fs 0.5 - 1), the
/// smallest power of two above floor(fs 0.5 - 1) (3.2 kHz: 2048).
std::size_t klipperSegmentLength(double samplingHz);

/// The power spectral densities of the three axes and their sum.
struct AccelerometerSpectra {
    std::vector<double> frequencyHz;
    std::vector<double> psdX, psdY, psdZ, psdSum; ///< (mm/s^2)^2 / Hz
    double samplingHz = 0.0;                      ///< Klipper's N / T
    std::size_t samples = 0;
    WelchSegments segments;
};

/**
 * The spectra as Klipper's shaper_calibrate.py calc_freq_response computes them: fs = N / T,
 * M = klipperSegmentLength(fs), Welch with a symmetric Kaiser window of beta 6, half overlap,
 * segment means removed, density scaling (powerSpectralDensity), and psd_sum = psd_x + psd_y
 * + psd_z. Before calibrate_shaper.py fits a shaper it divides by (f + 0.1) and damps the band
 * below 10 Hz (CalibrationData.normalize_to_frequencies); these are the spectra before that.
 * @param maxFrequencyHz bins above it are dropped (Klipper plots up to 200 Hz).
 * @throws InvalidInput naming "<file>" when the log holds no more than M samples (Klipper
 *         then returns no data), "--max-frequency" when @p maxFrequencyHz is not positive.
 */
AccelerometerSpectra accelerometerSpectra(const AccelerometerLog& log, double maxFrequencyHz);

} // namespace xyt
