// SPDX-License-Identifier: GPL-3.0-or-later
// What real segmentations do to centrelines (the VMTK users' complaints):
// repeated points and triangles, triangles without area, holes in a wall,
// a non-manifold fin, triangles wound the wrong way, ends on another piece,
// a single point. Each gets a result or a clear error, never a hang.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "vv/analysis/Centerlines.h"
#include "vv/demo/TubePhantom.h"

namespace {

using vv::analysis::AnalysisError;
using vv::analysis::CenterlineOptions;
using vv::analysis::computeCenterlines;
using vv::analysis::EndPoint;

vv::scene::Mesh cylinder(std::size_t triangles = 20'000) {
    vv::demo::TubePhantomOptions o;
    o.radiusMm = 5.0;
    o.lengthMm = 100.0;
    o.targetTriangles = triangles;
    return vv::demo::makeTubePhantom(o).mesh;
}

bool notesSay(const vv::analysis::CenterlineTree& tree, const std::string& what) {
    return std::ranges::any_of(
        tree.notes, [&](const std::string& note) { return note.find(what) != std::string::npos; });
}

void expectOneTube(const vv::analysis::CenterlineTree& tree) {
    ASSERT_EQ(tree.branches.size(), 1U);
    EXPECT_NEAR(tree.branches[0].lengthMm, 100.0, 1.0);
    for (const auto& end : tree.ends) {
        EXPECT_EQ(end.kind, EndPoint::Kind::OpenEnd);
    }
}

TEST(Robustness, RepeatedPointsAndTrianglesAndTrianglesWithoutArea) {
    vv::scene::Mesh mesh = cylinder();
    const std::size_t triangles = mesh.triangleCount();
    // Every point once more, the second half of the triangles using the copies.
    const auto n = static_cast<std::uint32_t>(mesh.positions.size());
    for (std::uint32_t i = 0; i < n; ++i) {
        mesh.positions.push_back(mesh.positions[i]);
        mesh.normals.push_back(mesh.normals[i]);
    }
    for (std::size_t i = mesh.indices.size() / 2; i < mesh.indices.size(); ++i) {
        mesh.indices[i] += n;
    }
    for (std::size_t t = 0; t < 100; ++t) {  // 100 repeated triangles
        mesh.indices.insert(mesh.indices.end(), {mesh.indices[3 * t], mesh.indices[3 * t + 1],
                                                 mesh.indices[3 * t + 2]});
    }
    for (std::uint32_t t = 0; t < 10; ++t) {  // 10 without area
        mesh.indices.insert(mesh.indices.end(), {t, t, t + 1});
    }
    const auto tree = computeCenterlines(mesh);
    expectOneTube(tree);
    EXPECT_TRUE(notesSay(tree, "10 degenerate triangles")) << triangles;
    EXPECT_TRUE(notesSay(tree, "100 repeated triangles"));
}

// A hole in the wall (2 mm across, in a 10 mm vessel) is closed, not taken
// for a vessel's end: still one branch, and the user is told.
TEST(Robustness, AHoleInTheWallIsNotAVesselEnd) {
    vv::scene::Mesh mesh = cylinder(50'000);
    const glm::vec3 at(5.0F, 0.0F, 50.0F);
    std::vector<std::uint32_t> kept;
    for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
        const glm::vec3 centre =
            (mesh.positions[mesh.indices[t]] + mesh.positions[mesh.indices[t + 1]] +
             mesh.positions[mesh.indices[t + 2]]) /
            3.0F;
        if (glm::length(centre - at) > 1.0F) {
            kept.insert(kept.end(), {mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]});
        }
    }
    ASSERT_LT(kept.size(), mesh.indices.size());
    mesh.indices = kept;
    const auto tree = computeCenterlines(mesh);
    expectOneTube(tree);
    EXPECT_EQ(tree.ends.size(), 2U);
    EXPECT_TRUE(notesSay(tree, "1 hole in a vessel wall was closed"));
}

// A fin: a triangle on an edge two triangles already share (non-manifold),
// and a patch of triangles wound the wrong way.
TEST(Robustness, ANonManifoldFinAndTrianglesWoundTheWrongWay) {
    vv::scene::Mesh mesh = cylinder();
    const std::uint32_t a = mesh.indices[std::size_t{3} * 500];
    const std::uint32_t b = mesh.indices[std::size_t{3} * 500 + 1];
    mesh.positions.push_back(mesh.positions[a] * 1.3F);
    mesh.normals.emplace_back(0.0F, 0.0F, 1.0F);
    mesh.indices.insert(mesh.indices.end(),
                        {a, b, static_cast<std::uint32_t>(mesh.positions.size() - 1)});
    for (std::size_t t = 1000; t < 1400; t += 2) {
        std::swap(mesh.indices[3 * t + 1], mesh.indices[3 * t + 2]);
    }
    const auto tree = computeCenterlines(mesh);
    expectOneTube(tree);
    EXPECT_TRUE(notesSay(tree, "turned round"));
}

TEST(Robustness, AnEndOnAnotherPieceIsAClearError) {
    vv::scene::Mesh mesh = cylinder(5'000);
    const vv::scene::Mesh other = cylinder(5'000);
    const auto offset = static_cast<std::uint32_t>(mesh.positions.size());
    for (const auto& p : other.positions) {
        mesh.positions.push_back(p + glm::vec3(40.0F, 0.0F, 0.0F));
        mesh.normals.emplace_back(0.0F, 0.0F, 1.0F);
    }
    for (const auto index : other.indices) {
        mesh.indices.push_back(index + offset);
    }
    CenterlineOptions options;
    options.source = glm::dvec3(0.0, 0.0, 0.0);
    options.targets = {glm::dvec3(40.0, 0.0, 100.0)};  // the other tube's end
    try {
        static_cast<void>(computeCenterlines(mesh, options));
        FAIL() << "no error";
    } catch (const AnalysisError& e) {
        EXPECT_NE(std::string(e.what()).find("another piece"), std::string::npos) << e.what();
    }
}

TEST(Robustness, ASinglePointIsAClearError) {
    vv::scene::Mesh point;
    point.name = "point";
    point.positions = {{1.0F, 2.0F, 3.0F}};
    try {
        static_cast<void>(computeCenterlines(point));
        FAIL() << "no error";
    } catch (const AnalysisError& e) {
        EXPECT_NE(std::string(e.what()).find("no triangles"), std::string::npos) << e.what();
    }
}

// A surface far larger than a vessel in mm (here the cylinder in
// micrometres, fuzz finding: a 3e10 mm surface hung tracing its path at
// 0.1 mm): refused with a message at the default step, analysed at a step
// that keeps the centreline under 100,000 points.
TEST(Robustness, ASurfaceInMicrometresIsRefusedAtAStepOfHalfAMillimetre) {
    vv::scene::Mesh mesh = cylinder(2'000);
    for (glm::vec3& p : mesh.positions) {
        p *= 1000.0F;
    }
    try {
        static_cast<void>(computeCenterlines(mesh));
        ADD_FAILURE() << "a 100,000 mm centreline at 0.5 mm was not refused";
    } catch (const AnalysisError& e) {
        EXPECT_NE(std::string(e.what()).find("is the surface in mm?"), std::string::npos)
            << e.what();
    }
    CenterlineOptions options;
    options.stepMm = 10.0;
    const auto tree = computeCenterlines(mesh, options);
    ASSERT_EQ(tree.branches.size(), 1U);
    EXPECT_NEAR(tree.branches[0].lengthMm, 100'000.0, 1'000.0);
    EXPECT_NEAR(tree.branches[0].points[tree.branches[0].points.size() / 2].radiusMm, 5'000.0,
                250.0);
}

}  // namespace
