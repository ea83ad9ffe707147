// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/model/diagnostic_tables.h"

namespace xyt::diagnostic_tables {

/// The warnings and refusals of core/simulation.
const std::vector<DiagnosticTemplate>& simulation() {
    static const std::vector<DiagnosticTemplate> table = {
        // The digital implementation's poles (sampled_data.cpp).
        XYT_DIAGNOSTIC("digital_loop_unstable",
                       "the digital loop at Ts = %1 s is unstable (its largest closed-loop pole "
                       "has |z| = %2); lower the controller sample time"),
        XYT_DIAGNOSTIC("digital_loop_less_damped",
                       "the digital loop at Ts = %1 s is much less damped than the design "
                       "(damping ratio %2 against %3 in the z-plane poles); lower the controller "
                       "sample time or the delay"),
    };
    return table;
}

} // namespace xyt::diagnostic_tables
