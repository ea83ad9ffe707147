N10 g1 x 1 y2 f60 ; c
X3
Y-1 Z5 M3 S100 T1
%
