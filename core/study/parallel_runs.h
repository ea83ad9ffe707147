// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstddef>
#include <functional>

namespace xyt {

/// How parallelRuns divides and reports its work.
struct ParallelRunOptions {
    int threads = 0;       ///< 0: std::thread::hardware_concurrency() (at least 1)
    std::size_t chunk = 1; ///< consecutive items a worker takes at a time
    /// Called on the CALLING thread about every 20 ms with the fraction of items done (scaled
    /// by progressScale); false cancels: the workers stop after the chunk each is computing.
    std::function<bool(double fraction)> progress;
    double progressScale = 1.0;
    std::function<void()> onWorkerStart; ///< first thing on each worker (may be empty)
};

/// What parallelRuns did.
struct ParallelRunOutcome {
    int threadsUsed = 0;
    bool cancelled = false;
};

/**
 * Runs body(first, count) over [0, total) in chunks on worker threads (never more workers than
 * chunks), while the calling thread reports progress. Each item is computed by the same code
 * into its own slot whatever thread takes it, which is what keeps the design sweep and the
 * robustness analysis identical bit for bit across thread counts. The first exception a body
 * throws cancels the rest and is rethrown here after every worker has stopped.
 */
ParallelRunOutcome
parallelRuns(std::size_t total, const ParallelRunOptions& options,
             const std::function<void(std::size_t first, std::size_t count)>& body);

} // namespace xyt
