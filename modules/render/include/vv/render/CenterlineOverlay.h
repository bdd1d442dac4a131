// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Centrelines drawn over a rendered view (`render` and `report
// --centerlines on`): thin lines through the vessels, seen through their own
// wall but hidden behind other vessels in front, coloured by branch or by the
// vessel's inscribed diameter along them, with the legend that says which.

#include <QImage>
#include <cstddef>
#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <vector>

#include "vv/colormaps/ColorMap.h"
#include "vv/core/Image.h"
#include "vv/render/Camera.h"
#include "vv/render/LegendPainter.h"

class QPainter;

namespace vv::render {

/// One centreline: its points (world, mm) and the radius of the largest
/// sphere inside the vessel around each (mm): the diameter its colour shows,
/// and how far behind the vessel's front surface the line may lie and still
/// be seen through that wall.
struct OverlayPolyline {
    int branch = 0;  ///< its number, as the analysis names it ("branch N")
    std::vector<glm::vec3> points;
    std::vector<float> radiiMm;  ///< one per point
};

/// What the lines' colour shows.
enum class CenterlineColouring {
    Branch,  ///< one colour per branch (colormaps::labelColor), its number written beside it
    /// Twice OverlayPolyline::radiiMm (the inscribed-sphere diameter, as
    /// VMTK's MaximumInscribedSphereRadius) through `map` over [min, max],
    /// with a legend.
    InscribedDiameter,
};

/// The centrelines of a view and how to draw them.
struct CenterlineOverlay {
    std::vector<OverlayPolyline> lines;
    CenterlineColouring colouring = CenterlineColouring::InscribedDiameter;
    colormaps::ColorMap map = colormaps::ColorMap::Inferno;
    float min = 0.0F;  ///< diameter (mm) at the map's first colour
    float max = 1.0F;  ///< ... at its last
};

/// How far behind the front surface a centreline point may lie and still be
/// drawn, in radii of its vessel: the axis of a vessel seen side-on lies one
/// radius behind its wall, one tilted by 30 degrees towards the viewer two.
inline constexpr double kSeenThroughRadii = 2.5;

/// Whether each point of `line` shows in the view of `camera` whose linear
/// depth (DepthRasterizer.h's convention: distance along the view axis,
/// +Inf on background, row 0 on top) is `depth`, an image of the camera's
/// viewport size: in the viewport, in front of the camera, and at most
/// kSeenThroughRadii of its radius (plus one pixel's footprint) behind the
/// surface drawn at its pixel. Throws InvalidArgumentError when `depth` is
/// not of the viewport's size or radii / points differ in number.
[[nodiscard]] std::vector<bool> visiblePoints(const OverlayPolyline& line, const Camera& camera,
                                              const Image<float>& depth);

/// Paints the visible parts of the overlay's lines (visiblePoints(): a
/// segment shows when both its ends do) onto `image` (the camera's viewport
/// size), each in a dark halo so that it reads on any vessel colour, `scale`
/// times the width on a 1600 x 1200 view; in Branch colouring each branch's
/// number beside the middle of its visible part. Throws as visiblePoints().
void paintCenterlines(QImage& image, const Camera& camera, const Image<float>& depth,
                      const CenterlineOverlay& overlay, double scale);

/// The legend of an InscribedDiameter overlay with at least one line (its
/// map over [min, max], titled centerlineLegendTitle()); nullopt for Branch colouring (the numbers
/// name the branches) or no lines.
[[nodiscard]] std::optional<ParameterLegend> centerlineLegend(const CenterlineOverlay& overlay);

/// "Centreline: inscribed diameter (mm)", in the UI language.
[[nodiscard]] std::string centerlineLegendTitle();

/// Adds centerlineLegend(overlay), when there is one, to `legends`: as the
/// parameter legend when there is none, else above it.
void addCenterlineLegend(Legends& legends, const CenterlineOverlay& overlay);

}  // namespace vv::render
