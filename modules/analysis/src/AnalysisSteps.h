// SPDX-License-Identifier: GPL-3.0-or-later
// Private to vv::analysis: the centrelines and the sections of a surface
// prepared once (computeCenterlines and computeSections each prepare their
// own; analyseVessels shares one).
#pragma once

#include <vector>

#include "PreparedSurface.h"
#include "SurfaceIndex.h"
#include "VoronoiGraph.h"
#include "vv/analysis/Centerlines.h"
#include "vv/analysis/Sections.h"

namespace vv::analysis::detail {

/// The internal Voronoi diagram of the prepared surface `s`
/// (VoronoiSamples.h's points, a note when they are fewer than the
/// surface's); marks the surface's loops that are holes and notes them. A
/// wall that folds over itself is smoothed first when `smoothFoldedWall`
/// (CenterlineOptions::smoothFoldedWall; WallSmoothing.h), and noted.
/// Releases `s.cappedPositions` and `s.cappedTriangles` (left empty: no step
/// after the diagram reads them; the graph's poles still number the capped
/// vertices).
[[nodiscard]] VoronoiGraph diagramOf(PreparedSurface& s, bool smoothFoldedWall,
                                     const Progress& progress);

/// computeCenterlines() on the prepared surface `s` (options validated),
/// its diagram `g` and its index `surface`; its notes are s.notes.
[[nodiscard]] CenterlineTree centerlinesOf(PreparedSurface& s, const VoronoiGraph& g,
                                           const SurfaceIndex& surface,
                                           const CenterlineOptions& options,
                                           const Progress& progress);

/// computeSections() on a prepared surface.
[[nodiscard]] std::vector<std::vector<CrossSection>> sectionsOf(const PreparedSurface& s,
                                                                const SurfaceIndex& index,
                                                                const CenterlineTree& tree,
                                                                const Progress& progress);

}  // namespace vv::analysis::detail
