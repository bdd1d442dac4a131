// SPDX-License-Identifier: GPL-3.0-or-later
// Orders a void region's contour pixels along their borders, for the step
// solver (private to the vss module).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "vv/vss/Solver.h"

namespace vv::vss::detail {

/// A permutation of a contour list that walks along its borders.
struct ContourOrder {
    /// index[j] = the position in the input of the j-th point of the order:
    /// a permutation of 0 .. n-1.
    std::vector<std::uint32_t> index;
    /// Where each chain starts in `index` (ascending, the first is 0; empty for
    /// an empty input). Within a chain, consecutive points are 8-neighbours
    /// (or the same pixel, for a point listed twice); the last point of one
    /// chain and the first of the next are never 8-neighbours.
    std::vector<std::uint32_t> chainStart;
};

/// Orders `points` in chains of 8-connected pixels, walked along the border:
/// - a chain starts at the first unvisited pixel in row-major order (y, then x);
/// - it steps to an unvisited 8-neighbour in the set, preferring the one with
///   the fewest unvisited neighbours of its own (but one with none only when
///   there is nothing else: that is a dead end), then a 4-neighbour over a
///   diagonal one, then the fixed direction order E, S, W, N, SE, SW, NW, NE;
/// - when stuck, it is extended the same way backwards from its first pixel
///   (so an open curve entered in its middle still becomes one chain), and the
///   next chain starts.
/// A pixel listed several times is emitted once per listing, consecutively, in
/// input order. Deterministic (a function of the input sequence only).
/// Time O(n log n) (one sort of the pixels), lookups O(1) through a hash table
/// of the pixels; memory O(n), independent of the image size.
/// Throws InvalidArgumentError for more than 2^32 - 1 points.
[[nodiscard]] ContourOrder orderAlongBorders(std::span<const ContourPoint> points);

}  // namespace vv::vss::detail
