// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Network calls off the GUI thread whose owner never waits for them (a
// connect may take its whole timeout and cannot be stopped).

#include <QFuture>
#include <QFutureWatcher>
#include <QObject>
#include <QtConcurrent/QtConcurrentRun>
#include <cstdint>
#include <stop_token>
#include <utility>

namespace vv::gui {

/// Hands `future`'s result to `done(result)` on the thread of `context` (the
/// GUI thread), always through its event queue, so never inside this call even
/// when `future` has already finished (a caller that sets "Searching…" after
/// starting a call would overwrite the answer). A QFutureWatcher owned by
/// `context` delivers it, as LatestRun's do: destroying `context` first drops
/// the result (QFuture::then(context, …) instead calls straight through on a
/// finished future, and reads its guard of `context` on the worker thread).
template <typename Result, typename Done>
void deliverLater(const QFuture<Result>& future, QObject* context, Done done) {
    auto* watcher = new QFutureWatcher<Result>(context);
    QObject::connect(watcher, &QFutureWatcher<Result>::finished, watcher,
                     [watcher, done = std::move(done)]() mutable {
                         watcher->deleteLater();
                         // Out of the connection first: `handler` may end the
                         // context, and with it this connection.
                         auto handler = std::move(done);
                         handler(watcher->result());
                     });
    watcher->setFuture(future);
}

/// `work()` runs on a QtConcurrent worker, `done(result)` later on the thread
/// of `context` (the GUI thread, through its event queue: never inside this
/// call) unless `context` was destroyed first; then the result is dropped.
/// `work` must capture what it reads by value (it may outlive its owner until
/// its own timeouts end it).
template <typename Work, typename Done>
void runInBackground(QObject* context, Work work, Done done) {
    deliverLater(QtConcurrent::run(std::move(work)), context, std::move(done));
}

/// A series of such calls of which only the newest one's answer counts
/// (a search, a series search, a Test): start() stops the call before it
/// and cancel() the newest, through the stop token `work(std::stop_token)`
/// gets (the pacs calls abort their association at once); a stopped call's
/// answer is dropped, so `done(result)` runs only for the newest call that
/// was neither stopped nor overtaken. Never waits for a worker; a member of
/// `context`.
template <typename Result>
class LatestCall {
  public:
    explicit LatestCall(QObject* context) : context_(context) {}
    ~LatestCall() { cancel(); }
    LatestCall(const LatestCall&) = delete;
    LatestCall& operator=(const LatestCall&) = delete;
    LatestCall(LatestCall&&) = delete;
    LatestCall& operator=(LatestCall&&) = delete;

    template <typename Work, typename Done>
    void start(Work work, Done done) {
        cancel();
        stop_ = std::stop_source();
        running_ = true;
        const std::uint64_t call = newest_;
        runInBackground(
            context_,
            [work = std::move(work), stop = stop_.get_token()]() mutable { return work(stop); },
            [this, call, done = std::move(done)](const Result& result) mutable {
                if (call != newest_) {
                    return;  // stopped or overtaken
                }
                running_ = false;
                done(result);
            });
    }
    /// Stops the newest call; its answer is never handed over.
    void cancel() noexcept {
        stop_.request_stop();
        ++newest_;
        running_ = false;
    }
    /// True from start() until its answer was handed over or it was stopped.
    [[nodiscard]] bool isRunning() const noexcept { return running_; }

  private:
    QObject* context_;
    std::stop_source stop_;
    std::uint64_t newest_ = 0;  ///< counts the calls stopped: an older one's answer is dropped
    bool running_ = false;
};

}  // namespace vv::gui
