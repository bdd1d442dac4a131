// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// How many connections the listener holds open, per peer address and in all.
// A configured node's address (the host of an allowed peer) gets its own cap;
// any other address (it can never be let in, only told so) a small one, and
// all of those together another. Each open connection holds a Slot from
// accept to close: the gate takes it, a worker ends it.

#include <cstddef>
#include <map>
#include <mutex>
#include <optional>
#include <set>
#include <string>

namespace vv::pacs::detail {

class ConnectionBudget {
  public:
    struct Caps {
        int perNodeAddress = 8;
        int total = 64;
        int perStrangerAddress = 2;
        int strangers = 8;
    };

    /// An open connection's share of the budget, given back on destruction.
    class Slot {
      public:
        Slot(Slot&& other) noexcept;
        Slot& operator=(Slot&& other) noexcept;
        Slot(const Slot&) = delete;
        Slot& operator=(const Slot&) = delete;
        ~Slot();
        [[nodiscard]] const std::string& address() const noexcept { return address_; }

      private:
        friend class ConnectionBudget;
        Slot(ConnectionBudget* budget, std::string address, bool stranger) noexcept;
        ConnectionBudget* budget_;
        std::string address_;
        bool stranger_;
    };

    /// `nodeAddresses`: the hosts (IPv4 addresses) of the configured nodes.
    ConnectionBudget(Caps caps, std::set<std::string> nodeAddresses);
    ConnectionBudget(const ConnectionBudget&) = delete;
    ConnectionBudget& operator=(const ConnectionBudget&) = delete;
    ConnectionBudget(ConnectionBudget&&) = delete;
    ConnectionBudget& operator=(ConnectionBudget&&) = delete;
    /// Every Slot must be gone by then.
    ~ConnectionBudget() = default;

    /// A slot for a new connection from `address`, or nullopt when it is over
    /// a cap; then `why` (if given) says which ("over the 8 connections one
    /// address may hold").
    [[nodiscard]] std::optional<Slot> take(const std::string& address, std::string* why = nullptr);

    /// Connections open now.
    [[nodiscard]] std::size_t open() const;

    /// True when `address` is a configured node's host.
    [[nodiscard]] bool isNode(const std::string& address) const;

  private:
    void give(const std::string& address, bool stranger) noexcept;

    const Caps caps_;
    const std::set<std::string> nodes_;
    mutable std::mutex mutex_;
    std::map<std::string, int> perAddress_;
    int total_ = 0;
    int strangers_ = 0;
};

}  // namespace vv::pacs::detail
