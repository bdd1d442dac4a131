// SPDX-License-Identifier: GPL-3.0-or-later
// Orientation letters of oblique directions, the slice position text,
// window / level and its presets, the voxel read-out, and overlay pixels.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "Phantom.h"
#include "vv/slices/OrientationLetters.h"
#include "vv/slices/SliceOverlay.h"
#include "vv/slices/VoxelProbe.h"
#include "vv/slices/WindowLevel.h"

namespace {

using vv::slices::Window;
using vv::slices::WindowPreset;

TEST(OrientationLettersTest, DominantLettersFirst) {
    EXPECT_EQ(vv::slices::directionLetters({1.0, 0.0, 0.0}), "L");
    EXPECT_EQ(vv::slices::directionLetters({0.0, -2.0, 0.0}), "A");
    EXPECT_EQ(vv::slices::directionLetters({0.0, 0.0, -1.0}), "I");
    // 30 degrees off the left axis towards posterior: "LP".
    EXPECT_EQ(vv::slices::directionLetters({std::cos(0.5236), std::sin(0.5236), 0.0}), "LP");
    // 10 degrees off: the secondary component is below a quarter of the main one.
    EXPECT_EQ(vv::slices::directionLetters({std::cos(0.1745), -std::sin(0.1745), 0.0}), "L");
    EXPECT_EQ(vv::slices::directionLetters({-0.5, 0.3, 0.9}), "SRP");
    EXPECT_EQ(vv::slices::directionLetters({0.0, 0.0, 0.0}), "");
}

TEST(OrientationLettersTest, ObliquePlaneEdges) {
    vv::slices::SlicePlane plane;
    plane.right = glm::normalize(glm::dvec3(1.0, 0.0, -0.6));  // left and a little inferior
    plane.down = glm::dvec3(0.0, 1.0, 0.0);
    const auto e = vv::slices::edgeLetters(plane);
    EXPECT_EQ(e.right, "LI");
    EXPECT_EQ(e.left, "RS");
    EXPECT_EQ(e.top, "A");
    EXPECT_EQ(e.bottom, "P");
}

TEST(OrientationLettersTest, SlicePositionText) {
    const auto s = vv::slices::slicePositionText(2, -12.5);
    EXPECT_EQ(s.letter, 'I');
    EXPECT_DOUBLE_EQ(s.distance, 12.5);
    EXPECT_EQ(vv::slices::slicePositionText(0, 3.0).letter, 'L');
    EXPECT_EQ(vv::slices::slicePositionText(1, -3.0).letter, 'A');
}

TEST(WindowLevelTest, LinearRampBetweenWindowEdges) {
    const Window w{40.0, 400.0};
    EXPECT_EQ(vv::slices::windowGray(-160.0F, w), 0);
    EXPECT_EQ(vv::slices::windowGray(-1000.0F, w), 0);
    EXPECT_EQ(vv::slices::windowGray(240.0F, w), 255);
    EXPECT_EQ(vv::slices::windowGray(3000.0F, w), 255);
    EXPECT_EQ(vv::slices::windowGray(40.0F, w), 128);
    EXPECT_EQ(vv::slices::windowGray(-60.0F, w), 64);
    EXPECT_EQ(vv::slices::windowGray(std::numeric_limits<float>::quiet_NaN(), w), 0);
}

TEST(WindowLevelTest, ApplyWindowMatchesThePixelRule) {
    vv::Image<float> values(37, 11);
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> dist(-1200.0F, 2000.0F);
    for (int r = 0; r < values.height(); ++r) {
        for (int c = 0; c < values.width(); ++c) {
            values(c, r) = dist(rng);
        }
    }
    values(3, 4) = std::numeric_limits<float>::quiet_NaN();
    const Window w{300.0, 600.0};
    const auto gray = vv::slices::applyWindow(values.view(), w);
    for (int r = 0; r < values.height(); ++r) {
        for (int c = 0; c < values.width(); ++c) {
            EXPECT_NEAR(gray(c, r), vv::slices::windowGray(values(c, r), w), 1) << c << "," << r;
        }
    }
    EXPECT_EQ(gray(3, 4), 0);
}

TEST(WindowLevelTest, CtPresets) {
    const auto volume = vv::test::ballPhantom({8, 8, 8}, glm::dmat4(1.0), {{{4, 4, 4}, 2.0}});
    const auto presets = vv::slices::windowPresets(volume);
    ASSERT_EQ(presets.size(), 4U);
    EXPECT_EQ(presets[0].preset, WindowPreset::Cta);
    EXPECT_EQ(presets[2].preset, WindowPreset::Bone);
    // CTA: contrast lumen (~400 HU) light grey, tissue (40 HU) dark, bone white.
    EXPECT_GT(vv::slices::windowGray(400.0F, presets[0].window), 150);
    EXPECT_LT(vv::slices::windowGray(40.0F, presets[0].window), 40);
    EXPECT_EQ(vv::slices::windowGray(1200.0F, presets[0].window), 255);
    // Bone: bone is not saturated.
    EXPECT_LT(vv::slices::windowGray(1000.0F, presets[2].window), 255);
    EXPECT_EQ(presets[3].preset, WindowPreset::FullRange);
    EXPECT_EQ(vv::slices::windowGray(0.0F, presets[3].window), 0);
    EXPECT_EQ(vv::slices::windowGray(1000.0F, presets[3].window), 255);
}

TEST(WindowLevelTest, MrPresetsFromTheValueRange) {
    // An MR-like volume: body ~300 (most voxels), air ~20, vessels ~1500 (2 %).
    vv::scene::Volume mr({40, 40, 40}, vv::scene::VoxelType::Float32);
    mr.setModality("MR");
    std::mt19937 rng(3);
    std::normal_distribution<float> noise(0.0F, 10.0F);
    for (std::size_t n = 0; n < mr.voxelCount(); ++n) {
        const std::size_t m = n % 100;
        const float base = m < 2 ? 1500.0F : (m < 20 ? 20.0F : 300.0F);
        mr.setValueAt(n, base + noise(rng));
    }
    const auto presets = vv::slices::windowPresets(mr);
    ASSERT_EQ(presets.size(), 3U);
    EXPECT_EQ(presets[0].preset, WindowPreset::Mra);
    // MRA: vessels bright, body dark.
    EXPECT_GT(vv::slices::windowGray(1500.0F, presets[0].window), 200);
    EXPECT_LT(vv::slices::windowGray(300.0F, presets[0].window), 30);
    // Soft tissue: body mid-grey, air black-ish.
    const Window soft = presets[1].window;
    EXPECT_GT(vv::slices::windowGray(300.0F, soft), 40);
    EXPECT_LT(vv::slices::windowGray(300.0F, soft), 220);
    EXPECT_LT(vv::slices::windowGray(20.0F, soft), 30);
    EXPECT_EQ(vv::slices::presetKey(WindowPreset::SoftTissue), "soft-tissue");
}

TEST(WindowLevelTest, DragChangesWidthAndLevel) {
    const Window start{300.0, 600.0};
    const Window wider = vv::slices::dragWindow(start, 50.0, 0.0, 4000.0);
    EXPECT_DOUBLE_EQ(wider.center, 300.0);
    EXPECT_DOUBLE_EQ(wider.width, 1000.0);
    const Window lower = vv::slices::dragWindow(start, 0.0, -25.0, 4000.0);
    EXPECT_DOUBLE_EQ(lower.center, 200.0);
    const Window narrowest = vv::slices::dragWindow(start, -10000.0, 0.0, 4000.0);
    EXPECT_DOUBLE_EQ(narrowest.width, 4.0);
}

TEST(VoxelProbeTest, ValueAndUnitOfTheVoxelUnderAPoint) {
    const glm::dmat3 r = vv::test::rotationAbout({0.2, 1.0, 0.1}, 33.0);
    const auto volume = vv::test::ballPhantom(
        {20, 20, 20}, vv::test::gridGeometry({0.7, 0.8, 1.3}, r, 0.2, {5.0, -3.0, 8.0}),
        {{{10.0, 3.0, 18.0}, 3.0}});
    const glm::dvec3 inBall = volume.worldPosition({9.2, 9.1, 8.7});
    const auto sample = vv::slices::voxelAt(volume, inBall);
    ASSERT_TRUE(sample.has_value());
    EXPECT_EQ(sample->voxel, glm::ivec3(9, 9, 9));
    EXPECT_EQ(sample->value, volume.value(9, 9, 9));
    EXPECT_EQ(sample->unit, "HU");
    EXPECT_FALSE(vv::slices::voxelAt(volume, volume.worldPosition({-0.6, 3.0, 3.0})).has_value());
    EXPECT_FALSE(vv::slices::voxelAt(volume, volume.worldPosition({3.0, 19.6, 3.0})).has_value());
    EXPECT_TRUE(vv::slices::voxelAt(volume, volume.worldPosition({3.0, 19.4, 3.0})).has_value());
    vv::scene::Volume mr({2, 2, 2}, vv::scene::VoxelType::Float32);
    mr.setModality("MR");
    EXPECT_EQ(vv::slices::valueUnit(mr), "");
    mr.setModality("CT");
    EXPECT_EQ(vv::slices::valueUnit(mr), "HU");
}

TEST(SliceOverlayTest, OutlineAndTranslucentFill) {
    vv::Image<std::uint8_t> gray(9, 9, 100);
    vv::Image<std::uint8_t> labels(9, 9, 0);
    for (int r = 2; r <= 6; ++r) {
        for (int c = 2; c <= 6; ++c) {
            labels(c, r) = 1;
        }
    }
    const std::uint32_t colour = vv::slices::overlayColor(1);
    const auto both = vv::slices::composeSlice(gray.view(), labels.view());
    EXPECT_EQ(both(0, 0), 0xFF646464U);           // background: grey 100
    EXPECT_EQ(both(2, 4), 0xFF000000U | colour);  // edge: the label colour
    const std::uint32_t inner = both(4, 4);       // inside: blended
    EXPECT_NE(inner, 0xFF646464U);
    EXPECT_NE(inner, 0xFF000000U | colour);
    const int red = static_cast<int>((inner >> 16U) & 0xFFU);
    const int expectedRed = static_cast<int>(
        std::lround(100 + 0.35 * (static_cast<int>((colour >> 16U) & 0xFFU) - 100)));
    EXPECT_NEAR(red, expectedRed, 1);

    vv::slices::OverlayStyle outlineOnly;
    outlineOnly.fill = false;
    const auto outline = vv::slices::composeSlice(gray.view(), labels.view(), outlineOnly);
    EXPECT_EQ(outline(4, 4), 0xFF646464U);
    EXPECT_EQ(outline(6, 6), 0xFF000000U | colour);

    const auto edges = vv::slices::labelOutline(labels.view());
    int count = 0;
    for (int r = 0; r < 9; ++r) {
        for (int c = 0; c < 9; ++c) {
            count += edges(c, r);
        }
    }
    EXPECT_EQ(count, 16);  // the ring of a 5 x 5 square

    vv::Image<std::uint8_t> small(3, 3, 0);
    EXPECT_THROW((void)vv::slices::composeSlice(gray.view(), small.view()),
                 vv::InvalidArgumentError);
    const auto plain = vv::slices::composeSlice(gray.view(), {});
    EXPECT_EQ(plain(4, 4), 0xFF646464U);
}

}  // namespace
