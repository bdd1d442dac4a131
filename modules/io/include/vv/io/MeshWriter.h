// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <filesystem>

#include "vv/io/Mesh.h"

namespace vv::io {

/// Writes `mesh` as VTK XML polydata (.vtp, binary, zlib-compressed) with its
/// normals, point and cell arrays; units travel in the array names as
/// "name [unit]". Written atomically (temporary file + rename).
/// Throws IoError naming `file` when it cannot be written.
void writeVtp(const Mesh& mesh, const std::filesystem::path& file);

}  // namespace vv::io
