// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>
#include <stop_token>

#include "vv/core/Error.h"
#include "vv/meshio/MeshSimplify.h"

namespace vv::meshio {
using scene::DataArray;
using scene::Mesh;
using scene::Scene;
namespace {

constexpr float kRadius = 10.0F;

/// A UV sphere of radius 10 around the origin with a label array (1 above
/// z = 0, 2 below) and a value array (x, NaN where x > 5).
Mesh sphere(int slices, int stacks) {
    Mesh mesh;
    mesh.name = "sphere";
    DataArray label{.name = "label", .unit = "", .components = 1, .values = {}, .integer = true};
    DataArray value{.name = "value", .unit = "mm", .components = 1, .values = {}};
    const auto add = [&](const glm::vec3& p) {
        mesh.positions.push_back(p);
        label.values.push_back(p.z > 0.0F ? 1.0F : 2.0F);
        value.values.push_back(p.x > 5.0F ? std::nanf("") : p.x);
        return static_cast<std::uint32_t>(mesh.positions.size() - 1);
    };
    // One vertex per pole, rings in between: a closed, manifold surface.
    const std::uint32_t north = add(glm::vec3(0.0F, 0.0F, kRadius));
    for (int j = 1; j < stacks; ++j) {
        const double theta = std::numbers::pi * j / stacks;
        for (int i = 0; i < slices; ++i) {
            const double phi = 2.0 * std::numbers::pi * i / slices;
            add(glm::vec3(kRadius * std::sin(theta) * std::cos(phi),
                          kRadius * std::sin(theta) * std::sin(phi), kRadius * std::cos(theta)));
        }
    }
    const std::uint32_t south = add(glm::vec3(0.0F, 0.0F, -kRadius));
    const auto ring = [&](int j, int i) {
        return static_cast<std::uint32_t>(1 + (j - 1) * slices + i % slices);
    };
    for (int i = 0; i < slices; ++i) {
        mesh.indices.insert(mesh.indices.end(), {north, ring(1, i), ring(1, i + 1)});
        mesh.indices.insert(mesh.indices.end(),
                            {south, ring(stacks - 1, i + 1), ring(stacks - 1, i)});
    }
    for (int j = 1; j < stacks - 1; ++j) {
        for (int i = 0; i < slices; ++i) {
            mesh.indices.insert(mesh.indices.end(), {ring(j, i), ring(j + 1, i), ring(j, i + 1)});
            mesh.indices.insert(mesh.indices.end(),
                                {ring(j, i + 1), ring(j + 1, i), ring(j + 1, i + 1)});
        }
    }
    mesh.pointArrays = {label, value};
    computeNormals(mesh);
    return mesh;
}

TEST(MeshSimplifyTest, ReachesAboutTheTargetAndKeepsTheShape) {
    const Mesh input = sphere(160, 80);
    ASSERT_EQ(input.triangleCount(), 160U * 79U * 2U);
    const Mesh out = simplifiedMesh(input, 2000);
    EXPECT_LE(out.triangleCount(), 2200U);
    EXPECT_GE(out.triangleCount(), 1000U);
    ASSERT_EQ(out.normals.size(), out.positions.size());
    for (const std::uint32_t index : out.indices) {
        ASSERT_LT(index, out.vertexCount());
    }
    // Every vertex stays close to the sphere (volume preservation, small error).
    for (const glm::vec3& p : out.positions) {
        EXPECT_NEAR(glm::length(p), kRadius, 0.05F * kRadius);
    }
    const Aabb box = out.bounds();
    EXPECT_NEAR(box.max.x - box.min.x, 2.0F * kRadius, 0.1F * kRadius);
    EXPECT_NEAR(box.max.z - box.min.z, 2.0F * kRadius, 0.1F * kRadius);
    // Normals point outwards.
    for (std::size_t i = 0; i < out.vertexCount(); ++i) {
        EXPECT_GT(glm::dot(out.normals[i], glm::normalize(out.positions[i])), 0.5F);
    }
}

TEST(MeshSimplifyTest, ArraysComeFromTheNearestOriginalVertex) {
    const Mesh input = sphere(120, 60);
    const Mesh out = simplifiedMesh(input, 1500);
    const DataArray* label = out.pointArray("label");
    const DataArray* value = out.pointArray("value");
    ASSERT_NE(label, nullptr);
    ASSERT_NE(value, nullptr);
    EXPECT_TRUE(label->integer);
    EXPECT_EQ(value->unit, "mm");
    ASSERT_EQ(label->tupleCount(), out.vertexCount());
    ASSERT_EQ(value->tupleCount(), out.vertexCount());
    std::size_t nan = 0;
    for (std::size_t i = 0; i < out.vertexCount(); ++i) {
        const glm::vec3& p = out.positions[i];
        // Labels are exact original values, on the right side away from the equator.
        const float l = label->values[i];
        EXPECT_TRUE(l == 1.0F || l == 2.0F) << l;
        if (std::abs(p.z) > 1.0F) {
            EXPECT_EQ(l, p.z > 0.0F ? 1.0F : 2.0F);
        }
        const float v = value->values[i];
        if (std::isnan(v)) {
            ++nan;
            EXPECT_GT(p.x, 4.0F);  // no data stays where it was
        } else {
            EXPECT_NEAR(v, p.x, 1.5F);
        }
    }
    EXPECT_GT(nan, 0U);
}

TEST(MeshSimplifyTest, SmallMeshesComeBackUnchanged) {
    const Mesh input = sphere(12, 6);
    const Mesh out = simplifiedMesh(input, input.triangleCount());
    EXPECT_EQ(out.positions, input.positions);
    EXPECT_EQ(out.indices, input.indices);
}

TEST(MeshSimplifyTest, RefusesTinyTargetsAndStopsWhenCancelled) {
    const Mesh input = sphere(60, 30);
    EXPECT_THROW(static_cast<void>(simplifiedMesh(input, 3)), InvalidArgumentError);
    std::stop_source stop;
    stop.request_stop();
    const Progress cancelled([](double, std::string_view) {}, stop.get_token());
    EXPECT_THROW(static_cast<void>(simplifiedMesh(input, 100, cancelled)), CancelledError);
}

TEST(MeshSimplifyTest, SceneTargetIsSplitByTriangleCount) {
    Scene scene;
    scene.meshes.push_back(sphere(120, 60));  // 14,160 triangles
    scene.meshes.push_back(sphere(60, 30));   // 3,480
    const Scene out = simplifiedScene(scene, 1800);
    ASSERT_EQ(out.meshes.size(), 2U);
    EXPECT_NEAR(static_cast<double>(out.meshes[0].triangleCount()), 1445.0, 300.0);
    EXPECT_NEAR(static_cast<double>(out.meshes[1].triangleCount()), 355.0, 100.0);
}

}  // namespace
}  // namespace vv::meshio
