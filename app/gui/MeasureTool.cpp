// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/MeasureTool.h"

#include <QLabel>
#include <cmath>

#include "gui/MeasureOverlay.h"

namespace vv::gui {

MeasureTool::MeasureTool(ViewerWidget* viewer, QLabel* label, QObject* parent)
    : QObject(parent), viewer_(viewer), label_(label), overlay_(new MeasureOverlay(viewer)) {}

void MeasureTool::setActive(bool on) {
    active_ = on;
    viewer_->setMeasureMode(on);
    if (!on) {
        clear();
    } else if (points_.isEmpty()) {
        label_->setText(tr("Measure: click a point on a vessel"));
    }
}

void MeasureTool::addPoint(const ProbeResult& point) {
    if (points_.size() >= 2) {
        points_.clear();
    }
    points_ << point;
    overlay_->setPoints(points_);
    const auto where = [](const ProbeResult& p) {
        return p.objectName.isEmpty() ? tr("object %1").arg(p.meshIndex + 1) : p.objectName;
    };
    if (points_.size() == 1) {
        label_->setText(tr("Measure: A on %1, %2 mm deep; click a second point")
                            .arg(where(point))
                            .arg(static_cast<double>(point.depthBelowNearest), 0, 'f', 1));
        return;
    }
    const Measurement m = measure(points_[0], points_[1]);
    const auto depth = static_cast<double>(m.depthDifference);
    const QString deeper = std::abs(depth) < 0.05 ? tr("same depth")
                           : depth > 0.0 ? tr("B deeper by %1 mm").arg(std::abs(depth), 0, 'f', 1)
                                         : tr("A deeper by %1 mm").arg(std::abs(depth), 0, 'f', 1);
    label_->setText(
        tr("Distance A–B: %1 mm; %2").arg(static_cast<double>(m.distance), 0, 'f', 1).arg(deeper));
}

void MeasureTool::missed() {
    label_->setText(tr("Measure: no vessel under the mouse"));
}

void MeasureTool::clear() {
    points_.clear();
    overlay_->setPoints(points_);
    label_->setText(active_ ? tr("Measure: click a point on a vessel") : QString());
}

}  // namespace vv::gui
