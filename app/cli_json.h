// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/analysis/nyquist.h"
#include "core/analysis/stability_margins.h"
#include "core/model/polynomial.h"
#include "core/model/transfer_function.h"
#include "core/simulation/metrics.h"
#include "core/simulation/move_settle.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QJsonValue>

#include <complex>
#include <vector>

namespace xyt::cli {

/// A JSON number, or null for NaN/infinity (JSON has no such numbers; never print NaN).
QJsonValue number(double v);
QJsonArray numbers(const std::vector<double>& v);
/// Coefficients highest power first (the CLI's convention for polynomials of s).
QJsonArray descending(const Polynomial& p);
/// Coefficients in ascending order (the CLI's convention for polynomials of z^-1).
QJsonArray ascending(const Polynomial& p);
/// [[re, im], ...]
QJsonArray complexPairs(const std::vector<std::complex<double>>& roots);
/// {num, den} of a continuous transfer function, descending powers of s.
QJsonObject continuousTf(const TransferFunction& tf);
/// {rmse, max_abs_error, ..., settling_time, overshoot_pct, itae}: the metric names of the CLI
/// (sweep points; simulate splits them into trackingJson and stepResponseJson).
QJsonObject metricsJson(const TrackingMetrics& m, const StepCharacteristics& step);
/// {rmse, max_abs_error, max_abs_error_pct, max_abs_u, saturated, diverged, saturated_time,
/// itae}: the figures of the tracking run.
QJsonObject trackingJson(const TrackingMetrics& m);
/// {stable, final_value, settling_time, settling_band_pct, overshoot_pct, peak_time}: the
/// closed loop's unit-step figures (null when unstable).
QJsonObject stepResponseJson(const StepCharacteristics& step);
/// {window_mm, move_end, run_end, reached_move_end, settled, settle_time (null unless
/// settled), final_error, final_overshoot_mm, diverged}.
QJsonObject moveSettleJson(const MoveSettleMetrics& m);
/// {gain_margin {factor, db, omega}, phase_margin {deg, omega}, delay_margin, peak_sensitivity,
/// peak_complementary_sensitivity, bandwidth, closed_loop_stable, every crossing, nyquist, ts,
/// warnings}: the loop's exact margins (an infinite margin is "inf").
QJsonObject marginsJson(const StabilityMargins& m, const NyquistCurve& n);
/// Writes the object to stdout, indented, with a newline.
void print(const QJsonObject& object);

} // namespace xyt::cli
