// SPDX-License-Identifier: GPL-3.0-or-later
// The refinement policy of an interactive view, without GL: moving ->
// settled -> exact -> occlusion, what each phase's frames are drawn with,
// and the frame-budget steps of dynamic resolution.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>

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

/// A measured frame: wall, process and drawing thread CPU, GPU (< 0: none)
/// milliseconds.
FrameMeasurement measured(double wall, double process, double thread, double gpu, int cores,
                          bool softwareGl) {
    FrameMeasurement frame;
    frame.wallMilliseconds = wall;
    if (process >= 0.0) {
        frame.processCpuMilliseconds = process;
    }
    if (thread >= 0.0) {
        frame.threadCpuMilliseconds = thread;
    }
    if (gpu >= 0.0) {
        frame.gpuMilliseconds = gpu;
    }
    frame.cores = cores;
    frame.softwareGl = softwareGl;
    return frame;
}

// The budget weighs a frame's work, not the wall time other processes
// stretch: on software OpenGL the drawing thread's CPU time plus the other
// threads' spread over the cores.
TEST(RefinementPolicyTest, LoadFromOtherProcessesDoesNotPushTheBudgetDown) {
    RefinementPolicy policy;
    policy.setFrameBudget(30.0);
    ASSERT_FLOAT_EQ(policy.interactiveScale(), 0.5F);
    // 80 ms on the wall clock, of which this process worked 10 ms on the
    // drawing thread and 30 ms on two cores: 25 ms on a free machine.
    const FrameMeasurement loaded = measured(80.0, 40.0, 10.0, -1.0, 2, true);
    policy.frameMeasured(loaded);
    EXPECT_DOUBLE_EQ(policy.lastFrameCost(), 25.0);
    EXPECT_FLOAT_EQ(policy.nextInteractiveScale(), 0.5F);  // holds
    EXPECT_FLOAT_EQ(policy.nextInteractiveVssScale(), 0.5F);
    // The same wall time with the work to match steps down.
    FrameMeasurement slow = loaded;
    slow.processCpuMilliseconds = 110.0;
    slow.threadCpuMilliseconds = 20.0;  // 20 + 90 / 2
    policy.frameMeasured(slow);
    EXPECT_DOUBLE_EQ(policy.lastFrameCost(), 65.0);
    EXPECT_FLOAT_EQ(policy.nextInteractiveScale(), 0.42F);
    // A frame known by its wall time only: the wall time, as before.
    policy.frameMeasured(80.0);
    EXPECT_DOUBLE_EQ(policy.lastFrameCost(), 80.0);
    EXPECT_FLOAT_EQ(policy.nextInteractiveScale(), 0.42F);  // down, as the loaded frame would
    ASSERT_TRUE(policy.cameraMoved());
    policy.frameMeasured(80.0);
    EXPECT_FLOAT_EQ(policy.nextInteractiveScale(), 0.35F);
}

TEST(RefinementPolicyTest, OnAGpuTheFramesGpuTimeCounts) {
    RefinementPolicy policy;
    policy.setFrameBudget(30.0);
    // Little CPU work, 45 ms of GPU work: too slow, whatever the CPU says.
    FrameMeasurement frame = measured(48.0, 6.0, 5.0, 45.0, 8, false);
    policy.frameMeasured(frame);
    EXPECT_DOUBLE_EQ(policy.lastFrameCost(), 45.0);
    EXPECT_FLOAT_EQ(policy.nextInteractiveScale(), 0.42F);
    // A fast GPU on a loaded machine (70 ms on the wall clock): fast.
    frame.wallMilliseconds = 70.0;
    frame.gpuMilliseconds = 9.0;
    policy.frameMeasured(frame);
    EXPECT_NEAR(policy.lastFrameCost(), 9.0, 1e-12);
    EXPECT_FLOAT_EQ(policy.nextInteractiveScale(), 0.6F);  // one step up from 0.5
    // Without a GPU time (no timer queries) a GPU's work is unknown: the wall time.
    frame.gpuMilliseconds.reset();
    policy.frameMeasured(frame);
    EXPECT_DOUBLE_EQ(policy.lastFrameCost(), 70.0);
}

TEST(FrameCostTest, TheCostIsNeverAboveTheWallTimeAndFallsBackToIt) {
    // Threads that ran side by side with the drawing thread: the wall time.
    EXPECT_DOUBLE_EQ(frameCostMilliseconds(measured(50.0, 200.0, 100.0, -1.0, 2, true)), 50.0);
    // No CPU clocks: the wall time.
    EXPECT_DOUBLE_EQ(frameCostMilliseconds(measured(50.0, -1.0, -1.0, -1.0, 2, true)), 50.0);
    // Nonsense counts as missing; the thread's time never above the process's.
    FrameMeasurement nonsense = measured(50.0, 0.0, 10.0, -1.0, 2, true);
    nonsense.processCpuMilliseconds = -1.0;
    EXPECT_DOUBLE_EQ(frameCostMilliseconds(nonsense), 50.0);
    EXPECT_DOUBLE_EQ(frameCostMilliseconds(measured(50.0, 12.0, 30.0, -1.0, 0, true)), 12.0);
    EXPECT_DOUBLE_EQ(frameCostMilliseconds(measured(std::numeric_limits<double>::quiet_NaN(), -1.0,
                                                    -1.0, -1.0, 1, false)),
                     0.0);
}

TEST(FrameCostTest, SoftwareRasterisersAreRecognisedByName) {
    EXPECT_TRUE(isSoftwareRenderer("llvmpipe (LLVM 15.0.6, 256 bits)"));
    EXPECT_TRUE(isSoftwareRenderer("Google SwiftShader"));
    EXPECT_FALSE(isSoftwareRenderer("NVIDIA GeForce RTX 3060/PCIe/SSE2"));
    EXPECT_FALSE(isSoftwareRenderer("AMD Radeon Pro (radeonsi, navi10, LLVM 15.0.6)"));
    EXPECT_FALSE(isSoftwareRenderer(nullptr));
}

TEST(FrameCostTest, TheCpuClocksCountThisThreadsWork) {
    const std::optional<CpuTimes> before = cpuTimesNow();
    ASSERT_TRUE(before.has_value());  // Linux: CLOCK_PROCESS_CPUTIME_ID, CLOCK_THREAD_CPUTIME_ID
    volatile double sink = 0.0;
    std::optional<CpuTimes> after;
    do {
        for (int i = 0; i < 100000; ++i) {
            sink = sink + std::sqrt(static_cast<double>(i));
        }
        after = cpuTimesNow();
    } while (after->threadMilliseconds - before->threadMilliseconds < 5.0);
    EXPECT_GE(after->processMilliseconds - before->processMilliseconds,
              after->threadMilliseconds - before->threadMilliseconds - 0.5);
}

}  // namespace
}  // namespace vv::render
