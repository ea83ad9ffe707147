// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/identification/experiment_table.h"

#include <string>
#include <string_view>
#include <vector>

namespace xyt {

/// The field separator of a delimited text file.
enum class Delimiter { Detect, Comma, Semicolon, Tab, Whitespace };
/// The decimal separator: Detect is the comma when the fields are separated by ';' (the
/// Brazilian/European LabVIEW and Excel exports, "0,25;1,5"), the point otherwise.
enum class DecimalSeparator { Detect, Point, Comma };

struct DelimitedReadOptions {
    Delimiter delimiter = Delimiter::Detect;
    DecimalSeparator decimal = DecimalSeparator::Detect;
    /// The columns to keep (keptColumns: checked against the header before any row is read);
    /// empty: all of them. The others are still checked for their number of fields, not parsed.
    std::vector<std::string> columns;
};

/// What the reader decided (reported back, since Detect is a decision the user should see).
struct DelimitedTable {
    ExperimentTable table;
    Delimiter delimiter = Delimiter::Comma;
    bool decimalComma = false;
};

/**
 * Reads CSV/TSV text whose first non-blank line holds the column names.
 *   - Delimiter::Detect looks at the header line outside quotes: a tab if it has one, else ';',
 *     else ',', else runs of spaces (whitespace-aligned columns).
 *   - Header names and cells may be quoted ("Position (mm)"; "" stands for a quote inside);
 *     names are trimmed and must be unique and non-empty, except that one empty name at the end
 *     of the header (a trailing separator, as Excel writes) drops that column.
 *   - Lines end at LF, CRLF or a lone CR (TextLines); blank lines are skipped (line numbers
 *     still count them); a row with fewer fields than
 *     names leaves the rest missing, one with more non-empty fields is refused.
 *   - Cells are parsed by parseCellNumber; a cell that is not a number is kept as a problem of
 *     its column (refused only if that column is used, experiment_data.h).
 *   - Memory: the text plus 8 bytes a kept cell and 8 a row (the rows are counted first, so
 *     every column is allocated once); no string or vector per cell or row.
 * @param fileName named in every message ("run.csv: line 12, column 3 (Position): ...").
 * @throws InvalidInput whose field names the file and line (and column where there is one): no
 *         header, a header of numbers only (the first line must name the columns), an empty or
 *         repeated name, an unclosed quote, a row with too many fields, more than
 *         kMaxExperimentColumns columns, more than kMaxExperimentBytes bytes, a column of
 *         options.columns that the header does not name, not enough memory (throwOutOfMemory).
 */
DelimitedTable readDelimited(std::string_view text, const std::string& fileName,
                             const DelimitedReadOptions& options = {});

/// readDelimited on the file at @p path (readExperimentFile: at most kMaxExperimentBytes).
/// @throws FileError when the file cannot be read; InvalidInput as readDelimited.
DelimitedTable readDelimitedFile(const std::string& path, const DelimitedReadOptions& options = {});

} // namespace xyt
