// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/model/diagnostic_tables.h"

namespace xyt::diagnostic_tables {

/// The warnings and refusals of core/session.
const std::vector<DiagnosticTemplate>& session() {
    static const std::vector<DiagnosticTemplate> table = {
        // The session evaluation of an axis (session_evaluation.cpp and the design methods).
        XYT_DIAGNOSTIC("closed_loop_unstable", "the closed loop is unstable"),
        XYT_DIAGNOSTIC("run_diverged", "the simulated run diverged (a sample is not a finite "
                                       "number): it has no tracking figures"),
        XYT_DIAGNOSTIC("flexible_mode_on_arx",
                       "the flexible mode and the notch of gt apply to a continuous plant: this "
                       "pole-placement axis runs its ARX model, which holds whatever mode its "
                       "data showed (identify it from a log that excites the mode)"),
        XYT_DIAGNOSTIC("run_ends_before_move",
                       "the run ends before the move does (tf): no settle figures"),
        XYT_DIAGNOSTIC("no_stability_margins", "no stability margins: %1"),
        XYT_DIAGNOSTIC("no_digital_implementation", "no digital implementation: %1"),
        XYT_DIAGNOSTIC("pp_u_exceeds_limit", "|u| exceeds the actuator limit (the discrete loop "
                                             "is simulated without saturation)"),
        XYT_DIAGNOSTIC("feedforward_beyond_limit", "the feedforward alone needs %1 V on this "
                                                   "trajectory, beyond the output limit of %2 V"),
        XYT_DIAGNOSTIC("ff3_acceleration_spike",
                       "the cubic's acceleration step becomes a %1 V spike of the FF3 term (one "
                       "controller period); the quintic move has no acceleration step"),
        XYT_DIAGNOSTIC("limit_cycle_at_rest",
                       "a limit cycle at rest: after the move the measured position keeps "
                       "oscillating (%1 mm peak to peak, %2 turns in the last half of the rest), "
                       "caused by the encoder/DAC quantization"),
        // The contour run (contour_run.cpp).
        XYT_DIAGNOSTIC("contour_axis_diverged", "%1 axis: the simulated run diverged (a sample "
                                                "is not a finite number)"),
        XYT_DIAGNOSTIC("contour_axis_saturated",
                       "%1 axis: |u| reached the actuator limit of %2 V for %3 s"),
        XYT_DIAGNOSTIC("iso230_circle_too_short",
                       "ISO 230-4: a full circle of the program lasts fewer than 3 samples: no "
                       "figures"),
        XYT_DIAGNOSTIC("circle_too_short",
                       "the circle lasts fewer than 3 samples: no ISO 230-4 figures"),
        XYT_DIAGNOSTIC("reversal_spikes", "reversal spikes up to %1 mm at the quadrant changes "
                                          "(the table's friction and backlash)"),
    };
    return table;
}

} // namespace xyt::diagnostic_tables
