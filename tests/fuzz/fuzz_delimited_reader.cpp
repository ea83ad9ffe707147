// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer harness: the CSV/TSV reader (core/identification/delimited_reader.h) on arbitrary
// text with the delimiter detected and, from the first byte, forced settings; then
// experimentData on what it accepts. Either a one-line InvalidInput, or a consistent table
// (fuzz_experiment_support.h) and a finite, uniformly sampled record.
#include "tests/fuzz/fuzz_experiment_support.h"

#include "core/identification/delimited_reader.h"

#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    xyt::DelimitedReadOptions options;
    if (size > 0) {
        options.delimiter = static_cast<xyt::Delimiter>(data[0] % 5);
        options.decimal = static_cast<xyt::DecimalSeparator>((data[0] / 5) % 3);
    }
    for (const xyt::DelimitedReadOptions& o : {xyt::DelimitedReadOptions{}, options}) {
        xyt::DelimitedTable r;
        try {
            r = xyt::readDelimited(text, "fuzz.csv", o);
        } catch (const xyt::InvalidInput& e) {
            xyt::fuzz::requireOneLine(e);
            continue;
        }
        XYT_FUZZ_REQUIRE(!(r.decimalComma && r.delimiter == xyt::Delimiter::Comma));
        xyt::fuzz::checkTable(r.table, true);
        xyt::fuzz::checkExperimentData(r.table);
    }
    return 0;
}
