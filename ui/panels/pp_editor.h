// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/session/session.h"

#include <QWidget>

class QCheckBox;
class QComboBox;
class QLineEdit;

namespace xyt::ui {

class NumberField;
class ParameterSlider;

/**
 * Editor of a discrete pole-placement + ZPETC axis (Patrick, Ishak and Adnan): the ARX polynomials
 * A and B in ascending powers of z^-1 (as typed in the paper), the desired pole t1 (T = 1 + t1
 * z^-1) as a slider, the sample time, and whether the ZPETC feedforward is on. Invalid entries stay
 * at the field with the reason and are not applied.
 */
class PpEditor : public QWidget {
    Q_OBJECT
public:
    explicit PpEditor(QWidget* parent = nullptr);
    void setSettings(const PpAxisSettings& settings);
    QLineEdit* aField() const { return a_; }
    QLineEdit* bField() const { return b_; }
    ParameterSlider* t1Slider() const { return t1_; }
    QCheckBox* zpetcBox() const { return zpetc_; }

signals:
    /// A change; @p mergeKey is kMergeT1 for slider drags (one undo step), -1 otherwise.
    void settingsEdited(const PpAxisSettings& settings, int mergeKey);

private:
    bool parseList(QLineEdit* field, const char* name, std::vector<double>& out);
    void emitIfValid(int mergeKey);

    QComboBox* preset_;
    QLineEdit* a_;
    QLineEdit* b_;
    ParameterSlider* t1_;
    NumberField* ts_;
    QCheckBox* zpetc_;
    PpAxisSettings current_;
};

} // namespace xyt::ui
