// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/session/session.h"
#include "core/session/session_evaluation.h"
#include "ui/plots/plot_widget.h"

#include <qcustomplot.h>

#include <QStringList>

#include <array>
#include <memory>

namespace xyt::ui {

class PlotNotice;

/**
 * The XY plane: the commanded path, the traced path, and the traced path with its error
 * magnified by a factor (as a ballbar plot does: radially for the circle preset, along the
 * error vector for a straight move, along the path normal for a G-code program), with the
 * contour error figures. Equal scales on both axes.
 *
 * For a G-code program (SessionEvaluation::program) the commanded curve is the programmed path
 * (lines and arcs of the core's Path), the magnified error is coloured by its size (the base
 * curve below a quarter of the largest |e|, then three overlays from 1/4, 1/2 and 3/4 of it),
 * the worst point is marked, and the sharp corners can be stepped through (zoomToCorner). For
 * a program that is one full circle the polar (ballbar) mode draws the ISO 230-4 test of
 * contour_run.h: both runs' radial deviation magnified about the nominal centre, the F max/F min
 * circles about it and the two circles about the least-squares centre whose separation is G.
 */
class ContourPlot : public PlotWidget {
    Q_OBJECT
public:
    explicit ContourPlot(QWidget* parent = nullptr);
    /// Leaves @p px at the right end of the title row free for the view's buttons.
    void reserveTitleRoom(int px);
    ~ContourPlot() override;

    /// @p notices: what the live evaluation changed (TuningSession::liveNotice), shown on the plot.
    void showSession(const Session& session, const SessionEvaluation& evaluation,
                     const QStringList& notices = {});
    void setMagnification(double factor);
    double magnification() const { return magnification_; }

    /// The ballbar view of a single-circle program (ignored when polarAvailable() is false).
    void setPolar(bool polar);
    bool polar() const { return polar_ && polarAvailable(); }
    bool polarAvailable() const;

    /// The sharp corners of the shown program (ContourErrorResult::corners).
    int cornerCount() const;
    /// Zooms onto corner @p index (centred on it, showing its window and its magnified error);
    /// returns false when there is no such corner.
    bool zoomToCorner(int index);
    int currentCorner() const { return corner_; }
    /// Fits the whole path again (the corner stepping ends).
    void fitAll();

    QCPCurve* commandedCurve() const { return commanded_; }
    QCPCurve* tracedCurve() const { return traced_; }
    QCPCurve* magnifiedCurve() const { return magnified_; }
    /// Overlays of the magnified error from 1/4, 1/2, 3/4 of its largest |e| (G-code only).
    const std::array<QCPCurve*, 3>& errorBands() const { return bands_; }
    /// The traced point of the largest contour error (ContourErrorResult::maxPoint).
    QCPGraph* worstMarker() const { return worst_; }
    QCPGraph* cornerMarkers() const { return corners_; }
    /// Polar mode: the reverse run, the F max/F min circles, the G circles (inner, outer).
    QCPCurve* reverseCurve() const { return reverse_; }
    /// The ballbar's first run without the friction compensation (empty without one).
    QCPCurve* uncompensatedCurve() const { return uncompensated_; }
    /// The same run with the axes independent, beside a cross-coupled one (else empty).
    QCPCurve* independentCurve() const { return independent_; }
    /// ... and without the axes' feedforward (ContourRun::feedbackOnly; else empty).
    QCPCurve* feedbackOnlyCurve() const { return feedbackOnly_; }
    QCPCurve* fMaxCircle() const { return fMax_; }
    QCPCurve* fMinCircle() const { return fMin_; }
    QCPCurve* gInnerCircle() const { return gInner_; }
    QCPCurve* gOuterCircle() const { return gOuter_; }
    QString figuresText() const;
    QString noticeText() const;

signals:
    /// The corner shown changed (-1: none), or the program and its corners did.
    void cornerChanged(int index, int count);

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    void fitEqualScale();
    void showBox(double minX, double maxX, double minY, double maxY);
    void showCornerBox();
    void redraw();
    void drawPresetRun();
    void drawProgram();
    void drawCircularTest();
    void clearCurves();
    /// Row 1 holds the legend when it has entries, else a spacer (see the definition).
    void showLegendRow(bool show);

    QCPCurve* commanded_;
    QCPCurve* traced_;
    QCPCurve* magnified_;
    std::array<QCPCurve*, 3> bands_{};
    QCPGraph* worst_;
    QCPGraph* corners_;
    QCPCurve* reverse_;
    QCPCurve* uncompensated_;
    QCPCurve* independent_;
    QCPCurve* feedbackOnly_;
    QCPLayoutElement* legendSpacer_ = nullptr; ///< row 1 while the legend is empty
    QCPCurve* fMax_;
    QCPCurve* fMin_;
    QCPCurve* gInner_;
    QCPCurve* gOuter_;
    QCPTextElement* figures_;
    std::unique_ptr<PlotNotice> notice_;
    double magnification_ = 10.0;
    QSize fittedRectSize_; ///< the axis rect's size at the last equal-scale fit
    bool polar_ = false;
    int corner_ = -1;
    Session session_;
    SessionEvaluation evaluation_;
    QStringList notices_;
    bool hasData_ = false;
};

} // namespace xyt::ui
