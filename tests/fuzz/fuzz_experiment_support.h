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
#include <set>

namespace xyt::fuzz {

inline void checkTable(const ExperimentTable& t, bool equalLengths) {
    const std::size_t n = t.names.size();
    XYT_FUZZ_REQUIRE(n <= kMaxExperimentColumns);
    XYT_FUZZ_REQUIRE(t.columns.size() == n && t.fieldNumbers.size() == n && t.firstProblem.size() == n);
    XYT_FUZZ_REQUIRE(std::set<std::string>(t.names.begin(), t.names.end()).size() == n);
    for (std::size_t r = 1; r < t.rowNumbers.size(); ++r)
        XYT_FUZZ_REQUIRE(t.rowNumbers[r] > t.rowNumbers[r - 1]);
    for (std::size_t c = 0; c < n; ++c) {
        const std::vector<double>& col = t.columns[c];
        XYT_FUZZ_REQUIRE(equalLengths ? col.size() == t.rowNumbers.size() : col.size() <= t.rowNumbers.size());
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
            XYT_FUZZ_REQUIRE(t.cellField(c, t.firstProblem[c]->row).find('\n') == std::string::npos);
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

} // namespace xyt::fuzz
