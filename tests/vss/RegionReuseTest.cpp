// SPDX-License-Identifier: GPL-3.0-or-later
// vss::solve's `previous`: regions whose pixels and contour did not change
// are taken from the previous solve, and the result is the fresh solve's.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <string>

#include "RingScene.h"
#include "vv/core/Image.h"
#include "vv/vss/DepthNormalization.h"
#include "vv/vss/Solver.h"
#include "vv/vss/Vss.h"

namespace {

using vv::Image;
namespace vss = vv::vss;

using vv::test::baseRings;
using vv::test::ringSceneDepth;
constexpr float kInf = std::numeric_limits<float>::infinity();

vss::VssResult solveOf(const Image<float>& depth, const vss::Solver& solver,
                       const vss::PreviousSolve* previous = nullptr) {
    const Image<std::uint8_t> mask = vss::maskFromFiniteDepth(depth.view());
    return vss::solve(depth.view(), mask.view(), solver, {}, {}, previous);
}

vss::PreviousSolve previousOf(const vss::VssResult& r) {
    return vss::PreviousSolve{r.height.view(), r.labels.view(), &r.regions};
}

/// The two heights are the same bytes (NaN where the other has NaN).
void expectSameBytes(const Image<float>& a, const Image<float>& b) {
    ASSERT_EQ(a.width(), b.width());
    ASSERT_EQ(a.height(), b.height());
    for (int y = 0; y < a.height(); ++y) {
        ASSERT_EQ(
            std::memcmp(a.row(y), b.row(y), sizeof(float) * static_cast<std::size_t>(a.width())), 0)
            << "row " << y;
    }
}

class RegionReuse : public ::testing::TestWithParam<vss::SolverKind> {
  protected:
    [[nodiscard]] static std::unique_ptr<vss::Solver> solver() {
        vss::SolverOptions o;
        o.kind = GetParam();
        o.p = 4.0;
        return vss::makeSolver(o);
    }
};

TEST_P(RegionReuse, OneRingDeeperResolvesItsTwoRegionsOnly) {
    const auto s = solver();
    const vss::VssResult before = solveOf(ringSceneDepth(baseRings()), *s);
    ASSERT_EQ(before.regions.size(), 5U);  // outside and inside each ring
    auto rings = baseRings();
    rings[2].depth = 0.65F;  // inside the range the dots hold
    const Image<float> depth = ringSceneDepth(rings);
    const vss::PreviousSolve previous = previousOf(before);
    const vss::VssResult reused = solveOf(depth, *s, &previous);
    const vss::VssResult fresh = solveOf(depth, *s);
    expectSameBytes(reused.height, fresh.height);
    // the three untouched rings' insides; the outside sees ring 2's wall
    EXPECT_EQ(reused.stats.reusedRegions, 3U);
    EXPECT_EQ(fresh.stats.reusedRegions, 0U);
    EXPECT_GT(reused.stats.reusedPixels, 3 * 400);
    EXPECT_LT(reused.stats.reusedPixels, reused.stats.voidPixels / 4);
}

TEST_P(RegionReuse, AHiddenRingRenumbersTheRegionsAndTheRestIsTaken) {
    const auto s = solver();
    const vss::VssResult before = solveOf(ringSceneDepth(baseRings()), *s);
    auto rings = baseRings();
    rings[1].shown = false;  // its inside joins the outside: ids after it move
    const Image<float> depth = ringSceneDepth(rings);
    const vss::PreviousSolve previous = previousOf(before);
    const vss::VssResult reused = solveOf(depth, *s, &previous);
    const vss::VssResult fresh = solveOf(depth, *s);
    ASSERT_EQ(reused.regions.size(), 4U);
    expectSameBytes(reused.height, fresh.height);
    EXPECT_EQ(reused.stats.reusedRegions, 3U);
    // and back: shown again, the three rings' insides are taken again
    const vss::PreviousSolve hidden = previousOf(reused);
    const Image<float> shownAgain = ringSceneDepth(baseRings());
    const vss::VssResult back = solveOf(shownAgain, *s, &hidden);
    expectSameBytes(back.height, before.height);
    EXPECT_EQ(back.stats.reusedRegions, 3U);
}

TEST_P(RegionReuse, TheSameDepthTakesEveryRegion) {
    const auto s = solver();
    const Image<float> depth = ringSceneDepth(baseRings());
    const vss::VssResult before = solveOf(depth, *s);
    const vss::PreviousSolve previous = previousOf(before);
    const vss::VssResult again = solveOf(depth, *s, &previous);
    expectSameBytes(again.height, before.height);
    EXPECT_EQ(again.stats.reusedRegions, before.regions.size());
    EXPECT_EQ(again.stats.reusedPixels, before.stats.voidPixels);
}

TEST_P(RegionReuse, ADifferentPixelSetIsSolvedAgain) {
    // The previous labels say one pixel inside ring 0 belonged elsewhere:
    // same box, count and contour, but not the same pixels.
    const auto s = solver();
    const Image<float> depth = ringSceneDepth(baseRings());
    const vss::VssResult before = solveOf(depth, *s);
    Image<std::int32_t> labels = before.labels;
    Image<float> height = before.height;
    const std::int32_t inside = labels(30, 40);
    ASSERT_NE(inside, vss::kVesselLabel);
    labels(30, 40) = inside == 0 ? 1 : 0;
    height(30, 40) = 7.0F;  // would show if the region were taken
    const vss::PreviousSolve previous{height.view(), labels.view(), &before.regions};
    const vss::VssResult again = solveOf(depth, *s, &previous);
    expectSameBytes(again.height, before.height);
    EXPECT_EQ(again.stats.reusedRegions, before.regions.size() - 1);
}

TEST_P(RegionReuse, APreviousSolveOfAnotherSizeIsIgnored) {
    // The same rings in an image 20 rows taller: the rings' insides have the
    // same boxes, pixels and contours, but the previous images another size.
    const auto s = solver();
    const Image<float> depth = ringSceneDepth(baseRings());
    Image<float> taller(depth.width(), depth.height() + 20, kInf);
    for (int y = 0; y < depth.height(); ++y) {
        for (int x = 0; x < depth.width(); ++x) {
            taller(x, y) = depth(x, y);
        }
    }
    const vss::VssResult other = solveOf(taller, *s);
    const vss::PreviousSolve previous = previousOf(other);
    const vss::VssResult r = solveOf(depth, *s, &previous);
    expectSameBytes(r.height, solveOf(depth, *s).height);
    EXPECT_EQ(r.stats.reusedRegions, 0U);
}

std::string solverName(const ::testing::TestParamInfo<vss::SolverKind>& param) {
    return param.param == vss::SolverKind::Fast ? "Fast" : "Brute";
}

INSTANTIATE_TEST_SUITE_P(Solvers, RegionReuse,
                         ::testing::Values(vss::SolverKind::Fast, vss::SolverKind::Brute),
                         solverName);

}  // namespace
