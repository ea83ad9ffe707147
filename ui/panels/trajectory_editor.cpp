// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/panels/trajectory_editor.h"

#include "core/model/errors.h"
#include "core/simulation/trajectory.h"
#include "ui/panels/fitted_stack.h"
#include "ui/panels/number_field.h"

#include <QComboBox>
#include <QFormLayout>
#include <QStackedWidget>
#include <QVBoxLayout>

namespace xyt::ui {

TrajectoryEditor::TrajectoryEditor(QWidget* parent) : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    kind_ = new QComboBox(this);
    kind_->addItem(tr("Cubic point-to-point (both axes)"));
    kind_->addItem(tr("Circle (x = R sin ωt, y = R cos ωt)"));
    kind_->setAccessibleName(tr("Trajectory kind"));
    layout->addWidget(kind_);
    pages_ = new QStackedWidget(this);
    layout->addWidget(pages_);

    auto finite = [](const char* name) {
        return [name](double v) { requireFinite(v, name); };
    };
    auto positive = [](const char* name) {
        return [name](double v) { requirePositive(v, name); };
    };
    auto nonNegative = [](const char* name) {
        return [name](double v) {
            requireFinite(v, name);
            if (v < 0)
                throw InvalidInput(name, "must be >= 0");
        };
    };
    auto* cubic = new QWidget(pages_);
    auto* cubicForm = new QFormLayout(cubic);
    cubicForm->setContentsMargins(0, 0, 0, 0);
    const QList<std::tuple<QString, QString, NumberField::Validator>> cubicFields = {
        {"x0", tr("x0 (mm)"), finite("x0")},   {"xf", tr("xf (mm)"), finite("xf")},
        {"t0", tr("t0 (s)"), nonNegative("t0")}, {"tf", tr("tf (s)"), positive("tf")},
        {"v0", tr("v0 (mm/s)"), finite("v0")}, {"vf", tr("vf (mm/s)"), finite("vf")}};
    for (const auto& [name, label, validator] : cubicFields) {
        auto* f = new NumberField(name, validator, cubic);
        fields_.insert(name, f);
        cubicForm->addRow(label, f);
    }
    auto* circle = new QWidget(pages_);
    auto* circleForm = new QFormLayout(circle);
    circleForm->setContentsMargins(0, 0, 0, 0);
    const QList<std::tuple<QString, QString, NumberField::Validator>> circleFields = {
        {"radius", tr("Radius (mm)"), positive("radius")},
        {"omega", tr("ω (rad/s)"), positive("omega")},
        {"ramp_in", tr("Ramp-in (s)"), nonNegative("ramp_in")}};
    for (const auto& [name, label, validator] : circleFields) {
        auto* f = new NumberField(name, validator, circle);
        fields_.insert(name, f);
        circleForm->addRow(label, f);
    }
    pages_->addWidget(cubic);
    pages_->addWidget(circle);
    fitStackToCurrentPage(pages_);

    auto* common = new QFormLayout;
    auto* dt = new NumberField("dt", [](double v) {
        requirePositive(v, "dt");
        if (v > 1.0)
            throw InvalidInput("dt", "must be at most 1 s");
    }, this);
    auto* duration = new NumberField("duration", [](double v) {
        requireFinite(v, "duration");
        if (v < 0)
            throw InvalidInput("duration", "must be >= 0 (0 = automatic)");
        if (v > 1.0e5)
            throw InvalidInput("duration", "must be at most 100000 s");
    }, this);
    duration->setToolTip(tr("0 = automatic: tf for a cubic, one revolution plus the ramp-in for a circle"));
    duration->setProperty("normalToolTip", duration->toolTip());
    fields_.insert("dt", dt);
    fields_.insert("duration", duration);
    common->addRow(tr("Step dt (s)"), dt);
    common->addRow(tr("Duration (s)"), duration);
    layout->addLayout(common);

    for (NumberField* f : fields_)
        connect(f, &NumberField::valueAccepted, this, &TrajectoryEditor::emitIfValid);
    connect(kind_, &QComboBox::activated, this, [this](int index) {
        pages_->setCurrentIndex(index);
        emitIfValid();
    });
}

NumberField* TrajectoryEditor::field(const QString& name) const { return fields_.value(name); }

void TrajectoryEditor::setTrajectory(const TrajectorySettings& t) {
    current_ = t;
    const int index = t.kind == TrajectoryKind::Cubic ? 0 : 1;
    kind_->setCurrentIndex(index);
    pages_->setCurrentIndex(index);
    fields_["x0"]->setValue(t.x0);
    fields_["xf"]->setValue(t.xf);
    fields_["t0"]->setValue(t.t0Seconds);
    fields_["tf"]->setValue(t.tfSeconds);
    fields_["v0"]->setValue(t.v0);
    fields_["vf"]->setValue(t.vf);
    fields_["radius"]->setValue(t.radius);
    fields_["omega"]->setValue(t.omegaRadPerSec);
    fields_["ramp_in"]->setValue(t.rampInSeconds);
    fields_["dt"]->setValue(t.dtSeconds);
    fields_["duration"]->setValue(t.durationSeconds);
}

void TrajectoryEditor::emitIfValid() {
    for (NumberField* f : fields_)
        if (f->hasError())
            return;
    TrajectorySettings t = current_;
    t.kind = kind_->currentIndex() == 0 ? TrajectoryKind::Cubic : TrajectoryKind::Circle;
    t.x0 = fields_["x0"]->value();
    t.xf = fields_["xf"]->value();
    t.t0Seconds = fields_["t0"]->value();
    t.tfSeconds = fields_["tf"]->value();
    t.v0 = fields_["v0"]->value();
    t.vf = fields_["vf"]->value();
    t.radius = fields_["radius"]->value();
    t.omegaRadPerSec = fields_["omega"]->value();
    t.rampInSeconds = fields_["ramp_in"]->value();
    t.dtSeconds = fields_["dt"]->value();
    t.durationSeconds = fields_["duration"]->value();
    if (t.kind == TrajectoryKind::Cubic && !(t.tfSeconds > t.t0Seconds)) {
        markFieldError(fields_["tf"], tr("tf: must be later than t0"));
        return;
    }
    clearFieldError(fields_["tf"], QString());
    // A run that cannot fit in memory is refused at the field the user just edited (dt unless it
    // was a time field), naming the count, never simulated.
    auto* edited = qobject_cast<NumberField*>(sender());
    NumberField* blamed = edited && QStringList{"duration", "tf", "t0", "dt"}.contains(edited->accessibleName())
                              ? edited
                              : fields_["dt"];
    const double samples = t.effectiveDurationSeconds() / t.dtSeconds + 1.0;
    if (!(samples <= static_cast<double>(sampleLimit()))) {
        markFieldError(blamed, tr("%1: a %2 s run at dt = %3 s needs %4 samples; at most %5 fit in memory")
                                   .arg(blamed->accessibleName())
                                   .arg(t.effectiveDurationSeconds(), 0, 'g', 6)
                                   .arg(t.dtSeconds, 0, 'g', 6)
                                   .arg(samples, 0, 'g', 3)
                                   .arg(static_cast<double>(sampleLimit()), 0, 'g', 3));
        return;
    }
    for (const char* name : {"duration", "tf", "t0", "dt"})
        if (!fields_[name]->hasError())
            clearFieldError(fields_[name], fields_[name]->property("normalToolTip").toString());
    if (t == current_)
        return;
    current_ = t;
    emit trajectoryEdited(t);
}

} // namespace xyt::ui
