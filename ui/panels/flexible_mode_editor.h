// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/design/notch_filter.h"
#include "core/design/shaper_recommendation.h"
#include "core/identification/accelerometer_log.h"
#include "core/model/flexible_mode.h"
#include "core/session/session.h"

#include <QWidget>

#include <memory>

class QComboBox;
class QLabel;
class QPushButton;
class QToolButton;

namespace xyt::ui {

class FieldForm;
class NumberField;

/**
 * The "Flexible mode" fold of a Guillemin-Truxal or PID + feedforward axis: the table's
 * resonance above the rigid plant (FlexibleMode: frequency, damping, and for a two-mass model
 * the anti-resonance) and the notch after the PI (NotchFilter: centre, width, depth), with a
 * button that designs the notch from the mode (notchForMode); and the input shaper on both axes'
 * reference (ReferenceShaping: type, frequency, damping), with a button that tunes it to the
 * mode. Folded, its header says what is set. A value the core refuses stays at its field, red with
 * the reason, and nothing is applied.
 */
class FlexibleModeEditor : public QWidget {
    Q_OBJECT

public:
    explicit FlexibleModeEditor(QWidget* parent = nullptr);
    ~FlexibleModeEditor() override;
    /// Shows the axis' settings; @p continuousPlant false (a pole-placement axis, whose ARX model
    /// holds what its data showed) disables the fields with the reason; @p notchAllowed false (a
    /// PID + feedforward axis: LinuxCNC's pid has no notch stage) disables the notch's.
    void setSettings(const FlexibleMode& mode, const NotchFilter& notch, bool continuousPlant,
                     bool notchAllowed);
    /// "frequency", "damping", "anti_resonance", "anti_resonance_damping", "centre", "width",
    /// "depth".
    NumberField* field(const QString& name) const;
    QPushButton* notchFromModeButton() const { return fromMode_; }
    /// The trajectory's shaper (both axes): "none" then the seven types.
    void setShaping(const ReferenceShaping& shaping);
    QComboBox* shaperTypeBox() const { return shaperType_; }
    NumberField* shaperField(const QString& name) const;
    QPushButton* shaperAtModeButton() const { return shaperAtMode_; }
    /// Klipper's recommendation (recommendShaper) over the spectrum of the axis' mode, or of a
    /// Klipper accelerometer log; applied as the trajectory's shaper, its figures shown below
    /// the buttons (adviceText). A log the reader refuses is reported there, nothing applied.
    QPushButton* recommendFromModeButton() const { return recommendMode_; }
    QPushButton* recommendFromLogButton() const { return recommendLog_; }
    void recommendFromLog(const QString& path);
    QString adviceText() const;
    QToolButton* foldButton() const { return fold_; }

signals:
    void loopElementsEdited(const FlexibleMode& mode, const NotchFilter& notch);
    void shapingEdited(const ReferenceShaping& shaping);
    /// recommendFromLog read a log: its spectra, for the Vibration view.
    void accelerationLoaded(const AccelerometerSpectra& spectra, const QString& source);

private:
    void emitIfValid();
    void emitShapingIfValid();
    void applyRecommendation(const PowerSpectrum& spectrum, double dampingRatio,
                             const QString& source);
    void updateHeader();

    QToolButton* fold_;
    QWidget* body_;
    QPushButton* fromMode_;
    QLabel* note_;
    QComboBox* shaperType_;
    QPushButton* shaperAtMode_;
    QPushButton* recommendMode_;
    QPushButton* recommendLog_;
    QLabel* advice_;
    std::unique_ptr<FieldForm> shaperForm_;
    ReferenceShaping shaping_;
    std::unique_ptr<FieldForm> form_; ///< the mode's and the notch's fields
    FlexibleMode mode_;
    NotchFilter notch_;
    bool notchAllowed_ = true;
};

} // namespace xyt::ui
