// SPDX-License-Identifier: GPL-3.0-or-later
// The ballbar test of a table with friction: a 25 mm circle at 150 mm/min on Braga et al.'s two
// bases under the drives' PID with the model's feedforward (the paper's PI gains, FF1..FF3 from
// the model), traced as runProgramContour traces a G-code program. The reversal spikes appear at
// the quadrant changes, grow with the Coulomb level, and the firmware's friction compensation at
// the true levels cuts them by at least half; with every element at zero the run is the linear
// one bit for bit.
//
// The paper's PI is soft (P = 0.03 V per mm of error), so a Coulomb level of tens of millivolts
// already costs tenths of a millimetre: the figures are printed by the test (qInfo) and quoted
// in tests/data/README.md. Under the Guillemin-Truxal PI alone (no feedforward) the loop lags
// the reference, so a compensation switched by the reference velocity flips before the table
// reverses and removes less (stated, not asserted).
#include "core/contour/gcode_reader.h"
#include "core/session/contour_run.h"
#include "core/session/session.h"
#include "core/session/session_evaluation.h"

#include <QTest>

#include <algorithm>
#include <cmath>

using namespace xyt;

namespace {

constexpr const char* kCircle = "G21 G90 G17\n"
                                "G0 X25 Y0\n"
                                "G2 X25 Y0 I-25 J0 F150\n";

ContourRun ballbar(double coulombVolts, double compensationPercent) {
    Session s = Session::paperDefault();
    for (AxisSettings& a : s.axes) {
        a.method = DesignMethod::PidFeedforward;
        a.friction.coulombVolts = coulombVolts;
        a.frictionCompensation.percent = compensationPercent;
    }
    ContourRunOptions o;
    o.profile.dtSeconds = 0.01; // the session's simulation step
    return runProgramContour(s, readGcode(kCircle), o);
}

/// The largest |reversal spike| of the clockwise run at 90, 180 and 270 degrees (mm): the run
/// starts from rest at 0 degrees, whose window holds the start's transient as well.
double largestSpike(const ContourRun& run) {
    double m = 0.0;
    for (const ReversalSpike& s : run.circular->iso.reversalSpikes)
        if (s.angleDeg > 45.0)
            m = std::max(m, std::abs(s.heightMm));
    return m;
}

} // namespace

class TstFrictionContour : public QObject {
    Q_OBJECT

private slots:
    void theSpikesGrowWithCoulombAndCompensationHalvesThem() {
        const ContourRun linear = ballbar(0.0, 0.0);
        const ContourRun low = ballbar(0.01, 0.0);
        const ContourRun high = ballbar(0.02, 0.0);
        const ContourRun compensated = ballbar(0.02, 100.0);
        for (const ContourRun* r : {&linear, &low, &high, &compensated}) {
            QVERIFY(r->circular.has_value());
            QCOMPARE(r->circular->iso.reversalSpikes.size(), std::size_t{4});
        }
        const double s0 = largestSpike(linear), s1 = largestSpike(low), s2 = largestSpike(high),
                     sc = largestSpike(compensated);
        const auto g = [](const ContourRun& r) { return r.circular->iso.circularDeviationG; };
        qInfo("largest reversal spike (um): linear %.4g, Fc 10 mV %.4g, Fc 20 mV %.4g, 20 mV "
              "compensated %.4g; G (um): %.4g %.4g %.4g %.4g",
              1e3 * s0, 1e3 * s1, 1e3 * s2, 1e3 * sc, 1e3 * g(linear), 1e3 * g(low), 1e3 * g(high),
              1e3 * g(compensated));
        QVERIFY(s1 > 1.5 * s0);    // friction makes the spikes, beyond the loops' lag
        QVERIFY(g(high) > g(low)); // and what it leaves grows with the Coulomb level
        QVERIFY(g(low) > g(linear));
        QVERIFY(sc - s0 <= 0.5 * (s2 - s0)); // the compensation removes at least half of it
        QVERIFY(g(compensated) - g(linear) <= 0.5 * (g(high) - g(linear)));
        const auto warned = [](const ContourRun& r) {
            return std::any_of(r.warnings.begin(), r.warnings.end(), [](const std::string& w) {
                return w.rfind("reversal spikes up to", 0) == 0;
            });
        };
        QVERIFY(warned(high));
        QVERIFY(!warned(linear));
    }

    void theEvaluationWarnsOfHuntingAndStickSlip() {
        // A stiff PID (crossover 20 rad/s, phase margin 60 deg: xytune-cli tune's gains for the
        // lower base) on a 50 mm move in 10 s: with a static level four times the Coulomb level
        // the integral action breaks the table free again and again at rest (the classic
        // hunting limit cycle); with a static level just above Coulomb it settles.
        const auto evaluate = [](double staticVolts) {
            Session s = Session::paperDefault();
            s.trajectory.xf = 50.0;
            s.trajectory.tfSeconds = 10.0;
            s.trajectory.durationSeconds = 30.0;
            AxisSettings& a = s.axes[0];
            a.method = DesignMethod::PidFeedforward;
            a.parameters = {{"p", 1.049}, {"i", 9.198}, {"d", 0.0299}};
            a.friction.coulombVolts = 0.05;
            a.friction.staticVolts = staticVolts;
            a.friction.stribeckVelocityMmPerS = 0.5;
            return evaluateAxis(s, 0);
        };
        const auto warns = [](const AxisEvaluation& e, const char* start) {
            return std::any_of(e.warnings.begin(), e.warnings.end(),
                               [&](const std::string& w) { return w.rfind(start, 0) == 0; });
        };
        const AxisEvaluation hunting = evaluate(0.2);
        QVERIFY2(hunting.ok, hunting.error.text.c_str());
        QVERIFY(warns(hunting, "hunting at rest"));
        QVERIFY(warns(hunting, "stick-slip during the move"));
        QVERIFY(warns(hunting, "the digital implementation: hunting at rest"));
        const AxisEvaluation settled = evaluate(0.06);
        QVERIFY(!warns(settled, "hunting at rest"));
        QVERIFY(!warns(settled, "stick-slip during the move"));
    }

    void aPolePlacementAxisTakesAnInputDeadZone() {
        // Patrick, Ishak and Adnan's x axis on the default cubic: a dead zone wider than any
        // command the loop can give (1e6 V: the error is at most the 600 mm travel) keeps the
        // table exactly at rest (the plant's input is 0 at every sample), in the design's run
        // and in the digital one; an ARX axis refuses what needs a moving mass, by name; and
        // without a table the run is the linear one.
        Session s = Session::paperDefault();
        s.axes[0].method = DesignMethod::PolePlacementZpetc;
        const AxisEvaluation linear = evaluateAxis(s, 0);
        QVERIFY2(linear.ok, linear.error.text.c_str());
        s.axes[0].friction.coulombVolts = 1e6;
        const AxisEvaluation stuck = evaluateAxis(s, 0);
        QVERIFY2(stuck.ok, stuck.error.text.c_str());
        for (double y : stuck.run.y)
            QCOMPARE(y, 0.0);
        QVERIFY(stuck.digital);
        for (double y : stuck.digital->run.result.y)
            QCOMPARE(y, 0.0);
        // A small dead zone changes the run but not its end: the RST integrator winds through it.
        s.axes[0].friction.coulombVolts = 0.05;
        s.axes[0].friction.amplifierDeadbandVolts = 0.0;
        const AxisEvaluation some = evaluateAxis(s, 0);
        QVERIFY(some.ok);
        QVERIFY(some.run.y != linear.run.y);
        s.axes[0].friction.backlashMm = 0.01;
        const AxisEvaluation refused = evaluateAxis(s, 0);
        QVERIFY(!refused.ok);
        QCOMPARE(QString::fromStdString(refused.errorField),
                 QStringLiteral("axes[0].friction.backlash"));
    }

    void aTableOfZerosIsTheLinearRunBitForBit() {
        Session s = Session::paperDefault();
        for (AxisSettings& a : s.axes)
            a.method = DesignMethod::PidFeedforward;
        ContourRunOptions o;
        o.profile.dtSeconds = 0.01;
        const ContourRun plain = runProgramContour(s, readGcode(kCircle), o);
        s.axes[0].friction.electricalPole = ElectricalPole::Slower; // not an element: inactive
        const ContourRun zero = runProgramContour(s, readGcode(kCircle), o);
        QCOMPARE(zero.trace.x, plain.trace.x);
        QCOMPARE(zero.trace.y, plain.trace.y);
    }
};

QTEST_APPLESS_MAIN(TstFrictionContour)
#include "tst_friction_contour.moc"
