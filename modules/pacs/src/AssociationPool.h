// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The listener's workers: a fixed number of threads, each serving one
// connection (one association) at a time. A connection is offered; with no
// worker free it is handed back at once (the caller refuses it), never
// queued behind a slow peer. Stopping trips every served connection's abort
// switch (its socket is shut down, DCMTK's wait ends) and joins the threads.

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "AbortableLayer.h"
#include "ConnectionGate.h"

namespace vv::pacs::detail {

class AssociationPool {
  public:
    /// Serves one connection on a worker's thread; `abortSwitch` trips when the pool stops.
    using Serve = std::function<void(ReadyConnection&&, const std::shared_ptr<AbortSwitch>&)>;

    /// Starts `workers` threads (at least 1).
    AssociationPool(int workers, Serve serve);
    /// Aborts what is being served, drops what waits, joins the threads.
    ~AssociationPool();
    AssociationPool(const AssociationPool&) = delete;
    AssociationPool& operator=(const AssociationPool&) = delete;
    AssociationPool(AssociationPool&&) = delete;
    AssociationPool& operator=(AssociationPool&&) = delete;

    /// Gives `connection` to a free worker; hands it back when none is free
    /// (or the pool stops).
    [[nodiscard]] std::optional<ReadyConnection> offer(ReadyConnection&& connection);

    /// Connections given to workers and not yet done.
    [[nodiscard]] std::size_t active() const;

  private:
    void work(std::size_t index);

    Serve serve_;
    mutable std::mutex mutex_;
    std::condition_variable wake_;
    std::deque<ReadyConnection> queue_;
    std::vector<std::shared_ptr<AbortSwitch>> serving_;  ///< per worker; null when idle
    std::size_t free_ = 0;
    bool stopping_ = false;
    std::vector<std::thread> threads_;
};

}  // namespace vv::pacs::detail
