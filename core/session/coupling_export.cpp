// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/session/coupling_export.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/model/number_format.h"
#include "core/session/c_export.h"
#include "core/session/design_method_module.h"

#include <cmath>
#include <sstream>

namespace xyt {

using namespace cexport;

std::string crossCouplingCBlock(const Session& session, const SessionEvaluation& evaluation,
                                const ExportOptions& options) {
    const CrossCoupling& c = session.crossCoupling;
    validateCrossCoupling(c, "cross_coupling");
    double period[2] = {0.0, 0.0};
    for (int i = 0; i < 2; ++i) {
        const AxisEvaluation& a = evaluation.axes[static_cast<std::size_t>(i)];
        if (!a.ok || !a.digital)
            throw InvalidInput("cross_coupling",
                               makeDiagnostic("session_axis_no_digital_to_couple",
                                              {session.axes[static_cast<std::size_t>(i)].id}));
        period[i] = a.digital->tsSeconds;
    }
    if (std::abs(period[0] - period[1]) > 1e-9 * period[0])
        throw InvalidInput("cross_coupling",
                           makeDiagnostic("session_coupling_one_digital_period",
                                          {formatNumber(period[0]), formatNumber(period[1])}));
    const std::string& x = session.axes[0].id;
    const std::string& y = session.axes[1].id;
    const CPrecision p = options.precision;
    std::ostringstream out;
    out << "/* Cross-coupled contouring (Koren): both axes together. IT NEEDS BOTH AXES' MEASURED\n"
           " * POSITIONS. Every XYT_CCC_TS seconds, in place of xyt_"
        << x << "_step and xyt_" << y
        << "_step (after\n"
           " * xyt_ccc_init and the axes' own init, and any ZPETC preview steps):\n"
           " *   xyt_ccc_step(&ccc, &state_"
        << x << ", &state_" << y
        << ", rx, ry, rx_step, ry_step, mx, my, tx, ty, kappa,\n"
           " *                feed, ffx, ffy, given_"
        << x << ", given_" << y
        << ", u);\n"
           " * rx, ry: the reference now (mm); rx_step, ry_step: what each axis' step takes\n"
           " * (r(k + PREVIEW) for a ZPETC axis, else rx, ry); mx, my: the encoders (mm); (tx, "
           "ty):\n"
           " * the unit tangent of the path at the reference point (the direction of travel);\n"
           " * kappa: the path's signed curvature there (1/mm, + counter-clockwise, 0 on a line);\n"
           " * feed: 0 on rapid moves (the coupling rests, its integral restarts), else 1; ffx,\n"
           " * ffy: the feedforward each axis adds (friction compensation, else 0); given_*: a\n"
           " * PID's trajectory derivatives {v, a, j} or 0; u: the two commands (V).\n"
           " * The law: e = r - m per axis; eps = -ex ty + ey tx"
        << (c.estimate == ContourEstimateKind::Circular
                ? " + kappa tau^2 / 2 (tau = ex tx + ey ty), the\n"
                  " * circular estimate, shared as Cx = -ty + kappa tau tx, Cy = tx + kappa tau ty;"
                : ", the linear estimate, shared as\n * Cx = -ty, Cy = tx;")
        << "\n * I+ = I + TS eps, uc = KP eps + KI I+; each axis' command with Cx uc (Cy uc) "
           "added\n"
           " * before its limit; I+ kept unless a command is at the limit; I = 0 where the "
           "tangent\n"
           " * turns by more than 0.1 rad from one period to the next (a sharp corner).\n */\n";
    out << "#define XYT_CCC_CIRCULAR " << (c.estimate == ContourEstimateKind::Circular ? 1 : 0)
        << "\n"
        << "static const xyt_real XYT_CCC_KP XYT_MAYBE_UNUSED = "
        << realNum(c.kp, "cross_coupling.kp", "XYT_CCC_KP", p) << ";\n"
        << "static const xyt_real XYT_CCC_KI XYT_MAYBE_UNUSED = "
        << realNum(c.ki, "cross_coupling.ki", "XYT_CCC_KI", p) << ";\n"
        << "static const xyt_real XYT_CCC_TS XYT_MAYBE_UNUSED = "
        << realNum(period[0], "controller_ts", "XYT_CCC_TS", p) << ";\n"
        << "static const xyt_real XYT_CCC_COS_CORNER XYT_MAYBE_UNUSED = "
        << realNum(std::cos(kCornerTurnRad), "cross_coupling", "XYT_CCC_COS_CORNER", p) << ";\n"
        << "typedef struct {\n    xyt_real integral, previous_tx, previous_ty;\n"
           "    int started;\n} xyt_ccc_state;\n"
        << "static inline XYT_MAYBE_UNUSED void xyt_ccc_init(xyt_ccc_state *c) {\n"
           "    c->integral = 0;\n    c->previous_tx = 0;\n    c->previous_ty = 0;\n"
           "    c->started = 0;\n}\n";
    for (int i = 0; i < 2; ++i) {
        const AxisEvaluation& a = evaluation.axes[static_cast<std::size_t>(i)];
        out << designMethodModule(a.method).cCoupledAxis(session, a, i);
    }
    out << "static inline XYT_MAYBE_UNUSED void xyt_ccc_step(xyt_ccc_state *c, xyt_" << x
        << "_state *sx, xyt_" << y
        << "_state *sy,\n"
           "        xyt_real rx, xyt_real ry, xyt_real rx_step, xyt_real ry_step, xyt_real mx,\n"
           "        xyt_real my, xyt_real tx, xyt_real ty, xyt_real kappa, int feed, xyt_real "
           "ffx,\n"
           "        xyt_real ffy, const xyt_real *given_x, const xyt_real *given_y, xyt_real u[2]) "
           "{\n"
           "    const xyt_real ex = rx - mx, ey = ry - my;\n"
           "    xyt_real eps, gx, gy, next, uc;\n"
           "    if (c->started && tx * c->previous_tx + ty * c->previous_ty < XYT_CCC_COS_CORNER)\n"
           "        c->integral = 0;\n"
           "    c->previous_tx = tx;\n    c->previous_ty = ty;\n    c->started = 1;\n"
           "    eps = -ex * ty + ey * tx;\n    gx = -ty;\n    gy = tx;\n"
           "    if (XYT_CCC_CIRCULAR && kappa != (xyt_real)0) {\n"
           "        const xyt_real tau = ex * tx + ey * ty;\n"
           "        eps = -ex * ty + ey * tx + (xyt_real)0.5 * kappa * tau * tau;\n"
           "        gx = -ty + kappa * tau * tx;\n        gy = tx + kappa * tau * ty;\n    }\n"
           "    if (!feed) {\n        c->integral = 0;\n"
           "        u[0] = xyt_"
        << x
        << "_coupled(sx, rx_step, mx, ffx, 0, given_x);\n"
           "        u[1] = xyt_"
        << y
        << "_coupled(sy, ry_step, my, ffy, 0, given_y);\n"
           "        return;\n    }\n"
           "    next = c->integral + XYT_CCC_TS * eps;\n"
           "    uc = XYT_CCC_KP * eps + XYT_CCC_KI * next;\n"
           "    u[0] = xyt_"
        << x
        << "_coupled(sx, rx_step, mx, ffx, gx * uc, given_x);\n"
           "    u[1] = xyt_"
        << y
        << "_coupled(sy, ry_step, my, ffy, gy * uc, given_y);\n"
           "    if (u[0] < XYT_UMAX && u[0] > -XYT_UMAX && u[1] < XYT_UMAX && u[1] > -XYT_UMAX)\n"
           "        c->integral = next;\n}\n\n";
    return out.str();
}

} // namespace xyt
