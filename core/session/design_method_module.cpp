// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/session/design_method_module.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/model/number_format.h"
#include "core/session/guillemin_truxal_method.h"
#include "core/session/pid_feedforward_method.h"
#include "core/session/pole_placement_method.h"

#include <algorithm>
#include <cmath>

namespace xyt {

namespace {

std::vector<const DesignMethodModule*>& registry() {
    // The built-in methods: one line each.
    static std::vector<const DesignMethodModule*> modules = {
        &guilleminTruxalMethod(),
        &polePlacementMethod(),
        &pidFeedforwardMethod(),
    };
    return modules;
}

/// The modules registered at start-up, owned for the life of the program.
std::vector<std::unique_ptr<const DesignMethodModule>>& registeredModules() {
    static std::vector<std::unique_ptr<const DesignMethodModule>> owned;
    return owned;
}

bool isKey(std::string_view name, bool allowDash) {
    return !name.empty() && name.size() <= 32 && std::all_of(name.begin(), name.end(), [&](char c) {
        return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' ||
               (allowDash && c == '-');
    });
}

std::string shown(double v) {
    return formatNumber(v);
}

/// "name = value unit".
std::string coefficientText(const DesignCoefficient& c) {
    return c.name + " = " + shown(c.value) + (c.unit.empty() ? "" : " " + c.unit);
}

} // namespace

std::unique_ptr<SteppedLoop> DesignMethodModule::steppedPath(
    const Session& /*session*/, int /*axisIndex*/, const std::vector<double>& /*t*/,
    const std::vector<double>& /*reference*/, double /*dtSeconds*/) const {
    throw InvalidInput("cross_coupling", makeDiagnostic("session_method_takes_no_coupling",
                                                        {std::string(displayName())}));
}

SampledAxisModel DesignMethodModule::couplingModel(const Session& /*session*/, int /*axisIndex*/,
                                                   double /*periodSeconds*/) const {
    throw InvalidInput("cross_coupling", makeDiagnostic("session_method_takes_no_coupling",
                                                        {std::string(displayName())}));
}

std::unique_ptr<SampledLoopStepper>
DesignMethodModule::steppedDigitalPath(const Session& /*session*/, int /*axisIndex*/,
                                       const std::vector<double>& /*t*/,
                                       const std::vector<double>& /*reference*/) const {
    throw InvalidInput("cross_coupling", makeDiagnostic("session_method_takes_no_coupling",
                                                        {std::string(displayName())}));
}

std::string DesignMethodModule::cCoupledAxis(const Session& /*session*/,
                                             const AxisEvaluation& /*axis*/,
                                             int /*axisIndex*/) const {
    throw InvalidInput("cross_coupling", makeDiagnostic("session_method_takes_no_coupling",
                                                        {std::string(displayName())}));
}

std::vector<std::string> DesignMethodModule::reportLines(const AxisSettings& /*settings*/,
                                                         const AxisEvaluation& axis) const {
    std::string line;
    for (const DesignCoefficient& c : coefficients(axis)) {
        if (!line.empty())
            line += ", ";
        line += coefficientText(c);
    }
    if (line.empty())
        return {};
    return {line};
}

std::vector<Diagnostic> DesignMethodModule::equations(const AxisSettings& /*settings*/,
                                                      const AxisEvaluation& axis) const {
    std::vector<Diagnostic> lines;
    for (const DesignCoefficient& c : coefficients(axis))
        lines.push_back(coefficientText(c));
    return lines;
}

const std::vector<const DesignMethodModule*>& designMethodModules() {
    return registry();
}

const DesignMethodModule& designMethodModule(DesignMethod method) {
    for (const DesignMethodModule* m : designMethodModules())
        if (m->method() == method)
            return *m;
    throw InvalidInput("method", makeDiagnostic("session_method_not_registered"));
}

const DesignMethodModule* findDesignMethodModule(std::string_view id) {
    for (const DesignMethodModule* m : designMethodModules())
        if (m->id() == id)
            return m;
    return nullptr;
}

void registerDesignMethodModule(std::unique_ptr<const DesignMethodModule> module) {
    if (!module)
        throw InvalidInput("method", makeDiagnostic("session_no_module"));
    const std::string id(module->id());
    if (!isKey(id, true))
        throw InvalidInput("method", makeDiagnostic("session_bad_method_id", {id}));
    for (const DesignMethodModule* m : registry())
        if (m->method() == module->method() || m->id() == module->id())
            throw InvalidInput("method", makeDiagnostic("session_method_registered", {id}));
    for (const MethodParameter& p : module->parameters())
        if (!isMethodParameterName(p.name) || !(p.minimum <= p.defaultValue) ||
            !(p.defaultValue <= p.maximum))
            throw InvalidInput("method",
                               makeDiagnostic("session_bad_method_parameter", {p.name, id}));
    registry().push_back(module.get());
    registeredModules().push_back(std::move(module));
}

bool isMethodParameterName(std::string_view name) {
    return isKey(name, false);
}

double methodParameterValue(const AxisSettings& settings, int axisIndex,
                            const MethodParameter& parameter) {
    const auto it = settings.parameters.find(parameter.name);
    if (it == settings.parameters.end())
        return parameter.defaultValue;
    const double v = it->second;
    if (!std::isfinite(v) || v < parameter.minimum || v > parameter.maximum)
        throw InvalidInput(
            "axes[" + std::to_string(axisIndex) + "].parameters." + parameter.name,
            parameter.unit.empty()
                ? makeDiagnostic("session_parameter_out_of_range",
                                 {shown(v), parameter.label, shown(parameter.minimum),
                                  shown(parameter.maximum)})
                : makeDiagnostic("session_parameter_out_of_range_unit",
                                 {shown(v), parameter.label, shown(parameter.minimum),
                                  shown(parameter.maximum), parameter.unit}));
    return v;
}

std::optional<LoopTransferFunctions> axisLoop(const AxisEvaluation& axis) {
    return designMethodModule(axis.method).loop(axis);
}

std::vector<PoleZeroSet> axisPoleZeroSets(const AxisEvaluation& axis,
                                          const AxisSettings& settings) {
    return designMethodModule(axis.method).poleZeroSets(axis, settings);
}

} // namespace xyt
