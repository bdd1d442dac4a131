// SPDX-License-Identifier: GPL-3.0-or-later
// The frame budget's meter: time a frame spends without the cores (other
// processes had them) is wall time but not the frame's cost.
#include <gtest/gtest.h>

#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFunctions_4_1_Core>
#include <chrono>
#include <cmath>
#include <thread>

#include "RenderTestUtil.h"
#include "vv/render/FrameCost.h"
#include "vv/render/FrameMeter.h"
#include "vv/render/GlResources.h"

namespace vv::render {
namespace {

class FrameMeterTest : public test::GlRenderTest {
  protected:
    void SetUp() override {
        ASSERT_TRUE(vv::test::makeGl41Current(surface_, context_))
            << "no OpenGL 4.1 context (run under xvfb-run with QT_QPA_PLATFORM=xcb)";
    }
    void TearDown() override { context_.doneCurrent(); }

    QOffscreenSurface surface_;
    QOpenGLContext context_;
};

TEST_F(FrameMeterTest, TimeWithoutTheCoresIsWallTimeButNoCost) {
    FrameMeter meter;
    meter.initialize();
    // This machine's llvmpipe is a software rasteriser.
    const auto* renderer = reinterpret_cast<const char*>(currentGl41().glGetString(GL_RENDERER));
    EXPECT_EQ(meter.softwareGl(), isSoftwareRenderer(renderer));

    // A frame that works ~15 ms on this thread, then waits 60 ms (as when
    // other processes hold the cores), up to its swap.
    meter.beginFrame();
    const auto start = std::chrono::steady_clock::now();
    volatile double sink = 0.0;
    while (std::chrono::steady_clock::now() - start < std::chrono::milliseconds(15)) {
        sink = sink + std::sqrt(2.0);
    }
    currentGl41().glFinish();
    meter.endFrame(true);
    std::this_thread::sleep_for(std::chrono::milliseconds(60));
    const auto frame = meter.atSwap();
    ASSERT_TRUE(frame.has_value());
    EXPECT_FALSE(meter.atSwap().has_value());  // once
    EXPECT_GE(frame->wallMilliseconds, 75.0);
    ASSERT_TRUE(frame->processCpuMilliseconds.has_value());
    ASSERT_TRUE(frame->threadCpuMilliseconds.has_value());
    if (meter.softwareGl()) {
        // The cost is the ~15 ms of work, not the 75 ms on the wall clock
        // (this thread's work may have been stretched by load too: it is
        // at most its wall time).
        const double cost = frameCostMilliseconds(*frame);
        // The 60 ms wait adds wall time and no CPU time, however loaded the
        // machine is.
        EXPECT_LT(cost, frame->wallMilliseconds - 50.0)
            << "wall " << frame->wallMilliseconds << ", process CPU "
            << *frame->processCpuMilliseconds << ", thread CPU " << *frame->threadCpuMilliseconds;
        EXPECT_GE(*frame->threadCpuMilliseconds, 1.0);
    }

    // A frame that is not measured keeps nothing.
    meter.beginFrame();
    meter.endFrame(false);
    EXPECT_FALSE(meter.atSwap().has_value());
    meter.release();
}

}  // namespace
}  // namespace vv::render
