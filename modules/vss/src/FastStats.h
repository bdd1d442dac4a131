// SPDX-License-Identifier: GPL-3.0-or-later
// Counters of the fast VSS solver, for tests and the micro-benchmark.
#pragma once

#include <cstdint>

namespace vv::vss::detail {

struct FastSolverStats {
    std::int64_t pixels = 0;           ///< void pixels written
    std::int64_t fallbackPixels = 0;   ///< pixels recomputed exactly after a failed check
    std::int64_t leaves = 0;           ///< leaf tiles evaluated
    std::int64_t nearPairs = 0;        ///< (row of 16 pixels) x (near point) kernel iterations
    std::int64_t m2l = 0;              ///< multipole-to-local translations
    std::int64_t dropped = 0;          ///< clusters dropped with their weight bound charged
    std::int64_t perPixelLeaves = 0;   ///< leaves in per-pixel scale mode
    std::int64_t exactTiles = 0;       ///< leaves re-evaluated with every contour point
    std::int64_t coarseBoxes = 0;      ///< boxes interpolated from a coarse grid (FastCoarse.h)
    std::int64_t coarsePixels = 0;     ///< of the pixels, written by coarse boxes
    std::int64_t nearLeaves = 0;       ///< leaf tiles that summed near points exactly
    std::int64_t nearLeafPixels = 0;   ///< of the pixels, in those tiles
    std::int64_t nearBoxes = 0;        ///< near-band boxes interpolated from a grid (FastNearBox.h)
    std::int64_t nearBoxPixels = 0;    ///< of the pixels, written by those boxes
    std::int64_t nearBoxPoints = 0;    ///< contour points those boxes summed at their samples
    std::int64_t bandBoxes = 0;        ///< band boxes on an adaptive grid (FastBandBox.h)
    std::int64_t bandBoxPixels = 0;    ///< of the pixels, written by those boxes
    std::int64_t bandExactPixels = 0;  ///< of those, summed exactly at the pixel
    std::int64_t bandSamples = 0;      ///< grid samples those boxes evaluated
    std::int64_t tableLeaves = 0;      ///< leaf tiles that read weights from the distance table
    std::int64_t tablePairs = 0;       ///< of nearPairs, those whose weights came from the table
};

/// Totals since the last reset (all solver instances, all threads).
FastSolverStats fastSolverStats();
void resetFastSolverStats();

/// Test hook: multiplies the a-priori error budget (default 1), and the
/// estimate with which near boxes (FastNearBox.h) are tried. A loose budget
/// must not break the guarantee: the per-pixel check then sends pixels to the
/// exact fall-backs, and the near boxes' bound refuses the boxes. Affects solvers created
/// afterwards.
void setFastSolverBudgetScaleForTesting(double scale);

/// Test / benchmark hook: coarse boxes (FastCoarse.h) on (the default) or
/// off, to compare the two. Affects solvers created afterwards.
void setFastSolverCoarseBoxesForTesting(bool on);

/// Test / benchmark hook: near-band boxes on a coarse grid (FastNearBox.h) on
/// (the default) or off. Affects solvers created afterwards.
void setFastSolverNearBoxesForTesting(bool on);

/// Test / benchmark hook: band boxes on an adaptive grid (FastBandBox.h) on
/// (the default) or off. Affects solvers created afterwards.
void setFastSolverBandBoxesForTesting(bool on);

/// Test hook: multiplies the interpolation terms of the band boxes' bound
/// (default 1). Below 1 the bound no longer holds: tests show that the
/// tolerance then breaks, i.e. that the bound is what keeps it. Affects
/// solvers created afterwards.
void setFastSolverBandBoundScaleForTesting(double scale);

/// Test / benchmark hook: near boxes split the clusters they could not expand
/// and expand the parts far enough from the box, so that only the near points
/// are summed at their samples (on), or sum all their points (off, the
/// default: measured no faster at 32-64 pixel boxes, docs/benchmarks/vss.md
/// "Fourth step"). Affects solvers created afterwards.
void setFastSolverNearSplitForTesting(bool on);

/// Test hook: multiplies the a-priori budget of that split only (default 1):
/// the parts a near box expands or drops then carry truncation bounds that its
/// interpolation check must charge. Affects solvers created afterwards.
void setFastSolverNearSplitBudgetScaleForTesting(double scale);

/// Test / benchmark hook: leaf tiles read their near weights from the
/// distance table (FastKernel.h, LeafKernelArgs::table; on, the default) or
/// compute them (off). Affects solvers created afterwards.
void setFastSolverDistanceTableForTesting(bool on);

}  // namespace vv::vss::detail
