// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/study/parallel_runs.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace xyt {

ParallelRunOutcome
parallelRuns(std::size_t total, const ParallelRunOptions& options,
             const std::function<void(std::size_t first, std::size_t count)>& body) {
    if (options.threads < 0 || options.threads > 1024)
        throw InvalidInput("threads", makeDiagnostic("study_threads_range"));
    if (options.chunk < 1)
        throw InvalidInput("chunk", makeDiagnostic("at_least", {"1"}));
    const std::size_t chunk = options.chunk;
    const std::size_t chunks = (total + chunk - 1) / chunk;
    const int hardware = static_cast<int>(std::thread::hardware_concurrency());
    const int wanted = options.threads > 0 ? options.threads : std::max(1, hardware);
    ParallelRunOutcome outcome;
    outcome.threadsUsed =
        static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(wanted), chunks));

    std::atomic<std::size_t> next{0};
    std::atomic<std::size_t> done{0};
    std::atomic<bool> cancel{false};
    std::mutex mutex;
    std::condition_variable finishedSignal;
    int finishedWorkers = 0;
    std::exception_ptr failure;
    const auto& progress = options.progress;
    if (progress && !progress(0.0))
        cancel = true;

    auto worker = [&] {
        try {
            if (options.onWorkerStart)
                options.onWorkerStart();
            while (!cancel.load(std::memory_order_relaxed)) {
                const std::size_t first = next.fetch_add(chunk);
                if (first >= total)
                    break;
                const std::size_t count = std::min(chunk, total - first);
                body(first, count);
                done.fetch_add(count, std::memory_order_release);
            }
        } catch (...) {
            const std::lock_guard lock(mutex);
            if (!failure)
                failure = std::current_exception();
            cancel = true;
        }
        {
            const std::lock_guard lock(mutex);
            ++finishedWorkers;
        }
        finishedSignal.notify_all();
    };
    std::vector<std::thread> workers;
    workers.reserve(static_cast<std::size_t>(outcome.threadsUsed));
    for (int i = 0; i < outcome.threadsUsed; ++i)
        workers.emplace_back(worker);

    // The calling thread only reports progress, so the callback never runs on a worker.
    const double scale = total > 0 ? options.progressScale / static_cast<double>(total) : 0.0;
    {
        std::unique_lock lock(mutex);
        while (!finishedSignal.wait_for(lock, std::chrono::milliseconds(20),
                                        [&] { return finishedWorkers == outcome.threadsUsed; })) {
            if (!progress || cancel.load())
                continue;
            lock.unlock();
            const bool goOn =
                progress(static_cast<double>(done.load(std::memory_order_acquire)) * scale);
            lock.lock();
            if (!goOn)
                cancel = true;
        }
    }
    for (auto& t : workers)
        t.join();
    if (failure)
        std::rethrow_exception(failure);
    outcome.cancelled = cancel.load() || done.load() < total;
    return outcome;
}

} // namespace xyt
