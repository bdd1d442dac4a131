// SPDX-License-Identifier: GPL-3.0-or-later
#include "AssociationPool.h"

#include <algorithm>
#include <utility>

namespace vv::pacs::detail {

AssociationPool::AssociationPool(int workers, Serve serve) : serve_(std::move(serve)) {
    const auto n = static_cast<std::size_t>(std::max(1, workers));
    serving_.resize(n);
    free_ = n;
    threads_.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
        threads_.emplace_back([this, i] { work(i); });
    }
}

AssociationPool::~AssociationPool() {
    {
        const std::lock_guard lock(mutex_);
        stopping_ = true;
        queue_.clear();
        for (const auto& abortSwitch : serving_) {
            if (abortSwitch) {
                abortSwitch->abort();
            }
        }
    }
    wake_.notify_all();
    for (std::thread& thread : threads_) {
        thread.join();
    }
}

std::optional<ReadyConnection> AssociationPool::offer(ReadyConnection&& connection) {
    {
        const std::lock_guard lock(mutex_);
        if (stopping_ || free_ == 0) {
            return std::move(connection);
        }
        --free_;
        queue_.push_back(std::move(connection));
    }
    wake_.notify_one();
    return std::nullopt;
}

std::size_t AssociationPool::active() const {
    const std::lock_guard lock(mutex_);
    return serving_.size() - free_;
}

void AssociationPool::work(std::size_t index) {
    std::unique_lock lock(mutex_);
    while (true) {
        wake_.wait(lock, [this] { return stopping_ || !queue_.empty(); });
        if (stopping_) {
            return;
        }
        ReadyConnection connection = std::move(queue_.front());
        queue_.pop_front();
        auto abortSwitch = std::make_shared<AbortSwitch>();
        serving_[index] = abortSwitch;
        lock.unlock();
        serve_(std::move(connection), abortSwitch);
        lock.lock();
        serving_[index].reset();
        ++free_;
    }
}

}  // namespace vv::pacs::detail
