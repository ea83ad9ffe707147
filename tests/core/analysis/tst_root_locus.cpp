// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/analysis/root_locus.h"
#include "core/design/guillemin_truxal.h"
#include "core/model/errors.h"
#include "core/model/root_matching.h"
#include "tests/support/tolerance.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <numbers>

using namespace xyt;
using Complex = std::complex<double>;
Q_DECLARE_METATYPE(xyt::Polynomial)

namespace {

struct Loop {
    Polynomial num, den;
    double ts;
};

/// L = G_c G of the GT design of a preset (K multiplies it: K = 1 is the design).
Loop gtLoop(const char* preset) {
    const GtPreset p = *findGtPreset(preset);
    const GtDesign d = designGuilleminTruxal(p.plant, p.omegaNRadPerSec, p.kp);
    return {d.openLoop.num(), d.openLoop.den(), 0.0};
}

/// Patrick, Ishak and Adnan Eq. 1 (x axis): B/A in ascending powers of z^-1, Ts = 0.07 s.
Loop paperXAxis() {
    const TransferFunction tf =
        TransferFunction::fromZInverse(Polynomial::fromAscending({0.0, 0.0421, 0.0628, -0.0454}),
                                       Polynomial::fromAscending({1.0, -1.6580, 0.6583}), 0.07);
    return {tf.num(), tf.den(), tf.tsSeconds()};
}

/// The test loops by name (the same names as in tests/data/root_locus_reference.json).
Loop loopNamed(const QString& name) {
    if (name == "type1")
        return {Polynomial::fromDescending({1}), Polynomial::fromDescending({1, 3, 2, 0}), 0.0};
    if (name == "double_integrator_lead")
        return {Polynomial::fromDescending({1, 1}), Polynomial::fromDescending({1, 10, 0, 0}), 0.0};
    if (name == "z_double_pole_zero")
        return {Polynomial::fromDescending({1, 0.5}), Polynomial::fromDescending({1, -1, 0.25}),
                0.1};
    if (name == "z_double_pole")
        return {Polynomial::fromDescending({1}), Polynomial::fromDescending({1, -1, 0.25}), 0.1};
    if (name == "arx_x_axis")
        return paperXAxis();
    if (name == "gt_lower_base")
        return gtLoop("lower-base");
    if (name == "gt_upper_base")
        return gtLoop("upper-base");
    qFatal("unknown loop %s", qPrintable(name));
}

const QStringList kLoopNames = {
    "type1",      "double_integrator_lead", "z_double_pole_zero", "z_double_pole",
    "arx_x_axis", "gt_lower_base",          "gt_upper_base"};

QJsonArray referenceLoops() {
    // XYT_TEST_DATA_DIR points at tests/core/data (the helper's CMAKE_CURRENT_SOURCE_DIR is the
    // calling directory); the committed data live in tests/data.
    QFile f(QStringLiteral(XYT_SOURCE_DIR "/tests/data/root_locus_reference.json"));
    if (!f.open(QIODevice::ReadOnly))
        qFatal("cannot read root_locus_reference.json");
    return QJsonDocument::fromJson(f.readAll()).object()["loops"].toArray();
}

/// GT crossing by Routh-Hurwitz on s^4 + a1 s^3 + a2 s^2 + K k0 kp s + K k0 ki: the s^1 row
/// (b1 K k0 kp - a1 K k0 ki)/b1 with b1 = (a1 a2 - K k0 kp)/a1 vanishes at
/// K = (a1 a2 kp - a1^2 ki)/(k0 kp^2); the s^3-row auxiliary a1 s^3 + K k0 kp s gives
/// omega^2 = K k0 kp / a1.
void gtRouth(const char* preset, double& k, double& omega) {
    const GtPreset p = *findGtPreset(preset);
    const GtDesign d = designGuilleminTruxal(p.plant, p.omegaNRadPerSec, p.kp);
    const double a1 = p.plant.a1, a2 = p.plant.a2, k0 = p.plant.k0, kp = d.kp, ki = d.ki;
    k = (a1 * a2 * kp - a1 * a1 * ki) / (k0 * kp * kp);
    omega = std::sqrt(k * k0 * kp / a1);
}

} // namespace

class TstRootLocus : public QObject {
    Q_OBJECT
private slots:
    void crossingsMatchClosedForms_data();
    void crossingsMatchClosedForms();
    void breakawaysMatchClosedForms_data();
    void breakawaysMatchClosedForms();
    void featureGainsMatchNumpyReference_data();
    void featureGainsMatchNumpyReference();
    void asymptotes_data();
    void asymptotes();
    void everyPointIsAClosedLoopPole_data();
    void everyPointIsAClosedLoopPole();
    void branchesAreContinuous_data();
    void branchesAreContinuous();
    void pointsAreDenserNearBreakaway();
    void branchesEndAtZerosOrLeaveTheView_data();
    void branchesEndAtZerosOrLeaveTheView();
    void designPointIsTheGtClosedLoop_data();
    void designPointIsTheGtClosedLoop();
    void kMaxEndsTheTraceExactly();
    void pointLimitBoundsTheRun();
    void matchingMinimisesTotalDisplacement();
    void pickGivesGainAndDamping();
    void pickOnDiscreteLocusUsesLogMap();
    void invalidInputThrows_data();
    void invalidInputThrows();
    void refusalsAndWarningsAreCoded();
    void clusteredPolesWarnAndWorkIsBounded();
};

void TstRootLocus::crossingsMatchClosedForms_data() {
    QTest::addColumn<QString>("loop");
    QTest::addColumn<double>("gain");
    QTest::addColumn<double>("re");
    QTest::addColumn<double>("im");
    // Routh: s^3 + 3 s^2 + 2 s + K marginal at 3 * 2 = K, auxiliary 3 s^2 + 6: omega = sqrt(2).
    QTest::newRow("type1 Routh") << "type1" << 6.0 << 0.0 << std::sqrt(2.0);
    // Jury for z^2 + (K-1) z + 0.25 + 0.5K: |a0| < 1 fails at K = 1.5, where the pair is the
    // root of z^2 + 0.5 z + 1: -0.25 + j sqrt(15)/4; 1 - a1 + a0 = 2.25 - 0.5K fails at K = 4.5
    // (real root at z = -1).
    QTest::newRow("z (z+0.5)/(z-0.5)^2 Jury a0")
        << "z_double_pole_zero" << 1.5 << -0.25 << std::sqrt(15.0) / 4.0;
    QTest::newRow("z (z+0.5)/(z-0.5)^2 Jury z=-1") << "z_double_pole_zero" << 4.5 << -1.0 << 0.0;
    // Jury for z^2 - z + 0.25 + K: a0 = 0.25 + K reaches 1 at K = 0.75; roots 0.5 +- j sqrt(K).
    QTest::newRow("z 1/(z-0.5)^2 Jury") << "z_double_pole" << 0.75 << 0.5 << std::sqrt(0.75);
    double k = 0.0, omega = 0.0;
    gtRouth("lower-base", k, omega);
    QTest::newRow("GT lower base Routh") << "gt_lower_base" << k << 0.0 << omega;
    gtRouth("upper-base", k, omega);
    QTest::newRow("GT upper base Routh") << "gt_upper_base" << k << 0.0 << omega;
    // Patrick, Ishak and Adnan's x axis: A(z) z + K B(z) = z^3 + a2 z^2 + a1 z + a0 with a2 =
    // -1.658 + 0.0421K, a1 = 0.6583 + 0.0628K, a0 = -0.0454K has a unit-circle pair (z^2 - 2cz +
    // 1)(z + a0) when the Jury/Schur-Cohn determinant 1 - a0^2 - a1 + a0 a2 = 0: a quadratic in K,
    // 0.3417 + (0.0454*1.658 - 0.0628) K - (0.0454^2 + 0.0454*0.0421) K^2 = 0, and then
    // Re z = c = (a0 - a2)/2.
    const double qa = -(0.0454 * 0.0454 + 0.0454 * 0.0421), qb = 0.0454 * 1.658 - 0.0628,
                 qc = 1.0 - 0.6583;
    const double kx = (-qb - std::sqrt(qb * qb - 4.0 * qa * qc)) / (2.0 * qa);
    const double c = (-0.0454 * kx - (-1.658 + 0.0421 * kx)) / 2.0;
    QTest::newRow("Patrick, Ishak and Adnan's x axis Jury")
        << "arx_x_axis" << kx << c << std::sqrt(1.0 - c * c);
}

void TstRootLocus::crossingsMatchClosedForms() {
    QFETCH(QString, loop);
    QFETCH(double, gain);
    QFETCH(double, re);
    QFETCH(double, im);
    const Loop l = loopNamed(loop);
    const RootLocus r = rootLocus(l.num, l.den, l.ts);
    // Each crossing comes from a polynomial root (simple here) polished to round-off: 1e-9
    // relative leaves room for the conditioning of the degree-2n boundary polynomial.
    bool found = false;
    for (const LocusFeature& f : r.crossings)
        if (std::abs(f.gain - gain) <= 1e-9 * gain && f.point.imag() >= 0.0) {
            found = true;
            XYT_COMPARE_NEAR(f.point.real(), re, 1e-9, 1e-9);
            XYT_COMPARE_NEAR(f.point.imag(), im, 1e-9, 1e-9);
        }
    QVERIFY2(found, qPrintable(QStringLiteral("no crossing at K = %1").arg(gain, 0, 'g', 12)));
}

void TstRootLocus::breakawaysMatchClosedForms_data() {
    QTest::addColumn<QString>("loop");
    QTest::addColumn<QList<double>>("points"); // real breakaway points, in gain order
    QTest::addColumn<QList<double>>("gains");
    // 1/(s(s+1)(s+2)): N D' - N' D = 3s^2 + 6s + 2 = 0 -> s = -1 +- 1/sqrt(3); only
    // -1 + 1/sqrt(3) has K = -s(s+1)(s+2) = 2/(3 sqrt(3)) > 0.
    QTest::newRow("type1") << "type1" << QList<double>{-1.0 + 1.0 / std::sqrt(3.0)}
                           << QList<double>{2.0 / (3.0 * std::sqrt(3.0))};
    // (s+1)/(s^2(s+10)): N D' - N' D = s(2s^2 + 13s + 20) -> -2.5 (K = 31.25), -4 (K = 32);
    // s = 0 is the double pole (K = 0, not listed).
    QTest::newRow("double integrator + lead")
        << "double_integrator_lead" << QList<double>{-2.5, -4.0} << QList<double>{31.25, 32.0};
    // (z+0.5)/(z-0.5)^2: N D' - N' D = (z - 0.5)(z + 1.5): break-in at -1.5 with K = 4.
    QTest::newRow("z double pole + zero")
        << "z_double_pole_zero" << QList<double>{-1.5} << QList<double>{4.0};
    // 1/(z-0.5)^2: N D' - N' D = 2(z - 0.5) only at the double pole: no breakaway for K > 0.
    QTest::newRow("z double pole") << "z_double_pole" << QList<double>{} << QList<double>{};
}

void TstRootLocus::breakawaysMatchClosedForms() {
    QFETCH(QString, loop);
    QFETCH(QList<double>, points);
    QFETCH(QList<double>, gains);
    const Loop l = loopNamed(loop);
    const RootLocus r = rootLocus(l.num, l.den, l.ts);
    QCOMPARE(r.breakaways.size(), static_cast<std::size_t>(points.size()));
    for (qsizetype i = 0; i < points.size(); ++i) {
        // Simple roots of N D' - N' D, polished: 1e-10 relative.
        XYT_COMPARE_NEAR(r.breakaways[i].point.real(), points[i], 1e-10, 1e-12);
        XYT_COMPARE_NEAR(r.breakaways[i].point.imag(), 0.0, 0.0, 1e-12);
        XYT_COMPARE_NEAR(r.breakaways[i].gain, gains[i], 1e-10, 0.0);
    }
}

void TstRootLocus::featureGainsMatchNumpyReference_data() {
    QTest::addColumn<QString>("loop");
    QTest::addColumn<QJsonObject>("reference");
    for (const QJsonValue& v : referenceLoops())
        QTest::newRow(qPrintable(v["name"].toString())) << v["name"].toString() << v.toObject();
}

void TstRootLocus::featureGainsMatchNumpyReference() {
    // tests/data/root_locus_reference.json (gen_root_locus.py): stability-boundary gains found
    // by brentq on the sign change of numpy's root margin, a method independent of the core's
    // boundary polynomial; breakaway gains from numpy.roots. brentq stops at xtol 1e-14 on a
    // margin with slope ~1: 1e-9 relative covers both computations' round-off.
    QFETCH(QString, loop);
    QFETCH(QJsonObject, reference);
    const Loop l = loopNamed(loop);
    const RootLocus r = rootLocus(l.num, l.den, l.ts);
    for (const QJsonValue& c : reference["crossings"].toArray()) {
        const double k = c["k"].toDouble();
        bool found = false;
        for (const LocusFeature& f : r.crossings)
            if (std::abs(f.gain - k) <= 1e-9 * k && f.point.imag() >= 0.0) {
                found = true;
                XYT_COMPARE_NEAR(f.point.real(), c["re"].toDouble(), 1e-8, 1e-8);
                XYT_COMPARE_NEAR(f.point.imag(), c["im"].toDouble(), 1e-8, 1e-8);
            }
        QVERIFY2(found,
                 qPrintable(QStringLiteral("numpy crossing K = %1 missing").arg(k, 0, 'g', 15)));
    }
    const QJsonArray breakaways = reference["breakaways"].toArray();
    QCOMPARE(r.breakaways.size(), static_cast<std::size_t>(breakaways.size()));
    for (qsizetype i = 0; i < breakaways.size(); ++i) {
        XYT_COMPARE_NEAR(r.breakaways[i].gain, breakaways[i]["k"].toDouble(), 1e-9, 0.0);
        XYT_COMPARE_NEAR(r.breakaways[i].point.real(), breakaways[i]["re"].toDouble(), 1e-9, 1e-12);
    }
}

void TstRootLocus::asymptotes_data() {
    QTest::addColumn<Polynomial>("num");
    QTest::addColumn<Polynomial>("den");
    QTest::addColumn<double>("centroid");
    QTest::addColumn<QList<double>>("angles");
    // (sum p - sum z)/(n - m) and (2q+1) 180/(n-m) for n_m/d_n > 0.
    QTest::newRow("type1: (0-1-2)/3")
        << Polynomial::fromDescending({1}) << Polynomial::fromDescending({1, 3, 2, 0}) << -1.0
        << QList<double>{60.0, 180.0, 300.0};
    QTest::newRow("dbl+lead: (-10 + 1)/2")
        << Polynomial::fromDescending({1, 1}) << Polynomial::fromDescending({1, 10, 0, 0}) << -4.5
        << QList<double>{90.0, 270.0};
    // n_m/d_n < 0 (positive feedback for K > 0): s^2 = +K on the far locus, angles 2q 180/2.
    QTest::newRow("negative gain -1/(s(s+1))")
        << Polynomial::fromDescending({-1}) << Polynomial::fromDescending({1, 1, 0}) << -0.5
        << QList<double>{0.0, 180.0};
    const GtPreset p = *findGtPreset("lower-base");
    const GtDesign d = designGuilleminTruxal(p.plant, p.omegaNRadPerSec, p.kp);
    // GT: poles 0, 0 and the roots of s^2 + a1 s + a2 (sum -a1), zero -ki/kp: (-a1 + ki/kp)/3.
    QTest::newRow("GT lower base")
        << d.openLoop.num() << d.openLoop.den() << (-p.plant.a1 + d.ki / d.kp) / 3.0
        << QList<double>{60.0, 180.0, 300.0};
}

void TstRootLocus::asymptotes() {
    QFETCH(Polynomial, num);
    QFETCH(Polynomial, den);
    QFETCH(double, centroid);
    QFETCH(QList<double>, angles);
    const LocusAsymptotes a = locusAsymptotes(num, den);
    QCOMPARE(a.count, den.degree() - num.degree());
    XYT_COMPARE_NEAR(a.centroid, centroid, 1e-14, 1e-14); // a few operations on coefficients
    QCOMPARE(a.anglesDeg.size(), static_cast<std::size_t>(angles.size()));
    for (qsizetype i = 0; i < angles.size(); ++i)
        XYT_COMPARE_NEAR(a.anglesDeg[i], angles[i], 1e-14, 0.0);
}

void TstRootLocus::everyPointIsAClosedLoopPole_data() {
    QTest::addColumn<QString>("loop");
    for (const QString& name : kLoopNames)
        QTest::newRow(qPrintable(name)) << name;
}

void TstRootLocus::everyPointIsAClosedLoopPole() {
    // Invariant: every locus point r at gain K is a root of D + K N. The relative backward
    // error |D + K N| / (sum |d_i||r|^i + K sum |n_i||r|^i) of a computed root is a small
    // multiple of the machine epsilon (2.2e-16) for a backward-stable solver; 1e-12 leaves
    // margin for the near-multiple roots at breakaway points.
    QFETCH(QString, loop);
    const Loop l = loopNamed(loop);
    const RootLocus r = rootLocus(l.num, l.den, l.ts);
    QCOMPARE(r.status, RootLocusStatus::Complete);
    QVERIFY(r.gains.size() > 10);
    QCOMPARE(r.branches.size(), static_cast<std::size_t>(l.den.degree()));
    for (const LocusBranch& b : r.branches) {
        QCOMPARE(b.roots.size(), r.gains.size());
        for (std::size_t i = 0; i < b.roots.size(); ++i) {
            const double residual = locusResidual(l.num, l.den, r.gains[i], b.roots[i]);
            QVERIFY2(
                residual <= 1e-12,
                qPrintable(QStringLiteral("K = %1: residual %2").arg(r.gains[i]).arg(residual)));
        }
    }
    for (std::size_t i = 1; i < r.gains.size(); ++i)
        QVERIFY(r.gains[i] > r.gains[i - 1]);
}

void TstRootLocus::branchesAreContinuous_data() {
    everyPointIsAClosedLoopPole_data();
}

void TstRootLocus::branchesAreContinuous() {
    // The step bound of RootLocusOptions: no root inside the view moves more than maxStep between
    // consecutive points (so no branch jumps to a neighbour, which is at least as far away as
    // the approach bound allows). Exact comparison: the tracer accepts a step only when every
    // displacement <= bound, with the same arithmetic.
    QFETCH(QString, loop);
    const Loop l = loopNamed(loop);
    const RootLocus r = rootLocus(l.num, l.den, l.ts);
    XYT_COMPARE_NEAR(r.maxStep, 0.01 * r.view.span(), 1e-15, 0.0); // default fraction 0.01
    QVERIFY(r.warnings.empty());
    for (const LocusBranch& b : r.branches)
        for (std::size_t i = 1; i < b.roots.size(); ++i) {
            if (!r.view.contains(b.roots[i]) && !r.view.contains(b.roots[i - 1]))
                continue;
            const double step = std::abs(b.roots[i] - b.roots[i - 1]);
            QVERIFY2(step <= r.maxStep * (1.0 + 1e-12),
                     qPrintable(QStringLiteral("jump %1 > bound %2 at K = %3")
                                    .arg(step)
                                    .arg(r.maxStep)
                                    .arg(r.gains[i])));
        }
    // Conjugate symmetry of a real polynomial's roots: the branch set at each gain is closed
    // under conjugation (1e-9 of the view: the roots of each step are computed together).
    for (std::size_t i = 0; i < r.gains.size(); i += 7)
        for (const LocusBranch& b : r.branches) {
            double nearest = 1e300;
            for (const LocusBranch& c : r.branches)
                nearest = std::min(nearest, std::abs(std::conj(b.roots[i]) - c.roots[i]));
            QVERIFY(nearest <= 1e-9 * std::max(1.0, std::abs(b.roots[i])));
        }
}

void TstRootLocus::pointsAreDenserNearBreakaway() {
    // 1/(s(s+1)(s+2)): the branches from 0 and -1 meet at -0.4226. Near there the spacing
    // follows a quarter of the branch separation, far below the bound; away from the real axis
    // the branches move by the full bound.
    const Loop l = loopNamed("type1");
    const RootLocus r = rootLocus(l.num, l.den, l.ts);
    const Complex breakaway(-1.0 + 1.0 / std::sqrt(3.0), 0.0);
    double nearSpacing = 1e300, farSpacing = 0.0;
    for (const LocusBranch& b : r.branches)
        for (std::size_t i = 1; i < b.roots.size(); ++i) {
            const double step = std::abs(b.roots[i] - b.roots[i - 1]);
            if (std::abs(b.roots[i] - breakaway) < 0.05)
                nearSpacing = std::min(nearSpacing, step);
            if (std::abs(b.roots[i].imag()) > 1.0 && r.view.contains(b.roots[i]))
                farSpacing = std::max(farSpacing, step);
        }
    QVERIFY2(nearSpacing < 0.1 * r.maxStep, qPrintable(QString::number(nearSpacing)));
    QVERIFY2(farSpacing > 0.5 * r.maxStep, qPrintable(QString::number(farSpacing)));
}

void TstRootLocus::branchesEndAtZerosOrLeaveTheView_data() {
    everyPointIsAClosedLoopPole_data();
}

void TstRootLocus::branchesEndAtZerosOrLeaveTheView() {
    // The automatic end: every branch within one step bound of its zero or outside the view;
    // deg N branches end at zeros, so deg N ends are set.
    QFETCH(QString, loop);
    const Loop l = loopNamed(loop);
    const RootLocus r = rootLocus(l.num, l.den, l.ts);
    int ends = 0;
    for (const LocusBranch& b : r.branches) {
        XYT_COMPARE_NEAR(std::abs(b.start - b.roots.front()), 0.0, 0.0, 0.0);
        if (b.end) {
            ++ends;
            QVERIFY(std::abs(b.roots.back() - *b.end) <= r.maxStep);
        } else {
            QVERIFY(!r.view.contains(b.roots.back()));
        }
    }
    QCOMPARE(ends, l.num.degree());
}

void TstRootLocus::designPointIsTheGtClosedLoop_data() {
    QTest::addColumn<QString>("preset");
    QTest::newRow("lower-base") << "lower-base";
    QTest::newRow("upper-base") << "upper-base";
}

void TstRootLocus::designPointIsTheGtClosedLoop() {
    // Invariant: K multiplies L = G_c G, so the locus at K = 1 is feedback(L).poles(), the
    // poles of the reference model G_R (Braga et al. Eq. 7). Same polynomial, two solvers:
    // 1e-9 relative to the largest pole magnitude (the slow pole near -wn^4/(kp k0) is ~1e-4
    // of the fastest).
    QFETCH(QString, preset);
    const GtPreset p = *findGtPreset(preset.toStdString());
    const GtDesign d = designGuilleminTruxal(p.plant, p.omegaNRadPerSec, p.kp);
    RootLocusOptions o;
    o.kMax = 1.0;
    const RootLocus r = rootLocus(d.openLoop, o);
    QCOMPARE(r.gains.back(), 1.0);
    for (const Complex& pole : d.closedLoopPoles) {
        double nearest = 1e300;
        for (const LocusBranch& b : r.branches)
            nearest = std::min(nearest, std::abs(b.roots.back() - pole));
        XYT_COMPARE_NEAR(nearest, 0.0, 0.0, 1e-9 * std::abs(d.closedLoopPoles.front()));
    }
}

void TstRootLocus::kMaxEndsTheTraceExactly() {
    const Loop l = loopNamed("arx_x_axis");
    RootLocusOptions o;
    o.kMax = 20.0;
    const RootLocus r = rootLocus(l.num, l.den, l.ts, o);
    QCOMPARE(r.status, RootLocusStatus::Complete);
    QCOMPARE(r.gains.back(), 20.0); // clamped to kMax exactly, not computed
}

void TstRootLocus::pointLimitBoundsTheRun() {
    // A locus that cannot finish within the point budget returns with a status and a warning.
    const Loop l = loopNamed("type1");
    RootLocusOptions o;
    o.maxPoints = 30;
    const RootLocus r = rootLocus(l.num, l.den, l.ts, o);
    QCOMPARE(r.status, RootLocusStatus::PointLimitReached);
    QCOMPARE(r.gains.size(), std::size_t(30));
    QVERIFY(!r.warnings.empty());
    // A tiny step fraction on a huge view: still bounded by maxPoints.
    o.maxPoints = 2000;
    o.maxStepFraction = 1e-6;
    const RootLocus fine = rootLocus(l.num, l.den, l.ts, o);
    QCOMPARE(fine.status, RootLocusStatus::PointLimitReached);
    QCOMPARE(fine.gains.size(), std::size_t(2000));
}

void TstRootLocus::matchingMinimisesTotalDisplacement() {
    // previous {0, 1}, next {0.4, -1}: matching previous[0] greedily to its nearest (0.4) costs
    // 0.4 + 2.0 = 2.4; the least total displacement is 0 -> -1, 1 -> 0.4: 1.0 + 0.6 = 1.6.
    const auto order = matchRoots({Complex(0.0), Complex(1.0)}, {Complex(0.4), Complex(-1.0)});
    QCOMPARE(order, (std::vector<std::size_t>{1, 0}));
    // Two branches passing close by: the crossing pair keeps its directions.
    const std::vector<Complex> prev = {Complex(-0.1, 0.01), Complex(0.1, -0.01), Complex(5, 0)};
    const std::vector<Complex> next = {Complex(5.01, 0), Complex(-0.09, 0.011),
                                       Complex(0.09, -0.011)};
    QCOMPARE(matchRoots(prev, next), (std::vector<std::size_t>{1, 2, 0}));
    QVERIFY_THROWS_EXCEPTION(InvalidInput, matchRoots(prev, {Complex(1.0)}));
}

void TstRootLocus::pickGivesGainAndDamping() {
    const Loop l = loopNamed("type1");
    const RootLocus r = rootLocus(l.num, l.den, l.ts);
    // Click at the jw crossing s = j sqrt(2) (K = 6): the nearest traced point is within half a
    // step bound, so its gain is within the gain change over one step there (dK/ds ~ |D'/N|
    // ~ 6 per unit at s = j sqrt 2, times maxStep ~ 0.04: 0.3).
    const auto pick = pickLocusPoint(r, Complex(0.0, std::sqrt(2.0)));
    QVERIFY(pick.has_value());
    QVERIFY(pick->distance <= 0.5 * r.maxStep);
    XYT_COMPARE_NEAR(pick->gain, 6.0, 0.0, 0.3);
    XYT_COMPARE_NEAR(pick->gain, r.gains[pick->index], 0.0, 0.0);
    // zeta = -Re s/|s|, omega_n = |s| of the picked point (definition).
    XYT_COMPARE_NEAR(pick->damping.omegaNRadPerSec, std::abs(pick->point), 1e-15, 0.0);
    XYT_COMPARE_NEAR(pick->damping.zeta, -pick->point.real() / std::abs(pick->point), 1e-12, 1e-15);
    // A real point left of the breakaway: zeta = 1.
    const auto real = pickLocusPoint(r, Complex(-1.5, 0.0));
    XYT_COMPARE_NEAR(real->damping.zeta, 1.0, 1e-12, 0.0);
}

void TstRootLocus::pickOnDiscreteLocusUsesLogMap() {
    // 1/(z-0.5)^2: the locus is z = 0.5 +- j sqrt(K) exactly.
    const Loop l = loopNamed("z_double_pole");
    const RootLocus r = rootLocus(l.num, l.den, l.ts);
    const auto pick = pickLocusPoint(r, Complex(0.5, 0.6));
    QVERIFY(pick.has_value());
    XYT_COMPARE_NEAR(pick->point.real(), 0.5, 0.0, 1e-12);
    XYT_COMPARE_NEAR(pick->gain, pick->point.imag() * pick->point.imag(), 1e-12, 0.0);
    // s = ln(z)/Ts (Ts = 0.1): omega_n = |s|, zeta = -Re s/|s|.
    const Complex s = std::log(pick->point) / 0.1;
    XYT_COMPARE_NEAR(pick->damping.omegaNRadPerSec, std::abs(s), 1e-14, 0.0);
    XYT_COMPARE_NEAR(pick->damping.zeta, -s.real() / std::abs(s), 1e-14, 0.0);
}

void TstRootLocus::invalidInputThrows_data() {
    QTest::addColumn<Polynomial>("num");
    QTest::addColumn<Polynomial>("den");
    QTest::addColumn<double>("ts");
    QTest::addColumn<double>("kMax");
    QTest::addColumn<double>("stepFraction");
    QTest::addColumn<QString>("field");
    const Polynomial one = Polynomial::constant(1.0), d2 = Polynomial::fromDescending({1, 1, 0});
    QTest::newRow("zero numerator") << Polynomial() << d2 << 0.0 << 0.0 << 0.01 << "num";
    QTest::newRow("improper") << Polynomial::fromDescending({1, 0, 0, 0}) << d2 << 0.0 << 0.0
                              << 0.01 << "num";
    QTest::newRow("constant denominator")
        << one << Polynomial::constant(2.0) << 0.0 << 0.0 << 0.01 << "den";
    QTest::newRow("negative ts") << one << d2 << -0.1 << 0.0 << 0.01 << "ts";
    QTest::newRow("negative kMax") << one << d2 << 0.0 << -1.0 << 0.01 << "kMax";
    QTest::newRow("zero step") << one << d2 << 0.0 << 0.0 << 0.0 << "maxStepFraction";
}

void TstRootLocus::invalidInputThrows() {
    QFETCH(Polynomial, num);
    QFETCH(Polynomial, den);
    QFETCH(double, ts);
    QFETCH(double, kMax);
    QFETCH(double, stepFraction);
    QFETCH(QString, field);
    RootLocusOptions o;
    o.kMax = kMax;
    o.maxStepFraction = stepFraction;
    try {
        rootLocus(num, den, ts, o);
        QFAIL("no exception");
    } catch (const InvalidInput& e) {
        QCOMPARE(QString::fromStdString(e.field()), field);
        QVERIFY2(e.reasonDiagnostic().coded(), e.what()); // the workbench translates it
    }
}

void TstRootLocus::refusalsAndWarningsAreCoded() {
    // The improper loop: its reason names both degrees as arguments of its template.
    try {
        rootLocus(Polynomial::fromDescending({1, 0, 0, 0}), Polynomial::fromDescending({1, 1, 0}),
                  0.0);
        QFAIL("no exception");
    } catch (const InvalidInput& e) {
        QCOMPARE(e.reasonDiagnostic().code, std::string("analysis_locus_improper"));
        QCOMPARE(e.reasonDiagnostic().args.size(), std::size_t(2));
        QCOMPARE(e.reasonDiagnostic().args[0].text, std::string("3"));
        QCOMPARE(e.reasonDiagnostic().args[1].text, std::string("2"));
        QCOMPARE(e.reason(),
                 std::string("degree 3 exceeds the denominator's 2: the loop is improper"));
    }
    // A pole cancelled by a zero: the warning's code, with the place as its argument.
    const RootLocus r =
        rootLocus(Polynomial::fromDescending({1, 1}), Polynomial::fromDescending({1, 3, 2}), 0.0);
    const auto it = std::find_if(r.warnings.begin(), r.warnings.end(), [](const Diagnostic& w) {
        return w.code == "analysis_locus_cancellation";
    });
    QVERIFY(it != r.warnings.end());
    QCOMPARE(it->args.size(), std::size_t(1));
    QCOMPARE(it->text, "near pole-zero cancellation at " + it->args[0].text +
                           ": that branch has (almost) no length");
}

void TstRootLocus::clusteredPolesWarnAndWorkIsBounded() {
    // 1/(s+1)^40 ran 15-72 s and reported the poles at -2.28 without a word.
    // Binomial coefficients (closed form) give D = (s+1)^40 exactly in double (all < 2^53).
    std::vector<double> d(41);
    double c = 1.0;
    for (int k = 0; k <= 40; ++k) {
        d[static_cast<std::size_t>(k)] = c;
        c = c * (40 - k) / (k + 1);
    }
    // The work bound, checked on counted work (not on time: CI machines are shared, and the
    // sanitizer build runs this loop 60 times slower). A bound of 2e7 operations is about 300
    // eigenvalue solves at n = 40 (10 n^3 = 6.4e5 each): far below what this locus needs.
    xyt::RootLocusOptions bounded;
    bounded.maxWork = 2e7;
    // Only the counted bound decides here: under the sanitizers on a loaded machine the 2 s
    // default time bound was reached first (a fresh-clone run stopped "at the time bound").
    bounded.maxSeconds = 1e6;
    const xyt::RootLocus r = xyt::rootLocus(xyt::Polynomial::fromAscending({1.0}),
                                            xyt::Polynomial::fromAscending(d), 0.0, bounded);
    const auto has = [&](const char* text) {
        return std::any_of(r.warnings.begin(), r.warnings.end(),
                           [&](const std::string& w) { return w.find(text) != std::string::npos; });
    };
    QVERIFY(has("ill-conditioned"));
    QVERIFY(has("work bound"));
    QCOMPARE(r.status, xyt::RootLocusStatus::PointLimitReached);
    // The run stops at the first check past the bound: one step's attempts (at most 81 root
    // solves of at most 20 n^2 + 10 n^3 = 6.72e5 operations) can overshoot it.
    QVERIFY2(r.work > bounded.maxWork && r.work <= bounded.maxWork + 81 * 6.72e5,
             qPrintable(QString::number(r.work)));
    // Whatever was traced is consistent: one root per branch per gain.
    for (const xyt::LocusBranch& b : r.branches)
        QCOMPARE(b.roots.size(), r.gains.size());
    // The time bound (the safety net for solves the count underestimates): any trace outlasts
    // a nanosecond, so it stops there with its own warning.
    xyt::RootLocusOptions quick;
    quick.maxSeconds = 1e-9;
    const xyt::RootLocus timed = xyt::rootLocus(xyt::Polynomial::fromAscending({1.0}),
                                                xyt::Polynomial::fromAscending(d), 0.0, quick);
    QCOMPARE(timed.status, xyt::RootLocusStatus::PointLimitReached);
    QVERIFY(std::any_of(timed.warnings.begin(), timed.warnings.end(), [](const std::string& w) {
        return w.find("time bound") != std::string::npos;
    }));
    for (const xyt::LocusBranch& b : timed.branches)
        QCOMPARE(b.roots.size(), timed.gains.size());
    quick.maxSeconds = 0.0;
    QVERIFY_THROWS_EXCEPTION(xyt::InvalidInput,
                             xyt::rootLocus(xyt::Polynomial::fromAscending({1.0}),
                                            xyt::Polynomial::fromAscending(d), 0.0, quick));
    xyt::RootLocusOptions none;
    none.maxWork = 0.0;
    QVERIFY_THROWS_EXCEPTION(xyt::InvalidInput,
                             xyt::rootLocus(xyt::Polynomial::fromAscending({1.0}),
                                            xyt::Polynomial::fromAscending(d), 0.0, none));
    // Invariant: the GT design's simple poles are well conditioned: no such warning there.
    const auto gt = xyt::designGuilleminTruxal({77.8, 125.3, 3665.0}, 2.0, 30.0);
    const xyt::RootLocus simple = xyt::rootLocus(gt.openLoop);
    for (const std::string& w : simple.warnings)
        QVERIFY2(w.find("ill-conditioned") == std::string::npos, w.c_str());
}

QTEST_APPLESS_MAIN(TstRootLocus)
#include "tst_root_locus.moc"
