// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/simulation/mode_excitation.h"

#include "core/model/errors.h"
#include "core/model/flexible_mode.h"
#include "core/model/math_constants.h"
#include "core/model/state_space.h"

#include <cmath>

namespace xyt {

namespace {

/// The states (q, q') at every sample of the mode driven by -a, a linear between samples (the
/// exact steps in fixed-size matrices: this runs once per sample of a run).
std::vector<Eigen::Vector2d> modeStates(const std::vector<double>& a, double dt, double f,
                                        double zeta) {
    requirePositive(f, "frequency");
    requireDampingRatio(zeta, "damping");
    requirePositive(dt, "dt");
    const double w = kTwoPi * f;
    Eigen::Matrix2d am;
    am << 0.0, 1.0, -w * w, -2.0 * zeta * w;
    Eigen::MatrixXd bm(2, 1);
    bm << 0.0, -1.0;
    const FohDiscretization d = discretizeFoh(am, bm, dt);
    const Eigen::Matrix2d phi = d.phi;
    const Eigen::Vector2d g0 = d.gamma0.col(0), g1 = d.gamma1.col(0) / dt;
    std::vector<Eigen::Vector2d> out;
    out.reserve(a.size());
    Eigen::Vector2d x = Eigen::Vector2d::Zero();
    for (std::size_t k = 0; k < a.size(); ++k) {
        out.push_back(x);
        const double next = k + 1 < a.size() ? a[k + 1] : a[k];
        x = phi * x + g0 * a[k] + g1 * (next - a[k]);
    }
    return out;
}

} // namespace

std::vector<double> modeDeflection(const std::vector<double>& acceleration, double dtSeconds,
                                   double frequencyHz, double dampingRatio) {
    const auto states = modeStates(acceleration, dtSeconds, frequencyHz, dampingRatio);
    std::vector<double> q(states.size());
    for (std::size_t k = 0; k < q.size(); ++k)
        q[k] = states[k](0);
    return q;
}

std::vector<double> modeAmplitudes(const std::vector<double>& acceleration, double dtSeconds,
                                   double frequencyHz, double dampingRatio) {
    const auto states = modeStates(acceleration, dtSeconds, frequencyHz, dampingRatio);
    const double w = kTwoPi * frequencyHz;
    const double wd = w * std::sqrt(1.0 - dampingRatio * dampingRatio);
    std::vector<double> out(states.size());
    for (std::size_t k = 0; k < out.size(); ++k) {
        const double q = states[k](0);
        const double s = (states[k](1) + dampingRatio * w * q) / wd;
        out[k] = std::sqrt(q * q + s * s);
    }
    return out;
}

} // namespace xyt
