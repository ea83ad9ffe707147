// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/simulation/metrics.h"
#include "core/simulation/move_settle.h"

#include <optional>

namespace xyt {

/**
 * The performance specification of Braga et al. (Sec. 3): settling time of 100 s, no overshoot,
 * the control voltage never saturating at +-2.5 V, and a tracking error below 2 %.
 *
 * Overshoot and settling time are those of the closed loop's unit step response
 * (stepCharacteristics, 2 % band); the error and the control voltage are those of one tracking
 * run (trackingMetrics), the error as max |e| / travel * 100.
 */
struct Specification {
    double maxSettlingTimeSeconds = 100.0;
    double maxOvershootPct = 0.0; ///< the paper's "no overshoot"
    double umaxVolts = 2.5;       ///< |u| must stay within this and never be clipped
    double maxErrorPct = 2.0;     ///< max |e| as % of the travel
    /// In-position window of a point-to-point move (mm): the table is "in position" while
    /// |e| <= this (MoveSettleMetrics). 0.01 mm is a small fraction of any travel (1/60000 of
    /// the paper's 600 mm move) and the resolution class of the tables it describes.
    double inPositionWindowMm = 0.01;
    /**
     * Move-and-settle limit (s): the settle time after the end of a point-to-point move
     * (MoveSettleMetrics::settleTimeSeconds) must not exceed this. The paper states no such
     * limit; 100 s reuses its settling-time figure. The paper's own default design does NOT
     * pass it, and no sensible limit would let it: its slow closed-loop pole near -psi1 (the PI
     * zero; -0.0069 and -0.0014 rad/s for the lower and upper base) takes 876 s and some 3000 s
     * after tf to bring |e| inside 0.01 mm. Saying so is what the issue asks for; a limit of
     * 3000 s would hide it.
     */
    double maxSettleTimeSeconds = 100.0;
    /**
     * Minimum phase margin (degrees) and gain margin (dB) of the loop L (stability_margins.h:
     * the reported margins, i.e. the phase margin of smallest magnitude and the gain margin
     * nearest 0 dB). Braga et al. state no margin requirement, so both are 0 by default: a stable
     * loop with positive margins passes, as every design of the papers does (45.9 dB / 88.1
     * deg and 38.1 dB / 86.1 deg for the two bases). 45-60 deg and 6 dB are the usual rules.
     */
    double minPhaseMarginDeg = 0.0;
    double minGainMarginDb = 0.0;

    /**
     * Slack on the overshoot criterion, in percent, for round-off only. The sampled step
     * response is a recursion of some 10^4 steps, so its samples carry a relative round-off of
     * about 1e4 * 1.1e-16 ~ 1e-12 (1e-10 %); 1e-9 % sits above that and is 6 pm on a 600 mm move.
     *
     * Note that no Guillemin-Truxal design of Braga et al. has zero step overshoot: G_R is type 2
     * (Eq. 7), so the step error E(s) = s (s^2 + a1 s + a2) / D(s) has integral E(0) = 0; it
     * starts at 1, so it must go negative, i.e. y overshoots. With maxOvershootPct = 0 every
     * design fails the overshoot criterion (the paper's own lower-base design overshoots 0.997 %,
     * through its slow pole-zero pair); that is reported, not hidden by a larger tolerance.
     */
    static constexpr double kOvershootRoundOffPct = 1e-9;

    /// @throws InvalidInput "max_settling_time", "max_overshoot_pct", "max_error_pct" (finite,
    ///         >= 0; settling and error > 0), "umax", "in_position_window_mm",
    ///         "max_settle_time" (finite, > 0), "min_phase_margin" (finite, 0 .. 180),
    ///         "min_gain_margin" (finite, >= 0).
    void validate() const;
    friend bool operator==(const Specification&, const Specification&) = default;
};

/// Pass/fail of each criterion of a Specification. A failed criterion says nothing about the
/// others; a metric that is not finite fails its criterion.
struct SpecificationCheck {
    bool stable = false;        ///< closed loop asymptotically stable (needed by the step figures)
    bool settlingTime = false;  ///< settlingTimeSeconds <= maxSettlingTimeSeconds
    bool overshoot = false;     ///< overshootPct <= maxOvershootPct + kOvershootRoundOffPct
    bool noSaturation = false;  ///< no clipped sample and maxAbsU <= umaxVolts
    bool trackingError = false; ///< maxAbsErrorPct <= maxErrorPct
    /// Point-to-point moves only (settleApplies): the run settled into the window and
    /// settleTimeSeconds <= maxSettleTimeSeconds. True when it does not apply (a circle).
    bool settle = true;
    bool settleApplies = false; ///< the run was a point-to-point move with move-and-settle figures
    /// The loop's margins (marginsApply: they were given to the check) against the minima; an
    /// unstable closed loop fails both (its margins are no robustness measure). True when they
    /// do not apply.
    bool phaseMargin = true;
    bool gainMargin = true;
    bool marginsApply = false;

    bool allPassed() const {
        return stable && settlingTime && overshoot && noSaturation && trackingError && settle &&
               phaseMargin && gainMargin;
    }
};

/**
 * Each criterion passing only where it passes in both @p a and @p b: the verdict of a design
 * together with its implementation (the worse of the two; a criterion applies where it applies
 * in either). Equal to @p a when @p b is @p a.
 */
SpecificationCheck bothPass(const SpecificationCheck& a, const SpecificationCheck& b);

/// The two margins a Specification judges (StabilityMargins::phaseMarginDeg, gainMarginDb):
/// +infinity when the loop has no such crossing (it passes), NaN fails.
struct LoopMarginFigures {
    double phaseMarginDeg = 0.0;
    double gainMarginDb = 0.0;
};

/**
 * Checks one design against @p spec. An unstable closed loop fails `stable`, `settlingTime` and
 * `overshoot` (its step figures are undefined); the tracking criteria are still judged on the run.
 * With @p move (a point-to-point run) `settle` is judged too: a run that did not settle, that
 * diverged, or whose window is not the spec's inPositionWindowMm fails it. With @p margins the
 * minimum phase and gain margins are judged too.
 * @throws InvalidInput from Specification::validate.
 */
SpecificationCheck
checkSpecification(const Specification& spec, const TrackingMetrics& tracking,
                   const StepCharacteristics& step,
                   const std::optional<MoveSettleMetrics>& move = std::nullopt,
                   const std::optional<LoopMarginFigures>& margins = std::nullopt);

} // namespace xyt
