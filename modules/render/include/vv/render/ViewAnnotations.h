// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QPointF>
#include <QRectF>
#include <QSizeF>
#include <QString>
#include <array>
#include <glm/glm.hpp>
#include <optional>

#include "vv/render/Camera.h"
#include "vv/scene/Mesh.h"

class QPainter;

namespace vv::render {

/// The frame a scene's coordinates are given in (scene::Scene::frame):
/// Unknown names the axes x, y, z; PatientLps names patient directions
/// L/R, A/P, S/I.
using SceneFrame = scene::SceneFrame;

/// What the view draws over the frame besides the legends: an orientation
/// marker (top-left) and a scale bar (top-right). Both on by default.
struct ViewAnnotations {
    bool orientationMarker = true;
    bool scaleBar = true;
    SceneFrame frame = SceneFrame::Unknown;
};

/// The name of the world direction `world` (need not be unit length): the
/// letters of the axes it has a share of at least kDirectionShare along,
/// largest share first. PatientLps: "L"/"R", "P"/"A", "S"/"I" (e.g. "RA" for
/// right-anterior); Unknown: "+x"/"-x", "+y"/"-y", "+z"/"-z" joined by
/// spaces. Empty for a zero vector.
[[nodiscard]] QString directionName(const glm::vec3& world, SceneFrame frame);
inline constexpr float kDirectionShare = 0.38F;  ///< ~cos 67.5 degrees

/// What lies towards each edge of the view seen with `camera`
/// (directionName() of the screen's left, right, up and down directions).
struct EdgeLabels {
    QString left;
    QString right;
    QString top;
    QString bottom;
};
[[nodiscard]] EdgeLabels edgeLabels(const Camera& camera, SceneFrame frame);

/// The perspective camera shows lengths true only in one plane: the focal
/// plane through the camera's target (the centre of rotation), facing the
/// camera. Pixels per scene unit (mm) there in a view `heightPixels` tall
/// (the camera's vertical field of view spans that height).
[[nodiscard]] double focalPlanePixelsPerMillimetre(const Camera& camera, double heightPixels);

/// The smallest distance between two of the marker's axis letters, in
/// letter heights (the annotations' font size).
inline constexpr double kMarkerLetterGap = 1.25;

/// Where the orientation marker of a view of `area` (logical pixels) seen
/// with `camera` centres its letters of the x, y and z axes: a little past
/// each axis' tip, beside the centre for an axis along the view direction,
/// and pushed apart to at least kMarkerLetterGap letter heights from one
/// another (two axes can project onto one direction).
[[nodiscard]] std::array<QPointF, 3> markerLetterPositions(const Camera& camera,
                                                           const QRectF& area);

/// A scale bar: a round length (1, 2 or 5 x 10^k mm) and its length on screen.
struct ScaleBar {
    double millimetres = 0.0;
    double pixels = 0.0;
};
/// The bar for a view of `area` (logical pixels): the longest round length
/// whose bar is at most kScaleBarMaxShare of the width at the focal plane;
/// nullopt for an empty area.
[[nodiscard]] std::optional<ScaleBar> scaleBarFor(const Camera& camera, const QSizeF& area);
inline constexpr double kScaleBarMaxShare = 0.25;

/// Paints what `annotations` asks for into `area` (logical pixels; the
/// camera's field of view spans its height): the orientation marker top-left
/// (the three axes as seen now, each labelled, and with a patient frame the
/// patient directions at the middle of each edge) and the scale bar
/// top-right, labelled with its length "at the focal plane". Text in the UI
/// locale (QLocale()).
void paintViewAnnotations(QPainter& painter, const QRectF& area, const Camera& camera,
                          const ViewAnnotations& annotations);

}  // namespace vv::render
