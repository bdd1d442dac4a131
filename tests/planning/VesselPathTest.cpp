// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "TreeBuilder.h"
#include "vv/core/Error.h"
#include "vv/planning/VesselPath.h"

namespace vv::planning {
namespace {

/// A trunk 100 mm along +z; from its end a branch 60 mm towards +x and one
/// 80 mm towards -x, each 30 degrees from +z. Ends: 0 the source, 1 the +x
/// branch's tip, 2 the -x branch's.
analysis::CenterlineTree aY() {
    test::TreeBuilder builder;
    const auto r = [](double) { return 5.0; };
    builder.add(-1, {0, 0, 0}, {{{0, 0, 1}, 100.0}}, r);
    builder.add(0, {0, 0, 100}, {{test::tilted(30), 60.0}}, r);
    builder.add(0, {0, 0, 100}, {{test::tilted(-30), 80.0}}, r);
    return builder.finish();
}

TEST(VesselPath, RunsFromOneTipToAnotherThroughTheirBifurcation) {
    const auto tree = aY();
    const VesselPath path = VesselPath::betweenEnds(tree, 1, 2);
    EXPECT_NEAR(path.lengthMm(), 140.0, 1e-9);
    ASSERT_EQ(path.stretches().size(), 2U);
    EXPECT_EQ(path.stretches()[0].branch, 1);
    EXPECT_NEAR(path.stretches()[0].fromMm, 160.0, 1e-9);  // against the branch
    EXPECT_NEAR(path.stretches()[0].toMm, 100.0, 1e-9);
    EXPECT_EQ(path.stretches()[1].branch, 2);
    EXPECT_NEAR(path.stretches()[1].toMm, 180.0, 1e-9);
    // Every point once: the -x branch's first point is the bifurcation,
    // already passed as the +x branch's first.
    const auto points = path.points(tree);
    ASSERT_EQ(points.size(), 61U + 81U - 1U);
    for (std::size_t i = 1; i < points.size(); ++i) {
        EXPECT_NEAR(points[i].pathMm - points[i - 1].pathMm, 1.0, 1e-9) << i;
    }
    EXPECT_EQ(points.front().branch, 1);
    EXPECT_EQ(points.front().pointIndex, 60U);
    EXPECT_EQ(points.back().branch, 2);
    EXPECT_EQ(points.back().pointIndex, 80U);
    // The trunk is not on it.
    EXPECT_FALSE(path.abscissaOf(tree, {0, 50.0}).has_value());
    // The bifurcation is, whichever branch names it.
    EXPECT_NEAR(path.abscissaOf(tree, {0, 100.0}).value(), 60.0, 1e-9);
    EXPECT_NEAR(path.abscissaOf(tree, {2, 100.0}).value(), 60.0, 1e-9);
}

TEST(VesselPath, FromTheSourceRunsDownItsBranches) {
    const auto tree = aY();
    const VesselPath path = VesselPath::betweenEnds(tree, 0, 2);
    EXPECT_NEAR(path.lengthMm(), 180.0, 1e-9);
    EXPECT_EQ(path.points(tree).size(), 101U + 81U - 1U);
    // Back up the same way: the same length, the stretches reversed.
    const VesselPath back = VesselPath::betweenEnds(tree, 2, 0);
    EXPECT_NEAR(back.lengthMm(), 180.0, 1e-9);
    EXPECT_EQ(back.stretches().front().branch, 2);
    EXPECT_EQ(back.stretches().back().branch, 0);
}

TEST(VesselPath, TheFarthestEndIsTheLongerBranchsTip) {
    EXPECT_EQ(farthestEnd(aY()), 2);  // 100 + 80 against 100 + 60
    test::TreeBuilder builder;
    const auto r = [](double) { return 5.0; };
    builder.add(-1, {0, 0, 0}, {{{0, 0, 1}, 100.0}}, r);
    builder.add(0, {0, 0, 100}, {{test::tilted(30), 90.0}}, r);
    builder.add(0, {0, 0, 100}, {{test::tilted(-30), 20.0}}, r);
    EXPECT_EQ(farthestEnd(builder.finish()), 1);
    analysis::CenterlineTree none;
    EXPECT_EQ(farthestEnd(none), -1);
}

TEST(VesselPath, PlacesAndAbscissaeRoundTrip) {
    const auto tree = aY();
    const VesselPath path = VesselPath::betweenEnds(tree, 1, 2);
    std::mt19937 random(35U);
    std::uniform_real_distribution<double> along(0.0, path.lengthMm());
    for (int i = 0; i < 200; ++i) {
        const double s = along(random);
        const TreeLocation at = path.locationAt(s);
        const auto back = path.abscissaOf(tree, at);
        ASSERT_TRUE(back.has_value()) << s;
        EXPECT_NEAR(*back, s, 1e-9);
        // On the +x branch before the bifurcation, the -x one after it.
        EXPECT_EQ(at.branch, s < 60.0 ? 1 : 2) << s;
    }
    EXPECT_NEAR(path.locationAt(-5.0).abscissaMm, 160.0, 1e-9);  // clamped
    EXPECT_NEAR(path.locationAt(1e9).abscissaMm, 180.0, 1e-9);
}

TEST(VesselPath, LengthsAlongGoThroughWhereTheRoutesPart) {
    const auto tree = aY();
    EXPECT_NEAR(lengthAlong(tree, {1, 130.0}, {2, 150.0}), 30.0 + 50.0, 1e-9);
    EXPECT_NEAR(lengthAlong(tree, {0, 50.0}, {2, 150.0}), 100.0, 1e-9);
    EXPECT_NEAR(lengthAlong(tree, {2, 150.0}, {0, 50.0}), 100.0, 1e-9);
    EXPECT_NEAR(lengthAlong(tree, {0, 20.0}, {0, 70.0}), 50.0, 1e-9);
    // Straight distance is shorter across the fork.
    const glm::dvec3 a = sampleAt(tree, {1, 130.0}).position;
    const glm::dvec3 b = sampleAt(tree, {2, 150.0}).position;
    EXPECT_LT(glm::length(b - a), 80.0);
}

TEST(VesselPath, SamplesAndNearestPlacesFollowTheLines) {
    const auto tree = aY();
    const CenterlineSample at = sampleAt(tree, {0, 42.5});
    EXPECT_NEAR(at.position.z, 42.5, 1e-9);
    EXPECT_NEAR(at.radiusMm, 5.0, 1e-12);
    EXPECT_NEAR(at.tangent.z, 1.0, 1e-12);
    const NearestLocation near = nearestLocation(tree, {3.0, 0.0, 42.25});
    EXPECT_EQ(near.location.branch, 0);
    EXPECT_NEAR(near.location.abscissaMm, 42.25, 1e-9);
    EXPECT_NEAR(near.distanceMm, 3.0, 1e-9);
    const glm::dvec3 onBranch = glm::dvec3(0, 0, 100) + 20.0 * test::tilted(-30);
    const NearestLocation there = nearestLocation(tree, onBranch + glm::dvec3(0, 2, 0));
    EXPECT_EQ(there.location.branch, 2);
    EXPECT_NEAR(there.location.abscissaMm, 120.0, 1e-9);
    EXPECT_NEAR(there.distanceMm, 2.0, 1e-9);
}

TEST(VesselPath, BadPlacesAndEndsAreClearErrors) {
    const auto tree = aY();
    EXPECT_THROW(static_cast<void>(VesselPath::betweenEnds(tree, 1, 1)), InvalidArgumentError);
    EXPECT_THROW(static_cast<void>(VesselPath::betweenEnds(tree, 0, 9)), InvalidArgumentError);
    EXPECT_THROW(static_cast<void>(sampleAt(tree, {7, 0.0})), InvalidArgumentError);
    EXPECT_THROW(static_cast<void>(sampleAt(tree, {0, std::nan("")})), InvalidArgumentError);
    EXPECT_THROW(static_cast<void>(
                     nearestLocation(tree, {std::numeric_limits<double>::infinity(), 0.0, 0.0})),
                 InvalidArgumentError);
    EXPECT_THROW(static_cast<void>(nearestLocation(analysis::CenterlineTree{}, {0, 0, 0})),
                 InvalidArgumentError);
    // Off its branch's ends, a place is clamped to them.
    EXPECT_NEAR(clampedLocation(tree, {1, 500.0}).abscissaMm, 160.0, 1e-12);
}

}  // namespace
}  // namespace vv::planning
