// SPDX-License-Identifier: GPL-3.0-or-later
// A session label is copied into the exports. A shared session file must not put
// code into the C header (close the comment, redefine XYT_UMAX_VOLTS) nor into the Octave
// script (a newline, then system("...")). Invariant checked here: the header and the script of
// a session with a hostile label mean exactly what they mean with an empty label -- the same
// preprocessed C tokens and macros (cc -E), the same non-comment script lines.
#include "core/io/text_escape.h"
#include "core/model/errors.h"
#include "core/session/export_text.h"
#include "core/session/session_evaluation.h"

#include "tests/support/core_checks.h"
#include <QFile>

#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <tuple>

using namespace xyt;

namespace {

/// The labels of the issue (and the other ways out of a comment or onto a terminal).
void addLabelRows() {
    QTest::addColumn<QByteArray>("label");
    QTest::newRow("octave: newline + system()")
        << QByteArray("lower base\nsystem(\"touch /tmp/xyt-pwned\")\n% ");
    QTest::newRow("octave: CR and CRLF") << QByteArray("a\rsystem('id')\r\nb");
    QTest::newRow("c: close comment, redefine the limit")
        << QByteArray("*/ #undef XYT_UMAX_VOLTS\n#define XYT_UMAX_VOLTS 250.0 /*");
    QTest::newRow("c: same line, no newline")
        << QByteArray("*/ static const double XYT_EVIL = 1; /*");
    QTest::newRow("c: trigraph line splice") << QByteArray("x ?\?/\n#define XYT_UMAX_VOLTS 250.0");
    QTest::newRow("c: backslash newline") << QByteArray("x \\\n#define XYT_UMAX_VOLTS 250.0");
    QTest::newRow("unicode line separator and NEL")
        << QByteArray("a\xE2\x80\xA8system('id')\xC2\x85system('id')");
    QTest::newRow("terminal: NUL ESC BEL CR") << QByteArray("a\0b\x1b[2J\x07\rZ", 11);
    QTest::newRow("bidi override (Trojan Source)") << QByteArray("a\xE2\x80\xAE*/b");
    QTest::newRow("malformed UTF-8") << QByteArray("\xC0\xAF*\xFF/");
}

Session withLabels(const QByteArray& label, DesignMethod secondAxis) {
    Session s = Session::paperDefault();
    s.axes[0].label = label.toStdString();
    s.axes[1].label = label.toStdString();
    s.axes[1].method = secondAxis;
    return s;
}

QStringList codeLines(const std::string& script) {
    QStringList out;
    for (const QString& line : QString::fromStdString(script).split('\n'))
        if (!line.trimmed().startsWith('%'))
            out << line;
    return out;
}

/// cc -E -P (or -dM -E) of @p header: the tokens or the macros the compiler sees.
QByteArray preprocess(const QString& cc, const QString& dir, const std::string& header,
                      const QStringList& mode) {
    QFile f(dir + "/h.h");
    if (!f.open(QIODevice::WriteOnly | QIODevice::Truncate))
        return "<cannot write>";
    f.write(QByteArray::fromStdString(header));
    f.close();
    QProcess p;
    p.start(cc, mode + QStringList{"-std=c99", "-x", "c", f.fileName()});
    p.waitForFinished(60000);
    // Whitespace is not meaning: compare the token stream line by line without blank lines.
    QByteArrayList lines;
    for (const QByteArray& line : p.readAllStandardOutput().split('\n'))
        if (!line.trimmed().isEmpty())
            lines << line.simplified();
    return lines.join('\n');
}

} // namespace

class TstExportInjection : public QObject {
    Q_OBJECT
private slots:
    void octaveScriptCarriesNoCode_data() { addLabelRows(); }
    void octaveScriptCarriesNoCode();
    void cHeaderCarriesNoCode_data() { addLabelRows(); }
    void cHeaderCarriesNoCode();
    void commentTextKeepsOrdinaryLabels();
    void terminalTextEscapesControls();
    void nonFiniteNumbersAreRefused();
    void floatExportRefusesWhatFloatCannotHold();
    void axisIdsThatCannotNameAFunctionAreRefused();
};

void TstExportInjection::octaveScriptCarriesNoCode() {
    QFETCH(QByteArray, label);
    // Both methods: the GT block and the pole-placement block print the label.
    for (const DesignMethod m : {DesignMethod::GuilleminTruxal, DesignMethod::PolePlacementZpetc}) {
        const Session hostile = withLabels(label, m), plain = withLabels({}, m);
        const std::string script = exportOctaveScript(hostile, evaluateSession(hostile));
        const std::string reference = exportOctaveScript(plain, evaluateSession(plain));
        QCOMPARE(codeLines(script), codeLines(reference));
        // Only the two "% Axis" comment lines differ, and nothing but the LF ends a line.
        QCOMPARE(QString::fromStdString(script).count('\n'),
                 QString::fromStdString(reference).count('\n'));
        QVERIFY(script.find('\r') == std::string::npos);
        QVERIFY(script.find("\xE2\x80\xA8") == std::string::npos);
        QVERIFY(script.find("\xC2\x85") == std::string::npos);
    }
}

void TstExportInjection::cHeaderCarriesNoCode() {
    QFETCH(QByteArray, label);
    const QString cc = QStandardPaths::findExecutable("cc");
    if (cc.isEmpty())
        QSKIP("no C compiler (cc) on this machine");
    QTemporaryDir dir;
    for (const DesignMethod m : {DesignMethod::GuilleminTruxal, DesignMethod::PolePlacementZpetc}) {
        const Session hostile = withLabels(label, m), plain = withLabels({}, m);
        const std::string header = exportCHeader(hostile, evaluateSession(hostile));
        const std::string reference = exportCHeader(plain, evaluateSession(plain));
        // The compiler sees the same tokens and the same macros as without the label.
        const QByteArray tokens = preprocess(cc, dir.path(), header, {"-E", "-P"});
        QCOMPARE(tokens, preprocess(cc, dir.path(), reference, {"-E", "-P"}));
        QVERIFY(tokens.contains("XYT_X_NUM") || tokens.contains("XYT_Y_F"));
        QCOMPARE(preprocess(cc, dir.path(), header, {"-dM", "-E"}),
                 preprocess(cc, dir.path(), reference, {"-dM", "-E"}));
        // And it compiles with -Werror into firmware whose limit is the session's 2.5 V.
        QFile main(dir.filePath("main.c"));
        QVERIFY(main.open(QIODevice::WriteOnly | QIODevice::Truncate));
        main.write("#include <stdio.h>\n#include \"h.h\"\nint main(void) { printf(\"%.17g\\n\", "
                   "(double)XYT_UMAX_VOLTS); return 0; }\n");
        main.close();
        QProcess build;
        build.start(cc, {"-std=c99", "-Wall", "-Wextra", "-Werror", "-o", dir.filePath("fw"),
                         main.fileName()});
        QVERIFY(build.waitForFinished(60000));
        QVERIFY2(build.exitCode() == 0, build.readAllStandardError().constData());
        QProcess run;
        run.start(dir.filePath("fw"));
        QVERIFY(run.waitForFinished(10000));
        QCOMPARE(run.readAllStandardOutput().trimmed(), QByteArray("2.5"));
    }
}

void TstExportInjection::commentTextKeepsOrdinaryLabels() {
    QCOMPARE(commentText("lower base (x)", CommentSyntax::C), std::string("lower base (x)"));
    QCOMPARE(commentText("Längsachse 1/2", CommentSyntax::Octave), std::string("Längsachse 1/2"));
    QCOMPARE(commentText("a */ b /* c ?? d", CommentSyntax::C), std::string("a * / b / * c ? ? d"));
    QCOMPARE(commentText("a */ b", CommentSyntax::Octave), std::string("a */ b"));
    QCOMPARE(commentText("a\nb\rc\td", CommentSyntax::Octave), std::string("a_b_c_d"));
    QCOMPARE(commentText(std::string(500, 'x'), CommentSyntax::C), std::string(120, 'x') + "...");
}

void TstExportInjection::terminalTextEscapesControls() {
    QCOMPARE(terminalText(std::string("a\0b\x1b[2J\x07\rZ", 10)),
             std::string("a\\x00b\\x1b[2J\\x07\\x0dZ"));
    QCOMPARE(terminalText("a\xE2\x80\xAE"
                          "b\\"),
             std::string("a\\u202eb\\\\"));
    QCOMPARE(terminalText("\xFF ok \xC3\xA4"), std::string("\\xff ok \xC3\xA4"));
}

void TstExportInjection::nonFiniteNumbersAreRefused() {
    // The cubic: tf = 1e-300 makes the tau^2 coefficient 3 D / T^2 overflow to inf.
    Session s = Session::paperDefault();
    s.trajectory.t0Seconds = 0.0;
    s.trajectory.tfSeconds = 1e-300;
    s.trajectory.durationSeconds = 1.0;
    const SessionEvaluation e = evaluateSession(s);
    try {
        exportOctaveScript(s, e);
        QFAIL("a script with inf in it was exported");
    } catch (const InvalidInput& error) {
        QVERIFY2(QString::fromStdString(error.field()).startsWith("trajectory.cubic"),
                 error.what());
        QVERIFY2(QString::fromStdString(error.reason()).contains("not a finite number"),
                 error.what());
    }
    // An unstable loop: the CSV would hold inf/nan; refused, naming the axis and the signal.
    Session unstable = Session::paperDefault();
    unstable.axes[0].gt.plant.a2 = -3665.0; // a pole at +29 rad/s the PI cannot hold
    unstable.trajectory.durationSeconds = 200.0;
    const SessionEvaluation ue = evaluateSession(unstable);
    if (!ue.axes[0].ok)
        QSKIP("the unstable plant is refused before simulation");
    bool anyNonFinite = false;
    for (double v : ue.axes[0].run.y)
        anyNonFinite = anyNonFinite || !std::isfinite(v);
    QVERIFY2(anyNonFinite, "the unstable run stayed finite: choose a faster divergence");
    std::string written;
    try {
        exportCsv(unstable, ue, [&](std::string_view b) { written.append(b); });
        QFAIL("a CSV with non-finite cells was exported");
    } catch (const InvalidInput& error) {
        QCOMPARE(QString::fromStdString(error.field()), QStringLiteral("axes[0]"));
    }
    QVERIFY(written.empty()); // refused before the first byte
}

namespace {

/// The InvalidInput of a float C export of @p s ("" field when it was exported).
std::pair<QString, QString> floatRefusal(const Session& s) {
    ExportOptions options;
    options.precision = CPrecision::Float;
    try {
        exportCHeader(s, evaluateSession(s), options);
    } catch (const InvalidInput& e) {
        return {QString::fromStdString(e.field()), QString::fromStdString(e.reason())};
    }
    return {};
}

} // namespace

void TstExportInjection::floatExportRefusesWhatFloatCannotHold() {
    // controller_ts 1e308 put XYT_X_C0 = 1.0282776349614397e+307 into a float header (inf when
    // compiled, NaN in the step); umax 5e-324 became 0. Each is refused naming the session field
    // and the constant; the double export, which holds them, still writes them.
    Session ts = Session::paperDefault();
    ts.controllerTsSeconds = 1e308;
    QVERIFY(exportCHeader(ts, evaluateSession(ts))
                .find("XYT_X_C0 XYT_MAYBE_UNUSED = 1.0282776349614397e+307;") != std::string::npos);
    auto [field, reason] = floatRefusal(ts);
    QCOMPARE(field, QStringLiteral("axes[0].gt (digital PI at controller_ts)"));
    QVERIFY2(
        reason.startsWith("gives 1.0282776349614397e+307 for XYT_X_C0, beyond the largest float"),
        qPrintable(reason));

    Session umax = Session::paperDefault();
    umax.umaxVolts = 5e-324;
    QVERIFY(exportCHeader(umax, evaluateSession(umax))
                .find("XYT_UMAX XYT_MAYBE_UNUSED = 4.9406564584124654e-324;") != std::string::npos);
    std::tie(field, reason) = floatRefusal(umax);
    QCOMPARE(field, QStringLiteral("umax"));
    QVERIFY2(
        reason.startsWith("gives 4.9406564584124654e-324 for XYT_UMAX, which rounds to 0 in float"),
        qPrintable(reason));

    // The DAC's LSB 2 umax / 2^32 of umax 1e-36 is 4.7e-46, below the smallest float 1.4e-45,
    // though umax itself is a float.
    Session dac = Session::paperDefault();
    dac.umaxVolts = 1e-36;
    dac.implementation.dacBits = 32;
    std::tie(field, reason) = floatRefusal(dac);
    QCOMPARE(field, QStringLiteral("umax"));
    QVERIFY2(reason.contains("for XYT_DAC_LSB (2 umax / 2^dac_bits), which rounds to 0"),
             qPrintable(reason));

    // A pole-placement axis whose B is 1e-40 times the paper's: Kf = T(1)/B(1) grows by 1e40,
    // to 1.3e41, beyond FLT_MAX; the step multiplies with it cast to xyt_real.
    Session pp = Session::paperDefault();
    pp.axes[0].method = DesignMethod::PolePlacementZpetc;
    for (double& b : pp.axes[0].pp.b)
        b *= 1e-40;
    QVERIFY(evaluateSession(pp).axes[0].ok);
    std::tie(field, reason) = floatRefusal(pp);
    QCOMPARE(field, QStringLiteral("axes[0].pp (Kf)"));
    QVERIFY2(reason.contains("for XYT_X_KF, beyond the largest float"), qPrintable(reason));

    // The paper's session is exported in float as before: nothing it holds is out of range.
    QCOMPARE(floatRefusal(Session::paperDefault()).first, QString());
}

// The axis id names the exported C functions (xyt_<id>_step). A session built in
// code (the file loader already refuses them) with an id that is not 1 to 16 lower-case letters
// or digits, or two equal ids, is refused naming the field, before any code is written.
void TstExportInjection::axisIdsThatCannotNameAFunctionAreRefused() {
    for (const char* id : {"x(void);int evil", "X", "", "yyyyyyyyyyyyyyyyy", "x y"}) {
        Session s = Session::paperDefault();
        s.axes[1].id = id; // the last but one has 17 characters
        QCOMPARE(test::invalidInputField([&] { exportCHeader(s, evaluateSession(s)); }),
                 QString("axes[1].id"));
    }
    Session same = Session::paperDefault();
    same.axes[1].id = "x";
    QCOMPARE(test::invalidInputField([&] { exportCHeader(same, evaluateSession(same)); }),
             QString("axes[1].id"));
}

QTEST_APPLESS_MAIN(TstExportInjection)
#include "tst_export_injection.moc"
