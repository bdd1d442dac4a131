// SPDX-License-Identifier: GPL-3.0-or-later
// Private to the fast VSS solver: a box of 32 x 32 pixels of the near-contour
// band (level 1, with source clusters it could not expand) evaluated on an
// adaptive grid: cells of 8, 4 and 2 pixels interpolated bilinearly where a
// rigorous bound of the interpolation error holds for that cell, the pixels
// of the cells where it fails summed exactly (the box's near points and its
// local expansion), so that contour points inside or next to the box no
// longer send all its pixels down to the leaf tiles (the derivation: the
// comment at the top of FastBandBox.cpp).
#pragma once

#include <cstdint>
#include <vector>

#include "FastExpansion.h"
#include "FastLeaf.h"
#include "FastRegion.h"

namespace vv::vss::detail::fast {

/// Largest p for which band boxes are tried (at p = 8 they measured no faster
/// than the leaf tiles: the cells next to the contours fail more often and the
/// box sums all its near points there; docs/benchmarks/vss.md, "Sixth step").
inline constexpr double kBandMaxP = 4.0;

/// What one band box did, for the solver's statistics (FastStats.h).
struct BandCounts {
    std::int64_t pixels = 0;          ///< region pixels written (0: not taken)
    std::int64_t exactPixels = 0;     ///< of which summed exactly at the pixel
    std::int64_t fallbackPixels = 0;  ///< of which failed that check (double-precision sum)
    std::int64_t samples = 0;         ///< grid samples evaluated
};

/// Writes z' to rg.out for every pixel of region rg.id in the box with
/// geometry geo (its region pixels span at most 32 x 32): the points of the
/// source nodes `near` exactly, the rest through far (the box's local
/// expansion; nullptr when there is none) and charged to bounds.E, every
/// pixel within rg.tol of the exact value and clamped to the contour depth
/// range. Returns counts.pixels == 0 and writes nothing when the box is not
/// tried (larger box, no near point, weights outside float's range with one
/// scale); the caller then descends as usual. Throws nothing.
BandCounts evalBandBox(const Region& rg, const BoxGeo& geo, const std::vector<int>& near,
                       const Local* far, const LeafBounds& bounds);

}  // namespace vv::vss::detail::fast
