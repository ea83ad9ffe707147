// SPDX-License-Identifier: GPL-3.0-or-later
// xytune-cli identify: an axis model from a logged experiment. Reads the file, picks
// the columns, preprocesses (range, detrend, decimate), identifies the chosen structure and
// prints the estimate with its uncertainty, fits, FPE/AIC, residual tests, poles and zeros.
#include "app/cli_args.h"
#include "app/cli_commands.h"
#include "app/cli_design_args.h"
#include "app/cli_friction.h"
#include "app/cli_json.h"
#include "app/cli_spectra.h"

#include "core/identification/continuous_fit.h"
#include "core/identification/experiment_data.h"
#include "core/identification/experiment_file.h"
#include "core/identification/identification.h"
#include "core/identification/preprocessing.h"
#include "core/io/file_io.h"
#include "core/io/text_escape.h"
#include "core/model/errors.h"
#include "core/model/number_format.h"
#include "core/session/identified_axis.h"
#include "core/session/session_evaluation.h"
#include "ui/files/session_file.h"

#include <QJsonDocument>

#include <QJsonArray>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace xyt::cli {

namespace {

/// The table of @p path, only @p columns kept; a file that cannot be read is bad input naming
/// @p option.
ExperimentTable readTable(const QString& option, const QString& path, std::size_t segment,
                          const std::vector<std::string>& columns) {
    try {
        return readExperimentTable(fileNameBytes(path), segment, columns);
    } catch (const FileError& e) {
        throw InvalidInput(option.toStdString(), e.what());
    }
}

/// "T0:T1" in seconds.
std::pair<double, double> parseRange(const QString& text) {
    const QStringList parts = text.split(':');
    bool ok0 = false, ok1 = false;
    const double t0 = parts.size() == 2 ? parts[0].toDouble(&ok0) : 0.0;
    const double t1 = parts.size() == 2 ? parts[1].toDouble(&ok1) : 0.0;
    if (!ok0 || !ok1 || !std::isfinite(t0) || !std::isfinite(t1) || !(t1 > t0))
        throw InvalidInput("--range",
                           "'" + text.toStdString() + "' is not T0:T1 in seconds with T1 > T0");
    return {t0, t1};
}

/// The record of one file with the command's column, time and scale options.
IoData record(const CliArgs& args, const QString& option, const QString& path) {
    const auto segment = static_cast<std::size_t>(args.count("segment", 1, 1'000'000));
    ExperimentColumns c;
    c.input = args.text("input-col", QString()).toStdString();
    c.output = args.text("output-col", QString()).toStdString();
    if (c.input.empty())
        throw InvalidInput("--input-col", "give the command column's name");
    if (c.output.empty())
        throw InvalidInput("--output-col", "give the position column's name");
    if (args.has("time-col") && args.has("ts"))
        throw InvalidInput("--ts", "give either --time-col or --ts, not both");
    if (args.has("time-col"))
        c.time = args.text("time-col", QString()).toStdString();
    else if (args.has("ts")) {
        c.sampleTimeSeconds = args.number("ts");
        requireSampleTime(*c.sampleTimeSeconds, "--ts");
    }
    // The columns are checked against the file's names before its rows are read, and only
    // they are kept: the other columns of a large file cost no memory.
    ExperimentTable table = readTable(option, path, segment, usedColumns(c, path.toStdString()));
    if (!args.has("time-col") && !args.has("ts")) {
        if (!table.sampleTimeSeconds)
            throw InvalidInput(
                "--ts", "the file states no sample time: give --time-col NAME or --ts SECONDS");
        c.fileSampleTime = true;
    }
    const QString unit = args.text("output-unit", "mm");
    if (unit == "m")
        c.outputScale.unit = OutputUnit::Metres;
    else if (unit == "counts") {
        c.outputScale.unit = OutputUnit::EncoderCounts;
        c.outputScale.mmPerCount = args.number("mm-per-count");
    } else if (unit != "mm")
        throw InvalidInput("--output-unit", "must be mm, m or counts");
    PreprocessingSteps steps;
    if (const auto range = args.value("range")) {
        const auto [t0, t1] = parseRange(*range);
        steps.rangeSeconds = std::array<double, 2>{t0, t1};
    }
    steps.offsets = args.flag("detrend")        ? OffsetRemoval::Trends
                    : args.flag("remove-means") ? OffsetRemoval::Means
                                                : OffsetRemoval::None;
    if (args.has("decimate"))
        steps.decimateFactor = args.count("decimate", 1, 1000);
    return preprocess(experimentData(std::move(table), c), steps);
}

QJsonObject dataJson(const IoData& d) {
    return {{"source", QString::fromStdString(d.source)},
            {"samples", static_cast<qint64>(d.size())},
            {"ts", number(d.tsSeconds)},
            {"start", number(d.startSeconds)}};
}

QJsonObject correlationJson(const CorrelationTest& t) {
    return {{"passed", t.passed},        {"bound", number(t.bound)},
            {"outside", t.outsideCount}, {"lags", static_cast<qint64>(t.lags.size())},
            {"worst_lag", t.worstLag},   {"worst_value", number(t.worstValue)}};
}

QJsonObject fitJson(const ModelFit& simulation, const ModelFit& prediction) {
    return {{"simulation", number(simulation.fitPercent)},
            {"prediction", number(prediction.fitPercent)},
            {"horizon", prediction.horizon}};
}

/// @p originMm: the position the record's outputs were taken relative to (gt3: its first
/// sample), added back so that initial_position is where the table stood, not where it stood
/// relative to that sample.
QJsonObject modelJson(const IdentifiedModel& m, double originMm) {
    QJsonObject parameters;
    for (std::size_t i = 0; i < m.parameters.size(); ++i)
        parameters.insert(
            QString::fromStdString(m.parameterNames[i]),
            QJsonObject{
                {"value", number(m.parameters[i])},
                {"std", number(i < m.standardDeviations.size() ? m.standardDeviations[i] : NAN)}});
    QJsonObject polynomials{{"a", numbers(m.model.a)}, {"b", numbers(m.model.b)},
                            {"c", numbers(m.model.c)}, {"d", numbers(m.model.d)},
                            {"f", numbers(m.model.f)}, {"ts", number(m.model.tsSeconds)}};
    QJsonObject out{{"structure", QString::fromStdString(m.structure)},
                    {"status", QString::fromStdString(estimationStatusName(m.status))},
                    {"message", QString::fromStdString(m.message)},
                    {"parameters", parameters},
                    {"polynomials", polynomials}};
    if (m.plant)
        out.insert("plant",
                   QJsonObject{{"k0", number(m.plant->k0)},
                               {"a1", number(m.plant->a1)},
                               {"a2", number(m.plant->a2)},
                               {"output_unit", "mm"},
                               {"initial_position", number(originMm + m.initialPositionMm)}});
    return out;
}

/// The most fits one --order-table runs: 10 x 10 x 10 orders. Each is a least-squares fit over
/// the whole record; 1:100,1:100,0:100 asked for a million of them (hours, with no end shown).
constexpr double kMaxOrderTableFits = 1000;

/// "NA0:NA1,NB0:NB1,NK0:NK1": the ARX order ranges of --order-table, refused (naming the
/// option) when malformed or when they ask for more than kMaxOrderTableFits fits.
std::array<OrderRange, 3> parseOrderTable(const QString& text) {
    const QStringList parts = text.split(',');
    std::vector<OrderRange> ranges;
    for (const QString& part : parts) {
        const QStringList ends = part.split(':');
        bool ok0 = false, ok1 = false;
        const int lo = ends.size() == 2 ? ends[0].toInt(&ok0) : 0;
        const int hi = ends.size() == 2 ? ends[1].toInt(&ok1) : 0;
        if (!ok0 || !ok1)
            throw InvalidInput("--order-table",
                               "'" + text.toStdString() +
                                   "' is not NA0:NA1,NB0:NB1,NK0:NK1 (e.g. 1:4,1:4,0:2)");
        ranges.push_back({lo, hi});
    }
    if (ranges.size() != 3)
        throw InvalidInput("--order-table", "give three ranges: na, nb, nk (e.g. 1:4,1:4,0:2)");
    double fits = 1.0;
    for (const OrderRange& r : ranges)
        fits *= std::max(0.0, double(r.max) - double(r.min) + 1.0);
    if (fits > kMaxOrderTableFits)
        throw InvalidInput("--order-table", "'" + text.toStdString() + "' asks for " +
                                                formatNumber(fits, 15) + " fits; at most " +
                                                formatNumber(kMaxOrderTableFits) +
                                                " are run in one table (narrow the ranges)");
    return {ranges[0], ranges[1], ranges[2]};
}

/// The table of the ARX orders of @p ranges, its progress on stderr (a table of 1000 fits on a
/// long record takes minutes).
QJsonObject orderTableJson(const std::array<OrderRange, 3>& ranges, const IoData& estimation,
                           const IoData* validation) {
    int shown = -1; // the last tenth reported
    const auto progress = [&shown](double fraction) {
        const int tenth = static_cast<int>(fraction * 10.0);
        if (tenth > shown) {
            shown = tenth;
            std::fprintf(stderr, "xytune-cli identify: order table %d %% done\n", tenth * 10);
            std::fflush(stderr);
        }
        return true;
    };
    ArxOrderTable t;
    try {
        t = arxOrderTable(estimation, validation, ranges[0], ranges[1], ranges[2], progress);
    } catch (const InvalidInput& e) {
        throw InvalidInput("--order-table", e.what());
    }
    QJsonArray rows;
    for (const ArxOrderRow& r : t.rows)
        rows.append(QJsonObject{{"na", r.orders.na},
                                {"nb", r.orders.nb},
                                {"nk", r.orders.nk},
                                {"status", QString::fromStdString(estimationStatusName(r.status))},
                                {"loss", number(r.loss)},
                                {"fpe", number(r.fpe)},
                                {"aic", number(r.aic)},
                                {"validation_loss", number(r.validationLoss)}});
    QJsonObject out{{"rows", rows}, {"common_first_sample", static_cast<qint64>(t.commonFirstRow)}};
    const auto orders = [&](std::optional<std::size_t> i) {
        return i ? QJsonValue(QString::fromStdString(t.rows[*i].orders.toString())) : QJsonValue();
    };
    out.insert("best_aic", orders(t.bestAic));
    out.insert("best_validation", orders(t.bestValidation));
    return out;
}

} // namespace

IoData identifyRecord(const CliArgs& args, const QString& option, const QString& path) {
    return record(args, option, path);
}

int runIdentify(const QStringList& argv) {
    const CliArgs args = CliArgs::parse(argv, {"detrend", "remove-means", "no-stribeck"});
    if (args.text("structure", QString()) == "friction")
        return identifyFrictionCurve(args);
    if (args.text("structure", QString()) == "frf")
        return identifyFrequencyResponse(args);
    args.allowOnly({"data",
                    "time-col",
                    "ts",
                    "input-col",
                    "output-col",
                    "output-unit",
                    "mm-per-count",
                    "segment",
                    "structure",
                    "na",
                    "nb",
                    "nc",
                    "nd",
                    "nf",
                    "nk",
                    "validate",
                    "range",
                    "detrend",
                    "remove-means",
                    "decimate",
                    "horizon",
                    "max-lag",
                    "max-iterations",
                    "session",
                    "axis",
                    "o",
                    "order-table"});
    // --session IN.json --axis x|y -o OUT.json: "use this model" from the command line.
    std::optional<Session> session;
    int axis = 0;
    if (args.has("session") || args.has("o") || args.has("axis")) {
        if (!args.has("session"))
            throw InvalidInput("--session",
                               "give the session whose axis takes the model (with --axis and -o)");
        const auto output = args.value("o");
        if (!output || output->isEmpty())
            throw InvalidInput("-o",
                               "give the file to write the session with the identified model to");
        const QString axisName = args.text("axis", QString());
        if (axisName != "x" && axisName != "y")
            throw InvalidInput("--axis", "must be x or y (the axis that takes the model)");
        axis = axisName == "x" ? 0 : 1;
        session = loadSessionOrThrow(*args.value("session"));
    }
    if (!args.has("data"))
        throw InvalidInput("--data", "give the experiment file (CSV/TSV, .lvm or .mat)");
    if (!args.has("structure"))
        throw InvalidInput("--structure", "give arx, oe, bj, gt3, friction or frf");
    IdentificationSpec spec;
    try {
        spec.structure = parseModelStructure(args.text("structure", QString()).toStdString());
    } catch (const InvalidInput& e) {
        throw InvalidInput("--structure", e.reason());
    }
    // The orders each estimator takes (ArxOrders, OeOrders, BjOrders::validate): 0 for na (FIR),
    // nk (a direct feedthrough), nc, nd and nf; nb at least 1 (a model without input).
    const auto order = [&](const char* name, int fallback, int minimum) {
        return args.integer(name, fallback, minimum, 100);
    };
    spec.arx = {order("na", 2, 0), order("nb", 3, 1), order("nk", 1, 0)};
    spec.oe = {order("nb", 3, 1), order("nf", 2, 0), order("nk", 1, 0)};
    spec.bj = {order("nb", 3, 1), order("nc", 1, 0), order("nd", 1, 0), order("nf", 2, 0),
               order("nk", 1, 0)};
    spec.predictionHorizon = args.count("horizon", 5, 1'000'000);
    spec.maxLag = args.count("max-lag", 25, 10'000);
    spec.search.maxIterations = args.count("max-iterations", 100, 100'000);
    std::optional<std::array<OrderRange, 3>> orderTable;
    if (const auto text = args.value("order-table"))
        orderTable = parseOrderTable(*text);

    IoData estimation = record(args, "--data", *args.value("data"));
    std::optional<IoData> validation;
    if (const auto path = args.value("validate"))
        validation = record(args, "--validate", *path);
    QJsonArray notes;
    double estimationOrigin = 0.0; // the position the estimation record was taken relative to
    if (spec.structure == ModelStructure::ContinuousThirdOrder) {
        // The plant integrates: its model starts at rest at position 0, so the record's initial
        // position is taken off (said here, not guessed silently).
        for (IoData* d : {&estimation, validation ? &*validation : nullptr}) {
            const std::optional<double> y0 = d ? subtractInitialPosition(*d) : std::nullopt;
            if (!y0)
                continue;
            if (d == &estimation)
                estimationOrigin = *y0;
            notes.append(
                QStringLiteral(
                    "%1: the first sample %2 mm was subtracted for the fit; initial_position "
                    "adds it back (where the table stood)")
                    .arg(QString::fromStdString(d->source))
                    .arg(*y0, 0, 'g', 10));
        }
    }
    const IdentifiedModel m = identifyModel(estimation, validation ? &*validation : nullptr, spec);
    QJsonObject out{{"data", dataJson(estimation)}, {"model", modelJson(m, estimationOrigin)}};
    if (orderTable)
        out.insert("order_table",
                   orderTableJson(*orderTable, estimation, validation ? &*validation : nullptr));
    if (validation)
        out.insert("validation_data", dataJson(*validation));
    if (m.hasEstimate()) {
        QJsonObject fit{
            {"estimation", fitJson(m.fit.estimationSimulation, m.fit.estimationPrediction)}};
        if (m.fit.validationSimulation)
            fit.insert("validation",
                       fitJson(*m.fit.validationSimulation, *m.fit.validationPrediction));
        out.insert("fit", fit);
        out.insert("fpe", number(m.criteria.samples > 0 ? m.criteria.fpe : NAN));
        out.insert("aic", number(m.criteria.samples > 0 ? m.criteria.aic : NAN));
        if (m.residualTests.samples > 0)
            out.insert(
                "residual_tests",
                QJsonObject{
                    {"passed", m.residualTests.passed()},
                    {"autocorrelation", correlationJson(m.residualTests.autocorrelation)},
                    {"cross_correlation", correlationJson(m.residualTests.crossCorrelation)}});
        out.insert("poles", complexPairs(m.roots.poles));
        out.insert("zeros", complexPairs(m.roots.zeros));
        if (!m.roots.continuousPoles.empty())
            out.insert("continuous_poles", complexPairs(m.roots.continuousPoles));
        out.insert("stable", m.roots.stable);
        out.insert("integrating", m.roots.integrating);
        out.insert("non_minimum_phase", m.roots.nonMinimumPhase);
    }
    QJsonArray warnings = notes;
    for (const std::string& w : m.warnings)
        warnings.append(QString::fromStdString(w));
    out.insert("warnings", warnings);
    if (session && m.hasEstimate()) {
        session->axes[static_cast<std::size_t>(axis)] =
            axisWithIdentifiedModel(session->axes[static_cast<std::size_t>(axis)], m, estimation);
        // The session written must run as `report` runs it: a Ts the session's run cannot
        // sample (pp.ts 1e-6 s: the default session's run needs 5.2e8 samples) is refused
        // here, not by the next command that opens the file.
        std::string refused;
        try {
            for (const AxisEvaluation& a : evaluateSession(*session).axes)
                if (!a.ok && a.runRefused && refused.empty())
                    refused = a.errorField + ": " + a.error.text;
        } catch (const InvalidInput& e) {
            refused = e.what();
        }
        if (!refused.empty())
            throw InvalidInput("-o",
                               "the session with this model cannot be run as report runs it (" +
                                   refused + "); nothing was written");
        writeTextFile("-o", *args.value("o"),
                      QString::fromUtf8(QJsonDocument(files::sessionToJson(*session)).toJson()));
        out.insert("session", QString::fromStdString(terminalText(args.value("o")->toStdString())));
    }
    print(out);
    return m.hasEstimate() ? 0 : 3;
}

} // namespace xyt::cli
