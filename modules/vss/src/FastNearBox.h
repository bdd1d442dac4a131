// SPDX-License-Identifier: GPL-3.0-or-later
// Private to the fast VSS solver: a target box of the near-contour band (32
// or 64 pixels, with source clusters it could not expand) whose nearest
// contour point is some pixels away, evaluated on a grid of samples every 2
// or 4 pixels (those clusters' points summed exactly, plus the box's local
// expansion) and interpolated bilinearly, when a rigorous bound of the
// interpolation error from the points' distances and the LOCAL spread of
// their depths keeps every pixel within the tolerance (the derivation: the
// comment at the top of FastNearBox.cpp).
#pragma once

#include <cstdint>
#include <vector>

#include "FastExpansion.h"
#include "FastLeaf.h"
#include "FastRegion.h"

namespace vv::vss::detail::fast {

/// Highest quadtree level tried (level 1: 32 pixels, samples every 2; level
/// 2: 64 pixels, samples every 4).
inline constexpr int kNearBoxMaxLevel = 2;

/// False when the box of a source node in nodes comes within 4 pixels of the
/// samples of a near box of the given level with geometry geo (evalNearBox
/// then returns 0). Throws nothing.
bool nearBoxHasRoom(const Region& rg, const BoxGeo& geo, int level, const std::vector<int>& nodes);

/// Writes z' to rg.out for every pixel of region rg.id in the box of the
/// given level (1 or 2) with geometry geo: the points of the source nodes
/// `near` exactly, the rest through far (the box's local expansion; nullptr
/// when there is none) and charged to bounds.E, all within rg.tol of the
/// exact value and clamped to the contour depth range; returns the number of
/// pixels written. Returns 0 when the bound does not allow it (pixels it may
/// have written are then overwritten by the caller's usual descent). Throws
/// nothing.
std::int64_t evalNearBox(const Region& rg, const BoxGeo& geo, int level,
                         const std::vector<int>& near, const Local* far, const LeafBounds& bounds);

}  // namespace vv::vss::detail::fast
