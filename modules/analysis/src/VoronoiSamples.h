// SPDX-License-Identifier: GPL-3.0-or-later
// Private to vv::analysis: which surface points the Voronoi diagram is built
// from. A surface much finer than its vessels need (a 1M-triangle aorta: a
// hundred points around a 20 mm lumen) costs the Delaunay step time and
// memory and buys the medial axis nothing; where a vessel's wall is sampled
// more densely than kSpacingPerRadius of its radius, one point per cell of
// that size is kept. The sections and the ends still use every point.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "PreparedSurface.h"
#include "vv/core/Progress.h"

namespace vv::analysis::detail {

/// The spacing kept, in local radii: a quarter radius puts 25 points around a
/// lumen; the chords between them lie at most kSpacingPerRadius^2 / 8 of the
/// radius (0.8 %) inside the circle through them.
inline constexpr double kSpacingPerRadius = 0.25;

/// Where a facet of the wall is longer than kCoarseFacetRadii times its
/// local radius (its longest edge against the larger of its vertices'
/// smallest local radius and its own shortest edge), points are added on it
/// for the diagram, kDenseSpacingPerRadius of that radius apart (at most
/// kMaxFacetSteps along the facet): the Voronoi diagram of samples that far
/// apart is no longer near the medial axis (a decimated straight tube is two
/// rings joined by 50 mm long triangles, and its diagram has no axis
/// between them). A tube sampled in near-square quads (a facet's diagonal
/// under a radius) keeps its points as they are. Measured on the 1k-triangle
/// phantoms (docs/benchmarks/analysis.md): a lower threshold (1.25-1.5)
/// gives better angles on the decimated Y but false vessel ends on the
/// staircase surface of a coarse CTA segmentation; a wider spacing (0.375)
/// misses the 30-degree Y by 4 degrees.
inline constexpr double kCoarseFacetRadii = 2.0;
inline constexpr double kDenseSpacingPerRadius = 0.25;
inline constexpr int kMaxFacetSteps = 256;
/// About this many points at most are added; beyond, every spacing grows
/// alike (VoronoiSamples::addedSpacingScale).
inline constexpr double kMaxAddedPoints = 2'000'000.0;

/// Above this fraction of its vertices folded (VoronoiSamples::foldedFraction)
/// a wall's noise is larger than its triangles, and the analysis says so:
/// measured, every phantom up to 5 % jitter and every decimated or segmented
/// surface folds at under 0.03 % of its vertices; the jittered 1M tubes
/// (0.1 mm of noise on 0.08 mm triangles) at 1-5 %, where the narrowed and
/// bent ones go wrong (docs/benchmarks/analysis.md).
inline constexpr double kFoldedFraction = 0.005;

struct VoronoiSamples {
    /// The capped surface's vertices to triangulate, ascending; every one
    /// when the surface is nowhere finer than needed (`reduced` false).
    /// Ids from cappedPositions.size() on are the added points.
    std::vector<std::uint32_t> kept;
    /// Points added on coarse facets (flat, inside the facet or on its
    /// edges) and their normals (interpolated over the facet, unit).
    std::vector<glm::dvec3> addedPositions;
    std::vector<glm::dvec3> addedNormals;
    /// The added points' spacing against kDenseSpacingPerRadius: above 1
    /// when kMaxAddedPoints made it wider.
    double addedSpacingScale = 1.0;
    /// Per capped vertex: the kept vertex standing for it (itself when kept).
    std::vector<std::uint32_t> representative;
    bool reduced = false;
    /// The largest distance from a left-out vertex to its representative, mm.
    double largestGapMm = 0.0;
    /// The fraction of the surface's vertices whose own normal points away
    /// from their neighbourhood's (more than 90 degrees from it, averaged
    /// over four rings): there the wall folds over itself.
    double foldedFraction = 0.0;
    /// Per surface vertex: its local radius (as the reduction measures it),
    /// 0 where the wall is rough there; infinite on a flat wall.
    std::vector<float> wallRadiusMm;
};

/// Chooses the samples of `surface`. The local radius at a vertex is the
/// inverse of the largest curvature its edges see (how fast the normal,
/// averaged four times over its neighbours, turns along them), the smallest over the vertex and its
/// neighbours (a rough surface curves more, and keeps more points); the cell is kSpacingPerRadius
/// of it (where that is at least twice the vertex's shortest edge, and its own normal is within 15
/// degrees of the averaged one, not on a rough wall; else the vertex is kept), rounded down to a
/// power of two of the finest cell; boundary loops and cap centres are always kept. Keeps
/// everything when that would leave out less than a fifth of the points. Coarse facets of the
/// wall (kCoarseFacetRadii; not the caps) get points added, one per cell of their spacing that
/// holds no vertex. Deterministic; CancelledError on a stop.
[[nodiscard]] VoronoiSamples chooseVoronoiSamples(const PreparedSurface& surface,
                                                  const Progress& progress);

/// VoronoiSamples::foldedFraction alone: the fraction of the surface's
/// vertices where its wall folds over itself.
[[nodiscard]] double foldedFractionOf(const PreparedSurface& surface);

}  // namespace vv::analysis::detail
