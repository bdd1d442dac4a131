// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// An abdominal angiography phantom for measuring segmentation against an
// analytic truth: an aorta running head to foot through the whole volume
// (curved, radius 10 mm), two renal arteries (3 mm) and two iliac arteries
// (6 mm); a body (elliptic cylinder) with a subcutaneous fat layer and a
// spine beside the aorta, air around it. CT or contrast-enhanced MR
// intensities, every edge with partial volume, MR with an optional smooth
// receive gain (a surface coil's sensitivity falling off towards the head)
// and Rician noise, CT with Gaussian noise. Used by the segmentation tests
// and bench/segmentation_accuracy (docs/benchmarks/dicom.md).

#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "vv/core/Progress.h"
#include "vv/scene/Volume.h"

namespace vv::demo {

enum class PhantomModality : std::uint8_t {
    CT,  ///< HU: air -1000, fat -100, tissue 40, lumen 400, spine 1100; Gaussian noise
    MR,  ///< fat-suppressed contrast-enhanced MRA: air 0, fat 70, tissue 100, spine 80, lumen 600
};

struct VesselPhantomOptions {
    PhantomModality modality = PhantomModality::MR;
    glm::ivec3 dims{112, 96, 120};  ///< voxels (left-right, anterior-posterior, slices); 8..2048
    /// The grid's extent, mm: left-right, anterior-posterior, foot-head.
    glm::dvec3 fieldOfViewMm{280.0, 240.0, 300.0};
    /// MR only: the receive gain's lowest value over the volume, in (0, 1];
    /// the gain spans [minGain, 1] (1 = no gain). The field is that of a
    /// receive array covering the body up to 80 mm above the volume's centre
    /// and fading beyond it (a logistic fall-off over ~25 mm), seeing more
    /// near the body's front and back (surface coils), scaled to that span:
    /// the aorta's upper ~4 cm lie where the signal fades.
    double minGain = 1.0;
    /// Noise standard deviation; negative: the modality's default (CT 15 HU,
    /// MR 8, i.e. tissue at 12.5 times the noise where the gain is 1).
    double noiseSigma = -1.0;
    std::uint32_t noiseSeed = 20241118U;
};

/// One vessel of the truth: a polyline centre line (mm, LPS) and a radius.
struct PhantomVessel {
    std::string name;
    std::vector<glm::dvec3> centerline;
    double radiusMm = 0.0;
};

struct VesselPhantom {
    VesselPhantomOptions options;
    /// Int16: HU (modality CT, unit HU) or MR signal (modality MR, no unit).
    /// Axial slices, LPS: columns run to the patient's left, rows to
    /// posterior, slices from foot to head; origin centred on the body.
    scene::Volume volume;
    /// [0] is the aorta; it leaves the volume at its head and foot ends.
    std::vector<PhantomVessel> vessels;
    /// Per voxel (as Volume::index()): 1 where its centre lies inside a vessel.
    std::vector<std::uint8_t> truth;

    /// Signed distance from `world` (mm) to the vessels' surface, negative
    /// inside: min over the vessels of (distance to the centre line - radius).
    /// Exact outside the vessels; inside, the depth in the deepest vessel.
    [[nodiscard]] double signedDistance(const glm::dvec3& world) const;
    /// The receive gain at `world` (MR; 1 for CT or minGain = 1).
    [[nodiscard]] double gain(const glm::dvec3& world) const;

    double gainLow = 0.0;  ///< the coil sensitivity's extremes over the grid (normalisation)
    double gainHigh = 1.0;
};

/// Builds the phantom. Deterministic for the same options (the noise of each
/// slice comes from its own seeded generator, so threads do not change it).
/// Reports progress ("Building the vessel phantom"); throws
/// InvalidArgumentError for options out of range, CancelledError.
[[nodiscard]] VesselPhantom generateVesselPhantom(const VesselPhantomOptions& options = {},
                                                  const Progress& progress = {});

}  // namespace vv::demo
