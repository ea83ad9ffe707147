// SPDX-License-Identifier: GPL-3.0-or-later
// From a read table to the IoData the estimators use (core/identification/experiment_data.h):
// the chosen columns, the time base, the output scale, and a table of bad files whose every
// error names the file, the line and the column. Expected values are closed forms (the numbers
// written in each text, times the stated scale).
#include "core/identification/delimited_reader.h"
#include "core/identification/experiment_data.h"
#include "core/identification/lvm_reader.h"
#include "core/model/errors.h"
#include "tests/support/core_checks.h"
#include "tests/support/tolerance.h"

#include <QTest>

namespace {

xyt::ExperimentTable csv(const QString& text) {
    return xyt::readDelimited(text.toStdString(), "run.csv").table;
}

xyt::ExperimentColumns byTime(const char* time = "t") {
    xyt::ExperimentColumns c;
    c.input = "u";
    c.output = "y";
    c.time = time;
    return c;
}

} // namespace

class TstExperimentData : public QObject {
    Q_OBJECT
private slots:
    void timeColumnGivesTsAndStart();
    void givenAndFileSampleTimes();
    void outputScales_data();
    void outputScales();
    void nonUniformWithinOnePercentIsAccepted();
    void badFiles_data();
    void badFiles();
    void choiceErrors();
    void requireSamplesNamesTheUse();
    void sampleTimesOutsideTheRangeAreRefused_data();
    void sampleTimesOutsideTheRangeAreRefused();
    void takenTableGivesTheSameRecord();
};

void TstExperimentData::timeColumnGivesTsAndStart() {
    const xyt::IoData d = xyt::experimentData(
        csv("t,u,y\n1.00,0,5\n1.01,2.5,5.5\n1.02,2.5,6\n1.03,2.5,7\n"), byTime());
    QCOMPARE(d.u, (std::vector<double>{0.0, 2.5, 2.5, 2.5}));
    QCOMPARE(d.y, (std::vector<double>{5.0, 5.5, 6.0, 7.0}));
    // Ts = (1.03 - 1.00) / 3 = 0.01 up to the round-off of the decimal times (a few ulp of 1).
    XYT_COMPARE_NEAR(d.tsSeconds, 0.01, 1e-12, 0.0);
    QCOMPARE(d.startSeconds, 1.0);
    QCOMPARE(d.source, std::string("run.csv: u=u, y=y"));
}

void TstExperimentData::givenAndFileSampleTimes() {
    xyt::ExperimentColumns c = byTime("");
    c.sampleTimeSeconds = 0.07;
    const xyt::IoData given = xyt::experimentData(csv("u,y\n0,1\n1,2\n"), c);
    QCOMPARE(given.tsSeconds, 0.07);
    QCOMPARE(given.startSeconds, 0.0);
    // The LVM's Delta_X, only when asked for.
    const char* lvm =
        "LabVIEW Measurement\t\nSeparator\tTab\nX_Columns\tNo\n***End_of_Header***\t\n"
        "Channels\t2\nDelta_X\t0.010000\t0.010000\n***End_of_Header***\n"
        "X_Value\tu\ty\tComment\n\t0\t1\n\t1\t2\n\t1\t4\n";
    xyt::ExperimentColumns f = byTime("");
    f.fileSampleTime = true;
    const xyt::IoData fromFile = xyt::experimentData(xyt::readLvm(lvm, "run.lvm").table, f);
    QCOMPARE(fromFile.tsSeconds, 0.01);
    QCOMPARE(fromFile.y, (std::vector<double>{1.0, 2.0, 4.0}));
    QCOMPARE(
        xyt::test::invalidInputMessage([&] { xyt::experimentData(csv("u,y\n0,1\n1,2\n"), f); }),
        QString("run.csv: states no sample time (no Delta_X equal for every channel): give a time "
                "column or a sample time"));
}

void TstExperimentData::outputScales_data() {
    QTest::addColumn<int>("unit");
    QTest::addColumn<double>("mmPerCount");
    QTest::addColumn<double>("factor");
    QTest::newRow("mm") << int(xyt::OutputUnit::Millimetres) << 0.0 << 1.0;
    QTest::newRow("m") << int(xyt::OutputUnit::Metres) << 0.0 << 1000.0;
    QTest::newRow("encoder, 0.005 mm per count")
        << int(xyt::OutputUnit::EncoderCounts) << 0.005 << 0.005;
}

void TstExperimentData::outputScales() {
    QFETCH(int, unit);
    QFETCH(double, mmPerCount);
    QFETCH(double, factor);
    xyt::ExperimentColumns c = byTime();
    c.outputScale = {xyt::OutputUnit(unit), mmPerCount};
    const xyt::IoData d = xyt::experimentData(csv("t,u,y\n0,0,400\n0.5,1,-1200\n"), c);
    // One multiplication each: exact to the rounding of the product.
    QCOMPARE(d.y[0], 400.0 * factor);
    QCOMPARE(d.y[1], -1200.0 * factor);
}

void TstExperimentData::nonUniformWithinOnePercentIsAccepted() {
    // Steps 0.01, 0.0100 +- 0.9 %: within the 1 % bound (logged times jitter by a clock tick).
    const xyt::IoData d =
        xyt::experimentData(csv("t,u,y\n0,0,0\n0.01,0,0\n0.02009,0,0\n0.03,0,0\n"), byTime());
    XYT_COMPARE_NEAR(d.tsSeconds, 0.01, 1e-12, 0.0);
}

void TstExperimentData::badFiles_data() {
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("expected");
    // Each row: a file with one defect, and the message's start: file, line, column, reason.
    QTest::newRow("non-numeric cell in u")
        << "t,u,y\n0,0,1\n0.01,abc,2\n"
        << "run.csv: line 3, column 2 (u): 'abc' is not a number";
    QTest::newRow("missing value in y") << "t,u,y\n0,0,1\n0.01,1\n"
                                        << "run.csv: line 3, column 3 (y): the value is missing";
    QTest::newRow("empty cell in y") << "t,u,y\n0,0,1\n0.01,1,\n"
                                     << "run.csv: line 3, column 3 (y): the value is missing";
    QTest::newRow("NaN in y") << "t,u,y\n0,0,1\n0.01,1,NaN\n"
                              << "run.csv: line 3, column 3 (y): 'NaN' is NaN or infinite";
    QTest::newRow("Inf in time") << "t,u,y\n0,0,1\ninf,1,2\n"
                                 << "run.csv: line 3, column 1 (t): 'inf' is NaN or infinite";
    QTest::newRow("decimal comma in a comma file")
        << "t;u;y\n0;0;1\n0,01;1.5;2\n"
        << "run.csv: line 3, column 2 (u): '1.5' is not a number (a decimal point";
    QTest::newRow("time goes back")
        << "t,u,y\n0,0,1\n0.01,0,1\n0.005,0,1\n0.02,0,1\n"
        << "run.csv: line 4, column 1 (t): time 0.005 s does not increase";
    QTest::newRow("time repeats") << "t,u,y\n0,0,1\n0.01,0,1\n0.01,0,1\n"
                                  << "run.csv: line 4, column 1 (t): time 0.01 s does not increase";
    QTest::newRow("non-uniform time, 5 % off")
        << "t,u,y\n0,0,1\n0.01,0,1\n0.0205,0,1\n0.03,0,1\n0.04,0,1\n"
        << "run.csv: line 4, column 1 (t): the time step 0.0105 s differs from the mean sample "
           "time 0.01 s by more than 1 %";
    QTest::newRow("unknown column") << "time,u,y\n0,0,1\n0.01,0,1\n"
                                    << "run.csv: has no column 't'; the columns are: time, u, y";
    QTest::newRow("one sample")
        << "t,u,y\n0,0,1\n"
        << "run.csv: u=u, y=y: has 1 sample; a sampled record needs at least 2";
    QTest::newRow("no sample")
        << "t,u,y\n"
        << "run.csv: u=u, y=y: has 0 samples; a sampled record needs at least 2";
    // Blank lines still count: the line is the file's, not the row's.
    QTest::newRow("line numbers count blank lines")
        << "t,u,y\n\n0,0,1\n\n0.01,x,1\n"
        << "run.csv: line 5, column 2 (u): 'x' is not a number";
}

void TstExperimentData::badFiles() {
    QFETCH(QString, text);
    QFETCH(QString, expected);
    const QString message =
        xyt::test::invalidInputMessage([&] { xyt::experimentData(csv(text), byTime()); });
    QVERIFY2(message.startsWith(expected), qPrintable(message));
}

void TstExperimentData::choiceErrors() {
    const xyt::ExperimentTable t = csv("t,u,y\n0,0,1\n0.01,0,1\n");
    xyt::ExperimentColumns none = byTime("");
    QCOMPARE(xyt::test::invalidInputMessage([&] { xyt::experimentData(t, none); }),
             QString("run.csv: no time source: give a time column or a sample time"));
    xyt::ExperimentColumns both = byTime();
    both.sampleTimeSeconds = 0.01;
    QVERIFY(xyt::test::invalidInputMessage([&] {
                xyt::experimentData(t, both);
            }).contains("give one time source"));
    xyt::ExperimentColumns same = byTime();
    same.output = "u";
    QCOMPARE(xyt::test::invalidInputMessage([&] { xyt::experimentData(t, same); }),
             QString("run.csv: column 'u' is chosen as both input and output"));
    xyt::ExperimentColumns encoder = byTime();
    encoder.outputScale.unit = xyt::OutputUnit::EncoderCounts;
    QCOMPARE(xyt::test::invalidInputField([&] { xyt::experimentData(t, encoder); }),
             QString("mm_per_count"));
    xyt::ExperimentColumns badTs = byTime("");
    badTs.sampleTimeSeconds = -0.01;
    QCOMPARE(xyt::test::invalidInputField([&] { xyt::experimentData(t, badTs); }),
             QString("sample_time"));
    // A text column that is never used does not stop the others.
    const xyt::ExperimentTable withNotes = csv("t,u,y,note\n0,0,1,start\n0.01,0,1,\n");
    QCOMPARE(xyt::experimentData(withNotes, byTime()).size(), std::size_t(2));
}

void TstExperimentData::requireSamplesNamesTheUse() {
    xyt::IoData d;
    d.u = {1, 2, 3};
    d.y = {1, 2, 3};
    d.source = "run.csv: u=u, y=y";
    xyt::requireSamples(d, 3, "ARX(2,3,1) estimation");
    QCOMPARE(
        xyt::test::invalidInputMessage([&] { xyt::requireSamples(d, 4, "ARX(2,3,1) estimation"); }),
        QString("run.csv: u=u, y=y: has 3 samples; ARX(2,3,1) estimation needs at least 4"));
    d.source.clear();
    d.y.pop_back();
    QCOMPARE(xyt::test::invalidInputMessage([&] { xyt::requireSamples(d, 1, "x"); }),
             QString("data: u has 3 samples but y has 2"));
}

void TstExperimentData::sampleTimesOutsideTheRangeAreRefused_data() {
    QTest::addColumn<double>("ts");
    QTest::addColumn<bool>("accepted");
    // The bounds themselves are accepted (kMinSampleTimeSeconds, kMaxSampleTimeSeconds).
    QTest::newRow("1 ns") << 1e-9 << true;
    QTest::newRow("10000 s") << 1e4 << true;
    // 5e-324 was written into a session as pp.ts, which `report` then refused.
    QTest::newRow("subnormal") << 5e-324 << false;
    QTest::newRow("below 1 ns") << 0.99e-9 << false;
    QTest::newRow("above 10000 s") << 1.01e4 << false;
    QTest::newRow("1e300") << 1e300 << false;
}

void TstExperimentData::sampleTimesOutsideTheRangeAreRefused() {
    QFETCH(double, ts);
    QFETCH(bool, accepted);
    const xyt::ExperimentTable t = csv("u,y\n0,1\n1,2\n");
    xyt::ExperimentColumns given;
    given.input = "u";
    given.output = "y";
    given.sampleTimeSeconds = ts;
    const QString message = xyt::test::invalidInputMessage([&] { xyt::experimentData(t, given); });
    if (accepted) {
        QCOMPARE(message, QString("<no exception>"));
        return;
    }
    QVERIFY2(message.startsWith("sample_time: ") &&
                 message.contains("outside the accepted sample times, 1e-09 s to 10000 s"),
             qPrintable(message));
    // The same sample time from a time column: the column and its last line are named (a
    // subnormal cell is refused before, as out of the range of a double).
    if (ts < 1e-300)
        return;
    const QString timed = QString("t,u,y\n0,0,1\n%1,1,2\n").arg(ts, 0, 'g', 17);
    const QString fromColumn =
        xyt::test::invalidInputMessage([&] { xyt::experimentData(csv(timed), byTime()); });
    QVERIFY2(
        fromColumn.startsWith("run.csv: line 3, column 1 (t): the time column's sample time: "),
        qPrintable(fromColumn));
}

void TstExperimentData::takenTableGivesTheSameRecord() {
    // The rvalue overload moves the input column out instead of copying it: same record.
    const QString text = "t,u,y\n0,0.5,1\n0.01,1.5,2\n0.02,2.5,3\n";
    const xyt::IoData copied = xyt::experimentData(csv(text), byTime());
    xyt::ExperimentTable table = csv(text);
    const xyt::IoData taken = xyt::experimentData(std::move(table), byTime());
    QCOMPARE(taken.u, (std::vector<double>{0.5, 1.5, 2.5}));
    QCOMPARE(taken.u, copied.u);
    QCOMPARE(taken.y, copied.y);
    QCOMPARE(taken.tsSeconds, copied.tsSeconds);
    // The time column may be the input column: it is then copied, not moved away.
    xyt::ExperimentColumns c = byTime("u");
    c.output = "y";
    xyt::ExperimentTable again = csv(text);
    QCOMPARE(xyt::experimentData(std::move(again), c).tsSeconds, 1.0);
}

QTEST_APPLESS_MAIN(TstExperimentData)
#include "tst_experiment_data.moc"
