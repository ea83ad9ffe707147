// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/analysis/parameter_locus.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/model/root_matching.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace xyt {

namespace {

using Complex = std::complex<double>;

struct Sample {
    double value;
    std::vector<Complex> roots;
};

double maxDisplacement(const std::vector<Complex>& a, const std::vector<Complex>& b) {
    double worst = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i)
        worst = std::max(worst, std::abs(a[i] - b[i]));
    return worst;
}

class Refiner {
public:
    Refiner(const ParameterSweep& sweep, const std::function<std::vector<Complex>(double)>& poles,
            double bound)
        : sweep_(sweep), poles_(poles), bound_(bound) {}

    /// Appends the samples after out.back() up to and including @p end, refined, matched.
    void extend(std::vector<Sample>& out, const Sample& end, int depth) const {
        const Sample& start = out.back();
        std::vector<Complex> matched = continueBranches(start.roots, end.roots);
        if (depth >= sweep_.maxRefinements || maxDisplacement(start.roots, matched) <= bound_) {
            out.push_back({end.value, std::move(matched)});
            return;
        }
        const double mid = sweep_.logSpacing ? std::sqrt(start.value * end.value)
                                             : 0.5 * (start.value + end.value);
        std::vector<Complex> midRoots = poles_(mid);
        if (midRoots.size() != start.roots.size()) {
            out.push_back({end.value, std::move(matched)});
            return;
        }
        extend(out, Sample{mid, std::move(midRoots)}, depth + 1);
        extend(out, end, depth + 1);
    }

private:
    const ParameterSweep& sweep_;
    const std::function<std::vector<Complex>(double)>& poles_;
    double bound_;
};

} // namespace

std::vector<double> sweepValues(const ParameterSweep& s) {
    requireFinite(s.from, "from");
    requireFinite(s.to, "to");
    if (s.from == s.to)
        throw InvalidInput("to", makeDiagnostic("analysis_to_equals_from"));
    if (s.logSpacing) {
        requirePositive(s.from, "from");
        requirePositive(s.to, "to");
    }
    if (s.count < 2 || s.count > 100000)
        throw InvalidInput("count", makeDiagnostic("analysis_in_integer_range", {"2", "100000"}));
    if (!(s.maxStepFraction > 0.0 && s.maxStepFraction <= 1.0))
        throw InvalidInput("maxStepFraction", makeDiagnostic("in_zero_one_open_left"));
    if (s.maxRefinements < 0 || s.maxRefinements > 20)
        throw InvalidInput("maxRefinements",
                           makeDiagnostic("analysis_in_integer_range", {"0", "20"}));
    std::vector<double> v(static_cast<std::size_t>(s.count));
    for (int i = 0; i < s.count; ++i) {
        const double t = static_cast<double>(i) / (s.count - 1);
        v[static_cast<std::size_t>(i)] =
            s.logSpacing ? s.from * std::pow(s.to / s.from, t) : s.from + t * (s.to - s.from);
    }
    v.back() = s.to; // exact end despite round-off
    return v;
}

ParameterLocus
parameterLocus(const std::string& parameterName, const ParameterSweep& sweep,
               const std::function<std::vector<std::complex<double>>(double)>& poles) {
    const std::vector<double> values = sweepValues(sweep);
    ParameterLocus locus;
    locus.parameterName = parameterName;
    std::vector<Sample> base;
    for (double v : values) {
        std::vector<Complex> roots = poles(v);
        if (!base.empty() && roots.size() != base.front().roots.size()) {
            locus.warnings.push_back(makeDiagnostic("analysis_locus_sample_skipped",
                                                    {parameterName, std::to_string(v)}));
            continue;
        }
        base.push_back({v, std::move(roots)});
    }
    // The step bound is a fraction of the extent of all base poles (the view they need).
    double reMin = std::numeric_limits<double>::infinity(), reMax = -reMin, imAbs = 0.0;
    for (const Sample& s : base)
        for (const Complex& r : s.roots) {
            reMin = std::min(reMin, r.real());
            reMax = std::max(reMax, r.real());
            imAbs = std::max(imAbs, std::abs(r.imag()));
        }
    const double extent = std::max(reMax - reMin, 2.0 * imAbs);
    const Refiner refiner(sweep, poles, sweep.maxStepFraction * extent);
    std::vector<Sample> samples{base.front()};
    for (std::size_t i = 1; i < base.size(); ++i)
        refiner.extend(samples, base[i], 0);
    locus.branches.assign(samples.front().roots.size(), {});
    const auto maxRe = [](const std::vector<Complex>& roots) {
        double m = -std::numeric_limits<double>::infinity();
        for (const Complex& r : roots)
            m = std::max(m, r.real());
        return m;
    };
    for (std::size_t i = 1; i < samples.size(); ++i) {
        const bool stableBefore = maxRe(samples[i - 1].roots) < 0.0;
        if (stableBefore == (maxRe(samples[i].roots) < 0.0))
            continue;
        // Bisection on the value: 200 halvings reach adjacent doubles from any interval.
        double lo = samples[i - 1].value, hi = samples[i].value;
        std::vector<Complex> atHi = samples[i].roots;
        for (int k = 0; k < 200; ++k) {
            const double mid = 0.5 * (lo + hi);
            if (!(mid > std::min(lo, hi) && mid < std::max(lo, hi)))
                break;
            std::vector<Complex> r = poles(mid);
            if ((maxRe(r) < 0.0) == stableBefore)
                lo = mid;
            else {
                hi = mid;
                atHi = std::move(r);
            }
            if (std::abs(hi - lo) <= 1e-13 * std::abs(hi))
                break;
        }
        StabilityChange change;
        change.value = 0.5 * (lo + hi);
        change.becomesUnstable = stableBefore == (samples[i].value > samples[i - 1].value);
        double best = std::numeric_limits<double>::infinity();
        for (const Complex& r : atHi)
            if (std::abs(r.real()) < best && r.imag() >= 0.0) {
                best = std::abs(r.real());
                change.pole = r;
            }
        locus.stabilityChanges.push_back(change);
    }
    for (const Sample& s : samples) {
        locus.values.push_back(s.value);
        for (std::size_t b = 0; b < s.roots.size(); ++b)
            locus.branches[b].push_back(s.roots[b]);
    }
    return locus;
}

ParameterLocus gtParameterLocus(const ThirdOrderPlant& plant, GtSweptParameter parameter,
                                const ParameterSweep& sweep, double fixedValue) {
    plant.validate();
    const bool sweepsOmega = parameter == GtSweptParameter::OmegaN;
    requirePositive(fixedValue, sweepsOmega ? "kp" : "wn");
    const std::string name = sweepsOmega ? "wn" : "kp";
    if (!(std::min(sweep.from, sweep.to) > 0.0))
        throw InvalidInput(name, makeDiagnostic("analysis_swept_values_not_positive"));
    return parameterLocus(name, sweep, [&](double value) {
        const GtDesign d = sweepsOmega ? designGuilleminTruxal(plant, value, fixedValue)
                                       : designGuilleminTruxal(plant, fixedValue, value);
        return d.closedLoopPoles;
    });
}

} // namespace xyt
