// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/identification/lvm_reader.h"

#include "core/identification/experiment_data.h"
#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/model/number_format.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <new>

namespace xyt {

namespace {

constexpr std::string_view kEndOfHeader = "***End_of_Header***";
constexpr std::string_view kStartSpecial = "***Start_Special***";
constexpr std::string_view kEndSpecial = "***End_Special***";

enum class XColumns { No, One, Multi };

std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t'))
        s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t'))
        s.remove_suffix(1);
    return s;
}

/// Splits @p line at @p sep into @p out (a buffer reused from line to line: no allocation a row).
void split(std::string_view line, char sep, std::vector<std::string_view>& out) {
    out.clear();
    std::size_t start = 0;
    while (true) {
        const std::size_t end = line.find(sep, start);
        out.push_back(line.substr(start, end == std::string_view::npos ? std::string_view::npos
                                                                       : end - start));
        if (end == std::string_view::npos || out.size() > kMaxExperimentColumns * 2 + 2)
            break;
        start = end + 1;
    }
}

/// Tag and first value of a header line, split at the first tab or comma (the separator is
/// not known before the Separator tag is read).
std::pair<std::string_view, std::string_view> tagValue(std::string_view line) {
    const std::size_t cut = line.find_first_of("\t,");
    if (cut == std::string_view::npos)
        return {trim(line), {}};
    std::string_view rest = line.substr(cut + 1);
    const std::size_t end = rest.find(line[cut]);
    return {trim(line.substr(0, cut)), trim(rest.substr(0, end))};
}

bool blank(std::string_view line) {
    return trim(line).empty();
}

/// The steps of one X_Value column over the segment read, to compare with its Delta_X.
struct XSteps {
    std::size_t field = 0; ///< 0-based
    double first = 0.0, last = 0.0;
    std::size_t firstLine = 0, lastLine = 0, count = 0;
    bool usable = true; ///< every cell a number
};

class LvmParser {
public:
    /// @p countOnly: a first pass that only counts the rows of the segment read (so that the
    /// second can allocate each column once) and finds every structural error.
    LvmParser(std::string_view text, const std::string& fileName, const LvmReadOptions& options,
              bool countOnly, std::size_t rows)
        : lines_(text), fileName_(fileName), wanted_(options.segment),
          wantedColumns_(options.columns), countOnly_(countOnly), expectedRows_(rows) {
        out_.table.fileName = fileName;
    }

    LvmTable run() {
        readFileHeader();
        if (decimalComma_ && sep_ == ',')
            throw InvalidInput(fileName_, makeDiagnostic("ident_lvm_decimal_comma_separator"));
        while (!lines_.atEnd())
            step();
        if (out_.segmentCount == 0)
            throw InvalidInput(fileName_, makeDiagnostic("ident_lvm_no_segment"));
        if (wanted_ > out_.segmentCount)
            throw InvalidInput(
                fileName_,
                makeDiagnostic(out_.segmentCount == 1 ? "ident_lvm_one_segment_not"
                                                      : "ident_lvm_segments_not",
                               {std::to_string(out_.segmentCount), std::to_string(wanted_)}));
        if (out_.segmentCount > 1)
            out_.table.warnings.push_back(
                makeDiagnostic("ident_lvm_segment_read",
                               {std::to_string(out_.segmentCount), std::to_string(wanted_)}));
        if (allNames_.empty())
            throw InvalidInput(fileName_, makeDiagnostic("ident_lvm_segment_no_channel",
                                                         {std::to_string(wanted_)}));
        if (!countOnly_)
            checkDeltaX();
        return std::move(out_);
    }

    std::size_t rowsCounted() const { return rows_; }

private:
    std::string at(std::size_t lineNumber) const {
        return fileName_ + ": line " + std::to_string(lineNumber);
    }

    /// From a ***Start_Special*** line to the line after its ***End_Special***.
    void skipSpecial() {
        const std::size_t start = lines_.number();
        for (lines_.next(); !lines_.atEnd(); lines_.next())
            if (trim(tagValue(lines_.line()).first) == kEndSpecial) {
                lines_.next();
                return;
            }
        throw InvalidInput(at(start), makeDiagnostic("ident_lvm_special_not_closed"));
    }

    void readFileHeader() {
        while (!lines_.atEnd() && blank(lines_.line()))
            lines_.next();
        if (lines_.atEnd() || tagValue(lines_.line()).first != "LabVIEW Measurement")
            throw InvalidInput(lines_.atEnd() ? fileName_ : at(lines_.number()),
                               makeDiagnostic("ident_lvm_not_lvm"));
        const std::size_t start = lines_.number();
        lines_.next();
        bool separatorSeen = false, xColumnsSeen = false;
        while (!lines_.atEnd()) {
            const std::string_view line = lines_.line();
            const auto [tag, value] = tagValue(line);
            if (tag == kStartSpecial) {
                skipSpecial();
                continue;
            }
            if (tag == kEndOfHeader) {
                lines_.next();
                if (!separatorSeen)
                    out_.table.warnings.push_back(makeDiagnostic("ident_lvm_no_separator_tag"));
                if (!xColumnsSeen)
                    out_.table.warnings.push_back(makeDiagnostic("ident_lvm_no_x_columns_tag"));
                return;
            }
            if (tag == "Separator") {
                separatorSeen = true;
                if (value == "Tab")
                    sep_ = '\t';
                else if (value == "Comma")
                    sep_ = ',';
                else
                    throw InvalidInput(
                        at(lines_.number()),
                        makeDiagnostic("ident_lvm_bad_separator", {shownCell(value)}));
            } else if (tag == "Decimal_Separator") {
                // With comma-separated fields the value itself is the second field:
                // "Decimal_Separator,," holds an empty value between two commas, so look at the raw
                // text too.
                const std::string_view raw = trim(line.substr(tag.size()));
                if (value == ".")
                    decimalComma_ = false;
                else if (value == "," || raw == ",," || raw == "\t,")
                    decimalComma_ = true;
                else
                    throw InvalidInput(
                        at(lines_.number()),
                        makeDiagnostic("ident_lvm_bad_decimal_separator", {shownCell(value)}));
            } else if (tag == "X_Columns") {
                xColumnsSeen = true;
                if (value == "No")
                    xColumns_ = XColumns::No;
                else if (value == "One")
                    xColumns_ = XColumns::One;
                else if (value == "Multi")
                    xColumns_ = XColumns::Multi;
                else
                    throw InvalidInput(
                        at(lines_.number()),
                        makeDiagnostic("ident_lvm_bad_x_columns", {shownCell(value)}));
            }
            lines_.next();
        }
        throw InvalidInput(at(start), makeDiagnostic("ident_lvm_header_not_closed"));
    }

    /// One line (or a block) of the data part.
    void step() {
        split(lines_.line(), sep_, fields_);
        bool empty = true; // a line of separators only ("," in comma files) is blank too
        for (std::string_view f : fields_)
            empty = empty && blank(f);
        if (empty) {
            lines_.next();
            return;
        }
        const std::string_view first = trim(fields_[0]);
        if (first == kStartSpecial) {
            skipSpecial();
            return;
        }
        if (first == "X_Value") {
            if (segmentHasRows_ || !inSegment_)
                beginSegment();
            if (current() && namesSeen_)
                throw InvalidInput(at(lines_.number()), makeDiagnostic("ident_lvm_second_name_row",
                                                                       {std::to_string(wanted_)}));
            if (current())
                setColumnsFromNames(fields_);
            namesSeen_ = true;
            lines_.next();
            return;
        }
        if (first.empty() || parseCellNumber(first, decimalComma_, reason_)) {
            if (!inSegment_)
                beginSegment();
            if (current())
                addRow(fields_);
            segmentHasRows_ = true;
            lines_.next();
            return;
        }
        readSegmentHeader();
    }

    bool current() const { return out_.segmentCount == wanted_; }

    void beginSegment() {
        ++out_.segmentCount;
        inSegment_ = true;
        segmentHasRows_ = false;
        namesSeen_ = false;
    }

    void readSegmentHeader() {
        const std::size_t start = lines_.number();
        const std::string startTag(trim(fields_[0]));
        beginSegment();
        std::vector<double> deltaX;
        std::size_t deltaXLine = 0;
        std::size_t channels = 0;
        for (; !lines_.atEnd(); lines_.next()) {
            split(lines_.line(), sep_, fields_);
            const std::string_view tag = trim(fields_[0]);
            if (tag == kEndOfHeader) {
                lines_.next();
                if (current()) {
                    channels_ = channels;
                    setSampleTime(deltaX, deltaXLine);
                }
                return;
            }
            if (tag == "Channels" && fields_.size() > 1) {
                const auto n = parseCellNumber(fields_[1], false, reason_);
                if (n && *n >= 1 && *n <= double(kMaxExperimentColumns) &&
                    *n == double(std::size_t(*n)))
                    channels = std::size_t(*n);
            } else if (tag == "Delta_X") {
                deltaXLine = lines_.number();
                for (std::size_t k = 1; k < fields_.size(); ++k) {
                    if (blank(fields_[k]))
                        continue;
                    const auto v = parseCellNumber(fields_[k], decimalComma_, reason_);
                    deltaX.push_back(v ? *v : std::numeric_limits<double>::quiet_NaN());
                }
            }
        }
        throw InvalidInput(at(start), makeDiagnostic("ident_lvm_segment_header_not_closed",
                                                     {shownCell(startTag)}));
    }

    void setSampleTime(const std::vector<double>& deltaX, std::size_t line) {
        if (deltaX.empty())
            return;
        for (double d : deltaX)
            if (!(d > 0.0) || d != deltaX.front()) {
                out_.table.warnings.push_back(
                    makeDiagnostic("ident_lvm_delta_x_differ", {std::to_string(wanted_)}));
                return;
            }
        // A stated sample time nobody can use is refused here, where the line is known, rather
        // than written into a session that then fails to load or gives a meaningless model.
        requireSampleTime(deltaX.front(), at(line) + ": Delta_X");
        out_.table.sampleTimeSeconds = deltaX.front();
        deltaXLine_ = line;
    }

    /// The X_Value columns must step by the Delta_X the file states: when they do not, one of
    /// the two is wrong and nothing says which (a Delta_X of 0.5 beside steps of 0.01 s).
    void checkDeltaX() const {
        if (!out_.table.sampleTimeSeconds)
            return;
        const double dx = *out_.table.sampleTimeSeconds;
        for (const XSteps& x : xSteps_) {
            if (!x.usable || x.count < 2)
                continue;
            const double step = (x.last - x.first) / double(x.count - 1);
            if (std::abs(step - dx) > kSampleTimeTolerance * dx)
                throw InvalidInput(
                    at(deltaXLine_),
                    makeDiagnostic("ident_lvm_delta_x_contradicts",
                                   {formatNumber(dx, 10), std::to_string(x.field + 1),
                                    std::to_string(x.firstLine), std::to_string(x.lastLine),
                                    formatNumber(step, 10)}));
        }
    }

    /// A name of the name row (or a default name): checked, and kept when asked for.
    void addName(std::string name, std::size_t field) {
        if (allNames_.size() >= kMaxExperimentColumns)
            throw InvalidInput(
                at(lines_.number()),
                makeDiagnostic("ident_more_than_columns", {std::to_string(kMaxExperimentColumns)}));
        for (const std::string& other : allNames_)
            if (other == name)
                throw InvalidInput(
                    at(lines_.number()) + ", column " + std::to_string(field),
                    makeDiagnostic("ident_lvm_channel_name_twice", {shownCell(name)}));
        allNames_.push_back(std::move(name));
        allFields_.push_back(field);
    }

    /// After the names: the columns kept (LvmReadOptions::columns) become the table's, and the
    /// X_Value fields are watched for checkDeltaX.
    void keepColumns() {
        const std::vector<bool> kept = keptColumns(allNames_, wantedColumns_, fileName_);
        ExperimentTable& t = out_.table;
        for (std::size_t c = 0; c < allNames_.size(); ++c) {
            if (xColumns_ != XColumns::No && allNames_[c].compare(0, 7, "X_Value") == 0 &&
                (xColumns_ == XColumns::One ? c == 0 : c % 2 == 0)) {
                XSteps x;
                x.field = allFields_[c] - 1;
                xSteps_.push_back(x);
            }
            if (!kept[c])
                continue;
            t.addColumn(allNames_[c], allFields_[c]);
            columnFields_.push_back(allFields_[c] - 1);
        }
        lastField_ = 0;
        for (std::size_t f : allFields_)
            lastField_ = std::max(lastField_, f);
    }

    void setColumnsFromNames(const std::vector<std::string_view>& fields) {
        std::size_t n = fields.size();
        while (n > 1 && blank(fields[n - 1]))
            --n;
        if (n > 1 && trim(fields[n - 1]) == "Comment") {
            --n;
            commentField_ = n;
        }
        if (xColumns_ == XColumns::Multi) {
            if (n % 2 != 0)
                throw InvalidInput(at(lines_.number()), makeDiagnostic("ident_lvm_multi_unpaired"));
            for (std::size_t k = 0; k < n; k += 2) {
                const std::string name(trim(fields[k + 1]));
                if (name.empty())
                    throw InvalidInput(at(lines_.number()) + ", column " + std::to_string(k + 2),
                                       makeDiagnostic("ident_lvm_channel_name_empty"));
                addName("X_Value (" + name + ")", k + 1);
                addName(name, k + 2);
            }
            keepColumns();
            return;
        }
        if (xColumns_ == XColumns::One)
            addName("X_Value", 1);
        for (std::size_t k = 1; k < n; ++k) {
            const std::string name(trim(fields[k]));
            if (name.empty())
                throw InvalidInput(at(lines_.number()) + ", column " + std::to_string(k + 1),
                                   makeDiagnostic("ident_lvm_channel_name_empty"));
            addName(name, k + 1);
        }
        keepColumns();
    }

    /// No name row before the first data row: LabVIEW's default names, with a warning.
    void setDefaultColumns(std::size_t fieldCount) {
        std::size_t channels = channels_;
        if (channels == 0)
            channels = xColumns_ == XColumns::Multi ? fieldCount / 2
                       : fieldCount > 0             ? fieldCount - 1
                                                    : 0;
        auto untitled = [](std::size_t k) {
            return k == 0 ? std::string("Untitled") : "Untitled " + std::to_string(k);
        };
        if (xColumns_ == XColumns::One)
            addName("X_Value", 1);
        for (std::size_t k = 0; k < channels; ++k) {
            if (xColumns_ == XColumns::Multi) {
                addName("X_Value (" + untitled(k) + ")", 2 * k + 1);
                addName(untitled(k), 2 * k + 2);
            } else {
                addName(untitled(k), k + 2);
            }
        }
        commentField_ = xColumns_ == XColumns::Multi ? 2 * channels : channels + 1;
        keepColumns();
        out_.table.warnings.push_back(
            makeDiagnostic("ident_lvm_no_name_row", {std::to_string(wanted_)}));
    }

    void addRow(const std::vector<std::string_view>& fields) {
        ExperimentTable& t = out_.table;
        if (!namesSeen_ && allNames_.empty()) {
            setDefaultColumns(fields.size());
            namesSeen_ = true;
        }
        const std::size_t used = commentField_ ? *commentField_ : fields.size();
        for (std::size_t k = lastField_; k < fields.size() && k < used; ++k)
            if (!blank(fields[k]))
                throw InvalidInput(at(lines_.number()) + ", column " + std::to_string(k + 1),
                                   makeDiagnostic("ident_lvm_row_more_fields"));
        ++rows_;
        if (countOnly_)
            return;
        if (t.rowNumbers.empty())
            reserveRows(t, expectedRows_);
        const std::size_t row = t.rowNumbers.size();
        t.rowNumbers.push_back(lines_.number());
        for (std::size_t c = 0; c < t.names.size(); ++c) {
            const std::size_t f = columnFields_[c];
            double value = std::numeric_limits<double>::quiet_NaN();
            if (f >= fields.size())
                noteCellProblem(t, c, row, "", missing_);
            else if (const auto v = parseCellNumber(fields[f], decimalComma_, reason_))
                value = *v;
            else
                noteCellProblem(t, c, row, fields[f], reason_);
            t.columns[c].push_back(value);
        }
        for (XSteps& x : xSteps_) {
            if (!x.usable)
                continue;
            const auto v = x.field < fields.size()
                               ? parseCellNumber(fields[x.field], decimalComma_, reason_)
                               : std::nullopt;
            if (!v) {
                x.usable = false;
                continue;
            }
            if (x.count++ == 0) {
                x.first = *v;
                x.firstLine = lines_.number();
            }
            x.last = *v;
            x.lastLine = lines_.number();
        }
    }

    TextLines lines_;
    std::string fileName_;
    std::size_t wanted_;
    std::vector<std::string> wantedColumns_;
    bool countOnly_ = false;
    std::size_t expectedRows_ = 0, rows_ = 0;
    char sep_ = '\t';
    bool decimalComma_ = false;
    XColumns xColumns_ = XColumns::One;
    bool inSegment_ = false, segmentHasRows_ = false, namesSeen_ = false;
    std::size_t channels_ = 0;
    std::vector<std::string> allNames_;     ///< every column of the segment read, kept or not
    std::vector<std::size_t> allFields_;    ///< their 1-based fields
    std::vector<std::size_t> columnFields_; ///< 0-based field of each table column
    std::size_t lastField_ = 0;             ///< the fields beyond it must be blank
    std::optional<std::size_t> commentField_;
    std::vector<XSteps> xSteps_;
    std::size_t deltaXLine_ = 0;
    std::vector<std::string_view> fields_; ///< the fields of the current line
    Diagnostic reason_; ///< parseCellNumber's, unused where only "is it a number" counts
    const Diagnostic missing_ = makeDiagnostic("is_missing");
    LvmTable out_;
};

} // namespace

LvmTable readLvm(std::string_view text, const std::string& fileName,
                 const LvmReadOptions& options) {
    if (text.size() > kMaxExperimentBytes)
        throw InvalidInput(fileName, makeDiagnostic("ident_larger_than_bytes",
                                                    {std::to_string(kMaxExperimentBytes)}));
    if (options.segment < 1)
        throw InvalidInput("segment", makeDiagnostic("ident_lvm_segment_from_one"));
    try {
        LvmParser counter(text, fileName, options, true, 0);
        counter.run();
        return LvmParser(text, fileName, options, false, counter.rowsCounted()).run();
    } catch (const std::bad_alloc&) {
        throwOutOfMemory(fileName, 0, makeDiagnostic("ident_oom_its_table"));
    }
}

LvmTable readLvmFile(const std::string& path, const LvmReadOptions& options) {
    return readLvm(readExperimentFile(path), path, options);
}

} // namespace xyt
