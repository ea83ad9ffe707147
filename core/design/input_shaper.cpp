// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/design/input_shaper.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"

#include <cmath>
#include <complex>
#include <numbers>

namespace xyt {

namespace {

void requireMode(double frequencyHz, double dampingRatio) {
    requirePositive(frequencyHz, "frequency");
    if (!(dampingRatio >= 0.0 && dampingRatio < 1.0))
        throw InvalidInput("damping", makeDiagnostic("in_zero_one_open_right"));
}

struct ShaperName {
    ShaperType type;
    const char* name;
};
constexpr ShaperName kShaperNames[] = {
    {ShaperType::Zv, "zv"},
    {ShaperType::Zvd, "zvd"},
    {ShaperType::Zvdd, "zvdd"},
    {ShaperType::Mzv, "mzv"},
    {ShaperType::Ei, "ei"},
    {ShaperType::TwoHumpEi, "2hump_ei"},
    {ShaperType::ThreeHumpEi, "3hump_ei"},
};

} // namespace

const char* shaperName(ShaperType type) {
    for (const ShaperName& n : kShaperNames)
        if (n.type == type)
            return n.name;
    return "zv";
}

bool shaperFromName(const std::string& name, ShaperType& type) {
    for (const ShaperName& n : kShaperNames)
        if (name == n.name) {
            type = n.type;
            return true;
        }
    return false;
}

InputShaper designInputShaper(ShaperType type, double frequencyHz, double dampingRatio) {
    requireMode(frequencyHz, dampingRatio);
    constexpr double kPi = std::numbers::pi;
    const double df = std::sqrt(1.0 - dampingRatio * dampingRatio);
    const double k = std::exp(-dampingRatio * kPi / df);
    const double td = 1.0 / (frequencyHz * df);
    const double v = kShaperVibrationTolerance;
    InputShaper s;
    s.type = type;
    s.frequencyHz = frequencyHz;
    s.dampingRatio = dampingRatio;
    switch (type) {
    case ShaperType::Zv:
        s.amplitudes = {1.0, k};
        break;
    case ShaperType::Zvd:
        s.amplitudes = {1.0, 2.0 * k, k * k};
        break;
    case ShaperType::Zvdd:
        s.amplitudes = {1.0, 3.0 * k, 3.0 * k * k, k * k * k};
        break;
    case ShaperType::Mzv: {
        const double km = std::exp(-0.75 * dampingRatio * kPi / df);
        const double a1 = 1.0 - 1.0 / std::sqrt(2.0);
        s.amplitudes = {a1, (std::sqrt(2.0) - 1.0) * km, a1 * km * km};
        s.times = {0.0, 0.375 * td, 0.75 * td};
        break;
    }
    case ShaperType::Ei:
        s.amplitudes = {0.25 * (1.0 + v), 0.5 * (1.0 - v) * k, 0.25 * (1.0 + v) * k * k};
        break;
    case ShaperType::TwoHumpEi: {
        const double v2 = v * v;
        const double x = std::cbrt(v2 * (std::sqrt(1.0 - v2) + 1.0));
        const double a1 = (3.0 * x * x + 2.0 * x + 3.0 * v2) / (16.0 * x);
        const double a2 = (0.5 - a1) * k;
        s.amplitudes = {a1, a2, a2 * k, a1 * k * k * k};
        break;
    }
    case ShaperType::ThreeHumpEi: {
        const double k2 = k * k;
        const double a1 = 0.0625 * (1.0 + 3.0 * v + 2.0 * std::sqrt(2.0 * (v + 1.0) * v));
        const double a2 = 0.25 * (1.0 - v) * k;
        s.amplitudes = {a1, a2, (0.5 * (1.0 + v) - 2.0 * a1) * k2, a2 * k2, a1 * k2 * k2};
        break;
    }
    }
    if (s.times.empty()) // every other shaper: impulses half a damped period apart
        for (std::size_t i = 0; i < s.amplitudes.size(); ++i)
            s.times.push_back(0.5 * td * static_cast<double>(i));
    double sum = 0.0;
    for (double a : s.amplitudes)
        sum += a;
    for (double& a : s.amplitudes)
        a /= sum;
    return s;
}

double residualVibration(const InputShaper& shaper, double frequencyHz, double dampingRatio) {
    // f = 0 is allowed here (the formula gives sum A_i = 1: a static move passes whole).
    if (!(std::isfinite(frequencyHz) && frequencyHz >= 0.0))
        throw InvalidInput("frequency", makeDiagnostic("finite_not_negative"));
    if (!(dampingRatio >= 0.0 && dampingRatio < 1.0))
        throw InvalidInput("damping", makeDiagnostic("in_zero_one_open_right"));
    const double w = 2.0 * std::numbers::pi * frequencyHz;
    const double wd = w * std::sqrt(1.0 - dampingRatio * dampingRatio);
    const double tn = shaper.duration();
    std::complex<double> sum = 0.0;
    // exp(-zeta w (tn - t_i)) instead of exp(-zeta w tn) exp(zeta w t_i): no overflow.
    for (std::size_t i = 0; i < shaper.amplitudes.size(); ++i)
        sum += shaper.amplitudes[i] * std::exp(-dampingRatio * w * (tn - shaper.times[i])) *
               std::polar(1.0, wd * shaper.times[i]);
    return std::abs(sum);
}

} // namespace xyt
