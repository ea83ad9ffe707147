// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QWidget>

class QDoubleSpinBox;
class QLabel;
class QSlider;

namespace xyt::ui {

/**
 * A design parameter as a slider with a linked spin box and the exact value beside it. The
 * slider maps its integer positions to [min, max] linearly or logarithmically (for ranges that
 * span decades, like kp). Tracking is on: `valueChanged` fires continuously while dragging.
 */
class ParameterSlider : public QWidget {
    Q_OBJECT
public:
    ParameterSlider(const QString& label, const QString& unit, double minimum, double maximum,
                    bool logScale, QWidget* parent = nullptr);

    double value() const { return value_; }
    /// Shows @p v without emitting valueChanged; widens the range if v is outside it.
    void setValue(double v);
    QSlider* slider() const { return slider_; }
    QDoubleSpinBox* spinBox() const { return spin_; }
    double minimum() const { return min_; }
    double maximum() const { return max_; }

signals:
    void valueChanged(double value);

private:
    int toPosition(double v) const;
    double fromPosition(int position) const;
    void showValue(double v);

    QSlider* slider_;
    QDoubleSpinBox* spin_;
    QLabel* exact_;
    double min_, max_;
    bool log_;
    double value_ = 0.0;
    bool updating_ = false;
};

} // namespace xyt::ui
