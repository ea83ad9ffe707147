%
; SPDX-License-Identifier: GPL-3.0-or-later
; XY Tune example: a short engraving of the letters "XY", 15 mm tall, lower left at the
; origin. Z lifts and lowers the tool between strokes: the XY path ignores those lines with
; a warning each. The right arm of the Y curves onto the stem through an arc of 1.5 mm
; radius tangent to the arm (the join turns by 0.13 degree at 3 decimals, so the profile keeps
; its speed into it), ending on the stem at (19, 8.5). Units mm, absolute coordinates,
; engraving at 300 mm/min.
G17 G21 G90 G94
G0 Z2
; letter X: two crossing strokes
G0 X0 Y0
G1 Z-0.1 F100
G1 X10 Y15 F300
G0 Z2
G0 X0 Y15
G1 Z-0.1 F100
G1 X10 Y0 F300
G0 Z2
; letter Y: left arm, stem, then the right arm drawn back to the stem through an arc
G0 X14 Y15
G1 Z-0.1 F100
G1 X19 Y7.5 F300
G1 Y0
G0 Z2
G0 X24 Y15
G1 Z-0.1 F100
G1 X20.109 Y9.164 F300
G2 X19 Y8.5 R1.5
G0 Z2
G0 X0 Y0
M5
M30
%
