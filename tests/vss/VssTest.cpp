// SPDX-License-Identifier: GPL-3.0-or-later
// The pipeline: normalisation, regions, interpolation, statistics.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stop_token>

#include "VssTestUtil.h"
#include "vv/core/Error.h"
#include "vv/vss/Vss.h"

namespace vv::vss {
namespace {

VssOptions bruteOptions(double p = 2.0) {
    VssOptions o;
    o.solver.kind = SolverKind::Brute;
    o.solver.p = p;
    return o;
}

TEST(VssPipelineTest, ResultFieldsAndStatistics) {
    const auto mask = test::randomMask(64, 48, 12);
    const auto depth = test::randomDepth(64, 48, 12, 100.0, 300.0);
    const VssResult r = solve(depth.view(), mask.view(), bruteOptions());
    const auto naive = test::naiveRegions(mask.view());
    ASSERT_EQ(r.regions.size(), naive.contours.size());
    EXPECT_EQ(r.stats.regionCount, r.regions.size());
    ASSERT_EQ(r.stats.contourPixels.size(), r.regions.size());
    std::int64_t maxContour = 0;
    std::int64_t voidPixels = 0;
    for (std::size_t i = 0; i < r.regions.size(); ++i) {
        EXPECT_EQ(r.stats.contourPixels[i], static_cast<std::int64_t>(naive.contours[i].size()));
        maxContour = std::max<std::int64_t>(maxContour, naive.contours[i].size());
        voidPixels += naive.counts[i];
    }
    EXPECT_EQ(r.stats.maxContourPixels, maxContour);
    EXPECT_EQ(r.stats.voidPixels, voidPixels);
    EXPECT_GE(r.stats.normalizeMs, 0.0);
    EXPECT_GE(r.stats.regionsMs, 0.0);
    EXPECT_GE(r.stats.interpolateMs, 0.0);
    EXPECT_EQ(r.errorBound, 0.0);
    // dmin / dmax in scene units: the vessel pixels' range.
    double lo = 1e30;
    double hi = -1e30;
    for (int y = 0; y < 48; ++y) {
        for (int x = 0; x < 64; ++x) {
            if (mask(x, y) != 0) {
                lo = std::min<double>(lo, depth(x, y));
                hi = std::max<double>(hi, depth(x, y));
            }
        }
    }
    EXPECT_EQ(r.dmin, lo);
    EXPECT_EQ(r.dmax, hi);
    EXPECT_FALSE(r.flat);
    // Vessel pixels keep their own z; contour points carry it.
    for (int y = 0; y < 48; ++y) {
        for (int x = 0; x < 64; ++x) {
            if (mask(x, y) != 0) {
                EXPECT_FLOAT_EQ(r.height(x, y), static_cast<float>((depth(x, y) - lo) / (hi - lo)));
                EXPECT_EQ(r.labels(x, y), kVesselLabel);
            }
        }
    }
    for (const auto& region : r.regions) {
        for (const auto& c : region.contour) {
            EXPECT_EQ(c.z, r.height(c.x, c.y));
        }
    }
}

TEST(VssPipelineTest, NonFiniteVesselDepthIsBackground) {
    // A vessel column with a NaN hole: the hole joins the two sides.
    Image<std::uint8_t> mask(5, 5, 0);
    Image<float> depth(5, 5, 1.0F);
    for (int y = 0; y < 5; ++y) {
        mask(2, y) = 1;
        depth(2, y) = static_cast<float>(y);
    }
    depth(2, 2) = std::numeric_limits<float>::quiet_NaN();
    const VssResult r = solve(depth.view(), mask.view(), bruteOptions());
    EXPECT_EQ(r.regions.size(), 1U);
    EXPECT_NE(r.labels(2, 2), kVesselLabel);
    EXPECT_TRUE(std::isfinite(r.height(2, 2)));
}

TEST(VssPipelineTest, FixedRangeAndCancellation) {
    const auto mask = test::randomMask(30, 20, 5);
    const auto depth = test::randomDepth(30, 20, 5, 10.0, 20.0);
    VssOptions o = bruteOptions();
    o.range = {RangeMode::Fixed, 0.0, 40.0};
    const VssResult r = solve(depth.view(), mask.view(), o);
    EXPECT_EQ(r.dmin, 0.0);
    EXPECT_EQ(r.dmax, 40.0);
    for (int y = 0; y < 20; ++y) {
        for (int x = 0; x < 30; ++x) {
            EXPECT_GE(r.height(x, y), 0.25F - 1e-6F);
            EXPECT_LE(r.height(x, y), 0.5F + 1e-6F);
        }
    }
    std::stop_source stop;
    stop.request_stop();
    o.stop = stop.get_token();
    EXPECT_THROW(static_cast<void>(solve(depth.view(), mask.view(), o)), CancelledError);
}

TEST(VssPipelineTest, InvalidArguments) {
    const Image<std::uint8_t> mask(3, 3, 0);
    const Image<float> depth(3, 4, 1.0F);
    EXPECT_THROW(static_cast<void>(solve(depth.view(), mask.view(), bruteOptions())),
                 InvalidArgumentError);
    const Image<float> ok(3, 3, 1.0F);
    EXPECT_THROW(static_cast<void>(solve(ok.view(), mask.view(), bruteOptions(-1.0))),
                 InvalidArgumentError);
}

TEST(VssPipelineTest, ManySmallRegionsAreSolved) {
    // A fine grid of vessel lines: hundreds of small regions, solved in batches.
    Image<std::uint8_t> mask(200, 150, 0);
    for (int y = 0; y < 150; ++y) {
        for (int x = 0; x < 200; ++x) {
            mask(x, y) = (x % 5 == 0 || y % 4 == 0) ? 1 : 0;
        }
    }
    const auto depth = test::randomDepth(200, 150, 8);
    const VssResult r = solve(depth.view(), mask.view(), bruteOptions(4.0));
    EXPECT_EQ(r.regions.size(), 40U * 37U + 40U);  // 40 x 38 cells, the last row of cells 1 high
    for (int y = 0; y < 150; ++y) {
        for (int x = 0; x < 200; ++x) {
            ASSERT_TRUE(std::isfinite(r.height(x, y))) << x << ", " << y;
        }
    }
}

}  // namespace
}  // namespace vv::vss
