// SPDX-License-Identifier: GPL-3.0-or-later
// choosePreviewLevel: which simplified copy a moving frame of a given size draws.
#include <gtest/gtest.h>

#include <cstddef>
#include <vector>

#include "vv/render/MeshRenderer.h"

namespace vv::render {
namespace {

TEST(PreviewLevelTest, NoLevelsMeansTheFullMeshes) {
    EXPECT_EQ(choosePreviewLevel({}, 1280LL * 720LL), 0U);
}

TEST(PreviewLevelTest, TheFinestLevelWithAboutOneTrianglePerThreePixels) {
    const std::vector<std::size_t> levels = {60000, 20000};
    // 1280x720 (921,600 px) and 640x360 (230,400 px) take 60k triangles.
    EXPECT_EQ(choosePreviewLevel(levels, 1280LL * 720LL), 1U);
    EXPECT_EQ(choosePreviewLevel(levels, 640LL * 360LL), 1U);
    // Exactly at the limit still takes the finer one; a pixel row less does not.
    EXPECT_EQ(choosePreviewLevel(levels, 60000LL * kPixelsPerPreviewTriangle), 1U);
    EXPECT_EQ(choosePreviewLevel(levels, 60000LL * kPixelsPerPreviewTriangle - 1), 2U);
    // 538x302 and the smallest interactive frames take the coarser one.
    EXPECT_EQ(choosePreviewLevel(levels, 538LL * 302LL), 2U);
    EXPECT_EQ(choosePreviewLevel(levels, 320LL * 180LL), 2U);
}

TEST(PreviewLevelTest, TinyOrEmptyFramesTakeTheCoarsestLevel) {
    const std::vector<std::size_t> levels = {9000, 3000, 1000};
    EXPECT_EQ(choosePreviewLevel(levels, 0), 3U);
    EXPECT_EQ(choosePreviewLevel(levels, -5), 3U);
    EXPECT_EQ(choosePreviewLevel(levels, 3000LL * kPixelsPerPreviewTriangle), 2U);
    EXPECT_EQ(choosePreviewLevel(std::vector<std::size_t>{5000}, 10), 1U);
}

}  // namespace
}  // namespace vv::render
