// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The worker side of a retrieve from the PACS browser: C-GET into the local
// store, or C-MOVE to our own listener (which stores into the same store)
// followed by a bounded wait until the listener has committed the
// instances. Runs on a worker thread; the GUI reads `fraction` and stops it
// through `stop`.

#include <atomic>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <stop_token>

#include "gui/pacs/NetworkFailure.h"
#include "gui/pacs/PacsSettings.h"
#include "vv/pacs/Node.h"
#include "vv/pacs/Retrieve.h"

namespace vv::gui {

struct RetrieveJob {
    /// Our AE (settings.me) and the local store (openStore(settings): its
    /// folder and size limit).
    PacsSettings settings;
    pacs::Node node;
    pacs::RetrieveRequest request;
    bool move = false;  ///< C-MOVE to settings.me.aeTitle (our listener) instead of C-GET
    int listenerWaitSeconds = 10;  ///< C-MOVE: how long the listener may take to commit
};

/// Shared between the GUI and the worker.
struct RetrieveControl {
    std::stop_source stop;
    std::atomic<double> fraction{0.0};  ///< share of the instances received so far
};

struct RetrieveOutcome {
    NetworkFailure failure;            ///< Kind::None when the retrieve is complete
    std::size_t instances = 0;         ///< instances retrieved
    std::filesystem::path folder;      ///< the retrieved series' (or study's) folder in the store
    bool notStoredByListener = false;  ///< C-MOVE done, but our listener stored nothing in time
    /// A failed retrieve: instances of it the local store holds now that it
    /// did not before (C-GET: none, its transaction is discarded; C-MOVE:
    /// what our listener committed from associations the peer released);
    /// nullopt when the store could not be read.
    std::optional<std::size_t> kept;
};

/// Runs `job`; never throws (failures are in the outcome; a stop through
/// `control.stop` gives Kind::Cancelled, and then nothing is complete in the store).
[[nodiscard]] RetrieveOutcome runRetrieve(const RetrieveJob& job, RetrieveControl& control);

}  // namespace vv::gui
