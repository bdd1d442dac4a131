// SPDX-License-Identifier: GPL-3.0-or-later
// A slab's margins per column: every point inside a sphere lies in a column
// whose margin is at least the least the sphere's columns have (the slab's
// test that a sphere stays within the points it took rests on this), and a
// raise reaches exactly the columns of the sphere's box.
#include <gtest/gtest.h>

#include <random>

#include "CutMargins.h"

namespace vv::analysis::detail {
namespace {

TEST(CutMargins, APointInASphereLiesInAColumnAtLeastAsWideAsTheSpheresLeast) {
    // Slabs across y: the columns are in z and x, 10 x 5 mm of them.
    CutMargins margins(1, {0.0, 0.0, 0.0}, {50.0, 100.0, 100.0}, 10, 0.0);
    std::mt19937 random(7);
    std::uniform_real_distribution<double> coordinate(-20.0, 120.0);
    std::uniform_real_distribution<double> size(0.0, 15.0);
    for (int i = 0; i < 200; ++i) {
        margins.raise({coordinate(random), 0.0, coordinate(random)}, size(random), size(random));
    }
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    int checked = 0;
    for (int i = 0; i < 2000; ++i) {
        const glm::dvec3 centre(coordinate(random), coordinate(random), coordinate(random));
        const double radius = size(random);
        const double least = margins.leastOver(centre, radius);
        for (int k = 0; k < 20; ++k) {
            const glm::dvec3 offset(unit(random), unit(random), unit(random));
            if (glm::length(offset) <= 1.0) {
                EXPECT_GE(margins.at(centre + radius * offset), least);
                ++checked;
            }
        }
    }
    EXPECT_GT(checked, 10000);
    EXPECT_GT(margins.largest(), 0.0);
}

TEST(CutMargins, ARaiseReachesTheColumnsOfTheSpheresBoxAndNoOthers) {
    // 10 columns of 10 mm along x (axis 0 is the slabs' own, so z and x).
    CutMargins margins(1, {0.0, 0.0, 0.0}, {100.0, 10.0, 10.0}, 10, 1.0);
    margins.raise({35.0, 0.0, 5.0}, 4.0, 3.0);  // x from 31 to 39: column 3 alone
    EXPECT_EQ(margins.at({35.0, 50.0, 2.0}), 3.0);
    EXPECT_EQ(margins.at({29.0, 0.0, 5.0}), 1.0);
    EXPECT_EQ(margins.at({41.0, 0.0, 5.0}), 1.0);
    margins.raise({40.0, 0.0, 5.0}, 1.0, 2.0);     // 39 to 41: columns 3 and 4
    EXPECT_EQ(margins.at({35.0, 0.0, 5.0}), 3.0);  // never lowered
    EXPECT_EQ(margins.at({45.0, 0.0, 5.0}), 2.0);
    EXPECT_EQ(margins.leastOver({40.0, 0.0, 5.0}, 20.0), 1.0);
    // Beyond the grid: the nearest column's.
    EXPECT_EQ(margins.at({-50.0, 0.0, 5.0}), 1.0);
    margins.raiseAll(5.0);
    EXPECT_EQ(margins.largest(), 5.0);
    EXPECT_EQ(margins.leastOver({1e9, 0.0, -1e9}, 1.0), 5.0);
}

TEST(CutMargins, WithoutColumnsEveryMarginIsZero) {
    CutMargins none;
    EXPECT_EQ(none.at({1.0, 2.0, 3.0}), 0.0);
    EXPECT_EQ(none.leastOver({1.0, 2.0, 3.0}, 5.0), 0.0);
    EXPECT_EQ(none.largest(), 0.0);
}

}  // namespace
}  // namespace vv::analysis::detail
