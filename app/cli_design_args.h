// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Argument parsing shared by the commands on the Guillemin-Truxal design of Braga et al.
// (gt, simulate, sweep): the plant, the design point, the trajectory and the simulation setup.

#include "app/cli_args.h"

#include "core/analysis/stability_margins.h"

#include "core/design/guillemin_truxal.h"
#include "core/io/file_io.h"
#include "core/model/errors.h"
#include "core/session/session.h"
#include "core/simulation/move_settle.h"
#include "core/simulation/sampled_data.h"
#include "core/simulation/simulation.h"

#include <QJsonObject>
#include <QString>
#include <QStringList>

#include <functional>
#include <vector>

namespace xyt::cli {

/// --preset, --k0, --a1, --a2: the plant.
extern const QStringList kPlantOptions;
/// kPlantOptions plus --wn, --kp: one design.
extern const QStringList kDesignOptions;
/// Only for commands that simulate: model units per trajectory unit.
extern const QString kUnitOption;
/// The trajectory and simulation options (--trajectory ... --dt --umax --csv).
extern const QStringList kTrajectoryOptions;

/// The plant from --preset and/or --k0 --a1 --a2 (explicit values override the preset's).
struct PlantInput {
    ThirdOrderPlant plant;
    double modelUnitsPerPositionUnit = 1.0; ///< the preset's (0.001: m per mm), else 1
    std::optional<GtPreset> preset;
};
PlantInput parsePlant(const CliArgs& args);

/// The plant plus --wn --kp (defaulting to the preset's design).
struct DesignInput {
    ThirdOrderPlant plant;
    double wn;
    double kp;
    double modelUnitsPerPositionUnit = 1.0;
};
DesignInput parseDesign(const CliArgs& args);

QJsonObject plantJson(const ThirdOrderPlant& plant);
QJsonObject designJson(const GtDesign& d);

/// A reference signal and its default duration.
struct Reference {
    std::function<double(double)> at;
    double defaultDuration;
    QString description;
    /// The cubic: a point-to-point move (its end tf is defaultDuration) and its start time t0.
    std::optional<PointToPointMove> move;
    double t0Seconds = 0.0;
};
/// --trajectory cubic|quintic|sine and its parameters (quintic: the rest-to-rest move with zero
/// acceleration at both ends, QuinticTrajectory, on the cubic's options).
Reference parseTrajectory(const CliArgs& args);

/// The sampled trajectory and loop options of a simulating command: --dt (0.01), --umax (2.5),
/// --duration (the trajectory's default), --model-unit-scale (the plant's default).
struct SimulationSetup {
    Reference trajectory;
    std::vector<double> reference;
    double durationSeconds = 0.0;
    LoopSimulationOptions options;
};
/// A cubic move shorter than one step of --dt is refused naming --tf (and --dt); one shorter than
/// ten steps gets a warning on stderr naming both.
SimulationSetup parseSimulationSetup(const CliArgs& args, const PlantInput& plant);
/// Samples the reference of @p setup again over @p durationSeconds (an automatic duration
/// chosen after parsing), with the refusals of parseSimulationSetup.
void resampleSetup(SimulationSetup& setup, const CliArgs& args, double durationSeconds);
/// The setup's description keys: trajectory, duration, dt, umax, model_unit_scale, samples.
void insertSetupJson(QJsonObject& out, const SimulationSetup& setup);

/// A number > 0 from --name, or @p fallback.
double positiveNumber(const CliArgs& args, const QString& name, double fallback);

/**
 * Writes @p path atomically (xyt::writeFileAtomically), the content streamed by @p produce.
 * @throws InvalidInput naming @p argument ("-o", "--csv") with the path and the system's
 *         reason when the file cannot be written; the old file is then unchanged.
 */
void writeFile(const std::string& argument, const QString& path,
               const std::function<void(const ByteSink&)>& produce);
/// The message of a file that could not be written, naming @p argument: "-o: cannot write
/// <path>: <reason>; nothing was written, an existing file is unchanged".
InvalidInput cannotWrite(const std::string& argument, const FileError& e);
/// The same for a text held in memory.
void writeTextFile(const std::string& argument, const QString& path, const QString& text);
/// t,r,y,e,u of one run, streamed. @throws InvalidInput @p field when a signal is not finite.
/// With @p digital (simulate --digital), also t_digital,y_digital,e_digital,u_digital: at each
/// row the digital run's sample held at t (the last at or before it, heldSampleIndices; with
/// --controller-ts equal to --dt the row's own sample), 17 significant digits; empty where not
/// finite.
void writeCsv(const QString& path, const SimulationResult& run,
              const SimulationResult* digital = nullptr);

/// "GM 45.9 dB at 60.5 rad/s, PM 88.1 deg at 0.637 rad/s, delay margin 2.42 s, Ms 1.02" (for the
/// text reports; infinite margins as inf, and a word when the closed loop is unstable).
QString marginsText(const StabilityMargins& m);

/// The session file @p path (its warnings printed to stderr).
/// @throws InvalidInput naming the path with the loader's message (field path and reason).
Session loadSessionOrThrow(const QString& path);

/// The sampled-data options of simulate --digital: --delay-samples, --encoder-resolution,
/// --dac-bits, --anti-windup, with @p umaxVolts; a refusal names the option.
SampledDataOptions parseSampledDataOptions(const CliArgs& args, double umaxVolts);
/// --discretization tustin|backward-euler, or @p fallback when not given.
PiDiscretization parseDiscretization(const CliArgs& args, PiDiscretization fallback);
/// --anti-windup none|clamp|back-calculation (clamp when not given).
AntiWindup parseAntiWindup(const CliArgs& args);

} // namespace xyt::cli
