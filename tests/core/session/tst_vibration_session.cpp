// SPDX-License-Identifier: GPL-3.0-or-later
// A flexible mode, a notch and an input shaper in a session, against closed forms and an
// independent construction: the Guillemin-Truxal loop with them is C N G R, each factor's
// closed form at j w; the digital loop's poles with the notch (the state matrix of
// sampledPiLoopPoles) are the roots of 1 + C(z) N(z) G(z) built from transfer functions (the
// PI's difference equation, the biquad, the plant's exact zero-order-hold discretization); the
// shaped reference of a move is Singer and Seering's two-impulse ZV sum of the move; and the
// refusals name the session's fields.
#include "core/analysis/stability_margins.h"
#include "core/model/errors.h"
#include "core/model/math_constants.h"
#include "core/model/root_matching.h"
#include "core/model/state_space.h"
#include "core/session/axis_frequency.h"
#include "core/session/axis_vibration.h"
#include "core/session/contour_run.h"
#include "core/session/export_text.h"
#include "core/session/pid_feedforward_method.h"
#include "core/session/session_evaluation.h"
#include "core/simulation/mode_excitation.h"
#include "core/simulation/sampled_data.h"
#include "core/simulation/trajectory.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <complex>
#include <random>

using namespace xyt;
using Complex = std::complex<double>;

namespace {

/// The paper's default session with a 20 Hz mode (zeta 0.05) on x and, when asked, its notch.
Session sessionWithMode(bool notch) {
    Session s = Session::paperDefault();
    s.axes[0].gt.flexibleMode = {20.0, 0.05, 0.0, 0.02};
    if (notch)
        s.axes[0].gt.notch = notchForMode(s.axes[0].gt.flexibleMode);
    return s;
}

} // namespace

class TstVibrationSession : public QObject {
    Q_OBJECT

private slots:
    /// L(j w) of the evaluated axis equals (kp + ki / (j w)) N(j w) k0 / (j w ((j w)^2 + a1 j w
    /// + a2)) wr^2 / (wr^2 - w^2 + 2 j zr wr w), each factor from its closed form. Round-off of
    /// polynomial products of degree 8 evaluated at |s| up to 300: 1e-9 relative.
    void theLoopIsThePiTheNotchThePlantAndTheMode() {
        const Session s = sessionWithMode(true);
        const GtDesign d = sessionGtDesign(s.axes[0].gt, 0);
        const ThirdOrderPlant& p = s.axes[0].gt.plant;
        const NotchFilter& n = s.axes[0].gt.notch;
        const double wr = kTwoPi * 20.0, w0 = kTwoPi * n.centreHz;
        for (const double w : {0.3, 2.0, 40.0, wr * 0.97, wr, 300.0}) {
            const Complex jw(0.0, w);
            const Complex c = d.kp + d.ki / jw;
            const Complex notch = (jw * jw + 2.0 * n.zeroDamping() * w0 * jw + w0 * w0) /
                                  (jw * jw + 2.0 * n.poleDamping() * w0 * jw + w0 * w0);
            const Complex g = p.k0 / (jw * (jw * jw + p.a1 * jw + p.a2));
            const Complex r = wr * wr / (wr * wr - w * w + Complex(0.0, 2.0 * 0.05 * wr * w));
            const Complex expected = c * notch * g * r;
            const Complex got = d.openLoop.frequencyResponse(w);
            QVERIFY2(std::abs(got - expected) <= 1e-9 * std::abs(expected),
                     qPrintable(QString::number(w)));
        }
        // The design itself is the paper's: the reference model and gains are unchanged.
        const GtDesign rigid =
            designGuilleminTruxal(p, s.axes[0].gt.omegaNRadPerSec, s.axes[0].gt.kp);
        QCOMPARE(d.ki, rigid.ki);
        QVERIFY(d.referenceModel == rigid.referenceModel);
        // The evaluation's margins are the loop's (stability_margins of this L).
        const AxisEvaluation e = evaluateAxis(s, 0);
        QVERIFY2(e.ok, e.error.text.c_str());
        QVERIFY(e.margins.has_value());
        QCOMPARE(e.margins->phaseMarginDeg, stabilityMargins(d.openLoop).phaseMarginDeg);
        // The frequency analysis draws the same loop: order 4 (PI G) + 2 (mode) + 2 (notch).
        const AxisFrequencyAnalysis f = analyzeAxisFrequency(s, e);
        QVERIFY(f.ok);
        QCOMPARE(f.loop.openLoop.den().degree(), 8);
    }

    /// The digital loop's poles with the notch: the eigenvalues of sampledPiLoopPoles' state
    /// matrix are roots of the characteristic polynomial of 1 + C N G, built independently from
    /// transfer functions: C(z) = kp + (c0 + c1 z^-1) / (1 - z^-1) (stepDigitalPi), N the
    /// biquad, G the plant's zero-order-hold discretization (c2dZoh, not sampledPlant). The
    /// matrix has one state more (e_f[k-1] beside I: the PI's non-minimal realization), whose
    /// mode is at z = 0 to the eigensolver's accuracy eps ||M|| (the plant's states in model
    /// units make ||M|| ~ 1e10: 1e-5). Each other eigenvalue's backward error |P(z)| / sum
    /// |p_k| |z|^k is bounded by 1e-9 (round-off of a degree-8 evaluation gives ~1e-13; a
    /// missing or misplaced notch leaves residuals of order 1).
    void theDigitalPolesWithTheNotchMatchTheTransferFunctions() {
        Session s = sessionWithMode(true);
        s.controllerTsSeconds = 0.002;
        const GtDesign d = sessionGtDesign(s.axes[0].gt, 0);
        const DigitalPi pi = sessionDigitalPi(s, d, 0);
        QVERIFY(pi.hasNotch);
        const TransferFunction plant = axisPlantTransferFunction(s.axes[0].gt, 0);
        const double ts = pi.tsSeconds;
        std::vector<Complex> fromMatrix = sampledPiLoopPoles(sampledPlant(plant, ts), pi, 0);
        const TransferFunction c =
            parallel(TransferFunction::gain(pi.kp, ts),
                     TransferFunction::fromZInverse(Polynomial::fromAscending({pi.c0, pi.c1}),
                                                    Polynomial::fromAscending({1.0, -1.0}), ts));
        const TransferFunction loop =
            series(series(c, pi.errorNotch.transferFunction(ts)), c2dZoh(plant, ts));
        std::vector<Complex> fromTf = feedback(loop, TransferFunction::gain(1.0, ts)).poles();
        sortRoots(fromMatrix);
        sortRoots(fromTf);
        // The state matrix also holds e_f[k-1], whose pole at z = 0 the transfer function
        // cancels: drop one root at the origin.
        QCOMPARE(fromMatrix.size(), fromTf.size() + 1);
        const auto origin =
            std::min_element(fromMatrix.begin(), fromMatrix.end(),
                             [](Complex a, Complex b) { return std::abs(a) < std::abs(b); });
        QVERIFY(std::abs(*origin) < 1e-5);
        fromMatrix.erase(origin);
        // Each eigenvalue is a root of the closed loop's characteristic polynomial P: its
        // backward error |P(z)| / sum |p_k| |z|^k (the conditioning-free measure; the roots
        // cluster near z = 1, where a root's forward error is far larger).
        const Polynomial p = feedback(loop, TransferFunction::gain(1.0, ts)).den();
        for (const Complex& z : fromMatrix) {
            Complex value = 0.0;
            double scale = 0.0;
            for (int k = p.degree(); k >= 0; --k) {
                value = value * z + p.coefficient(k);
                scale = scale * std::abs(z) + std::abs(p.coefficient(k));
            }
            qInfo("z %.9g%+.9gj backward error %.3g", z.real(), z.imag(), std::abs(value) / scale);
            QVERIFY2(std::abs(value) <= 1e-9 * scale,
                     qPrintable(QString("%1%2j").arg(z.real()).arg(z.imag())));
        }
    }

    /// Singer and Seering's ZV for f, zeta: impulses 1/(1+K) at 0 and K/(1+K) at td/2, td = 1 /
    /// (f sqrt(1 - zeta^2)), K = exp(-zeta pi / sqrt(1 - zeta^2)); the session's reference is
    /// their sum over the cubic move (CubicTrajectory), and the run lasts td/2 longer.
    void theShapedMoveIsTheZvSumOfTheMove() {
        Session s = Session::paperDefault();
        s.trajectory.tfSeconds = 10.0;
        s.trajectory.shaping = {ShaperType::Zv, 0.5, 0.1};
        const double zeta = 0.1, f = 0.5;
        const double td = 1.0 / (f * std::sqrt(1.0 - zeta * zeta));
        const double k = std::exp(-zeta * kPi / std::sqrt(1.0 - zeta * zeta));
        const CubicTrajectory cubic(s.trajectory.x0, s.trajectory.xf, 0.0, 10.0, 0.0, 0.0);
        const auto r = axisReference(s.trajectory, 0);
        for (const double t : {-1.0, 0.3, 1.0, 5.0, 9.9, 10.5, 10.99, 11.2, 20.0}) {
            const double expected =
                (cubic.position(t) + k * cubic.position(t - td / 2.0)) / (1.0 + k);
            QVERIFY2(std::abs(r(t) - expected) <= 1e-12 * 600.0, qPrintable(QString::number(t)));
        }
        QVERIFY(std::abs(shapedMoveEndSeconds(s.trajectory) - (10.0 + td / 2.0)) < 1e-12);
        // The derivatives a feedforward reads are shaped alike.
        const MotionSample m = axisMotion(s.trajectory, 0)(5.0);
        const double v =
            (cubic.motion(5.0).velocity + k * cubic.motion(5.0 - td / 2.0).velocity) / (1.0 + k);
        QVERIFY(std::abs(m.velocity - v) <= 1e-12 * std::abs(v));
        // The evaluation compares the run with the unshaped one.
        const AxisEvaluation e = evaluateAxis(s, 0);
        QVERIFY2(e.ok, e.error.text.c_str());
        QVERIFY(e.shaping);
        QCOMPARE(e.shaping->unshapedRun.t.size(), e.run.t.size());
        QVERIFY(!e.shaping->fromAxisMode); // the rigid table: the shaper's own mode
        QVERIFY(e.shaping->afterMove);
    }

    /// The residual vibration after a move, against a direct simulation: the mode driven by
    /// the shaped move's commanded acceleration (axisMotion), sampled every 10 us and stepped
    /// exactly between samples (modeAmplitudes), its amplitude at the shaped move's end. The
    /// evaluation gets it by superposition (the unshaped amplitude times residualVibration),
    /// from the unshaped move alone. The direct route spreads each jump of the acceleration
    /// (the cubic's ends, delayed by each impulse) over one sample: a first-order error
    /// w dt / 2 of that impulse's share (6.3e-4 at 20 Hz); hence 1e-3 of the unshaped amplitude.
    /// A ZVD designed at 22 Hz (the mode off its design point) leaves a known fraction; the ZV
    /// at the mode, nothing.
    void theResidualMatchesADirectSimulation() {
        Session s = sessionWithMode(false);
        s.trajectory.xf = 50.0;
        s.trajectory.tfSeconds = 0.2;
        s.trajectory.durationSeconds = 0.3;
        for (const auto& [type, f] : {std::pair{ShaperType::Zvd, 22.0}, {ShaperType::Zv, 20.0}}) {
            s.trajectory.shaping = {type, f, 0.05};
            const AxisEvaluation e = evaluateAxis(s, 0);
            QVERIFY2(e.ok, e.error.text.c_str());
            QVERIFY(e.shaping && e.shaping->fromAxisMode);
            const double h = 1e-5;
            const auto motion = axisMotion(s.trajectory, 0);
            std::vector<double> a;
            for (double t = 0.0; t <= 0.3; t += h)
                a.push_back(motion(t).acceleration);
            const std::vector<double> amplitude = modeAmplitudes(a, h, 20.0, 0.05);
            const auto end =
                static_cast<std::size_t>(std::ceil(shapedMoveEndSeconds(s.trajectory) / h - 1e-9));
            qInfo("%s: residual %.6g mm shaped (direct %.6g), %.6g mm unshaped", shaperName(type),
                  e.shaping->residualShapedMm, amplitude[end], e.shaping->residualUnshapedMm);
            QVERIFY(e.shaping->residualUnshapedMm > 0.0);
            QVERIFY(std::abs(e.shaping->residualShapedMm - amplitude[end]) <=
                    1e-3 * e.shaping->residualUnshapedMm);
        }
    }

    /// The Vibration view's data: the resonant pair's peak 1 / (2 zeta sqrt(1 - zeta^2)) above
    /// the rigid plant (at wr sqrt(1 - 2 zeta^2)), to the grid's resolution (600 points over 3.5
    /// decades, 1.35 % apart: at most 0.1 dB below the peak for zeta 0.05); and the ZV shaper
    /// at the mode leaves nothing there (residualVibration, round-off).
    void theVibrationDataHoldTheModesPeak() {
        Session s = sessionWithMode(false);
        s.trajectory.shaping = {ShaperType::Zv, 20.0, 0.05};
        const AxisVibration v = analyzeAxisVibration(s, 0);
        QVERIFY2(v.ok, v.error.text.c_str());
        double peak = -1e300;
        for (std::size_t i = 0; i < v.frequencyHz.size(); ++i)
            peak = std::max(peak, v.plantDb[i] - v.rigidDb[i]);
        const double expected = 20.0 * std::log10(1.0 / (2.0 * 0.05 * std::sqrt(1.0 - 0.0025)));
        QVERIFY2(peak <= expected + 1e-9 && peak > expected - 0.1,
                 qPrintable(QString::number(peak)));
        QVERIFY(v.notchDb.empty());
        QVERIFY(v.residualAtModePercent < 1e-10);
        QVERIFY(!v.sensitivity.frequencyHz.empty());
        // A pole-placement axis is not analysed, and says why.
        s.axes[1].method = DesignMethod::PolePlacementZpetc;
        const AxisVibration pp = analyzeAxisVibration(s, 1);
        QVERIFY(!pp.ok);
        QVERIFY(pp.error.text.find("ARX") != std::string::npos);
    }

    /// The rigid table is the rigid table: no mode and no notch give the same loop and run, bit
    /// for bit, as a session that never had the fields.
    void noModeIsTheRigidTableBitForBit() {
        Session s = Session::paperDefault();
        s.axes[0].gt.flexibleMode.dampingRatio = 0.3; // no frequency: no mode
        const AxisEvaluation a = evaluateAxis(Session::paperDefault(), 0);
        const AxisEvaluation b = evaluateAxis(s, 0);
        QVERIFY(a.run.y == b.run.y);
        QVERIFY(a.gt->openLoop == b.gt->openLoop);
    }

    /// The Octave script closes the loop the workbench runs: the plant times the mode (its
    /// denominator s^2 + 2 zr wr s + wr^2, wr = 2 pi 20), the PI times the notch, and the
    /// digital PI times the prewarped biquad; the rigid session's script has none of them.
    void theOctaveScriptHasTheModeAndTheNotch() {
        const Session s = sessionWithMode(true);
        const std::string script = exportOctaveScript(s, evaluateSession(s), ExportOptions{});
        const double wr = kTwoPi * 20.0;
        const std::size_t at = script.find("mode_x = tf([");
        QVERIFY(at != std::string::npos);
        const double numerator = std::stod(script.substr(at + 13, 30));
        QVERIFY(std::abs(numerator - wr * wr) <= 1e-15 * wr * wr); // printed to 17 digits
        QVERIFY(script.find("plant_x = plant_x * mode_x;") != std::string::npos);
        QVERIFY(script.find("controller_x = controller_x * notch_x;") != std::string::npos);
        QVERIFY(script.find("digital_controller_x = digital_controller_x * filt([") !=
                std::string::npos);
        QVERIFY(script.find("mode_y") == std::string::npos); // y has no mode
        const Session rigid = Session::paperDefault();
        const std::string plain =
            exportOctaveScript(rigid, evaluateSession(rigid), ExportOptions{});
        QVERIFY(plain.find("mode_") == std::string::npos &&
                plain.find("notch_") == std::string::npos);
    }

    /// The mode picked from a measured response over the rigid model: white noise (seeded)
    /// through the plant with a 20 Hz, zeta 0.05 mode, sampled exactly (sampledPlant) at 1 ms,
    /// 0.001 mm of output noise; Welch's H1 over |G_rigid| peaks at the resonant pair's damped
    /// peak fr sqrt(1 - 2 zeta^2) = 19.95 Hz, to one bin (1 / (4096 ms) = 0.24 Hz); the half-power
    /// damping is zeta (1 + 2 zeta^2) to O(zeta^4), widened by the Hann window's kernel (its
    /// main lobe 4 bins, a 1 Hz spread against the 2 Hz half-power band) and the estimate's
    /// scatter: within 25 %.
    void theMeasuredModeIsPickedOverTheRigidModel() {
        Session s = sessionWithMode(false);
        const GtAxisSettings& gt = s.axes[0].gt;
        const double ts = 0.001;
        const SampledPlant p = sampledPlant(axisPlantTransferFunction(gt, 0), ts);
        std::mt19937_64 random(20261126);
        std::normal_distribution<double> normal;
        const std::size_t n = 200000;
        std::vector<double> u(n), y(n), x(static_cast<std::size_t>(p.states), 0.0), next(x.size());
        for (std::size_t k = 0; k < n; ++k) {
            u[k] = normal(random);
            double out = 0.0;
            for (std::size_t j = 0; j < x.size(); ++j)
                out += p.c[j] * x[j];
            y[k] = out / gt.modelUnitsPerPositionUnit + 0.001 * normal(random);
            for (std::size_t i = 0; i < x.size(); ++i) {
                double v = p.gamma[i] * u[k];
                for (std::size_t j = 0; j < x.size(); ++j)
                    v += p.phi[i * x.size() + j] * x[j];
                next[i] = v;
            }
            x.swap(next);
        }
        const FrequencyResponseEstimate h = estimateFrequencyResponse(u, y, ts);
        const std::optional<ResonancePick> pick = measuredModePick(h, gt);
        QVERIFY(pick && pick->dampingRatio);
        qInfo("picked %.4f Hz, zeta %.4f", pick->frequencyHz, *pick->dampingRatio);
        QVERIFY(std::abs(pick->frequencyHz - 20.0 * std::sqrt(1.0 - 2.0 * 0.0025)) < 0.25);
        QVERIFY(std::abs(*pick->dampingRatio - 0.05 * (1.0 + 2.0 * 0.0025)) < 0.25 * 0.05);
    }

    /// A G-code program with a shaper: the contour run traces the shaped profile (shapePath of
    /// the planned one) and each axis' own run follows the shaped reference function; both
    /// routes interpolate the profile linearly, so the traced x is each axis' y sample for
    /// sample (1e-9 mm: round-off of two summation orders over a 10 mm square).
    void aProgramRunsOnItsShapedProfile() {
        Session s = Session::paperDefault();
        s.trajectory.kind = TrajectoryKind::Gcode;
        s.trajectory.gcode.program = "G21 G90\nG1 X10 F600\nG1 Y10\nG1 X0\nG1 Y0\n";
        s.trajectory.dtSeconds = 0.001;
        s.trajectory.shaping = {ShaperType::Zvd, 15.0, 0.05};
        const SessionEvaluation e = evaluateSession(s);
        QVERIFY(e.axes[0].ok && e.program);
        const ContourTrace& trace = e.program->trace;
        const InputShaper zvd = designInputShaper(ShaperType::Zvd, 15.0, 0.05);
        // Longer by the shaper's duration, ending where the program ends.
        QVERIFY(trace.profile.t.back() >= s.trajectory.effectiveDurationSeconds() - 0.0015);
        QVERIFY(std::abs(trace.profile.x.back()) < 1e-12 &&
                std::abs(trace.profile.y.back()) < 1e-12);
        const SimulationResult& x = e.axes[0].run;
        const std::size_t n = std::min(x.y.size(), trace.x.size());
        QVERIFY(n > 1000);
        double worst = 0.0;
        for (std::size_t k = 0; k < n; ++k)
            worst = std::max(worst, std::abs(x.y[k] - trace.x[k]));
        QVERIFY2(worst < 1e-9, qPrintable(QString::number(worst)));
        QVERIFY(zvd.duration() > 0.0);
    }

    /// The loop with a measured plant: given the model plant's own response as the
    /// "measurement" (|G| / unit in mm/V, its phase unwrapped, coherence 1), C H is the model's
    /// L at every bin, magnitude and phase on the model's branch (round-off: 1e-9 dB, 1e-9
    /// degrees).
    void theMeasuredLoopIsCTimesH() {
        const Session s = sessionWithMode(true);
        const AxisEvaluation e = evaluateAxis(s, 0);
        const AxisFrequencyAnalysis f = analyzeAxisFrequency(s, e);
        QVERIFY(f.ok);
        const TransferFunction plant = axisPlantTransferFunction(s.axes[0].gt, 0);
        const double unit = s.axes[0].gt.modelUnitsPerPositionUnit;
        FrequencyResponseEstimate h;
        double previous = 0.0;
        for (int k = 1; k <= 400; ++k) {
            const double hz = 0.25 * k;
            const std::complex<double> g = plant.frequencyResponse(kTwoPi * hz);
            double phase = std::arg(g);
            if (k > 1) // unwrap against the previous bin
                phase += 2.0 * kPi * std::round((previous - phase) / (2.0 * kPi));
            previous = phase;
            h.frequencyHz.push_back(hz);
            h.magnitude.push_back(std::abs(g) / unit);
            h.phaseRad.push_back(phase);
            h.coherence.push_back(1.0);
        }
        const MeasuredOpenLoop l =
            measuredOpenLoop(h, e.gt->controller, unit, f.responses.openLoop);
        QCOMPARE(l.omegaRadPerSec.size(), h.frequencyHz.size());
        const FrequencyResponse model = frequencyResponse(e.gt->openLoop, l.omegaRadPerSec);
        for (std::size_t i = 0; i < l.omegaRadPerSec.size(); ++i) {
            QVERIFY(std::abs(l.magnitudeDb[i] - model.magnitudeDb[i]) < 1e-9);
            // On one branch with the model's drawn phase (whole turns apart at most elsewhere).
            const double d = l.phaseDeg[i] - model.phaseDeg[i];
            QVERIFY2(std::abs(d - 360.0 * std::round(d / 360.0)) < 1e-9,
                     qPrintable(QString::number(d)));
        }
        QVERIFY(std::abs(l.phaseDeg.front() - model.phaseDeg.front()) < 1e-9);
    }

    void badSettingsAreRefusedNamingTheField() {
        Session s = sessionWithMode(true);
        s.axes[0].gt.flexibleMode.dampingRatio = 1.0;
        AxisEvaluation e = evaluateAxis(s, 0);
        QVERIFY(!e.ok);
        QCOMPARE(e.errorField, std::string("axes[0].gt.flexible_mode.damping"));
        s = sessionWithMode(true);
        s.axes[0].gt.notch.centreHz = 60.0; // above 1 / (2 * 0.01 s) = 50 Hz
        e = evaluateAxis(s, 0);
        QVERIFY(e.ok); // the continuous loop runs; the digital implementation is refused
        QVERIFY(!e.digital);
        const bool warned =
            std::any_of(e.warnings.begin(), e.warnings.end(), [](const std::string& w) {
                return w.find("axes[0].gt.notch.centre") != std::string::npos &&
                       w.find("Nyquist") != std::string::npos;
            });
        QVERIFY(warned);
        s = Session::paperDefault();
        s.trajectory.shaping = {ShaperType::Zvd, 0.001, 0.1}; // lasts 1000 s, the move 130 s
        e = evaluateAxis(s, 0);
        QVERIFY(!e.ok);
        QCOMPARE(e.errorField, std::string("trajectory.shaping.frequency"));
        s.trajectory.shaping = {ShaperType::Zv, 5.0, 1.0};
        e = evaluateAxis(s, 0);
        QCOMPARE(e.errorField, std::string("trajectory.shaping.damping"));
        // Friction and a mode are not simulated together: refused at the mode.
        s = sessionWithMode(false);
        s.axes[0].friction.coulombVolts = 0.02;
        e = evaluateAxis(s, 0);
        QVERIFY(!e.ok);
        QCOMPARE(e.errorField, std::string("axes[0].gt.flexible_mode.frequency"));
        // A PID + feedforward axis has no notch stage.
        s = sessionWithMode(true);
        s.axes[0] = withModelFeedforward(s.axes[0], 0);
        e = evaluateAxis(s, 0);
        QVERIFY(!e.ok);
        QCOMPARE(e.errorField, std::string("axes[0].gt.notch.centre"));
    }
};

QTEST_APPLESS_MAIN(TstVibrationSession)
#include "tst_vibration_session.moc"
