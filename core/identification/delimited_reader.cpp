// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/identification/delimited_reader.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"

#include <algorithm>
#include <limits>
#include <new>

namespace xyt {

namespace {

std::string lineField(const std::string& fileName, std::size_t line) {
    return fileName + ": line " + std::to_string(line);
}

bool isBlank(std::string_view line) {
    for (char c : line)
        if (c != ' ' && c != '\t')
            return false;
    return true;
}

/**
 * The fields of one line, one at a time: an unquoted field is a view of the line, a quoted one
 * is unescaped into a buffer the scanner keeps (valid until the next call), so a row costs no
 * allocation. Whitespace: runs of spaces and tabs separate, the ends are ignored.
 */
class FieldScanner {
public:
    FieldScanner(Delimiter d, const std::string& fileName) : d_(d), fileName_(fileName) {
        sep_ = d == Delimiter::Comma ? ',' : d == Delimiter::Semicolon ? ';' : '\t';
    }

    void start(std::string_view line, std::size_t lineNumber) {
        line_ = line;
        lineNumber_ = lineNumber;
        i_ = 0;
        count_ = 0;
        finished_ = false;
    }

    /// The next field in @p text; false after the last. @throws InvalidInput for an unclosed
    /// quote, text after a closing quote, more than kMaxExperimentColumns + 1 fields.
    bool next(std::string_view& text) {
        if (finished_)
            return false;
        if (d_ == Delimiter::Whitespace) {
            while (i_ < line_.size() && (line_[i_] == ' ' || line_[i_] == '\t'))
                ++i_;
            if (i_ >= line_.size()) {
                finished_ = true;
                return false;
            }
            counted();
            if (line_[i_] == '"') {
                i_ = quoted(i_);
                text = buffer_;
            } else {
                const std::size_t from = i_;
                while (i_ < line_.size() && line_[i_] != ' ' && line_[i_] != '\t')
                    ++i_;
                text = line_.substr(from, i_ - from);
            }
            return true;
        }
        counted();
        std::size_t j = i_;
        while (j < line_.size() && (line_[j] == ' ' || (line_[j] == '\t' && sep_ != '\t')))
            ++j;
        if (j < line_.size() && line_[j] == '"') {
            j = quoted(j);
            while (j < line_.size() && (line_[j] == ' ' || (line_[j] == '\t' && sep_ != '\t')))
                ++j;
            if (j < line_.size() && line_[j] != sep_)
                throw InvalidInput(
                    lineField(fileName_, lineNumber_) + ", column " + std::to_string(count_),
                    makeDiagnostic("ident_text_after_quote", {std::to_string(j + 1)}));
            text = buffer_;
        } else {
            const std::size_t end = std::min(line_.find(sep_, i_), line_.size());
            text = line_.substr(i_, end - i_);
            j = end;
        }
        if (j >= line_.size())
            finished_ = true;
        else
            i_ = j + 1; // past the separator
        return true;
    }

    /// 1-based number of the field last returned.
    std::size_t count() const { return count_; }

private:
    void counted() {
        if (++count_ > kMaxExperimentColumns + 1)
            throw InvalidInput(
                lineField(fileName_, lineNumber_),
                makeDiagnostic("ident_more_than_fields", {std::to_string(kMaxExperimentColumns)}));
    }

    /// Reads the quoted field opening at line_[open] into buffer_ ("" inside stands for one
    /// quote). Returns the index after the closing quote.
    std::size_t quoted(std::size_t open) {
        buffer_.clear();
        std::size_t i = open + 1;
        while (i < line_.size()) {
            if (line_[i] == '"') {
                if (i + 1 < line_.size() && line_[i + 1] == '"') {
                    buffer_ += '"';
                    i += 2;
                    continue;
                }
                return i + 1;
            }
            buffer_ += line_[i++];
        }
        throw InvalidInput(lineField(fileName_, lineNumber_) + ", column " + std::to_string(count_),
                           makeDiagnostic("ident_quote_not_closed", {std::to_string(open + 1)}));
    }

    Delimiter d_;
    char sep_ = ',';
    const std::string& fileName_;
    std::string_view line_;
    std::size_t lineNumber_ = 0, i_ = 0, count_ = 0;
    bool finished_ = false;
    std::string buffer_;
};

Delimiter detect(std::string_view header) {
    bool inQuotes = false, tab = false, semicolon = false, comma = false;
    for (char c : header) {
        if (c == '"')
            inQuotes = !inQuotes;
        else if (!inQuotes) {
            tab = tab || c == '\t';
            semicolon = semicolon || c == ';';
            comma = comma || c == ',';
        }
    }
    return tab         ? Delimiter::Tab
           : semicolon ? Delimiter::Semicolon
           : comma     ? Delimiter::Comma
                       : Delimiter::Whitespace;
}

std::string_view trimmed(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t'))
        s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t'))
        s.remove_suffix(1);
    return s;
}

DelimitedTable parse(std::string_view text, const std::string& fileName,
                     const DelimitedReadOptions& options) {
    TextLines lines(text);
    while (!lines.atEnd() && isBlank(lines.line()))
        lines.next();
    if (lines.atEnd())
        throw InvalidInput(fileName, makeDiagnostic("ident_csv_no_header"));

    DelimitedTable out;
    ExperimentTable& t = out.table;
    t.fileName = fileName;
    out.delimiter =
        options.delimiter == Delimiter::Detect ? detect(lines.line()) : options.delimiter;
    out.decimalComma =
        options.decimal == DecimalSeparator::Comma ||
        (options.decimal == DecimalSeparator::Detect && out.delimiter == Delimiter::Semicolon);
    if (out.decimalComma && out.delimiter == Delimiter::Comma)
        throw InvalidInput(fileName, makeDiagnostic("ident_csv_decimal_comma_separator"));

    const std::size_t headerLine = lines.number();
    FieldScanner fields(out.delimiter, fileName);
    std::vector<std::string> names;
    std::vector<std::size_t> nameFields;
    fields.start(lines.line(), headerLine);
    for (std::string_view f; fields.next(f);) {
        names.emplace_back(trimmed(f));
        nameFields.push_back(fields.count());
    }
    if (names.size() > 1 && names.back().empty()) {
        names.pop_back(); // a trailing separator
        nameFields.pop_back();
    }
    if (names.size() > kMaxExperimentColumns)
        throw InvalidInput(
            lineField(fileName, headerLine),
            makeDiagnostic("ident_more_than_columns", {std::to_string(kMaxExperimentColumns)}));
    bool allNumbers = true;
    for (std::size_t c = 0; c < names.size(); ++c) {
        const std::string field =
            lineField(fileName, headerLine) + ", column " + std::to_string(nameFields[c]);
        if (names[c].empty())
            throw InvalidInput(field, makeDiagnostic("ident_column_name_empty"));
        for (std::size_t other = 0; other < c; ++other)
            if (names[other] == names[c])
                throw InvalidInput(
                    field, makeDiagnostic("ident_column_name_twice", {shownCell(names[c])}));
        Diagnostic reason;
        allNumbers = allNumbers && parseCellNumber(names[c], out.decimalComma, reason).has_value();
    }
    if (allNumbers)
        throw InvalidInput(lineField(fileName, headerLine),
                           makeDiagnostic("ident_csv_header_numbers"));
    const std::size_t columns = names.size();
    const std::vector<bool> kept = keptColumns(names, options.columns, fileName);
    std::vector<std::size_t> tableColumn(columns, columns); // columns: not kept
    for (std::size_t c = 0; c < columns; ++c)
        if (kept[c]) {
            tableColumn[c] = t.names.size();
            t.addColumn(names[c], nameFields[c]);
        }

    // Count the rows before reading them, so each column is allocated once at its final size.
    lines.next();
    std::size_t rows = 0;
    for (TextLines count = lines; !count.atEnd(); count.next())
        rows += isBlank(count.line()) ? 0 : 1;
    reserveRows(t, rows);

    const double nan = std::numeric_limits<double>::quiet_NaN();
    Diagnostic reason;
    const Diagnostic missing = makeDiagnostic("is_missing");
    for (; !lines.atEnd(); lines.next()) {
        if (isBlank(lines.line()))
            continue;
        const std::size_t lineNumber = lines.number();
        const std::size_t row = t.rowNumbers.size();
        t.rowNumbers.push_back(lineNumber);
        for (std::vector<double>& c : t.columns)
            c.push_back(nan);
        fields.start(lines.line(), lineNumber);
        std::size_t extra = 0; // the first non-empty field beyond the named ones (1-based)
        std::size_t seen = 0;
        for (std::string_view f; fields.next(f);) {
            const std::size_t c = seen++;
            if (c >= columns) {
                if (extra == 0 && !trimmed(f).empty())
                    extra = c + 1;
                continue;
            }
            const std::size_t tc = tableColumn[c];
            if (tc == columns)
                continue;
            if (const auto v = parseCellNumber(f, out.decimalComma, reason))
                t.columns[tc].back() = *v;
            else
                noteCellProblem(t, tc, row, f, reason);
        }
        if (extra != 0)
            throw InvalidInput(lineField(fileName, lineNumber) + ", column " +
                                   std::to_string(extra),
                               makeDiagnostic("ident_csv_line_fields",
                                              {std::to_string(seen), std::to_string(columns)}));
        for (std::size_t c = seen; c < columns; ++c)
            if (tableColumn[c] != columns)
                noteCellProblem(t, tableColumn[c], row, "", missing);
    }
    return out;
}

} // namespace

DelimitedTable readDelimited(std::string_view text, const std::string& fileName,
                             const DelimitedReadOptions& options) {
    if (text.size() > kMaxExperimentBytes)
        throw InvalidInput(fileName, makeDiagnostic("ident_larger_than_bytes",
                                                    {std::to_string(kMaxExperimentBytes)}));
    try {
        return parse(text, fileName, options);
    } catch (const std::bad_alloc&) {
        throwOutOfMemory(fileName, 0, makeDiagnostic("ident_oom_its_table"));
    }
}

DelimitedTable readDelimitedFile(const std::string& path, const DelimitedReadOptions& options) {
    return readDelimited(readExperimentFile(path), path, options);
}

} // namespace xyt
