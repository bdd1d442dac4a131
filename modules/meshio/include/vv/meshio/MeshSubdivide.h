// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "vv/core/Progress.h"
#include "vv/scene/Mesh.h"

namespace vv::meshio {

/// A mesh refined by subdivision, and how far it lies from the mesh it was
/// made from.
struct SubdividedMesh {
    scene::Mesh mesh;
    /// What the refinement moved the surface by, in the mesh's units:
    /// `largestDeviation` the Hausdorff distance between the two surfaces
    /// (the farthest of its points from the input's triangles, and of the
    /// input's vertices and triangle centres from its triangles);
    /// `meanDeviation` the mean distance of its points from the input's
    /// triangles.
    double largestDeviation = 0.0;
    double meanDeviation = 0.0;
};

/// A copy of `mesh` refined `levels` times by Loop subdivision (VTK's
/// vtkLoopSubdivisionFilter; Loop 1987): each triangle becomes four per
/// level, and the surface converges to a smooth one (its curvature
/// continuous) near the input. The scheme approximates: the input's points
/// move too, a convex vessel wall inward by a fraction of its facets' sag;
/// the result says by how much. (VTK's interpolating butterfly scheme keeps
/// the points but overshoots into spikes next to irregular vertices of a
/// decimated surface.) Each point array is taken from the input where the
/// new point lies over it (the nearest point of the input's triangles):
/// interpolated linearly over that triangle, as the input shows it, so a
/// value never exceeds its triangle's; an integer (id, label) array, and
/// one with no data (NaN) at a corner that counts, takes the nearest
/// corner's value. Cell arrays are left out; normals are computed afresh;
/// name and source are kept.
/// Progress is reported on [0, 1]; a stop request throws CancelledError.
/// Throws InvalidArgumentError for levels outside [1, 3]; FormatError
/// (naming the mesh's source) for no triangles, indices out of range,
/// non-finite coordinates, or when VTK fails.
[[nodiscard]] SubdividedMesh subdividedMesh(const scene::Mesh& mesh, int levels,
                                            const Progress& progress = {});

/// subdividedMesh() of every mesh of a scene, with the largest and the
/// mean (over the new points) deviation of all.
struct SubdividedScene {
    scene::Scene scene;
    double largestDeviation = 0.0;
    double meanDeviation = 0.0;
};
/// Progress over the whole scene, in proportion to the meshes' triangles.
/// Throws as subdividedMesh().
[[nodiscard]] SubdividedScene subdividedScene(const scene::Scene& scene, int levels,
                                              const Progress& progress = {});

}  // namespace vv::meshio
