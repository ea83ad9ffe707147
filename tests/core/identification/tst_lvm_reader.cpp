// SPDX-License-Identifier: GPL-3.0-or-later
// The LabVIEW Measurement reader (core/identification/lvm_reader.h) on files laid out as NI's
// "Specification for the LabVIEW Measurement File (.lvm)" describes them (file header, segment
// headers, X_Value name row, Comment column). Expected values are the numbers written in the
// test's own text (closed form: what the file says).
#include "core/identification/lvm_reader.h"
#include "core/model/errors.h"
#include "tests/support/core_checks.h"

#include <QTest>

namespace {

/// A one-segment file as LabVIEW writes it: tab separated, X_Columns One.
const char* kOneSegment = "LabVIEW Measurement\t\n"
                          "Writer_Version\t2\n"
                          "Reader_Version\t2\n"
                          "Separator\tTab\n"
                          "Decimal_Separator\t.\n"
                          "Multi_Headings\tNo\n"
                          "X_Columns\tOne\n"
                          "Time_Pref\tRelative\n"
                          "Operator\tlab\n"
                          "Date\t2023/05/04\n"
                          "Time\t10:11:12.5\n"
                          "***End_of_Header***\t\n"
                          "\t\n"
                          "Channels\t2\t\t\n"
                          "Samples\t3\t3\t\n"
                          "Date\t2023/05/04\t2023/05/04\t\n"
                          "Time\t10:11:12.5\t10:11:12.5\t\n"
                          "X_Dimension\tTime\tTime\t\n"
                          "X0\t0.0000000000000000E+0\t0.0000000000000000E+0\t\n"
                          "Delta_X\t0.010000\t0.010000\t\n"
                          "***End_of_Header***\t\t\t\n"
                          "X_Value\tCommand\tPosition\tComment\n"
                          "0.000000\t0.000000\t1.250000\n"
                          "0.010000\t2.500000\t1.500000\tstep\n"
                          "0.020000\t2.500000\t1.750000\n";

} // namespace

class TstLvmReader : public QObject {
    Q_OBJECT
private slots:
    void readsOneSegment();
    void commaSeparatorAndDecimalComma();
    void noXColumn();
    void multiXColumns();
    void segmentsAreChosen();
    void specialBlocksAreSkipped();
    void withoutNameRowChannelsAreUntitled();
    void errorsNameFileAndLine_data();
    void errorsNameFileAndLine();
    void lineEndsOfEveryConvention_data();
    void lineEndsOfEveryConvention();
    void deltaXContradictedByXValueIsRefused();
    void deltaXOutsideTheSampleTimesIsRefused_data();
    void deltaXOutsideTheSampleTimesIsRefused();
    void chosenColumnsAreCheckedAtTheNameRow();
};

void TstLvmReader::readsOneSegment() {
    const xyt::LvmTable r = xyt::readLvm(kOneSegment, "run.lvm");
    QCOMPARE(r.segmentCount, std::size_t(1));
    const xyt::ExperimentTable& t = r.table;
    QCOMPARE(t.names, (std::vector<std::string>{"X_Value", "Command", "Position"}));
    QCOMPARE(t.columns[0], (std::vector<double>{0.0, 0.01, 0.02}));
    QCOMPARE(t.columns[1], (std::vector<double>{0.0, 2.5, 2.5}));
    QCOMPARE(t.columns[2], (std::vector<double>{1.25, 1.5, 1.75}));
    QCOMPARE(t.rowNumbers, (std::vector<std::size_t>{23, 24, 25}));
    QVERIFY(t.sampleTimeSeconds);
    QCOMPARE(*t.sampleTimeSeconds, 0.01); // Delta_X "0.010000"
    QCOMPARE(QString::fromStdString(t.cellField(2, 1)),
             QString("run.lvm: line 24, column 3 (Position)"));
    QVERIFY(t.warnings.empty());
}

void TstLvmReader::commaSeparatorAndDecimalComma() {
    // Comma separated (the layout of the lvm_read test file "with comma"), decimal point.
    const char* comma =
        "LabVIEW Measurement,\nWriter_Version,2\nSeparator,Comma\nDecimal_Separator,.\n"
        "X_Columns,One\n***End_of_Header***,\n,\nChannels,1,\nDelta_X,2.000000E-6,\n"
        "***End_of_Header***,\nX_Value,Voltage,Comment\n0.000000E+0,1.5\n2.000000E-6,-0.25\n";
    const xyt::LvmTable a = xyt::readLvm(comma, "c.lvm");
    QCOMPARE(a.table.columns[1], (std::vector<double>{1.5, -0.25}));
    QCOMPARE(*a.table.sampleTimeSeconds, 2e-6);
    // Tab separated with a decimal comma (a LabVIEW on a Brazilian or German Windows).
    const char* decimalComma =
        "LabVIEW Measurement\t\nSeparator\tTab\nDecimal_Separator\t,\nX_Columns\tOne\n"
        "***End_of_Header***\t\nChannels\t1\nDelta_X\t0,010000\n***End_of_Header***\n"
        "X_Value\tTensao\tComment\n0,000000\t0,250000\n0,010000\t-1,500000\n";
    const xyt::LvmTable b = xyt::readLvm(decimalComma, "d.lvm");
    QCOMPARE(b.table.columns[0], (std::vector<double>{0.0, 0.01}));
    QCOMPARE(b.table.columns[1], (std::vector<double>{0.25, -1.5}));
    QCOMPARE(*b.table.sampleTimeSeconds, 0.01);
}

void TstLvmReader::noXColumn() {
    // X_Columns No: each data row starts with an empty x field; the channels start at field 2.
    const char* text =
        "LabVIEW Measurement\t\nSeparator\tTab\nX_Columns\tNo\n***End_of_Header***\t\n"
        "Channels\t2\nDelta_X\t1.000000\t1.000000\n***End_of_Header***\n"
        "X_Value\tMass0\tThermocouple1\tComment\n\t28.5\t25.25\n\t28.75\t25.5\t15:49:24\n";
    const xyt::ExperimentTable t = xyt::readLvm(text, "n.lvm").table;
    QCOMPARE(t.names, (std::vector<std::string>{"Mass0", "Thermocouple1"}));
    QCOMPARE(t.fieldNumbers, (std::vector<std::size_t>{2, 3}));
    QCOMPARE(t.columns[1], (std::vector<double>{25.25, 25.5}));
    QCOMPARE(*t.sampleTimeSeconds, 1.0);
}

void TstLvmReader::multiXColumns() {
    const char* text =
        "LabVIEW Measurement\t\nSeparator\tTab\nX_Columns\tMulti\n***End_of_Header***\t\n"
        "Channels\t2\nDelta_X\t0.1\t0.2\n***End_of_Header***\n"
        "X_Value\tA\tX_Value\tB\tComment\n0\t1\t0\t2\n0.1\t3\t0.2\t4\n";
    const xyt::ExperimentTable t = xyt::readLvm(text, "m.lvm").table;
    QCOMPARE(t.names, (std::vector<std::string>{"X_Value (A)", "A", "X_Value (B)", "B"}));
    QCOMPARE(t.columns[2], (std::vector<double>{0.0, 0.2}));
    QCOMPARE(t.columns[3], (std::vector<double>{2.0, 4.0}));
    // The channels' Delta_X differ: no sample time, and a warning says so.
    QVERIFY(!t.sampleTimeSeconds);
    QCOMPARE(t.warnings.size(), std::size_t(1));
}

void TstLvmReader::segmentsAreChosen() {
    std::string text = kOneSegment;
    text += "Channels\t1\nDelta_X\t0.5\n***End_of_Header***\nX_Value\tOther\tComment\n0\t7\n0."
            "5\t8\n1\t9\n";
    const xyt::LvmTable first = xyt::readLvm(text, "s.lvm");
    QCOMPARE(first.segmentCount, std::size_t(2));
    QCOMPARE(first.table.names[1], std::string("Command"));
    QCOMPARE(first.table.warnings.size(),
             std::size_t(1)); // "the file has 2 segments; segment 1 was read"
    xyt::LvmReadOptions o;
    o.segment = 2;
    const xyt::LvmTable second = xyt::readLvm(text, "s.lvm", o);
    QCOMPARE(second.table.names, (std::vector<std::string>{"X_Value", "Other"}));
    QCOMPARE(second.table.columns[1], (std::vector<double>{7.0, 8.0, 9.0}));
    QCOMPARE(*second.table.sampleTimeSeconds, 0.5);
    QCOMPARE(second.table.rowNumbers.front(), std::size_t(30));
    o.segment = 3;
    QCOMPARE(xyt::test::invalidInputMessage([&] { xyt::readLvm(text, "s.lvm", o); }),
             QString("s.lvm: has 2 segments, not a segment 3"));
}

void TstLvmReader::specialBlocksAreSkipped() {
    const char* text =
        "LabVIEW Measurement\t\nSeparator\tTab\nX_Columns\tOne\n***Start_Special***\nX_Value\t9\n"
        "***End_Special***\n***End_of_Header***\t\nChannels\t1\n***End_of_Header***\n"
        "X_Value\tu\tComment\n0\t1\n***Start_Special***\nanything\there\n***End_Special***\n1\t2\n";
    const xyt::ExperimentTable t = xyt::readLvm(text, "sp.lvm").table;
    QCOMPARE(t.columns[1], (std::vector<double>{1.0, 2.0}));
}

void TstLvmReader::withoutNameRowChannelsAreUntitled() {
    const char* text =
        "LabVIEW Measurement\t\nSeparator\tTab\nX_Columns\tOne\n***End_of_Header***\t\n"
        "Channels\t2\n***End_of_Header***\n0\t1\t2\n1\t3\t4\n";
    const xyt::ExperimentTable t = xyt::readLvm(text, "u.lvm").table;
    QCOMPARE(t.names, (std::vector<std::string>{"X_Value", "Untitled", "Untitled 1"}));
    QCOMPARE(t.columns[2], (std::vector<double>{2.0, 4.0}));
    QCOMPARE(t.warnings.size(), std::size_t(1));
}

void TstLvmReader::errorsNameFileAndLine_data() {
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("expected");
    const QString head =
        "LabVIEW Measurement\t\nSeparator\tTab\nX_Columns\tOne\n***End_of_Header***\t\n";
    QTest::newRow("not an LVM file") << "t,u\n0,1\n"
                                     << "run.lvm: line 1: is not a LabVIEW Measurement file";
    QTest::newRow("empty") << ""
                           << "run.lvm: is not a LabVIEW Measurement file";
    QTest::newRow("file header not closed") << "LabVIEW Measurement\t\nSeparator\tTab\n"
                                            << "run.lvm: line 1: the file header is not closed";
    QTest::newRow("bad separator") << "LabVIEW Measurement\t\nSeparator\tSpace\n"
                                   << "run.lvm: line 2: Separator 'Space' is not Tab or Comma";
    QTest::newRow("bad X_Columns") << "LabVIEW Measurement\t\nX_Columns\tTwo\n"
                                   << "run.lvm: line 2: X_Columns 'Two' is not No, One or Multi";
    QTest::newRow("bad decimal separator")
        << "LabVIEW Measurement\t\nDecimal_Separator\t;\n"
        << "run.lvm: line 2: Decimal_Separator ';' is not '.' or ','";
    QTest::newRow("decimal comma with comma separator")
        << "LabVIEW Measurement,\nSeparator,Comma\nDecimal_Separator,,\n***End_of_Header***,\n0,1\n"
        << "run.lvm: a decimal comma cannot be read with Comma separators";
    QTest::newRow("segment header not closed")
        << head + "Channels\t1\nDelta_X\t1\n"
        << "run.lvm: line 5: the segment header that starts here with 'Channels' is not closed";
    QTest::newRow("no segment") << head << "run.lvm: holds no data segment";
    QTest::newRow("repeated channel")
        << head + "Channels\t2\n***End_of_Header***\nX_Value\tu\tu\tComment\n0\t1\t2\n"
        << "run.lvm: line 7, column 3: the channel name 'u' is used twice";
    QTest::newRow("too many fields")
        << head + "Channels\t1\n***End_of_Header***\nX_Value\tu\n0\t1\t2\n"
        << "run.lvm: line 8, column 3: the row has more fields";
    QTest::newRow("garbage data row starts a header that never ends")
        << head + "Channels\t1\n***End_of_Header***\nX_Value\tu\tComment\n0\t1\nabc\t2\n"
        << "run.lvm: line 9: the segment header that starts here with 'abc' is not closed";
}

void TstLvmReader::errorsNameFileAndLine() {
    QFETCH(QString, text);
    QFETCH(QString, expected);
    const std::string bytes = text.toStdString();
    const QString message = xyt::test::invalidInputMessage([&] { xyt::readLvm(bytes, "run.lvm"); });
    QVERIFY2(message.startsWith(expected), qPrintable(message));
}

void TstLvmReader::lineEndsOfEveryConvention_data() {
    QTest::addColumn<QString>("eol");
    QTest::newRow("LF") << "\n";
    QTest::newRow("CRLF") << "\r\n";
    QTest::newRow("CR") << "\r"; // old Mac OS
}

void TstLvmReader::lineEndsOfEveryConvention() {
    QFETCH(QString, eol);
    // kOneSegment with its line ends replaced: the same table, the same line numbers.
    const std::string text = QString(kOneSegment).replace("\n", eol).toStdString();
    const xyt::ExperimentTable t = xyt::readLvm(text, "run.lvm").table;
    QCOMPARE(t.names, (std::vector<std::string>{"X_Value", "Command", "Position"}));
    QCOMPARE(t.columns[2], (std::vector<double>{1.25, 1.5, 1.75}));
    QCOMPARE(t.rowNumbers, (std::vector<std::size_t>{23, 24, 25}));
    QCOMPARE(*t.sampleTimeSeconds, 0.01);
    const std::string unclosed =
        QString(kOneSegment).append("abc\t2\n").replace("\n", eol).toStdString();
    QCOMPARE(
        xyt::test::invalidInputMessage([&] { xyt::readLvm(unclosed, "run.lvm"); }),
        QString("run.lvm: line 26: the segment header that starts here with 'abc' is not closed by "
                "***End_of_Header***"));
}

void TstLvmReader::deltaXContradictedByXValueIsRefused() {
    // Delta_X 0.5 over an X_Value column that steps by 0.01: one of them is wrong, and taking
    // 0.5 s silently made every identified pole 50 times too slow.
    std::string text = kOneSegment;
    text.replace(text.find("Delta_X\t0.010000\t0.010000"), 25, "Delta_X\t0.500000\t0.500000");
    QCOMPARE(
        xyt::test::invalidInputMessage([&] { xyt::readLvm(text, "run.lvm"); }),
        QString(
            "run.lvm: line 20: Delta_X 0.5 contradicts the X_Value column (field 1), whose mean "
            "step "
            "from line 23 to line 25 is 0.01: one of the two is wrong (give the sample time or a "
            "time column, after correcting the file)"));
    // Within 1 % (kSampleTimeTolerance) they agree: 0.01005 beside steps of 0.01.
    std::string close = kOneSegment;
    close.replace(close.find("Delta_X\t0.010000\t0.010000"), 25, "Delta_X\t0.010050\t0.010050");
    QCOMPARE(*xyt::readLvm(close, "run.lvm").table.sampleTimeSeconds, 0.01005);
}

void TstLvmReader::deltaXOutsideTheSampleTimesIsRefused_data() {
    QTest::addColumn<QString>("deltaX");
    QTest::newRow("subnormal") << "5e-324";
    QTest::newRow("below 1 ns") << "1e-10";
    QTest::newRow("huge") << "1e300";
    QTest::newRow("above 10000 s") << "20000";
}

void TstLvmReader::deltaXOutsideTheSampleTimesIsRefused() {
    QFETCH(QString, deltaX);
    // No X column, so only the range speaks: such a Ts was written as the session's pp.ts,
    // which the session then refused.
    const std::string text =
        ("LabVIEW Measurement\t\nSeparator\tTab\nX_Columns\tNo\n***End_of_Header***\t\n"
         "Channels\t2\nDelta_X\t" +
         deltaX + "\t" + deltaX +
         "\n***End_of_Header***\n"
         "X_Value\tu\ty\tComment\n\t1\t2\n\t3\t4\n")
            .toStdString();
    const QString message = xyt::test::invalidInputMessage([&] { xyt::readLvm(text, "run.lvm"); });
    QVERIFY2(message.startsWith("run.lvm: line 6: Delta_X: "), qPrintable(message));
    QVERIFY2(message.contains(" s is outside the accepted sample times, 1e-09 s to 10000 s"),
             qPrintable(message));
}

void TstLvmReader::chosenColumnsAreCheckedAtTheNameRow() {
    xyt::LvmReadOptions o;
    o.columns = {"Position", "Speed"};
    QCOMPARE(
        xyt::test::invalidInputMessage([&] { xyt::readLvm(kOneSegment, "run.lvm", o); }),
        QString("run.lvm: has no column 'Speed'; the columns are: X_Value, Command, Position"));
    o.columns = {"Position"};
    const xyt::ExperimentTable t = xyt::readLvm(kOneSegment, "run.lvm", o).table;
    QCOMPARE(t.names, (std::vector<std::string>{"Position"}));
    QCOMPARE(t.fieldNumbers, (std::vector<std::size_t>{3}));
    QCOMPARE(t.columns[0], (std::vector<double>{1.25, 1.5, 1.75}));
    // The X_Value column is not kept but still checked against Delta_X.
    std::string text = kOneSegment;
    text.replace(text.find("Delta_X\t0.010000\t0.010000"), 25, "Delta_X\t0.500000\t0.500000");
    QVERIFY(xyt::test::invalidInputMessage([&] {
                xyt::readLvm(text, "run.lvm", o);
            }).contains("contradicts"));
}

QTEST_APPLESS_MAIN(TstLvmReader)
#include "tst_lvm_reader.moc"
