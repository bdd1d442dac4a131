// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "vv/core/Progress.h"
#include "vv/scene/Mesh.h"

namespace vv::meshio {

struct MeshLoadOptions {
    /// Multiplies every coordinate: files are taken to be in millimetres, so a
    /// file in metres loads with scale = 1000. Must be finite and > 0.
    double scale = 1.0;
    /// Also convert cell arrays into point arrays: each point gets the mean of
    /// the finite values of the triangles around it (integer arrays: the most
    /// common value, the smallest on ties), NaN when none has a value. The
    /// converted arrays are marked DataArray::fromCells, keep the unit, and are
    /// named like the cell array, or "name (cells)" when a point array already
    /// has that name. The cell arrays are kept as well.
    bool cellArraysToPoints = true;
};

/// File extensions loadMesh accepts, lower case with the dot: ".stl", ".obj",
/// ".ply", ".vtk", ".vtp", ".vtu".
[[nodiscard]] const std::vector<std::string>& supportedMeshExtensions();

/// Loads one triangle mesh from STL (ASCII or binary), OBJ, PLY, legacy VTK
/// (polydata or unstructured grid), VTP or VTU (outer surface extracted).
/// The extension decides the format (case-insensitive). Polygons are
/// triangulated; lines and vertices are dropped. Normals are taken from the
/// file or computed when it has none. Point and cell arrays are kept with
/// their units (from "name [unit]" array names); non-finite array values are
/// kept as NaN. Identical STL corners are merged into shared vertices. OBJ
/// group ids become a cell array "GroupIds" only when there are several
/// groups; scalar PLY vertex / face properties VTK does not know become point
/// / cell arrays. The mesh is named after the file stem.
/// The file is only read, never modified. Files are checked before VTK reads
/// them, so corrupt headers (absurd counts, out-of-range indices) are refused
/// instead of crashing or allocating without bound.
/// Reports progress; stops with CancelledError when a stop is requested.
/// Throws IoError (missing, unreadable, a folder, not a regular file),
/// FormatError (unknown extension, empty file, corrupt or truncated content,
/// wrong file type, empty mesh, non-finite coordinates, zero area),
/// InvalidArgumentError (scale not finite or <= 0), CancelledError.
/// Every message names the file.
[[nodiscard]] scene::Mesh loadMesh(const std::filesystem::path& file,
                                   const MeshLoadOptions& options = {},
                                   const Progress& progress = {});

/// Loads several files into one scene, in order; fails on the first bad file
/// (with the exceptions of loadMesh). An empty list gives an empty scene.
[[nodiscard]] scene::Scene loadScene(const std::vector<std::filesystem::path>& files,
                                     const MeshLoadOptions& options = {},
                                     const Progress& progress = {});

}  // namespace vv::meshio
