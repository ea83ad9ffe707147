// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/identification/experiment_table.h"
#include "core/identification/io_data.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace xyt {

/// The unit of the output column; y is converted to mm.
enum class OutputUnit { Millimetres, Metres, EncoderCounts };

/// y_mm = scale * y_file: 1 (mm), 1000 (m), mmPerCount (encoder counts).
struct OutputScale {
    OutputUnit unit = OutputUnit::Millimetres;
    double mmPerCount = 0.0; ///< required (> 0) for EncoderCounts, ignored otherwise
};

/// Where the sample instants come from: exactly one of the three must be chosen.
struct ExperimentColumns {
    std::string input;  ///< the command column (V)
    std::string output; ///< the position column (unit in outputScale)
    std::string time;   ///< a time column (s); empty when the sample time is given
    std::optional<double> sampleTimeSeconds; ///< a given sample time (s), time 0 at the first row
    bool fileSampleTime = false;             ///< the sample time the file states (LVM Delta_X)
    OutputScale outputScale;
};

/// Non-uniform sampling beyond this fraction of Ts is refused: 1 %.
inline constexpr double kSampleTimeTolerance = 0.01;

/**
 * The input/output record of the chosen columns: u[k] = input[k] (V), y[k] = scale * output[k]
 * (mm), Ts from the time column (Ts = (t[n-1] - t[0]) / (n - 1), startSeconds = t[0]), the
 * given sample time (startSeconds = 0) or the file's. source reads "run.csv: u=Command, y=X".
 * Nothing is guessed: every choice is the caller's.
 * @throws InvalidInput:
 *   - naming the file: an unknown column (listing those that exist), the same column for u and
 *     y, no time source or more than one, the file states no sample time, columns of unequal
 *     length (MAT);
 *   - naming file, line and column (ExperimentTable::cellField): a cell that is not a number,
 *     is missing or is NaN/infinite (the first one of a used column); time not increasing
 *     (t[k] <= t[k-1]); a step of the time column off Ts by more than kSampleTimeTolerance Ts;
 *   - "sample_time" (the given one), the file's stated one and the time column's: outside the
 *     accepted sample times (requireSampleTime, experiment_table.h); "mm_per_count" (encoder
 *     counts without a positive count size);
 *   - too few samples: fewer than 2 (requireSamples).
 */
IoData experimentData(const ExperimentTable& table, const ExperimentColumns& columns);
/// experimentData on a table that is not needed afterwards: the input column is moved into the
/// record instead of copied.
IoData experimentData(ExperimentTable&& table, const ExperimentColumns& columns);

/**
 * The names of the columns @p columns reads (input, output and the time column when there is
 * one), for a reader to keep only those (DelimitedReadOptions::columns, LvmReadOptions::columns),
 * so that a choice that cannot work is refused before the file is parsed.
 * @throws InvalidInput naming @p fileName when input and output are the same column.
 */
std::vector<std::string> usedColumns(const ExperimentColumns& columns, const std::string& fileName);

/**
 * Refuses records too short for a use: @p what names the use ("ARX(2,3,1) estimation").
 * @throws InvalidInput whose field is data.source (or "data" when empty): "has N samples;
 *         <what> needs at least <minimum>"; also when u and y differ in length.
 */
void requireSamples(const IoData& data, std::size_t minimum, const Diagnostic& what);

} // namespace xyt
