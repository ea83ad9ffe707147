// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/session/session.h"

#include "core/model/errors.h"
#include "core/session/program_trajectory.h"
#include "core/simulation/move_settle.h"

#include <cmath>
#include <numbers>

namespace xyt {

namespace {

std::shared_ptr<const ProgramState> stateOf(std::string text) {
    if (text.empty())
        return nullptr; // the empty program needs no state: a default session allocates none
    return std::make_shared<const ProgramState>(std::move(text));
}

} // namespace

ProgramText::ProgramText(std::string text) : state_(stateOf(std::move(text))) {}

ProgramText::ProgramText(const char* text) : ProgramText(std::string(text ? text : "")) {}

const std::string& ProgramText::str() const {
    static const std::string empty;
    return state_ ? state_->text : empty;
}

bool operator==(const ProgramText& a, const ProgramText& b) {
    if (a.state_ == b.state_)
        return true; // one shared text (or both empty)
    if (a.size() != b.size())
        return false;
    if (!a.state_ || !b.state_)
        return true; // both empty
    // The hash tells most different texts apart without reading them; equal hashes may still
    // be different texts.
    return a.state_->hash == b.state_->hash && a.state_->text == b.state_->text;
}

double TrajectorySettings::effectiveDurationSeconds() const {
    if (durationSeconds > 0.0 && kind != TrajectoryKind::Gcode)
        return durationSeconds;
    double shaper = 0.0;
    if (shaping.active()) {
        try {
            shaper = designInputShaper(shaping.type, shaping.frequencyHz, shaping.dampingRatio)
                         .duration();
        } catch (const InvalidInput&) {
            // the evaluation names the bad field
        }
    }
    if (kind == TrajectoryKind::Gcode) {
        try {
            return programRunSeconds(*this) + shaper;
        } catch (const InvalidInput&) {
            return 0.0; // the evaluation names the bad field
        }
    }
    if (kind == TrajectoryKind::Cubic)
        return automaticMoveCapSeconds(t0Seconds, tfSeconds + shaper, dtSeconds);
    const double w = std::abs(omegaRadPerSec);
    return (w > 0.0 ? 2.0 * std::numbers::pi / w : 0.0) + rampInSeconds + shaper;
}

DesignSnapshot Session::snapshot(const std::string& name) const {
    return {name, axes, trajectory, umaxVolts};
}

Session Session::withDesign(const DesignSnapshot& snapshot) const {
    Session s = *this;
    s.axes = snapshot.axes;
    s.trajectory = snapshot.trajectory;
    s.umaxVolts = snapshot.umaxVolts;
    return s;
}

Session Session::paperDefault() {
    Session s;
    const GtPreset lower = *findGtPreset("lower-base");
    const GtPreset upper = *findGtPreset("upper-base");
    s.axes[0].id = "x";
    s.axes[0].label = "lower base";
    s.axes[0].gt.plant = lower.plant;
    s.axes[0].gt.omegaNRadPerSec = lower.omegaNRadPerSec;
    s.axes[0].gt.kp = lower.kp;
    s.axes[0].gt.modelUnitsPerPositionUnit = lower.modelUnitsPerPositionUnit;
    s.axes[1].id = "y";
    s.axes[1].label = "upper base";
    s.axes[1].gt.plant = upper.plant;
    s.axes[1].gt.omegaNRadPerSec = upper.omegaNRadPerSec;
    s.axes[1].gt.kp = upper.kp;
    s.axes[1].gt.modelUnitsPerPositionUnit = upper.modelUnitsPerPositionUnit;
    s.axes[1].pp.a = {1.0, -1.4590, 0.4587};
    s.axes[1].pp.b = {0.0, 0.0352, 0.0599, -0.0067};
    return s;
}

bool operator==(const ModelOrigin& a, const ModelOrigin& b) {
    const auto same = [](double x, double y) { return x == y || (std::isnan(x) && std::isnan(y)); };
    if (a.standardDeviations.size() != b.standardDeviations.size())
        return false;
    for (std::size_t i = 0; i < a.standardDeviations.size(); ++i)
        if (!same(a.standardDeviations[i], b.standardDeviations[i]))
            return false;
    return a.source == b.source && a.structure == b.structure && a.tsSeconds == b.tsSeconds &&
           a.samples == b.samples && same(a.fitPercent, b.fitPercent) &&
           a.validationFitPercent.has_value() == b.validationFitPercent.has_value() &&
           (!a.validationFitPercent || same(*a.validationFitPercent, *b.validationFitPercent)) &&
           a.parameterNames == b.parameterNames && a.covariance == b.covariance;
}

} // namespace xyt
