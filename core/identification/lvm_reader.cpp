// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/identification/lvm_reader.h"

#include "core/model/errors.h"

#include <limits>

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

std::vector<std::string_view> split(std::string_view line, char sep) {
    std::vector<std::string_view> out;
    std::size_t start = 0;
    while (true) {
        const std::size_t end = line.find(sep, start);
        out.push_back(line.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start));
        if (end == std::string_view::npos || out.size() > kMaxExperimentColumns * 2 + 2)
            break;
        start = end + 1;
    }
    return out;
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

bool blank(std::string_view line) { return trim(line).empty(); }

class LvmParser {
public:
    LvmParser(std::string_view text, const std::string& fileName, std::size_t segment)
        : lines_(splitLines(text)), fileName_(fileName), wanted_(segment) {
        out_.table.fileName = fileName;
    }

    LvmTable run() {
        readFileHeader();
        if (decimalComma_ && sep_ == ',')
            throw InvalidInput(fileName_, "a decimal comma cannot be read with Comma separators");
        while (i_ < lines_.size())
            step();
        if (out_.segmentCount == 0)
            throw InvalidInput(fileName_, "holds no data segment");
        if (wanted_ > out_.segmentCount)
            throw InvalidInput(fileName_, "has " + std::to_string(out_.segmentCount) + " segment" +
                                              (out_.segmentCount == 1 ? "" : "s") + ", not a segment " +
                                              std::to_string(wanted_));
        if (out_.segmentCount > 1)
            out_.table.warnings.push_back("the file has " + std::to_string(out_.segmentCount) +
                                          " segments; segment " + std::to_string(wanted_) + " was read");
        if (out_.table.names.empty())
            throw InvalidInput(fileName_, "segment " + std::to_string(wanted_) + " holds no channel");
        return std::move(out_);
    }

private:
    std::string at(std::size_t index) const { return fileName_ + ": line " + std::to_string(index + 1); }

    void skipSpecial() {
        const std::size_t start = i_;
        while (++i_ < lines_.size())
            if (trim(tagValue(lines_[i_]).first) == kEndSpecial) {
                ++i_;
                return;
            }
        throw InvalidInput(at(start), "the ***Start_Special*** block is not closed by ***End_Special***");
    }

    void readFileHeader() {
        while (i_ < lines_.size() && blank(lines_[i_]))
            ++i_;
        if (i_ == lines_.size() || tagValue(lines_[i_]).first != "LabVIEW Measurement")
            throw InvalidInput(i_ == lines_.size() ? fileName_ : at(i_),
                               "is not a LabVIEW Measurement file (the first line must be the tag "
                               "'LabVIEW Measurement')");
        const std::size_t start = i_++;
        bool separatorSeen = false, xColumnsSeen = false;
        for (; i_ < lines_.size(); ++i_) {
            const auto [tag, value] = tagValue(lines_[i_]);
            if (tag == kStartSpecial) {
                skipSpecial();
                --i_;
                continue;
            }
            if (tag == kEndOfHeader) {
                ++i_;
                if (!separatorSeen)
                    out_.table.warnings.push_back("the file header has no Separator tag: Tab assumed");
                if (!xColumnsSeen)
                    out_.table.warnings.push_back("the file header has no X_Columns tag: One assumed");
                return;
            }
            if (tag == "Separator") {
                separatorSeen = true;
                if (value == "Tab")
                    sep_ = '\t';
                else if (value == "Comma")
                    sep_ = ',';
                else
                    throw InvalidInput(at(i_), "Separator '" + shownCell(value) + "' is not Tab or Comma");
            } else if (tag == "Decimal_Separator") {
                // With comma-separated fields the value itself is the second field: "Decimal_Separator,,"
                // holds an empty value between two commas, so look at the raw text too.
                const std::string_view raw = trim(lines_[i_].substr(tag.size()));
                if (value == ".")
                    decimalComma_ = false;
                else if (value == "," || raw == ",," || raw == "\t,")
                    decimalComma_ = true;
                else
                    throw InvalidInput(at(i_), "Decimal_Separator '" + shownCell(value) + "' is not '.' or ','");
            } else if (tag == "X_Columns") {
                xColumnsSeen = true;
                if (value == "No")
                    xColumns_ = XColumns::No;
                else if (value == "One")
                    xColumns_ = XColumns::One;
                else if (value == "Multi")
                    xColumns_ = XColumns::Multi;
                else
                    throw InvalidInput(at(i_), "X_Columns '" + shownCell(value) + "' is not No, One or Multi");
            }
        }
        throw InvalidInput(at(start), "the file header is not closed by ***End_of_Header***");
    }

    /// One line (or a block) of the data part.
    void step() {
        const std::vector<std::string_view> fields = split(lines_[i_], sep_);
        bool empty = true; // a line of separators only ("," in comma files) is blank too
        for (std::string_view f : fields)
            empty = empty && blank(f);
        if (empty) {
            ++i_;
            return;
        }
        const std::string_view first = trim(fields[0]);
        if (first == kStartSpecial) {
            skipSpecial();
            return;
        }
        std::string reason;
        if (first == "X_Value") {
            if (segmentHasRows_ || !inSegment_)
                beginSegment(false);
            if (current() && namesSeen_)
                throw InvalidInput(at(i_), "a second column-name row in segment " + std::to_string(wanted_));
            if (current())
                setColumnsFromNames(fields);
            namesSeen_ = true;
            ++i_;
            return;
        }
        if (first.empty() || parseCellNumber(first, decimalComma_, reason)) {
            if (!inSegment_)
                beginSegment(false);
            if (current())
                addRow(fields);
            segmentHasRows_ = true;
            ++i_;
            return;
        }
        readSegmentHeader();
    }

    bool current() const { return out_.segmentCount == wanted_; }

    void beginSegment(bool /*withHeader*/) {
        ++out_.segmentCount;
        inSegment_ = true;
        segmentHasRows_ = false;
        namesSeen_ = false;
    }

    void readSegmentHeader() {
        const std::size_t start = i_;
        beginSegment(true);
        std::vector<double> deltaX;
        std::size_t channels = 0;
        for (; i_ < lines_.size(); ++i_) {
            const std::vector<std::string_view> fields = split(lines_[i_], sep_);
            const std::string_view tag = trim(fields[0]);
            if (tag == kEndOfHeader) {
                ++i_;
                if (current()) {
                    channels_ = channels;
                    setSampleTime(deltaX);
                }
                return;
            }
            if (tag == "Channels" && fields.size() > 1) {
                std::string reason;
                const auto n = parseCellNumber(fields[1], false, reason);
                if (n && *n >= 1 && *n <= double(kMaxExperimentColumns) && *n == double(std::size_t(*n)))
                    channels = std::size_t(*n);
            } else if (tag == "Delta_X") {
                for (std::size_t k = 1; k < fields.size(); ++k) {
                    if (blank(fields[k]))
                        continue;
                    std::string reason;
                    const auto v = parseCellNumber(fields[k], decimalComma_, reason);
                    deltaX.push_back(v ? *v : std::numeric_limits<double>::quiet_NaN());
                }
            }
        }
        throw InvalidInput(at(start), "the segment header that starts here with '" +
                                          shownCell(trim(split(lines_[start], sep_)[0])) +
                                          "' is not closed by ***End_of_Header***");
    }

    void setSampleTime(const std::vector<double>& deltaX) {
        if (deltaX.empty())
            return;
        for (double d : deltaX)
            if (!(d > 0.0) || d != deltaX.front()) {
                out_.table.warnings.push_back("the Delta_X of segment " + std::to_string(wanted_) +
                                              " differ between channels or are not positive: no sample time taken from the file");
                return;
            }
        out_.table.sampleTimeSeconds = deltaX.front();
    }

    void addName(std::string name, std::size_t field) {
        ExperimentTable& t = out_.table;
        if (t.names.size() >= kMaxExperimentColumns)
            throw InvalidInput(at(i_), "has more than " + std::to_string(kMaxExperimentColumns) + " columns");
        for (const std::string& other : t.names)
            if (other == name)
                throw InvalidInput(at(i_) + ", column " + std::to_string(field),
                                   "the channel name '" + shownCell(name) + "' is used twice");
        t.addColumn(std::move(name), field);
        columnFields_.push_back(field - 1);
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
                throw InvalidInput(at(i_), "X_Columns is Multi but the name row does not pair every "
                                           "channel with an X_Value column");
            for (std::size_t k = 0; k < n; k += 2) {
                const std::string name(trim(fields[k + 1]));
                if (name.empty())
                    throw InvalidInput(at(i_) + ", column " + std::to_string(k + 2), "the channel name is empty");
                addName("X_Value (" + name + ")", k + 1);
                addName(name, k + 2);
            }
            return;
        }
        if (xColumns_ == XColumns::One)
            addName("X_Value", 1);
        for (std::size_t k = 1; k < n; ++k) {
            const std::string name(trim(fields[k]));
            if (name.empty())
                throw InvalidInput(at(i_) + ", column " + std::to_string(k + 1), "the channel name is empty");
            addName(name, k + 1);
        }
    }

    /// No name row before the first data row: LabVIEW's default names, with a warning.
    void setDefaultColumns(std::size_t fieldCount) {
        std::size_t channels = channels_;
        if (channels == 0)
            channels = xColumns_ == XColumns::Multi ? fieldCount / 2 : fieldCount > 0 ? fieldCount - 1 : 0;
        auto untitled = [](std::size_t k) { return k == 0 ? std::string("Untitled") : "Untitled " + std::to_string(k); };
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
        out_.table.warnings.push_back("segment " + std::to_string(wanted_) +
                                      " has no column-name row: the channels are named Untitled, Untitled 1, ...");
    }

    void addRow(const std::vector<std::string_view>& fields) {
        ExperimentTable& t = out_.table;
        if (!namesSeen_ && t.names.empty()) {
            setDefaultColumns(fields.size());
            namesSeen_ = true;
        }
        const std::size_t used = commentField_ ? *commentField_ : fields.size();
        std::size_t last = 0;
        for (std::size_t f : columnFields_)
            last = std::max(last, f + 1);
        for (std::size_t k = last; k < fields.size() && k < used; ++k)
            if (!blank(fields[k]))
                throw InvalidInput(at(i_) + ", column " + std::to_string(k + 1),
                                   "the row has more fields than the column-name row names");
        const std::size_t row = t.rowNumbers.size();
        t.rowNumbers.push_back(i_ + 1);
        for (std::size_t c = 0; c < t.names.size(); ++c) {
            const std::size_t f = columnFields_[c];
            double value = std::numeric_limits<double>::quiet_NaN();
            std::string reason;
            if (f >= fields.size())
                noteCellProblem(t, c, row, "", "is missing");
            else if (const auto v = parseCellNumber(fields[f], decimalComma_, reason))
                value = *v;
            else
                noteCellProblem(t, c, row, fields[f], reason);
            t.columns[c].push_back(value);
        }
    }

    std::vector<std::string_view> lines_;
    std::string fileName_;
    std::size_t wanted_;
    std::size_t i_ = 0;
    char sep_ = '\t';
    bool decimalComma_ = false;
    XColumns xColumns_ = XColumns::One;
    bool inSegment_ = false, segmentHasRows_ = false, namesSeen_ = false;
    std::size_t channels_ = 0;
    std::vector<std::size_t> columnFields_; ///< 0-based field of each table column
    std::optional<std::size_t> commentField_;
    LvmTable out_;
};

} // namespace

LvmTable readLvm(std::string_view text, const std::string& fileName, const LvmReadOptions& options) {
    if (text.size() > kMaxExperimentBytes)
        throw InvalidInput(fileName, "is larger than " + std::to_string(kMaxExperimentBytes) + " bytes");
    if (options.segment < 1)
        throw InvalidInput("segment", "must be 1 or more (segments are counted from 1)");
    return LvmParser(text, fileName, options.segment).run();
}

LvmTable readLvmFile(const std::string& path, const LvmReadOptions& options) {
    return readLvm(readExperimentFile(path), path, options);
}

} // namespace xyt
