%
; SPDX-License-Identifier: GPL-3.0-or-later
; XY Tune example: the circle contour of Braga et al., Eq. 23-24:
; x = 25 sin(0.06 t), y = 25 cos(0.06 t) mm. Radius 25 mm about the origin, starting
; at the top (0, 25) and turning clockwise at 25 x 0.06 = 1.5 mm/s = 90 mm/min;
; one revolution takes 2 pi / 0.06 = 104.7 s. The paper ramps its amplitude in; here the
; feed profile accelerates along the circle instead. Units mm, absolute coordinates.
G17 G21 G90 G94
G0 X0 Y25 (rapid from the origin to the start point)
G2 X0 Y25 I0 J-25 F90 (one full clockwise circle about the origin)
M30
%
