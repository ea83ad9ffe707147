// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/session/session.h"
#include "core/session/session_evaluation.h"
#include "ui/plots/plot_widget.h"

#include <qcustomplot.h>

namespace xyt::ui {

/**
 * The XY plane: the commanded path, the traced path, and the traced path with its error
 * magnified by a factor (as a ballbar plot does: radially for a circle, along the error vector
 * for a straight move), with the contour error figures. Equal scales on both axes.
 */
class ContourPlot : public PlotWidget {
    Q_OBJECT
public:
    explicit ContourPlot(QWidget* parent = nullptr);

    void showSession(const Session& session, const SessionEvaluation& evaluation);
    void setMagnification(double factor);
    double magnification() const { return magnification_; }

    QCPCurve* commandedCurve() const { return commanded_; }
    QCPCurve* tracedCurve() const { return traced_; }
    QCPCurve* magnifiedCurve() const { return magnified_; }

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    void fitEqualScale();
    void redraw();

    QCPCurve* commanded_;
    QCPCurve* traced_;
    QCPCurve* magnified_;
    QCPTextElement* figures_;
    double magnification_ = 10.0;
    Session session_;
    SessionEvaluation evaluation_;
    bool hasData_ = false;
};

} // namespace xyt::ui
