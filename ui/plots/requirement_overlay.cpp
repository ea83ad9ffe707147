// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/plots/requirement_overlay.h"
#include "ui/plots/number_text.h"

#include "core/analysis/damping_grid.h"
#include "ui/plots/plane_grid.h"
#include "ui/plots/plot_tools.h"

#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

namespace xyt::ui {

namespace {
using Complex = std::complex<double>;
const QColor kBoundary{0xc6, 0x28, 0x28};
const QColor kShade{0xd6, 0x27, 0x28, 16}; // light: the locus stays readable through it
const QColor kOmega{0x94, 0x67, 0xbd};
const QColor kAllowed{0x2c, 0xa0, 0x2c, 90};

QCPCurve* makeCurve(QCustomPlot* plot, const QPen& pen, const QBrush& brush = Qt::NoBrush) {
    auto* c = new QCPCurve(plot->xAxis, plot->yAxis);
    c->setPen(pen);
    c->setBrush(brush);
    c->removeFromLegend();
    return c;
}

void setPoints(QCPCurve* curve, const std::vector<Complex>& points) {
    QVector<QCPCurveData> data;
    data.reserve(static_cast<qsizetype>(points.size()));
    for (std::size_t i = 0; i < points.size(); ++i)
        data.append(QCPCurveData(static_cast<double>(i), points[i].real(), points[i].imag()));
    curve->data()->set(data, true);
}

/// The square of half-width @p l, closed; followed by a closed inner loop it makes, under the
/// odd-even fill of a curve's brush, the region outside that loop.
std::vector<Complex> square(double l) {
    return {{-l, -l}, {l, -l}, {l, l}, {-l, l}, {-l, -l}};
}

std::vector<Complex> circle(double r, int n = 181) {
    std::vector<Complex> out;
    for (int i = 0; i <= n; ++i)
        out.push_back(std::polar(r, 2.0 * std::numbers::pi * i / n));
    return out;
}
struct DominantPair {
    Complex pole;      ///< in the plane drawn (upper half)
    double omegaN = 0; ///< |s| of its continuous equivalent, rad/s
    double zeta = 0;   ///< -Re s / |s|
};

/// The complex pair whose continuous equivalent (s, or ln z / Ts) decays slowest; none when
/// the loop has no complex pair.
std::optional<DominantPair> dominantPair(const std::vector<Complex>& poles, double ts) {
    std::optional<DominantPair> best;
    double slowest = std::numeric_limits<double>::infinity();
    for (const Complex& p : poles) {
        if (!(std::isfinite(p.real()) && std::isfinite(p.imag())) || p.imag() <= 1e-9 * std::abs(p))
            continue;
        if (ts > 0.0 && std::abs(p) == 0.0)
            continue;
        const Complex s = ts > 0.0 ? std::log(p) / ts : p;
        if (-s.real() < slowest) {
            slowest = -s.real();
            best = DominantPair{p, std::abs(s), -s.real() / std::abs(s)};
        }
    }
    return best;
}
} // namespace

RequirementOverlay::RequirementOverlay(QCustomPlot* plot) {
    dampingShade_ = makeCurve(plot, Qt::NoPen, kShade);
    settlingShade_ = makeCurve(plot, Qt::NoPen, kShade);
    for (QCPCurve* shade : {dampingShade_, settlingShade_})
        shade->setLayer(QStringLiteral("background"));
    damping_ = makeCurve(plot, QPen(kBoundary, 1.6, Qt::DashLine));
    settling_ = makeCurve(plot, QPen(kBoundary, 1.6, Qt::DashDotLine));
    omega_ = makeCurve(plot, QPen(kOmega, 1.4, Qt::DashLine));
    violating_ = plot->addGraph();
    violating_->setLineStyle(QCPGraph::lsNone);
    violating_->setScatterStyle(
        QCPScatterStyle(QCPScatterStyle::ssCircle, QPen(colors::error, 2.0), Qt::NoBrush, 18));
    violating_->setName(QObject::tr("breaks spec"));
    violating_->removeFromLegend();
    dominant_ = plot->addGraph();
    dominant_->setLineStyle(QCPGraph::lsNone);
    dominant_->setScatterStyle(
        QCPScatterStyle(QCPScatterStyle::ssSquare, QPen(kOmega, 1.6), Qt::NoBrush, 14));
    dominant_->removeFromLegend();
}

void RequirementOverlay::clear() {
    for (QCPCurve* c : {damping_, settling_, omega_, dampingShade_, settlingShade_}) {
        c->data()->clear();
        c->removeFromLegend();
    }
    violating_->data()->clear();
    violating_->removeFromLegend();
    dominant_->data()->clear();
    dominant_->removeFromLegend();
}

void RequirementOverlay::show(const LocusRequirements& req, double ts, double extent,
                              const std::vector<Complex>& closedLoopPoles) {
    clear();
    if (!req.active)
        return;
    PoleRequirements poles;
    try {
        poles = poleRequirements(req.maxOvershootPct, req.maxSettlingTimeSeconds);
    } catch (const std::exception&) {
        return; // a specification the metrics panel refuses has nothing to draw
    }
    const bool discrete = ts > 0.0;
    // Far beyond any view the user reaches by zooming out from the fitted one.
    const double far = 1e3 * std::max(extent, discrete ? 1.0 : 1e-6);
    const double zeta = poles.minDamping;

    // zeta: the wedge (s) or spiral (z) of the overshoot limit; zeta = 1 leaves only the
    // negative real axis (the real segment (0, 1] in z), drawn thick so it shows.
    std::vector<Complex> boundary, shade;
    if (discrete) {
        boundary = zPlaneDampingGrid({zeta}, {}, ts).dampingLines.front().points;
        shade = square(far);
        shade.insert(shade.end(), boundary.begin(), boundary.end());
        shade.push_back(boundary.front());
    } else {
        boundary = sPlaneDampingGrid({zeta}, {}, far).dampingLines.front().points;
        // Forbidden: the sector from the upper ray clockwise through the right half plane to
        // the lower ray, a polygon star-shaped about the origin (vertices by falling angle).
        const double upperAngle = std::arg(boundary.front());
        shade = {Complex(0.0), boundary.front()};
        for (double corner : {0.75, 0.25, -0.25, -0.75})
            if (corner * std::numbers::pi < upperAngle && corner * std::numbers::pi > -upperAngle)
                shade.push_back(std::polar(far * std::sqrt(2.0), corner * std::numbers::pi));
        shade.push_back(boundary.back());
        shade.push_back(Complex(0.0));
    }
    setPoints(damping_, boundary);
    // zeta = 1 forbids all but a line: shading the whole plane would hide the locus and say
    // nothing the green strip and the ringed poles do not, so only a partial wedge is shaded.
    if (zeta < 1.0)
        setPoints(dampingShade_, shade);
    // zeta = 1: the allowed set is a line, drawn as a wide translucent green strip.
    damping_->setPen(zeta >= 1.0 ? QPen(kAllowed, 4.0) : QPen(kBoundary, 1.6, Qt::DashLine));
    damping_->setName(zeta >= 1.0
                          ? QObject::tr("ζ = 1 (Mp 0 %)")
                          : QObject::tr("ζ ≥ %1 (Mp %2 %)")
                                .arg(significant(zeta, 3), significant(req.maxOvershootPct, 3)));
    damping_->addToLegend();

    // Settling: Re s <= sigma, or |z| <= exp(sigma Ts).
    if (std::isfinite(poles.maxRealPartPerSec)) {
        const double sigma = poles.maxRealPartPerSec;
        if (discrete) {
            const double r = settlingRadius(poles, ts);
            const std::vector<Complex> ring = circle(r);
            setPoints(settling_, ring);
            std::vector<Complex> s = square(far);
            s.insert(s.end(), ring.begin(), ring.end());
            setPoints(settlingShade_, s);
            settling_->setName(
                QObject::tr("|z| ≤ %1 (ts %2 s)")
                    .arg(significant(r, 4), significant(req.maxSettlingTimeSeconds, 3)));
        } else {
            setPoints(settling_, {Complex(sigma, far), Complex(sigma, -far)});
            setPoints(settlingShade_,
                      {{sigma, -far}, {far, -far}, {far, far}, {sigma, far}, {sigma, -far}});
            settling_->setName(
                QObject::tr("σ ≤ %1 (ts %2 s)")
                    .arg(significant(sigma, 3), significant(req.maxSettlingTimeSeconds, 3)));
        }
        settling_->addToLegend();
    }

    // The reference model's omega_n (a Guillemin-Truxal design parameter, not a requirement,
    // and not the closed-loop poles' own omega_n: marked below).
    if (!discrete && std::isfinite(req.designOmegaNRadPerSec) && req.designOmegaNRadPerSec > 0.0) {
        setPoints(
            omega_,
            sPlaneDampingGrid({}, {req.designOmegaNRadPerSec}, far).frequencyLines.front().points);
        omega_->setName(
            QObject::tr("reference model ωn %1").arg(significant(req.designOmegaNRadPerSec, 3)));
        omega_->addToLegend();
    }
    if (const auto pair = dominantPair(closedLoopPoles, ts)) {
        setComplexPoints(dominant_, {pair->pole, std::conj(pair->pole)});
        dominant_->setName(QObject::tr("dominant poles: ωn %1 rad/s, ζ %2")
                               .arg(significant(pair->omegaN, 3), significant(pair->zeta, 2)));
        dominant_->addToLegend();
    }

    std::vector<Complex> bad;
    for (const Complex& p : closedLoopPoles)
        if (std::isfinite(p.real()) && std::isfinite(p.imag()) && checkPole(p, poles, ts).any())
            bad.push_back(p);
    setComplexPoints(violating_, bad);
    if (!bad.empty())
        violating_->addToLegend();
}

} // namespace xyt::ui
