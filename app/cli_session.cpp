// SPDX-License-Identifier: GPL-3.0-or-later
// xytune-cli new | export, and report SESSION.json: session files, coefficient exports and the
// LinuxCNC pid gains.
#include "app/cli_args.h"
#include "app/cli_commands.h"
#include "app/cli_design_args.h"

#include "core/io/file_io.h"
#include "core/io/text_escape.h"
#include "core/model/errors.h"
#include "core/session/axis_frequency.h"
#include "core/session/design_method_module.h"
#include "core/session/export_text.h"
#include "core/session/linuxcnc_export.h"
#include "core/session/session_evaluation.h"
#include "ui/files/coefficient_json.h"
#include "ui/files/session_file.h"

#include <QJsonDocument>
#include <QTextStream>

#include <cmath>
#include <cstdio>

namespace xyt::cli {

namespace {

void writeOrThrow(const QString& path, const QByteArray& bytes) {
    writeFile("-o", path, [&bytes](const ByteSink& sink) {
        sink(std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size())));
    });
}

/// User text (a label, a file name) as the terminal may show it: controls escaped.
QString shown(const std::string& text) {
    return QString::fromStdString(terminalText(text));
}

QString outputPath(const CliArgs& args) {
    const auto o = args.value("o");
    if (!o || o->isEmpty())
        throw InvalidInput("-o", "an output file is required (-o FILE)");
    return *o;
}

/// A session whose run itself was refused (trajectory out of range, too many samples, a single
/// sample) has nothing to report or export: exit 2 naming the session field, as for bad input.
void refuseRefusedRun(const SessionEvaluation& evaluation) {
    for (const AxisEvaluation& a : evaluation.axes)
        if (!a.ok && a.runRefused)
            throw InvalidInput(a.errorField, a.error);
}

QString number(double v, int decimals = 4) {
    return std::isfinite(v) ? QString::number(v, 'f', decimals) : QStringLiteral("n/a");
}

/// "RMSE ... mm, max |e| ... mm (... % of travel), max |u| ... V, saturated ..., ITAE ...".
QString trackingText(const TrackingMetrics& m) {
    QString saturated = m.saturated ? QStringLiteral("yes") : QStringLiteral("no");
    if (m.saturated)
        saturated += " (" + number(m.saturatedTimeSeconds, 2) + " s)";
    return "RMSE " + number(m.rmse) + " mm, max |e| " + number(m.maxAbsError) + " mm (" +
           number(m.maxAbsErrorPct, 3) + " % of travel), max |u| " + number(m.maxAbsU) +
           " V, saturated " + saturated + ", ITAE " + number(m.itae, 1);
}

/// "settled ... s after tf, final error ... mm, final-position overshoot ... mm".
QString moveSettleText(const MoveSettleMetrics& ms) {
    QString out;
    if (ms.diverged)
        out = "n/a (the run diverged)";
    else if (ms.settled)
        out = "settled " + number(*ms.settleTimeSeconds, 2) + " s after tf";
    else
        out = "not settled by the end of the run (" + number(ms.runEndSeconds, 2) + " s)";
    return out + ", final error " + number(ms.finalErrorMm, 5) + " mm, final-position overshoot " +
           number(ms.finalOvershootMm, 4) + " mm";
}

/// Which run fails a criterion the verdict fails: the design's, the implementation's or both.
QString failedOn(bool design, bool implementation) {
    if (!design && !implementation)
        return QStringLiteral(" (as designed and as it runs)");
    return !implementation ? QStringLiteral(" (as it runs)") : QStringLiteral(" (as designed)");
}

} // namespace

int runNew(const QStringList& argv) {
    const CliArgs args = CliArgs::parse(argv);
    args.allowOnly({"o"});
    const QString path = outputPath(args);
    writeOrThrow(path, QJsonDocument(files::sessionToJson(Session::paperDefault())).toJson());
    std::printf("%s\n", terminalText(fileNameBytes(path)).c_str());
    return 0;
}

int runSessionReport(const QString& path) {
    const Session session = loadSessionOrThrow(path);
    const SessionEvaluation evaluation = evaluateSession(session);
    refuseRefusedRun(evaluation);
    QString text;
    QTextStream out(&text);
    const TrajectorySettings& t = session.trajectory;
    out << "XY Tune report: " << shown(fileNameBytes(path)) << "\n";
    if (t.kind == TrajectoryKind::Cubic)
        out << "Trajectory: " << (t.profile == MoveProfile::Quintic ? "quintic " : "cubic ") << t.x0
            << " -> " << t.xf << " mm from " << t.t0Seconds << " s to " << t.tfSeconds << " s";
    else if (t.kind == TrajectoryKind::Gcode)
        out << "Trajectory: G-code program " << shown(t.gcode.fileName) << ", feed scale "
            << t.gcode.feedScale << ", max acceleration " << t.gcode.maxAccelMmPerS2
            << " mm/s^2, max jerk " << t.gcode.maxJerkMmPerS3 << " mm/s^3";
    else
        out << "Trajectory: circle R = " << t.radius << " mm at " << t.omegaRadPerSec
            << " rad/s, ramp-in " << t.rampInSeconds << " s";
    out << "; |u| <= " << session.umaxVolts << " V\n";
    out << "Run: " << QString::fromStdString(evaluation.duration.description) << ".\n";
    for (int i = 0; i < 2; ++i) {
        const AxisSettings& s = session.axes[static_cast<std::size_t>(i)];
        const AxisEvaluation& a = evaluation.axes[static_cast<std::size_t>(i)];
        out << "\n== Axis " << QString::fromStdString(s.id) << " (" << shown(s.label)
            << "): " << files::methodName(s.method) << "\n";
        if (s.origin) {
            const ModelOrigin& o = *s.origin;
            out << "  model: identified " << shown(o.structure) << " from " << shown(o.source)
                << " (" << o.samples << " samples at " << o.tsSeconds << " s), fit "
                << QString::number(o.fitPercent, 'f', 2) << " %";
            if (o.validationFitPercent)
                out << ", on validation data " << QString::number(*o.validationFitPercent, 'f', 2)
                    << " %";
            out << "\n";
        }
        if (!a.ok) {
            out << "  not designed: " << shown(a.errorField) << ": " << shown(a.error) << "\n";
            continue;
        }
        const DesignMethodModule& module = designMethodModule(s.method);
        for (const std::string& line : module.reportLines(s, a))
            out << "  " << QString::fromStdString(line) << "\n";
        if (s.friction.active() || s.frictionCompensation.percent != 0.0) {
            const TableFriction& f = s.friction;
            const auto g = [](double v) { return QString::number(v, 'g', 6); };
            out << "  table: Coulomb " << g(f.coulombVolts) << " V, static "
                << g(f.breakawayVolts()) << " V"
                << (f.staticVolts > f.coulombVolts
                        ? " (Stribeck velocity " + g(f.stribeckVelocityMmPerS) + " mm/s)"
                        : QString())
                << ", viscous " << g(f.viscousVoltsPerMmPerS) << " V per mm/s, backlash "
                << g(f.backlashMm) << " mm, amplifier deadband " << g(f.amplifierDeadbandVolts)
                << " V; friction compensation " << g(s.frictionCompensation.percent) << " % (band "
                << g(s.frictionCompensation.bandMmPerS) << " mm/s)\n";
        }
        // The run that will really happen first (the digital implementation: sampled, delayed,
        // quantized, |u| limited), then the design's own run, each labelled: a design whose
        // implementation saturates must not be read from the design's figures.
        const DigitalEvaluation* digital = a.digital.get();
        const QString designRun = QString::fromStdString(module.designRunDescription());
        const QString digitalRun = digital ? "the digital implementation at Ts = " +
                                                 QString::number(digital->tsSeconds, 'g', 6) +
                                                 " s, |u| limited to " +
                                                 QString::number(session.umaxVolts, 'g', 6) + " V"
                                           : QString();
        if (digital)
            out << "  tracking as it runs (" << digitalRun
                << "): " << trackingText(digital->metrics) << "\n";
        out << "  tracking as designed (" << designRun << "): " << trackingText(a.metrics) << "\n";
        out << "  unit step of the closed loop: settling (2 %) "
            << (a.step.stable ? number(a.step.settlingTimeSeconds, 2) + " s" : QString("unstable"))
            << ", overshoot "
            << (a.step.stable ? number(a.step.overshootPct, 3) + " %" : QString("unstable"))
            << "\n";
        out << "  loop margins: " << marginsText(analyzeAxisFrequency(session, a).margins) << "\n";
        if (a.moveSettle) {
            const QString window = QString::number(a.moveSettle->windowMm, 'g', 6);
            if (digital && digital->moveSettle)
                out << "  move and settle (window " << window
                    << " mm) as it runs: " << moveSettleText(*digital->moveSettle) << "\n";
            out << "  move and settle (window " << window
                << " mm) as designed: " << moveSettleText(*a.moveSettle) << "\n";
        }
        // The verdict is the worse of the design and its implementation (AxisEvaluation::check);
        // each failed criterion says which run fails it.
        QStringList failed;
        const SpecificationCheck& c = a.check;
        const SpecificationCheck& d = a.designCheck;
        const SpecificationCheck im = a.implementationCheck.value_or(a.designCheck);
        // The step and the margins are the design's in both checks: only the run's own figures
        // (saturation, tracking error, settle) can fail on one run and not the other.
        struct Criterion {
            bool passed, design, implementation;
            const char* name;
            bool perRun;
        };
        const Criterion criteria[] = {
            {c.stable, d.stable, im.stable, "stable", false},
            {c.settlingTime, d.settlingTime, im.settlingTime, "step settling", false},
            {c.overshoot, d.overshoot, im.overshoot, "step overshoot", false},
            {c.noSaturation, d.noSaturation, im.noSaturation, "no saturation", true},
            {c.trackingError, d.trackingError, im.trackingError, "tracking error", true},
            {c.settle, d.settle, im.settle, "move settle", true},
            {c.phaseMargin, d.phaseMargin, im.phaseMargin, "phase margin", false},
            {c.gainMargin, d.gainMargin, im.gainMargin, "gain margin", false}};
        for (const Criterion& k : criteria)
            if (!k.passed)
                failed << k.name + (a.implementationCheck && k.perRun
                                        ? failedOn(k.design, k.implementation)
                                        : QString());
        out << "  specification: "
            << (failed.isEmpty() ? QStringLiteral("met") : "fails " + failed.join(", ")) << "\n";
        for (const auto& w : a.warnings)
            out << "  warning: " << shown(w) << "\n";
    }
    if (evaluation.contour)
        out << "\n== Circle contour: radial error max " << number(evaluation.contour->maxAbs)
            << " mm, RMS " << number(evaluation.contour->rms) << " mm\n";
    out.flush();
    const QByteArray bytes = text.toUtf8();
    std::fwrite(bytes.constData(), 1, static_cast<std::size_t>(bytes.size()), stdout);
    return 0;
}

int runExport(const QStringList& argv) {
    const CliArgs args = CliArgs::parse(argv, {"ff-from-model"});
    args.allowOnly({"format", "o", "discretization", "precision", "ff-from-model"});
    if (args.positional().size() != 1)
        throw InvalidInput("SESSION", "export takes exactly one session file");
    const QString format = args.text("format", "");
    if (!QStringList{"json", "c", "m", "csv", "linuxcnc"}.contains(format))
        throw InvalidInput("--format", "must be json, c, m, csv or linuxcnc");
    if (args.flag("ff-from-model") && format != "linuxcnc")
        throw InvalidInput("--ff-from-model", "applies to --format linuxcnc only");
    if (args.has("discretization") && format == "linuxcnc")
        throw InvalidInput("--discretization",
                           "does not apply to --format linuxcnc: LinuxCNC's pid integrates by "
                           "the rectangle rule");
    const QString path = outputPath(args);
    const Session session = loadSessionOrThrow(args.positional().first());
    ExportOptions options;
    options.piMethod =
        parseDiscretization(args, session.piDiscretization); // the session's unless given
    const QString precision = args.text("precision", "double");
    if (precision == "float")
        options.precision = CPrecision::Float;
    else if (precision != "double")
        throw InvalidInput("--precision", "must be double or float");
    if (args.has("precision") && format != "c")
        throw InvalidInput("--precision", "applies to --format c only");
    const SessionEvaluation evaluation = evaluateSession(session);
    refuseRefusedRun(evaluation);
    if (format == "csv") // streamed: a long simulation is never held as text
        writeFile("-o", path, [&](const ByteSink& sink) { exportCsv(session, evaluation, sink); });
    else if (format == "json")
        writeOrThrow(path,
                     QJsonDocument(files::coefficientsJson(session, evaluation, options)).toJson());
    else if (format == "c")
        writeOrThrow(path, QByteArray::fromStdString(exportCHeader(session, evaluation, options)));
    else if (format == "linuxcnc") // refuses a pole-placement axis naming axes[i].method
        writeOrThrow(path, QByteArray::fromStdString(
                               exportLinuxCnc(session, evaluation, args.flag("ff-from-model"))));
    else
        writeOrThrow(path,
                     QByteArray::fromStdString(exportOctaveScript(session, evaluation, options)));
    std::printf("%s\n", terminalText(fileNameBytes(path)).c_str());
    return 0;
}

} // namespace xyt::cli
