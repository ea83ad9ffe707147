// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/design/model_feedforward.h"
#include "ui/panels/method_editor.h"

#include <array>
#include <optional>

class QCheckBox;
class QComboBox;
class QLabel;
class QPushButton;

namespace xyt::ui {

class MethodParameterEditor;
class ParameterSlider;

/**
 * The editor of the PID + feedforward method (core/session/pid_feedforward_method.h): the
 * feedback gains P, I, D as fields; the feedforward FF1, FF2, FF3 each as a slider in percent
 * of the plant's exact inverse (modelFeedforwardGains of the axis' plant), with the gain beside
 * it, and "From model" setting all three to 100 %; where the command's derivatives come from;
 * and the limits, filter and choices of LinuxCNC's pid as fields and a check box. A slider drag
 * is one undo step.
 */
class PidFeedforwardEditor : public MethodEditor {
    Q_OBJECT
public:
    PidFeedforwardEditor(const DesignMethodModule& module, QWidget* parent = nullptr);
    void setSettings(const AxisSettings& settings) override;

    /// The percent slider of FF1, FF2 or FF3 (@p order 1..3).
    ParameterSlider* feedforwardSlider(int order) const;
    QPushButton* fromModelButton() const { return fromModel_; }
    QComboBox* derivativeSourceBox() const { return derivativeSource_; }
    QCheckBox* derivativeOnMeasurementBox() const { return onMeasurement_; }
    MethodParameterEditor* gainsEditor() const { return gains_; }
    MethodParameterEditor* limitsEditor() const { return limits_; }
    /// The text beside the sliders: the model's gains, or why there are none.
    QString modelText() const;

private:
    void edit(const AxisSettings& next, const QString& description, int mergeKey = -1);

    AxisSettings current_;
    std::vector<MethodParameter> parameters_;
    std::optional<ModelFeedforwardGains> model_;
    MethodParameterEditor* gains_;
    MethodParameterEditor* limits_;
    std::array<ParameterSlider*, 3> sliders_{};
    QLabel* modelLabel_;
    QPushButton* fromModel_;
    QComboBox* derivativeSource_;
    QCheckBox* onMeasurement_;
};

} // namespace xyt::ui
