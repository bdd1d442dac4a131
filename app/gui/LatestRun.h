// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The GUI's one "newest answer wins" helper: a series of background runs of
// which only the newest result counts (the viewer's simplified geometry, a
// resliced slice, the Segmentation panel's default range, the local study
// store's listing, a PACS search, a network Test). The policy says what
// destruction does with the newest run: wait for it, or leave it behind.

#include <QFuture>
#include <QFutureWatcher>
#include <QObject>
#include <QtConcurrent/QtConcurrentRun>
#include <stop_token>
#include <utility>

namespace vv::gui {

/// What LatestRun's destructor does with the newest run, after requesting
/// its stop.
enum class AtDestruction {
    /// Waits until its work returned: the newest run's work may read what
    /// the owner keeps until then (declare the LatestRun after it). For work
    /// that a stop ends quickly (the engine's Progress throws CancelledError
    /// at its next report).
    Wait,
    /// Returns at once: for work a stop may not end in time (a network
    /// connect can take its whole timeout); the work must capture what it
    /// reads by value, as it may outlive its owner until its own timeouts
    /// end it.
    Detach,
};

/// A series of runs of `work(std::stop_token) -> Result` on QtConcurrent
/// workers of which only the newest result counts: start() requests the stop
/// of the run before it, whose result is then dropped unseen, and hands the
/// new run's result to `done` on the thread that owns `context` (the GUI
/// thread), unless cancel() or a newer start() came first. The result always
/// arrives through that thread's event queue, never inside start(), even when
/// the work has already finished (a caller that shows "Searching…" after
/// start() would else overwrite the answer). Runs other than the newest are
/// never waited for: their work must capture by value what it reads.
/// `policy`: what destruction does with the newest run. Use on the context's
/// thread only.
template <typename Result, AtDestruction policy>
class LatestRun {
  public:
    /// Results arrive on `context`'s thread; `context` must outlive this (a
    /// LatestRun is a member of its context).
    explicit LatestRun(QObject* context) : context_(context) {}
    ~LatestRun() {
        cancel();
        if constexpr (policy == AtDestruction::Wait) {
            waitForFinished();
        }
    }
    LatestRun(const LatestRun&) = delete;
    LatestRun& operator=(const LatestRun&) = delete;
    LatestRun(LatestRun&&) = delete;
    LatestRun& operator=(LatestRun&&) = delete;

    /// Runs `work(stop token) -> Result` on a worker, then `done(Result)` on
    /// the context's thread if this is still the newest run and was not
    /// cancelled. `done` may start the next run, or end the context. Throws
    /// what starting a QtConcurrent task throws (std::bad_alloc).
    template <typename Work, typename Done>
    void start(Work work, Done done) {
        cancel();
        stop_ = std::stop_source();
        running_ = true;
        // A child of the context, so that no watcher outlives it; deleted
        // once its run is handed over or given up (cancel()).
        auto* watcher = new QFutureWatcher<Result>(context_);
        watcher_ = watcher;
        QObject::connect(watcher, &QFutureWatcher<Result>::finished, context_,
                         [this, watcher, done = std::move(done)]() mutable {
                             // Only the newest run's watcher is connected.
                             watcher_ = nullptr;
                             running_ = false;
                             watcher->deleteLater();
                             done(watcher->result());
                         });
        future_ = QtConcurrent::run(
            [work = std::move(work), stop = stop_.get_token()]() mutable { return work(stop); });
        watcher->setFuture(future_);
    }
    /// Requests the newest run's stop; its result is never handed over.
    void cancel() noexcept {
        stop_.request_stop();
        running_ = false;
        if (watcher_ != nullptr) {
            watcher_->disconnect();
            watcher_->deleteLater();
            watcher_ = nullptr;
        }
    }
    /// True from start() until its result was handed over or it was
    /// cancelled or overtaken (so false inside its own `done`).
    [[nodiscard]] bool isRunning() const noexcept { return running_; }
    /// Blocks until the newest run's work returned, a cancelled one's too
    /// (tests, an owner's destructor); a result not cancelled is still handed
    /// over later, through the event queue.
    void waitForFinished() { future_.waitForFinished(); }

  private:
    QObject* context_;
    std::stop_source stop_;
    /// The newest run's work (finished and empty before the first start()).
    QFuture<Result> future_;
    /// The newest run's watcher until its result is handed over or it is
    /// cancelled; older runs' work goes on unwatched.
    QFutureWatcher<Result>* watcher_ = nullptr;
    bool running_ = false;
};

}  // namespace vv::gui
