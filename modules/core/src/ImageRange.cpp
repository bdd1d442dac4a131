// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/core/ImageRange.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vv {

std::optional<std::pair<float, float>> finiteRange(ImageView<const float> image) noexcept {
    float lo = std::numeric_limits<float>::infinity();
    float hi = -std::numeric_limits<float>::infinity();
    for (int y = 0; y < image.height(); ++y) {
        const float* row = image.row(y);
        for (int x = 0; x < image.width(); ++x) {
            if (std::isfinite(row[x])) {
                lo = std::min(lo, row[x]);
                hi = std::max(hi, row[x]);
            }
        }
    }
    if (lo > hi) {
        return std::nullopt;
    }
    return std::make_pair(lo, hi);
}

}  // namespace vv
