// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string_view>

#include "AneurysmTruth.h"
#include "TreeBuilder.h"
#include "vv/analysis/Bifurcations.h"
#include "vv/demo/AneurysmPhantom.h"
#include "vv/planning/AorticSizing.h"

namespace vv::planning {
namespace {

/// An aorta of known angulation: 40 mm of suprarenal aorta along +z (the
/// lowest renal artery at its end), a 25 mm neck tilted 20 degrees from it,
/// a 60 mm aneurysm tilted 35 degrees further, then two iliacs 30 degrees
/// either side of the aneurysm's axis, 70 mm each. The radius: 11 mm above
/// the renal, narrowing to 10 mm over the neck, 25 mm at the sac's middle,
/// the iliacs 6 mm with a narrowing to 4 mm 30 mm down the left one.
struct AngulatedAorta {
    analysis::CenterlineTree tree;
    std::vector<std::vector<analysis::CrossSection>> sections;
    std::vector<Landmark> landmarks;

    static double aorticRadius(double s) {
        if (s <= 40.0) {
            return 11.0;
        }
        if (s <= 65.0) {
            return 11.0 - (s - 40.0) / 25.0;  // 11 -> 10 over the neck
        }
        // The sac: 10 -> 25 -> 10 over 60 mm.
        return 10.0 + 15.0 * std::sin(test::kPi * (s - 65.0) / 60.0);
    }
};

AngulatedAorta angulatedAorta() {
    test::TreeBuilder builder;
    const glm::dvec3 neck = test::tilted(20.0);
    const glm::dvec3 sac = test::tilted(55.0);
    builder.add(-1, {0, 0, 0}, {{{0, 0, 1}, 40.0}, {neck, 25.0}, {sac, 60.0}},
                AngulatedAorta::aorticRadius);
    const glm::dvec3 bifurcation = glm::dvec3(0, 0, 40) + 25.0 * neck + 60.0 * sac;
    const int left = builder.add(0, bifurcation, {{test::tilted(55.0 + 30.0), 70.0}}, [](double s) {
        // 125 mm is the bifurcation: narrowest 30 mm down the left iliac.
        return 6.0 - 2.0 * std::exp(-std::pow((s - 155.0) / 4.0, 2.0));
    });
    const int right = builder.add(0, bifurcation, {{test::tilted(55.0 - 30.0), 70.0}},
                                  [](double) { return 6.0; });
    AngulatedAorta a;
    a.tree = builder.finish();
    a.sections = test::roundSections(a.tree);
    a.landmarks = {
        {"Lowest renal artery", LandmarkKind::LowestRenalArtery, {0, 40.0}},
        {"Start of the aneurysm", LandmarkKind::AneurysmStart, {0, 65.0}},
        {"Largest aneurysm diameter", LandmarkKind::LargestAneurysmDiameter, {0, 95.0}},
        {"Aortic bifurcation", LandmarkKind::AorticBifurcation, {0, 125.0}},
        {"Left internal iliac origin", LandmarkKind::LeftInternalIliacOrigin, {left, 175.0}},
        {"Right internal iliac origin", LandmarkKind::RightInternalIliacOrigin, {right, 165.0}},
    };
    return a;
}

TEST(AorticSizing, ReadsTheNeckAnglesAndLengthsOfAKnownAorta) {
    const AngulatedAorta a = angulatedAorta();
    const AorticSizing table = aorticSizing(a.tree, a.sections, a.landmarks);
    for (std::size_t i = 0; i < AorticSizing::kNeckDepthsMm.size(); ++i) {
        const auto& cell = table.neckDiameters[i];
        ASSERT_TRUE(cell.value.has_value()) << blankText(cell.blank);
        const double s = 40.0 + AorticSizing::kNeckDepthsMm[i];
        EXPECT_NEAR(cell.value->equivalentDiameterMm, 2.0 * AngulatedAorta::aorticRadius(s), 1e-9)
            << "at " << s << " mm";
        EXPECT_NEAR(cell.value->location.abscissaMm, s, 1e-9);
    }
    ASSERT_TRUE(table.neckLengthMm.value.has_value());
    EXPECT_NEAR(*table.neckLengthMm.value, 25.0, 1e-9);
    ASSERT_TRUE(table.suprarenalToNeckDeg.value.has_value())
        << blankText(table.suprarenalToNeckDeg.blank);
    EXPECT_NEAR(*table.suprarenalToNeckDeg.value, 20.0, 1e-6);
    ASSERT_TRUE(table.neckToAneurysmDeg.value.has_value())
        << blankText(table.neckToAneurysmDeg.blank);
    EXPECT_NEAR(*table.neckToAneurysmDeg.value, 35.0, 1e-6);
    ASSERT_TRUE(table.largestAneurysm.value.has_value());
    EXPECT_NEAR(table.largestAneurysm.value->maxDiameterMm, 50.0, 1e-9);
    EXPECT_NEAR(table.renalToBifurcationMm.value.value(), 85.0, 1e-9);
    EXPECT_NEAR(table.bifurcationToInternalIliacMm[0].value.value(), 50.0, 1e-9);
    EXPECT_NEAR(table.bifurcationToInternalIliacMm[1].value.value(), 40.0, 1e-9);
    EXPECT_NEAR(table.renalToInternalIliacMm[0].value.value(), 135.0, 1e-9);
    EXPECT_NEAR(table.renalToInternalIliacMm[1].value.value(), 125.0, 1e-9);
    // The left iliac's narrowing, found where it is; the right one is 12 mm.
    ASSERT_TRUE(table.smallestIliac[0].value.has_value());
    EXPECT_NEAR(table.smallestIliac[0].value->minDiameterMm, 8.0, 1e-9);
    EXPECT_NEAR(table.smallestIliac[0].value->location.abscissaMm, 155.0, 1e-9);
    EXPECT_NEAR(table.smallestIliac[1].value.value().minDiameterMm, 12.0, 1e-9);
}

TEST(AorticSizing, LeavesBlankWhatItsLandmarksDoNotGiveAndSaysWhy) {
    const AngulatedAorta a = angulatedAorta();
    const AorticSizing none = aorticSizing(a.tree, a.sections, {});
    EXPECT_FALSE(none.neckDiameters[0].value.has_value());
    EXPECT_NE(blankText(none.neckDiameters[0].blank).find("Lowest renal artery"), std::string::npos)
        << blankText(none.neckDiameters[0].blank);
    EXPECT_FALSE(none.neckLengthMm.value.has_value());
    EXPECT_FALSE(none.largestAneurysm.value.has_value());
    EXPECT_NE(blankText(none.largestAneurysm.blank).find("Largest aneurysm diameter"),
              std::string::npos);
    EXPECT_FALSE(none.smallestIliac[1].value.has_value());
    EXPECT_EQ(none.neckDiameters[0].blank.reason, Blank::Reason::LandmarkMissing);
    EXPECT_EQ(none.neckDiameters[0].blank.landmark, LandmarkKind::LowestRenalArtery);
    EXPECT_EQ(none.smallestIliac[1].blank.landmark, LandmarkKind::AorticBifurcation);

    // Without the bifurcation: the neck from the sac's widest point, beta blank.
    auto some = a.landmarks;
    some.erase(some.begin() + 3);
    const AorticSizing partial = aorticSizing(a.tree, a.sections, some);
    EXPECT_NEAR(partial.neckLengthMm.value.value(), 25.0, 1e-9);
    EXPECT_NEAR(partial.suprarenalToNeckDeg.value.value(), 20.0, 1e-6);
    EXPECT_FALSE(partial.neckToAneurysmDeg.value.has_value());
    EXPECT_NE(blankText(partial.neckToAneurysmDeg.blank).find("Aortic bifurcation"),
              std::string::npos);
    EXPECT_FALSE(partial.renalToBifurcationMm.value.has_value());

    // An aneurysm "starting" above the renal artery gives no neck, not a negative one.
    auto swapped = a.landmarks;
    swapped[1].location = {0, 30.0};
    const AorticSizing wrong = aorticSizing(a.tree, a.sections, swapped);
    EXPECT_FALSE(wrong.neckLengthMm.value.has_value());
    EXPECT_FALSE(wrong.suprarenalToNeckDeg.value.has_value());
    EXPECT_EQ(wrong.neckLengthMm.blank.reason, Blank::Reason::AneurysmNotBelowRenal);

    // A renal landmark on an iliac is not on the aortic path.
    auto offPath = a.landmarks;
    offPath[0].location = {1, 140.0};
    const AorticSizing off = aorticSizing(a.tree, a.sections, offPath);
    EXPECT_FALSE(off.neckDiameters[0].value.has_value());
    EXPECT_NE(blankText(off.neckDiameters[0].blank).find("not on the centreline"),
              std::string::npos);

    // A section without a contour is blank, never its neighbour's size.
    auto holed = a.sections;
    holed[0][40].status = analysis::CrossSection::Status::NoContour;
    const AorticSizing hole = aorticSizing(a.tree, holed, a.landmarks);
    EXPECT_FALSE(hole.neckDiameters[0].value.has_value());
    EXPECT_EQ(hole.neckDiameters[0].blank.reason, Blank::Reason::NoContour);
    EXPECT_EQ(off.neckDiameters[0].blank.reason, Blank::Reason::NotOnAorticPath);
    EXPECT_EQ(off.neckDiameters[0].blank.other, LandmarkKind::AorticBifurcation);
    // Every reason has its own key and sentence.
    std::set<std::string_view> keys;
    for (int r = 0; r <= static_cast<int>(Blank::Reason::NoVesselSection); ++r) {
        const Blank b{static_cast<Blank::Reason>(r), LandmarkKind::AneurysmStart,
                      LandmarkKind::AorticBifurcation, 5.0};
        EXPECT_TRUE(keys.insert(blankKey(b.reason)).second) << r;
        EXPECT_EQ(blankReasonOfKey(blankKey(b.reason)), b.reason) << r;
        EXPECT_EQ(blankText(b).empty(), b.reason == Blank::Reason::None) << r;
    }
    EXPECT_FALSE(blankReasonOfKey("landmark missing").has_value());
    EXPECT_TRUE(hole.neckDiameters[1].value.has_value());
}

// The aneurysm phantom analysed (50k triangles; open ends as a CFD surface
// comes, or closed and jittered by 2 % of r as a noisy segmentation): the landmarks placed where a
// planner would click, at the truth's places, and every value against the truth within the
// analysis' goals (lengths and diameters 1 %, angles 1 degree). A length's truth runs along the
// phantom's axes between where the landmarks are.
struct PhantomCase {
    bool openEnds = true;
    double jitter = 0.0;
};

class AorticSizingOnThePhantom : public ::testing::TestWithParam<PhantomCase> {};

TEST_P(AorticSizingOnThePhantom, MeasuresItAsItsTruth) {
    demo::AneurysmPhantomOptions options;
    options.targetTriangles = 50'000;
    options.openEnds = GetParam().openEnds;
    options.jitterFraction = GetParam().jitter;
    const demo::AneurysmPhantom phantom = demo::makeAneurysmPhantom(options);
    const analysis::VesselAnalysis analysed = analysis::analyseVessels(phantom.mesh);
    const auto& tree = analysed.tree;
    const auto place = [&](LandmarkKind kind, const glm::dvec3& point) {
        EXPECT_LT(nearestLocation(tree, point).distanceMm, 0.5) << "the point is on the centreline";
        return Landmark{std::string(landmarkEnglishName(kind)), kind,
                        placeLandmark(tree, kind, point)};
    };
    const double renalZ = 20.0;  // a place on the straight neck: the phantom has no renals
    const double startZ = options.bulgeCentreMm - options.bulgeLengthMm / 2.0;
    const double iliacMm = 40.0;  // the internal iliac origins' distance down each iliac
    const std::vector<Landmark> landmarks{
        place(LandmarkKind::LowestRenalArtery, {0, 0, renalZ}),
        place(LandmarkKind::AneurysmStart, {0, 0, startZ}),
        place(LandmarkKind::LargestAneurysmDiameter, {0, 0, options.bulgeCentreMm}),
        place(LandmarkKind::AorticBifurcation, phantom.bifurcationPoint),
        place(LandmarkKind::LeftInternalIliacOrigin,
              phantom.bifurcationPoint + iliacMm * phantom.iliacDirections[1]),
        place(LandmarkKind::RightInternalIliacOrigin,
              phantom.bifurcationPoint + iliacMm * phantom.iliacDirections[0]),
    };
    // The bifurcation landmark went to the tree's bifurcation, where both
    // iliacs' paths start.
    const TreeLocation fork = landmarks[3].location;
    EXPECT_EQ(fork.branch, 0);
    EXPECT_EQ(tree.branches[0].children.size(), 2U);
    EXPECT_DOUBLE_EQ(fork.abscissaMm, tree.branches[0].points.back().abscissaMm);

    const AorticSizing table = aorticSizing(tree, analysed.sections, landmarks);
    for (std::size_t i = 0; i < AorticSizing::kNeckDepthsMm.size(); ++i) {
        const auto& cell = table.neckDiameters[i];
        ASSERT_TRUE(cell.value.has_value()) << blankText(cell.blank);
        const double truth = 2.0 * phantom.trunkRadiusAt(renalZ + AorticSizing::kNeckDepthsMm[i]);
        EXPECT_NEAR(cell.value->equivalentDiameterMm, truth, 0.01 * truth) << i;
    }
    const auto length = [&](std::size_t a, std::size_t b) {
        return vv::test::truthAlongAxes(phantom, tree, landmarks[a].location,
                                        landmarks[b].location);
    };
    EXPECT_NEAR(table.neckLengthMm.value.value(), length(0, 1), 0.01 * length(0, 1));
    EXPECT_NEAR(table.suprarenalToNeckDeg.value.value(), 0.0, 1.0);
    EXPECT_NEAR(table.neckToAneurysmDeg.value.value(), 0.0, 1.0);
    ASSERT_TRUE(table.largestAneurysm.value.has_value());
    EXPECT_NEAR(table.largestAneurysm.value->equivalentDiameterMm, phantom.maxDiameterMm,
                0.01 * phantom.maxDiameterMm);
    // A Feret width is an extreme of the contour: each of two opposite walls
    // may stand off by the jitter's amplitude, which the goal's 1 % does not
    // hold on the jittered wall.
    const double feretSlack = 2.0 * options.jitterFraction * options.radiusMm;
    EXPECT_NEAR(table.largestAneurysm.value->maxDiameterMm, phantom.maxDiameterMm,
                0.01 * phantom.maxDiameterMm + feretSlack);
    EXPECT_NEAR(table.renalToBifurcationMm.value.value(), length(0, 3), 0.01 * length(0, 3));
    for (std::size_t side = 0; side < 2; ++side) {
        const std::size_t origin = 4 + side;
        EXPECT_NEAR(table.bifurcationToInternalIliacMm[side].value.value(), length(3, origin),
                    0.01 * length(3, origin))
            << side;
        EXPECT_NEAR(table.renalToInternalIliacMm[side].value.value(), length(0, origin),
                    0.01 * length(0, origin))
            << side;
        ASSERT_TRUE(table.smallestIliac[side].value.has_value())
            << blankText(table.smallestIliac[side].blank);
        const double iliac = 2.0 * options.iliacRadiusMm;
        EXPECT_NEAR(table.smallestIliac[side].value->minDiameterMm, iliac,
                    0.01 * iliac + feretSlack)
            << side;
        EXPECT_NEAR(table.smallestIliac[side].value->equivalentDiameterMm, iliac, 0.01 * iliac)
            << side;
    }
}

INSTANTIATE_TEST_SUITE_P(OpenAndClosedJittered, AorticSizingOnThePhantom,
                         ::testing::Values(PhantomCase{true, 0.0}, PhantomCase{false, 0.02}),
                         [](const ::testing::TestParamInfo<PhantomCase>& test) {
                             return std::string(test.param.openEnds ? "Open" : "Closed") +
                                    (test.param.jitter > 0.0 ? "Jittered" : "");
                         });

TEST(Landmarks, ABifurcationsLandmarkGoesToTheBifurcationClickedNearIt) {
    const AngulatedAorta a = angulatedAorta();
    const glm::dvec3 node = a.tree.branches[0].points.back().position;  // radius 10 there
    for (const LandmarkKind kind :
         {LandmarkKind::AorticBifurcation, LandmarkKind::LeftInternalIliacOrigin}) {
        const TreeLocation at = placeLandmark(a.tree, kind, node + glm::dvec3(3.0, 4.0, 0.0));
        EXPECT_EQ(at.branch, 0);
        EXPECT_DOUBLE_EQ(at.abscissaMm, 125.0);
    }
    // Farther than the radius, or a landmark of another kind: where it was clicked.
    const glm::dvec3 down = a.tree.branches[1].points[12].position;
    const TreeLocation iliac = placeLandmark(a.tree, LandmarkKind::AorticBifurcation, down);
    EXPECT_EQ(iliac.branch, 1);
    EXPECT_NEAR(iliac.abscissaMm, 137.0, 1e-9);
    const TreeLocation free =
        placeLandmark(a.tree, LandmarkKind::Free, a.tree.branches[2].points[2].position);
    EXPECT_EQ(free.branch, 2);
    EXPECT_NEAR(free.abscissaMm, 127.0, 1e-9);
}

TEST(Landmarks, KeysNameEveryPresetAndReadBack) {
    EXPECT_EQ(landmarkPresets().size(), 6U);
    for (const LandmarkKind kind : landmarkPresets()) {
        EXPECT_EQ(landmarkKindOfKey(landmarkKey(kind)), kind);
        EXPECT_FALSE(landmarkEnglishName(kind).empty());
    }
    EXPECT_EQ(landmarkKindOfKey("free"), LandmarkKind::Free);
    EXPECT_FALSE(landmarkKindOfKey("lowest renal artery").has_value());
    EXPECT_FALSE(landmarkKindOfKey("").has_value());
}

}  // namespace
}  // namespace vv::planning
