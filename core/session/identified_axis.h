// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/identification/identification.h"
#include "core/identification/io_data.h"
#include "core/session/session.h"

namespace xyt {

/**
 * @p axis with an identified model as its plant ("Use this model"), its origin
 * recorded (ModelOrigin: the record, the structure, the fits, the parameters' standard
 * deviations):
 *  - the continuous third-order fit sets the Guillemin-Truxal plant and method; its k0 was fitted
 *    to y in mm, so it is scaled by the axis' model unit (0.001 for the paper's metre models:
 *    k0 = 77 800 mm/(V s^3) becomes 77.8);
 *  - an ARX, OE or BJ model sets the pole-placement model and method: A = A F (the input
 *    denominator), B with its delay, Ts = the data's; t1 and ZPETC stay as they were.
 * The design parameters (wn, kp, t1) are kept: the engineer tunes them next.
 * @throws InvalidInput "model" when the model has no estimate (saying its status).
 */
AxisSettings axisWithIdentifiedModel(const AxisSettings& axis, const IdentifiedModel& model,
                                     const IoData& data);

} // namespace xyt
