// SPDX-License-Identifier: GPL-3.0-or-later
#include "RefusalLog.h"

#include "vv/core/Log.h"

namespace vv::pacs::detail {

namespace {

constexpr log::Category kLog("vv.pacs");
/// Addresses remembered at most; beyond, the memory starts afresh (a flood
/// from many addresses costs a few more lines, never unbounded memory).
constexpr std::size_t kMaxEntries = 4096;

}  // namespace

RefusalLog::RefusalLog(std::chrono::steady_clock::duration interval) : interval_(interval) {}

void RefusalLog::note(const std::string& what, const std::string& address, const std::string& why) {
    const auto now = std::chrono::steady_clock::now();
    std::size_t leftOut = 0;
    {
        const std::lock_guard lock(mutex_);
        const std::string key = address + '\n' + what + '\n' + why;
        const auto it = entries_.find(key);
        if (it != entries_.end() && now - it->second.last < interval_) {
            ++it->second.leftOut;
            return;
        }
        if (it != entries_.end()) {
            leftOut = it->second.leftOut;
            it->second = Entry{now, 0};
        } else {
            if (entries_.size() >= kMaxEntries) {
                entries_.clear();
            }
            entries_.emplace(key, Entry{now, 0});
        }
    }
    std::string line =
        what + " from " + (address.empty() ? "an unknown host" : address) + ": " + why;
    if (leftOut > 0) {
        line += " (and " + std::to_string(leftOut) + " more like it since the last such line)";
    }
    log::warning(kLog, line);
}

}  // namespace vv::pacs::detail
