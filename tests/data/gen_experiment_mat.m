% SPDX-License-Identifier: GPL-3.0-or-later
% Writes experiment_octave.mat: a small MATLAB v7 (compressed v5) file made by GNU Octave, read
% by tests/core/identification/tst_mat_reader.cpp. Run from this folder:
%   octave --no-gui --eval "run('gen_experiment_mat.m')"
% The values are exact in binary so the test compares them exactly.
t = (0:9)' * 0.25;               % time, s (column vector)
u = [0, 2.5 * ones(1, 9)];       % command, V (row vector)
y = 0.125 * ((0:9)') .^ 2;       % position, mm
counts = int32([0; -3; 7; 1000000; -2147483648; 2147483647; 5; 6; 7; 8]); % encoder counts
ysingle = single(0.5 * (0:9)');  % single precision
cplx = [1 + 2i; 3];              % complex: not usable
M = magic(3);                    % a matrix: not usable
name = 'axis x';                 % char: not usable
flag = logical([1 0 1]);         % logical: not usable
withnan = [1; NaN; 3];           % a NaN in element 2
save('-mat7-binary', 'experiment_octave.mat', 't', 'u', 'y', 'counts', 'ysingle', 'cplx', 'M', ...
     'name', 'flag', 'withnan');
