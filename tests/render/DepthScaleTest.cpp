// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <QColor>
#include <cmath>
#include <limits>
#include <set>
#include <string>

#include "vv/colormaps/ColorMap.h"
#include "vv/colormaps/DepthScale.h"
#include "vv/core/Error.h"

namespace {

using vv::colormaps::DepthScale;

/// Hue in degrees of an sRGB colour (Qt's HSV), -1 for greys.
int hue(const glm::vec3& c) {
    return QColor::fromRgbF(c.r, c.g, c.b).hsvHue();
}

TEST(DepthScaleTest, NamesRoundTripLongAndShort) {
    for (const auto scale : vv::colormaps::allDepthScales()) {
        EXPECT_EQ(vv::colormaps::depthScaleFromName(vv::colormaps::name(scale)), scale);
        EXPECT_EQ(vv::colormaps::depthScaleFromName(vv::colormaps::shortName(scale)), scale);
        EXPECT_FALSE(vv::colormaps::displayName(scale).empty());
    }
    EXPECT_EQ(vv::colormaps::depthScaleFromName("DMD"), DepthScale::DarkMeansDeep);
    EXPECT_EQ(vv::colormaps::depthScaleFromName("Pseudo-Chromadepth"),
              DepthScale::PseudoChromadepth);
    EXPECT_FALSE(vv::colormaps::depthScaleFromName("viridis").has_value());
    EXPECT_EQ(vv::colormaps::allDepthScales().size(), 3U);
}

TEST(DepthScaleTest, ChromadepthRunsRedOrangeYellowGreenBlue) {
    const auto at = [](float t) { return hue(sample(DepthScale::Chromadepth, t)); };
    EXPECT_LT(at(0.0F), 10);   // red
    EXPECT_GT(at(0.22F), 20);  // orange
    EXPECT_LT(at(0.22F), 45);
    EXPECT_GT(at(0.42F), 45);  // yellow
    EXPECT_LT(at(0.42F), 70);
    EXPECT_GT(at(0.66F), 100);  // green
    EXPECT_LT(at(0.66F), 150);
    EXPECT_GT(at(1.0F), 210);  // blue
    EXPECT_LT(at(1.0F), 250);
    // Hue rises monotonically from near to far.
    int previous = -1;
    for (int i = 0; i <= 100; ++i) {
        const int h = at(static_cast<float>(i) / 100.0F);
        EXPECT_GE(h, previous) << i;
        previous = h;
    }
}

TEST(DepthScaleTest, PseudoChromadepthIsRedToBlueWithoutGreen) {
    const glm::vec3 near = sample(DepthScale::PseudoChromadepth, 0.0F);
    const glm::vec3 far = sample(DepthScale::PseudoChromadepth, 1.0F);
    EXPECT_GT(near.r, 0.8F);
    EXPECT_LT(near.b, 0.2F);
    EXPECT_GT(far.b, 0.8F);
    EXPECT_LT(far.r, 0.2F);
    for (int i = 0; i <= 100; ++i) {
        const float t = static_cast<float>(i) / 100.0F;
        const glm::vec3 c = sample(DepthScale::PseudoChromadepth, t);
        EXPECT_LE(c.g, std::max(c.r, c.b)) << t;  // never green-dominated
    }
}

TEST(DepthScaleTest, DarkMeansDeepIsWhiteToBlackGreyAndMonotonic) {
    EXPECT_EQ(sample(DepthScale::DarkMeansDeep, 0.0F), glm::vec3(1.0F));
    EXPECT_EQ(sample(DepthScale::DarkMeansDeep, 1.0F), glm::vec3(0.0F));
    float previous = 101.0F;
    for (int i = 0; i <= 100; ++i) {
        const glm::vec3 c = sample(DepthScale::DarkMeansDeep, static_cast<float>(i) / 100.0F);
        EXPECT_FLOAT_EQ(c.r, c.g);
        EXPECT_FLOAT_EQ(c.g, c.b);
        const float l = vv::colormaps::cieLightness(c);
        EXPECT_LT(l, previous);
        previous = l;
    }
}

TEST(DepthScaleTest, SampleClampsAndHandlesNan) {
    for (const auto scale : vv::colormaps::allDepthScales()) {
        EXPECT_EQ(sample(scale, -3.0F), sample(scale, 0.0F));
        EXPECT_EQ(sample(scale, 7.0F), sample(scale, 1.0F));
        EXPECT_EQ(sample(scale, -std::numeric_limits<float>::infinity()), sample(scale, 0.0F));
        EXPECT_EQ(sample(scale, std::numeric_limits<float>::quiet_NaN()), sample(scale, 0.5F));
    }
}

TEST(DepthScaleTest, LutMatchesSamplesAndRejectsBadSizes) {
    for (const auto scale : vv::colormaps::allDepthScales()) {
        const auto table = lut(scale, 256);
        ASSERT_EQ(table.size(), 256U);
        EXPECT_EQ(table.front(), vv::colormaps::toRgba8(sample(scale, 0.0F)));
        EXPECT_EQ(table.back(), vv::colormaps::toRgba8(sample(scale, 1.0F)));
        EXPECT_EQ(table[100], vv::colormaps::toRgba8(sample(scale, 100.0F / 255.0F)));
        EXPECT_EQ(table[7].a, 255);
    }
    EXPECT_THROW((void)lut(DepthScale::Chromadepth, 1), vv::InvalidArgumentError);
    EXPECT_THROW((void)lut(DepthScale::Chromadepth, 65537), vv::InvalidArgumentError);
}

}  // namespace
