// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Does a bright tubular structure continue past the segmentation? A
// threshold cuts a vessel off where its signal fades (MR coil sensitivity,
// a late contrast bolus) without a word; this check finds such ends so the
// user can be told.
//
// Rule: the local level of the volume is the median of the unsegmented body
// voxels (air left out, see airThreshold()) in blocks of about 40 mm,
// interpolated trilinearly between block centres (a vessel fills too little
// of a block to move its median). The segmented voxels' contrast over their
// local level — v / level - 1 for MR and other signal intensities, which a
// receive gain scales, v - level for CT, whose HU are absolute — has a
// median; an unsegmented voxel "continues the vessel" when its own contrast
// reaches half of it (and its value is not above the range's upper bound,
// which keeps bone out in CT). Grown from the segmentation's surface through
// such voxels (6-connected), each connected piece remembers where it left
// the segmentation; a piece is a cut-off vessel when it reaches at least
// 10 mm (and 3 voxels) from there, its mean radius (volume / length) is at
// least one voxel and it is at least 2.5 times as long as that radius: a
// thick tube, not the partial-volume rim of a thin vessel nor a bright organ.

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "vv/core/Progress.h"
#include "vv/scene/LabelMap.h"
#include "vv/scene/Volume.h"

namespace vv::segmentation {

struct ThresholdRange;

/// A bright tube that continues past the segmentation.
struct CutOffVessel {
    glm::dvec3 end{0.0};     ///< where it leaves the segmentation (LPS mm, a segmented voxel)
    glm::dvec3 farEnd{0.0};  ///< its point farthest from `end` (LPS mm)
    double lengthMm = 0.0;   ///< |farEnd - end|
    double radiusMm = 0.0;   ///< mean radius: sqrt(volume / (pi length))
};

/// The patient direction (LPS) a vector points to most.
enum class PatientDirection : std::uint8_t { Left, Right, Posterior, Anterior, Superior, Inferior };

/// The direction of LPS vector `v`'s largest component (+x left, +y
/// posterior, +z superior); Superior for a zero vector.
[[nodiscard]] PatientDirection dominantDirection(const glm::dvec3& v) noexcept;

/// "left", "right", "posterior", "anterior", "superior", "inferior".
[[nodiscard]] const char* directionName(PatientDirection direction) noexcept;

struct CutOffOptions {
    double blockMm = 40.0;          ///< the local level's block size
    double relativeContrast = 0.5;  ///< share of the segmented vessels' contrast that continues
    double minimumLengthMm = 10.0;
    double minimumRadiusVoxels = 1.0;  ///< in voxel sizes (cube root of the voxel volume)
    double elongation = 2.5;           ///< length at least this many mean radii
    /// The growth stops (and nothing is reported) beyond max(this, 2 x the
    /// segmented voxels): the contrast does not single out vessels then.
    std::size_t maximumVoxels = 2000000;
};

/// The cut-off vessels of the segmentation `map` (labels != 0) of `volume`
/// (the values it was thresholded on) with `range`, longest first; empty
/// when none, when the map is empty or the segmented voxels are not brighter
/// than their surroundings. `map` must be on `volume`'s grid. Reports
/// progress ("Checking the segmentation's ends"); throws
/// InvalidArgumentError (the map does not match the volume), CancelledError.
[[nodiscard]] std::vector<CutOffVessel> findCutOffVessels(const scene::Volume& volume,
                                                          const scene::LabelMap& map,
                                                          const ThresholdRange& range,
                                                          const CutOffOptions& options = {},
                                                          const Progress& progress = {});

}  // namespace vv::segmentation
