// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <complex>
#include <cstddef>
#include <vector>

namespace xyt {

/**
 * Matches the roots of one step of a locus to those of the previous step so that each branch
 * continues with its own root: the assignment that minimises the total displacement
 *   sum_i |next[order[i]] - previous[i]|
 * (a linear assignment problem, solved exactly by the Hungarian method in O(n^3)), so a branch
 * never jumps to its neighbour when two branches pass close to each other.
 *
 * @return order, with order[i] the index in @p next that continues previous[i].
 * @throws InvalidInput "next" when the two lists differ in size.
 */
std::vector<std::size_t> matchRoots(const std::vector<std::complex<double>>& previous,
                                    const std::vector<std::complex<double>>& next);

/// @p next reordered by matchRoots(previous, next): result[i] continues previous[i].
std::vector<std::complex<double>>
continueBranches(const std::vector<std::complex<double>>& previous,
                 const std::vector<std::complex<double>>& next);

} // namespace xyt
