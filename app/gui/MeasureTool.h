// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QList>
#include <QObject>

#include "gui/ViewerWidget.h"

class QLabel;

namespace vv::gui {

class MeasureOverlay;

/// View > Measure: the points picked on the vessels (at most two; a third
/// starts anew), their markers over the viewer (MeasureOverlay) and what
/// `label` (in the status bar) says: the first point's object and depth,
/// then the 3-D distance of the two and their depth difference.
class MeasureTool : public QObject {
    Q_OBJECT

  public:
    MeasureTool(ViewerWidget* viewer, QLabel* label, QObject* parent);

    /// Measure mode on (left clicks pick points; the label asks for one) or
    /// off (the measurement is cleared). Ctrl + click picks in either.
    void setActive(bool on);
    /// Adds a picked point (what a click on the viewer does).
    void addPoint(const ProbeResult& point);
    /// A click that hit no vessel.
    void missed();
    /// Forgets the points.
    void clear();

    /// The picked points of the measurement in progress (0, 1 or 2).
    [[nodiscard]] const QList<ProbeResult>& points() const noexcept { return points_; }
    [[nodiscard]] MeasureOverlay* overlay() const noexcept { return overlay_; }

  private:
    ViewerWidget* viewer_;
    QLabel* label_;
    MeasureOverlay* overlay_;
    QList<ProbeResult> points_;
    bool active_ = false;
};

}  // namespace vv::gui
