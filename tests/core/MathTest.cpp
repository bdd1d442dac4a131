// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "vv/core/Math.h"

namespace {

TEST(Aabb, EmptyUntilExtended) {
    vv::Aabb box;
    EXPECT_TRUE(box.empty());
    EXPECT_EQ(box.size(), glm::vec3(0.0F));
    box.extend(glm::vec3(1, 2, 3));
    EXPECT_FALSE(box.empty());
    box.extend(glm::vec3(-1, 0, 5));
    EXPECT_EQ(box.min, glm::vec3(-1, 0, 3));
    EXPECT_EQ(box.max, glm::vec3(1, 2, 5));
    EXPECT_EQ(box.center(), glm::vec3(0, 1, 4));
    EXPECT_FLOAT_EQ(box.radius(), std::sqrt(12.0F) / 2.0F);  // size (2, 2, 2)
}

TEST(Aabb, ExtendByEmptyBoxChangesNothing) {
    vv::Aabb box;
    box.extend(glm::vec3(0));
    const vv::Aabb before = box;
    box.extend(vv::Aabb{});
    EXPECT_EQ(box.min, before.min);
    EXPECT_EQ(box.max, before.max);
}

TEST(Math, FiniteAndArea) {
    EXPECT_TRUE(vv::isFinite(glm::vec3(1, 2, 3)));
    EXPECT_FALSE(vv::isFinite(glm::vec3(1, NAN, 3)));
    EXPECT_FALSE(vv::isFinite(glm::vec3(INFINITY, 0, 0)));
    EXPECT_FLOAT_EQ(vv::doubleTriangleArea({0, 0, 0}, {2, 0, 0}, {0, 3, 0}), 6.0F);
    const std::vector<glm::vec3> pts{{0, 0, 0}, {1, -1, 2}};
    const auto b = vv::boundsOf(pts);
    EXPECT_EQ(b.min, glm::vec3(0, -1, 0));
    EXPECT_EQ(b.max, glm::vec3(1, 0, 2));
}

}  // namespace
