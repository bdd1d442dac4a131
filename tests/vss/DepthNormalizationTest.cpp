// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

#include "vv/core/Error.h"
#include "vv/vss/DepthNormalization.h"

namespace vv::vss {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

TEST(DepthNormalizationTest, VisibleRangeOverVesselPixelsOnly) {
    Image<float> depth(4, 2);
    Image<std::uint8_t> mask(4, 2, 1);
    const float values[8] = {5, 7, 9, 100, 6, 8, -40, 6.5F};
    for (int i = 0; i < 8; ++i) {
        depth(i % 4, i / 4) = values[i];
    }
    mask(3, 0) = 0;  // 100: background, ignored
    mask(2, 1) = 0;  // -40: background, ignored
    const auto n = normalizeDepth(depth.view(), mask.view());
    EXPECT_EQ(n.dmin, 5.0);
    EXPECT_EQ(n.dmax, 9.0);
    EXPECT_FALSE(n.flat);
    EXPECT_EQ(n.vesselPixels, 6);
    EXPECT_EQ(n.z(0, 0), 0.0F);
    EXPECT_EQ(n.z(2, 0), 1.0F);
    EXPECT_FLOAT_EQ(n.z(1, 0), 0.5F);
    EXPECT_FLOAT_EQ(n.z(3, 1), 0.375F);
    EXPECT_TRUE(std::isnan(n.z(3, 0)));
    EXPECT_TRUE(std::isnan(n.z(2, 1)));
    EXPECT_EQ(n.vessel(3, 0), 0);
    EXPECT_EQ(n.vessel(0, 0), 1);
}

TEST(DepthNormalizationTest, NonFiniteVesselDepthIsBackground) {
    Image<float> depth(3, 1);
    depth(0, 0) = 1.0F;
    depth(1, 0) = kNaN;
    depth(2, 0) = kInf;
    const Image<std::uint8_t> mask(3, 1, 1);
    const auto n = normalizeDepth(depth.view(), mask.view());
    EXPECT_EQ(n.vesselPixels, 1);
    EXPECT_EQ(n.vessel(1, 0), 0);
    EXPECT_EQ(n.vessel(2, 0), 0);
    EXPECT_TRUE(std::isnan(n.z(1, 0)));
    EXPECT_EQ(n.dmin, 1.0);
    EXPECT_EQ(n.dmax, 1.0);
    EXPECT_TRUE(n.flat);
    EXPECT_EQ(n.z(0, 0), 0.0F);
}

TEST(DepthNormalizationTest, WideRowsMatchAPixelByPixelReference) {
    // The range pass works on the floats' bits, many pixels at a time: over
    // rows of odd widths with NaN, +-Inf, negative zero, huge and tiny depths
    // and mask bytes other than 1, every vessel flag, the count and the
    // range must be those of a plain pixel-by-pixel loop.
    const std::array<float, 8> specials = {kNaN, kInf,    -kInf,    -0.0F,
                                           0.0F, 3.4e38F, -3.4e38F, 1e-45F};
    std::uint64_t state = 7;
    const auto next = [&state] {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        return static_cast<std::uint32_t>(state >> 33);
    };
    for (const int w : {1, 7, 8, 9, 63, 257}) {
        const int h = 37;
        Image<float> depth(w, h);
        Image<std::uint8_t> mask(w, h);
        for (int y = 0; y < h; ++y) {
            for (int x = 0; x < w; ++x) {
                const std::uint32_t r = next();
                depth(x, y) = r % 5 == 0 ? specials[r / 5 % specials.size()]
                                         : static_cast<float>(r % 100003) * 0.37F - 9000.0F;
                mask(x, y) = static_cast<std::uint8_t>(r % 3 == 0 ? 0 : 1 + (r >> 8) % 255);
            }
        }
        double lo = std::numeric_limits<double>::infinity();
        double hi = -lo;
        std::int64_t count = 0;
        const auto n = normalizeDepth(depth.view(), mask.view());
        for (int y = 0; y < h; ++y) {
            for (int x = 0; x < w; ++x) {
                const bool vessel = mask(x, y) != 0 && std::isfinite(depth(x, y));
                ASSERT_EQ(n.vessel(x, y), vessel ? 1 : 0) << w << ": " << x << ", " << y;
                if (vessel) {
                    ++count;
                    lo = std::min(lo, static_cast<double>(depth(x, y)));
                    hi = std::max(hi, static_cast<double>(depth(x, y)));
                } else {
                    ASSERT_TRUE(std::isnan(n.z(x, y)));
                }
            }
        }
        EXPECT_EQ(n.vesselPixels, count) << w;
        EXPECT_EQ(n.dmin, lo) << w;
        EXPECT_EQ(n.dmax, hi) << w;
    }
}

TEST(DepthNormalizationTest, FlatSceneHasZeroNotNaN) {
    for (const float d : {0.0F, 1.0F, 1e6F, -3.0F}) {
        Image<float> depth(5, 5, d);
        // Half the relative epsilon 1e-6 * max(1, |dmax|) above the rest: flat.
        depth(2, 2) = d + 0.5e-6F * std::max(1.0F, std::abs(d));
        ASSERT_NE(depth(2, 2), d);
        const Image<std::uint8_t> mask(5, 5, 1);
        const auto n = normalizeDepth(depth.view(), mask.view());
        EXPECT_TRUE(n.flat) << d;
        for (int y = 0; y < 5; ++y) {
            for (int x = 0; x < 5; ++x) {
                EXPECT_EQ(n.z(x, y), 0.0F);
            }
        }
    }
    // Just above the epsilon: not flat.
    Image<float> depth(2, 1, 1000.0F);
    depth(1, 0) = 1000.0F + 0.01F;
    const Image<std::uint8_t> mask(2, 1, 1);
    EXPECT_FALSE(normalizeDepth(depth.view(), mask.view()).flat);
    EXPECT_DOUBLE_EQ(flatEpsilon(1000.0), 1e-3);
    EXPECT_DOUBLE_EQ(flatEpsilon(0.5), 1e-6);
    EXPECT_DOUBLE_EQ(flatEpsilon(-2000.0), 2e-3);
}

TEST(DepthNormalizationTest, FixedRangeClampsAndKeepsTheRange) {
    Image<float> depth(4, 1);
    depth(0, 0) = -5.0F;
    depth(1, 0) = 0.0F;
    depth(2, 0) = 25.0F;
    depth(3, 0) = 500.0F;
    const Image<std::uint8_t> mask(4, 1, 1);
    const auto n = normalizeDepth(depth.view(), mask.view(), {RangeMode::Fixed, 0.0, 100.0});
    EXPECT_EQ(n.dmin, 0.0);
    EXPECT_EQ(n.dmax, 100.0);
    EXPECT_EQ(n.z(0, 0), 0.0F);
    EXPECT_EQ(n.z(1, 0), 0.0F);
    EXPECT_FLOAT_EQ(n.z(2, 0), 0.25F);
    EXPECT_EQ(n.z(3, 0), 1.0F);
    // A fixed range of zero width is flat.
    const auto flat = normalizeDepth(depth.view(), mask.view(), {RangeMode::Fixed, 3.0, 3.0});
    EXPECT_TRUE(flat.flat);
    EXPECT_EQ(flat.z(3, 0), 0.0F);
}

TEST(DepthNormalizationTest, FarNearRatio1e7) {
    Image<float> depth(3, 1);
    depth(0, 0) = 1e-3F;
    depth(1, 0) = 1.0F;
    depth(2, 0) = 1e4F;
    const Image<std::uint8_t> mask(3, 1, 1);
    const auto n = normalizeDepth(depth.view(), mask.view());
    EXPECT_FALSE(n.flat);
    EXPECT_EQ(n.z(0, 0), 0.0F);
    EXPECT_EQ(n.z(2, 0), 1.0F);
    EXPECT_NEAR(n.z(1, 0), (1.0 - 1e-3) / (1e4 - 1e-3), 1e-9);
    EXPECT_GT(n.z(1, 0), 0.0F);
}

TEST(DepthNormalizationTest, NoVesselPixels) {
    const Image<float> depth(3, 2, 4.0F);
    const Image<std::uint8_t> mask(3, 2, 0);
    const auto n = normalizeDepth(depth.view(), mask.view());
    EXPECT_EQ(n.vesselPixels, 0);
    EXPECT_TRUE(std::isnan(n.dmin));
    EXPECT_TRUE(std::isnan(n.dmax));
    EXPECT_TRUE(n.flat);
    const auto fixed = normalizeDepth(depth.view(), mask.view(), {RangeMode::Fixed, 1.0, 2.0});
    EXPECT_EQ(fixed.dmin, 1.0);
    EXPECT_EQ(fixed.dmax, 2.0);
}

TEST(DepthNormalizationTest, InvalidArguments) {
    const Image<float> depth(3, 2, 4.0F);
    const Image<std::uint8_t> mask(2, 3, 1);
    EXPECT_THROW(static_cast<void>(normalizeDepth(depth.view(), mask.view())),
                 InvalidArgumentError);
    const Image<std::uint8_t> ok(3, 2, 1);
    for (const auto& range :
         {DepthRange{RangeMode::Fixed, 2.0, 1.0}, DepthRange{RangeMode::Fixed, std::nan(""), 1.0},
          DepthRange{RangeMode::Fixed, 0.0, HUGE_VAL}}) {
        EXPECT_THROW(static_cast<void>(normalizeDepth(depth.view(), ok.view(), range)),
                     InvalidArgumentError);
    }
}

TEST(DepthNormalizationTest, MaskFromFiniteDepth) {
    Image<float> depth(3, 1);
    depth(0, 0) = 2.0F;
    depth(1, 0) = kInf;
    depth(2, 0) = kNaN;
    const auto mask = maskFromFiniteDepth(depth.view());
    EXPECT_EQ(mask(0, 0), 1);
    EXPECT_EQ(mask(1, 0), 0);
    EXPECT_EQ(mask(2, 0), 0);
}

}  // namespace
}  // namespace vv::vss
