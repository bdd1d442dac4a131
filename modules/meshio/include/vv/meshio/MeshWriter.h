// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <filesystem>

#include "vv/scene/Mesh.h"

namespace vv::meshio {

/// Writes `mesh` as VTK XML polydata (.vtp, binary, zlib-compressed) with its
/// normals, point and cell arrays; units travel in the array names as
/// "name [unit]". Integer arrays (DataArray::integer) are written as 32-bit
/// integers when all their values are finite and in range, so they load back
/// as integer; otherwise as floats. Point arrays converted from a cell array
/// of the mesh (DataArray::fromCells) are not written: loading the file with
/// MeshLoadOptions::cellArraysToPoints recreates them. NaN values are kept.
/// Written atomically (temporary file in the same folder + rename): on failure
/// neither `file` nor a temporary file is left behind, and an existing `file`
/// is unchanged.
/// Throws IoError naming `file` when it cannot be written (missing folder, no
/// permission, disk full); InvalidArgumentError when the mesh is inconsistent
/// (indices out of range, array sizes not matching the vertex / triangle
/// count, unnamed or duplicate array names).
void writeVtp(const scene::Mesh& mesh, const std::filesystem::path& file);

}  // namespace vv::meshio
