// SPDX-License-Identifier: GPL-3.0-or-later
// The table with friction, backlash and amplifier deadband (core/simulation/table_dynamics.h):
// closed forms of a mass under a held command with Coulomb friction (sticking below the level,
// the sliding velocity and distance above it, stopping without chatter), the fourth order of the
// switching integration, backlash and deadband in closed form, viscous friction against the
// linear loop of the equivalent plant (an exact identity), and the inactive table bit for bit.
#include "core/design/digital_controller.h"
#include "core/design/guillemin_truxal.h"
#include "core/model/errors.h"
#include "core/simulation/sampled_data.h"
#include "core/simulation/simulation.h"
#include "core/simulation/stick_slip.h"
#include "core/simulation/table_dynamics.h"
#include "core/simulation/trajectory.h"
#include "tests/support/core_checks.h"
#include "tests/support/reference_data.h"
#include "tests/support/tolerance.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace xyt;

namespace {

/// Braga et al. Eq. 2, the lower base: k0 = 77.8, a1 = 125.3, a2 = 3665 (m, V).
ThirdOrderPlant lowerBase() {
    return findGtPreset("lower-base")->plant;
}

TableMechanics coulombOnly(double fc) {
    TableFriction f;
    f.coulombVolts = fc;
    return tableMechanics(lowerBase().transferFunction(), f, 0.001);
}

/// The closed form of the mass from rest under a held u > Fc (Fs = Fc, no viscous term):
/// z = u (1 - e^{-pe t}) reaches Fc at t_b = -ln(1 - Fc/u) / pe, then v' + pm v = g (z - Fc):
///   v = P (1 - e^{-pm tau}) + A (e^{-pe t} - e^{-pe t_b} e^{-pm tau}),  tau = t - t_b,
///   P = g (u - Fc) / pm,  A = -g u / (pm - pe),
/// and x its integral from t_b.
struct Breakaway {
    double tb, velocity, position;
};
Breakaway closedForm(const TableMechanics& m, double u, double t) {
    const double pe = m.electricalPole, pm = m.mechanicalPole, g = m.forceGain, fc = m.coulomb;
    const double tb = -std::log(1.0 - fc / u) / pe;
    if (t <= tb)
        return {tb, 0.0, 0.0};
    const double tau = t - tb;
    const double p = g * (u - fc) / pm, a = -g * u / (pm - pe);
    const double eb = std::exp(-pe * tb);
    const double v =
        p * (1.0 - std::exp(-pm * tau)) + a * (std::exp(-pe * t) - eb * std::exp(-pm * tau));
    const double x = p * (tau - (1.0 - std::exp(-pm * tau)) / pm) +
                     a * ((eb - std::exp(-pe * t)) / pe - eb * (1.0 - std::exp(-pm * tau)) / pm);
    return {tb, v, x};
}

std::vector<double> cubic(double x0, double xf, double tf, double duration, double dt) {
    const CubicTrajectory c(x0, xf, 0.0, tf);
    return sampled([&](double t) { return c.position(t); }, sampleTimes(duration, dt));
}

/// The paper's PI on the lower base on @p table following 5 sin(0.5 t) mm for 40 s at 10 ms
/// (@p substeps: LoopSimulationOptions::tableSubsteps).
SimulationResult sineRun(const TableFriction& table, int substeps = 0) {
    const auto p = findGtPreset("lower-base");
    const GtDesign d = designGuilleminTruxal(p->plant, p->omegaNRadPerSec, p->kp);
    const std::vector<double> r =
        sampled([](double t) { return 5.0 * std::sin(0.5 * t); }, sampleTimes(40.0, 0.01));
    LoopSimulationOptions o;
    o.umaxVolts = 2.5;
    o.modelUnitsPerPositionUnit = 0.001;
    o.table = &table;
    o.tableSubsteps = substeps;
    return simulateLoop(p->plant.transferFunction(), d.controller, r, o);
}

/// v' = g (z - bv v) - pm v is the mass with pole pm + g bv: the linear plant k0 / (s (s + pe)
/// (s + pm + g bv)) that a table with viscous friction alone (@p f) is exactly.
ThirdOrderPlant slowerMass(const ThirdOrderPlant& p, const TableFriction& f) {
    const TableMechanics m = tableMechanics(p.transferFunction(), f, 0.001);
    const double slower = m.mechanicalPole + m.forceGain * m.viscous;
    return {p.k0, m.electricalPole + slower, m.electricalPole * slower};
}

double maxDiff(const std::vector<double>& a, const std::vector<double>& b) {
    double m = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i)
        m = std::max(m, std::abs(a[i] - b[i]));
    return m;
}

GtDesign paperDesign() {
    const auto p = findGtPreset("lower-base");
    return designGuilleminTruxal(p->plant, p->omegaNRadPerSec, p->kp);
}

} // namespace

class TstTableDynamics : public QObject {
    Q_OBJECT

private slots:
    void splitsThePlantIntoLagAndMass() {
        // pe + pm = a1, pe pm = a2, g pe = k0 (the transfer function's identity).
        const TableMechanics m = coulombOnly(0.1);
        const ThirdOrderPlant p = lowerBase();
        QVERIFY(test::near(m.electricalPole + m.mechanicalPole, p.a1, 1e-14));
        QVERIFY(test::near(m.electricalPole * m.mechanicalPole, p.a2, 1e-14));
        QVERIFY(m.electricalPole > m.mechanicalPole); // the faster one by default
        QVERIFY(test::near(m.forceGain * m.electricalPole, p.k0, 1e-14));
        TableFriction slower;
        slower.coulombVolts = 0.1;
        slower.electricalPole = ElectricalPole::Slower;
        const TableMechanics s = tableMechanics(p.transferFunction(), slower, 0.001);
        QCOMPARE(s.electricalPole, m.mechanicalPole);
        // Complex poles cannot be split: refused naming the plant.
        const TransferFunction complexPoles =
            TransferFunction::fromDescending({1.0}, {1.0, 1.0, 100.0, 0.0});
        QVERIFY_THROWS_EXCEPTION(InvalidInput, tableMechanics(complexPoles, slower, 0.001));
        try {
            tableMechanics(complexPoles, slower, 0.001);
        } catch (const InvalidInput& e) {
            QCOMPARE(QString::fromStdString(e.field()), QStringLiteral("plant"));
        }
    }

    void aForceBelowTheStaticLevelDoesNotMove() {
        TablePlant plant(coulombOnly(0.2));
        for (int k = 0; k < 500; ++k)
            plant.hold(0.199, 0.01);
        QCOMPARE(plant.state().motor, 0.0); // exactly: the mass never left the stick mode
        QCOMPARE(plant.state().velocity, 0.0);
        QCOMPARE(plant.state().sliding, 0);
        QCOMPARE(plant.transitions(), std::uint64_t{0});
        // The drive force settles at the command: 0.199 V, below Fc = 0.2 V.
        QVERIFY(test::near(plant.state().drive, 0.199, 1e-12));
    }

    void aboveItTheSlidingFollowsTheClosedForm() {
        const TableMechanics m = coulombOnly(0.2);
        const double u = 0.5;
        TablePlant plant(m);
        // 60 sub-steps per 10 ms hold: h pe = 0.013, RK4's error below 1e-12 of the values.
        for (int k = 1; k <= 40; ++k) {
            plant.hold(u, 0.01, 60);
            const Breakaway c = closedForm(m, u, 0.01 * k);
            // Absolute tolerances 1e-9 of the scales g u / pm (0.011 m/s) and 0.4 mm travelled.
            QVERIFY2(test::near(plant.state().velocity, c.velocity, 1e-9, 1e-11),
                     qPrintable(test::describe(plant.state().velocity, c.velocity, 1e-9, 1e-11)));
            QVERIFY2(test::near(plant.state().motor, c.position, 1e-9, 4e-13),
                     qPrintable(test::describe(plant.state().motor, c.position, 1e-9, 4e-13)));
        }
        QCOMPARE(plant.transitions(), std::uint64_t{1});
        QVERIFY(plant.state().sliding == 1);
    }

    void theSwitchingIntegrationIsFourthOrder() {
        // The error at 0.2 s against the closed form, with the breakaway inside a sub-step:
        // halving h divides it by 2^4 = 16 (Runge-Kutta between located events). Accepted:
        // ratios in [12, 20] (the next order's term at these steps is below 25 %).
        const TableMechanics m = coulombOnly(0.2);
        const double u = 0.5;
        const Breakaway c = closedForm(m, u, 0.2);
        std::vector<double> errors;
        for (int substeps : {4, 8, 16, 32}) {
            TablePlant plant(m);
            for (int k = 0; k < 20; ++k)
                plant.hold(u, 0.01, substeps);
            errors.push_back(std::abs(plant.state().motor - c.position));
        }
        for (std::size_t i = 1; i < errors.size(); ++i) {
            const double ratio = errors[i - 1] / errors[i];
            QVERIFY2(ratio > 12.0 && ratio < 20.0, qPrintable(QString::number(ratio)));
        }
    }

    void stopsAndHoldsWithoutChattering() {
        // Pushed for 50 ms, then released: the mass coasts, z decays, it sticks once v = 0 and
        // holds exactly (one breakaway, one stick, nothing after).
        TablePlant plant(coulombOnly(0.2));
        for (int k = 0; k < 5; ++k)
            plant.hold(1.0, 0.01);
        QVERIFY(plant.state().velocity > 0.0);
        for (int k = 0; k < 30; ++k)
            plant.hold(0.0, 0.01);
        QCOMPARE(plant.state().sliding, 0);
        QCOMPARE(plant.state().velocity, 0.0);
        const double stopped = plant.state().motor;
        QVERIFY(stopped > 0.0);
        for (int k = 0; k < 300; ++k)
            plant.hold(0.0, 0.01);
        QCOMPARE(plant.state().motor, stopped);
        QCOMPARE(plant.transitions(), std::uint64_t{2});
    }

    void backlashIsAPlayOfItsWidth() {
        // The table stays until the motor has crossed half the gap (it starts centred), then
        // follows at motor - b/2; on the way back it holds while the motor crosses the full gap.
        TableFriction f;
        f.backlashMm = 0.05;
        const TableMechanics m = tableMechanics(lowerBase().transferFunction(), f, 0.001);
        TablePlant plant(m);
        const double half = 0.5 * 0.05 * 0.001;
        bool engaged = false;
        for (int k = 0; k < 100; ++k) {
            plant.hold(0.5, 0.002);
            const TableState& s = plant.state();
            if (s.motor <= half)
                QCOMPARE(s.table, 0.0);
            else {
                engaged = true;
                QVERIFY(test::near(s.table, s.motor - half, 1e-15, 1e-18));
            }
        }
        QVERIFY(engaged);
        // Driven back: the play holds (|motor - table| <= b/2), the table moves only while the
        // motor pushes it at the gap's edge, it holds while the motor crosses the gap, and ends
        // engaged on the other side (table = motor + b/2).
        int heldWhileMotorMoved = 0;
        double previousTable = plant.state().table, previousMotor = plant.state().motor;
        for (int k = 0; k < 400; ++k) {
            plant.hold(-0.5, 0.002);
            const TableState& s = plant.state();
            QVERIFY(std::abs(s.motor - s.table) <= half * (1.0 + 1e-12));
            if (s.table == previousTable && s.motor != previousMotor)
                ++heldWhileMotorMoved;
            previousTable = s.table;
            previousMotor = s.motor;
        }
        QVERIFY(heldWhileMotorMoved > 0);
        QVERIFY(test::near(plant.state().table, plant.state().motor + half, 1e-12, 1e-18));
    }

    void theDeadbandTakesItsWidthOffTheCommand() {
        // A held 0.8 V through a 0.3 V deadband is the linear plant under 0.5 V: z = 0.5 (1 -
        // e^{-pe t}) exactly at every step (the lag's closed form), and at 0.2 V nothing moves.
        TableFriction f;
        f.amplifierDeadbandVolts = 0.3;
        const TableMechanics m = tableMechanics(lowerBase().transferFunction(), f, 0.001);
        TablePlant plant(m);
        for (int k = 1; k <= 10; ++k) {
            plant.hold(0.8, 0.01, 60);
            const double z = 0.5 * (1.0 - std::exp(-m.electricalPole * 0.01 * k));
            // RK4's local error (h pe)^5 / 120 = 3e-12 at h pe = 0.013, over 60 steps a hold.
            QVERIFY2(test::near(plant.state().drive, z, 1e-9),
                     qPrintable(test::describe(plant.state().drive, z, 1e-9, 0.0)));
        }
        TablePlant idle(m);
        idle.hold(0.2, 1.0);
        QCOMPARE(idle.state().motor, 0.0);
        QCOMPARE(idle.state().drive, 0.0);
    }

    void viscousFrictionIsTheLinearLoopOfTheSlowerMass() {
        // v' = g (z - bv v) - pm v is the mass with pole pm + g bv: the loop with the table's
        // viscous friction equals simulateLoop's exact linear loop on k0 / (s (s + pe)(s + pm +
        // g bv)). Runge-Kutta at h lambda <= 1/4 is checked to 2e-6 of the move (600 mm).
        TableFriction f;
        f.viscousVoltsPerMmPerS = 0.02;
        const ThirdOrderPlant p = lowerBase();
        const ThirdOrderPlant equivalent = slowerMass(p, f);
        const GtDesign d = paperDesign();
        const std::vector<double> r = cubic(0.0, 600.0, 130.0, 150.0, 0.01);
        LoopSimulationOptions o;
        o.umaxVolts = 2.5;
        o.modelUnitsPerPositionUnit = 0.001;
        const SimulationResult linear =
            simulateLoop(equivalent.transferFunction(), d.controller, r, o);
        o.table = &f;
        const SimulationResult table = simulateLoop(p.transferFunction(), d.controller, r, o);
        QVERIFY(table.sliding.empty()); // no dry friction
        const double diff = maxDiff(linear.y, table.y);
        QVERIFY2(diff < 2e-6 * 600.0, qPrintable(QString::number(diff)));
        QVERIFY(maxDiff(linear.u, table.u) < 1e-5);
    }

    void anInactiveTableIsTheLinearRunBitForBit() {
        const GtDesign d = paperDesign();
        const std::vector<double> r = cubic(0.0, 600.0, 130.0, 140.0, 0.01);
        LoopSimulationOptions o;
        o.umaxVolts = 2.5;
        o.modelUnitsPerPositionUnit = 0.001;
        const SimulationResult plain =
            simulateLoop(lowerBase().transferFunction(), d.controller, r, o);
        const TableFriction zero;
        o.table = &zero;
        const SimulationResult same =
            simulateLoop(lowerBase().transferFunction(), d.controller, r, o);
        QCOMPARE(same.y, plain.y);
        QCOMPARE(same.u, plain.u);
    }

    void theLoopConvergesAtFourthOrderThroughStickAndSlip() {
        // The paper's PI on the lower base, a 50 mm move in 10 s with Coulomb 0.3 V and a Stribeck
        // dip (the mass sticks at the start, during the PI's wind-up and at the end): the error
        // at the samples against a run at 64 sub-steps falls by about 16 per halving of the
        // sub-step (accepted > 8: the saturation and the stick instants are corners).
        TableFriction f;
        f.coulombVolts = 0.3;
        f.staticVolts = 0.4;
        f.stribeckVelocityMmPerS = 0.5;
        const GtDesign d = paperDesign();
        const std::vector<double> r = cubic(0.0, 50.0, 10.0, 20.0, 0.01);
        LoopSimulationOptions o;
        o.umaxVolts = 2.5;
        o.modelUnitsPerPositionUnit = 0.001;
        o.table = &f;
        const auto run = [&](int substeps) {
            o.tableSubsteps = substeps;
            return simulateLoop(lowerBase().transferFunction(), d.controller, r, o);
        };
        const SimulationResult fine = run(64);
        int stuck = 0;
        for (std::int8_t s : fine.sliding)
            stuck += s == 0 ? 1 : 0;
        QVERIFY(stuck > 10);
        const double e4 = maxDiff(run(4).y, fine.y);
        const double e8 = maxDiff(run(8).y, fine.y);
        const double e16 = maxDiff(run(16).y, fine.y);
        QVERIFY2(e4 / e8 > 8.0 && e8 / e16 > 8.0,
                 qPrintable(QStringLiteral("%1 %2 %3").arg(e4).arg(e8).arg(e16)));
    }

    void theLoopMatchesAnIndependentEventDrivenIntegration() {
        // tests/data/table_friction_coulomb.csv (gen_table_friction.py): the paper's PI on the
        // lower base with Coulomb 0.05 V following 5 sin(0.5 t) mm, integrated by SciPy's DOP853
        // at rtol 1e-12 with its own event location: 13 stick/slip transitions in 40 s. The
        // runs agree to 2.5e-10 mm (measured); asserted to 1e-8 mm, 2e-9 of the 5 mm amplitude:
        // RK4 on this slow loop (its closed-loop poles near 2 rad/s, h = 2.5 ms) is far below
        // that, and a mislocated event (an error of a sub-step in its time) would move y by
        // v h ~ 1e-5 mm, a thousand times more.
        const test::CsvTable ref = test::readCsv("table_friction_coulomb.csv");
        QVERIFY(ref.rows.size() == 81);
        TableFriction f;
        f.coulombVolts = 0.05;
        const SimulationResult run = sineRun(f);
        double worst = 0.0;
        for (std::size_t i = 0; i < ref.rows.size(); ++i) {
            const double t = ref.number(i, "t");
            const auto k = static_cast<std::size_t>(std::llround(t / 0.01));
            worst = std::max(worst, std::abs(run.y[k] - ref.number(i, "y")));
        }
        qInfo("largest difference from the SciPy run: %.3g mm", worst);
        QVERIFY(worst < 1e-8);
        // The transitions seen at the samples: each one of the reference's (none closer than a
        // sample to the next).
        int changes = 0;
        for (std::size_t k = 1; k < run.sliding.size(); ++k)
            changes += run.sliding[k] != run.sliding[k - 1] ? 1 : 0;
        QCOMPARE(changes, 13);
    }

    void theExactStepsAgreeWithTheEngine() {
        // Coulomb friction and backlash (no Stribeck dip, no deadband): the loop takes exact
        // piecewise-affine steps between events and the Runge-Kutta engine at them. Forcing the
        // engine everywhere (64 sub-steps a sample: h lambda = 0.012) gives the same run to the
        // engine's error at the event samples, where the backlash's engagement corners are not
        // located (an O(h^2) local error at each, h = 2.5 ms there against 0.16 ms): measured
        // 1.7e-8 mm, asserted 1e-7 mm (2e-8 of the 5 mm amplitude).
        TableFriction f;
        f.coulombVolts = 0.05;
        f.backlashMm = 0.02;
        const SimulationResult exact = sineRun(f);
        const SimulationResult engine = sineRun(f, 64);
        const double diff = maxDiff(exact.y, engine.y);
        qInfo("exact steps against the engine: %.3g mm", diff);
        QVERIFY(diff < 1e-7);
        QCOMPARE(exact.sliding, engine.sliding);
    }

    void theSampledLoopHoldsTheCommandOnTheTable() {
        // The digital PI at 10 ms with viscous friction only equals the exact linear sampled loop
        // on the equivalent plant (as above) to the integration's error.
        TableFriction f;
        f.viscousVoltsPerMmPerS = 0.02;
        const ThirdOrderPlant p = lowerBase();
        const ThirdOrderPlant equivalent = slowerMass(p, f);
        const GtDesign d = paperDesign();
        const DigitalPi pi =
            digitalPi(d.kp, d.ki, 0.01, PiDiscretization::Tustin, AntiWindup::Clamp);
        const std::vector<double> r = cubic(0.0, 600.0, 130.0, 150.0, 0.01);
        SampledDataOptions o;
        o.umaxVolts = 2.5;
        const SampledDataRun linear =
            simulateSampledPi(equivalent.transferFunction(), pi, r, o, 0.001);
        o.table = &f;
        const SampledDataRun table = simulateSampledPi(p.transferFunction(), pi, r, o, 0.001);
        const double diff = maxDiff(linear.result.y, table.result.y);
        QVERIFY2(diff < 2e-6 * 600.0, qPrintable(QString::number(diff)));
    }

    void stickSlipWarningsAreCoded() {
        // The findings reach the user as coded warnings (the workbench translates each, the
        // count of stops a coded argument of its own), the English unchanged.
        StickSlipFindings f;
        f.stopsDuringMove = 2;
        f.firstStopSeconds = 0.125;
        const std::vector<Diagnostic> plain = stickSlipWarnings(f);
        QCOMPARE(plain.size(), std::size_t(1));
        QCOMPARE(plain[0].code, std::string("sim_stick_slip_during_move"));
        QCOMPARE(plain[0].args.at(0).code, std::string("sim_times"));
        QCOMPARE(plain[0].text, std::string("stick-slip during the move: the table stopped 2 "
                                            "times while the reference kept moving (first at "
                                            "t = 0.125 s)"));
        const std::vector<Diagnostic> digital =
            stickSlipWarnings(f, StickSlipRun::digitalImplementation);
        QCOMPARE(digital.at(0).code, std::string("sim_digital_implementation_finding"));
        QCOMPARE(digital.at(0).args.at(0), plain[0]);
        QCOMPARE(digital.at(0).text, "the digital implementation: " + plain[0].text);
    }
};

QTEST_APPLESS_MAIN(TstTableDynamics)
#include "tst_table_dynamics.moc"
