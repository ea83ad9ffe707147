// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/contour/contour_metrics.h"
#include "core/contour/gcode_reader.h"
#include "core/session/contour_run.h"
#include "core/simulation/cross_coupled_run.h"
#include "core/simulation/sampled_data.h"

#include <array>
#include <vector>

namespace xyt {

struct Session;

/**
 * A program run by both axes' digital implementations (what the C export's code does: each
 * controller at its period with the encoder, DAC, delay and limit of the session's
 * implementation; DesignMethodModule::steppedDigitalPath), with the session's cross-coupling
 * between them when it is on: the coupling reads the encoders, the direction of travel and
 * curvature of the path at each period (pathCouplingDirections) and is off on rapids.
 */
struct DigitalContourRun {
    double periodSeconds = 0.0;
    std::array<SampledDataRun, 2> axes;
    CouplingDirections directions; ///< what the coupled step was given each period
    CouplingSignals coupling;      ///< empty when the coupling is off
    ContourErrorResult contour;    ///< of the tables' positions against the path
};

/**
 * @throws InvalidInput "cross_coupling" when the two digital controllers run at different
 *         periods (the coupling runs at one), as the methods' digital implementations.
 */
DigitalContourRun runDigitalProgramContour(const Session& session, const GcodeProgram& program,
                                           const ContourRunOptions& options);

} // namespace xyt
