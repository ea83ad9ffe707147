// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/identification/spectral_estimate.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/model/number_format.h"

#include <unsupported/Eigen/FFT>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>

namespace xyt {

namespace {

constexpr double kSpectralPi = 3.14159265358979323846;

/// Zeroth-order modified Bessel function of the first kind by its power series
/// sum_k ((x/2)^k / k!)^2 (Abramowitz and Stegun 9.6.10): all terms positive, so it converges
/// without cancellation; for beta <= 50 about 60 terms reach double precision.
double spectralBesselI0(double x) {
    const double q = 0.25 * x * x;
    double term = 1.0, sum = 1.0;
    for (int k = 1; k < 500; ++k) {
        term *= q / (static_cast<double>(k) * static_cast<double>(k));
        sum += term;
        if (term < sum * 1e-17)
            break;
    }
    return sum;
}

std::vector<double> spectralWindow(const WelchOptions& o, std::size_t m) {
    std::vector<double> w(m);
    if (o.window == SpectralWindow::Hann) {
        for (std::size_t n = 0; n < m; ++n)
            w[n] = 0.5 - 0.5 * std::cos(2.0 * kSpectralPi * static_cast<double>(n) /
                                        static_cast<double>(m));
    } else {
        const double denom = spectralBesselI0(o.kaiserBeta);
        for (std::size_t n = 0; n < m; ++n) {
            const double r = 2.0 * static_cast<double>(n) / static_cast<double>(m - 1) - 1.0;
            w[n] = spectralBesselI0(o.kaiserBeta * std::sqrt(std::max(0.0, 1.0 - r * r))) / denom;
        }
    }
    return w;
}

void requireSpectralSegmentOptions(const WelchOptions& o) {
    if (o.segmentLength != 0 && o.segmentLength < 4)
        throw InvalidInput("segment", makeDiagnostic("ident_segment_at_least_4",
                                                     {std::to_string(o.segmentLength)}));
    if (o.window == SpectralWindow::Kaiser &&
        !(std::isfinite(o.kaiserBeta) && o.kaiserBeta >= 0.0 && o.kaiserBeta <= 50.0))
        throw InvalidInput("kaiser_beta", makeDiagnostic("ident_kaiser_beta_range"));
}

void requireSpectralSignal(const std::vector<double>& x, const std::string& field,
                           const WelchSegments& s) {
    for (std::size_t i = 0; i < x.size(); ++i)
        if (!std::isfinite(x[i]))
            throw InvalidInput(field, makeDiagnostic("sample_not_finite", {std::to_string(i + 1)}));
    if (s.count < 2)
        throw InvalidInput(
            field, makeDiagnostic("ident_welch_too_few",
                                  {std::to_string(x.size()), std::to_string(s.segmentLength),
                                   std::to_string(s.segmentLength + s.step)}));
}

/// Samples near the top of the double range (1e160 and up) square past it: refused rather than
/// returned as an infinite spectrum.
void requireSpectralFinite(double value, const std::string& field) {
    if (!std::isfinite(value))
        throw InvalidInput(field, makeDiagnostic("ident_psd_overflows"));
}

void requireSpectralTs(double ts) {
    if (!(std::isfinite(ts) && ts > 0.0))
        throw InvalidInput("ts", makeDiagnostic("ident_positive_finite"));
}

/// The windowed, mean-removed FFT (bins 0..M/2) of every segment of one signal, in turn.
class SpectralSegmentTransformer {
public:
    SpectralSegmentTransformer(const WelchSegments& s, const std::vector<double>& window)
        : s_(s), window_(window), buffer_(s.segmentLength) {
        fft_.SetFlag(Eigen::FFT<double>::HalfSpectrum);
    }
    const std::vector<std::complex<double>>& transform(const std::vector<double>& x,
                                                       std::size_t segment) {
        const std::size_t start = segment * s_.step;
        double mean = 0.0;
        for (std::size_t n = 0; n < s_.segmentLength; ++n)
            mean += x[start + n];
        mean /= static_cast<double>(s_.segmentLength);
        for (std::size_t n = 0; n < s_.segmentLength; ++n)
            buffer_[n] = (x[start + n] - mean) * window_[n];
        fft_.fwd(spectrum_, buffer_);
        return spectrum_;
    }

private:
    const WelchSegments& s_;
    const std::vector<double>& window_;
    std::vector<double> buffer_;
    std::vector<std::complex<double>> spectrum_;
    Eigen::FFT<double> fft_;
};

/// c_k / (fs sum w^2): the one-sided density scale of bin k.
std::vector<double> spectralDensityScale(const std::vector<double>& w, double ts,
                                         std::size_t bins) {
    double power = 0.0;
    for (double v : w)
        power += v * v;
    std::vector<double> scale(bins, 2.0 * ts / power);
    scale[0] = ts / power;
    if (w.size() % 2 == 0)
        scale[bins - 1] = ts / power; // the unpaired Nyquist bin
    return scale;
}

std::vector<double> spectralFrequencyAxis(std::size_t bins, std::size_t m, double ts) {
    std::vector<double> f(bins);
    for (std::size_t k = 0; k < bins; ++k)
        f[k] = static_cast<double>(k) / (static_cast<double>(m) * ts);
    return f;
}

} // namespace

std::size_t defaultWelchSegmentLength(std::size_t samples) {
    std::size_t m = kMinDefaultWelchSegment;
    while (m * 2 <= kMaxDefaultWelchSegment && 2 * samples >= 9 * (m * 2))
        m *= 2;
    return m;
}

WelchSegments welchSegments(std::size_t samples, const WelchOptions& options) {
    requireSpectralSegmentOptions(options);
    WelchSegments s;
    s.segmentLength =
        options.segmentLength != 0 ? options.segmentLength : defaultWelchSegmentLength(samples);
    s.step = s.segmentLength - s.segmentLength / 2;
    s.count = samples < s.segmentLength ? 0 : (samples - s.segmentLength) / s.step + 1;
    if (s.count == 0)
        return s;
    // Overlap correlation at lag one segment (the only nonzero one: S >= M/2).
    const std::vector<double> w = spectralWindow(options, s.segmentLength);
    double power = 0.0, lagged = 0.0;
    for (std::size_t n = 0; n < s.segmentLength; ++n) {
        power += w[n] * w[n];
        if (n + s.step < s.segmentLength)
            lagged += w[n] * w[n + s.step];
    }
    const double rho = lagged / power;
    const double k = static_cast<double>(s.count);
    s.equivalentAverages = k / (1.0 + 2.0 * (1.0 - 1.0 / k) * rho * rho);
    return s;
}

WelchSpectrum powerSpectralDensity(const std::vector<double>& x, double tsSeconds,
                                   const WelchOptions& options) {
    requireSpectralTs(tsSeconds);
    const WelchSegments s = welchSegments(x.size(), options);
    requireSpectralSignal(x, "x", s);
    const std::vector<double> w = spectralWindow(options, s.segmentLength);
    const std::size_t bins = s.segmentLength / 2 + 1;
    WelchSpectrum out;
    out.sampleTimeSeconds = tsSeconds;
    out.segments = s;
    out.frequencyHz = spectralFrequencyAxis(bins, s.segmentLength, tsSeconds);
    out.psd.assign(bins, 0.0);
    SpectralSegmentTransformer t(s, w);
    for (std::size_t i = 0; i < s.count; ++i) {
        const auto& X = t.transform(x, i);
        for (std::size_t k = 0; k < bins; ++k)
            out.psd[k] += std::norm(X[k]);
    }
    const std::vector<double> scale = spectralDensityScale(w, tsSeconds, bins);
    for (std::size_t k = 0; k < bins; ++k) {
        out.psd[k] *= scale[k] / static_cast<double>(s.count);
        requireSpectralFinite(out.psd[k], "x");
    }
    return out;
}

FrequencyResponseEstimate estimateFrequencyResponse(const std::vector<double>& u,
                                                    const std::vector<double>& y, double tsSeconds,
                                                    const WelchOptions& options,
                                                    double bandSigmas) {
    requireSpectralTs(tsSeconds);
    if (!(std::isfinite(bandSigmas) && bandSigmas > 0.0))
        throw InvalidInput("band_sigmas", makeDiagnostic("ident_positive_finite"));
    if (y.size() != u.size())
        throw InvalidInput("y",
                           makeDiagnostic("ident_y_u_equally_long",
                                          {std::to_string(y.size()), std::to_string(u.size())}));
    const WelchSegments s = welchSegments(u.size(), options);
    requireSpectralSignal(u, "u", s);
    requireSpectralSignal(y, "y", s);
    const std::vector<double> w = spectralWindow(options, s.segmentLength);
    const std::size_t bins = s.segmentLength / 2 + 1;
    std::vector<double> puu(bins, 0.0), pyy(bins, 0.0);
    std::vector<std::complex<double>> puy(bins, 0.0);
    SpectralSegmentTransformer tu(s, w), ty(s, w);
    for (std::size_t i = 0; i < s.count; ++i) {
        const auto& U = tu.transform(u, i);
        const auto& Y = ty.transform(y, i);
        for (std::size_t k = 0; k < bins; ++k) {
            puu[k] += std::norm(U[k]);
            pyy[k] += std::norm(Y[k]);
            puy[k] += std::conj(U[k]) * Y[k];
        }
    }
    const std::vector<double> scale = spectralDensityScale(w, tsSeconds, bins);
    FrequencyResponseEstimate out;
    out.sampleTimeSeconds = tsSeconds;
    out.segments = s;
    out.bandSigmas = bandSigmas;
    out.frequencyHz = spectralFrequencyAxis(bins, s.segmentLength, tsSeconds);
    out.magnitude.resize(bins);
    out.phaseRad.resize(bins);
    out.coherence.resize(bins);
    out.relativeError.resize(bins);
    out.magnitudeLow.resize(bins);
    out.magnitudeHigh.resize(bins);
    const double perSegment = 1.0 / static_cast<double>(s.count);
    double previousPhase = 0.0, offset = 0.0;
    for (std::size_t k = 0; k < bins; ++k) {
        puu[k] *= scale[k] * perSegment;
        pyy[k] *= scale[k] * perSegment;
        puy[k] *= scale[k] * perSegment;
        requireSpectralFinite(puu[k], "u");
        requireSpectralFinite(pyy[k], "y");
        requireSpectralFinite(std::abs(puy[k]), "y");
        // An input without power at a bin (a constant, or a multisine's empty bins) gives no
        // estimate there: H1 = 0 with coherence 0 and an infinite error, never a NaN.
        const std::complex<double> h = puu[k] > 0.0 ? puy[k] / puu[k] : 0.0;
        const double g2 = puu[k] > 0.0 && pyy[k] > 0.0
                              ? std::min(1.0, std::norm(puy[k]) / (puu[k] * pyy[k]))
                              : 0.0;
        out.magnitude[k] = std::abs(h);
        // numpy.unwrap: a jump beyond pi between neighbours is taken as a wrap.
        const double raw = std::arg(h);
        if (k > 0) {
            const double d = raw + offset - previousPhase;
            if (d > kSpectralPi || d < -kSpectralPi)
                offset -= 2.0 * kSpectralPi * std::round(d / (2.0 * kSpectralPi));
        }
        out.phaseRad[k] = raw + offset;
        previousPhase = out.phaseRad[k];
        out.coherence[k] = g2;
        const double eps =
            g2 > 0.0 ? std::sqrt(1.0 - g2) / (std::sqrt(g2) * std::sqrt(2.0 * s.equivalentAverages))
                     : std::numeric_limits<double>::infinity();
        out.relativeError[k] = eps;
        out.magnitudeLow[k] = std::max(0.0, out.magnitude[k] * (1.0 - bandSigmas * eps));
        out.magnitudeHigh[k] = std::isfinite(eps) ? out.magnitude[k] * (1.0 + bandSigmas * eps)
                                                  : std::numeric_limits<double>::infinity();
    }
    out.inputPsd = std::move(puu);
    out.outputPsd = std::move(pyy);
    return out;
}

ResonancePick pickResonance(const std::vector<double>& f, const std::vector<double>& v,
                            ResonanceQuantity quantity, const ResonanceBand& band) {
    if (f.size() != v.size())
        throw InvalidInput("frequency",
                           makeDiagnostic("ident_frequency_values_lengths",
                                          {std::to_string(f.size()), std::to_string(v.size())}));
    if (f.size() < 3)
        throw InvalidInput("frequency", makeDiagnostic("ident_three_bins"));
    for (std::size_t k = 0; k < f.size(); ++k) {
        if (!std::isfinite(f[k]) || (k > 0 && !(f[k] > f[k - 1])))
            throw InvalidInput("frequency",
                               makeDiagnostic("ident_bin_increasing", {std::to_string(k + 1)}));
        if (!std::isfinite(v[k]) || v[k] < 0.0)
            throw InvalidInput("values",
                               makeDiagnostic("ident_bin_not_negative", {std::to_string(k + 1)}));
    }
    const double lowHz = band.lowHz.value_or(f[2]);
    const double highHz = band.highHz.value_or(f.back());
    const std::string bandText = "[" + formatNumber(lowHz) + ", " + formatNumber(highHz) + "] Hz";
    if (!(std::isfinite(lowHz) && std::isfinite(highHz) && lowHz < highHz))
        throw InvalidInput("band", makeDiagnostic("ident_band_empty", {bandText}));
    std::size_t first = f.size(), last = 0;
    for (std::size_t k = 0; k < f.size(); ++k)
        if (f[k] >= lowHz && f[k] <= highHz) {
            first = std::min(first, k);
            last = k;
        }
    if (first >= f.size() || last < first + 2)
        throw InvalidInput(
            "band", makeDiagnostic("ident_band_few_bins",
                                   {bandText, formatNumber(f.front()), formatNumber(f.back())}));
    std::size_t p = first;
    for (std::size_t k = first; k <= last; ++k)
        if (v[k] > v[p])
            p = k;
    ResonancePick r;
    r.peakBin = p;
    r.frequencyHz = f[p];
    r.peakValue = v[p];
    if (p > first && p < last) {
        // The parabola through (f[p-1], v[p-1]), (f[p], v[p]), (f[p+1], v[p+1]); the bins are
        // equally spaced in an estimate, but the general three-point vertex is used.
        const double x0 = f[p - 1] - f[p], x2 = f[p + 1] - f[p];
        const double y0 = v[p - 1] - v[p], y2 = v[p + 1] - v[p];
        const double a = (y0 * x2 - y2 * x0) / (x0 * x2 * (x0 - x2));
        const double b = (y0 - a * x0 * x0) / x0;
        if (a < 0.0) {
            const double xv = std::clamp(-b / (2.0 * a), x0, x2);
            r.frequencyHz = f[p] + xv;
            r.peakValue = std::max(v[p], v[p] + a * xv * xv + b * xv);
        }
    }
    const double level =
        quantity == ResonanceQuantity::Magnitude ? r.peakValue / std::sqrt(2.0) : r.peakValue / 2.0;
    for (std::size_t k = p; k > first; --k)
        if (v[k - 1] <= level) {
            r.lowHalfPowerHz =
                f[k - 1] + (level - v[k - 1]) / (v[k] - v[k - 1]) * (f[k] - f[k - 1]);
            break;
        }
    for (std::size_t k = p; k < last; ++k)
        if (v[k + 1] <= level) {
            r.highHalfPowerHz = f[k] + (v[k] - level) / (v[k] - v[k + 1]) * (f[k + 1] - f[k]);
            break;
        }
    if (!r.lowHalfPowerHz)
        r.note = makeDiagnostic("ident_no_damping_below", {formatNumber(r.frequencyHz), bandText});
    else if (!r.highHalfPowerHz)
        r.note = makeDiagnostic("ident_no_damping_above", {formatNumber(r.frequencyHz), bandText});
    else
        r.dampingRatio = (*r.highHalfPowerHz - *r.lowHalfPowerHz) / (2.0 * r.frequencyHz);
    return r;
}

void requireBelowNyquist(double frequencyHz, double tsSeconds, const std::string& field) {
    if (!(std::isfinite(frequencyHz) && frequencyHz > 0.0))
        throw InvalidInput(field, makeDiagnostic("ident_positive_frequency_hz"));
    const double nyquist = 0.5 / tsSeconds;
    if (frequencyHz > nyquist)
        throw InvalidInput(field,
                           makeDiagnostic("ident_above_log_nyquist",
                                          {formatNumber(frequencyHz), formatNumber(nyquist)}));
}

} // namespace xyt
