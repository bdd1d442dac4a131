// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Binding the listener to one interface. DCMTK 3.6.7's DcmSCP listens on
// every interface; before it accepts its first connection, the listener
// replaces that socket (same descriptor number) with one bound to the
// configured address.

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmnet/assoc.h>

#include <cstdint>
#include <string>

namespace vv::pacs::detail {

/// Throws InvalidArgumentError unless `address` is a dotted IPv4 address.
void validateBindAddress(const std::string& address);

/// Replaces the listening socket of `network` by one listening on
/// `address`:`port`. Throws IoError when it cannot be bound.
void rebindListenSocket(T_ASC_Network& network, const std::string& address, std::uint16_t port);

}  // namespace vv::pacs::detail
