// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Triangle surfaces from label maps (VTK flying edges behind this header).

#include <cstddef>
#include <cstdint>
#include <vector>

#include "vv/core/Progress.h"
#include "vv/scene/Mesh.h"
#include "vv/segmentation/VolumeSegmentation.h"

namespace vv::segmentation {

struct SurfaceOptions {
    /// Windowed-sinc smoothing iterations; 0 = no smoothing.
    int smoothingIterations = 20;
    /// Windowed-sinc pass band in (0, 2]; smaller smooths more.
    double passBand = 0.1;
    /// Decimate (quadric, volume preserving) to about this many triangles;
    /// 0 = keep every triangle.
    std::size_t targetTriangles = 300000;
};

/// The surface around the voxels of `map` whose label is in `labels` (all
/// non-zero labels when empty), as one mesh: flying edges at the half-way
/// level of the binary mask (the map is padded by one background voxel so
/// the surface is closed where the segment touches the volume's border),
/// mapped to world (LPS, mm) through map.indexToWorld — a general affine map,
/// so anisotropic spacing and a gantry-tilt shear are exact — then
/// windowed-sinc smoothing and decimation in world space, triangles wound so
/// that normals point out of the segment (also when indexToWorld mirrors),
/// area-weighted vertex normals. Reports progress ("Extracting surface").
/// Throws InvalidArgumentError (inconsistent map, options out of range),
/// FormatError when no voxel has one of the labels or VTK fails,
/// CancelledError.
[[nodiscard]] scene::Mesh extractSurface(const scene::LabelMap& map,
                                         const std::vector<std::uint8_t>& labels = {},
                                         const SurfaceOptions& options = {},
                                         const Progress& progress = {});

/// The label of each vertex of `mesh` (world, LPS mm) in `map`: of the
/// labelled voxels within two voxels of it (index space, per axis), the
/// nearest; 0 when there is none. An integer point array named "label"
/// (no unit) whose label names (Mesh::labelNames) the caller may add.
[[nodiscard]] scene::DataArray surfaceLabels(const scene::Mesh& mesh, const scene::LabelMap& map);

}  // namespace vv::segmentation
