// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/design/digital_controller.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/model/translatable_text.h"

#include <cmath>

namespace xyt {

DigitalController discretizePi(double kp, double ki, double tsSeconds, PiDiscretization method) {
    requireFinite(kp, "kp");
    requireFinite(ki, "ki");
    requirePositive(tsSeconds, "ts");
    DigitalController c;
    c.tsSeconds = tsSeconds;
    c.den = {1.0, -1.0};
    if (method == PiDiscretization::Tustin)
        c.num = {kp + ki * tsSeconds / 2.0, ki * tsSeconds / 2.0 - kp};
    else
        c.num = {kp + ki * tsSeconds, -kp};
    return c;
}

std::string discretizationName(PiDiscretization method) {
    return method == PiDiscretization::Tustin
               ? XYT_TRANSLATE_NOOP("xyt::Discretization", "tustin")
               : XYT_TRANSLATE_NOOP("xyt::Discretization", "backward-euler");
}

std::string antiWindupName(AntiWindup method) {
    switch (method) {
    case AntiWindup::None:
        return XYT_TRANSLATE_NOOP("xyt::AntiWindup", "none");
    case AntiWindup::Clamp:
        return XYT_TRANSLATE_NOOP("xyt::AntiWindup", "clamp");
    case AntiWindup::BackCalculation:
        break;
    }
    return XYT_TRANSLATE_NOOP("xyt::AntiWindup", "back-calculation");
}

DigitalPi digitalPi(double kp, double ki, double tsSeconds, PiDiscretization method,
                    AntiWindup antiWindup, double trackingTimeSeconds) {
    requireFinite(kp, "kp");
    requireFinite(ki, "ki");
    requirePositive(tsSeconds, "ts");
    requireFinite(trackingTimeSeconds, "tracking_time");
    if (trackingTimeSeconds < 0.0)
        throw InvalidInput("tracking_time", makeDiagnostic("design_tracking_time_not_negative"));
    DigitalPi pi;
    pi.kp = kp;
    pi.tsSeconds = tsSeconds;
    pi.antiWindup = antiWindup;
    if (method == PiDiscretization::Tustin)
        pi.c0 = pi.c1 = ki * tsSeconds / 2.0;
    else
        pi.c0 = ki * tsSeconds;
    if (antiWindup == AntiWindup::BackCalculation) {
        const double tt = trackingTimeSeconds > 0.0 ? trackingTimeSeconds : kp / ki;
        if (!std::isfinite(tt) || !(tt > 0.0))
            throw InvalidInput("tracking_time", makeDiagnostic("design_ti_not_positive"));
        pi.trackingGain = tsSeconds / tt;
    }
    return pi;
}

std::vector<double> filterDifferenceEquation(const std::vector<double>& num,
                                             const std::vector<double>& den,
                                             const std::vector<double>& input) {
    if (num.empty())
        throw InvalidInput("num", makeDiagnostic("is_empty"));
    if (den.empty() || den[0] == 0.0)
        throw InvalidInput("den", makeDiagnostic("design_z0_nonzero"));
    std::vector<double> out(input.size(), 0.0);
    for (std::size_t k = 0; k < input.size(); ++k) {
        double acc = 0.0;
        for (std::size_t i = 0; i < num.size() && i <= k; ++i)
            acc += num[i] * input[k - i];
        for (std::size_t i = 1; i < den.size() && i <= k; ++i)
            acc -= den[i] * out[k - i];
        out[k] = acc / den[0];
    }
    return out;
}

} // namespace xyt
