// SPDX-License-Identifier: GPL-3.0-or-later
// CIEDE2000 against the published test data (Sharma, Wu, Dalal 2005, table 1)
// and the colour bar finder on a painted bar.
#include <gtest/gtest.h>

#include <QPainter>

#include "ColourDifference.h"

namespace vv::test {
namespace {

TEST(ColourDifference, Ciede2000MatchesThePublishedPairs) {
    struct Pair {
        Lab x;
        Lab y;
        double expected;
    };
    const Pair pairs[] = {
        {{50.0, 2.6772, -79.7751}, {50.0, 0.0, -82.7485}, 2.0425},
        {{50.0, 0.0, 0.0}, {50.0, -1.0, 2.0}, 2.3669},
        {{50.0, 2.49, -0.001}, {50.0, -2.49, 0.0009}, 7.1792},
        {{50.0, 2.5, 0.0}, {73.0, 25.0, -18.0}, 27.1492},
        {{60.2574, -34.0099, 36.2677}, {60.4626, -34.1751, 39.4387}, 1.2644},
        {{22.7233, 20.0904, -46.6940}, {23.0331, 14.9730, -42.5619}, 2.0373},
    };
    for (const Pair& p : pairs) {
        EXPECT_NEAR(ciede2000(p.x, p.y), p.expected, 5e-5);
        EXPECT_NEAR(ciede2000(p.y, p.x), p.expected, 5e-5);  // symmetric
    }
    const Lab white = toLab(qRgb(255, 255, 255));
    EXPECT_NEAR(white.l, 100.0, 0.01);
    EXPECT_NEAR(white.a, 0.0, 0.01);
    EXPECT_NEAR(white.b, 0.0, 0.01);
    EXPECT_EQ(ciede2000(qRgb(10, 200, 30), qRgb(10, 200, 30)), 0.0);
}

TEST(ColourDifference, FindsABarAndSeesDimmedColours) {
    const std::vector<QRgb> table = {qRgb(0, 0, 4), qRgb(120, 28, 109), qRgb(252, 255, 164)};
    QImage image(200, 60, QImage::Format_RGB32);
    image.fill(qRgb(40, 40, 40));
    for (int x = 20; x < 170; ++x) {
        for (int y = 20; y < 30; ++y) {
            image.setPixel(x, y, table[static_cast<std::size_t>((x - 20) / 50)]);
        }
    }
    const auto bar = findBar(image, image.rect(), table.front(), table.back(), 5);
    ASSERT_TRUE(bar);
    EXPECT_EQ(bar->left, 20);
    EXPECT_EQ(bar->right, 169);
    EXPECT_TRUE(barMismatches(image, *bar, table).empty());
    // The same bar at two thirds opacity over the dark background is not found.
    QImage dimmed = image;
    {
        QPainter p(&dimmed);
        p.setOpacity(0.33);
        p.fillRect(dimmed.rect(), QColor(40, 40, 40));
    }
    EXPECT_FALSE(findBar(dimmed, dimmed.rect(), table.front(), table.back(), 5));
    EXPECT_EQ(barMismatches(dimmed, *bar, table).size(), 3U);
}

}  // namespace
}  // namespace vv::test
