// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstddef>

// A ballbar program as machine shops write it (the Renishaw QC20 routine's shape): a feed-in
// arc onto the 25 mm circle about the origin, the circle clockwise, a feed-out and a feed-in
// arc, the circle counter-clockwise, a feed-out arc. The feed-in and feed-out arcs (radius 5
// about (20, 0)) meet the circle tangentially at (25, 0).
namespace xyt::test {

inline constexpr const char* kBallbarProgram = "G21 G90 G17\n"
                                               "G0 X15 Y0\n"
                                               "G2 X25 Y0 I5 J0 F120\n"
                                               "G2 X25 Y0 I-25 J0\n"
                                               "G3 X15 Y0 I-5 J0\n"
                                               "G2 X25 Y0 I5 J0\n"
                                               "G3 X25 Y0 I-25 J0\n"
                                               "G3 X15 Y0 I-5 J0\n";
/// The circles' segments in the path (segment 0 is the G0 rapid) and their lines.
inline constexpr std::size_t kBallbarClockwiseSegment = 2, kBallbarClockwiseLine = 4;
inline constexpr std::size_t kBallbarCounterClockwiseSegment = 5, kBallbarCounterClockwiseLine = 7;
inline constexpr double kBallbarRadiusMm = 25.0;

// The same test with each circle written as consecutive arcs, as many controllers and CAM
// posts write full circles: the clockwise circle as two semicircles, the counter-clockwise one
// as four quadrants, with the same feed-in and feed-out arcs.
inline constexpr const char* kBallbarArcsProgram = "G21 G90 G17\n"
                                                   "G0 X15 Y0\n"
                                                   "G2 X25 Y0 I5 J0 F120\n"
                                                   "G2 X-25 Y0 I-25 J0\n"
                                                   "G2 X25 Y0 I25 J0\n"
                                                   "G3 X15 Y0 I-5 J0\n"
                                                   "G2 X25 Y0 I5 J0\n"
                                                   "G3 X0 Y25 I-25 J0\n"
                                                   "G3 X-25 Y0 I0 J-25\n"
                                                   "G3 X0 Y-25 I25 J0\n"
                                                   "G3 X25 Y0 I0 J25\n"
                                                   "G3 X15 Y0 I-5 J0\n";
/// The circles' segments [begin, end) in the path and the lines of their first arcs.
inline constexpr std::size_t kBallbarArcsClockwiseBegin = 2, kBallbarArcsClockwiseEnd = 4,
                             kBallbarArcsClockwiseLine = 4;
inline constexpr std::size_t kBallbarArcsCounterClockwiseBegin = 6,
                             kBallbarArcsCounterClockwiseEnd = 10,
                             kBallbarArcsCounterClockwiseLine = 8;

} // namespace xyt::test
