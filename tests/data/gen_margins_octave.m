% SPDX-License-Identifier: GPL-3.0-or-later
% Reference stability margins of random loops from GNU Octave's control package.
% Regenerate from tests/data/:   octave-cli --no-gui gen_margins_octave.m
% Writes margins_octave.csv: one loop per row, numerator and denominator in DESCENDING powers
% of s or z (space-separated), ts (0 = continuous), then
%   gm, wgm   [gm, ~, wgm] = margin(L): gain margin as a FACTOR (not dB), Inf/NaN when none
%   pm, wpm   margin's phase margin in degrees, 180 + arg L in (0, 360]; 180/NaN when none
%   ms, wms   [ms, wms] = norm(feedback(1, L), Inf, 1e-10): peak sensitivity and its frequency
%             (tolerance 1e-10: with 1e-12 AB13DD returned 1.0000000000010 instead of 1.19620 on loop 3)
%   mt, wmt   [mt, wmt] = norm(feedback(L, 1), Inf, 1e-10): peak complementary sensitivity
% Only loops whose closed loop is stable are kept (the H-infinity norms need it); the open
% loops include integrators and unstable poles.
pkg load control
rand("state", 17);

function s = num2s(x)
  if isnan(x)
    s = "nan";
  elseif isinf(x)
    if x > 0
      s = "inf";
    else
      s = "-inf";
    end
  else
    s = sprintf("%.17g", x);
  end
end

function s = poly2s(p)
  s = strjoin(arrayfun(@num2s, p, "UniformOutput", false), " ");
end

function u = unif(a, b)
  u = a + (b - a) * rand();
end

fid = fopen("margins_octave.csv", "w");
fprintf(fid, "id,ts,num,den,gm,wgm,pm,wpm,ms,wms,mt,wmt\n");
kept = 0;
attempt = 0;
while kept < 24
  attempt = attempt + 1;
  discrete = kept >= 16;
  if ~discrete
    ts = 0;
    p = -unif(0.1, 10) * ones(1, 0);
    nInt = floor(unif(0, 3));           % 0..2 integrators
    p = [p, zeros(1, nInt)];
    for k = 1:floor(unif(1, 3))           % 1..2 real poles
      p = [p, -10 ^ unif(-1, 1)];
    end
    if rand() < 0.5                       % a complex pair
      wn = 10 ^ unif(-0.5, 1); zeta = unif(0.05, 0.9);
      p = [p, wn * (-zeta + 1i * sqrt(1 - zeta^2)), wn * (-zeta - 1i * sqrt(1 - zeta^2))];
    end
    if rand() < 0.25                      % an unstable pole
      p = [p, unif(0.1, 2)];
    end
    z = [];
    for k = 1:floor(unif(0, min(3, numel(p))))
      z = [z, unif(-10, 5)];
    end
    num = real(poly(z));
    den = real(poly(p));
  else
    ts = unif(0.01, 0.5);
    p = [];
    if rand() < 0.5
      p = [p, 1];                         % an integrator
    end
    for k = 1:floor(unif(1, 3))
      p = [p, unif(-0.8, 0.98)];
    end
    if rand() < 0.5
      r = unif(0.3, 0.95); th = unif(0.1, 2.5);
      p = [p, r * exp(1i * th), r * exp(-1i * th)];
    end
    if rand() < 0.25
      p = [p, unif(1.05, 1.5)];
    end
    z = [];
    for k = 1:floor(unif(0, numel(p)))    % relative degree >= 1
      z = [z, unif(-2, 0.9)];
    end
    num = real(poly(z));
    den = real(poly(p));
  end
  % A gain that closes the loop stably, if one of 2^-8 .. 2^8 does.
  k0 = 10 ^ unif(-1, 1);
  found = false;
  for e = [0, -1, 1, -2, 2, -3, 3, -4, 4, -5, 5, -6, 6, -7, 7, -8, 8]
    if ts == 0
      L = tf(k0 * 2^e * num, den);
    else
      L = tf(k0 * 2^e * num, den, ts);
    end
    if isstable(feedback(L, 1))
      found = true;
      break;
    end
  end
  if ~found
    continue;
  end
  [nn, dd] = tfdata(L, "vector");
  [gm, pm, wgm, wpm] = margin(L);
  [ms, wms] = norm(feedback(1, L), Inf, 1e-10);
  [mt, wmt] = norm(feedback(L, 1), Inf, 1e-10);
  kept = kept + 1;
  fprintf(fid, "%d,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s\n", kept, num2s(ts), poly2s(nn), ...
          poly2s(dd), num2s(gm), num2s(wgm), num2s(pm), num2s(wpm), num2s(ms), num2s(wms), ...
          num2s(mt), num2s(wmt));
end
fclose(fid);
printf("%d loops kept of %d drawn\n", kept, attempt);
