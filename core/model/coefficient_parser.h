// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace xyt {

/// The most coefficients one typed list may hold (a polynomial of degree 63): beyond that the
/// root finder and the Sylvester matrices are meaningless for a motion axis.
inline constexpr std::size_t kMaxCoefficients = 64;

/**
 * Parses a list of coefficients as typed in the CLI or the plant editor: numbers separated by
 * spaces, commas or semicolons, optionally wrapped in [ ] (as copied from MATLAB), e.g.
 * "1 -1.6580 0.6583" or "[0.0421, 0.0628, -0.0454]". The order is the caller's convention.
 * @throws InvalidInput naming @p field and the offending token: empty list, a token that is not
 *         a number, NaN or infinity, more than kMaxCoefficients entries.
 */
std::vector<double> parseCoefficientList(std::string_view text, const std::string& field);

/// Parses one finite number (the whole text). @throws InvalidInput naming @p field.
double parseNumber(std::string_view text, const std::string& field);

} // namespace xyt
