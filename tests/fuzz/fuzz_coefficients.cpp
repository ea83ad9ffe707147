// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer harness: the coefficient parser (core/model/coefficient_parser.h) on arbitrary text, as
// pasted from a paper or MATLAB. Either the text is rejected with xyt::InvalidInput whose message
// is one printable line (the CLI prints it as its single stderr line), or the result holds
// 1..kMaxCoefficients finite values that survive a print/parse round trip exactly.
#include "tests/fuzz/fuzz_support.h"

#include "core/model/coefficient_parser.h"
#include "core/model/errors.h"

#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        const double v = xyt::parseNumber(text, "--wn");
        XYT_FUZZ_REQUIRE_FINITE(v);
    } catch (const xyt::InvalidInput& e) {
        xyt::fuzz::requireOneLine(e);
    }
    try {
        const std::vector<double> values = xyt::parseCoefficientList(text, "--num");
        XYT_FUZZ_REQUIRE(!values.empty() && values.size() <= xyt::kMaxCoefficients);
        XYT_FUZZ_REQUIRE_FINITE(values);
        std::string printed;
        for (const double v : values) {
            char buffer[32];
            std::snprintf(buffer, sizeof buffer, "%.17g ", v);
            printed += buffer;
        }
        XYT_FUZZ_REQUIRE(xyt::parseCoefficientList(printed, "--num") == values);
    } catch (const xyt::InvalidInput& e) {
        xyt::fuzz::requireOneLine(e);
    }
    return 0;
}
