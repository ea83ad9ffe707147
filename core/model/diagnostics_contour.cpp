// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/model/diagnostic_tables.h"

namespace xyt::diagnostic_tables {

/// The warnings and refusals of core/contour.
const std::vector<DiagnosticTemplate>& contour() {
    static const std::vector<DiagnosticTemplate> table = {
        // Points and traces of the contour metrics (contour_metrics.cpp).
        XYT_DIAGNOSTIC("contour_xy_different_lengths", "x and y have different lengths"),
        XYT_DIAGNOSTIC("contour_needs_points", "needs at least %1 points"),
        XYT_DIAGNOSTIC("contour_reversal_window", "must be in (0, 45] degrees"),
        XYT_DIAGNOSTIC("contour_has_no_sample", "has no sample"),
        XYT_DIAGNOSTIC("contour_one_flag_per_segment", "needs one flag per path segment"),
        XYT_DIAGNOSTIC("contour_points_collinear",
                       "are collinear (or coincide): no circle fits them"),
        XYT_DIAGNOSTIC("contour_fit_radius_not_real",
                       "give no circle (the algebraic fit's radius is not real)"),
        // Paths (path.cpp).
        XYT_DIAGNOSTIC("contour_line_not_finite", "a line's end points must be finite numbers"),
        XYT_DIAGNOSTIC("contour_line_zero_length", "a line must have a nonzero length"),
        XYT_DIAGNOSTIC("contour_line_length_overflows", "a line's length overflows a double"),
        XYT_DIAGNOSTIC("contour_arc_not_finite",
                       "an arc's centre, radius and angles must be finite numbers"),
        XYT_DIAGNOSTIC("contour_arc_radius_not_positive",
                       "an arc's radius must be greater than zero"),
        XYT_DIAGNOSTIC("contour_arc_sweep", "an arc's sweep must be nonzero and at most one turn"),
        XYT_DIAGNOSTIC("contour_arc_length_overflows", "an arc's length overflows a double"),
        XYT_DIAGNOSTIC("contour_has_no_segment", "has no segment"),
        XYT_DIAGNOSTIC("contour_path_length_overflows", "its length overflows a double"),
        // Feed profiles (feed_profile.cpp).
        XYT_DIAGNOSTIC("contour_program_own_feeds_too_long",
                       "the program needs at least %1 at its own feeds (the F words), more than "
                       "the %2 samples at dt %3 s hold (%4)"),
        XYT_DIAGNOSTIC("contour_rapids_too_long",
                       "running the rapids needs at least %1 at the rapid feed, more than the %2 "
                       "samples at dt %3 s hold (%4)"),
        XYT_DIAGNOSTIC("contour_program_scaled_too_long",
                       "the program needs at least %1 at %5 times its feeds, more than the %2 "
                       "samples at dt %3 s hold (%4)"),
        XYT_DIAGNOSTIC("contour_feeds_too_long",
                       "every segment at its feed needs at least %1 to move the path's %5 mm, more "
                       "than the %2 samples at dt %3 s hold (%4)"),
        XYT_DIAGNOSTIC("contour_accel_too_long",
                       "%5 mm/s^2 needs at least %1 to move the path's %6 mm from rest to rest (2 "
                       "sqrt(L / A)), more than the %2 samples at dt %3 s hold (%4)"),
        XYT_DIAGNOSTIC("contour_jerk_too_long",
                       "%5 mm/s^3 needs at least %1 to move the path's %6 mm from rest to rest (4 "
                       "(L / 2J)^(1/3)), more than the %2 samples at dt %3 s hold (%4)"),
        XYT_DIAGNOSTIC("contour_rate_unit_segment", "%1 (segment %2)"),
        XYT_DIAGNOSTIC("contour_feed_per_segment", "needs one value per path segment (%1), got %2"),
        XYT_DIAGNOSTIC("contour_segment_feed_invalid",
                       "segment %1: must be a finite number > 0, got %2"),
        XYT_DIAGNOSTIC("contour_max_jerk", "must be a finite number >= 0 (0: no jerk limit)"),
        XYT_DIAGNOSTIC("contour_corner_angle", "must be in [0, 180) degrees"),
        XYT_DIAGNOSTIC("contour_segment_peak_speed",
                       "segment %1 (%2 mm) cannot be planned: its peak speed rounds to %3 mm/s"),
        XYT_DIAGNOSTIC("contour_profile_too_long",
                       "the profile lasts %1 s, %2 samples at dt %3 s, more than the limit of %4"),
        XYT_DIAGNOSTIC("contour_rapid_of_line", "%1 (the rapid of line %2)"),
        XYT_DIAGNOSTIC(
            "contour_feed_scale_outside",
            "%1 makes the feed of line %2 (%3 mm/s) %4 mm/s, outside the planner's [%5, %6] mm/s"),
        XYT_DIAGNOSTIC("contour_rate_outside_range",
                       "%1 %2 is outside the planner's range [%3, %4]"),
        XYT_DIAGNOSTIC("contour_rate_outside_range_or_zero",
                       "%1 %2 is outside the planner's range [%3, %4] (0: none)"),
        // The G-code reader's refusals (gcode_reader.cpp): the field names the line.
        XYT_DIAGNOSTIC("contour_gcode_malformed_number", "malformed number %1 at column %2: %3"),
        XYT_DIAGNOSTIC("contour_gcode_two_decimal_points", "more than one decimal point"),
        XYT_DIAGNOSTIC("contour_gcode_hex_number", "G-code numbers are decimal (no 0x prefix)"),
        XYT_DIAGNOSTIC("contour_gcode_comment_not_closed",
                       "comment opened at column %1 is not closed"),
        XYT_DIAGNOSTIC("contour_gcode_number_too_long",
                       "the number of word %1 at column %2 is longer than %3 characters"),
        XYT_DIAGNOSTIC("contour_gcode_word_no_number", "word %1 at column %2 has no number"),
        XYT_DIAGNOSTIC("contour_gcode_number_not_representable",
                       "the number of word %1 at column %2 is not a representable number"),
        XYT_DIAGNOSTIC("contour_gcode_unexpected_character",
                       "unexpected character '%1' at column %2"),
        XYT_DIAGNOSTIC("contour_gcode_beyond_limit", "%1 at column %2 is beyond %3 mm"),
        XYT_DIAGNOSTIC("contour_gcode_arc_needs_centre",
                       "arc %1 at column %2 needs I/J (its centre) or R (its radius)"),
        XYT_DIAGNOSTIC("contour_gcode_arc_both_r_ij",
                       "arc %1 at column %2 has both R and I/J; give one of them"),
        XYT_DIAGNOSTIC("contour_gcode_full_circle_r",
                       "a full circle needs I and J: R at column %1 leaves its centre undefined"),
        XYT_DIAGNOSTIC("contour_gcode_zero_radius_word", "%1 at column %2 is a zero radius"),
        XYT_DIAGNOSTIC("contour_gcode_radius_below_half_chord",
                       "%1 at column %2 is smaller than half the chord (%3 mm) to the end point"),
        XYT_DIAGNOSTIC("contour_gcode_arc_zero_radius",
                       "arc %1 at column %2 has a zero radius (I and J are 0)"),
        XYT_DIAGNOSTIC("contour_gcode_arc_end_off_circle",
                       "arc %1 at column %2: the end point is off the circle (radius %3 mm at the "
                       "end, %4 mm at the start; tolerance %5 mm)"),
        XYT_DIAGNOSTIC("contour_gcode_word_twice", "word %1 is given twice (%2 at column %3)"),
        XYT_DIAGNOSTIC("contour_gcode_two_motion_codes",
                       "two motion codes %1 and %2 on one line (at column %3)"),
        XYT_DIAGNOSTIC("contour_gcode_two_unit_codes",
                       "two unit codes on one line (%1 at column %2)"),
        XYT_DIAGNOSTIC("contour_gcode_two_distance_modes",
                       "two distance modes on one line (%1 at column %2)"),
        XYT_DIAGNOSTIC("contour_gcode_plane_not_xy",
                       "only the XY plane (G17) is supported, not %1 at column %2"),
        XYT_DIAGNOSTIC("contour_gcode_unknown_word", "unknown word %1 at column %2"),
        XYT_DIAGNOSTIC("contour_gcode_block_number",
                       "block number %1 at column %2 must be a whole number 0..1e9"),
        XYT_DIAGNOSTIC("contour_gcode_feed_not_positive",
                       "feed %1 at column %2 must be greater than zero"),
        XYT_DIAGNOSTIC("contour_gcode_needs_arc", "%1 at column %2 needs an arc (G2 or G3)"),
        XYT_DIAGNOSTIC("contour_gcode_no_motion_mode",
                       "%1 at column %2 has no motion mode (G0, G1, G2 or G3) before it"),
        XYT_DIAGNOSTIC("contour_gcode_no_feed",
                       "feed move %1 at column %2 has no feed rate (no F programmed before it)"),
        XYT_DIAGNOSTIC("contour_gcode_no_feed_modal",
                       "feed move at column %1 has no feed rate (no F programmed before it)"),
        XYT_DIAGNOSTIC("contour_gcode_incremental_beyond",
                       "the incremental move at column %1 ends beyond %2 mm"),
        XYT_DIAGNOSTIC("contour_gcode_no_motion", "has no XY motion (no G0, G1, G2 or G3 move)"),
        XYT_DIAGNOSTIC("contour_rapid_feed_outside",
                       "%1 mm/min is outside the planner's range [%2, %3] mm/min"),
        XYT_DIAGNOSTIC("contour_start_within", "must be finite and within %1 mm"),
        XYT_DIAGNOSTIC("contour_gcode_too_many_lines", "has more than the limit of %1 lines"),
        // The G-code program's warnings (GcodeProgram::warnings).
        XYT_DIAGNOSTIC("contour_gcode_line_warning", "line %1: %2"),
        XYT_DIAGNOSTIC("contour_gcode_lines_after_end",
                       "the lines after the program end %1 are not read"),
        XYT_DIAGNOSTIC("contour_gcode_ignored_not_xy", "%1 ignored (not an XY motion)"),
        XYT_DIAGNOSTIC("contour_gcode_ignored_z", "%1 ignored (the path is XY only)"),
        XYT_DIAGNOSTIC("contour_gcode_ignored_spindle", "%1 ignored (spindle speed)"),
        XYT_DIAGNOSTIC("contour_gcode_ignored_tool", "%1 ignored (tool)"),
        XYT_DIAGNOSTIC("contour_gcode_more_warnings", "... and %1 more warnings"),
        // The ballbar circles of a program and the ISO 230-4 note (ballbar_circles.cpp).
        XYT_DIAGNOSTIC("contour_gcode_line", "line %1"),
        XYT_DIAGNOSTIC("contour_gcode_lines", "lines %1-%2"),
        XYT_DIAGNOSTIC("contour_ballbar_one_way",
                       "the program runs its full circle (%1) one way only: no circular hysteresis "
                       "H, which needs a clockwise and a counter-clockwise run of the same circle"),
        XYT_DIAGNOSTIC(
            "contour_ballbar_no_opposite",
            "none of the program's %1 full circles runs the circle of %2 the other way on the same "
            "centre and radius: G and F are that circle's, no circular hysteresis H"),
        XYT_DIAGNOSTIC("contour_ballbar_many",
                       "the program holds %1 full circles: the figures are those of %2 and %3"),
    };
    return table;
}

} // namespace xyt::diagnostic_tables
