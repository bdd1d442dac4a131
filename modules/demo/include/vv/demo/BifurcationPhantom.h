// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// A Y-bifurcation of known geometry for measuring branch trees and
// bifurcation angles: a straight parent along +z ending at the origin, two
// straight daughters leaving the origin in the x-z plane, each at half the
// bifurcation angle from +z. The surface is the demo tree's (flying edges
// over a smooth union of the tubes, windowed-sinc smoothed, rounded closed
// tips), at about a chosen triangle count. Under 20k triangles it is
// extracted at 20k and decimated (quadric edge collapse, as coarse
// segmentations are made): a voxel grid that coarse would blur the tubes.

#include <array>
#include <cstddef>
#include <glm/glm.hpp>

#include "vv/core/Progress.h"
#include "vv/demo/DemoTree.h"
#include "vv/scene/Mesh.h"

namespace vv::demo {

struct BifurcationPhantomOptions {
    double parentRadiusMm = 5.0;  ///< > 0
    /// 0: Murray's law, parent / 2^(1/3); else > 0 and <= parentRadiusMm.
    double daughterRadiusMm = 0.0;
    double angleDeg = 60.0;                ///< between the daughters, in [10, 170]
    double parentLengthMm = 60.0;          ///< >= 4 parent radii
    double daughterLengthMm = 60.0;        ///< >= 4 parent radii
    std::size_t targetTriangles = 50'000;  ///< about; in [1000, 5'000'000]
};

struct BifurcationPhantom {
    BifurcationPhantomOptions options;
    /// The truth: segments[0] the parent (from (0, 0, -parentLength) to the
    /// origin), [1] the daughter towards +x, [2] towards -x.
    VesselTree tree;
    scene::Mesh mesh;
    glm::dvec3 parentDirection{0.0, 0.0, 1.0};
    std::array<glm::dvec3, 2> daughterDirections{};
};

/// Builds the phantom. Throws InvalidArgumentError for options out of range;
/// CancelledError on a stop request.
[[nodiscard]] BifurcationPhantom makeBifurcationPhantom(const BifurcationPhantomOptions& options,
                                                        const Progress& progress = {});

}  // namespace vv::demo
