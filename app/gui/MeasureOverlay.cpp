// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/MeasureOverlay.h"

#include <QEvent>
#include <QLocale>
#include <QPainter>
#include <QPainterPath>
#include <glm/glm.hpp>

namespace vv::gui {

MeasureOverlay::MeasureOverlay(ViewerWidget* viewer) : QWidget(viewer), viewer_(viewer) {
    setObjectName(QStringLiteral("measureOverlay"));
    setAttribute(Qt::WA_TransparentForMouseEvents);
    setAttribute(Qt::WA_NoSystemBackground);
    setAttribute(Qt::WA_TranslucentBackground);
    setFocusPolicy(Qt::NoFocus);
    setGeometry(viewer->rect());
    viewer->installEventFilter(this);
    connect(viewer, &ViewerWidget::frameRendered, this, [this] {
        if (!points_.isEmpty()) {
            update();
        }
    });
    hide();
}

QString MeasureOverlay::pointLabel(qsizetype index) {
    return QLocale().toString(index + 1);
}

void MeasureOverlay::setPoints(const QList<ProbeResult>& points) {
    points_ = points.mid(0, 2);
    setVisible(!points_.isEmpty());
    raise();
    update();
}

std::optional<QPointF> MeasureOverlay::project(const ProbeResult& point) const {
    const render::Camera& camera = viewer_->camera();
    const glm::vec4 clip =
        camera.projectionMatrix() * camera.viewMatrix() * glm::vec4(point.worldPosition, 1.0F);
    if (clip.w <= 0.0F) {
        return std::nullopt;
    }
    const float x = clip.x / clip.w;
    const float y = clip.y / clip.w;
    return QPointF((static_cast<double>(x) + 1.0) * 0.5 * viewer_->width(),
                   (1.0 - static_cast<double>(y)) * 0.5 * viewer_->height());
}

void MeasureOverlay::paintEvent(QPaintEvent* event) {
    Q_UNUSED(event);
    if (points_.isEmpty()) {
        return;
    }
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    QList<QPointF> screen;
    for (const ProbeResult& p : points_) {
        if (const auto at = project(p)) {
            screen << *at;
        }
    }
    const QColor ink(255, 255, 255);
    const QColor halo(0, 0, 0, 200);
    if (screen.size() == 2) {
        for (const auto& [color, width] : {std::pair{halo, 4.0}, std::pair{ink, 2.0}}) {
            painter.setPen(QPen(color, width, Qt::DashLine, Qt::RoundCap));
            painter.drawLine(screen[0], screen[1]);
        }
        const Measurement m = measure(points_[0], points_[1], viewer_->camera());
        const QString text =
            tr("%1 mm").arg(QLocale().toString(static_cast<double>(m.distance), 'f', 1));
        QPainterPath path;
        QFont font = painter.font();
        font.setBold(true);
        path.addText((screen[0] + screen[1]) / 2.0 + QPointF(8.0, -8.0), font, text);
        painter.setPen(QPen(halo, 3.0));
        painter.setBrush(Qt::NoBrush);
        painter.drawPath(path);
        painter.fillPath(path, ink);
    }
    for (qsizetype i = 0; i < screen.size(); ++i) {
        painter.setPen(QPen(halo, 2.0));
        painter.setBrush(ink);
        painter.drawEllipse(screen[i], 5.0, 5.0);
        QPainterPath label;
        QFont font = painter.font();
        font.setBold(true);
        label.addText(screen[i] + QPointF(8.0, 16.0), font, pointLabel(i));
        painter.setPen(QPen(halo, 3.0));
        painter.setBrush(Qt::NoBrush);
        painter.drawPath(label);
        painter.fillPath(label, ink);
    }
}

bool MeasureOverlay::eventFilter(QObject* watched, QEvent* event) {
    if (watched == viewer_ && event->type() == QEvent::Resize) {
        setGeometry(viewer_->rect());
    }
    return QWidget::eventFilter(watched, event);
}

}  // namespace vv::gui
