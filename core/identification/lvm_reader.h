// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/identification/experiment_table.h"

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace xyt {

struct LvmReadOptions {
    std::size_t segment = 1; ///< which segment to read, 1-based (a file may hold several)
    /// The columns to keep (keptColumns, checked at the segment's name row, before its rows);
    /// empty: all of them.
    std::vector<std::string> columns;
};

/// The segment read, and how many the file holds.
struct LvmTable {
    ExperimentTable table;
    std::size_t segmentCount = 0;
};

/**
 * Reads a LabVIEW Measurement file (.lvm, text, LVM 1.0 and 2.0 as NI's "Specification for the
 * LabVIEW Measurement File" describes it):
 *   - the file header: first line "LabVIEW Measurement", tag/value lines (Separator Tab|Comma,
 *     Decimal_Separator . or ,, X_Columns No|One|Multi; other tags are ignored), ending with
 *     ***End_of_Header***; a missing Separator tag means Tab and a missing X_Columns means One
 *     (both with a warning), a missing Decimal_Separator (LVM 1.0) means '.';
 *   - per segment a header (Channels, Samples, ..., X0, Delta_X) ending with ***End_of_Header***,
 *     then the column-name row "X_Value<sep>name...<sep>Comment", then data rows until the next
 *     segment header (a line whose first field is a tag, not a number); ***Start_Special*** ...
 *     ***End_Special*** blocks are skipped;
 *   - columns: X_Columns One: "X_Value" (the x values, usually time in s) and the channels;
 *     No: the channels only (the empty x field is skipped); Multi: each channel preceded by its
 *     x column, named "X_Value (<channel>)". The trailing Comment column is not read. Without a
 *     column-name row the channels are named "Untitled", "Untitled 1", ... as LabVIEW names them
 *     (with a warning).
 *   - sampleTimeSeconds: the segment's Delta_X when every channel states the same positive one;
 *     it must be an accepted sample time (requireSampleTime) and agree with every X_Value column
 *     of the segment whose cells are all numbers (their mean step within kSampleTimeTolerance of
 *     it): a file whose two statements of its sample time disagree is refused, naming both.
 *   - Lines end at LF, CRLF or a lone CR (TextLines). The file is read twice: the first pass
 *     counts the segment's rows, so each column is allocated once (8 bytes a cell and a row).
 * @throws InvalidInput naming the file and line (and column): not an LVM file, an unknown
 *         Separator, X_Columns or Decimal_Separator value, a decimal comma with Comma separators,
 *         a header without ***End_of_Header***, a segment that does not exist (naming how many
 *         there are), a repeated channel name, a row with more fields than the name row, more
 *         than kMaxExperimentColumns columns or kMaxExperimentBytes bytes, a column of
 *         options.columns the segment does not name, a Delta_X outside the accepted sample
 *         times or contradicted by an X_Value column, not enough memory (throwOutOfMemory).
 */
LvmTable readLvm(std::string_view text, const std::string& fileName,
                 const LvmReadOptions& options = {});

/// readLvm on the file at @p path (readExperimentFile: at most kMaxExperimentBytes).
/// @throws FileError when the file cannot be read; InvalidInput as readLvm.
LvmTable readLvmFile(const std::string& path, const LvmReadOptions& options = {});

} // namespace xyt
