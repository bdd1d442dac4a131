// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>
#include <vector>

#include "vv/core/Image.h"
#include "vv/vss/Solver.h"

namespace vv::vss {

/// The void regions of a vessel mask (VSS.md, definitions 2 and 3).
struct VoidRegionSet {
    /// kVesselLabel (-1) on vessel pixels, the region id 0..n-1 on background pixels.
    Image<std::int32_t> labels;
    /// regions[i].id == i. Ids follow the raster order (row by row, left to
    /// right) of each region's first pixel, so they are deterministic.
    std::vector<VoidRegion> regions;
};

/// Finds the void regions of `vesselMask` (nonzero = vessel): the 4-connected
/// components of background pixels. The contour of a region is
/// every vessel pixel 8-adjacent to one of its pixels, each listed once, in
/// row-major order (y, then x); a vessel pixel may be in several regions'
/// contours. The image border is not a contour: a region may touch it.
/// ContourPoint::z is taken from `z` when it is given (same size as the mask),
/// else 0.
/// Special cases: an empty image or an all-vessel mask gives no region; an
/// all-background mask gives one region with an empty contour.
/// Labelling and contours run in bands of rows in parallel (vv::parallelFor);
/// the result does not depend on the thread count.
/// Memory: the label image, a few bytes per provisional component of the
/// labelling, plus the contours; no per-region full-size image.
/// Throws InvalidArgumentError when `z` is given with a different size.
[[nodiscard]] VoidRegionSet findVoidRegions(ImageView<const std::uint8_t> vesselMask,
                                            ImageView<const float> z = {});

}  // namespace vv::vss
