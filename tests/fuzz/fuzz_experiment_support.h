// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Shared by the experiment-reader harnesses: the invariants of any ExperimentTable a reader
// accepted, and experimentData() on its first columns (it either refuses with a one-line
// InvalidInput or returns a finite, uniformly sampled record).

#include "tests/fuzz/fuzz_support.h"

#include "core/identification/experiment_data.h"
#include "core/identification/experiment_table.h"
#include "core/model/errors.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <limits>
#include <set>
#include <string>
#include <vector>

namespace xyt::fuzz {

inline void checkTable(const ExperimentTable& t, bool equalLengths) {
    const std::size_t n = t.names.size();
    XYT_FUZZ_REQUIRE(n <= kMaxExperimentColumns);
    XYT_FUZZ_REQUIRE(t.columns.size() == n && t.fieldNumbers.size() == n &&
                     t.firstProblem.size() == n);
    XYT_FUZZ_REQUIRE(std::set<std::string>(t.names.begin(), t.names.end()).size() == n);
    for (std::size_t r = 1; r < t.rowNumbers.size(); ++r)
        XYT_FUZZ_REQUIRE(t.rowNumbers[r] > t.rowNumbers[r - 1]);
    for (std::size_t c = 0; c < n; ++c) {
        const std::vector<double>& col = t.columns[c];
        XYT_FUZZ_REQUIRE(equalLengths ? col.size() == t.rowNumbers.size()
                                      : col.size() <= t.rowNumbers.size());
        // Every non-finite cell is covered by the column's problem, which is the first of them.
        std::size_t firstBad = col.size();
        for (std::size_t r = 0; r < col.size() && firstBad == col.size(); ++r)
            if (!std::isfinite(col[r]))
                firstBad = r;
        if (firstBad == col.size())
            XYT_FUZZ_REQUIRE(!t.firstProblem[c]);
        else
            XYT_FUZZ_REQUIRE(t.firstProblem[c] && t.firstProblem[c]->row == firstBad);
        if (t.firstProblem[c])
            XYT_FUZZ_REQUIRE(t.cellField(c, t.firstProblem[c]->row).find('\n') ==
                             std::string::npos);
    }
}

/// experimentData on columns (0, 1) with a given sample time, and (1, 2) timed by column 0.
inline void checkExperimentData(const ExperimentTable& t) {
    if (t.names.size() < 2)
        return;
    for (int variant = 0; variant < 2; ++variant) {
        ExperimentColumns cols;
        if (variant == 0 || t.names.size() < 3) {
            cols.input = t.names[0];
            cols.output = t.names[1];
            cols.sampleTimeSeconds = 0.01;
        } else {
            cols.time = t.names[0];
            cols.input = t.names[1];
            cols.output = t.names[2];
        }
        IoData d;
        try {
            d = experimentData(t, cols);
        } catch (const InvalidInput& e) {
            requireOneLine(e);
            continue;
        }
        XYT_FUZZ_REQUIRE(d.size() >= 2 && d.u.size() == d.y.size());
        XYT_FUZZ_REQUIRE(d.tsSeconds > 0.0);
        XYT_FUZZ_REQUIRE_FINITE(d.tsSeconds);
        XYT_FUZZ_REQUIRE_FINITE(d.startSeconds);
        XYT_FUZZ_REQUIRE_FINITE(d.u);
        XYT_FUZZ_REQUIRE_FINITE(d.y);
    }
}

/**
 * The reader's and the record's options drawn from the input's own bytes, read cyclically: the
 * text stays whole (a seed keeps its meaning) while its bytes also pick the options, so every
 * option of the readers is fuzzed with the text.
 */
class OptionBytes {
public:
    OptionBytes(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
    std::uint8_t next() { return size_ == 0 ? 0 : data_[at_++ % size_]; }
    /// A sample time: the edges of the accepted range, just beyond them, the extremes of
    /// double (subnormal, huge), invalid ones, or eight of the bytes taken as a double.
    double sampleTime() {
        constexpr double special[] = {0.01,
                                      kMinSampleTimeSeconds,
                                      kMaxSampleTimeSeconds,
                                      0.99 * kMinSampleTimeSeconds,
                                      1.01 * kMaxSampleTimeSeconds,
                                      std::numeric_limits<double>::denorm_min(),
                                      std::numeric_limits<double>::min(),
                                      1e300,
                                      std::numeric_limits<double>::max(),
                                      0.0,
                                      -0.01,
                                      std::numeric_limits<double>::quiet_NaN(),
                                      std::numeric_limits<double>::infinity()};
        const std::size_t kind = next() % (std::size(special) + 1);
        if (kind < std::size(special))
            return special[kind];
        std::uint8_t raw[8];
        for (std::uint8_t& b : raw)
            b = next();
        double v = 0.0;
        std::memcpy(&v, raw, sizeof v);
        return v;
    }

private:
    const std::uint8_t* data_;
    std::size_t size_;
    std::size_t at_ = 0;
};

/// The columns a reader is asked to keep: none (all), or up to three of @p t's names, or (one
/// time in eight) a name it does not have.
inline std::vector<std::string> chosenNames(const ExperimentTable& t, OptionBytes& o) {
    std::vector<std::string> chosen;
    const std::size_t count = o.next() % 4;
    for (std::size_t k = 0; k < count && !t.names.empty(); ++k)
        chosen.push_back(t.names[o.next() % t.names.size()]);
    if (o.next() % 8 == 0)
        chosen.push_back("no such column");
    return chosen;
}

inline bool sameBits(const std::vector<double>& a, const std::vector<double>& b) {
    return a.size() == b.size() &&
           (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

/// A table read keeping only @p chosen equals the table read whole (@p full), on those columns.
inline void checkChosenColumns(const ExperimentTable& full, const ExperimentTable& kept,
                               const std::vector<std::string>& chosen) {
    const std::set<std::string> wanted(chosen.begin(), chosen.end());
    std::size_t k = 0;
    for (std::size_t c = 0; c < full.names.size(); ++c) {
        if (!chosen.empty() && !wanted.count(full.names[c]))
            continue;
        XYT_FUZZ_REQUIRE(k < kept.names.size() && kept.names[k] == full.names[c]);
        XYT_FUZZ_REQUIRE(kept.fieldNumbers[k] == full.fieldNumbers[c]);
        XYT_FUZZ_REQUIRE(sameBits(kept.columns[k], full.columns[c]));
        XYT_FUZZ_REQUIRE(kept.firstProblem[k].has_value() == full.firstProblem[c].has_value());
        if (kept.firstProblem[k])
            XYT_FUZZ_REQUIRE(kept.firstProblem[k]->row == full.firstProblem[c]->row &&
                             kept.firstProblem[k]->text == full.firstProblem[c]->text &&
                             kept.firstProblem[k]->reason == full.firstProblem[c]->reason);
        ++k;
    }
    XYT_FUZZ_REQUIRE(k == kept.names.size());
    XYT_FUZZ_REQUIRE(kept.rowNumbers == full.rowNumbers);
    XYT_FUZZ_REQUIRE(kept.sampleTimeSeconds == full.sampleTimeSeconds);
}

/// Reads the text again through @p read (names to keep -> table), keeping chosenNames: equal to
/// @p full on those columns (then checkExperimentOptions on it), or refused in one line only for
/// a name the file does not have (everything else was read before).
template <class Read> void checkKeptColumns(const ExperimentTable& full, OptionBytes& o, Read read);

/**
 * experimentData with the columns, the time source, the sample time and the output unit drawn
 * from the bytes: it refuses in one line or returns a finite record whose Ts is an accepted
 * sample time (the given one or the file's when those were chosen); the overload that takes
 * the table gives the same outcome.
 */
inline void checkExperimentOptions(const ExperimentTable& t, OptionBytes& o) {
    if (t.names.empty())
        return;
    const std::size_t n = t.names.size();
    ExperimentColumns cols;
    cols.input = t.names[o.next() % n];
    cols.output = t.names[o.next() % n];
    switch (o.next() % 3) {
    case 0:
        cols.time = t.names[o.next() % n];
        break;
    case 1:
        cols.sampleTimeSeconds = o.sampleTime();
        break;
    default:
        cols.fileSampleTime = true;
        break;
    }
    switch (o.next() % 3) {
    case 0:
        cols.outputScale.unit = OutputUnit::Millimetres;
        break;
    case 1:
        cols.outputScale.unit = OutputUnit::Metres;
        break;
    default:
        cols.outputScale.unit = OutputUnit::EncoderCounts;
        cols.outputScale.mmPerCount = o.sampleTime(); // the same edges suit a count size
        break;
    }
    IoData d;
    std::string refused;
    try {
        d = experimentData(t, cols);
    } catch (const InvalidInput& e) {
        requireOneLine(e);
        refused = e.what();
    }
    ExperimentTable copy = t;
    try {
        const IoData taken = experimentData(std::move(copy), cols);
        XYT_FUZZ_REQUIRE(refused.empty());
        XYT_FUZZ_REQUIRE(sameBits(taken.u, d.u) && sameBits(taken.y, d.y) &&
                         taken.tsSeconds == d.tsSeconds);
    } catch (const InvalidInput& e) {
        XYT_FUZZ_REQUIRE(refused == e.what());
    }
    if (!refused.empty())
        return;
    XYT_FUZZ_REQUIRE(d.size() >= 2 && d.u.size() == d.y.size());
    XYT_FUZZ_REQUIRE(d.tsSeconds >= kMinSampleTimeSeconds && d.tsSeconds <= kMaxSampleTimeSeconds);
    if (cols.sampleTimeSeconds)
        XYT_FUZZ_REQUIRE(d.tsSeconds == *cols.sampleTimeSeconds);
    if (cols.fileSampleTime)
        XYT_FUZZ_REQUIRE(t.sampleTimeSeconds && d.tsSeconds == *t.sampleTimeSeconds);
    XYT_FUZZ_REQUIRE_FINITE(d.startSeconds);
    XYT_FUZZ_REQUIRE_FINITE(d.u);
    XYT_FUZZ_REQUIRE_FINITE(d.y);
}

template <class Read>
void checkKeptColumns(const ExperimentTable& full, OptionBytes& o, Read read) {
    const std::vector<std::string> chosen = chosenNames(full, o);
    try {
        const ExperimentTable kept = read(chosen);
        checkChosenColumns(full, kept, chosen);
        checkExperimentOptions(kept, o);
    } catch (const InvalidInput& e) {
        requireOneLine(e);
        XYT_FUZZ_REQUIRE(!chosen.empty() && chosen.back() == "no such column");
    }
}

} // namespace xyt::fuzz
