// SPDX-License-Identifier: GPL-3.0-or-later
// The frequency-domain view of a session's axes, as the workbench draws it.
#include "core/session/axis_frequency.h"
#include "core/session/design_method_module.h"
#include "tests/support/tolerance.h"

#include <QTest>

#include <algorithm>
#include <cmath>

using namespace xyt;

class TstAxisFrequency : public QObject {
    Q_OBJECT
private slots:
    void gtAxisHoldsItsCrossoversOnTheGrid();
    void polePlacementAxisHasTheZpetcTracking();
    void axisWithoutDesignSaysWhy();
    void axisLoopIsWhatEachMethodCloses();
};

namespace {
bool onGrid(const std::vector<double>& grid, double omega) {
    return std::any_of(grid.begin(), grid.end(),
                       [omega](double w) { return std::abs(w - omega) <= 1e-12 * omega; });
}
} // namespace

void TstAxisFrequency::gtAxisHoldsItsCrossoversOnTheGrid() {
    const Session s; // Braga et al.'s defaults: lower base wn = 2, kp = 30
    const SessionEvaluation e = evaluateSession(s);
    const AxisFrequencyAnalysis a = analyzeAxisFrequency(s, e.axes[0]);
    QVERIFY2(a.ok, a.error.text.c_str());
    const std::vector<double>& w = a.responses.openLoop.omegaRadPerSec;
    // The margins are drawn at their frequencies: those must be grid points, not neighbours.
    QVERIFY(onGrid(w, a.margins.gainMarginOmegaRadPerSec));
    QVERIFY(onGrid(w, a.margins.phaseMarginOmegaRadPerSec));
    // One grid for every curve, and S + T = 1 at each point (identity, round-off 1e-12).
    QCOMPARE(a.responses.sensitivity.omegaRadPerSec, w);
    QCOMPARE(a.responses.complementarySensitivity.omegaRadPerSec, w);
    for (std::size_t i = 0; i < w.size(); ++i)
        QVERIFY(std::abs(a.responses.sensitivity.value[i] +
                         a.responses.complementarySensitivity.value[i] - 1.0) < 1e-9);
    // The GT loop has two integrators: the phase starts at -180 degrees.
    QCOMPARE(a.responses.openLoop.lowFrequencyIntegrators, 2);
    // Nyquist criterion: the design's closed loop (G_R) is stable, so Z = 0.
    QCOMPARE(a.nyquist.closedLoopUnstablePoles, 0);
    QVERIFY(a.margins.closedLoopStable);
    QVERIFY(std::isnan(a.referenceOmegaRadPerSec)); // a cubic move has no reference frequency
    QVERIFY(!a.tracking);
}

void TstAxisFrequency::polePlacementAxisHasTheZpetcTracking() {
    Session s;
    s.axes[0].method = DesignMethod::PolePlacementZpetc;
    s.trajectory.kind = TrajectoryKind::Circle;
    s.trajectory.radius = 30.0;
    s.trajectory.omegaRadPerSec = 0.1; // Patrick, Ishak and Adnan's circle
    s.trajectory.rampInSeconds = 0.0;
    const SessionEvaluation e = evaluateSession(s);
    const AxisFrequencyAnalysis a = analyzeAxisFrequency(s, e.axes[0]);
    QVERIFY2(a.ok, a.error.text.c_str());
    QCOMPARE(a.referenceOmegaRadPerSec, 0.1);
    QVERIFY(onGrid(a.responses.openLoop.omegaRadPerSec, 0.1));
    QVERIFY(a.tracking.has_value());
    // Zero phase with ZPETC at every grid frequency (Patrick, Ishak and Adnan Eq. 6), to round-off.
    for (double phase : a.tracking->withZpetc.phaseDeg)
        QVERIFY(std::abs(phase) < 1e-6);
    // The grid ends at the Nyquist frequency pi / 0.07.
    XYT_COMPARE_NEAR(a.responses.openLoop.omegaRadPerSec.back(), M_PI / 0.07, 1e-12, 0.0);
}

void TstAxisFrequency::axisWithoutDesignSaysWhy() {
    Session s;
    s.axes[1].gt.omegaNRadPerSec = -1.0; // no design
    const SessionEvaluation e = evaluateSession(s);
    QVERIFY(!e.axes[1].ok);
    const AxisFrequencyAnalysis a = analyzeAxisFrequency(s, e.axes[1]);
    QVERIFY(!a.ok);
    QVERIFY(!a.error.text.empty());
}

void TstAxisFrequency::axisLoopIsWhatEachMethodCloses() {
    // One dispatch gives every analysis its loop. Guillemin-Truxal: the design's G_c G (Braga et
    // al., unity feedback), the same polynomials. Pole placement: L = B G/(A F), the loop broken
    // at the plant input (Patrick, Ishak and Adnan Fig. 9), from the design's polynomials.
    Session s;
    s.axes[1].method = DesignMethod::PolePlacementZpetc;
    const SessionEvaluation e = evaluateSession(s);
    const std::optional<LoopTransferFunctions> gt = axisLoop(e.axes[0]);
    QVERIFY(gt && e.axes[0].gt);
    QCOMPARE(gt->openLoop.num(), e.axes[0].gt->openLoop.num());
    QCOMPARE(gt->openLoop.den(), e.axes[0].gt->openLoop.den());
    QCOMPARE(gt->openLoop.tsSeconds(), 0.0);
    const std::optional<LoopTransferFunctions> pp = axisLoop(e.axes[1]);
    QVERIFY(pp && e.axes[1].pp);
    const PolePlacementDesign& d = *e.axes[1].pp;
    QVERIFY(pp->openLoop == TransferFunction::fromZInverse(d.b * d.g, d.a * d.f, d.tsSeconds));
    QCOMPARE(pp->openLoop.tsSeconds(), 0.07);

    // The pole-zero sets: the pole-placement map lists the ZPETC filter only when it runs.
    const auto names = [](const std::vector<PoleZeroSet>& sets) {
        QStringList out;
        for (const PoleZeroSet& set : sets)
            out << QString::fromStdString(set.name);
        return out;
    };
    AxisSettings feedforwardOff = s.axes[1];
    feedforwardOff.pp.zpetcEnabled = false;
    QCOMPARE(names(axisPoleZeroSets(e.axes[1], feedforwardOff)),
             QStringList({"plant B/A", "feedback G/F", "closed loop Kf B/T"}));
    QCOMPARE(names(axisPoleZeroSets(e.axes[1], s.axes[1])),
             QStringList({"plant B/A", "feedback G/F", "closed loop Kf B/T", "ZPETC feedforward"}));
    QCOMPARE(names(axisPoleZeroSets(e.axes[0], s.axes[0])), names(gtPoleZeroSets(*e.axes[0].gt)));

    // No design, no loop.
    s.axes[0].gt.omegaNRadPerSec = -1.0;
    const AxisEvaluation invalid = evaluateAxis(s, 0);
    QVERIFY(!invalid.ok);
    QVERIFY(!axisLoop(invalid));
    QVERIFY(axisPoleZeroSets(invalid, s.axes[0]).empty());
}

QTEST_APPLESS_MAIN(TstAxisFrequency)
#include "tst_axis_frequency.moc"
