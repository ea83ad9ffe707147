// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/analysis/parameter_locus.h"
#include "core/analysis/pole_zero_map.h"
#include "core/analysis/root_locus.h"
#include "core/identification/accelerometer_log.h"
#include "core/identification/spectral_estimate.h"
#include "core/session/axis_frequency.h"
#include "core/session/result_dependence.h"
#include "core/session/session.h"
#include "core/session/session_evaluation.h"

#include <QObject>
#include <QString>
#include <QUndoStack>

#include <array>
#include <cstdint>
#include <memory>
#include <optional>

namespace xyt::ui {

/**
 * What a view's result was computed for: the session's revision and the session itself at that
 * moment, the axis (-1 for a joint XY result) and what of the session the result depends on.
 * Views keep it beside the result and ask TuningSession::isCurrent before showing it as the
 * current design's.
 */
struct ResultStamp {
    std::uint64_t revision = 0;
    int axis = -1;
    ResultScope scope = ResultScope::AxisDesign;
    Session session;
};

/**
 * The presenter of the workbench: owns the design (a core `Session`), its evaluation, and the
 * undo stack. Widgets call the setters and observe `designChanged()`; nothing is computed in a
 * widget. Every change goes through `apply()`, which pushes an undoable command holding the
 * session before and after; consecutive changes with the same merge key (one slider drag) merge
 * into one undo step.
 */
class TuningSession : public QObject {
    Q_OBJECT
public:
    explicit TuningSession(QObject* parent = nullptr);

    const Session& session() const { return session_; }
    const SessionEvaluation& evaluation() const { return evaluation_; }
    const AxisEvaluation& axisEvaluation(int axis) const;
    QUndoStack* undoStack() { return &undo_; }

    int currentAxis() const { return currentAxis_; }

    /// Counts the changes of the session (undo, redo, load and File › New included).
    std::uint64_t revision() const { return revision_; }
    /// A stamp for a result of @p scope about @p axis (-1 with BothAxes) computed from now.
    ResultStamp stamp(int axis, ResultScope scope) const;
    /**
     * True when a result stamped @p stamp describes the session as it is: the same revision,
     * or a session that agrees in everything the result depends on (an undo back to it).
     */
    bool isCurrent(const ResultStamp& stamp) const;
    /// What @p stamp's result was computed for, in words: "axis X, ωn = 2 rad/s, kp = 30".
    static QString describe(const ResultStamp& stamp);

    /**
     * Samples per axis that one live refresh may simulate. A run that needs more (dt = 1e-5 s on
     * a 130 s move is 13 million samples, 0.6 GB and over a second per axis) is evaluated at the
     * coarser dt = duration / kLiveSampleLimit and the views say so (liveNotice); the exports and
     * the report still use the session's dt. One million samples take about 50 ms per axis.
     */
    static constexpr double kLiveSampleLimit = 1'000'000;
    /// The session as the live views evaluate it (its dt raised to the live limit when needed).
    const Session& liveSession() const { return live_; }
    /// The live version of any session @p s (a snapshot's too): its dt raised so that a run
    /// needs at most kLiveSampleLimit samples; @p notice says what was changed ("" if nothing).
    static Session liveSessionOf(const Session& s, QString& notice);
    /// What the live evaluation changed, for the views ("" when it is the session itself).
    const QString& liveNotice() const { return liveNotice_; }
    /// True when the session differs from the last saved or loaded state.
    bool isModified() const { return !undo_.isClean(); }

    /**
     * Replaces the whole session as one undoable step named @p description. A change whose
     * @p mergeKey equals the previous command's merges with it (slider drags); -1 never merges.
     */
    void apply(const Session& next, const QString& description, int mergeKey = -1);
    /// Replaces the session without an undo step (load, new) and marks it clean.
    void reset(const Session& next);
    /// Marks the current state as saved.
    void markSaved() { undo_.setClean(); }

    /**
     * The root locus of the axis' loop, 1 + K L = 0 with K = 1 the design: L = G_c G for a
     * continuous design, L = B G / (A F) (the feedback path) for a discrete one. Computed on
     * first use after each change (cached).
     */
    const RootLocus& rootLocus(int axis) const;
    /// The closed-loop poles of a GT axis as wn or kp sweeps a decade each way (cached).
    const ParameterLocus& parameterLocus(int axis, GtSweptParameter parameter) const;
    /// The frequency-domain view of an axis: responses, margins, Nyquist curve (cached).
    const AxisFrequencyAnalysis& frequencyAnalysis(int axis) const;
    /**
     * Axis @p axis of snapshot @p index evaluated with this session's trajectory, limits and
     * implementation (what the time plot overlays), at the live dt. Cached: a change of the
     * current design (a slider step) does not evaluate it again, a change of what it depends
     * on does. @throws std::out_of_range for an index past the snapshots.
     */
    const AxisEvaluation& snapshotEvaluation(std::size_t index, int axis) const;
    /// How many snapshot evaluations were computed (the cache's misses), for the tests.
    std::size_t snapshotEvaluationsComputed() const { return snapshotCache_.computed; }
    /// Pole-zero sets of the axis: plant, controller, open loop, closed loop, reference model
    /// (GT) or plant, feedback, closed loop, ZPETC feedforward (discrete).
    std::vector<PoleZeroSet> poleZeroSets(int axis) const;

    /**
     * Uses the loop gain K picked on the root locus of a GT axis: the controller becomes
     * K (kp + ki/s), i.e. kp' = K kp and, since ki = wn^4/k0 (Eq. 11, 16), wn' = K^(1/4) wn.
     * Returns false (and changes nothing) for a discrete axis or a gain that is not > 0.
     */
    bool applyLoopGain(int axis, double gain);
    /// The loop gain @p gain applied to @p base (the axis as it was when a drag along the locus
    /// began), so that a drag's steps do not compound; steps with @p mergeKey merge.
    bool applyLoopGainTo(int axis, const AxisSettings& base, double gain, int mergeKey = -1);

    // Convenience setters (each one apply() step). Axis index 0 = x, 1 = y.
    void setMethod(int axis, DesignMethod method);
    void setPp(int axis, const PpAxisSettings& pp, int mergeKey = -1);
    void setSpecification(const Specification& spec);
    void setOmegaN(int axis, double omegaNRadPerSec);
    void setKp(int axis, double kp);
    void setPlant(int axis, const ThirdOrderPlant& plant);
    void setModelUnitScale(int axis, double modelUnitsPerPositionUnit);
    /// The table's friction and the friction compensation of @p axis, as one undo step.
    void setFriction(int axis, const TableFriction& friction,
                     const FrictionCompensation& compensation);
    /// The axis' flexible mode and notch (GtAxisSettings), one undo step.
    void setLoopElements(int axis, const FlexibleMode& mode, const NotchFilter& notch);
    void setTrajectory(const TrajectorySettings& trajectory);
    void setCrossCoupling(const CrossCoupling& coupling);
    void setUmax(double umaxVolts);
    void setImplementation(const ImplementationSettings& implementation);
    void setControllerTs(double seconds);
    void setPiDiscretization(PiDiscretization discretization);
    /// The specification and the actuator limit together (the design-space view edits both).
    void setSpecificationAndLimit(const Specification& spec, double umaxVolts);
    /// A whole Guillemin–Truxal parameter set of an axis (a preset, a point of the design space).
    void setGt(int axis, const GtAxisSettings& gt, const QString& description);
    /**
     * Moves the zero of a PID + feedforward axis' controller at @p from to @p to
     * (pidGainsWithMovedZero): P, I, D change, successive moves of one drag merge into one undo
     * step. Returns why nothing changed (another method, a zero a PID cannot have), or empty.
     */
    QString moveControllerZero(int axis, std::complex<double> from, std::complex<double> to);
    /// One axis replaced (an identified model with its origin); false when nothing changed.
    /// Successive changes with the same @p mergeKey (>= 0: a slider drag) are one undo step.
    bool setAxis(int axis, const AxisSettings& settings, const QString& description,
                 int mergeKey = -1);
    /// Both axes replaced together (a worst-case plant pair), as one step.
    void setAxes(const std::array<AxisSettings, 2>& axes, const QString& description);
    /// Stores the current design as a snapshot named @p name.
    void storeSnapshot(const QString& name);

    /// A measured frequency response of axis @p axis (Welch's estimate of a logged experiment,
    /// y in mm over u in V), drawn against the model in the Vibration view. Measurements are
    /// not part of the session (nor of its undo): they stay until replaced or cleared (null).
    struct MeasuredResponse {
        FrequencyResponseEstimate estimate;
        QString source;
    };
    void setMeasuredResponse(int axis, std::shared_ptr<const MeasuredResponse> response);
    const std::shared_ptr<const MeasuredResponse>& measuredResponse(int axis) const {
        return measuredResponse_.at(static_cast<std::size_t>(axis));
    }
    /// An accelerometer log's spectra (Klipper's), drawn in the Vibration view.
    struct MeasuredAcceleration {
        AccelerometerSpectra spectra;
        QString source;
    };
    void setMeasuredAcceleration(std::shared_ptr<const MeasuredAcceleration> acceleration);
    const std::shared_ptr<const MeasuredAcceleration>& measuredAcceleration() const {
        return measuredAcceleration_;
    }

public slots:
    void setCurrentAxis(int axis);

signals:
    /// A measurement was set or cleared: the views that draw one redraw.
    void measurementsChanged();
    /// The session or its evaluation changed: every view redraws from the getters.
    void designChanged();
    void currentAxisChanged(int axis);

private:
    friend class SessionCommand;
    /// Sets the session and re-evaluates it (used by the undo commands).
    void assign(const Session& next);

    Session session_;
    Session live_;
    QString liveNotice_;
    SessionEvaluation evaluation_;
    mutable std::array<std::optional<RootLocus>, 2> locus_;
    mutable std::array<std::optional<ParameterLocus>, 4> parameterLocus_;
    mutable std::array<std::optional<AxisFrequencyAnalysis>, 2> frequency_;
    struct SnapshotCache {
        Session evaluated; ///< the snapshot's design in this session, at the live dt
        int axis = -1;
        std::optional<AxisEvaluation> evaluation;
        std::size_t computed = 0;
    };
    mutable SnapshotCache snapshotCache_;
    QUndoStack undo_;
    int currentAxis_ = 0;
    std::array<std::shared_ptr<const MeasuredResponse>, 2> measuredResponse_;
    std::shared_ptr<const MeasuredAcceleration> measuredAcceleration_;
    std::uint64_t revision_ = 0;
};

/// "X" or "Y": axis @p axis of @p s as the window names it.
QString axisName(const Session& s, int axis);

/// The name the workbench shows for @p method (its module's displayName).
QString methodDisplayName(DesignMethod method);

/// Merge keys for slider drags: one per parameter and axis.
enum MergeKey {
    kMergeOmegaN = 100,
    kMergeKp = 200,
    kMergeT1 = 300,
    kMergeMethodEditor = 400,
    kMergeZeroDrag = 500,
    kMergeGainDrag = 600
};

} // namespace xyt::ui
