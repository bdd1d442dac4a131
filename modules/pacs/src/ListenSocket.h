// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The listener's socket: bound to one interface (IPv4) and port, listening,
// non-blocking (the connection gate polls it).

#include <cstdint>
#include <string>

#include "Socket.h"

namespace vv::pacs::detail {

/// Throws InvalidArgumentError unless `address` is a dotted IPv4 address.
void validateBindAddress(const std::string& address);

/// A socket listening on `address`:`port`, non-blocking, close-on-exec.
/// Throws IoError naming the address and port when it cannot be bound.
[[nodiscard]] OwnedSocket openListenSocket(const std::string& address, std::uint16_t port);

}  // namespace vv::pacs::detail
