// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "app/cli_args.h"
#include "core/identification/io_data.h"
#include "core/identification/spectral_estimate.h"

#include <QJsonObject>
#include <QString>

namespace xyt::cli {

/// The record of identify's data options (--data's file, --input-col, --output-col, --time-col
/// or --ts, --segment, --output-unit, --range, --detrend/--remove-means, --decimate), as every
/// identify structure reads it (app/cli_identify.cpp).
IoData identifyRecord(const CliArgs& args, const QString& option, const QString& path);

/// identify --structure frf: the Welch H1 estimate with its coherence band and the resonance
/// pick (app/cli_frequency_response_estimate.cpp).
int identifyFrequencyResponse(const CliArgs& args);

/// "F0:F1" in Hz (--band); refused naming @p option.
ResonanceBand parseResonanceBand(const QString& option, const QString& text);

/// {frequency, peak, damping (null when a half-power crossing lies outside the band),
/// low_half_power, high_half_power, note}.
QJsonObject resonanceJson(const ResonancePick& pick);

} // namespace xyt::cli
