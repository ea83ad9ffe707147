// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/model/diagnostic.h"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace xyt {

/// The largest experiment file read: 128 MiB (a 10 ms log of 3 channels over 24 hours is about
/// 8.6 million rows, some 300 MB as text; a 1-hour run at 10 ms is 15 MB). Larger files are
/// refused by readExperimentFile before anything is parsed.
inline constexpr std::size_t kMaxExperimentBytes = 128u * 1024u * 1024u;
/// The most columns (channels, variables) a table may hold: far beyond any axis experiment, and
/// it bounds the work on a header row of a million separators.
inline constexpr std::size_t kMaxExperimentColumns = 1000;

/// The first cell of a column that holds no usable number.
struct CellProblem {
    std::size_t row = 0; ///< index into ExperimentTable::rowNumbers
    std::string text;  ///< the cell as written (shown one-line, at most 40 characters); "" = empty
    Diagnostic reason; ///< "is not a number", "is missing", "is NaN", ... (coded)
};

/**
 * A file of named numeric columns, as read (nothing converted or guessed yet):
 * columns[c][r] is row r of column names[c]; a cell that holds no usable number is NaN there and
 * the first such cell of each column is kept in firstProblem[c], so the step that uses a column
 * (experiment_data.h) can refuse it naming the file, the line and the column, while columns that
 * are never used may hold text. Columns of a text file all have rowNumbers.size() rows; the
 * variables of a MAT file may differ in length.
 */
struct ExperimentTable {
    std::string fileName;           ///< as given to the reader, for messages
    std::string rowLabel = "line";  ///< "line" (text files) or "element" (MAT variables)
    std::vector<std::string> names; ///< unique column names
    std::vector<std::vector<double>> columns;
    std::vector<std::size_t> fieldNumbers; ///< 1-based field of each column in its line (0: MAT)
    std::vector<std::size_t> rowNumbers;   ///< 1-based source line (or element) of each row
    std::vector<std::optional<CellProblem>> firstProblem; ///< per column
    /// The sample time the file states, if any (LVM Delta_X, equal for every channel), s.
    std::optional<double> sampleTimeSeconds;
    std::vector<Diagnostic> warnings; ///< what was read in an unusual way (coded)

    /// Index of the column called @p name (exact, case-sensitive).
    /// @throws InvalidInput naming the file: no such column, with the list of those that exist.
    std::size_t column(std::string_view name) const;
    /// "run.csv: line 12, column 3 (Position)" or "run.mat: element 57 of y": the field of an
    /// InvalidInput about row @p row of column @p column.
    std::string cellField(std::size_t column, std::size_t row) const;
    /// Adds a column (name checked for uniqueness by the readers).
    void addColumn(std::string name, std::size_t fieldNumber);
};

/**
 * A number in a text cell: optional spaces, an optional sign, decimal digits with an optional
 * decimal separator ('.' or, with @p decimalComma, ',' instead) and exponent. Returns the value,
 * or nullopt with @p reason set ("is not a number", "is missing", "is NaN or infinite", "is out
 * of the range of a double"). "1.5" is refused with @p decimalComma and "1,5" without it: a cell
 * holding the other separator is a sign of a wrong setting, not something to guess.
 */
std::optional<double> parseCellNumber(std::string_view cell, bool decimalComma, Diagnostic& reason);

/// Records the first problem of column @p column at row @p row (later ones are ignored).
void noteCellProblem(ExperimentTable& table, std::size_t column, std::size_t row,
                     std::string_view text, const Diagnostic& reason);

/// Text of a file for a one-line message: escaped (core/io/text_escape.h rules) and cut to
/// @p maxChars characters.
std::string shownCell(std::string_view text, std::size_t maxChars = 40);

/**
 * The lines of a text file, one at a time (a table of all of them would cost 16 bytes a line:
 * 2 GB for a file of 128 MiB of blank lines). A line ends at "\r\n", "\n" or a lone "\r" (the
 * line end of old Mac OS), so the three conventions give the same lines and the same line
 * numbers; a UTF-8 BOM at the start is dropped; a final line end starts no further line.
 */
class TextLines {
public:
    explicit TextLines(std::string_view text);
    bool atEnd() const { return done_; }
    /// The current line, without its line end.
    std::string_view line() const { return text_.substr(start_, end_ - start_); }
    /// 1-based number of the current line.
    std::size_t number() const { return number_; }
    void next();

private:
    void find();
    std::string_view text_;
    std::size_t start_ = 0, end_ = 0, number_ = 1;
    bool done_ = false;
};

/// Of @p names (a file's columns, in file order), those a reader keeps: all when @p wanted is
/// empty, else those named in @p wanted. Checked before any row is read, so a file is not parsed
/// for a column it does not have.
/// @throws InvalidInput as ExperimentTable::column, naming @p fileName and listing @p names,
///         for a name of @p wanted that is not among @p names.
std::vector<bool> keptColumns(const std::vector<std::string>& names,
                              const std::vector<std::string>& wanted, const std::string& fileName);

/**
 * Reserves @p rows rows in every column of @p table and in rowNumbers, so no column grows by
 * doubling (a growing vector holds its old and its new block at once: up to three times its
 * size). The readers count the rows first for this.
 * @throws InvalidInput naming the file (outOfMemory) when the memory is not available.
 */
void reserveRows(ExperimentTable& table, std::size_t rows);

/// "<file>: the file needs more memory than is available (<N> MB for <what>)": what a reader
/// throws instead of std::bad_alloc. @p bytes 0 leaves the amount out.
[[noreturn]] void throwOutOfMemory(const std::string& fileName, std::size_t bytes,
                                   const Diagnostic& what);

/**
 * The bytes of an experiment file, at most kMaxExperimentBytes (core/io/file_io.h
 * readRegularFile: regular files only, never more than the cap read).
 * @throws FileError naming @p path (no such file, not a regular file, too large, ...).
 */
std::string readExperimentFile(const std::string& path);

/**
 * The accepted sample times, s: 1 ns to 10 000 s. Beyond them a record is not a sampled axis
 * experiment (1 ns is a 1 GHz data logger; 10 000 s is one sample in almost three hours), and
 * what is derived from Ts breaks: with 5e-324 s a gt3 fit's gain underflowed ("k0: must be
 * nonzero") and a session given that pp.ts could not be run ("needs more than 1e308 samples").
 * The session file itself accepts any positive pp.ts; the session's runs bound it by their
 * sample count, which these bounds keep far from.
 */
inline constexpr double kMinSampleTimeSeconds = 1e-9;
inline constexpr double kMaxSampleTimeSeconds = 1e4;

/// @throws InvalidInput naming @p field unless @p seconds is within the accepted sample times,
///         saying the range and why.
void requireSampleTime(double seconds, const std::string& field);

} // namespace xyt
