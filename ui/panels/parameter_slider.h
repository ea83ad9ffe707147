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
 *
 * The spin box takes what the other number fields take (scientific notation included, "1e9"),
 * over the field range (by default the slider's; setFieldRange widens it). Text that is not a
 * number, or a number outside the field range, is refused with the field's message (red frame,
 * tooltip, fieldError()) and changes nothing; it is never cut to the digits that fit. A value
 * beyond the slider's range is kept exactly, the slider pinned at its end and the label beside
 * it saying so.
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
    /// The values the field accepts (a superset of the slider's range).
    void setFieldRange(double minimum, double maximum);
    /// The message of the last refused entry, empty once a value is accepted.
    QString fieldError() const { return fieldError_; }
    /// The note beside the slider: the exact value, and "beyond the slider" when it is.
    QString exactText() const;
    /// What the parameter is, its unit and what it sets (one or two sentences): the tooltip of
    /// the slider and of the field, ahead of how to type a value.
    void setDescription(const QString& description);

signals:
    void valueChanged(double value);

private:
    int toPosition(double v) const;
    double fromPosition(int position) const;
    void showValue(double v);
    void refuse(const QString& text);
    void clearFieldError();
    /// The tooltips of the slider and the field from the name and the description.
    void describe();

    QSlider* slider_;
    QDoubleSpinBox* spin_;
    QLabel* exact_;
    double min_, max_;
    bool log_;
    double value_ = 0.0;
    bool updating_ = false;
    QString name_; ///< the label without its mnemonic '&', for tooltips and messages
    QString fieldError_;
    QString description_; ///< setDescription's text (empty: the name alone)
};

} // namespace xyt::ui
