// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QPointF>
#include <glm/vec3.hpp>
#include <optional>
#include <utility>

#include "gui/FollowingOverlay.h"

namespace vv::gui {

class PlanningState;
class ViewerWidget;

/// The planning marks over the 3-D view (issue 35): the centrelines as thin
/// lines (the chosen path wider), the landmarks as labelled dots, the cursor
/// as a ring where the profile's cursor is, and a hollow ring where the mouse
/// hovers the profile; repainted after each frame (FollowingOverlay). Drawn over the vessels (a
/// centreline lies inside its vessel), each in a dark halo so that it reads
/// on any colour. Not part of the GL frame (grabFramebuffer() stays the
/// frame alone). Hidden without an analysis.
class PlanningOverlay : public FollowingOverlay {
    Q_OBJECT

  public:
    /// What the centrelines' colour shows.
    enum class Colouring {
        Path,      ///< white, the chosen path wider in yellow
        Branch,    ///< one colour per branch (the label palette), the path wider
        Diameter,  ///< the inscribed diameter along them (a colour map, with its legend)
    };

    PlanningOverlay(ViewerWidget* viewer, PlanningState* state);

    void setColouring(Colouring colouring);
    [[nodiscard]] Colouring colouring() const noexcept { return colouring_; }
    /// The diameter colouring's range (mm) and map, for its legend.
    [[nodiscard]] std::pair<float, float> diameterRange() const;

    /// Where `world` appears in the viewer now (FollowingOverlay::project).
    [[nodiscard]] std::optional<QPointF> project(const glm::dvec3& world) const;
    /// The hover mark at `pathMm` along the path; NaN removes it.
    void setHoverMm(double pathMm);

  protected:
    void paintEvent(QPaintEvent* event) override;

  private:
    void follow();

    PlanningState* state_;
    double hoverMm_;
    Colouring colouring_ = Colouring::Path;
};

}  // namespace vv::gui
