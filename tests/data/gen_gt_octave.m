% SPDX-License-Identifier: GPL-3.0-or-later
% Reference data for the Guillemin-Truxal design of Braga et al. from GNU Octave + octave-control.
% Regenerate (from this folder):  octave-cli --no-gui gen_gt_octave.m
% Writes
%   gt_zoh.csv        c2d(tf(...), Ts, 'zoh') of both plants (Eq. 1, 2) and both GT closed loops
%                     at Ts = 0.01 and 0.07: one row per polynomial, descending powers of z.
%   gt_lsim_cubic.csv lsim (first-order hold, Octave's default) of both GT closed loops driven by
%                     the cubic 0 -> 600 in 130 s (paper Eq. 6) held at 600 until 160 s, simulated
%                     at dt = 0.01 s and stored every 1 s.
pkg load control
format long

% Plants G = k0 / (s^3 + a1 s^2 + a2 s) and designs (wn, kp) of Braga et al. Sec. 3.1 and 3.2.
names = {'lower-base', 'upper-base'};
k0 = [77.8, 24.44]; a1 = [125.3, 68.18]; a2 = [3665, 863]; wn = [2, 1]; kp = [30, 30];
systems = {}; labels = {};
for i = 1:2
  G = tf(k0(i), [1 a1(i) a2(i) 0]);
  ki = kp(i) * wn(i)^4 / (kp(i) * k0(i));           % ki = kp psi1, psi1 = wn^4/(kp k0)
  Gc = tf([kp(i) ki], [1 0]);
  T = feedback(Gc * G, 1);
  T = minreal(T, 1e-12);                            % drop nothing real; keeps order 4
  systems{end+1} = G; labels{end+1} = [names{i} ' plant'];
  systems{end+1} = T; labels{end+1} = [names{i} ' closed loop'];
end

fid = fopen('gt_zoh.csv', 'w');
fprintf(fid, 'system,ts,part,c0,c1,c2,c3,c4\n');
for ts = [0.01 0.07]
  for j = 1:numel(systems)
    Gd = c2d(systems{j}, ts, 'zoh');
    [n, d] = tfdata(Gd, 'v');
    n = [zeros(1, numel(d) - numel(n)) n];          % pad the numerator to the denominator's length
    for part = {'num', 'den'}
      if strcmp(part{1}, 'num'); v = n; else; v = d; end
      v = [zeros(1, 5 - numel(v)) v];                % leading zeros: same polynomial
      fprintf(fid, '%s,%.2f,%s', labels{j}, ts, part{1});
      fprintf(fid, ',%.17g', v);
      fprintf(fid, '\n');
    end
  end
end
fclose(fid);

dt = 0.01;
t = (0:dt:160)';
tau = min(t, 130);
r = 600 * (3 * (tau / 130).^2 - 2 * (tau / 130).^3);  % Eq. 6 in closed form
y = zeros(numel(t), 2);
for i = 1:2
  y(:, i) = lsim(systems{2 * i}, r, t);
end
fid = fopen('gt_lsim_cubic.csv', 'w');
fprintf(fid, 't,r,y_lower,y_upper\n');
for k = 1:100:numel(t)
  fprintf(fid, '%.2f,%.17g,%.17g,%.17g\n', t(k), r(k), y(k, 1), y(k, 2));
end
fclose(fid);
