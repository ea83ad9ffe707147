// SPDX-License-Identifier: GPL-3.0-or-later
// The CSV/TSV reader (core/identification/delimited_reader.h). Every expected value is the
// number written in the test's own text (closed form: the reader must give back what the file
// says, to the last bit where the decimal text is a double's shortest form).
#include "core/identification/delimited_reader.h"
#include "core/model/errors.h"
#include "tests/support/core_checks.h"
#include "tests/support/tolerance.h"

#include <QTest>

#include <cmath>

namespace {

xyt::DelimitedTable read(const char* text, xyt::DelimitedReadOptions options = {}) {
    return xyt::readDelimited(text, "run.csv", options);
}

} // namespace

class TstDelimitedReader : public QObject {
    Q_OBJECT
private slots:
    void detectsTheDelimiter_data();
    void detectsTheDelimiter();
    void semicolonMeansDecimalComma();
    void quotedHeaderNamesAndCells();
    void keepsLineNumbersAndProblems();
    void trailingSeparatorIsDropped();
    void structuralErrorsNameLineAndColumn_data();
    void structuralErrorsNameLineAndColumn();
    void readsAFile();
    void lineEndsOfEveryConvention_data();
    void lineEndsOfEveryConvention();
    void chosenColumnsAreCheckedBeforeTheRows();
    void refusalsCarryTheirCode();
};

void TstDelimitedReader::detectsTheDelimiter_data() {
    QTest::addColumn<QString>("text");
    QTest::addColumn<int>("delimiter");
    QTest::newRow("comma") << "t,u,y\n0,0.5,-1\n0.01,0.25,2e-3\n" << int(xyt::Delimiter::Comma);
    QTest::newRow("tab") << "t\tu\ty\n0\t0.5\t-1\n0.01\t0.25\t2e-3\n" << int(xyt::Delimiter::Tab);
    QTest::newRow("semicolon, decimal point cells") << "t;u;y\n0;0,5;-1\n0,01;0,25;2e-3\n"
                                                    << int(xyt::Delimiter::Semicolon);
    QTest::newRow("aligned with spaces, CRLF")
        << "  t      u      y\r\n  0    0.5     -1\r\n  0.01 0.25   2e-3\r\n"
        << int(xyt::Delimiter::Whitespace);
}

void TstDelimitedReader::detectsTheDelimiter() {
    QFETCH(QString, text);
    QFETCH(int, delimiter);
    const std::string bytes = text.toStdString();
    const xyt::DelimitedTable r = xyt::readDelimited(bytes, "run.csv");
    QCOMPARE(int(r.delimiter), delimiter);
    const xyt::ExperimentTable& t = r.table;
    QCOMPARE(t.names, (std::vector<std::string>{"t", "u", "y"}));
    // The values are the decimal text of the file: 0.01, 0.25 ... parse to the nearest double,
    // which is what the same literal in C++ gives, so they compare exactly.
    QCOMPARE(t.columns[0], (std::vector<double>{0.0, 0.01}));
    QCOMPARE(t.columns[1], (std::vector<double>{0.5, 0.25}));
    QCOMPARE(t.columns[2], (std::vector<double>{-1.0, 2e-3}));
    QCOMPARE(t.rowNumbers, (std::vector<std::size_t>{2, 3}));
    for (const auto& p : t.firstProblem)
        QVERIFY(!p);
}

void TstDelimitedReader::semicolonMeansDecimalComma() {
    // A Brazilian LabVIEW/Excel export: ';' between fields, ',' as the decimal separator.
    const auto r = read("Tempo (s);Tensão (V);Posição (mm)\n0,00;0,25;1,5\n0,01;-2,5;1,75\n");
    QVERIFY(r.decimalComma);
    QCOMPARE(r.table.names[1], std::string("Tensão (V)"));
    QCOMPARE(r.table.columns[1], (std::vector<double>{0.25, -2.5}));
    QCOMPARE(r.table.columns[2], (std::vector<double>{1.5, 1.75}));
    // A decimal point in such a file is not guessed: the cell is a problem of its column.
    const auto mixed = read("t;u\n0,00;1.5\n");
    QVERIFY(mixed.table.firstProblem[1]);
    QVERIFY(QString::fromStdString(mixed.table.firstProblem[1]->reason).contains("decimal point"));
    // The choice can be forced: ';' with decimal points.
    xyt::DelimitedReadOptions o;
    o.decimal = xyt::DecimalSeparator::Point;
    QCOMPARE(read("t;u\n0.5;1.5\n", o).table.columns[1], (std::vector<double>{1.5}));
    // And tab-separated files with a decimal comma, when said so.
    o.decimal = xyt::DecimalSeparator::Comma;
    QCOMPARE(read("t\tu\n0,5\t1,5\n", o).table.columns[1], (std::vector<double>{1.5}));
}

void TstDelimitedReader::quotedHeaderNamesAndCells() {
    const auto r = read("\"time, s\",\"say \"\"u\"\"\", y\n\"0\",1,2\n");
    QCOMPARE(r.table.names, (std::vector<std::string>{"time, s", "say \"u\"", "y"}));
    QCOMPARE(r.table.columns[0], (std::vector<double>{0.0}));
    QCOMPARE(r.table.columns[2], (std::vector<double>{2.0}));
}

void TstDelimitedReader::keepsLineNumbersAndProblems() {
    // Blank lines keep counting; a text cell, a NaN and a missing cell are problems of their
    // columns only (the other columns stay usable).
    const auto r = read("t,u,y,note\n\n0,1,2,ok\n0.01,abc,NaN\n");
    const xyt::ExperimentTable& t = r.table;
    QCOMPARE(t.rowNumbers, (std::vector<std::size_t>{3, 4}));
    QVERIFY(!t.firstProblem[0]);
    QVERIFY(t.firstProblem[1] && t.firstProblem[2] && t.firstProblem[3]);
    QCOMPARE(t.firstProblem[1]->text, std::string("abc"));
    QCOMPARE(t.firstProblem[1]->row, std::size_t(1));
    QCOMPARE(t.firstProblem[2]->reason.text, std::string("is NaN or infinite"));
    // The reasons are coded, so the workbench can translate them.
    QCOMPARE(t.firstProblem[1]->reason.code, std::string("ident_cell_not_number"));
    QCOMPARE(t.firstProblem[2]->reason.code, std::string("not_finite_value"));
    QCOMPARE(t.firstProblem[3]->text, std::string("ok")); // "ok" comes first, at line 3
    QCOMPARE(QString::fromStdString(t.cellField(1, 1)), QString("run.csv: line 4, column 2 (u)"));
    QVERIFY(std::isnan(t.columns[1][1]));
}

void TstDelimitedReader::trailingSeparatorIsDropped() {
    const auto r = read("t;u;\n0;1;\n1;2;\n");
    QCOMPARE(r.table.names, (std::vector<std::string>{"t", "u"}));
    QCOMPARE(r.table.columns[1], (std::vector<double>{1.0, 2.0}));
}

void TstDelimitedReader::structuralErrorsNameLineAndColumn_data() {
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("expected");
    QTest::newRow("empty file") << ""
                                << "run.csv: holds no header line";
    QTest::newRow("only blank lines") << "\n \n"
                                      << "run.csv: holds no header line";
    QTest::newRow("numbers as header") << "0,1,2\n1,2,3\n"
                                       << "run.csv: line 1: holds numbers, not column names";
    QTest::newRow("empty name") << "t,,y\n0,1,2\n"
                                << "run.csv: line 1, column 2: the column name is empty";
    QTest::newRow("repeated name")
        << "t,u,u\n0,1,2\n"
        << "run.csv: line 1, column 3: the column name 'u' is used twice";
    QTest::newRow("unclosed quote")
        << "t,\"u\n"
        << "run.csv: line 1, column 2: the quote opened at character 3 is not closed";
    QTest::newRow("text after quote")
        << "t,\"u\"x\n"
        << "run.csv: line 1, column 2: text follows the closing quote";
    QTest::newRow("too many fields")
        << "t,u\n0,1\n0.01,2,3\n"
        << "run.csv: line 3, column 3: the line has 3 fields but the header names 2";
}

void TstDelimitedReader::structuralErrorsNameLineAndColumn() {
    QFETCH(QString, text);
    QFETCH(QString, expected);
    const std::string bytes = text.toStdString();
    const QString message =
        xyt::test::invalidInputMessage([&] { xyt::readDelimited(bytes, "run.csv"); });
    QVERIFY2(message.startsWith(expected), qPrintable(message));
}

void TstDelimitedReader::readsAFile() {
    const QString path = QStringLiteral(XYT_TEST_DATA_DIR) + "/experiment_step_semicolon.csv";
    const auto r = xyt::readDelimitedFile(path.toStdString());
    QCOMPARE(r.table.fileName, path.toStdString());
    QCOMPARE(r.table.names, (std::vector<std::string>{"Tempo", "Comando", "Posicao"}));
    QCOMPARE(r.table.columns[0].size(), std::size_t(5));
    QCOMPARE(r.table.columns[1][1], 2.5);
    QCOMPARE(r.table.columns[2][4], 0.125);
    bool threw = false;
    try {
        xyt::readDelimitedFile(QStringLiteral(XYT_TEST_DATA_DIR).toStdString() +
                               "/no_such_file.csv");
    } catch (const std::runtime_error& e) { // FileError
        threw = QString(e.what()).contains("no_such_file.csv");
    }
    QVERIFY(threw);
}

void TstDelimitedReader::lineEndsOfEveryConvention_data() {
    QTest::addColumn<QString>("eol");
    QTest::newRow("LF") << "\n";
    QTest::newRow("CRLF") << "\r\n";
    // Old Mac OS ended lines with CR alone: such a file was one line whose names repeated
    // ("the column name '2.0' is used twice").
    QTest::newRow("CR") << "\r";
}

void TstDelimitedReader::lineEndsOfEveryConvention() {
    QFETCH(QString, eol);
    // The same file in each convention: the same table and the same line numbers, blank line
    // included.
    const std::string text = QString("t,u,y%1%1 0,0.5,1.0%1 0.01,1.5,2.0%1").arg(eol).toStdString();
    const xyt::ExperimentTable t = xyt::readDelimited(text, "run.csv").table;
    QCOMPARE(t.names, (std::vector<std::string>{"t", "u", "y"}));
    QCOMPARE(t.columns[1], (std::vector<double>{0.5, 1.5}));
    QCOMPARE(t.columns[2], (std::vector<double>{1.0, 2.0}));
    QCOMPARE(t.rowNumbers, (std::vector<std::size_t>{3, 4}));
    // A message names the line as an editor numbers it.
    const std::string bad = QString("t,u%1 0,1%1 0.01,2,3%1").arg(eol).toStdString();
    QCOMPARE(xyt::test::invalidInputMessage([&] { xyt::readDelimited(bad, "run.csv"); }),
             QString("run.csv: line 3, column 3: the line has 3 fields but the header names 2"));
}

void TstDelimitedReader::chosenColumnsAreCheckedBeforeTheRows() {
    // Line 3 would be refused (an unclosed quote): a missing column is said first, so a file is
    // not parsed for a column it does not have.
    const char* text = "t,u,y,note\n0,1,2,a\n0.01,\"3,4,b\n";
    xyt::DelimitedReadOptions o;
    o.columns = {"u", "X"};
    QCOMPARE(xyt::test::invalidInputMessage([&] { xyt::readDelimited(text, "run.csv", o); }),
             QString("run.csv: has no column 'X'; the columns are: t, u, y, note"));
    // The kept columns only, in the file's order, with their own field numbers; the others
    // are not parsed (the text column 'note' is no problem).
    o.columns = {"y", "t"};
    const xyt::ExperimentTable t =
        xyt::readDelimited("t,u,y,note\n0,1,2,a\n0.01,3,4,b\n", "run.csv", o).table;
    QCOMPARE(t.names, (std::vector<std::string>{"t", "y"}));
    QCOMPARE(t.fieldNumbers, (std::vector<std::size_t>{1, 3}));
    QCOMPARE(t.columns[1], (std::vector<double>{2.0, 4.0}));
    QCOMPARE(t.rowNumbers, (std::vector<std::size_t>{2, 3}));
    // A row's fields are still counted for every column, kept or not.
    QCOMPARE(
        xyt::test::invalidInputMessage([&] { xyt::readDelimited("t,u\n0,1,9\n", "run.csv", o); }),
        QString("run.csv: has no column 'y'; the columns are: t, u"));
    o.columns = {"t"};
    QCOMPARE(
        xyt::test::invalidInputMessage([&] { xyt::readDelimited("t,u\n0,1,9\n", "run.csv", o); }),
        QString("run.csv: line 2, column 3: the line has 3 fields but the header names 2"));
}

void TstDelimitedReader::refusalsCarryTheirCode() {
    // The workbench translates a refusal by its code; the numbers are its arguments.
    try {
        xyt::readDelimited("t,u\n0,1,2\n", "run.csv");
        QFAIL("a line with more fields than the header was read");
    } catch (const xyt::InvalidInput& e) {
        QCOMPARE(e.field(), std::string("run.csv: line 2, column 3"));
        QCOMPARE(e.reasonDiagnostic().code, std::string("ident_csv_line_fields"));
        QCOMPARE(e.reasonDiagnostic().args.size(), std::size_t(2));
        QCOMPARE(e.reasonDiagnostic().args[0].text, std::string("3"));
        QCOMPARE(e.reasonDiagnostic().args[1].text, std::string("2"));
        QCOMPARE(e.reason(), std::string("the line has 3 fields but the header names 2"));
    }
}

QTEST_APPLESS_MAIN(TstDelimitedReader)
#include "tst_delimited_reader.moc"
