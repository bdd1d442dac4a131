// SPDX-License-Identifier: GPL-3.0-or-later
// The smooth copy of a coarse scene that the renderer draws where its
// facets are large on screen (render::FrameSettings::smoothCoarseMeshes):
// made once per scene, by the GUI in the background and by the command
// line before it renders.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "vv/core/Progress.h"
#include "vv/render/ViewRenderer.h"
#include "vv/scene/Mesh.h"

namespace vv::app {

/// From this many triangles on, a scene gets no smooth copy: its copy
/// (four triangles for one) would cost more to draw than the scene, and
/// such a scene's facets are small on screen in every view but the
/// closest (the demo tree's 300k: 1-3 px in the far, medium and close
/// views).
inline constexpr std::size_t kMaxSmoothedTriangles = 150'000;
/// The most a smooth copy may move the wall, in the scene's median edges:
/// Loop subdivision moves a coarse vessel's wall inward by a fraction of
/// its facets' sag (0.62 mm at most, both ways, on the 2k-triangle aorta of
/// `vesselview-cli demo --aorta --triangles 2000`); more
/// means the mesh is not a faceted smooth surface (a staircase, spikes),
/// and it is drawn as it is.
inline constexpr double kMaxSmoothDeviationEdges = 0.5;

/// The median edge length of `scene`'s triangles (scene units); 0 without.
[[nodiscard]] double medianEdgeLength(const scene::Scene& scene);

/// The smooth copy of `scene` (one Loop subdivision, meshio::subdividedScene:
/// arrays carried, the deviation measured), or nullopt when the scene
/// needs none or cannot have one: no triangles, kMaxSmoothedTriangles or
/// more, or a copy more than kMaxSmoothDeviationEdges median edges from it
/// (`why`, when given, says which, for a note). Throws CancelledError on a
/// stop; other failures of the subdivision give nullopt and their message
/// in `why`.
[[nodiscard]] std::optional<render::RefinedGeometry> smoothCopyOf(const scene::Scene& scene,
                                                                  const Progress& progress = {},
                                                                  std::string* why = nullptr);

/// A line for a user about a smooth copy: how far it lies from the mesh.
[[nodiscard]] std::string smoothCopyNote(const render::RefinedGeometry& copy);

}  // namespace vv::app
