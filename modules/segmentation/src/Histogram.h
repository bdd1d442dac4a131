// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Otsu's threshold of a histogram, shared by the threshold defaults and the
// intensity correction.

#include <cstddef>
#include <vector>

namespace vv::segmentation::detail {

/// Otsu's threshold of `histogram`: the bin edge maximising the between-class
/// variance; the voxels in bins >= the result are "above". 0 when every count
/// lies in one bin.
[[nodiscard]] std::size_t otsuBin(const std::vector<std::size_t>& histogram);

}  // namespace vv::segmentation::detail
