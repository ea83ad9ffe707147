// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/design/digital_controller.h"

#include "core/model/errors.h"

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
    return method == PiDiscretization::Tustin ? "tustin" : "backward-euler";
}

std::vector<double> filterDifferenceEquation(const std::vector<double>& num,
                                             const std::vector<double>& den,
                                             const std::vector<double>& input) {
    if (num.empty())
        throw InvalidInput("num", "is empty");
    if (den.empty() || den[0] == 0.0)
        throw InvalidInput("den", "the z^0 coefficient must be nonzero");
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
