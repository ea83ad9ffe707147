// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/identification/jog_experiment.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace xyt {

namespace {

/// One trapezoidal move (jogReference's notation): starts at t0 from p0 in direction sigma.
struct JogMove {
    double t0 = 0;
    double p0 = 0;
    double sigma = 1;
    double speed = 0;
    double rampSeconds = 0;   // t_a = V / A
    double cruiseSeconds = 0; // t_c = D / V - V / A
    double moveSeconds = 0;   // T = D / V + V / A
};

/// The closed form of jogReference's header at tau = t - t0 (0 <= tau < T).
double jogMovePosition(const JogMove& m, double tau, double travel, double accel) {
    double s = 0;
    if (tau < m.rampSeconds)
        s = 0.5 * accel * tau * tau;
    else if (tau < m.rampSeconds + m.cruiseSeconds)
        s = 0.5 * m.speed * m.rampSeconds + m.speed * (tau - m.rampSeconds);
    else {
        // Measured back from the end, so that the move ends at exactly p0 + sigma D.
        const double left = m.moveSeconds - tau;
        s = travel - 0.5 * accel * left * left;
    }
    return m.p0 + m.sigma * s;
}

} // namespace

JogReference jogReference(const JogProgram& program) {
    const std::vector<double>& speeds = program.speedsMmPerS;
    if (speeds.empty())
        throw InvalidInput("speeds", makeDiagnostic("ident_jog_no_speed"));
    if (speeds.size() > kMaxJogSpeeds)
        throw InvalidInput(
            "speeds", makeDiagnostic("ident_jog_too_many_speeds", {std::to_string(speeds.size()),
                                                                   std::to_string(kMaxJogSpeeds)}));
    for (double v : speeds)
        if (!std::isfinite(v) || v <= 0)
            throw InvalidInput("speeds",
                               makeDiagnostic("ident_jog_speed_positive", {std::to_string(v)}));
    requirePositive(program.travelMm, "travel");
    requirePositive(program.accelMmPerS2, "accel");
    if (!std::isfinite(program.dwellSeconds) || program.dwellSeconds < 0)
        throw InvalidInput("dwell", makeDiagnostic("ident_jog_dwell"));
    requirePositive(program.tsSeconds, "ts");

    const double travel = program.travelMm;
    const double accel = program.accelMmPerS2;
    const double dwell = program.dwellSeconds;
    const double ts = program.tsSeconds;

    std::vector<JogMove> moves;
    moves.reserve(2 * speeds.size());
    double clock = dwell;
    for (double v : speeds) {
        // t_c >= T / 2  <=>  D / V - V / A >= (D / V + V / A) / 2  <=>  D >= 3 V^2 / A.
        const double minimum = 3.0 * v * v / accel;
        if (travel < minimum)
            throw InvalidInput(
                "travel",
                makeDiagnostic("ident_jog_travel", {std::to_string(v), std::to_string(minimum)}));
        JogMove m;
        m.speed = v;
        m.rampSeconds = v / accel;
        m.cruiseSeconds = travel / v - v / accel;
        m.moveSeconds = travel / v + v / accel;
        for (double sigma : {1.0, -1.0}) {
            m.t0 = clock;
            m.sigma = sigma;
            m.p0 = sigma > 0 ? 0.0 : travel;
            moves.push_back(m);
            clock += m.moveSeconds + dwell;
        }
    }

    const double duration = clock;
    // A quotient within 1e-9 of a whole number is that number (17.3 / 0.01 = 1730.0000000000002).
    double steps = duration / ts;
    const double nearest = std::round(steps);
    steps = std::abs(steps - nearest) <= 1e-9 * std::max(1.0, nearest) ? nearest : std::ceil(steps);
    if (!(steps + 1.0 <= static_cast<double>(kMaxJogSamples)))
        throw InvalidInput(
            "ts", makeDiagnostic("ident_jog_too_long",
                                 {std::to_string(duration), std::to_string(kMaxJogSamples)}));
    const std::size_t n = static_cast<std::size_t>(steps) + 1;

    JogReference r;
    r.t.resize(n);
    r.position.resize(n);
    std::size_t next = 0; // the first move not yet finished
    double rest = 0.0;    // where the axis stands between moves
    for (std::size_t k = 0; k < n; ++k) {
        const double t = static_cast<double>(k) * ts;
        while (next < moves.size() && t >= moves[next].t0 + moves[next].moveSeconds) {
            rest = moves[next].p0 + moves[next].sigma * travel;
            ++next;
        }
        r.t[k] = t;
        r.position[k] = next < moves.size() && t >= moves[next].t0
                            ? jogMovePosition(moves[next], t - moves[next].t0, travel, accel)
                            : rest;
    }
    r.segments.reserve(moves.size());
    for (const JogMove& m : moves)
        r.segments.push_back(JogSegment{m.t0 + m.rampSeconds,
                                        m.t0 + m.rampSeconds + m.cruiseSeconds, m.sigma * m.speed});
    return r;
}

} // namespace xyt
