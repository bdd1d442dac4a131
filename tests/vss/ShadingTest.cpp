// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <limits>

#include "vv/core/Error.h"
#include "vv/vss/Shading.h"

namespace vv::vss {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

TEST(IsoLevelTest, BandsAndDistanceToTheNearestLine) {
    // Lines at k / 4: 0, 0.25, 0.5, 0.75, 1.
    EXPECT_EQ(isoLevel(0.0F, 4).band, 0);
    EXPECT_FLOAT_EQ(isoLevel(0.0F, 4).distance, 0.0F);
    EXPECT_EQ(isoLevel(0.3F, 4).band, 1);
    EXPECT_NEAR(isoLevel(0.3F, 4).distance, 0.2F, 1e-6);    // 0.3 * 4 = 1.2
    EXPECT_NEAR(isoLevel(0.45F, 4).distance, 0.2F, 1e-6);   // 1.8: 0.2 below line 2
    EXPECT_NEAR(isoLevel(0.125F, 4).distance, 0.5F, 1e-6);  // the middle of a band
    EXPECT_EQ(isoLevel(1.0F, 4).band, 3);
    EXPECT_FLOAT_EQ(isoLevel(1.0F, 4).distance, 0.0F);
    // Clamped outside [0, 1].
    EXPECT_EQ(isoLevel(-0.5F, 4).band, 0);
    EXPECT_EQ(isoLevel(7.0F, 4).band, 3);
    // No VSS.
    EXPECT_EQ(isoLevel(kNaN, 4).band, -1);
    EXPECT_TRUE(std::isnan(isoLevel(kNaN, 4).distance));
    EXPECT_EQ(isoLevel(0.99F, 1).band, 0);
    EXPECT_THROW(static_cast<void>(isoLevel(0.5F, 0)), InvalidArgumentError);
    // Distance is always in [0, 0.5].
    for (int i = 0; i <= 1000; ++i) {
        const auto l = isoLevel(static_cast<float>(i) / 1000.0F, 7);
        EXPECT_GE(l.distance, 0.0F);
        EXPECT_LE(l.distance, 0.5F);
        EXPECT_GE(l.band, 0);
        EXPECT_LT(l.band, 7);
    }
}

TEST(HeightFieldNormalsTest, TiltedPlaneInSceneUnits) {
    // h = z * scale with z = 0.01 x + 0.02 y; scale 10 mm, pixel 0.5 mm:
    // dh/dx = 0.1 / 0.5 = 0.2, dh/dy = 0.4.
    Image<float> z(6, 5);
    for (int y = 0; y < 5; ++y) {
        for (int x = 0; x < 6; ++x) {
            z(x, y) = 0.01F * x + 0.02F * y;
        }
    }
    const auto n = heightFieldNormals(z.view(), 10.0, 0.5);
    const glm::vec3 expected = glm::normalize(glm::vec3(0.2F, 0.4F, -1.0F));
    for (int y = 0; y < 5; ++y) {
        for (int x = 0; x < 6; ++x) {  // borders included: one-sided differences
            EXPECT_NEAR(n(x, y).x, expected.x, 1e-5) << x << ", " << y;
            EXPECT_NEAR(n(x, y).y, expected.y, 1e-5);
            EXPECT_NEAR(n(x, y).z, expected.z, 1e-5);
            EXPECT_NEAR(glm::length(n(x, y)), 1.0F, 1e-6);
        }
    }
}

TEST(HeightFieldNormalsTest, CentralDifferencesInside) {
    // h = x^2: central difference at x = 2 is ((9 - 1) / 2) = 4, one-sided at 0 is 1.
    Image<float> z(5, 1);
    for (int x = 0; x < 5; ++x) {
        z(x, 0) = static_cast<float>(x * x);
    }
    const auto n = heightFieldNormals(z.view(), 1.0, 1.0);
    EXPECT_NEAR(n(2, 0).x / -n(2, 0).z, 4.0F, 1e-5);
    EXPECT_NEAR(n(0, 0).x / -n(0, 0).z, 1.0F, 1e-5);
    EXPECT_NEAR(n(4, 0).x / -n(4, 0).z, 7.0F, 1e-5);
    EXPECT_EQ(n(2, 0).y, 0.0F);  // a single row: no y derivative
}

TEST(HeightFieldNormalsTest, OneSidedNextToNaNAndNeverNaN) {
    Image<float> z(5, 3, 0.0F);
    for (int y = 0; y < 3; ++y) {
        for (int x = 0; x < 5; ++x) {
            z(x, y) = 0.1F * x;
        }
    }
    z(3, 1) = kNaN;
    z(0, 2) = kNaN;
    z(1, 2) = std::numeric_limits<float>::infinity();
    const auto n = heightFieldNormals(z.view(), 1.0, 1.0);
    // (2, 1): right neighbour missing, left difference 0.1.
    EXPECT_NEAR(n(2, 1).x / -n(2, 1).z, 0.1F, 1e-6);
    // (4, 1): left neighbour missing and at the border: no x derivative.
    EXPECT_EQ(n(4, 1).x, 0.0F);
    // No VSS: facing the viewer.
    EXPECT_EQ(n(3, 1), glm::vec3(0.0F, 0.0F, -1.0F));
    for (int y = 0; y < 3; ++y) {
        for (int x = 0; x < 5; ++x) {
            EXPECT_FALSE(std::isnan(n(x, y).x) || std::isnan(n(x, y).y) || std::isnan(n(x, y).z));
        }
    }
}

TEST(HeightFieldNormalsTest, FlatAndExtremeScales) {
    Image<float> z(4, 4, 0.5F);
    z(1, 1) = 0.7F;
    const auto flat = heightFieldNormals(z.view(), 0.0, 1.0);  // flat scene: dmax = dmin
    for (int y = 0; y < 4; ++y) {
        for (int x = 0; x < 4; ++x) {
            EXPECT_EQ(flat(x, y), glm::vec3(0.0F, 0.0F, -1.0F));
        }
    }
    const auto steep = heightFieldNormals(z.view(), 1e300, 1e-300);
    for (int y = 0; y < 4; ++y) {
        for (int x = 0; x < 4; ++x) {
            EXPECT_TRUE(std::isfinite(steep(x, y).x) && std::isfinite(steep(x, y).z));
        }
    }
    EXPECT_THROW(static_cast<void>(heightFieldNormals(z.view(), -1.0, 1.0)), InvalidArgumentError);
    EXPECT_THROW(static_cast<void>(heightFieldNormals(z.view(), 1.0, 0.0)), InvalidArgumentError);
    EXPECT_THROW(static_cast<void>(heightFieldNormals(z.view(), std::nan(""), 1.0)),
                 InvalidArgumentError);
}

}  // namespace
}  // namespace vv::vss
