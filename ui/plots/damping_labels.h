// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <qcustomplot.h>

#include <complex>
#include <vector>

namespace xyt::ui {

/**
 * The ζ labels of a damping grid, placed each time the plot is drawn, for the view as it is
 * then (fitted, zoomed or panned): an s-plane label where its ray leaves the axis rect, a
 * z-plane label above the top of its spiral. A label that would leave the axis rect or
 * overlap one placed before it is left out: the rays of light damping converge near the
 * imaginary axis, where their labels used to stack.
 */
class DampingLabels : public QCPAbstractItem {
public:
    struct Label {
        QString text;
        std::complex<double> anchor;    ///< the ray's origin, or the label's point
        std::complex<double> direction; ///< the ray's direction; 0: the label sits at anchor
    };
    /// A label as last drawn: its text and its rectangle in the plot's pixels.
    struct Placed {
        QString text;
        QRectF rect;
    };

    explicit DampingLabels(QCustomPlot* plot);
    void setLabels(std::vector<Label> labels);
    /// The labels the last draw placed (those left out are not listed).
    const std::vector<Placed>& placed() const { return placed_; }
    double selectTest(const QPointF& pos, bool onlySelectable,
                      QVariant* details = nullptr) const override;

protected:
    void draw(QCPPainter* painter) override;

private:
    QRectF rectFor(const Label& label, const QSizeF& size, const QRectF& area) const;

    std::vector<Label> labels_;
    std::vector<Placed> placed_;
};

} // namespace xyt::ui
