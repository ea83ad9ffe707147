// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Shared by the libFuzzer harnesses: a decoder that turns the fuzz bytes into bounded design
// parameters, and checks that abort() (so libFuzzer and the replay test report a crash) when a
// result that the code reported as valid holds NaN or infinity.

#include "core/model/polynomial.h"
#include "core/model/transfer_function.h"

#include <cmath>
#include <complex>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <iterator>
#include <limits>
#include <vector>

namespace xyt::fuzz {

/// The values that break naive code: 0, -0, NaN, +-inf, the extremes of double, a denormal, and
/// a few ordinary ones. A harness picks one by a byte of its input, so the order is the encoding
/// of the seeds (tests/fuzz/make_seeds.py for FuzzInput::number, byte values 0-15).
inline constexpr double kSpecialValues[] = {0.0,
                                            -0.0,
                                            std::numeric_limits<double>::quiet_NaN(),
                                            std::numeric_limits<double>::infinity(),
                                            -std::numeric_limits<double>::infinity(),
                                            std::numeric_limits<double>::max(),
                                            -std::numeric_limits<double>::max(),
                                            std::numeric_limits<double>::min(),
                                            std::numeric_limits<double>::denorm_min(),
                                            1.0,
                                            -1.0,
                                            1e-300,
                                            1e300,
                                            0.5,
                                            2.0,
                                            -2.0};

/// Reads the fuzz bytes front to back; once they run out every read returns a benign default,
/// so short inputs still reach the deep code paths.
class FuzzInput {
public:
    FuzzInput(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

    std::uint8_t byte(std::uint8_t fallback = 0) { return pos_ < size_ ? data_[pos_++] : fallback; }
    /// Two bytes, little-endian (read in sequence: the operands of | are unsequenced).
    unsigned word() {
        const unsigned low = byte();
        const unsigned high = byte();
        return low | (high << 8);
    }
    /// A whole number in [lo, hi].
    int integer(int lo, int hi) {
        const unsigned raw = hi - lo >= 256 ? word() : byte();
        return lo + static_cast<int>(raw % static_cast<unsigned>(hi - lo + 1));
    }
    /// A double over many decades with both signs, plus (one byte value in 16) the values that
    /// break naive code: 0, -0, NaN, +-inf, the extremes of double, denormals.
    double number(double fallback = 1.0) {
        if (pos_ >= size_)
            return fallback;
        const std::uint8_t kind = byte();
        if (kind < std::size(kSpecialValues))
            return kSpecialValues[kind];
        // |value| = m 10^e, m in [1, 10), e in -12 .. 12 (tests/fuzz/make_seeds.py encodes).
        const int exponent = static_cast<int>(kind % 25) - 12;
        const double mantissa = 1.0 + 9.0 * static_cast<double>(word()) / 65536.0;
        const double sign = kind & 0x80 ? -1.0 : 1.0;
        return sign * mantissa * std::pow(10.0, exponent);
    }
    /// A "reasonable" positive number in [lo, hi] (for sizes that bound the run time).
    double within(double lo, double hi) {
        const double f = static_cast<double>(word()) / 65535.0;
        return lo + f * (hi - lo);
    }
    std::vector<double> coefficients(int minCount, int maxCount) {
        const int n = integer(minCount, maxCount);
        std::vector<double> c(static_cast<std::size_t>(n));
        for (double& v : c)
            v = number();
        return c;
    }

private:
    const std::uint8_t* data_;
    std::size_t size_;
    std::size_t pos_ = 0;
};

[[noreturn]] inline void fail(const char* what, const char* file, int line) {
    std::fprintf(stderr, "%s:%d: non-finite value in a valid result: %s\n", file, line, what);
    std::abort();
}

inline bool finite(double v) {
    return std::isfinite(v);
}
inline bool finite(std::complex<double> v) {
    return std::isfinite(v.real()) && std::isfinite(v.imag());
}
inline bool finite(const Polynomial& p) {
    for (double c : p.ascending())
        if (!std::isfinite(c))
            return false;
    return true;
}
inline bool finite(const TransferFunction& tf) {
    return finite(tf.num()) && finite(tf.den());
}
template <class T> bool finite(const std::vector<T>& values) {
    for (const T& v : values)
        if (!finite(v))
            return false;
    return true;
}

} // namespace xyt::fuzz

/// Aborts when @p value (a double, complex, Polynomial, TransferFunction or a vector of them)
/// holds NaN or infinity.
#define XYT_FUZZ_REQUIRE_FINITE(value)                                                             \
    do {                                                                                           \
        if (!::xyt::fuzz::finite(value))                                                           \
            ::xyt::fuzz::fail(#value, __FILE__, __LINE__);                                         \
    } while (false)
/// Aborts when an invariant of a valid result does not hold.
#define XYT_FUZZ_REQUIRE(condition)                                                                \
    do {                                                                                           \
        if (!(condition)) {                                                                        \
            std::fprintf(stderr, "%s:%d: invariant failed: %s\n", __FILE__, __LINE__, #condition); \
            std::abort();                                                                          \
        }                                                                                          \
    } while (false)

namespace xyt::fuzz {

/// Aborts unless the message of a refusal is one non-empty line (the CLI prints it as its
/// single stderr line).
inline void requireOneLine(const std::exception& e) {
    const char* message = e.what();
    XYT_FUZZ_REQUIRE(message[0] != '\0');
    for (const char* c = message; *c; ++c)
        XYT_FUZZ_REQUIRE(*c != '\n' && *c != '\r');
}

} // namespace xyt::fuzz
