// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/session/session.h"

#include <QWidget>

#include <cstddef>
#include <string>

class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QStackedWidget;

namespace xyt::ui {

class NumberField;

/// Editor of the commanded motion: cubic point-to-point (x0, xf, t0, tf, v0, vf), circle
/// (radius, omega, ramp-in) or a G-code program (opened from a file or the examples; feed
/// scale, maximum acceleration and jerk), plus the simulation step and duration.
class TrajectoryEditor : public QWidget {
    Q_OBJECT
public:
    explicit TrajectoryEditor(QWidget* parent = nullptr);

    void setTrajectory(const TrajectorySettings& trajectory);
    QComboBox* kindBox() const { return kind_; }
    QComboBox* profileBox() const { return profile_; }
    NumberField* field(const QString& name) const;

    /// The most bytes of a program held in a session: 4 MiB, so that the session file (which
    /// embeds the program) stays within kMaxSessionFileBytes.
    static constexpr std::size_t kMaxProgramBytes = 4u * 1024u * 1024u;
    /**
     * Reads the program at @p path (bounded, regular files only) and, when it reads and plans,
     * makes it the trajectory (kind G-code) and emits trajectoryEdited. A file or program error
     * is shown at the program field (programField()) and nothing changes. The Open button and
     * the examples box call this.
     */
    bool loadProgramFile(const QString& path);
    /// The same with the text given (@p fileName is shown).
    bool loadProgramText(const QString& fileName, const std::string& text);

    QLineEdit* programField() const { return programField_; }
    QLabel* programSummary() const { return summary_; }
    QComboBox* examplesBox() const { return examples_; }
    QPushButton* openButton() const { return open_; }

    /**
     * Why the kind chosen in the editor is not the session's ("" when it is): a G-code kind
     * without a program, or with fields the planner refuses. The plots still show the session's
     * trajectory then, and the window says so over them.
     */
    QString refusal() const { return refusal_; }

signals:
    void trajectoryEdited(const TrajectorySettings& trajectory);
    void refusalChanged(const QString& refusal);

private:
    /// The tooltips of the fields: what each is, its unit and how the run uses it.
    void describeFields();
    /// The program field's tooltip: the file name (when there is one) and what the field is.
    static QString programToolTip(const QString& fileName);
    void emitIfValid();
    /// Emits the editor's trajectory when every field holds; false when one refuses it.
    bool emitTrajectory();
    void updateRefusal();
    void showProgram(const TrajectorySettings& t);
    QWidget* buildProgramPage();

    QComboBox* kind_;
    QComboBox* profile_;
    QString refusal_;
    QStackedWidget* pages_;
    QMap<QString, NumberField*> fields_;
    QLineEdit* programField_ = nullptr;
    QLabel* summary_ = nullptr;
    QComboBox* examples_ = nullptr;
    QPushButton* open_ = nullptr;
    TrajectorySettings current_;
};

} // namespace xyt::ui
