// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/model/diagnostic_catalogue.h"

#include <stdexcept>

namespace xyt {

const std::vector<DiagnosticTemplate>& diagnosticCatalogue() {
    static const std::vector<DiagnosticTemplate> catalogue = {
        // The generic reasons of InvalidInput (errors.cpp): "<field>: <reason>".
        {"not_a_number", "must be a number, got NaN"},
        {"not_finite", "must be finite, got infinity"},
        {"not_positive", "must be greater than zero"},
        {"zero", "must be nonzero"},
        // The session evaluation of an axis (session_evaluation.cpp and the design methods).
        {"closed_loop_unstable", "the closed loop is unstable"},
        {"run_diverged", "the simulated run diverged (a sample is not a finite number): it has no "
                         "tracking figures"},
        {"flexible_mode_on_arx",
         "the flexible mode and the notch of gt apply to a continuous plant: this pole-placement "
         "axis runs its ARX model, which holds whatever mode its data showed (identify it from a "
         "log that excites the mode)"},
        {"run_ends_before_move", "the run ends before the move does (tf): no settle figures"},
        {"no_stability_margins", "no stability margins: %1"},
        {"no_digital_implementation", "no digital implementation: %1"},
        {"pp_u_exceeds_limit", "|u| exceeds the actuator limit (the discrete loop is simulated "
                               "without saturation)"},
        {"feedforward_beyond_limit", "the feedforward alone needs %1 V on this trajectory, beyond "
                                     "the output limit of %2 V"},
        {"ff3_acceleration_spike",
         "the cubic's acceleration step becomes a %1 V spike of the FF3 term (one controller "
         "period); the quintic move has no acceleration step"},
        {"limit_cycle_at_rest",
         "a limit cycle at rest: after the move the measured position keeps oscillating (%1 mm "
         "peak to peak, %2 turns in the last half of the rest), caused by the encoder/DAC "
         "quantization"},
        // The digital implementation's poles (sampled_data.cpp).
        {"digital_loop_unstable",
         "the digital loop at Ts = %1 s is unstable (its largest closed-loop pole has |z| = %2); "
         "lower the controller sample time"},
        {"digital_loop_less_damped",
         "the digital loop at Ts = %1 s is much less damped than the design (damping ratio %2 "
         "against %3 in the z-plane poles); lower the controller sample time or the delay"},
        // The contour run (contour_run.cpp).
        {"contour_axis_diverged", "%1 axis: the simulated run diverged (a sample is not a finite "
                                  "number)"},
        {"contour_axis_saturated", "%1 axis: |u| reached the actuator limit of %2 V for %3 s"},
        {"iso230_circle_too_short",
         "ISO 230-4: a full circle of the program lasts fewer than 3 samples: no figures"},
        {"circle_too_short", "the circle lasts fewer than 3 samples: no ISO 230-4 figures"},
        {"reversal_spikes", "reversal spikes up to %1 mm at the quadrant changes (the table's "
                            "friction and backlash)"},
    };
    return catalogue;
}

const char* diagnosticTemplate(std::string_view code) {
    for (const DiagnosticTemplate& t : diagnosticCatalogue())
        if (code == t.code)
            return t.englishTemplate;
    throw std::out_of_range("no diagnostic code '" + std::string(code) + "' in the catalogue");
}

std::string fillDiagnosticTemplate(std::string_view templ, const std::vector<std::string>& args) {
    std::string out;
    out.reserve(templ.size());
    for (std::size_t i = 0; i < templ.size(); ++i) {
        const char c = templ[i];
        if (c == '%' && i + 1 < templ.size() && templ[i + 1] >= '1' && templ[i + 1] <= '9') {
            const auto k = static_cast<std::size_t>(templ[i + 1] - '1');
            if (k < args.size()) {
                out += args[k];
                ++i;
                continue;
            }
        }
        out += c;
    }
    return out;
}

Diagnostic makeDiagnostic(std::string_view code, std::vector<std::string> args) {
    Diagnostic d;
    d.text = fillDiagnosticTemplate(diagnosticTemplate(code), args);
    d.code = std::string(code);
    d.args = std::move(args);
    return d;
}

} // namespace xyt
