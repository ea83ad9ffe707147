// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/identification/experiment_table.h"

#include "core/io/file_io.h"
#include "core/io/text_escape.h"
#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/model/number_format.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <new>
#include <stdexcept>

namespace xyt {

std::size_t ExperimentTable::column(std::string_view name) const {
    for (std::size_t c = 0; c < names.size(); ++c)
        if (names[c] == name)
            return c;
    std::string list;
    for (std::size_t c = 0; c < names.size() && c < 50; ++c)
        list += (c ? ", " : "") + shownCell(names[c]);
    const Diagnostic shown =
        names.size() > 50
            ? makeDiagnostic("ident_column_list_cut", {list, std::to_string(names.size())})
            : Diagnostic(list);
    throw InvalidInput(fileName, list.empty()
                                     ? makeDiagnostic("ident_no_column_none", {shownCell(name)})
                                     : makeDiagnostic("ident_no_column", {shownCell(name), shown}));
}

std::string ExperimentTable::cellField(std::size_t c, std::size_t row) const {
    const std::size_t where = row < rowNumbers.size() ? rowNumbers[row] : row + 1;
    if (fieldNumbers.at(c) == 0)
        return fileName + ": " + rowLabel + " " + std::to_string(where) + " of " +
               shownCell(names[c]);
    return fileName + ": " + rowLabel + " " + std::to_string(where) + ", column " +
           std::to_string(fieldNumbers[c]) + " (" + shownCell(names[c]) + ")";
}

void ExperimentTable::addColumn(std::string name, std::size_t fieldNumber) {
    names.push_back(std::move(name));
    columns.emplace_back();
    fieldNumbers.push_back(fieldNumber);
    firstProblem.emplace_back();
}

std::optional<double> parseCellNumber(std::string_view cell, bool decimalComma,
                                      Diagnostic& reason) {
    // Made once: a column of text that is never used is refused cell by cell.
    static const Diagnostic missing = makeDiagnostic("is_missing");
    static const Diagnostic notNumber = makeDiagnostic("ident_cell_not_number");
    static const Diagnostic notFinite = makeDiagnostic("not_finite_value");
    static const Diagnostic outOfRange = makeDiagnostic("ident_cell_out_of_range");
    static const Diagnostic decimalPoint = makeDiagnostic("ident_cell_decimal_point");
    static const Diagnostic decimalCommaReason = makeDiagnostic("ident_cell_decimal_comma");
    auto space = [](char c) {
        return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
    };
    while (!cell.empty() && space(cell.front()))
        cell.remove_prefix(1);
    while (!cell.empty() && space(cell.back()))
        cell.remove_suffix(1);
    if (cell.empty()) {
        reason = missing;
        return std::nullopt;
    }
    // from_chars takes no '+'; a doubled sign stays an error.
    if (cell.front() == '+' && cell.size() > 1 && cell[1] != '-' && cell[1] != '+')
        cell.remove_prefix(1);
    if (cell.size() > 64) {
        reason = notNumber;
        return std::nullopt;
    }
    char buffer[64];
    std::size_t n = 0;
    for (char c : cell) {
        const bool digit = c >= '0' && c <= '9';
        const bool ok = digit || c == '-' || c == '+' || c == 'e' || c == 'E' ||
                        c == (decimalComma ? ',' : '.');
        if (!ok) {
            const std::string lower = [&] {
                std::string l;
                for (char x : cell)
                    l += static_cast<char>(x >= 'A' && x <= 'Z' ? x - 'A' + 'a' : x);
                return l;
            }();
            if (lower == "nan" || lower == "-nan" || lower == "inf" || lower == "-inf" ||
                lower == "infinity" || lower == "-infinity" || lower == "1.#qnan" ||
                lower == "1.#inf")
                reason = notFinite;
            else if (c == (decimalComma ? '.' : ','))
                reason = decimalComma ? decimalPoint : decimalCommaReason;
            else
                reason = notNumber;
            return std::nullopt;
        }
        buffer[n++] = c == ',' ? '.' : c;
    }
    double value = 0.0;
    const auto [end, ec] = std::from_chars(buffer, buffer + n, value, std::chars_format::general);
    if (ec == std::errc::result_out_of_range) {
        reason = outOfRange;
        return std::nullopt;
    }
    if (ec != std::errc() || end != buffer + n) {
        reason = notNumber;
        return std::nullopt;
    }
    if (!std::isfinite(value)) {
        reason = notFinite;
        return std::nullopt;
    }
    return value;
}

void noteCellProblem(ExperimentTable& table, std::size_t column, std::size_t row,
                     std::string_view text, const Diagnostic& reason) {
    if (!table.firstProblem[column])
        table.firstProblem[column] = CellProblem{row, shownCell(text), reason};
}

std::string shownCell(std::string_view text, std::size_t maxChars) {
    const bool cut = text.size() > maxChars;
    if (cut) {
        text = text.substr(0, maxChars);
        // Do not end in the middle of a UTF-8 sequence (terminalText would show it escaped).
        while (!text.empty() && (static_cast<unsigned char>(text.back()) & 0xC0) == 0x80)
            text.remove_suffix(1);
        if (!text.empty() && static_cast<unsigned char>(text.back()) >= 0xC0)
            text.remove_suffix(1);
    }
    return terminalText(text) + (cut ? "..." : "");
}

TextLines::TextLines(std::string_view text) : text_(text) {
    if (text_.substr(0, 3) == "\xEF\xBB\xBF")
        text_.remove_prefix(3);
    done_ = text_.empty();
    find();
}

void TextLines::find() {
    // A plain loop: find_first_of("\r\n") compares each byte with the set, twice as slow here.
    std::size_t i = start_;
    const std::size_t n = text_.size();
    while (i < n && text_[i] != '\n' && text_[i] != '\r')
        ++i;
    end_ = i;
}

void TextLines::next() {
    if (done_)
        return;
    std::size_t after = end_;
    if (after < text_.size())
        after +=
            text_[after] == '\r' && after + 1 < text_.size() && text_[after + 1] == '\n' ? 2 : 1;
    if (after >= text_.size()) {
        done_ = true;
        return;
    }
    start_ = after;
    ++number_;
    find();
}

std::vector<bool> keptColumns(const std::vector<std::string>& names,
                              const std::vector<std::string>& wanted, const std::string& fileName) {
    std::vector<bool> kept(names.size(), wanted.empty());
    for (const std::string& w : wanted) {
        bool found = false;
        for (std::size_t c = 0; c < names.size(); ++c)
            if (names[c] == w)
                kept[c] = found = true;
        if (!found) {
            ExperimentTable listing;
            listing.fileName = fileName;
            listing.names = names;
            listing.column(w); // throws: no such column, with the list
        }
    }
    return kept;
}

void reserveRows(ExperimentTable& table, std::size_t rows) {
    const std::size_t columns = table.columns.size();
    try {
        table.rowNumbers.reserve(rows);
        for (std::vector<double>& c : table.columns)
            c.reserve(rows);
    } catch (const std::bad_alloc&) {
        const double bytes = double(rows) * double(columns + 1) * 8.0;
        throwOutOfMemory(
            table.fileName, std::size_t(std::min(bytes, 1e18)),
            makeDiagnostic(columns == 1 ? "ident_oom_rows_of_column" : "ident_oom_rows_of_columns",
                           {std::to_string(rows), std::to_string(columns)}));
    } catch (const std::length_error&) {
        throwOutOfMemory(table.fileName, 0,
                         makeDiagnostic("ident_oom_rows", {std::to_string(rows)}));
    }
}

void throwOutOfMemory(const std::string& fileName, std::size_t bytes, const Diagnostic& what) {
    const Diagnostic amount =
        bytes > 0 ? makeDiagnostic("ident_oom_mb_for",
                                   {std::to_string((bytes + (1u << 20) - 1) >> 20), what})
                  : what;
    throw InvalidInput(fileName, makeDiagnostic("ident_oom", {amount}));
}

void requireSampleTime(double seconds, const std::string& field) {
    requirePositive(seconds, field);
    if (seconds < kMinSampleTimeSeconds || seconds > kMaxSampleTimeSeconds)
        throw InvalidInput(field,
                           makeDiagnostic("ident_sample_time_outside", {formatNumber(seconds, 6)}));
}

std::string readExperimentFile(const std::string& path) {
    try {
        return readRegularFile(path, kMaxExperimentBytes);
    } catch (const std::bad_alloc&) {
        std::error_code ignored;
        const auto size = std::filesystem::file_size(path, ignored);
        throwOutOfMemory(path, ignored ? 0 : std::size_t(size),
                         makeDiagnostic("ident_oom_file_text"));
    }
}

} // namespace xyt
