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

/// The internal Voronoi diagram of a prepared surface (VoronoiSamples.h's
/// points, a note when they are fewer than the surface's); marks the
/// surface's loops that are holes and notes them.
[[nodiscard]] VoronoiGraph diagramOf(PreparedSurface& surface, const Progress& progress);

/// computeCenterlines() on a prepared surface (options validated) and its
/// diagram; its notes are surface.notes.
[[nodiscard]] CenterlineTree centerlinesOf(PreparedSurface& surface, const VoronoiGraph& graph,
                                           const SurfaceIndex& index,
                                           const CenterlineOptions& options,
                                           const Progress& progress);

/// computeSections() on a prepared surface.
[[nodiscard]] std::vector<std::vector<CrossSection>> sectionsOf(const PreparedSurface& surface,
                                                                const SurfaceIndex& index,
                                                                const CenterlineTree& tree,
                                                                const Progress& progress);

}  // namespace vv::analysis::detail
