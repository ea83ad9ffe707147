// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/files/session_file.h"

#include "core/io/file_io.h"
#include "core/simulation/trajectory.h"
#include "tests/support/small_filesystem.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QScopeGuard>
#include <QTemporaryDir>
#include <QTest>

#include <limits>

#include <cerrno>
#include <cstring>

#include <sys/stat.h>

using namespace xyt;
using namespace xyt::files;

class TstSessionFile : public QObject {
    Q_OBJECT
private slots:
    void roundTripDefault();
    void roundTripEveryField();
    void malformed_data();
    void malformed();
    void unknownFieldsAreReported();
    void filesWithoutMarginMinimaLoad();
    void filesWithoutImplementationLoad();
    void versionOneFilesMigrate();
    void roundTripGcode();
    void filesWithoutGcodeLoad();
    void badGcodeFields_data();
    void badGcodeFields();
    void roundTripModelOrigin();
    void badModelOriginFields_data();
    void badModelOriginFields();
    void roundTripFrictionAndCoupling();
    void badFrictionAndCouplingFields_data();
    void badFrictionAndCouplingFields();
    void newerVersionIsRefused();
    void fileErrors();
    void failedSaveKeepsOldFile();
    void duplicateKeysAreRefused_data();
    void duplicateKeysAreRefused();
    void specialFilesAreRefused();
    void injectedWriteFailureKeepsOldFile();
    void fullDiskKeepsOldFile(); // last: it moves the process into its own mount namespace
};

namespace {

QByteArray readAll(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray("<unreadable>");
}

QJsonObject defaultJson() {
    return sessionToJson(Session::paperDefault());
}

/// Sets the value at a dotted path with [i] indices in a copy of @p root.
QJsonValue setPath(QJsonValue node, QStringList keys, const QJsonValue& value) {
    if (keys.isEmpty())
        return value;
    const QString key = keys.takeFirst();
    if (key.startsWith('[')) {
        QJsonArray a = node.toArray();
        const int i = key.mid(1, key.size() - 2).toInt();
        a[i] = setPath(a[i], keys, value);
        return a;
    }
    QJsonObject o = node.toObject();
    if (value.isUndefined() && keys.isEmpty())
        o.remove(key);
    else
        o[key] = setPath(o.value(key), keys, value);
    return o;
}

QStringList splitPath(const QString& path) {
    QStringList out;
    for (const QString& part : path.split('.')) {
        const qsizetype b = part.indexOf('[');
        if (b < 0) {
            out << part;
            continue;
        }
        out << part.left(b);
        for (const QString& idx : part.mid(b).split('[', Qt::SkipEmptyParts))
            out << "[" + idx;
    }
    return out;
}

} // namespace

void TstSessionFile::roundTripDefault() {
    // Invariant: load(save(s)) == s, field by field (Session has a defaulted operator==).
    const Session s = Session::paperDefault();
    const auto r = sessionFromBytes(QJsonDocument(sessionToJson(s)).toJson());
    QVERIFY2(r.ok, qPrintable(r.message()));
    QVERIFY(r.session == s);
    QVERIFY(r.warnings.isEmpty());
}

void TstSessionFile::roundTripEveryField() {
    Session s = Session::paperDefault();
    s.axes[1].method = DesignMethod::PolePlacementZpetc;
    s.axes[1].pp.t1 = -0.35;
    s.axes[1].pp.zpetcEnabled = false;
    s.axes[0].gt.kp = 12.345678901234567;
    s.trajectory.kind = TrajectoryKind::Circle;
    s.trajectory.radius = 30.0;
    s.trajectory.durationSeconds = 77.5;
    s.umaxVolts = 10.0;
    s.controllerTsSeconds = 0.002;
    s.piDiscretization = PiDiscretization::BackwardEuler;
    s.spec.maxOvershootPct = 1.5;
    s.spec.minPhaseMarginDeg = 47.25;
    s.spec.minGainMarginDb = 6.5;
    s.implementation.delaySamples = 1;
    s.implementation.encoderResolutionMm = 0.0005;
    s.implementation.dacBits = 16;
    s.implementation.antiWindup = AntiWindup::BackCalculation;
    s.implementation.trackingTimeSeconds = 2.75;
    s.snapshots.push_back(s.snapshot("first"));
    s.snapshots.back().axes[0].gt.omegaNRadPerSec = 3.25;
    QTemporaryDir dir;
    const QString path = dir.filePath("s.json");
    QString error;
    QVERIFY2(saveSessionFile(s, path, &error), qPrintable(error));
    const auto r = loadSessionFile(path);
    QVERIFY2(r.ok, qPrintable(r.message()));
    QVERIFY(r.session == s); // doubles survive exactly: Qt writes the shortest round-trip form
}

namespace {

/// A session of the G-code kind: the square example's first lines.
Session gcodeSession() {
    Session s = Session::paperDefault();
    s.trajectory.kind = TrajectoryKind::Gcode;
    s.trajectory.gcode.fileName = "square.nc";
    s.trajectory.gcode.program =
        "G21 G90\nG1 X10 Y0 F600\nX10 Y10\nG3 X0 Y10 I-5 J0 (half circle)\n";
    s.trajectory.gcode.feedScale = 1.25;
    s.trajectory.gcode.maxAccelMmPerS2 = 750.5;
    s.trajectory.gcode.maxJerkMmPerS3 = 20000.0;
    s.trajectory.dtSeconds = 0.002;
    return s;
}

} // namespace

void TstSessionFile::roundTripGcode() {
    // Invariant: load(save(s)) == s with the program text embedded (the session is complete
    // without the .nc file), in the session and in a snapshot.
    Session s = gcodeSession();
    s.snapshots.push_back(s.snapshot("program"));
    const QJsonObject json = sessionToJson(s);
    QCOMPARE(json["trajectory"].toObject()["kind"].toString(), QString("gcode"));
    QCOMPARE(json["trajectory"].toObject()["gcode"].toObject()["program"].toString(),
             QString::fromStdString(s.trajectory.gcode.program));
    const auto r = sessionFromBytes(QJsonDocument(json).toJson());
    QVERIFY2(r.ok, qPrintable(r.message()));
    QVERIFY(r.session == s);
    QVERIFY(r.warnings.isEmpty());
}

void TstSessionFile::filesWithoutGcodeLoad() {
    // Format version 1 did not always write trajectory.gcode: such files load with its
    // defaults (the migration to version 2); version 2 requires it.
    QJsonObject root = defaultJson();
    root["version"] = 1;
    root = setPath(root, {"trajectory", "gcode"}, QJsonValue(QJsonValue::Undefined)).toObject();
    QVERIFY(!root["trajectory"].toObject().contains("gcode"));
    const auto r = sessionFromJson(root);
    QVERIFY2(r.ok, qPrintable(r.message()));
    QVERIFY(r.session == Session::paperDefault());
    QVERIFY(r.session.trajectory.gcode == GcodeTrajectory{});
    root["version"] = kSessionFormatVersion;
    const auto current = sessionFromJson(root);
    QVERIFY(!current.ok);
    QCOMPARE(current.message(), QString("trajectory.gcode: is missing"));
    root["version"] = 1;
    // ... and a version-1 file of the G-code kind had to have it.
    root = setPath(root, {"trajectory", "kind"}, "gcode").toObject();
    const auto missing = sessionFromJson(root);
    QVERIFY(!missing.ok);
    QCOMPARE(missing.errorPath, QString("trajectory.gcode"));
}

namespace {

/// Patrick, Ishak and Adnan's x axis as identified from a log: an ARX origin, one deviation
/// unknown.
Session identifiedSession() {
    Session s = Session::paperDefault();
    ModelOrigin o;
    o.source = "run3.lvm: u=Command, y=X";
    o.structure = "ARX(2,3,1)";
    o.tsSeconds = 0.07;
    o.samples = 1023;
    o.fitPercent = 97.25;
    o.validationFitPercent = 95.5;
    o.parameterNames = {"a1", "a2", "b1", "b2", "b3"};
    o.standardDeviations = {0.01, 0.011, std::numeric_limits<double>::quiet_NaN(), 0.002, 0.003};
    s.axes[0].method = DesignMethod::PolePlacementZpetc;
    s.axes[0].origin = o;
    return s;
}

} // namespace

void TstSessionFile::roundTripModelOrigin() {
    // Invariant: load(save(s)) == s with the model's origin, an unknown deviation (NaN, null in
    // JSON) included; a hand-typed axis has none, and files from before identification load without
    // it.
    const Session s = identifiedSession();
    const QJsonObject json = sessionToJson(s);
    const QJsonObject origin = json["axes"].toArray()[0].toObject()["model_origin"].toObject();
    QVERIFY(origin["std"].toArray()[2].isNull());
    QVERIFY(!json["axes"].toArray()[1].toObject().contains("model_origin"));
    const auto r = sessionFromBytes(QJsonDocument(json).toJson());
    QVERIFY2(r.ok, qPrintable(r.message()));
    QVERIFY(r.session == s);
    QVERIFY(r.warnings.isEmpty());
    QVERIFY(!r.session.axes[1].origin);
}

void TstSessionFile::badModelOriginFields_data() {
    QTest::addColumn<QString>("path");
    QTest::addColumn<QJsonValue>("value");
    QTest::addColumn<QString>("expectedPath");
    QTest::addColumn<QString>("expectedReason");
    const QString o = "axes[0].model_origin.";
    QTest::newRow("ts zero") << o + "ts" << QJsonValue(0) << o + "ts"
                             << "must be greater than zero";
    QTest::newRow("samples fractional") << o + "samples" << QJsonValue(10.5) << o + "samples"
                                        << "must be a whole number";
    QTest::newRow("fit a string") << o + "fit" << QJsonValue("high") << o + "fit"
                                  << "must be a finite number or null";
    QTest::newRow("std too short") << o + "std" << QJsonValue(QJsonArray{0.1}) << o + "std"
                                   << "must be an array as long";
    QTest::newRow("std entry text") << o + "std[1]" << QJsonValue("x") << o + "std[1]"
                                    << "must be a finite number or null";
    QTest::newRow("parameter not a name")
        << o + "parameters[0]" << QJsonValue(3) << o + "parameters[0]"
        << "must be a string";
    QTest::newRow("structure missing")
        << o + "structure" << QJsonValue(QJsonValue::Undefined) << o + "structure"
        << "is missing";
}

void TstSessionFile::badModelOriginFields() {
    QFETCH(QString, path);
    QFETCH(QJsonValue, value);
    QFETCH(QString, expectedPath);
    QFETCH(QString, expectedReason);
    const QJsonObject root =
        setPath(sessionToJson(identifiedSession()), splitPath(path), value).toObject();
    const auto r = sessionFromJson(root);
    QVERIFY(!r.ok);
    QCOMPARE(r.errorPath, expectedPath);
    QVERIFY2(r.error.startsWith(expectedReason), qPrintable(r.message()));
}

namespace {

/// The default session with a table under x (every friction field set, compensation on) and a
/// cross-coupled controller.
Session frictionSession() {
    Session s = Session::paperDefault();
    TableFriction& f = s.axes[0].friction;
    f.coulombVolts = 0.02;
    f.staticVolts = 0.03;
    f.stribeckVelocityMmPerS = 0.4;
    f.viscousVoltsPerMmPerS = 0.001;
    f.backlashMm = 0.005;
    f.amplifierDeadbandVolts = 0.01;
    f.electricalPole = ElectricalPole::Slower;
    s.axes[0].frictionCompensation = {80.0, 0.1};
    s.crossCoupling = {0.1, 1.5, ContourEstimateKind::Linear};
    // The vibration settings of format 7: a two-mass mode and a notch on y, a shaper.
    s.axes[1].gt.flexibleMode = {42.0, 0.03, 30.0, 0.02};
    s.axes[1].gt.notch = {42.0, 8.0, 25.0};
    s.trajectory.shaping = {ShaperType::TwoHumpEi, 38.5, 0.08};
    return s;
}

} // namespace

void TstSessionFile::roundTripFrictionAndCoupling() {
    // Invariant: load(save(s)) == s with every friction field and the cross-coupling; an axis
    // without friction writes no "friction" object, a session without coupling no
    // "cross_coupling", and a version-4 file (neither) loads as the linear table, uncoupled.
    const Session s = frictionSession();
    const QJsonObject json = sessionToJson(s);
    QCOMPARE(json["version"].toInt(), 7);
    const QJsonObject gtY = json["axes"].toArray()[1].toObject()["gt"].toObject();
    QCOMPARE(gtY["flexible_mode"].toObject()["anti_resonance"].toDouble(), 30.0);
    QCOMPARE(gtY["notch"].toObject()["depth"].toDouble(), 25.0);
    QCOMPARE(json["trajectory"].toObject()["shaping"].toObject()["type"].toString(),
             QStringLiteral("2hump_ei"));
    // The rigid, unshaped session writes none of them (a version-6 reader's file).
    const QJsonObject plain = sessionToJson(Session::paperDefault());
    QVERIFY(!plain["axes"].toArray()[0].toObject()["gt"].toObject().contains("flexible_mode"));
    QVERIFY(!plain["trajectory"].toObject().contains("shaping"));
    QCOMPARE(json["cross_coupling"].toObject()["estimate"].toString(), QStringLiteral("linear"));
    QVERIFY(!sessionToJson(Session::paperDefault()).contains("cross_coupling"));
    const QJsonObject f = json["axes"].toArray()[0].toObject()["friction"].toObject();
    QCOMPARE(f["electrical_pole"].toString(), QStringLiteral("slower"));
    QCOMPARE(f["compensation"].toObject()["percent"].toDouble(), 80.0);
    QVERIFY(!json["axes"].toArray()[1].toObject().contains("friction"));
    const auto r = sessionFromBytes(QJsonDocument(json).toJson());
    QVERIFY2(r.ok, qPrintable(r.message()));
    QVERIFY(r.session == s);
    QJsonObject v4 = sessionToJson(Session::paperDefault());
    v4["version"] = 4;
    const auto old = sessionFromJson(v4);
    QVERIFY2(old.ok, qPrintable(old.message()));
    QVERIFY(!old.session.axes[0].friction.active());
    QCOMPARE(old.session.axes[0].frictionCompensation, FrictionCompensation{});
    QVERIFY(old.session.crossCoupling == CrossCoupling{});
}

void TstSessionFile::badFrictionAndCouplingFields_data() {
    QTest::addColumn<QString>("path");
    QTest::addColumn<QJsonValue>("value");
    QTest::addColumn<QString>("expectedPath");
    QTest::addColumn<QString>("expectedReason");
    const QString f = "axes[0].friction.";
    QTest::newRow("negative coulomb") << f + "coulomb" << QJsonValue(-0.1) << f + "coulomb"
                                      << "must be a finite number >= 0";
    QTest::newRow("static below coulomb") << f + "static" << QJsonValue(0.01) << f + "static"
                                          << "must be at least the Coulomb level";
    QTest::newRow("no stribeck velocity")
        << f + "stribeck_velocity" << QJsonValue(0) << f + "stribeck_velocity"
        << "must be > 0 when the static level";
    QTest::newRow("backlash text") << f + "backlash" << QJsonValue("wide") << f + "backlash"
                                   << "must be a finite number";
    QTest::newRow("pole unknown") << f + "electrical_pole" << QJsonValue("middle")
                                  << f + "electrical_pole"
                                  << "must be \"faster\" or \"slower\"";
    QTest::newRow("percent too high")
        << f + "compensation.percent" << QJsonValue(300) << f + "compensation.percent"
        << "must be between 0 and 200";
    QTest::newRow("band zero") << f + "compensation.band" << QJsonValue(0)
                               << f + "compensation.band"
                               << "must be a finite number > 0";
    QTest::newRow("coupling gain negative")
        << "cross_coupling.kp" << QJsonValue(-1) << "cross_coupling.kp"
        << "must be >= 0";
    QTest::newRow("coupling gain text")
        << "cross_coupling.ki" << QJsonValue("high") << "cross_coupling.ki"
        << "must be a finite number";
    QTest::newRow("coupling estimate unknown")
        << "cross_coupling.estimate" << QJsonValue("parabolic") << "cross_coupling.estimate"
        << "must be \"linear\" or \"circular\"";
    const QString m = "axes[1].gt.flexible_mode.";
    QTest::newRow("mode damping one") << m + "damping" << QJsonValue(1.0) << m + "damping"
                                      << "must be a damping ratio in [0, 1)";
    QTest::newRow("anti-resonance above the mode")
        << m + "anti_resonance" << QJsonValue(50.0) << m + "anti_resonance"
        << "must lie below the resonance";
    QTest::newRow("mode frequency zero") << m + "frequency" << QJsonValue(0) << m + "frequency"
                                         << "must be greater than zero";
    const QString n = "axes[1].gt.notch.";
    QTest::newRow("notch too wide") << n + "width" << QJsonValue(100.0) << n + "width"
                                    << "must be a bandwidth > 0 Hz and below twice";
    QTest::newRow("notch depth missing")
        << n + "depth" << QJsonValue(QJsonValue::Undefined) << n + "depth"
        << "is missing";
    const QString sh = "trajectory.shaping.";
    QTest::newRow("shaper unknown") << sh + "type" << QJsonValue("zvx") << sh + "type"
                                    << "must be zv, mzv, zvd, zvdd, ei, 2hump_ei or 3hump_ei";
    QTest::newRow("shaper damping negative") << sh + "damping" << QJsonValue(-0.1) << sh + "damping"
                                             << "must be in [0, 1)";
    QTest::newRow("deadband missing")
        << f + "amplifier_deadband" << QJsonValue(QJsonValue::Undefined) << f + "amplifier_deadband"
        << "is missing";
}

void TstSessionFile::badFrictionAndCouplingFields() {
    QFETCH(QString, path);
    QFETCH(QJsonValue, value);
    QFETCH(QString, expectedPath);
    QFETCH(QString, expectedReason);
    const QJsonObject root =
        setPath(sessionToJson(frictionSession()), splitPath(path), value).toObject();
    const auto r = sessionFromJson(root);
    QVERIFY(!r.ok);
    QCOMPARE(r.errorPath, expectedPath);
    QVERIFY2(r.error.startsWith(expectedReason), qPrintable(r.message()));
}

void TstSessionFile::badGcodeFields_data() {
    QTest::addColumn<QString>("path");
    QTest::addColumn<QJsonValue>("value");
    QTest::addColumn<QString>("expectedPath");
    QTest::addColumn<QString>("expectedReason");
    // The reasons of the program rows are the G-code reader's (gcode_reader.h), with its line.
    QTest::newRow("unknown word") << "trajectory.gcode.program"
                                  << QJsonValue("G21\nG1 X1 F100\nG5 X2\n")
                                  << "trajectory.gcode.program"
                                  << "line 3: unknown word G5 at column 1";
    QTest::newRow("arc off its circle")
        << "trajectory.gcode.program" << QJsonValue("G1 X10 F100\nG2 X20 Y0 I4 J0\n")
        << "trajectory.gcode.program"
        << "line 2:";
    QTest::newRow("no motion") << "trajectory.gcode.program" << QJsonValue("G21 G90\n")
                               << "trajectory.gcode.program"
                               << "";
    QTest::newRow("program not a string")
        << "trajectory.gcode.program" << QJsonValue(3) << "trajectory.gcode.program"
        << "must be a string";
    QTest::newRow("feed scale zero")
        << "trajectory.gcode.feed_scale" << QJsonValue(0) << "trajectory.gcode.feed_scale"
        << "must be greater than zero";
    QTest::newRow("max accel NaN")
        << "trajectory.gcode.max_accel" << QJsonValue("NaN") << "trajectory.gcode.max_accel"
        << "must be a finite number";
    QTest::newRow("negative jerk")
        << "trajectory.gcode.max_jerk" << QJsonValue(-1) << "trajectory.gcode.max_jerk"
        << "must be >= 0 (0 = none)";
    // Profile options the planner cannot plan, by their JSON path: a jerk of 1e-300 crashed every
    // command that read the session and the workbench on open. Out of the planner's range
    // (feed_profile.h) whatever the program; in it, by the time the option alone needs for the
    // program's 35.7 mm (4 (L / 2J)^(1/3) = 4.85e7 s), past what the samples at dt hold.
    QTest::newRow("jerk 1e-300") << "trajectory.gcode.max_jerk" << QJsonValue(1e-300)
                                 << "trajectory.gcode.max_jerk"
                                 << "1e-300 mm/s^3 is outside the planner's range [1e-100, 1e+100]";
    QTest::newRow("jerk 1e-20") << "trajectory.gcode.max_jerk" << QJsonValue(1e-20)
                                << "trajectory.gcode.max_jerk"
                                << "1e-20 mm/s^3 needs at least 4.85e+07 s";
    QTest::newRow("snapshot jerk") << "snapshots[0].trajectory.gcode.max_jerk" << QJsonValue(5e-324)
                                   << "snapshots[0].trajectory.gcode.max_jerk"
                                   << "4.94066e-324 mm/s^3 is outside";
    QTest::newRow("accel 1e300") << "trajectory.gcode.max_accel" << QJsonValue(1e300)
                                 << "trajectory.gcode.max_accel"
                                 << "1e+300 mm/s^2 is outside";
    QTest::newRow("feed scale 1e-300")
        << "trajectory.gcode.feed_scale" << QJsonValue(1e-300) << "trajectory.gcode.feed_scale"
        << "1e-300 makes the feed of line 2";
    QTest::newRow("missing file name")
        << "trajectory.gcode.file" << QJsonValue(QJsonValue::Undefined) << "trajectory.gcode.file"
        << "is missing";
    QTest::newRow("snapshot program")
        << "snapshots[0].trajectory.gcode.program" << QJsonValue("G1 X1\n")
        << "snapshots[0].trajectory.gcode.program"
        << "line 1:";
}

void TstSessionFile::badGcodeFields() {
    QFETCH(QString, path);
    QFETCH(QJsonValue, value);
    QFETCH(QString, expectedPath);
    QFETCH(QString, expectedReason);
    Session s = gcodeSession();
    s.snapshots.push_back(s.snapshot("program"));
    const QJsonObject root = setPath(sessionToJson(s), splitPath(path), value).toObject();
    const auto r = sessionFromJson(root);
    QVERIFY(!r.ok);
    QCOMPARE(r.errorPath, expectedPath);
    QVERIFY2(r.error.startsWith(expectedReason), qPrintable(r.message()));
}

void TstSessionFile::malformed_data() {
    QTest::addColumn<QString>("path");
    QTest::addColumn<QJsonValue>("value");
    QTest::addColumn<QString>("expectedPath");
    QTest::addColumn<QString>("expectedReason");
    QTest::newRow("NaN as a string")
        << "axes[1].gt.plant.a2" << QJsonValue("NaN") << "axes[1].gt.plant.a2"
        << "must be a finite number";
    QTest::newRow("wrong type") << "axes[0].gt.kp" << QJsonValue(true) << "axes[0].gt.kp"
                                << "must be a finite number";
    QTest::newRow("negative kp") << "axes[0].gt.kp" << QJsonValue(-3) << "axes[0].gt.kp"
                                 << "must be greater than zero";
    QTest::newRow("zero k0") << "axes[0].gt.plant.k0" << QJsonValue(0) << "axes[0].gt.plant.k0"
                             << "must be nonzero";
    QTest::newRow("missing field")
        << "trajectory.dt" << QJsonValue(QJsonValue::Undefined) << "trajectory.dt"
        << "is missing";
    QTest::newRow("unknown method") << "axes[0].method" << QJsonValue("pid") << "axes[0].method"
                                    << "must be \"guillemin-truxal\", \"pole-placement-zpetc\" "
                                       "or \"pid-ff\"";
    QTest::newRow("unknown profile")
        << "trajectory.cubic.profile" << QJsonValue("septic") << "trajectory.cubic.profile"
        << "must be \"cubic\" or \"quintic\"";
    QJsonArray huge;
    for (int i = 0; i < 100000; ++i)
        huge.append(1.0);
    QTest::newRow("huge array") << "axes[1].pp.a" << QJsonValue(huge) << "axes[1].pp.a"
                                << "has 100000 entries; at most 64 are allowed";
    QTest::newRow("empty array") << "axes[1].pp.b" << QJsonValue(QJsonArray()) << "axes[1].pp.b"
                                 << "must not be empty";
    QTest::newRow("one axis") << "axes"
                              << QJsonValue(QJsonArray{defaultJson()["axes"].toArray()[0]})
                              << "axes"
                              << "must be an array of exactly two axes";
    QTest::newRow("tf before t0") << "trajectory.cubic.tf" << QJsonValue(-1)
                                  << "trajectory.cubic.tf"
                                  << "must be later than t0";
    QTest::newRow("object expected") << "trajectory" << QJsonValue(3) << "trajectory"
                                     << "must be an object";
    QTest::newRow("phase margin above 180")
        << "specification.min_phase_margin" << QJsonValue(190) << "specification.min_phase_margin"
        << "must be 0 .. 180 degrees";
    QTest::newRow("negative gain margin")
        << "specification.min_gain_margin" << QJsonValue(-1) << "specification.min_gain_margin"
        << "must be >= 0 dB";
    QTest::newRow("dac bits above 32")
        << "implementation.dac_bits" << QJsonValue(33) << "implementation.dac_bits"
        << "must be an integer in 0..32 (0: ideal DAC)";
    QTest::newRow("dac bits fractional")
        << "implementation.dac_bits" << QJsonValue(12.5) << "implementation.dac_bits"
        << "must be an integer in 0..32 (0: ideal DAC)";
    QTest::newRow("dac bits a string")
        << "implementation.dac_bits" << QJsonValue("16") << "implementation.dac_bits"
        << "must be an integer in 0..32 (0: ideal DAC)";
    QTest::newRow("negative delay")
        << "implementation.delay_samples" << QJsonValue(-1) << "implementation.delay_samples"
        << "must be an integer in 0..100";
    QTest::newRow("negative encoder") << "implementation.encoder_resolution" << QJsonValue(-0.001)
                                      << "implementation.encoder_resolution"
                                      << "must be >= 0 (mm per count; 0: ideal encoder)";
    QTest::newRow("encoder NaN") << "implementation.encoder_resolution" << QJsonValue("NaN")
                                 << "implementation.encoder_resolution"
                                 << "must be a finite number";
    QTest::newRow("unknown anti-windup")
        << "implementation.anti_windup" << QJsonValue("integrator-reset")
        << "implementation.anti_windup"
        << "must be \"none\", \"clamp\" or \"back-calculation\"";
    QTest::newRow("negative tracking time")
        << "implementation.tracking_time" << QJsonValue(-2) << "implementation.tracking_time"
        << "must be >= 0 (s; 0: Tt = Ti = kp/ki)";
    QTest::newRow("implementation not an object")
        << "implementation" << QJsonValue(1) << "implementation"
        << "must be an object";
    QTest::newRow("duration too long")
        << "trajectory.duration" << QJsonValue(1e12) << "trajectory.duration"
        << QStringLiteral("needs 1e+14 samples at this dt; the limit is %1 on this machine")
               .arg(xyt::sampleLimit()); // 1e12 s at dt 0.01; the limit follows the memory
}

void TstSessionFile::malformed() {
    QFETCH(QString, path);
    QFETCH(QJsonValue, value);
    QFETCH(QString, expectedPath);
    QFETCH(QString, expectedReason);
    const QJsonObject root = setPath(defaultJson(), splitPath(path), value).toObject();
    const auto r = sessionFromJson(root);
    QVERIFY(!r.ok);
    QCOMPARE(r.errorPath, expectedPath);
    QCOMPARE(r.error, expectedReason);
}

void TstSessionFile::filesWithoutImplementationLoad() {
    // Format version 1 did not always write the implementation object, and a hand-written one
    // could give only some of its fields: the rest keep the defaults (ideal encoder and DAC, no
    // delay, clamping anti-windup). Version 2 requires the object and every field.
    QJsonObject root = defaultJson();
    root["version"] = 1;
    QVERIFY(root.contains("implementation"));
    root.remove("implementation");
    auto r = sessionFromJson(root);
    QVERIFY2(r.ok, qPrintable(r.message()));
    QVERIFY(r.session.implementation == ImplementationSettings{});
    QCOMPARE(r.session.implementation.antiWindup, AntiWindup::Clamp);
    QVERIFY(r.warnings.isEmpty());
    root["implementation"] = QJsonObject{{"dac_bits", 12}};
    r = sessionFromJson(root);
    QVERIFY2(r.ok, qPrintable(r.message()));
    QCOMPARE(r.session.implementation.dacBits, 12);
    QCOMPARE(r.session.implementation.delaySamples, 0);
    root["version"] = kSessionFormatVersion;
    QCOMPARE(sessionFromJson(root).message(), QString("implementation.delay_samples: is missing"));
    root.remove("implementation");
    QCOMPARE(sessionFromJson(root).message(), QString("implementation: is missing"));
}

void TstSessionFile::filesWithoutMarginMinimaLoad() {
    // Format version 1 did not always write the margin minima: such files load with none (0).
    QJsonObject root = defaultJson();
    root["version"] = 1;
    QJsonObject spec = root["specification"].toObject();
    QVERIFY(spec.contains("min_phase_margin") && spec.contains("min_gain_margin"));
    spec.remove("min_phase_margin");
    spec.remove("min_gain_margin");
    root["specification"] = spec;
    const auto r = sessionFromJson(root);
    QVERIFY2(r.ok, qPrintable(r.message()));
    QCOMPARE(r.session.spec.minPhaseMarginDeg, 0.0);
    QCOMPARE(r.session.spec.minGainMarginDb, 0.0);
    root["version"] = kSessionFormatVersion;
    QCOMPARE(sessionFromJson(root).message(),
             QString("specification.min_phase_margin: is missing"));
}

void TstSessionFile::versionOneFilesMigrate() {
    // Invariants of the migration (session_format_migration.h): a complete version-1 document
    // (what the last version-1 writer wrote: every field) becomes the current document with
    // only "version" changed, and reads as the same session; written files say the current
    // version; a version-1 file without any of the fields version 1 left optional, a snapshot
    // included, reads as the session with those fields at their defaults.
    Session s = Session::paperDefault();
    s.implementation.dacBits = 14;
    s.spec.minPhaseMarginDeg = 45.0;
    s.snapshots.push_back({"before", s.axes, s.trajectory, s.umaxVolts});
    const QJsonObject current = sessionToJson(s);
    QCOMPARE(current["version"].toInt(), kSessionFormatVersion);
    QCOMPARE(kSessionFormatVersion, 7);
    // Version 3 had no "profile" in its point-to-point move (nor in its snapshots'): the
    // migration says "cubic", the current document.
    const auto withoutProfile = [](QJsonObject holder) {
        QJsonObject trajectory = holder["trajectory"].toObject();
        QJsonObject cubic = trajectory["cubic"].toObject();
        cubic.remove("profile");
        trajectory["cubic"] = cubic;
        holder["trajectory"] = trajectory;
        return holder;
    };
    QJsonObject versionThree = withoutProfile(current);
    versionThree["version"] = 3;
    QJsonArray threeSnapshots = versionThree["snapshots"].toArray();
    threeSnapshots[0] = withoutProfile(threeSnapshots[0].toObject());
    versionThree["snapshots"] = threeSnapshots;
    QCOMPARE(migrateSessionJson(versionThree, 3), current);
    QVERIFY(sessionFromJson(versionThree).session == s);
    // ... version 4 requires it, and the quintic move round-trips.
    QCOMPARE(sessionFromJson(withoutProfile(current)).message(),
             QString("trajectory.cubic.profile: is missing"));
    Session quintic = s;
    quintic.trajectory.profile = MoveProfile::Quintic;
    QVERIFY(sessionFromJson(sessionToJson(quintic)).session == quintic);
    // Version 2 had no "parameters" object in its axes (nor in its snapshots' axes): the
    // migration gives each an empty one, the current document.
    QJsonObject versionTwo = current;
    versionTwo["version"] = 2;
    const auto withoutParameters = [](QJsonArray axes) {
        for (qsizetype i = 0; i < axes.size(); ++i) {
            QJsonObject axis = axes[i].toObject();
            axis.remove("parameters");
            axes[i] = axis;
        }
        return axes;
    };
    versionTwo["axes"] = withoutParameters(current["axes"].toArray());
    QJsonArray twoSnapshots = versionTwo["snapshots"].toArray();
    QJsonObject twoSnapshot = twoSnapshots[0].toObject();
    twoSnapshot["axes"] = withoutParameters(twoSnapshot["axes"].toArray());
    twoSnapshots[0] = twoSnapshot;
    versionTwo["snapshots"] = twoSnapshots;
    versionTwo = withoutProfile(versionTwo);
    twoSnapshots = versionTwo["snapshots"].toArray();
    twoSnapshots[0] = withoutProfile(twoSnapshots[0].toObject());
    versionTwo["snapshots"] = twoSnapshots;
    QCOMPARE(migrateSessionJson(versionTwo, 2), current);
    QVERIFY(sessionFromJson(versionTwo).session == s);
    // ... and version 3 requires it.
    QJsonObject missing = current;
    missing["axes"] = withoutParameters(current["axes"].toArray());
    QCOMPARE(sessionFromJson(missing).message(), QString("axes[0].parameters: is missing"));
    QJsonObject versionOne = current;
    versionOne["version"] = 1;
    QCOMPARE(migrateSessionJson(versionOne, 1), current);
    auto r = sessionFromJson(versionOne);
    QVERIFY2(r.ok, qPrintable(r.message()));
    QVERIFY(r.session == s);

    QJsonObject sparse = versionOne;
    sparse.remove("implementation");
    QJsonObject spec = sparse["specification"].toObject();
    for (const char* key :
         {"in_position_window_mm", "max_settle_time", "min_phase_margin", "min_gain_margin"})
        spec.remove(key);
    sparse["specification"] = spec;
    sparse = setPath(sparse, {"trajectory", "gcode"}, QJsonValue(QJsonValue::Undefined)).toObject();
    QJsonArray snapshots = sparse["snapshots"].toArray();
    QJsonObject snapshot = snapshots[0].toObject();
    QJsonObject trajectory = snapshot["trajectory"].toObject();
    trajectory.remove("gcode");
    snapshot["trajectory"] = trajectory;
    snapshots[0] = snapshot;
    sparse["snapshots"] = snapshots;
    r = sessionFromJson(sparse);
    QVERIFY2(r.ok, qPrintable(r.message()));
    QVERIFY(r.warnings.isEmpty());
    Session expected = s;
    expected.implementation = ImplementationSettings{};
    expected.spec.inPositionWindowMm = Specification{}.inPositionWindowMm;
    expected.spec.maxSettleTimeSeconds = Specification{}.maxSettleTimeSeconds;
    expected.spec.minPhaseMarginDeg = 0.0;
    expected.spec.minGainMarginDb = 0.0;
    QVERIFY(r.session == expected);
    // Wrong values are kept for the reader to name, not replaced by defaults.
    sparse["implementation"] = QJsonObject{{"dac_bits", 40}};
    QCOMPARE(sessionFromJson(sparse).message(),
             QString("implementation.dac_bits: must be an integer in 0..32 (0: ideal DAC)"));
}

void TstSessionFile::unknownFieldsAreReported() {
    QJsonObject root = defaultJson();
    root["comment"] = "hand-written";
    QJsonArray axes = root["axes"].toArray();
    QJsonObject x = axes[0].toObject();
    x["colour"] = "red";
    axes[0] = x;
    root["axes"] = axes;
    const auto r = sessionFromJson(root);
    QVERIFY(r.ok);
    QCOMPARE(r.warnings.size(), 2);
    QVERIFY(r.warnings.contains("comment: unknown field ignored"));
    QVERIFY(r.warnings.contains("axes[0].colour: unknown field ignored"));
}

void TstSessionFile::newerVersionIsRefused() {
    QJsonObject root = defaultJson();
    root["version"] = kSessionFormatVersion + 1;
    const auto r = sessionFromJson(root);
    QVERIFY(!r.ok);
    QCOMPARE(r.errorPath, QString("version"));
    QVERIFY(r.error.contains("please update XY Tune"));
}

void TstSessionFile::fileErrors() {
    QTemporaryDir dir;
    auto r = loadSessionFile(dir.path());
    QVERIFY(!r.ok);
    QVERIFY2(r.error.contains("is a directory"), qPrintable(r.error));
    r = loadSessionFile(dir.filePath("missing.json"));
    QVERIFY(r.error.contains("no such file"));
    QFile truncated(dir.filePath("t.json"));
    QVERIFY(truncated.open(QIODevice::WriteOnly));
    truncated.write(QJsonDocument(defaultJson()).toJson().left(200));
    truncated.close();
    r = loadSessionFile(truncated.fileName());
    QVERIFY(!r.ok);
    QVERIFY2(r.error.startsWith("not valid JSON"), qPrintable(r.error));
    r = sessionFromBytes("[1, 2]");
    QVERIFY(r.error.contains("must be a JSON object"));
}

void TstSessionFile::failedSaveKeepsOldFile() {
    QTemporaryDir dir;
    const QString path = dir.filePath("keep.json");
    QString error;
    QVERIFY(saveSessionFile(Session::paperDefault(), path, &error));
    const QByteArray before = [&] {
        QFile f(path);
        f.open(QIODevice::ReadOnly);
        return f.readAll();
    }();
    // A directory where the file should go, and a read-only directory: both fail cleanly.
    QVERIFY(!saveSessionFile(Session::paperDefault(), dir.path(), &error));
    QVERIFY(error.contains("is a directory"));
    Session changed = Session::paperDefault();
    changed.umaxVolts = 7.0;
    QFile::setPermissions(dir.path(), QFileDevice::ReadOwner | QFileDevice::ExeOwner);
    const bool saved = saveSessionFile(changed, path, &error);
    QFile::setPermissions(dir.path(),
                          QFileDevice::ReadOwner | QFileDevice::WriteOwner | QFileDevice::ExeOwner);
    if (saved)
        QSKIP("running as root: a read-only directory does not stop the write");
    QVERIFY(!error.isEmpty());
    QFile f(path);
    QVERIFY(f.open(QIODevice::ReadOnly));
    QCOMPARE(f.readAll(), before);
}

void TstSessionFile::duplicateKeysAreRefused_data() {
    // Qt's reader keeps the last of two equal keys, others the first: the file means two
    // sessions. The key is named by its JSON path, after decoding escapes.
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("path");
    QTest::newRow("top level") << QByteArray(R"({"umax": 2.5, "format": 1, "umax": 250})")
                               << "umax";
    QTest::newRow("nested in an array")
        << QByteArray(R"({"axes": [{}, {"gt": {"plant": {"k0": 1, "a1": 2, "k0": 3}}}]})")
        << "axes[1].gt.plant.k0";
    QTest::newRow("escaped spelling of the same key")
        << QByteArray(R"({"a": [1, [2, {}]], "snapshots": [{"name": "a", "n\u0061me": "b"}]})")
        << "snapshots[0].name";
}

void TstSessionFile::duplicateKeysAreRefused() {
    QFETCH(QByteArray, json);
    QFETCH(QString, path);
    const SessionLoadResult r = sessionFromBytes(json);
    QVERIFY(!r.ok);
    QCOMPARE(r.errorPath, path);
    QVERIFY2(r.error.contains("more than once"), qPrintable(r.message()));
    // The saved default session has no duplicates and loads.
    QVERIFY(sessionFromBytes(QJsonDocument(defaultJson()).toJson()).ok);
}

void TstSessionFile::specialFilesAreRefused() {
    QTemporaryDir dir;
    const QString fifo = dir.filePath("pipe");
    QVERIFY(::mkfifo(QFile::encodeName(fifo).constData(), 0600) == 0);
    for (const QString& path : {fifo, QStringLiteral("/dev/zero")}) {
        const SessionLoadResult r = loadSessionFile(path); // returns: no blocking, no bad_alloc
        QVERIFY(!r.ok);
        QVERIFY2(r.error.contains("not a regular file"), qPrintable(r.error));
    }
    // A GUI save over a FIFO does not replace it.
    QString error;
    QVERIFY(!saveSessionFile(Session::paperDefault(), fifo, &error));
    QVERIFY2(error.contains("not a regular file"), qPrintable(error));
}

void TstSessionFile::injectedWriteFailureKeepsOldFile() {
    QTemporaryDir dir;
    const QString path = dir.filePath("keep.json");
    QString error;
    QVERIFY(saveSessionFile(Session::paperDefault(), path, &error));
    const QByteArray before = readAll(path);
    Session changed = Session::paperDefault();
    changed.umaxVolts = 7.0;
    for (const auto& [step, reason] :
         {std::pair{WriteStep::Write, ENOSPC}, std::pair{WriteStep::Sync, EIO},
          std::pair{WriteStep::Rename, EIO}}) {
        injectWriteFailureForTesting(step);
        const bool saved = saveSessionFile(changed, path, &error);
        injectWriteFailureForTesting(WriteStep::None);
        QVERIFY(!saved);
        QCOMPARE(error, path + ": " + QString::fromUtf8(std::strerror(reason)));
        QCOMPARE(readAll(path), before);
    }
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList{"keep.json"});
}

void TstSessionFile::fullDiskKeepsOldFile() {
    QTemporaryDir dir;
    if (const QString why = xyt::test::mountSmallFilesystem(dir.path(), 64); !why.isEmpty())
        QSKIP(qPrintable(why));
    const auto unmount = qScopeGuard([&] { xyt::test::unmountSmallFilesystem(dir.path()); });
    const QString path = dir.filePath("keep.json");
    QString error;
    QVERIFY(saveSessionFile(Session::paperDefault(), path, &error));
    const QByteArray before = readAll(path);
    xyt::test::fillFilesystem(dir.path());
    Session changed = Session::paperDefault();
    changed.umaxVolts = 7.0;
    QVERIFY(!saveSessionFile(changed, path, &error));
    QCOMPARE(error, path + ": " + QString::fromUtf8(std::strerror(ENOSPC)));
    QCOMPARE(readAll(path), before);
}

QTEST_APPLESS_MAIN(TstSessionFile)
#include "tst_session_file.moc"
