// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/model/polynomial.h"

#include <complex>
#include <vector>

namespace xyt {

/**
 * A SISO transfer function N/D, continuous in s (`tsSeconds() == 0`) or discrete in z with
 * sample time `tsSeconds() > 0`.
 *
 * Both polynomials are in the transform variable with ascending coefficient order (see
 * Polynomial): for discrete systems that is z, in positive powers, so that poles and zeros are
 * the polynomials' roots. `fromZInverse` and `numZInverse()/denZInverse()` convert to and from the
 * z^-1 form the ARX models of the second paper are written in.
 *
 * Normalized at construction: the denominator is made monic (both polynomials divided by its
 * leading coefficient). No pole-zero cancellation is done.
 */
class TransferFunction {
public:
    using Complex = std::complex<double>;

    /// The unit gain, continuous.
    TransferFunction();
    /// @throws InvalidInput "den" when the denominator is zero, "ts" when tsSeconds is negative
    ///         or not finite.
    TransferFunction(const Polynomial& num, const Polynomial& den, double tsSeconds = 0.0);
    /// Continuous N(s)/D(s) with coefficients highest power first.
    static TransferFunction fromDescending(const std::vector<double>& num,
                                           const std::vector<double>& den);
    /**
     * Discrete N(z^-1)/D(z^-1) given in ascending powers of z^-1 (as the ARX models are typed).
     * @throws InvalidInput "den" unless D(0), the coefficient of z^0, is nonzero (causality).
     */
    static TransferFunction fromZInverse(const Polynomial& numZInv, const Polynomial& denZInv,
                                         double tsSeconds);
    static TransferFunction gain(double k, double tsSeconds = 0.0);

    const Polynomial& num() const { return num_; }
    const Polynomial& den() const { return den_; }
    double tsSeconds() const { return ts_; }
    bool isDiscrete() const { return ts_ > 0.0; }

    /// The numerator and denominator in ascending powers of z^-1 (both divided by z^n, n the
    /// denominator degree). @throws InvalidInput for continuous or improper systems.
    Polynomial numZInverse() const;
    Polynomial denZInverse() const;

    std::vector<Complex> poles() const;
    std::vector<Complex> zeros() const;
    /// Value at s = 0 (continuous) or z = 1 (discrete); +-infinity for a pole there.
    double dcGain() const;
    Complex operator()(Complex x) const;
    /// G(j omega) or G(e^{j omega Ts}).
    Complex frequencyResponse(double omegaRadPerSec) const;
    int relativeDegree() const { return den_.degree() - num_.degree(); }
    bool isProper() const { return relativeDegree() >= 0; }
    bool isStrictlyProper() const { return relativeDegree() > 0; }
    /// All poles in the open left half plane (continuous) or inside the unit circle (discrete).
    bool isStable() const;

    friend bool operator==(const TransferFunction& a, const TransferFunction& b) {
        return a.num_ == b.num_ && a.den_ == b.den_ && a.ts_ == b.ts_;
    }

private:
    Polynomial num_;
    Polynomial den_;
    double ts_ = 0.0;
};

/// a * b. @throws InvalidInput "ts" when the sample times differ.
TransferFunction series(const TransferFunction& a, const TransferFunction& b);
/// a + b.
TransferFunction parallel(const TransferFunction& a, const TransferFunction& b);
/// g / (1 - sign * g * h): negative feedback by default.
TransferFunction feedback(const TransferFunction& g, const TransferFunction& h = TransferFunction(),
                          int sign = -1);

/// True when the root is in the stable region for the given sample time.
bool isStableRoot(std::complex<double> root, double tsSeconds);

} // namespace xyt
