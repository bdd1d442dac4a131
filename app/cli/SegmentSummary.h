// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// What the commands that segment DICOM (render, report, segment) say about
// the segmentation: one summary line and the cut-off warnings.

#include <ostream>
#include <string>

#include "vv/scene/Mesh.h"
#include "vv/segmentation/CutOffVessels.h"
#include "vv/segmentation/SceneSource.h"

namespace vv::cli {

/// "segmented series UID (COLSxROWSxSLICES): RULE[, intensity correction on
/// (gain LO..HI)], kept K of N components, B bone-like removed, T triangles"
/// for a segmented series; "read N segment(s) from the DICOM SEG: 'a' 'b'"
/// for a SEG; empty otherwise.
[[nodiscard]] std::string segmentationSummary(const segmentation::SceneSourceReport& report,
                                              const scene::Scene& scene);

/// "warning: a bright tube continues 42 mm superior (radius about 9 mm) past
/// the segmentation's end at (6, 22, 108) mm (patient LPS): the vessel may be
/// cut off where its signal fades; ..." with advice: the intensity
/// correction when `suggestCorrection`, and a lower threshold.
[[nodiscard]] std::string cutOffWarning(const segmentation::CutOffVessel& vessel,
                                        bool suggestCorrection);

/// The summary on `out` (when there is one) and each cut-off warning on `err`
/// (suggesting the correction for an uncorrected series that is not CT).
void printSegmentationSummary(std::ostream& out, std::ostream& err,
                              const segmentation::SceneSourceReport& report,
                              const scene::Scene& scene);

/// Each cut-off warning of `report` on `err` (cutOffWarning(); the correction
/// suggested for an uncorrected series that is not CT).
void printCutOffWarnings(std::ostream& err, const segmentation::SceneSourceReport& report);

}  // namespace vv::cli
