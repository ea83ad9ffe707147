// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/contour/gcode_reader.h"

#include "core/contour/feed_profile.h"
#include "core/model/diagnostic_catalogue.h"

#include "core/model/errors.h"
#include "core/model/math_constants.h"
#include "core/model/number_format.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <numbers>
#include <optional>

namespace xyt {

namespace {

constexpr double kMmPerInch = 25.4;
/// A number longer than this is refused (no G-code writer needs more digits than a double has).
constexpr std::size_t kMaxNumberChars = 40;

/// One word of a line: its letter (upper case), value, the text as written, 1-based column.
struct Word {
    char letter = 0;
    double value = 0.0;
    std::string text;
    std::size_t column = 0;
};

/// The 1-based column of a word or character as the messages' argument ("at column %2").
std::string columnText(std::size_t column) {
    return std::to_string(column);
}

/// A byte as it may be shown in a one-line message: printable ASCII as is, else \xNN.
std::string shown(char c) {
    const auto u = static_cast<unsigned char>(c);
    if (u >= 0x20 && u < 0x7f)
        return std::string(1, c);
    const char* hex = "0123456789abcdef";
    return std::string("\\x") + hex[u >> 4] + hex[u & 15];
}

bool isSpace(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}
bool isDigit(char c) {
    return c >= '0' && c <= '9';
}
bool isLetter(char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z');
}

bool isHexDigit(char c) {
    return isDigit(c) || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F');
}

/**
 * Refuses a number that goes on past where the tokenizer stops reading it, when what follows
 * cannot be another word: a second decimal point ("X1.2.3"), or a hexadecimal "0x" on an X word
 * ("X0x10", which would otherwise read as X0 and X10 and be called a word given twice). After
 * any other word, "0x10" stays the valid "0 X10" ("Y0x10" is Y0 X10). @p next is the index of
 * the first character after the number.
 */
void malformedNumber(std::string_view line, std::size_t next, const Word& w,
                     const std::string& number, const std::string& field) {
    if (next >= line.size())
        return;
    const char* whyCode = nullptr;
    std::size_t end = next;
    if (line[next] == '.') {
        while (end < line.size() && (isDigit(line[end]) || line[end] == '.'))
            ++end;
        whyCode = "contour_gcode_two_decimal_points";
    } else if (w.letter == 'X' && (line[next] == 'x' || line[next] == 'X') &&
               next + 1 < line.size() && isHexDigit(line[next + 1]) &&
               number.find_first_not_of("+-0") == std::string::npos) {
        end = next + 1;
        while (end < line.size() && isHexDigit(line[end]))
            ++end;
        whyCode = "contour_gcode_hex_number";
    } else {
        return;
    }
    const std::string text =
        std::string(1, w.letter) + number + std::string(line.substr(next, end - next));
    throw InvalidInput(field, makeDiagnostic("contour_gcode_malformed_number",
                                             {text.substr(0, kMaxNumberChars + 1),
                                              columnText(w.column), makeDiagnostic(whyCode)}));
}

/// Splits one line into words, dropping comments. @throws InvalidInput @p field.
std::vector<Word> words(std::string_view line, const std::string& field) {
    std::vector<Word> out;
    std::size_t i = 0;
    while (i < line.size()) {
        const char c = line[i];
        if (isSpace(c)) {
            ++i;
        } else if (c == ';') {
            break;
        } else if (c == '(') {
            const std::size_t close = line.find(')', i + 1);
            if (close == std::string_view::npos)
                throw InvalidInput(
                    field, makeDiagnostic("contour_gcode_comment_not_closed", {columnText(i + 1)}));
            i = close + 1;
        } else if (isLetter(c)) {
            Word w;
            w.letter = static_cast<char>(c >= 'a' ? c - 'a' + 'A' : c);
            w.column = i + 1;
            ++i;
            while (i < line.size() && isSpace(line[i]))
                ++i;
            std::string number;
            if (i < line.size() && (line[i] == '+' || line[i] == '-'))
                number += line[i++];
            bool digits = false, point = false;
            while (i < line.size() && (isDigit(line[i]) || (line[i] == '.' && !point))) {
                digits = digits || isDigit(line[i]);
                point = point || line[i] == '.';
                number += line[i++];
                if (number.size() > kMaxNumberChars)
                    throw InvalidInput(
                        field, makeDiagnostic("contour_gcode_number_too_long",
                                              {std::string(1, w.letter), columnText(w.column),
                                               std::to_string(kMaxNumberChars)}));
            }
            if (!digits)
                throw InvalidInput(
                    field, makeDiagnostic("contour_gcode_word_no_number",
                                          {std::string(1, w.letter), columnText(w.column)}));
            malformedNumber(line, i, w, number, field);
            w.text = std::string(1, w.letter) + number;
            const char* begin = number.data() + (number[0] == '+' ? 1 : 0);
            const auto [end, error] = std::from_chars(begin, number.data() + number.size(), w.value,
                                                      std::chars_format::fixed);
            if (error != std::errc() || end != number.data() + number.size() ||
                !std::isfinite(w.value))
                throw InvalidInput(field, makeDiagnostic("contour_gcode_number_not_representable",
                                                         {w.text, columnText(w.column)}));
            out.push_back(std::move(w));
        } else {
            throw InvalidInput(field, makeDiagnostic("contour_gcode_unexpected_character",
                                                     {shown(c), columnText(i + 1)}));
        }
    }
    return out;
}

/// A G or M code's number when it is a whole number 0..999, else -1 (an unknown word).
int code(const Word& w) {
    if (w.value < 0.0 || w.value > 999.0 || w.value != std::floor(w.value))
        return -1;
    return static_cast<int>(w.value);
}

enum class Motion { None, Rapid, Line, Clockwise, CounterClockwise };

/// The state a program carries from line to line (the modal groups of RS274/NGC).
struct Modal {
    Motion motion = Motion::None;
    bool inch = false;
    bool incremental = false;
    std::optional<double> feed; ///< in units per minute, as programmed
    Point2 position;            ///< mm
};

class Reader {
public:
    explicit Reader(const GcodeReadOptions& options) : options_(options) {
        modal_.position = options.start;
    }

    void line(std::string_view text, std::size_t number);
    /// The program end (M2 or M30) was read: the lines after it are not part of the program.
    bool ended() const { return ended_; }
    /// Says that lines holding more than blanks and '%' follow the program end (they are not
    /// run, which their author may not expect).
    void textAfterEnd() { warn(makeDiagnostic("contour_gcode_lines_after_end", {endWord_})); }
    GcodeProgram finish();

private:
    void warn(const Diagnostic& message);
    double unit() const { return modal_.inch ? kMmPerInch : 1.0; }
    /// A length word in mm, refused beyond kMaxGcodeCoordinateMm.
    double millimetres(const Word& w) const;
    void addSegment(const PathSegment& segment, bool rapid);
    void arc(const Point2& target, bool clockwise, const Word* i, const Word* j, const Word* r,
             const Word& motionWord);

    GcodeReadOptions options_;
    Modal modal_;
    std::string field_;
    std::size_t lineNumber_ = 0;
    long blockNumber_ = -1;
    std::vector<PathSegment> segments_;
    std::vector<GcodeSegmentInfo> info_;
    std::vector<Diagnostic> warnings_;
    std::size_t droppedWarnings_ = 0;
    std::size_t lines_ = 0;
    bool ended_ = false;
    std::string endWord_;
};

void Reader::warn(const Diagnostic& message) {
    if (warnings_.size() < kMaxGcodeWarnings)
        warnings_.push_back(
            makeDiagnostic("contour_gcode_line_warning", {std::to_string(lineNumber_), message}));
    else
        ++droppedWarnings_;
}

double Reader::millimetres(const Word& w) const {
    const double mm = w.value * unit();
    if (!(std::abs(mm) <= kMaxGcodeCoordinateMm))
        throw InvalidInput(field_, makeDiagnostic("contour_gcode_beyond_limit",
                                                  {w.text, columnText(w.column),
                                                   formatNumber(kMaxGcodeCoordinateMm)}));
    return mm;
}

void Reader::addSegment(const PathSegment& segment, bool rapid) {
    GcodeSegmentInfo info;
    info.rapid = rapid;
    info.feedMmPerSec = rapid ? options_.rapidFeedMmPerMin / 60.0 : *modal_.feed * unit() / 60.0;
    info.line = lineNumber_;
    info.blockNumber = blockNumber_;
    segments_.push_back(segment);
    info_.push_back(info);
}

void Reader::arc(const Point2& target, bool clockwise, const Word* i, const Word* j, const Word* r,
                 const Word& motionWord) {
    const Point2 start = modal_.position;
    const std::string name = motionWord.text;
    if (!i && !j && !r)
        throw InvalidInput(field_, makeDiagnostic("contour_gcode_arc_needs_centre",
                                                  {name, columnText(motionWord.column)}));
    if (r && (i || j))
        throw InvalidInput(field_, makeDiagnostic("contour_gcode_arc_both_r_ij",
                                                  {name, columnText(motionWord.column)}));
    const double chord = norm(target - start);
    Point2 centre;
    if (r) {
        if (chord == 0.0)
            throw InvalidInput(
                field_, makeDiagnostic("contour_gcode_full_circle_r", {columnText(r->column)}));
        const double radius = std::abs(millimetres(*r));
        if (radius == 0.0)
            throw InvalidInput(field_, makeDiagnostic("contour_gcode_zero_radius_word",
                                                      {r->text, columnText(r->column)}));
        const double half = chord / 2.0;
        const double tolerance = arcEndTolerance(radius, modal_.inch);
        if (half > radius + tolerance)
            throw InvalidInput(
                field_, makeDiagnostic("contour_gcode_radius_below_half_chord",
                                       {r->text, columnText(r->column), formatNumber(half)}));
        const double h = std::sqrt(std::max(radius * radius - half * half, 0.0));
        const Point2 u = (1.0 / chord) * (target - start);
        const Point2 left{-u.y, u.x};
        // The centre of the shorter arc lies left of the chord for G3, right for G2; R < 0 asks
        // for the longer arc, whose centre is on the other side.
        const double side = (clockwise ? -1.0 : 1.0) * (r->value < 0.0 ? -1.0 : 1.0);
        centre = 0.5 * (start + target) + (side * h) * left;
    } else {
        centre = start + Point2{i ? millimetres(*i) : 0.0, j ? millimetres(*j) : 0.0};
    }
    const double radius = norm(start - centre);
    if (radius == 0.0)
        throw InvalidInput(field_, makeDiagnostic("contour_gcode_arc_zero_radius",
                                                  {name, columnText(motionWord.column)}));
    const double endRadius = norm(target - centre);
    const double tolerance = arcEndTolerance(radius, modal_.inch);
    if (std::abs(endRadius - radius) > tolerance)
        throw InvalidInput(
            field_, makeDiagnostic("contour_gcode_arc_end_off_circle",
                                   {name, columnText(motionWord.column), formatNumber(endRadius),
                                    formatNumber(radius), formatNumber(tolerance)}));
    const double a0 = std::atan2(start.y - centre.y, start.x - centre.x);
    const double a1 = std::atan2(target.y - centre.y, target.x - centre.x);
    double sweep = std::fmod(clockwise ? a0 - a1 : a1 - a0, kTwoPi);
    if (sweep < 0.0)
        sweep += kTwoPi;
    // End equal to the start (or on the same ray within the tolerance): a full circle.
    if (chord == 0.0 || sweep == 0.0)
        sweep = kTwoPi;
    addSegment(PathSegment::arc(centre, radius, a0, clockwise ? -sweep : sweep), false);
}

void Reader::line(std::string_view text, std::size_t number) {
    lineNumber_ = number;
    lines_ = number;
    field_ = "line " + std::to_string(number);
    blockNumber_ = -1;
    {
        std::string_view trimmed = text;
        while (!trimmed.empty() && isSpace(trimmed.front()))
            trimmed.remove_prefix(1);
        while (!trimmed.empty() && isSpace(trimmed.back()))
            trimmed.remove_suffix(1);
        if (trimmed == "%")
            return;
    }
    const std::vector<Word> all = words(text, field_);
    const Word* motionWord = nullptr;
    std::optional<Motion> motion;
    // Axis and parameter words, at most once each.
    const Word* x = nullptr;
    const Word* y = nullptr;
    const Word* i = nullptr;
    const Word* j = nullptr;
    const Word* r = nullptr;
    const Word* f = nullptr;
    const Word* n = nullptr;
    bool unitsSeen = false, distanceSeen = false;
    for (const Word& w : all) {
        const Word** slot = nullptr;
        switch (w.letter) {
        case 'X':
            slot = &x;
            break;
        case 'Y':
            slot = &y;
            break;
        case 'I':
            slot = &i;
            break;
        case 'J':
            slot = &j;
            break;
        case 'R':
            slot = &r;
            break;
        case 'F':
            slot = &f;
            break;
        case 'N':
            slot = &n;
            break;
        default:
            break;
        }
        if (slot) {
            if (*slot)
                throw InvalidInput(field_, makeDiagnostic("contour_gcode_word_twice",
                                                          {std::string(1, w.letter), w.text,
                                                           columnText(w.column)}));
            *slot = &w;
            continue;
        }
        const int c = code(w);
        if (w.letter == 'G') {
            if (c >= 0 && c <= 3) {
                if (motionWord)
                    throw InvalidInput(
                        field_, makeDiagnostic("contour_gcode_two_motion_codes",
                                               {motionWord->text, w.text, columnText(w.column)}));
                motionWord = &w;
                motion = c == 0   ? Motion::Rapid
                         : c == 1 ? Motion::Line
                         : c == 2 ? Motion::Clockwise
                                  : Motion::CounterClockwise;
            } else if (c == 20 || c == 21) {
                if (unitsSeen)
                    throw InvalidInput(field_, makeDiagnostic("contour_gcode_two_unit_codes",
                                                              {w.text, columnText(w.column)}));
                unitsSeen = true;
                modal_.inch = c == 20;
            } else if (c == 90 || c == 91) {
                if (distanceSeen)
                    throw InvalidInput(field_, makeDiagnostic("contour_gcode_two_distance_modes",
                                                              {w.text, columnText(w.column)}));
                distanceSeen = true;
                modal_.incremental = c == 91;
            } else if (c == 18 || c == 19) {
                throw InvalidInput(field_, makeDiagnostic("contour_gcode_plane_not_xy",
                                                          {w.text, columnText(w.column)}));
            } else if (c != 17 && c != 94) {
                throw InvalidInput(field_, makeDiagnostic("contour_gcode_unknown_word",
                                                          {w.text, columnText(w.column)}));
            }
        } else if (w.letter == 'M') {
            // M2 and M30 end the program: nothing to warn about, as every program ends so.
            if (c == 2 || c == 30) {
                ended_ = true;
                endWord_ = w.text;
                continue;
            }
            static constexpr int kIgnored[] = {0, 1, 3, 4, 5, 6, 7, 8, 9};
            if (std::find(std::begin(kIgnored), std::end(kIgnored), c) == std::end(kIgnored))
                throw InvalidInput(field_, makeDiagnostic("contour_gcode_unknown_word",
                                                          {w.text, columnText(w.column)}));
            warn(makeDiagnostic("contour_gcode_ignored_not_xy", {w.text}));
        } else if (w.letter == 'Z') {
            warn(makeDiagnostic("contour_gcode_ignored_z", {w.text}));
        } else if (w.letter == 'S' || w.letter == 'T') {
            warn(makeDiagnostic(w.letter == 'S' ? "contour_gcode_ignored_spindle"
                                                : "contour_gcode_ignored_tool",
                                {w.text}));
        } else {
            throw InvalidInput(field_, makeDiagnostic("contour_gcode_unknown_word",
                                                      {w.text, columnText(w.column)}));
        }
    }
    if (n) {
        if (n->value < 0.0 || n->value != std::floor(n->value) || n->value > 1e9)
            throw InvalidInput(field_, makeDiagnostic("contour_gcode_block_number",
                                                      {n->text, columnText(n->column)}));
        blockNumber_ = static_cast<long>(n->value);
    }
    if (f) {
        if (!(f->value > 0.0))
            throw InvalidInput(field_, makeDiagnostic("contour_gcode_feed_not_positive",
                                                      {f->text, columnText(f->column)}));
        modal_.feed = f->value;
    }
    if (motion)
        modal_.motion = *motion;
    const bool arcWords = i || j || r;
    const bool axisWords = x || y;
    const bool arcMode =
        modal_.motion == Motion::Clockwise || modal_.motion == Motion::CounterClockwise;
    if (arcWords && !arcMode) {
        const Word* w = i ? i : j ? j : r;
        throw InvalidInput(
            field_, makeDiagnostic("contour_gcode_needs_arc", {w->text, columnText(w->column)}));
    }
    if (!axisWords && !arcWords)
        return; // modes, feed, ignored words: no motion
    if (modal_.motion == Motion::None) {
        const Word* w = x ? x : y;
        throw InvalidInput(field_, makeDiagnostic("contour_gcode_no_motion_mode",
                                                  {w->text, columnText(w->column)}));
    }
    const Word& modeWord = motionWord ? *motionWord : *(x ? x : y ? y : i ? i : j ? j : r);
    if (modal_.motion != Motion::Rapid && !modal_.feed)
        throw InvalidInput(
            field_, motionWord ? makeDiagnostic("contour_gcode_no_feed",
                                                {motionWord->text, columnText(modeWord.column)})
                               : makeDiagnostic("contour_gcode_no_feed_modal",
                                                {columnText(modeWord.column)}));
    Point2 target = modal_.position;
    if (x)
        target.x = modal_.incremental ? target.x + millimetres(*x) : millimetres(*x);
    if (y)
        target.y = modal_.incremental ? target.y + millimetres(*y) : millimetres(*y);
    if (!(std::abs(target.x) <= kMaxGcodeCoordinateMm &&
          std::abs(target.y) <= kMaxGcodeCoordinateMm))
        throw InvalidInput(field_, makeDiagnostic("contour_gcode_incremental_beyond",
                                                  {columnText(modeWord.column),
                                                   formatNumber(kMaxGcodeCoordinateMm)}));
    if (arcMode) {
        Word named = modeWord;
        if (!motionWord)
            named.text = modal_.motion == Motion::Clockwise ? "G2" : "G3";
        arc(target, modal_.motion == Motion::Clockwise, i, j, r, named);
    } else if (!(target == modal_.position)) {
        addSegment(PathSegment::line(modal_.position, target), modal_.motion == Motion::Rapid);
    }
    modal_.position = target;
}

GcodeProgram Reader::finish() {
    if (segments_.empty())
        throw InvalidInput("program", makeDiagnostic("contour_gcode_no_motion"));
    if (droppedWarnings_ > 0)
        warnings_.push_back(
            makeDiagnostic("contour_gcode_more_warnings", {std::to_string(droppedWarnings_)}));
    GcodeProgram program;
    program.path = Path(std::move(segments_));
    program.segments = std::move(info_);
    program.warnings = std::move(warnings_);
    program.lines = lines_;
    return program;
}

} // namespace

double arcEndTolerance(double radiusMm, bool inch) {
    return std::max(inch ? 0.0002 * kMmPerInch : 0.002, 1e-6 * radiusMm);
}

GcodeProgram readGcode(std::string_view text, const GcodeReadOptions& options) {
    if (!(options.rapidFeedMmPerMin > 0.0) || !std::isfinite(options.rapidFeedMmPerMin))
        throw InvalidInput("rapid_feed", makeDiagnostic("finite_positive"));
    // The planner's range of feeds (feed_profile.h), in mm/min.
    if (!(options.rapidFeedMmPerMin >= 60.0 * kMinProfileRate &&
          options.rapidFeedMmPerMin <= 60.0 * kMaxProfileRate))
        throw InvalidInput("rapid_feed", makeDiagnostic("contour_rapid_feed_outside",
                                                        {formatNumber(options.rapidFeedMmPerMin),
                                                         formatNumber(60.0 * kMinProfileRate),
                                                         formatNumber(60.0 * kMaxProfileRate)}));
    if (!(std::abs(options.start.x) <= kMaxGcodeCoordinateMm &&
          std::abs(options.start.y) <= kMaxGcodeCoordinateMm))
        throw InvalidInput(
            "start", makeDiagnostic("contour_start_within", {formatNumber(kMaxGcodeCoordinateMm)}));
    if (text.size() > kMaxGcodeBytes)
        throw InvalidInput(
            "program", makeDiagnostic("io_larger_than_limit", {std::to_string(kMaxGcodeBytes)}));
    // Lines end at LF (Unix), CR LF (DOS) or a lone CR (classic Mac OS): a CR not followed by LF
    // ends a line too, so a CR-only file has its lines and their numbers.
    const auto lineEnd = [&](std::size_t begin) {
        std::size_t end = begin;
        while (end < text.size() && text[end] != '\n' && text[end] != '\r')
            ++end;
        return end;
    };
    const auto nextLine = [&](std::size_t end) {
        return end + (end + 1 < text.size() && text[end] == '\r' && text[end + 1] == '\n' ? 2 : 1);
    };
    std::size_t lines = 0;
    for (std::size_t begin = 0; begin < text.size(); begin = nextLine(lineEnd(begin)))
        ++lines;
    if (lines > kMaxGcodeLines)
        throw InvalidInput("program", makeDiagnostic("contour_gcode_too_many_lines",
                                                     {std::to_string(kMaxGcodeLines)}));
    Reader reader(options);
    std::size_t number = 0;
    // The program end's line is read whole (its motion comes before the end, as RS274/NGC
    // orders a block); the lines after it are not read, as a controller never runs them.
    std::size_t begin = 0;
    while (begin < text.size() && !reader.ended()) {
        const std::size_t end = lineEnd(begin);
        reader.line(text.substr(begin, end - begin), ++number);
        begin = nextLine(end);
    }
    const std::string_view rest = begin < text.size() ? text.substr(begin) : std::string_view();
    if (std::any_of(rest.begin(), rest.end(),
                    [](char c) { return !isSpace(c) && c != '\n' && c != '%'; }))
        reader.textAfterEnd();
    return reader.finish();
}

bool GcodeProgram::isSingleFullCircle() const {
    std::size_t feedMoves = 0;
    bool circle = false;
    for (std::size_t i = 0; i < segments.size(); ++i) {
        if (segments[i].rapid)
            continue;
        ++feedMoves;
        const PathSegment& s = path.segments()[i];
        circle = s.isArc() && std::abs(s.sweep()) == kTwoPi;
    }
    return feedMoves == 1 && circle;
}

std::size_t GcodeProgram::fullCircleSegment() const {
    for (std::size_t i = 0; i < segments.size(); ++i)
        if (!segments[i].rapid)
            return i;
    return 0;
}

} // namespace xyt
