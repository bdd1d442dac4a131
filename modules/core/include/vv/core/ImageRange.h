// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <optional>
#include <utility>

#include "vv/core/Image.h"

namespace vv {

/// The smallest and largest finite value of `image` (NaN and ±Inf skipped:
/// the background of a linear depth image is +Inf); nullopt when it has
/// none. E.g. the visible depth range of a G-buffer's linear depth.
[[nodiscard]] std::optional<std::pair<float, float>> finiteRange(
    ImageView<const float> image) noexcept;

}  // namespace vv
