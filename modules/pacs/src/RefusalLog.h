// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Log lines for refused and dropped connections that a flood cannot turn into
// a flood of lines: at most one per address and reason a minute, the next one
// saying how many were left out meanwhile. Never patient data: only the peer's
// address and the reason.

#include <chrono>
#include <cstddef>
#include <map>
#include <mutex>
#include <string>
#include <utility>

namespace vv::pacs::detail {

class RefusalLog {
  public:
    /// `interval`: the shortest time between two lines of one address and reason.
    explicit RefusalLog(std::chrono::steady_clock::duration interval = std::chrono::minutes(1));

    /// Logs (warning, "vv.pacs") "<what> from <address>: <why>" unless a line
    /// of the same address and `what`/`why` went out within the interval.
    void note(const std::string& what, const std::string& address, const std::string& why);

  private:
    struct Entry {
        std::chrono::steady_clock::time_point last;
        std::size_t leftOut = 0;
    };
    std::chrono::steady_clock::duration interval_;
    std::mutex mutex_;
    std::map<std::string, Entry> entries_;
};

}  // namespace vv::pacs::detail
