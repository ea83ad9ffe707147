// SPDX-License-Identifier: GPL-3.0-or-later
// Export tests: the C header compiles standalone and its controller reproduces the core's
// difference equation; the JSON parses back to the design; the script and CSV carry the design.
#include "core/design/digital_controller.h"
#include "core/session/export_text.h"
#include "core/session/session_evaluation.h"
#include "tests/support/core_checks.h"
#include "tests/support/tolerance.h"
#include "ui/files/coefficient_json.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <set>

using namespace xyt;

Q_DECLARE_METATYPE(xyt::Session)

class TstCoefficientExport : public QObject {
    Q_OBJECT
private slots:
    void tustinAndBackwardEulerClosedForms();
    void cHeaderCompilesAndMatchesCore();
    void jsonParsesBack();
    void octaveScriptDefinesTheTfObjects();
    void csvColumnsAndRows();
    void csvHoldsTheDigitalRunAtEachRow_data();
    void csvHoldsTheDigitalRunAtEachRow();
    void csvSamplesAtTheSessionDt_data();
    void csvSamplesAtTheSessionDt();
    void polePlacementAxisExports();
    void jsonRefusesNonFiniteNumbers();
};

void TstCoefficientExport::tustinAndBackwardEulerClosedForms() {
    // Closed forms: Tustin PI = [(kp + ki T/2) + (ki T/2 - kp) z^-1] / (1 - z^-1).
    const auto t = discretizePi(30.0, 0.2, 0.01, PiDiscretization::Tustin);
    XYT_COMPARE_NEAR(t.num[0], 30.001, 1e-15, 0.0);
    XYT_COMPARE_NEAR(t.num[1], -29.999, 1e-15, 0.0);
    QCOMPARE(t.den, (std::vector<double>{1.0, -1.0}));
    const auto b = discretizePi(30.0, 0.2, 0.01, PiDiscretization::BackwardEuler);
    XYT_COMPARE_NEAR(b.num[0], 30.002, 1e-15, 0.0);
    XYT_COMPARE_NEAR(b.num[1], -30.0, 1e-15, 0.0);
    // Invariant: the step response of a PI grows by ki*T per sample after the first.
    const auto step = filterDifferenceEquation(t.num, t.den, std::vector<double>(5, 1.0));
    for (std::size_t k = 2; k < step.size(); ++k)
        XYT_COMPARE_NEAR(step[k] - step[k - 1], 0.2 * 0.01, 1e-9, 0.0);
}

void TstCoefficientExport::cHeaderCompilesAndMatchesCore() {
    const QString cc = QStandardPaths::findExecutable("cc");
    if (cc.isEmpty())
        QSKIP("no C compiler (cc) on this machine");
    const Session s = Session::paperDefault();
    const SessionEvaluation e = evaluateSession(s);
    QTemporaryDir dir;
    QFile header(dir.filePath("xyt.h"));
    QVERIFY(header.open(QIODevice::WriteOnly));
    header.write(QByteArray::fromStdString(exportCHeader(s, e)));
    header.close();
    // A firmware-like loop: the difference equation on a unit step of the error, both axes.
    QFile program(dir.filePath("main.c"));
    QVERIFY(program.open(QIODevice::WriteOnly));
    program.write(R"(#include <stdio.h>
#include "xyt.h"
static void run(const double* num, int nn, const double* den, int nd) {
    double e[50], u[50];
    for (int k = 0; k < 50; ++k) {
        e[k] = 1.0;
        double acc = 0.0;
        for (int i = 0; i < nn && i <= k; ++i) acc += num[i] * e[k - i];
        for (int i = 1; i < nd && i <= k; ++i) acc -= den[i] * u[k - i];
        u[k] = acc / den[0];
        printf("%.17g\n", u[k]);
    }
}
int main(void) {
    run(XYT_X_NUM, XYT_X_NUM_LEN, XYT_X_DEN, XYT_X_DEN_LEN);
    run(XYT_Y_NUM, XYT_Y_NUM_LEN, XYT_Y_DEN, XYT_Y_DEN_LEN);
    printf("%.17g %.17g\n", XYT_X_TS, XYT_Y_TS);
    return 0;
}
)");
    program.close();
    QProcess compile;
    compile.setWorkingDirectory(dir.path());
    compile.start(cc,
                  {"-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic", "main.c", "-o", "main"});
    QVERIFY(compile.waitForFinished(60000));
    QVERIFY2(compile.exitCode() == 0, compile.readAllStandardError().constData());
    // The header alone, as a translation unit, must also compile warning-free.
    QProcess alone;
    alone.setWorkingDirectory(dir.path());
    alone.start(cc,
                {"-std=c99", "-Wall", "-Wextra", "-Werror", "-fsyntax-only", "-x", "c", "xyt.h"});
    QVERIFY(alone.waitForFinished(60000));
    QVERIFY2(alone.exitCode() == 0, alone.readAllStandardError().constData());
    QProcess run;
    run.start(dir.filePath("main"), {});
    QVERIFY(run.waitForFinished(60000));
    const QList<QByteArray> lines = run.readAllStandardOutput().split('\n');
    QVERIFY(lines.size() >= 101);
    for (int axis = 0; axis < 2; ++axis) {
        const auto& gt = *e.axes[static_cast<std::size_t>(axis)].gt;
        const auto c = discretizePi(gt.kp, gt.ki, s.controllerTsSeconds, PiDiscretization::Tustin);
        const auto expected = filterDifferenceEquation(c.num, c.den, std::vector<double>(50, 1.0));
        for (int k = 0; k < 50; ++k)
            // 17 printed digits round-trip exactly; the sums differ only in evaluation order.
            XYT_COMPARE_NEAR(lines[axis * 50 + k].toDouble(), expected[static_cast<std::size_t>(k)],
                             1e-14, 1e-14);
    }
    QCOMPARE(lines[100].trimmed(), QByteArray("0.01 0.01"));
}

void TstCoefficientExport::jsonParsesBack() {
    const Session s = Session::paperDefault();
    const SessionEvaluation e = evaluateSession(s);
    const QJsonObject json =
        QJsonDocument::fromJson(QJsonDocument(files::coefficientsJson(s, e)).toJson()).object();
    QCOMPARE(json["format"].toString(), QString("xytune-coefficients"));
    // The anti-windup the controller ships with travels with the coefficients.
    QCOMPARE(json["implementation"].toObject()["anti_windup"].toString(), QString("clamp"));
    const QJsonArray axes = json["axes"].toArray();
    QCOMPARE(axes.size(), 2);
    const QJsonObject x = axes[0].toObject();
    QCOMPARE(x["id"].toString(), QString("x"));
    QCOMPARE(x["continuous_pi"].toObject()["ki"].toDouble(), e.axes[0].gt->ki);
    QCOMPARE(x["digital_controller"].toObject()["order"].toString(),
             QString("ascending powers of z^-1"));
    const QJsonArray den = x["reference_model"].toObject()["den"].toArray();
    // Braga et al. Eq. 19: s^4 + 125.3 s^3 + 3665 s^2 + 2334 s + 16.
    QCOMPARE(den.size(), 5);
    XYT_COMPARE_NEAR(den[3].toDouble(), 2334.0, 1e-14, 0.0);
    XYT_COMPARE_NEAR(den[4].toDouble(), 16.0, 1e-14, 0.0);
    // The cross-coupled controller travels with the coefficients when it is on, and only then.
    QVERIFY(!json.contains("cross_coupling"));
    Session coupled = s;
    coupled.crossCoupling = {0.1, 1.5, ContourEstimateKind::Linear};
    const QJsonObject c =
        files::coefficientsJson(coupled, evaluateSession(coupled))["cross_coupling"].toObject();
    QCOMPARE(c["kp"].toDouble(), 0.1);
    QCOMPARE(c["ki"].toDouble(), 1.5);
    QCOMPARE(c["estimate"].toString(), QStringLiteral("linear"));
    QCOMPARE(c["corner_turn_rad"].toDouble(), kCornerTurnRad);
}

void TstCoefficientExport::octaveScriptDefinesTheTfObjects() {
    const Session s = Session::paperDefault();
    const std::string m = exportOctaveScript(s, evaluateSession(s));
    for (const char* needle :
         {"pkg load control", "plant_x = tf(77.799999999999997, [1 125.3 3665 0]);",
          "controller_x = tf([30 ", "closed_loop_x = feedback(controller_x * plant_x, 1);",
          "plant_y = tf(24.440000000000001, [1 68.180000000000007 863 0]);", "closed_loop_y",
          "lsim(closed_loop_y"})
        QVERIFY2(m.find(needle) != std::string::npos, needle);
    // The implementation travels into the script, in its default and another state.
    QVERIFY(
        m.find(
            "anti-windup clamp,\n% computation delay 0 samples, encoder 0 mm/count, DAC 0 bits") !=
        std::string::npos);
    Session q = s;
    q.implementation.antiWindup = AntiWindup::BackCalculation;
    q.implementation.trackingTimeSeconds = 0.25;
    q.implementation.delaySamples = 1;
    q.implementation.encoderResolutionMm = 0.001;
    q.implementation.dacBits = 16;
    const std::string mq = exportOctaveScript(q, evaluateSession(q));
    for (const char* needle : {"anti-windup back-calculation (tracking time 0.25 s; 0: kp/ki),",
                               "% computation delay 1 samples, encoder 0.001 mm/count, DAC 16 bits "
                               "(0: ideal), umax 2.5 V."})
        QVERIFY2(mq.find(needle) != std::string::npos, needle);
}

void TstCoefficientExport::csvColumnsAndRows() {
    const Session s = Session::paperDefault();
    const SessionEvaluation e = evaluateSession(s);
    const QList<QByteArray> lines =
        QByteArray::fromStdString(exportCsv(s, e)).trimmed().split('\n');
    QCOMPARE(lines[0],
             QByteArray("t,r_x,y_x,e_x,u_x,r_y,y_y,e_y,u_y,t_digital_x,y_digital_x,e_digital_x,"
                        "u_digital_x,t_digital_y,y_digital_y,e_digital_y,u_digital_y"));
    // The automatic run: the move and its settle, both ends; at 0.01 s.
    const double duration = e.duration.seconds;
    QVERIFY(duration > 130.0);
    QCOMPARE(lines.size(), qsizetype(1 + std::floor(duration / 0.01 + 1e-9) + 1));
    const QList<QByteArray> last = lines.back().split(',');
    XYT_COMPARE_NEAR(last[0].toDouble(), e.axes[0].run.t.back(), 1e-9, 0.0); // 10 printed digits
    XYT_COMPARE_NEAR(last[1].toDouble(), 600.0, 1e-9, 0.0);                  // 10 printed digits
}

namespace {

/// The exported CSV as a header and rows of numbers (an empty cell reads as NaN).
struct CsvTable {
    QList<QByteArray> header;
    std::vector<std::vector<double>> rows;
    std::size_t column(const char* name) const {
        const auto i = header.indexOf(QByteArray(name));
        return i < 0 ? std::size_t(-1) : static_cast<std::size_t>(i);
    }
};

CsvTable readCsv(const std::string& text) {
    CsvTable out;
    const QList<QByteArray> lines = QByteArray::fromStdString(text).trimmed().split('\n');
    out.header = lines[0].split(',');
    for (qsizetype k = 1; k < lines.size(); ++k) {
        std::vector<double> row;
        for (const QByteArray& cell : lines[k].split(','))
            row.push_back(cell.isEmpty() ? std::nan("") : std::strtod(cell.constData(), nullptr));
        out.rows.push_back(std::move(row));
    }
    return out;
}

/// The session's dt grid: floor(duration / dt + 1e-9) + 1 samples (sampleTimes).
std::size_t dtRows(const SessionEvaluation& e, double dt) {
    return static_cast<std::size_t>(std::floor(e.duration.seconds / dt + 1e-9)) + 1;
}

constexpr DesignMethod kGt = DesignMethod::GuilleminTruxal, kPp = DesignMethod::PolePlacementZpetc;

/// How the controller of a table's session is implemented.
enum class Implementation {
    Ideal,               ///< the default: no delay, DAC or encoder, controller_ts = dt
    Dac12Bits,           ///< a 12-bit DAC
    SlowDelayedQuantized ///< controller_ts 5 dt, one sample of delay, a 12-bit DAC, a 1 um encoder
};

/// A row of the CSV tables: Braga et al.'s default session with a method on each axis.
struct SessionRow {
    const char* name;
    DesignMethod x, y;
    Implementation implementation;
};

/// The "session" column and one row per @p rows, each session built from the default.
void addSessionRows(std::initializer_list<SessionRow> rows) {
    QTest::addColumn<Session>("session");
    for (const SessionRow& row : rows) {
        Session s = Session::paperDefault();
        s.axes[0].method = row.x;
        s.axes[1].method = row.y;
        if (row.implementation != Implementation::Ideal)
            s.implementation.dacBits = 12;
        if (row.implementation == Implementation::SlowDelayedQuantized) {
            s.controllerTsSeconds = 0.05;
            s.implementation.delaySamples = 1;
            s.implementation.encoderResolutionMm = 0.001;
        }
        QTest::newRow(row.name) << s;
    }
}

} // namespace

void TstCoefficientExport::csvHoldsTheDigitalRunAtEachRow_data() {
    addSessionRows(
        {{"guillemin-truxal, controller_ts = dt", kGt, kGt, Implementation::Ideal},
         {"guillemin-truxal, controller_ts 5 dt, delay, DAC, encoder", kGt, kGt,
          Implementation::SlowDelayedQuantized},
         {"pole placement + ZPETC, Ts 0.07 s, DAC", kPp, kPp, Implementation::Dac12Bits}});
}

void TstCoefficientExport::csvHoldsTheDigitalRunAtEachRow() {
    // Engineers compare the digital implementation with their firmware's logs: each row holds
    // the controller's last sample at or before t, with its instant, bit for bit as the core's
    // sampled-data run (DigitalEvaluation::run) computed it; every controller sample appears.
    QFETCH(Session, session);
    const SessionEvaluation e = evaluateSession(session);
    const CsvTable csv = readCsv(exportCsv(session, e));
    const double dt = session.trajectory.dtSeconds;
    QCOMPARE(csv.rows.size(), dtRows(e, dt));
    for (std::size_t i = 0; i < 2; ++i) {
        const std::string id = session.axes[i].id;
        QVERIFY(e.axes[i].digital);
        const SimulationResult& d = e.axes[i].digital->run.result;
        const double ts = e.axes[i].digital->tsSeconds;
        const std::size_t ct = csv.column(("t_digital_" + id).c_str()),
                          cy = csv.column(("y_digital_" + id).c_str()),
                          ce = csv.column(("e_digital_" + id).c_str()),
                          cu = csv.column(("u_digital_" + id).c_str()),
                          cOwn = csv.column(("y_" + id).c_str());
        QVERIFY(ct != std::size_t(-1) && cy != std::size_t(-1) && ce != std::size_t(-1) &&
                cu != std::size_t(-1));
        std::set<std::size_t> seen;
        bool differsFromTheDesignRun = false;
        for (std::size_t k = 0; k < csv.rows.size(); ++k) {
            const std::vector<double>& row = csv.rows[k];
            const double t = static_cast<double>(k) * dt;
            // The held sample: found by its instant, bit for bit.
            const auto at = std::lower_bound(d.t.begin(), d.t.end(), row[ct]);
            QVERIFY(at != d.t.end() && *at == row[ct]);
            const std::size_t j = static_cast<std::size_t>(at - d.t.begin());
            // The last sample at or before t (1e-9 s for the round-off of k dt against j Ts).
            QVERIFY2(d.t[j] <= t + 1e-9 && (j + 1 == d.t.size() || d.t[j + 1] > t + 1e-9),
                     qPrintable(QString("row %1: t %2, t_digital %3").arg(k).arg(t).arg(d.t[j])));
            QVERIFY(row[cy] == d.y[j] && row[ce] == d.e[j] && row[cu] == d.u[j]);
            seen.insert(j);
            if (std::abs(row[cy] - row[cOwn]) > 1e-9)
                differsFromTheDesignRun = true;
        }
        QCOMPARE(seen.size(), d.t.size());
        QVERIFY(ts >= dt);
        // The columns are the implementation's run, not a copy of the design's (the DAC and the
        // encoder's quantization, the delay, the slower sampling move it).
        if (session.implementation.dacBits > 0)
            QVERIFY(differsFromTheDesignRun);
    }
}

void TstCoefficientExport::csvSamplesAtTheSessionDt_data() {
    addSessionRows({{"guillemin-truxal both", kGt, kGt, Implementation::Ideal},
                    {"pole placement on x (Ts 0.07 s), guillemin-truxal on y", kPp, kGt,
                     Implementation::Ideal},
                    {"pole placement both", kPp, kPp, Implementation::Ideal}});
}

void TstCoefficientExport::csvSamplesAtTheSessionDt() {
    // One row per step of the session's dt (before, the pole-placement Ts of 0.07 s when x was
    // a pole-placement axis); a pole-placement axis' columns hold its last sample at or before t.
    QFETCH(Session, session);
    const SessionEvaluation e = evaluateSession(session);
    const CsvTable csv = readCsv(exportCsv(session, e));
    const double dt = session.trajectory.dtSeconds;
    QCOMPARE(csv.rows.size(), dtRows(e, dt));
    for (std::size_t k = 0; k < csv.rows.size(); ++k)
        XYT_COMPARE_NEAR(csv.rows[k][0], static_cast<double>(k) * dt, 1e-9,
                         1e-12); // 10 printed digits
    for (std::size_t i = 0; i < 2; ++i) {
        const std::string id = session.axes[i].id;
        const SimulationResult& run = e.axes[i].run;
        const std::size_t cr = csv.column(("r_" + id).c_str()),
                          cy = csv.column(("y_" + id).c_str());
        for (std::size_t k = 0; k < csv.rows.size(); k += 13) {
            const double t = static_cast<double>(k) * dt;
            // The run's last sample at or before t (1e-9 s for the round-off of k dt and j Ts).
            const std::size_t j = static_cast<std::size_t>(
                std::upper_bound(run.t.begin(), run.t.end(), t + 1e-9) - run.t.begin() - 1);
            XYT_COMPARE_NEAR(csv.rows[k][cr], run.r[j], 1e-9, 1e-9);
            XYT_COMPARE_NEAR(csv.rows[k][cy], run.y[j], 1e-9, 1e-9);
        }
    }
}

void TstCoefficientExport::polePlacementAxisExports() {
    Session s = Session::paperDefault();
    s.axes[1].method =
        DesignMethod::PolePlacementZpetc; // the y-axis ARX model of Patrick, Ishak and Adnan
    const SessionEvaluation e = evaluateSession(s);
    QVERIFY(e.axes[1].ok);
    const QJsonObject y = files::coefficientsJson(s, e)["axes"].toArray()[1].toObject();
    const QJsonObject rst = y["rst"].toObject();
    // The RST polynomials are the core's, exactly (JSON keeps the shortest round-trip digits).
    QCOMPARE(rst["Kf"].toDouble(), e.axes[1].pp->kf);
    QCOMPARE(rst["G"].toArray()[0].toDouble(), e.axes[1].pp->g.coefficient(0));
    QCOMPARE(y["zpetc"].toObject()["preview_steps"].toInt(), e.axes[1].zpetc->previewSteps);
    const std::string header = exportCHeader(s, e);
    QVERIFY(header.find("XYT_Y_KF") != std::string::npos);
    QVERIFY(header.find("XYT_Y_FF_NUM") != std::string::npos);
    QVERIFY(header.find("#define XYT_Y_PREVIEW 2") != std::string::npos);
    const QString cc = QStandardPaths::findExecutable("cc");
    if (cc.isEmpty())
        QSKIP("no C compiler (cc) on this machine");
    QTemporaryDir dir;
    QFile f(dir.filePath("pp.h"));
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(QByteArray::fromStdString(header));
    f.close();
    QProcess compile;
    compile.setWorkingDirectory(dir.path());
    compile.start(cc,
                  {"-std=c99", "-Wall", "-Wextra", "-Werror", "-fsyntax-only", "-x", "c", "pp.h"});
    QVERIFY(compile.waitForFinished(60000));
    QVERIFY2(compile.exitCode() == 0, compile.readAllStandardError().constData());
    const std::string m = exportOctaveScript(s, e);
    QVERIFY(m.find("plant_y = filt([0 0.035200000000000002 0.059900000000000002 "
                   "-0.0067000000000000002]") != std::string::npos);
    QVERIFY(m.find("closed_loop_y = Kf_y * feedback(") != std::string::npos);
}

QTEST_APPLESS_MAIN(TstCoefficientExport)
void TstCoefficientExport::jsonRefusesNonFiniteNumbers() {
    // QJsonValue writes inf as null, so the JSON export used to succeed with null
    // coefficients. Closed form: ki = wn^4/k0 = 1e4/77.8 = 128.5 at wn 10, and the Tustin
    // kp + ki Ts/2 overflows a double at Ts = 1e308.
    Session s = Session::paperDefault();
    s.axes[0].gt.omegaNRadPerSec = 10.0;
    s.controllerTsSeconds = 1e308;
    const SessionEvaluation e = evaluateSession(s);
    QVERIFY(e.axes[0].ok);
    QCOMPARE(xyt::test::invalidInputField([&] { files::coefficientsJson(s, e); }),
             QString("axes[0].gt (digital PI at controller_ts)"));
    // The C header names the same field (the same check, exportableNumber).
    QCOMPARE(xyt::test::invalidInputField([&] { exportCHeader(s, e); }),
             QString("axes[0].gt (digital PI at controller_ts)"));
}

#include "tst_coefficient_export.moc"
