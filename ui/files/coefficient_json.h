// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/session/export_text.h"

#include <QJsonObject>

namespace xyt::files {

/**
 * The controller coefficients of both axes as JSON, with units and coefficient order stated:
 * the continuous PI (kp, ki), its digital form at the controller sample time, the reference
 * model, and (for discrete designs) the RST polynomials and the ZPETC filter.
 * @throws InvalidInput when an axis could not be designed.
 */
QJsonObject coefficientsJson(const Session& session, const SessionEvaluation& evaluation,
                             const ExportOptions& options = {});

} // namespace xyt::files
