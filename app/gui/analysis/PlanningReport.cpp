// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/analysis/PlanningReport.h"

#include "common/MeasurementFile.h"
#include "common/MeasurementSection.h"
#include "gui/analysis/CrossSectionView.h"
#include "gui/analysis/CurvedReformation.h"
#include "gui/analysis/PlanningState.h"

namespace vv::gui {

PlanningReport planningReport(const PlanningState& state, const CurvedReformation& reformation,
                              const CrossSectionView& crossSection) {
    const app::ReportMeasurements m = app::measurementsOf(state.measurementInput());
    PlanningReport out{app::measurementSection(m), app::measurementGroups(m)};
    if (crossSection.volume() != nullptr) {
        // As the command line's report takes them from the file: the
        // reformation turned as on screen, the slice views' window.
        app::addVolumePictures(out.section, m, *crossSection.volume(), crossSection.window(),
                               reformation.rotation());
    }
    return out;
}

}  // namespace vv::gui
