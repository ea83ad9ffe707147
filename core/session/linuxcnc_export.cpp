// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/session/linuxcnc_export.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/session/friction_export.h"

#include "core/model/errors.h"
#include "core/session/axis_run.h"
#include "core/session/c_export.h"
#include "core/session/pid_feedforward_method.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace xyt {

namespace {

/// The largest |e| of @p run, and the largest where the command moves at most a tenth of its
/// peak speed (backward differences of r).
std::pair<double, double> followingErrors(const SimulationResult& run) {
    std::vector<double> speed(run.r.size(), 0.0);
    double peak = 0.0;
    for (std::size_t k = 1; k < run.r.size(); ++k) {
        speed[k] = std::abs(run.r[k] - run.r[k - 1]);
        peak = std::max(peak, speed[k]);
    }
    double all = 0.0, slow = 0.0;
    for (std::size_t k = 0; k < run.e.size(); ++k) {
        const double e = std::abs(run.e[k]);
        all = std::max(all, e);
        if (speed[k] <= 0.1 * peak)
            slow = std::max(slow, e);
    }
    return {all, slow};
}

} // namespace

std::string exportLinuxCnc(const Session& session, const SessionEvaluation& evaluation,
                           bool feedforwardFromModel) {
    std::ostringstream out;
    out << "# XY Tune: LinuxCNC pid gains (the pid component of LinuxCNC 2.8 and later).\n"
        << "# Units: position in mm (the joint's position scale in mm), the pid output in volts\n"
        << "# before the DAC's scale (+-" << cexport::num(session.umaxVolts, "umax")
        << " V the amplifier's range).\n"
        << "# A HAL file (halcmd -f): load the component for the joints first, e.g.\n"
        << "# `loadrt pid names=pid.0,pid.1`. The INI suggestions are comments.\n";
    for (std::size_t i = 0; i < session.axes.size(); ++i) {
        const int index = static_cast<int>(i);
        const AxisEvaluation& a = evaluation.axes[i];
        AxisSettings axis = session.axes[i];
        if (axis.method != DesignMethod::GuilleminTruxal &&
            axis.method != DesignMethod::PidFeedforward)
            throw InvalidInput(
                axisFieldPath(index, "method"),
                makeDiagnostic("session_no_linuxcnc_pid",
                               {std::string(designMethodModule(axis.method).displayName())}));
        if (!a.ok)
            throw InvalidInput(a.errorField, Diagnostic(a.error)); // its coded reason
        if (feedforwardFromModel || axis.method == DesignMethod::GuilleminTruxal) {
            const AxisSettings withFf = withModelFeedforward(axis, index);
            axis = withFf;
            if (!feedforwardFromModel)
                for (const char* name : {"ff0", "ff1", "ff2", "ff3"})
                    axis.parameters[name] = 0.0;
        }
        Session probe = session;
        probe.axes[i] = axis;
        const PidFeedforwardDesign d = designPidFeedforward(probe, index);
        const ServoPidGains& g = d.gains;
        const std::string pin = "pid." + std::to_string(i) + ".";
        const auto setp = [&](const char* name, double v, const std::string& field) {
            out << "setp " << pin << name << " " << cexport::num(v, field) << "\n";
        };
        const std::string field = axisFieldPath(index, "parameters");
        out << "\n# Axis " << axis.id << cexport::labelComment(axis, CommentSyntax::Octave)
            << " as joint " << i << ": "
            << (session.axes[i].method == DesignMethod::GuilleminTruxal
                    ? "Braga et al.'s Guillemin-Truxal PI (P = kp u, I = ki u per mm)"
                    : "PID + feedforward")
            << (feedforwardFromModel ? ", feedforward from the model (FF1 = a2 u/k0, FF2 = a1 "
                                       "u/k0, FF3 = u/k0)"
                                     : "")
            << ".\n";
        setp("Pgain", g.p, field + ".p");
        setp("Igain", g.i, field + ".i");
        setp("Dgain", g.d, field + ".d");
        setp("bias", g.bias, field + ".bias");
        setp("FF0", g.ff0, field + ".ff0");
        setp("FF1", g.ff1, field + ".ff1");
        setp("FF2", g.ff2, field + ".ff2");
        setp("FF3", g.ff3, field + ".ff3");
        setp("deadband", g.deadband, field + ".deadband");
        setp("maxerrorI", g.maxErrorI, field + ".max_error_i");
        setp("maxoutput", g.maxOutput, field + ".max_output");
        if (g.derivativeFilterSeconds > 0.0)
            out << "# The derivative filter Tf = "
                << cexport::num(g.derivativeFilterSeconds, field + ".derivative_filter")
                << " s has no pid pin: LinuxCNC differentiates without a filter.\n";
        if (g.derivativeOnMeasurement)
            out << "# D acts on the measurement here; LinuxCNC's pid differentiates the error.\n";
        out << linuxCncFrictionNote(session.axes[i], index, i);
        if (d.derivativeSource == CommandDerivativeSource::TrajectoryGenerator)
            out << "# The session reads the command's derivatives from the trajectory: connect "
                   "pid."
                << i << ".command-deriv (and -dd/-ddd where your motion controller gives them).\n";
        // The following error of the run the axis makes (the digital one when there is one);
        // the exported feedforward may differ from the session's, so the run is that of the
        // exported gains only when nothing was changed.
        const SimulationResult& run = a.digital ? a.digital->run.result : a.run;
        const auto [all, slow] = followingErrors(run);
        out << "# INI: " << kFollowingErrorMargin
            << " x the simulated following error of the session's "
            << (a.digital ? "digital loop" : "run") << " (" << cexport::num(all, "run")
            << " mm at any speed, " << cexport::num(slow, "run")
            << " mm below a tenth of the peak speed)"
            << (feedforwardFromModel ? "; the feedforward from the model changes it: run the "
                                       "session with it to measure again"
                                     : "")
            << ".\n# Copy into the machine's INI file:\n#   [JOINT_" << i
            << "]\n#   FERROR = " << cexport::num(kFollowingErrorMargin * all, "run")
            << "\n#   MIN_FERROR = " << cexport::num(kFollowingErrorMargin * slow, "run") << "\n";
    }
    return out.str();
}

} // namespace xyt
