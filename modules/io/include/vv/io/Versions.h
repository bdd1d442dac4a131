// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <string>
#include <vector>

namespace vv::io {

/// A third-party library the io module uses, and its version.
struct LibraryVersion {
    std::string name;     ///< "VTK", "DCMTK"
    std::string version;  ///< e.g. "9.1.0"
};

/// The versions of the libraries behind vv::io, for the About box: VTK (as
/// the linked library reports it) and DCMTK (the version built against).
/// Never throws.
[[nodiscard]] std::vector<LibraryVersion> libraryVersions();

}  // namespace vv::io
