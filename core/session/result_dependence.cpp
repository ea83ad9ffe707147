// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/session/result_dependence.h"

#include <map>
#include <string>

namespace xyt {

namespace {

bool sameAxisSettings(const Session& a, const Session& b, int axis) {
    return a.axes.at(static_cast<std::size_t>(axis)) == b.axes.at(static_cast<std::size_t>(axis));
}

/// A method's parameters without the PI gains p and i, which a design-space map varies (the
/// feedforward and the limits a PID + feedforward axis' map runs with stay).
std::map<std::string, double> withoutPiGains(std::map<std::string, double> parameters) {
    parameters.erase("p");
    parameters.erase("i");
    return parameters;
}

bool sameRunInputs(const Session& a, const Session& b) {
    return a.trajectory == b.trajectory && a.umaxVolts == b.umaxVolts;
}

} // namespace

bool sessionsAgree(const Session& a, const Session& b, int axis, ResultScope scope) {
    switch (scope) {
    case ResultScope::AxisDesign:
        return sameAxisSettings(a, b, axis) && sameRunInputs(a, b) && a.spec == b.spec;
    case ResultScope::BothAxes:
        return sameAxisSettings(a, b, 0) && sameAxisSettings(a, b, 1) && sameRunInputs(a, b) &&
               a.spec == b.spec;
    case ResultScope::AxisStudy: {
        const AxisSettings& sa = a.axes.at(static_cast<std::size_t>(axis));
        const AxisSettings& sb = b.axes.at(static_cast<std::size_t>(axis));
        // The other limits (overshoot, error, margins) only judge the runs: the view re-judges
        // a study against them without running it again.
        return sa.method == sb.method && sa.gt.plant == sb.gt.plant &&
               withoutPiGains(sa.parameters) == withoutPiGains(sb.parameters) &&
               sa.gt.modelUnitsPerPositionUnit == sb.gt.modelUnitsPerPositionUnit &&
               sameRunInputs(a, b) && a.spec.maxSettleTimeSeconds == b.spec.maxSettleTimeSeconds &&
               a.spec.inPositionWindowMm == b.spec.inPositionWindowMm;
    }
    }
    return false;
}

} // namespace xyt
