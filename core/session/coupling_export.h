// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/session/export_text.h"
#include "core/session/session_evaluation.h"

#include <string>

namespace xyt {

/**
 * The cross-coupled controller in C (core/design/cross_coupling.h), the block exportCHeader
 * appends when Session::crossCoupling is on: its gains and period, its state, and
 * xyt_ccc_step, which runs both axes together each period (it needs both axes' measured
 * positions) in place of their own steps, calling each axis' xyt_<id>_coupled
 * (DesignMethodModule::cCoupledAxis). It performs the operations of the cross-coupled digital
 * run (runDigitalProgramContour: runCrossCoupled over the methods' sampled-data loops) in their
 * order; tests/core/session/tst_coupled_firmware.cpp checks it in the loop.
 * @throws InvalidInput "cross_coupling" when an axis has no digital implementation or the two
 *         run at different periods, and naming a gain C cannot hold (cross_coupling.kp).
 */
std::string crossCouplingCBlock(const Session& session, const SessionEvaluation& evaluation,
                                const ExportOptions& options);

} // namespace xyt
