// SPDX-License-Identifier: GPL-3.0-or-later
#include "ConnectionBudget.h"

#include <utility>

namespace vv::pacs::detail {

ConnectionBudget::Slot::Slot(ConnectionBudget* budget, std::string address, bool stranger) noexcept
    : budget_(budget), address_(std::move(address)), stranger_(stranger) {}

ConnectionBudget::Slot::Slot(Slot&& other) noexcept
    : budget_(std::exchange(other.budget_, nullptr)),
      address_(std::move(other.address_)),
      stranger_(other.stranger_) {}

ConnectionBudget::Slot& ConnectionBudget::Slot::operator=(Slot&& other) noexcept {
    if (this != &other) {
        if (budget_ != nullptr) {
            budget_->give(address_, stranger_);
        }
        budget_ = std::exchange(other.budget_, nullptr);
        address_ = std::move(other.address_);
        stranger_ = other.stranger_;
    }
    return *this;
}

ConnectionBudget::Slot::~Slot() {
    if (budget_ != nullptr) {
        budget_->give(address_, stranger_);
    }
}

ConnectionBudget::ConnectionBudget(Caps caps, std::set<std::string> nodeAddresses)
    : caps_(caps), nodes_(std::move(nodeAddresses)) {}

bool ConnectionBudget::isNode(const std::string& address) const {
    return nodes_.contains(address);
}

std::optional<ConnectionBudget::Slot> ConnectionBudget::take(const std::string& address,
                                                             std::string* why) {
    const bool stranger = !isNode(address);
    const std::lock_guard lock(mutex_);
    const int mine = perAddress_.contains(address) ? perAddress_.at(address) : 0;
    std::string over;
    if (total_ >= caps_.total) {
        over = "over the " + std::to_string(caps_.total) + " connections the listener holds";
    } else if (!stranger && mine >= caps_.perNodeAddress) {
        over = "over the " + std::to_string(caps_.perNodeAddress) +
               " connections one address may hold";
    } else if (stranger && mine >= caps_.perStrangerAddress) {
        over = "not a configured node's address, over its " +
               std::to_string(caps_.perStrangerAddress) + " connections";
    } else if (stranger && strangers_ >= caps_.strangers) {
        over = "not a configured node's address, over the " + std::to_string(caps_.strangers) +
               " connections all such addresses may hold";
    }
    if (!over.empty()) {
        if (why != nullptr) {
            *why = std::move(over);
        }
        return std::nullopt;
    }
    ++perAddress_[address];
    ++total_;
    strangers_ += stranger ? 1 : 0;
    return Slot(this, address, stranger);
}

std::size_t ConnectionBudget::open() const {
    const std::lock_guard lock(mutex_);
    return static_cast<std::size_t>(total_);
}

void ConnectionBudget::give(const std::string& address, bool stranger) noexcept {
    const std::lock_guard lock(mutex_);
    const auto it = perAddress_.find(address);
    if (it != perAddress_.end() && --it->second <= 0) {
        perAddress_.erase(it);
    }
    --total_;
    strangers_ -= stranger ? 1 : 0;
}

}  // namespace vv::pacs::detail
