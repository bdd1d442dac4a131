// SPDX-License-Identifier: GPL-3.0-or-later
// The vessels' silhouettes of a reduced frame as the "upscale" pass draws
// them (SilhouetteRuns.h): rebuilt from the render pixels' staircase, they
// lie on the straight edge the staircase samples; and the rectangles the
// EDGES program is drawn in hold every target pixel whose bilinear
// footprint straddles a silhouette (upscale.frag's test, evaluated here
// pixel by pixel as the shader does).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <vector>

#include "passes/SilhouetteRuns.h"
#include "vv/core/Error.h"

namespace vv::render::silhouette_runs_test {
namespace {

bool inside(const std::vector<glm::ivec4>& rects, int x, int y) {
    return std::any_of(rects.begin(), rects.end(), [&](const glm::ivec4& r) {
        return x >= r.x && x < r.z && y >= r.y && y < r.w;
    });
}

/// Whether upscale.frag's EDGES variant sees a silhouette at target pixel
/// (x, y): its bilinear footprint (the 2x2 texels around the pixel's
/// centre, clamped to the edge) holds vessel and other texels.
bool edgePixel(const Image<std::uint8_t>& vessels, glm::ivec2 target, int x, int y) {
    const double tx = (x + 0.5) * vessels.width() / target.x - 0.5;
    const double ty = (y + 0.5) * vessels.height() / target.y - 0.5;
    const int x0 = static_cast<int>(std::floor(tx));
    const int y0 = static_cast<int>(std::floor(ty));
    int n = 0;
    for (int j = 0; j < 2; ++j) {
        for (int i = 0; i < 2; ++i) {
            n += vessels(std::clamp(x0 + i, 0, vessels.width() - 1),
                         std::clamp(y0 + j, 0, vessels.height() - 1));
        }
    }
    return n > 0 && n < 4;
}

/// A render size's depth with vessels: a slanted band and a disc (finite),
/// one vessel pixel alone, the rest +Inf.
Image<float> vesselDepth(int w, int h) {
    Image<float> depth(w, h, std::numeric_limits<float>::infinity());
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const double u = static_cast<double>(x) / w;
            const double v = static_cast<double>(y) / h;
            const bool band = std::abs(v - 0.3 - 0.4 * u) < 0.05;
            const bool disc = std::hypot(u - 0.75, v - 0.25) < 0.12;
            if (band || disc) {
                depth(x, y) = static_cast<float>(1.0 + u);
            }
        }
    }
    depth(w / 5, h - 3) = 2.0F;
    return depth;
}

TEST(SilhouetteRunsTest, EveryPixelOnASilhouetteIsInARect) {
    for (const glm::ivec2 size : {glm::ivec2(160, 90), glm::ivec2(79, 45), glm::ivec2(213, 120)}) {
        const Image<std::uint8_t> vessels = vesselMask(vesselDepth(size.x, size.y));
        for (const glm::ivec2 target : {glm::ivec2(333, 181), glm::ivec2(380, 214)}) {
            const std::vector<glm::ivec4> rects = silhouetteRects(vessels, target);
            long long edgePixels = 0;
            for (int y = 0; y < target.y; ++y) {
                for (int x = 0; x < target.x; ++x) {
                    if (edgePixel(vessels, target, x, y)) {
                        ++edgePixels;
                        ASSERT_TRUE(inside(rects, x, y))
                            << "pixel " << x << ", " << y << " of " << size.x << "x" << size.y
                            << " into " << target.x << "x" << target.y;
                    }
                }
            }
            long long area = 0;
            for (const glm::ivec4& r : rects) {
                EXPECT_TRUE(r.x >= 0 && r.y >= 0 && r.z <= target.x && r.w <= target.y);
                area += static_cast<long long>(r.z - r.x) * (r.w - r.y);
            }
            EXPECT_GT(edgePixels, 0);
            // The program runs on little more than the pixels that need it.
            EXPECT_LT(area, 3 * edgePixels);
        }
    }
}

/// The offset (texels) `runs` puts the silhouette at, from the midline of
/// the pair at `texel`, at `along` texels from its centre (-0.5 .. 0.5):
/// as upscale.frag reads it. `steep`: the pair with the texel to the right.
double rebuilt(const Image<glm::u8vec4>& runs, glm::ivec2 texel, bool steep, double along) {
    const glm::u8vec4 t = runs(texel.x, texel.y);
    const double a = t[steep ? 2 : 0] / 255.0 - 0.5;
    const double b = t[steep ? 3 : 1] / 255.0 - 0.5;
    return a + (b - a) * (along + 0.5);
}

TEST(SilhouetteRunsTest, ARebuiltSilhouetteLiesOnTheEdgeItsStepsSample) {
    // Half planes at 3 to 35 degrees off the x axis (vessel below the
    // line through the texel centres' grid), and their transposes: where the
    // rebuilt edge crosses each straddling pair, against the line. The
    // staircase itself (the pairs' midlines) is a quarter texel off on
    // average.
    const int w = 240;
    const int h = 240;
    for (const double degrees : {3.0, 8.0, 15.0, 24.0, 35.0}) {
        for (const bool steep : {false, true}) {
            const double slope = std::tan(degrees * std::numbers::pi / 180.0);
            const double c = 100.37;
            Image<std::uint8_t> vessels(w, h, 0);
            for (int y = 0; y < h; ++y) {
                for (int x = 0; x < w; ++x) {
                    const double along = steep ? y : x;
                    const double across = steep ? x : y;
                    vessels(x, y) = across < slope * along + c ? 1 : 0;
                }
            }
            const Image<glm::u8vec4> runs = silhouetteRuns(vessels);
            double error = 0.0;
            double staircase = 0.0;
            int n = 0;
            for (int a = 20; a < 220; ++a) {
                for (int b = 0; b + 1 < 240; ++b) {
                    const glm::ivec2 t = steep ? glm::ivec2(b, a) : glm::ivec2(a, b);
                    const glm::ivec2 next = steep ? glm::ivec2(b + 1, a) : glm::ivec2(a, b + 1);
                    if (vessels(t.x, t.y) == vessels(next.x, next.y)) {
                        continue;
                    }
                    const double line = slope * a + c;  // across, at the pair's centre
                    for (const double along : {-0.4, 0.0, 0.4}) {
                        const double truth = line + slope * along;
                        error += std::abs(b + 0.5 + rebuilt(runs, t, steep, along) - truth);
                        staircase += std::abs(b + 0.5 - truth);
                        ++n;
                    }
                }
            }
            ASSERT_GT(n, 500);
            error /= n;
            staircase /= n;
            std::printf("%.0f degrees%s: rebuilt edge %.3f texels off the line, staircase %.3f\n",
                        degrees, steep ? " (steep)" : "", error, staircase);
            EXPECT_LT(error, 0.5 * staircase) << degrees << " degrees, steep " << steep;
            EXPECT_LT(error, 0.15) << degrees << " degrees, steep " << steep;
        }
    }
}

TEST(SilhouetteRunsTest, PairsOffTheSilhouettesHoldNoOffset) {
    Image<float> depth(20, 10, std::numeric_limits<float>::infinity());
    depth(5, 5) = 1.0F;
    const Image<glm::u8vec4> runs = silhouetteRuns(vesselMask(depth));
    const glm::u8vec4 none(128);
    EXPECT_EQ(runs(0, 0), none);
    EXPECT_EQ(runs(15, 8), none);
    // The lone pixel: a pair with the one above and with the one to the
    // right, each a run of one with a step towards the vessel pixel at both
    // ends: a bump, drawn as a bar a quarter texel past its centre (the
    // bump's mean height) instead of vanishing.
    EXPECT_EQ(runs(5, 5), glm::u8vec4(64));
    EXPECT_TRUE(silhouetteRects(vesselMask(Image<float>(20, 10, 1.0F)), {40, 20}).empty());
    EXPECT_FALSE(silhouetteRects(vesselMask(depth), {40, 20}).empty());
}

TEST(SilhouetteRunsTest, BadArgumentsThrow) {
    const Image<std::uint8_t> vessels(8, 8, 0);
    EXPECT_THROW(static_cast<void>(silhouetteRuns(vessels, -1)), InvalidArgumentError);
    EXPECT_THROW(static_cast<void>(silhouetteRects(Image<std::uint8_t>(), {10, 10})),
                 InvalidArgumentError);
    EXPECT_THROW(static_cast<void>(silhouetteRects(vessels, {0, 10})), InvalidArgumentError);
}

}  // namespace
}  // namespace vv::render::silhouette_runs_test
