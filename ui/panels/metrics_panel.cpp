// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/panels/metrics_panel.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/session/specification_advice.h"
#include "ui/panels/number_field.h"
#include "ui/session/diagnostic_text.h"

#include <QGridLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QSet>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace xyt::ui {

QString displayNumber(double v, int significant) {
    if (!std::isfinite(v))
        return QObject::tr("n/a");
    if (v == 0.0)
        return QStringLiteral("0");
    const double magnitude = std::abs(v);
    if (magnitude >= 1e6 || magnitude < 1e-4)
        return QString::number(v, 'g', significant);
    const int exponent = static_cast<int>(std::floor(std::log10(magnitude)));
    QString text = QString::number(v, 'f', std::max(0, significant - 1 - exponent));
    // Rounding may carry into a new digit (9.9996 -> "10.000"): drop the extra one.
    if (std::abs(text.toDouble()) >= std::pow(10.0, exponent + 1) &&
        significant - 2 - exponent >= 0)
        text = QString::number(v, 'f', significant - 2 - exponent);
    return text;
}

MetricsPanel::MetricsPanel(QWidget* parent) : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    buildTable();
    describeRows();
    addGroupTitles();
    fitTableToItsRows();
    buildVerdict();
    layout->addWidget(table_);
    buildNotices(layout);
    buildSpecFields();
    layout->addLayout(specTitleRow());
    layout->addLayout(specForm());
    connectSpecFields();
}

void MetricsPanel::buildTable() {
    table_ = new QTableWidget(RowCount, 3, this);
    table_->setHorizontalHeaderLabels({tr("X"), tr("Y"), tr("spec")});
    QStringList titles;
    for (int r = 0; r < RowCount; ++r)
        titles << rowTitle(r);
    table_->setVerticalHeaderLabels(titles);
}

QString MetricsPanel::rowTitle(int row) {
    switch (row) {
    case Rmse:
    case DigitalRmse:
        return tr("RMSE (mm)");
    case MaxError:
    case DigitalMaxError:
        return tr("max |e| (mm)");
    case MaxErrorPct:
        return tr("max |e| (%)");
    case MaxU:
        return tr("max |u| (V)");
    case Saturated:
        return tr("saturated (s)");
    case Itae:
        return tr("ITAE (mm·s²)");
    case Improvement:
        return tr("ZPETC gain (%)");
    case SettleAfterMove:
        return tr("settle time (s)");
    case FinalError:
        return tr("final e (mm)");
    case FinalOvershoot:
        return tr("overrun (mm)");
    case Settling:
        return tr("settling 2 % (s)");
    case Overshoot:
        return tr("overshoot (%)");
    case DigitalDamping:
        return tr("min ζ (z-plane)");
    case GainMargin:
        return tr("gain margin (dB)");
    case PhaseMargin:
        return tr("phase margin (°)");
    case DelayMargin:
        return tr("delay margin (s)");
    case PeakSensitivity:
        return tr("Ms = max |S|");
    default:
        return QString(); // a group's title row
    }
}

QString MetricsPanel::groupTitle(int row) {
    switch (row) {
    case TrackingGroup:
        return tr("Tracking the trajectory");
    case MoveGroup:
        return tr("Move and settle (point-to-point)");
    case StepGroup:
        return tr("Unit step, as each axis runs");
    case DigitalGroup:
        return tr("Digital implementation");
    case MarginGroup:
        return tr("Loop margins (open loop L)");
    default:
        return QString();
    }
}

void MetricsPanel::describeRows() {
    // Every figure: what it is, its unit and how it is computed (one or two sentences).
    const QList<QPair<int, QString>> rows = {
        {Rmse, tr("RMSE (mm): the root mean square of the tracking error e = r − y over the "
                  "samples of the run on the trajectory.")},
        {MaxError, tr("max |e| (mm): the largest absolute tracking error e = r − y over the run "
                      "on the trajectory.")},
        {MaxErrorPct, tr("max |e| (%): the largest absolute tracking error as a percentage of "
                         "the travel; judged against the specification's maximum error.")},
        {MaxU, tr("max |u| (V): the largest absolute command applied to the plant over the run "
                  "(after the ±umax limit).")},
        {Saturated, tr("saturated (s): the time the command spends clipped at ±umax during the "
                       "run (sample count × dt).")},
        {Itae, tr("ITAE (mm·s²): the integral of t·|e(t)| over the run (trapezoidal rule on "
                  "the samples); it weighs late errors more than early ones.")},
        {Improvement, tr("ZPETC gain (%): the RMSE improvement of the ZPETC feedforward over the "
                         "loop alone, 100 (1 − RMSE with / RMSE without).")},
        {SettleAfterMove,
         tr("settle time (s): from the end of the move (tf) until |e| stays inside the "
            "in-position window; judged against the specification's settle limit.")},
        {FinalError, tr("final e (mm): the tracking error r − y at the last sample of the run.")},
        {FinalOvershoot, tr("overrun (mm): how far the axis went beyond the target after tf, "
                            "in the direction of travel (0 when it never passed it).")},
        {Settling, tr("settling 2 % (s): the time after which the closed loop's unit step stays "
                      "within ±2 % of its final value.")},
        {Overshoot, tr("overshoot (%): the unit step's peak above its final value, 100 (peak − "
                       "final)/final; judged against the specification's maximum overshoot.")},
        {DigitalRmse, tr("RMSE (mm) of the digital implementation: the same figure for the "
                         "sampled-data loop (controller at its Ts, hold, quantization, limit, "
                         "delay); amber when it differs from the design's by more than 5 %.")},
        {DigitalMaxError, tr("max |e| (mm) of the digital implementation: the largest absolute "
                             "error of the sampled-data loop's run; amber when it differs from "
                             "the design's by more than 5 %.")},
        {DigitalDamping, tr("min ζ: the least damping ratio of the digital closed loop's poles, "
                            "ζ = −Re s/|s| with s = ln z / Ts; the design's in the tooltip.")},
        {GainMargin, tr("Gain margin (dB): −20 log10 |L(jω180)| at the phase crossover ω180 "
                        "where arg L = −180°: how much the loop gain may grow before the closed "
                        "loop becomes unstable; ∞: never. Computed on the continuous loop.")},
        {PhaseMargin, tr("Phase margin (°): 180° + arg L(jωc) at the gain crossover ωc where "
                         "|L| = 1; computed on the continuous loop.")},
        {DelayMargin, tr("Delay margin (s): the extra loop delay the closed loop tolerates, "
                         "phase margin (rad) / ωc, the smallest over the gain crossovers.")},
        {PeakSensitivity, tr("Ms: the peak of the sensitivity |S(jω)| = |1/(1 + L(jω))|, i.e. 1 / "
                             "the closest distance of L to −1; 1.2–2 is a usual target.")}};
    for (const auto& [row, tip] : rows)
        table_->verticalHeaderItem(row)->setToolTip(tip);
}

void MetricsPanel::addGroupTitles() {
    // Group titles: which system and which signal each block of figures belongs to.
    for (const int row : {TrackingGroup, MoveGroup, StepGroup, DigitalGroup, MarginGroup}) {
        const QString title = groupTitle(row);
        table_->setSpan(row, 0, 1, 3);
        auto* item = new QTableWidgetItem(title);
        QFont bold = item->font();
        bold.setBold(true);
        item->setFont(bold);
        item->setBackground(QColor(0xee, 0xee, 0xee));
        item->setFlags(Qt::ItemIsEnabled);
        table_->setItem(row, 0, item);
        table_->verticalHeaderItem(row)->setText(QString());
    }
    table_->item(StepGroup, 0)
        ->setToolTip(tr(
            "Guillemin–Truxal: the step of G_R(s), the continuous closed loop. Pole placement: the "
            "step previewed through the ZPETC feedforward and the loop when ZPETC is on, else the "
            "step of the feedback loop Kf·B/T alone."));
    table_->item(DigitalGroup, 0)
        ->setToolTip(tr(
            "The controller at its sample time with the hold, the encoder and DAC quantization, "
            "the "
            "limit, the anti-windup and the delay of the Digital implementation settings. An amber "
            "figure differs from the design's above by more than 5 %."));
}

void MetricsPanel::fitTableToItsRows() {
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    // Columns as wide as their figures (nothing cut to "0.000562..."); the spec column takes
    // what is left.
    table_->horizontalHeader()->setMinimumSectionSize(36);
    table_->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Interactive);
    table_->horizontalHeader()->setSectionResizeMode(1, QHeaderView::Interactive);
    table_->horizontalHeader()->setSectionResizeMode(2, QHeaderView::Stretch);
    table_->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    table_->setWordWrap(false);
    // One line per row, all the same height: fixed, so that a new figure does not make the
    // view measure every row again (ResizeToContents cost a third of a slider step's repaint).
    table_->verticalHeader()->setSectionResizeMode(QHeaderView::Fixed);
    // fontMetrics().height() + 2: the text's line with a pixel either side, so that
    // the digital implementation's group fits a 1366x768 window with the others.
    table_->verticalHeader()->setMinimumSectionSize(table_->fontMetrics().height() + 2);
    table_->verticalHeader()->setDefaultSectionSize(table_->fontMetrics().height() + 2);
    table_->setAccessibleName(tr("Metrics"));
    // Exactly as tall as its rows (they are fixed): not AdjustToContents, which asks the whole
    // window for a new layout at every figure that changes.
    table_->setSizeAdjustPolicy(QAbstractScrollArea::AdjustIgnored);
    table_->setFixedHeight(table_->horizontalHeader()->sizeHint().height() +
                           RowCount * table_->verticalHeader()->defaultSectionSize() +
                           2 * table_->frameWidth());
}

void MetricsPanel::buildVerdict() {
    // Whether the design meets the specification, why not (tooltip), and the limits it would
    // meet (the default specification, Braga et al.'s, fails every design): on the
    // specification's title line and beside its last field, where the panel has room at
    // 1366x768.
    advice_ = new QLabel(this);
    advice_->setTextFormat(Qt::PlainText);
    advice_->setAccessibleName(tr("Why the specification fails"));
    relax_ = new QPushButton(tr("Relax the limits"), this);
    relax_->setEnabled(false);
    connect(relax_, &QPushButton::clicked, this, [this] {
        if (relaxed_)
            emit specificationEdited(*relaxed_);
    });
    // Fixed sizes: nothing here may ask the window for a new layout on a slider step.
    advice_->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
    advice_->setFixedHeight(advice_->fontMetrics().height() + 2);
    relax_->setFixedSize(relax_->sizeHint());
}

void MetricsPanel::buildNotices(QVBoxLayout* layout) {
    contour_ = new QLabel(this);
    contour_->setWordWrap(true);
    contour_->setTextFormat(Qt::PlainText);
    contour_->setAccessibleName(tr("Contour error figures"));
    contour_->setVisible(false);
    layout->addWidget(contour_);
    notices_ = new QLabel(this);
    notices_->setWordWrap(true);
    notices_->setTextFormat(Qt::PlainText);
    notices_->setStyleSheet(QStringLiteral("QLabel { background: #fff4d6; border: 1px solid "
                                           "#e0b24a; border-radius: 3px; padding: 3px; }"));
    notices_->setAccessibleName(tr("Warnings"));
    notices_->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    // At most five lines tall, scrolling beyond: six warnings of a pole-placement design made
    // the panel taller than a 1366x768 screen and covered the table's last rows.
    noticeArea_ = new QScrollArea(this);
    noticeArea_->setWidget(notices_);
    noticeArea_->setWidgetResizable(true);
    noticeArea_->setFrameShape(QFrame::NoFrame);
    noticeArea_->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    noticeArea_->setMaximumHeight(5 * notices_->fontMetrics().lineSpacing() + 10);
    noticeArea_->setMinimumHeight(2 * notices_->fontMetrics().lineSpacing() + 10);
    noticeArea_->setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Maximum);
    noticeArea_->setVisible(false);
    layout->addWidget(noticeArea_);
}

void MetricsPanel::buildSpecFields() {
    auto positive = [](const char* name) { return [name](double v) { requirePositive(v, name); }; };
    auto nonNegative = [](const char* name, double max, const Diagnostic& range) {
        return [name, max, range](double v) {
            requireFinite(v, name);
            if (v < 0 || v > max)
                throw InvalidInput(name, range);
        };
    };
    spec_.insert("settling",
                 new NumberField("max settling time", positive("max settling time"), this));
    spec_.insert(
        "overshoot",
        new NumberField("max overshoot",
                        nonNegative("max overshoot", 1e308, makeDiagnostic("not_negative")), this));
    spec_.insert("error", new NumberField("max error", positive("max error"), this));
    spec_.insert("settle", new NumberField("max settle time", positive("max settle time"), this));
    spec_.insert("window",
                 new NumberField("in-position window", positive("in-position window"), this));
    spec_.insert("phase_margin",
                 new NumberField("min phase margin",
                                 nonNegative("min phase margin", 180.0,
                                             tr("must be 0 .. 180 degrees").toStdString()),
                                 this));
    spec_.insert("gain_margin", new NumberField("min gain margin",
                                                nonNegative("min gain margin", 1e308,
                                                            tr("must be >= 0 dB").toStdString()),
                                                this));
    spec_["settling"]->setToolTip(tr("Maximum settling time (2 % band) of the unit step"));
    spec_["error"]->setToolTip(tr("Maximum |e| as a percentage of the travel"));
    spec_["settle"]->setToolTip(
        tr("Maximum settle time after the end (tf) of a point-to-point move"));
    spec_["window"]->setToolTip(tr("In-position window of a point-to-point move: |e| ≤ this (mm)"));
    spec_["phase_margin"]->setToolTip(
        tr("Minimum phase margin (PM, degrees) of the loop; 0 = none (the paper states "
           "none). 45–60° is the usual rule."));
    spec_["gain_margin"]->setToolTip(
        tr("Minimum gain margin (GM, dB) of the loop; 0 = none. 6 dB is the usual rule."));
    spec_["overshoot"]->setToolTip(tr("Every Guillemin–Truxal design overshoots a little on a step "
                                      "(its reference model is type 2), so 0 % fails them all."));
}

QHBoxLayout* MetricsPanel::specTitleRow() {
    // The title leaves the verdict beside it the panel's width at 1366x768 (a longer title
    // cut the verdict to "hover for wh").
    auto* specTitle = new QLabel(tr("<b>Specification</b>"));
    specTitle->setToolTip(
        tr("The limits of the spec column above: each figure is judged against them"));
    auto* titleRow = new QHBoxLayout;
    titleRow->addWidget(specTitle);
    titleRow->addWidget(advice_, 1);
    return titleRow;
}

QGridLayout* MetricsPanel::specForm() {
    // Two limits a row (label, field, label, field): seven limits in four rows keep the table
    // above free of a scroll bar at 1366x768.
    auto* form = new QGridLayout;
    form->setHorizontalSpacing(6);
    form->setVerticalSpacing(3);
    // Short labels (the full wording is in each field's tooltip) keep the panel as narrow as
    // the table above, leaving the plots their width.
    const std::pair<QString, QString> cells[] = {
        {tr("settling ≤ s"), "settling"}, {tr("overshoot ≤ %"), "overshoot"},
        {tr("max |e| ≤ %"), "error"},     {tr("settle ≤ s"), "settle"},
        {tr("window mm"), "window"},      {tr("PM ≥ °"), "phase_margin"},
        {tr("GM ≥ dB"), "gain_margin"}};
    int index = 0;
    for (const auto& [label, key] : cells) {
        auto* text = new QLabel(label);
        text->setBuddy(spec_[key]);
        spec_[key]->setMinimumWidth(48);
        spec_[key]->setMaximumWidth(76);
        form->addWidget(text, index / 2, (index % 2) * 2);
        form->addWidget(spec_[key], index / 2, (index % 2) * 2 + 1);
        ++index;
    }
    form->addWidget(relax_, index / 2, (index % 2) * 2, 1, 2, Qt::AlignLeft);
    form->setColumnStretch(1, 1);
    form->setColumnStretch(3, 1);
    return form;
}

void MetricsPanel::connectSpecFields() {
    for (NumberField* f : spec_)
        connect(f, &NumberField::valueAccepted, this, [this] {
            Specification next = current_;
            next.maxSettlingTimeSeconds = spec_["settling"]->value();
            next.maxOvershootPct = spec_["overshoot"]->value();
            next.maxErrorPct = spec_["error"]->value();
            next.maxSettleTimeSeconds = spec_["settle"]->value();
            next.inPositionWindowMm = spec_["window"]->value();
            next.minPhaseMarginDeg = spec_["phase_margin"]->value();
            next.minGainMarginDb = spec_["gain_margin"]->value();
            if (!(next == current_))
                emit specificationEdited(next);
        });
}

QString MetricsPanel::noticeText() const {
    return notices_->text();
}

void MetricsPanel::setCell(int row, int column, const Cell& cell) {
    // In place, and only what changed: a replaced item makes the view lay the row out again.
    QTableWidgetItem* item = table_->item(row, column);
    if (!item) {
        item = new QTableWidgetItem;
        item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        table_->setItem(row, column, item);
    }
    if (item->text() != cell.text)
        item->setText(cell.text);
    const QBrush foreground = cell.color.isValid() ? QBrush(cell.color) : QBrush();
    if (item->foreground() != foreground)
        item->setForeground(foreground);
    if (item->toolTip() != cell.toolTip)
        item->setToolTip(cell.toolTip);
}

void MetricsPanel::fitColumns() {
    // The axis columns as wide as their widest figure. Not ResizeToContents: that would count
    // the group titles, which span all three columns, as column X's content.
    const QFontMetrics fm(table_->font());
    for (int c = 0; c < 2; ++c) {
        int width = fm.horizontalAdvance(
            table_->horizontalHeaderItem(c) ? table_->horizontalHeaderItem(c)->text() : QString());
        for (int r = 0; r < RowCount; ++r)
            if (!isGroupRow(r) && table_->item(r, c))
                width = std::max(width, fm.horizontalAdvance(table_->item(r, c)->text()));
        if (table_->columnWidth(c) != width + 12) // a resize asks the window for a new layout
            table_->setColumnWidth(c, width + 12);
    }
}

namespace {

/// Why an axis has no margins: its error, or the evaluation's "no stability margins" warning.
QString noMarginsReason(const AxisEvaluation& e) {
    if (!e.ok)
        return QString::fromStdString(e.errorField) + QStringLiteral(": ") +
               diagnosticText(e.error);
    for (const Diagnostic& w : e.warnings)
        if (w.code == "no_stability_margins")
            return diagnosticText(w);
    return QObject::tr("the axis has no loop to analyse");
}

} // namespace

void MetricsPanel::showMargins(int axis, const AxisEvaluation& e) {
    const bool ok = e.ok && e.margins.has_value();
    const StabilityMargins m = e.margins.value_or(StabilityMargins{});
    const auto shown = [](double v) {
        return std::isinf(v) && v > 0 ? QStringLiteral("∞") : displayNumber(v);
    };
    // The delay margin and Ms describe how far a stable loop is from instability; an unstable
    // closed loop has neither (its |S| peak is not the gain of anything that exists), so they
    // read "n/a" there, while the gain and phase margins still say how far the crossing is.
    const bool robustnessDefined = ok && m.closedLoopStable;
    const QMap<int, QString> values = {{GainMargin, ok ? shown(m.gainMarginDb) : tr("—")},
                                       {PhaseMargin, ok ? shown(m.phaseMarginDeg) : tr("—")},
                                       {DelayMargin, robustnessDefined ? shown(m.delayMarginSeconds)
                                                     : ok              ? tr("n/a")
                                                                       : tr("—")},
                                       {PeakSensitivity, robustnessDefined
                                                             ? shown(m.peakSensitivity)
                                                         : ok ? tr("n/a")
                                                              : tr("—")}};
    const std::optional<SpecificationCheck>& check = marginChecks_[static_cast<std::size_t>(axis)];
    for (auto it = values.begin(); it != values.end(); ++it) {
        Cell cell{it.value()};
        if (ok && check && (it.key() == GainMargin || it.key() == PhaseMargin)) {
            const bool pass = it.key() == GainMargin ? check->gainMargin : check->phaseMargin;
            cell.text += pass ? QStringLiteral(" ✓") : QStringLiteral(" ✗");
            cell.color = pass ? kPass : kFail;
        }
        if (ok && !m.closedLoopStable) {
            cell.color = kFail;
            cell.toolTip = tr("the closed loop is unstable: not a robustness measure");
        } else if (ok && it.key() == GainMargin && std::isfinite(m.gainMarginOmegaRadPerSec)) {
            cell.toolTip = tr("at %1 rad/s (factor %2)")
                               .arg(displayNumber(m.gainMarginOmegaRadPerSec))
                               .arg(displayNumber(m.gainMarginFactor));
        } else if (ok && it.key() == PhaseMargin && std::isfinite(m.phaseMarginOmegaRadPerSec)) {
            cell.toolTip = tr("at %1 rad/s").arg(displayNumber(m.phaseMarginOmegaRadPerSec));
        } else if (!ok) {
            cell.toolTip = noMarginsReason(e);
        }
        setCell(it.key(), axis, cell);
    }
    fitColumns();
}

QString MetricsPanel::contourText() const {
    return contour_->text();
}

QString MetricsPanel::contourToolTip() const {
    return contour_->toolTip();
}

QString MetricsPanel::adviceText() const {
    return advice_->toolTip();
}

void MetricsPanel::showAdvice(const Session& session, const SessionEvaluation& evaluation) {
    const SpecificationAdvice advice = adviseSpecification(session, evaluation);
    QStringList reasons;
    for (const auto& r : advice.reasons)
        reasons << diagnosticText(r);
    relaxed_ = advice.relaxed;
    // One line whose size does not change with the figures, and nothing shown or hidden: a new
    // size would make the window lay itself out again on every slider step. The reasons,
    // numbers included, are in the tooltip.
    const QString headline =
        reasons.isEmpty() ? tr("✓ both axes meet it") : tr("✗ fails: hover for why");
    if (advice_->text() != headline)
        advice_->setText(headline);
    const QString style = reasons.isEmpty() ? QStringLiteral("QLabel { color: #1b7f2a; }")
                                            : QStringLiteral("QLabel { color: #8a1c1c; }");
    if (advice_->styleSheet() != style) // a new style sheet re-polishes and lays out again
        advice_->setStyleSheet(style);
    advice_->setToolTip(reasons.join(QLatin1Char('\n')));
    relax_->setEnabled(relaxed_.has_value());
    QStringList changes;
    for (const auto& c : advice.changes)
        changes << diagnosticText(c);
    relax_->setToolTip(
        relaxed_ ? tr("Set the limits to what this design reaches: %1 (one undo step)")
                       .arg(changes.join(tr(", ")))
        : reasons.isEmpty() ? tr("The design meets the specification")
                            : tr("No limit makes this design pass (see why): change the design"));
}

void MetricsPanel::showContour(const SessionEvaluation& evaluation, bool withFriction,
                               QStringList& notices) {
    const auto mm = [](double v) { return QString::number(v, 'f', 4); };
    QStringList lines;
    if (evaluation.program) {
        const ContourErrorResult& c = evaluation.program->contour;
        lines << tr("Contour error (XY): max %1, RMS %2 mm").arg(mm(c.maxAbs), mm(c.rms));
        contour_->setToolTip(tr("The program's warnings are shown on the XY contour view"));
        if (evaluation.program->circular) {
            const ContourCircularTest& test = *evaluation.program->circular;
            const Iso230Circular& iso = test.iso;
            // One line: G, F max/F min (of each direction when there are two), H (mm).
            const QString first = test.clockwise ? tr("CW") : tr("CCW");
            const QString second = test.clockwise ? tr("CCW") : tr("CW");
            QString iso230 =
                test.reverseIso ? tr("ISO 230-4: G %1 %2, %3 %4, F %5/%6")
                                      .arg(first, mm(iso.circularDeviationG), second,
                                           mm(test.reverseIso->circularDeviationG),
                                           mm(iso.radialDeviationFMax), mm(iso.radialDeviationFMin))
                                : tr("ISO 230-4: G %1, F %2/%3")
                                      .arg(mm(iso.circularDeviationG), mm(iso.radialDeviationFMax),
                                           mm(iso.radialDeviationFMin));
            if (iso.hysteresisH)
                iso230 += tr(", H %1").arg(mm(*iso.hysteresisH));
            // With a table that has friction: the largest reversal spike on the ISO line (the
            // panel has no room for another line at 1366 x 768), each quadrant's and G without
            // the compensation in the tooltip (and on the ballbar view).
            if (withFriction && !iso.reversalSpikes.empty()) {
                QStringList spikes;
                double largest = 0.0;
                for (const ReversalSpike& spike : iso.reversalSpikes) {
                    spikes << tr("%1° %2").arg(spike.angleDeg, 0, 'f', 0).arg(mm(spike.heightMm));
                    largest = std::max(largest, std::abs(spike.heightMm));
                }
                iso230 += tr(", spikes ≤ %1").arg(mm(largest));
                QString tip = tr("Reversal spikes (mm): %1").arg(spikes.join(QStringLiteral(", ")));
                if (test.uncompensatedIso)
                    tip += tr("\nWithout the friction compensation: G %1 mm")
                               .arg(mm(test.uncompensatedIso->circularDeviationG));
                contour_->setToolTip(tip);
            }
            lines << iso230 + tr(" mm");
        }
        // The program's warnings are on the XY contour view and in the editor's summary.
    } else if (!evaluation.programError.text.empty()) {
        notices << tr("program: %1").arg(diagnosticText(evaluation.programError));
    }
    contour_->setText(lines.join(QLatin1Char('\n')));
    contour_->setVisible(!lines.isEmpty());
}

void MetricsPanel::showEvaluation(const Session& session, const SessionEvaluation& evaluation,
                                  const QString& liveNotice) {
    QStringList notices;
    if (!liveNotice.isEmpty())
        notices << liveNotice;
    showSpecification(session);
    for (int c = 0; c < 2; ++c)
        showAxis(session, evaluation.axes[static_cast<std::size_t>(c)], c, notices);
    fitColumns();
    showAdvice(session, evaluation);
    showContour(evaluation, session.axes[0].friction.active() || session.axes[1].friction.active(),
                notices);
    notices_->setText(notices.join(QLatin1Char('\n')));
    noticeArea_->setVisible(!notices.isEmpty());
}

void MetricsPanel::showSpecification(const Session& session) {
    current_ = session.spec;
    spec_["settling"]->setValue(session.spec.maxSettlingTimeSeconds);
    spec_["overshoot"]->setValue(session.spec.maxOvershootPct);
    spec_["error"]->setValue(session.spec.maxErrorPct);
    spec_["settle"]->setValue(session.spec.maxSettleTimeSeconds);
    spec_["window"]->setValue(session.spec.inPositionWindowMm);
    spec_["phase_margin"]->setValue(session.spec.minPhaseMarginDeg);
    spec_["gain_margin"]->setValue(session.spec.minGainMarginDb);
    QMap<int, QString> specText = {
        {MaxErrorPct, tr("≤ %1").arg(session.spec.maxErrorPct)},
        {MaxU, tr("≤ %1").arg(session.umaxVolts)},
        {Saturated, tr("no")},
        {SettleAfterMove, tr("≤ %1").arg(session.spec.maxSettleTimeSeconds)},
        {FinalError, tr("|e| ≤ %1").arg(session.spec.inPositionWindowMm)},
        {Settling, tr("≤ %1").arg(session.spec.maxSettlingTimeSeconds)},
        {Overshoot, tr("≤ %1").arg(session.spec.maxOvershootPct)},
        {GainMargin, tr("≥ %1").arg(session.spec.minGainMarginDb)},
        {PhaseMargin, tr("≥ %1").arg(session.spec.minPhaseMarginDeg)}};
    for (int r = 0; r < RowCount; ++r) {
        if (isGroupRow(r))
            continue;
        setCell(r, 2, Cell{specText.value(r)});
    }
}

void MetricsPanel::showAxis(const Session& session, const AxisEvaluation& a, int column,
                            QStringList& notices) {
    const auto axis = static_cast<std::size_t>(column);
    marginChecks_[axis] = a.ok && a.check.marginsApply ? std::optional(a.check) : std::nullopt;
    const QString header = QString::fromStdString(session.axes[axis].id).toUpper();
    if (!table_->horizontalHeaderItem(column) ||
        table_->horizontalHeaderItem(column)->text() != header)
        table_->setHorizontalHeaderItem(column, new QTableWidgetItem(header));
    QMap<int, QString> values = axisFigures(a, session.axes[axis].pp.zpetcEnabled);
    if (!a.ok)
        notices << tr("%1: no design (%2: %3)")
                       .arg(header, QString::fromStdString(a.errorField), diagnosticText(a.error));
    for (const Diagnostic& w : a.warnings)
        notices << tr("%1: %2").arg(header, diagnosticText(w));
    // Which rows the specification judges, and whether this axis passes them.
    QMap<int, bool> judged = {{MaxErrorPct, a.check.trackingError},
                              {MaxU, a.check.noSaturation},
                              {Saturated, a.check.noSaturation},
                              {Settling, a.check.settlingTime},
                              {Overshoot, a.check.overshoot}};
    if (a.check.settleApplies)
        judged[SettleAfterMove] = a.check.settle;
    const QSet<int> byImplementation = showImplementationFigures(a, values);
    for (int r = 0; r < RowCount; ++r) {
        if (isGroupRow(r) || isMarginRow(r))
            continue;
        Cell cell{values.value(r)};
        if (a.ok && judged.contains(r))
            judgeCell(cell, judged[r], byImplementation.contains(r),
                      a.implementationCheck.has_value());
        explainCell(cell, r, a);
        setCell(r, column, cell);
    }
}

namespace {

/// "> the run's time after tf" when the run ended before the axis settled.
QString settleText(const MoveSettleMetrics& ms) {
    // Not settled in the run: "> the run's time after tf", a lower bound an engineer can read
    // in the column's width (the duration line quotes the estimate).
    return ms.diverged            ? MetricsPanel::tr("n/a")
           : ms.settleTimeSeconds ? displayNumber(*ms.settleTimeSeconds)
                                  : MetricsPanel::tr("> %1").arg(displayNumber(
                                        std::max(0.0, ms.runEndSeconds - ms.moveEndSeconds)));
}

} // namespace

QMap<int, QString> MetricsPanel::axisFigures(const AxisEvaluation& a, bool zpetcEnabled) const {
    QMap<int, QString> values;
    if (!a.ok) {
        for (int r = 0; r < RowCount; ++r)
            values[r] = tr("—");
        return values;
    }
    const auto& m = a.metrics;
    values[Rmse] = displayNumber(m.rmse);
    values[MaxError] = displayNumber(m.maxAbsError);
    values[MaxErrorPct] = displayNumber(m.maxAbsErrorPct);
    values[MaxU] = displayNumber(m.maxAbsU);
    values[Saturated] = m.diverged     ? tr("n/a")
                        : !m.saturated ? tr("no")
                        : a.pp         ? tr("%1*").arg(displayNumber(m.saturatedTimeSeconds))
                                       : displayNumber(m.saturatedTimeSeconds);
    values[Itae] = displayNumber(m.itae);
    values[Improvement] = a.zpetc && zpetcEnabled ? displayNumber(a.improvementPct) : tr("—");
    if (a.moveSettle) {
        values[SettleAfterMove] = settleText(*a.moveSettle);
        values[FinalError] = displayNumber(a.moveSettle->finalErrorMm);
        values[FinalOvershoot] = displayNumber(a.moveSettle->finalOvershootMm);
    } else {
        for (int r : {SettleAfterMove, FinalError, FinalOvershoot})
            values[r] = tr("—");
    }
    for (int r : {DigitalRmse, DigitalMaxError, DigitalDamping})
        values[r] = tr("—");
    if (a.digital) {
        const TrackingMetrics& dm = a.digital->metrics;
        values[DigitalRmse] = displayNumber(dm.rmse);
        values[DigitalMaxError] = displayNumber(dm.maxAbsError);
        values[DigitalDamping] = displayNumber(a.digital->minDamping, 3);
    }
    values[Settling] = a.step.stable ? displayNumber(a.step.settlingTimeSeconds) : tr("unstable");
    values[Overshoot] = a.step.stable ? displayNumber(a.step.overshootPct) : tr("unstable");
    return values;
}

QSet<int> MetricsPanel::showImplementationFigures(const AxisEvaluation& a,
                                                  QMap<int, QString>& values) const {
    // Rows the design passes but its digital implementation fails show the implementation's
    // figure: the verdict is the run that will really happen.
    QSet<int> byImplementation;
    if (!a.ok || !a.implementationCheck || !a.digital)
        return byImplementation;
    const SpecificationCheck& d = a.designCheck;
    const SpecificationCheck& i = *a.implementationCheck;
    const TrackingMetrics& dm = a.digital->metrics;
    if (d.trackingError && !i.trackingError) {
        byImplementation << MaxErrorPct;
        values[MaxErrorPct] = displayNumber(dm.maxAbsErrorPct);
    }
    if (d.noSaturation && !i.noSaturation) {
        byImplementation << MaxU << Saturated;
        values[MaxU] = displayNumber(dm.maxAbsU);
        values[Saturated] = dm.diverged ? tr("n/a") : displayNumber(dm.saturatedTimeSeconds);
    }
    if (d.settleApplies && d.settle && !i.settle && a.digital->moveSettle) {
        byImplementation << SettleAfterMove;
        values[SettleAfterMove] = settleText(*a.digital->moveSettle);
    }
    return byImplementation;
}

void MetricsPanel::judgeCell(Cell& cell, bool pass, bool byImplementation,
                             bool implementationChecked) const {
    cell.text += pass ? QStringLiteral(" ✓") : QStringLiteral(" ✗");
    cell.color = pass ? kPass : kFail;
    cell.toolTip = pass ? (implementationChecked
                               ? tr("meets the specification, as designed and as implemented")
                               : tr("meets the specification"))
                        : tr("fails the specification");
    if (byImplementation) {
        cell.text += tr(" digital");
        cell.toolTip = tr("the design meets the specification here, its digital implementation "
                          "(Ts, quantization, ±umax, delay) does not: this is the "
                          "implementation's figure");
    }
}

void MetricsPanel::explainCell(Cell& cell, int r, const AxisEvaluation& a) const {
    if (!a.ok) {
        cell.toolTip =
            QString::fromStdString(a.errorField) + QStringLiteral(": ") + diagnosticText(a.error);
        return;
    }
    if (r == SettleAfterMove && a.moveSettle && !a.moveSettle->diverged &&
        !a.moveSettle->settleTimeSeconds)
        cell.toolTip = tr("not settled into ±%1 mm by the end of the run, %2 s after tf; %3")
                           .arg(displayNumber(a.moveSettle->windowMm),
                                displayNumber(std::max(0.0, a.moveSettle->runEndSeconds -
                                                                a.moveSettle->moveEndSeconds)),
                                cell.toolTip);
    if (a.digital && (r == DigitalRmse || r == DigitalMaxError)) {
        const double design = r == DigitalRmse ? a.metrics.rmse : a.metrics.maxAbsError;
        const TrackingMetrics& dm = a.digital->metrics;
        const double digital = r == DigitalRmse ? dm.rmse : dm.maxAbsError;
        const bool differs = !(std::abs(digital - design) <= 0.05 * std::abs(design));
        if (differs)
            cell.color = kDiffers;
        cell.toolTip = tr("design %1, digital %2%3")
                           .arg(displayNumber(design), displayNumber(digital),
                                differs ? tr(" (differs by more than 5 %)") : QString());
    }
    if (r == DigitalDamping && a.digital) {
        const bool low = a.digital->minDamping < 0.8 * a.digital->designMinDamping;
        if (low)
            cell.color = kFail;
        cell.toolTip = tr("digital loop %1, design %2 at Ts = %3 s")
                           .arg(displayNumber(a.digital->minDamping, 3),
                                displayNumber(a.digital->designMinDamping, 3))
                           .arg(a.digital->tsSeconds);
    }
    if (r == Saturated && a.pp && a.metrics.saturated)
        cell.toolTip = tr("* not applied: the discrete loop of Patrick, Ishak and Adnan is "
                          "simulated without a limit; |u| would be clipped this long");
}

} // namespace xyt::ui
