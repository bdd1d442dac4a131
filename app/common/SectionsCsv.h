// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The section table as CSV (`centerline --sections` and the GUI's "Export
// sections"): one row per centreline section, units in the header, numbers in
// the C locale (a machine format: a spreadsheet imports it with "." as the
// decimal mark).

#include <cstddef>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "vv/analysis/Sections.h"

namespace vv::app {

/// One row: the section at point `pointIndex` of branch `branch`, and where
/// it lies along a path when the rows follow one.
struct SectionRow {
    int branch = 0;
    std::size_t pointIndex = 0;
    std::optional<double> pathMm;
};

/// Every section of every branch, branch by branch.
[[nodiscard]] std::vector<SectionRow> allSectionRows(const analysis::VesselAnalysis& analysis);

/// Writes `rows` of `analysis`'s sections to `file`, atomically. The
/// columns: path_mm (when any row has one), branch_id, branch_name (when
/// `names` names any branch), point, abscissa_mm, x/y/z_mm, area_mm2,
/// equivalent / min / max / inscribed diameter_mm, perimeter_mm,
/// circularity, status ("ok" or "no contour": its sizes are then empty),
/// end_zone. Throws IoError naming `file` when it cannot be written,
/// InvalidArgumentError for a row outside the analysis.
void writeSectionsCsv(const std::filesystem::path& file, const analysis::VesselAnalysis& analysis,
                      const std::vector<SectionRow>& rows,
                      const std::map<int, std::string>& names = {});

}  // namespace vv::app
