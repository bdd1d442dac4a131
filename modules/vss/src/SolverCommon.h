// SPDX-License-Identifier: GPL-3.0-or-later
// Helpers shared by the solvers (private to the vss module).
#pragma once

#include <cstdint>
#include <functional>
#include <stop_token>

#include "vv/core/Image.h"
#include "vv/vss/Solver.h"

namespace vv::vss::detail {

/// Below this many (pixel, contour pixel) pairs a region is solved on the
/// calling thread: starting threads would cost more than the work.
inline constexpr double kSerialPairs = 1 << 17;

/// Calls row(y) for every row of the region's bounding box, in parallel
/// (vv::parallelFor, one row per chunk) when pixelCount * pairsPerPixel is large
/// enough, else on the calling thread. Throws CancelledError when `stop` is
/// requested, InvalidArgumentError when the bounding box is outside `labels`.
void forEachRegionRow(ImageView<const std::int32_t> labels, const VoidRegion& region,
                      double pairsPerPixel, const std::stop_token& stop,
                      const std::function<void(int y)>& row);

/// Sets out(x, y) = value for every pixel of the region.
void fillRegion(ImageView<const std::int32_t> labels, const VoidRegion& region,
                ImageView<float> out, float value, const std::stop_token& stop);

}  // namespace vv::vss::detail
