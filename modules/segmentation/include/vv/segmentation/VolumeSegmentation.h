// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Vessel segmentation of contrast-enhanced CT / MR angiography volumes:
// an optional intensity correction (MR), a threshold range, connected
// components, optional bone removal; the result is a label map on the
// volume's grid and the vessels the segmentation cut off.

#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "vv/core/Progress.h"
#include "vv/scene/LabelMap.h"
#include "vv/scene/Volume.h"
#include "vv/segmentation/CutOffVessels.h"
#include "vv/segmentation/IntensityCorrection.h"

namespace vv::segmentation {

/// Which neighbours join voxels into one component.
enum class Connectivity : std::uint8_t {
    Face6,   ///< voxels sharing a face (the default: thin touching vessels stay apart)
    Full26,  ///< voxels sharing a face, an edge or a corner
};

/// A closed value range [lower, upper] and the rule it came from.
struct ThresholdRange {
    float lower = 0.0F;
    float upper = 0.0F;
    std::string rule;  ///< e.g. "CT angiography default 200..700 HU"
};

/// Default vessel threshold range for `volume`:
/// - CT (modality "CT", or unit "HU"): 200..700 HU, the usual window of
///   contrast-filled lumen in CT angiography (tissue ~40 HU, bone > 700 HU).
/// - Otherwise (MR and unknown modalities), from the histogram (4096 bins over
///   the value range) with Otsu's method: t1 = the Otsu threshold of all
///   voxels. When at most 10 % of the voxels lie above t1, that bright class
///   is taken to be the vessels (a volume cropped to the body) and the range
///   is t1..max; otherwise the bright class is the body (t1 split air from
///   tissue) and the lower bound is the Otsu threshold of the voxels above
///   t1 (tissue versus bright blood). The upper bound is the maximum.
/// Throws InvalidArgumentError for an empty volume.
[[nodiscard]] ThresholdRange defaultThresholdRange(const scene::Volume& volume);

/// Whether segmentVessels() corrects the intensity fall-off of `volume` by
/// default: for MR (modality "MR"), not otherwise.
[[nodiscard]] bool intensityCorrectionDefault(const scene::Volume& volume) noexcept;

struct SegmentationOptions {
    /// Threshold range; nullopt: defaultThresholdRange() of the values
    /// thresholded (the corrected ones with the intensity correction).
    /// lower <= upper.
    std::optional<ThresholdRange> range;
    /// Divide a slow multiplicative intensity fall-off out before
    /// thresholding (IntensityCorrection.h): range, default range and seed
    /// then apply to the corrected values. nullopt:
    /// intensityCorrectionDefault() (MR). Refused for CT (HU have no gain).
    std::optional<bool> correctIntensity;
    /// The gain to divide out; null: estimateGainField() of the volume.
    std::shared_ptr<const GainField> gainField;
    /// Keep this many of the largest components (1..255); ignored with a seed.
    int keepComponents = 1;
    /// Keep only the component under this voxel (i, j, k) instead.
    std::optional<glm::ivec3> seed;
    Connectivity connectivity = Connectivity::Face6;
    /// Bone removal; nullopt: on for CT, off otherwise (bone is dark in MR).
    /// Rule: the voxels >= range.lower ("bright": lumen, bone, the partial
    /// volume rim between them) are split into components (same
    /// connectivity); a bright component in which more than `boneFraction` of
    /// the voxels reach `boneThreshold` is bone-like and every voxel of it is
    /// dropped before the vessel components are formed. A vessel that touches
    /// bone joins its component and is dropped with it.
    std::optional<bool> removeBone;
    float boneThreshold = 1000.0F;  ///< HU
    double boneFraction = 0.2;      ///< in (0, 1]
};

/// Whether segmentVessels() corrects `volume`'s intensities with `options`:
/// options.correctIntensity, else intensityCorrectionDefault(). Throws
/// InvalidArgumentError when asked for a CT (HU have no receive gain).
[[nodiscard]] bool correctsIntensity(const scene::Volume& volume,
                                     const SegmentationOptions& options);

struct Segmentation {
    scene::LabelMap labelMap;
    ThresholdRange range;             ///< the range used
    bool boneRemoved = false;         ///< bone removal ran
    std::size_t boneComponents = 0;   ///< bright components dropped as bone
    std::size_t componentsFound = 0;  ///< vessel components before keeping N
    bool intensityCorrected = false;  ///< the intensity correction ran
    /// Its gain's extremes (1, 1 without the correction).
    double gainLowest = 1.0;
    double gainHighest = 1.0;
    /// Bright tubes that continue past the segmentation (findCutOffVessels()).
    std::vector<CutOffVessel> cutOff;
};

/// Segments vessels in `volume`: with the intensity correction, divides the
/// gain out first (estimateGainField(), correctedVolume()); then voxels
/// within the threshold range, bone-like components removed (see
/// SegmentationOptions::removeBone), then the `keepComponents` largest
/// connected components, or the one under `seed`; last, findCutOffVessels()
/// on the values thresholded. Without the correction the label map does not
/// depend on the correction code at all.
/// Memory: the label map plus, while labelling, 5 bytes per voxel (mask and
/// component ids) and the flood fill's stack (at most 8 bytes per voxel of
/// the largest component); the correction 4 bytes per voxel more, the check
/// 1 bit per voxel and 16 bytes per voxel it grows.
/// Reports progress ("Segmenting"); throws InvalidArgumentError (empty volume,
/// lower > upper or non-finite bounds, keepComponents outside 1..255, seed
/// outside the volume or not within the range, boneFraction outside (0, 1],
/// the intensity correction asked for a CT), FormatError when no voxel is in
/// the range, CancelledError.
[[nodiscard]] Segmentation segmentVessels(const scene::Volume& volume,
                                          const SegmentationOptions& options = {},
                                          const Progress& progress = {});

}  // namespace vv::segmentation
