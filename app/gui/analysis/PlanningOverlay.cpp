// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/analysis/PlanningOverlay.h"

#include <QPainter>
#include <QPainterPath>
#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <limits>

#include "gui/ViewerWidget.h"
#include "gui/analysis/PlanningState.h"
#include "gui/panels/PanelUtil.h"
#include "vv/colormaps/ColorMap.h"
#include "vv/colormaps/LabelPalette.h"
#include "vv/planning/VesselPath.h"
#include "vv/render/CenterlineOverlay.h"
#include "vv/render/LegendPainter.h"

namespace vv::gui {

namespace {

const QColor kHalo(0, 0, 0, 190);
const QColor kLine(255, 255, 255, 200);
const QColor kPath(255, 214, 0);
const QColor kCursor(255, 60, 60);
/// The diameter colouring's map: not the vessels' usual ones (Viridis, the
/// CVD-safe Cividis), so that the two legends cannot be read for each other.
constexpr colormaps::ColorMap kDiameterMap = colormaps::ColorMap::Inferno;

void haloText(QPainter& painter, const QPointF& at, const QString& text) {
    QPainterPath path;
    QFont font = painter.font();
    font.setBold(true);
    path.addText(at, font, text);
    painter.setPen(QPen(kHalo, 3.0));
    painter.setBrush(Qt::NoBrush);
    painter.drawPath(path);
    painter.fillPath(path, Qt::white);
}

}  // namespace

PlanningOverlay::PlanningOverlay(ViewerWidget* viewer, PlanningState* state)
    : FollowingOverlay(viewer, QStringLiteral("planningOverlay")),
      state_(state),
      hoverMm_(std::numeric_limits<double>::quiet_NaN()) {
    connect(viewer, &ViewerWidget::frameRendered, this, [this] {
        if (isVisible()) {
            update();
        }
    });
    for (const auto signal : {&PlanningState::analysisChanged, &PlanningState::pathChanged,
                              &PlanningState::landmarksChanged}) {
        connect(state_, signal, this, &PlanningOverlay::follow);
    }
    connect(state_, &PlanningState::cursorMoved, this, [this] { update(); });
    connect(state_, &PlanningState::landmarkSelected, this, [this] { update(); });
    follow();
}

void PlanningOverlay::setColouring(Colouring colouring) {
    colouring_ = colouring;
    update();
}

std::pair<float, float> PlanningOverlay::diameterRange() const {
    float lo = std::numeric_limits<float>::max();
    float hi = 0.0F;
    if (state_->hasAnalysis()) {
        for (const auto& branch : state_->analysis()->tree.branches) {
            for (const auto& p : branch.points) {
                lo = std::min(lo, static_cast<float>(2.0 * p.radiusMm));
                hi = std::max(hi, static_cast<float>(2.0 * p.radiusMm));
            }
        }
    }
    return lo <= hi ? std::pair{lo, hi} : std::pair{0.0F, 1.0F};
}

void PlanningOverlay::follow() {
    setVisible(state_->hasAnalysis());
    raise();
    update();
}

void PlanningOverlay::setHoverMm(double pathMm) {
    if (std::isnan(pathMm) && std::isnan(hoverMm_)) {
        return;
    }
    hoverMm_ = pathMm;
    update();
}

std::optional<QPointF> PlanningOverlay::project(const glm::dvec3& world) const {
    return FollowingOverlay::project(glm::vec3(world));
}

void PlanningOverlay::paintEvent(QPaintEvent* event) {
    Q_UNUSED(event);
    if (!state_->hasAnalysis()) {
        return;
    }
    const auto& tree = state_->analysis()->tree;
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    const auto polyline = [this](const std::vector<glm::dvec3>& points) {
        QPainterPath path;
        bool open = false;
        for (const glm::dvec3& p : points) {
            const auto at = project(p);
            if (!at) {
                open = false;
                continue;
            }
            if (open) {
                path.lineTo(*at);
            } else {
                path.moveTo(*at);
                open = true;
            }
        }
        return path;
    };
    // The chosen path: a wide dark band under the lines, and in the Path
    // colouring a yellow core over them.
    QPainterPath chosen;
    if (!state_->profile().empty()) {
        std::vector<glm::dvec3> points;
        for (const planning::PathPoint& p : state_->path().points(tree)) {
            points.push_back(
                tree.branches[static_cast<std::size_t>(p.branch)].points[p.pointIndex].position);
        }
        chosen = polyline(points);
        painter.setBrush(Qt::NoBrush);
        painter.setPen(QPen(kHalo, 5.0, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
        painter.drawPath(chosen);
    }
    // Every centreline, thin: white, or per branch, or by diameter per segment.
    painter.setBrush(Qt::NoBrush);
    // The diameters' range: only the diameter colouring needs it (every paint).
    const auto [lo, hi] =
        colouring_ == Colouring::Diameter ? diameterRange() : std::pair{0.0F, 1.0F};
    for (const auto& branch : tree.branches) {
        std::vector<glm::dvec3> points;
        for (const auto& p : branch.points) {
            points.push_back(p.position);
        }
        const QPainterPath line = polyline(points);
        painter.setPen(QPen(kHalo, 3.0, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
        painter.drawPath(line);
        if (colouring_ == Colouring::Diameter) {
            for (std::size_t i = 1; i < branch.points.size(); ++i) {
                const auto a = project(branch.points[i - 1].position);
                const auto b = project(branch.points[i].position);
                if (!a || !b) {
                    continue;
                }
                const double d = branch.points[i - 1].radiusMm + branch.points[i].radiusMm;
                const float t = hi > lo ? (static_cast<float>(d) - lo) / (hi - lo) : 0.5F;
                painter.setPen(QPen(panels::toQColor(colormaps::sample(kDiameterMap, t)), 1.6,
                                    Qt::SolidLine, Qt::RoundCap));
                painter.drawLine(*a, *b);
            }
            continue;
        }
        const QColor colour =
            colouring_ == Colouring::Branch
                ? panels::toQColor(colormaps::labelColor(static_cast<std::size_t>(branch.id)))
                : kLine;
        painter.setPen(QPen(colour, colouring_ == Colouring::Branch ? 1.8 : 1.2, Qt::SolidLine,
                            Qt::RoundCap, Qt::RoundJoin));
        painter.drawPath(line);
    }
    if (colouring_ == Colouring::Path && !chosen.isEmpty()) {
        painter.setPen(QPen(kPath, 2.5, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
        painter.drawPath(chosen);
    }
    if (colouring_ == Colouring::Diameter) {
        // The colours' legend, above the viewer's own parameter legend.
        render::Legends legends;
        render::ParameterLegend legend;
        legend.name = "inscribed diameter";
        legend.unit = "mm";
        legend.title = render::centerlineLegendTitle();
        legend.min = lo;
        legend.max = hi;
        legend.map = kDiameterMap;
        legends.parameter = legend;
        render::paintLegends(painter, QRectF(0.0, 0.0, width(), height() - 90.0), legends);
    }
    // Landmarks.
    const auto& landmarks = state_->landmarks();
    for (std::size_t i = 0; i < landmarks.size(); ++i) {
        const auto at = project(planning::sampleAt(tree, landmarks[i].location).position);
        if (!at) {
            continue;
        }
        const bool selected = static_cast<int>(i) == state_->selectedLandmark();
        painter.setPen(QPen(kHalo, 2.0));
        painter.setBrush(selected ? kPath : QColor(Qt::white));
        painter.drawEllipse(*at, selected ? 6.0 : 4.5, selected ? 6.0 : 4.5);
        haloText(painter, *at + QPointF(9.0, -6.0), PlanningState::landmarkLabel(landmarks[i]));
    }
    // The cursor and the hover mark: rings the size of the vessel there.
    const auto ring = [&](double pathMm, const QColor& colour, bool filled) {
        const planning::TreeLocation at = state_->path().locationAt(pathMm);
        const planning::CenterlineSample sample = planning::sampleAt(tree, at);
        const auto centre = project(sample.position);
        if (!centre) {
            return;
        }
        // The inscribed radius on screen: project a point one radius off the
        // axis, across the view.
        const render::Camera& camera = viewer()->camera();
        const glm::vec3 right = glm::vec3(glm::inverse(camera.viewMatrix())[0]);
        const auto edge = project(sample.position + glm::dvec3(right) * sample.radiusMm);
        const double r = std::max(
            5.0, edge ? std::hypot(edge->x() - centre->x(), edge->y() - centre->y()) : 5.0);
        painter.setBrush(Qt::NoBrush);
        painter.setPen(QPen(kHalo, 4.5));
        painter.drawEllipse(*centre, r, r);
        painter.setPen(QPen(colour, filled ? 2.5 : 1.5, filled ? Qt::SolidLine : Qt::DashLine));
        painter.drawEllipse(*centre, r, r);
    };
    if (!state_->profile().empty()) {
        if (std::isfinite(hoverMm_)) {
            ring(hoverMm_, Qt::white, false);
        }
        ring(state_->cursorMm(), kCursor, true);
    }
}

}  // namespace vv::gui
