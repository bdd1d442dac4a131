// SPDX-License-Identifier: GPL-3.0-or-later
// The mesh data types: array statistics, normals, bounds.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "vv/scene/Mesh.h"

namespace {

using vv::scene::DataArray;
using vv::scene::Mesh;
using vv::scene::Scene;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

DataArray scalars(std::vector<float> values) {
    DataArray a;
    a.name = "s";
    a.components = 1;
    a.values = std::move(values);
    return a;
}

/// A closed tetrahedron with outward-facing (counter-clockwise) triangles.
Mesh tetrahedron() {
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    m.indices = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
    return m;
}

TEST(DataArray, TupleCountFollowsComponents) {
    DataArray a;
    a.components = 3;
    a.values = {1, 2, 3, 4, 5, 6};
    EXPECT_EQ(a.tupleCount(), 2U);
    a.components = 0;
    EXPECT_EQ(a.tupleCount(), 0U);
}

TEST(DataArray, FiniteRangeOfScalarsSkipsNonFinite) {
    const DataArray a = scalars({3.0F, kNaN, -2.5F, kInf, 7.0F, -kInf});
    const auto range = a.finiteRange();
    ASSERT_TRUE(range.has_value());
    EXPECT_FLOAT_EQ(range->first, -2.5F);
    EXPECT_FLOAT_EQ(range->second, 7.0F);
}

TEST(DataArray, FiniteRangeIsEmptyWithoutFiniteValues) {
    EXPECT_FALSE(scalars({}).finiteRange().has_value());
    EXPECT_FALSE(scalars({kNaN, kInf}).finiteRange().has_value());
}

TEST(DataArray, FiniteRangeOfSingleValue) {
    const auto range = scalars({4.0F}).finiteRange();
    ASSERT_TRUE(range.has_value());
    EXPECT_EQ(range->first, 4.0F);
    EXPECT_EQ(range->second, 4.0F);
}

TEST(DataArray, FiniteRangeOfVectorsIsOfTheMagnitude) {
    DataArray a;
    a.components = 3;
    a.values = {3,    4, 0,   // |v| = 5
                0,    0, -1,  // |v| = 1
                kNaN, 0, 0,   // skipped
                1,    2, 2};  // |v| = 3
    const auto range = a.finiteRange();
    ASSERT_TRUE(range.has_value());
    EXPECT_FLOAT_EQ(range->first, 1.0F);
    EXPECT_FLOAT_EQ(range->second, 5.0F);
}

TEST(DataArray, NonFiniteCountCountsTuples) {
    EXPECT_EQ(scalars({1, kNaN, kInf, -kInf, 2}).nonFiniteCount(), 3U);
    EXPECT_EQ(scalars({1, 2}).nonFiniteCount(), 0U);
    DataArray v;
    v.components = 2;
    v.values = {kNaN, kNaN,  // one tuple, counted once
                1,    kInf,  // one tuple
                1,    2};
    EXPECT_EQ(v.nonFiniteCount(), 2U);
}

TEST(Mesh, CountsAndBounds) {
    const Mesh m = tetrahedron();
    EXPECT_EQ(m.vertexCount(), 4U);
    EXPECT_EQ(m.triangleCount(), 4U);
    const auto box = m.bounds();
    EXPECT_EQ(box.min, glm::vec3(0.0F));
    EXPECT_EQ(box.max, glm::vec3(1.0F));
    EXPECT_TRUE(Mesh{}.bounds().empty());
}

TEST(Mesh, PointArrayFindsByName) {
    Mesh m = tetrahedron();
    m.pointArrays.push_back(scalars({1, 2, 3, 4}));
    m.pointArrays.back().name = "wss";
    m.pointArrays.push_back(scalars({5, 6, 7, 8}));
    m.pointArrays.back().name = "pressure";
    ASSERT_NE(m.pointArray("pressure"), nullptr);
    EXPECT_EQ(m.pointArray("pressure")->values[0], 5.0F);
    EXPECT_EQ(m.pointArray("wss")->values[0], 1.0F);
    EXPECT_EQ(m.pointArray("WSS"), nullptr);
    EXPECT_EQ(m.pointArray(""), nullptr);
}

TEST(Mesh, ComputeNormalsPointOutwardWithUnitLength) {
    Mesh m = tetrahedron();
    vv::scene::computeNormals(m);
    ASSERT_EQ(m.normals.size(), m.positions.size());
    const glm::vec3 centre(0.25F);
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
        EXPECT_NEAR(glm::length(m.normals[i]), 1.0F, 1e-5F);
        EXPECT_GT(glm::dot(m.normals[i], m.positions[i] - centre), 0.0F) << "vertex " << i;
    }
    // Area-weighted: at the apex (0,0,1) the faces -x and -y (area 1/2 each)
    // and the slanted face (1,1,1)/sqrt(3) (area sqrt(3)/2) sum to +z.
    EXPECT_NEAR(glm::length(m.normals[3] - glm::vec3(0, 0, 1)), 0.0F, 1e-6F);
    // At the origin the three axis faces sum to -(1,1,1).
    EXPECT_NEAR(glm::length(m.normals[0] - glm::normalize(glm::vec3(-1))), 0.0F, 1e-6F);
}

TEST(Mesh, ComputeNormalsOfFlatSquareFollowWinding) {
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    m.indices = {0, 1, 2, 0, 2, 3};
    vv::scene::computeNormals(m);
    for (const auto& n : m.normals) {
        EXPECT_NEAR(n.z, 1.0F, 1e-6F);
    }
    m.indices = {0, 2, 1, 0, 3, 2};  // reversed winding
    vv::scene::computeNormals(m);
    for (const auto& n : m.normals) {
        EXPECT_NEAR(n.z, -1.0F, 1e-6F);
    }
}

TEST(Mesh, ComputeNormalsHandlesUnusedAndDegenerateVertices) {
    Mesh m = tetrahedron();
    m.positions.push_back({5, 5, 5});  // in no triangle
    m.positions.push_back({6, 6, 6});
    m.indices.insert(m.indices.end(), {5, 5, 5});   // degenerate triangle
    m.indices.insert(m.indices.end(), {0, 1, 99});  // out of range: ignored
    vv::scene::computeNormals(m);
    ASSERT_EQ(m.normals.size(), 6U);
    EXPECT_EQ(m.normals[4], glm::vec3(0, 0, 1));
    EXPECT_EQ(m.normals[5], glm::vec3(0, 0, 1));
    for (const auto& n : m.normals) {
        EXPECT_TRUE(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z));
    }
}

TEST(Scene, BoundsIsTheUnionOfTheMeshes) {
    Scene scene;
    EXPECT_TRUE(scene.bounds().empty());
    Mesh a = tetrahedron();
    Mesh b = tetrahedron();
    for (auto& p : b.positions) {
        p += glm::vec3(10, -5, 2);
    }
    scene.meshes.push_back(a);
    scene.meshes.push_back(Mesh{});  // an empty mesh does not widen the box
    scene.meshes.push_back(b);
    const auto box = scene.bounds();
    EXPECT_EQ(box.min, glm::vec3(0, -5, 0));
    EXPECT_EQ(box.max, glm::vec3(11, 1, 3));
    EXPECT_FLOAT_EQ(box.center().x, 5.5F);
}

}  // namespace
