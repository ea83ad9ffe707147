// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/model/number_format.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace xyt {

std::string formatNumber(double v, int significantDigits) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "%.*g", significantDigits, v);
    return buf;
}

std::string formatComplex(std::complex<double> z, int significantDigits) {
    if (std::abs(z.imag()) <= 1e-12 * std::max(1.0, std::abs(z.real())))
        return formatNumber(z.real(), significantDigits);
    char buf[96];
    std::snprintf(buf, sizeof buf, "%.*g%+.*gj", significantDigits, z.real(), significantDigits,
                  z.imag());
    return buf;
}

} // namespace xyt
