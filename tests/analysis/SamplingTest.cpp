// SPDX-License-Identifier: GPL-3.0-or-later
// A surface much finer than its vessel needs: the Voronoi diagram is built
// from fewer points (one per quarter radius), says so, and the centreline,
// its length, a given end and the sections keep their accuracy; a rough
// (jittered) surface keeps every point; neither gets points added (that is
// for facets coarse against their vessel); analyseVessels gives what
// computeCenterlines and computeSections give.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "TubeOptions.h"
#include "vv/analysis/Centerlines.h"
#include "vv/analysis/Sections.h"
#include "vv/core/Error.h"
#include "vv/demo/TubePhantom.h"

namespace vv::analysis {
namespace {

bool reducedNote(const CenterlineTree& tree) {
    return std::ranges::any_of(tree.notes, [](const std::string& note) {
        return note.find("the Voronoi diagram was built from") != std::string::npos;
    });
}

/// The note that points were added on coarse facets.
bool addedNote(const CenterlineTree& tree) {
    return std::ranges::any_of(tree.notes, [](const std::string& note) {
        return note.find("points added") != std::string::npos;
    });
}

/// The note that the wall folds over itself.
bool foldedNote(const CenterlineTree& tree) {
    return std::ranges::any_of(tree.notes, [](const std::string& note) {
        return note.find("folds over itself") != std::string::npos;
    });
}

// A 10 mm cylinder in 300k triangles: some 150 points around its lumen.
TEST(VoronoiSampling, ANeedlesslyFineSurfaceIsSampledAndStaysAccurate) {
    const auto truth =
        demo::makeTubePhantom(test::tubeOptions(demo::TubeShape::Cylinder, 10.0, 300'000));
    CenterlineOptions options;
    options.targets = {glm::dvec3(0.0, -11.0, 150.0)};  // 1 mm outside the wall at z = 150
    const VesselAnalysis analysed = analyseVessels(truth.mesh, options);
    const CenterlineTree& tree = analysed.tree;
    EXPECT_TRUE(reducedNote(tree));
    // Fine everywhere, its open ends too (where the rim's turn onto the cap
    // once read as a tiny radius): no points added.
    EXPECT_FALSE(addedNote(tree));
    ASSERT_EQ(tree.branches.size(), 1U);
    EXPECT_LT(test::worstAxisDistance(tree, truth, truth.options.radiusMm), 0.02 * 10.0);
    // The given end: the sphere touching the wall there, exactly, not a
    // sample's pole a quarter radius away.
    ASSERT_EQ(tree.ends.size(), 2U);
    EXPECT_NEAR(tree.ends[1].position.z, 150.0, 0.1);
    EXPECT_NEAR(tree.ends[1].radiusMm, 10.0, 0.1);
    EXPECT_NEAR(tree.branches[0].lengthMm, 150.0, 0.01 * 150.0);
    // The sections are cut from every point: the 300k surface's polygon.
    int measured = 0;
    for (const CrossSection& s : analysed.sections[0]) {
        if (s.measuresTheVessel()) {
            EXPECT_NEAR(s.equivalentDiameterMm, 20.0, 0.01 * 20.0);
            ++measured;
        }
    }
    EXPECT_GT(measured, 200);
}

TEST(VoronoiSampling, ARoughSurfaceKeepsEveryPoint) {
    const auto truth =
        demo::makeTubePhantom(test::tubeOptions(demo::TubeShape::Cylinder, 10.0, 300'000, 0.02));
    const CenterlineTree tree = computeCenterlines(truth.mesh);
    EXPECT_FALSE(reducedNote(tree));
    // Its curvature measures the roughness, not the vessel: no points added.
    EXPECT_FALSE(addedNote(tree));
    // Rough, but its noise (2 % of r) is under its triangles: no fold.
    EXPECT_FALSE(foldedNote(tree));
    EXPECT_LT(test::worstAxisDistance(tree, truth, truth.options.radiusMm), 0.02 * 10.0);
}

// Noise larger than the triangles (10 % of r on a 50k tube: 6 % of its
// vertices' normals point against their neighbourhood's) is said, with how
// much of the wall it takes.
TEST(VoronoiSampling, AWallThatFoldsOverItselfIsNamed) {
    const auto truth =
        demo::makeTubePhantom(test::tubeOptions(demo::TubeShape::Cylinder, 5.0, 50'000, 0.1));
    const CenterlineTree tree = computeCenterlines(truth.mesh);
    EXPECT_TRUE(foldedNote(tree));
    const auto smooth =
        demo::makeTubePhantom(test::tubeOptions(demo::TubeShape::Cylinder, 5.0, 50'000, 0.05));
    EXPECT_FALSE(foldedNote(computeCenterlines(smooth.mesh)));
}

// Noise of 20 % of r: whether the analysis still finds a path or not, the
// fold is named, in the notes or in the error.
TEST(VoronoiSampling, AFoldedWallIsNamedInTheErrorToo) {
    const auto truth =
        demo::makeTubePhantom(test::tubeOptions(demo::TubeShape::Stenosis, 5.0, 50'000, 0.2));
    try {
        EXPECT_TRUE(foldedNote(computeCenterlines(truth.mesh)));
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("folds over itself"), std::string::npos) << e.what();
    }
}

TEST(VoronoiSampling, AnalyseVesselsGivesWhatTheTwoStepsGive) {
    const auto truth =
        demo::makeTubePhantom(test::tubeOptions(demo::TubeShape::Stenosis, 5.0, 40'000));
    const VesselAnalysis together = analyseVessels(truth.mesh);
    const CenterlineTree tree = computeCenterlines(truth.mesh);
    const auto sections = computeSections(truth.mesh, tree);
    ASSERT_EQ(together.tree.branches.size(), tree.branches.size());
    ASSERT_EQ(together.sections.size(), sections.size());
    for (std::size_t b = 0; b < sections.size(); ++b) {
        ASSERT_EQ(together.tree.branches[b].points.size(), tree.branches[b].points.size());
        ASSERT_EQ(together.sections[b].size(), sections[b].size());
        for (std::size_t i = 0; i < sections[b].size(); ++i) {
            EXPECT_EQ(together.tree.branches[b].points[i].position,
                      tree.branches[b].points[i].position);
            EXPECT_EQ(together.sections[b][i].status, sections[b][i].status);
            EXPECT_EQ(together.sections[b][i].areaMm2, sections[b][i].areaMm2);
            EXPECT_EQ(together.sections[b][i].inEndZone, sections[b][i].inEndZone);
        }
    }
}

// More triangles than the analysis takes (a 10M-triangle export, here 60k
// against a limit of 15k): the points are merged in cubes, a note says how
// far they moved, and the measures keep within what that allows.
TEST(SurfaceCoarsening, AMeshOverTheLimitIsCoarsenedAndSaysSo) {
    const auto truth =
        demo::makeTubePhantom(test::tubeOptions(demo::TubeShape::Cylinder, 5.0, 60'000));
    CenterlineOptions options;
    options.maxTriangles = 15'000;
    const VesselAnalysis analysed = analyseVessels(truth.mesh, options);
    std::string note;
    for (const auto& n : analysed.tree.notes) {
        if (n.find("points were merged in cubes of") != std::string::npos) {
            note = n;
        }
    }
    ASSERT_FALSE(note.empty());
    EXPECT_NE(note.find(std::to_string(truth.mesh.triangleCount()) + " triangles"),
              std::string::npos)
        << note;
    ASSERT_EQ(analysed.tree.branches.size(), 1U);
    EXPECT_LT(test::worstAxisDistance(analysed.tree, truth, truth.options.radiusMm), 0.02 * 5.0);
    EXPECT_NEAR(analysed.tree.branches[0].lengthMm, truth.lengthMm, 0.01 * truth.lengthMm);
    int measured = 0;
    for (const CrossSection& s : analysed.sections[0]) {
        if (s.measuresTheVessel()) {
            EXPECT_NEAR(s.equivalentDiameterMm, 10.0, 0.03 * 10.0);
            ++measured;
        }
    }
    EXPECT_GT(measured, 100);
    // Under the limit, nothing is merged.
    options.maxTriangles = 100'000;
    for (const auto& n : analyseVessels(truth.mesh, options).tree.notes) {
        EXPECT_EQ(n.find("merged in cubes"), std::string::npos) << n;
    }
    options.maxTriangles = 999;
    EXPECT_THROW(static_cast<void>(computeCenterlines(truth.mesh, options)), InvalidArgumentError);
}

}  // namespace
}  // namespace vv::analysis
