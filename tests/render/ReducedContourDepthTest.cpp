// SPDX-License-Identifier: GPL-3.0-or-later
// The depth a VSS below the render size is solved from (reduceDepth).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "ReducedContourDepth.h"
#include "vv/core/Error.h"

namespace vv::render {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

TEST(ReducedContourDepthTest, AVesselThinnerThanAReducedPixelIsKept) {
    // A vessel one render pixel wide (column 5 of 8): at half the size the
    // reduced pixel that covers it is a vessel pixel, every row.
    Image<float> depth(8, 6, kInf);
    for (int y = 0; y < 6; ++y) {
        depth(5, y) = 10.0F;
    }
    const Image<float> reduced = reduceDepth(depth, 4, 3);
    for (int y = 0; y < 3; ++y) {
        for (int x = 0; x < 4; ++x) {
            EXPECT_EQ(std::isfinite(reduced(x, y)), x == 2) << x << "," << y;
        }
        EXPECT_FLOAT_EQ(reduced(2, y), 10.0F);
    }
}

TEST(ReducedContourDepthTest, AReducedPixelTakesItsFarthestVesselPixel) {
    // The outermost pixel of a round vessel's flank is its farthest: the
    // reduced contour's depth is the render size's contour depth.
    Image<float> depth(4, 4, kInf);
    depth(0, 0) = 5.0F;
    depth(1, 0) = 7.0F;
    depth(0, 1) = 6.0F;
    depth(3, 3) = 2.0F;
    const Image<float> reduced = reduceDepth(depth, 2, 2);
    EXPECT_FLOAT_EQ(reduced(0, 0), 7.0F);
    EXPECT_FALSE(std::isfinite(reduced(1, 0)));
    EXPECT_FALSE(std::isfinite(reduced(0, 1)));
    EXPECT_FLOAT_EQ(reduced(1, 1), 2.0F);
}

TEST(ReducedContourDepthTest, OddSizesCoverEveryRenderPixelOnce) {
    // 7 -> 3 columns: every render pixel's centre falls in exactly one
    // reduced pixel, so each lone vessel pixel appears in exactly one.
    for (int column = 0; column < 7; ++column) {
        Image<float> depth(7, 1, kInf);
        depth(column, 0) = 1.0F;
        const Image<float> reduced = reduceDepth(depth, 3, 1);
        int vessels = 0;
        for (int x = 0; x < 3; ++x) {
            vessels += std::isfinite(reduced(x, 0)) ? 1 : 0;
        }
        EXPECT_EQ(vessels, 1) << "column " << column;
        // The one whose span holds the pixel's centre: (column + 0.5) * 3 / 7.
        EXPECT_TRUE(std::isfinite(reduced((2 * column + 1) * 3 / 14, 0))) << "column " << column;
    }
}

TEST(ReducedContourDepthTest, ReducingToALargerSizeThrows) {
    const Image<float> depth(4, 4, kInf);
    EXPECT_THROW(static_cast<void>(reduceDepth(depth, 5, 4)), InvalidArgumentError);
    EXPECT_THROW(static_cast<void>(reduceDepth(depth, 0, 4)), InvalidArgumentError);
}

}  // namespace
}  // namespace vv::render
