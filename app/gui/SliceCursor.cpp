// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/SliceCursor.h"

#include <QEvent>
#include <QMouseEvent>
#include <QPainter>

#include "gui/ViewerWidget.h"

namespace vv::gui {

namespace {

constexpr int kClickSlop = 4;  // px a click may move

// The cursor's marker over the 3-D view: a ring with a cross, not part of
// the GL frame (exports stay the frame alone).
class CursorMarker : public QWidget {
  public:
    CursorMarker(ViewerWidget* viewer, const SliceCursor* cursor)
        : QWidget(viewer), cursor_(cursor) {
        setObjectName(QStringLiteral("sliceCursorMarker"));
        setAttribute(Qt::WA_TransparentForMouseEvents);
        setAttribute(Qt::WA_NoSystemBackground);
        setAttribute(Qt::WA_TranslucentBackground);
        setFocusPolicy(Qt::NoFocus);
        hide();
    }

  protected:
    void paintEvent(QPaintEvent* /*event*/) override {
        const auto at = cursor_->markerPosition();
        if (!at) {
            return;
        }
        QPainter painter(this);
        painter.setRenderHint(QPainter::Antialiasing);
        for (const auto& [colour, width] :
             {std::pair{QColor(0, 0, 0, 200), 4.0}, std::pair{QColor(120, 255, 120), 2.0}}) {
            painter.setPen(QPen(colour, width));
            painter.drawEllipse(*at, 7.0, 7.0);
            painter.drawLine(*at - QPointF(13, 0), *at - QPointF(4, 0));
            painter.drawLine(*at + QPointF(4, 0), *at + QPointF(13, 0));
            painter.drawLine(*at - QPointF(0, 13), *at - QPointF(0, 4));
            painter.drawLine(*at + QPointF(0, 4), *at + QPointF(0, 13));
        }
    }

  private:
    const SliceCursor* cursor_;
};

}  // namespace

SliceCursor::SliceCursor(ViewerWidget* viewer, QObject* parent) : QObject(parent), viewer_(viewer) {
    if (viewer_ == nullptr) {
        return;
    }
    marker_ = new CursorMarker(viewer_, this);
    viewer_->installEventFilter(this);
    connect(viewer_, &ViewerWidget::frameRendered, marker_, [this] {
        if (point_) {
            marker_->update();
        }
    });
}

void SliceCursor::setPoint(const std::optional<glm::dvec3>& world) {
    point_ = world;
    if (marker_ != nullptr) {
        marker_->setGeometry(viewer_->rect());
        marker_->setVisible(point_.has_value());
        marker_->raise();
        marker_->update();
    }
    emit pointChanged(point_);
}

void SliceCursor::setActive(bool active) {
    active_ = active;
    if (!active_ && point_) {
        setPoint(std::nullopt);
    }
}

std::optional<QPointF> SliceCursor::markerPosition() const {
    if (!point_ || viewer_ == nullptr) {
        return std::nullopt;
    }
    const render::Camera& camera = viewer_->camera();
    const glm::vec4 clip =
        camera.projectionMatrix() * camera.viewMatrix() * glm::vec4(glm::vec3(*point_), 1.0F);
    if (clip.w <= 0.0F) {
        return std::nullopt;
    }
    return QPointF((static_cast<double>(clip.x / clip.w) + 1.0) * 0.5 * viewer_->width(),
                   (1.0 - static_cast<double>(clip.y / clip.w)) * 0.5 * viewer_->height());
}

bool SliceCursor::eventFilter(QObject* watched, QEvent* event) {
    if (watched == viewer_) {
        const auto* mouse = dynamic_cast<const QMouseEvent*>(event);
        if (event->type() == QEvent::Resize && marker_ != nullptr) {
            marker_->setGeometry(viewer_->rect());
        } else if (!active_) {
            return QObject::eventFilter(watched, event);
        } else if (mouse != nullptr && event->type() == QEvent::MouseButtonPress) {
            pressed_ = mouse->button() == Qt::LeftButton;
            pressAt_ = mouse->position();
        } else if (mouse != nullptr && event->type() == QEvent::MouseButtonRelease && pressed_) {
            pressed_ = false;
            if (mouse->button() == Qt::LeftButton &&
                (mouse->position() - pressAt_).manhattanLength() < kClickSlop) {
                if (const auto hit = viewer_->probeAt(mouse->position())) {
                    setPoint(glm::dvec3(hit->worldPosition));
                }
            }
        }
    }
    return QObject::eventFilter(watched, event);
}

}  // namespace vv::gui
