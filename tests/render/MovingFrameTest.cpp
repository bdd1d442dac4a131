// SPDX-License-Identifier: GPL-3.0-or-later
// What a person sees while the camera moves: a moving frame (reduced render
// size, preview solve, no occlusion, no FXAA: RefinementPolicy's moving
// settings) of the demo tree looks like the settled frame of the same view
// (exact VSS, occlusion, FXAA) at the same window size, by SSIM; and the
// VSS's iso-lines keep their width in window pixels instead of growing with
// the reduction. Needs a display (xvfb-run, QT_QPA_PLATFORM=xcb).
#include <gtest/gtest.h>

#include <QImage>
#include <cmath>
#include <cstdio>
#include <memory>

#include "ImageCompare.h"
#include "RenderTestUtil.h"
#include "vv/demo/DemoTree.h"
#include "vv/render/RefinementPolicy.h"

namespace vv::render {
namespace {

/// The demo tree, a little smaller than the bundled one (its look at a
/// window's size is the same; it is made faster).
const scene::Scene& demoTree() {
    static const scene::Scene tree = [] {
        demo::DemoTreeOptions options;
        options.generations = 5;
        options.maxTriangles = 100000;
        scene::Scene scene;
        scene.meshes.push_back(demo::generateDemoMesh(options));
        return scene;
    }();
    return tree;
}

/// The display settings of the viewer: VSS with iso-lines, AO and FXAA on.
FrameSettings displaySettings() {
    FrameSettings settings;
    settings.vss.isoLines = 8;
    return settings;
}

/// The settings of a moving frame at `scale` (RefinementPolicy, camera moving).
FrameSettings movingSettings(float scale) {
    RefinementPolicy policy;
    policy.setInteractiveScale(scale);
    EXPECT_TRUE(policy.cameraMoved());
    return policy.frameSettings(displaySettings());
}

class MovingFrameTest : public test::GlRenderTest {
  protected:
    void SetUp() override {
        harness_ = std::make_unique<test::FrameHarness>(kWidth, kHeight);
        harness_->setScene(demoTree());
    }
    void TearDown() override { harness_.reset(); }

    QImage render(const FrameSettings& settings) { return harness_->render(style_, settings); }

    static constexpr int kWidth = 1280;
    static constexpr int kHeight = 720;
    std::unique_ptr<test::FrameHarness> harness_;
    MeshStyle style_;
};

TEST_F(MovingFrameTest, AMovingFrameLooksLikeTheSettledFrameOfTheSameView) {
    const QImage settled = render(displaySettings());
    // The floor of dynamic resolution, where moving frames look worst.
    const QImage moving = render(movingSettings(RefinementPolicy::kMinInteractiveScale));
    ASSERT_EQ(harness_->renderer().lastRenderSize(), glm::ivec2(kWidth / 4, kHeight / 4));
    test::saveImage(settled, "moving-frame-", "settled");
    test::saveImage(moving, "moving-frame-", "moving");
    const vv::test::ImageComparison c = vv::test::compareImages(moving, settled);
    std::printf("moving frame at %.2f against the settled frame: %s\n",
                static_cast<double>(RefinementPolicy::kMinInteractiveScale), c.message.c_str());
    // 0.912 when the reduced frame solved its VSS from the depth as read
    // (every contour depth nearer than at the window's size, see
    // silhouetteDepth); 0.933 from the silhouette depth.
    EXPECT_GE(1.0 - c.difference, 0.925) << c.message;
}

/// The VSS height (z') of a frame on its void pixels, with the depth its
/// solve read (to tell vessel pixels apart).
struct ShownVss {
    Image<float> height;
    Image<float> depth;
};

TEST_F(MovingFrameTest, AMovingFramesVssLiesWhereTheSettledFramesDoes) {
    // Where the far field's iso-lines lie: its z' against the settled one's,
    // averaged over the void pixels of the moving frame. Its flat parts move
    // an iso-line by tens of pixels for a few thousandths of z'.
    static_cast<void>(render(displaySettings()));
    const ShownVss settled{harness_->renderer().shownHeight(),
                           harness_->renderer().lastSolvedDepth()};
    static_cast<void>(render(movingSettings(RefinementPolicy::kMinInteractiveScale)));
    const ShownVss moving{harness_->renderer().shownHeight(),
                          harness_->renderer().lastSolvedDepth()};
    ASSERT_EQ(moving.height.width(), kWidth / 4);
    ASSERT_EQ(settled.height.width(), kWidth);
    double sum = 0.0;
    long n = 0;
    for (int y = 0; y < moving.height.height(); ++y) {
        for (int x = 0; x < moving.height.width(); ++x) {
            // The settled pixel at the centre of the moving pixel's 4x4 block.
            const int sx = 4 * x + 2;
            const int sy = 4 * y + 2;
            if (std::isfinite(moving.depth(x, y)) || std::isfinite(settled.depth(sx, sy)) ||
                !std::isfinite(moving.height(x, y)) || !std::isfinite(settled.height(sx, sy))) {
                continue;
            }
            sum += moving.height(x, y) - settled.height(sx, sy);
            ++n;
        }
    }
    ASSERT_GT(n, moving.height.width() * moving.height.height() / 2);
    const double offset = sum / static_cast<double>(n);
    std::printf("moving frame's z' - settled frame's z', mean over %ld void pixels: %.5f\n", n,
                offset);
    // -0.0051 from the depth as read: the whole far field nearer.
    EXPECT_LT(std::abs(offset), 0.002);
}

/// Pixels where `with` and `without` differ by more than 40 of 255 in some
/// channel: where the iso-lines are drawn.
long linePixels(const QImage& with, const QImage& without) {
    // differenceImage: the largest channel difference, 4 times, as grey.
    const QImage difference = vv::test::differenceImage(with, without);
    long n = 0;
    for (int y = 0; y < difference.height(); ++y) {
        for (int x = 0; x < difference.width(); ++x) {
            n += qRed(difference.pixel(x, y)) > 4 * 40 ? 1 : 0;
        }
    }
    return n;
}

TEST_F(MovingFrameTest, IsoLinesKeepTheirWidthInWindowPixelsWhileMoving) {
    // Two tubes at different depths: the VSS between them is a ramp that
    // many iso-lines cross. AO and FXAA off in both frames: only the lines
    // and the size differ.
    harness_->setScene(test::twoTubes(1.5F, 8.0F, 32, 32));
    FrameSettings display = displaySettings();
    display.vss.isoLines = 16;
    display.ao.enabled = false;
    display.antialiasing = false;
    FrameSettings noLines = display;
    noLines.vss.isoLines = 0;
    RefinementPolicy policy;
    policy.setInteractiveScale(RefinementPolicy::kMinInteractiveScale);
    ASSERT_TRUE(policy.cameraMoved());

    const long settled = linePixels(render(display), render(noLines));
    const QImage moving = render(policy.frameSettings(display));
    const long whileMoving = linePixels(moving, render(policy.frameSettings(noLines)));
    test::saveImage(moving, "moving-frame-", "iso-lines");
    ASSERT_GT(settled, 1000) << "no iso-lines drawn";
    // Drawn at the reduced size they were 4 times as wide (and blurred).
    std::printf("iso-line pixels: settled %ld, moving %ld\n", settled, whileMoving);
    EXPECT_GT(whileMoving, settled / 2);
    EXPECT_LT(whileMoving, settled * 3 / 2)
        << "iso-lines wider while moving: " << whileMoving << " line pixels against " << settled;
}

}  // namespace
}  // namespace vv::render
