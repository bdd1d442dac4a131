// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QPointF>
#include <QWidget>
#include <glm/vec3.hpp>
#include <optional>

namespace vv::gui {

class ViewerWidget;

/// What the marks over the 3-D view (MeasureOverlay, PlanningOverlay) are
/// painted on: a transparent child of the viewer that lets the mouse
/// through, follows its size, and is not part of the GL frame
/// (grabFramebuffer() stays the frame alone). Marks are world positions
/// projected with the viewer's current camera at every repaint (project()),
/// so they stay on the vessels as the camera moves.
class FollowingOverlay : public QWidget {
    Q_OBJECT

  public:
    FollowingOverlay(ViewerWidget* viewer, const QString& objectName);

    /// Where `world` (mm) appears in the viewer now (logical widget
    /// coordinates); nullopt when it lies behind the camera.
    [[nodiscard]] std::optional<QPointF> project(const glm::vec3& world) const;

  protected:
    bool eventFilter(QObject* watched, QEvent* event) override;
    [[nodiscard]] ViewerWidget* viewer() const noexcept { return viewer_; }

  private:
    ViewerWidget* viewer_;
};

}  // namespace vv::gui
