// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/identification/experiment_data.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/model/number_format.h"

#include <cmath>

namespace xyt {

namespace {

/// The column's values after checking every cell is a usable number.
const std::vector<double>& usedColumn(const ExperimentTable& t, std::size_t c) {
    if (const auto& p = t.firstProblem[c])
        throw InvalidInput(t.cellField(c, p->row),
                           p->text.empty()
                               ? makeDiagnostic("ident_value_missing")
                               : makeDiagnostic("ident_cell_reason", {p->text, p->reason}));
    return t.columns[c];
}

} // namespace

std::vector<std::string> usedColumns(const ExperimentColumns& cols, const std::string& fileName) {
    if (cols.input == cols.output)
        throw InvalidInput(fileName,
                           makeDiagnostic("ident_column_input_output", {shownCell(cols.input)}));
    std::vector<std::string> names{cols.input, cols.output};
    if (!cols.time.empty() && cols.time != cols.input && cols.time != cols.output)
        names.push_back(cols.time);
    return names;
}

namespace {

/// experimentData; with @p take the table's u column is moved into the record rather than
/// copied (a record of 10 million samples is 80 MB a column).
IoData record(const ExperimentTable& t, const ExperimentColumns& cols, ExperimentTable* take) {
    const int timeSources = int(!cols.time.empty()) + int(cols.sampleTimeSeconds.has_value()) +
                            int(cols.fileSampleTime);
    if (timeSources != 1)
        throw InvalidInput(t.fileName, makeDiagnostic(timeSources == 0 ? "ident_no_time_source"
                                                                       : "ident_one_time_source"));
    usedColumns(cols, t.fileName);
    const std::size_t ui = t.column(cols.input);
    const std::size_t yi = t.column(cols.output);
    double scale = 1.0;
    switch (cols.outputScale.unit) {
    case OutputUnit::Millimetres:
        scale = 1.0;
        break;
    case OutputUnit::Metres:
        scale = 1000.0;
        break;
    case OutputUnit::EncoderCounts:
        requirePositive(cols.outputScale.mmPerCount, "mm_per_count");
        scale = cols.outputScale.mmPerCount;
        break;
    }
    const std::vector<double>& u = usedColumn(t, ui);
    const std::vector<double>& y = usedColumn(t, yi);
    if (u.size() != y.size())
        throw InvalidInput(t.fileName,
                           makeDiagnostic("ident_column_lengths",
                                          {shownCell(cols.input), std::to_string(u.size()),
                                           shownCell(cols.output), std::to_string(y.size())}));
    IoData d;
    // Names shown escaped: a header may hold control characters, and messages are one line.
    d.source =
        t.fileName + ": u=" + shownCell(cols.input, 80) + ", y=" + shownCell(cols.output, 80);
    if (take && cols.time != cols.input)
        d.u = std::move(take->columns[ui]);
    else
        d.u = u;
    const std::size_t n = d.u.size();
    d.y.resize(y.size());
    for (std::size_t k = 0; k < y.size(); ++k) {
        d.y[k] = scale * y[k];
        if (!std::isfinite(d.y[k]))
            throw InvalidInput(t.cellField(yi, k), makeDiagnostic("ident_scaled_beyond_double"));
    }
    requireSamples(d, 2, makeDiagnostic("ident_a_sampled_record"));

    if (cols.sampleTimeSeconds) {
        requireSampleTime(*cols.sampleTimeSeconds, "sample_time");
        d.tsSeconds = *cols.sampleTimeSeconds;
    } else if (cols.fileSampleTime) {
        if (!t.sampleTimeSeconds)
            throw InvalidInput(t.fileName, makeDiagnostic("ident_no_stated_sample_time"));
        requireSampleTime(*t.sampleTimeSeconds, t.fileName + ": the stated sample time");
        d.tsSeconds = *t.sampleTimeSeconds;
    } else {
        const std::size_t ti = t.column(cols.time);
        const std::vector<double>& time = usedColumn(t, ti);
        if (time.size() != n)
            throw InvalidInput(t.fileName,
                               makeDiagnostic("ident_time_lengths",
                                              {shownCell(cols.time), std::to_string(time.size()),
                                               std::to_string(n)}));
        for (std::size_t k = 1; k < time.size(); ++k)
            if (!(time[k] > time[k - 1]))
                throw InvalidInput(
                    t.cellField(ti, k),
                    makeDiagnostic("ident_time_not_increasing",
                                   {formatNumber(time[k], 10), formatNumber(time[k - 1], 10)}));
        const double ts = (time[n - 1] - time[0]) / double(n - 1);
        if (!(ts > 0.0) || !std::isfinite(ts))
            throw InvalidInput(t.cellField(ti, n - 1), makeDiagnostic("ident_time_no_sample_time"));
        requireSampleTime(ts, t.cellField(ti, n - 1) + ": the time column's sample time");
        for (std::size_t k = 1; k < n; ++k) {
            const double step = time[k] - time[k - 1];
            if (std::abs(step - ts) > kSampleTimeTolerance * ts)
                throw InvalidInput(t.cellField(ti, k),
                                   makeDiagnostic("ident_time_step_differs",
                                                  {formatNumber(step, 6), formatNumber(ts, 6)}));
        }
        d.tsSeconds = ts;
        d.startSeconds = time[0];
    }
    return d;
}

} // namespace

IoData experimentData(const ExperimentTable& table, const ExperimentColumns& columns) {
    return record(table, columns, nullptr);
}

IoData experimentData(ExperimentTable&& table, const ExperimentColumns& columns) {
    return record(table, columns, &table);
}

void requireSamples(const IoData& data, std::size_t minimum, const Diagnostic& what) {
    const std::string field = data.source.empty() ? std::string("data") : data.source;
    if (data.u.size() != data.y.size())
        throw InvalidInput(
            field, makeDiagnostic("ident_u_y_lengths",
                                  {std::to_string(data.u.size()), std::to_string(data.y.size())}));
    if (data.size() < minimum)
        throw InvalidInput(
            field,
            makeDiagnostic(data.size() == 1 ? "ident_one_sample_needs" : "ident_samples_needs",
                           {std::to_string(data.size()), what, std::to_string(minimum)}));
}

} // namespace xyt
