// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/report/design_report.h"

#include "core/design/input_shaper.h"
#include "core/model/errors.h"
#include "core/session/design_method_module.h"
#include "core/session/export_text.h"
#include "core/session/specification_advice.h"
#include "ui/panels/equations_panel.h"
#include "ui/panels/metrics_panel.h"
#include "ui/plots/number_text.h"
#include "ui/report/report_metrics.h"
#include "ui/session/diagnostic_text.h"

#include <QTextDocument>
#include <QUrl>

namespace xyt::ui {

namespace {

/// Coefficients and settings print with six significant digits, as the equations panel does.
QString coefficientText(double v) {
    return significant(v, 6);
}

QString escaped(const std::string& text) {
    return QString::fromStdString(text).toHtmlEscaped();
}

/// A core warning or reason in the user's language, escaped for HTML.
QString escapedDiagnostic(const Diagnostic& d) {
    return diagnosticText(d).toHtmlEscaped();
}

QString listHtml(const QStringList& items) {
    if (items.isEmpty())
        return QString();
    return QStringLiteral("<ul><li>") + items.join(QStringLiteral("</li><li>")) +
           QStringLiteral("</li></ul>");
}

/// u[k] = n0 e[k] + n1 e[k-1] ... - d1 u[k-1] ...: the difference equation of a controller in
/// ascending powers of z^-1 with den[0] = 1 (as the coefficient export states it).
QString differenceEquationHtml(const DigitalController& c) {
    QString out = QStringLiteral("u[k] =");
    bool first = true;
    const auto term = [&](double coefficient, const QString& signal) {
        if (coefficient == 0.0)
            return;
        out += first ? (coefficient < 0 ? QStringLiteral(" −") : QString())
                     : (coefficient < 0 ? QStringLiteral(" −") : QStringLiteral(" +"));
        out += QStringLiteral(" ") + coefficientText(std::abs(coefficient)) + QStringLiteral(" ") +
               signal;
        first = false;
    };
    for (std::size_t i = 0; i < c.num.size(); ++i)
        term(c.num[i], i == 0 ? QStringLiteral("e[k]") : QStringLiteral("e[k−%1]").arg(i));
    for (std::size_t i = 1; i < c.den.size(); ++i)
        term(-c.den[i], QStringLiteral("u[k−%1]").arg(i));
    return first ? out + QStringLiteral(" 0") : out;
}

QString coefficientList(const std::vector<double>& v) {
    QStringList parts;
    for (double x : v)
        parts << coefficientText(x);
    return parts.join(QStringLiteral(", "));
}

} // namespace

DesignReport::DesignReport(const Session& session, const SessionEvaluation& evaluation,
                           const ReportSource& source, const Progress& progress)
    : session_(session), evaluation_(evaluation) {
    int done = 0;
    const auto step = [&] {
        if (progress)
            progress(++done, kParts);
    };
    html_ = QStringLiteral("<html><body>") + titleBlock(source) + overview();
    for (int axis = 0; axis < 2; ++axis) {
        std::vector<ReportFigure> figures = axisFigures(session, evaluation, axis);
        html_ += axisSection(axis, figures);
        for (ReportFigure& f : figures)
            figures_.push_back(std::move(f));
        step();
    }
    std::vector<ReportFigure> contour = contourFigures(session, evaluation);
    html_ += contourSection(contour);
    for (ReportFigure& f : contour)
        figures_.push_back(std::move(f));
    step();
    html_ += QStringLiteral("</body></html>");
    step();
}

QString DesignReport::version() {
    return QStringLiteral(XYT_VERSION_STRING);
}

void DesignReport::loadInto(QTextDocument& document) const {
    for (const ReportFigure& f : figures_)
        document.addResource(QTextDocument::ImageResource, QUrl(f.name), f.image);
    QFont font = document.defaultFont();
    font.setPointSizeF(10.0);
    document.setDefaultFont(font);
    document.setDefaultStyleSheet(QStringLiteral(
        "h1 { font-size: 20pt; } h2 { font-size: 15pt; color: #1f3a5f; } "
        "h3 { font-size: 12pt; color: #1f3a5f; } p.caption { font-size: 9pt; color: #444444; } "
        "td, th { font-size: 9.5pt; }"));
    document.setHtml(html_);
}

QString DesignReport::figureHtml(const ReportFigure& figure) {
    return QStringLiteral("<p align='center'><img src='%1' width='%2' height='%3'></p>"
                          "<p class='caption'>%4</p>")
        .arg(figure.name)
        .arg(figure.logicalWidth)
        .arg(figure.logicalHeight)
        .arg(figure.caption.toHtmlEscaped());
}

QString DesignReport::titleBlock(const ReportSource& source) const {
    QString html = tr("<h1>XY Tune design report</h1>");
    html += QStringLiteral("<table cellpadding='2'>");
    const auto row = [](const QString& name, const QString& value) {
        return QStringLiteral("<tr><td><b>%1</b></td><td>%2</td></tr>")
            .arg(name.toHtmlEscaped(), value.toHtmlEscaped());
    };
    html += row(tr("Date"), QLocale().toString(source.created, QLocale::LongFormat));
    html += row(tr("XY Tune version"), version());
    html += row(tr("Session file"),
                source.sessionName.isEmpty() ? tr("(unsaved session)") : source.sessionName);
    for (int i = 0; i < 2; ++i) {
        const AxisSettings& a = session_.axes.at(static_cast<std::size_t>(i));
        html +=
            row(tr("Axis %1").arg(QString::fromStdString(a.id).toUpper()),
                tr("%1%2").arg(coreText("xyt::MethodName",
                                        std::string(designMethodModule(a.method).displayName())),
                               a.label.empty() ? QString()
                                               : tr(" (%1)").arg(QString::fromStdString(a.label))));
    }
    return html + QStringLiteral("</table>");
}

QString DesignReport::overview() const {
    QString html = tr("<h2>Verdict</h2>");
    const SpecificationAdvice advice = adviseSpecification(session_, evaluation_);
    if (advice.reasons.empty()) {
        html += tr("<p><span style='color:#1b7f2a'>✓</span> Both axes meet the specification, as "
                   "designed and as implemented.</p>");
    } else {
        html += tr("<p><span style='color:#c62828'>✗</span> The design fails the "
                   "specification:</p>");
        QStringList reasons;
        for (const auto& r : advice.reasons)
            reasons << escapedDiagnostic(r);
        html += listHtml(reasons);
        if (!advice.changes.empty()) {
            QStringList changes;
            for (const auto& c : advice.changes)
                changes << escapedDiagnostic(c);
            html += tr("<p>Limits this design would meet: %1.</p>").arg(changes.join(tr(", ")));
        }
    }
    const Specification& spec = session_.spec;
    html += tr("<h2>Specification</h2>");
    html += listHtml({tr("unit step: settling time (2 %) ≤ %1 s, overshoot ≤ %2 %")
                          .arg(spec.maxSettlingTimeSeconds)
                          .arg(spec.maxOvershootPct),
                      tr("tracking: max |e| ≤ %1 % of the travel, |u| ≤ %2 V and never clipped")
                          .arg(spec.maxErrorPct)
                          .arg(session_.umaxVolts),
                      tr("point-to-point move: settled into ±%1 mm within %2 s of its end")
                          .arg(spec.inPositionWindowMm)
                          .arg(spec.maxSettleTimeSeconds),
                      tr("loop margins: phase margin ≥ %1°, gain margin ≥ %2 dB (0: none stated)")
                          .arg(spec.minPhaseMarginDeg)
                          .arg(spec.minGainMarginDb)});

    html += tr("<h2>Trajectory and implementation</h2>");
    const TrajectorySettings& t = session_.trajectory;
    QString trajectory;
    if (t.kind == TrajectoryKind::Cubic)
        trajectory = tr("%1 move from %2 mm to %3 mm, from t = %4 s to %5 s")
                         .arg(t.profile == MoveProfile::Quintic ? tr("Quintic") : tr("Cubic"))
                         .arg(t.x0)
                         .arg(t.xf)
                         .arg(t.t0Seconds)
                         .arg(t.tfSeconds);
    else if (t.kind == TrajectoryKind::Circle)
        trajectory = tr("Circle of radius %1 mm at %2 rad/s, ramp-in %3 s")
                         .arg(t.radius)
                         .arg(t.omegaRadPerSec)
                         .arg(t.rampInSeconds);
    else
        trajectory = tr("G-code program %1, feed scale %2, max acceleration %3 mm/s², max jerk "
                        "%4 mm/s³")
                         .arg(QString::fromStdString(t.gcode.fileName))
                         .arg(t.gcode.feedScale)
                         .arg(t.gcode.maxAccelMmPerS2)
                         .arg(t.gcode.maxJerkMmPerS3);
    const ImplementationSettings& impl = session_.implementation;
    QString antiWindup = coreText("xyt::AntiWindup", antiWindupName(impl.antiWindup));
    if (impl.antiWindup == AntiWindup::BackCalculation)
        antiWindup +=
            tr(" (tracking time %1)")
                .arg(impl.trackingTimeSeconds > 0.0 ? tr("%1 s").arg(impl.trackingTimeSeconds)
                                                    : tr("Ti = kp/ki"));
    html += listHtml(
        {trajectory.toHtmlEscaped(),
         tr("Simulation: %1 (step %2 s)")
             .arg(escapedDiagnostic(evaluation_.duration.description))
             .arg(t.dtSeconds),
         tr("Actuator limit: |u| ≤ %1 V").arg(session_.umaxVolts),
         tr("Digital PI: Ts = %1 s, %2 discretization; anti-windup %3")
             .arg(session_.controllerTsSeconds)
             .arg(coreText("xyt::Discretization", discretizationName(session_.piDiscretization)),
                  antiWindup.toHtmlEscaped()),
         tr("Computation delay %1 samples; encoder %2; DAC %3")
             .arg(impl.delaySamples)
             .arg(impl.encoderResolutionMm > 0.0
                      ? tr("%1 mm per count").arg(impl.encoderResolutionMm)
                      : tr("ideal"),
                  impl.dacBits > 0 ? tr("%1 bits over ±umax").arg(impl.dacBits) : tr("ideal"))});
    return html;
}

QString DesignReport::axisSection(int axis, const std::vector<ReportFigure>& figures) const {
    const AxisSettings& a = session_.axes.at(static_cast<std::size_t>(axis));
    const AxisEvaluation& e = evaluation_.axes.at(static_cast<std::size_t>(axis));
    QString html =
        QStringLiteral("<h2 style='page-break-before: always'>%1</h2>")
            .arg(a.label.empty()
                     ? tr("Axis %1").arg(QString::fromStdString(a.id).toUpper())
                     : tr("Axis %1 (%2)")
                           .arg(QString::fromStdString(a.id).toUpper(), escaped(a.label)));
    html += plantHtml(axis) + designHtml(axis) + controllerHtml(axis);
    html += tr("<h3>Figures against the specification</h3>");
    html += ReportMetrics::tableHtml(session_, axis, e);
    html += warningsHtml(axis);
    html += tr("<h3>Plots</h3>");
    for (const ReportFigure& f : figures)
        html += figureHtml(f);
    return html;
}

QString DesignReport::plantHtml(int axis) const {
    const AxisSettings& a = session_.axes.at(static_cast<std::size_t>(axis));
    QString html = tr("<h3>Plant</h3>");
    QStringList lines;
    if (a.method == DesignMethod::PolePlacementZpetc) {
        try {
            lines << tr("ARX model A(z<sup>−1</sup>) y = B(z<sup>−1</sup>) u at T<sub>s</sub> = %1 "
                        "s (position in mm, u in V)")
                         .arg(coefficientText(a.pp.tsSeconds));
            lines << tr("A = %1").arg(zInverseHtml(Polynomial::fromAscending(a.pp.a)));
            lines << tr("B = %1").arg(zInverseHtml(Polynomial::fromAscending(a.pp.b)));
        } catch (const InvalidInput& ex) {
            lines << tr("not a valid model: %1").arg(exceptionText(ex).toHtmlEscaped());
        }
    } else {
        const ThirdOrderPlant& p = a.gt.plant;
        lines << tr("G(s) = k<sub>0</sub> / (s (s<sup>2</sup> + a<sub>1</sub> s + a<sub>2</sub>)), "
                    "k<sub>0</sub> = %1, a<sub>1</sub> = %2, a<sub>2</sub> = %3")
                     .arg(coefficientText(p.k0), coefficientText(p.a1), coefficientText(p.a2));
        lines << tr("model units per mm of trajectory: %1")
                     .arg(coefficientText(a.gt.modelUnitsPerPositionUnit));
        const FlexibleMode& mode = a.gt.flexibleMode;
        if (mode.present()) {
            QString text =
                tr("flexible mode: %1 Hz, damping %2")
                    .arg(coefficientText(mode.frequencyHz), coefficientText(mode.dampingRatio));
            if (mode.twoMass())
                text += tr("; anti-resonance %1 Hz, damping %2")
                            .arg(coefficientText(mode.antiResonanceHz),
                                 coefficientText(mode.antiResonanceDamping));
            lines << text;
        }
        try {
            const TransferFunction g = axisPlantTransferFunction(a.gt, axis);
            lines << tr("as every run and analysis sees it: G(s) = (%1) / (%2)")
                         .arg(polynomialHtml(g.num(), "s"), polynomialHtml(g.den(), "s"));
        } catch (const InvalidInput& ex) {
            lines << tr("not a valid plant: %1").arg(exceptionText(ex).toHtmlEscaped());
        }
    }
    if (a.origin) {
        const ModelOrigin& o = *a.origin;
        QString text = tr("identified as %1 from %2 (%3 samples at %4 s), fit %5 %")
                           .arg(escaped(o.structure), escaped(o.source))
                           .arg(o.samples)
                           .arg(o.tsSeconds)
                           .arg(QString::number(o.fitPercent, 'f', 2));
        if (o.validationFitPercent)
            text += tr(", on validation data %1 %")
                        .arg(QString::number(*o.validationFitPercent, 'f', 2));
        lines << text;
    } else {
        lines << tr("entered by hand: the session records no identification");
    }
    if (a.friction.active() || a.frictionCompensation.percent != 0.0) {
        const TableFriction& f = a.friction;
        lines << tr("table friction: Coulomb %1 V, static %2 V, viscous %3 V per mm/s, backlash "
                    "%4 mm, amplifier deadband %5 V; friction compensation %6 % (band %7 mm/s)")
                     .arg(coefficientText(f.coulombVolts), coefficientText(f.breakawayVolts()),
                          coefficientText(f.viscousVoltsPerMmPerS), coefficientText(f.backlashMm),
                          coefficientText(f.amplifierDeadbandVolts),
                          coefficientText(a.frictionCompensation.percent),
                          coefficientText(a.frictionCompensation.bandMmPerS));
    }
    return html + listHtml(lines);
}

QString DesignReport::designHtml(int axis) const {
    const AxisSettings& a = session_.axes.at(static_cast<std::size_t>(axis));
    const AxisEvaluation& e = evaluation_.axes.at(static_cast<std::size_t>(axis));
    const DesignMethodModule& module = designMethodModule(a.method);
    QString html =
        tr("<h3>Design: %1</h3>")
            .arg(coreText("xyt::MethodName", std::string(module.displayName())).toHtmlEscaped());
    QStringList settings;
    if (a.method == DesignMethod::GuilleminTruxal) {
        settings << tr("ω<sub>n</sub> = %1 rad/s").arg(coefficientText(a.gt.omegaNRadPerSec))
                 << tr("k<sub>p</sub> = %1").arg(coefficientText(a.gt.kp));
    } else if (a.method == DesignMethod::PolePlacementZpetc) {
        settings << tr("T = 1 + t<sub>1</sub> z<sup>−1</sup>, t<sub>1</sub> = %1")
                        .arg(coefficientText(a.pp.t1))
                 << tr("T<sub>s</sub> = %1 s").arg(coefficientText(a.pp.tsSeconds))
                 << (a.pp.zpetcEnabled ? tr("ZPETC feedforward on") : tr("ZPETC feedforward off"));
    }
    for (const MethodParameter& p : module.parameters()) {
        try {
            settings << tr("%1 = %2 %3")
                            .arg(coreText("xyt::ParameterLabel", p.label).toHtmlEscaped(),
                                 coefficientText(methodParameterValue(a, axis, p)),
                                 QString::fromStdString(p.unit).toHtmlEscaped());
        } catch (const InvalidInput& ex) {
            settings << exceptionText(ex).toHtmlEscaped();
        }
    }
    if (!settings.isEmpty())
        html += tr("<p>Settings: %1</p>").arg(settings.join(tr("; ")));
    if (!e.ok)
        return html + tr("<p><b>No design</b>: %1: %2</p>")
                          .arg(escaped(e.errorField), escapedDiagnostic(e.error));
    const std::vector<DesignCoefficient> coefficients = module.coefficients(e);
    if (!coefficients.empty()) {
        html += tr("<p>Coefficients of the design:</p>");
        html += QStringLiteral("<table border='1' cellspacing='0' cellpadding='3' "
                               "style='border-collapse:collapse; border-color:#999'>");
        html += tr("<tr style='background:#dddddd'><th>Name</th><th>Value</th><th>Unit</th></tr>");
        for (const DesignCoefficient& c : coefficients)
            html += QStringLiteral("<tr><td>%1</td><td align='right'>%2</td><td>%3</td></tr>")
                        .arg(escaped(c.name), coefficientText(c.value), escaped(c.unit));
        html += QStringLiteral("</table>");
    }
    return html;
}

QString DesignReport::controllerHtml(int axis) const {
    const AxisSettings& a = session_.axes.at(static_cast<std::size_t>(axis));
    const AxisEvaluation& e = evaluation_.axes.at(static_cast<std::size_t>(axis));
    if (!e.ok)
        return QString();
    QString html = tr("<h3>Controller</h3>");
    {
        EquationsPanel equations; // the equations as the workbench's panel typesets them
        equations.showAxis(a, e);
        html += QStringLiteral("<p>") + equations.text() + QStringLiteral("</p>");
    }
    QStringList digital;
    if (e.gt) {
        try {
            ExportOptions options;
            options.piMethod = session_.piDiscretization;
            const DigitalController c = axisDigitalController(session_, evaluation_, axis, options);
            digital << tr("digital PI at T<sub>s</sub> = %1 s (%2): C(z) = (%3) / (%4)")
                           .arg(coefficientText(c.tsSeconds),
                                coreText("xyt::Discretization",
                                         discretizationName(options.piMethod)),
                                zInverseHtml(Polynomial::fromAscending(c.num)),
                                zInverseHtml(Polynomial::fromAscending(c.den)));
            digital << tr("difference equation: %1, e = r − y").arg(differenceEquationHtml(c));
            digital << tr("num = [%1], den = [%2] (ascending powers of z<sup>−1</sup>)")
                           .arg(coefficientList(c.num), coefficientList(c.den));
            const NotchFilter& n = a.gt.notch;
            if (n.present()) {
                const Biquad b = discreteNotch(n, c.tsSeconds);
                digital
                    << tr("notch at %1 Hz, width %2 Hz, depth %3 dB on the error: N(s) = (%4) / "
                          "(%5); biquad b = [%6], a = [1, %7, %8] (bilinear, prewarped)")
                           .arg(coefficientText(n.centreHz), coefficientText(n.widthHz),
                                coefficientText(n.depthDb),
                                polynomialHtml(n.transferFunction().num(), "s"),
                                polynomialHtml(n.transferFunction().den(), "s"),
                                coefficientList({b.b0, b.b1, b.b2}), coefficientText(b.a1),
                                coefficientText(b.a2));
            }
        } catch (const InvalidInput& ex) {
            digital << tr("no digital controller: %1").arg(exceptionText(ex).toHtmlEscaped());
        }
    } else if (e.pp) {
        digital << tr("the RST law above runs as designed, at T<sub>s</sub> = %1 s")
                       .arg(coefficientText(e.pp->tsSeconds));
    } else {
        digital << tr("the method's step runs at T<sub>s</sub> = %1 s (File › Export › Firmware C "
                      "header)")
                       .arg(coefficientText(session_.controllerTsSeconds));
    }
    if (e.digital)
        digital << tr("digital loop: least damping of its z-plane poles %1 (the design's %2)")
                       .arg(displayNumber(e.digital->minDamping, 3),
                            displayNumber(e.digital->designMinDamping, 3));
    html += tr("<p><b>Digital implementation</b></p>") + listHtml(digital);
    return html;
}

QString DesignReport::warningsHtml(int axis) const {
    const AxisEvaluation& e = evaluation_.axes.at(static_cast<std::size_t>(axis));
    QStringList warnings;
    if (!e.ok)
        warnings << tr("no design: %1: %2").arg(escaped(e.errorField), escapedDiagnostic(e.error));
    for (const auto& w : e.warnings)
        warnings << escapedDiagnostic(w);
    if (warnings.isEmpty())
        return tr("<h3>Warnings</h3><p>None.</p>");
    return tr("<h3>Warnings</h3>") + listHtml(warnings);
}

QString DesignReport::contourSection(const std::vector<ReportFigure>& figures) const {
    QString html = tr("<h2 style='page-break-before: always'>Both axes: the XY contour</h2>");
    QStringList lines;
    if (evaluation_.contour)
        lines << tr("radial error of the circle: max %1 mm, RMS %2 mm")
                     .arg(displayNumber(evaluation_.contour->maxAbs),
                          displayNumber(evaluation_.contour->rms));
    if (evaluation_.program) {
        const ContourErrorResult& c = evaluation_.program->contour;
        lines << tr("contour error of the program: max %1 mm, RMS %2 mm")
                     .arg(displayNumber(c.maxAbs), displayNumber(c.rms));
        if (evaluation_.program->circular) {
            const Iso230Circular& iso = evaluation_.program->circular->iso;
            lines << tr("ISO 230-4: circular deviation G %1 mm, radial deviation F max %2 mm, F "
                        "min %3 mm")
                         .arg(displayNumber(iso.circularDeviationG),
                              displayNumber(iso.radialDeviationFMax),
                              displayNumber(iso.radialDeviationFMin));
        }
    }
    if (!evaluation_.programError.text.empty())
        lines << tr("program: %1").arg(escapedDiagnostic(evaluation_.programError));
    const ReferenceShaping& shaping = session_.trajectory.shaping;
    if (shaping.active()) {
        QString text =
            tr("input shaper %1 on the reference at %2 Hz, damping %3")
                .arg(QString::fromUtf8(shaperName(shaping.type)),
                     coefficientText(shaping.frequencyHz), coefficientText(shaping.dampingRatio));
        for (int i = 0; i < 2; ++i)
            if (const auto& s = evaluation_.axes.at(static_cast<std::size_t>(i)).shaping)
                text += tr("; axis %1: residual vibration %2 mm shaped, %3 mm unshaped")
                            .arg(QString::fromStdString(
                                     session_.axes.at(static_cast<std::size_t>(i)).id)
                                     .toUpper(),
                                 displayNumber(s->residualShapedMm),
                                 displayNumber(s->residualUnshapedMm));
        lines << text;
    }
    const CrossCoupling& cc = session_.crossCoupling;
    if (cc.active())
        lines << tr("cross-coupled contouring controller (Koren): k<sub>p</sub> = %1 V/mm, "
                    "k<sub>i</sub> = %2 V/(mm s), %3 contour estimate")
                     .arg(coefficientText(cc.kp), coefficientText(cc.ki),
                          QString::fromUtf8(contourEstimateName(cc.estimate)));
    if (!evaluation_.couplingError.text.empty())
        lines << tr("cross-coupling: %1").arg(escapedDiagnostic(evaluation_.couplingError));
    html += listHtml(lines);
    for (const ReportFigure& f : figures)
        html += figureHtml(f);
    return html;
}

} // namespace xyt::ui
