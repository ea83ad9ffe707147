// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer harness: the LabVIEW Measurement reader (core/identification/lvm_reader.h) on
// arbitrary text, segments 1 and 2; then experimentData on what it accepts (also with the file's
// Delta_X). Either a one-line InvalidInput, or a consistent table (fuzz_experiment_support.h)
// whose stated sample time is positive, and a finite, uniformly sampled record.
#include "tests/fuzz/fuzz_experiment_support.h"

#include "core/identification/lvm_reader.h"

#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    for (std::size_t segment : {1u, 2u}) {
        xyt::LvmTable r;
        try {
            r = xyt::readLvm(text, "fuzz.lvm", {segment});
        } catch (const xyt::InvalidInput& e) {
            xyt::fuzz::requireOneLine(e);
            continue;
        }
        XYT_FUZZ_REQUIRE(r.segmentCount >= segment);
        XYT_FUZZ_REQUIRE(!r.table.names.empty());
        if (r.table.sampleTimeSeconds)
            XYT_FUZZ_REQUIRE(*r.table.sampleTimeSeconds > 0.0 && std::isfinite(*r.table.sampleTimeSeconds));
        xyt::fuzz::checkTable(r.table, true);
        xyt::fuzz::checkExperimentData(r.table);
        if (r.table.names.size() >= 2 && r.table.sampleTimeSeconds) {
            xyt::ExperimentColumns cols;
            cols.input = r.table.names[0];
            cols.output = r.table.names[1];
            cols.fileSampleTime = true;
            try {
                const xyt::IoData d = xyt::experimentData(r.table, cols);
                XYT_FUZZ_REQUIRE(d.tsSeconds == *r.table.sampleTimeSeconds);
            } catch (const xyt::InvalidInput& e) {
                xyt::fuzz::requireOneLine(e);
            }
        }
    }
    return 0;
}
