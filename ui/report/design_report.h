// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/session/session_evaluation.h"
#include "ui/report/report_figures.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QString>

#include <functional>
#include <vector>

class QTextDocument;

namespace xyt::ui {

/// What the report says about where it came from, on its title block.
struct ReportSource {
    QString sessionName; ///< the session file's name; empty for a session never saved
    QDateTime created;   ///< when the report was made
};

/**
 * The design report of a session as HTML with its figures: what a lab report or a design review
 * needs of the design. A title block (date, XY Tune's version, session file), the verdict
 * against the specification (adviseSpecification's reasons), the trajectory, actuator and
 * digital implementation; per axis the plant and where it came from (the model's origin, the
 * table's friction, a flexible mode), the method with its parameters and coefficients, the
 * controller's equations (the equations panel's) and its digital implementation (the
 * difference equation of the coefficient export, axisDigitalController; a notch's biquad), the
 * figures against the specification (ReportMetrics), the warnings, and the workbench's plots
 * (report_figures.h); then the XY contour, an input shaper and the cross-coupling.
 *
 * Everything is computed from the session and its evaluation given: the caller evaluates the
 * session it reports (evaluateSession, at the session's dt: never the live view's coarser one).
 */
class DesignReport {
    Q_DECLARE_TR_FUNCTIONS(DesignReport)
public:
    /// Called after each part is drawn: parts done, parts in all.
    using Progress = std::function<void(int done, int total)>;
    /// Parts the constructor reports progress for (both axes' plots, the contour, the text).
    static constexpr int kParts = 4;

    DesignReport(const Session& session, const SessionEvaluation& evaluation,
                 const ReportSource& source, const Progress& progress = {});

    const QString& html() const { return html_; }
    const std::vector<ReportFigure>& figures() const { return figures_; }
    /// Puts the report into @p document: its figures as image resources, its default font
    /// (10 pt) and the HTML.
    void loadInto(QTextDocument& document) const;

    /// XY Tune's version, as the title block prints it.
    static QString version();

private:
    QString titleBlock(const ReportSource& source) const;
    QString overview() const;
    QString axisSection(int axis, const std::vector<ReportFigure>& figures) const;
    QString plantHtml(int axis) const;
    QString designHtml(int axis) const;
    QString controllerHtml(int axis) const;
    QString warningsHtml(int axis) const;
    QString contourSection(const std::vector<ReportFigure>& figures) const;
    static QString figureHtml(const ReportFigure& figure);

    const Session& session_;
    const SessionEvaluation& evaluation_;
    QString html_;
    std::vector<ReportFigure> figures_;
};

} // namespace xyt::ui
