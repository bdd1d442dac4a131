// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// What File > Export Report and Send to PACS take of the planning work: the
// Measurements section (the measurement file's tables and figures, through
// its one writer and reader) with the pictures only the GUI has (the curved
// reformation, the resliced cross-sections), and the SR's groups.

#include <vector>

#include "vv/dicom/MeasurementReport.h"
#include "vv/report/PdfReport.h"

namespace vv::gui {

class CrossSectionView;
class CurvedReformation;
class PlanningState;

struct PlanningReport {
    report::ReportMeasurementSection section;
    std::vector<dicom::SrGroup> groups;
};

/// The planning work of `state` (which must hold an analysis) for a report:
/// the section app::measurementSection() words, with the reformation's
/// image when `reformation` shows one, and each landmark's cross-section
/// over the volume resliced there when `crossSection` has a volume (its
/// window). Throws as app::measurementsOf().
[[nodiscard]] PlanningReport planningReport(const PlanningState& state,
                                            const CurvedReformation& reformation,
                                            const CrossSectionView& crossSection);

}  // namespace vv::gui
