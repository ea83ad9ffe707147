// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/analysis/damping_grid.h"
#include "core/model/diagnostic.h"
#include "core/model/polynomial.h"
#include "core/model/transfer_function.h"

#include <complex>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace xyt {

/// A rectangle of the s- or z-plane (real part horizontal, imaginary part vertical).
struct LocusView {
    double reMin = 0.0, reMax = 0.0, imMin = 0.0, imMax = 0.0;

    /// max(width, height): the length the step bound is a fraction of.
    double span() const;
    bool contains(std::complex<double> p) const;
    /// @throws InvalidInput "view" unless finite with reMin < reMax and imMin < imMax.
    void validate() const;
};

struct RootLocusOptions {
    /// The view: computed from the poles, zeros, breakaway points, crossings and asymptote
    /// centroid (plus a margin; for discrete loops it always holds the unit circle) when empty.
    std::optional<LocusView> view;
    /// > 0: trace K from 0 exactly to kMax. 0: trace until every branch has reached its zero
    /// (within one step bound) or left the view.
    double kMax = 0.0;
    /// The step bound: a root inside the view moves at most this fraction of view.span()
    /// between consecutive points.
    double maxStepFraction = 0.01;
    /// Denser points where branches approach each other (and so near breakaway points): a root
    /// moves at most this fraction of its distance to the nearest other root ...
    double approachFraction = 0.25;
    /// ... but not less than this fraction of the step bound (a floor, so that a multiple pole
    /// does not stall the trace).
    double minStepFraction = 1e-3;
    /// Bound on the number of gains traced (the run time is bounded even when the locus does
    /// not converge; status PointLimitReached then).
    int maxPoints = 5000;
    /// Bound on the root-finding work, in counted operations (about 20 n^2 per Newton
    /// correction and 10 n^3 per eigenvalue solve, n = deg D): the 4th-order GT locus uses
    /// about 1e6, a 40th-order one ran for minutes before this bound (status PointLimitReached).
    /// 2e8 is 200 times the GT locus and well under a second where the count holds.
    double maxWork = 2e8;
    /**
     * Wall-clock bound (s), the safety net under the count: an eigenvalue solve that does not
     * converge costs 40 Francis steps a row, far above the counted 10 n^3. A 7th-order loop
     * found by fuzz_design (corpus timeout-locus-work) ran 6.7 s within the work bound, over
     * 15 s in the sanitizer build. Status PointLimitReached with a warning, as the work bound.
     */
    double maxSeconds = 2.0;
};

/// One branch: roots[i] is a closed-loop pole at gains[i] of the RootLocus.
struct LocusBranch {
    std::vector<std::complex<double>> roots;
    std::complex<double> start; ///< the open-loop pole it starts from (K = 0)
    /// The finite open-loop zero it converges to, when the trace ended within one step bound
    /// of it; empty when the branch left the view (towards an asymptote) or the trace stopped.
    std::optional<std::complex<double>> end;
};

/// The n - m branches that go to infinity follow straight lines from the centroid.
struct LocusAsymptotes {
    int count = 0;                 ///< n - m (0: no asymptotes, centroid meaningless)
    double centroid = 0.0;         ///< (sum of poles - sum of zeros)/(n - m), on the real axis
    std::vector<double> anglesDeg; ///< in [0, 360)
};

/// A point of the locus with its gain (breakaway, break-in, stability-boundary crossing).
struct LocusFeature {
    std::complex<double> point;
    double gain = 0.0;
};

enum class RootLocusStatus {
    Complete,          ///< every branch reached its zero or left the view, or K reached kMax
    PointLimitReached, ///< stopped at options.maxPoints (see warnings)
    GainLimitReached,  ///< stopped at K > 1e250 (see warnings)
};

/**
 * The root locus of 1 + K N/D = 0, i.e. the roots of D + K N for 0 <= K (continuous: in s;
 * discrete: in z, positive powers), as branches of matched roots plus its features.
 */
struct RootLocus {
    double tsSeconds = 0.0;                  ///< 0: s-plane; > 0: z-plane
    std::vector<double> gains;               ///< K of each point, increasing from 0
    std::vector<LocusBranch> branches;       ///< deg D of them
    std::vector<std::complex<double>> poles; ///< roots of D
    std::vector<std::complex<double>> zeros; ///< roots of N
    LocusAsymptotes asymptotes;
    std::vector<LocusFeature> breakaways; ///< breakaway and break-in points, real or complex
    /// Where a branch crosses the imaginary axis (continuous) or the unit circle (discrete):
    /// the stability boundary. Each point of a conjugate pair is listed.
    std::vector<LocusFeature> crossings;
    LocusView view;
    double maxStep = 0.0; ///< the step bound used, maxStepFraction * view.span()
    RootLocusStatus status = RootLocusStatus::Complete;
    std::vector<Diagnostic> warnings;
    double work = 0.0; ///< root-finding operations counted (RootLocusOptions::maxWork)
};

/**
 * Traces the root locus of 1 + K N/D = 0 from K = 0 with adaptive gain steps. Each root r
 * inside the view may move at most delta = min(maxStep, approachFraction * distance to its
 * nearest neighbour), floored at minStepFraction * maxStep; the gain step is predicted as
 * min over roots of |D(r + delta) + K N(r + delta)| / |N(r + delta)| (to first order
 * delta / |dr/dK| with dr/dK = -N/(D' + K N'), and still right at a multiple root, where the
 * velocity is infinite), then shrunk until the new roots of D + K N, matched to the previous
 * ones (matchRoots: least total displacement), satisfy every bound. The new roots come from
 * Aberth corrections of the previous ones, or the companion eigenvalues when those do not
 * converge.
 * The features (asymptotes, breakaways, crossings) are computed algebraically for all K > 0,
 * independently of the traced range.
 *
 * @param num N, @param den D: polynomials in s (tsSeconds = 0) or in z (tsSeconds > 0),
 *        ascending coefficients (see Polynomial).
 * @throws InvalidInput "num" when N is zero or of higher degree than D (an improper loop),
 *         "den" when D is constant, "ts" when tsSeconds < 0, and the options' fields
 *         ("view", "kMax", "maxStepFraction", "approachFraction", "minStepFraction",
 *         "maxPoints") when out of range.
 */
RootLocus rootLocus(const Polynomial& num, const Polynomial& den, double tsSeconds = 0.0,
                    const RootLocusOptions& options = {});
/// The root locus of 1 + K L = 0 for the open loop L = num/den.
RootLocus rootLocus(const TransferFunction& openLoop, const RootLocusOptions& options = {});

/**
 * Asymptotes of 1 + K N/D = 0 for K -> +infinity: with n = deg D, m = deg N, the far roots
 * satisfy s^(n-m) = -K n_m/d_n, so the angles are (2q+1) 180/(n-m) degrees when n_m/d_n > 0
 * and 2q 180/(n-m) when it is negative, q = 0..n-m-1; the centroid (sum p - sum z)/(n-m) is
 * computed from the coefficients: (n_{m-1}/n_m - d_{n-1}/d_n)/(n-m).
 */
LocusAsymptotes locusAsymptotes(const Polynomial& num, const Polynomial& den);

/**
 * Breakaway and break-in points: the roots s_b of N D' - N' D (where dK/ds = 0 on
 * K(s) = -D(s)/N(s)) at which K = -D(s_b)/N(s_b) is real and positive (relative imaginary
 * part below 1e-6). Multiple open-loop poles (K = 0) are not listed. Sorted by gain.
 */
std::vector<LocusFeature> locusBreakaways(const Polynomial& num, const Polynomial& den);

/**
 * Gains K > 0 at which a root of D + K N lies on the stability boundary, with the point.
 * Continuous: s = j omega, K = -D(j omega)/N(j omega) real: with D(j omega) = De(u) +
 * j omega Do(u), u = omega^2 (same for N), the candidates are omega = 0 and the positive real
 * roots u of Do Ne - De No. Discrete: z = e^{j theta}, K real where D(z) N(1/z) is real: the
 * unit-circle roots of z^(n-m) D(z) N~(z) - D~(z) N(z) (N~, D~ the reversed polynomials), which
 * include z = 1 and z = -1. Both points of a conjugate pair are listed; sorted by gain.
 */
std::vector<LocusFeature> locusCrossings(const Polynomial& num, const Polynomial& den,
                                         double tsSeconds);

/// The locus point nearest to a clicked point, with its gain and damping.
struct LocusPick {
    std::size_t branch = 0;
    std::size_t index = 0; ///< into gains and branches[branch].roots
    double gain = 0.0;
    std::complex<double> point;
    double distance = 0.0;       ///< from the clicked point
    DampingAndFrequency damping; ///< through s = ln(z)/Ts for a discrete locus (dampingOf)
};

/// The nearest traced point to @p clicked (empty for a locus without points).
/// @throws InvalidInput "clicked" when not finite.
std::optional<LocusPick> pickLocusPoint(const RootLocus& locus, std::complex<double> clicked);

/// The relative residual |D(r) + K N(r)| / (sum |d_i||r|^i + K sum |n_i||r|^i) of a root r at
/// gain K: about the machine precision for an exact closed-loop pole.
double locusResidual(const Polynomial& num, const Polynomial& den, double gain,
                     std::complex<double> root);

} // namespace xyt
