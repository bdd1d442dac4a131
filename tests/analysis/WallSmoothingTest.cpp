// SPDX-License-Identifier: GPL-3.0-or-later
// A wall whose noise is larger than its triangles folds over itself; it is
// smoothed before the analysis (said in the notes, with how far its points
// moved), and then measured as the vessel it is: the centreline on the
// axis, the stenosis graded, the diameters right. Analysed as it is, the
// same wall gives a centreline off the axis or none. A wall that does not
// fold is left alone.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "TubeOptions.h"
#include "vv/analysis/AnalysisError.h"
#include "vv/analysis/Centerlines.h"
#include "vv/analysis/Sections.h"
#include "vv/analysis/Stenosis.h"
#include "vv/demo/TubePhantom.h"

namespace vv::analysis {
namespace {

/// A stenosis of `percent` in a 5 mm tube 100 mm long, over 20 mm.
demo::TubePhantom stenosis(double percent, std::size_t triangles, double jitter) {
    demo::TubePhantomOptions o =
        test::tubeOptions(demo::TubeShape::Stenosis, 5.0, triangles, jitter);
    o.stenosisPercent = percent;
    return demo::makeTubePhantom(o);
}

bool noteHas(const CenterlineTree& tree, const std::string& words) {
    return std::ranges::any_of(
        tree.notes, [&](const std::string& note) { return note.find(words) != std::string::npos; });
}

// A 70 % stenosis in 50k triangles with noise of 10 % of r (0.5 mm against
// 0.4 mm triangles): 8 % of its vertices fold. Smoothed, it is graded as
// the phantom's; as it is, its inside breaks up at the throat.
TEST(FoldedWall, IsSmoothedAndGradedAsTheVessel) {
    const auto truth = stenosis(70.0, 50'000, 0.1);
    const VesselAnalysis a = analyseVessels(truth.mesh);
    EXPECT_TRUE(noteHas(a.tree, "folds over itself")) << a.tree.notes.front();
    EXPECT_TRUE(noteHas(a.tree, "it was smoothed before the analysis"));
    EXPECT_FALSE(noteHas(a.tree, "smooth the surface first"));
    ASSERT_EQ(a.tree.branches.size(), 1U);
    // Noise five times the accuracy goals' 2 % of r: the axis within 3 % of r
    // (measured 2.7 %; at the goals' noise, on the jittered 1M tubes, 0.2-1.5 %).
    EXPECT_LT(test::worstAxisDistance(a.tree, truth, 5.0), 0.03 * 5.0);
    EXPECT_NEAR(a.tree.branches[0].lengthMm, 100.0, 1.0);
    const auto graded = gradeStenosis(a.tree, a.sections, 0);
    ASSERT_TRUE(graded.has_value());
    EXPECT_NEAR(graded->diameterPercent, 70.0, 2.0);
    EXPECT_NEAR(graded->abscissaMm, 50.0, 1.0);
    // The healthy tube's equivalent diameter within 1 %.
    int measured = 0;
    for (std::size_t i = 0; i < a.sections[0].size(); ++i) {
        const CrossSection& section = a.sections[0][i];
        const double from = std::abs(a.tree.branches[0].points[i].position.z - 50.0);
        if (section.measuresTheVessel() && from > 15.0) {
            EXPECT_NEAR(section.equivalentDiameterMm, 10.0, 0.1) << "at " << from;
            ++measured;
        }
    }
    EXPECT_GT(measured, 100);

    CenterlineOptions asItIs;
    asItIs.smoothFoldedWall = false;
    try {
        const CenterlineTree tree = computeCenterlines(truth.mesh, asItIs);
        EXPECT_TRUE(noteHas(tree, "smooth the surface first"));
        EXPECT_FALSE(noteHas(tree, "it was smoothed"));
    } catch (const AnalysisError& e) {
        EXPECT_NE(std::string(e.what()).find("smooth the surface first"), std::string::npos)
            << e.what();
    }
}

// computeSections cuts the wall computeCenterlines measured: smoothed too.
TEST(FoldedWall, ComputeSectionsCutsTheSmoothedWallToo) {
    const auto truth = stenosis(50.0, 50'000, 0.1);
    const VesselAnalysis together = analyseVessels(truth.mesh);
    const CenterlineTree tree = computeCenterlines(truth.mesh);
    const auto sections = computeSections(truth.mesh, tree);
    ASSERT_EQ(sections.size(), together.sections.size());
    for (std::size_t b = 0; b < sections.size(); ++b) {
        ASSERT_EQ(sections[b].size(), together.sections[b].size());
        for (std::size_t i = 0; i < sections[b].size(); ++i) {
            EXPECT_EQ(sections[b][i].status, together.sections[b][i].status);
            EXPECT_DOUBLE_EQ(sections[b][i].areaMm2, together.sections[b][i].areaMm2);
        }
    }
}

// Noise under the triangles' size (2 % of r on 50k triangles) folds nothing:
// the wall is analysed as it is.
TEST(FoldedWall, AWallThatDoesNotFoldIsLeftAsItIs) {
    const auto truth = stenosis(50.0, 50'000, 0.02);
    const CenterlineTree tree = computeCenterlines(truth.mesh);
    EXPECT_FALSE(noteHas(tree, "folds over itself"));
    EXPECT_FALSE(noteHas(tree, "smoothed"));
}

}  // namespace
}  // namespace vv::analysis
