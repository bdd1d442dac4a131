// SPDX-License-Identifier: GPL-3.0-or-later
// The Measurements section's figures (issue 35), painted with QPainter at the
// report's 300 dpi: the diameter profile along the path, the stretched curved
// reformation, the cross-section at each landmark. Private to vv::report.
#pragma once

#include <QColor>
#include <vector>

#include "PdfFlow.h"
#include "vv/report/PdfReport.h"

namespace vv::report::figures {

/// The profile's series colours in order (equivalent, minimum, maximum):
/// colormaps::diameterColors(), as the GUI draws them.
[[nodiscard]] const std::vector<QColor>& seriesColours();
/// The contour's colour in a section figure, and the calipers' (minimum,
/// maximum: the series' colours).
inline const QColor kContour(230, 170, 0);

/// The profile chart at the cursor, full width, with its title and note,
/// kept on one page.
void profileFigure(pdf::Flow& flow, const ProfileFigure& figure);

/// The reformation at the cursor, full width, its height true to the
/// distances (within 18 to 60 mm: the caption says when it is stretched).
void reformationFigure(pdf::Flow& flow, const ReformationFigure& figure);

/// The cross-sections, three to a row, each square with its title above and
/// its caption below.
void sectionFigures(pdf::Flow& flow, const std::vector<SectionFigure>& figures);

}  // namespace vv::report::figures
