// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer harness: the MAT-file reader (core/identification/mat_reader.h, libmatio behind our
// own header check) on arbitrary bytes written to a temporary file: list the variables, read the
// usable ones. Either a one-line InvalidInput, or a consistent list and table
// (fuzz_experiment_support.h; MAT columns may differ in length). libmatio must neither crash
// nor leak (LeakSanitizer runs with libFuzzer's -detect_leaks default). One exception, found by
// this harness: libhdf5 1.10.8 (Debian 12), which libmatio uses for v7.3 files, leaks about
// 1.7 KB of its own allocations when it gives up on a corrupt HDF5 file
// (corpus/fuzz_mat_reader/leak-hdf5-corrupt-v73); that is outside our code and libmatio's, so
// leaks whose allocation is in libhdf5 are suppressed below, and nothing else is. Likewise
// libhdf5's metadata cache asks malloc for absurd sizes (4.7e18 bytes) on some corrupt files
// (corpus/fuzz_mat_reader/crash-hdf5-metadata-cache-huge-malloc): a real malloc returns NULL and
// libhdf5 reports an error, so ASan is told to return NULL too (allocator_may_return_null)
// instead of aborting. Requests libmatio makes from sizes a file claims are bounded by our
// own checks (mat_reader.cpp) and are not covered by either exception.
// A third defect of libhdf5 1.10.8 cannot be worked around from outside: on some corrupt v7.3
// files its attribute decoder (H5O__attr_open_by_name, reached from libmatio's H5Literate when
// listing the variables) reads a few bytes past one of its own heap buffers. Without ASan that
// read is silent and the file is refused; under ASan it aborts the run. So when this harness is
// built with AddressSanitizer (the libFuzzer build), inputs with a v7.3 header, which go to
// libhdf5, are skipped; the replay build (no ASan, ctest replay_fuzz_mat_reader) still reads the
// committed v7.3 seeds and regressions (CTest checks that it reached v73_unwritten_dataset.mat,
// a variable claiming 3.2 GB beside two small ones), and tst_mat_reader reads v7.3 files under
// ASan.
#include "tests/fuzz/fuzz_experiment_support.h"

#include "core/identification/mat_reader.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <unistd.h>
#include <vector>

extern "C" const char* __asan_default_options() {
    return "allocator_may_return_null=1";
}
extern "C" const char* __lsan_default_suppressions() {
    return "leak:libhdf5_serial.so\n";
}

namespace {

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define XYT_FUZZ_UNDER_ASAN 1
#endif
#endif

#ifdef XYT_FUZZ_UNDER_ASAN
/// A MAT v7.3 header (version 0x0200 in either byte order): the file goes to libhdf5.
bool isV73Header(const std::uint8_t* h, std::size_t size) {
    if (size < 128)
        return false;
    if (h[126] == 'I' && h[127] == 'M')
        return h[124] == 0x00 && h[125] == 0x02;
    if (h[126] == 'M' && h[127] == 'I')
        return h[124] == 0x02 && h[125] == 0x00;
    return false;
}
#endif

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
#ifdef XYT_FUZZ_UNDER_ASAN
    if (isV73Header(data, size))
        return 0;
#endif
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
                XYT_FUZZ_REQUIRE(!v.whyNot.text.empty());
            }
        }
        // Every usable vector, as the identification window reads a file: within the bounds,
        // those beyond them left out with a warning each (at most ten, then a count).
        const xyt::ExperimentTable t = xyt::readMat(path);
        XYT_FUZZ_REQUIRE(t.names.size() <= usable && t.warnings.size() <= 11);
        std::uint64_t total = 0;
        for (const std::vector<double>& column : t.columns) {
            XYT_FUZZ_REQUIRE(column.size() <= xyt::kMaxMatVariableElements);
            total += column.size();
        }
        XYT_FUZZ_REQUIRE(total <= xyt::kMaxMatTableElements);
        xyt::fuzz::checkTable(t, false);
        xyt::fuzz::checkExperimentData(t);
        // The last two usable variables by name, as the CLI asks for its columns: exactly those
        // are read, or the one beyond a bound is refused (InvalidInput, below).
        std::vector<std::string> names;
        for (auto v = info.variables.rbegin(); v != info.variables.rend() && names.size() < 2; ++v)
            if (v->usable && (names.empty() || names[0] != v->name))
                names.push_back(v->name);
        if (!names.empty()) {
            const xyt::ExperimentTable named = xyt::readMat(path, names);
            XYT_FUZZ_REQUIRE(named.names == names);
            xyt::fuzz::checkTable(named, false);
        }
    } catch (const xyt::InvalidInput& e) {
        xyt::fuzz::requireOneLine(e);
    }
    ::unlink(path);
    return 0;
}
