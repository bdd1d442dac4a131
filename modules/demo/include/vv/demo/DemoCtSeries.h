// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// A CT-angiography-like volume of the synthetic demo tree (lumen ~400 HU,
// tissue ~40 HU with Gaussian noise, a bone-like block ~1000 HU beside the
// tree, partial volume at every edge, on an oblique grid); dicom::writeCtSeries
// (vv/dicom/SeriesWriter.h) stores it as a CT image series.
// Used by `vesselview-cli demo --dicom DIR` and the round-trip tests.

#include <cstdint>
#include <glm/glm.hpp>

#include "vv/core/Progress.h"
#include "vv/demo/DemoTree.h"
#include "vv/scene/Volume.h"

namespace vv::demo {

struct DemoCtOptions {
    glm::ivec3 dims{96, 96, 80};  ///< voxels (columns, rows, slices); each >= 8
    int generations = 4;          ///< branching generations of the tree, 1..10
    double angleDegrees = 20.0;   ///< rows rotated by this about the superior axis
    double noiseSigma = 15.0;     ///< Gaussian noise, HU; >= 0
    std::uint32_t noiseSeed = 20240611U;
};

/// The voxelised demo tree and where things are in it.
struct DemoCt {
    VesselTree tree;
    DemoTreeOptions treeOptions;
    scene::Volume volume;     ///< Int16, HU, modality CT, unit HU
    glm::dmat3 frame{1.0};    ///< columns: row direction, column direction, normal
    glm::dvec3 boneMin{0.0};  ///< the bone block in frame coordinates (u, v, w), mm
    glm::dvec3 boneMax{0.0};
    /// True when world point `p` lies in the bone block grown by `margin` mm.
    [[nodiscard]] bool inBone(const glm::dvec3& p, double margin) const;
};

/// The demo tree (root radius 3 mm) voxelised into a CT-like volume whose
/// grid covers the tree and the bone block with a 4 mm margin. Deterministic
/// for the same options. Reports progress ("Voxelising the demo tree");
/// throws InvalidArgumentError for out-of-range options, CancelledError.
[[nodiscard]] DemoCt generateDemoCt(const DemoCtOptions& options = {},
                                    const Progress& progress = {});

}  // namespace vv::demo
