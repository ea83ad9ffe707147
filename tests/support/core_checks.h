// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Checks shared by the core tests: which field an InvalidInput names, and coefficient-wise
// polynomial comparison.

#include "core/model/errors.h"
#include "core/model/polynomial.h"
#include "tests/support/tolerance.h"

#include <QString>

#include <algorithm>
#include <cmath>
#include <vector>

namespace xyt::test {

/// The largest |v[k]| (0 for none): the scale a signal's tolerance is stated against.
inline double maxAbs(const std::vector<double>& v) {
    double m = 0.0;
    for (double x : v)
        m = std::max(m, std::abs(x));
    return m;
}

/// The field of the InvalidInput that @p f throws, or "<no exception>".
template <class F> QString invalidInputField(F&& f) {
    try {
        f();
    } catch (const xyt::InvalidInput& e) {
        return QString::fromStdString(e.field());
    }
    return QStringLiteral("<no exception>");
}

/// The whole message (what()) of the InvalidInput that @p f throws, or "<no exception>".
template <class F> QString invalidInputMessage(F&& f) {
    try {
        f();
    } catch (const xyt::InvalidInput& e) {
        return QString::fromStdString(e.what());
    }
    return QStringLiteral("<no exception>");
}

/// Same degree and every coefficient within relTol of the largest expected coefficient.
inline void comparePolynomials(const Polynomial& actual, const Polynomial& expected,
                               double relTol) {
    QCOMPARE(actual.degree(), expected.degree());
    const double scale = expected.maxAbsCoefficient();
    for (int i = 0; i <= expected.degree(); ++i)
        XYT_COMPARE_NEAR(actual.coefficient(i), expected.coefficient(i), 0.0, relTol * scale);
}

} // namespace xyt::test
