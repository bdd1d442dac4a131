// SPDX-License-Identifier: GPL-3.0-or-later
// Private to vv::demo: the surface where a sampled field is zero, as the demo
// tree (DemoSurface.cpp) and the aneurysm phantom (AneurysmPhantom.cpp) make
// theirs: the field sampled slab by slab on a regular grid (so the whole grid
// never needs to be in memory), flying edges at 0, windowed-sinc smoothing,
// outward normals.
#pragma once

#include <vtkPolyData.h>
#include <vtkPolyDataAlgorithm.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <glm/glm.hpp>
#include <string_view>

#include "vv/core/Progress.h"
#include "vv/scene/Mesh.h"

namespace vv::demo::detail {

/// A phantom of fewer triangles than this is extracted at this many and
/// decimated to its count, as coarse segmentations are made: a voxel grid as
/// coarse as 1k triangles needs (3 mm voxels for a 5 mm radius) blurs the
/// tubes, shrinks their radii by a third, and the phantom is no longer its
/// truth.
inline constexpr std::size_t kFinestExtractionTriangles = 20'000;

/// Field values are kept this far (in voxels) from 0, so that no surface
/// point lies on (or rounds onto) a grid point or grid plane.
inline constexpr double kZeroGuardVoxels = 0.05;
/// Field values are clamped to +-(this many voxels); within that band the
/// field must be the distance-like function whose zero level is wanted.
inline constexpr double kBandVoxels = 3.0;

/// A regular grid: voxel (x, y, z) is at origin + spacing * (x, y, z).
struct FieldGrid {
    glm::dvec3 origin{0.0};
    double spacing = 0.0;
    int nx = 0;
    int ny = 0;
    int nz = 0;
    [[nodiscard]] double voxelCount() const {
        return static_cast<double>(nx) * static_cast<double>(ny) * static_cast<double>(nz);
    }
};

/// A field value as the extraction needs it: clamped to +-band and moved to
/// +-guard when it lies within guard of 0.
inline float guardedFieldValue(float value, float band, float guard) {
    const float v = std::clamp(value, -band, band);
    if (std::abs(v) < guard) {
        return v < 0.0F ? -guard : guard;
    }
    return v;
}

/// Polynomial smooth minimum of width k: min(a, b) away from a == b, blended
/// (and at most k / 4 lower) where they are within k of each other: the
/// smooth union of two shapes whose fields are a and b.
inline float smoothMin(float a, float b, float k) {
    const float h = std::max(k - std::abs(a - b), 0.0F) / k;
    return std::min(a, b) - h * h * k * 0.25F;
}

/// Fills `values` with the field at the voxel layers z0..z1 (every x and y,
/// x fastest; each value guardedFieldValue() of the grid's band and guard)
/// and returns true; or returns false, leaving `values` alone, when the
/// surface cannot pass through those layers (the slab is skipped).
using SlabSampler = std::function<bool(int z0, int z1, float* values)>;

/// The zero level of the sampled field, slab by slab (neighbouring slabs
/// share a voxel layer; the points made on it are joined into one), in
/// world coordinates. Reports progress ("Extracting surface"); throws
/// CancelledError, Error when slabs do not join (an internal error).
[[nodiscard]] vtkSmartPointer<vtkPolyData> extractZeroLevel(const FieldGrid& grid,
                                                            const SlabSampler& sample,
                                                            const Progress& progress);

/// Runs the filter with meshio's progress forwarding and error capture;
/// returns a copy of its output. Throws CancelledError, FormatError.
[[nodiscard]] vtkSmartPointer<vtkPolyData> runFilter(vtkPolyDataAlgorithm* filter,
                                                     const Progress& progress,
                                                     std::string_view stage);

/// Windowed-sinc smoothing as the demo surfaces have it (20 iterations, pass
/// band 0.05, boundaries kept). Throws as runFilter.
[[nodiscard]] vtkSmartPointer<vtkPolyData> smoothSurface(vtkPolyData* surface,
                                                         const Progress& progress);

/// Point normals, the mesh, only its largest connected piece (specks a voxel
/// wide go), triangles wound outward. Throws as runFilter, Error when VTK
/// leaves data arrays on the surface (an internal error).
[[nodiscard]] scene::Mesh finishSurface(vtkSmartPointer<vtkPolyData> surface,
                                        const Progress& progress);

}  // namespace vv::demo::detail
