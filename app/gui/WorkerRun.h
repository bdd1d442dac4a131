// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QFuture>
#include <QFutureWatcher>
#include <QObject>
#include <QtConcurrent/QtConcurrentRun>
#include <stop_token>
#include <utility>

namespace vv::gui {

// The GUI's one background-task pattern: work(std::stop_token) on a
// QtConcurrent worker thread, cancelled through the token (the engine's
// Progress throws CancelledError at its next report), its result handed back
// on the GUI thread. WorkerRun is one run with signals (MeshLoadTask,
// SegmentationTask); a series of runs of which only the newest result counts
// is LatestRun (LatestRun.h).

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

}  // namespace vv::gui
