// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QObject>
#include <QPointF>
#include <QWidget>
#include <glm/glm.hpp>
#include <optional>

namespace vv::gui {

class ViewerWidget;

/// The linked cursor of the 3-D view and the slice views: one world point
/// (LPS mm). A left click without dragging on a vessel in the 3-D view (its
/// probe) or on a slice sets it; the slice views then show the slices through
/// it with a crosshair on it (SliceWorkspace does that on pointChanged()), and
/// the 3-D view shows a marker on it, re-projected after every frame.
class SliceCursor : public QObject {
    Q_OBJECT

  public:
    /// `viewer` may be null (no OpenGL): then only the slices are linked.
    explicit SliceCursor(ViewerWidget* viewer, QObject* parent = nullptr);

    [[nodiscard]] const std::optional<glm::dvec3>& point() const noexcept { return point_; }
    /// Whether clicks on the 3-D view set the cursor (only while slice views
    /// exist: a mesh scene's clicks stay without a marker). Off clears it.
    void setActive(bool active);
    /// Moves the cursor to `world` (nullopt: none) and emits pointChanged().
    void setPoint(const std::optional<glm::dvec3>& world);
    /// The 3-D view's marker widget (null without a viewer).
    [[nodiscard]] QWidget* marker() const noexcept { return marker_; }
    /// Where the marker is drawn in the 3-D view (nullopt: not drawn).
    [[nodiscard]] std::optional<QPointF> markerPosition() const;

  signals:
    void pointChanged(const std::optional<glm::dvec3>& world);

  protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

  private:
    ViewerWidget* viewer_;
    QWidget* marker_ = nullptr;
    std::optional<glm::dvec3> point_;
    bool active_ = false;
    bool pressed_ = false;
    QPointF pressAt_;
};

}  // namespace vv::gui
