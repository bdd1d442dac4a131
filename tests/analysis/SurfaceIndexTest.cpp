// SPDX-License-Identifier: GPL-3.0-or-later
// The surface index built on a thread of its own answers as the one built
// at once, to queries from several threads that arrive before it is done;
// and its answers are those of every triangle tried in turn.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <thread>
#include <vector>

#include "PreparedSurface.h"
#include "SurfaceIndex.h"
#include "TubeOptions.h"
#include "vv/demo/TubePhantom.h"

namespace vv::analysis::detail {
namespace {

TEST(SurfaceIndex, BuiltInTheBackgroundAnswersAsBuiltAtOnce) {
    const auto tube =
        demo::makeTubePhantom(test::tubeOptions(demo::TubeShape::Cylinder, 5.0, 200'000));
    const PreparedSurface s = prepareSurface(tube.mesh, std::nullopt, {}, 3'000'000);
    const SurfaceIndex now(s);
    const SurfaceIndex later(s, SurfaceIndex::Build::InBackground);
    // Points along the axis and off it; each thread asks its own half.
    std::vector<glm::dvec3> probes;
    for (int i = 0; i < 64; ++i) {
        probes.emplace_back(0.3 * (i % 7), -0.2 * (i % 5), 1.5 * i);
    }
    std::vector<double> expected;
    for (const glm::dvec3& p : probes) {
        expected.push_back(now.nearest(p).distance);
    }
    std::vector<double> got(probes.size(), -1.0);
    {
        std::jthread other([&] {
            for (std::size_t i = 1; i < probes.size(); i += 2) {
                got[i] = later.nearest(probes[i]).distance;
            }
        });
        for (std::size_t i = 0; i < probes.size(); i += 2) {
            got[i] = later.nearest(probes[i]).distance;
        }
    }
    for (std::size_t i = 0; i < probes.size(); ++i) {
        EXPECT_EQ(got[i], expected[i]) << i;
        EXPECT_GT(expected[i], 0.0);
    }
    const auto hit = later.firstHit({0.0, 0.0, 50.0}, {1.0, 0.0, 0.0});
    ASSERT_TRUE(hit.has_value());
    EXPECT_NEAR(hit->x, 5.0, 0.05);
}

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

Kernel::Triangle_3 triangleOf(const PreparedSurface& s, std::uint32_t t) {
    const auto point = [&](std::uint32_t v) {
        return Kernel::Point_3(s.positions[v].x, s.positions[v].y, s.positions[v].z);
    };
    return {point(s.triangles[t][0]), point(s.triangles[t][1]), point(s.triangles[t][2])};
}

// The tree reads its triangles from the surface and starts from sparse
// hints: neither may change an answer. A narrowed tube (20k triangles), probed
// inside, outside and far away.
TEST(SurfaceIndex, AnswersAsEveryTriangleTriedInTurn) {
    const auto tube =
        demo::makeTubePhantom(test::tubeOptions(demo::TubeShape::Stenosis, 5.0, 20'000));
    const PreparedSurface s = prepareSurface(tube.mesh, std::nullopt, {}, 3'000'000);
    const SurfaceIndex index(s);
    std::mt19937 random(7);
    std::uniform_real_distribution<double> across(-12.0, 12.0);
    std::uniform_real_distribution<double> along(-30.0, 130.0);
    for (int i = 0; i < 200; ++i) {
        const glm::dvec3 p(across(random), across(random), along(random));
        double best = std::numeric_limits<double>::max();
        for (std::uint32_t t = 0; t < s.triangles.size(); ++t) {
            best = std::min(
                best, CGAL::squared_distance(Kernel::Point_3(p.x, p.y, p.z), triangleOf(s, t)));
        }
        const SurfaceIndex::Nearest n = index.nearest(p);
        EXPECT_NEAR(n.distance, std::sqrt(best), 1e-9) << i;
        // The triangle it names holds the point it gives.
        EXPECT_NEAR(
            std::sqrt(CGAL::squared_distance(Kernel::Point_3(n.point.x, n.point.y, n.point.z),
                                             triangleOf(s, n.triangle))),
            0.0, 1e-9)
            << i;
        glm::dvec3 hint =
            s.positions[s.triangles[(static_cast<std::size_t>(i) * 97U) % s.triangles.size()][0]];
        EXPECT_NEAR(index.distance(p, hint), std::sqrt(best), 1e-9) << i;
    }
    // A section plane's triangles: those with corners on both sides.
    const glm::dvec3 point(0.0, 0.0, 50.0);
    const glm::dvec3 normal = glm::normalize(glm::dvec3(0.1, 0.0, 1.0));
    std::vector<std::uint32_t> crossing =
        index.trianglesOnPlane(point, normal, glm::dvec3(-100.0), glm::dvec3(100.0));
    std::sort(crossing.begin(), crossing.end());
    std::vector<std::uint32_t> expected;
    for (std::uint32_t t = 0; t < s.triangles.size(); ++t) {
        int above = 0;
        for (const std::uint32_t v : s.triangles[t]) {
            above += glm::dot(s.positions[v] - point, normal) >= 0.0 ? 1 : 0;
        }
        if (above == 1 || above == 2) {
            expected.push_back(t);
        }
    }
    EXPECT_FALSE(expected.empty());
    EXPECT_EQ(crossing, expected);
}

// Built when first asked, the first kScanQueries queries that ask for a
// scan come from a scan of every triangle, without building the tree; they
// are the tree's answers. A query that does not ask for one, or one past
// the budget, builds the tree.
TEST(SurfaceIndex, ScannedQueriesAnswerAsTheTreeWithoutBuildingIt) {
    using Lookup = SurfaceIndex::Lookup;
    const auto tube =
        demo::makeTubePhantom(test::tubeOptions(demo::TubeShape::TorusSegment, 5.0, 20'000));
    const PreparedSurface s = prepareSurface(tube.mesh, std::nullopt, {}, 3'000'000);
    const SurfaceIndex tree(s);
    const SurfaceIndex scanned(s, SurfaceIndex::Build::OnFirstQuery);
    std::mt19937 random(11);
    std::uniform_real_distribution<double> coordinate(-20.0, 60.0);
    for (int i = 0; i < SurfaceIndex::kScanQueries / 2; ++i) {
        const glm::dvec3 p(coordinate(random), coordinate(random) / 4.0, coordinate(random));
        const SurfaceIndex::Nearest a = tree.nearest(p);
        const SurfaceIndex::Nearest b = scanned.nearest(p, Lookup::ScanUnlessBuilt);
        EXPECT_NEAR(b.distance, a.distance, 1e-12) << i;
        EXPECT_NEAR(glm::length(b.point - a.point), 0.0, 1e-9) << i;
        // From inside the lumen outward, the wall.
        const glm::dvec3 inside = tube.axisAt(10.0 * (i + 1)).position;
        const glm::dvec3 direction(std::cos(i), std::sin(i), 0.3);
        const auto hitA = tree.firstHit(inside, direction);
        const auto hitB = scanned.firstHit(inside, direction, Lookup::ScanUnlessBuilt);
        ASSERT_TRUE(hitA.has_value());
        ASSERT_TRUE(hitB.has_value());
        EXPECT_NEAR(glm::length(*hitB - *hitA), 0.0, 1e-9) << i;
        EXPECT_NEAR(tube.distanceToAxis(*hitB).first, 5.0, 0.05) << i;  // on the wall
    }
    EXPECT_FALSE(scanned.built());
    // Past the budget: the tree. From outside, away from the tube: nothing.
    EXPECT_FALSE(
        scanned.firstHit({0.0, 100.0, 0.0}, {0.0, 1.0, 0.0}, Lookup::ScanUnlessBuilt).has_value());
    EXPECT_TRUE(scanned.built());
}

// A query that does not ask for a scan builds the tree at once (the tips'
// and the radii's queries: many of them, after the paths' tree is freed).
TEST(SurfaceIndex, AQueryWithoutAScanBuildsTheTree) {
    const auto tube =
        demo::makeTubePhantom(test::tubeOptions(demo::TubeShape::Cylinder, 5.0, 2'000));
    const PreparedSurface s = prepareSurface(tube.mesh, std::nullopt, {}, 3'000'000);
    const SurfaceIndex index(s, SurfaceIndex::Build::OnFirstQuery);
    EXPECT_FALSE(index.built());
    EXPECT_NEAR(index.nearest({0.0, 0.0, 50.0}).distance, 5.0, 0.25);  // a chord inside
    EXPECT_TRUE(index.built());
}

}  // namespace
}  // namespace vv::analysis::detail
