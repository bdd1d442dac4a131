// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/vss/DepthNormalization.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "vv/core/Error.h"
#include "vv/core/Parallel.h"

namespace vv::vss {

namespace {

/// Range and count of the vessel depths of one row.
struct RowRange {
    float lo = std::numeric_limits<float>::infinity();
    float hi = -std::numeric_limits<float>::infinity();
    std::int64_t count = 0;
};

/// Writes v[x] = 1 where m[x] != 0 and d[x] is finite (a vessel pixel), else
/// 0, for x < w, and returns the range and count of those d[x]. Branch-free,
/// on the bits of the floats, so that the compiler vectorises it; float min /
/// max are exact, so the range is that of a double loop.
RowRange vesselRow(const float* d, const std::uint8_t* m, std::uint8_t* v, int w) {
    RowRange r;
    std::int32_t count = 0;
    for (int x = 0; x < w; ++x) {
        const float dx = d[x];
        const auto bits = std::bit_cast<std::uint32_t>(dx);
        const bool vessel = m[x] != 0 && (bits & 0x7f800000U) != 0x7f800000U;
        v[x] = vessel ? 1 : 0;
        count += vessel ? 1 : 0;
        r.lo = vessel && dx < r.lo ? dx : r.lo;
        r.hi = vessel && dx > r.hi ? dx : r.hi;
    }
    r.count = count;
    return r;
}

}  // namespace

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
    // Both passes below write every pixel (in parallel): no fill first.
    result.z = Image<float>(w, h, UninitialisedPixels{});
    result.vessel = Image<std::uint8_t>(w, h, UninitialisedPixels{});

    // In bands of rows in parallel; min, max and count are exact, so the
    // result does not depend on the bands.
    constexpr int kBandRows = 32;
    const long bands = (h + kBandRows - 1) / kBandRows;
    struct BandRange {
        double lo = std::numeric_limits<double>::infinity();
        double hi = -std::numeric_limits<double>::infinity();
        std::int64_t count = 0;
    };
    std::vector<BandRange> ranges(static_cast<std::size_t>(bands));
    parallelFor(0, bands, 1, [&](long b0, long b1) {
        for (long b = b0; b < b1; ++b) {
            BandRange& r = ranges[static_cast<std::size_t>(b)];
            const int yEnd = std::min(h, static_cast<int>(b + 1) * kBandRows);
            for (int y = static_cast<int>(b) * kBandRows; y < yEnd; ++y) {
                const RowRange rr = vesselRow(depth.row(y), mask.row(y), result.vessel.row(y), w);
                r.lo = std::min(r.lo, static_cast<double>(rr.lo));
                r.hi = std::max(r.hi, static_cast<double>(rr.hi));
                r.count += rr.count;
            }
        }
    });
    double lo = std::numeric_limits<double>::infinity();
    double hi = -std::numeric_limits<double>::infinity();
    std::int64_t count = 0;
    for (const BandRange& r : ranges) {
        lo = std::min(lo, r.lo);
        hi = std::max(hi, r.hi);
        count += r.count;
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
    parallelFor(0, h, kBandRows, [&](long y0, long y1) {
        for (long yl = y0; yl < y1; ++yl) {
            const int y = static_cast<int>(yl);
            const float* d = depth.row(y);
            const std::uint8_t* v = result.vessel.row(y);
            float* z = result.z.row(y);
            for (int x = 0; x < w; ++x) {
                if (v[x] != 0) {
                    const double t = (static_cast<double>(d[x]) - offset) * scale;
                    z[x] = static_cast<float>(std::clamp(t, 0.0, 1.0));
                } else {
                    z[x] = std::numeric_limits<float>::quiet_NaN();
                }
            }
        }
    });
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
