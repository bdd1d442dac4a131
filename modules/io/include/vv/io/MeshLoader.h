// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "vv/core/Progress.h"
#include "vv/io/Mesh.h"

namespace vv::io {

struct MeshLoadOptions {
    /// Multiplies every coordinate: files are taken to be in millimetres, so a
    /// file in metres loads with scale = 1000. Must be finite and > 0.
    double scale = 1.0;
    /// Also convert cell arrays into point arrays (averaging the cells around
    /// each point); the converted arrays are marked DataArray::fromCells.
    bool cellArraysToPoints = true;
};

/// File extensions loadMesh accepts, lower case with the dot: ".stl", ".obj",
/// ".ply", ".vtk", ".vtp", ".vtu".
[[nodiscard]] const std::vector<std::string>& supportedMeshExtensions();

/// Loads one triangle mesh from STL (ASCII or binary), OBJ, PLY, legacy VTK
/// (polydata or unstructured grid), VTP or VTU (outer surface extracted).
/// Normals are computed when the file has none. Non-finite array values are
/// kept as NaN. The file is only read, never modified.
/// Throws IoError (missing, unreadable, a folder), FormatError (unknown
/// extension, corrupt or truncated content, empty mesh, non-finite
/// coordinates, zero area), InvalidArgumentError (bad scale), CancelledError.
/// Every message names the file.
[[nodiscard]] Mesh loadMesh(const std::filesystem::path& file, const MeshLoadOptions& options = {},
                            const Progress& progress = {});

/// Loads several files into one scene, in order; fails on the first bad file.
[[nodiscard]] Scene loadScene(const std::vector<std::filesystem::path>& files,
                              const MeshLoadOptions& options = {}, const Progress& progress = {});

}  // namespace vv::io
