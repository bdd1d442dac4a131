// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>
#include <string>

#include "vv/colormaps/ColorMap.h"
#include "vv/core/Error.h"

namespace {

using vv::colormaps::ColorMap;

void expectNear(const glm::vec3& actual, const glm::vec3& expected, float tolerance) {
    EXPECT_NEAR(actual.r, expected.r, tolerance);
    EXPECT_NEAR(actual.g, expected.g, tolerance);
    EXPECT_NEAR(actual.b, expected.b, tolerance);
}

// Published matplotlib values (256-entry tables, entry k at t = k / 255).
TEST(ColorMapTest, ViridisEndpointsAndMiddleMatchPublishedValues) {
    expectNear(sample(ColorMap::Viridis, 0.0F), {0.267004F, 0.004874F, 0.329415F}, 1e-6F);
    expectNear(sample(ColorMap::Viridis, 1.0F), {0.993248F, 0.906157F, 0.143936F}, 1e-6F);
    // Entries that are not control points: within half an 8-bit step.
    expectNear(sample(ColorMap::Viridis, 128.0F / 255.0F), {0.127568F, 0.566949F, 0.550556F},
               0.5F / 255.0F);
    expectNear(sample(ColorMap::Viridis, 64.0F / 255.0F), {0.229739F, 0.322361F, 0.545706F},
               0.5F / 255.0F);
    expectNear(sample(ColorMap::Viridis, 191.0F / 255.0F), {0.360741F, 0.785964F, 0.387814F},
               0.5F / 255.0F);
}

TEST(ColorMapTest, CividisEndpointsAndMiddleMatchPublishedValues) {
    expectNear(sample(ColorMap::Cividis, 0.0F), {0.0F, 0.135112F, 0.304751F}, 1e-6F);
    expectNear(sample(ColorMap::Cividis, 1.0F), {0.995737F, 0.909344F, 0.217772F}, 1e-6F);
    expectNear(sample(ColorMap::Cividis, 63.0F / 255.0F), {0.259740F, 0.305120F, 0.422810F},
               0.5F / 255.0F);
    expectNear(sample(ColorMap::Cividis, 191.0F / 255.0F), {0.732422F, 0.677364F, 0.425717F},
               0.5F / 255.0F);
}

TEST(ColorMapTest, LightnessIncreasesMonotonicallyAlongViridisAndCividis) {
    for (const ColorMap map : vv::colormaps::allColorMaps()) {
        float previous = -1.0F;
        for (int i = 0; i <= 1000; ++i) {
            const float l =
                vv::colormaps::cieLightness(sample(map, static_cast<float>(i) / 1000.0F));
            ASSERT_GT(l, previous) << name(map) << " at t = " << i / 1000.0;
            previous = l;
        }
        // Spans most of the lightness axis: a dark start and a light end.
        EXPECT_LT(vv::colormaps::cieLightness(sample(map, 0.0F)), 25.0F) << name(map);
        EXPECT_GT(vv::colormaps::cieLightness(sample(map, 1.0F)), 85.0F) << name(map);
    }
}

TEST(ColorMapTest, TIsClampedAndNanGivesNoDataColour) {
    for (const ColorMap map : vv::colormaps::allColorMaps()) {
        expectNear(sample(map, -3.0F), sample(map, 0.0F), 0.0F);
        expectNear(sample(map, 7.0F), sample(map, 1.0F), 0.0F);
        expectNear(sample(map, -std::numeric_limits<float>::infinity()), sample(map, 0.0F), 0.0F);
        expectNear(sample(map, std::numeric_limits<float>::infinity()), sample(map, 1.0F), 0.0F);
        expectNear(sample(map, std::numeric_limits<float>::quiet_NaN()),
                   vv::colormaps::noDataColor(map), 0.0F);
    }
}

TEST(ColorMapTest, NoDataColourIsFarFromEveryMapColour) {
    for (const ColorMap map : vv::colormaps::allColorMaps()) {
        const glm::vec3 noData = vv::colormaps::noDataColor(map);
        for (int i = 0; i <= 255; ++i) {
            const glm::vec3 c = sample(map, static_cast<float>(i) / 255.0F);
            EXPECT_GT(glm::length(c - noData), 0.15F) << name(map) << " entry " << i;
        }
    }
}

TEST(ColorMapTest, LutHasRequestedSizeAndEndpoints) {
    const auto table = vv::colormaps::lut(ColorMap::Viridis, 256);
    ASSERT_EQ(table.size(), 256U);
    EXPECT_EQ(table.front(), glm::u8vec4(68, 1, 84, 255));    // round(0.267004*255) ...
    EXPECT_EQ(table.back(), glm::u8vec4(253, 231, 37, 255));  // round(0.993248*255) ...
    for (const auto& entry : table) {
        EXPECT_EQ(entry.a, 255);
    }
    // Consecutive entries differ: 256 distinct colours.
    std::set<std::tuple<int, int, int>> distinct;
    for (const auto& e : table) {
        distinct.insert({e.r, e.g, e.b});
    }
    EXPECT_GT(distinct.size(), 200U);

    const auto two = vv::colormaps::lut(ColorMap::Cividis, 2);
    ASSERT_EQ(two.size(), 2U);
    EXPECT_EQ(two[0], vv::colormaps::toRgba8(sample(ColorMap::Cividis, 0.0F)));
    EXPECT_EQ(two[1], vv::colormaps::toRgba8(sample(ColorMap::Cividis, 1.0F)));
}

TEST(ColorMapTest, LutRejectsBadSizes) {
    EXPECT_THROW((void)vv::colormaps::lut(ColorMap::Viridis, 1), vv::InvalidArgumentError);
    EXPECT_THROW((void)vv::colormaps::lut(ColorMap::Viridis, 0), vv::InvalidArgumentError);
    EXPECT_THROW((void)vv::colormaps::lut(ColorMap::Viridis, -5), vv::InvalidArgumentError);
    EXPECT_THROW((void)vv::colormaps::lut(ColorMap::Viridis, 65537), vv::InvalidArgumentError);
}

TEST(ColorMapTest, NamesRoundTripIgnoringCase) {
    for (const ColorMap map : vv::colormaps::allColorMaps()) {
        EXPECT_EQ(vv::colormaps::colorMapFromName(name(map)), map);
        std::string upper(name(map));
        for (auto& c : upper) {
            c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
        }
        EXPECT_EQ(vv::colormaps::colorMapFromName(upper), map);
        EXPECT_FALSE(vv::colormaps::displayName(map).empty());
    }
    EXPECT_EQ(vv::colormaps::colorMapFromName("viridis"), ColorMap::Viridis);
    EXPECT_FALSE(vv::colormaps::colorMapFromName("jet").has_value());
    EXPECT_FALSE(vv::colormaps::colorMapFromName("").has_value());
}

TEST(ColorMapTest, CieLightnessOfBlackWhiteAndGrey) {
    EXPECT_NEAR(vv::colormaps::cieLightness({0, 0, 0}), 0.0F, 1e-4F);
    EXPECT_NEAR(vv::colormaps::cieLightness({1, 1, 1}), 100.0F, 1e-3F);
    // sRGB 119/255 grey is L* ~ 50.
    EXPECT_NEAR(vv::colormaps::cieLightness(glm::vec3(119.0F / 255.0F)), 50.0F, 0.5F);
}

}  // namespace
