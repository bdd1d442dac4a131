// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// What made a segmentation of a DICOM series — the series and the settings —
// in one place, so that everything that records or sends it says the same:
// an exported surface's metadata (SurfaceExport.h), the DICOM SEG sent to a
// PACS and the PDF report (SegmentationText.h).

#include <cstddef>
#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <vector>

#include "vv/segmentation/CutOffVessels.h"
#include "vv/segmentation/SceneSource.h"
#include "vv/segmentation/SegmentationPipeline.h"
#include "vv/segmentation/VolumeSegmentation.h"

namespace vv::app {

/// Where a segmentation came from and how it was made.
struct SegmentationProvenance {
    std::string seriesInstanceUid;
    std::string seriesDescription;
    std::string modality;
    std::optional<int> seriesNumber;
    /// A DICOM SEG object's segments (label i + 1 = segmentNames[i]); empty
    /// for a segmented image series, whose settings follow.
    std::vector<std::string> segmentNames;
    std::string unit;                    ///< of the threshold ("HU", or empty)
    segmentation::ThresholdRange range;  ///< the range used and its rule
    bool intensityCorrected = false;
    double gainLowest = 1.0;  ///< the correction's gain extremes
    double gainHighest = 1.0;
    std::optional<glm::ivec3> seed;  ///< the component under it, else the largest
    int keepComponents = 1;
    std::size_t componentsKept = 0;
    std::size_t componentsFound = 0;
    bool boneRemoved = false;
    std::size_t targetTriangles = 0;  ///< 0: no decimation
    /// Bright tubes that continue past the segmentation (the vessel may be cut off).
    std::vector<segmentation::CutOffVessel> cutOff;
};

/// The provenance of a segmentation of a DICOM image series or SEG: `report`
/// says what the series is and what segmenting it found (as
/// loadSceneSource() reports it), `options` how it was segmented.
[[nodiscard]] SegmentationProvenance provenanceOf(const segmentation::SceneSourceReport& report,
                                                  const segmentation::SceneSourceOptions& options);

/// Sets the segmentation's part of `provenance` (range, correction, seed,
/// components, bone removal, triangle target, cut-off vessels) from a run of
/// `request` that gave `outcome` (the Segmentation panel's Apply); the
/// series stays.
void describeSegmentation(SegmentationProvenance& provenance,
                          const segmentation::SegmentationRequest& request,
                          const segmentation::SegmentationOutcome& outcome);

/// "200..700 HU": the threshold range with its unit (C locale numbers).
[[nodiscard]] std::string thresholdText(const SegmentationProvenance& provenance);
/// "on (MR signal fall-off divided out; gain 0.31..1.00)" or "off".
[[nodiscard]] std::string correctionText(const SegmentationProvenance& provenance);
/// "the 2 largest, 6-connected: kept 2 of 5" or "the one under voxel (i, j, k), ...".
[[nodiscard]] std::string componentsText(const SegmentationProvenance& provenance);
/// A SEG's segments: "1=Aorta; 2=Renal arteries".
[[nodiscard]] std::string segmentsText(const SegmentationProvenance& provenance);

/// The settings of a segmented image series in one English line (for DICOM
/// attributes and logs, not translated; C locale numbers): "threshold
/// 200..700 HU (CT angiography default 200..700 HU); intensity correction
/// off; components: the 1 largest, 6-connected: kept 1 of 3; bone removal
/// on". A SEG's: "segments: 1=Aorta; 2=...".
[[nodiscard]] std::string settingsDescription(const SegmentationProvenance& provenance);

}  // namespace vv::app
