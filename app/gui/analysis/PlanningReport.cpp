// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/analysis/PlanningReport.h"

#include <QCoreApplication>
#include <QLocale>

#include "common/MeasurementFile.h"
#include "common/MeasurementSection.h"
#include "gui/analysis/CrossSectionView.h"
#include "gui/analysis/CurvedReformation.h"
#include "gui/analysis/PlanningState.h"
#include "vv/slices/WindowLevel.h"

namespace vv::gui {

PlanningReport planningReport(const PlanningState& state, const CurvedReformation& reformation,
                              const CrossSectionView& crossSection) {
    const app::ReportMeasurements m = app::measurementsOf(state.measurementInput());
    PlanningReport out{app::measurementSection(m), app::measurementGroups(m)};
    const auto& a = *state.analysis();
    if (!reformation.values().empty()) {
        report::ReformationFigure figure;
        const auto& values = reformation.values();
        const Image<std::uint8_t> gray = slices::applyWindow(values.view(), reformation.window());
        figure.image = QImage(gray.width(), gray.height(), QImage::Format_Grayscale8);
        for (int y = 0; y < gray.height(); ++y) {
            std::copy_n(gray.row(y), gray.width(), figure.image.scanLine(y));
        }
        figure.lengthMm = state.path().lengthMm();
        figure.halfWidthMm = reformation.halfWidthMm();
        for (const planning::Landmark& l : state.landmarks()) {
            if (const auto along = state.pathMmOf(l.location)) {
                figure.landmarks.push_back({*along, PlanningState::landmarkLabel(l).toStdString()});
            }
        }
        figure.caption =
            QCoreApplication::translate(
                "vv::gui::PlanningReport",
                "Curved reformation along the path (stretched: the path straight, distances "
                "true along it), turned %1° about the path; window width %2, level %3.")
                .arg(QLocale().toString(reformation.rotation()))
                .arg(QLocale().toString(reformation.window().width, 'f', 0))
                .arg(QLocale().toString(reformation.window().center, 'f', 0))
                .toStdString();
        out.section.reformation = std::move(figure);
    }
    if (crossSection.volume() != nullptr) {
        // The figures follow the landmarks with a section contour, in order.
        std::size_t next = 0;
        for (std::size_t i = 0; i < m.landmarks.size() && next < out.section.sections.size(); ++i) {
            const app::MeasuredLandmark& l = m.landmarks[i];
            if (!l.section || l.contour.size() < 3) {
                continue;
            }
            const auto& at = l.section->location;
            const auto& points = a.tree.branches[static_cast<std::size_t>(at.branch)].points;
            std::size_t nearest = 0;
            for (std::size_t p = 0; p < points.size(); ++p) {
                if (std::abs(points[p].abscissaMm - at.abscissaMm) <
                    std::abs(points[nearest].abscissaMm - at.abscissaMm)) {
                    nearest = p;
                }
            }
            report::SectionFigure& figure = out.section.sections[next++];
            figure.image = CrossSectionView::resliceImage(
                *crossSection.volume(), a.sections[static_cast<std::size_t>(at.branch)][nearest],
                figure.fieldMm, crossSection.window());
        }
    }
    return out;
}

}  // namespace vv::gui
