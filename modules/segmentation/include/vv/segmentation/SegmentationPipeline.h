// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Segmenting a volume into a vessel surface in one call: the full-resolution
// pipeline and its fast preview on a downsampled copy (the GUI's
// Segmentation panel runs it on a worker thread).

#include <cstddef>
#include <glm/glm.hpp>
#include <memory>
#include <optional>
#include <vector>

#include "vv/core/Progress.h"
#include "vv/scene/Mesh.h"
#include "vv/scene/Volume.h"
#include "vv/segmentation/VolumeSegmentation.h"
#include "vv/segmentation/VolumeSurface.h"

namespace vv::segmentation {

/// Voxels a preview segments at most: with the surface, about 0.1 s on a
/// busy 2-core machine (a full 256 x 256 x 200 CTA took 0.35 s there).
inline constexpr std::size_t kPreviewVoxels = 2000000;

/// Every `step`-th voxel of `volume` along each axis: voxel (i, j, k) of the
/// result is voxel (step i, step j, step k) of `volume`; dims are
/// ceil(dims / step); indexToWorld is scaled by `step`, so world positions
/// stay where they were; voxel type, modality and unit are kept. step 1
/// copies. Throws InvalidArgumentError for step < 1 or an empty volume.
[[nodiscard]] scene::Volume downsampledVolume(const scene::Volume& volume, int step);

/// The step of a preview of a `dims` volume: the smallest step >= 2 that
/// leaves at most `voxelBudget` voxels, but 1 when every second voxel would
/// leave an axis with fewer than 8 voxels.
[[nodiscard]] int previewStep(glm::ivec3 dims, std::size_t voxelBudget = kPreviewVoxels) noexcept;

/// The voxel of `volume` with a value in [lower, upper] nearest to the
/// continuous voxel index `ijk`, among the voxels at most `radius` away along
/// each axis; nullopt when there is none (or `ijk` is not finite). With
/// `gain`, the values are the corrected ones (value / gain, as the intensity
/// correction thresholds them).
[[nodiscard]] std::optional<glm::ivec3> nearestVoxelInRange(const scene::Volume& volume,
                                                            const glm::dvec3& ijk, float lower,
                                                            float upper, int radius,
                                                            const GainField* gain = nullptr);

/// What to segment and how.
struct SegmentationRequest {
    std::shared_ptr<const scene::Volume> volume;
    /// The options in full-resolution voxels (seed, range). No range: the
    /// modality default of the full volume.
    SegmentationOptions segmentation;
    SurfaceOptions surface;
    /// 1: full resolution; n > 1: a preview of every n-th voxel per axis.
    int step = 1;
};

/// What a segmentation produced: one mesh "vessels" (or "vessels (preview)").
struct SegmentationOutcome {
    std::shared_ptr<const scene::Scene> scene;
    /// The label map the surface came from, on the segmented grid (the
    /// preview's coarse grid when step > 1): the slice views' overlay.
    std::shared_ptr<const scene::LabelMap> labelMap;
    ThresholdRange range;  ///< the range used
    std::size_t componentsFound = 0;
    std::size_t componentsKept = 0;
    std::size_t boneComponents = 0;
    bool intensityCorrected = false;  ///< the intensity correction ran
    double gainLowest = 1.0;          ///< its gain's extremes
    double gainHighest = 1.0;
    /// Bright tubes continuing past the segmentation (on the segmented grid).
    std::vector<CutOffVessel> cutOff;
    std::size_t triangles = 0;
    int step = 1;
    double milliseconds = 0.0;  ///< segmentation and surface, wall clock
};

/// Runs `request` on the calling thread: downsamples when step > 1, divides
/// the intensity correction's gain out when it applies (correctsIntensity();
/// the request's gain field, else one estimated from the downsampled or full
/// volume; no range: the default of the corrected values), moves a preview's
/// seed to the nearest in-range voxel of the coarse grid within one coarse
/// voxel, segments (segmentVessels) and extracts the surface
/// (extractSurface). Throws InvalidArgumentError (no volume, bad
/// options, a seed outside the range or, in a preview, on a structure too
/// thin for the coarse grid), FormatError (no voxel in range), CancelledError.
[[nodiscard]] SegmentationOutcome runSegmentation(const SegmentationRequest& request,
                                                  const Progress& progress = {});

}  // namespace vv::segmentation
