// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QFuture>
#include <QFutureWatcher>
#include <QObject>
#include <QtConcurrent/QtConcurrentRun>
#include <cstdint>
#include <memory>
#include <stop_token>
#include <utility>

namespace vv::gui {

// The GUI's one background-task pattern: work(std::stop_token) on a
// QtConcurrent worker thread, cancelled through the token (the engine's
// Progress throws CancelledError at its next report), its result handed back
// on the GUI thread. WorkerRun is one run with signals (MeshLoadTask,
// SegmentationTask); LatestRun is a series of runs of which only the newest
// result counts (the viewer's simplified geometry, the Segmentation panel's
// default range).

/// One run of `work(std::stop_token)` on a QtConcurrent worker thread, for
/// the GUI's tasks: watcher().finished() arrives on the thread that owns the
/// WorkerRun once the result is ready; cancel() requests a stop through the
/// token (the engine's Progress then throws CancelledError at its next
/// report). The destructor requests a stop and waits for the worker, so the
/// work may use its owner until then (declare the WorkerRun after what the
/// work reads).
template <typename Result>
class WorkerRun {
  public:
    WorkerRun() = default;
    ~WorkerRun() {
        stop_.request_stop();
        if (started_) {
            future_.waitForFinished();
        }
    }
    WorkerRun(const WorkerRun&) = delete;
    WorkerRun& operator=(const WorkerRun&) = delete;
    WorkerRun(WorkerRun&&) = delete;
    WorkerRun& operator=(WorkerRun&&) = delete;

    /// Runs `work(stop token)` on a worker; does nothing (returns false)
    /// when this run was started before. Connect watcher() first.
    template <typename Work>
    bool start(Work work) {
        if (started_) {
            return false;
        }
        started_ = true;
        future_ = QtConcurrent::run(
            [work = std::move(work), stop = stop_.get_token()]() mutable { return work(stop); });
        watcher_.setFuture(future_);
        return true;
    }
    void cancel() noexcept { stop_.request_stop(); }
    [[nodiscard]] bool stopRequested() const noexcept { return stop_.stop_requested(); }
    [[nodiscard]] bool isRunning() const { return started_ && !future_.isFinished(); }
    /// Its finished() signal says that result() is ready.
    [[nodiscard]] QFutureWatcher<Result>& watcher() noexcept { return watcher_; }
    /// The work's result; blocks until it is there.
    [[nodiscard]] Result result() const { return future_.result(); }

  private:
    std::stop_source stop_;
    QFuture<Result> future_;
    QFutureWatcher<Result> watcher_;
    bool started_ = false;
};

/// A series of background runs of which only the newest result counts:
/// start() stops the run before it (its result is dropped unseen) and hands
/// the new run's result to `done` on the thread that owns `context` (the GUI
/// thread), unless cancel() or a newer start() came first. The destructor
/// stops the newest run and waits for it, so its work may read what the
/// owner keeps until then; older runs must capture what they read by value.
template <typename Result>
class LatestRun {
  public:
    /// Results arrive on `context`'s thread; `context` must outlive this.
    explicit LatestRun(QObject* context) : context_(context) {}
    ~LatestRun() {
        cancel();
        if (watcher_) {
            watcher_->waitForFinished();
        }
    }
    LatestRun(const LatestRun&) = delete;
    LatestRun& operator=(const LatestRun&) = delete;
    LatestRun(LatestRun&&) = delete;
    LatestRun& operator=(LatestRun&&) = delete;

    /// Runs `work(stop token) -> Result` on a worker, then `done(Result)` on
    /// the context's thread if this is still the newest run.
    template <typename Work, typename Done>
    void start(Work work, Done done) {
        cancel();
        stop_ = std::stop_source();
        watcher_ = std::make_unique<QFutureWatcher<Result>>();
        QFutureWatcher<Result>* watcher = watcher_.get();
        QObject::connect(watcher, &QFutureWatcher<Result>::finished, context_,
                         [watcher, done = std::move(done)]() mutable { done(watcher->result()); });
        watcher->setFuture(QtConcurrent::run(
            [work = std::move(work), stop = stop_.get_token()]() mutable { return work(stop); }));
    }
    /// Stops the newest run; its result is never handed over.
    void cancel() noexcept {
        stop_.request_stop();
        if (watcher_) {
            watcher_->disconnect();
        }
    }
    [[nodiscard]] bool isRunning() const { return watcher_ && watcher_->isRunning(); }
    /// Blocks until the newest run's work returned (tests, destruction).
    void waitForFinished() {
        if (watcher_) {
            watcher_->waitForFinished();
        }
    }

  private:
    QObject* context_;
    std::stop_source stop_;
    /// The newest run's; replacing it leaves an older run's future unwatched.
    std::unique_ptr<QFutureWatcher<Result>> watcher_;
};

}  // namespace vv::gui
