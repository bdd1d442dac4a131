// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/vss/DepthNormalization.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "vv/core/Error.h"

namespace vv::vss {

double flatEpsilon(double dmax) noexcept {
    return 1e-6 * std::max(1.0, std::abs(dmax));
}

NormalizedDepth normalizeDepth(ImageView<const float> depth, ImageView<const std::uint8_t> mask,
                               const DepthRange& range) {
    if (depth.width() != mask.width() || depth.height() != mask.height()) {
        throw InvalidArgumentError("normalizeDepth: depth is " + std::to_string(depth.width()) +
                                   "x" + std::to_string(depth.height()) + " but the mask is " +
                                   std::to_string(mask.width()) + "x" +
                                   std::to_string(mask.height()));
    }
    if (range.mode == RangeMode::Fixed) {
        if (!std::isfinite(range.dmin) || !std::isfinite(range.dmax) || range.dmin > range.dmax) {
            throw InvalidArgumentError(
                "normalizeDepth: a fixed range needs finite dmin <= dmax, got [" +
                std::to_string(range.dmin) + ", " + std::to_string(range.dmax) + "]");
        }
    }
    const int w = depth.width();
    const int h = depth.height();
    NormalizedDepth result;
    result.z = Image<float>(w, h, std::numeric_limits<float>::quiet_NaN());
    result.vessel = Image<std::uint8_t>(w, h, 0);

    double lo = std::numeric_limits<double>::infinity();
    double hi = -std::numeric_limits<double>::infinity();
    std::int64_t count = 0;
    for (int y = 0; y < h; ++y) {
        const float* d = depth.row(y);
        const std::uint8_t* m = mask.row(y);
        std::uint8_t* v = result.vessel.row(y);
        for (int x = 0; x < w; ++x) {
            if (m[x] != 0 && std::isfinite(d[x])) {
                v[x] = 1;
                ++count;
                lo = std::min(lo, static_cast<double>(d[x]));
                hi = std::max(hi, static_cast<double>(d[x]));
            }
        }
    }
    result.vesselPixels = count;
    if (range.mode == RangeMode::Fixed) {
        result.dmin = range.dmin;
        result.dmax = range.dmax;
    } else if (count > 0) {
        result.dmin = lo;
        result.dmax = hi;
    } else {
        result.dmin = std::numeric_limits<double>::quiet_NaN();
        result.dmax = std::numeric_limits<double>::quiet_NaN();
    }
    const double span = result.dmax - result.dmin;
    result.flat = count == 0 || !(span >= flatEpsilon(result.dmax));
    const double scale = result.flat ? 0.0 : 1.0 / span;
    const double offset = result.flat ? 0.0 : result.dmin;
    for (int y = 0; y < h; ++y) {
        const float* d = depth.row(y);
        const std::uint8_t* v = result.vessel.row(y);
        float* z = result.z.row(y);
        for (int x = 0; x < w; ++x) {
            if (v[x] != 0) {
                const double t = (static_cast<double>(d[x]) - offset) * scale;
                z[x] = static_cast<float>(std::clamp(t, 0.0, 1.0));
            }
        }
    }
    return result;
}

Image<std::uint8_t> maskFromFiniteDepth(ImageView<const float> depth) {
    Image<std::uint8_t> mask(depth.width(), depth.height(), 0);
    for (int y = 0; y < depth.height(); ++y) {
        const float* d = depth.row(y);
        std::uint8_t* m = mask.row(y);
        for (int x = 0; x < depth.width(); ++x) {
            m[x] = std::isfinite(d[x]) ? 1 : 0;
        }
    }
    return mask;
}

}  // namespace vv::vss
