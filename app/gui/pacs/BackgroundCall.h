// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// One network call off the GUI thread whose owner never waits for it:
// `work()` runs on a QtConcurrent worker, `done(result)` on the thread of
// `context` (the GUI thread) unless `context` was destroyed first; then the
// result is dropped. `work` must capture what it reads by value (it may
// outlive its owner until its own timeouts end it).

#include <QFuture>
#include <QObject>
#include <QtConcurrent/QtConcurrentRun>
#include <utility>

namespace vv::gui {

template <typename Work, typename Done>
void runInBackground(QObject* context, Work work, Done done) {
    (void)QtConcurrent::run(std::move(work)).then(context, std::move(done));
}

}  // namespace vv::gui
