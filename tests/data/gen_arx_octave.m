% SPDX-License-Identifier: GPL-3.0-or-later
% Reference ARX estimates from GNU Octave 7.3 with the control package 3.4 (Debian 12), for
% tests/core/identification/tst_arx.cpp. Run from tests/data/:
%   octave-cli --no-gui gen_arx_octave.m
% Writes arx_octave_data.csv (the data: k, u, y) and arx_octave_result.csv (one row per
% estimated coefficient: na, nb, name, value; Octave's nk = 0 = our nk = 1).
%
% The data: Patrick, Ishak and Adnan's x-axis ARX(2,3,1) model (Eq. 1: A = 1 - 1.6580 q^-1 + 0.6583 q^-2,
% B = 0.0421 q^-1 + 0.0628 q^-2 - 0.0454 q^-3) driven by a random binary +-1 V input, with
% equation noise e ~ N(0, 0.01^2): A y = B u + e. 400 samples at Ts = 0.07 s.
%
% DELAY CONVENTION: control 3.4's arx has no dead time for 'nk', 0: its B is
% [0; b1; ...; b_nb] (arx.m: "b0 = 0 (leading zero required by filt)"), i.e. the first
% coefficient multiplies u(t-1). So arx(dat, 'na', 2, 'nb', 3, 'nk', 0) is MATLAB's (and Patrick,
% Ishak and Adnan's) ARX231 with nk = 1. The script checks this below: B(1) is exactly 0 and B has nb + 1
% entries.
pkg load control
rand("seed", 11);
randn("seed", 12);
N = 400;
Ts = 0.07;
A = [1 -1.6580 0.6583];
B = [0 0.0421 0.0628 -0.0454];
u = 2 * (rand(N, 1) > 0.5) - 1;
e = 0.01 * randn(N, 1);
y = filter(B, A, u) + filter(1, A, e);

fid = fopen("arx_octave_data.csv", "w");
fprintf(fid, "k,u,y\n");
for k = 1:N
  fprintf(fid, "%d,%.17g,%.17g\n", k - 1, u(k), y(k));
end
fclose(fid);

dat = iddata(y, u, Ts);
fid = fopen("arx_octave_result.csv", "w");
fprintf(fid, "na,nb,name,value\n");
% (na, nb) pairs, Octave nk = 0 = MATLAB nk = 1.
orders = [2 3; 1 2; 3 3];
for i = 1:rows(orders)
  na = orders(i, 1);
  nb = orders(i, 2);
  sys = arx(dat, "na", na, "nb", nb, "nk", 0);
  [num, den] = filtdata(sys);
  bq = num{1, 1}(:).';
  aq = den{1, 1}(:).';
  % filt stores ascending powers of z^-1; check the delay convention stated above.
  if (numel(bq) != nb + 1 || bq(1) != 0)
    error("unexpected B from arx: %s", mat2str(bq));
  end
  for j = 2:numel(aq)
    fprintf(fid, "%d,%d,a%d,%.17g\n", na, nb, j - 1, aq(j));
  end
  for j = 2:numel(bq)
    fprintf(fid, "%d,%d,b%d,%.17g\n", na, nb, j - 1, bq(j));
  end
end
fclose(fid);
