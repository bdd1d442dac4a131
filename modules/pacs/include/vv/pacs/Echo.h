// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// C-ECHO: "is the node there and does it talk to us?"

#include <stop_token>

#include "vv/pacs/Node.h"

namespace vv::pacs {

/// Opens an association with `peer` as `me`, sends C-ECHO and releases.
/// Returns normally when the peer answered with success. A stop of `stop`
/// (from any thread) aborts the association at once and throws
/// CancelledError (the TCP connect itself runs to its own timeout first).
/// Throws InvalidArgumentError (bad AE title / node), ConnectionRefusedError,
/// AssociationRejectedError, TimeoutError, PeerFailedError or CancelledError.
void echo(const LocalAe& me, const Node& peer, std::stop_token stop = {});

}  // namespace vv::pacs
