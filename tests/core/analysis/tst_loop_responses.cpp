// SPDX-License-Identifier: GPL-3.0-or-later
// Loop transfer functions of both design methods and the ZPETC tracking response.
#include "core/analysis/loop_responses.h"
#include "core/analysis/stability_margins.h"
#include "core/design/guillemin_truxal.h"
#include "core/design/pole_placement.h"
#include "core/design/zpetc.h"
#include "tests/support/tolerance.h"

#include <QTest>

#include <cmath>

using namespace xyt;

namespace {
PolePlacementDesign presetDesign(const char* name) {
    const auto p = *findPolePlacementPreset(name);
    return designPolePlacement(p.a, p.b, p.t, p.tsSeconds);
}
} // namespace

class TstLoopResponses : public QObject {
    Q_OBJECT
private slots:
    void gtLoopIdentities();
    void rstLoopIdentities();
    void zpetcTrackingHasZeroPhase();
};

// Identities of unity feedback, at every grid frequency: S + T = 1, T = L S, u/r = G_c S, and
// T equals the design's closed loop (Braga et al.: feedback(G_c G) = G_R, Eq. 10 = Eq. 7). L has
// the double pole at s = 0 (phase from -180 degrees).
void TstLoopResponses::gtLoopIdentities() {
    for (const char* preset : {"lower-base", "upper-base"}) {
        const GtPreset p = *findGtPreset(preset);
        const GtDesign d = designGuilleminTruxal(p.plant, p.omegaNRadPerSec, p.kp);
        const LoopTransferFunctions loop = gtLoopTransferFunctions(d);
        const std::vector<double> w = logFrequencyGrid(1e-3, 1e3, 300);
        const LoopFrequencyResponses r = loopFrequencyResponses(loop, w);
        QCOMPARE(r.openLoop.lowFrequencyIntegrators, 2);
        // Far below the PI zero psi1 (0.00686 and 0.0409 rad/s) the phase is that of the
        // double integrator.
        XYT_COMPARE_NEAR(frequencyResponse(loop.openLoop, {1e-9}).phaseDeg[0], -180.0, 0.0, 1e-4);
        for (std::size_t i = 0; i < w.size(); ++i) {
            const auto l = r.openLoop.value[i], s = r.sensitivity.value[i],
                       t = r.complementarySensitivity.value[i], u = r.inputSensitivity.value[i];
            // 1e-12 relative to the largest term: the same polynomials evaluated by Horner.
            QVERIFY(test::nearComplex(s + t, 1.0, 0.0, 1e-12 * (std::abs(s) + std::abs(t))));
            QVERIFY(test::nearComplex(t, l * s, 1e-12));
            QVERIFY(test::nearComplex(u, d.controller.frequencyResponse(w[i]) * s, 1e-12));
            QVERIFY(test::nearComplex(t, d.closedLoop.frequencyResponse(w[i]), 1e-10));
        }
    }
}

// The RST identities (Patrick, Ishak and Adnan Fig. 9): S + T = 1, T = L S, and the tracking
// without feedforward equals the design's K_f B/T closed loop to the Diophantine residual.
void TstLoopResponses::rstLoopIdentities() {
    for (const char* preset : {"x-axis", "y-axis"}) {
        const PolePlacementDesign d = presetDesign(preset);
        const LoopTransferFunctions loop = rstLoopTransferFunctions(d);
        const std::vector<double> w = nyquistLogGrid(d.tsSeconds, 200);
        const LoopFrequencyResponses r = loopFrequencyResponses(loop, w);
        const TrackingFrequencyResponses tr = zpetcTrackingFrequencyResponses(d, designZpetc(d), w);
        for (std::size_t i = 0; i < w.size(); ++i) {
            const auto l = r.openLoop.value[i], s = r.sensitivity.value[i],
                       t = r.complementarySensitivity.value[i];
            QVERIFY(test::nearComplex(s + t, 1.0, 0.0, 1e-12 * (std::abs(s) + std::abs(t))));
            QVERIFY(test::nearComplex(t, l * s, 1e-12));
            QVERIFY(test::nearComplex(tr.withoutFeedforward.value[i],
                                      d.closedLoop().frequencyResponse(w[i]), 1e-9));
        }
        const StabilityMargins m = stabilityMargins(loop.openLoop);
        QVERIFY(m.closedLoopStable);
    }
}

// Patrick, Ishak and Adnan Sec. 4 (Tomizuka's ZPETC): with the feedforward the tracking phase is
// zero at every frequency to round-off and the DC gain is 1; the gain falls monotonically from 1
// towards the Nyquist frequency (|B-(e^{j theta})|^2/B-(1)^2 of the uncancelled zeros). Compared
// with zpetcFrequencyResponse, which evaluates the two filters separately.
void TstLoopResponses::zpetcTrackingHasZeroPhase() {
    for (const char* preset : {"x-axis", "y-axis"}) {
        const PolePlacementDesign d = presetDesign(preset);
        const ZpetcDesign z = designZpetc(d);
        std::vector<double> w = nyquistLogGrid(d.tsSeconds, 400);
        w.insert(w.begin(), 0.0);
        const TrackingFrequencyResponses tr = zpetcTrackingFrequencyResponses(d, z, w);
        const ZpetcFrequencyResponse filters = zpetcFrequencyResponse(d, z, w);
        // DC gain 1: round-off of the polynomial sums (1e-12).
        XYT_COMPARE_NEAR(std::abs(tr.withZpetc.value[0]), 1.0, 0.0, 1e-12);
        for (std::size_t i = 0; i < w.size(); ++i) {
            // Zero phase to round-off: 1e-9 degrees (the values are products of polynomials
            // of degree <= 8 with coefficients of order 1-10 at |z| = 1).
            QVERIFY2(std::abs(tr.withZpetc.phaseDeg[i]) < 1e-9,
                     qPrintable(QString::number(tr.withZpetc.phaseDeg[i])));
            XYT_COMPARE_NEAR(std::abs(tr.withZpetc.value[i]), filters.gainWithFf[i], 1e-10, 0.0);
            if (i > 0)
                QVERIFY(std::abs(tr.withZpetc.value[i]) <=
                        std::abs(tr.withZpetc.value[i - 1]) * (1.0 + 1e-12));
        }
        QVERIFY(std::abs(tr.withZpetc.value.back()) < 0.9); // a real gain error near Nyquist
        // Without feedforward the phase lags (the NMP zero and T): clearly non-zero at Nyquist.
        QVERIFY(std::abs(tr.withoutFeedforward.phaseDeg.back()) > 10.0);
    }
}

QTEST_APPLESS_MAIN(TstLoopResponses)
#include "tst_loop_responses.moc"
