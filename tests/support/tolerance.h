// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The one place tests compare doubles. Every call states its tolerance; the test that uses it
// says why that tolerance (round-off of the operation, digits printed in a paper, ...).

#include <QString>
#include <QTest>

#include <cmath>
#include <complex>

namespace xyt::test {

/// |actual - expected| <= absTol + relTol * |expected|.
inline bool near(double actual, double expected, double relTol, double absTol = 0.0) {
    if (!std::isfinite(actual) || !std::isfinite(expected))
        return actual == expected;
    return std::abs(actual - expected) <= absTol + relTol * std::abs(expected);
}

inline QString describe(double actual, double expected, double relTol, double absTol) {
    return QStringLiteral("actual %1, expected %2 (rel tol %3, abs tol %4, diff %5)")
        .arg(actual, 0, 'g', 17)
        .arg(expected, 0, 'g', 17)
        .arg(relTol, 0, 'g', 3)
        .arg(absTol, 0, 'g', 3)
        .arg(actual - expected, 0, 'g', 3);
}

inline bool nearComplex(std::complex<double> actual, std::complex<double> expected, double relTol,
                        double absTol = 0.0) {
    return std::abs(actual - expected) <= absTol + relTol * std::abs(expected);
}

} // namespace xyt::test

/// QVERIFY2 with a message that shows both numbers and the tolerance.
#define XYT_COMPARE_NEAR(actual, expected, relTol, absTol)                                         \
    do {                                                                                           \
        const double xytActual_ = (actual);                                                        \
        const double xytExpected_ = (expected);                                                    \
        QVERIFY2(::xyt::test::near(xytActual_, xytExpected_, (relTol), (absTol)),                  \
                 qPrintable(::xyt::test::describe(xytActual_, xytExpected_, (relTol), (absTol)))); \
    } while (false)
