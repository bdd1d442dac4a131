// SPDX-License-Identifier: GPL-3.0-or-later
// Private to vv::vss (Vss.cpp): taking a void region's z' from the previous
// solve when the region is the same, pixel for pixel and contour point for
// contour point (solve's `previous`, Vss.h).
#pragma once

#include <cstdint>
#include <unordered_map>
#include <vector>

#include "vv/core/Image.h"
#include "vv/vss/Solver.h"
#include "vv/vss/Vss.h"

namespace vv::vss::detail {

/// The regions of a previous solve, found by what identifies them cheaply:
/// their bounding box, pixel count and a hash of their contour. Built once
/// per solve; then read by several threads at once.
class PreviousRegions {
  public:
    /// Indexes previous.regions; `previous` must outlive this object.
    explicit PreviousRegions(const PreviousSolve& previous);

    /// Writes into `out` the previous solve's z' over the pixels of `region`
    /// (labelled region.id in `labels`) when the previous solve had a region
    /// with the same pixels and the same contour (positions and depths bit
    /// for bit), and returns true: the same solver then computed the same
    /// z' there. Returns false otherwise (pixels of `region` in `out` may
    /// then hold the previous values: the caller solves the region). Throws
    /// nothing.
    bool copyIfSame(ImageView<const std::int32_t> labels, const VoidRegion& region,
                    ImageView<float> out) const;

  private:
    const PreviousSolve& previous_;
    std::unordered_multimap<std::uint64_t, std::size_t> byKey_;
};

}  // namespace vv::vss::detail
