// SPDX-License-Identifier: GPL-3.0-or-later
// parseCoefficientList / parseNumber: the accepted spellings and the refused ones.
#include "core/model/coefficient_parser.h"
#include "core/model/errors.h"

#include <QTest>

class TstCoefficientParser : public QObject {
    Q_OBJECT
private slots:
    void accepts_data();
    void accepts();
    void refuses_data();
    void refuses();
    void parseNumberWholeText();
    void refusalsAreCoded();
};

void TstCoefficientParser::accepts_data() {
    QTest::addColumn<QString>("text");
    QTest::addColumn<QList<double>>("expected");
    // Values are exactly representable or parsed by from_chars to the nearest double, so the
    // comparison is exact against the same literals.
    QTest::newRow("spaces, A(z^-1) of Patrick, Ishak and Adnan")
        << "1 -1.6580 0.6583" << QList<double>{1.0, -1.6580, 0.6583};
    QTest::newRow("MATLAB brackets and commas")
        << "[0.0421, 0.0628, -0.0454]" << QList<double>{0.0421, 0.0628, -0.0454};
    QTest::newRow("semicolons, tabs, newlines")
        << "1;\t125.3\n3665 ; 0" << QList<double>{1.0, 125.3, 3665.0, 0.0};
    QTest::newRow("exponents and plus sign")
        << "+2e3 -1.5E-2 .5" << QList<double>{2000.0, -0.015, 0.5};
    QTest::newRow("surrounding separators") << "  ,1,  " << QList<double>{1.0};
    QTest::newRow("64 coefficients (the limit)")
        << QString("1 ").repeated(64) << QList<double>(64, 1.0);
}

void TstCoefficientParser::accepts() {
    QFETCH(QString, text);
    QFETCH(QList<double>, expected);
    const std::vector<double> got = xyt::parseCoefficientList(text.toStdString(), "den");
    QCOMPARE(got, (std::vector<double>(expected.begin(), expected.end())));
}

void TstCoefficientParser::refuses_data() {
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("field");
    QTest::newRow("empty") << ""
                           << "den";
    QTest::newRow("only separators") << " , ; "
                                     << "den";
    QTest::newRow("empty brackets") << "[ ]"
                                    << "den";
    QTest::newRow("unclosed bracket") << "[1 2"
                                      << "den";
    QTest::newRow("word") << "1 abc 3"
                          << "den[1]";
    QTest::newRow("trailing garbage") << "1 2x"
                                      << "den[1]";
    QTest::newRow("nan") << "1 nan"
                         << "den[1]";
    QTest::newRow("NaN") << "NaN"
                         << "den[0]";
    QTest::newRow("inf") << "inf 1"
                         << "den[0]";
    QTest::newRow("-infinity") << "1 2 -infinity"
                               << "den[2]";
    QTest::newRow("overflow 1e999") << "1e999"
                                    << "den[0]";
    QTest::newRow("65 coefficients") << QString("1 ").repeated(65) << "den";
    QTest::newRow("double sign") << "--1"
                                 << "den[0]";
}

void TstCoefficientParser::refuses() {
    QFETCH(QString, text);
    QFETCH(QString, field);
    try {
        xyt::parseCoefficientList(text.toStdString(), "den");
        QFAIL("accepted");
    } catch (const xyt::InvalidInput& e) {
        QCOMPARE(QString::fromStdString(e.field()), field);
    }
}

void TstCoefficientParser::parseNumberWholeText() {
    QCOMPARE(xyt::parseNumber(" 2.5\t", "--wn"), 2.5);
    QCOMPARE(xyt::parseNumber("+30", "--kp"), 30.0);
    for (const char* bad : {"", "2.5 3", "1,5", "0x10", "nan", "-inf", "1e400", "+"}) {
        try {
            xyt::parseNumber(bad, "--wn");
            QFAIL(bad);
        } catch (const xyt::InvalidInput& e) {
            QCOMPARE(QString::fromStdString(e.field()), QString("--wn"));
        }
    }
}

void TstCoefficientParser::refusalsAreCoded() {
    // The reason carries its catalogue code and, as its argument, the quoted text or the limit.
    try {
        xyt::parseCoefficientList("1 abc 3", "den");
        QFAIL("accepted");
    } catch (const xyt::InvalidInput& e) {
        QCOMPARE(e.reasonDiagnostic().code, std::string("model_not_a_number_text"));
        QCOMPARE(e.reasonDiagnostic().args.size(), std::size_t(1));
        QCOMPARE(e.reasonDiagnostic().args.at(0).text, std::string("'abc'"));
        QCOMPARE(std::string(e.what()), std::string("den[1]: 'abc' is not a number"));
    }
    try {
        xyt::parseCoefficientList(QString("1 ").repeated(65).toStdString(), "den");
        QFAIL("accepted");
    } catch (const xyt::InvalidInput& e) {
        QCOMPARE(e.reasonDiagnostic().code, std::string("model_too_many_coefficients"));
        QCOMPARE(e.reasonDiagnostic().args.at(0).text, std::string("64"));
        QCOMPARE(std::string(e.what()), std::string("den: more than 64 coefficients"));
    }
}

QTEST_APPLESS_MAIN(TstCoefficientParser)
#include "tst_coefficient_parser.moc"
