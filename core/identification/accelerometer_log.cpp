// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/identification/accelerometer_log.h"

#include "core/identification/experiment_table.h"
#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/model/number_format.h"

#include <array>
#include <cmath>
#include <new>

namespace xyt {

namespace {

std::string accelLineField(const std::string& fileName, std::size_t line) {
    return fileName + ": line " + std::to_string(line);
}

std::string_view accelTrim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t'))
        s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t'))
        s.remove_suffix(1);
    return s;
}

bool accelBlank(std::string_view line) {
    return accelTrim(line).empty();
}

/// The comma-separated fields of a line, one at a time, as views (no allocation).
class AccelFields {
public:
    explicit AccelFields(std::string_view line) : line_(line) {}
    bool next(std::string_view& field) {
        if (done_)
            return false;
        const std::size_t comma = line_.find(',', pos_);
        if (comma == std::string_view::npos) {
            field = line_.substr(pos_);
            done_ = true;
        } else {
            field = line_.substr(pos_, comma - pos_);
            pos_ = comma + 1;
        }
        return true;
    }

private:
    std::string_view line_;
    std::size_t pos_ = 0;
    bool done_ = false;
};

constexpr std::array<const char*, 4> kAccelColumnNames = {"time", "accel_x", "accel_y", "accel_z"};

} // namespace

AccelerometerLog readAccelerometerLog(std::string_view text, const std::string& fileName) {
    if (text.size() > kMaxExperimentBytes)
        throw InvalidInput(fileName, makeDiagnostic("ident_larger_than_mib",
                                                    {std::to_string(kMaxExperimentBytes >> 20)}));
    AccelerometerLog log;
    log.fileName = fileName;
    TextLines lines(text);
    // The header: the first line that is neither blank nor a "##" statistics line.
    while (!lines.atEnd() &&
           (accelBlank(lines.line()) || lines.line().substr(0, 2) == std::string_view("##")))
        lines.next();
    const std::size_t headerLine = lines.atEnd() ? 1 : lines.number();
    if (lines.atEnd() || lines.line().empty() || lines.line().front() != '#')
        throw InvalidInput(accelLineField(fileName, headerLine),
                           makeDiagnostic("ident_accel_no_header"));
    std::array<std::size_t, 4> position{}; // 1-based field of time, accel_x, accel_y, accel_z
    std::size_t fieldCount = 0;
    {
        AccelFields header(lines.line().substr(1));
        std::string_view name;
        while (header.next(name)) {
            ++fieldCount;
            if (fieldCount > kMaxExperimentColumns)
                throw InvalidInput(accelLineField(fileName, headerLine),
                                   makeDiagnostic("ident_more_than_names",
                                                  {std::to_string(kMaxExperimentColumns)}));
            for (std::size_t c = 0; c < 4; ++c)
                if (accelTrim(name) == kAccelColumnNames[c] && position[c] == 0)
                    position[c] = fieldCount;
        }
    }
    for (std::size_t c = 0; c < 4; ++c)
        if (position[c] == 0)
            throw InvalidInput(accelLineField(fileName, headerLine),
                               makeDiagnostic("ident_accel_no_column", {kAccelColumnNames[c]}));
    lines.next();
    // Count the data lines first (bounded by the text's size, never by a number in it), so
    // each column is allocated once.
    std::size_t rows = 0;
    for (TextLines count = lines; !count.atEnd(); count.next())
        if (!accelBlank(count.line()) && count.line().front() != '#')
            ++rows;
    try {
        log.timeSeconds.reserve(rows);
        log.x.reserve(rows);
        log.y.reserve(rows);
        log.z.reserve(rows);
    } catch (const std::bad_alloc&) {
        throwOutOfMemory(fileName, rows * 32,
                         makeDiagnostic("ident_oom_rows_32_bytes", {std::to_string(rows)}));
    }
    std::size_t previousLine = 0;
    std::array<double, 4> value{};
    Diagnostic reason;
    for (; !lines.atEnd(); lines.next()) {
        const std::string_view line = lines.line();
        if (accelBlank(line) || line.front() == '#')
            continue;
        const std::size_t n = lines.number();
        AccelFields fields(line);
        std::string_view cell;
        std::size_t column = 0;
        while (fields.next(cell)) {
            ++column;
            if (column > fieldCount)
                throw InvalidInput(
                    accelLineField(fileName, n),
                    makeDiagnostic("ident_more_than_header_fields", {std::to_string(fieldCount)}));
            for (std::size_t c = 0; c < 4; ++c) {
                if (position[c] != column)
                    continue;
                const auto v = parseCellNumber(cell, false, reason);
                if (!v)
                    throw InvalidInput(
                        accelLineField(fileName, n) + ", column " + std::to_string(column) + " (" +
                            kAccelColumnNames[c] + ")",
                        makeDiagnostic("ident_cell_reason", {shownCell(cell), reason}));
                if (c > 0 && std::abs(*v) > kMaxAccelerometerMmPerS2)
                    throw InvalidInput(
                        accelLineField(fileName, n) + ", column " + std::to_string(column) + " (" +
                            kAccelColumnNames[c] + ")",
                        makeDiagnostic("ident_accel_beyond",
                                       {formatNumber(*v), formatNumber(kMaxAccelerometerMmPerS2)}));
                value[c] = *v;
            }
        }
        if (column < fieldCount)
            throw InvalidInput(
                accelLineField(fileName, n),
                makeDiagnostic("ident_accel_fields_header",
                               {std::to_string(column), std::to_string(fieldCount)}));
        if (!log.timeSeconds.empty() && !(value[0] > log.timeSeconds.back()))
            throw InvalidInput(
                accelLineField(fileName, n) + ", column " + std::to_string(position[0]) + " (time)",
                makeDiagnostic("ident_accel_time_not_after",
                               {formatNumber(value[0], 9), formatNumber(log.timeSeconds.back(), 9),
                                std::to_string(previousLine)}));
        previousLine = n;
        log.timeSeconds.push_back(value[0]);
        log.x.push_back(value[1]);
        log.y.push_back(value[2]);
        log.z.push_back(value[3]);
    }
    const std::size_t count = log.timeSeconds.size();
    if (count < kMinAccelerometerSamples)
        throw InvalidInput(fileName, makeDiagnostic("ident_fewer_samples_than",
                                                    {std::to_string(count),
                                                     std::to_string(kMinAccelerometerSamples)}));
    const double span = log.timeSeconds.back() - log.timeSeconds.front();
    log.meanIntervalSeconds = span / static_cast<double>(count - 1);
    log.klipperSamplingHz = static_cast<double>(count) / span;
    if (!(std::isfinite(log.meanIntervalSeconds) && log.meanIntervalSeconds > 0.0 &&
          std::isfinite(log.klipperSamplingHz)))
        throw InvalidInput(fileName,
                           makeDiagnostic("ident_accel_times_span", {formatNumber(span)}));
    requireSampleTime(log.meanIntervalSeconds, fileName);
    // The interval check, with the lines found again (a second pass over the text rather than
    // a table of line numbers: 8 bytes a row saved).
    for (std::size_t i = 1; i < count; ++i) {
        const double dt = log.timeSeconds[i] - log.timeSeconds[i - 1];
        if (std::abs(dt / log.meanIntervalSeconds - 1.0) <= kAccelerometerIntervalTolerance)
            continue;
        std::size_t row = 0, line = 0;
        TextLines again(text);
        for (; !again.atEnd(); again.next())
            if (again.number() > headerLine && !accelBlank(again.line()) &&
                again.line().front() != '#' && row++ == i) {
                line = again.number();
                break;
            }
        throw InvalidInput(accelLineField(fileName, line),
                           makeDiagnostic("ident_accel_interval",
                                          {formatNumber(dt * 1e3, 6),
                                           formatNumber(log.meanIntervalSeconds * 1e3, 6),
                                           formatNumber(kAccelerometerIntervalTolerance * 100.0)}));
    }
    return log;
}

AccelerometerLog readAccelerometerLogFile(const std::string& path) {
    const std::string text = readExperimentFile(path);
    return readAccelerometerLog(text, path);
}

std::size_t klipperSegmentLength(double samplingHz) {
    // int(fs * 0.5 - 1).bit_length() (Python truncates toward zero; bit_length(0) = 0).
    const double k = std::trunc(samplingHz * kKlipperWindowSeconds - 1.0);
    std::size_t bits = 0;
    for (double v = std::abs(k); v >= 1.0 && bits < 62; v = std::floor(v / 2.0))
        ++bits;
    return std::size_t{1} << bits;
}

AccelerometerSpectra accelerometerSpectra(const AccelerometerLog& log, double maxFrequencyHz) {
    if (!(std::isfinite(maxFrequencyHz) && maxFrequencyHz > 0.0))
        throw InvalidInput("--max-frequency", makeDiagnostic("ident_positive_frequency_hz"));
    AccelerometerSpectra out;
    out.samplingHz = log.klipperSamplingHz;
    out.samples = log.size();
    WelchOptions o;
    o.window = SpectralWindow::Kaiser;
    o.kaiserBeta = kKlipperKaiserBeta;
    o.segmentLength = std::max<std::size_t>(4, klipperSegmentLength(out.samplingHz));
    // calc_freq_response returns nothing when N <= M; fewer than two segments are refused too.
    if (log.size() <= o.segmentLength || log.size() < o.segmentLength + o.segmentLength / 2)
        throw InvalidInput(
            log.fileName,
            makeDiagnostic("ident_accel_klipper_too_few",
                           {std::to_string(log.size()), formatNumber(out.samplingHz),
                            std::to_string(o.segmentLength), formatNumber(kKlipperWindowSeconds),
                            std::to_string(o.segmentLength + o.segmentLength / 2)}));
    const double ts = 1.0 / out.samplingHz;
    const WelchSpectrum px = powerSpectralDensity(log.x, ts, o);
    const WelchSpectrum py = powerSpectralDensity(log.y, ts, o);
    const WelchSpectrum pz = powerSpectralDensity(log.z, ts, o);
    out.segments = px.segments;
    for (std::size_t k = 0; k < px.frequencyHz.size() && px.frequencyHz[k] <= maxFrequencyHz; ++k) {
        out.frequencyHz.push_back(px.frequencyHz[k]);
        out.psdX.push_back(px.psd[k]);
        out.psdY.push_back(py.psd[k]);
        out.psdZ.push_back(pz.psd[k]);
        out.psdSum.push_back(px.psd[k] + py.psd[k] + pz.psd[k]);
    }
    return out;
}

} // namespace xyt
