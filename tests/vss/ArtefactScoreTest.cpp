// SPDX-License-Identifier: GPL-3.0-or-later
// The artefact score (app/evaluation/ArtefactScore.h) on synthetic images whose
// high-frequency energy along the contour is known.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <glm/vec4.hpp>
#include <limits>
#include <numbers>

#include "evaluation/ArtefactScore.h"
#include "vv/core/Error.h"

namespace vv::evaluation {
namespace {

constexpr int kSize = 96;
constexpr int kVesselColumns = 10;  // columns 0..9 are a vessel: a straight, vertical contour

Image<std::uint8_t> stripe() {
    Image<std::uint8_t> vessels(kSize, kSize, 0);
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kVesselColumns; ++x) {
            vessels(x, y) = 1;
        }
    }
    return vessels;
}

/// A steep profile across the contour (as the VSS is next to one), plus a
/// ripple of `amplitude` and `period` pixels along it.
Image<float> luminance(double amplitude, double period) {
    Image<float> l(kSize, kSize, std::numeric_limits<float>::quiet_NaN());
    for (int y = 0; y < kSize; ++y) {
        for (int x = kVesselColumns; x < kSize; ++x) {
            const double across = 0.2 + 0.6 * std::exp(-(x - kVesselColumns) / 2.0);
            const double along = amplitude * std::sin(2.0 * std::numbers::pi * y / period);
            l(x, y) = static_cast<float>(across + along);
        }
    }
    return l;
}

TEST(ArtefactScoreTest, DistanceToVesselsIsTheChamferDistance) {
    Image<std::uint8_t> vessels(7, 7, 0);
    vessels(3, 3) = 1;
    const Image<float> d = distanceToVessels(vessels.view());
    EXPECT_EQ(d(3, 3), 0.0F);
    EXPECT_EQ(d(4, 3), 1.0F);
    EXPECT_EQ(d(3, 0), 3.0F);
    EXPECT_NEAR(d(4, 4), std::sqrt(2.0F), 1e-5);
    EXPECT_NEAR(d(6, 5), 1.0F + 2.0F * std::sqrt(2.0F), 1e-5);
    const Image<float> none = distanceToVessels(Image<std::uint8_t>(4, 4, 0).view());
    EXPECT_TRUE(std::isinf(none(2, 2)));
}

TEST(ArtefactScoreTest, BlindToTheProfileAcrossTheContour) {
    const Image<std::uint8_t> vessels = stripe();
    const ArtefactScore score = artefactScore(luminance(0.0, 12.0).view(), vessels.view());
    // Band: columns 10..17 (distance 1..8), rows whose samples 3 px up and
    // down are inside the image.
    EXPECT_EQ(score.bandPixels, 8 * (kSize - 2 * 3));
    EXPECT_LT(score.rms, 1e-6);
}

TEST(ArtefactScoreTest, MeasuresARippleAlongTheContour) {
    // The second difference over +-3 px of A sin(2 pi y / P) has amplitude
    // A (1 - cos(2 pi 3 / P)); its RMS over whole periods is that / sqrt 2.
    const Image<std::uint8_t> vessels = stripe();
    for (const double period : {12.0, 18.0, 6.0}) {
        const double amplitude = 0.05;
        const double expected =
            amplitude * (1.0 - std::cos(2.0 * std::numbers::pi * 3.0 / period)) / std::sqrt(2.0);
        const ArtefactScore score =
            artefactScore(luminance(amplitude, period).view(), vessels.view());
        // 90 rows are whole periods of 6 and 18 px and 7.5 of 12 px.
        EXPECT_NEAR(score.rms, expected, 0.02 * expected) << "period " << period;
    }
}

TEST(ArtefactScoreTest, OnlyTheBandCounts) {
    // A ripple beyond 8 px from the contour is no artefact of the contour.
    const Image<std::uint8_t> vessels = stripe();
    Image<float> l = luminance(0.0, 12.0);
    for (int y = 0; y < kSize; ++y) {
        for (int x = kVesselColumns + 12; x < kSize; ++x) {
            l(x, y) += static_cast<float>(0.1 * std::sin(2.0 * std::numbers::pi * y / 12.0));
        }
    }
    EXPECT_LT(artefactScore(l.view(), vessels.view()).rms, 1e-6);
    ArtefactScoreOptions wide;
    wide.bandFar = 20.0;
    EXPECT_GT(artefactScore(l.view(), vessels.view(), wide).rms, 0.01);
}

TEST(ArtefactScoreTest, RejectsBadInput) {
    const Image<std::uint8_t> vessels = stripe();
    const Image<float> l = luminance(0.0, 12.0);
    const Image<float> small(8, 8, 0.0F);
    EXPECT_THROW(static_cast<void>(artefactScore(small.view(), vessels.view())),
                 InvalidArgumentError);
    ArtefactScoreOptions bad;
    bad.bandNear = 9.0;  // > bandFar
    EXPECT_THROW(static_cast<void>(artefactScore(l.view(), vessels.view(), bad)),
                 InvalidArgumentError);
    bad = {};
    bad.spacing = 0.0;
    EXPECT_THROW(static_cast<void>(artefactScore(l.view(), vessels.view(), bad)),
                 InvalidArgumentError);
}

TEST(ArtefactScoreTest, LuminanceIsTheShadersLighting) {
    // A flat VSS facing the headlight: ambient + diffuse on the base grey plus
    // the full specular; a vessel pixel and a pixel without slope get NaN.
    Image<float> height(3, 1, 0.5F);
    Image<glm::vec4> slopes(3, 1, glm::vec4(0.0F, 0.0F, 1.0F, 1.0F));
    slopes(2, 0) = glm::vec4(0.0F);
    Image<std::uint8_t> vessels(3, 1, 0);
    vessels(1, 0) = 1;
    VssLight light;
    light.pixelScale = 0.001;
    const Image<float> l = vssLuminance(height.view(), slopes.view(), vessels.view(), light);
    EXPECT_NEAR(l(0, 0), 0.5 * (0.30 + 0.70) + 0.25, 1e-6);
    EXPECT_TRUE(std::isnan(l(1, 0)));
    EXPECT_TRUE(std::isnan(l(2, 0)));
    light.pixelScale = 0.0;
    EXPECT_THROW(
        static_cast<void>(vssLuminance(height.view(), slopes.view(), vessels.view(), light)),
        InvalidArgumentError);
}

}  // namespace
}  // namespace vv::evaluation
