// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/session/session_evaluation.h"

#include <QColor>
#include <QMap>
#include <QSet>
#include <QStringList>
#include <QWidget>

#include <array>
#include <optional>

class QGridLayout;
class QHBoxLayout;
class QLabel;
class QScrollArea;
class QPushButton;
class QTableWidget;
class QVBoxLayout;

namespace xyt::ui {
class NumberField;
}

namespace xyt::ui {

/// The figures of both axes side by side against the editable specification, in labelled
/// groups: the tracking of the trajectory (RMSE, max error, max |u|, saturation, ITAE, ZPETC
/// improvement), the unit step of the closed loop (settling, overshoot), the digital
/// implementation (its RMSE and max error, marked where they differ from the design's
/// by more than 5 %, and the least damping of its z-plane poles), with a pass/fail
/// mark on each judged figure. Every figure has four significant digits; values that are not
/// finite show as "n/a", never as NaN.
class MetricsPanel : public QWidget {
    Q_OBJECT
public:
    explicit MetricsPanel(QWidget* parent = nullptr);
    /// Shows both axes' figures and warnings; @p liveNotice says what the live view limited.
    void showEvaluation(const Session& session, const SessionEvaluation& evaluation,
                        const QString& liveNotice = QString());
    QTableWidget* table() const { return table_; }
    NumberField* specField(const QString& name) const { return spec_.value(name); }
    /// The warnings of both axes and of the live view, one per line ("" when there are none).
    QString noticeText() const;
    /// The XY figures of a G-code program: contour error max and RMS, and for one full circle
    /// the ISO 230-4 G, F max, F min and H ("" for the presets).
    QString contourText() const;
    /// The contour figures' tooltip (the reversal spikes of a table with friction).
    QString contourToolTip() const;
    /// Why the design fails the specification, one reason per line ("" when it passes).
    QString adviceText() const;
    /// The one-line verdict beside the specification's title (adviceText is its tooltip).
    QLabel* verdictLabel() const { return advice_; }
    /// Sets the specification to the limits the design reaches (shown when that can help).
    QPushButton* relaxButton() const { return relax_; }

    /// Row order of the table: a group title row (spanning the columns) before each group.
    enum Row {
        TrackingGroup,
        Rmse,
        MaxError,
        MaxErrorPct,
        MaxU,
        Saturated,
        Itae,
        Improvement,
        MoveGroup,
        SettleAfterMove,
        FinalError,
        FinalOvershoot,
        StepGroup,
        Settling,
        Overshoot,
        DigitalGroup,
        DigitalRmse,
        DigitalMaxError,
        DigitalDamping,
        MarginGroup,
        GainMargin,
        PhaseMargin,
        DelayMargin,
        PeakSensitivity,
        RowCount
    };
    static bool isGroupRow(int row) {
        return row == TrackingGroup || row == MoveGroup || row == StepGroup ||
               row == DigitalGroup || row == MarginGroup;
    }
    static bool isMarginRow(int row) { return row > MarginGroup; }
    /// The title of figure row @p row as the table's header shows it ("RMSE (mm)"; "" for a
    /// group row), and of group row @p row ("Tracking the trajectory"; "" for a figure row):
    /// the design report names its rows with them.
    static QString rowTitle(int row);
    static QString groupTitle(int row);
    /// Fills the loop-margin rows of column @p axis from the axis' evaluation (its margins are
    /// the ones the frequency analysis draws; the panel does not need the curves, so a slider
    /// step does not compute them for the table), judged (✓/✗) against the minima with the
    /// check of the last showEvaluation. Without margins: "—" with the reason as tooltip.
    void showMargins(int axis, const AxisEvaluation& evaluation);

signals:
    void specificationEdited(const Specification& spec);

private:
    // The constructor's steps, in the order the widgets are made (their tab order).
    void buildTable();
    /// Tooltips on the row headers that need more than their short title.
    void describeRows();
    void addGroupTitles();
    void fitTableToItsRows();
    /// The verdict beside the specification's title and the button that relaxes the limits.
    void buildVerdict();
    /// The contour figures and the warnings below the table, added to @p layout.
    void buildNotices(QVBoxLayout* layout);
    void buildSpecFields();
    QHBoxLayout* specTitleRow();
    QGridLayout* specForm();
    /// Each accepted specification field emits the whole edited specification.
    void connectSpecFields();

    void fitColumns();
    void showContour(const SessionEvaluation& evaluation, bool withFriction, QStringList& notices);
    /// What one figure cell shows: its text, a pass (kPass) or fail (kFail) colour or none.
    struct Cell {
        QString text;
        QColor color = {};
        QString toolTip = {};
    };
    static constexpr QRgb kPass = 0xff1b7f2a;
    static constexpr QRgb kFail = 0xffc62828;
    static constexpr QRgb kDiffers =
        0xffb26a00; ///< a digital figure that differs from the design's
    void setCell(int row, int column, const Cell& cell);

    // showEvaluation's steps.
    void showSpecification(const Session& session);
    void showAxis(const Session& session, const AxisEvaluation& a, int column,
                  QStringList& notices);
    /// The figures of one axis by row ("—" where it has none).
    QMap<int, QString> axisFigures(const AxisEvaluation& a, bool zpetcEnabled) const;
    /// Puts the digital implementation's figure in each row the design passes and the
    /// implementation fails; returns those rows.
    QSet<int> showImplementationFigures(const AxisEvaluation& a, QMap<int, QString>& values) const;
    /// Marks a judged cell pass or fail.
    void judgeCell(Cell& cell, bool pass, bool byImplementation, bool implementationChecked) const;
    /// The tool tips that explain a figure (the reason of an axis without design, a settle
    /// after the run, the digital figures against the design's, a clip not applied).
    void explainCell(Cell& cell, int row, const AxisEvaluation& a) const;

    void showAdvice(const Session& session, const SessionEvaluation& evaluation);

    QTableWidget* table_;
    QLabel* advice_;
    QPushButton* relax_;
    std::optional<Specification> relaxed_;
    QLabel* notices_;
    QScrollArea* noticeArea_; ///< holds notices_, at most five lines tall
    QLabel* contour_;
    QMap<QString, NumberField*> spec_;
    Specification current_;
    /// Per axis, from the last showEvaluation: the margin checks (when the axis was evaluated).
    std::array<std::optional<SpecificationCheck>, 2> marginChecks_;
};

/// @p v with @p significant digits, in fixed notation from 1e-4 to 1e6 ("40553", "5.874",
/// "0.0005620"), in exponent notation beyond; "n/a" for non-finite values.
QString displayNumber(double v, int significant = 4);

} // namespace xyt::ui
