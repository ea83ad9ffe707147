// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer harness: the MAT-file reader (core/identification/mat_reader.h, libmatio behind our
// own header check) on arbitrary bytes written to a temporary file: list the variables, read the
// usable ones. Either a one-line InvalidInput, or a consistent list and table
// (fuzz_experiment_support.h; MAT columns may differ in length). libmatio must neither crash
// nor leak (LeakSanitizer runs with libFuzzer's -detect_leaks default).
#include "tests/fuzz/fuzz_experiment_support.h"

#include "core/identification/mat_reader.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <unistd.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    char path[] = "/tmp/xyt_fuzz_mat_XXXXXX";
    const int fd = ::mkstemp(path);
    if (fd < 0)
        return 0;
    std::size_t written = 0;
    while (written < size) {
        const ssize_t n = ::write(fd, data + written, size - written);
        if (n <= 0)
            break;
        written += static_cast<std::size_t>(n);
    }
    ::close(fd);
    try {
        const xyt::MatFileInfo info = xyt::listMatVariables(path);
        XYT_FUZZ_REQUIRE(info.version == "v4" || info.version == "v5" || info.version == "v7.3");
        std::size_t usable = 0;
        for (const xyt::MatVariableInfo& v : info.variables) {
            if (v.usable) {
                ++usable;
                XYT_FUZZ_REQUIRE(v.rows >= 1 && v.columns >= 1 && (v.rows == 1 || v.columns == 1));
            } else {
                XYT_FUZZ_REQUIRE(!v.whyNot.empty());
            }
        }
        const xyt::ExperimentTable t = xyt::readMat(path);
        XYT_FUZZ_REQUIRE(t.names.size() <= usable);
        xyt::fuzz::checkTable(t, false);
        xyt::fuzz::checkExperimentData(t);
    } catch (const xyt::InvalidInput& e) {
        xyt::fuzz::requireOneLine(e);
    }
    ::unlink(path);
    return 0;
}
