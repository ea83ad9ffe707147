// SPDX-License-Identifier: GPL-3.0-or-later
// The design problem of a session's axis, at full and at live-preview fidelity.
// Expected values are built here from the session's own fields and the trajectory formulas
// (closed forms: the cubic of Braga et al. Eq. 4, the circle of Eq. 23-24), not by the code tested.
#include "core/model/errors.h"
#include "core/session/design_study.h"
#include "core/simulation/trajectory.h"
#include "tests/support/tolerance.h"

#include <QTest>

#include <cmath>

using namespace xyt;

class TstDesignStudy : public QObject {
    Q_OBJECT
private slots:
    void fullFidelityIsTheSessionsDt();
    void previewSpreadsAtMostMaxSamples();
    void shortRunKeepsTheSessionsDt();
    void circleHasNoMoveAndRunsItsDuration();
    void badAxisAndMethodAreNamed();
};

void TstDesignStudy::fullFidelityIsTheSessionsDt() {
    Session s; // the paper's default: cubic 0 -> 600 mm in 130 s, dt 0.01, settle limit 100 s
    const DesignProblem p = sessionDesignProblem(s, 1);
    QVERIFY(p.plant == s.axes[1].gt.plant);
    QCOMPARE(p.modelUnitsPerPositionUnit, s.axes[1].gt.modelUnitsPerPositionUnit);
    QCOMPARE(p.dtSeconds, 0.01);
    QCOMPARE(p.stepSamples, 500);
    QCOMPARE(p.spec.umaxVolts, s.umaxVolts);
    // tf + 2 x 100 s = 330 s at 0.01 s: 33,001 samples of the cubic.
    QCOMPARE(p.reference.size(), std::size_t(33001));
    const CubicTrajectory cubic(0.0, 600.0, 0.0, 130.0);
    for (std::size_t k :
         {std::size_t(0), std::size_t(6500), std::size_t(13000), std::size_t(33000)})
        XYT_COMPARE_NEAR(p.reference[k], cubic.position(static_cast<double>(k) * 0.01), 1e-15,
                         1e-12);
    QVERIFY(p.move.has_value());
    QCOMPARE(p.move->endSeconds, 130.0);
    QCOMPARE(p.move->targetMm, 600.0);
}

void TstDesignStudy::previewSpreadsAtMostMaxSamples() {
    Session s;
    const DesignProblem p = sessionDesignProblem(s, 0, kLivePreviewFidelity);
    // 330 s in 1,500 samples: dt = 330 / 1499, the last sample at 330 s.
    QCOMPARE(p.reference.size(), std::size_t(1500));
    XYT_COMPARE_NEAR(p.dtSeconds, 330.0 / 1499.0, 1e-15, 0.0);
    QCOMPARE(p.stepSamples, 100);
    const CubicTrajectory cubic(0.0, 600.0, 0.0, 130.0);
    XYT_COMPARE_NEAR(p.reference[1000], cubic.position(1000.0 * p.dtSeconds), 1e-15, 1e-12);
    XYT_COMPARE_NEAR(p.reference.back(), 600.0, 1e-15, 0.0);
}

void TstDesignStudy::shortRunKeepsTheSessionsDt() {
    Session s;
    s.trajectory.tfSeconds = 5.0;
    s.spec.maxSettleTimeSeconds = 2.0; // 9 s at 0.01 s: 901 samples, under the preview's 1,500
    const DesignProblem p = sessionDesignProblem(s, 0, kLivePreviewFidelity);
    QCOMPARE(p.dtSeconds, 0.01);
    QCOMPARE(p.reference.size(), std::size_t(901));
}

void TstDesignStudy::circleHasNoMoveAndRunsItsDuration() {
    Session s;
    s.trajectory.kind = TrajectoryKind::Circle; // 25 mm at 0.06 rad/s, ramp-in 10 s
    const DesignProblem p = sessionDesignProblem(s, 0);
    QVERIFY(!p.move);
    const double duration = 2.0 * M_PI / 0.06 + 10.0; // one revolution and the ramp-in
    QCOMPARE(p.reference.size(), std::size_t(std::floor(duration / 0.01 + 1e-9)) + 1);
    // x = R sin(w t) scaled by the ramp-in t / Tr before Tr: at t = 5 s, 25 * 0.5 * sin(0.3).
    XYT_COMPARE_NEAR(p.reference[500], 12.5 * std::sin(0.3), 1e-12, 1e-12);
}

void TstDesignStudy::badAxisAndMethodAreNamed() {
    Session s;
    const auto field = [&](int axis, const StudyFidelity& f) -> std::string {
        try {
            sessionDesignProblem(s, axis, f);
        } catch (const InvalidInput& e) {
            return e.field();
        }
        return {};
    };
    QCOMPARE(field(2, {}), std::string("axis"));
    QCOMPARE(field(-1, {}), std::string("axis"));
    QCOMPARE(field(0, StudyFidelity{1, 500}), std::string("max_samples"));
    s.axes[1].method = DesignMethod::PolePlacementZpetc;
    QCOMPARE(field(1, {}), std::string("method"));
    QCOMPARE(field(0, {}), std::string());
}

QTEST_APPLESS_MAIN(TstDesignStudy)
#include "tst_design_study.moc"
