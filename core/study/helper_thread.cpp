// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/study/helper_thread.h"

#include <condition_variable>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>

namespace xyt {

namespace {

/// The helper: sleeps until a task is posted, runs it, reports it done. Joined at exit.
class HelperThread {
public:
    HelperThread() : thread_([this] { loop(); }) {}
    ~HelperThread() {
        {
            const std::lock_guard lock(mutex_);
            stop_ = true;
        }
        wake_.notify_all();
        thread_.join();
    }
    HelperThread(const HelperThread&) = delete;
    HelperThread& operator=(const HelperThread&) = delete;

    /// One caller at a time; false when another caller holds the helper.
    bool tryAcquire() { return user_.try_lock(); }
    void release() { user_.unlock(); }

    void post(const std::function<void()>* task) {
        {
            const std::lock_guard lock(mutex_);
            task_ = task;
            done_ = false;
            failure_ = nullptr;
        }
        wake_.notify_all();
    }
    /// Waits for the posted task; returns its exception (or null).
    std::exception_ptr wait() {
        std::unique_lock lock(mutex_);
        finished_.wait(lock, [this] { return done_; });
        return failure_;
    }

private:
    void loop() {
        std::unique_lock lock(mutex_);
        for (;;) {
            wake_.wait(lock, [this] { return stop_ || task_; });
            if (stop_)
                return;
            const std::function<void()>* task = task_;
            task_ = nullptr;
            lock.unlock();
            std::exception_ptr failure;
            try {
                (*task)();
            } catch (...) {
                failure = std::current_exception();
            }
            lock.lock();
            failure_ = failure;
            done_ = true;
            finished_.notify_all();
        }
    }

    std::mutex user_;
    std::mutex mutex_;
    std::condition_variable wake_, finished_;
    const std::function<void()>* task_ = nullptr;
    bool done_ = false;
    bool stop_ = false;
    std::exception_ptr failure_;
    std::thread thread_; // last: started once the state above exists
};

/// The helper, started on first use; nullptr when no thread can be started.
HelperThread* helper() {
    static HelperThread* const instance = []() -> HelperThread* {
        try {
            static HelperThread h;
            return &h;
        } catch (const std::system_error&) {
            return nullptr;
        }
    }();
    return instance;
}

} // namespace

void runAlongside(const std::function<void()>& there, const std::function<void()>& here) {
    HelperThread* h = helper();
    if (!h || !h->tryAcquire()) {
        here();
        there();
        return;
    }
    h->post(&there);
    std::exception_ptr mine;
    try {
        here();
    } catch (...) {
        mine = std::current_exception();
    }
    const std::exception_ptr theirs = h->wait();
    h->release();
    if (mine)
        std::rethrow_exception(mine);
    if (theirs)
        std::rethrow_exception(theirs);
}

} // namespace xyt
