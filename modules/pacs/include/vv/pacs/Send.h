// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// C-STORE: sending DICOM files (report outputs, SEG, series) to a node.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "vv/core/Progress.h"
#include "vv/pacs/Node.h"

namespace vv::pacs {

/// What the node said about one instance.
struct SendStatus {
    std::filesystem::path file;
    bool accepted = false;     ///< success or warning status
    std::uint16_t status = 0;  ///< the DIMSE status of the C-STORE response
};

/// Sends `files` to `peer` in one association (each file's SOP class is
/// proposed in its own transfer syntax and explicit little endian). Returns
/// one status per file, in order. Progress reports "Sending" per file.
/// Throws FormatError (naming the file) when a file is not DICOM, the
/// NetworkError family when the association or a transfer fails,
/// CancelledError (the association is aborted).
std::vector<SendStatus> sendFiles(const LocalAe& me, const Node& peer,
                                  const std::vector<std::filesystem::path>& files,
                                  const Progress& progress = {});

}  // namespace vv::pacs
