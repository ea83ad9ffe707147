// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/design/guillemin_truxal.h"
#include "core/model/transfer_function.h"

#include <complex>
#include <string>
#include <vector>

namespace xyt {

/// The poles and zeros of one named transfer function, for a pole-zero map.
struct PoleZeroSet {
    std::string name;
    double tsSeconds = 0.0;                  ///< 0: s-plane; > 0: z-plane (positive powers of z)
    std::vector<std::complex<double>> poles; ///< sorted (sortRoots)
    std::vector<std::complex<double>> zeros; ///< sorted (sortRoots)
};

/// The set of any transfer function (the generic builder: plants, controllers, feedforward
/// filters alike). A constant numerator has no zeros.
PoleZeroSet poleZeroSet(const std::string& name, const TransferFunction& tf);

/**
 * The sets of a Guillemin-Truxal design (Braga et al.), in this order and with these names:
 * "plant" G (Eq. 9), "controller" G_c (Eq. 16), "open loop" G_c G, "closed loop"
 * feedback(G_c G) (Eq. 10) and "reference model" G_R (Eq. 7); the last two coincide by
 * construction of the design.
 */
std::vector<PoleZeroSet> gtPoleZeroSets(const GtDesign& design);

} // namespace xyt
