%
; SPDX-License-Identifier: GPL-3.0-or-later
; XY Tune example: a five-pointed star {5/2} inscribed in a 30 mm circle about the origin,
; points at 90 + k 144 degrees, k = 0..4, i.e. 30 (cos, sin) of those angles to 3 decimals.
; Each point turns by 144 degrees, a sharp corner; the strokes cross each other five times.
; Units mm, absolute coordinates, 900 mm/min.
G17 G21 G90 G94
G0 X0 Y30
G1 X-17.634 Y-24.271 F900
X28.532 Y9.271
X-28.532 Y9.271
X17.634 Y-24.271
X0 Y30
M30
%
