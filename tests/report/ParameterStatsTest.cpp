// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "ReportTestUtil.h"
#include "vv/core/Error.h"
#include "vv/report/ParameterStats.h"

namespace vv::report {
namespace {

TEST(AreaFraction, MatchesMonteCarlo) {
    // Corner values and thresholds in every ordering; sample the triangle.
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const double cases[][4] = {{0, 0, 1, 0.5},  {0, 1, 2, 0.5},  {0, 1, 2, 1.5}, {2, 0, 1, 1.0},
                               {3, 3, 3, 3.5},  {-1, 5, 2, 0.0}, {1, 1, 4, 2.0}, {0, 4, 4, 1.0},
                               {0, 1, 2, -1.0}, {0, 1, 2, 2.5}};
    for (const auto& c : cases) {
        int below = 0;
        constexpr int kSamples = 200000;
        for (int s = 0; s < kSamples; ++s) {
            double u = unit(random);
            double v = unit(random);
            if (u + v > 1.0) {
                u = 1.0 - u;
                v = 1.0 - v;
            }
            const double f = c[0] * (1.0 - u - v) + c[1] * u + c[2] * v;
            below += f < c[3] ? 1 : 0;
        }
        const double expected = static_cast<double>(below) / kSamples;
        EXPECT_NEAR(areaFractionBelow(c[0], c[1], c[2], c[3]), expected, 0.005)
            << c[0] << " " << c[1] << " " << c[2] << " t=" << c[3];
    }
    EXPECT_DOUBLE_EQ(areaFractionBelow(0, 0, 1, 0.5), 0.75);
    EXPECT_DOUBLE_EQ(areaFractionBelow(0, 1, 1, 0.5), 0.25);
}

TEST(ParameterStats, AreaWeightedOverTheTube) {
    scene::Scene scene;
    scene.meshes.push_back(test::makeTube("left"));
    scene::Mesh noArray = test::makeTube("no array");
    noArray.pointArrays.clear();
    scene.meshes.push_back(std::move(noArray));
    const auto stats = parameterStats(scene, "wss", {0.4, 8.0});
    ASSERT_EQ(stats.size(), 1U);  // the mesh without the array is left out
    const ParameterStats& s = stats.front();
    EXPECT_EQ(s.object, "left");
    EXPECT_EQ(s.triangles, scene.meshes[0].triangleCount());
    EXPECT_DOUBLE_EQ(s.coveredFraction, 1.0);
    EXPECT_FLOAT_EQ(static_cast<float>(s.min), 0.0F);
    EXPECT_FLOAT_EQ(static_cast<float>(s.max), 10.0F);
    // wss = x / 2 on a tube of uniform girth: mean 5, 4 % of the length below 0.4,
    // 20 % above 8 (exact for a linear function).
    EXPECT_NEAR(s.mean, 5.0, 1e-4);
    ASSERT_TRUE(s.fractionBelow && s.fractionAbove);
    EXPECT_NEAR(*s.fractionBelow, 0.04, 1e-6);
    EXPECT_NEAR(*s.fractionAbove, 0.20, 1e-6);
    // The tube's area: 2 pi r L, polygonal (32 segments).
    EXPECT_NEAR(s.area, 2.0 * 32.0 * std::sin(3.14159265358979 / 32.0) * 20.0, 1e-3);
}

TEST(ParameterStats, WeightsByAreaAndSkipsMissingValues) {
    // Two triangles: a large one (area 2) with value 1, a small one (area 0.5)
    // with value 3, and a third with a NaN corner that is left out.
    scene::Mesh mesh;
    mesh.name = "patch";
    mesh.positions = {{0, 0, 0},  {2, 0, 0},  {0, 2, 0},  {10, 0, 0}, {11, 0, 0},
                      {10, 1, 0}, {20, 0, 0}, {21, 0, 0}, {20, 1, 0}};
    mesh.indices = {0, 1, 2, 3, 4, 5, 6, 7, 8};
    scene::DataArray a;
    a.name = "wss";
    const float nan = std::numeric_limits<float>::quiet_NaN();
    a.values = {1, 1, 1, 3, 3, 3, 5, nan, 5};
    mesh.pointArrays.push_back(a);
    scene::Scene scene;
    scene.meshes.push_back(mesh);
    const auto stats = parameterStats(scene, "wss", {2.0, std::nullopt});
    ASSERT_EQ(stats.size(), 1U);
    EXPECT_EQ(stats[0].triangles, 2U);
    EXPECT_NEAR(stats[0].mean, (2.0 * 1 + 0.5 * 3) / 2.5, 1e-12);
    EXPECT_NEAR(*stats[0].fractionBelow, 0.8, 1e-12);
    EXPECT_FALSE(stats[0].fractionAbove);
    EXPECT_NEAR(stats[0].coveredFraction, 2.5 / 3.0, 1e-12);
    EXPECT_DOUBLE_EQ(stats[0].max, 3.0);
}

TEST(ParameterStats, VectorArraysUseTheMagnitude) {
    scene::Mesh mesh;
    mesh.name = "v";
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.indices = {0, 1, 2};
    scene::DataArray a;
    a.name = "velocity";
    a.components = 3;
    a.values = {3, 4, 0, 0, 0, 5, 5, 0, 0};
    mesh.pointArrays.push_back(a);
    scene::Scene scene;
    scene.meshes.push_back(mesh);
    const auto stats = parameterStats(scene, "velocity", {});
    ASSERT_EQ(stats.size(), 1U);
    EXPECT_DOUBLE_EQ(stats[0].min, 5.0);
    EXPECT_DOUBLE_EQ(stats[0].mean, 5.0);
}

TEST(ParameterStats, RejectsBadArguments) {
    scene::Scene scene;
    EXPECT_THROW((void)parameterStats(scene, "", {}), InvalidArgumentError);
    EXPECT_THROW((void)parameterStats(scene, "wss", {std::numeric_limits<double>::infinity(), {}}),
                 InvalidArgumentError);
    EXPECT_TRUE(parameterStats(scene, "wss", {}).empty());
}

}  // namespace
}  // namespace vv::report
