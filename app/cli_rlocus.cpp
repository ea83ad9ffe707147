// SPDX-License-Identifier: GPL-3.0-or-later
// xytune-cli rlocus: the root locus of 1 + K N/D = 0 (continuous or discrete), or of the
// Guillemin-Truxal loop of Braga et al. (K = 1 is the design point).
#include "app/cli_args.h"
#include "app/cli_commands.h"
#include "app/cli_json.h"

#include "core/analysis/root_locus.h"
#include "core/design/guillemin_truxal.h"
#include "core/model/coefficient_parser.h"
#include "core/model/errors.h"

#include <map>
#include <optional>

namespace xyt::cli {

namespace {

/// Core field names of rootLocus/fromZInverse -> the CLI argument that supplied them.
InvalidInput asArgument(const InvalidInput& e) {
    static const std::map<std::string, std::string> arguments = {{"num", "--num"},
                                                                 {"den", "--den"},
                                                                 {"ts", "--ts"},
                                                                 {"kMax", "--kmax"},
                                                                 {"maxStepFraction", "--max-step"},
                                                                 {"maxPoints", "--max-points"},
                                                                 {"wn", "--wn"},
                                                                 {"kp", "--kp"}};
    const auto it = arguments.find(e.field());
    return InvalidInput(it != arguments.end() ? it->second : e.field(), e.reason());
}

struct LoopInput {
    Polynomial num, den;
    double tsSeconds = 0.0;
    std::optional<GtDesign> design;
};

LoopInput parseLoop(const CliArgs& args) {
    LoopInput in;
    if (const auto presetName = args.value("gt-preset")) {
        for (const char* excluded : {"num", "den", "ts"})
            if (args.has(excluded))
                throw InvalidInput(CliArgs::field(excluded), "cannot be combined with --gt-preset");
        const auto preset = findGtPreset(presetName->toStdString());
        if (!preset)
            throw InvalidInput("--gt-preset", "unknown preset '" + presetName->toStdString() +
                                                  "' (lower-base or upper-base)");
        const double wn = args.number("wn", preset->omegaNRadPerSec);
        const double kp = args.number("kp", preset->kp);
        if (!(wn > 0.0))
            throw InvalidInput("--wn", "must be greater than zero");
        if (!(kp > 0.0))
            throw InvalidInput("--kp", "must be greater than zero");
        try {
            in.design = designGuilleminTruxal(preset->plant, wn, kp);
        } catch (const InvalidInput& e) {
            throw asArgument(e);
        }
        in.num = in.design->openLoop.num();
        in.den = in.design->openLoop.den();
        return in;
    }
    for (const char* gtOnly : {"wn", "kp"})
        if (args.has(gtOnly))
            throw InvalidInput(CliArgs::field(gtOnly), "needs --gt-preset");
    const auto numText = args.value("num");
    const auto denText = args.value("den");
    if (!numText)
        throw InvalidInput("--num", "is required (or --gt-preset)");
    if (!denText)
        throw InvalidInput("--den", "is required (or --gt-preset)");
    const std::vector<double> num = parseCoefficientList(numText->toStdString(), "--num");
    const std::vector<double> den = parseCoefficientList(denText->toStdString(), "--den");
    try {
        if (args.has("ts")) {
            // Discrete: ascending powers of z^-1, as Patrick, Ishak and Adnan write their ARX
            // models.
            in.tsSeconds = args.number("ts");
            if (!(in.tsSeconds > 0.0))
                throw InvalidInput("--ts", "must be greater than zero");
            const TransferFunction tf = TransferFunction::fromZInverse(
                Polynomial::fromAscending(num, "--num"), Polynomial::fromAscending(den, "--den"),
                in.tsSeconds);
            in.num = tf.num();
            in.den = tf.den();
        } else {
            in.num = Polynomial::fromDescending(num, "--num");
            in.den = Polynomial::fromDescending(den, "--den");
        }
    } catch (const InvalidInput& e) {
        throw asArgument(e);
    }
    return in;
}

QJsonArray pointJson(std::initializer_list<double> values) {
    QJsonArray a;
    for (double v : values)
        a.append(number(v));
    return a;
}

QJsonObject locusJson(const RootLocus& r) {
    QJsonArray branches;
    for (const LocusBranch& b : r.branches) {
        QJsonArray points;
        for (std::size_t i = 0; i < b.roots.size(); ++i)
            points.append(pointJson({r.gains[i], b.roots[i].real(), b.roots[i].imag()}));
        branches.append(points);
    }
    QJsonArray ends;
    for (const LocusBranch& b : r.branches)
        ends.append(b.end ? QJsonValue(pointJson({b.end->real(), b.end->imag()})) : QJsonValue());
    QJsonArray breakaway, crossings;
    for (const LocusFeature& f : r.breakaways)
        breakaway.append(pointJson({f.point.real(), f.point.imag(), f.gain}));
    for (const LocusFeature& f : r.crossings)
        crossings.append(pointJson({f.gain, f.point.real(), f.point.imag()}));
    QJsonArray warnings;
    for (const std::string& w : r.warnings)
        warnings.append(QString::fromStdString(w));
    const bool hasAsymptotes = r.asymptotes.count > 0;
    return {{"ts", number(r.tsSeconds)},
            {"branches", branches},
            {"branch_ends", ends},
            {"poles", complexPairs(r.poles)},
            {"zeros", complexPairs(r.zeros)},
            {"asymptotes",
             QJsonObject{{"count", r.asymptotes.count},
                         {"centroid", hasAsymptotes ? number(r.asymptotes.centroid) : QJsonValue()},
                         {"angles_deg", numbers(r.asymptotes.anglesDeg)}}},
            {"breakaway", breakaway},
            {"crossings", crossings},
            {"view", QJsonObject{{"re_min", number(r.view.reMin)},
                                 {"re_max", number(r.view.reMax)},
                                 {"im_min", number(r.view.imMin)},
                                 {"im_max", number(r.view.imMax)}}},
            {"max_step", number(r.maxStep)},
            {"status", r.status == RootLocusStatus::Complete            ? "complete"
                       : r.status == RootLocusStatus::PointLimitReached ? "point_limit_reached"
                                                                        : "gain_limit_reached"},
            {"warnings", warnings}};
}

} // namespace

int runRlocus(const QStringList& argv) {
    const CliArgs args = CliArgs::parse(argv);
    args.allowOnly({"num", "den", "ts", "kmax", "max-step", "max-points", "gt-preset", "wn", "kp"});
    if (!args.positional().isEmpty())
        throw InvalidInput(args.positional().first().toStdString(),
                           "unexpected argument (quote coefficient lists: --num \"1 2\")");
    const LoopInput in = parseLoop(args);
    RootLocusOptions options;
    if (args.has("kmax")) {
        options.kMax = args.number("kmax");
        if (!(options.kMax > 0.0))
            throw InvalidInput("--kmax", "must be greater than zero");
    }
    options.maxStepFraction = args.number("max-step", options.maxStepFraction);
    options.maxPoints = args.count("max-points", options.maxPoints, 1000000);
    RootLocus locus;
    try {
        locus = rootLocus(in.num, in.den, in.tsSeconds, options);
    } catch (const InvalidInput& e) {
        throw asArgument(e);
    }
    QJsonObject out = locusJson(locus);
    if (in.design) {
        // K multiplies L = G_c G, so K = 1 is the design: its closed-loop poles (Eq. 7).
        out.insert("design_gain", 1.0);
        out.insert("design_poles", complexPairs(in.design->closedLoopPoles));
        out.insert("wn", number(in.design->omegaNRadPerSec));
        out.insert("kp", number(in.design->kp));
        out.insert("ki", number(in.design->ki));
    }
    print(out);
    return 0;
}

} // namespace xyt::cli
