// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/design/cross_coupling.h"
#include "core/design/digital_controller.h"
#include "core/design/guillemin_truxal.h"
#include "core/design/input_shaper.h"
#include "core/design/notch_filter.h"
#include "core/model/flexible_mode.h"
#include "core/model/table_friction.h"
#include "core/study/specification.h"

#include <array>
#include <cstddef>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace xyt {

struct ProgramState; // core/session/program_trajectory.h

/**
 * The text of a G-code program, immutable once set and shared by every copy of the session
 * that holds it, together with what was read and planned from it (ProgramState): a session is
 * copied into every undo step and view, and its program is read once per text rather than by
 * each evaluation. Two texts compare by size and by a hash computed once when the text is set,
 * and by content only when both agree, so comparing sessions does not walk megabytes of
 * program on every edit.
 */
class ProgramText {
public:
    ProgramText() = default;
    ProgramText(std::string text); // NOLINT: implicit, a program is set from its text
    ProgramText(const char* text); // NOLINT
    const std::string& str() const;
    operator const std::string&() const { return str(); } // NOLINT
    bool empty() const { return str().empty(); }
    std::size_t size() const { return str().size(); }
    /// The shared text and its reads and plans; null for the empty program.
    const std::shared_ptr<const ProgramState>& state() const { return state_; }
    friend bool operator==(const ProgramText& a, const ProgramText& b);

private:
    std::shared_ptr<const ProgramState> state_;
};

/// How an axis is controlled. The two built-in methods are named; a method registered at
/// start-up (registerDesignMethodModule, core/session/design_method_module.h) takes a value of
/// its own.
enum class DesignMethod : int {
    GuilleminTruxal,    ///< continuous PI by the reference-model method (Braga et al.)
    PolePlacementZpetc, ///< discrete RST pole placement + ZPETC feedforward (Patrick, Ishak and
                        ///< Adnan)
    PidFeedforward      ///< the drives' PID with command feedforward (LinuxCNC's pid)
};

/// The Guillemin-Truxal parameters of one axis.
struct GtAxisSettings {
    ThirdOrderPlant plant{77.8, 125.3, 3665.0};
    double omegaNRadPerSec = 2.0;
    double kp = 30.0;
    /// Model output units per trajectory unit (0.001 for the paper's metre models, mm paths).
    double modelUnitsPerPositionUnit = 0.001;
    /// A mode of the table above the rigid plant (none by default). The design is made on the
    /// rigid plant, as the method knows it; every run and analysis closes the loop around the
    /// plant with the mode (axisPlantTransferFunction). Guillemin-Truxal and PID + feedforward
    /// axes; a pole-placement axis' ARX model holds whatever mode its data showed.
    FlexibleMode flexibleMode;
    /// A notch after the Guillemin-Truxal PI, on the position error it reads (none by default).
    NotchFilter notch;
    friend bool operator==(const GtAxisSettings&, const GtAxisSettings&) = default;
};

/// The discrete pole-placement + ZPETC parameters of one axis (polynomials in ascending z^-1).
struct PpAxisSettings {
    std::vector<double> a{1.0, -1.6580, 0.6583};
    std::vector<double> b{0.0, 0.0421, 0.0628, -0.0454};
    double t1 = -0.2; ///< desired closed-loop polynomial T = 1 + t1 z^-1
    double tsSeconds = 0.07;
    bool zpetcEnabled = true;
    friend bool operator==(const PpAxisSettings&, const PpAxisSettings&) = default;
};

/**
 * Where an axis model came from when it was identified from measured data: the
 * record, the structure and how well the model fitted. The session keeps it so that a shared
 * session says what its plant rests on; a plant typed by hand has none.
 */
struct ModelOrigin {
    std::string source; ///< the record, e.g. "run3.lvm: u=Command, y=X"
    std::string
        structure; ///< "ARX(2,3,1)", "OE(3,2,1)", "BJ(3,1,1,2,1)", "GT3 k0/(s^3+a1 s^2+a2 s)"
    double tsSeconds = 0.0;
    std::size_t samples = 0;
    double fitPercent = 0.0;                    ///< simulation fit on the estimation data (%)
    std::optional<double> validationFitPercent; ///< simulation fit on separate validation data
    std::vector<std::string> parameterNames;    ///< as the estimator names them
    std::vector<double> standardDeviations;     ///< of those parameters (NaN when unknown)
    /// Their covariance, row-major (d x d), or empty when the estimator could not give one.
    std::vector<double> covariance;
    /// Equal field by field, two NaN standard deviations counting as equal (a session must
    /// equal its copy, or every comparison of designs would see a change).
    friend bool operator==(const ModelOrigin& a, const ModelOrigin& b);
};

struct AxisSettings {
    std::string id = "x"; ///< "x" or "y": names the axis in exports (XYT_X_NUM, plant_x)
    std::string label;    ///< free text, e.g. "lower base"
    DesignMethod method = DesignMethod::GuilleminTruxal;
    GtAxisSettings gt;
    PpAxisSettings pp;
    /// The settings of a registered method that declares them (DesignMethodModule::parameters),
    /// by name; kept when the axis switches method, as gt and pp are.
    std::map<std::string, double> parameters;
    std::optional<ModelOrigin> origin; ///< set when the plant was identified from data
    /// The table's friction, backlash and amplifier deadband under this axis (all zero: the
    /// linear table). They act on the continuous plant k0 / (s (s^2 + a1 s + a2)) of gt: on
    /// Guillemin-Truxal and PID + feedforward axes. A pole-placement axis' ARX model has no
    /// moving mass: it takes the Coulomb level and the deadband as an input dead zone
    /// (arxInputDeadzoneVolts) and refuses the other elements by name.
    TableFriction friction;
    /// The firmware's friction feedforward from the reference velocity (FrictionCompensation).
    FrictionCompensation frictionCompensation;
    friend bool operator==(const AxisSettings&, const AxisSettings&) = default;
};

/// The trajectory: a point-to-point move (Cubic: its profile is TrajectorySettings::profile),
/// the circle, or a G-code program.
enum class TrajectoryKind { Cubic, Circle, Gcode };

/// The profile of a point-to-point move: Braga et al.'s cubic (CubicTrajectory), or the quintic
/// with zero acceleration at both ends that machine builders use (QuinticTrajectory).
enum class MoveProfile { Cubic, Quintic };

/**
 * A G-code program as a trajectory. The program text is held in the session, so a
 * shared session file is complete without the .nc file; fileName is only shown. The profile
 * options are those of FeedProfileOptions (core/contour/feed_profile.h); its step is the
 * trajectory's dtSeconds.
 */
struct GcodeTrajectory {
    std::string fileName; ///< where the program was read from (its name only, for display)
    ProgramText program;  ///< the program text
    double feedScale = 1.0;
    double maxAccelMmPerS2 = 500.0;
    double maxJerkMmPerS3 = 0.0; ///< 0: none (trapezoidal profile)
    friend bool operator==(const GcodeTrajectory&, const GcodeTrajectory&) = default;
};

/**
 * An input shaper on the reference of both axes (core/design/input_shaper.h): each axis'
 * reference becomes r_s(t) = sum A_i r(t - t_i), which cancels or bounds the residual vibration
 * of a mode of frequencyHz and dampingRatio at the price of a delay and, on a path, smoothing.
 * It acts on the trajectory at its own step, so the controller's period does not limit it.
 * frequencyHz = 0: no shaping, bit for bit.
 */
struct ReferenceShaping {
    ShaperType type = ShaperType::Zv;
    double frequencyHz = 0.0; ///< 0: none
    double dampingRatio = 0.1;
    bool active() const { return frequencyHz != 0.0; }
    friend bool operator==(const ReferenceShaping&, const ReferenceShaping&) = default;
};

/// The commanded motion. A cubic drives both axes with the same profile (a diagonal move, as
/// Braga et al. Fig. 8); the circle drives x with R sin(w t) and y with R cos(w t); a G-code
/// program drives x and y along its feed profile (core/session/program_trajectory.h).
struct TrajectorySettings {
    TrajectoryKind kind = TrajectoryKind::Cubic;
    double x0 = 0.0, xf = 600.0, t0Seconds = 0.0, tfSeconds = 130.0, v0 = 0.0, vf = 0.0;
    MoveProfile profile = MoveProfile::Cubic; ///< of the point-to-point move
    double radius = 25.0, omegaRadPerSec = 0.06, rampInSeconds = 10.0;
    GcodeTrajectory gcode;
    /// The input shaper on the reference (none by default). A shaped run lasts the shaper's
    /// duration longer (effectiveDurationSeconds) so that the shaped move ends.
    ReferenceShaping shaping;
    /// 0: automatic. A circle runs one revolution plus the ramp-in. A cubic runs past tf until
    /// the response has settled into the specification's in-position window, as the evaluation
    /// estimates from the closed-loop poles (SessionEvaluation::duration says what it chose), at
    /// most kAutomaticSettleMoves (move_settle.h) move durations after tf.
    double durationSeconds = 0.0;
    /// Simulation step of continuous axes (discrete axes use their own sample time).
    double dtSeconds = 0.01;

    /**
     * The longest run this trajectory asks for: for a G-code program always its feed profile's
     * run time (0 when the program cannot be read or planned; durationSeconds is not used); the
     * duration when it is set; for the circle one
     * revolution plus the ramp-in; for an automatic cubic the cap automaticMoveCapSeconds (tf + 3
     * (tf - t0), lowered to what the machine's sample limit holds at dtSeconds, never below tf;
     * the evaluation picks a run between tf and this). Sample-count checks use it, so they hold
     * for any run the evaluation may choose.
     */
    double effectiveDurationSeconds() const;
    friend bool operator==(const TrajectorySettings&, const TrajectorySettings&) = default;
};

/// A named copy of a design, stored in the session to compare against and to go back to.
struct DesignSnapshot {
    std::string name;
    std::array<AxisSettings, 2> axes;
    TrajectorySettings trajectory;
    double umaxVolts = 2.5;
    friend bool operator==(const DesignSnapshot&, const DesignSnapshot&) = default;
};

/**
 * How the firmware runs the controllers: the digital implementation simulated next to
 * the design (core/simulation/sampled_data.h) and exported as C code. Digital PI axes run at the
 * session's controllerTsSeconds with its piDiscretization; pole-placement axes at their own Ts.
 */
struct ImplementationSettings {
    /// Computation delay in samples (0..kMaxDelaySamples): u computed at k is applied at k + delay.
    int delaySamples = 0;
    /// Encoder resolution (mm per count); 0: ideal.
    double encoderResolutionMm = 0.0;
    /// DAC bits over +-umax (0..32); 0: ideal.
    int dacBits = 0;
    /// The anti-windup of the digital PI; clamping (conditional integration) is what an engineer
    /// ships: no parameter to tune and no overshoot from a wound-up integrator.
    AntiWindup antiWindup = AntiWindup::Clamp;
    /// Back-calculation's tracking time Tt (s); 0: Tt = Ti = kp/ki.
    double trackingTimeSeconds = 0.0;
    friend bool operator==(const ImplementationSettings&, const ImplementationSettings&) = default;
};

/// The whole design: two axes, the motion, the actuator limit.
struct Session {
    std::array<AxisSettings, 2> axes;
    TrajectorySettings trajectory;
    double umaxVolts = 2.5;
    /// Sample time of the digital PI when a continuous design is exported (Tustin by default).
    double controllerTsSeconds = 0.01;
    /// How that PI is discretized (Tustin by default).
    PiDiscretization piDiscretization = PiDiscretization::Tustin;
    /// The digital implementation (delay, encoder, DAC, anti-windup).
    ImplementationSettings implementation;
    /// What the design must meet (Braga et al.: settling <= 100 s, no overshoot, no saturation,
    /// max error <= 2 %). Its umaxVolts is ignored: the session's umaxVolts is the limit.
    Specification spec;
    /// Koren's cross-coupled contouring controller over both axes on a program's contour run
    /// (core/design/cross_coupling.h); off (gains 0) by default.
    CrossCoupling crossCoupling;
    std::vector<DesignSnapshot> snapshots;

    /// The current design as a snapshot named @p name.
    DesignSnapshot snapshot(const std::string& name) const;
    /// This session with the design of @p snapshot (snapshots and export settings kept).
    Session withDesign(const DesignSnapshot& snapshot) const;

    /// The design of Braga et al.: x is the lower base, y the upper base, cubic 0 -> 600 mm in 130
    /// s.
    static Session paperDefault();
    friend bool operator==(const Session&, const Session&) = default;
};

} // namespace xyt
