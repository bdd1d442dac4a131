// SPDX-License-Identifier: GPL-3.0-or-later
// The colour science behind the colour-blind-safe checks: sRGB, CIELAB,
// CIEDE2000 (against the published test data) and the CVD simulation.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "vv/colormaps/ColorVision.h"

namespace vv::colormaps {
namespace {

TEST(ColorVision, SrgbTransferRoundTripsAndHitsKnownValues) {
    EXPECT_DOUBLE_EQ(srgbToLinear(0.0), 0.0);
    EXPECT_DOUBLE_EQ(srgbToLinear(1.0), 1.0);
    EXPECT_NEAR(srgbToLinear(0.5), 0.214041, 1e-6);  // sRGB 128/255-ish mid grey
    EXPECT_NEAR(srgbToLinear(0.04045), 0.04045 / 12.92, 1e-12);
    for (double v = 0.0; v <= 1.0; v += 0.01) {
        EXPECT_NEAR(linearToSrgb(srgbToLinear(v)), v, 1e-12) << v;
    }
    EXPECT_DOUBLE_EQ(srgbToLinear(1.5), 1.0);  // clamped
}

TEST(ColorVision, LabOfPrimariesMatchesTheStandardValues) {
    const Lab white = srgbToLab({1.0, 1.0, 1.0});
    EXPECT_NEAR(white.l, 100.0, 1e-3);
    EXPECT_NEAR(white.a, 0.0, 1e-2);
    EXPECT_NEAR(white.b, 0.0, 1e-2);
    const Lab black = srgbToLab({0.0, 0.0, 0.0});
    EXPECT_NEAR(black.l, 0.0, 1e-9);
    // sRGB red and green in CIELAB (D65): (53.24, 80.09, 67.20), (87.73, -86.18, 83.18).
    const Lab red = srgbToLab({1.0, 0.0, 0.0});
    EXPECT_NEAR(red.l, 53.24, 0.01);
    EXPECT_NEAR(red.a, 80.09, 0.02);
    EXPECT_NEAR(red.b, 67.20, 0.02);
    const Lab green = srgbToLab({0.0, 1.0, 0.0});
    EXPECT_NEAR(green.l, 87.73, 0.01);
    EXPECT_NEAR(green.a, -86.18, 0.02);
    EXPECT_NEAR(green.b, 83.18, 0.02);
}

struct SharmaPair {
    int number;  ///< row of Table 1 in Sharma, Wu & Dalal (2005)
    Lab first;
    Lab second;
    double expected;
};

TEST(ColorVision, Ciede2000MatchesSharmaWuDalalTestData) {
    // Rows of the supplementary test data (Table 1) of Sharma, Wu & Dalal,
    // Color Res. Appl. 30(1), 2005; among them the pairs that probe the hue
    // angle's discontinuity (13-17) and the rotation term (1-4).
    const std::vector<SharmaPair> pairs{
        {1, {50.0000, 2.6772, -79.7751}, {50.0000, 0.0000, -82.7485}, 2.0425},
        {2, {50.0000, 3.1571, -77.2803}, {50.0000, 0.0000, -82.7485}, 2.8615},
        {4, {50.0000, -1.3802, -84.2814}, {50.0000, 0.0000, -82.7485}, 1.0000},
        {7, {50.0000, 0.0000, 0.0000}, {50.0000, -1.0000, 2.0000}, 2.3669},
        {13, {50.0000, 2.4900, -0.0010}, {50.0000, -2.4900, 0.0009}, 7.1792},
        {15, {50.0000, 2.4900, -0.0010}, {50.0000, -2.4900, 0.0011}, 7.2195},
        {17, {50.0000, -0.0010, 2.4900}, {50.0000, 0.0009, -2.4900}, 4.8045},
        {21, {50.0000, 2.5000, 0.0000}, {73.0000, 25.0000, -18.0000}, 27.1492},
        {24, {50.0000, 2.5000, 0.0000}, {58.0000, 24.0000, 15.0000}, 19.4535},
        {29, {60.2574, -34.0099, 36.2677}, {60.4626, -34.1751, 39.4387}, 1.2644},
        {34, {36.4612, 47.8580, 18.3852}, {36.2715, 50.5065, 21.2231}, 1.4146},
        {37, {6.7747, -0.2908, -2.4247}, {5.8714, -0.0985, -2.2286}, 0.6377},
        {38, {2.0776, 0.0795, -1.1350}, {0.9033, -0.0636, -0.5514}, 0.9082},
    };
    for (const SharmaPair& p : pairs) {
        EXPECT_NEAR(ciede2000(p.first, p.second), p.expected, 1e-4) << "pair " << p.number;
        EXPECT_NEAR(ciede2000(p.second, p.first), p.expected, 1e-4) << "pair " << p.number;
    }
    EXPECT_EQ(ciede2000(Lab{40.0, 10.0, -5.0}, Lab{40.0, 10.0, -5.0}), 0.0);
}

TEST(ColorVision, MachadoMatricesKeepGreysAndMergeRedWithGreen) {
    for (const ColorVision vision : allColorVisions()) {
        const auto& m = machadoMatrix(vision);
        for (const auto& row : m) {
            EXPECT_NEAR(row[0] + row[1] + row[2], 1.0, 2e-6) << name(vision);
        }
        for (const double grey : {0.0, 0.2, 0.5, 0.8, 1.0}) {
            const glm::dvec3 seen = simulate(vision, glm::dvec3(grey));
            EXPECT_NEAR(seen.r, grey, 1e-4) << name(vision);
            EXPECT_NEAR(seen.g, grey, 1e-4) << name(vision);
            EXPECT_NEAR(seen.b, grey, 1e-4) << name(vision);
        }
    }
    EXPECT_EQ(machadoMatrix(ColorVision::Deuteranopia)[0][0], 0.367322);
    EXPECT_EQ(machadoMatrix(ColorVision::Protanopia)[1][1], 0.786281);
    EXPECT_EQ(machadoMatrix(ColorVision::Tritanopia)[2][1], 0.691367);

    // A red and a green of similar lightness: far apart for normal vision,
    // close for the red-green dichromats, still apart for a tritanope.
    const glm::dvec3 red{0.80, 0.35, 0.20};
    const glm::dvec3 green{0.45, 0.50, 0.20};
    EXPECT_GT(ciede2000(red, green), 20.0);
    EXPECT_LT(ciede2000(simulate(ColorVision::Deuteranopia, red),
                        simulate(ColorVision::Deuteranopia, green)),
              6.0);
    EXPECT_GT(
        ciede2000(simulate(ColorVision::Tritanopia, red), simulate(ColorVision::Tritanopia, green)),
        10.0);
}

TEST(ColorVision, CheckRampFindsMonotonicLightnessAndTheSmallestStep) {
    const std::vector<glm::dvec3> greys{
        {0.1, 0.1, 0.1}, {0.4, 0.4, 0.4}, {0.45, 0.45, 0.45}, {0.9, 0.9, 0.9}};
    const RampCheck up = checkRamp(greys, ColorVision::Normal);
    EXPECT_TRUE(up.monotonicLightness);
    EXPECT_EQ(up.minAdjacentIndex, 1);
    EXPECT_LT(up.minAdjacentDelta, 5.0);
    EXPECT_FALSE(checkRamp(greys, ColorVision::Normal, 10.0).monotonicLightness);
    const std::vector<glm::dvec3> bump{{0.1, 0.1, 0.1}, {0.9, 0.9, 0.9}, {0.5, 0.5, 0.5}};
    EXPECT_FALSE(checkRamp(bump, ColorVision::Normal).monotonicLightness);
    EXPECT_FALSE(checkRamp(std::vector<glm::dvec3>{{0.1, 0.1, 0.1}}, ColorVision::Normal)
                     .monotonicLightness);
}

TEST(ColorVision, DominantColorsBinsAndDropsRareColours) {
    std::vector<glm::u8vec3> pixels(1000, glm::u8vec3(10, 20, 30));
    pixels.resize(1900, glm::u8vec3(200, 100, 50));
    pixels.push_back({0, 255, 0});  // 1 of 1901: below the default fraction
    const auto palette = dominantColors(pixels);
    ASSERT_EQ(palette.size(), 2U);
    EXPECT_NEAR(palette[0].fraction, 1000.0 / 1901.0, 1e-12);
    EXPECT_NEAR(palette[0].srgb.r, 10.0 / 255.0, 1e-12);
    EXPECT_NEAR(palette[1].srgb.g, 100.0 / 255.0, 1e-12);
    EXPECT_TRUE(dominantColors({}).empty());
}

TEST(ColorVision, FindsRedGreenConfusionsButNotLightnessOrBlueYellowPairs) {
    const std::vector<glm::dvec3> redGreen{{0.80, 0.35, 0.20}, {0.45, 0.50, 0.20}};
    const auto pairs = findRedGreenConfusions(redGreen, {10.0, 6.0});
    ASSERT_EQ(pairs.size(), 1U);
    EXPECT_TRUE(pairs[0].vision == ColorVision::Deuteranopia ||
                pairs[0].vision == ColorVision::Protanopia);
    EXPECT_GT(pairs[0].normalDelta, 10.0);
    const std::vector<glm::dvec3> safe{
        {0.1, 0.1, 0.1}, {0.5, 0.5, 0.5}, {0.9, 0.9, 0.9}, {0.1, 0.2, 0.8}, {0.9, 0.8, 0.1}};
    EXPECT_TRUE(findRedGreenConfusions(safe).empty());
}

}  // namespace
}  // namespace vv::colormaps
