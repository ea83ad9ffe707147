// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/model/transfer_function.h"

#include <string>

namespace xyt {

/**
 * The lightly damped mode of a belt, a ball screw or a gantry above an axis' rigid-body
 * dynamics, as a factor of unit static gain in series with the rigid plant:
 *  - a resonant pair (antiResonanceHz = 0): wr^2 / (s^2 + 2 zr wr s + wr^2), the tool point
 *    measured through the compliance;
 *  - a two-mass model (antiResonanceHz > 0, below the resonance): the motor side of the
 *    compliance, (wr^2 / wa^2) (s^2 + 2 za wa s + wa^2) / (s^2 + 2 zr wr s + wr^2), whose
 *    anti-resonance wa = wr sqrt(m_motor / (m_motor + m_load)) comes first (Ellis, Control System
 *    Design Guide, 4th ed., ch. 16).
 * with w = 2 pi f. frequencyHz = 0 is the rigid table, bit for bit.
 */
struct FlexibleMode {
    double frequencyHz = 0.0;           ///< wr / 2 pi; 0: no mode
    double dampingRatio = 0.02;         ///< zr, in [0, 1)
    double antiResonanceHz = 0.0;       ///< wa / 2 pi; 0: a resonant pair only
    double antiResonanceDamping = 0.02; ///< za, in [0, 1)

    bool present() const { return frequencyHz != 0.0; }
    bool twoMass() const { return antiResonanceHz != 0.0; }
    /// The factor above (continuous, unit static gain); the gain 1 when !present().
    TransferFunction transferFunction() const;
    friend bool operator==(const FlexibleMode&, const FlexibleMode&) = default;
};

/**
 * @throws InvalidInput "frequency" unless finite and >= 0, "damping" unless in [0, 1),
 *         "anti_resonance" unless 0 or finite, > 0 and below the frequency,
 *         "anti_resonance_damping" unless in [0, 1); each field prefixed by @p prefix.
 */
void validateFlexibleMode(const FlexibleMode& mode, const std::string& prefix = "");

/// @throws InvalidInput @p field unless @p zeta is a damping ratio in [0, 1).
void requireDampingRatio(double zeta, const std::string& field);

} // namespace xyt
