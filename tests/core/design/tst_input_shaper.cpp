// SPDX-License-Identifier: GPL-3.0-or-later
// Input shapers against their closed forms: the residual vibration of an undamped mode after
// ZV is |cos(pi r / 2)| and after ZVD cos^2(pi r / 2), r the mode's frequency over the design
// frequency (Singer and Seering 1990); ZV cancels a damped mode at its design point exactly;
// EI leaves its tolerance at the design frequency of an undamped mode (Singhose, Seering and
// Singer 1994) and cancels at the two frequencies around it; every shaper's amplitudes sum to 1.
#include "core/design/input_shaper.h"
#include "core/model/errors.h"

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
