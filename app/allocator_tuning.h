// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdlib> // defines __GLIBC__ on glibc

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace xyt::app {

/**
 * Keeps freed memory in the process instead of handing it back to the kernel at once. Every
 * slider step of the workbench simulates both axes again (the continuous run and the
 * digital implementation: some 3 MB of signals per axis at the default 52 001 samples)
 * and frees the previous ones. With glibc's defaults those blocks are unmapped or trimmed on
 * free and page-faulted in again on the next step, which measured 60 % of a digital run's time.
 * The GUI and its benchmark call this first; the command-line tool does not (one run, then exit).
 * A no-op on other C libraries.
 */
inline void keepFreedMemory() {
#if defined(__GLIBC__)
    constexpr int kBytes = 256 * 1024 * 1024;
    mallopt(M_MMAP_THRESHOLD,
            32 * 1024 * 1024);         // glibc's largest: blocks below it come from the heap
    mallopt(M_TRIM_THRESHOLD, kBytes); // free heap kept up to this before trimming
#endif
}

} // namespace xyt::app
