// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/analysis/PlanningOverlay.h"

#include <QEvent>
#include <QPainter>
#include <QPainterPath>
#include <cmath>
#include <glm/glm.hpp>
#include <limits>

#include "gui/ViewerWidget.h"
#include "gui/analysis/PlanningState.h"
#include "vv/planning/VesselPath.h"

namespace vv::gui {

namespace {

const QColor kHalo(0, 0, 0, 190);
const QColor kLine(255, 255, 255, 200);
const QColor kPath(255, 214, 0);
const QColor kCursor(255, 60, 60);

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
    : QWidget(viewer),
      viewer_(viewer),
      state_(state),
      hoverMm_(std::numeric_limits<double>::quiet_NaN()) {
    setObjectName(QStringLiteral("planningOverlay"));
    setAttribute(Qt::WA_TransparentForMouseEvents);
    setAttribute(Qt::WA_NoSystemBackground);
    setAttribute(Qt::WA_TranslucentBackground);
    setFocusPolicy(Qt::NoFocus);
    setGeometry(viewer->rect());
    viewer->installEventFilter(this);
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
    const render::Camera& camera = viewer_->camera();
    const glm::vec4 clip =
        camera.projectionMatrix() * camera.viewMatrix() * glm::vec4(glm::vec3(world), 1.0F);
    if (clip.w <= 0.0F) {
        return std::nullopt;
    }
    return QPointF((static_cast<double>(clip.x / clip.w) + 1.0) * 0.5 * viewer_->width(),
                   (1.0 - static_cast<double>(clip.y / clip.w)) * 0.5 * viewer_->height());
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
    // Every centreline, thin.
    QPainterPath all;
    for (const auto& branch : tree.branches) {
        std::vector<glm::dvec3> points;
        for (const auto& p : branch.points) {
            points.push_back(p.position);
        }
        all.addPath(polyline(points));
    }
    painter.setBrush(Qt::NoBrush);
    painter.setPen(QPen(kHalo, 3.0, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
    painter.drawPath(all);
    painter.setPen(QPen(kLine, 1.2, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
    painter.drawPath(all);
    // The chosen path, wider.
    if (!state_->profile().empty()) {
        std::vector<glm::dvec3> points;
        for (const planning::PathPoint& p : state_->path().points(tree)) {
            points.push_back(
                tree.branches[static_cast<std::size_t>(p.branch)].points[p.pointIndex].position);
        }
        const QPainterPath path = polyline(points);
        painter.setPen(QPen(kHalo, 5.0, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
        painter.drawPath(path);
        painter.setPen(QPen(kPath, 2.5, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
        painter.drawPath(path);
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
        const render::Camera& camera = viewer_->camera();
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

bool PlanningOverlay::eventFilter(QObject* watched, QEvent* event) {
    if (watched == viewer_ && event->type() == QEvent::Resize) {
        setGeometry(viewer_->rect());
    }
    return QWidget::eventFilter(watched, event);
}

}  // namespace vv::gui
