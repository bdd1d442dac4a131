// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <string>
#include <tuple>

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

TEST(ColorMapTest, LightnessIncreasesMonotonicallyAlongViridisCividisAndInferno) {
    for (const ColorMap map : {ColorMap::Viridis, ColorMap::Cividis, ColorMap::Inferno}) {
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

TEST(ColorMapTest, InfernoEndpointsAndMiddleMatchPublishedValues) {
    expectNear(sample(ColorMap::Inferno, 0.0F), {0.001462F, 0.000466F, 0.013866F}, 1e-6F);
    expectNear(sample(ColorMap::Inferno, 1.0F), {0.988362F, 0.998364F, 0.644924F}, 1e-6F);
    // Table entries 64, 128 and 200 (not all control points): within half an 8-bit step.
    expectNear(sample(ColorMap::Inferno, 64.0F / 255.0F), {0.341500F, 0.062325F, 0.429425F},
               0.5F / 255.0F);
    expectNear(sample(ColorMap::Inferno, 128.0F / 255.0F), {0.735683F, 0.215906F, 0.330245F},
               0.5F / 255.0F);
    expectNear(sample(ColorMap::Inferno, 230.0F / 255.0F), {0.964394F, 0.843848F, 0.273391F},
               0.5F / 255.0F);
}

TEST(ColorMapTest, BlueWhiteRedIsBlueToWhiteToRedAndSymmetricInLightness) {
    using vv::colormaps::cieLightness;
    const ColorMap map = ColorMap::BlueWhiteRed;
    // Published RdBu end and centre colours.
    expectNear(sample(map, 0.0F), {0x05 / 255.0F, 0x30 / 255.0F, 0x61 / 255.0F}, 1e-6F);
    expectNear(sample(map, 1.0F), {0x67 / 255.0F, 0x00 / 255.0F, 0x1f / 255.0F}, 1e-6F);
    const glm::vec3 centre = sample(map, 0.5F);
    EXPECT_GT(cieLightness(centre), 95.0F);
    EXPECT_LT(std::max({centre.r, centre.g, centre.b}) - std::min({centre.r, centre.g, centre.b}),
              0.01F);  // neutral: white
    float previous = cieLightness(sample(map, 0.0F));
    for (int i = 1; i <= 500; ++i) {
        const float t = static_cast<float>(i) / 1000.0F;
        const glm::vec3 low = sample(map, 0.5F - t);
        const glm::vec3 high = sample(map, 0.5F + t);
        // Lightness mirrors around the centre and falls off towards both ends.
        EXPECT_NEAR(cieLightness(low), cieLightness(high), 5.0F) << "t = 0.5 +- " << t;
        // Blue below the centre, red above.
        EXPECT_GT(low.b, low.r) << t;
        EXPECT_GT(high.r, high.b) << t;
        const float l = cieLightness(sample(map, t * 1.0F));
        EXPECT_GT(l, previous) << t;  // lighter towards the centre
        previous = l;
    }
    EXPECT_EQ(vv::colormaps::colorMapFromName("bwr"), ColorMap::BlueWhiteRed);
    EXPECT_EQ(vv::colormaps::colorMapFromName("Diverging"), ColorMap::BlueWhiteRed);
}

TEST(ColorMapTest, BinsGiveExactlyNDistinctColoursCoveringTheMap) {
    for (const ColorMap map : vv::colormaps::allColorMaps()) {
        for (const int bins : {2, 3, 5, 8, 16}) {
            std::set<std::tuple<int, int, int>> distinct;
            for (int i = 0; i <= 4000; ++i) {
                const auto c =
                    vv::colormaps::toRgba8(sample(map, static_cast<float>(i) / 4000.0F, bins));
                distinct.insert({c.r, c.g, c.b});
            }
            EXPECT_EQ(distinct.size(), static_cast<std::size_t>(bins)) << name(map) << " " << bins;
            // First and last bins carry the map's end colours; a bin is constant inside.
            expectNear(sample(map, 0.0F, bins), sample(map, 0.0F), 0.0F);
            expectNear(sample(map, 1.0F, bins), sample(map, 1.0F), 0.0F);
            expectNear(sample(map, 0.99F / static_cast<float>(bins), bins), sample(map, 0.0F),
                       0.0F);
            // The bin colours are exactly lut(map, bins).
            const auto table = vv::colormaps::lut(map, bins);
            for (int b = 0; b < bins; ++b) {
                const float mid = (static_cast<float>(b) + 0.5F) / static_cast<float>(bins);
                EXPECT_EQ(vv::colormaps::binIndex(mid, bins), b);
                EXPECT_EQ(vv::colormaps::toRgba8(sample(map, mid, bins)),
                          table[static_cast<std::size_t>(b)]);
            }
        }
        // 0 bins = continuous; NaN stays no-data.
        expectNear(sample(map, 0.3F, 0), sample(map, 0.3F), 0.0F);
        expectNear(sample(map, std::numeric_limits<float>::quiet_NaN(), 4),
                   vv::colormaps::noDataColor(map), 0.0F);
    }
    EXPECT_EQ(vv::colormaps::binIndex(1.0F, 4), 3);
    EXPECT_EQ(vv::colormaps::binIndex(0.25F, 4), 1);
    EXPECT_EQ(vv::colormaps::binIndex(-1.0F, 4), 0);
    EXPECT_NO_THROW(vv::colormaps::validateBins(0));
    EXPECT_NO_THROW(vv::colormaps::validateBins(256));
    EXPECT_THROW(vv::colormaps::validateBins(1), vv::InvalidArgumentError);
    EXPECT_THROW(vv::colormaps::validateBins(257), vv::InvalidArgumentError);
    EXPECT_THROW(vv::colormaps::validateBins(-2), vv::InvalidArgumentError);
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
