// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/contour/path.h"
#include "core/model/diagnostic.h"

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace xyt {

/// Where each segment of a read program came from, and how fast it is to be run.
struct GcodeSegmentInfo {
    double feedMmPerSec = 0.0; ///< programmed feed (F, or the rapid feed for G0), mm/s
    bool rapid = false;        ///< a G0 move (run at GcodeReadOptions::rapidFeedMmPerMin)
    std::size_t line = 0;      ///< 1-based line of the file
    long blockNumber = -1;     ///< the N word of that line, -1 when it has none
};

/// A read G-code program: the path (mm), per segment its feed and origin, and the warnings.
struct GcodeProgram {
    Path path;
    std::vector<GcodeSegmentInfo> segments; ///< one per path segment
    /// Words that were read but do not change the XY path (Z, M3, S, T, ...), each naming its
    /// line ("line 3: Z word ignored (the path is XY only)"); at most kMaxGcodeWarnings, then
    /// one line saying how many more there were.
    std::vector<Diagnostic> warnings;
    std::size_t lines = 0; ///< lines read

    /// True when the program's feed moves (G1, G2, G3) are exactly one full-circle arc (G0
    /// rapids before or after it allowed): the ISO 230-4 circular test applies to it.
    bool isSingleFullCircle() const;
    /// Index of that arc in path.segments() (valid when isSingleFullCircle()).
    std::size_t fullCircleSegment() const;
};

struct GcodeReadOptions {
    /// Feed of G0 rapids (mm/min). Rapids are part of the path, flagged as such (the contour
    /// statistics can leave them out); a real machine runs them at its rapid rate.
    double rapidFeedMmPerMin = 3000.0;
    /// Where the tool is before the first move (mm): the program's first move starts here.
    Point2 start{0.0, 0.0};
};

/// The most lines a program may have: 1 000 000 (a 10 000-block program is a large one for an
/// XY table; the path holds about 100 bytes per segment, so this bounds it near 100 MB).
inline constexpr std::size_t kMaxGcodeLines = 1'000'000;
/// The most bytes a program may have: 64 MiB (64 bytes per line at the line limit).
inline constexpr std::size_t kMaxGcodeBytes = 64u * 1024u * 1024u;
/// The most warnings kept (a program with a Z word on every line would otherwise keep a
/// million of them); the rest are counted in one last warning.
inline constexpr std::size_t kMaxGcodeWarnings = 100;
/// Coordinates, offsets and radii beyond 1e9 mm are refused (the trajectories' kMaxPositionMm:
/// no table spans more than metres, and the simulation would only overflow).
inline constexpr double kMaxGcodeCoordinateMm = 1e9;

/**
 * The tolerance on an arc's end point: the distance from the centre to the end point may differ
 * from the distance to the start point by at most max(0.002 mm, 1e-6 R) (programs in mm) or
 * max(0.0002 in, 1e-6 R) (programs in inch). Why: a CAM post-processor writes 3 decimals in
 * mm (4 in inch); rounding X, Y, I and J each by half a unit of the last digit moves the two
 * radii apart by at most 2 sqrt(2) x 0.0005 mm = 0.0014 mm (0.00014 in), under the bound; a
 * larger difference is a programming error (a wrong I/J or a wrong end), as LinuxCNC also
 * judges. The relative 1e-6 R keeps radii beyond 2 m from failing on digits a double holds.
 * The same tolerance lets the chord of an R arc exceed 2|R| (rounding) and is then a half
 * circle.
 */
double arcEndTolerance(double radiusMm, bool inch);

/**
 * Reads the XY subset of RS274/NGC G-code, its lines ended by LF, CR LF or a lone CR (classic
 * Mac OS), each counted as one line in the numbers of the messages:
 *   - G0 (rapid), G1 (line), G2 (clockwise arc), G3 (counter-clockwise arc); the motion mode is
 *     modal: a line with only X/Y (and F) continues the last one;
 *   - arcs with I, J (the centre relative to the start point, always incremental) or R (the
 *     radius; R > 0 the arc of at most a half turn, R < 0 the larger one); I/J with the end
 *     point equal to the start is a full circle (R is refused there: it has no centre);
 *   - G17 (the XY plane, the only one), G20/G21 (inch/mm, modal), G90/G91 (absolute/
 *     incremental X/Y, modal), G94 (feed per minute, the only feed mode), F (modal feed in
 *     units per minute), N (block numbers), comments in parentheses and after ';', a line
 *     holding only '%' (the program delimiter), letters in either case, spaces anywhere
 *     between words and between a letter and its number.
 *   - M2 and M30 end the program, silently: their line is read whole, the lines after it
 *     are not read (a controller never runs them; a warning says so when they hold more
 *     than blanks and '%');
 *   - Z words and the M codes M0 M1 M3 M4 M5 M6 M7 M8 M9, S (spindle speed) and T (tool)
 *     words are read and ignored with a warning naming the line.
 * The tool starts at GcodeReadOptions::start. Every move becomes a path segment (a zero-length
 * move none); G0 moves too, flagged rapid.
 *
 * @throws InvalidInput whose field names the line ("line 12") and whose reason names the word
 *         and its column where there is one ("unknown word G5 at column 4"): an unknown word or
 *         letter, a number missing or malformed ("malformed number X1.2.3 at column 4: more
 *         than one decimal point", "X0x10": no 0x prefix), a word given twice on a line, two motion
 * G codes on a line, X/Y before any motion mode, I/J/R without G2/G3, an arc without I/J or R or
 * with both, an arc whose end is off its circle by more than arcEndTolerance, a zero radius, R too
 * small for the chord, a full circle given by R, a feed move before any F, F <= 0, a coordinate
 * beyond kMaxGcodeCoordinateMm, an unclosed comment. Field "program": more than kMaxGcodeLines
 * lines or kMaxGcodeBytes bytes, or no motion at all. "rapid_feed": the option not finite and
 * within the planner's range of feeds (kMinProfileRate .. kMaxProfileRate mm/s, feed_profile.h).
 */
GcodeProgram readGcode(std::string_view text, const GcodeReadOptions& options = {});

} // namespace xyt
