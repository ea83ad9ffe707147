// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/session/tuning_session.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/session/design_method_module.h"
#include "core/session/pid_feedforward_method.h"
#include "ui/session/diagnostic_text.h"

#include <QLocale>
#include <QUndoCommand>

#include <algorithm>
#include <cmath>

namespace xyt::ui {

/// One undo step: the whole session before and after (the session is a few hundred bytes).
class SessionCommand : public QUndoCommand {
public:
    SessionCommand(TuningSession* owner, Session before, Session after, const QString& text,
                   int mergeKey)
        : QUndoCommand(text), owner_(owner), before_(std::move(before)), after_(std::move(after)),
          mergeKey_(mergeKey) {}

    void undo() override { owner_->assign(before_); }
    void redo() override { owner_->assign(after_); }
    int id() const override { return mergeKey_; }
    bool mergeWith(const QUndoCommand* other) override {
        if (other->id() != id() || mergeKey_ < 0)
            return false;
        after_ = static_cast<const SessionCommand*>(other)->after_;
        // The entry names where the drag ended, not its first step.
        setText(other->text());
        return true;
    }

private:
    TuningSession* owner_;
    Session before_;
    Session after_;
    int mergeKey_;
};

Session TuningSession::liveSessionOf(const Session& s, QString& notice) {
    notice.clear();
    Session live = s;
    const double duration = s.trajectory.effectiveDurationSeconds();
    const double dt = s.trajectory.dtSeconds;
    if (!(duration > 0.0) || !(dt > 0.0) || !std::isfinite(duration / dt))
        return live; // the evaluation names the bad field
    const double samples = duration / dt + 1.0;
    if (samples <= TuningSession::kLiveSampleLimit)
        return live;
    live.trajectory.dtSeconds = duration / (TuningSession::kLiveSampleLimit - 1.0);
    notice = QObject::tr("live view simulated at dt = %1 s, not %2 s: %3 samples exceed the live "
                         "limit of %4 (the exports and the report use dt = %2 s)")
                 .arg(QString::number(live.trajectory.dtSeconds, 'g', 3),
                      QString::number(dt, 'g', 6), QLocale().toString(samples, 'f', 0),
                      QLocale().toString(TuningSession::kLiveSampleLimit, 'f', 0));
    return live;
}

TuningSession::TuningSession(QObject* parent) : QObject(parent) {
    session_ = Session::paperDefault();
    live_ = liveSessionOf(session_, liveNotice_);
    evaluation_ = evaluateSession(live_);
}

const AxisEvaluation& TuningSession::axisEvaluation(int axis) const {
    return evaluation_.axes.at(static_cast<std::size_t>(axis));
}

void TuningSession::assign(const Session& next) {
    session_ = next;
    live_ = liveSessionOf(session_, liveNotice_);
    evaluation_ = evaluateSession(live_);
    locus_ = {};
    parameterLocus_ = {};
    frequency_ = {};
    ++revision_;
    emit designChanged();
}

void TuningSession::apply(const Session& next, const QString& description, int mergeKey) {
    if (next == session_)
        return; // no undo step (nor a modified flag) for a change that changes nothing
    undo_.push(new SessionCommand(this, session_, next, description, mergeKey));
}

const AxisEvaluation& TuningSession::snapshotEvaluation(std::size_t index, int axis) const {
    QString ignored;
    Session evaluated = liveSessionOf(session_.withDesign(session_.snapshots.at(index)), ignored);
    evaluated.snapshots.clear(); // what the run depends on, not the list it came from
    SnapshotCache& cache = snapshotCache_;
    if (cache.evaluation && cache.axis == axis && cache.evaluated == evaluated)
        return *cache.evaluation;
    cache.evaluation = evaluateAxis(evaluated, axis);
    cache.evaluated = std::move(evaluated);
    cache.axis = axis;
    ++cache.computed;
    return *cache.evaluation;
}

ResultStamp TuningSession::stamp(int axis, ResultScope scope) const {
    return {revision_, scope == ResultScope::BothAxes ? -1 : axis, scope, session_};
}

bool TuningSession::isCurrent(const ResultStamp& stamp) const {
    return stamp.revision == revision_ ||
           sessionsAgree(stamp.session, session_, std::max(stamp.axis, 0), stamp.scope);
}

QString methodDisplayName(DesignMethod method) {
    return coreText("xyt::MethodName", std::string(designMethodModule(method).displayName()));
}

namespace {

QString axisDesignWords(const Session& s, int axis) {
    const AxisSettings& a = s.axes.at(static_cast<std::size_t>(axis));
    if (a.method == DesignMethod::GuilleminTruxal)
        return QObject::tr("ωn = %1 rad/s, kp = %2")
            .arg(QString::number(a.gt.omegaNRadPerSec, 'g', 4), QString::number(a.gt.kp, 'g', 4));
    if (a.method != DesignMethod::PolePlacementZpetc) {
        // A registered method: its name and its parameters.
        QStringList words{methodDisplayName(a.method)};
        for (const MethodParameter& p : designMethodModule(a.method).parameters()) {
            const auto it = a.parameters.find(p.name);
            words << QStringLiteral("%1 = %2").arg(
                QString::fromStdString(p.name),
                QString::number(it == a.parameters.end() ? p.defaultValue : it->second, 'g', 4));
        }
        return words.join(QStringLiteral(", "));
    }
    return QObject::tr("pole placement, t1 = %1, Ts = %2 s%3")
        .arg(QString::number(a.pp.t1, 'g', 4), QString::number(a.pp.tsSeconds, 'g', 4),
             a.pp.zpetcEnabled ? QObject::tr(", ZPETC") : QString());
}

QString axisPlantWords(const Session& s, int axis) {
    const AxisSettings& a = s.axes.at(static_cast<std::size_t>(axis));
    if (a.method != DesignMethod::GuilleminTruxal)
        return methodDisplayName(a.method);
    return QObject::tr("plant k0 = %1, a1 = %2, a2 = %3")
        .arg(QString::number(a.gt.plant.k0, 'g', 5), QString::number(a.gt.plant.a1, 'g', 5),
             QString::number(a.gt.plant.a2, 'g', 5));
}

} // namespace

QString axisName(const Session& s, int axis) {
    return QString::fromStdString(s.axes.at(static_cast<std::size_t>(axis)).id).toUpper();
}

QString TuningSession::describe(const ResultStamp& stamp) {
    const Session& s = stamp.session;
    switch (stamp.scope) {
    case ResultScope::AxisDesign:
        return tr("axis %1, %2").arg(axisName(s, stamp.axis), axisDesignWords(s, stamp.axis));
    case ResultScope::AxisStudy:
        return tr("axis %1, %2").arg(axisName(s, stamp.axis), axisPlantWords(s, stamp.axis));
    case ResultScope::BothAxes:
        return tr("%1: %2; %3: %4")
            .arg(axisName(s, 0), axisDesignWords(s, 0), axisName(s, 1), axisDesignWords(s, 1));
    }
    return {};
}

void TuningSession::reset(const Session& next) {
    undo_.clear();
    assign(next);
    undo_.setClean();
}

void TuningSession::setCurrentAxis(int axis) {
    if (axis == currentAxis_ || axis < 0 || axis > 1)
        return;
    currentAxis_ = axis;
    emit currentAxisChanged(axis);
}

void TuningSession::setOmegaN(int axis, double omegaNRadPerSec) {
    Session next = session_;
    next.axes.at(static_cast<std::size_t>(axis)).gt.omegaNRadPerSec = omegaNRadPerSec;
    apply(next, tr("Set ωn of %1 to %2").arg(axisName(next, axis)).arg(omegaNRadPerSec),
          kMergeOmegaN + axis);
}

void TuningSession::setKp(int axis, double kp) {
    Session next = session_;
    next.axes.at(static_cast<std::size_t>(axis)).gt.kp = kp;
    apply(next, tr("Set kp of %1 to %2").arg(axisName(next, axis)).arg(kp), kMergeKp + axis);
}

void TuningSession::setPlant(int axis, const ThirdOrderPlant& plant) {
    Session next = session_;
    next.axes.at(static_cast<std::size_t>(axis)).gt.plant = plant;
    apply(next, tr("Change the plant of %1").arg(axisName(next, axis)));
}

void TuningSession::setModelUnitScale(int axis, double modelUnitsPerPositionUnit) {
    Session next = session_;
    next.axes.at(static_cast<std::size_t>(axis)).gt.modelUnitsPerPositionUnit =
        modelUnitsPerPositionUnit;
    apply(next, tr("Change the model unit of %1").arg(axisName(next, axis)));
}

void TuningSession::setFriction(int axis, const TableFriction& friction,
                                const FrictionCompensation& compensation) {
    Session next = session_;
    AxisSettings& a = next.axes.at(static_cast<std::size_t>(axis));
    a.friction = friction;
    a.frictionCompensation = compensation;
    apply(next, tr("Change the friction of %1").arg(axisName(next, axis)));
}

void TuningSession::setLoopElements(int axis, const FlexibleMode& mode, const NotchFilter& notch) {
    Session next = session_;
    GtAxisSettings& gt = next.axes.at(static_cast<std::size_t>(axis)).gt;
    gt.flexibleMode = mode;
    gt.notch = notch;
    apply(next, tr("Change the flexible mode and notch of %1").arg(axisName(next, axis)));
}

void TuningSession::setMeasuredResponse(int axis,
                                        std::shared_ptr<const MeasuredResponse> response) {
    measuredResponse_.at(static_cast<std::size_t>(axis)) = std::move(response);
    emit measurementsChanged();
}

void TuningSession::setMeasuredAcceleration(
    std::shared_ptr<const MeasuredAcceleration> acceleration) {
    measuredAcceleration_ = std::move(acceleration);
    emit measurementsChanged();
}

void TuningSession::setTrajectory(const TrajectorySettings& trajectory) {
    Session next = session_;
    next.trajectory = trajectory;
    apply(next, tr("Change the trajectory"));
}

void TuningSession::setCrossCoupling(const CrossCoupling& coupling) {
    Session next = session_;
    next.crossCoupling = coupling;
    apply(next, coupling.active() ? tr("Change the cross-coupling")
                                  : tr("Switch the cross-coupling off"));
}

void TuningSession::setUmax(double umaxVolts) {
    Session next = session_;
    next.umaxVolts = umaxVolts;
    apply(next, tr("Set the actuator limit to %1 V").arg(umaxVolts));
}

void TuningSession::setImplementation(const ImplementationSettings& implementation) {
    Session next = session_;
    next.implementation = implementation;
    apply(next, tr("Change the digital implementation"));
}

void TuningSession::setControllerTs(double seconds) {
    Session next = session_;
    next.controllerTsSeconds = seconds;
    apply(next, tr("Set the controller sample time to %1 s").arg(seconds));
}

void TuningSession::setPiDiscretization(PiDiscretization discretization) {
    Session next = session_;
    next.piDiscretization = discretization;
    apply(next, tr("Change the PI discretization"));
}

void TuningSession::setSpecificationAndLimit(const Specification& spec, double umaxVolts) {
    Session next = session_;
    next.spec = spec;
    next.umaxVolts = umaxVolts;
    apply(next, tr("Change the specification"));
}

void TuningSession::setGt(int axis, const GtAxisSettings& gt, const QString& description) {
    Session next = session_;
    next.axes.at(static_cast<std::size_t>(axis)).gt = gt;
    apply(next, description);
}

bool TuningSession::setAxis(int axis, const AxisSettings& settings, const QString& description,
                            int mergeKey) {
    Session next = session_;
    next.axes.at(static_cast<std::size_t>(axis)) = settings;
    const bool changes = !(next == session_);
    apply(next, description, mergeKey);
    return changes;
}

void TuningSession::setAxes(const std::array<AxisSettings, 2>& axes, const QString& description) {
    Session next = session_;
    next.axes = axes;
    apply(next, description);
}

void TuningSession::storeSnapshot(const QString& name) {
    Session next = session_;
    next.snapshots.push_back(next.snapshot(name.toStdString()));
    apply(next, tr("Store snapshot %1").arg(name));
}

} // namespace xyt::ui

namespace xyt::ui {

const RootLocus& TuningSession::rootLocus(int axis) const {
    auto& cached = locus_.at(static_cast<std::size_t>(axis));
    if (!cached) {
        // The loop whatever the method (for pole placement F u = -G y around A y = B u gives
        // 1 + B G / (A F) = 0).
        const std::optional<LoopTransferFunctions> loop = axisLoop(axisEvaluation(axis));
        cached = loop ? xyt::rootLocus(loop->openLoop) : RootLocus{};
    }
    return *cached;
}

const AxisFrequencyAnalysis& TuningSession::frequencyAnalysis(int axis) const {
    auto& cached = frequency_.at(static_cast<std::size_t>(axis));
    if (!cached)
        cached = analyzeAxisFrequency(liveSession(), axisEvaluation(axis));
    return *cached;
}

const ParameterLocus& TuningSession::parameterLocus(int axis, GtSweptParameter parameter) const {
    auto& cached = parameterLocus_.at(
        static_cast<std::size_t>(axis * 2 + (parameter == GtSweptParameter::Kp)));
    if (!cached) {
        const GtAxisSettings& gt = session_.axes.at(static_cast<std::size_t>(axis)).gt;
        ParameterSweep sweep;
        sweep.logSpacing = true;
        const double centre = parameter == GtSweptParameter::OmegaN ? gt.omegaNRadPerSec : gt.kp;
        sweep.from = centre / 10.0;
        sweep.to = centre * 10.0;
        sweep.count = 80;
        try {
            cached = gtParameterLocus(gt.plant, parameter, sweep,
                                      parameter == GtSweptParameter::OmegaN ? gt.kp
                                                                            : gt.omegaNRadPerSec);
        } catch (const InvalidInput& e) {
            cached = ParameterLocus{};
            cached->warnings.emplace_back(
                makeDiagnostic("field_reason", {e.field(), e.reasonDiagnostic()}));
        }
    }
    return *cached;
}

std::vector<PoleZeroSet> TuningSession::poleZeroSets(int axis) const {
    return axisPoleZeroSets(axisEvaluation(axis),
                            session().axes.at(static_cast<std::size_t>(axis)));
}

bool TuningSession::applyLoopGain(int axis, double gain) {
    return applyLoopGainTo(axis, session_.axes.at(static_cast<std::size_t>(axis)), gain);
}

bool TuningSession::applyLoopGainTo(int axis, const AxisSettings& base, double gain, int mergeKey) {
    if (!(gain > 0.0) || !std::isfinite(gain))
        return false;
    Session next = session_;
    AxisSettings& a = next.axes.at(static_cast<std::size_t>(axis));
    a = base;
    if (base.method == DesignMethod::PidFeedforward) {
        // K multiplies the controller: P, I and D (the feedforward is outside the loop).
        for (const MethodParameter& p : pidFeedforwardParameters())
            if (p.name == "p" || p.name == "i" || p.name == "d") {
                const auto it = base.parameters.find(p.name);
                a.parameters[p.name] =
                    gain * (it == base.parameters.end() ? p.defaultValue : it->second);
            }
    } else if (base.method == DesignMethod::GuilleminTruxal) {
        a.gt.kp *= gain;
        a.gt.omegaNRadPerSec *= std::pow(gain, 0.25);
    } else {
        return false;
    }
    apply(next, tr("Use loop gain %1 from the root locus").arg(gain, 0, 'g', 4), mergeKey);
    return true;
}

QString TuningSession::moveControllerZero(int axis, std::complex<double> from,
                                          std::complex<double> to) {
    const AxisEvaluation& e = axisEvaluation(axis);
    if (session_.axes.at(static_cast<std::size_t>(axis)).method != DesignMethod::PidFeedforward ||
        !e.methodDesign)
        return tr("Only a PID + feedforward axis has zeros of its own to drag.");
    const PidFeedbackGains g = pidGainsWithMovedZero(pidFeedforwardDesign(e), from, to);
    if (!g.ok)
        return diagnosticText(g.reason);
    Session next = session_;
    auto& parameters = next.axes.at(static_cast<std::size_t>(axis)).parameters;
    parameters["p"] = g.p;
    parameters["i"] = g.i;
    parameters["d"] = g.d;
    apply(next, tr("Move a zero of %1's PID").arg(axisName(next, axis)), kMergeZeroDrag + axis);
    return {};
}

void TuningSession::setMethod(int axis, DesignMethod method) {
    Session next = session_;
    next.axes.at(static_cast<std::size_t>(axis)).method = method;
    apply(next, tr("Change the design method"));
}

void TuningSession::setPp(int axis, const PpAxisSettings& pp, int mergeKey) {
    Session next = session_;
    next.axes.at(static_cast<std::size_t>(axis)).pp = pp;
    apply(next, tr("Change the pole-placement design"), mergeKey < 0 ? -1 : mergeKey + axis);
}

void TuningSession::setSpecification(const Specification& spec) {
    Session next = session_;
    next.spec = spec;
    apply(next, tr("Change the specification"));
}

} // namespace xyt::ui
