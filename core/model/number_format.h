// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <complex>
#include <string>

namespace xyt {

/// printf "%.<digits>g" of @p v, for messages, warnings and equations (e.g. "0.5", "1.3e+04").
std::string formatNumber(double v, int significantDigits = 6);
/// "0.5" for a real value (|imag| <= 1e-12 |real|), else "0.5+0.2j".
std::string formatComplex(std::complex<double> z, int significantDigits = 6);

/// @p v rounded up (away from zero, for v > 0) to 3 significant digits, never below v: a limit
/// to suggest must let the value pass. Non-positive and non-finite values are returned as given.
double roundUp3(double v);
/// @p v rounded down to 3 significant digits, never above v (a minimum to suggest); 0 for a
/// non-positive value, v for +infinity.
double roundDown3(double v);

} // namespace xyt
