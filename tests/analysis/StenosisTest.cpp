// SPDX-License-Identifier: GPL-3.0-or-later
// Stenosis grading on the stenosis phantoms (50 % and 70 % in diameter):
// the narrowest point, percent diameter and area within 2 points, with the
// automatic, the given and the NASCET reference.
#include <gtest/gtest.h>

#include "vv/analysis/Centerlines.h"
#include "vv/analysis/Sections.h"
#include "vv/analysis/Stenosis.h"
#include "vv/demo/TubePhantom.h"

namespace {

using vv::analysis::computeCenterlines;
using vv::analysis::computeSections;
using vv::analysis::gradeStenosis;
using vv::analysis::StenosisReference;

struct Graded {
    vv::demo::TubePhantom truth;
    vv::analysis::CenterlineTree tree;
    std::vector<std::vector<vv::analysis::CrossSection>> sections;
};

Graded grade(double percent, std::size_t triangles = 50'000, double jitter = 0.0) {
    vv::demo::TubePhantomOptions o;
    o.shape = vv::demo::TubeShape::Stenosis;
    o.radiusMm = 5.0;
    o.lengthMm = 100.0;
    o.stenosisLengthMm = 20.0;
    o.stenosisPercent = percent;
    o.targetTriangles = triangles;
    o.jitterFraction = jitter;
    Graded g{vv::demo::makeTubePhantom(o), {}, {}};
    g.tree = computeCenterlines(g.truth.mesh);
    g.sections = computeSections(g.truth.mesh, g.tree);
    return g;
}

class StenosisGrade : public ::testing::TestWithParam<double> {};

TEST_P(StenosisGrade, AutomaticReferenceWithinTwoPoints) {
    const double percent = GetParam();
    for (const double jitter : {0.0, 0.02}) {
        const Graded g = grade(percent, 50'000, jitter);
        ASSERT_EQ(g.tree.branches.size(), 1U);
        const auto s = gradeStenosis(g.tree, g.sections, 0);
        ASSERT_TRUE(s.has_value());
        EXPECT_NEAR(s->diameterPercent, percent, 2.0) << "jitter " << jitter;
        const double area = 100.0 * (1.0 - (1.0 - percent / 100.0) * (1.0 - percent / 100.0));
        EXPECT_NEAR(s->areaPercent, area, 2.0) << "jitter " << jitter;
        // The throat is in the middle of the tube, whichever end is the source.
        EXPECT_NEAR(s->abscissaMm, 50.0, 1.0);
        EXPECT_NEAR(s->referenceDiameterMm, 10.0, 0.1);
        // The lesion spans the narrowing (20 mm long, < 95 % of 10 mm over
        // about 17 mm of it); the references lie outside it.
        EXPECT_GT(s->lesionToMm - s->lesionFromMm, 10.0);
        EXPECT_LT(s->lesionToMm - s->lesionFromMm, 20.0);
        EXPECT_LE(s->proximalToMm, s->lesionFromMm);
        EXPECT_GE(s->distalFromMm, s->lesionToMm);
        EXPECT_NE(s->method.find("Automatic"), std::string::npos) << s->method;
    }
}

INSTANTIATE_TEST_SUITE_P(Phantoms, StenosisGrade, ::testing::Values(50.0, 70.0));

TEST(Stenosis, GivenAndNascetReferences) {
    const Graded g = grade(50.0);
    StenosisReference given;
    given.kind = StenosisReference::Kind::Given;
    given.proximalMm = 20.0;
    given.distalMm = 80.0;
    const auto s = gradeStenosis(g.tree, g.sections, 0, given);
    ASSERT_TRUE(s.has_value());
    EXPECT_NEAR(s->diameterPercent, 50.0, 2.0);
    EXPECT_NE(s->method.find("20.0 mm"), std::string::npos) << s->method;

    // NASCET with the distal reference in the narrowing itself (at 5 mm from
    // the throat the lumen is narrowed too): a smaller percentage, as NASCET
    // gives when the distal vessel is narrow.
    StenosisReference nascet;
    nascet.kind = StenosisReference::Kind::Nascet;
    nascet.distalMm = 55.0;
    const auto n = gradeStenosis(g.tree, g.sections, 0, nascet);
    ASSERT_TRUE(n.has_value());
    EXPECT_LT(n->diameterPercent, 40.0);
    EXPECT_GT(n->diameterPercent, 0.0);
    EXPECT_NE(n->method.find("NASCET"), std::string::npos) << n->method;
}

TEST(Stenosis, ReferencesOutsideTheBranchAreRejected) {
    const Graded g = grade(50.0, 5'000);
    StenosisReference given;
    given.kind = StenosisReference::Kind::Given;
    given.proximalMm = -10.0;
    given.distalMm = 80.0;
    EXPECT_THROW(static_cast<void>(gradeStenosis(g.tree, g.sections, 0, given)),
                 vv::InvalidArgumentError);
    EXPECT_THROW(static_cast<void>(gradeStenosis(g.tree, g.sections, 3)), vv::InvalidArgumentError);
}

// A healthy tube has no stenosis to speak of: within a point of 0.
TEST(Stenosis, AHealthyTubeGradesNearZero) {
    vv::demo::TubePhantomOptions o;
    o.radiusMm = 5.0;
    o.targetTriangles = 50'000;
    const auto truth = vv::demo::makeTubePhantom(o);
    const auto tree = computeCenterlines(truth.mesh);
    const auto sections = computeSections(truth.mesh, tree);
    const auto s = gradeStenosis(tree, sections, 0);
    ASSERT_TRUE(s.has_value());
    EXPECT_NEAR(s->diameterPercent, 0.0, 1.0);
}

}  // namespace
