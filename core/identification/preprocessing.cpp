// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/identification/preprocessing.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <tuple>

namespace xyt {

namespace {

void requireRecord(const IoData& d) {
    if (d.u.size() != d.y.size())
        throw InvalidInput(
            "data", makeDiagnostic("ident_u_y_lengths",
                                   {std::to_string(d.u.size()), std::to_string(d.y.size())}));
}

/// Offset and slope of the least-squares line through x_k over k = 0..n-1.
std::pair<double, double> line(const std::vector<double>& x) {
    const double n = double(x.size());
    const double kbar = (n - 1.0) / 2.0;
    double mean = 0.0;
    for (double v : x)
        mean += v;
    mean /= n;
    double sxy = 0.0, sxx = 0.0;
    for (std::size_t k = 0; k < x.size(); ++k) {
        const double dk = double(k) - kbar;
        sxy += dk * (x[k] - mean);
        sxx += dk * dk;
    }
    const double slope = sxx > 0.0 ? sxy / sxx : 0.0;
    return {mean - slope * kbar, slope};
}

std::vector<double> minusLine(const std::vector<double>& x, double offset, double slope) {
    std::vector<double> out(x.size());
    for (std::size_t k = 0; k < x.size(); ++k)
        out[k] = x[k] - (offset + slope * double(k));
    return out;
}

constexpr std::size_t kPad = 3 * kDecimationFilterOrder; // 3 (nfilt - 1), nfilt = 9 coefficients

/// Runs the cascade over x in place (transposed direct form II), starting every section in its
/// steady state for a constant input equal to x[0].
void runCascade(const std::vector<BiquadSection>& sections, std::vector<double>& x) {
    double level = x.empty() ? 0.0 : x[0];
    for (const BiquadSection& s : sections) {
        const double gain = (s.b[0] + s.b[1] + s.b[2]) / (s.a[0] + s.a[1] + s.a[2]);
        const double out = gain * level;
        double z2 = s.b[2] * level - s.a[2] * out;
        double z1 = s.b[1] * level - s.a[1] * out + z2;
        for (double& v : x) {
            const double in = v;
            const double y = s.b[0] * in + z1;
            z1 = s.b[1] * in - s.a[1] * y + z2;
            z2 = s.b[2] * in - s.a[2] * y;
            v = y;
        }
        level = out;
    }
}

} // namespace

IoData selectTimeRange(const IoData& data, double t0, double t1) {
    requireRecord(data);
    requireFinite(t0, "t0");
    requireFinite(t1, "t1");
    requirePositive(data.tsSeconds, "data");
    if (t1 < t0)
        throw InvalidInput("t1", makeDiagnostic("ident_range_reversed"));
    const double ts = data.tsSeconds;
    const double first = std::ceil((t0 - data.startSeconds) / ts - 1e-9);
    const double last = std::floor((t1 - data.startSeconds) / ts + 1e-9);
    const double n = double(data.size());
    const double from = std::max(first, 0.0), to = std::min(last, n - 1.0);
    if (!(to >= from))
        throw InvalidInput("range", makeDiagnostic("ident_range_no_sample"));
    IoData out = data;
    const auto a = static_cast<std::ptrdiff_t>(from), b = static_cast<std::ptrdiff_t>(to) + 1;
    out.u.assign(data.u.begin() + a, data.u.begin() + b);
    out.y.assign(data.y.begin() + a, data.y.begin() + b);
    out.startSeconds = data.startSeconds + from * ts;
    return out;
}

Detrended removeMeans(const IoData& data) {
    requireRecord(data);
    if (data.size() == 0)
        throw InvalidInput("data", makeDiagnostic("ident_holds_no_sample"));
    Detrended r;
    r.data = data;
    double su = 0.0, sy = 0.0;
    for (std::size_t k = 0; k < data.size(); ++k) {
        su += data.u[k];
        sy += data.y[k];
    }
    r.uOffset = su / double(data.size());
    r.yOffset = sy / double(data.size());
    r.data.u = minusLine(data.u, r.uOffset, 0.0);
    r.data.y = minusLine(data.y, r.yOffset, 0.0);
    return r;
}

Detrended removeTrends(const IoData& data) {
    requireRecord(data);
    if (data.size() < 2)
        throw InvalidInput("data", makeDiagnostic("ident_trend_two_samples"));
    Detrended r;
    r.data = data;
    std::tie(r.uOffset, r.uSlopePerSample) = line(data.u);
    std::tie(r.yOffset, r.ySlopePerSample) = line(data.y);
    r.data.u = minusLine(data.u, r.uOffset, r.uSlopePerSample);
    r.data.y = minusLine(data.y, r.yOffset, r.ySlopePerSample);
    return r;
}

std::vector<BiquadSection> decimationFilter(int factor) {
    if (factor < 2 || factor > 1000)
        throw InvalidInput("factor", makeDiagnostic("ident_anti_alias_factors"));
    constexpr int n = kDecimationFilterOrder;
    const double eps = std::sqrt(std::pow(10.0, kDecimationRippleDb / 10.0) - 1.0);
    const double mu = std::asinh(1.0 / eps) / n;
    const double wc = kDecimationEdge * std::numbers::pi / factor; // rad/sample
    const double warped =
        std::tan(wc / 2.0); // bilinear s = (1 - z^-1)/(1 + z^-1): Omega = tan(w/2)
    std::vector<BiquadSection> sections;
    for (int k = 1; k <= n / 2; ++k) {
        const double theta = (2.0 * k - 1.0) * std::numbers::pi / (2.0 * n);
        const std::complex<double> p(-std::sinh(mu) * std::sin(theta),
                                     std::cosh(mu) * std::cos(theta));
        const std::complex<double> s = warped * p;
        const std::complex<double> z = (1.0 + s) / (1.0 - s);
        BiquadSection sec;
        sec.a = {1.0, -2.0 * z.real(), std::norm(z)};
        const double g = (sec.a[0] + sec.a[1] + sec.a[2]) / 4.0; // unit gain at DC (z = 1)
        sec.b = {g, 2.0 * g, g};
        sections.push_back(sec);
    }
    // Every section has unit gain at DC, so the cascade has too (MATLAB's cheby1 of even order
    // puts DC at the bottom of the ripple, 1/sqrt(1 + eps^2); here a step keeps its level).
    return sections;
}

std::vector<double> zeroPhaseFilter(const std::vector<BiquadSection>& sections,
                                    const std::vector<double>& x) {
    const std::size_t n = x.size();
    if (n <= kPad)
        throw InvalidInput("data",
                           makeDiagnostic("ident_zero_phase_samples", {std::to_string(kPad)}));
    std::vector<double> padded;
    padded.reserve(n + 2 * kPad);
    for (std::size_t k = kPad; k >= 1; --k)
        padded.push_back(2.0 * x[0] - x[k]);
    padded.insert(padded.end(), x.begin(), x.end());
    for (std::size_t k = 1; k <= kPad; ++k)
        padded.push_back(2.0 * x[n - 1] - x[n - 1 - k]);
    runCascade(sections, padded);
    std::reverse(padded.begin(), padded.end());
    runCascade(sections, padded);
    std::reverse(padded.begin(), padded.end());
    return std::vector<double>(padded.begin() + kPad,
                               padded.begin() + static_cast<std::ptrdiff_t>(kPad + n));
}

IoData decimate(const IoData& data, int factor) {
    requireRecord(data);
    if (factor < 1 || factor > 1000)
        throw InvalidInput("factor", makeDiagnostic("ident_factor_whole"));
    requirePositive(data.tsSeconds, "data");
    if (factor == 1)
        return data;
    if (data.size() <= kPad)
        throw InvalidInput("data",
                           makeDiagnostic("ident_decimation_samples",
                                          {std::to_string(data.size()), std::to_string(kPad)}));
    const std::vector<BiquadSection> sections = decimationFilter(factor);
    const std::vector<double> u = zeroPhaseFilter(sections, data.u);
    const std::vector<double> y = zeroPhaseFilter(sections, data.y);
    IoData out;
    out.tsSeconds = data.tsSeconds * factor;
    out.startSeconds = data.startSeconds;
    out.source = data.source;
    for (std::size_t k = 0; k < u.size(); k += static_cast<std::size_t>(factor)) {
        out.u.push_back(u[k]);
        out.y.push_back(y[k]);
    }
    return out;
}

IoData preprocess(const IoData& data, const PreprocessingSteps& steps) {
    IoData out = steps.rangeSeconds
                     ? selectTimeRange(data, (*steps.rangeSeconds)[0], (*steps.rangeSeconds)[1])
                     : data;
    if (steps.offsets == OffsetRemoval::Trends)
        out = removeTrends(out).data;
    else if (steps.offsets == OffsetRemoval::Means)
        out = removeMeans(out).data;
    if (steps.decimateFactor != 1)
        out = decimate(out, steps.decimateFactor);
    return out;
}

} // namespace xyt
