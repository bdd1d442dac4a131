// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// A segmentation as a person reads it, in the UI (or report) language: the
// cut-off warning the Segmentation panel and the report show, and the
// report's "Segmentation" section. Numbers in the default QLocale.

#include <QString>
#include <vector>

#include "common/SegmentationProvenance.h"
#include "vv/report/PdfReport.h"
#include "vv/segmentation/CutOffVessels.h"

namespace vv::app {

/// "The vessel may be cut off: a bright tube continues 42 mm towards the head
/// past the segmentation's end at LPS (6, 22, 108) mm, where the signal may
/// fade." for the longest of `vessels`, then "2 more such ends." when there
/// are more; empty when there are none.
[[nodiscard]] QString cutOffText(const std::vector<segmentation::CutOffVessel>& vessels);

/// The rule a threshold range came from, e.g. "CT angiography default",
/// "chosen in the Segmentation panel", "given with --threshold" (the
/// rule's text as it is when it is none of the known ones).
[[nodiscard]] QString thresholdRuleName(const segmentation::ThresholdRange& range);

/// The report's "Segmentation" section for a segmented image series: the
/// threshold and its rule, the intensity correction (not for CT), the
/// components kept, bone removal, and the cut-off warning (cutOffText()).
/// The same settings as settingsDescription() (what a DICOM SEG says).
[[nodiscard]] report::ReportSegmentation reportSegmentation(
    const SegmentationProvenance& provenance);

}  // namespace vv::app
