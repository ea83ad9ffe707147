// SPDX-License-Identifier: GPL-3.0-or-later
// A design method of this test's own, registered at start-up: a pure proportional controller
// u = kp e on the axis' continuous third-order plant, with its settings in the session's
// parameter block. With no change outside this file, it runs through every view of the
// workbench, every export (session file, coefficient JSON, firmware C, Octave script, CSV) and
// `xytune-cli report`: what adding a design method takes is its module, its parameters (the
// workbench's parameter editor edits them) and one registration.
#include "app/cli_command_line.h"
#include "core/analysis/loop_responses.h"
#include "core/model/number_format.h"
#include "core/session/axis_frequency.h"
#include "core/session/axis_run.h"
#include "core/session/c_export.h"
#include "core/session/continuous_plant_method.h"
#include "core/session/design_method_module.h"
#include "core/session/export_text.h"
#include "core/session/robustness_problem.h"
#include "core/simulation/move_settle.h"
#include "core/simulation/sampled_data.h"
#include "core/simulation/step_response.h"
#include "core/simulation/trajectory.h"
#include "tests/support/ballbar_program.h"
#include "tests/support/built_programs.h"
#include "tests/support/gui_checks.h"
#include "ui/design_space_view.h"
#include "ui/files/coefficient_json.h"
#include "ui/files/session_file.h"
#include "ui/main_window.h"
#include "ui/panels/equations_panel.h"
#include "ui/panels/method_editor.h"
#include "ui/panels/method_parameter_editor.h"
#include "ui/panels/number_field.h"
#include "ui/robustness_view.h"
#include "ui/session/session_file_controller.h"
#include "ui/session/tuning_session.h"
#include "ui/snapshot_compare_dialog.h"

#include <QDoubleSpinBox>
#include <QJsonArray>
#include <QJsonDocument>
#include <QProcess>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QTemporaryFile>
#include <QTest>
#include <QUndoStack>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <unistd.h>

using namespace xyt;
using namespace xyt::ui;
using namespace xyt::files;

namespace {

constexpr DesignMethod kProportional = static_cast<DesignMethod>(41);

/// The proportional design: the gain and the loop it closes around the plant.
struct ProportionalDesign : MethodDesign {
    double kp = 0.0;
    TransferFunction plant;
    TransferFunction controller; ///< kp
    LoopTransferFunctions loop;
};

const ProportionalDesign& designOf(const AxisEvaluation& axis) {
    const auto* d = dynamic_cast<const ProportionalDesign*>(axis.methodDesign.get());
    if (!d)
        throw InvalidInput("axis", "has no design");
    return *d;
}

MethodParameter gainParameter() {
    return {"kp", "Proportional gain kp", "V/model unit", 30.0, 1e-6, 1e6};
}

/// u = kp e, e = (r - y) in model units, |u| <= umax: the continuous loop, and the same gain
/// sampled at the session's controller period (a PI with no integral action). Its contour run,
/// plant parameters and robustness problem are those of every continuous controller on the
/// third-order plant (ContinuousPlantMethod).
class ProportionalMethod final : public ContinuousPlantMethod {
public:
    DesignMethod method() const override { return kProportional; }
    std::string_view id() const override { return "proportional"; }
    std::string_view displayName() const override { return "proportional control"; }
    std::vector<MethodParameter> parameters() const override { return {gainParameter()}; }

    void evaluate(const Session& session, int axisIndex, double durationSeconds, bool withDigital,
                  AxisEvaluation& out) const override {
        const AxisSettings& axis = session.axes.at(static_cast<std::size_t>(axisIndex));
        auto design = std::make_shared<ProportionalDesign>();
        design->kp = methodParameterValue(axis, axisIndex, gainParameter());
        design->plant = axis.gt.plant.transferFunction();
        design->controller =
            TransferFunction(Polynomial::constant(design->kp), Polynomial::constant(1.0));
        design->loop = unityFeedbackLoop(design->controller, design->plant);
        out.methodDesign = design;
        LoopSimulationOptions options;
        options.dtSeconds = session.trajectory.dtSeconds;
        options.umaxVolts = session.umaxVolts;
        options.modelUnitsPerPositionUnit = axis.gt.modelUnitsPerPositionUnit;
        const auto reference = sessionReference(session.trajectory, axisIndex);
        const auto times = axisSampleTimes(session.trajectory, durationSeconds, options.dtSeconds,
                                           "trajectory.dt");
        out.run =
            simulateLoop(design->plant, design->controller, sampled(reference, times), options);
        out.metrics = trackingMetrics(out.run);
        out.step = stepCharacteristics(design->loop.complementarySensitivity);
        if (!withDigital)
            return;
        DigitalEvaluation d;
        DigitalPi p; // a proportional controller: no integral, no notch
        p.kp = design->kp;
        p.tsSeconds = session.controllerTsSeconds;
        p.antiWindup = AntiWindup::None;
        d.tsSeconds = p.tsSeconds;
        d.run = simulateSampledPi(
            design->plant, p,
            sampled(reference, axisSampleTimes(session.trajectory, durationSeconds, p.tsSeconds,
                                               "controller_ts")),
            sessionSampledDataOptions(session), axis.gt.modelUnitsPerPositionUnit);
        d.poles = sampledPiLoopPoles(sampledPlant(design->plant, p.tsSeconds), p,
                                     session.implementation.delaySamples);
        const auto poles = design->loop.complementarySensitivity.poles();
        d.designMinDamping = minContinuousDamping(poles);
        for (const auto& s : poles)
            d.designPoles.push_back(std::exp(s * p.tsSeconds));
        finishDigital(session, d, out);
        out.digital = std::make_shared<const DigitalEvaluation>(std::move(d));
    }

    TransferFunction evaluatedController(const AxisEvaluation& axis) const override {
        return designOf(axis).controller;
    }
    TransferFunction designedController(const Session& session, int axisIndex) const override {
        return TransferFunction(
            Polynomial::constant(methodParameterValue(
                session.axes.at(static_cast<std::size_t>(axisIndex)), axisIndex, gainParameter())),
            Polynomial::constant(1.0));
    }

    std::string cController(const Session& session, const AxisEvaluation& axis, int axisIndex,
                            const ExportOptions& options) const override {
        const AxisSettings& settings = session.axes.at(static_cast<std::size_t>(axisIndex));
        const std::string id = settings.id, up = cexport::upper(id);
        const std::string field = cexport::axisField(axisIndex, "parameters.kp");
        std::ostringstream out;
        out << "/* Axis " << id << ": proportional control, u = KP (r - y) UNIT. */\n"
            << "static const xyt_real XYT_" << up << "_KP XYT_MAYBE_UNUSED = "
            << cexport::realNum(designOf(axis).kp, field, "XYT_" + up + "_KP", options.precision)
            << ";\nstatic const xyt_real XYT_" << up << "_UNIT XYT_MAYBE_UNUSED = "
            << cexport::realNum(settings.gt.modelUnitsPerPositionUnit,
                                cexport::axisField(axisIndex, "gt.model_unit_scale"),
                                "XYT_" + up + "_UNIT", options.precision)
            << ";\ntypedef struct { int unused; } xyt_" << id << "_state;\n"
            << "static inline XYT_MAYBE_UNUSED void xyt_" << id << "_init(xyt_" << id
            << "_state *s) { s->unused = 0; }\n"
            << "static inline XYT_MAYBE_UNUSED xyt_real xyt_" << id << "_step(xyt_" << id
            << "_state *s, xyt_real reference, xyt_real measured) {\n"
            << "    const xyt_real v = XYT_" << up << "_KP * (reference - measured) * XYT_" << up
            << "_UNIT;\n    xyt_real u;\n    (void)s;\n    " << cexport::cSaturate("u", "v")
            << "    return u;\n}\n\n";
        return out.str();
    }

    OctaveLines octaveController(const Session& session, const AxisEvaluation& axis, int axisIndex,
                                 const ExportOptions& /*options*/,
                                 double /*durationSeconds*/) const override {
        const AxisSettings& settings = session.axes.at(static_cast<std::size_t>(axisIndex));
        const std::string& id = settings.id;
        const auto& p = settings.gt.plant;
        const std::string f = cexport::axisField(axisIndex, "gt.plant");
        std::ostringstream out;
        out << "plant_" << id << " = tf(" << cexport::num(p.k0, f + ".k0") << ", [1 "
            << cexport::num(p.a1, f + ".a1") << " " << cexport::num(p.a2, f + ".a2") << " 0]);\n"
            << "controller_" << id << " = tf("
            << cexport::num(designOf(axis).kp, cexport::axisField(axisIndex, "parameters.kp"))
            << ", 1);\nclosed_loop_" << id << " = feedback(controller_" << id << " * plant_" << id
            << ", 1);\n"
            << octaveTrajectoryLines(session.trajectory, axisIndex, id) << "y_" << id
            << " = lsim(closed_loop_" << id << ", r_" << id << ", t);\n\n";
        return {out.str(), "t"};
    }

    std::optional<LoopTransferFunctions> loop(const AxisEvaluation& axis) const override {
        if (!axis.methodDesign)
            return std::nullopt;
        return designOf(axis).loop;
    }
    TransferFunction closedLoop(const AxisEvaluation& axis) const override {
        return designOf(axis).loop.complementarySensitivity;
    }
    std::vector<PoleZeroSet> poleZeroSets(const AxisEvaluation& axis,
                                          const AxisSettings& /*settings*/) const override {
        if (!axis.methodDesign)
            return {};
        return {poleZeroSet("plant G", designOf(axis).plant),
                poleZeroSet("closed loop", closedLoop(axis))};
    }
    double slowestDecayPerSecond(const AxisEvaluation& axis) const override {
        return axis.methodDesign ? continuousDecayPerSecond(closedLoop(axis).poles()) : 0.0;
    }
    std::vector<DesignCoefficient> coefficients(const AxisEvaluation& axis) const override {
        if (!axis.methodDesign)
            return {};
        return {{"kp", designOf(axis).kp, "V/model unit"}};
    }
    std::vector<Diagnostic> equations(const AxisSettings& /*settings*/,
                                      const AxisEvaluation& axis) const override {
        return {"u = kp e, kp = " + xyt::formatNumber(designOf(axis).kp) + " V/model unit"};
    }
};

/// Braga et al.'s session with axis x on proportional control, kp = 20 V per model unit.
Session proportionalSession() {
    Session s = Session::paperDefault();
    s.axes[0].method = kProportional;
    s.axes[0].parameters["kp"] = 20.0;
    return s;
}

/// The parameter editor of the proportional method in @p window (the built-in PID +
/// feedforward method has parameter editors too, on its own page), or null.
MethodParameterEditor* proportionalEditor(QWidget* window) {
    for (auto* e : window->findChildren<MethodParameterEditor*>())
        if (e->field("kp"))
            return e;
    return nullptr;
}

/// What @p command prints on stdout, run in this process; @p exitCode its exit code.
QByteArray runCli(const QStringList& command, int* exitCode) {
    std::fflush(stdout);
    QTemporaryFile capture;
    if (!capture.open())
        qFatal("no temporary file");
    const int saved = ::dup(1);
    ::dup2(capture.handle(), 1);
    *exitCode = cli::runCommandLine(command);
    std::fflush(stdout);
    ::dup2(saved, 1);
    ::close(saved);
    capture.seek(0);
    return capture.readAll();
}

/// A method's own editor panel: the gain as a spin box.
class GainKnob final : public MethodEditor {
    Q_OBJECT
public:
    explicit GainKnob(QWidget* parent) : MethodEditor(parent), box_(new QDoubleSpinBox(this)) {
        box_->setRange(0.001, 1000.0);
        connect(box_, &QDoubleSpinBox::valueChanged, this, [this](double v) {
            AxisSettings next = current_;
            next.parameters["kp"] = v;
            emit settingsEdited(next, QStringLiteral("Turn the gain knob"));
        });
    }
    void setSettings(const AxisSettings& settings) override {
        current_ = settings;
        const QSignalBlocker quiet(box_);
        box_->setValue(settings.parameters.count("kp") ? settings.parameters.at("kp") : 30.0);
    }
    QDoubleSpinBox* box() const { return box_; }

private:
    QDoubleSpinBox* box_;
    AxisSettings current_;
};

/// @p window shown at 1600 x 1000 on proportionalSession(), set through @p session as one step.
bool openOnProportionalSession(TuningSession& session, MainWindow& window) {
    session.apply(proportionalSession(), "proportional");
    window.resize(1600, 1000);
    window.show();
    return QTest::qWaitForWindowExposed(&window);
}

} // namespace

class TstRegisteredMethod : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void evaluatesTheLoopItsModuleCloses();
    void sessionFileHoldsItsParameters();
    void everyExportWritesIt();
    void cliReportShowsIt();
    void everyViewOfTheWorkbenchDrawsIt();
    void itsEditorChangesTheDesign();
    void robustnessAndDesignSpaceTakeIt();
    // Last: it registers an editor, which every window built afterwards shows.
    void aRegisteredEditorReplacesTheParameterEditor();

private:
    QTemporaryDir dir_;
};

void TstRegisteredMethod::initTestCase() {
    registerDesignMethodModule(std::make_unique<ProportionalMethod>());
    // Registered once: a second module with its value or id is refused.
    QVERIFY_THROWS_EXCEPTION(InvalidInput,
                             registerDesignMethodModule(std::make_unique<ProportionalMethod>()));
    QCOMPARE(findDesignMethodModule("proportional")->method(), kProportional);
}

void TstRegisteredMethod::evaluatesTheLoopItsModuleCloses() {
    const Session s = proportionalSession();
    const SessionEvaluation e = evaluateSession(s);
    const AxisEvaluation& x = e.axes[0];
    QVERIFY2(x.ok, x.error.text.c_str());
    QVERIFY(!x.gt && !x.pp && x.digital);
    // T = kp k0 / (s^3 + a1 s^2 + a2 s + kp k0): the closed loop in closed form.
    const ThirdOrderPlant& g = s.axes[0].gt.plant;
    const double k = 20.0 * g.k0;
    const TransferFunction t = x.closedLoop();
    const double lead = t.den().coefficient(3);
    QCOMPARE(t.den().degree(), 3);
    const double tol = 1e-12; // the polynomial products of unityFeedbackLoop: exact to rounding
    QVERIFY(std::abs(t.den().coefficient(2) / lead - g.a1) <= tol * g.a1);
    QVERIFY(std::abs(t.den().coefficient(1) / lead - g.a2) <= tol * g.a2);
    QVERIFY(std::abs(t.den().coefficient(0) / lead - k) <= tol * k);
    QVERIFY(std::abs(t.num().coefficient(0) / lead - k) <= tol * k);
    // Its gain margin in closed form (Routh: s^3 + a1 s^2 + a2 s + K is stable for K < a1 a2,
    // the phase crossing at w = sqrt(a2)): GM = a1 a2 / (kp k0).
    const AxisFrequencyAnalysis f = analyzeAxisFrequency(s, x);
    QVERIFY2(f.ok, f.error.text.c_str());
    const double gm = g.a1 * g.a2 / k;
    // Tolerance: the margin is located by the analysis to 1e-9 relative (stability_margins.h).
    QVERIFY2(std::abs(f.margins.gainMarginFactor - gm) <= 1e-9 * gm,
             qPrintable(QString::number(f.margins.gainMarginFactor, 'g', 17)));
    QVERIFY(std::abs(f.margins.gainMarginOmegaRadPerSec - std::sqrt(g.a2)) <= 1e-9 * 100.0);
    // A type-1 loop ends a point-to-point move at the target: the final error is the decay of
    // the slowest pole, well inside the in-position window after the automatic settle.
    QVERIFY(std::abs(x.run.e.back()) < s.spec.inPositionWindowMm);
    // The y axis keeps its own method, untouched.
    QVERIFY(e.axes[1].gt.has_value());
    // A G-code program: the contour run traces x with the module (tracePath), from rest at the
    // program's start, on the profile's samples.
    Session program = s;
    program.trajectory.kind = TrajectoryKind::Gcode;
    program.trajectory.gcode.program = test::kBallbarProgram;
    const SessionEvaluation p = evaluateSession(program);
    QVERIFY2(p.program, p.programError.text.c_str());
    const ContourTrace& trace = p.program->trace;
    const SimulationResult& x0 = trace.axes[0];
    QCOMPARE(x0.y.size(), trace.profile.t.size());
    QCOMPARE(x0.y.front(), trace.profile.x.front());
    QCOMPARE(trace.x, x0.y); // a continuous axis: traced on the profile's own samples
    QVERIFY(!trackingMetrics(x0).diverged);
}

void TstRegisteredMethod::sessionFileHoldsItsParameters() {
    const Session s = proportionalSession();
    const QJsonObject json = sessionToJson(s);
    const QJsonObject x = json["axes"].toArray()[0].toObject();
    QCOMPARE(x["method"].toString(), QString("proportional"));
    QCOMPARE(x["parameters"].toObject()["kp"].toDouble(), 20.0); // exact in binary and decimal
    const SessionLoadResult back = sessionFromJson(json);
    QVERIFY2(back.ok, qPrintable(back.message()));
    QVERIFY(back.session == s);
    // Out of the range the module declares: refused at its JSON path.
    QJsonArray axes = json["axes"].toArray();
    QJsonObject bad = x;
    bad["parameters"] = QJsonObject{{"kp", -1.0}};
    axes[0] = bad;
    QJsonObject root = json;
    root["axes"] = axes;
    QCOMPARE(sessionFromJson(root).message(),
             QString("axes[0].parameters.kp: must be within 1e-06 .. 1e+06 V/model unit"));
    bad["parameters"] = QJsonObject{{"K p", 1.0}};
    axes[0] = bad;
    root["axes"] = axes;
    QVERIFY(sessionFromJson(root).message().startsWith(
        "axes[0].parameters.K p: must be named by 1 to 32 lower-case letters"));
    // Set beyond the range in the session itself: the evaluation refuses it at the field.
    Session outOfRange = s;
    outOfRange.axes[0].parameters["kp"] = 2e6;
    const AxisEvaluation refused = evaluateAxis(outOfRange, 0);
    QVERIFY(!refused.ok);
    QCOMPARE(refused.errorField, std::string("axes[0].parameters.kp"));
}

void TstRegisteredMethod::everyExportWritesIt() {
    const Session s = proportionalSession();
    const SessionEvaluation e = evaluateSession(s);
    // The coefficient file lists the module's coefficients.
    const QJsonObject json = coefficientsJson(s, e, {});
    const QJsonObject x = json["axes"].toArray()[0].toObject();
    QCOMPARE(x["method"].toString(), QString("proportional"));
    QCOMPARE(x["coefficients"].toArray()[0].toObject()["name"].toString(), QString("kp"));
    // (20 is exact in binary and in JSON's decimal text: an exact comparison.)
    QCOMPARE(x["coefficients"].toArray()[0].toObject()["value"].toDouble(), 20.0);
    // The firmware header holds the module's block and compiles; one step of it is u = kp e UNIT.
    const std::string header = exportCHeader(s, e);
    QVERIFY(header.find("xyt_x_step") != std::string::npos);
    QVERIFY(header.find("xyt_y_step") != std::string::npos); // the other axis' PI
    QFile h(dir_.filePath("xytune_controller.h"));
    QVERIFY(h.open(QIODevice::WriteOnly));
    h.write(QByteArray::fromStdString(header));
    h.close();
    QFile c(dir_.filePath("step.c"));
    QVERIFY(c.open(QIODevice::WriteOnly));
    c.write("#include <stdio.h>\n#include \"xytune_controller.h\"\n"
            "int main(void) {\n  xyt_x_state s;\n  xyt_x_init(&s);\n"
            "  printf(\"%.17g %.17g\\n\", (double)xyt_x_step(&s, 10.0, 0.0),\n"
            "         (double)xyt_x_step(&s, 1.0e6, 0.0));\n  return 0;\n}\n");
    c.close();
    QProcess cc;
    cc.setWorkingDirectory(dir_.path());
    cc.start(XYT_C_COMPILER, {"-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic", "step.c",
                              "-o", "step", "-lm"});
    QVERIFY(cc.waitForFinished(120000));
    QVERIFY2(cc.exitCode() == 0, cc.readAllStandardError().constData());
    QProcess run;
    run.start(dir_.filePath("step"), {});
    QVERIFY(run.waitForFinished(60000));
    const QList<QByteArray> u = run.readAllStandardOutput().trimmed().split(' ');
    QCOMPARE(u.size(), 2);
    // Exact: the C step computes (KP (r - y)) UNIT in double, the operations written here, and
    // prints 17 significant digits, which read back to the same double.
    QCOMPARE(u[0].toDouble(), 20.0 * 10.0 * 0.001); // kp e UNIT, inside the limit
    QCOMPARE(u[1].toDouble(), s.umaxVolts);         // clipped at +umax
    // The Octave script has the module's controller and closed loop.
    const std::string octave = exportOctaveScript(s, e);
    QVERIFY(octave.find("controller_x = tf(20, 1);") != std::string::npos);
    QVERIFY(octave.find("closed_loop_x = feedback(controller_x * plant_x, 1);") !=
            std::string::npos);
    // The CSV has the run the evaluation made.
    const std::string csv = exportCsv(s, e);
    QVERIFY(csv.rfind("t,r_x,y_x,e_x,u_x", 0) == 0);
}

void TstRegisteredMethod::cliReportShowsIt() {
    const QString path = dir_.filePath("proportional.json");
    QString error;
    QVERIFY2(saveSessionFile(proportionalSession(), path, &error), qPrintable(error));
    int code = -1;
    const QString report = QString::fromUtf8(runCli({"report", path}, &code));
    QCOMPARE(code, 0);
    QVERIFY2(report.contains("== Axis x (lower base): proportional\n  kp = 20 V/model unit\n"),
             qPrintable(report));
    const ThirdOrderPlant g = proportionalSession().axes[0].gt.plant;
    const double gm = g.a1 * g.a2 / (20.0 * g.k0);
    // The margins line (3 significant digits) with the closed-form gain margin.
    QVERIFY2(report.contains(QStringLiteral("loop margins: GM %1 dB at %2 rad/s")
                                 .arg(QString::number(20.0 * std::log10(gm), 'g', 3),
                                      QString::number(std::sqrt(g.a2), 'g', 3))),
             qPrintable(report));
    QVERIFY(report.contains("tracking as designed (the continuous loop, |u| limited)"));
    QVERIFY(report.contains("tracking as it runs (the digital implementation at Ts = 0.01 s"));
    // The other commands that read a session take it too.
    const QString c = dir_.filePath("cli.h");
    QCOMPARE((runCli({"export", path, "--format", "c", "-o", c}, &code), code), 0);
    QVERIFY(QFile::exists(c));
}

void TstRegisteredMethod::everyViewOfTheWorkbenchDrawsIt() {
    TuningSession session;
    MainWindow window(&session);
    QVERIFY(openOnProportionalSession(session, window));
    // The method is offered by name, chosen for x; its page is the parameter editor.
    QComboBox* method = window.methodBox();
    QCOMPARE(method->count(), static_cast<int>(designMethodModules().size()));
    QCOMPARE(method->currentText(), QString("proportional control"));
    MethodParameterEditor* editor = proportionalEditor(&window);
    QVERIFY(editor && editor->isVisible());
    QCOMPARE(editor->field("kp")->value(), 20.0);
    // Every plot tab draws what the core computes for this design (plotsMismatch visits each).
    QCOMPARE(test::plotsMismatch(&window, &session), QString());
    QVERIFY(window.rootLocusPlot()->hasResult());
    QVERIFY(window.poleZeroPlot()->polesGraph("plant G"));
    QVERIFY(window.poleZeroPlot()->polesGraph("closed loop"));
    QVERIFY(window.bodePlot()->hasResult());
    // The parameter locus says why it has none; the equations are the module's.
    window.upperTabs()->setCurrentWidget(window.parameterLocusPlot());
    QVERIFY(!window.parameterLocusPlot()->hasResult());
    QVERIFY(window.equationsPanel()->text().contains("proportional control"));
    QVERIFY(window.equationsPanel()->text().contains("u = kp e, kp = 20"));
    // The contour and every other tab are drawn (a pixel grab of each).
    for (QTabWidget* tabs : {window.upperTabs(), window.lowerTabs()})
        for (int i = 0; i < tabs->count(); ++i) {
            tabs->setCurrentIndex(i);
            QVERIFY(!tabs->currentWidget()->grab().isNull());
        }
    // The snapshot comparison lists its coefficient.
    bool kpRow = false;
    for (const auto& row : comparisonRows(session.session()))
        kpRow = kpRow || (row.first == "X kp (V/model unit)" && row.second == "20");
    QVERIFY(kpRow);
    // Saving and exporting from the window's file controller.
    QVERIFY(window.files()->saveTo(dir_.filePath("window.json")));
    QVERIFY(window.files()->exportTo("json", dir_.filePath("window-coefficients.json")));
    QVERIFY(window.files()->exportTo("c", dir_.filePath("window.h")));
    QVERIFY(window.files()->exportTo("m", dir_.filePath("window.m")));
    QVERIFY(window.files()->exportTo("csv", dir_.filePath("window.csv")));
    const SessionLoadResult saved = loadSessionFile(dir_.filePath("window.json"));
    QVERIFY(saved.ok && saved.session == session.session());
    // Switching x back to Guillemin-Truxal and to this method again, as a user would.
    method->setCurrentIndex(0);
    emit method->activated(0);
    QCOMPARE(session.session().axes[0].method, DesignMethod::GuilleminTruxal);
    const int index = method->findText("proportional control");
    method->setCurrentIndex(index);
    emit method->activated(index);
    QCOMPARE(session.session().axes[0].method, kProportional);
    QCOMPARE(session.session().axes[0].parameters.at("kp"), 20.0); // kept while away
    QCOMPARE(test::plotsMismatch(&window, &session), QString());
}

void TstRegisteredMethod::itsEditorChangesTheDesign() {
    TuningSession session;
    MainWindow window(&session);
    QVERIFY(openOnProportionalSession(session, window));
    MethodParameterEditor* editor = proportionalEditor(&window);
    QVERIFY(editor);
    NumberField* kp = editor->field("kp");
    const int steps = session.undoStack()->count();
    test::typeInto(kp, "12.5");
    QCOMPARE(session.session().axes[0].parameters.at("kp"), 12.5);
    QCOMPARE(session.undoStack()->count(), steps + 1);
    QVERIFY(window.equationsPanel()->text().contains("kp = 12.5"));
    QCOMPARE(test::plotsMismatch(&window, &session), QString());
    // Out of range: refused at the field, the design unchanged.
    test::typeInto(kp, "-3");
    QVERIFY(kp->hasError());
    QVERIFY(kp->errorText().contains("must be within"));
    QCOMPARE(session.session().axes[0].parameters.at("kp"), 12.5);
    session.undoStack()->undo();
    QCOMPARE(session.session().axes[0].parameters.at("kp"), 20.0);
    QCOMPARE(kp->value(), 20.0);
    // On the other axis (Guillemin-Truxal) the editor is not shown.
    session.setCurrentAxis(1);
    QVERIFY(!editor->isVisible());
}

void TstRegisteredMethod::robustnessAndDesignSpaceTakeIt() {
    TuningSession session;
    MainWindow window(&session);
    QVERIFY(openOnProportionalSession(session, window));
    auto* robustness = window.findChild<RobustnessView*>();
    window.lowerTabs()->setCurrentWidget(robustness);
    QCOMPARE(robustness->parameterNames(), (QStringList{"a1", "a2", "k0"})); // (sorted)
    robustness->rangeBox("k0")->setValue(10.0);
    robustness->samplesBox()->setValue(8);
    robustness->cornersBox()->setChecked(false);
    QSignalSpy done(robustness, &RobustnessView::analysisFinished);
    QTest::mouseClick(robustness->runButton(), Qt::LeftButton);
    QVERIFY(done.wait(120000));
    QVERIFY(robustness->result().has_value());
    // The same analysis in the core, on the module's problem: the nominal run is the evaluation's.
    RobustnessProblem p = sessionRobustnessProblem(session.session(), 0);
    QVERIFY(p.controller.has_value());
    // (The study runs the same loop on the same samples: to rounding, 1e-9 relative.)
    const double rmse = session.axisEvaluation(0).metrics.rmse;
    QVERIFY(std::abs(robustness->result()->nominal.tracking.rmse - rmse) <= 1e-9 * rmse);
    // Its worst plant loads through the module, as one undo step.
    const double k0 = session.session().axes[0].gt.plant.k0;
    QTest::mouseClick(robustness->worstButton(), Qt::LeftButton);
    QVERIFY(session.session().axes[0].gt.plant.k0 != k0);
    QCOMPARE(session.session().axes[0].method, kProportional);
    session.undoStack()->undo();
    QCOMPARE(session.session().axes[0].gt.plant.k0, k0);
    // The design space studies Guillemin-Truxal axes: it names this method instead.
    auto* space = window.findChild<DesignSpaceView*>();
    window.lowerTabs()->setCurrentWidget(space);
    QTest::mouseClick(space->runButton(), Qt::LeftButton);
    QVERIFY2(space->statusLabel()->text().contains("uses proportional control"),
             qPrintable(space->statusLabel()->text()));
}

void TstRegisteredMethod::aRegisteredEditorReplacesTheParameterEditor() {
    registerMethodEditor(kProportional,
                         [](const DesignMethodModule&, QWidget* parent) -> MethodEditor* {
                             return new GainKnob(parent);
                         });
    TuningSession session;
    MainWindow window(&session);
    QVERIFY(openOnProportionalSession(session, window));
    QVERIFY(!proportionalEditor(&window)); // the method's own editor instead
    auto* knob = window.findChild<GainKnob*>();
    QVERIFY(knob && knob->isVisible());
    QCOMPARE(knob->box()->value(), 20.0);
    const int steps = session.undoStack()->count();
    knob->box()->setValue(7.5);
    QCOMPARE(session.session().axes[0].parameters.at("kp"), 7.5);
    QCOMPARE(session.undoStack()->count(), steps + 1);
    QCOMPARE(session.undoStack()->undoText(), QString("Turn the gain knob"));
    QVERIFY(window.equationsPanel()->text().contains("kp = 7.5"));
    session.undoStack()->undo();
    QCOMPARE(knob->box()->value(), 20.0); // the window keeps the editor in step
}

QTEST_MAIN(TstRegisteredMethod)
#include "tst_registered_method.moc"
