// SPDX-License-Identifier: GPL-3.0-or-later
// The frame's solve takes the regions that did not change from the previous
// exact frame (solveFrame's `previous`, SolveWorker): same bytes as a fresh
// solve, and only with the same solver options, size and exactness.
#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <stop_token>

#include "RingScene.h"
#include "SolveWorker.h"
#include "vv/core/Image.h"
#include "vv/vss/Solver.h"

namespace {

using vv::Image;
using vv::render::SolvedFrame;
using vv::render::solveFrame;

SolvedFrame solved(const Image<float>& depth, double p, bool preview,
                   const SolvedFrame* previous = nullptr) {
    vv::vss::SolverOptions options;
    options.p = p;
    return solveFrame(1, depth, options, preview, {}, 1.0F, 1.0F, {0, 0}, std::stop_token{},
                      previous, true);
}

bool sameBytes(const Image<float>& a, const Image<float>& b) {
    return a.width() == b.width() && a.height() == b.height() &&
           std::memcmp(a.view().data(), b.view().data(),
                       sizeof(float) * static_cast<std::size_t>(a.width()) *
                           static_cast<std::size_t>(a.height())) == 0;
}

Image<float> oneRingHidden() {
    auto rings = vv::test::baseRings();
    rings[1].shown = false;
    return vv::test::ringSceneDepth(rings);
}

TEST(SolveReuse, AnExactFrameTakesTheUnchangedRegionsOfThePreviousOne) {
    const SolvedFrame before = solved(vv::test::ringSceneDepth(vv::test::baseRings()), 4.0, false);
    ASSERT_NE(before.regions, nullptr);
    EXPECT_EQ(before.regions->regions.size(), 5U);
    const Image<float> depth = oneRingHidden();
    const SolvedFrame after = solved(depth, 4.0, false, &before);
    EXPECT_EQ(after.reusedRegions, 3U);
    EXPECT_GT(after.reusedPixels, 0);
    EXPECT_TRUE(sameBytes(after.height, solved(depth, 4.0, false).height));
}

TEST(SolveReuse, AnotherPOrAPreviewSolvesEverything) {
    const SolvedFrame before = solved(vv::test::ringSceneDepth(vv::test::baseRings()), 4.0, false);
    const Image<float> depth = oneRingHidden();
    const SolvedFrame otherP = solved(depth, 2.0, false, &before);
    EXPECT_EQ(otherP.reusedRegions, 0U);
    EXPECT_TRUE(sameBytes(otherP.height, solved(depth, 2.0, false).height));
    const SolvedFrame preview = solved(depth, 4.0, true, &before);
    EXPECT_EQ(preview.reusedRegions, 0U);
    EXPECT_EQ(preview.regions, nullptr);  // previews keep no regions
    // and a preview as the previous frame offers nothing
    const SolvedFrame afterPreview = solved(depth, 4.0, false, &preview);
    EXPECT_EQ(afterPreview.reusedRegions, 0U);
}

TEST(SolveReuse, AnInlineSolveKeepsNoRegions) {
    // exports and the command line solve once: no labels kept (4 bytes a pixel)
    vv::vss::SolverOptions options;
    const SolvedFrame frame = solveFrame(1, vv::test::ringSceneDepth(vv::test::baseRings()),
                                         options, false, {}, 1.0F, 1.0F, {0, 0}, std::stop_token{});
    EXPECT_EQ(frame.regions, nullptr);
    EXPECT_EQ(frame.height.width(), vv::test::kRingSceneWidth);
}

TEST(SolveReuse, TheWorkerPassesItsLatestExactFrame) {
    vv::render::SolveWorker worker({});
    vv::vss::SolverOptions options;
    options.p = 4.0;
    const auto submit = [&](std::uint64_t key, Image<float> depth) {
        vv::render::SolveWorker::Job job;
        job.key = key;
        job.depth = std::make_shared<const Image<float>>(std::move(depth));
        job.options = options;
        job.pixelScale = 1.0F;
        worker.submit(std::move(job));
        worker.waitIdle();
        return worker.latest().first;
    };
    const auto first = submit(1, vv::test::ringSceneDepth(vv::test::baseRings()));
    ASSERT_NE(first, nullptr);
    EXPECT_EQ(first->reusedRegions, 0U);
    const auto second = submit(2, oneRingHidden());
    ASSERT_NE(second, nullptr);
    EXPECT_EQ(second->key, 2U);
    EXPECT_EQ(second->reusedRegions, 3U);
    EXPECT_TRUE(sameBytes(second->height, solved(oneRingHidden(), 4.0, false).height));
}

}  // namespace
