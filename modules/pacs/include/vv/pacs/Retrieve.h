// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Retrieve (Study Root Q/R) of a study or one series: C-GET straight into the
// local store, or C-MOVE to a storage SCP (usually our own listener).

#include <cstddef>
#include <string>

#include "vv/core/Progress.h"
#include "vv/pacs/LocalStore.h"
#include "vv/pacs/Node.h"

namespace vv::pacs {

struct RetrieveRequest {
    std::string studyInstanceUid;   ///< required
    std::string seriesInstanceUid;  ///< empty: the whole study
};

struct RetrieveResult {
    std::size_t instances = 0;  ///< instances retrieved (C-GET: stored; C-MOVE: the peer's count)
};

/// C-GET of `request` from `peer` into `store`, one store transaction: only
/// when the peer reports success for every sub-operation are the instances
/// committed (marked complete). Progress reports "Retrieving" with the share
/// of instances received; a stop through `progress` aborts the association
/// at once, also while waiting for the peer.
/// Throws InvalidArgumentError (a malformed UID), the NetworkError family
/// (PeerFailedError also when a sub-operation failed, ConnectionClosedError
/// when the peer went away), CancelledError, IoError (the store). Nothing
/// is marked complete on any throw: the transaction and every instance
/// received are discarded. A NetworkError thrown after the request went out
/// carries transfer(): the instances received by then and all of them.
RetrieveResult getInto(LocalStore& store, const LocalAe& me, const Node& peer,
                       const RetrieveRequest& request, const Progress& progress = {});

/// C-MOVE of `request` from `peer` to the AE title `destination` (which the
/// peer must know). Returns when the peer reports the move done; the
/// destination's storage SCP stores the instances (ours commits them per
/// association, when the peer releases it, and discards an aborted one).
/// Progress and errors as getInto; transfer().received counts the
/// sub-operations the peer reported done.
RetrieveResult moveTo(const std::string& destination, const LocalAe& me, const Node& peer,
                      const RetrieveRequest& request, const Progress& progress = {});

}  // namespace vv::pacs
