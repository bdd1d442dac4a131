// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/FollowingOverlay.h"

#include <QEvent>
#include <glm/glm.hpp>

#include "gui/ViewerWidget.h"

namespace vv::gui {

FollowingOverlay::FollowingOverlay(ViewerWidget* viewer, const QString& objectName)
    : QWidget(viewer), viewer_(viewer) {
    setObjectName(objectName);
    setAttribute(Qt::WA_TransparentForMouseEvents);
    setAttribute(Qt::WA_NoSystemBackground);
    setAttribute(Qt::WA_TranslucentBackground);
    setFocusPolicy(Qt::NoFocus);
    setGeometry(viewer->rect());
    viewer->installEventFilter(this);
}

std::optional<QPointF> FollowingOverlay::project(const glm::vec3& world) const {
    const render::Camera& camera = viewer_->camera();
    const glm::vec4 clip = camera.projectionMatrix() * camera.viewMatrix() * glm::vec4(world, 1.0F);
    if (clip.w <= 0.0F) {
        return std::nullopt;
    }
    return QPointF((static_cast<double>(clip.x / clip.w) + 1.0) * 0.5 * viewer_->width(),
                   (1.0 - static_cast<double>(clip.y / clip.w)) * 0.5 * viewer_->height());
}

bool FollowingOverlay::eventFilter(QObject* watched, QEvent* event) {
    if (watched == viewer_ && event->type() == QEvent::Resize) {
        setGeometry(viewer_->rect());
    }
    return QWidget::eventFilter(watched, event);
}

}  // namespace vv::gui
