// SPDX-License-Identifier: GPL-3.0-or-later
// The band boxes of the fast VSS solver (modules/vss/src/FastBandBox.cpp):
// 32-pixel boxes of the near-contour band on an adaptive grid, cell by cell,
// with the pixels of failing cells summed exactly. Every void pixel is
// compared with the exact sum: they must keep the tolerance (odd sizes, p up
// to the largest they are tried for, tiny depth ranges), be taken with both
// interpolated and exact pixels, and their per-cell bound must be what keeps
// the tolerance.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "FastSolverTestUtil.h"
#include "FastStats.h"
#include "vv/core/Image.h"

namespace vv::vss {
namespace {

using namespace fasttest;  // NOLINT(google-build-using-namespace): the shared test scenes

/// Vessels whose contour depth changes slowly along them, crossing the image
/// and one another at different depths: the band boxes see contours inside
/// them (partial grids), and pixels next to a crossing see two depths.
Scene crossingScene(int w, int h, double depthRange) {
    Image<std::uint8_t> mask(w, h, 0);
    paintLine(mask, 5.0, 0.3 * h, w - 5.0, 0.55 * h, 2.0);
    paintLine(mask, 0.4 * w, 3.0, 0.6 * w, h - 3.0, 1.5);
    paintLine(mask, 0.1 * w, h - 8.0, 0.9 * w, 0.1 * h, 1.0);
    Image<float> z(w, h, 0.0F);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const double t = 0.25 + 0.5 * (x + 0.5 * y) / (w + 0.5 * h) + 0.03 * std::sin(0.07 * y);
            z(x, y) = static_cast<float>(0.5 + depthRange * (t - 0.5));
        }
    }
    return makeScene(mask, z);
}

TEST(FastBandBoxTest, AreTakenAndKeepTheToleranceOnEveryPixel) {
    struct Case {
        int w, h;
        double depthRange;
        int kind;  // 0 crossing, 1 far field (rough contour), 2 random tree
    };
    const Case cases[] = {{289, 223, 1.0, 0},
                          {256, 192, 0.02, 0},
                          {255, 193, 6.0 / 255.0, 0},
                          {257, 191, 1.0, 1},
                          {301, 203, 1.0, 2}};
    std::int64_t bandPixels = 0;
    std::int64_t exactPixels = 0;
    for (const Case& k : cases) {
        const Scene s = k.kind == 0   ? crossingScene(k.w, k.h, k.depthRange)
                        : k.kind == 1 ? farFieldScene(k.w, k.h, k.depthRange, false)
                                      : randomScene(k.w, k.h, MaskKind::Tree, 5);
        for (const double p : {0.5, 1.0, 2.0, 3.0, 4.0, 8.0}) {
            const Image<double> ref = referenceImage(s, p);
            for (const double tol : {0.5 / 255.0, 1e-3, 1e-2}) {
                detail::resetFastSolverStats();
                const Check c = compare(s, solveAll(s, p, tol), ref);
                const detail::FastSolverStats st = detail::fastSolverStats();
                EXPECT_EQ(c.bad, 0) << "case " << k.kind << " p " << p << " tol " << tol;
                EXPECT_LE(c.maxErr, tol) << "case " << k.kind << " range " << k.depthRange << " p "
                                         << p << " tol " << tol;
                // regions whose depth range is <= 2 tol get their mid-range, uncounted
                EXPECT_LE(st.pixels, c.pixels) << "case " << k.kind << " tol " << tol;
                EXPECT_LE(st.bandExactPixels, st.bandBoxPixels);
                if (p > 4.0) {
                    EXPECT_EQ(st.bandBoxPixels, 0) << "tried only for p <= 4";
                }
                bandPixels += st.bandBoxPixels;
                exactPixels += st.bandExactPixels;
            }
        }
    }
    // taken, with both interpolated cells and exact pixels
    EXPECT_GT(bandPixels, 0);
    EXPECT_GT(exactPixels, 0);
    EXPECT_GT(bandPixels, 4 * exactPixels);
}

TEST(FastBandBoxTest, OnAndOffAgreeWithinTheTolerance) {
    // Switched off, the band's boxes go down to the leaf tiles as before
    // (more leaves, more translations); both within the tolerance.
    const Scene s = crossingScene(256, 192, 1.0);
    const double tol = 0.5 / 255.0;
    for (const double p : {1.0, 2.0, 4.0}) {
        const Image<double> ref = referenceImage(s, p);
        detail::setFastSolverBandBoxesForTesting(false);
        detail::resetFastSolverStats();
        const Image<float> off = solveAll(s, p, tol);
        const detail::FastSolverStats stOff = detail::fastSolverStats();
        detail::setFastSolverBandBoxesForTesting(true);
        detail::resetFastSolverStats();
        const Image<float> on = solveAll(s, p, tol);
        const detail::FastSolverStats stOn = detail::fastSolverStats();
        EXPECT_EQ(stOff.bandBoxPixels, 0);
        EXPECT_GT(stOn.bandBoxPixels, 0) << p;
        EXPECT_LT(stOn.leaves, stOff.leaves) << p;
        EXPECT_LT(stOn.m2l, stOff.m2l) << p;
        EXPECT_LE(compare(s, off, ref).maxErr, tol) << p;
        const Check cOn = compare(s, on, ref);
        EXPECT_LE(cOn.maxErr, tol) << p;
        EXPECT_EQ(cOn.bad, 0) << p;
    }
}

TEST(FastBandBoxTest, ThePerCellBoundIsWhatKeepsTheTolerance) {
    // With the interpolation terms of the per-cell bound scaled down, cells
    // next to the contours pass that should not, and some pixel leaves the
    // tolerance (so this scene and these tolerances do test the bound); with
    // the bound as it is, every pixel is within the tolerance.
    const Scene scenes[] = {crossingScene(200, 150, 1.0), randomScene(220, 160, MaskKind::Tree, 7)};
    double worstScaled = 0.0;  // largest error / tol with the bound scaled down
    for (const Scene& s : scenes) {
        for (const double p : {1.0, 2.0, 4.0}) {
            const Image<double> ref = referenceImage(s, p);
            for (const double tol : {0.5 / 255.0, 1e-3}) {
                detail::setFastSolverBandBoundScaleForTesting(0.01);
                const Check scaled = compare(s, solveAll(s, p, tol), ref);
                detail::setFastSolverBandBoundScaleForTesting(1.0);
                worstScaled = std::max(worstScaled, scaled.maxErr / tol);
                const Check c = compare(s, solveAll(s, p, tol), ref);
                EXPECT_EQ(c.bad, 0) << p;
                EXPECT_LE(c.maxErr, tol) << "p " << p << " tol " << tol;
            }
        }
    }
    EXPECT_GT(worstScaled, 1.0);
}

}  // namespace
}  // namespace vv::vss
