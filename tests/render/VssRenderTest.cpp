// SPDX-License-Identifier: GPL-3.0-or-later
// The VSS frame through the render graph, offscreen with a real OpenGL 4.1
// context. Needs a display: run under `xvfb-run -a` with QT_QPA_PLATFORM=xcb.
// Without a GL context the tests fail (they never skip).
#include <gtest/gtest.h>

#include <QColor>
#include <QGuiApplication>
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <string>

#include "RenderTestUtil.h"
#include "vv/colormaps/ColorMap.h"
#include "vv/colormaps/DepthScale.h"
#include "vv/core/Error.h"
#include "vv/render/DepthRasterizer.h"
#include "vv/render/OffscreenRenderer.h"

namespace {

using vv::colormaps::DepthScale;
using vv::render::OffscreenOptions;
using vv::render::OffscreenRenderer;
using vv::render::PassState;

/// A near tube on top (z = +4) and a far tube below (z = -4): seen from the
/// default camera (looking down -z, +y up) the void between them runs from
/// near (top) to far (bottom).
vv::scene::Scene twoTubes() {
    return vv::render::test::twoTubes(1.0F, 4.0F, 32, 24);
}

class VssRenderTest : public vv::render::test::GlRenderTest {
  protected:
    static void keep(const QImage& image, const std::string& name) {
        vv::render::test::saveImage(image, "vss-", name);
    }

    OffscreenOptions options() const {
        // Exact pixel checks below: no AO darkening, no FXAA blending
        // (AoAaTest covers those).
        return vv::render::test::exactOptions(240, 180);
    }

    /// The rows of column x that are vessel (non-void) in a VSS-off image.
    std::vector<bool> vesselColumn(const QImage& off, int x) const {
        std::vector<bool> out(static_cast<std::size_t>(off.height()));
        for (int y = 0; y < off.height(); ++y) {
            out[static_cast<std::size_t>(y)] = off.pixel(x, y) != backgroundRgb_;
        }
        return out;
    }
};

TEST_F(VssRenderTest, VssOffShowsBackgroundInTheVoidAndCullsTheVssPasses) {
    auto renderer = makeRenderer();
    ASSERT_TRUE(renderer);
    const auto scene = twoTubes();
    auto o = options();
    o.display.vss.enabled = false;
    const QImage image = renderer->render(scene, o);
    keep(image, "off");
    long vessel = 0;
    long background = 0;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            (image.pixel(x, y) == backgroundRgb_ ? background : vessel) += 1;
        }
    }
    EXPECT_GT(vessel, 2000);
    EXPECT_GT(background, 10000);
    EXPECT_EQ(state(*renderer, "vss-solve"), PassState::Culled);
    EXPECT_EQ(state(*renderer, "vss-shading"), PassState::Culled);
    EXPECT_EQ(state(*renderer, "geometry"), PassState::Executed);
    EXPECT_EQ(state(*renderer, "composite"), PassState::Executed);
    EXPECT_FALSE(renderer->vssStatus().shown);
}

TEST_F(VssRenderTest, VssOnColoursTheVoidAndKeepsVesselPixels) {
    auto renderer = makeRenderer();
    ASSERT_TRUE(renderer);
    const auto scene = twoTubes();
    auto o = options();
    o.display.vss.enabled = false;
    const QImage off = renderer->render(scene, o);
    o.display.vss.enabled = true;  // chromadepth, lighting, iso-lines: the defaults
    const QImage on = renderer->render(scene, o);
    keep(on, "on-chromadepth");
    EXPECT_EQ(state(*renderer, "vss-solve"), PassState::Executed);
    EXPECT_EQ(state(*renderer, "vss-shading"), PassState::Executed);
    EXPECT_TRUE(renderer->vssStatus().shown);
    EXPECT_TRUE(renderer->vssStatus().current);
    long voidPixels = 0;
    long voidColoured = 0;
    long vesselPixels = 0;
    long vesselChanged = 0;
    for (int y = 0; y < off.height(); ++y) {
        for (int x = 0; x < off.width(); ++x) {
            if (off.pixel(x, y) == backgroundRgb_) {
                ++voidPixels;
                voidColoured += on.pixel(x, y) != backgroundRgb_ ? 1 : 0;
            } else {
                ++vesselPixels;
                vesselChanged += on.pixel(x, y) != off.pixel(x, y) ? 1 : 0;
            }
        }
    }
    EXPECT_GT(vesselPixels, 2000);
    EXPECT_EQ(vesselChanged, 0);
    EXPECT_GT(voidColoured, voidPixels * 99 / 100) << voidColoured << " of " << voidPixels;

    // Chromadepth: reddish just below the near (top) tube, bluish just above
    // the far (bottom) one.
    const int x = on.width() / 2;
    const auto column = vesselColumn(off, x);
    int nearEdge = -1;
    int farEdge = -1;
    for (int y = 1; y < on.height(); ++y) {
        if (column[static_cast<std::size_t>(y - 1)] && !column[static_cast<std::size_t>(y)] &&
            nearEdge < 0) {
            nearEdge = y;  // first void row below the top tube
        }
        if (!column[static_cast<std::size_t>(y - 1)] && column[static_cast<std::size_t>(y)] &&
            nearEdge >= 0) {
            farEdge = y - 1;  // last void row above the bottom tube
            break;
        }
    }
    ASSERT_GT(nearEdge, 0);
    ASSERT_GT(farEdge, nearEdge + 10);
    const QColor nearColour(on.pixel(x, nearEdge + 2));
    const QColor farColour(on.pixel(x, farEdge - 2));
    EXPECT_LT(nearColour.hsvHue(), 40) << nearColour.name().toStdString();
    EXPECT_GT(farColour.hsvHue(), 180) << farColour.name().toStdString();
}

TEST_F(VssRenderTest, DarkMeansDeepGreyFallsMonotonicallyFromNearToFar) {
    auto renderer = makeRenderer();
    ASSERT_TRUE(renderer);
    const auto scene = twoTubes();
    auto o = options();
    o.display.vss.enabled = false;
    const QImage off = renderer->render(scene, o);
    o.display.vss.enabled = true;
    o.display.vss.scale = DepthScale::DarkMeansDeep;
    o.display.vss.isoLines = 0;
    o.display.vss.lighting = 0.0F;  // the plain scale
    const QImage on = renderer->render(scene, o);
    keep(on, "dmd-flat");
    o.display.vss.isoLines = 8;
    o.display.vss.lighting = 1.0F;
    keep(renderer->render(scene, o), "dmd-lit");

    for (const int x : {on.width() / 3, on.width() / 2, 2 * on.width() / 3}) {
        const auto column = vesselColumn(off, x);
        std::vector<int> greys;
        bool belowTop = false;
        for (int y = 0; y < on.height(); ++y) {
            const bool vessel = column[static_cast<std::size_t>(y)];
            if (vessel && greys.empty()) {
                belowTop = true;
                continue;
            }
            if (vessel && !greys.empty()) {
                break;  // the far tube
            }
            if (belowTop && !vessel) {
                const QRgb p = on.pixel(x, y);
                EXPECT_EQ(qRed(p), qGreen(p));
                EXPECT_EQ(qGreen(p), qBlue(p));
                greys.push_back(qRed(p));
            }
        }
        ASSERT_GT(greys.size(), 20U) << x;
        for (std::size_t i = 1; i < greys.size(); ++i) {
            EXPECT_LE(greys[i], greys[i - 1] + 1) << "x " << x << " row " << i;
        }
        // Between the tubes: lighter than the far tube's depth (black) and
        // darker than the near tube's (white); the ramp spans most of it.
        EXPECT_GT(greys.front(), 150);
        EXPECT_LT(greys.back(), 100);
        EXPECT_GT(greys.front() - greys.back(), 100);
        EXPECT_LT(greys.front(), 256);
        EXPECT_GT(greys.back(), -1);
    }
}

TEST_F(VssRenderTest, ScaleAndIsoLinesReShadeWithoutReSolvingButPAndTheCameraReSolve) {
    auto renderer = makeRenderer();
    ASSERT_TRUE(renderer);
    const auto scene = twoTubes();
    auto o = options();
    o.display.vss.scale = DepthScale::DarkMeansDeep;
    const QImage first = renderer->render(scene, o);
    EXPECT_EQ(state(*renderer, "geometry"), PassState::Executed);
    EXPECT_EQ(state(*renderer, "vss-solve"), PassState::Executed);

    o.display.vss.scale = DepthScale::PseudoChromadepth;
    const QImage second = renderer->render(scene, o);
    keep(second, "pcd");
    EXPECT_EQ(state(*renderer, "geometry"), PassState::Cached);
    EXPECT_EQ(state(*renderer, "vss-solve"), PassState::Cached);
    EXPECT_EQ(state(*renderer, "vss-shading"), PassState::Executed);
    EXPECT_NE(first, second);  // and the colours did change

    o.display.vss.isoLines = 3;
    o.display.vss.isoLineWidth = 3.0F;
    (void)renderer->render(scene, o);
    EXPECT_EQ(state(*renderer, "vss-solve"), PassState::Cached);

    o.display.vss.solver.p = 4.0;
    (void)renderer->render(scene, o);
    EXPECT_EQ(state(*renderer, "geometry"), PassState::Cached);
    EXPECT_EQ(state(*renderer, "vss-solve"), PassState::Executed);

    vv::render::Camera camera;
    camera.setViewport(o.width, o.height);
    camera.fit(scene.bounds());
    camera.rotateView(0.3F, {0.0F, 1.0F, 0.0F});
    o.camera = camera;
    (void)renderer->render(scene, o);
    EXPECT_EQ(state(*renderer, "geometry"), PassState::Executed);
    EXPECT_EQ(state(*renderer, "vss-solve"), PassState::Executed);

    o.display.vss.solver.tolerance = 1e-3;
    (void)renderer->render(scene, o);
    EXPECT_EQ(state(*renderer, "vss-solve"), PassState::Executed);
    o.display.vss.solver.kind = vv::vss::SolverKind::Brute;
    (void)renderer->render(scene, o);
    EXPECT_EQ(state(*renderer, "vss-solve"), PassState::Executed);
    (void)renderer->render(scene, o);
    EXPECT_EQ(state(*renderer, "vss-solve"), PassState::Cached);
}

TEST_F(VssRenderTest, AFixedDepthRangeIsUsedAndReSolvesWhenItChanges) {
    auto renderer = makeRenderer();
    ASSERT_TRUE(renderer);
    const auto scene = twoTubes();
    auto o = options();
    const QImage visible = renderer->render(scene, o);
    const auto& status = renderer->vssStatus();
    ASSERT_TRUE(status.shown);
    const double visibleMin = status.dmin;
    const double visibleMax = status.dmax;
    ASSERT_LT(visibleMin, visibleMax);

    // A fixed range twice as deep as the visible one, starting at the same depth.
    o.display.vss.range.mode = vv::vss::RangeMode::Fixed;
    o.display.vss.range.dmin = visibleMin;
    o.display.vss.range.dmax = visibleMin + 2.0 * (visibleMax - visibleMin);
    const QImage fixed = renderer->render(scene, o);
    EXPECT_EQ(state(*renderer, "geometry"), PassState::Cached);
    EXPECT_EQ(state(*renderer, "vss-solve"), PassState::Executed);
    EXPECT_DOUBLE_EQ(renderer->vssStatus().dmin, o.display.vss.range.dmin);
    EXPECT_DOUBLE_EQ(renderer->vssStatus().dmax, o.display.vss.range.dmax);
    EXPECT_NE(visible, fixed);  // the far tube is now half way down the scale
    (void)renderer->render(scene, o);
    EXPECT_EQ(state(*renderer, "vss-solve"), PassState::Cached);

    o.display.vss.range.dmax = o.display.vss.range.dmin - 1.0;
    EXPECT_THROW((void)renderer->render(scene, o), vv::InvalidArgumentError);
    o.display.vss.range.dmax = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW((void)renderer->render(scene, o), vv::InvalidArgumentError);
}

TEST_F(VssRenderTest, GBufferLinearDepthMatchesTheCpuRasteriser) {
    auto renderer = makeRenderer();
    ASSERT_TRUE(renderer);
    const auto scene = twoTubes();
    auto o = options();
    vv::render::Camera camera;
    camera.setViewport(o.width, o.height);
    camera.fit(scene.bounds());
    camera.rotateView(0.4F, {1.0F, 0.3F, 0.0F});
    o.camera = camera;
    (void)renderer->render(scene, o);
    const vv::Image<float> gl = renderer->lastLinearDepth();
    camera.setSceneBounds(scene.bounds());
    const vv::Image<float> cpu = vv::render::rasterizeDepth(scene, camera);
    ASSERT_EQ(gl.width(), cpu.width());
    ASSERT_EQ(gl.height(), cpu.height());
    long both = 0;
    long onlyOne = 0;
    double worst = 0.0;
    for (int y = 0; y < gl.height(); ++y) {
        for (int x = 0; x < gl.width(); ++x) {
            const float a = gl(x, y);
            const float b = cpu(x, y);
            if (std::isfinite(a) && std::isfinite(b)) {
                ++both;
                worst = std::max(worst, static_cast<double>(std::abs(a - b)) / b);
            } else if (std::isfinite(a) != std::isfinite(b)) {
                ++onlyOne;
            } else {
                EXPECT_TRUE(std::isinf(a) && a > 0.0F);
            }
        }
    }
    EXPECT_GT(both, 3000);
    EXPECT_LT(worst, 1e-4);
    // Edge pixels may be covered by one rasteriser only (tie rules differ).
    EXPECT_LT(onlyOne, both / 50) << onlyOne << " of " << both;
}

TEST_F(VssRenderTest, EveryScaleRenders) {
    auto renderer = makeRenderer();
    ASSERT_TRUE(renderer);
    const auto scene = twoTubes();
    auto o = options();
    o.width = 480;
    o.height = 360;
    for (const auto scale : vv::colormaps::allDepthScales()) {
        o.display.vss.scale = scale;
        const QImage image = renderer->render(scene, o);
        keep(image, std::string(vv::colormaps::shortName(scale)));
        EXPECT_NE(image.pixel(image.width() / 2, image.height() / 2), backgroundRgb_);
    }
}

}  // namespace
