// SPDX-License-Identifier: GPL-3.0-or-later
// Private to vv::analysis: a wall whose noise is larger than its triangles
// folds over itself (VoronoiSamples::foldedFraction), and its inside breaks
// up where the vessel narrows or bends: the Voronoi diagram of such a wall
// follows the noise, not the vessel. Such a wall is smoothed first, by a
// low-pass filter over its mesh (VTK's windowed-sinc filter, Taubin, Zhang
// and Golub 1996): it removes what varies from vertex to vertex and keeps
// what varies over many of them (a vessel's narrowing, its bends), without
// the shrinking of plain Laplacian smoothing.
#pragma once

#include <string>

#include "PreparedSurface.h"
#include "vv/core/Progress.h"

namespace vv::analysis::detail {

/// The filter's settings: VTK's pass band (of the mesh's spectrum, in
/// [0, 2]; the lower, the smoother) and iterations. Measured on the
/// jittered 1M-triangle tubes (docs/benchmarks/analysis.md).
inline constexpr double kSmoothingPassBand = 0.1;
inline constexpr int kSmoothingIterations = 20;

/// How far the smoothing moved the wall's points, mm.
struct WallSmoothing {
    double meanMoveMm = 0.0;
    double largestMoveMm = 0.0;
};

/// Smooths the wall of `s` (its boundary loops stay where they are) and
/// re-measures what depends on its points (movePositions). Deterministic;
/// CancelledError on a stop request, AnalysisError when the filter fails.
[[nodiscard]] WallSmoothing smoothWall(PreparedSurface& s, const Progress& progress);

/// Whether the wall of `s` folds over itself: s.foldedFraction above
/// kFoldedFraction.
[[nodiscard]] bool folds(const PreparedSurface& s);

/// "the wall folds over itself at X % of its vertices: ..." (s.foldedFraction).
[[nodiscard]] std::string foldFinding(const PreparedSurface& s);

/// When the wall of `s` folds (s.foldedFraction, which must be measured):
/// smooths it, notes what was done and how far its points moved, sets
/// s.foldedFractionBeforeSmoothing and measures s.foldedFraction afresh.
/// Returns whether it smoothed. CancelledError on a stop request.
bool smoothIfFolded(PreparedSurface& s, const Progress& progress);

}  // namespace vv::analysis::detail
