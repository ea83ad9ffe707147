// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/session/session_evaluation.h"

#include <QCoreApplication>
#include <QString>

namespace xyt::ui {

/**
 * The figures of one axis against the specification, as an HTML table for the design report:
 * the rows of the metrics panel (MetricsPanel::rowTitle, in its groups), each with its limit,
 * the figure of the design's run and of the digital implementation's, and a pass (✓) or fail
 * (✗) mark from the core's checks (AxisEvaluation::designCheck and implementationCheck,
 * checkSpecification): nothing is judged here. Figures are written as the panel writes them
 * (displayNumber: four significant digits, "n/a" for a figure that is not finite).
 */
class ReportMetrics {
    Q_DECLARE_TR_FUNCTIONS(ReportMetrics)
public:
    /// The table of axis @p axis (0 = x) of @p session, evaluated as @p evaluation.
    static QString tableHtml(const Session& session, int axis, const AxisEvaluation& evaluation);
};

} // namespace xyt::ui
