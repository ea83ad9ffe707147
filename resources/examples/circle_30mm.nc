%
; SPDX-License-Identifier: GPL-3.0-or-later
; XY Tune example: the circle of Patrick, Ishak and Adnan, the reference of both axes of the ZPETC study:
; x = 30 sin(0.1 t), y = 30 cos(0.1 t) mm. Radius 30 mm about the origin, starting at the
; top (0, 30) and turning clockwise at 30 x 0.1 = 3 mm/s = 180 mm/min; one revolution
; takes 2 pi / 0.1 = 62.8 s. Units mm, absolute coordinates.
G17 G21 G90 G94
G0 X0 Y30 (rapid from the origin to the start point)
G2 X0 Y30 I0 J-30 F180 (one full clockwise circle about the origin)
M30
%
