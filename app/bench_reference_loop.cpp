// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/bench_reference_loop.h"

#include "core/model/state_space.h"
#include "core/simulation/simulation.h"

#include <algorithm>
#include <cmath>

namespace xyt::bench {

ReferenceLoop referenceLoop(const TransferFunction& plant, const TransferFunction& controller,
                            double dt) {
    const LoopModes modes = loopModes(plant, controller);
    const FohDiscretization lin = discretizeFoh(modes.aLinear, modes.bLinear, dt);
    const FohDiscretization sat = discretizeFoh(modes.aClipped, modes.bClipped, dt);
    ReferenceLoop m{};
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) {
            m.phiLinear[i][j] = lin.phi(i, j);
            m.phiClipped[i][j] = sat.phi(i, j);
        }
        m.g0Linear[i] = lin.gamma0(i, 0);
        m.g1Linear[i] = lin.gamma1(i, 0);
        m.g0Clipped[i][0] = sat.gamma0(i, 0);
        m.g0Clipped[i][1] = sat.gamma0(i, 1);
        m.g1Clipped[i] = sat.gamma1(i, 0);
    }
    for (int j = 0; j < 3; ++j)
        m.cp[j] = modes.plantC(j);
    m.cc = modes.controllerC(0);
    m.dc = modes.controllerD;
    return m;
}

namespace {
inline void advance(const ReferenceLoop& m, bool clip, double rk, double u, double slope,
                    double x[4]) {
    double next[4];
    for (int i = 0; i < 4; ++i) {
        if (clip)
            next[i] = m.phiClipped[i][0] * x[0] + m.phiClipped[i][1] * x[1] +
                      m.phiClipped[i][2] * x[2] + m.phiClipped[i][3] * x[3] +
                      m.g0Clipped[i][0] * rk + m.g0Clipped[i][1] * u + m.g1Clipped[i] * slope;
        else
            next[i] = m.phiLinear[i][0] * x[0] + m.phiLinear[i][1] * x[1] +
                      m.phiLinear[i][2] * x[2] + m.phiLinear[i][3] * x[3] + m.g0Linear[i] * rk +
                      m.g1Linear[i] * slope;
    }
    for (int i = 0; i < 4; ++i)
        x[i] = next[i];
}
/// The quantities of sample k, from the state x: output, scaled reference, command, clipped.
struct Sample {
    double y, rk, u;
    bool clip;
};
inline Sample sample(const ReferenceLoop& m, const double* reference, std::size_t k, double umax,
                     double unit, const double x[4]) {
    const double yk = m.cp[0] * x[0] + m.cp[1] * x[1] + m.cp[2] * x[2];
    const double rk = reference[k] * unit;
    const double v = m.dc * (rk - yk) + m.cc * x[3];
    const bool clip = std::abs(v) > umax;
    return {yk, rk, clip ? std::copysign(umax, v) : v, clip};
}
} // namespace

void referenceRun(const ReferenceLoop& m, const double* reference, std::size_t count, double dt,
                  double umax, double unit, double* t, double* y, double* e, double* u,
                  bool* clipped) {
    double x[4] = {0.0, 0.0, 0.0, 0.0};
    for (std::size_t k = 0; k < count; ++k) {
        const Sample s = sample(m, reference, k, umax, unit, x);
        t[k] = static_cast<double>(k) * dt;
        y[k] = s.y / unit;
        e[k] = reference[k] - s.y / unit;
        u[k] = s.u;
        clipped[k] = s.clip;
        if (k + 1 == count)
            break;
        advance(m, s.clip, s.rk, s.u, (reference[k + 1] - reference[k]) * unit / dt, x);
    }
}

ReferenceFigures referenceFigures(const ReferenceLoop& m, const double* reference,
                                  std::size_t count, double dt, double umax, double unit) {
    double x[4] = {0.0, 0.0, 0.0, 0.0};
    ReferenceFigures f;
    double sumSquares = 0.0, previous = 0.0;
    for (std::size_t k = 0; k < count; ++k) {
        const Sample s = sample(m, reference, k, umax, unit, x);
        const double e = std::abs(reference[k] - s.y / unit);
        const double t = static_cast<double>(k) * dt;
        sumSquares += e * e;
        f.maxAbsError = std::max(f.maxAbsError, e);
        f.maxAbsU = std::max(f.maxAbsU, std::abs(s.u));
        if (k > 0)
            f.itae += 0.5 * dt * (t * e + previous);
        previous = t * e;
        if (k + 1 == count)
            break;
        advance(m, s.clip, s.rk, s.u, (reference[k + 1] - reference[k]) * unit / dt, x);
    }
    f.rmse = std::sqrt(sumSquares / static_cast<double>(count));
    return f;
}

} // namespace xyt::bench
