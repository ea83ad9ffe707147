// SPDX-License-Identifier: GPL-3.0-or-later
// The G-code reader (core/contour/gcode_reader.h): arc geometry against hand-computed centres
// and points (RS274/NGC: I/J relative to the start, R > 0 the short arc, R < 0 the long one,
// G2 clockwise, G3 counter-clockwise), unit and mode switches, modal words, comments, the
// warnings, a table of bad programs naming their line, column and word, and the examples of
// resources/examples/. Tolerances: 1e-12 mm for points computed by a few trigonometric
// operations on values of order 10 mm (a few ulps).
#include "core/contour/gcode_reader.h"
#include "core/model/errors.h"
#include "tests/support/core_checks.h"
#include "tests/support/tolerance.h"

#include <QDir>
#include <QFile>
#include <QTest>

#include <cmath>
#include <numbers>
#include <string>

using xyt::GcodeProgram;
using xyt::Point2;
using xyt::readGcode;

namespace {
constexpr double kPi = std::numbers::pi;
constexpr double kTol = 1e-12;

void comparePoint(Point2 actual, Point2 expected, double tol = kTol) {
    XYT_COMPARE_NEAR(actual.x, expected.x, 0.0, tol);
    XYT_COMPARE_NEAR(actual.y, expected.y, 0.0, tol);
}

/// The last segment of a program, which must be an arc (a copy: the program is often a
/// temporary).
xyt::PathSegment arcOf(const GcodeProgram& p) {
    if (!p.path.segments().back().isArc()) {
        QTest::qFail("expected the program to end with an arc", __FILE__, __LINE__);
        return xyt::PathSegment::line({0.0, 0.0}, {1.0, 0.0});
    }
    return p.path.segments().back();
}

std::string readExample(const QString& name) {
    QFile f(QStringLiteral(XYT_SOURCE_DIR "/resources/examples/") + name);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    return f.readAll().toStdString();
}
} // namespace

class TstGcodeReader : public QObject {
    Q_OBJECT
private slots:
    void arcFromIjClockwise();
    void arcFromIjCounterClockwise();
    void arcFromPositiveR();
    void arcFromNegativeR();
    void fullCircle();
    void inchAndMillimetre();
    void incrementalAndModal();
    void commentsBlockNumbersAndWarnings();
    void programEndStopsReadingSilently_data();
    void programEndStopsReadingSilently();
    void arcEndWithinTolerance();
    void badPrograms_data();
    void badPrograms();
    void programLimits();
    void lineEndings_data();
    void lineEndings();
    void zeroBeforeAnotherWordIsNotHexadecimal();
    void examples_data();
    void examples();
    void everyExampleIsTested();
};

void TstGcodeReader::arcFromIjClockwise() {
    // From (10, 0) about the origin (I = -10, J = 0) clockwise to (0, -10): a quarter turn,
    // sweep -pi/2; the middle of the arc is at angle -45 degrees: (5 sqrt 2, -5 sqrt 2).
    const GcodeProgram p = readGcode("G0 X10 Y0\nG2 X0 Y-10 I-10 J0 F600\n");
    const auto a = arcOf(p);
    comparePoint(a.centre(), {0.0, 0.0});
    XYT_COMPARE_NEAR(a.radius(), 10.0, 0.0, kTol);
    XYT_COMPARE_NEAR(a.sweep(), -kPi / 2.0, 0.0, kTol);
    XYT_COMPARE_NEAR(a.length(), 5.0 * kPi, 0.0, kTol);
    comparePoint(a.pointAt(a.length() / 2.0), {5.0 * std::sqrt(2.0), -5.0 * std::sqrt(2.0)});
    comparePoint(a.end(), {0.0, -10.0});
    // Clockwise about the centre: the tangent at (10, 0) points down.
    comparePoint(a.tangentAt(0.0), {0.0, -1.0});
    // F600 mm/min = 10 mm/s; the G0 runs at the default rapid 3000 mm/min = 50 mm/s.
    XYT_COMPARE_NEAR(p.segments[1].feedMmPerSec, 10.0, 1e-15, 0.0);
    QVERIFY(p.segments[0].rapid);
    QVERIFY(!p.segments[1].rapid);
    XYT_COMPARE_NEAR(p.segments[0].feedMmPerSec, 50.0, 1e-15, 0.0);
    QCOMPARE(p.segments[1].line, std::size_t(2));
}

void TstGcodeReader::arcFromIjCounterClockwise() {
    // G3 from (10, 0) about the origin to (0, 10): sweep +pi/2, middle at 45 degrees.
    const GcodeProgram p = readGcode("G0 X10 Y0\nG3 X0 Y10 I-10 J0 F600\n");
    const auto a = arcOf(p);
    XYT_COMPARE_NEAR(a.sweep(), kPi / 2.0, 0.0, kTol);
    comparePoint(a.pointAt(a.length() / 2.0), {5.0 * std::sqrt(2.0), 5.0 * std::sqrt(2.0)});
    comparePoint(a.tangentAt(0.0), {0.0, 1.0});
    XYT_COMPARE_NEAR(a.curvature(), 0.1, 0.0, kTol);
}

void TstGcodeReader::arcFromPositiveR() {
    // (0,0) -> (10,10), R 10: chord 10 sqrt 2, the centre sqrt(100 - 50) = 5 sqrt 2 from the
    // chord's middle (5, 5) along its normal. G2 (short arc clockwise): right of the chord,
    // (10, 0); from angle 180 to 90 degrees, a quarter turn clockwise.
    const auto a = arcOf(readGcode("G2 X10 Y10 R10 F100\n"));
    comparePoint(a.centre(), {10.0, 0.0});
    XYT_COMPARE_NEAR(a.sweep(), -kPi / 2.0, 0.0, kTol);
    // G3 with R 10: left of the chord, (0, 10); from -90 to 0 degrees counter-clockwise.
    const auto b = arcOf(readGcode("G3 X10 Y10 R10 F100\n"));
    comparePoint(b.centre(), {0.0, 10.0});
    XYT_COMPARE_NEAR(b.sweep(), kPi / 2.0, 0.0, kTol);
    // A half circle (chord = 2 R): the centre is the chord's middle.
    const auto c = arcOf(readGcode("G2 X10 Y0 R5 F100\n"));
    comparePoint(c.centre(), {5.0, 0.0});
    XYT_COMPARE_NEAR(c.sweep(), -kPi, 0.0, kTol);
    comparePoint(c.pointAt(c.length() / 2.0), {5.0, 5.0}); // clockwise from (0,0) goes over the top
}

void TstGcodeReader::arcFromNegativeR() {
    // R -10: the long arc, centre on the other side. G2: (0, 10), from -90 degrees clockwise
    // to 0 degrees, three quarters of a turn: sweep -3 pi/2, length 15 pi.
    const auto a = arcOf(readGcode("G2 X10 Y10 R-10 F100\n"));
    comparePoint(a.centre(), {0.0, 10.0});
    XYT_COMPARE_NEAR(a.sweep(), -1.5 * kPi, 0.0, kTol);
    XYT_COMPARE_NEAR(a.length(), 15.0 * kPi, 0.0, 1e-11);
    // Its middle is at -90 - 135 = -225 degrees = 135 degrees about (0, 10).
    comparePoint(a.pointAt(a.length() / 2.0),
                 {10.0 * std::cos(0.75 * kPi), 10.0 + 10.0 * std::sin(0.75 * kPi)});
    // G3 R-10: centre (10, 0), from 180 degrees counter-clockwise to 90: sweep +3 pi/2.
    const auto b = arcOf(readGcode("G3 X10 Y10 R-10 F100\n"));
    comparePoint(b.centre(), {10.0, 0.0});
    XYT_COMPARE_NEAR(b.sweep(), 1.5 * kPi, 0.0, kTol);
}

void TstGcodeReader::fullCircle() {
    // The circle of Braga et al. (resources/examples/circle_25mm.nc): end = start with I/J.
    const GcodeProgram p = readGcode("G0 X0 Y25\nG2 I0 J-25 F90\n");
    const auto a = arcOf(p);
    comparePoint(a.centre(), {0.0, 0.0});
    XYT_COMPARE_NEAR(a.sweep(), -2.0 * kPi, 0.0, 0.0);
    XYT_COMPARE_NEAR(a.length(), 50.0 * kPi, 1e-15, 0.0);
    QCOMPARE(a.end(), a.start());
    // A quarter of the way round clockwise from the top: (25, 0).
    comparePoint(a.pointAt(a.length() / 4.0), {25.0, 0.0});
    QVERIFY(p.isSingleFullCircle());
    QCOMPARE(p.fullCircleSegment(), std::size_t(1));
    // With X/Y given and equal to the start, and counter-clockwise: the same, sweep +2 pi.
    const auto b = arcOf(readGcode("G0 X0 Y25\nG3 X0 Y25 I0 J-25 F90\n"));
    XYT_COMPARE_NEAR(b.sweep(), 2.0 * kPi, 0.0, 0.0);
    // Two feed moves: no longer a single circle.
    QVERIFY(!readGcode("G0 X0 Y25\nG2 I0 J-25 F90\nG1 X1\n").isSingleFullCircle());
}

void TstGcodeReader::inchAndMillimetre() {
    // G20: X1 Y2 are 25.4 and 50.8 mm; F10 in/min = 254 mm/min = 4.2333 mm/s. G21 switches
    // back: X3 is 3 mm. F stays 10 but is now read in mm/min.
    const GcodeProgram p = readGcode("G20 G1 X1 Y2 F10\nG21 X3\n");
    QCOMPARE(p.path.size(), std::size_t(2));
    comparePoint(p.path.segments()[0].end(), {25.4, 50.8});
    XYT_COMPARE_NEAR(p.segments[0].feedMmPerSec, 254.0 / 60.0, 1e-15, 0.0);
    comparePoint(p.path.segments()[1].end(), {3.0, 50.8});
    XYT_COMPARE_NEAR(p.segments[1].feedMmPerSec, 10.0 / 60.0, 1e-15, 0.0);
    // I/J are inch too: G20 arc from (1 in, 0) about the origin.
    const auto a = arcOf(readGcode("G20\nG0 X1 Y0\nG3 X0 Y1 I-1 J0 F5\n"));
    XYT_COMPARE_NEAR(a.radius(), 25.4, 0.0, kTol);
}

void TstGcodeReader::incrementalAndModal() {
    // G91: each X/Y adds to the position; the modal G0 continues on the lines with only X/Y.
    const GcodeProgram p = readGcode("G91 G0 X1 Y1\nX1\nY-2\nG90 G1 X0 Y0 F60\n");
    QCOMPARE(p.path.size(), std::size_t(4));
    comparePoint(p.path.segments()[0].end(), {1.0, 1.0});
    comparePoint(p.path.segments()[1].end(), {2.0, 1.0});
    comparePoint(p.path.segments()[2].end(), {2.0, -1.0});
    comparePoint(p.path.segments()[3].end(), {0.0, 0.0});
    QVERIFY(p.segments[2].rapid);
    QVERIFY(!p.segments[3].rapid);
    // A modal arc: the second line continues G3 with its own I/J.
    const GcodeProgram q = readGcode("G0 X10 Y0\nG3 X0 Y10 I-10 J0 F60\nX-10 Y0 I0 J-10\n");
    QCOMPARE(q.path.size(), std::size_t(3));
    comparePoint(q.path.segments()[2].centre(), {0.0, 0.0});
    XYT_COMPARE_NEAR(q.path.segments()[2].sweep(), kPi / 2.0, 0.0, kTol);
    // A move to the current position adds no segment.
    QCOMPARE(readGcode("G1 X0 Y0 F60\nX1\n").path.size(), std::size_t(1));
}

void TstGcodeReader::commentsBlockNumbersAndWarnings() {
    const GcodeProgram p =
        readGcode("%\n(header only)\nn10 g1 x 5 (inline) y1 f60 ; Y9 is a comment\n"
                  "N20 G0 X1 Z5 M3 S1000\n%\n");
    QCOMPARE(p.path.size(), std::size_t(2));
    comparePoint(p.path.segments()[0].end(), {5.0, 1.0});
    QCOMPARE(p.segments[0].blockNumber, 10L);
    QCOMPARE(p.segments[0].line, std::size_t(3));
    QCOMPARE(p.segments[1].blockNumber, 20L);
    QCOMPARE(p.lines, std::size_t(5));
    // Z, M3 and S each warn, naming line 4.
    QCOMPARE(p.warnings.size(), std::size_t(3));
    for (const auto& w : p.warnings)
        QVERIFY2(w.text.rfind("line 4: ", 0) == 0, w.text.c_str());
    QVERIFY(p.warnings[0].text.find("Z5") != std::string::npos);
    // Each warning is coded "line %1: %2", its reason coded in turn (the workbench translates
    // both), the English unchanged.
    QCOMPARE(p.warnings[0].code, std::string("contour_gcode_line_warning"));
    QCOMPARE(p.warnings[0].args.at(0).text, std::string("4"));
    QCOMPARE(p.warnings[0].args.at(1).code, std::string("contour_gcode_ignored_z"));
    QCOMPARE(p.warnings[0].args.at(1).args.at(0).text, std::string("Z5"));
    QCOMPARE(p.warnings[0].text, std::string("line 4: Z5 ignored (the path is XY only)"));
    // The warnings are bounded: 150 Z words keep 100 and count the rest.
    std::string many = "G0 X1\n";
    for (int i = 0; i < 150; ++i)
        many += "Z1\n";
    const auto bounded = readGcode(many).warnings;
    QCOMPARE(bounded.size(), xyt::kMaxGcodeWarnings + 1);
    QCOMPARE(bounded.back(), std::string("... and 50 more warnings"));
    QCOMPARE(bounded.back().code, std::string("contour_gcode_more_warnings"));
    // A refusal names the line as its field and gives its reason coded, the column an argument.
    try {
        readGcode("G1 X1 F60\nG1 X2 Q7\n");
        QFAIL("an unknown word was accepted");
    } catch (const xyt::InvalidInput& e) {
        QCOMPARE(e.field(), std::string("line 2"));
        QCOMPARE(e.reasonDiagnostic().code, std::string("contour_gcode_unknown_word"));
        QCOMPARE(e.reasonDiagnostic().args.at(0).text, std::string("Q7"));
        QCOMPARE(e.reasonDiagnostic().args.at(1).text, std::string("7"));
        QCOMPARE(e.reason(), std::string("unknown word Q7 at column 7"));
    }
}

void TstGcodeReader::programEndStopsReadingSilently_data() {
    // RS274/NGC: M2 and M30 end the program; a block's motion runs before its M code, and a
    // controller runs nothing after the end.
    QTest::addColumn<QString>("program");
    QTest::addColumn<int>("segments");
    QTest::addColumn<int>("lines");
    QTest::addColumn<QString>("warning"); // empty: none
    QTest::newRow("M30 last") << "G1 X5 F60\nM30\n" << 1 << 2 << "";
    QTest::newRow("M2 last") << "G1 X5 F60\nM2\n" << 1 << 2 << "";
    QTest::newRow("M02 then delimiter and blanks") << "%\nG1 X5 F60\nM02\n%\n\n  \n"
                                                   << 1 << 3 << "";
    QTest::newRow("motion on the end's line") << "G1 X5 F60\nG1 Y5 M30\n" << 2 << 2 << "";
    QTest::newRow("moves and bad words after M30 are not read")
        << "G1 X5 F60\nM30\nG1 Y5\nG5 Q?\n"
        << 1 << 2 << "line 2: the lines after the program end M30 are not read";
}

void TstGcodeReader::programEndStopsReadingSilently() {
    QFETCH(QString, program);
    QFETCH(int, segments);
    QFETCH(int, lines);
    QFETCH(QString, warning);
    const GcodeProgram p = readGcode(program.toStdString());
    QCOMPARE(p.path.size(), std::size_t(segments));
    QCOMPARE(p.lines, std::size_t(lines));
    if (warning.isEmpty()) {
        QVERIFY2(p.warnings.empty(), p.warnings.empty() ? "" : p.warnings.front().text.c_str());
    } else {
        QCOMPARE(p.warnings.size(), std::size_t(1));
        QCOMPARE(QString::fromStdString(p.warnings.front()), warning);
    }
}

void TstGcodeReader::arcEndWithinTolerance() {
    // The tolerance is max(0.002 mm, 1e-6 R) in mm: an end 0.0015 mm off the circle passes,
    // 0.0025 mm does not (line 2 named).
    QCOMPARE(readGcode("G0 X10 Y0\nG3 X0 Y10.0015 I-10 J0 F60\n").path.size(), std::size_t(2));
    try {
        readGcode("G0 X10 Y0\nG3 X0 Y10.0025 I-10 J0 F60\n");
        QFAIL("an end 0.0025 mm off the circle was accepted");
    } catch (const xyt::InvalidInput& e) {
        QCOMPARE(e.field(), std::string("line 2"));
        QVERIFY2(e.reason().find("off the circle") != std::string::npos, e.what());
    }
    XYT_COMPARE_NEAR(xyt::arcEndTolerance(10.0, false), 0.002, 0.0, 0.0);
    XYT_COMPARE_NEAR(xyt::arcEndTolerance(1e4, false), 0.01, 1e-15, 0.0);
    XYT_COMPARE_NEAR(xyt::arcEndTolerance(10.0, true), 0.0002 * 25.4, 1e-15, 0.0);
}

void TstGcodeReader::badPrograms_data() {
    QTest::addColumn<QString>("program");
    QTest::addColumn<QString>("field");
    QTest::addColumn<QString>("reason"); // a part of the reason
    QTest::newRow("unknown G") << "G5 X1"
                               << "line 1"
                               << "unknown word G5 at column 1";
    QTest::newRow("unknown letter") << "G0 X0\nG1 X1 Q3 F10"
                                    << "line 2"
                                    << "unknown word Q3 at column 7";
    QTest::newRow("fractional G") << "G0.5 X1"
                                  << "line 1"
                                  << "unknown word G0.5 at column 1";
    QTest::newRow("exponent") << "G1 X1e5 F100"
                              << "line 1"
                              << "unknown word E5 at column 6";
    QTest::newRow("unknown M") << "G0 X1\nM98"
                               << "line 2"
                               << "unknown word M98 at column 1";
    QTest::newRow("other plane") << "G18 G0 X1"
                                 << "line 1"
                                 << "only the XY plane (G17) is supported, not G18 at column 1";
    QTest::newRow("no feed") << "G1 X1"
                             << "line 1"
                             << "no feed rate";
    QTest::newRow("zero feed") << "G1 X1 F0"
                               << "line 1"
                               << "feed F0 at column 7 must be greater than zero";
    QTest::newRow("no motion mode") << "X1"
                                    << "line 1"
                                    << "X1 at column 1 has no motion mode";
    QTest::newRow("IJ without arc") << "G1 I5 F100"
                                    << "line 1"
                                    << "I5 at column 4 needs an arc (G2 or G3)";
    QTest::newRow("arc without centre") << "G2 X1 F100"
                                        << "line 1"
                                        << "arc G2 at column 1 needs I/J";
    QTest::newRow("R and IJ") << "G2 X1 Y1 I1 R1 F100"
                              << "line 1"
                              << "has both R and I/J";
    QTest::newRow("end off circle")
        << "G0 X0 Y0\nG2 X10 Y0 I4 J0 F100"
        << "line 2"
        << "arc G2 at column 1: the end point is off the circle (radius 6 mm at the end, 4 mm";
    QTest::newRow("modal arc off circle") << "G0 X0 Y0\nG3 X8 Y0 I4 F100\nX0 I-3"
                                          << "line 3"
                                          << "arc G3 at column 1: the end point is off the circle";
    QTest::newRow("R too small") << "G0 X0\nG2 X10 Y0 R4 F100"
                                 << "line 2"
                                 << "R4 at column 11 is smaller than half the chord";
    QTest::newRow("full circle by R") << "G2 R5 F100"
                                      << "line 1"
                                      << "a full circle needs I and J";
    QTest::newRow("zero radius") << "G2 I0 J0 F10"
                                 << "line 1"
                                 << "has a zero radius";
    QTest::newRow("word twice") << "G1 X1 X2 F100"
                                << "line 1"
                                << "word X is given twice (X2 at column 7)";
    // A number the tokenizer stops reading early: said to be malformed, not a word given twice
    // ("X0x10" used to read as X0 and X10) or a stray point.
    QTest::newRow("hexadecimal")
        << "G1 X0x10 F100"
        << "line 1"
        << "malformed number X0x10 at column 4: G-code numbers are decimal (no 0x prefix)";
    QTest::newRow("hexadecimal upper") << "G1 X-0X1f F100"
                                       << "line 1"
                                       << "malformed number X-0X1f at column 4";
    QTest::newRow("two points")
        << "G1 X1.2.3 F100"
        << "line 1"
        << "malformed number X1.2.3 at column 4: more than one decimal point";
    QTest::newRow("two points CR") << "G0 X0\rG1 Y.5. F100\r"
                                   << "line 2"
                                   << "malformed number Y.5. at column 4";
    QTest::newRow("two motions") << "G0 G1 X1 F100"
                                 << "line 1"
                                 << "two motion codes G0 and G1 on one line";
    QTest::newRow("two units") << "G20 G21"
                               << "line 1"
                               << "two unit codes";
    QTest::newRow("no number") << "G1 X (c)"
                               << "line 1"
                               << "word X at column 4 has no number";
    QTest::newRow("sign only") << "G1 X-"
                               << "line 1"
                               << "word X at column 4 has no number";
    QTest::newRow("open comment") << "G1 X1 (open"
                                  << "line 1"
                                  << "comment opened at column 7 is not closed";
    QTest::newRow("stray character") << "G1 X1 F100 #"
                                     << "line 1"
                                     << "unexpected character '#' at column 12";
    QTest::newRow("control character") << "G1 X1 F100 \x01"
                                       << "line 1"
                                       << "unexpected character '\\x01' at column 12";
    QTest::newRow("beyond 1e9 mm") << "G0 X2000000000"
                                   << "line 1"
                                   << "X2000000000 at column 4 is beyond 1e+09 mm";
    QTest::newRow("inch beyond") << "G20 G0 X50000000"
                                 << "line 1"
                                 << "is beyond 1e+09 mm";
    QTest::newRow("block number") << "N-5 G0 X1"
                                  << "line 1"
                                  << "block number N-5 at column 1";
    QTest::newRow("no motion") << "G21 G90\n(nothing)\n"
                               << "program"
                               << "has no XY motion";
    QTest::newRow("empty") << ""
                           << "program"
                           << "has no XY motion";
}

void TstGcodeReader::badPrograms() {
    QFETCH(QString, program);
    QFETCH(QString, field);
    QFETCH(QString, reason);
    try {
        readGcode(program.toStdString());
        QFAIL("the program was accepted");
    } catch (const xyt::InvalidInput& e) {
        QCOMPARE(QString::fromStdString(e.field()), field);
        QVERIFY2(QString::fromStdString(e.reason()).contains(reason), e.what());
        QVERIFY(!std::string(e.what()).empty());
        QVERIFY(std::string(e.what()).find('\n') == std::string::npos);
    }
}

void TstGcodeReader::programLimits() {
    // kMaxGcodeLines lines are read; one more is refused before any line is parsed.
    std::string lines(xyt::kMaxGcodeLines - 1, '\n');
    lines += "G0 X1";
    QCOMPARE(readGcode(lines).segments[0].line, xyt::kMaxGcodeLines);
    lines = std::string(xyt::kMaxGcodeLines, '\n') + "G0 X1";
    try {
        readGcode(lines);
        QFAIL("a program over the line limit was accepted");
    } catch (const xyt::InvalidInput& e) {
        QCOMPARE(e.field(), std::string("program"));
        QVERIFY2(e.reason().find("1000000 lines") != std::string::npos, e.what());
    }
    QVERIFY_THROWS_EXCEPTION(xyt::InvalidInput,
                             readGcode(std::string(xyt::kMaxGcodeBytes + 1, ' ')));
    xyt::GcodeReadOptions options;
    options.rapidFeedMmPerMin = 0.0;
    QVERIFY_THROWS_EXCEPTION(xyt::InvalidInput, readGcode("G0 X1", options));
    // The planner's range of feeds (feed_profile.h) in mm/min: 60 x [1e-100, 1e100].
    for (const double rate : {1e300, 1e-300, 5e-324, 59e-100, 61e100}) {
        options.rapidFeedMmPerMin = rate;
        QCOMPARE(xyt::test::invalidInputField([&] { readGcode("G0 X1", options); }),
                 QStringLiteral("rapid_feed"));
    }
    options.rapidFeedMmPerMin = 1e-98;
    QCOMPARE(readGcode("G0 X1", options).segments[0].feedMmPerSec, 1e-98 / 60.0);
}

void TstGcodeReader::lineEndings_data() {
    QTest::addColumn<QString>("separator");
    QTest::newRow("LF") << "\n";
    QTest::newRow("CR LF") << "\r\n";
    QTest::newRow("CR (classic Mac OS)") << "\r";
}

void TstGcodeReader::lineEndings() {
    QFETCH(QString, separator);
    const std::string sep = separator.toStdString();
    // The same program under each line ending: the same path, the same line numbers (a CR-only
    // file used to be one line: "two motion codes G1 and G1 on one line").
    const std::string text =
        "G21 G90" + sep + "G1 X10 F600" + sep + sep + "G1 Y10" + sep + "G0 X0 Y0" + sep;
    const auto p = readGcode(text);
    QCOMPARE(p.path.size(), std::size_t(3));
    QCOMPARE(p.lines, std::size_t(5));
    QCOMPARE(p.segments[0].line, std::size_t(2));
    QCOMPARE(p.segments[1].line, std::size_t(4));
    QCOMPARE(p.segments[2].line, std::size_t(5));
    comparePoint(p.path.segments()[1].end(), {10.0, 10.0});
    // An error names the line it is on.
    try {
        readGcode("G0 X1" + sep + "G1 X2 F100" + sep + "G5" + sep);
        QFAIL("G5 was accepted");
    } catch (const xyt::InvalidInput& e) {
        QCOMPARE(e.field(), std::string("line 3"));
    }
    // The line limit counts lines, whatever ends them.
    std::string lines;
    for (std::size_t i = 0; i + 1 < xyt::kMaxGcodeLines; ++i)
        lines += sep;
    QCOMPARE(readGcode(lines + "G0 X1").segments[0].line, xyt::kMaxGcodeLines);
    QVERIFY_THROWS_EXCEPTION(xyt::InvalidInput, readGcode(lines + sep + "G0 X1"));
}

void TstGcodeReader::zeroBeforeAnotherWordIsNotHexadecimal() {
    // Words need no space between them: "Y0x10" is Y0 and X10 (RS274/NGC letters in either
    // case), valid, unlike "X0x10" where a second X could only be a mistake.
    const auto p = readGcode("G1 Y0x10 F100");
    comparePoint(p.path.segments()[0].end(), {10.0, 0.0});
}

void TstGcodeReader::examples_data() {
    QTest::addColumn<QString>("file");
    QTest::addColumn<int>("segments");
    QTest::addColumn<double>("circleRadius"); // 0: not a single full circle
    QTest::addColumn<int>("warnings");
    // The papers' circles (Braga et al.: 25 mm at 90 mm/min; Patrick, Ishak and Adnan: 30 mm at 180
    // mm/min), each a rapid to the top then one clockwise circle; the program end M30 does not
    // warn.
    QTest::newRow("circle_25mm") << "circle_25mm.nc" << 2 << 25.0 << 0;
    QTest::newRow("circle_30mm") << "circle_30mm.nc" << 2 << 30.0 << 0;
    QTest::newRow("square") << "square_sharp_corners.nc" << 4 << 0.0 << 0;
    QTest::newRow("star") << "star.nc" << 6 << 0.0 << 0;
    // 10 XY moves (the first G0 X0 Y0 is already there); 9 Z words and M5 warn, M30 does not.
    QTest::newRow("engraving") << "engraving_xy.nc" << 10 << 0.0 << 10;
}

void TstGcodeReader::examples() {
    QFETCH(QString, file);
    QFETCH(int, segments);
    QFETCH(double, circleRadius);
    QFETCH(int, warnings);
    const std::string text = readExample(file);
    QVERIFY2(!text.empty(), qPrintable(file));
    const GcodeProgram p = readGcode(text);
    QCOMPARE(p.path.size(), std::size_t(segments));
    QCOMPARE(p.warnings.size(), std::size_t(warnings));
    QCOMPARE(p.isSingleFullCircle(), circleRadius > 0.0);
    if (circleRadius > 0.0) {
        const auto& c = p.path.segments()[p.fullCircleSegment()];
        XYT_COMPARE_NEAR(c.radius(), circleRadius, 0.0, kTol);
        comparePoint(c.centre(), {0.0, 0.0});
        QVERIFY(c.sweep() < 0.0); // clockwise, as x = R sin(w t), y = R cos(w t)
        // v = R omega: 25 x 0.06 = 1.5 mm/s (Braga et al.), 30 x 0.1 = 3 mm/s (Patrick, Ishak and
        // Adnan).
        XYT_COMPARE_NEAR(p.segments[p.fullCircleSegment()].feedMmPerSec,
                         circleRadius == 25.0 ? 1.5 : 3.0, 1e-15, 0.0);
    }
    if (file == "square_sharp_corners.nc") {
        XYT_COMPARE_NEAR(p.path.length(), 160.0, 1e-15, 0.0);
        QCOMPARE(xyt::sharpCorners(p.path, 0.01).size(), std::size_t(3)); // the 4th is the end
    }
    if (file == "star.nc") // 5 strokes of 2 x 30 sin 72 deg = 57.063 mm (3 decimals: 1e-3)
        XYT_COMPARE_NEAR(p.path.length() - 30.0, 5.0 * 60.0 * std::sin(0.4 * kPi), 0.0, 5e-3);
}

void TstGcodeReader::everyExampleIsTested() {
    // Every program in resources/examples is in the table above (a new one must be added).
    const QStringList files = QDir(QStringLiteral(XYT_SOURCE_DIR "/resources/examples"))
                                  .entryList({"*.nc"}, QDir::Files, QDir::Name);
    QCOMPARE(files, (QStringList{"circle_25mm.nc", "circle_30mm.nc", "engraving_xy.nc",
                                 "square_sharp_corners.nc", "star.nc"}));
}

QTEST_APPLESS_MAIN(TstGcodeReader)
#include "tst_gcode_reader.moc"
