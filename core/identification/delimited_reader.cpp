// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/identification/delimited_reader.h"

#include "core/model/errors.h"

#include <cmath>
#include <limits>

namespace xyt {

namespace {

struct Field {
    std::string text;
    std::size_t number = 0; ///< 1-based
};

std::string lineField(const std::string& fileName, std::size_t line) {
    return fileName + ": line " + std::to_string(line);
}

bool isBlank(std::string_view line) {
    for (char c : line)
        if (c != ' ' && c != '\t')
            return false;
    return true;
}

/// Reads the quoted field opening at line[open] into f.text ("" inside stands for one quote).
/// Returns the index after the closing quote. @throws InvalidInput when it is not closed.
std::size_t quoted(std::string_view line, std::size_t open, Field& f, const std::string& fileName,
                   std::size_t lineNumber) {
    std::size_t i = open + 1;
    while (i < line.size()) {
        if (line[i] == '"') {
            if (i + 1 < line.size() && line[i + 1] == '"') {
                f.text += '"';
                i += 2;
                continue;
            }
            return i + 1;
        }
        f.text += line[i++];
    }
    throw InvalidInput(lineField(fileName, lineNumber) + ", column " + std::to_string(f.number),
                       "the quote opened at character " + std::to_string(open + 1) + " is not closed");
}

/// Splits a line into fields. Whitespace: runs of spaces and tabs, ends ignored.
std::vector<Field> splitFields(std::string_view line, Delimiter d, const std::string& fileName,
                               std::size_t lineNumber) {
    std::vector<Field> out;
    auto tooMany = [&] {
        if (out.size() > kMaxExperimentColumns + 1)
            throw InvalidInput(lineField(fileName, lineNumber),
                               "has more than " + std::to_string(kMaxExperimentColumns) + " fields");
    };
    if (d == Delimiter::Whitespace) {
        std::size_t i = 0;
        while (i < line.size()) {
            while (i < line.size() && (line[i] == ' ' || line[i] == '\t'))
                ++i;
            if (i >= line.size())
                break;
            Field f;
            f.number = out.size() + 1;
            if (line[i] == '"') {
                i = quoted(line, i, f, fileName, lineNumber);
            } else {
                while (i < line.size() && line[i] != ' ' && line[i] != '\t')
                    f.text += line[i++];
            }
            out.push_back(std::move(f));
            tooMany();
        }
        return out;
    }
    const char sep = d == Delimiter::Comma ? ',' : d == Delimiter::Semicolon ? ';' : '\t';
    std::size_t i = 0;
    while (true) {
        Field f;
        f.number = out.size() + 1;
        std::size_t j = i;
        while (j < line.size() && (line[j] == ' ' || (line[j] == '\t' && sep != '\t')))
            ++j;
        if (j < line.size() && line[j] == '"') {
            j = quoted(line, j, f, fileName, lineNumber);
            while (j < line.size() && (line[j] == ' ' || (line[j] == '\t' && sep != '\t')))
                ++j;
            if (j < line.size() && line[j] != sep)
                throw InvalidInput(lineField(fileName, lineNumber) + ", column " + std::to_string(f.number),
                                   "text follows the closing quote at character " + std::to_string(j + 1));
        } else {
            while (j < line.size() && line[j] != sep)
                f.text += line[j++];
        }
        out.push_back(std::move(f));
        tooMany();
        if (j >= line.size())
            break;
        i = j + 1; // past the separator
    }
    return out;
}

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
    return tab ? Delimiter::Tab : semicolon ? Delimiter::Semicolon : comma ? Delimiter::Comma
                                                                       : Delimiter::Whitespace;
}

std::string trimmed(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t'))
        s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t'))
        s.remove_suffix(1);
    return std::string(s);
}

} // namespace

DelimitedTable readDelimited(std::string_view text, const std::string& fileName,
                             const DelimitedReadOptions& options) {
    if (text.size() > kMaxExperimentBytes)
        throw InvalidInput(fileName, "is larger than " + std::to_string(kMaxExperimentBytes) + " bytes");
    const std::vector<std::string_view> lines = splitLines(text);
    std::size_t headerIndex = 0;
    while (headerIndex < lines.size() && isBlank(lines[headerIndex]))
        ++headerIndex;
    if (headerIndex == lines.size())
        throw InvalidInput(fileName, "holds no header line (the first line must name the columns)");

    DelimitedTable out;
    ExperimentTable& t = out.table;
    t.fileName = fileName;
    out.delimiter = options.delimiter == Delimiter::Detect ? detect(lines[headerIndex]) : options.delimiter;
    out.decimalComma = options.decimal == DecimalSeparator::Comma ||
                       (options.decimal == DecimalSeparator::Detect && out.delimiter == Delimiter::Semicolon);
    if (out.decimalComma && out.delimiter == Delimiter::Comma)
        throw InvalidInput(fileName, "a decimal comma cannot be read with ',' separating the fields");

    const std::size_t headerLine = headerIndex + 1;
    std::vector<Field> header = splitFields(lines[headerIndex], out.delimiter, fileName, headerLine);
    if (header.size() > 1 && trimmed(header.back().text).empty())
        header.pop_back(); // a trailing separator
    if (header.size() > kMaxExperimentColumns)
        throw InvalidInput(lineField(fileName, headerLine),
                           "has more than " + std::to_string(kMaxExperimentColumns) + " columns");
    bool allNumbers = true;
    for (const Field& f : header) {
        const std::string name = trimmed(f.text);
        const std::string field = lineField(fileName, headerLine) + ", column " + std::to_string(f.number);
        if (name.empty())
            throw InvalidInput(field, "the column name is empty");
        for (const std::string& other : t.names)
            if (other == name)
                throw InvalidInput(field, "the column name '" + shownCell(name) + "' is used twice");
        std::string reason;
        allNumbers = allNumbers && parseCellNumber(name, out.decimalComma, reason).has_value();
        t.addColumn(name, f.number);
    }
    if (allNumbers)
        throw InvalidInput(lineField(fileName, headerLine),
                           "holds numbers, not column names: the first line must name the columns");

    const std::size_t columns = t.names.size();
    for (std::size_t li = headerIndex + 1; li < lines.size(); ++li) {
        if (isBlank(lines[li]))
            continue;
        const std::size_t lineNumber = li + 1;
        const std::vector<Field> fields = splitFields(lines[li], out.delimiter, fileName, lineNumber);
        for (std::size_t k = columns; k < fields.size(); ++k)
            if (!trimmed(fields[k].text).empty())
                throw InvalidInput(lineField(fileName, lineNumber) + ", column " + std::to_string(k + 1),
                                   "the line has " + std::to_string(fields.size()) +
                                       " fields but the header names " + std::to_string(columns));
        const std::size_t row = t.rowNumbers.size();
        t.rowNumbers.push_back(lineNumber);
        for (std::size_t c = 0; c < columns; ++c) {
            double value = std::numeric_limits<double>::quiet_NaN();
            std::string reason;
            if (c >= fields.size()) {
                noteCellProblem(t, c, row, "", "is missing");
            } else if (const auto v = parseCellNumber(fields[c].text, out.decimalComma, reason)) {
                value = *v;
            } else {
                noteCellProblem(t, c, row, fields[c].text, reason);
            }
            t.columns[c].push_back(value);
        }
    }
    return out;
}

DelimitedTable readDelimitedFile(const std::string& path, const DelimitedReadOptions& options) {
    return readDelimited(readExperimentFile(path), path, options);
}

} // namespace xyt
