// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Network calls off the GUI thread whose owner never waits for them (a
// connect may take its whole timeout and cannot be stopped). A series of
// calls of which only the newest answers: LatestRun<Result,
// AtDestruction::Detach> (gui/LatestRun.h).

#include <QFuture>
#include <QFutureWatcher>
#include <QObject>
#include <QtConcurrent/QtConcurrentRun>
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

}  // namespace vv::gui
