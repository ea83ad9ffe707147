// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer harness: the LabVIEW Measurement reader (core/identification/lvm_reader.h) on
// arbitrary text, with every option drawn from the input's own bytes (OptionBytes: the text
// stays whole): segments 1, 2 and one from the bytes, the columns kept, then experimentData with
// the columns, time source (the file's Delta_X among them), sample time (subnormal and huge
// ones among them) and output unit. Either a one-line InvalidInput, or a consistent table
// (fuzz_experiment_support.h) whose stated sample time is an accepted one, equal on the kept
// columns to the whole table, and a finite record whose Ts is an accepted sample time.
#include "tests/fuzz/fuzz_experiment_support.h"

#include "core/identification/lvm_reader.h"

#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    xyt::fuzz::OptionBytes bytes(data, size);
    const std::size_t drawn = bytes.next() % 4; // 0: refused (segments count from 1)
    for (std::size_t segment : {std::size_t(1), std::size_t(2), drawn}) {
        xyt::LvmReadOptions options;
        options.segment = segment;
        xyt::LvmTable r;
        try {
            r = xyt::readLvm(text, "fuzz.lvm", options);
        } catch (const xyt::InvalidInput& e) {
            xyt::fuzz::requireOneLine(e);
            continue;
        }
        XYT_FUZZ_REQUIRE(segment >= 1 && r.segmentCount >= segment);
        XYT_FUZZ_REQUIRE(!r.table.names.empty());
        if (r.table.sampleTimeSeconds)
            XYT_FUZZ_REQUIRE(*r.table.sampleTimeSeconds >= xyt::kMinSampleTimeSeconds &&
                             *r.table.sampleTimeSeconds <= xyt::kMaxSampleTimeSeconds);
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
        xyt::fuzz::checkExperimentOptions(r.table, bytes);
        xyt::fuzz::checkKeptColumns(r.table, bytes, [&](const std::vector<std::string>& columns) {
            xyt::LvmReadOptions kept = options;
            kept.columns = columns;
            const xyt::LvmTable k = xyt::readLvm(text, "fuzz.lvm", kept);
            XYT_FUZZ_REQUIRE(k.segmentCount == r.segmentCount);
            return k.table;
        });
    }
    return 0;
}
