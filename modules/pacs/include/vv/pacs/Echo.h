// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// C-ECHO: "is the node there and does it talk to us?"

#include "vv/pacs/Node.h"

namespace vv::pacs {

/// Opens an association with `peer` as `me`, sends C-ECHO and releases.
/// Returns normally when the peer answered with success. Throws
/// InvalidArgumentError (bad AE title / node), ConnectionRefusedError,
/// AssociationRejectedError, TimeoutError or PeerFailedError.
void echo(const LocalAe& me, const Node& peer);

}  // namespace vv::pacs
