// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QFutureWatcher>
#include <QObject>
#include <QPromise>
#include <QString>
#include <QThreadPool>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <functional>
#include <memory>
#include <optional>
#include <utility>

namespace xyt::ui {

/// What a job's work calls with its progress in [0, 1]; it returns false once the job is
/// cancelled or replaced (the core's long computations take exactly this callback).
using JobProgress = std::function<bool(double)>;

/**
 * The one runner of a view's long computation (the design-space study, the robustness analysis,
 * the identification fits): it owns the whole life cycle so that no view writes its own.
 *
 * - start(stamp, work) runs `work(progress)` on the runner's own thread (QtConcurrent over a
 *   one-thread pool: a view's jobs never wait for another view's). A job still running is
 *   cancelled first and forgotten: its result is never delivered.
 * - Progress reaches `onProgress` on the GUI thread (through QFutureWatcher, which also thins
 *   a burst of reports to what the event loop can show).
 * - cancel() makes `progress` return false; the work stops after the item it is computing and
 *   returns what it has, which is delivered like any result (the core marks it cancelled).
 * - The result, or the message of an exception the work threw, reaches `onDone` / `onFailed`
 *   on the GUI thread with the stamp given to start(): what the result was computed for.
 * - Destroying the runner cancels its job and waits for it (a short wait: one item). The work
 *   must capture its inputs by value, never the view.
 *
 * @tparam Result what the work returns (moved to the GUI thread once).
 * @tparam Stamp  what a result was computed for (the presenter's ResultStamp).
 */
template <class Result, class Stamp> class JobRunner {
public:
    using Work = std::function<Result(const JobProgress&)>;
    struct Handlers {
        std::function<void(double)> onProgress;
        std::function<void(Result&&, const Stamp&)> onDone;
        std::function<void(const QString&, const Stamp&)> onFailed;
        /// The message onFailed gets for an exception the work threw (on the worker thread):
        /// by default its what(); the views give the workbench's translated text.
        std::function<QString(const std::exception&)> describeFailure;
    };

    /// @p context: the view; the handlers run on its thread and never after it is destroyed.
    JobRunner(QObject* context, Handlers handlers)
        : context_(context), handlers_(std::move(handlers)) {
        pool_.setMaxThreadCount(1);
    }
    ~JobRunner() {
        cancel();
        pool_.waitForDone();
        watcher_.reset(); // not inside one of its signals here: deleted at once
    }
    JobRunner(const JobRunner&) = delete;
    JobRunner& operator=(const JobRunner&) = delete;

    void start(const Stamp& stamp, Work work) {
        abandon();
        auto cancelled = std::make_shared<std::atomic<bool>>(false);
        cancelled_ = cancelled;
        stamp_ = stamp;
        // A child of the view: one released to deleteLater is freed with the view at the latest.
        watcher_ = std::make_unique<QFutureWatcher<Outcome>>(context_);
        QFutureWatcher<Outcome>* watcher = watcher_.get();
        QObject::connect(watcher, &QFutureWatcherBase::progressValueChanged, context_,
                         [this](int value) {
                             if (handlers_.onProgress)
                                 handlers_.onProgress(value / double(kProgressSteps));
                         });
        QObject::connect(watcher, &QFutureWatcherBase::finished, context_,
                         [this, watcher] { deliver(watcher); });
        watcher->setFuture(QtConcurrent::run(
            &pool_, [work = std::move(work), cancelled,
                     describe = handlers_.describeFailure](QPromise<Outcome>& promise) {
                promise.setProgressRange(0, kProgressSteps);
                const JobProgress progress = [&promise, cancelled](double fraction) {
                    if (std::isfinite(fraction))
                        promise.setProgressValue(static_cast<int>(
                            std::lround(kProgressSteps * std::clamp(fraction, 0.0, 1.0))));
                    return !cancelled->load();
                };
                Outcome outcome;
                try {
                    outcome.value.emplace(work(progress));
                } catch (const std::exception& e) {
                    outcome.error = describe ? describe(e) : QString::fromStdString(e.what());
                } catch (...) {
                    outcome.error = QStringLiteral("an unknown error");
                }
                promise.addResult(std::move(outcome));
            }));
    }

    /// Asks the running job to stop after its current item; its partial result still arrives.
    void cancel() {
        if (cancelled_)
            cancelled_->store(true);
    }
    /// Cancels the running job and forgets it: its result will not be delivered.
    void discard() { abandon(); }
    bool isRunning() const { return watcher_ != nullptr; }
    bool isCancelling() const { return cancelled_ && cancelled_->load(); }
    /// What the running job computes for (meaningful while isRunning()).
    const Stamp& runningStamp() const { return stamp_; }

private:
    static constexpr int kProgressSteps = 1000;
    struct Outcome {
        std::optional<Result> value;
        QString error;
    };

    /// Cancels the running job and forgets it: its result is dropped when it comes.
    void abandon() {
        cancel();
        if (watcher_) {
            watcher_->disconnect();
            watcher_.release()->deleteLater(); // a handler of its own signal may be running
        }
        cancelled_.reset();
    }

    void deliver(QFutureWatcher<Outcome>* watcher) {
        if (watcher != watcher_.get())
            return;
        Outcome outcome = watcher->future().takeResult();
        const Stamp stamp = stamp_;
        watcher_.release()->deleteLater(); // inside its finished(): deleted once it returns
        cancelled_.reset();                // not running any more when the handlers look
        if (outcome.value)
            handlers_.onDone(std::move(*outcome.value), stamp);
        else
            handlers_.onFailed(outcome.error, stamp);
    }

    QObject* context_;
    Handlers handlers_;
    QThreadPool pool_;
    std::unique_ptr<QFutureWatcher<Outcome>> watcher_;
    std::shared_ptr<std::atomic<bool>> cancelled_;
    Stamp stamp_{};
};

} // namespace xyt::ui
