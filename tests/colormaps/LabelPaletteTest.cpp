// SPDX-License-Identifier: GPL-3.0-or-later
// The label palette (LabelPalette.h): the rule that picks its colours, and
// that its labels stay apart under colour-vision deficiency.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "vv/colormaps/ColorVision.h"
#include "vv/colormaps/DepthScale.h"
#include "vv/colormaps/LabelPalette.h"

namespace vv::colormaps {
namespace {

/// The chromadepth scale's yellow: its lightest colour (L* peaks at yellow).
glm::dvec3 chromadepthYellow() {
    glm::dvec3 best(0.0);
    double bestL = -1.0;
    for (int i = 0; i <= 1000; ++i) {
        const glm::dvec3 c(sample(DepthScale::Chromadepth, static_cast<float>(i) / 1000.0F));
        if (srgbToLab(c).l > bestL) {
            bestL = srgbToLab(c).l;
            best = c;
        }
    }
    return best;
}

TEST(LabelPaletteTest, NoLabelColourNearChromadepthYellowOrDark) {
    const glm::dvec3 yellow = chromadepthYellow();
    ASSERT_GE(labelPalette().size(), 6U);
    for (const glm::vec3& c : labelPalette()) {
        EXPECT_GE(ciede2000(glm::dvec3(c), yellow), 15.0) << c.r << "," << c.g << "," << c.b;
        EXPECT_GE(srgbToLab(glm::dvec3(c)).l, 30.0);
    }
}

TEST(LabelPaletteTest, LabelsStayApartForEveryColourVision) {
    const auto palette = labelPalette();
    for (const ColorVision vision : allColorVisions()) {
        double smallest = 1e9;
        for (std::size_t i = 0; i < palette.size(); ++i) {
            for (std::size_t j = i + 1; j < palette.size(); ++j) {
                smallest = std::min(smallest, ciede2000(simulate(vision, glm::dvec3(palette[i])),
                                                        simulate(vision, glm::dvec3(palette[j]))));
            }
        }
        // About 5 just-noticeable differences between any two labels.
        EXPECT_GE(smallest, 5.0) << name(vision);
    }
}

TEST(LabelPaletteTest, IndexWrapsAround) {
    const auto palette = labelPalette();
    EXPECT_EQ(labelColor(0), palette[0]);
    EXPECT_EQ(labelColor(palette.size() + 1), palette[1]);
}

}  // namespace
}  // namespace vv::colormaps
