// SPDX-License-Identifier: GPL-3.0-or-later
// Private to the fast VSS solver: a target box far from every contour point,
// evaluated from its local expansion on a coarse grid of 16 x 16 samples and
// interpolated bilinearly, when a rigorous bound of the interpolation error
// (with the truncation and round-off bounds) keeps every pixel within the
// tolerance (the bound: the comment at the top of FastSolver.cpp, "COARSE
// BOXES").
#pragma once

#include <cstdint>

#include "FastExpansion.h"
#include "FastLeaf.h"
#include "FastRegion.h"

namespace vv::vss::detail::fast {

/// Samples per side of a coarse box's grid (one kernel tile).
inline constexpr int kCoarseGrid = kLeafTile;
/// Highest quadtree level tried (level 2: boxes of 64 x 64 pixels).
inline constexpr int kCoarseMaxLevel = 2;

/// Writes z' to rg.out for every pixel of region rg.id in the box with
/// geometry geo from its local expansion far alone (no cluster left for the
/// children: bounds.E covers everything else) when the error bound allows it,
/// and returns the number of pixels written; returns 0 and writes nothing
/// when it does not (the caller then descends as usual). Throws nothing.
std::int64_t evalCoarseBox(const Region& rg, const BoxGeo& geo, const Local& far,
                           const LeafBounds& bounds);

}  // namespace vv::vss::detail::fast
