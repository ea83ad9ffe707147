// SPDX-License-Identifier: GPL-3.0-or-later
// Input shapers against their closed forms: the residual vibration of an undamped mode after
// ZV is |cos(pi r / 2)| and after ZVD cos^2(pi r / 2), r the mode's frequency over the design
// frequency (Singer and Seering 1990); ZV cancels a damped mode at its design point exactly;
// EI leaves its tolerance at the design frequency of an undamped mode (Singhose, Seering and
// Singer 1994) and cancels at the two frequencies around it; every shaper's amplitudes sum to 1.
#include "core/design/input_shaper.h"
#include "core/design/shaper_sensitivity.h"
#include "core/model/errors.h"

#include "tests/support/tolerance.h"

#include <QTest>

#include <cmath>
#include <numbers>

using namespace xyt;

class TstInputShaper : public QObject {
    Q_OBJECT

private slots:
    /// Round-off: sums of a handful of terms of size 1, 1e-14.
    void zvAndZvdMatchTheirClosedForms() {
        const double f = 40.0;
        const InputShaper zv = designInputShaper(ShaperType::Zv, f, 0.0);
        const InputShaper zvd = designInputShaper(ShaperType::Zvd, f, 0.0);
        for (double r = 0.1; r < 3.0; r += 0.05) {
            const double c = std::cos(std::numbers::pi * r / 2.0);
            QVERIFY(std::abs(residualVibration(zv, r * f, 0.0) - std::abs(c)) < 1e-14);
            QVERIFY(std::abs(residualVibration(zvd, r * f, 0.0) - c * c) < 1e-14);
        }
    }

    /// Damped: ZV, ZVD and ZVDD cancel the mode they are designed for (Singer and Seering's
    /// conditions), to round-off.
    void theZvFamilyCancelsItsDampedMode() {
        for (const ShaperType t : {ShaperType::Zv, ShaperType::Zvd, ShaperType::Zvdd})
            for (const double zeta : {0.0, 0.05, 0.1, 0.3}) {
                const InputShaper s = designInputShaper(t, 55.0, zeta);
                QVERIFY2(residualVibration(s, 55.0, zeta) < 1e-14,
                         qPrintable(QString("%1 zeta %2").arg(shaperName(t)).arg(zeta)));
            }
    }

    /// EI for an undamped mode: the tolerance exactly at the design frequency, and (near) zero
    /// on each side of it, where the hump ends (the minima on a 0.01 Hz grid below 1e-3).
    void eiLeavesItsToleranceAtTheDesignFrequency() {
        const InputShaper ei = designInputShaper(ShaperType::Ei, 50.0, 0.0);
        QVERIFY(std::abs(residualVibration(ei, 50.0, 0.0) - kShaperVibrationTolerance) < 1e-14);
        // The minima below and above the design frequency are (near) zero.
        double below = 1.0, above = 1.0;
        for (double f = 30.0; f < 50.0; f += 0.01)
            below = std::min(below, residualVibration(ei, f, 0.0));
        for (double f = 50.01; f < 70.0; f += 0.01)
            above = std::min(above, residualVibration(ei, f, 0.0));
        QVERIFY(below < 1e-3 && above < 1e-3);
    }

    /// Invariants: amplitudes sum to 1 (a shaped move ends where it should), all positive,
    /// times from 0 increasing; the multi-hump shapers stay below the tolerance over a wider
    /// band than EI around an undamped design point (their purpose).
    void everyShaperIsAConvolutionOfUnitGain() {
        for (const ShaperType t :
             {ShaperType::Zv, ShaperType::Zvd, ShaperType::Zvdd, ShaperType::Mzv, ShaperType::Ei,
              ShaperType::TwoHumpEi, ShaperType::ThreeHumpEi}) {
            const InputShaper s = designInputShaper(t, 40.0, 0.1);
            double sum = 0.0;
            for (double a : s.amplitudes) {
                QVERIFY(a > 0.0);
                sum += a;
            }
            QVERIFY(std::abs(sum - 1.0) < 1e-15);
            QCOMPARE(s.times.front(), 0.0);
            for (std::size_t i = 1; i < s.times.size(); ++i)
                QVERIFY(s.times[i] > s.times[i - 1]);
            ShaperType back;
            QVERIFY(shaperFromName(shaperName(t), back) && back == t);
        }
        const auto band = [](ShaperType t) {
            const InputShaper s = designInputShaper(t, 50.0, 0.0);
            double width = 0.0;
            for (double f = 20.0; f < 80.0; f += 0.01)
                if (residualVibration(s, f, 0.0) <= kShaperVibrationTolerance + 1e-12)
                    width += 0.01;
            return width;
        };
        QVERIFY(band(ShaperType::TwoHumpEi) > band(ShaperType::Ei));
        QVERIFY(band(ShaperType::ThreeHumpEi) > band(ShaperType::TwoHumpEi));
    }

    /// ZVD's sensitivity curve for an undamped mode: H(w) = (1 + 2 e^{-j w T/2} + e^{-j w T})/4
    /// = e^{-j w T/2} cos^2(w T/4) with T = 1/f_d, so V(f) = cos^2(pi f / (2 f_d)) (Singer and
    /// Seering 1990), on the stated grid 0 .. 2.5 f_d in 250 steps; round-off 1e-14.
    void zvdSensitivityCurveIsCosineSquared() {
        const InputShaper zvd = designInputShaper(ShaperType::Zvd, 40.0, 0.0);
        const ShaperSensitivity s = shaperSensitivity(zvd);
        QCOMPARE(s.frequencyHz.size(), std::size_t(251));
        QCOMPARE(s.frequencyHz.front(), 0.0);
        XYT_COMPARE_NEAR(s.frequencyHz.back(), 100.0, 1e-15, 0.0);
        for (std::size_t k = 0; k < s.frequencyHz.size(); ++k) {
            const double c = std::cos(std::numbers::pi * s.frequencyHz[k] / 80.0);
            XYT_COMPARE_NEAR(s.vibration[k], c * c, 0.0, 1e-14);
        }
    }

    /// EI for an undamped mode (amplitudes (1+V)/4, (1-V)/2, (1+V)/4 at 0, T/2, T): H(w) =
    /// e^{-j w T/2} ((1-V)/2 + (1+V)/2 cos(pi r)), r = f/f_d, so V(r) = |(1-V)/2 + (1+V)/2
    /// cos(pi r)|: V at r = 1 and zero where cos(pi r) = -(1-V)/(1+V), at r1 = acos(-(1-V)/(1+V))
    /// / pi = 0.86 and 2 - r1 = 1.14 for V = 5 %: the hump of height V between two zeros that
    /// Singhose, Seering and Singer (1994) place around the design frequency. Round-off 1e-14.
    void eiSensitivityHasItsHumpBetweenTwoZeros() {
        const double v = kShaperVibrationTolerance, fd = 40.0;
        const InputShaper ei = designInputShaper(ShaperType::Ei, fd, 0.0);
        const ShaperSensitivity s = shaperSensitivity(ei, 501);
        for (std::size_t k = 0; k < s.frequencyHz.size(); ++k) {
            const double r = s.frequencyHz[k] / fd;
            const double closed =
                std::abs(0.5 * (1.0 - v) + 0.5 * (1.0 + v) * std::cos(std::numbers::pi * r));
            XYT_COMPARE_NEAR(s.vibration[k], closed, 0.0, 1e-14);
        }
        const double r1 = std::acos(-(1.0 - v) / (1.0 + v)) / std::numbers::pi;
        QVERIFY(r1 > 0.85 && r1 < 0.87);
        QVERIFY(residualVibration(ei, r1 * fd, 0.0) < 1e-14);
        QVERIFY(residualVibration(ei, (2.0 - r1) * fd, 0.0) < 1e-14);
        XYT_COMPARE_NEAR(residualVibration(ei, fd, 0.0), v, 1e-13, 0.0);
    }

    /// The delay is the centroid sum A_i t_i: for an undamped mode every shaper's amplitudes
    /// are symmetric (K = 1), so the centroid is half the duration (1e-15 s); damping makes the
    /// later impulses smaller (K < 1), so it moves earlier.
    void delayIsTheCentroid() {
        for (const ShaperType t :
             {ShaperType::Zv, ShaperType::Zvd, ShaperType::Zvdd, ShaperType::Mzv, ShaperType::Ei,
              ShaperType::TwoHumpEi, ShaperType::ThreeHumpEi}) {
            const InputShaper s = designInputShaper(t, 40.0, 0.0);
            XYT_COMPARE_NEAR(shaperDelaySeconds(s), 0.5 * s.duration(), 0.0, 1e-15);
            const InputShaper damped = designInputShaper(t, 40.0, 0.1);
            QVERIFY(shaperDelaySeconds(damped) < 0.5 * damped.duration());
        }
        QVERIFY_THROWS_EXCEPTION(InvalidInput,
                                 shaperSensitivity(designInputShaper(ShaperType::Zv, 40, 0), 1));
    }

    void badModesAreRefusedByName() {
        for (const auto& [f, zeta, field] :
             {std::tuple{0.0, 0.1, "frequency"}, std::tuple{std::nan(""), 0.1, "frequency"},
              std::tuple{40.0, 1.0, "damping"}, std::tuple{40.0, -0.1, "damping"}}) {
            try {
                designInputShaper(ShaperType::Zv, f, zeta);
                QFAIL("a bad mode was accepted");
            } catch (const InvalidInput& e) {
                QCOMPARE(QString::fromStdString(e.field()), QString(field));
            }
        }
    }
};

QTEST_GUILESS_MAIN(TstInputShaper)
#include "tst_input_shaper.moc"
