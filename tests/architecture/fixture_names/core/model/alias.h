// SPDX-License-Identifier: GPL-3.0-or-later
// Test fixture of check_names.cmake (test names_catch_history): lines 5, 6 and 7 must be reported,
// line 8 must not (a figure quoted from a paper, and the issue as the source of a test case).
#pragma once
// The live design-space map (issue 18) recomputes on every change.
inline double paper001Gain() { return 0.8; }
// Tuned as in Issue #7.
// Kf = 13.4251 (paper 0.0203 low), as in the reproduction.
