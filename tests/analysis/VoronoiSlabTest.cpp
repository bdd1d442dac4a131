// SPDX-License-Identifier: GPL-3.0-or-later
// The internal Voronoi diagram tetrahedralised in slabs is the diagram of
// all the points at once: the same vertices (centres and radii to the last
// bit), the same edges and the same poles, whether the slabs' first margins
// hold or have to be widened; on a closed Y, an open aneurysm and a rough
// (jittered) tube.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <tuple>
#include <vector>

#include "PreparedSurface.h"
#include "TubeOptions.h"
#include "VoronoiGraph.h"
#include "VoronoiSamples.h"
#include "vv/demo/AneurysmPhantom.h"
#include "vv/demo/BifurcationPhantom.h"
#include "vv/demo/DemoTree.h"
#include "vv/demo/TubePhantom.h"

namespace vv::analysis::detail {
namespace {

using Point = std::array<double, 4>;  // centre and radius

Point pointOf(const VoronoiGraph& g, std::uint32_t v) {
    return {g.centre(v).x, g.centre(v).y, g.centre(v).z, g.radius(v)};
}

/// The graph without its numbering: its vertices, its edges and each surface
/// vertex's pole, each by the spheres they join, sorted.
struct Unnumbered {
    std::vector<Point> vertices;
    std::vector<std::pair<Point, Point>> edges;
    std::vector<std::tuple<std::size_t, Point>> poles;

    explicit Unnumbered(const VoronoiGraph& g) {
        for (std::uint32_t v = 0; v < g.size(); ++v) {
            vertices.push_back(pointOf(g, v));
            for (std::uint32_t e = g.offsets[v]; e < g.offsets[v + 1]; ++e) {
                edges.emplace_back(pointOf(g, v), pointOf(g, g.neighbours[e]));
            }
        }
        for (std::size_t v = 0; v < g.poles.size(); ++v) {
            if (g.poles[v] != UINT32_MAX) {
                poles.emplace_back(v, pointOf(g, g.poles[v]));
            }
        }
        std::sort(vertices.begin(), vertices.end());
        std::sort(edges.begin(), edges.end());
    }
};

/// Builds the diagram of `mesh` whole and in `policy`'s slabs, and checks
/// that they agree; returns the slabbed graph.
VoronoiGraph expectSameDiagram(const scene::Mesh& mesh, const SlabPolicy& policy) {
    const PreparedSurface s = prepareSurface(mesh, std::nullopt, {}, 3'000'000);
    const VoronoiSamples samples = chooseVoronoiSamples(s, {});
    SlabPolicy whole;
    whole.splitFrom = SIZE_MAX;
    const VoronoiGraph one = buildVoronoiGraph(s, samples, {}, whole);
    VoronoiGraph cut = buildVoronoiGraph(s, samples, {}, policy);
    EXPECT_EQ(one.slabs, 1);
    EXPECT_GT(cut.slabs, 4);
    const Unnumbered a(one);
    const Unnumbered b(cut);
    EXPECT_GT(a.vertices.size(), 1000U);
    EXPECT_EQ(a.vertices.size(), b.vertices.size());
    EXPECT_TRUE(a.vertices == b.vertices);
    EXPECT_EQ(a.edges.size(), b.edges.size());
    EXPECT_TRUE(a.edges == b.edges);
    // A pole may be another sphere of the same radius: compare the radii.
    EXPECT_EQ(a.poles.size(), b.poles.size());
    for (std::size_t i = 0; i < std::min(a.poles.size(), b.poles.size()); ++i) {
        EXPECT_EQ(std::get<0>(a.poles[i]), std::get<0>(b.poles[i]));
        EXPECT_EQ(std::get<1>(a.poles[i])[3], std::get<1>(b.poles[i])[3]);
    }
    return cut;
}

SlabPolicy manySlabs(double marginPerRadius = 1.25) {
    SlabPolicy policy;
    policy.splitFrom = 0;
    policy.maxPointsPerSlab = 1500;
    policy.marginPerRadius = marginPerRadius;
    return policy;
}

TEST(VoronoiSlabs, AClosedYInSlabsIsTheWholeDiagram) {
    demo::BifurcationPhantomOptions options;
    options.targetTriangles = 20'000;
    const VoronoiGraph g =
        expectSameDiagram(demo::makeBifurcationPhantom(options).mesh, manySlabs());
    EXPECT_EQ(g.slabRetries, 0);
}

TEST(VoronoiSlabs, MarginsTooNarrowAreWidenedUntilTheDiagramIsWhole) {
    demo::AneurysmPhantomOptions options;
    options.targetTriangles = 20'000;
    options.openEnds = true;
    // A tenth of the inscribed spheres' width: every slab is done again.
    const VoronoiGraph g =
        expectSameDiagram(demo::makeAneurysmPhantom(options).mesh, manySlabs(0.1));
    EXPECT_GE(g.slabRetries, g.slabs - 1);
}

TEST(VoronoiSlabs, ARoughTubeInSlabsIsTheWholeDiagram) {
    expectSameDiagram(
        demo::makeTubePhantom(test::tubeOptions(demo::TubeShape::Cylinder, 5.0, 20'000, 0.02)).mesh,
        manySlabs());
}

TEST(VoronoiSlabs, MarginsPerColumnTakeFewerPointsThanOnePerCut) {
    // The demo tree's trunk beside its thin branches: one margin per cut is
    // set by the trunk's radius for the branches too.
    demo::DemoTreeOptions options;
    options.generations = 4;
    options.maxTriangles = 100'000;
    const scene::Mesh mesh = demo::buildVesselSurface(demo::generateVesselTree(options), options);
    // Eight slabs either way: as many as "cores", which are never made fewer.
    SlabPolicy perColumnPolicy = manySlabs();
    perColumnPolicy.maxPointsPerSlab = SIZE_MAX;
    perColumnPolicy.cores = 8;
    SlabPolicy perCut = perColumnPolicy;
    perCut.marginColumns = 1;
    const VoronoiGraph onePerCut = expectSameDiagram(mesh, perCut);
    const VoronoiGraph perColumn = expectSameDiagram(mesh, perColumnPolicy);
    EXPECT_EQ(perColumn.slabs, 8);
    EXPECT_EQ(onePerCut.slabs, 8);
    EXPECT_LT(static_cast<double>(perColumn.tetrahedralisedPoints),
              0.95 * static_cast<double>(onePerCut.tetrahedralisedPoints))
        << "points tetrahedralised: one margin per cut " << onePerCut.tetrahedralisedPoints
        << ", per column " << perColumn.tetrahedralisedPoints;
}

TEST(VoronoiSlabs, SlabsThinnerThanTheirMarginsAreMadeFewer) {
    // A rough aneurysm, every point kept, asked for slabs of 500 points:
    // a few millimetres each across a sac 50 mm wide.
    demo::AneurysmPhantomOptions options;
    options.targetTriangles = 20'000;
    options.jitterFraction = 0.02;
    SlabPolicy thin = manySlabs();
    thin.maxPointsPerSlab = 500;
    const VoronoiGraph g = expectSameDiagram(demo::makeAneurysmPhantom(options).mesh, thin);
    const PreparedSurface s =
        prepareSurface(demo::makeAneurysmPhantom(options).mesh, std::nullopt, {}, 3'000'000);
    const std::size_t kept = chooseVoronoiSamples(s, {}).kept.size();
    EXPECT_LT(static_cast<std::size_t>(g.slabs), (kept + 499) / 500 / 2)
        << "slabs for " << kept << " points kept";
    EXPECT_LE(static_cast<double>(g.tetrahedralisedPoints), 3.0 * static_cast<double>(kept))
        << g.slabs << " slabs";
}

}  // namespace
}  // namespace vv::analysis::detail
