// SPDX-License-Identifier: GPL-3.0-or-later
// The "upscale" pass draws the iso-lines only in the parts of the target
// splitUpscaleTiles says they can reach: checked against upscale.frag's
// coverage, evaluated here pixel by pixel as the shader does (bilinear
// height, derivatives within 2x2 quads).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "passes/UpscaleTiles.h"
#include "vv/core/Error.h"

namespace vv::render {
namespace {

/// upscale.frag's bilinear, clamped height at target pixel (x, y) (centre
/// at +0.5, clamp to edge).
double heightAt(const Image<float>& h, glm::ivec2 target, int x, int y) {
    const auto texel = [](float v) { return std::isfinite(v) ? std::clamp(v, 0.0F, 1.0F) : 0.0F; };
    const double tx = (x + 0.5) * h.width() / target.x - 0.5;
    const double ty = (y + 0.5) * h.height() / target.y - 0.5;
    const int x0 = static_cast<int>(std::floor(tx));
    const int y0 = static_cast<int>(std::floor(ty));
    const double fx = tx - x0;
    const double fy = ty - y0;
    const auto at = [&](int i, int j) {
        return static_cast<double>(
            texel(h(std::clamp(i, 0, h.width() - 1), std::clamp(j, 0, h.height() - 1))));
    };
    const double top = at(x0, y0) * (1 - fx) + at(x0 + 1, y0) * fx;
    const double bottom = at(x0, y0 + 1) * (1 - fx) + at(x0 + 1, y0 + 1) * fx;
    return top * (1 - fy) + bottom * fy;
}

/// upscale.frag's iso-line coverage at (x, y), with the derivatives of its
/// 2x2 quad.
double coverage(const Image<float>& h, glm::ivec2 target, int x, int y, int lines, float width) {
    const int qx = x & ~1;
    const int qy = y & ~1;
    const double z = heightAt(h, target, x, y);
    const double dx = heightAt(h, target, qx + 1, qy) - heightAt(h, target, qx, qy);
    const double dy = heightAt(h, target, qx, qy + 1) - heightAt(h, target, qx, qy);
    const double perPixel = std::hypot(dx, dy) * lines;
    const double q = z * lines;
    const double f = q - std::floor(q);
    const double pixels = std::min(f, 1.0 - f) / std::max(perPixel, 1e-6);
    const double half = 0.5 * width;
    const double t = std::clamp((pixels - (half - 0.5)), 0.0, 1.0);
    return 1.0 - t * t * (3 - 2 * t);
}

bool inside(const std::vector<glm::ivec4>& rects, int x, int y) {
    return std::any_of(rects.begin(), rects.end(), [&](const glm::ivec4& r) {
        return x >= r.x && x < r.z && y >= r.y && y < r.w;
    });
}

/// A VSS-like height: a smooth bowl with a steep ring and a patch of "no
/// VSS" (non-finite) texels.
Image<float> bowl(int w, int h) {
    Image<float> height(w, h, 0.0F);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const double u = (x - 0.4 * w) / w;
            const double v = (y - 0.6 * h) / h;
            const double r = std::sqrt(u * u + v * v);
            height(x, y) = static_cast<float>(0.2 + 0.9 * r * r + 0.05 * std::tanh(40 * (r - 0.3)));
            if (x > w / 2 && x < w / 2 + 9 && y > h / 3 && y < h / 3 + 7) {
                height(x, y) = std::numeric_limits<float>::quiet_NaN();
            }
        }
    }
    return height;
}

TEST(UpscaleTilesTest, NoPixelOutsideTheLineTilesGetsIsoLineCoverage) {
    // Odd target sizes (the last tiles are partial) and several reductions.
    for (const glm::ivec2 size : {glm::ivec2(160, 90), glm::ivec2(79, 45), glm::ivec2(213, 120)}) {
        const Image<float> height = bowl(size.x, size.y);
        for (const int lines : {4, 8, 20}) {
            for (const float width : {1.5F, 4.0F}) {
                const glm::ivec2 target(333, 181);
                const UpscaleTiles tiles = splitUpscaleTiles(height, target, lines, width, 16);
                long long plainPixels = 0;
                long long coveredPixels = 0;
                for (int y = 0; y < target.y; ++y) {
                    for (int x = 0; x < target.x; ++x) {
                        const bool plain = inside(tiles.plain, x, y);
                        ASSERT_NE(plain, inside(tiles.lines, x, y)) << "every pixel once";
                        const double c = coverage(height, target, x, y, lines, width);
                        coveredPixels += c > 0.0 ? 1 : 0;
                        if (plain) {
                            ++plainPixels;
                            ASSERT_EQ(c, 0.0) << "pixel " << x << ", " << y << " of " << size.x
                                              << "x" << size.y << ", " << lines << " lines";
                        }
                    }
                }
                // It saves something where the lines are sparse, and the lines show.
                if (lines <= 8) {
                    EXPECT_GT(plainPixels, static_cast<long long>(target.x) * target.y / 20)
                        << lines << " lines, width " << width;
                }
                EXPECT_GT(coveredPixels, 0);
            }
        }
    }
}

TEST(UpscaleTilesTest, WithoutIsoLinesOrLevelsEverythingIsPlain) {
    const glm::ivec2 target(100, 60);
    UpscaleTiles tiles = splitUpscaleTiles(bowl(50, 30), target, 0, 1.5F, 16);
    EXPECT_TRUE(tiles.lines.empty());
    // Neighbours along a row merge: one rectangle per row of tiles.
    ASSERT_EQ(tiles.plain.size(), 4U);
    EXPECT_EQ(tiles.plain.front(), glm::ivec4(0, 0, 100, 16));
    EXPECT_EQ(tiles.plain.back(), glm::ivec4(0, 48, 100, 60));
    // A flat height between two levels: no line anywhere.
    tiles = splitUpscaleTiles(Image<float>(50, 30, 0.3F), target, 8, 1.5F, 16);
    EXPECT_TRUE(tiles.lines.empty());
    // On a level: lines everywhere (a flat height on a level is all line).
    tiles = splitUpscaleTiles(Image<float>(50, 30, 0.25F), target, 8, 1.5F, 16);
    EXPECT_TRUE(tiles.plain.empty());
}

TEST(UpscaleTilesTest, BadArgumentsThrow) {
    const Image<float> height(8, 8, 0.5F);
    EXPECT_THROW(static_cast<void>(splitUpscaleTiles(height, {0, 10}, 8, 1.5F, 16)),
                 InvalidArgumentError);
    EXPECT_THROW(static_cast<void>(splitUpscaleTiles(Image<float>(), {10, 10}, 8, 1.5F, 16)),
                 InvalidArgumentError);
    EXPECT_THROW(static_cast<void>(splitUpscaleTiles(height, {10, 10}, 8, 1.5F, 15)),
                 InvalidArgumentError);
}

}  // namespace
}  // namespace vv::render
