// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QList>
#include <QPointF>
#include <QWidget>
#include <optional>

#include "gui/FollowingOverlay.h"
#include "gui/ViewerWidget.h"

namespace vv::gui {

/// Marks the picked measurement points over the viewer: "1", "2" (never
/// letters, which views with orientation labels use for A = anterior), the line
/// between them and the distance. A transparent child of the viewer that lets
/// the mouse through and follows its size; the points are world positions,
/// projected with the viewer's current camera at every repaint (call
/// update() after a frame), so they stay on the vessels as the camera moves.
/// Not part of the GL frame (grabFramebuffer() stays the frame alone).
class MeasureOverlay : public FollowingOverlay {
    Q_OBJECT

  public:
    explicit MeasureOverlay(ViewerWidget* viewer);

    /// The mark of point `index` (0 or 1): "1", "2" in the UI locale's digits.
    [[nodiscard]] static QString pointLabel(qsizetype index);

    /// The points to mark (0, 1 or 2; more are ignored).
    void setPoints(const QList<ProbeResult>& points);
    [[nodiscard]] const QList<ProbeResult>& points() const noexcept { return points_; }

    /// Where `point` appears in the viewer now (logical widget coordinates);
    /// nullopt when it lies behind the camera.
    [[nodiscard]] std::optional<QPointF> project(const ProbeResult& point) const;

  protected:
    void paintEvent(QPaintEvent* event) override;

  private:
    QList<ProbeResult> points_;
};

}  // namespace vv::gui
