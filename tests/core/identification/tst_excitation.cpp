// SPDX-License-Identifier: GPL-3.0-or-later
// Excitation signals and their files (core/identification/excitation.h). Sources: closed forms
// (square wave and chirp formulas), invariants of maximal-length sequences (period 2^n - 1,
// 2^(n-1) ones; the feedback polynomial is primitive over GF(2), checked here by exponentiation
// independently of the shift register), and round trips through the project's own readers.
#include "core/identification/delimited_reader.h"
#include "core/identification/excitation.h"
#include "core/identification/lvm_reader.h"
#include "core/model/errors.h"
#include "tests/support/core_checks.h"
#include "tests/support/tolerance.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>

namespace {

/// a * b mod p over GF(2) (bit i = coefficient of x^i), deg p = n <= 31.
std::uint64_t mulMod(std::uint64_t a, std::uint64_t b, std::uint64_t p, int n) {
    std::uint64_t r = 0;
    while (b) {
        if (b & 1u)
            r ^= a;
        b >>= 1;
        a <<= 1;
        if (a >> n & 1u)
            a ^= p;
    }
    return r;
}

std::uint64_t powMod(std::uint64_t e, std::uint64_t p, int n) {
    std::uint64_t result = 1, base = 2; // x
    while (e) {
        if (e & 1u)
            result = mulMod(result, base, p, n);
        base = mulMod(base, base, p, n);
        e >>= 1;
    }
    return result;
}

std::vector<std::uint64_t> primeFactors(std::uint64_t m) {
    std::vector<std::uint64_t> f;
    for (std::uint64_t q = 2; q * q <= m; ++q)
        if (m % q == 0) {
            f.push_back(q);
            while (m % q == 0)
                m /= q;
        }
    if (m > 1)
        f.push_back(m);
    return f;
}

xyt::ExcitationTiming timing(double ts, double duration,
                             std::optional<double> umax = std::nullopt) {
    xyt::ExcitationTiming t;
    t.tsSeconds = ts;
    t.durationSeconds = duration;
    t.umaxVolts = umax;
    return t;
}

} // namespace

class TstExcitation : public QObject {
    Q_OBJECT
private slots:
    void prbsPolynomialsArePrimitive();
    void prbsPeriodAndBalance_data();
    void prbsPeriodAndBalance();
    void prbsHoldsEachBitForTheClock();
    void squareWave();
    void chirpFollowsItsFormula();
    void limitsNameTheField();
    void filesReadBackExactly_data();
    void filesReadBackExactly();
    void writeRefusesOtherExtensions();
};

void TstExcitation::prbsPolynomialsArePrimitive() {
    // The recurrence b_m = XOR_t b_{m-t} has feedback polynomial P(x) = 1 + sum_t x^t. It is
    // primitive (maximal period) iff x^(2^n - 1) = 1 mod P and x^((2^n - 1)/q) != 1 for every
    // prime q dividing 2^n - 1.
    for (int n = 2; n <= 31; ++n) {
        std::uint64_t p = 1;
        for (int t : xyt::prbsTaps(n))
            p |= std::uint64_t(1) << t;
        QCOMPARE(int(std::bit_width(p)) - 1, n);
        const std::uint64_t order = (std::uint64_t(1) << n) - 1;
        QVERIFY2(powMod(order, p, n) == 1, qPrintable(QString("n = %1").arg(n)));
        for (std::uint64_t q : primeFactors(order))
            QVERIFY2(powMod(order / q, p, n) != 1,
                     qPrintable(QString("n = %1, q = %2").arg(n).arg(q)));
    }
}

void TstExcitation::prbsPeriodAndBalance_data() {
    QTest::addColumn<int>("n");
    for (int n : {2, 3, 5, 7, 10, 12, 16})
        QTest::newRow(qPrintable(QString("register %1").arg(n))) << n;
}

void TstExcitation::prbsPeriodAndBalance() {
    QFETCH(int, n);
    const std::size_t period = (std::size_t(1) << n) - 1;
    const std::vector<std::uint8_t> bits = xyt::prbsBits(n, 2 * period);
    for (std::size_t k = 0; k < period; ++k)
        QCOMPARE(bits[k], bits[k + period]);
    // No shorter period: the least period divides 2^n - 1, so checking (2^n - 1)/q suffices.
    for (std::uint64_t q : primeFactors(period)) {
        const std::size_t d = period / q;
        bool differs = false;
        for (std::size_t k = 0; k + d < bits.size() && !differs; ++k)
            differs = bits[k] != bits[k + d];
        QVERIFY(differs);
    }
    // Balance: 2^(n-1) ones (+1) and 2^(n-1) - 1 zeros (-1) per period: they differ by one.
    xyt::Prbs p;
    p.registerLength = n;
    p.amplitudeVolts = 2.0;
    const xyt::ExcitationSignal s = xyt::prbs(p, timing(0.01, double(period) * 0.01));
    QCOMPARE(s.u.size(), period);
    std::size_t plus = 0, minus = 0;
    for (double v : s.u)
        (v == 2.0 ? plus : minus) += (v == 2.0 || v == -2.0) ? 1 : 0;
    QCOMPARE(plus + minus, period);
    QCOMPARE(plus, std::size_t(1) << (n - 1));
    QCOMPARE(plus - minus, std::size_t(1));
}

void TstExcitation::prbsHoldsEachBitForTheClock() {
    xyt::Prbs p;
    p.registerLength = 5;
    p.clockSamples = 3;
    p.offsetVolts = 0.5;
    const xyt::ExcitationSignal s = xyt::prbs(p, timing(0.01, 0.31 * 3));
    const std::vector<std::uint8_t> bits = xyt::prbsBits(5, 31);
    QCOMPARE(s.u.size(), std::size_t(93));
    for (std::size_t k = 0; k < s.u.size(); ++k)
        QCOMPARE(s.u[k], bits[k / 3] ? 1.5 : -0.5);
}

void TstExcitation::squareWave() {
    xyt::SquareWave w;
    w.amplitudeVolts = 1.5;
    w.periodSeconds = 0.1;
    w.offsetVolts = 0.25;
    const xyt::ExcitationSignal s = xyt::squareWave(w, timing(0.01, 1.0, 2.5));
    QCOMPARE(s.u.size(), std::size_t(100)); // 1.0 / 0.01 samples
    for (std::size_t k = 0; k < s.u.size(); ++k)
        QCOMPARE(s.u[k], k % 10 < 5 ? 1.75 : -1.25); // 5 samples high, 5 low
    QCOMPARE(s.tsSeconds, 0.01);
}

void TstExcitation::chirpFollowsItsFormula() {
    xyt::Chirp c;
    c.amplitudeVolts = 2.0;
    c.f0Hz = 0.5;
    c.f1Hz = 5.0;
    const double T = 4.0, ts = 0.01;
    const xyt::ExcitationSignal s = xyt::chirp(c, timing(ts, T));
    QCOMPARE(s.u.size(), std::size_t(400));
    for (std::size_t k = 0; k < s.u.size(); k += 37) {
        const double t = double(k) * ts;
        const double expected =
            2.0 * std::sin(2.0 * std::numbers::pi * (0.5 * t + 4.5 * t * t / (2.0 * T)));
        XYT_COMPARE_NEAR(s.u[k], expected, 0.0, 1e-12); // same formula, other association
    }
}

void TstExcitation::limitsNameTheField() {
    xyt::SquareWave w;
    w.amplitudeVolts = 2.0;
    w.offsetVolts = 1.0;
    QCOMPARE(xyt::test::invalidInputMessage([&] { xyt::squareWave(w, timing(0.01, 1.0, 2.5)); }),
             QString("amplitude: |offset| + amplitude = 3 V exceeds umax = 2.5 V"));
    w.offsetVolts = 0.0;
    w.periodSeconds = 0.01;
    QCOMPARE(xyt::test::invalidInputField([&] { xyt::squareWave(w, timing(0.01, 1.0)); }),
             QString("period"));
    QCOMPARE(xyt::test::invalidInputField([&] { xyt::squareWave(w, timing(0.0, 1.0)); }),
             QString("ts"));
    QCOMPARE(xyt::test::invalidInputField([&] { xyt::squareWave(w, timing(1e-9, 1e3)); }),
             QString("duration"));
    xyt::Prbs p;
    p.registerLength = 32;
    QCOMPARE(xyt::test::invalidInputField([&] { xyt::prbs(p, timing(0.01, 1.0)); }),
             QString("register"));
    p.registerLength = 1;
    QCOMPARE(xyt::test::invalidInputField([&] { xyt::prbs(p, timing(0.01, 1.0)); }),
             QString("register"));
    p.registerLength = 8;
    p.clockSamples = 0;
    QCOMPARE(xyt::test::invalidInputField([&] { xyt::prbs(p, timing(0.01, 1.0)); }),
             QString("clock"));
    xyt::Chirp c;
    c.f1Hz = 60.0; // above 1 / (2 x 0.01) = 50 Hz
    QCOMPARE(xyt::test::invalidInputField([&] { xyt::chirp(c, timing(0.01, 1.0)); }),
             QString("f1"));
    c.f1Hz = 1.0;
    c.amplitudeVolts = -1.0;
    QCOMPARE(xyt::test::invalidInputField([&] { xyt::chirp(c, timing(0.01, 1.0)); }),
             QString("amplitude"));
}

void TstExcitation::filesReadBackExactly_data() {
    QTest::addColumn<QString>("extension");
    QTest::newRow("csv") << "csv";
    QTest::newRow("lvm") << "lvm";
}

void TstExcitation::filesReadBackExactly() {
    QFETCH(QString, extension);
    xyt::Chirp c; // irrational samples: %.17g must bring every bit back
    c.amplitudeVolts = 2.5;
    c.f0Hz = 0.1;
    c.f1Hz = 3.0;
    const xyt::ExcitationSignal s = xyt::chirp(c, timing(0.01, 2.0));
    QTemporaryDir dir;
    const std::string path = dir.filePath("excite." + extension).toStdString();
    xyt::writeExcitation(path, s);
    xyt::ExperimentTable t;
    if (extension == "csv") {
        t = xyt::readDelimitedFile(path).table;
        QCOMPARE(t.names, (std::vector<std::string>{"t", "u"}));
        QVERIFY(!t.sampleTimeSeconds);
    } else {
        t = xyt::readLvmFile(path).table;
        QCOMPARE(t.names, (std::vector<std::string>{"X_Value", "u"}));
        QVERIFY(t.sampleTimeSeconds);
        QCOMPARE(*t.sampleTimeSeconds, 0.01);
        QVERIFY(t.warnings.empty());
    }
    QCOMPARE(t.columns[1], s.u);
    for (std::size_t k = 0; k < s.u.size(); ++k)
        QCOMPARE(t.columns[0][k], double(k) * 0.01);
    // Written atomically: no temporary file is left next to it.
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files).size(), qsizetype(1));
}

void TstExcitation::writeRefusesOtherExtensions() {
    QTemporaryDir dir;
    xyt::SquareWave w;
    const xyt::ExcitationSignal s = xyt::squareWave(w, timing(0.01, 1.0));
    QCOMPARE(xyt::test::invalidInputField(
                 [&] { xyt::writeExcitation(dir.filePath("u.txt").toStdString(), s); }),
             QString("output"));
    QVERIFY(!QFile::exists(dir.filePath("u.txt")));
}

QTEST_APPLESS_MAIN(TstExcitation)
#include "tst_excitation.moc"
