// SPDX-License-Identifier: GPL-3.0-or-later
// The identification window drives the core's identifyModel: a candidate is the
// core's result for the same file, columns and spec (computed here again), the plots draw that
// result, candidates accumulate for comparison, "Use for axis X" is one undo step, bad files
// and columns show the core's message instead of a plot, and a fit can be cancelled.
// Reference data: Patrick, Ishak and Adnan's x-axis ARX(2,3,1) model A = 1 - 1.6580 z^-1 + 0.6583
// z^-2, B = 0.0421 z^-2 + 0.0628 z^-3 - 0.0454 z^-4 (with its z^-1 delay), Ts = 0.07 s, driven by a
// +-2 V random binary input with a fixed seed: noise-free, so ARX recovers it exactly.
#include "core/identification/experiment_data.h"
#include "core/identification/experiment_file.h"
#include "core/identification/preprocessing.h"
#include "core/identification/spectral_estimate.h"
#include "core/session/identified_axis.h"
#include "tests/support/gui_checks.h"
#include "tests/support/identification_data.h"
#include "tests/support/tolerance.h"
#include "ui/identification_window.h"
#include "ui/main_window.h"
#include "ui/session/tuning_session.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QPushButton>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTabWidget>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTextStream>
#include <QUndoStack>

#include <qcustomplot.h>

#include <map>
#include <memory>

using namespace xyt;
using namespace xyt::ui;
using xyt::test::near;

namespace {

constexpr int kTimeoutMs = 120000;
const std::vector<double> kA{1.0, -1.6580, 0.6583};
const std::vector<double> kB{0.0, 0.0421, 0.0628, -0.0454};
constexpr double kTs = 0.07;

/// t, u, y of Patrick, Ishak and Adnan's model driven by a +-2 V random binary input; @p badCell
/// puts a word in row 10's y; @p noiseMm adds a +-noiseMm random binary sequence to y; the time
/// column steps by @p ts.
QString writeRecord(const QString& dir, const QString& name, std::size_t n, std::uint64_t seed,
                    bool badCell = false, const QString& header = "t,u,y", double noiseMm = 0.0,
                    double ts = kTs) {
    const std::vector<double> u = test::randomBinary(n, 2.0, seed);
    std::vector<double> y = filterDifferenceEquation(kB, kA, u);
    if (noiseMm > 0.0) {
        const std::vector<double> e = test::randomBinary(n, noiseMm, seed + 1);
        for (std::size_t k = 0; k < n; ++k)
            y[k] += e[k];
    }
    const QString path = dir + "/" + name;
    QFile f(path);
    f.open(QIODevice::WriteOnly | QIODevice::Text);
    QTextStream out(&f);
    out << header << "\n";
    for (std::size_t k = 0; k < n; ++k) {
        out << QString::number(static_cast<double>(k) * ts, 'g', 17) << ","
            << QString::number(u[k], 'g', 17) << ",";
        if (badCell && k == 10)
            out << "abc\n";
        else
            out << QString::number(y[k], 'g', 17) << "\n";
    }
    return path;
}

/// The record the window makes of @p path with columns u, y and time t.
IoData coreRecord(const QString& path) {
    ExperimentColumns c;
    c.input = "u";
    c.output = "y";
    c.time = "t";
    return experimentData(readExperimentTable(path.toStdString(), 1), c);
}

/// The "name = value ± sd" entries of the window's parameter line, by name.
std::map<QString, std::pair<double, double>> shownParameters(QString text) {
    text.replace(QChar(0x00A0), ' ');
    std::map<QString, std::pair<double, double>> out;
    static const QRegularExpression entry(QStringLiteral("(\\w+) = (\\S+) ± (\\S+)"));
    for (auto it = entry.globalMatch(text); it.hasNext();) {
        const auto m = it.next();
        out[m.captured(1)] = {m.captured(2).toDouble(), m.captured(3).toDouble()};
    }
    return out;
}

/// The window shows each of @p expected's parameters and standard deviations, to the digits
/// it prints (6 for the value, 3 for the deviation).
void compareShownParameters(const QString& text, const IdentifiedModel& expected) {
    const auto shown = shownParameters(text);
    QCOMPARE(shown.size(), expected.parameters.size());
    for (std::size_t i = 0; i < expected.parameters.size(); ++i) {
        const QString name = QString::fromStdString(expected.parameterNames[i]);
        QVERIFY2(shown.count(name), qPrintable(name + " in " + text));
        const auto [value, sd] = shown.at(name);
        QVERIFY2(near(value, expected.parameters[i], 1e-5, 0.0), qPrintable(name + ": " + text));
        QVERIFY2(near(sd, expected.standardDeviations[i], 6e-3, 0.0),
                 qPrintable(name + " sd: " + text));
    }
}

} // namespace

class TstIdentificationWindow : public QObject {
    Q_OBJECT
private slots:
    void init();
    void cleanup();
    void frequencyResponseGoesToTheAxis();
    void arxCandidateIsTheCoresModel();
    void secondCandidateAddsARow();
    void useForAxisIsOneUndoStep();
    void badInputShowsTheCoresMessage();
    void cancelLeavesTheWindowUsable();
    void sampleTimeWithoutATimeColumn();
    void validationFileIsJudged();
    void continuousFitFromTheExampleLog();
    void designMenuOpensOneWindow();
    void destroyedWhileFitting();
    void preprocessingReachesTheCore();
    void parametersShownWithTheirDeviations();
    void secondFileReplacesTheFirst();
    void fileNewClearsTheUndoStepMessage();

private:
    void pickColumns();
    bool fitAndWait();
    std::unique_ptr<QTemporaryDir> dir_;
    std::unique_ptr<TuningSession> session_;
    std::unique_ptr<IdentificationWindow> window_;
    QString path_;
};

void TstIdentificationWindow::init() {
    dir_ = std::make_unique<QTemporaryDir>();
    QVERIFY(dir_->isValid());
    path_ = writeRecord(dir_->path(), "x_axis_arx.csv", 600, 20261123);
    session_ = std::make_unique<TuningSession>();
    window_ = std::make_unique<IdentificationWindow>(session_.get());
    window_->resize(1300, 750);
    window_->show();
    QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
}

void TstIdentificationWindow::cleanup() {
    window_.reset();
    session_.reset();
    dir_.reset();
}

// The record's Welch estimate reaches the workbench as the chosen axis' measured response, on
// the one-sided grid k / (M Ts) up to the Nyquist frequency 1 / (2 Ts) (M the segment length it
// reports); without a record the window refuses and says why.
void TstIdentificationWindow::frequencyResponseGoesToTheAxis() {
    QVERIFY(!window_->showFrequencyResponse(0));
    QVERIFY(window_->statusText().contains(QStringLiteral("load a record first")));
    QVERIFY(window_->loadFile(path_));
    pickColumns();
    QTest::mouseClick(window_->frequencyResponseButton(1), Qt::LeftButton);
    QVERIFY(!session_->measuredResponse(0));
    const auto& measured = session_->measuredResponse(1);
    QVERIFY(measured);
    const FrequencyResponseEstimate& e = measured->estimate;
    const double ts = window_->sampleTimeBox()->value();
    const double m = static_cast<double>(e.segments.segmentLength);
    QVERIFY(e.segments.count >= 2);
    QCOMPARE(e.frequencyHz.size(), e.segments.segmentLength / 2 + 1);
    QVERIFY(std::abs(e.frequencyHz[1] - 1.0 / (m * ts)) < 1e-12 / ts);
    QVERIFY(std::abs(e.frequencyHz.back() - 0.5 / ts) < 1e-12 / ts);
    QVERIFY(window_->statusText().contains(QStringLiteral("Vibration view of axis Y")));
}

void TstIdentificationWindow::pickColumns() {
    QCOMPARE(window_->inputBox()->currentText(), QString("u")); // not LVM's X_Value
    QCOMPARE(window_->outputBox()->currentText(), QString("y"));
    window_->timeBox()->setCurrentText("t");
}

bool TstIdentificationWindow::fitAndWait() {
    QSignalSpy finished(window_.get(), &IdentificationWindow::fitFinished);
    QTest::mouseClick(window_->fitButton(), Qt::LeftButton);
    return finished.count() > 0 || finished.wait(kTimeoutMs);
}

void TstIdentificationWindow::arxCandidateIsTheCoresModel() {
    QVERIFY(window_->loadFile(path_));
    QCOMPARE(window_->fileLabel()->text(), QString("x_axis_arx.csv"));
    QCOMPARE(window_->inputBox()->count(), 3);
    QCOMPARE(window_->timeBox()->itemText(0), QString("(sample time)"));
    QCOMPARE(window_->timeBox()->currentText(), QString("t")); // guessed from the name
    pickColumns();
    QCOMPARE(window_->structureBox()->currentText(), QString("ARX"));
    QCOMPARE(window_->orderBox("na")->value(), 2);
    QCOMPARE(window_->orderBox("nb")->value(), 3);
    QCOMPARE(window_->orderBox("nk")->value(), 1);
    QVERIFY(!window_->orderBox("nf")->isEnabled());
    QVERIFY(fitAndWait());
    QCOMPARE(window_->candidateTable()->rowCount(), 1);
    const auto* c = window_->selectedCandidate();
    QVERIFY2(c, qPrintable(window_->statusText()));

    IdentificationSpec spec;
    spec.arx = {2, 3, 1};
    const IoData data = coreRecord(path_);
    const IdentifiedModel expected = identifyModel(data, nullptr, spec);
    QCOMPARE(c->model.structure, std::string("ARX(2,3,1)"));
    QCOMPARE(c->model.parameters.size(), expected.parameters.size());
    for (std::size_t i = 0; i < expected.parameters.size(); ++i)
        QVERIFY(near(c->model.parameters[i], expected.parameters[i], 0.0, 1e-9));
    // Noise-free data: the estimate is Patrick, Ishak and Adnan's model.
    QCOMPARE(c->model.model.a.size(), kA.size());
    for (std::size_t i = 0; i < kA.size(); ++i)
        QVERIFY2(near(c->model.model.a[i], kA[i], 0.0, 1e-9),
                 qPrintable(QString::number(c->model.model.a[i])));
    for (std::size_t i = 0; i < kB.size(); ++i)
        QVERIFY2(near(c->model.model.b[i], kB[i], 0.0, 1e-9),
                 qPrintable(QString::number(c->model.model.b[i])));

    // The plots draw the candidate.
    const std::vector<double>& yhat = expected.fit.estimationSimulation.yhat;
    auto sim = window_->simulatedGraph()->data();
    QCOMPARE(sim->size(), static_cast<int>(yhat.size()));
    int k = 0;
    for (auto it = sim->constBegin(); it != sim->constEnd(); ++it, ++k) {
        QVERIFY(near(it->value, yhat[static_cast<std::size_t>(k)], 0.0, 1e-9));
        QVERIFY(near(it->key, data.startSeconds + k * data.tsSeconds, 1e-12, 1e-12));
    }
    QCOMPARE(window_->measuredGraph()->data()->size(), static_cast<int>(data.size()));
    QCOMPARE(window_->autocorrelationGraph()->data()->size(),
             static_cast<int>(expected.residualTests.autocorrelation.values.size()));
    QCOMPARE(window_->crossCorrelationGraph()->data()->size(),
             static_cast<int>(expected.residualTests.crossCorrelation.values.size()));
    QCOMPARE(window_->polesGraph()->data()->size(), static_cast<int>(expected.roots.poles.size()));
    QCOMPARE(window_->zerosGraph()->data()->size(), static_cast<int>(expected.roots.zeros.size()));
    QCOMPARE(window_->candidateTable()->item(0, 0)->text(), QString("ARX(2,3,1)"));
    QCOMPARE(window_->candidateTable()->item(0, 6)->text(),
             expected.roots.nonMinimumPhase ? QString("yes") : QString("no"));

    if (qEnvironmentVariableIsSet("XYT_SCREENSHOT_DIR")) { // to look at it (not an assertion)
        for (int tab = 0; tab < window_->plotTabs()->count(); ++tab) {
            window_->plotTabs()->setCurrentIndex(tab);
            QTest::qWait(50);
            window_->grab().save(qEnvironmentVariable("XYT_SCREENSHOT_DIR") +
                                 QStringLiteral("/identification_%1.png").arg(tab));
        }
        window_->plotTabs()->setCurrentIndex(0);
    }
}

void TstIdentificationWindow::secondCandidateAddsARow() {
    QVERIFY(window_->loadFile(path_));
    pickColumns();
    QVERIFY(fitAndWait());
    window_->structureBox()->setCurrentText("OE");
    QVERIFY(!window_->orderBox("na")->isEnabled());
    QVERIFY(window_->orderBox("nf")->isEnabled());
    window_->orderBox("nb")->setValue(3);
    window_->orderBox("nf")->setValue(2);
    window_->orderBox("nk")->setValue(1);
    QVERIFY(fitAndWait());
    QCOMPARE(window_->candidateTable()->rowCount(), 2);
    QCOMPARE(window_->candidates().size(), std::size_t(2));
    QCOMPARE(window_->selectedCandidate()->model.structure, std::string("OE(3,2,1)"));
    // Selecting the first row shows the first candidate again.
    window_->candidateTable()->selectRow(0);
    QCOMPARE(window_->selectedCandidate()->model.structure, std::string("ARX(2,3,1)"));
    QCOMPARE(window_->simulatedGraph()->data()->size(),
             static_cast<int>(window_->candidates()[0].model.fit.estimationSimulation.yhat.size()));
}

void TstIdentificationWindow::useForAxisIsOneUndoStep() {
    QVERIFY(window_->loadFile(path_));
    pickColumns();
    QVERIFY(fitAndWait());
    const auto* c = window_->selectedCandidate();
    QVERIFY(c);
    const Session before = session_->session();
    const int steps = session_->undoStack()->count();
    QTest::mouseClick(window_->useXButton(), Qt::LeftButton);
    const AxisSettings& x = session_->session().axes[0];
    const AxisSettings expected = axisWithIdentifiedModel(before.axes[0], c->model, c->estimation);
    QVERIFY(x == expected);
    QCOMPARE(x.pp.a, c->model.model.a);
    QCOMPARE(x.pp.b, c->model.model.b);
    QVERIFY(x.origin);
    QCOMPARE(x.origin->structure, std::string("ARX(2,3,1)"));
    QVERIFY(session_->session().axes[1] == before.axes[1]);
    QCOMPARE(session_->undoStack()->count(), steps + 1);
    QVERIFY(session_->undoStack()->undoText().contains("ARX(2,3,1)"));
    session_->undoStack()->undo();
    QVERIFY(session_->session().axes[0] == before.axes[0]);
}

void TstIdentificationWindow::badInputShowsTheCoresMessage() {
    // A validation file without the estimation file's columns: the core names the column.
    const QString other = writeRecord(dir_->path(), "other.csv", 200, 7, false, "time,cmd,pos");
    QVERIFY(window_->loadFile(path_));
    pickColumns();
    QVERIFY(fitAndWait());
    QVERIFY(window_->selectedCandidate());
    QVERIFY(window_->loadValidationFile(other));
    QVERIFY(fitAndWait());
    QVERIFY2(window_->statusText().contains("'u'") || window_->statusText().contains("u"),
             qPrintable(window_->statusText()));
    QVERIFY2(window_->statusText().contains("other.csv"), qPrintable(window_->statusText()));
    QVERIFY(window_->statusText().startsWith("Cannot fit"));
    QVERIFY(!window_->selectedCandidate()); // no stale plot
    QVERIFY(window_->simulatedGraph()->data()->isEmpty());
    QCOMPARE(window_->candidateTable()->rowCount(), 1);
    QVERIFY(window_->loadValidationFile(QString()));

    // A non-numeric cell in the output column: the core names file, line and column.
    const QString bad = writeRecord(dir_->path(), "bad.csv", 100, 3, true);
    if (window_->loadFile(bad)) { // the reader keeps the cell; the record refuses it
        pickColumns();
        QVERIFY(fitAndWait());
    }
    QVERIFY2(window_->statusText().contains("bad.csv") && window_->statusText().contains("12") &&
                 window_->statusText().contains("abc"),
             qPrintable(window_->statusText()));
    QVERIFY(!window_->selectedCandidate());
    QVERIFY(window_->measuredGraph()->data()->isEmpty());
    if (qEnvironmentVariableIsSet("XYT_SCREENSHOT_DIR")) { // to look at it (not an assertion)
        QTest::qWait(50);
        window_->grab().save(qEnvironmentVariable("XYT_SCREENSHOT_DIR") +
                             "/identification_error.png");
    }

    // A file that does not exist.
    QVERIFY(!window_->loadFile(dir_->path() + "/missing.csv"));
    QVERIFY2(window_->statusText().contains("missing.csv"), qPrintable(window_->statusText()));
    QVERIFY(!window_->fitButton()->isEnabled());

    // Too few samples for the orders.
    const QString tiny = writeRecord(dir_->path(), "tiny.csv", 4, 5);
    QVERIFY(window_->loadFile(tiny));
    pickColumns();
    QVERIFY(fitAndWait());
    QVERIFY2(window_->statusText().contains("samples") ||
                 window_->statusText().contains("tiny.csv"),
             qPrintable(window_->statusText()));
    QVERIFY(!window_->selectedCandidate());
}

void TstIdentificationWindow::cancelLeavesTheWindowUsable() {
    QVERIFY(window_->loadFile(writeRecord(dir_->path(), "long.csv", 20000, 11)));
    pickColumns();
    window_->structureBox()->setCurrentText("BJ");
    window_->maxIterationsBox()->setValue(100000);
    QSignalSpy finished(window_.get(), &IdentificationWindow::fitFinished);
    QTest::mouseClick(window_->fitButton(), Qt::LeftButton);
    QVERIFY(window_->isRunning());
    QVERIFY(window_->cancelButton()->isEnabled());
    QTest::mouseClick(window_->cancelButton(), Qt::LeftButton);
    QVERIFY(finished.wait(kTimeoutMs));
    QVERIFY(!window_->isRunning());
    QVERIFY(window_->fitButton()->isEnabled());
    QVERIFY(!window_->cancelButton()->isEnabled());
    // Usable: an ARX fit runs next.
    window_->structureBox()->setCurrentText("ARX");
    const std::size_t before = window_->candidates().size();
    QVERIFY(fitAndWait());
    QCOMPARE(window_->candidates().size(), before + 1);
    QCOMPARE(window_->selectedCandidate()->model.structure, std::string("ARX(2,3,1)"));
}

void TstIdentificationWindow::sampleTimeWithoutATimeColumn() {
    // Only u and y: the time choice stays "(sample time)" and the Ts box gives the sample time.
    const QString path = dir_->path() + "/no_time.csv";
    {
        QFile in(path_), out(path);
        QVERIFY(in.open(QIODevice::ReadOnly | QIODevice::Text) &&
                out.open(QIODevice::WriteOnly | QIODevice::Text));
        while (!in.atEnd()) {
            const QList<QByteArray> fields = in.readLine().trimmed().split(',');
            out.write(fields[1] + "," + fields[2] + "\n");
        }
    }
    QVERIFY(window_->loadFile(path));
    QCOMPARE(window_->timeBox()->currentIndex(), 0);
    QVERIFY(window_->sampleTimeBox()->isEnabled());
    window_->sampleTimeBox()->setValue(kTs);
    QVERIFY(fitAndWait());
    const auto* c = window_->selectedCandidate();
    QVERIFY2(c, qPrintable(window_->statusText()));
    QVERIFY(near(c->estimation.tsSeconds, kTs, 1e-12));
    QVERIFY(near(c->model.model.tsSeconds, kTs, 1e-12));
    for (std::size_t i = 0; i < kA.size(); ++i)
        QVERIFY(near(c->model.model.a[i], kA[i], 0.0, 1e-9));
}

void TstIdentificationWindow::validationFileIsJudged() {
    const QString validation = writeRecord(dir_->path(), "validation.csv", 300, 99);
    QVERIFY(window_->loadFile(path_));
    pickColumns();
    QVERIFY(window_->loadValidationFile(validation));
    QVERIFY(fitAndWait());
    const auto* c = window_->selectedCandidate();
    QVERIFY2(c && c->validation, qPrintable(window_->statusText()));
    IdentificationSpec spec;
    const IoData v = coreRecord(validation);
    const IdentifiedModel expected = identifyModel(coreRecord(path_), &v, spec);
    QVERIFY(expected.fit.validationSimulation);
    QCOMPARE(window_->candidateTable()->item(0, 3)->text(),
             QString::number(expected.fit.validationSimulation->fitPercent, 'f', 2));
}

void TstIdentificationWindow::continuousFitFromTheExampleLog() {
    // The repository's synthetic lower-base log (.lvm, Ts stated by the file): the GT3 fit is
    // identifyModel's on the record with its first sample taken off, as xytune-cli identify does.
    const QString path =
        QStringLiteral(XYT_SOURCE_DIR "/resources/examples/synthetic_lower_base_square_10ms.lvm");
    QVERIFY2(window_->loadFile(path), qPrintable(window_->statusText()));
    QCOMPARE(window_->timeBox()->currentIndex(), 0); // the file's sample time
    QVERIFY(window_->sampleTimeBox()->value() > 0.0);
    window_->inputBox()->setCurrentText("u");
    window_->outputBox()->setCurrentText("y");
    window_->structureBox()->setCurrentText("GT3 continuous");
    for (const char* name : {"na", "nb", "nc", "nd", "nf", "nk"})
        QVERIFY(!window_->orderBox(name)->isEnabled());
    QVERIFY(fitAndWait());
    const auto* c = window_->selectedCandidate();
    QVERIFY2(c && c->model.plant, qPrintable(window_->statusText()));
    QVERIFY(c->notes.join(' ').contains("subtracted"));
    QVERIFY(near(c->estimation.y.front(), 0.0, 0.0, 1e-15));
    IdentificationSpec spec;
    spec.structure = ModelStructure::ContinuousThirdOrder;
    const IdentifiedModel expected = identifyModel(c->estimation, nullptr, spec);
    QVERIFY(expected.plant);
    QVERIFY(near(c->model.plant->k0, expected.plant->k0, 1e-12));
    QVERIFY(near(c->model.plant->a1, expected.plant->a1, 1e-12));
    QVERIFY(near(c->model.plant->a2, expected.plant->a2, 1e-12));
    // The plant's pole at z = 1 is an integrator, not an instability (before: "the model is
    // unstable").
    QVERIFY(c->model.roots.integrating);
    QVERIFY2(window_->poleZeroNoticeText().contains("integrates"),
             qPrintable(window_->poleZeroNoticeText()));
    QVERIFY(!window_->poleZeroNoticeText().contains("the model is unstable"));
    // k0, a1 and a2 with their standard deviations are shown for the selected candidate.
    compareShownParameters(window_->parametersText(), expected);
    QVERIFY2(window_->parametersText().contains("mm/(V·s³)"),
             qPrintable(window_->parametersText()));
    if (qEnvironmentVariableIsSet("XYT_SCREENSHOT_DIR")) { // to look at it (not an assertion)
        QTest::qWait(50);
        window_->grab().save(qEnvironmentVariable("XYT_SCREENSHOT_DIR") +
                             "/identification_gt3.png");
    }
}

void TstIdentificationWindow::designMenuOpensOneWindow() {
    MainWindow main(session_.get());
    main.show();
    QAction* action = test::findMenuAction(main.menuBar(), "Design/Identify from data...");
    QVERIFY(action);
    action->trigger();
    action->trigger();
    const auto windows = main.findChildren<IdentificationWindow*>();
    QCOMPARE(windows.size(), 1);
    QVERIFY(windows.front()->isVisible());
}

void TstIdentificationWindow::destroyedWhileFitting() {
    // Closing the workbench during a long fit: the window stops and joins its worker, and the
    // worker's queued progress reports die with it (ASan/UBSan builds would see a stray one).
    QVERIFY(window_->loadFile(writeRecord(dir_->path(), "long.csv", 20000, 13)));
    pickColumns();
    window_->structureBox()->setCurrentText("BJ");
    window_->maxIterationsBox()->setValue(100000);
    QTest::mouseClick(window_->fitButton(), Qt::LeftButton);
    QVERIFY(window_->isRunning());
    QTest::qWait(20);
    window_.reset();
    QTest::qWait(20); // queued reports, if any, are discarded with their receiver
    QCOMPARE(session_->undoStack()->count(), 0);
}

void TstIdentificationWindow::preprocessingReachesTheCore() {
    // The range, detrend and decimate boxes in a non-default state: the candidate is the core's
    // identifyModel on selectTimeRange, removeTrends and decimate of the same record (the same
    // calls in the same order, so the same bits; 1e-9 relative allows a different summation
    // order on the worker thread), and the output plot draws the preprocessed record.
    QVERIFY(window_->loadFile(path_));
    pickColumns();
    window_->rangeStartBox()->setValue(7.0);
    window_->rangeEndBox()->setValue(35.0);
    window_->detrendBox()->setChecked(true);
    window_->decimateBox()->setValue(2);
    QVERIFY(fitAndWait());
    const auto* c = window_->selectedCandidate();
    QVERIFY2(c, qPrintable(window_->statusText()));
    const IoData data =
        decimate(removeTrends(selectTimeRange(coreRecord(path_), 7.0, 35.0)).data, 2);
    QVERIFY(near(data.tsSeconds, 2 * kTs, 1e-12, 0.0));
    IdentificationSpec spec;
    spec.arx = {2, 3, 1};
    const IdentifiedModel expected = identifyModel(data, nullptr, spec);
    QCOMPARE(c->model.parameters.size(), expected.parameters.size());
    for (std::size_t i = 0; i < expected.parameters.size(); ++i)
        QVERIFY(near(c->model.parameters[i], expected.parameters[i], 1e-9, 1e-12));
    QVERIFY(near(c->model.model.tsSeconds, 2 * kTs, 1e-12, 0.0));
    QCOMPARE(window_->measuredGraph()->data()->size(), static_cast<int>(data.size()));
    QVERIFY(
        near(window_->measuredGraph()->data()->constBegin()->key, data.startSeconds, 1e-12, 1e-12));
    QVERIFY(data.startSeconds >= 7.0 - 1e-9);

    // A range that ends before it starts is refused, naming the field; no stale candidate.
    window_->rangeStartBox()->setValue(30.0);
    window_->rangeEndBox()->setValue(10.0);
    QVERIFY(fitAndWait());
    QVERIFY2(window_->statusText().contains("range"), qPrintable(window_->statusText()));
    QVERIFY(!window_->selectedCandidate());
    QCOMPARE(window_->candidateTable()->rowCount(), 1);
}

void TstIdentificationWindow::parametersShownWithTheirDeviations() {
    // The estimate and its standard deviations were shown only once "Use for axis" had taken
    // it. Noisy data (+-0.05 mm) give deviations well above rounding; the expected values are
    // identifyModel's on the same record.
    const QString path = writeRecord(dir_->path(), "noisy.csv", 600, 4242, false, "t,u,y", 0.05);
    QVERIFY(window_->loadFile(path));
    pickColumns();
    QVERIFY(window_->parametersText().isEmpty()); // nothing selected yet
    QVERIFY(fitAndWait());
    QVERIFY2(window_->selectedCandidate(), qPrintable(window_->statusText()));
    IdentificationSpec spec;
    spec.arx = {2, 3, 1};
    const IdentifiedModel expected = identifyModel(coreRecord(path), nullptr, spec);
    QCOMPARE(expected.parameterNames.size(), std::size_t(5)); // a1 a2 b1 b2 b3
    for (double sd : expected.standardDeviations)
        QVERIFY(sd > 1e-6);
    compareShownParameters(window_->parametersText(), expected);
    QVERIFY(window_->findChild<QLabel*>("identificationParameters")->isVisible());
    // The second candidate's own parameters follow its row.
    window_->structureBox()->setCurrentText("OE");
    QVERIFY(fitAndWait());
    spec.structure = ModelStructure::Oe;
    spec.oe = {3, 2, 1};
    const IdentifiedModel oe = identifyModel(coreRecord(path), nullptr, spec);
    compareShownParameters(window_->parametersText(), oe);
    window_->candidateTable()->selectRow(0);
    compareShownParameters(window_->parametersText(), expected);
}

void TstIdentificationWindow::secondFileReplacesTheFirst() {
    // A 10 ms record, then a 70 ms one: the first file's candidates were kept without saying
    // which file they came from, Ts still read 10 ms, the record was not drawn before a fit and
    // the range read "0.0000 s to 0.0000 s".
    const QString fast =
        writeRecord(dir_->path(), "fast_10ms.csv", 500, 31, false, "t,u,y", 0.0, 0.01);
    const QString slow =
        writeRecord(dir_->path(), "slow_70ms.csv", 300, 32, false, "t,u,y", 0.0, 0.07);
    QVERIFY(window_->loadFile(fast));
    QVERIFY(near(window_->sampleTimeBox()->value(), 0.01, 1e-12, 0.0));
    QVERIFY(fitAndWait());
    QCOMPARE(window_->candidateTable()->rowCount(), 1);

    QVERIFY(window_->loadFile(slow));
    QCOMPARE(window_->candidateTable()->rowCount(), 0);
    QVERIFY(window_->candidates().empty());
    QVERIFY(!window_->selectedCandidate());
    QVERIFY2(window_->statusText().contains("cleared"), qPrintable(window_->statusText()));
    QVERIFY(window_->parametersText().isEmpty());
    // The time column's sample time and range: Ts = 0.07 s, t from 0 to 299 * 0.07 = 20.93 s.
    QVERIFY(near(window_->sampleTimeBox()->value(), 0.07, 1e-12, 0.0));
    QVERIFY(near(window_->rangeStartBox()->value(), 0.0, 0.0, 1e-12));
    QVERIFY(near(window_->rangeEndBox()->value(), 20.93, 0.0, 1e-9));
    // The record is drawn before any fit: 300 samples from 0 to 20.93 s.
    const auto measured = window_->measuredGraph()->data();
    QCOMPARE(measured->size(), 300);
    QVERIFY(near(measured->constBegin()->key, 0.0, 0.0, 1e-12));
    QVERIFY(near((measured->constEnd() - 1)->key, 20.93, 0.0, 1e-9));
    QVERIFY(window_->simulatedGraph()->data()->isEmpty());
    if (qEnvironmentVariableIsSet("XYT_SCREENSHOT_DIR")) { // to look at it (not an assertion)
        QTest::qWait(50);
        window_->grab().save(qEnvironmentVariable("XYT_SCREENSHOT_DIR") +
                             "/identification_loaded.png");
    }

    // A fit on the shown range uses the whole record (the rounded range cuts nothing off).
    QVERIFY(fitAndWait());
    const auto* c = window_->selectedCandidate();
    QVERIFY2(c, qPrintable(window_->statusText()));
    QCOMPARE(c->estimation.size(), std::size_t(300));
    QVERIFY(near(c->estimation.tsSeconds, 0.07, 1e-12, 0.0));
    window_->structureBox()->setCurrentText("OE");
    QVERIFY(fitAndWait());
    QCOMPARE(window_->candidateTable()->rowCount(), 2);

    // The message area follows the selected row.
    window_->candidateTable()->selectRow(0);
    QCOMPARE(window_->statusText(), window_->candidates()[0].message);
    QVERIFY(window_->statusText().startsWith("ARX(2,3,1)"));
    window_->candidateTable()->selectRow(1);
    QCOMPARE(window_->statusText(), window_->candidates()[1].message);
    QVERIFY(window_->statusText().startsWith("OE(3,2,1)"));
}

void TstIdentificationWindow::fileNewClearsTheUndoStepMessage() {
    // "Axis X now uses ... (Edit › Undo restores the previous plant)" stayed after File › New
    // although the new session has no such undo step.
    MainWindow main(session_.get());
    main.show();
    QVERIFY(window_->loadFile(path_));
    pickColumns();
    QVERIFY(fitAndWait());
    QTest::mouseClick(window_->useXButton(), Qt::LeftButton);
    QVERIFY2(window_->statusText().contains("Undo"), qPrintable(window_->statusText()));
    QAction* fileNew = test::findMenuAction(main.menuBar(), "File/New");
    QVERIFY(fileNew);
    {
        test::DialogAnswerer answer(test::DialogAnswerer::Mode::Accept, [](QWidget* dialog) {
            auto* box = qobject_cast<QMessageBox*>(dialog);
            QVERIFY(box);
            box->setDefaultButton(qobject_cast<QPushButton*>(box->button(QMessageBox::Discard)));
        });
        fileNew->trigger();
        QCOMPARE(answer.answered(), 1);
    }
    QCOMPARE(session_->undoStack()->count(), 0);
    QVERIFY2(!window_->statusText().contains("Undo"), qPrintable(window_->statusText()));
    QVERIFY2(!window_->statusText().contains("now uses"), qPrintable(window_->statusText()));
    // The selected candidate's report instead.
    QCOMPARE(window_->statusText(), window_->selectedCandidate()->message);

    // Edit › Undo of the step: its message goes too.
    QTest::mouseClick(window_->useYButton(), Qt::LeftButton);
    QVERIFY(window_->statusText().contains("Axis Y now uses"));
    session_->undoStack()->undo();
    QCOMPARE(window_->statusText(), window_->selectedCandidate()->message);
}

QTEST_MAIN(TstIdentificationWindow)
#include "tst_identification_window.moc"
