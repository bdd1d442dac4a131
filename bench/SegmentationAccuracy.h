// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// How well a segmentation of the vessel phantom (vv/demo/VesselPhantom.h)
// matches its analytic truth: Dice of the voxels, symmetric surface
// distances, and how much of the aorta's centre line is missed. Used by
// bench/segmentation_accuracy (docs/benchmarks/dicom.md) and the tests.

#include <cstddef>

#include "vv/demo/VesselPhantom.h"
#include "vv/scene/LabelMap.h"
#include "vv/scene/Mesh.h"

namespace vv::bench {

struct SegmentationAccuracy {
    /// 2 |A and B| / (|A| + |B|) of the segmented voxels (labels != 0) and
    /// the truth voxels (centre inside a vessel).
    double dice = 0.0;
    /// Symmetric surface distance (mm): the extracted surface's vertices to
    /// the analytic surface (|signed distance|) and points on the analytic
    /// surface (every ~half voxel along each vessel, 32 around it; those
    /// inside another vessel left out) to the extracted surface (VTK cell
    /// locator), pooled; both without what lies within 1.5 voxels of the
    /// volume's faces, where the extracted surface is closed by a cap.
    double meanDistanceMm = 0.0;
    double p95DistanceMm = 0.0;
    /// Length (mm) of the aorta's centre line inside the volume (1.5 voxels
    /// off its faces) whose nearest voxel is not segmented.
    double aortaMissedMm = 0.0;
    double aortaLengthMm = 0.0;  ///< of the centre line inside the volume
};

/// Measures `labels` (on the phantom's grid) and `surface` (its extracted
/// surface, LPS mm) against `phantom`. Throws InvalidArgumentError when the
/// label map is not on the phantom's grid.
[[nodiscard]] SegmentationAccuracy measureSegmentation(const demo::VesselPhantom& phantom,
                                                       const scene::LabelMap& labels,
                                                       const scene::Mesh& surface);

}  // namespace vv::bench
