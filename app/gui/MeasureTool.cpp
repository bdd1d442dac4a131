// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/MeasureTool.h"

#include <QLabel>
#include <QLocale>
#include <cmath>

#include "gui/MeasureOverlay.h"

namespace vv::gui {

namespace {

/// A length in mm with one decimal, in the UI locale.
QString millimetres(float value) {
    return QLocale().toString(static_cast<double>(value), 'f', 1);
}

}  // namespace

MeasureTool::MeasureTool(ViewerWidget* viewer, QLabel* label, QObject* parent)
    : QObject(parent), viewer_(viewer), label_(label), overlay_(new MeasureOverlay(viewer)) {
    label_->setToolTip(
        tr("The distance is the 3-D distance of points 1 and 2. The depth difference is measured "
           "along the current view direction and changes as the view turns. Esc clears."));
    // Every frame may show another view direction: the depth difference follows it.
    connect(viewer_, &ViewerWidget::frameRendered, this, &MeasureTool::refresh);
}

void MeasureTool::setActive(bool on) {
    active_ = on;
    viewer_->setMeasureMode(on);
    if (on && points_.isEmpty()) {
        label_->setText(tr("Measure: click a point on a vessel"));
    } else if (!on && points_.isEmpty()) {
        label_->clear();
    }
}

void MeasureTool::addPoint(const ProbeResult& point) {
    if (points_.size() >= 2) {
        points_.clear();
    }
    points_ << point;
    overlay_->setPoints(points_);
    shown_.clear();
    if (points_.size() == 1) {
        const QString where = point.objectName.isEmpty() ? tr("object %1").arg(point.meshIndex + 1)
                                                         : point.objectName;
        label_->setText(tr("Measure: point 1 on %1; click a second point").arg(where));
        return;
    }
    refresh();
}

QString MeasureTool::measurementText() const {
    if (points_.size() < 2) {
        return {};
    }
    const Measurement m = measure(points_[0], points_[1], viewer_->camera());
    const float depth = m.depthDifference;
    const QString deeper = std::abs(depth) < 0.05F ? tr("points 1 and 2 at the same depth")
                           : depth > 0.0F ? tr("point 2 deeper by %1 mm").arg(millimetres(depth))
                                          : tr("point 1 deeper by %1 mm").arg(millimetres(-depth));
    return tr("Distance 1–2: %1 mm · depth difference in this view: %2")
        .arg(millimetres(m.distance), deeper);
}

void MeasureTool::refresh() {
    if (points_.size() < 2) {
        return;
    }
    const QString text = measurementText();
    if (text != shown_) {
        shown_ = text;
        label_->setText(text);
    }
}

void MeasureTool::missed() {
    shown_.clear();
    label_->setText(tr("Measure: no vessel under the mouse"));
}

std::optional<std::array<glm::vec3, 2>> MeasureTool::completePoints() const {
    if (points_.size() < 2) {
        return std::nullopt;
    }
    return std::array<glm::vec3, 2>{points_[0].worldPosition, points_[1].worldPosition};
}

void MeasureTool::restore(const std::array<glm::vec3, 2>& points) {
    points_.clear();
    for (const glm::vec3& world : points) {
        ProbeResult point;
        point.worldPosition = world;
        points_ << point;
    }
    overlay_->setPoints(points_);
    shown_.clear();
    refresh();
}

void MeasureTool::clear() {
    points_.clear();
    shown_.clear();
    overlay_->setPoints(points_);
    label_->setText(active_ ? tr("Measure: click a point on a vessel") : QString());
}

}  // namespace vv::gui
