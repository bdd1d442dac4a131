// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// A CT-angiography-like volume of the synthetic demo tree (lumen ~400 HU,
// tissue ~40 HU with Gaussian noise, a bone-like block ~1000 HU beside the
// tree, partial volume at every edge, on an oblique grid) and a writer that
// stores any HU volume as a CT image series (DCMTK, one file per slice).
// Used by `vesselview-cli demo --dicom DIR` and the round-trip tests.

#include <cstdint>
#include <filesystem>
#include <glm/glm.hpp>
#include <string>

#include "vv/core/Progress.h"
#include "vv/io/DemoTree.h"
#include "vv/io/Volume.h"

namespace vv::io {

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
    Volume volume;            ///< Int16, HU, modality CT, unit HU
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

struct CtSeriesWriteOptions {
    std::string seriesDescription = "synthetic CTA";
    std::string studyDescription = "VesselView demo";
    std::string patientName = "VesselView^Demo";  ///< synthetic; never logged
    std::string patientId = "VV-DEMO";
    /// Instance numbers run backwards (slice 0 = highest number), so that
    /// readers that sort by instance number instead of position go wrong.
    bool reverseInstanceNumbers = true;
};

/// Writes `volume` (values in HU) as a CT series into `folder` (created when
/// missing), one file "slice<k>.dcm" per slice, each written atomically:
/// CT Image Storage, explicit VR little endian, unsigned 16-bit stored values
/// with Rescale Slope 1 / Intercept -1024 (values clamped to -1024..64511),
/// new Study / Series / Frame of Reference / SOP Instance UIDs, Image
/// Orientation (Patient) from indexToWorld() columns 0 and 1, Image Position
/// (Patient) of slice k = origin + k × column 2, Pixel Spacing from the column
/// lengths, Slice Thickness and Spacing Between Slices = the step along the
/// normal. Returns the Series Instance UID. Reports progress ("Writing the
/// CT series"); throws IoError (naming the file), InvalidArgumentError for an
/// empty volume or a degenerate geometry, CancelledError (files already
/// written stay).
std::string writeCtSeries(const std::filesystem::path& folder, const Volume& volume,
                          const CtSeriesWriteOptions& options = {}, const Progress& progress = {});

}  // namespace vv::io
