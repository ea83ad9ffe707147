// SPDX-License-Identifier: GPL-3.0-or-later
// Every xytune-cli command on a table of bad inputs (non-numbers, empty lists, huge
// orders, Inf/NaN, zero leading coefficients, negative times, durations that would need
// gigabytes, bad grid specs, a directory or a truncated file as the session). The contract
// (app/cli_main.cpp): exit code 2, exactly one line on stderr naming the argument, nothing on
// stdout, and a prompt answer: each run must finish within 20 s (the bound only catches hangs
// and runaway allocations; normal runs take well under a second, even under ASan).
#include "tests/support/cli_runner.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QMap>

#include <QTemporaryDir>
#include <QTest>
#include <functional>

namespace {

constexpr int kTimeBoundMs = 20000;

/// n coefficients "1 1 1 ..." (65 is one more than kMaxCoefficients).
QString manyCoefficients(int n) {
    QStringList c;
    for (int i = 0; i < n; ++i)
        c << QStringLiteral("1");
    return c.join(' ');
}

const QStringList kGt = {"gt", "--preset", "lower-base"};
const QStringList kCubic = {"--trajectory", "cubic", "--xf", "600", "--tf", "130"};
const QStringList kPpX = {"--a",   "1 -1.6580 0.6583", "--b", "0 0.0421 0.0628 -0.0454", "--t",
                          "1 -0.2"};

} // namespace

class TstCliBadInput : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void badInputExitsWithTwoAndNamesTheArgument_data();
    void badInputExitsWithTwoAndNamesTheArgument();
    void sampleCountBoundedByPhysicalMemory_data();
    void sampleCountBoundedByPhysicalMemory();

private:
    /// @p s with "{default}", "{dir}", "{one-sample}" ... replaced by the files of initTestCase.
    QString substitute(QString s) const;
    /// Runs the CLI on @p args after substitute(); @p names is substituted in place.
    xyt::test::CliRun runWithFiles(QStringList args, QString& names,
                                   const QStringList& environment) const;

    QTemporaryDir dir_;
    QString defaultSession_, truncatedSession_, binarySession_;
    /// Sessions derived from the default one ("{name}" in the table), see initTestCase.
    QMap<QString, QString> variants_;
};

void TstCliBadInput::initTestCase() {
    QVERIFY(dir_.isValid());
    defaultSession_ = dir_.filePath("default.json");
    const auto created = xyt::test::runCli({"new", "-o", defaultSession_}, kTimeBoundMs);
    QVERIFY2(created.finished && created.exitCode == 0, created.err.constData());
    QFile full(defaultSession_);
    QVERIFY(full.open(QIODevice::ReadOnly));
    const QByteArray bytes = full.readAll();
    QVERIFY(bytes.size() > 100);
    // Cut in the middle of the document, as a crash during a save by another program would.
    truncatedSession_ = dir_.filePath("truncated.json");
    QFile truncated(truncatedSession_);
    QVERIFY(truncated.open(QIODevice::WriteOnly));
    truncated.write(bytes.left(bytes.size() / 2));
    binarySession_ = dir_.filePath("binary.json");
    QFile binary(binarySession_);
    QVERIFY(binary.open(QIODevice::WriteOnly));
    binary.write(QByteArray("\x00\xff\xfe{\x01\n\x02", 7));

    // Sessions whose run is refused (one sample, a position out of range, a run that
    // does not fit in memory) or whose export would carry inf.
    const QJsonObject base = QJsonDocument::fromJson(bytes).object();
    const auto variant = [&](const QString& name, const std::function<void(QJsonObject&)>& edit) {
        QJsonObject s = base;
        edit(s);
        const QString path = dir_.filePath(name + ".json");
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(QJsonDocument(s).toJson());
        variants_.insert("{" + name + "}", path);
    };
    const auto setIn = [](QJsonObject& o, const QStringList& path, double v) {
        // o[path[0]]...[path[n-1]] = v (objects only)
        std::function<void(QJsonObject&, int)> go = [&](QJsonObject& at, int i) {
            if (i + 1 == path.size()) {
                at.insert(path[i], v);
                return;
            }
            QJsonObject child = at.value(path[i]).toObject();
            go(child, i + 1);
            at.insert(path[i], child);
        };
        go(o, 0);
    };
    variant("one-sample", [&](QJsonObject& s) { setIn(s, {"trajectory", "dt"}, 1000.0); });
    variant("xf-1e308", [&](QJsonObject& s) { setIn(s, {"trajectory", "cubic", "xf"}, 1e308); });
    variant("radius-1e308", [&](QJsonObject& s) {
        QJsonObject t = s.value("trajectory").toObject();
        t.insert("kind", "circle");
        s.insert("trajectory", t);
        setIn(s, {"trajectory", "circle", "radius"}, 1e308);
    });
    const auto ppAxes = [](QJsonObject& s) {
        QJsonArray axes = s.value("axes").toArray();
        for (qsizetype i = 0; i < axes.size(); ++i) {
            QJsonObject a = axes[i].toObject();
            a.insert("method", "pole-placement-zpetc");
            axes[i] = a;
        }
        s.insert("axes", axes);
    };
    variant("pp-one-sample", [&](QJsonObject& s) {
        ppAxes(s);
        setIn(s, {"trajectory", "duration"}, 0.01); // shorter than Ts = 0.07 s
    });
    // 1e8 samples at the session's dt 0.01 (refused at load), 14.3 million at the axes' Ts 0.07.
    variant("pp-long", [&](QJsonObject& s) {
        ppAxes(s);
        setIn(s, {"trajectory", "duration"}, 1e6);
    });
    // kp + ki Ts/2 of the Tustin PI overflows with Ts = 1e308 (ki = wn^4/k0 = 128.5 at wn 10).
    variant("digital-pi-inf", [&](QJsonObject& s) {
        setIn(s, {"controller_ts"}, 1e308);
        QJsonArray axes = s.value("axes").toArray();
        QJsonObject x = axes[0].toObject();
        QJsonObject gt = x.value("gt").toObject();
        gt.insert("wn", 10.0);
        x.insert("gt", gt);
        axes[0] = x;
        s.insert("axes", axes);
    });
    // Constants a float header cannot hold (the double header holds them).
    variant("ts-1e308", [&](QJsonObject& s) { setIn(s, {"controller_ts"}, 1e308); });
    variant("umax-5e-324", [&](QJsonObject& s) { setIn(s, {"umax"}, 5e-324); });
}

void TstCliBadInput::badInputExitsWithTwoAndNamesTheArgument_data() {
    QTest::addColumn<QStringList>("args");
    // A substring of the one stderr line: the argument as typed ("--wn"), or the file path
    // ("{dir}" etc. are replaced by the files made in initTestCase).
    QTest::addColumn<QString>("names");

    const QString huge = manyCoefficients(65);

    // gt
    QTest::newRow("gt wn not a number") << kGt + QStringList{"--wn", "abc"} << "--wn";
    QTest::newRow("gt wn empty") << kGt + QStringList{"--wn", ""} << "--wn";
    QTest::newRow("gt kp NaN") << kGt + QStringList{"--kp", "nan"} << "--kp";
    QTest::newRow("gt kp Inf") << kGt + QStringList{"--kp", "inf"} << "--kp";
    QTest::newRow("gt kp overflows a double") << kGt + QStringList{"--kp", "1e999"} << "--kp";
    QTest::newRow("gt wn negative") << kGt + QStringList{"--wn", "-2"} << "--wn";
    QTest::newRow("gt k0 zero (leading coefficient of the plant)")
        << QStringList{"gt",   "--k0", "0", "--a1", "125.3", "--a2",
                       "3665", "--wn", "2", "--kp", "30"}
        << "--k0";
    QTest::newRow("gt a1 -Inf") << QStringList{"gt",   "--k0", "77.8", "--a1", "-inf", "--a2",
                                               "3665", "--wn", "2",    "--kp", "30"}
                                << "--a1";
    QTest::newRow("gt unknown preset") << QStringList{"gt", "--preset", "middle"} << "--preset";
    QTest::newRow("gt unknown option") << kGt + QStringList{"--bogus", "1"} << "--bogus";
    QTest::newRow("gt option without value") << kGt + QStringList{"--wn"} << "--wn";
    QTest::newRow("gt option twice") << kGt + QStringList{"--wn", "2", "--wn", "3"} << "--wn";
    QTest::newRow("gt control characters in a value")
        << kGt + QStringList{"--preset", "a\nb\rc"} << "--preset";

    // simulate
    QTest::newRow("simulate negative tf")
        << QStringList{"simulate", "--preset", "lower-base", "--trajectory", "cubic",
                       "--xf",     "600",      "--tf",       "-130"}
        << "--tf";
    QTest::newRow("simulate negative dt")
        << QStringList{"simulate", "--preset", "lower-base"} + kCubic + QStringList{"--dt", "-0.01"}
        << "--dt";
    QTest::newRow("simulate zero dt")
        << QStringList{"simulate", "--preset", "lower-base"} + kCubic + QStringList{"--dt", "0"}
        << "--dt";
    QTest::newRow("simulate negative duration")
        << QStringList{"simulate", "--preset", "lower-base"} + kCubic +
               QStringList{"--duration", "-1"}
        << "--duration";
    QTest::newRow("simulate duration needing gigabytes")
        << QStringList{"simulate", "--preset", "lower-base"} + kCubic +
               QStringList{"--duration", "1e9"}
        << "--duration";
    QTest::newRow("simulate dt needing gigabytes")
        << QStringList{"simulate", "--preset", "lower-base"} + kCubic + QStringList{"--dt", "1e-9"}
        << "--dt"; // not --duration: the user did not type it
    QTest::newRow("simulate digital dac bits 33")
        << QStringList{"simulate", "--preset", "lower-base", "--digital", "--dac-bits", "33"} +
               kCubic
        << "--dac-bits";
    QTest::newRow("simulate digital negative delay")
        << QStringList{"simulate", "--preset", "lower-base", "--digital", "--delay-samples", "-1"} +
               kCubic
        << "--delay-samples";
    QTest::newRow("simulate digital negative encoder")
        << QStringList{"simulate", "--preset", "lower-base", "--digital", "--encoder-resolution",
                       "-1"} +
               kCubic
        << "--encoder-resolution";
    QTest::newRow("simulate digital unknown anti-windup")
        << QStringList{"simulate",  "--preset",      "lower-base",
                       "--digital", "--anti-windup", "reset"} +
               kCubic
        << "--anti-windup";
    QTest::newRow("simulate digital zero controller ts")
        << QStringList{"simulate", "--preset", "lower-base", "--digital", "--controller-ts", "0"} +
               kCubic
        << "--controller-ts";
    QTest::newRow("simulate digital controller ts needing gigabytes")
        << QStringList{"simulate",  "--preset",        "lower-base",
                       "--digital", "--controller-ts", "1e-9"} +
               kCubic
        << "--controller-ts";
    QTest::newRow("simulate digital negative tracking time")
        << QStringList{"simulate", "--preset", "lower-base", "--digital", "--tracking-time", "-1"} +
               kCubic
        << "--tracking-time";
    QTest::newRow("simulate umax zero")
        << QStringList{"simulate", "--preset", "lower-base"} + kCubic + QStringList{"--umax", "0"}
        << "--umax";
    QTest::newRow("simulate umax NaN")
        << QStringList{"simulate", "--preset", "lower-base"} + kCubic + QStringList{"--umax", "NaN"}
        << "--umax";
    QTest::newRow("simulate unknown trajectory")
        << QStringList{"simulate", "--preset", "lower-base", "--trajectory", "square"}
        << "--trajectory";
    QTest::newRow("simulate sine omega Inf")
        << QStringList{"simulate",    "--preset", "lower-base", "--trajectory", "sine",
                       "--amplitude", "25",       "--omega",    "Infinity"}
        << "--omega";
    QTest::newRow("simulate sine omega tiny (period needing gigabytes)")
        << QStringList{"simulate",    "--preset", "lower-base", "--trajectory", "sine",
                       "--amplitude", "25",       "--omega",    "1e-300"}
        << "--omega";
    QTest::newRow("simulate csv into a directory")
        << QStringList{"simulate", "--preset", "lower-base"} + kCubic +
               QStringList{"--csv", "{dir}"}
        << "--csv";

    // report, new, export: session files
    QTest::newRow("report directory") << QStringList{"report", "{dir}"} << "{dir}";
    QTest::newRow("report truncated file") << QStringList{"report", "{truncated}"} << "{truncated}";
    QTest::newRow("report binary file") << QStringList{"report", "{binary}"} << "{binary}";
    QTest::newRow("report missing file")
        << QStringList{"report", "{dir}/missing.json"} << "{dir}/missing.json";
    QTest::newRow("report two files")
        << QStringList{"report", "{default}", "{default}"} << "SESSION";
    QTest::newRow("new without output") << QStringList{"new"} << "-o";
    QTest::newRow("new into a directory") << QStringList{"new", "-o", "{dir}"} << "-o";
    QTest::newRow("export directory")
        << QStringList{"export", "{dir}", "--format", "json", "-o", "{dir}/out.json"} << "{dir}";
    QTest::newRow("export truncated file")
        << QStringList{"export", "{truncated}", "--format", "c", "-o", "{dir}/out.h"}
        << "{truncated}";
    QTest::newRow("export unknown format")
        << QStringList{"export", "{default}", "--format", "xls", "-o", "{dir}/out.xls"}
        << "--format";
    QTest::newRow("export into a directory")
        << QStringList{"export", "{default}", "--format", "m", "-o", "{dir}"} << "-o";
    QTest::newRow("export unknown discretization")
        << QStringList{"export", "{default}",    "--format",         "json",
                       "-o",     "{dir}/o.json", "--discretization", "zoh"}
        << "--discretization";
    QTest::newRow("export unknown precision")
        << QStringList{"export", "{default}", "--format",    "c",
                       "-o",     "{dir}/o.h", "--precision", "half"}
        << "--precision";
    QTest::newRow("export precision for json")
        << QStringList{"export", "{default}",    "--format",    "json",
                       "-o",     "{dir}/o.json", "--precision", "float"}
        << "--precision";

    // rlocus
    QTest::newRow("rlocus empty num")
        << QStringList{"rlocus", "--num", "", "--den", "1 2 0"} << "--num";
    QTest::newRow("rlocus separators only")
        << QStringList{"rlocus", "--num", " , ;", "--den", "1 2"} << "--num";
    QTest::newRow("rlocus den not a number")
        << QStringList{"rlocus", "--num", "1", "--den", "1 two 3"} << "--den";
    QTest::newRow("rlocus den 65 coefficients")
        << QStringList{"rlocus", "--num", "1", "--den", huge} << "--den";
    QTest::newRow("rlocus num Inf")
        << QStringList{"rlocus", "--num", "1 inf", "--den", "1 2 3"} << "--num";
    QTest::newRow("rlocus den NaN")
        << QStringList{"rlocus", "--num", "1", "--den", "1 nan 3"} << "--den";
    QTest::newRow("rlocus den zero")
        << QStringList{"rlocus", "--num", "1", "--den", "0 0"} << "--den";
    QTest::newRow("rlocus improper after a zero leading coefficient")
        << QStringList{"rlocus", "--num", "1 2 3", "--den", "0 1 2"} << "--num";
    QTest::newRow("rlocus unbalanced bracket")
        << QStringList{"rlocus", "--num", "[1 2", "--den", "1 2 3"} << "--num";
    QTest::newRow("rlocus negative ts")
        << QStringList{"rlocus", "--num", "0 1", "--den", "1 -0.5", "--ts", "-0.1"} << "--ts";
    QTest::newRow("rlocus kmax negative")
        << QStringList{"rlocus", "--num", "1", "--den", "1 2 0", "--kmax", "-1"} << "--kmax";
    QTest::newRow("rlocus max-step zero")
        << QStringList{"rlocus", "--num", "1", "--den", "1 2 0", "--max-step", "0"} << "--max-step";
    QTest::newRow("rlocus max-step NaN")
        << QStringList{"rlocus", "--num", "1", "--den", "1 2 0", "--max-step", "nan"}
        << "--max-step";
    QTest::newRow("rlocus max-points zero")
        << QStringList{"rlocus", "--num", "1", "--den", "1 2 0", "--max-points", "0"}
        << "--max-points";
    QTest::newRow("rlocus max-points huge")
        << QStringList{"rlocus", "--num", "1", "--den", "1 2 0", "--max-points", "99999999999"}
        << "--max-points";
    QTest::newRow("rlocus gt preset with wn Inf")
        << QStringList{"rlocus", "--gt-preset", "lower-base", "--wn", "inf"} << "--wn";

    // sweep
    const QStringList sweep = QStringList{"sweep", "--preset", "lower-base"} + kCubic;
    QTest::newRow("sweep grid without N")
        << sweep + QStringList{"--wn", "1:2", "--kp", "10:20:3"} << "--wn";
    QTest::newRow("sweep grid N zero")
        << sweep + QStringList{"--wn", "1:2:0", "--kp", "10:20:3"} << "--wn";
    QTest::newRow("sweep grid N huge")
        << sweep + QStringList{"--wn", "1:2:3", "--kp", "10:20:100000"} << "--kp";
    QTest::newRow("sweep grid N not whole")
        << sweep + QStringList{"--wn", "1:2:2.5", "--kp", "1:2:3"} << "--wn";
    QTest::newRow("sweep grid NaN")
        << sweep + QStringList{"--wn", "nan:2:3", "--kp", "10:20:3"} << "--wn";
    QTest::newRow("sweep grid Inf")
        << sweep + QStringList{"--wn", "1:inf:3", "--kp", "10:20:3"} << "--wn";
    QTest::newRow("sweep grid words")
        << sweep + QStringList{"--wn", "a:b:c", "--kp", "10:20:3"} << "--wn";
    QTest::newRow("sweep log grid through zero")
        << sweep + QStringList{"--wn", "0:2:3", "--kp", "10:20:3", "--log"} << "--wn";
    QTest::newRow("sweep negative wn")
        << sweep + QStringList{"--wn", "-2:-1:3", "--kp", "10:20:3"} << "--wn";
    QTest::newRow("sweep threads zero")
        << sweep + QStringList{"--wn", "1:2:3", "--kp", "10:20:3", "--threads", "0"} << "--threads";
    QTest::newRow("sweep unknown criterion")
        << sweep + QStringList{"--wn", "1:2:3", "--kp", "10:20:3", "--criterion", "fast"}
        << "--criterion";
    QTest::newRow("sweep duration needing gigabytes")
        << sweep + QStringList{"--wn", "1:2:3", "--kp", "10:20:3", "--duration", "1e10"}
        << "--duration";

    // pp, zpetc, contour
    QTest::newRow("pp a leading zero")
        << QStringList{"pp", "--a", "0 1 0.5", "--b", "0 0.04 0.06", "--t", "1 -0.2"} << "--a";
    QTest::newRow("pp b without delay")
        << QStringList{"pp", "--a", "1 -1.658 0.6583", "--b", "0.04 0.06", "--t", "1 -0.2"}
        << "--b";
    QTest::newRow("pp b all zero")
        << QStringList{"pp", "--a", "1 -1.658 0.6583", "--b", "0 0", "--t", "1 -0.2"} << "--b";
    QTest::newRow("pp t not monic")
        << QStringList{"pp", "--a", "1 -1.658 0.6583", "--b", "0 0.04", "--t", "2 -0.2"} << "--t";
    QTest::newRow("pp empty a") << QStringList{"pp", "--a", "", "--b", "0 0.04", "--t", "1"}
                                << "--a";
    QTest::newRow("pp a 65 coefficients")
        << QStringList{"pp", "--a", huge, "--b", "0 0.04", "--t", "1"} << "--a";
    QTest::newRow("pp b NaN") << QStringList{"pp", "--a", "1 -0.5", "--b", "0 nan", "--t", "1"}
                              << "--b";
    QTest::newRow("pp negative ts")
        << QStringList{"pp", "--preset", "x-axis", "--ts", "-0.07"} << "--ts";
    QTest::newRow("pp ts Inf") << QStringList{"pp", "--preset", "x-axis", "--ts", "inf"} << "--ts";
    QTest::newRow("pp unknown preset") << QStringList{"pp", "--preset", "z-axis"} << "--preset";
    QTest::newRow("zpetc margin one")
        << QStringList{"zpetc"} + kPpX + QStringList{"--margin", "1"} << "--margin";
    QTest::newRow("zpetc margin negative")
        << QStringList{"zpetc"} + kPpX + QStringList{"--margin", "-0.1"} << "--margin";
    QTest::newRow("zpetc negative duration")
        << QStringList{"zpetc"} + kPpX + QStringList{"--duration", "-5"} << "--duration";
    QTest::newRow("zpetc duration needing gigabytes")
        << QStringList{"zpetc"} + kPpX + QStringList{"--duration", "1e12"} << "--duration";
    QTest::newRow("zpetc omega zero")
        << QStringList{"zpetc"} + kPpX + QStringList{"--omega", "0"} << "--omega";
    QTest::newRow("zpetc omega tiny (one period needing gigabytes)")
        << QStringList{"zpetc"} + kPpX + QStringList{"--omega", "1e-300"} << "--omega";
    QTest::newRow("zpetc amplitude NaN")
        << QStringList{"zpetc"} + kPpX + QStringList{"--amplitude", "nan"} << "--amplitude";
    QTest::newRow("zpetc unknown start")
        << QStringList{"zpetc"} + kPpX + QStringList{"--start", "middle"} << "--start";
    QTest::newRow("zpetc frequency points zero")
        << QStringList{"zpetc"} + kPpX + QStringList{"--frequency-points", "0"}
        << "--frequency-points";
    QTest::newRow("contour negative radius")
        << QStringList{"contour", "--radius", "-30"} << "--radius";
    QTest::newRow("contour omega NaN") << QStringList{"contour", "--omega", "nan"} << "--omega";
    QTest::newRow("contour duration needing gigabytes")
        << QStringList{"contour", "--duration", "1e12"} << "--duration";
    // No nonsense counts ("needs -9223372036854775808 samples"), no all-zero metrics
    // from a single sample; the message names what the user typed.
    const QStringList move = {"simulate", "--preset", "lower-base", "--trajectory", "cubic",
                              "--xf",     "600",      "--tf",       "130"};
    QTest::newRow("simulate dt subnormal")
        << move + QStringList{"--dt", "5e-324"} << "--dt: needs more than 1e308 samples";
    QTest::newRow("simulate dt longer than the move (one sample)")
        << move + QStringList{"--dt", "1000"}
        << "--tf: the move lasts 130 s (--tf minus --t0), less than one step of --dt 1000 s";
    QTest::newRow("simulate sine omega 1e300 (one sample)")
        << QStringList{"simulate",    "--preset", "lower-base", "--trajectory", "sine",
                       "--amplitude", "25",       "--omega",    "1e300"}
        << "--omega: gives a single sample";
    QTest::newRow("contour unknown preset")
        << QStringList{"contour", "--preset", "square"} << "--preset";

    // Overflowing design inputs name the argument, not an internal
    // coefficient ("den[2]: must be a number, got NaN" for wn = 1e300: wn^4 overflows).
    QTest::newRow("gt wn 1e300 (wn^4 overflows)")
        << kGt + QStringList{"--wn", "1e300"} << "--wn: 1e+300 rad/s is out of range";
    QTest::newRow("gt wn 1e-200 (wn^2 underflows)")
        << kGt + QStringList{"--wn", "1e-200"} << "--wn: 1e-200 rad/s is out of range";
    QTest::newRow("gt kp 1e308 (psi1 underflows)")
        << kGt + QStringList{"--kp", "1e308"} << "--kp: 1e+308 is out of range";
    QTest::newRow("simulate wn 1e300") << move + QStringList{"--wn", "1e300"} << "--wn";
    QTest::newRow("rlocus gt preset wn 1e300")
        << QStringList{"rlocus", "--gt-preset", "lower-base", "--wn", "1e300"} << "--wn";
    QTest::newRow("sweep wn grid to 1e300")
        << sweep + QStringList{"--wn", "1e299:1e300:2", "--kp", "10:20:2"} << "--wn";
    QTest::newRow("pp b negligible (0 1e-300)")
        << QStringList{"pp", "--a", "1 -1.658 0.6583", "--b", "0 1e-300", "--t", "1 -0.2"}
        << "--b: B(1) = 1e-300 is negligible";
    // Positions beyond kMaxPositionMm = 1e9 mm are refused before they overflow the run.
    QTest::newRow("simulate xf 1e308")
        << QStringList{"simulate", "--preset", "lower-base", "--trajectory", "cubic",
                       "--xf",     "1e308",    "--tf",       "130"}
        << "--xf: 1e+308 is beyond the 1e9 mm";
    QTest::newRow("simulate sine amplitude 1e308")
        << QStringList{"simulate",    "--preset", "lower-base", "--trajectory", "sine",
                       "--amplitude", "1e308",    "--omega",    "0.1"}
        << "--amplitude: 1e+308 is beyond the 1e9 mm";
    QTest::newRow("zpetc amplitude 1e308")
        << QStringList{"zpetc"} + kPpX + QStringList{"--amplitude", "1e308"}
        << "--amplitude: 1e+308 is beyond the 1e9 mm";
    QTest::newRow("contour radius 1e308")
        << QStringList{"contour", "--radius", "1e308"} << "--radius: 1e+308 is beyond the 1e9 mm";
    // One-sample runs: every metric would read 0.
    QTest::newRow("simulate tf 1e-300 (one sample)")
        << QStringList{"simulate", "--preset", "lower-base", "--trajectory", "cubic",
                       "--xf",     "600",      "--tf",       "1e-300"}
        << "--tf: the move lasts 1e-300 s";
    // A move shorter than one step used to run one sample and report zeros.
    QTest::newRow("simulate tf 0.005 dt 0.01 (move shorter than a step)")
        << QStringList{"simulate", "--preset", "lower-base", "--trajectory", "cubic", "--xf",
                       "600",      "--tf",     "0.005",      "--dt",         "0.01"}
        << "--tf: the move lasts 0.005 s (--tf minus --t0), less than one step of --dt 0.01 s: too "
           "short to measure";
    QTest::newRow("zpetc duration shorter than Ts (one sample)")
        << QStringList{"zpetc"} + kPpX + QStringList{"--duration", "0.01"}
        << "--duration: gives a single sample";
    QTest::newRow("zpetc omega 1e300 (one sample)")
        << QStringList{"zpetc"} + kPpX + QStringList{"--omega", "1e300"}
        << "--omega: gives a single sample";
    QTest::newRow("contour duration shorter than Ts (one sample)")
        << QStringList{"contour", "--duration", "0.01"} << "--duration: gives a single sample";
    QTest::newRow("contour omega 1e300 (one sample)")
        << QStringList{"contour", "--omega", "1e300"} << "--omega: gives a single sample";
    // Sessions: the message names the session field.
    QTest::newRow("report dt longer than the move (one sample)")
        << QStringList{"report", "{one-sample}"} << "trajectory.dt: gives a single sample";
    QTest::newRow("report pole placement duration shorter than Ts (one sample)")
        << QStringList{"report", "{pp-one-sample}"} << "trajectory.duration: gives a single sample";
    QTest::newRow("export csv one sample")
        << QStringList{"export", "{one-sample}", "--format", "csv", "-o", "{dir}/o.csv"}
        << "trajectory.dt: gives a single sample";
    QTest::newRow("export json one sample")
        << QStringList{"export", "{pp-one-sample}", "--format", "json", "-o", "{dir}/o.json"}
        << "trajectory.duration: gives a single sample";
    QTest::newRow("report xf 1e308") << QStringList{"report", "{xf-1e308}"}
                                     << "trajectory.cubic.xf: 1e+308 is beyond the 1e9 mm";
    QTest::newRow("export c xf 1e308")
        << QStringList{"export", "{xf-1e308}", "--format", "c", "-o", "{dir}/o.h"}
        << "trajectory.cubic.xf: 1e+308 is beyond the 1e9 mm";
    QTest::newRow("report circle radius 1e308")
        << QStringList{"report", "{radius-1e308}"} << "trajectory.circle.radius: 1e+308 is beyond";
    // No export writes a non-finite number: JSON used to write null.
    QTest::newRow("export json digital PI overflows")
        << QStringList{"export", "{digital-pi-inf}", "--format", "json", "-o", "{dir}/o.json"}
        << "axes[0].gt (digital PI at controller_ts): gives inf in the export";
    // A float header held XYT_X_C0 = 1.0282776349614397e+307 (inf when compiled) and
    // XYT_UMAX = 4.9406564584124654e-324 (0 in float).
    QTest::newRow("export c float constant beyond FLT_MAX")
        << QStringList{"export",      "{ts-1e308}", "--format", "c",
                       "--precision", "float",      "-o",       "{dir}/o.h"}
        << "axes[0].gt (digital PI at controller_ts): gives 1.0282776349614397e+307 for XYT_X_C0, "
           "beyond the "
           "largest float";
    QTest::newRow("export c float constant rounding to 0")
        << QStringList{"export",      "{umax-5e-324}", "--format", "c",
                       "--precision", "float",         "-o",       "{dir}/o.h"}
        << "umax: gives 4.9406564584124654e-324 for XYT_UMAX, which rounds to 0 in float";
}

QString TstCliBadInput::substitute(QString s) const {
    for (auto it = variants_.cbegin(); it != variants_.cend(); ++it)
        s.replace(it.key(), it.value());
    return s.replace("{default}", defaultSession_)
        .replace("{truncated}", truncatedSession_)
        .replace("{binary}", binarySession_)
        .replace("{dir}", dir_.path());
}

xyt::test::CliRun TstCliBadInput::runWithFiles(QStringList args, QString& names,
                                               const QStringList& environment) const {
    for (QString& a : args)
        a = substitute(a);
    names = substitute(names);
    const auto run = xyt::test::runCli(args, kTimeBoundMs, environment);
    if (!run.finished)
        qWarning("did not finish within 20 s (or crashed)");
    return run;
}

void TstCliBadInput::badInputExitsWithTwoAndNamesTheArgument() {
    QFETCH(QStringList, args);
    QFETCH(QString, names);
    const auto run = runWithFiles(args, names, {});
    QVERIFY2(run.finished, "did not finish within 20 s (or crashed)");
    const QByteArray diagnostic = "stderr: " + run.err + " stdout: " + run.out.left(200);
    QVERIFY2(run.exitCode == 2, diagnostic.constData());
    QVERIFY2(run.err.endsWith('\n') && run.err.count('\n') == 1 && !run.err.contains('\r'),
             diagnostic.constData());
    QVERIFY2(run.err.contains(names.toUtf8()), diagnostic.constData());
    QVERIFY2(run.out.isEmpty(), diagnostic.constData());
}

void TstCliBadInput::sampleCountBoundedByPhysicalMemory_data() {
    // On a machine with 4 GB (XYT_TEST_PHYSICAL_MEMORY_BYTES), a run may hold
    // floor(0.25 * 4e9 / 256) = 3 906 250 samples (core/trajectory.h: a quarter of the memory at
    // the 256 B per sample measured for the heaviest user). Each of these needs more: before,
    // they were bounded only by a fixed 20 million and took 1-3 GB.
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("names");
    QTest::newRow("contour duration 1e6 (14.3 million samples at Ts 0.07)")
        << QStringList{"contour", "--duration", "1e6"} << "--duration: needs 1.43e+07 samples";
    QTest::newRow("zpetc duration 1e6")
        << QStringList{"zpetc"} + kPpX + QStringList{"--duration", "1e6"}
        << "--duration: needs 1.43e+07 samples";
    QTest::newRow("simulate dt 1e-5 (13 million samples)")
        << QStringList{"simulate", "--preset", "lower-base"} + kCubic + QStringList{"--dt", "1e-5"}
        << "--dt: needs 1.3e+07 samples";
    QTest::newRow("report of a 14.3-million-sample session")
        << QStringList{"report", "{pp-long}"}
        << "trajectory.duration: needs 1e+08 samples"; // at dt 0.01
    QTest::newRow("export csv of a 14.3-million-sample session")
        << QStringList{"export", "{pp-long}", "--format", "csv", "-o", "{dir}/long.csv"}
        << "trajectory.duration: needs 1e+08 samples";
}

void TstCliBadInput::sampleCountBoundedByPhysicalMemory() {
    QFETCH(QStringList, args);
    QFETCH(QString, names);
    const auto run = runWithFiles(args, names, {"XYT_TEST_PHYSICAL_MEMORY_BYTES=4e9"});
    QVERIFY2(run.finished, "did not finish within 20 s (or crashed)");
    const QByteArray diagnostic = "stderr: " + run.err + " stdout: " + run.out.left(200);
    QCOMPARE(run.exitCode, 2);
    QVERIFY2(run.err.count('\n') == 1, diagnostic.constData());
    QVERIFY2(run.err.contains(names.toUtf8()), diagnostic.constData());
    QVERIFY2(run.err.contains("the limit is 3906250 on this machine"), diagnostic.constData());
    QVERIFY(!QFile::exists(dir_.filePath("long.csv")));
}

QTEST_APPLESS_MAIN(TstCliBadInput)
#include "tst_cli_bad_input.moc"
