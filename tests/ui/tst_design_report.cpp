// SPDX-License-Identifier: GPL-3.0-or-later
// The design report (ui/report): the PDF written by ReportWriter, by `xytune --report` and by
// File › Export report holds the session's numbers as the core computes them here, apart from
// the report's code (designGuilleminTruxal, discretizePi, designPolePlacement,
// stabilityMargins, evaluateSession), every row of the metrics panel, and the workbench's
// plots as images. The text is read back with poppler's pdftotext and pdfimages: a missing
// poppler-utils fails the test (scripts/dev.sh installs it), it never skips.
#include "tests/support/built_programs.h"

#include "core/analysis/loop_responses.h"
#include "core/analysis/stability_margins.h"
#include "core/design/digital_controller.h"
#include "core/design/guillemin_truxal.h"
#include "core/design/pole_placement.h"
#include "core/session/session_evaluation.h"
#include "ui/files/session_file.h"
#include "ui/main_window.h"
#include "ui/panels/metrics_panel.h"
#include "ui/report/report_exporter.h"
#include "ui/report/report_writer.h"
#include "ui/session/tuning_session.h"

#include <QAction>
#include <QElapsedTimer>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QMenu>
#include <QMenuBar>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

using namespace xyt;
using namespace xyt::ui;

namespace {

/// Runs a poppler tool on @p pdf; false (with the reason in @p out) when it cannot be run.
bool poppler(const QString& tool, const QStringList& args, QString& out) {
    QProcess p;
    p.start(tool, args);
    if (!p.waitForStarted(10000)) {
        out = QStringLiteral("%1 could not be started (install poppler-utils): %2")
                  .arg(tool, p.errorString());
        return false;
    }
    p.waitForFinished(60000);
    out = QString::fromUtf8(p.readAllStandardOutput());
    if (p.exitStatus() != QProcess::NormalExit || p.exitCode() != 0) {
        out = tool + QStringLiteral(" failed: ") + QString::fromUtf8(p.readAllStandardError());
        return false;
    }
    return true;
}

/// The report's numbers as the panels and the equations print them: six significant digits
/// for coefficients (QString::number 'g' 6), four for the figures (displayNumber).
QString six(double v) {
    return QString::number(v, 'g', 6);
}

/**
 * The text of @p pdf as pdftotext reads it, compatibility-normalized (NFKC): the PDF's fonts set
 * "fi" and "fl" as ligature glyphs, which pdftotext returns as U+FB01 and U+FB02. Needles are
 * normalized alike (plain()).
 */
bool pdfText(const QString& pdf, QString& text) {
    if (!poppler("pdftotext", {"-layout", pdf, "-"}, text))
        return false;
    text = text.normalized(QString::NormalizationForm_KC);
    return true;
}

QString plain(const QString& s) {
    return s.normalized(QString::NormalizationForm_KC);
}

/// Pages of @p pdf as pdfinfo reads them (0 on failure, with @p why).
int pageCount(const QString& pdf, QString& why) {
    if (!poppler("pdfinfo", {pdf}, why))
        return 0;
    for (const QString& line : why.split('\n'))
        if (line.startsWith("Pages:"))
            return line.mid(6).trimmed().toInt();
    return 0;
}

/// Images embedded in @p pdf as pdfimages -list lists them (-1 on failure, with @p why).
int imageCount(const QString& pdf, QString& why) {
    if (!poppler("pdfimages", {"-list", pdf}, why))
        return -1;
    // Two header lines (titles and dashes), then one line per image.
    return static_cast<int>(why.split('\n', Qt::SkipEmptyParts).size()) - 2;
}

Session polePlacementY() {
    Session s = Session::paperDefault();
    s.axes[1].method = DesignMethod::PolePlacementZpetc;
    return s;
}

} // namespace

class TstDesignReport : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void reportHoldsTheDesign_data();
    void reportHoldsTheDesign();
    void failedReportLeavesTheOldFile();
    void commandLine();
    void menuActionReportsTheCurrentSession();

private:
    QTemporaryDir dir_;
};

void TstDesignReport::initTestCase() {
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName("xytune-tests");
    QVERIFY(dir_.isValid());
}

void TstDesignReport::reportHoldsTheDesign_data() {
    QTest::addColumn<Session>("session");
    QTest::newRow("paper default (Guillemin-Truxal on both axes)") << Session::paperDefault();
    QTest::newRow("y by pole placement + ZPETC") << polePlacementY();
}

void TstDesignReport::reportHoldsTheDesign() {
    QFETCH(Session, session);
    const QString pdf = dir_.filePath(QString::fromUtf8(QTest::currentDataTag()).left(5) + ".pdf");
    QString error;
    QElapsedTimer timer;
    timer.start();
    QVERIFY2(ReportWriter::write(session, "design.json", pdf, &error), qPrintable(error));
    qInfo("report written in %lld ms", static_cast<long long>(timer.elapsed()));
    QString text;
    QVERIFY2(pdfText(pdf, text), qPrintable(text));
    QString why;
    QVERIFY2(pageCount(pdf, why) > 1, qPrintable(why));
    // Four plots per axis (root locus, Bode, step, time response) and the XY contour: the
    // figures axisFigures and contourFigures draw for a trajectory that is not a full circle.
    QCOMPARE(imageCount(pdf, why), 2 * 4 + 1);

    QVERIFY(text.contains("XY Tune design report"));
    QVERIFY(text.contains(QStringLiteral(PROJECT_VERSION_STRING)));
    QVERIFY(text.contains("design.json"));
    // The evaluation as the core makes it from the same session (evaluateSession at the
    // session's dt, as the report is documented to use).
    const SessionEvaluation evaluation = evaluateSession(session);
    for (int i = 0; i < 2; ++i) {
        const AxisSettings& a = session.axes[static_cast<std::size_t>(i)];
        const AxisEvaluation& e = evaluation.axes[static_cast<std::size_t>(i)];
        QVERIFY(e.ok);
        if (a.method == DesignMethod::GuilleminTruxal) {
            // Braga et al.'s design, computed here: ki = kp psi1 (Eq. 16), and the plant.
            const GtDesign d = designGuilleminTruxal(a.gt.plant, a.gt.omegaNRadPerSec, a.gt.kp);
            for (const double v : {a.gt.plant.k0, a.gt.plant.a1, a.gt.plant.a2, d.ki})
                QVERIFY2(text.contains(six(v)), qPrintable(six(v)));
            QVERIFY(text.contains(QStringLiteral("ωn = %1 rad/s").arg(six(a.gt.omegaNRadPerSec))));
            QVERIFY(text.contains(QStringLiteral("kp = %1").arg(six(a.gt.kp))));
            // The digital PI at controller_ts, discretized as the session says (Tustin: [kp + ki
            // Ts/2, ki Ts/2 - kp] / [1, -1]), as the coefficient export lists it.
            const DigitalController c =
                discretizePi(d.kp, d.ki, session.controllerTsSeconds, session.piDiscretization);
            const QString num =
                QStringLiteral("num = [%1, %2], den = [%3, %4]")
                    .arg(six(c.num[0]), six(c.num[1]), six(c.den[0]), six(c.den[1]));
            QVERIFY2(text.contains(num), qPrintable(num));
            // The phase margin of L = Gc G (stabilityMargins of gtLoopTransferFunctions), four
            // significant digits as the metrics panel writes it.
            const StabilityMargins m = stabilityMargins(gtLoopTransferFunctions(d).openLoop);
            QVERIFY2(text.contains(displayNumber(m.phaseMarginDeg)),
                     qPrintable(displayNumber(m.phaseMarginDeg)));
            QVERIFY(text.contains(displayNumber(m.gainMarginDb)));
        } else {
            // Patrick, Ishak and Adnan's RST design, computed here from the axis' A, B, T.
            const PolePlacementDesign d = designPolePlacement(
                Polynomial::fromAscending(a.pp.a), Polynomial::fromAscending(a.pp.b),
                Polynomial::fromAscending({1.0, a.pp.t1}), a.pp.tsSeconds);
            QVERIFY2(text.contains(six(d.kf)), qPrintable(six(d.kf)));
            for (const double g : d.g.ascending())
                QVERIFY2(text.contains(six(std::abs(g))), qPrintable(six(g)));
            QVERIFY(text.contains(QStringLiteral("t1 = %1").arg(six(a.pp.t1))));
            QVERIFY(text.contains(six(a.pp.b[1])));
            QVERIFY(text.contains(plain(MetricsPanel::rowTitle(MetricsPanel::Improvement))));
            QVERIFY(text.contains(displayNumber(e.improvementPct)));
        }
        // The run's and the digital implementation's figures.
        QVERIFY2(text.contains(displayNumber(e.metrics.rmse)),
                 qPrintable(displayNumber(e.metrics.rmse)));
        QVERIFY(text.contains(displayNumber(e.metrics.maxAbsError)));
        QVERIFY(e.digital);
        QVERIFY2(text.contains(displayNumber(e.digital->metrics.rmse)),
                 qPrintable(displayNumber(e.digital->metrics.rmse)));
        QVERIFY(text.contains(displayNumber(e.digital->minDamping, 3)));
        for (const std::string& w : e.warnings) // the start of each warning (lines wrap)
            QVERIFY2(text.contains(plain(QString::fromStdString(w).left(24))), w.c_str());
    }
    // Every row of the metrics panel that a point-to-point move fills, by its name.
    for (int r = 0; r < MetricsPanel::RowCount; ++r) {
        if (MetricsPanel::isGroupRow(r) || r == MetricsPanel::Improvement ||
            r == MetricsPanel::DigitalRmse || r == MetricsPanel::DigitalMaxError)
            continue; // ZPETC's row is checked above; the digital RMSE and max |e| are a column
        QVERIFY2(text.contains(plain(MetricsPanel::rowTitle(r))),
                 qPrintable(MetricsPanel::rowTitle(r)));
    }
}

void TstDesignReport::failedReportLeavesTheOldFile() {
    // A place that cannot be written: a file in a folder that does not exist. The message names
    // the path.
    const QString nowhere = dir_.filePath("no such folder/report.pdf");
    QString error;
    QVERIFY(!ReportWriter::write(Session::paperDefault(), QString(), nowhere, &error));
    QVERIFY2(error.contains(nowhere), qPrintable(error));
    QVERIFY(!QFile::exists(nowhere));
    // A session whose run is refused (dt = 1e-9 s over a 130 s move is 1.3e11 samples): no
    // report, the field named, and an existing file left as it was.
    const QString old = dir_.filePath("old.pdf");
    {
        QFile f(old);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("an older report");
    }
    Session refused = Session::paperDefault();
    refused.trajectory.dtSeconds = 1e-9;
    QVERIFY(!ReportWriter::write(refused, QString(), old, &error));
    QVERIFY2(error.contains("trajectory"), qPrintable(error));
    QFile f(old);
    QVERIFY(f.open(QIODevice::ReadOnly));
    QCOMPARE(f.readAll(), QByteArray("an older report"));
}

void TstDesignReport::commandLine() {
    const QString sessionPath = dir_.filePath("cli.json");
    QString saveError;
    QVERIFY2(files::saveSessionFile(polePlacementY(), sessionPath, &saveError),
             qPrintable(saveError));
    const auto run = [](const QStringList& args, QString& output) {
        QProcess p;
        p.start(QStringLiteral(XYT_GUI_PATH), args);
        if (!p.waitForFinished(120000))
            return -1;
        output = QString::fromUtf8(p.readAllStandardOutput() + p.readAllStandardError());
        return p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
    };
    QString output;
    const QString pdf = dir_.filePath("cli report.pdf");
    QCOMPARE(run({"--report", sessionPath, "--pdf", pdf}, output), 0);
    QVERIFY2(output.contains(pdf), qPrintable(output));
    QString text;
    QVERIFY2(pdfText(pdf, text), qPrintable(text));
    const Session s = polePlacementY();
    const GtDesign x =
        designGuilleminTruxal(s.axes[0].gt.plant, s.axes[0].gt.omegaNRadPerSec, s.axes[0].gt.kp);
    QVERIFY(text.contains(six(x.ki)));
    QVERIFY(text.contains("cli.json"));

    // A session whose plant gain is not a number: exit 2 naming its JSON path and the file.
    QJsonObject root = files::sessionToJson(Session::paperDefault());
    QJsonArray axes = root["axes"].toArray();
    QJsonObject y = axes[1].toObject();
    QJsonObject gt = y["gt"].toObject();
    QJsonObject plant = gt["plant"].toObject();
    plant["k0"] = "fast";
    gt["plant"] = plant;
    y["gt"] = gt;
    axes[1] = y;
    root["axes"] = axes;
    const QString bad = dir_.filePath("bad.json");
    {
        QFile f(bad);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(QJsonDocument(root).toJson());
    }
    QCOMPARE(run({"--report", bad, "--pdf", dir_.filePath("bad.pdf")}, output), 2);
    QVERIFY2(output.contains("axes[1].gt.plant.k0") && output.contains(bad), qPrintable(output));
    QVERIFY(!QFile::exists(dir_.filePath("bad.pdf")));
    // No --pdf, and a --pdf that cannot be written: exit 2 naming the option.
    QCOMPARE(run({"--report", sessionPath}, output), 2);
    QVERIFY2(output.contains("--pdf"), qPrintable(output));
    QCOMPARE(run({"--report", sessionPath, "--pdf", dir_.filePath("none/x.pdf")}, output), 2);
    QVERIFY2(output.contains("--pdf") && output.contains(dir_.filePath("none/x.pdf")),
             qPrintable(output));
}

void TstDesignReport::menuActionReportsTheCurrentSession() {
    TuningSession session;
    MainWindow window(&session);
    // File › Export report... is in the File menu and enabled.
    QAction* action = window.reportExporter()->action();
    QVERIFY(action);
    QVERIFY(window.menuBar()->actions().first()->menu()->actions().contains(action));
    QVERIFY(action->isEnabled());
    // A changed design: the report is of the session as it is now, never of an older state.
    session.setOmegaN(0, 3.5);
    session.setKp(1, 45.0);
    const QString pdf = dir_.filePath("menu.pdf");
    QVERIFY(window.reportExporter()->exportTo(pdf));
    QString text;
    QVERIFY2(pdfText(pdf, text), qPrintable(text));
    const Session& s = session.session();
    const GtDesign x = designGuilleminTruxal(s.axes[0].gt.plant, 3.5, s.axes[0].gt.kp);
    const GtDesign y =
        designGuilleminTruxal(s.axes[1].gt.plant, s.axes[1].gt.omegaNRadPerSec, 45.0);
    QVERIFY(text.contains(QStringLiteral("ωn = %1 rad/s").arg(six(3.5))));
    QVERIFY2(text.contains(six(x.ki)), qPrintable(six(x.ki)));
    QVERIFY(text.contains(QStringLiteral("kp = %1").arg(six(45.0))));
    QVERIFY2(text.contains(six(y.ki)), qPrintable(six(y.ki)));
    // The paper's ωn of axis x (2 rad/s) and its ki are gone.
    const GtDesign old = designGuilleminTruxal(s.axes[0].gt.plant, 2.0, s.axes[0].gt.kp);
    QVERIFY(!text.contains(six(old.ki)));
}

QTEST_MAIN(TstDesignReport)
#include "tst_design_report.moc"
