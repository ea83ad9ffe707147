// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/panels/trajectory_editor.h"

#include "core/contour/feed_profile.h"
#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/simulation/trajectory.h"
#include "ui/panels/fitted_stack.h"
#include "ui/panels/number_field.h"
#include "ui/session/install_paths.h"

#include "core/io/file_io.h"
#include "core/session/program_trajectory.h"
#include "ui/session/diagnostic_text.h"

#include <QComboBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QStackedWidget>
#include <QVBoxLayout>

namespace xyt::ui {

TrajectoryEditor::TrajectoryEditor(QWidget* parent) : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    kind_ = new QComboBox(this);
    kind_->addItem(tr("Point-to-point (both axes)"));
    kind_->addItem(tr("Circle (x = R sin ωt, y = R cos ωt)"));
    kind_->addItem(tr("G-code program (x and y along its feed profile)"));
    kind_->setAccessibleName(tr("Trajectory kind"));
    kind_->setToolTip(
        tr("The commanded motion both axes follow: a point-to-point move, a circle "
           "(x = R sin ωt, y = R cos ωt) or a G-code program along its feed profile"));
    kind_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    kind_->setMinimumContentsLength(14);
    // The move's profile beside the kind (a row of its own would push the panel past 768 px).
    profile_ = new QComboBox(this);
    profile_->addItem(tr("cubic"));
    profile_->addItem(tr("quintic"));
    profile_->setAccessibleName(tr("Move profile"));
    profile_->setToolTip(tr("The move's profile: Braga et al.'s cubic, whose acceleration steps "
                            "at the start and the end, or the quintic, whose acceleration starts "
                            "and ends at zero, so a jerk feedforward sees no spike"));
    connect(profile_, &QComboBox::activated, this, &TrajectoryEditor::emitIfValid);
    auto* kindRow = new QHBoxLayout;
    kindRow->addWidget(kind_, 1);
    kindRow->addWidget(profile_);
    layout->addLayout(kindRow);
    pages_ = new QStackedWidget(this);
    layout->addWidget(pages_);

    auto finite = [](const char* name) { return [name](double v) { requireFinite(v, name); }; };
    auto positive = [](const char* name) { return [name](double v) { requirePositive(v, name); }; };
    auto nonNegative = [](const char* name) {
        return [name](double v) {
            requireFinite(v, name);
            if (v < 0)
                throw InvalidInput(name, makeDiagnostic("not_negative"));
        };
    };
    auto* cubic = new QWidget(pages_);
    auto* cubicForm = new QFormLayout(cubic);
    cubicForm->setContentsMargins(0, 0, 0, 0);
    const QList<std::tuple<QString, QString, NumberField::Validator>> cubicFields = {
        {"x0", tr("x0 (mm)"), finite("x0")},     {"xf", tr("xf (mm)"), finite("xf")},
        {"t0", tr("t0 (s)"), nonNegative("t0")}, {"tf", tr("tf (s)"), positive("tf")},
        {"v0", tr("v0 (mm/s)"), finite("v0")},   {"vf", tr("vf (mm/s)"), finite("vf")}};
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
    pages_->addWidget(buildProgramPage());
    fitStackToCurrentPage(pages_);

    auto* common = new QFormLayout;
    auto* dt = new NumberField(
        "dt",
        [](double v) {
            requirePositive(v, "dt");
            if (v > 1.0)
                throw InvalidInput("dt", tr("must be at most 1 s").toStdString());
        },
        this);
    auto* duration = new NumberField(
        "duration",
        [](double v) {
            requireFinite(v, "duration");
            if (v < 0)
                throw InvalidInput("duration", tr("must be >= 0 (0 = automatic)").toStdString());
            if (v > 1.0e5)
                throw InvalidInput("duration", tr("must be at most 100000 s").toStdString());
        },
        this);
    duration->setToolTip(tr("0 = automatic: tf for a cubic, one revolution plus the ramp-in for a "
                            "circle; a G-code program always runs its feed profile's time"));
    duration->setProperty("normalToolTip", duration->toolTip());
    fields_.insert("dt", dt);
    fields_.insert("duration", duration);
    // Both on one row: the panel fits 1366 x 768 with the cross-coupling fold below.
    auto* stepRow = new QWidget(this);
    auto* stepLayout = new QHBoxLayout(stepRow);
    stepLayout->setContentsMargins(0, 0, 0, 0);
    for (NumberField* f : {dt, duration}) { // as wide as the row gives, not their text's hint
        f->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
        f->setMinimumWidth(60);
    }
    stepLayout->addWidget(dt, 1);
    auto* durationLabel = new QLabel(tr("Duration (s)"), stepRow);
    durationLabel->setBuddy(duration);
    stepLayout->addWidget(durationLabel);
    stepLayout->addWidget(duration, 1);
    common->addRow(tr("Step dt (s)"), stepRow);
    describeFields();
    layout->addLayout(common);

    for (NumberField* f : fields_)
        connect(f, &NumberField::valueAccepted, this, &TrajectoryEditor::emitIfValid);
    connect(kind_, &QComboBox::activated, this, [this](int index) {
        pages_->setCurrentIndex(index);
        profile_->setVisible(index == 0);
        emitIfValid();
    });
}

NumberField* TrajectoryEditor::field(const QString& name) const {
    return fields_.value(name);
}

namespace {

int kindIndex(TrajectoryKind kind) {
    switch (kind) {
    case TrajectoryKind::Cubic:
        return 0;
    case TrajectoryKind::Circle:
        return 1;
    case TrajectoryKind::Gcode:
        break;
    }
    return 2;
}

TrajectoryKind kindAt(int index) {
    return index == 0   ? TrajectoryKind::Cubic
           : index == 1 ? TrajectoryKind::Circle
                        : TrajectoryKind::Gcode;
}

} // namespace

QWidget* TrajectoryEditor::buildProgramPage() {
    auto* page = new QWidget(pages_);
    auto* form = new QFormLayout(page);
    form->setContentsMargins(0, 0, 0, 0);
    auto* fileRow = new QHBoxLayout;
    programField_ = new QLineEdit(page);
    programField_->setReadOnly(true);
    programField_->setAccessibleName(tr("G-code program"));
    programField_->setPlaceholderText(tr("no program"));
    programField_->setMinimumWidth(80);
    open_ = new QPushButton(tr("Open…"), page);
    open_->setToolTip(tr("Read a G-code program (.nc); it is kept in the session"));
    fileRow->addWidget(programField_, 1);
    fileRow->addWidget(open_);
    form->addRow(tr("Program"), fileRow);
    examples_ = new QComboBox(page);
    examples_->setAccessibleName(tr("Example programs"));
    examples_->setToolTip(tr("The example programs shipped with XY Tune (circles, a square, a "
                             "star, an engraving): choose one to load it as the program"));
    examples_->addItem(tr("Examples…"));
    // Sized to a short name, not the longest example's: the editor column must not widen the
    // window past 1366 px (square_sharp_corners.nc did by 15 px).
    examples_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    examples_->setMinimumContentsLength(12);
    const QString folder = examplesFolder();
    if (!folder.isEmpty())
        for (const QString& name : QDir(folder).entryList({"*.nc"}, QDir::Files, QDir::Name))
            examples_->addItem(name, QDir(folder).filePath(name));
    form->addRow(QString(), examples_);
    summary_ = new QLabel(page);
    summary_->setWordWrap(true);
    summary_->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred); // wraps to the column
    form->addRow(summary_);
    auto addField = [&](const QString& name, const QString& label, NumberField::Validator v) {
        auto* f = new NumberField(name, std::move(v), page);
        fields_.insert(name, f);
        form->addRow(label, f);
    };
    addField("feed_scale", tr("Feed scale"), [](double v) { requirePositive(v, "feed_scale"); });
    // The planner's range (feed_profile.h) at the field; how long the program runs with them is
    // checked when it is planned (emitIfValid), and shown at the field too.
    addField("max_accel", tr("Max accel. (mm/s²)"), [](double v) {
        requirePositive(v, "max_accel");
        requireProfileRate(v, "max_accel", "mm/s^2");
    });
    addField("max_jerk", tr("Max jerk (mm/s³)"), [](double v) {
        requireFinite(v, "max_jerk");
        if (v < 0)
            throw InvalidInput("max_jerk", tr("must be >= 0 (0 = none)").toStdString());
        requireProfileRate(v, "max_jerk", "mm/s^3", true);
    });
    connect(open_, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getOpenFileName(
            this, tr("Open a G-code program"), examplesFolder(),
            tr("G-code programs (*.nc *.ngc *.gcode *.tap);;All files (*)"));
        if (!path.isEmpty())
            loadProgramFile(path);
    });
    connect(examples_, &QComboBox::activated, this, [this](int index) {
        const QString path = examples_->itemData(index).toString();
        examples_->setCurrentIndex(0);
        if (!path.isEmpty())
            loadProgramFile(path);
    });
    return page;
}

void TrajectoryEditor::describeFields() {
    // What each field is, its unit and how the run uses it; a field keeps its own tooltip
    // where one was set with it (duration, max_jerk).
    const QList<QPair<QString, QString>> tips = {
        {"x0", tr("Start position x0 (mm) of the point-to-point move, held before t0")},
        {"xf", tr("End position xf (mm) of the point-to-point move, reached at tf")},
        {"t0", tr("Start time t0 (s) of the move")},
        {"tf", tr("End time tf (s) of the move: the cubic (or quintic) joins x0 at t0 to xf at "
                  "tf with the end velocities v0, vf (Braga et al. Eq. 4–6)")},
        {"v0", tr("Velocity v0 (mm/s) at the start of the move")},
        {"vf", tr("Velocity vf (mm/s) at the end of the move")},
        {"radius", tr("Radius R (mm) of the circle x = R sin ωt, y = R cos ωt")},
        {"omega", tr("Angular speed ω (rad/s) of the circle: one revolution takes 2π/ω seconds")},
        {"ramp_in", tr("Ramp-in (s): the circle's speed rises smoothly from 0 to ω over this "
                       "time, so the axes do not start with a step in velocity")},
        {"feed_scale", tr("Feed scale: the feed override applied to every F word of the program "
                          "(1 = as programmed)")},
        {"max_accel", tr("Maximum acceleration (mm/s²) of the feed profile along the path; on "
                         "arcs v²/R stays below it too")},
        {"dt", tr("Simulation step dt (s): the continuous runs are sampled at it (and a G-code "
                  "program's profile is planned at it)")}};
    for (const auto& [name, tip] : tips)
        if (NumberField* f = fields_.value(name); f && f->toolTip().isEmpty())
            f->setToolTip(tip);
    if (fields_.value("max_jerk"))
        fields_["max_jerk"]->setToolTip(tr("Maximum jerk (mm/s³) of the feed profile (an "
                                           "S-curve); 0 = no jerk limit (a trapezoidal profile)"));
    // What a field shows again once an error at it is cleared.
    for (NumberField* f : fields_)
        f->setProperty("normalToolTip", f->toolTip());
    programField_->setToolTip(programToolTip(QString()));
}

QString TrajectoryEditor::programToolTip(const QString& fileName) {
    const QString what = tr("The G-code program; its whole text is kept in the session, so a "
                            "shared session needs no .nc file");
    return fileName.isEmpty() ? what : tr("%1\n%2").arg(fileName, what);
}

bool TrajectoryEditor::loadProgramFile(const QString& path) {
    const QString name = QFileInfo(path).fileName();
    std::string text;
    try {
        text = readRegularFile(path.toStdString(), kMaxProgramBytes);
    } catch (const std::exception& e) {
        const QString message = tr("%1: %2").arg(name, exceptionText(e));
        markFieldError(programField_, message);
        summary_->setText(message);
        return false;
    }
    return loadProgramText(name, text);
}

bool TrajectoryEditor::loadProgramText(const QString& fileName, const std::string& text) {
    TrajectorySettings t = current_;
    t.kind = TrajectoryKind::Gcode;
    t.gcode.fileName = fileName.toStdString();
    t.gcode.program = text;
    try {
        const ProgramSummary summary = summarizeProgram(t);
        const double samples = summary.runSeconds / t.dtSeconds + 1.0;
        if (!(samples <= static_cast<double>(sampleLimit())))
            throw InvalidInput(
                "trajectory.dt",
                tr("a %1 s run at dt = %2 s needs %3 samples; at most %4 fit in memory")
                    .arg(summary.runSeconds, 0, 'g', 6)
                    .arg(t.dtSeconds, 0, 'g', 6)
                    .arg(samples, 0, 'g', 3)
                    .arg(static_cast<double>(sampleLimit()), 0, 'g', 3)
                    .toStdString());
    } catch (const InvalidInput& e) {
        // The session keeps its trajectory; the error is shown at the program field.
        const QString message = tr("%1: %2").arg(fileName, exceptionText(e));
        markFieldError(programField_, message);
        summary_->setText(message);
        return false;
    }
    clearFieldError(programField_, programToolTip(QString()));
    current_ = t;
    setTrajectory(t);
    emit trajectoryEdited(t);
    return true;
}

void TrajectoryEditor::showProgram(const TrajectorySettings& t) {
    programField_->setText(QString::fromStdString(t.gcode.fileName));
    programField_->setCursorPosition(0); // the name's start when it is wider than the field
    programField_->setToolTip(programToolTip(QString::fromStdString(t.gcode.fileName)));
    if (t.gcode.program.empty()) {
        summary_->setText(tr("Open a program or pick an example."));
        return;
    }
    try {
        const ProgramSummary s = summarizeProgram(t);
        QString text = tr("%n motion block(s), %1 mm, run %2 s", nullptr, static_cast<int>(s.moves))
                           .arg(s.lengthMm, 0, 'f', 1)
                           .arg(s.runSeconds, 0, 'f', 2);
        if (s.corners > 0)
            text += tr(", %n sharp corner(s)", nullptr, static_cast<int>(s.corners));
        if (s.singleFullCircle)
            text += tr("; one full circle: ISO 230-4 test");
        if (!s.warnings.empty())
            text += tr("; %n warning(s)", nullptr, static_cast<int>(s.warnings.size()));
        summary_->setText(text);
        QStringList warnings;
        for (const auto& w : s.warnings)
            warnings << diagnosticText(w);
        summary_->setToolTip(warnings.join('\n'));
    } catch (const InvalidInput& e) {
        summary_->setText(exceptionText(e));
    }
}

void TrajectoryEditor::setTrajectory(const TrajectorySettings& t) {
    current_ = t;
    const int index = kindIndex(t.kind);
    kind_->setCurrentIndex(index);
    pages_->setCurrentIndex(index);
    profile_->setVisible(index == 0);
    profile_->setCurrentIndex(t.profile == MoveProfile::Quintic ? 1 : 0);
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
    fields_["feed_scale"]->setValue(t.gcode.feedScale);
    fields_["max_accel"]->setValue(t.gcode.maxAccelMmPerS2);
    fields_["max_jerk"]->setValue(t.gcode.maxJerkMmPerS3);
    showProgram(t);
    updateRefusal();
}

void TrajectoryEditor::emitIfValid() {
    emitTrajectory();
    updateRefusal();
}

void TrajectoryEditor::updateRefusal() {
    const TrajectoryKind chosen = kindAt(kind_->currentIndex());
    QString why;
    if (chosen != current_.kind) {
        const QString shown = current_.kind == TrajectoryKind::Cubic    ? tr("cubic move")
                              : current_.kind == TrajectoryKind::Circle ? tr("circle")
                                                                        : tr("G-code program");
        why = chosen == TrajectoryKind::Gcode && current_.gcode.program.empty() &&
                      programField_->text().isEmpty()
                  ? tr("The plots still show the session's %1: a G-code trajectory needs a "
                       "program (Open… or pick an example).")
                        .arg(shown)
                  : tr("The plots still show the session's %1: the trajectory chosen in the "
                       "editor is not valid yet (see the field marked red).")
                        .arg(shown);
    }
    if (why == refusal_)
        return;
    refusal_ = why;
    emit refusalChanged(refusal_);
}

bool TrajectoryEditor::emitTrajectory() {
    for (NumberField* f : fields_)
        if (f->hasError())
            return false;
    TrajectorySettings t = current_;
    t.kind = kindAt(kind_->currentIndex());
    t.profile = profile_->currentIndex() == 1 ? MoveProfile::Quintic : MoveProfile::Cubic;
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
    t.gcode.feedScale = fields_["feed_scale"]->value();
    t.gcode.maxAccelMmPerS2 = fields_["max_accel"]->value();
    t.gcode.maxJerkMmPerS3 = fields_["max_jerk"]->value();
    if (t.kind == TrajectoryKind::Gcode) {
        if (t.gcode.program.empty()) {
            markFieldError(programField_, tr("no program: open one or pick an example"));
            return false;
        }
        // A profile option the planner refuses is shown at its field, never applied.
        try {
            summarizeProgram(t);
        } catch (const InvalidInput& e) {
            const QString field = QString::fromStdString(e.field()).section('.', -1);
            markFieldError(fields_.contains(field) ? fields_[field]
                                                   : static_cast<QLineEdit*>(programField_),
                           exceptionText(e));
            return false;
        }
        clearFieldError(programField_, programToolTip(QString::fromStdString(t.gcode.fileName)));
    }
    if (t.kind == TrajectoryKind::Cubic && !(t.tfSeconds > t.t0Seconds)) {
        markFieldError(fields_["tf"], tr("tf: must be later than t0"));
        return false;
    }
    clearFieldError(fields_["tf"], fields_["tf"]->property("normalToolTip").toString());
    // A run that cannot fit in memory is refused at the field the user just edited (dt unless it
    // was a time field), naming the count, never simulated.
    auto* edited = qobject_cast<NumberField*>(sender());
    NumberField* blamed =
        edited && QStringList{"duration", "tf", "t0", "dt", "feed_scale", "max_accel", "max_jerk"}
                      .contains(edited->accessibleName())
            ? edited
            : fields_["dt"];
    const double samples = t.effectiveDurationSeconds() / t.dtSeconds + 1.0;
    if (!(samples <= static_cast<double>(sampleLimit()))) {
        markFieldError(blamed,
                       tr("%1: a %2 s run at dt = %3 s needs %4 samples; at most %5 fit in memory")
                           .arg(blamed->accessibleName())
                           .arg(t.effectiveDurationSeconds(), 0, 'g', 6)
                           .arg(t.dtSeconds, 0, 'g', 6)
                           .arg(samples, 0, 'g', 3)
                           .arg(static_cast<double>(sampleLimit()), 0, 'g', 3));
        return false;
    }
    for (const char* name : {"duration", "tf", "t0", "dt", "feed_scale", "max_accel", "max_jerk"})
        if (!fields_[name]->hasError())
            clearFieldError(fields_[name], fields_[name]->property("normalToolTip").toString());
    if (t == current_)
        return true;
    current_ = t;
    if (t.kind == TrajectoryKind::Gcode)
        showProgram(t);
    emit trajectoryEdited(t);
    return true;
}

} // namespace xyt::ui
