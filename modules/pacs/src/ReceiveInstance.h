// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Receiving one C-STORE dataset straight into a file as it arrives (DCMTK's
// bit-preserving receive: the meta header from the request, then the dataset
// exactly as sent), never whole in memory, with a cap on its bytes.

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmnet/dimse.h>

#include <cstdint>
#include <filesystem>

namespace vv::pacs::detail {

struct ReceivedInstance {
    enum class Outcome {
        Stored,       ///< the whole dataset is in the file
        OverCap,      ///< more than the cap: the rest was read and thrown away, no file
        WriteFailed,  ///< the file could not be made or written (disk full): no file
    };
    Outcome outcome = Outcome::Stored;
    std::uint64_t bytes = 0;  ///< dataset bytes written to the file
};

/// Receives the dataset of `request` (command on presentation context
/// `presId`) on `association` into `path`, at most `cap` bytes of it, each
/// PDU within `timeoutSeconds`. Over the cap or when the file cannot be
/// written, the rest is read and thrown away (the association goes on) and
/// the file is removed. Returns a bad condition when the network fails,
/// the peer breaks off or stalls, or the dataset comes on another
/// presentation context (the association is unusable then; no file).
OFCondition receiveInstance(T_ASC_Association* association, T_DIMSE_C_StoreRQ& request,
                            T_ASC_PresentationContextID presId, const std::filesystem::path& path,
                            std::uint64_t cap, int timeoutSeconds, ReceivedInstance& result);

}  // namespace vv::pacs::detail
