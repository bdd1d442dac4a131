// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "vv/core/Progress.h"
#include "vv/scene/Mesh.h"

namespace vv::demo {

/// Parameters of the synthetic demo vessel tree. The defaults give the bundled
/// demo; tests make smaller or different variants. Physics in SI-friendly
/// clinical units: mm, mmHg, ml/s, Pa, Pa·s. The model is described in
/// docs/demo-data.md.
struct DemoTreeOptions {
    std::uint64_t seed = 20181021;     ///< same seed, same tree, bit for bit
    int generations = 6;               ///< root = generation 0; 1..10
    double rootRadiusMm = 3.0;         ///< radius of the inlet segment; > 0
    double rootLengthMm = 40.0;        ///< length of the inlet segment; >= 2 * rootRadiusMm
    double inletPressureMmHg = 100.0;  ///< pressure at the inlet; finite
    double inletFlowMlPerS = 5.0;      ///< flow into the inlet; > 0
    double viscosityPaS = 3.5e-3;      ///< blood dynamic viscosity; > 0
    /// Surface sampling grid spacing; 0 = automatic: 4 voxels across the
    /// thinnest vessel, or finer for about 300k triangles; coarser only to
    /// stay within maxTriangles or the grid size limit.
    double voxelSizeMm = 0.0;
    bool smooth = true;  ///< smooth the extracted surface (windowed sinc)
    /// Largest triangle count: a surface with more is extracted again on a
    /// coarser grid (overriding voxelSizeMm); 0 = no limit, else >= 10000.
    int maxTriangles = 500000;
};

/// One vessel segment: a curved centreline from its parent's end to its own end.
struct VesselSegment {
    int id = 0;
    int parent = -1;  ///< -1 for the root
    std::vector<int> children;
    int generation = 0;
    std::vector<glm::vec3> centerline;  ///< >= 2 points, mm; front() joins the parent
    double radiusMm = 0.0;
    double lengthMm = 0.0;    ///< arc length of the centreline
    double resistance = 0.0;  ///< Poiseuille 8 mu L / (pi r^4), Pa·s/m^3
    double flowMlPerS = 0.0;
    double pressureInMmHg = 0.0;   ///< at centerline.front()
    double pressureOutMmHg = 0.0;  ///< at centerline.back()
    double wssPa = 0.0;            ///< 4 mu Q / (pi r^3)
};

/// A branching tree; segments[0] is the root, parents come before children.
struct VesselTree {
    std::vector<VesselSegment> segments;
};

/// Builds the tree's geometry (centrelines and Murray's-law radii) and solves
/// Poiseuille flow through it (flows, pressures, wall shear stress).
/// Deterministic for a given seed. Throws InvalidArgumentError for options out
/// of range (generations < 1 or > 10, non-positive or non-finite radius /
/// length / flow / viscosity, root length < 2 root radii, non-finite inlet
/// pressure, negative voxel size, triangle limit neither 0 nor >= 10000).
[[nodiscard]] VesselTree generateVesselTree(const DemoTreeOptions& options);

/// A watertight triangulated surface around the tree with smooth junctions,
/// normals pointing outward, and point arrays `pressure` [mmHg], `wss` [Pa],
/// `segment_id` and `generation` (integer, no unit), each vertex taking the
/// values of its nearest segment. Uses options.voxelSizeMm, smooth and
/// maxTriangles. Reports progress; throws CancelledError when stopped,
/// InvalidArgumentError for bad options, an inconsistent tree (empty, bad
/// parent links, non-positive radius, fewer than 2 centreline points) or an
/// explicit voxel size that would need too large a grid.
[[nodiscard]] scene::Mesh buildVesselSurface(const VesselTree& tree, const DemoTreeOptions& options,
                                             const Progress& progress = {});

/// generateVesselTree + buildVesselSurface; the mesh is named "demo vessel tree".
[[nodiscard]] scene::Mesh generateDemoMesh(const DemoTreeOptions& options = {},
                                           const Progress& progress = {});

}  // namespace vv::demo
