%
; SPDX-License-Identifier: GPL-3.0-or-later
; XY Tune example: a 40 mm square run counter-clockwise from the origin at 600 mm/min.
; Four 90-degree corners: the feed profile stops at each, and the contour error shows
; how each axis' loop overshoots the corner. Units mm, absolute coordinates.
G17 G21 G90 G94
N10 G1 X40 Y0 F600
N20 Y40
N30 X0
N40 Y0
M30
%
