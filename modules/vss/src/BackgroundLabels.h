// SPDX-License-Identifier: GPL-3.0-or-later
// Private to vss: the 4-connected components of the background of a vessel
// mask, labelled in bands of rows in parallel (findVoidRegions).
#pragma once

#include <cstdint>
#include <vector>

#include "vv/core/Image.h"

namespace vv::vss::detail {

/// Bounding box (x1 / y1 exclusive) and pixel count of one component.
struct ComponentBox {
    int x0 = 0;
    int y0 = 0;
    int x1 = 0;
    int y1 = 0;
    std::int64_t pixels = 0;
};

/// Rows per band of the parallel passes over an image (a fixed size: the
/// bands, and so everything computed from them, do not depend on the thread
/// count).
inline constexpr int kBandRows = 32;

/// Writes to `labels` (same size as the mask) -1 on vessel pixels (mask
/// nonzero) and, on background pixels, the id of their 4-connected component:
/// 0, 1, ... in raster order (row by row, left to right) of each component's
/// first pixel. Returns the components' boxes, indexed by id. Labels each band
/// of kBandRows rows with its own union-find in parallel (vv::parallelFor),
/// joins the bands along their borders, then renumbers in parallel: the
/// result does not depend on the thread count. Throws InvalidArgumentError
/// when the sizes differ.
std::vector<ComponentBox> labelBackground(ImageView<const std::uint8_t> mask,
                                          ImageView<std::int32_t> labels);

}  // namespace vv::vss::detail
