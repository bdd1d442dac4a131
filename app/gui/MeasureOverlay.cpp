// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/MeasureOverlay.h"

#include <QLocale>
#include <QPainter>
#include <QPainterPath>
#include <glm/glm.hpp>

namespace vv::gui {

MeasureOverlay::MeasureOverlay(ViewerWidget* viewer)
    : FollowingOverlay(viewer, QStringLiteral("measureOverlay")) {
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
    return FollowingOverlay::project(point.worldPosition);
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
        const Measurement m = measure(points_[0], points_[1], viewer()->camera());
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

}  // namespace vv::gui
