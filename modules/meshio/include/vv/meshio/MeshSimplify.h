// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstddef>

#include "vv/core/Progress.h"
#include "vv/scene/Mesh.h"

namespace vv::meshio {

/// A coarser copy of `mesh` for drawing while the camera moves (level of
/// detail): quadric edge-collapse decimation (Garland & Heckbert) with volume
/// preservation down to about `targetTriangles` triangles, fresh normals, and
/// every point array carried over from the nearest original vertex (so ids
/// and labels stay exact values, NaN stays "no data"). Cell arrays are
/// dropped (the triangles are new). Name and source are kept.
///
/// A mesh with at most `targetTriangles` triangles comes back unchanged.
/// Progress is reported on [0, 1]; a stop request throws CancelledError.
/// Throws InvalidArgumentError for targetTriangles < 4 and FormatError
/// (naming the mesh's source) when VTK fails or the result has no triangles.
[[nodiscard]] scene::Mesh simplifiedMesh(const scene::Mesh& mesh, std::size_t targetTriangles,
                                         const Progress& progress = {});

/// simplifiedMesh() of every mesh, the target split over the meshes in
/// proportion to their triangle counts (at least 4 each); progress over the
/// whole scene.
[[nodiscard]] scene::Scene simplifiedScene(const scene::Scene& scene, std::size_t targetTriangles,
                                           const Progress& progress = {});

}  // namespace vv::meshio
