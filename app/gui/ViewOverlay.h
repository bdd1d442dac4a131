// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QWidget>

#include "vv/render/Camera.h"
#include "vv/render/LegendPainter.h"
#include "vv/render/ViewAnnotations.h"

namespace vv::gui {

/// Paints over the viewer's GL frame what is not part of it: the legends
/// (render::paintLegends), the orientation marker and the scale bar
/// (render::paintViewAnnotations, with the camera of the frame). A
/// transparent child that lets the mouse through, so that grabFramebuffer()
/// keeps returning the frame alone.
class ViewOverlay : public QWidget {
    Q_OBJECT

  public:
    explicit ViewOverlay(QWidget* parent);

    /// What the last frame showed: its legends, and its camera with the
    /// annotations asked for. Repaints when anything shown changes.
    void setFrame(render::Legends legends, const render::Camera& camera,
                  const render::ViewAnnotations& annotations);
    [[nodiscard]] const render::Legends& legends() const noexcept { return legends_; }

  protected:
    void paintEvent(QPaintEvent* event) override;

  private:
    [[nodiscard]] bool annotating() const noexcept {
        return annotations_.orientationMarker || annotations_.scaleBar;
    }

    render::Legends legends_;
    render::Camera camera_;
    render::ViewAnnotations annotations_{.orientationMarker = false, .scaleBar = false};
};

}  // namespace vv::gui
