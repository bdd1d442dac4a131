// SPDX-License-Identifier: GPL-3.0-or-later
// The refinement policy of an interactive view, without GL: moving ->
// settled -> exact -> occlusion, what each phase's frames are drawn with,
// and the frame-budget steps of dynamic resolution.
#include <gtest/gtest.h>

#include <limits>

#include "vv/render/RefinementPolicy.h"

namespace vv::render {
namespace {

using Phase = RefinementPolicy::Phase;

/// Display settings that differ from every adjustment the policy makes.
FrameSettings display() {
    FrameSettings settings;
    settings.vss.enabled = true;
    settings.ao.enabled = true;
    settings.antialiasing = true;
    settings.resolutionScale = 1.0F;
    settings.background = {0.1F, 0.2F, 0.3F};
    return settings;
}

VssFrameStatus status(bool pending, bool preview) {
    VssFrameStatus s;
    s.shown = !pending;
    s.current = !pending;
    s.pending = pending;
    s.preview = preview;
    return s;
}

/// What the policy may change in a frame's settings.
struct Expected {
    bool preview = false;
    bool occlusion = true;  ///< AO and FXAA
    float scale = 1.0F;
    bool simplified = false;
};

void expectSettings(const FrameSettings& s, const Expected& e) {
    EXPECT_EQ(s.vss.preview, e.preview);
    EXPECT_EQ(s.ao.enabled, e.occlusion);
    EXPECT_EQ(s.antialiasing, e.occlusion);
    EXPECT_FLOAT_EQ(s.resolutionScale, e.scale);
    EXPECT_EQ(s.simplifiedGeometry, e.simplified);
    EXPECT_FLOAT_EQ(s.background.g, 0.2F);  // never touched
}

void expectDisplay(const FrameSettings& s) {
    expectSettings(s, Expected{});
}

TEST(RefinementPolicyTest, StillFramesUseTheDisplaySettings) {
    RefinementPolicy policy;
    EXPECT_EQ(policy.phase(), Phase::Still);
    expectDisplay(policy.frameSettings(display()));
    const auto after = policy.frameDrawn(status(false, false));
    EXPECT_FALSE(after.measure);
    EXPECT_FALSE(after.showedCameraMove);
    EXPECT_FALSE(after.occlusionFrame);
}

TEST(RefinementPolicyTest, MovingSettledExactThenTheOcclusion) {
    RefinementPolicy policy;
    policy.setInteractiveScale(0.6F);
    // Moving: a preview solve at the interactive scale on the simplified
    // meshes, without occlusion and FXAA.
    EXPECT_TRUE(policy.cameraMoved());
    EXPECT_EQ(policy.phase(), Phase::Moving);
    expectSettings(
        policy.frameSettings(display()),
        Expected{.preview = true, .occlusion = false, .scale = 0.6F, .simplified = true});
    EXPECT_TRUE(policy.frameDrawn(status(false, true)).showedCameraMove);
    // A frame without a camera change in between (a preview arrived).
    EXPECT_FALSE(policy.frameDrawn(status(false, true)).showedCameraMove);

    // Settled: the exact solve at full size on the full meshes, still
    // without occlusion and FXAA.
    EXPECT_TRUE(policy.settle());
    EXPECT_EQ(policy.phase(), Phase::Settled);
    EXPECT_TRUE(policy.occlusionDeferred());
    expectSettings(policy.frameSettings(display()), Expected{.occlusion = false});

    // Neither a pending solve nor the last preview ends the deferral.
    EXPECT_FALSE(policy.frameDrawn(status(true, false)).occlusionFrame);
    EXPECT_FALSE(policy.frameDrawn(status(false, true)).occlusionFrame);
    EXPECT_EQ(policy.phase(), Phase::Settled);
    // The exact VSS on screen: one more frame, with the occlusion and FXAA.
    EXPECT_TRUE(policy.frameDrawn(status(false, false)).occlusionFrame);
    EXPECT_EQ(policy.phase(), Phase::Still);
    expectDisplay(policy.frameSettings(display()));
    EXPECT_FALSE(policy.frameDrawn(status(false, false)).occlusionFrame);
}

TEST(RefinementPolicyTest, SettlingAStillViewChangesNothing) {
    RefinementPolicy policy;
    EXPECT_FALSE(policy.settle());
    EXPECT_EQ(policy.phase(), Phase::Still);
    expectDisplay(policy.frameSettings(display()));
}

TEST(RefinementPolicyTest, MovingAgainWhileSettledMovesAgain) {
    RefinementPolicy policy;
    ASSERT_TRUE(policy.cameraMoved());
    ASSERT_TRUE(policy.settle());
    EXPECT_TRUE(policy.cameraMoved());
    EXPECT_EQ(policy.phase(), Phase::Moving);
    // A moving frame never ends the deferral, even with an exact status.
    EXPECT_FALSE(policy.frameDrawn(status(false, false)).occlusionFrame);
    EXPECT_TRUE(policy.settle());
    EXPECT_TRUE(policy.frameDrawn(status(false, false)).occlusionFrame);
}

TEST(RefinementPolicyTest, WithoutProgressiveRefinementTheCameraNeverMoves) {
    RefinementPolicy policy;
    policy.setProgressive(false);
    EXPECT_FALSE(policy.cameraMoved());
    EXPECT_EQ(policy.phase(), Phase::Still);
    expectDisplay(policy.frameSettings(display()));
    EXPECT_FALSE(policy.settle());
}

TEST(RefinementPolicyTest, OnlyTheFirstFrameOfACameraMoveMeasuresItself) {
    RefinementPolicy policy;
    ASSERT_GT(policy.frameBudget(), 0.0);  // on by default
    ASSERT_TRUE(policy.cameraMoved());
    EXPECT_TRUE(policy.frameDrawn(status(false, true)).measure);
    EXPECT_FALSE(policy.frameDrawn(status(false, true)).measure);
    policy.setFrameBudget(0.0);
    ASSERT_TRUE(policy.cameraMoved());
    EXPECT_FALSE(policy.frameDrawn(status(false, true)).measure);
}

TEST(RefinementPolicyTest, TheBudgetStepsTheScaleDownWhenSlowAndUpWhenFast) {
    RefinementPolicy policy;
    policy.setFrameBudget(30.0);
    ASSERT_FLOAT_EQ(policy.interactiveScale(), 0.5F);
    ASSERT_FLOAT_EQ(policy.interactiveVssScale(), 0.5F);
    // Over 1.15 x the budget: one step down, taken by the next camera move.
    // From half size the whole frame drops to 0.42, then to 0.35 (the
    // cheapest frames at SSIM >= 0.9 keep the VSS at the render size).
    policy.frameMeasured(40.0);
    EXPECT_FLOAT_EQ(policy.nextInteractiveScale(), 0.42F);
    EXPECT_FLOAT_EQ(policy.nextInteractiveVssScale(), 0.42F);
    EXPECT_FLOAT_EQ(policy.interactiveScale(), 0.5F);
    ASSERT_TRUE(policy.cameraMoved());
    EXPECT_FLOAT_EQ(policy.interactiveScale(), 0.42F);
    EXPECT_FLOAT_EQ(policy.interactiveVssScale(), 0.42F);
    EXPECT_FLOAT_EQ(policy.frameSettings(display()).vssResolutionScale, 1.0F);
    // Between 0.6 x and 1.15 x: the sizes hold.
    policy.frameMeasured(25.0);
    EXPECT_FLOAT_EQ(policy.nextInteractiveScale(), 0.42F);
    EXPECT_FLOAT_EQ(policy.nextInteractiveVssScale(), 0.42F);
    policy.frameMeasured(40.0);
    ASSERT_TRUE(policy.cameraMoved());
    EXPECT_FLOAT_EQ(policy.interactiveScale(), 0.35F);
    EXPECT_FLOAT_EQ(policy.interactiveVssScale(), 0.35F);
    // Then the VSS drops to a quarter under vessels at 0.35 (sharper edges).
    policy.frameMeasured(40.0);
    ASSERT_TRUE(policy.cameraMoved());
    EXPECT_FLOAT_EQ(policy.interactiveScale(), 0.35F);
    EXPECT_FLOAT_EQ(policy.interactiveVssScale(), 0.25F);
    EXPECT_FLOAT_EQ(policy.frameSettings(display()).vssResolutionScale, 0.25F / 0.35F);
    policy.frameMeasured(40.0);
    ASSERT_TRUE(policy.cameraMoved());
    EXPECT_FLOAT_EQ(policy.interactiveScale(), 0.3F);
    EXPECT_FLOAT_EQ(policy.interactiveVssScale(), 0.25F);
    // Under 0.6 x: one step up.
    policy.frameMeasured(10.0);
    EXPECT_FLOAT_EQ(policy.nextInteractiveScale(), 0.35F);
    EXPECT_FLOAT_EQ(policy.nextInteractiveVssScale(), 0.25F);
    // The steps end at kMinInteractiveScale and at full size; the VSS is
    // never larger than the render size.
    for (int i = 0; i < 20; ++i) {
        policy.frameMeasured(1e6);
        ASSERT_TRUE(policy.cameraMoved());
        ASSERT_LE(policy.interactiveVssScale(), policy.interactiveScale());
    }
    EXPECT_FLOAT_EQ(policy.interactiveScale(), RefinementPolicy::kMinInteractiveScale);
    for (int i = 0; i < 20; ++i) {
        policy.frameMeasured(0.0);
        ASSERT_TRUE(policy.cameraMoved());
        ASSERT_LE(policy.interactiveVssScale(), policy.interactiveScale());
    }
    EXPECT_FLOAT_EQ(policy.interactiveScale(), 1.0F);
    EXPECT_FLOAT_EQ(policy.interactiveVssScale(), 1.0F);
}

TEST(RefinementPolicyTest, AFixedScaleTurnsTheBudgetOff) {
    RefinementPolicy policy;
    policy.setInteractiveScale(0.7F);
    EXPECT_EQ(policy.frameBudget(), 0.0);
    EXPECT_FLOAT_EQ(policy.interactiveVssScale(), 0.7F);  // the VSS at the render size
    policy.setInteractiveScale(0.7F, 0.3F);
    EXPECT_FLOAT_EQ(policy.interactiveVssScale(), 0.3F);
    policy.setInteractiveScale(0.7F, 0.9F);
    EXPECT_FLOAT_EQ(policy.interactiveVssScale(), 0.7F);  // never above the render size
    policy.setInteractiveScale(0.7F);
    policy.frameMeasured(1e6);  // a measurement would not have come: nothing to do
    ASSERT_TRUE(policy.cameraMoved());
    EXPECT_FLOAT_EQ(policy.interactiveScale(), 0.7F);
    policy.setInteractiveScale(0.01F);
    EXPECT_FLOAT_EQ(policy.interactiveScale(), 0.1F);
    policy.setInteractiveScale(std::numeric_limits<float>::quiet_NaN());
    EXPECT_FLOAT_EQ(policy.interactiveScale(), 1.0F);
    policy.setFrameBudget(-3.0);
    EXPECT_EQ(policy.frameBudget(), 0.0);
    policy.setFrameBudget(std::numeric_limits<double>::infinity());
    EXPECT_EQ(policy.frameBudget(), 0.0);
}

}  // namespace
}  // namespace vv::render
