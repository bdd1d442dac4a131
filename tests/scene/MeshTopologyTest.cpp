// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <utility>

#include "TestMeshes.h"
#include "vv/core/Error.h"
#include "vv/demo/DemoTree.h"
#include "vv/meshio/MeshSimplify.h"
#include "vv/scene/MeshTopology.h"

namespace vv::scene {
namespace {

using vv::test::cube;
using vv::test::flip;
using vv::test::flipAll;
using vv::test::merged;

TEST(MeshTopologyTest, ACubeWoundCounterClockwiseFromOutsideIsClosedOutward) {
    EXPECT_EQ(surfaceClosure(cube()), SurfaceClosure::ClosedOutward);
    // Translation far from the origin does not change the verdict.
    EXPECT_EQ(surfaceClosure(cube(glm::vec3(1e4F, -2e4F, 5e3F), 0.5F)),
              SurfaceClosure::ClosedOutward);
}

TEST(MeshTopologyTest, EveryTriangleTurnedMakesItClosedInward) {
    Mesh mesh = cube();
    flipAll(mesh);
    EXPECT_EQ(surfaceClosure(mesh), SurfaceClosure::ClosedInward);
}

TEST(MeshTopologyTest, SignedVolumeAndOrientOutwardTurnAnInsideOutCube) {
    const Mesh outward = cube(glm::vec3(3.0F, -1.0F, 2.0F), 2.0F);
    EXPECT_NEAR(signedVolume(outward), 8.0, 1e-9);
    Mesh mesh = outward;
    EXPECT_FALSE(orientOutward(mesh));  // already outward: unchanged
    EXPECT_EQ(mesh.indices, outward.indices);
    flipAll(mesh);
    mesh.normals.assign(mesh.positions.size(), glm::vec3(0.0F, 0.0F, 1.0F));
    EXPECT_NEAR(signedVolume(mesh), -8.0, 1e-9);
    EXPECT_TRUE(orientOutward(mesh));
    EXPECT_NEAR(signedVolume(mesh), 8.0, 1e-9);
    EXPECT_EQ(surfaceClosure(mesh), SurfaceClosure::ClosedOutward);
    for (const glm::vec3& n : mesh.normals) {
        EXPECT_EQ(n, glm::vec3(0.0F, 0.0F, -1.0F));  // turned with the triangles
    }
}

TEST(MeshTopologyTest, AMissingTriangleLeavesItOpen) {
    Mesh mesh = cube();
    mesh.indices.resize(mesh.indices.size() - 3);
    EXPECT_EQ(surfaceClosure(mesh), SurfaceClosure::Open);
}

TEST(MeshTopologyTest, OneTriangleWoundAgainstItsNeighboursLeavesItOpen) {
    for (std::size_t t = 0; t < 12; ++t) {
        Mesh mesh = cube();
        flip(mesh, t);
        EXPECT_EQ(surfaceClosure(mesh), SurfaceClosure::Open) << "triangle " << t;
    }
}

TEST(MeshTopologyTest, AnEdgeSharedByFourTrianglesIsNotClosed) {
    // Two cubes sharing the edge from (1,1,0) to (1,1,1): every edge still has
    // as many triangles running each way, but that edge has four.
    Mesh mesh = merged(cube(), cube(glm::vec3(1.0F, 1.0F, 0.0F)));
    // Weld the second cube's copies of the shared corners onto the first's.
    for (std::uint32_t& i : mesh.indices) {
        if (i >= 8 && mesh.positions[i] == mesh.positions[3]) {
            i = 3;
        } else if (i >= 8 && mesh.positions[i] == mesh.positions[7]) {
            i = 7;
        }
    }
    EXPECT_EQ(surfaceClosure(mesh), SurfaceClosure::Open);
}

TEST(MeshTopologyTest, PartsFacingTheSameWayAreClosedPartsFacingBothWaysAreOpen) {
    const Mesh two = merged(cube(), cube(glm::vec3(3.0F, 0.0F, 0.0F)));
    EXPECT_EQ(surfaceClosure(two), SurfaceClosure::ClosedOutward);
    Mesh inverted = cube(glm::vec3(3.0F, 0.0F, 0.0F));
    flipAll(inverted);
    // One part outward, the other inward: no one side can be culled for the
    // whole mesh.
    EXPECT_EQ(surfaceClosure(merged(cube(glm::vec3(0.0F), 2.0F), inverted)), SurfaceClosure::Open);
}

TEST(MeshTopologyTest, DegenerateAndFlatSurfacesAreOpen) {
    Mesh degenerate = cube();
    degenerate.indices[1] = degenerate.indices[0];
    EXPECT_EQ(surfaceClosure(degenerate), SurfaceClosure::Open);
    // Two triangles on the same three vertices, wound against each other:
    // every edge pairs up, but they enclose nothing.
    Mesh flat;
    flat.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    flat.indices = {0, 1, 2, 0, 2, 1};
    EXPECT_EQ(surfaceClosure(flat), SurfaceClosure::Open);
    EXPECT_EQ(surfaceClosure(Mesh{}), SurfaceClosure::Open);
}

TEST(MeshTopologyTest, BadIndicesAreRefusedNamingTheFile) {
    Mesh mesh = cube();
    mesh.source = "vessels.stl";
    mesh.indices.back() = 8;
    try {
        (void)surfaceClosure(mesh);
        FAIL() << "no error for an index out of range";
    } catch (const InvalidArgumentError& e) {
        EXPECT_EQ(e.file(), std::filesystem::path("vessels.stl"));
        EXPECT_NE(std::string(e.what()).find("out of range"), std::string::npos) << e.what();
    }
    mesh.indices.pop_back();
    EXPECT_THROW((void)surfaceClosure(mesh), InvalidArgumentError);
}

TEST(MeshTopologyTest, TheDemoTreeIsClosedOutwardAndItsSimplifiedCopyIsChecked) {
    demo::DemoTreeOptions options;
    options.generations = 3;
    options.maxTriangles = 20000;
    const Mesh demo = demo::generateDemoMesh(options);
    EXPECT_EQ(surfaceClosure(demo), SurfaceClosure::ClosedOutward);
    // Decimation may or may not keep it watertight, but never turns it inside out.
    const Mesh coarse = meshio::simplifiedMesh(demo, demo.triangleCount() / 4);
    EXPECT_NE(surfaceClosure(coarse), SurfaceClosure::ClosedInward);
    // The same tree with a hole is open.
    Mesh holed = demo;
    holed.indices.erase(holed.indices.begin(), holed.indices.begin() + 3);
    EXPECT_EQ(surfaceClosure(holed), SurfaceClosure::Open);
}

}  // namespace
}  // namespace vv::scene
