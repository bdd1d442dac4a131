// SPDX-License-Identifier: GPL-3.0-or-later
// CIEDE2000 of 8-bit colours (colormaps::ciede2000, tested against the
// published data in tests/colormaps) and the colour bar finder on a painted bar.
#include <gtest/gtest.h>

#include <QPainter>

#include "ColourDifference.h"
#include "vv/colormaps/ColorVision.h"

namespace vv::test {
namespace {

TEST(ColourDifference, EightBitColoursGoThroughTheColourMapsCiede2000) {
    EXPECT_EQ(ciede2000(qRgb(10, 200, 30), qRgb(10, 200, 30)), 0.0);
    // The dimmed top Inferno bin is far from the real one.
    EXPECT_GT(ciede2000(qRgb(252, 255, 164), qRgb(184, 179, 96)), 10.0);
    EXPECT_LT(ciede2000(qRgb(252, 255, 164), qRgb(252, 254, 165)), 1.0);
    EXPECT_DOUBLE_EQ(ciede2000(qRgb(0, 0, 4), qRgb(252, 255, 164)),
                     colormaps::ciede2000(glm::dvec3(0.0, 0.0, 4.0 / 255.0),
                                          glm::dvec3(252.0 / 255.0, 1.0, 164.0 / 255.0)));
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
