// SPDX-License-Identifier: GPL-3.0-or-later
// The near boxes of the fast VSS solver (modules/vss/src/FastNearBox.cpp):
// boxes of the near-contour band evaluated on a coarse grid with their near
// points summed exactly. They must be taken, keep the tolerance on every void
// pixel (odd sizes, p from 0.5 to 64, tiny depth ranges, a single speck), and
// their interpolation bound, not the a-priori estimate, must be what decides.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "FastSolverTestUtil.h"
#include "FastStats.h"
#include "vv/core/Image.h"

namespace vv::vss {
namespace {

using namespace fasttest;  // NOLINT(google-build-using-namespace): the shared test scenes

/// Two vessels far apart at very different depths (0.1 and 0.9 for range 1,
/// scaled around 0.5 by depthRange), each with a depth that changes slowly
/// along it: the region's depth range is large, the spread of the contour
/// near either vessel small.
Scene twoDepthsScene(int w, int h, double depthRange = 1.0) {
    Image<std::uint8_t> mask(w, h, 0);
    paintLine(mask, 10.0, 10.0, 10.0, h - 10.0, 2.0);
    paintLine(mask, w - 10.0, 10.0, w - 10.0, h - 10.0, 2.0);
    Image<float> z(w, h, 0.0F);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const double base = x < w / 2 ? 0.1 : 0.9;
            const double t = base + 0.02 * std::sin(0.05 * y);
            z(x, y) = static_cast<float>(0.5 + depthRange * (t - 0.5));
        }
    }
    return makeScene(mask, z);
}

TEST(FastNearBoxTest, AreTakenAndKeepTheToleranceOnEveryPixel) {
    // Every void pixel against the exact reference, the stiff cases included:
    // p up to 64, tiny depth ranges (just above the 2 tol below which a region
    // gets its mid-range), one contour pair, odd sizes.
    // Strokes whose depth varies fast along them (a rough contour), and two
    // smooth vessels far apart (where the near boxes are taken).
    struct Case {
        int w, h;
        double depthRange;
        bool speck, smooth;
    };
    const Case cases[] = {{289, 223, 1.0, false, false}, {288, 224, 0.02, false, false},
                          {288, 224, 1.0, true, false},  {257, 191, 1.0, false, true},
                          {255, 193, 0.02, false, true}, {256, 192, 6.0 / 255.0, false, true}};
    std::int64_t nearAt2 = 0;
    for (const Case& k : cases) {
        const Scene s = k.smooth ? twoDepthsScene(k.w, k.h, k.depthRange)
                                 : farFieldScene(k.w, k.h, k.depthRange, k.speck);
        for (const double p : {0.5, 1.0, 2.0, 4.0, 8.0, 64.0}) {
            const Image<double> ref = referenceImage(s, p);
            for (const double tol : {0.5 / 255.0, 1e-3, 1e-2}) {
                detail::resetFastSolverStats();
                const Check c = compare(s, solveAll(s, p, tol), ref);
                const detail::FastSolverStats st = detail::fastSolverStats();
                EXPECT_EQ(c.bad, 0) << "range " << k.depthRange << " p " << p << " tol " << tol;
                EXPECT_LE(c.maxErr, tol)
                    << "range " << k.depthRange << " p " << p << " tol " << tol;
                if (st.pixels > 0) {  // else the region got its mid-range (range <= 2 tol)
                    EXPECT_EQ(st.pixels, c.pixels);
                }
                EXPECT_LE(st.nearBoxPixels, st.pixels);
                if (p == 2.0 && tol == 0.5 / 255.0) {
                    nearAt2 += st.nearBoxPixels;
                    if (k.smooth && k.depthRange == 1.0) {
                        EXPECT_GT(st.nearBoxes, 0);
                        EXPECT_GT(st.nearBoxPixels, 0);
                    }
                }
            }
        }
    }
    EXPECT_GT(nearAt2, 0);
}

TEST(FastNearBoxTest, TreesAtOddSizesKeepTheTolerance) {
    for (const std::uint64_t seed : {3U, 11U}) {
        const Scene s = randomScene(301, 203, MaskKind::Tree, seed);
        for (const double p : {1.0, 2.0, 4.0, 8.0}) {
            const Image<double> ref = referenceImage(s, p);
            detail::resetFastSolverStats();
            const Check c = compare(s, solveAll(s, p, 0.5 / 255.0), ref);
            EXPECT_EQ(c.bad, 0) << seed << " p " << p;
            EXPECT_LE(c.maxErr, 0.5 / 255.0) << seed << " p " << p;
        }
    }
}

TEST(FastNearBoxTest, TheBoundUsesTheLocalDepthSpread) {
    // The region's range is 0.8 + 0.04: a bound from the whole range,
    // h^2 / 4 p (p + 1) dz / rho^2, would need rho of hundreds of pixels at
    // p = 4 and 0.5/255, more than this image has. Near boxes are taken all
    // the same: the bound sees the depths of the contour near each box.
    const Scene s = twoDepthsScene(256, 192);
    const double tol = 0.5 / 255.0;
    for (const double p : {2.0, 4.0}) {
        const Image<double> ref = referenceImage(s, p);
        detail::resetFastSolverStats();
        const Check c = compare(s, solveAll(s, p, tol), ref);
        const detail::FastSolverStats st = detail::fastSolverStats();
        EXPECT_EQ(c.bad, 0) << p;
        EXPECT_LE(c.maxErr, tol) << p;
        EXPECT_GT(st.nearBoxes, 0) << p;
        EXPECT_GT(st.nearBoxPixels, c.pixels / 10) << p;
    }
}

TEST(FastNearBoxTest, OnAndOffAgreeWithinTheTolerance) {
    // Switched off, no pixel comes from a near box and more leaf tiles are
    // evaluated; both within the tolerance. (The band boxes, FastBandBox.h,
    // would take the leaf tiles of either: off here.)
    const Scene s = twoDepthsScene(256, 192);
    const double tol = 0.5 / 255.0;
    detail::setFastSolverBandBoxesForTesting(false);
    for (const double p : {1.0, 2.0, 4.0}) {
        const Image<double> ref = referenceImage(s, p);
        detail::setFastSolverNearBoxesForTesting(false);
        detail::resetFastSolverStats();
        const Image<float> off = solveAll(s, p, tol);
        const detail::FastSolverStats stOff = detail::fastSolverStats();
        detail::setFastSolverNearBoxesForTesting(true);
        detail::resetFastSolverStats();
        const Image<float> on = solveAll(s, p, tol);
        const detail::FastSolverStats stOn = detail::fastSolverStats();
        EXPECT_EQ(stOff.nearBoxPixels, 0);
        EXPECT_GT(stOn.nearBoxPixels, 0) << p;
        EXPECT_LT(stOn.leaves, stOff.leaves) << p;
        EXPECT_LE(compare(s, off, ref).maxErr, tol) << p;
        const Check cOn = compare(s, on, ref);
        EXPECT_LE(cOn.maxErr, tol) << p;
        EXPECT_EQ(cOn.bad, 0) << p;
    }
    detail::setFastSolverBandBoxesForTesting(true);  // the default
}

TEST(FastNearBoxTest, DoNotRestOnTheAPrioriEstimate) {
    // With the estimate (and the budget) 30x too loose, boxes close to the
    // contours, where z' bends fast, reach the interpolation bound: it must
    // refuse those whose samples are too far apart.
    const Scene scenes[] = {farFieldScene(256, 192, 1.0, false),
                            randomScene(200, 150, MaskKind::Tree, 8), twoDepthsScene(160, 120)};
    for (const Scene& s : scenes) {
        for (const double p : {1.0, 2.0, 8.0}) {
            const Image<double> ref = referenceImage(s, p);
            for (const double tol : {0.5 / 255.0, 0.05}) {
                detail::setFastSolverBudgetScaleForTesting(30.0);
                detail::resetFastSolverStats();
                const Image<float> out = solveAll(s, p, tol);
                const detail::FastSolverStats st = detail::fastSolverStats();
                detail::setFastSolverBudgetScaleForTesting(1.0);
                const Check c = compare(s, out, ref);
                EXPECT_EQ(c.bad, 0) << p;
                EXPECT_LE(c.maxErr, tol) << "p " << p << " tol " << tol << ", " << st.nearBoxPixels
                                         << " near-box pixels";
            }
        }
    }
}

TEST(FastNearBoxTest, SplitClustersSumOnlyTheNearPointsAndKeepTheTolerance) {
    // A near box splits the clusters it could not expand and expands the parts
    // far enough from it into its own expansion (their truncation charged to
    // the box's bound): fewer points summed at its samples, every pixel within
    // the tolerance, also with the a-priori budget 30x too loose (the expanded
    // parts then carry large truncation bounds that the box's check must see).
    const Scene scenes[] = {twoDepthsScene(256, 192), randomScene(301, 203, MaskKind::Tree, 3),
                            farFieldScene(256, 192, 1.0, false)};
    // points summed per near-box pixel, on and off
    double pointsOn = 0.0;
    double pointsOff = 0.0;
    double pixelsOn = 0.0;
    double pixelsOff = 0.0;
    for (const Scene& s : scenes) {
        for (const double p : {1.0, 2.0, 4.0, 8.0}) {
            const Image<double> ref = referenceImage(s, p);
            for (const double scale : {1.0, 30.0, 1e3, 1e5}) {
                for (const double tol : {0.5 / 255.0, 0.02}) {
                    detail::setFastSolverNearSplitBudgetScaleForTesting(scale);
                    detail::setFastSolverNearSplitForTesting(false);
                    detail::resetFastSolverStats();
                    const Image<float> off = solveAll(s, p, tol);
                    const detail::FastSolverStats stOff = detail::fastSolverStats();
                    detail::setFastSolverNearSplitForTesting(true);
                    detail::resetFastSolverStats();
                    const Image<float> on = solveAll(s, p, tol);
                    const detail::FastSolverStats stOn = detail::fastSolverStats();
                    detail::setFastSolverNearSplitBudgetScaleForTesting(1.0);
                    const Check c = compare(s, on, ref);
                    EXPECT_EQ(c.bad, 0) << "p " << p << " scale " << scale << " tol " << tol;
                    EXPECT_LE(c.maxErr, tol) << "p " << p << " scale " << scale << " tol " << tol
                                             << ", " << stOn.nearBoxPixels << " near-box pixels";
                    EXPECT_LE(compare(s, off, ref).maxErr, tol);
                    if (scale == 1.0) {
                        pointsOn += static_cast<double>(stOn.nearBoxPoints);
                        pointsOff += static_cast<double>(stOff.nearBoxPoints);
                        pixelsOn += static_cast<double>(stOn.nearBoxPixels);
                        pixelsOff += static_cast<double>(stOff.nearBoxPixels);
                    }
                }
            }
        }
    }
    detail::setFastSolverNearSplitForTesting(false);  // the default
    ASSERT_GT(pixelsOn, 0.0);
    ASSERT_GT(pixelsOff, 0.0);
    EXPECT_LT(pointsOn / pixelsOn, 0.8 * pointsOff / pixelsOff);
}

}  // namespace
}  // namespace vv::vss
