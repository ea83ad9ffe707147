// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer harness: the CSV/TSV reader (core/identification/delimited_reader.h) on arbitrary
// text, with every option drawn from the input's own bytes (OptionBytes: the text stays whole):
// the delimiter and decimal separator (detected, and forced by byte 0), the columns kept, and
// then experimentData with the columns, time source, sample time (subnormal and huge ones
// among them) and output unit. Either a one-line InvalidInput, or a consistent table
// (fuzz_experiment_support.h) equal on the kept columns to the whole table, and a finite record
// whose Ts is an accepted sample time.
#include "tests/fuzz/fuzz_experiment_support.h"

#include "core/identification/delimited_reader.h"

#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    xyt::fuzz::OptionBytes bytes(data, size);
    xyt::DelimitedReadOptions options;
    const std::uint8_t first = bytes.next();
    options.delimiter = static_cast<xyt::Delimiter>(first % 5);
    options.decimal = static_cast<xyt::DecimalSeparator>((first / 5) % 3);
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
        xyt::fuzz::checkExperimentOptions(r.table, bytes);
        xyt::fuzz::checkKeptColumns(r.table, bytes, [&](const std::vector<std::string>& columns) {
            xyt::DelimitedReadOptions kept = o;
            kept.columns = columns;
            return xyt::readDelimited(text, "fuzz.csv", kept).table;
        });
    }
    return 0;
}
