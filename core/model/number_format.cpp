// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/model/number_format.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

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

double roundUp3(double v) {
    if (!(v > 0.0) || !std::isfinite(v))
        return v;
    const double scale = std::pow(10.0, std::floor(std::log10(v)) - 2.0);
    const double r = std::ceil(v / scale) * scale;
    return r >= v ? r : std::nextafter(r, std::numeric_limits<double>::infinity());
}

double roundDown3(double v) {
    if (!(v > 0.0) || !std::isfinite(v))
        return v > 0.0 ? v : 0.0;
    const double scale = std::pow(10.0, std::floor(std::log10(v)) - 2.0);
    const double r = std::floor(v / scale) * scale;
    return r <= v ? r : std::nextafter(r, 0.0);
}

} // namespace xyt
