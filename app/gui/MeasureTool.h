// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QList>
#include <QObject>
#include <QString>
#include <array>
#include <glm/glm.hpp>
#include <optional>

#include "gui/ViewerWidget.h"

class QLabel;

namespace vv::gui {

class MeasureOverlay;

/// View > Measure: the points picked on the vessels (at most two; a third
/// starts anew), their markers over the viewer (MeasureOverlay) and what
/// `label` (in the status bar) says: the first point's object, then the 3-D
/// distance of the two (invariant) and their depth difference along the
/// current view direction (view-dependent: recomputed after every frame, so
/// it follows every rotation). Numbers in the UI locale (QLocale()).
///
/// The measurement stays until the user clears it (clear(): View > Clear
/// Measurement, Esc) or other data is shown; leaving measure mode keeps it.
class MeasureTool : public QObject {
    Q_OBJECT

  public:
    MeasureTool(ViewerWidget* viewer, QLabel* label, QObject* parent);

    /// Measure mode on (left clicks pick points; the label asks for one) or
    /// off (clicks rotate again; a measurement stays shown). Ctrl + click
    /// picks in either.
    void setActive(bool on);
    /// Adds a picked point (what a click on the viewer does).
    void addPoint(const ProbeResult& point);
    /// A click that hit no vessel.
    void missed();
    /// Forgets the points.
    void clear();

    /// The two points of a complete measurement (scene mm), what a session
    /// keeps; nullopt with fewer than two points.
    [[nodiscard]] std::optional<std::array<glm::vec3, 2>> completePoints() const;
    /// Shows the measurement of `points` again (a reopened session): the
    /// markers and the label's text as after picking them with the viewer's
    /// camera now (the depth difference follows the view from then on).
    void restore(const std::array<glm::vec3, 2>& points);

    /// The picked points of the measurement in progress (0, 1 or 2).
    [[nodiscard]] const QList<ProbeResult>& points() const noexcept { return points_; }
    [[nodiscard]] MeasureOverlay* overlay() const noexcept { return overlay_; }
    /// What the label says of the two points seen with the viewer's camera
    /// now; empty with fewer than two points.
    [[nodiscard]] QString measurementText() const;

  private:
    /// Rewrites the label when the measurement's text changed (the view turned).
    void refresh();

    ViewerWidget* viewer_;
    QLabel* label_;
    MeasureOverlay* overlay_;
    QList<ProbeResult> points_;
    QString shown_;  ///< the measurement text the label shows (empty: another message)
    bool active_ = false;
};

}  // namespace vv::gui
