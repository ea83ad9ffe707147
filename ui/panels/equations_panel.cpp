// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/panels/equations_panel.h"
#include "ui/plots/number_text.h"

#include "core/session/design_method_module.h"
#include "ui/session/diagnostic_text.h"

#include <QScrollBar>

#include <cmath>

namespace xyt::ui {

QString polynomialHtml(const Polynomial& p, const QString& variable) {
    if (p.isZero())
        return "0";
    QString out;
    bool first = true;
    for (int i = p.degree(); i >= 0; --i) {
        const double c = p.coefficient(i);
        if (c == 0.0)
            continue;
        out += first ? (c < 0 ? "−" : "") : (c < 0 ? " − " : " + ");
        const double mag = std::abs(c);
        if (mag != 1.0 || i == 0)
            out += significant(mag, 6);
        if (i > 0)
            out += variable + (i > 1 ? QString("<sup>%1</sup>").arg(i) : QString());
        first = false;
    }
    return out;
}

QString zInverseHtml(const Polynomial& p) {
    QString out;
    bool first = true;
    for (int i = 0; i <= p.degree(); ++i) {
        const double c = p.coefficient(i);
        if (c == 0.0)
            continue;
        out += first ? (c < 0 ? "−" : "") : (c < 0 ? " − " : " + ");
        out += significant(std::abs(c), 6);
        if (i > 0)
            out += QStringLiteral(" z<sup>−%1</sup>").arg(i);
        first = false;
    }
    return first ? QStringLiteral("0") : out;
}

EquationsPanel::EquationsPanel(QWidget* parent) : QTextBrowser(parent) {
    setOpenLinks(false);
    setFrameShape(QFrame::NoFrame);
    setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff); // the text wraps at the width
    // The look of the label it replaces: the window's colour, not an edit field's white.
    QPalette p = palette();
    p.setColor(QPalette::Base, p.color(QPalette::Window));
    setPalette(p);
    document()->setDocumentMargin(2);
    setAccessibleName(tr("Design equations"));
}

void EquationsPanel::showHtml(const QString& html) {
    if (html == html_)
        return;
    html_ = html;
    const int scrolled = verticalScrollBar()->value();
    setHtml(html);
    verticalScrollBar()->setValue(scrolled); // the reader keeps their place as numbers change
}

void EquationsPanel::showAxis(const AxisSettings& settings, const AxisEvaluation& axis) {
    const QString id = QString::fromStdString(settings.id).toUpper();
    if (!axis.ok) {
        showHtml(tr("<b>Axis %1</b>: %2: %3")
                     .arg(id, QString::fromStdString(axis.errorField), diagnosticText(axis.error)));
        return;
    }
    if (axis.pp) {
        const PolePlacementDesign& pp = *axis.pp;
        QString html = tr("<b>Axis %1 — pole placement + ZPETC</b> (T<sub>s</sub> = %2 s)<br>")
                           .arg(id, significant(pp.tsSeconds, 6));
        html += tr("A F + B G = T (Diophantine, Patrick, Ishak and Adnan Eq. 8)<br>");
        html += tr("A = %1<br>B = %2<br>T = %3<br>")
                    .arg(zInverseHtml(pp.a), zInverseHtml(pp.b), zInverseHtml(pp.t));
        html += tr("F = %1<br>G = %2<br>").arg(zInverseHtml(pp.f), zInverseHtml(pp.g));
        html += tr("K<sub>f</sub> = T(1)/B(1) = %1, residual %2<br>")
                    .arg(significant(pp.kf, 6), QString::number(pp.residual, 'g', 2));
        html += tr("control law: F u = K<sub>f</sub> w − G y<br>");
        if (axis.zpetc && settings.pp.zpetcEnabled) {
            const ZpetcDesign& z = *axis.zpetc;
            html += tr("ZPETC: w(k) = N/D · r(k + %1), [B<sup>−</sup>(1)]<sup>2</sup> = %2<br>")
                        .arg(z.previewSteps)
                        .arg(significant(z.gainFactor, 6));
            html += tr("N = %1<br>D = %2")
                        .arg(zInverseHtml(z.feedforwardNum), zInverseHtml(z.feedforwardDen));
        } else {
            html += tr("no feedforward: w = r");
        }
        showHtml(html);
        return;
    }
    if (!axis.gt) {
        // A registered method: its module's equations, as plain lines.
        const DesignMethodModule& module = designMethodModule(axis.method);
        QString html =
            tr("<b>Axis %1 — %2</b><br>")
                .arg(
                    id,
                    coreText("xyt::MethodName", std::string(module.displayName())).toHtmlEscaped());
        QStringList lines;
        for (const Diagnostic& line : module.equations(settings, axis))
            lines << diagnosticText(line).toHtmlEscaped();
        showHtml(html + lines.join(QStringLiteral("<br>")));
        return;
    }
    const GtDesign& d = *axis.gt;
    const double wn = d.omegaNRadPerSec;
    QString html;
    html += tr("<b>Axis %1 — Guillemin–Truxal PI</b> (ω<sub>n</sub> = %2 rad/s, k<sub>p</sub> = "
               "%3)<br>")
                .arg(id, significant(wn, 6), significant(d.kp, 6));
    html += tr("f<sub>1</sub> = a<sub>1</sub>/ω<sub>n</sub> = %1<br>").arg(significant(d.f1, 6));
    html += tr("f<sub>2</sub> = a<sub>2</sub>/ω<sub>n</sub><sup>2</sup> = %1<br>")
                .arg(significant(d.f2, 6));
    html += tr("f<sub>3</sub> = k<sub>p</sub>k<sub>0</sub>/ω<sub>n</sub><sup>3</sup> = %1<br>")
                .arg(significant(d.f3, 6));
    html += tr("ψ<sub>1</sub> = ω<sub>n</sub><sup>4</sup>/(k<sub>p</sub>k<sub>0</sub>) = %1, "
               "ψ<sub>2</sub> = %2<br>")
                .arg(significant(d.psi1, 6), significant(d.psi2, 6));
    html += tr("k<sub>i</sub> = k<sub>p</sub>ψ<sub>1</sub> = %1<br>").arg(significant(d.ki, 6));
    html += tr("G<sub>c</sub>(s) = %1 + %2/s<br>").arg(significant(d.kp, 6), significant(d.ki, 6));
    html += tr("G<sub>R</sub>(s) = (%1) / (%2)")
                .arg(polynomialHtml(d.referenceModel.num(), "s"),
                     polynomialHtml(d.referenceModel.den(), "s"));
    if (!d.stable)
        html += tr("<br><span style='color:#d32f2f'><b>The closed loop is unstable.</b></span>");
    showHtml(html);
}

} // namespace xyt::ui
