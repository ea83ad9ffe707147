// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/files/session_file.h"

#include "core/io/file_io.h"
#include "core/io/json_duplicate_keys.h"
#include "core/model/coefficient_parser.h"
#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/session/design_method_module.h"
#include "core/session/program_trajectory.h"
#include "core/simulation/sampled_data.h"
#include "core/simulation/trajectory.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonDocument>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

namespace xyt::files {

namespace {

/// The file format's own reasons and warnings, in the workbench's language once it loaded one
/// (Qt Linguist's context xyt::files::SessionFile); the CLI loads none and prints the English.
class SessionFileText {
    Q_DECLARE_TR_FUNCTIONS(xyt::files::SessionFile)
};

constexpr int kMaxSnapshots = 200;

/// A bad value at a JSON path.
struct FormatError {
    FormatError(QString atPath, QString why, Diagnostic coded = {})
        : path(std::move(atPath)), reason(std::move(why)), reasonDiagnostic(std::move(coded)) {}
    QString path;
    QString reason;
    /// The core's coded reason when the core refused the value (uncoded otherwise), so the
    /// workbench can show it in the user's language.
    Diagnostic reasonDiagnostic;
};

QString join(const QString& path, const QString& key) {
    return path.isEmpty() ? key : path + "." + key;
}

/// The registered design method named @p name, or a FormatError at @p path listing the names.
DesignMethod methodFromName(const QString& name, const QString& path) {
    QStringList names;
    for (const DesignMethodModule* m : designMethodModules()) {
        names << QStringLiteral("\"%1\"").arg(methodName(m->method()));
        if (name == methodName(m->method()))
            return m->method();
    }
    const QString last = names.takeLast();
    throw FormatError{
        path, SessionFileText::tr("must be %1 or %2").arg(names.join(QStringLiteral(", ")), last)};
}

/// Reads one JSON object, remembering its path and which keys were used, so that unknown keys
/// can be reported.
class ObjectReader {
public:
    ObjectReader(const QJsonValue& value, QString path, QStringList* warnings)
        : path_(std::move(path)), warnings_(warnings) {
        if (!value.isObject())
            throw FormatError{path_, SessionFileText::tr("must be an object")};
        object_ = value.toObject();
    }
    ~ObjectReader() = default;

    const QString& path() const { return path_; }
    bool has(const QString& key) const { return object_.contains(key); }
    QStringList keys() const { return object_.keys(); }

    QJsonValue get(const QString& key) {
        used_ << key;
        if (!object_.contains(key))
            throw FormatError{join(path_, key), SessionFileText::tr("is missing")};
        return object_.value(key);
    }
    double number(const QString& key) {
        const QJsonValue v = get(key);
        if (!v.isDouble() || !std::isfinite(v.toDouble()))
            throw FormatError{join(path_, key), SessionFileText::tr("must be a finite number")};
        return v.toDouble();
    }
    double positive(const QString& key) {
        const double v = number(key);
        if (!(v > 0.0))
            throw FormatError{join(path_, key), SessionFileText::tr("must be greater than zero")};
        return v;
    }
    QString string(const QString& key) {
        const QJsonValue v = get(key);
        if (!v.isString())
            throw FormatError{join(path_, key), SessionFileText::tr("must be a string")};
        return v.toString();
    }
    bool boolean(const QString& key) {
        const QJsonValue v = get(key);
        if (!v.isBool())
            throw FormatError{join(path_, key), SessionFileText::tr("must be true or false")};
        return v.toBool();
    }
    std::vector<double> coefficients(const QString& key) {
        const QJsonValue v = get(key);
        const QString p = join(path_, key);
        if (!v.isArray())
            throw FormatError{p, SessionFileText::tr("must be an array of numbers")};
        const QJsonArray a = v.toArray();
        if (a.isEmpty())
            throw FormatError{p, SessionFileText::tr("must not be empty")};
        if (a.size() > static_cast<qsizetype>(kMaxCoefficients))
            throw FormatError{p, SessionFileText::tr("has %1 entries; at most %2 are allowed")
                                     .arg(a.size())
                                     .arg(kMaxCoefficients)};
        std::vector<double> out;
        for (qsizetype i = 0; i < a.size(); ++i) {
            if (!a[i].isDouble() || !std::isfinite(a[i].toDouble()))
                throw FormatError{QStringLiteral("%1[%2]").arg(p).arg(i),
                                  SessionFileText::tr("must be a finite number")};
            out.push_back(a[i].toDouble());
        }
        return out;
    }
    /// A whole number in [lo, hi] (JSON numbers are doubles: 3.0 is accepted, 3.5 is not).
    int integer(const QString& key, int lo, int hi, const QString& note = QString()) {
        const QJsonValue v = get(key);
        const double d = v.toDouble();
        if (!v.isDouble() || !std::isfinite(d) || d != std::floor(d) || d < lo || d > hi)
            throw FormatError{
                join(path_, key),
                SessionFileText::tr("must be an integer in %1..%2%3").arg(lo).arg(hi).arg(note)};
        return static_cast<int>(d);
    }
    ObjectReader child(const QString& key) {
        return ObjectReader(get(key), join(path_, key), warnings_);
    }

    /// Reports keys that were never read.
    void finish() const {
        for (const QString& key : object_.keys())
            if (!used_.contains(key))
                warnings_->append(
                    SessionFileText::tr("%1: unknown field ignored").arg(join(path_, key)));
    }

private:
    QJsonObject object_;
    QString path_;
    QStringList* warnings_;
    QStringList used_;
};

QJsonArray toArray(const std::vector<double>& v) {
    QJsonArray a;
    for (double x : v)
        a.append(x);
    return a;
}

/// A number, or null for NaN (JSON has no NaN: an unknown standard deviation).
QJsonValue numberOrNull(double v) {
    return std::isfinite(v) ? QJsonValue(v) : QJsonValue();
}

QJsonObject originToJson(const ModelOrigin& o) {
    QJsonArray names, deviations;
    for (std::size_t i = 0; i < o.parameterNames.size(); ++i) {
        names.append(QString::fromStdString(o.parameterNames[i]));
        deviations.append(i < o.standardDeviations.size() ? numberOrNull(o.standardDeviations[i])
                                                          : QJsonValue());
    }
    QJsonObject out{{"source", QString::fromStdString(o.source)},
                    {"structure", QString::fromStdString(o.structure)},
                    {"ts", o.tsSeconds},
                    {"samples", static_cast<double>(o.samples)},
                    {"fit", numberOrNull(o.fitPercent)},
                    {"parameters", names},
                    {"std", deviations}};
    if (o.validationFitPercent)
        out.insert("validation_fit", numberOrNull(*o.validationFitPercent));
    if (!o.covariance.empty())
        out.insert("covariance", toArray(o.covariance));
    return out;
}

ModelOrigin readOrigin(ObjectReader r) {
    ModelOrigin o;
    o.source = r.string("source").toStdString();
    o.structure = r.string("structure").toStdString();
    o.tsSeconds = r.positive("ts");
    const double samples = r.positive("samples");
    if (samples != std::floor(samples) || samples > 1e12)
        throw FormatError{join(r.path(), "samples"),
                          SessionFileText::tr("must be a whole number of samples")};
    o.samples = static_cast<std::size_t>(samples);
    const auto optionalNumber = [&](const QString& key) {
        const QJsonValue v = r.get(key);
        if (v.isNull())
            return std::numeric_limits<double>::quiet_NaN();
        if (!v.isDouble() || !std::isfinite(v.toDouble()))
            throw FormatError{join(r.path(), key),
                              SessionFileText::tr("must be a finite number or null")};
        return v.toDouble();
    };
    o.fitPercent = optionalNumber("fit");
    if (r.has("validation_fit"))
        o.validationFitPercent = optionalNumber("validation_fit");
    const QJsonValue names = r.get("parameters");
    const QJsonValue deviations = r.get("std");
    if (!names.isArray() || names.toArray().size() > 1000)
        throw FormatError{join(r.path(), "parameters"),
                          SessionFileText::tr("must be an array of at most 1000 names")};
    if (!deviations.isArray() || deviations.toArray().size() != names.toArray().size())
        throw FormatError{join(r.path(), "std"),
                          SessionFileText::tr("must be an array as long as \"parameters\"")};
    for (qsizetype i = 0; i < names.toArray().size(); ++i) {
        const QJsonValue n = names.toArray()[i];
        const QJsonValue d = deviations.toArray()[i];
        if (!n.isString())
            throw FormatError{QStringLiteral("%1[%2]").arg(join(r.path(), "parameters")).arg(i),
                              SessionFileText::tr("must be a string")};
        if (!d.isNull() && (!d.isDouble() || !std::isfinite(d.toDouble())))
            throw FormatError{QStringLiteral("%1[%2]").arg(join(r.path(), "std")).arg(i),
                              SessionFileText::tr("must be a finite number or null")};
        o.parameterNames.push_back(n.toString().toStdString());
        o.standardDeviations.push_back(d.isNull() ? std::numeric_limits<double>::quiet_NaN()
                                                  : d.toDouble());
    }
    if (r.has("covariance")) {
        const QJsonValue c = r.get("covariance");
        const qsizetype n = names.toArray().size();
        if (!c.isArray() || c.toArray().size() != n * n)
            throw FormatError{join(r.path(), "covariance"),
                              SessionFileText::tr(
                                  "must be an array of %1 numbers (the %2 x %2 matrix, row by row)")
                                  .arg(n * n)
                                  .arg(n)};
        for (qsizetype i = 0; i < c.toArray().size(); ++i) {
            const QJsonValue v = c.toArray()[i];
            if (!v.isDouble() || !std::isfinite(v.toDouble()))
                throw FormatError{QStringLiteral("%1[%2]").arg(join(r.path(), "covariance")).arg(i),
                                  SessionFileText::tr("must be a finite number")};
            o.covariance.push_back(v.toDouble());
        }
    }
    r.finish();
    return o;
}

QJsonObject frictionToJson(const TableFriction& f, const FrictionCompensation& c) {
    return {{"coulomb", f.coulombVolts},
            {"static", f.staticVolts},
            {"stribeck_velocity", f.stribeckVelocityMmPerS},
            {"viscous", f.viscousVoltsPerMmPerS},
            {"backlash", f.backlashMm},
            {"amplifier_deadband", f.amplifierDeadbandVolts},
            {"electrical_pole", f.electricalPole == ElectricalPole::Faster
                                    ? QStringLiteral("faster")
                                    : QStringLiteral("slower")},
            {"compensation", QJsonObject{{"percent", c.percent}, {"band", c.bandMmPerS}}}};
}

/// An axis' "friction" object, every field required, checked by the core's rules at its path.
void readFriction(ObjectReader r, AxisSettings& a) {
    TableFriction& f = a.friction;
    f.coulombVolts = r.number("coulomb");
    f.staticVolts = r.number("static");
    f.stribeckVelocityMmPerS = r.number("stribeck_velocity");
    f.viscousVoltsPerMmPerS = r.number("viscous");
    f.backlashMm = r.number("backlash");
    f.amplifierDeadbandVolts = r.number("amplifier_deadband");
    const QString pole = r.string("electrical_pole");
    if (pole != "faster" && pole != "slower")
        throw FormatError{join(r.path(), "electrical_pole"),
                          SessionFileText::tr("must be \"faster\" or \"slower\"")};
    f.electricalPole = pole == "faster" ? ElectricalPole::Faster : ElectricalPole::Slower;
    ObjectReader c = r.child("compensation");
    a.frictionCompensation.percent = c.number("percent");
    a.frictionCompensation.bandMmPerS = c.number("band");
    try {
        validateTableFriction(f);
    } catch (const InvalidInput& e) {
        throw FormatError{join(r.path(), QString::fromStdString(e.field())),
                          QString::fromStdString(e.reason()), e.reasonDiagnostic()};
    }
    try {
        validateFrictionCompensation(a.frictionCompensation);
    } catch (const InvalidInput& e) {
        throw FormatError{join(c.path(), QString::fromStdString(e.field())),
                          QString::fromStdString(e.reason()), e.reasonDiagnostic()};
    }
    c.finish();
    r.finish();
}

/// An axis' "gt" object: the plant, the design's wn and kp, the unit, and the flexible mode and
/// notch when set.
QJsonObject gtToJson(const GtAxisSettings& g) {
    QJsonObject out{
        {"plant", QJsonObject{{"k0", g.plant.k0}, {"a1", g.plant.a1}, {"a2", g.plant.a2}}},
        {"wn", g.omegaNRadPerSec},
        {"kp", g.kp},
        {"model_unit_scale", g.modelUnitsPerPositionUnit}};
    const FlexibleMode& m = g.flexibleMode;
    if (m.present())
        out.insert("flexible_mode",
                   QJsonObject{{"frequency", m.frequencyHz},
                               {"damping", m.dampingRatio},
                               {"anti_resonance", m.antiResonanceHz},
                               {"anti_resonance_damping", m.antiResonanceDamping}});
    if (g.notch.present())
        out.insert("notch", QJsonObject{{"centre", g.notch.centreHz},
                                        {"width", g.notch.widthHz},
                                        {"depth", g.notch.depthDb}});
    return out;
}

/// The optional "flexible_mode" and "notch" of an axis' "gt", every field required, checked by
/// the core's rules at their paths.
void readGtLoopElements(ObjectReader& gt, GtAxisSettings& g) {
    const auto fieldError = [](const ObjectReader& r, const InvalidInput& e) {
        return FormatError{join(r.path(), QString::fromStdString(e.field())),
                           QString::fromStdString(e.reason()), e.reasonDiagnostic()};
    };
    if (gt.has("flexible_mode")) {
        ObjectReader r = gt.child("flexible_mode");
        FlexibleMode& m = g.flexibleMode;
        m.frequencyHz = r.positive("frequency");
        m.dampingRatio = r.number("damping");
        m.antiResonanceHz = r.number("anti_resonance");
        m.antiResonanceDamping = r.number("anti_resonance_damping");
        try {
            validateFlexibleMode(m);
        } catch (const InvalidInput& e) {
            throw fieldError(r, e);
        }
        r.finish();
    }
    if (gt.has("notch")) {
        ObjectReader r = gt.child("notch");
        NotchFilter& n = g.notch;
        n.centreHz = r.positive("centre");
        n.widthHz = r.number("width");
        n.depthDb = r.number("depth");
        try {
            validateNotchFilter(n);
        } catch (const InvalidInput& e) {
            throw fieldError(r, e);
        }
        r.finish();
    }
}

QJsonObject axisToJson(const AxisSettings& a) {
    QJsonObject out{
        {"id", QString::fromStdString(a.id)},
        {"label", QString::fromStdString(a.label)},
        {"method", methodName(a.method)},
        {"gt", gtToJson(a.gt)},
        {"pp", QJsonObject{{"a", toArray(a.pp.a)},
                           {"b", toArray(a.pp.b)},
                           {"t1", a.pp.t1},
                           {"ts", a.pp.tsSeconds},
                           {"zpetc", a.pp.zpetcEnabled}}},
    };
    QJsonObject parameters;
    for (const auto& [name, value] : a.parameters)
        parameters.insert(QString::fromStdString(name), value);
    out.insert("parameters", parameters);
    if (a.origin)
        out.insert("model_origin", originToJson(*a.origin));
    if (a.friction.active() || a.frictionCompensation != FrictionCompensation{})
        out.insert("friction", frictionToJson(a.friction, a.frictionCompensation));
    return out;
}

QString trajectoryKindName(TrajectoryKind kind) {
    switch (kind) {
    case TrajectoryKind::Cubic:
        return QStringLiteral("cubic");
    case TrajectoryKind::Circle:
        return QStringLiteral("circle");
    case TrajectoryKind::Gcode:
        break;
    }
    return QStringLiteral("gcode");
}

QJsonObject trajectoryMotionToJson(const TrajectorySettings& t);

QJsonObject trajectoryToJson(const TrajectorySettings& t) {
    QJsonObject out = trajectoryMotionToJson(t);
    if (t.shaping.active())
        out.insert("shaping", QJsonObject{{"type", QString(shaperName(t.shaping.type))},
                                          {"frequency", t.shaping.frequencyHz},
                                          {"damping", t.shaping.dampingRatio}});
    return out;
}

/// The trajectory's "shaping" object: the shaper's type, frequency and damping, refused at
/// their paths as designInputShaper refuses them.
ReferenceShaping readShaping(ObjectReader r) {
    ReferenceShaping s;
    const QString type = r.string("type");
    if (!shaperFromName(type.toStdString(), s.type))
        throw FormatError{
            join(r.path(), "type"),
            SessionFileText::tr("must be zv, mzv, zvd, zvdd, ei, 2hump_ei or 3hump_ei")};
    s.frequencyHz = r.positive("frequency");
    s.dampingRatio = r.number("damping");
    try {
        designInputShaper(s.type, s.frequencyHz, s.dampingRatio);
    } catch (const InvalidInput& e) {
        throw FormatError{join(r.path(), QString::fromStdString(e.field())),
                          QString::fromStdString(e.reason()), e.reasonDiagnostic()};
    }
    r.finish();
    return s;
}

QJsonObject trajectoryMotionToJson(const TrajectorySettings& t) {
    return {{"kind", trajectoryKindName(t.kind)},
            {"cubic",
             QJsonObject{{"x0", t.x0},
                         {"xf", t.xf},
                         {"t0", t.t0Seconds},
                         {"tf", t.tfSeconds},
                         {"v0", t.v0},
                         {"vf", t.vf},
                         {"profile", t.profile == MoveProfile::Quintic ? QStringLiteral("quintic")
                                                                       : QStringLiteral("cubic")}}},
            {"circle", QJsonObject{{"radius", t.radius},
                                   {"omega", t.omegaRadPerSec},
                                   {"ramp_in", t.rampInSeconds}}},
            {"gcode", QJsonObject{{"file", QString::fromStdString(t.gcode.fileName)},
                                  {"program", QString::fromStdString(t.gcode.program)},
                                  {"feed_scale", t.gcode.feedScale},
                                  {"max_accel", t.gcode.maxAccelMmPerS2},
                                  {"max_jerk", t.gcode.maxJerkMmPerS3}}},
            {"duration", t.durationSeconds},
            {"dt", t.dtSeconds}};
}

QJsonObject implementationToJson(const ImplementationSettings& i) {
    return {{"delay_samples", i.delaySamples},
            {"encoder_resolution", i.encoderResolutionMm},
            {"dac_bits", i.dacBits},
            {"anti_windup", QString::fromStdString(antiWindupName(i.antiWindup))},
            {"tracking_time", i.trackingTimeSeconds}};
}

/// The implementation object: every field required (format version 2).
ImplementationSettings readImplementation(ObjectReader r) {
    ImplementationSettings i;
    i.delaySamples = r.integer("delay_samples", 0, kMaxDelaySamples);
    i.encoderResolutionMm = r.number("encoder_resolution");
    if (i.encoderResolutionMm < 0.0)
        throw FormatError{join(r.path(), "encoder_resolution"),
                          SessionFileText::tr("must be >= 0 (mm per count; 0: ideal encoder)")};
    i.dacBits = r.integer("dac_bits", 0, 32, SessionFileText::tr(" (0: ideal DAC)"));
    {
        const QString method = r.string("anti_windup");
        bool found = false;
        for (const AntiWindup a :
             {AntiWindup::None, AntiWindup::Clamp, AntiWindup::BackCalculation})
            if (method == QString::fromStdString(antiWindupName(a))) {
                i.antiWindup = a;
                found = true;
            }
        if (!found)
            throw FormatError{
                join(r.path(), "anti_windup"),
                SessionFileText::tr("must be \"none\", \"clamp\" or \"back-calculation\"")};
    }
    i.trackingTimeSeconds = r.number("tracking_time");
    if (i.trackingTimeSeconds < 0.0)
        throw FormatError{join(r.path(), "tracking_time"),
                          SessionFileText::tr("must be >= 0 (s; 0: Tt = Ti = kp/ki)")};
    r.finish();
    return i;
}

QJsonObject crossCouplingToJson(const CrossCoupling& c) {
    return {{"kp", c.kp}, {"ki", c.ki}, {"estimate", contourEstimateName(c.estimate)}};
}

/// The optional "cross_coupling" object, every field required, checked by the core's rules.
CrossCoupling readCrossCoupling(ObjectReader r) {
    CrossCoupling c;
    c.kp = r.number("kp");
    c.ki = r.number("ki");
    const QString estimate = r.string("estimate");
    if (!contourEstimateFromName(estimate.toStdString(), c.estimate))
        throw FormatError{join(r.path(), "estimate"),
                          SessionFileText::tr("must be \"linear\" or \"circular\"")};
    try {
        validateCrossCoupling(c, "cross_coupling");
    } catch (const InvalidInput& e) {
        throw FormatError{QString::fromStdString(e.field()), QString::fromStdString(e.reason()),
                          e.reasonDiagnostic()};
    }
    r.finish();
    return c;
}

QJsonArray axesToJson(const std::array<AxisSettings, 2>& axes) {
    return QJsonArray{axisToJson(axes[0]), axisToJson(axes[1])};
}

/**
 * The "parameters" object of an axis: a registered method's numbers by name (at most
 * kMaxMethodParameters). Those that the axis' method declares are checked against its range;
 * others are kept for the method that declares them.
 */
std::map<std::string, double> readMethodParameters(ObjectReader r, DesignMethod method) {
    constexpr qsizetype kMaxMethodParameters = 64;
    const QStringList keys = r.keys();
    if (keys.size() > kMaxMethodParameters)
        throw FormatError{r.path(), SessionFileText::tr("has %1 entries; at most %2 are allowed")
                                        .arg(keys.size())
                                        .arg(kMaxMethodParameters)};
    const std::vector<MethodParameter> declared = designMethodModule(method).parameters();
    std::map<std::string, double> out;
    for (const QString& key : keys) {
        const QString path = join(r.path(), key);
        if (!isMethodParameterName(key.toStdString()))
            throw FormatError{path,
                              SessionFileText::tr("must be named by 1 to 32 lower-case letters, "
                                                  "digits or '_'")};
        const double v = r.number(key);
        for (const MethodParameter& p : declared)
            if (p.name == key.toStdString() && !(v >= p.minimum && v <= p.maximum))
                throw FormatError{path, SessionFileText::tr("must be within %1 .. %2 %3")
                                            .arg(p.minimum)
                                            .arg(p.maximum)
                                            .arg(QString::fromStdString(p.unit))
                                            .trimmed()};
        out[key.toStdString()] = v;
    }
    return out;
}

AxisSettings readAxis(ObjectReader r) {
    AxisSettings a;
    a.id = r.string("id").toStdString();
    if (a.id.empty() || a.id.size() > 16 || !std::all_of(a.id.begin(), a.id.end(), [](char c) {
            return std::islower(static_cast<unsigned char>(c)) ||
                   std::isdigit(static_cast<unsigned char>(c));
        }))
        throw FormatError{join(r.path(), "id"),
                          SessionFileText::tr("must be 1 to 16 lower-case letters or digits")};
    if (r.has("label"))
        a.label = r.string("label").toStdString();
    a.method = methodFromName(r.string("method"), join(r.path(), "method"));
    {
        ObjectReader gt = r.child("gt");
        ObjectReader plant = gt.child("plant");
        a.gt.plant.k0 = plant.number("k0");
        if (a.gt.plant.k0 == 0.0)
            throw FormatError{join(plant.path(), "k0"), SessionFileText::tr("must be nonzero")};
        a.gt.plant.a1 = plant.number("a1");
        a.gt.plant.a2 = plant.number("a2");
        plant.finish();
        a.gt.omegaNRadPerSec = gt.positive("wn");
        a.gt.kp = gt.positive("kp");
        a.gt.modelUnitsPerPositionUnit = gt.positive("model_unit_scale");
        readGtLoopElements(gt, a.gt);
        gt.finish();
    }
    {
        ObjectReader pp = r.child("pp");
        a.pp.a = pp.coefficients("a");
        if (a.pp.a[0] == 0.0)
            throw FormatError{join(pp.path(), "a[0]"),
                              SessionFileText::tr("must be nonzero (A is monic)")};
        a.pp.b = pp.coefficients("b");
        a.pp.t1 = pp.number("t1");
        a.pp.tsSeconds = pp.positive("ts");
        a.pp.zpetcEnabled = pp.boolean("zpetc");
        pp.finish();
    }
    a.parameters = readMethodParameters(r.child("parameters"), a.method);
    if (r.has("model_origin"))
        a.origin = readOrigin(r.child("model_origin"));
    if (r.has("friction"))
        readFriction(r.child("friction"), a);
    r.finish();
    return a;
}

TrajectorySettings readTrajectory(ObjectReader r) {
    TrajectorySettings t;
    const QString kind = r.string("kind");
    if (kind == "cubic")
        t.kind = TrajectoryKind::Cubic;
    else if (kind == "circle")
        t.kind = TrajectoryKind::Circle;
    else if (kind == "gcode")
        t.kind = TrajectoryKind::Gcode;
    else
        throw FormatError{join(r.path(), "kind"),
                          SessionFileText::tr("must be \"cubic\", \"circle\" or \"gcode\"")};
    {
        ObjectReader c = r.child("cubic");
        t.x0 = c.number("x0");
        t.xf = c.number("xf");
        t.t0Seconds = c.number("t0");
        t.tfSeconds = c.number("tf");
        if (!(t.tfSeconds > t.t0Seconds))
            throw FormatError{join(c.path(), "tf"), SessionFileText::tr("must be later than t0")};
        t.v0 = c.number("v0");
        t.vf = c.number("vf");
        const QString profile = c.string("profile");
        if (profile == "quintic")
            t.profile = MoveProfile::Quintic;
        else if (profile != "cubic")
            throw FormatError{join(c.path(), "profile"),
                              SessionFileText::tr("must be \"cubic\" or \"quintic\"")};
        c.finish();
    }
    {
        ObjectReader c = r.child("circle");
        t.radius = c.positive("radius");
        t.omegaRadPerSec = c.positive("omega");
        t.rampInSeconds = c.number("ramp_in");
        if (t.rampInSeconds < 0)
            throw FormatError{join(c.path(), "ramp_in"), SessionFileText::tr("must be >= 0")};
        c.finish();
    }
    {
        ObjectReader g = r.child("gcode");
        t.gcode.fileName = g.string("file").toStdString();
        t.gcode.program = g.string("program").toStdString();
        t.gcode.feedScale = g.positive("feed_scale");
        t.gcode.maxAccelMmPerS2 = g.positive("max_accel");
        t.gcode.maxJerkMmPerS3 = g.number("max_jerk");
        if (t.gcode.maxJerkMmPerS3 < 0)
            throw FormatError{join(g.path(), "max_jerk"),
                              SessionFileText::tr("must be >= 0 (0 = none)")};
        try { // the planner's range, whatever the kind: a jerk of 1e-300 is refused here
            checkProgramOptions(t.gcode);
        } catch (const InvalidInput& e) {
            throw FormatError{join(g.path(), QString::fromStdString(e.field()).section('.', -1)),
                              QString::fromStdString(e.reason()), e.reasonDiagnostic()};
        }
        g.finish();
    }
    if (r.has("shaping"))
        t.shaping = readShaping(r.child("shaping"));
    t.durationSeconds = r.number("duration");
    if (t.durationSeconds < 0)
        throw FormatError{join(r.path(), "duration"),
                          SessionFileText::tr("must be >= 0 (0 = automatic)")};
    t.dtSeconds = r.positive("dt");
    if (t.kind == TrajectoryKind::Gcode) {
        // The program, its profile and its sample count, named by the session path
        // ("trajectory.gcode.program: line 12: unknown word G5 at column 4").
        try {
            programRunSeconds(t);
        } catch (const InvalidInput& e) {
            // The core names "trajectory.<field>"; a snapshot's trajectory has its own path.
            QString field = QString::fromStdString(e.field());
            field.remove(0, field.indexOf('.') + 1);
            throw FormatError{join(r.path(), field), QString::fromStdString(e.reason()),
                              e.reasonDiagnostic()};
        }
    }
    const double samples = std::floor(t.effectiveDurationSeconds() / t.dtSeconds) + 1.0;
    if (!(samples <=
          static_cast<double>(sampleLimit()))) // the limit follows the memory (trajectory.h)
        throw FormatError{
            join(r.path(), t.kind == TrajectoryKind::Gcode ? "dt" : "duration"),
            SessionFileText::tr("needs %1 samples at this dt; the limit is %2 on this machine")
                .arg(samples, 0, 'g', 3)
                .arg(sampleLimit())};
    r.finish();
    return t;
}

} // namespace

QString methodName(DesignMethod method) {
    const std::string_view id = designMethodModule(method).id();
    return QString::fromUtf8(id.data(), static_cast<qsizetype>(id.size()));
}

QJsonObject sessionToJson(const Session& s) {
    QJsonArray snapshots;
    for (const DesignSnapshot& snap : s.snapshots)
        snapshots.append(QJsonObject{{"name", QString::fromStdString(snap.name)},
                                     {"axes", axesToJson(snap.axes)},
                                     {"trajectory", trajectoryToJson(snap.trajectory)},
                                     {"umax", snap.umaxVolts}});
    QJsonObject root{
        {"format", kSessionFormatName},
        {"version", kSessionFormatVersion},
        {"axes", axesToJson(s.axes)},
        {"trajectory", trajectoryToJson(s.trajectory)},
        {"umax", s.umaxVolts},
        {"controller_ts", s.controllerTsSeconds},
        {"pi_discretization", QString::fromStdString(discretizationName(s.piDiscretization))},
        {"implementation", implementationToJson(s.implementation)},
        {"specification", QJsonObject{{"max_settling_time", s.spec.maxSettlingTimeSeconds},
                                      {"max_overshoot_pct", s.spec.maxOvershootPct},
                                      {"max_error_pct", s.spec.maxErrorPct},
                                      {"in_position_window_mm", s.spec.inPositionWindowMm},
                                      {"max_settle_time", s.spec.maxSettleTimeSeconds},
                                      {"min_phase_margin", s.spec.minPhaseMarginDeg},
                                      {"min_gain_margin", s.spec.minGainMarginDb}}},
        {"snapshots", snapshots}};
    if (s.crossCoupling != CrossCoupling{})
        root.insert("cross_coupling", crossCouplingToJson(s.crossCoupling));
    return root;
}

namespace {

std::array<AxisSettings, 2> readAxisPair(ObjectReader& r, QStringList* warnings) {
    const QJsonValue v = r.get("axes");
    const QString path = join(r.path(), "axes");
    if (!v.isArray() || v.toArray().size() != 2)
        throw FormatError{path, SessionFileText::tr("must be an array of exactly two axes")};
    const QJsonArray a = v.toArray();
    std::array<AxisSettings, 2> axes;
    for (qsizetype i = 0; i < 2; ++i)
        axes[static_cast<std::size_t>(i)] =
            readAxis(ObjectReader(a[i], QStringLiteral("%1[%2]").arg(path).arg(i), warnings));
    if (axes[0].id == axes[1].id)
        throw FormatError{path + "[1].id", SessionFileText::tr("must differ from axes[0].id")};
    return axes;
}

double readUmax(ObjectReader& r) {
    const double u = r.positive("umax");
    return u;
}

} // namespace

SessionLoadResult sessionFromJson(const QJsonObject& root) {
    SessionLoadResult result;
    try {
        if (root.value("format").toString() != kSessionFormatName)
            throw FormatError{"format",
                              SessionFileText::tr("must be \"%1\"").arg(kSessionFormatName)};
        const QJsonValue version = root.value("version");
        if (!version.isDouble() || version.toDouble() != std::floor(version.toDouble()) ||
            version.toDouble() < 1)
            throw FormatError{"version", SessionFileText::tr("must be a whole number >= 1")};
        if (version.toDouble() > kSessionFormatVersion)
            throw FormatError{
                "version", SessionFileText::tr("the file has format version %1; this XY Tune reads "
                                               "version %2 and older: please update XY Tune")
                               .arg(version.toDouble())
                               .arg(kSessionFormatVersion)};
        const int fileVersion = version.toInt();
        ObjectReader r(fileVersion < kSessionFormatVersion ? migrateSessionJson(root, fileVersion)
                                                           : root,
                       QString(), &result.warnings);
        r.get("format"); // read above
        r.get("version");
        Session s;
        s.axes = readAxisPair(r, &result.warnings);
        s.trajectory = readTrajectory(r.child("trajectory"));
        s.umaxVolts = readUmax(r);
        s.controllerTsSeconds = r.positive("controller_ts");
        const QString discretization = r.string("pi_discretization");
        if (discretization == "tustin")
            s.piDiscretization = PiDiscretization::Tustin;
        else if (discretization == "backward-euler")
            s.piDiscretization = PiDiscretization::BackwardEuler;
        else
            throw FormatError{"pi_discretization",
                              SessionFileText::tr("must be \"tustin\" or \"backward-euler\"")};
        s.implementation = readImplementation(r.child("implementation"));
        if (r.has("cross_coupling"))
            s.crossCoupling = readCrossCoupling(r.child("cross_coupling"));
        {
            ObjectReader spec = r.child("specification");
            s.spec.maxSettlingTimeSeconds = spec.positive("max_settling_time");
            s.spec.maxOvershootPct = spec.number("max_overshoot_pct");
            if (s.spec.maxOvershootPct < 0)
                throw FormatError{"specification.max_overshoot_pct",
                                  SessionFileText::tr("must be >= 0")};
            s.spec.maxErrorPct = spec.positive("max_error_pct");
            s.spec.inPositionWindowMm = spec.positive("in_position_window_mm");
            s.spec.maxSettleTimeSeconds = spec.positive("max_settle_time");
            s.spec.minPhaseMarginDeg = spec.number("min_phase_margin");
            if (!(s.spec.minPhaseMarginDeg >= 0.0 && s.spec.minPhaseMarginDeg <= 180.0))
                throw FormatError{"specification.min_phase_margin",
                                  SessionFileText::tr("must be 0 .. 180 degrees")};
            s.spec.minGainMarginDb = spec.number("min_gain_margin");
            if (!(s.spec.minGainMarginDb >= 0.0))
                throw FormatError{"specification.min_gain_margin",
                                  SessionFileText::tr("must be >= 0 dB")};
            spec.finish();
        }
        const QJsonValue snaps = r.get("snapshots");
        if (!snaps.isArray())
            throw FormatError{"snapshots", SessionFileText::tr("must be an array")};
        const QJsonArray list = snaps.toArray();
        if (list.size() > kMaxSnapshots)
            throw FormatError{"snapshots",
                              SessionFileText::tr("has %1 entries; at most %2 are allowed")
                                  .arg(list.size())
                                  .arg(kMaxSnapshots)};
        for (qsizetype i = 0; i < list.size(); ++i) {
            ObjectReader sr(list[i], QStringLiteral("snapshots[%1]").arg(i), &result.warnings);
            DesignSnapshot snap;
            snap.name = sr.string("name").toStdString();
            snap.axes = readAxisPair(sr, &result.warnings);
            snap.trajectory = readTrajectory(sr.child("trajectory"));
            snap.umaxVolts = readUmax(sr);
            sr.finish();
            s.snapshots.push_back(std::move(snap));
        }
        r.finish();
        result.session = std::move(s);
        result.ok = true;
    } catch (const FormatError& e) {
        result.ok = false;
        result.errorPath = e.path;
        result.error = e.reason;
        result.errorDiagnostic = e.reasonDiagnostic;
    }
    return result;
}

SessionLoadResult sessionFromBytes(const QByteArray& bytes) {
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(bytes, &parseError);
    if (parseError.error != QJsonParseError::NoError) {
        SessionLoadResult r;
        r.error = SessionFileText::tr("not valid JSON: %1 at byte %2")
                      .arg(parseError.errorString())
                      .arg(parseError.offset);
        return r;
    }
    if (const auto duplicate = findDuplicateJsonKey(
            std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size())))) {
        SessionLoadResult r;
        r.errorPath = QString::fromStdString(*duplicate);
        r.error = SessionFileText::tr(
            "appears more than once in its object; a key may be given only once");
        return r;
    }
    if (!doc.isObject()) {
        SessionLoadResult r;
        r.error = SessionFileText::tr("not a session: the document must be a JSON object");
        return r;
    }
    return sessionFromJson(doc.object());
}

SessionLoadResult loadSessionFile(const QString& path) {
    std::string bytes;
    try {
        bytes = readRegularFile(path.toStdString(), static_cast<std::size_t>(kMaxSessionFileBytes));
    } catch (const FileError& e) {
        SessionLoadResult r;
        r.error = QString::fromStdString(e.what());
        r.errorDiagnostic = makeDiagnostic("field_reason", {e.path(), e.reasonDiagnostic()});
        return r;
    }
    return sessionFromBytes(QByteArray::fromStdString(bytes));
}

bool writeFileAtomically(const QString& path, const QByteArray& bytes, QString* error) {
    try {
        xyt::writeFileAtomically(
            path.toStdString(),
            std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size())));
        return true;
    } catch (const FileError& e) {
        if (error)
            *error = QString::fromStdString(e.what());
        return false;
    }
}

bool saveSessionFile(const Session& session, const QString& path, QString* error) {
    return writeFileAtomically(
        path, QJsonDocument(sessionToJson(session)).toJson(QJsonDocument::Indented), error);
}

} // namespace xyt::files
