// SPDX-License-Identifier: GPL-3.0-or-later
// Volume depth source (issue 5): first-hit iso-surface ray casting of a
// volume in the geometry pass, offscreen with a real OpenGL 4.1 context.
// Needs a display: run under `xvfb-run -a` with QT_QPA_PLATFORM=xcb.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/glm.hpp>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "RenderTestUtil.h"
#include "vv/core/Error.h"
#include "vv/render/Camera.h"
#include "vv/render/OffscreenRenderer.h"
#include "vv/scene/Volume.h"

namespace {

using vv::render::Camera;
using vv::render::OffscreenOptions;

struct Ball {
    glm::dvec3 centre;  ///< world, mm
    double radius;      ///< mm
};

constexpr double kIso = 500.0;
/// Anisotropic voxels (mm): the ray caster must handle them in index space.
const glm::dvec3 kSpacing{0.6, 0.8, 1.1};
const glm::dvec3 kOrigin{-19.2, -25.6, -35.2};  ///< voxel (0, 0, 0): the grid centred on 0

/// 64^3 voxels, 1000 inside the balls and 0 outside with a linear 2 mm edge:
/// the 500 iso-surface is the sphere of each ball's radius.
std::shared_ptr<vv::scene::Volume> ballVolume(const std::vector<Ball>& balls,
                                              bool sheared = false) {
    auto v = std::make_shared<vv::scene::Volume>(glm::ivec3(64), vv::scene::VoxelType::Int16);
    glm::dmat4 m(1.0);
    m[0] = glm::dvec4(kSpacing.x, 0, 0, 0);
    m[1] = glm::dvec4(0, kSpacing.y, 0, 0);
    m[2] = glm::dvec4(0, 0, kSpacing.z, 0);
    m[3] = glm::dvec4(kOrigin, 1.0);
    if (sheared) {
        // Rotated rows / columns and a gantry-tilt-like slice step, centred on 0.
        const double c = std::cos(0.4);
        const double s = std::sin(0.4);
        const glm::dmat3 l(glm::dvec3(c * kSpacing.x, s * kSpacing.x, 0.0),
                           glm::dvec3(-s * kSpacing.y, c * kSpacing.y, 0.0),
                           glm::dvec3(0.25, 0.0, kSpacing.z));
        m = glm::dmat4(l);
        m[3] = glm::dvec4(-(l * glm::dvec3(31.5)), 1.0);
    }
    v->setIndexToWorld(m);
    for (int k = 0; k < 64; ++k) {
        for (int j = 0; j < 64; ++j) {
            for (int i = 0; i < 64; ++i) {
                const glm::dvec3 p = v->worldPosition({i, j, k});
                double value = 0.0;
                for (const Ball& b : balls) {
                    const double r = glm::length(p - b.centre);
                    value =
                        std::max(value, 1000.0 * std::clamp(0.5 - (r - b.radius) / 2.0, 0.0, 1.0));
                }
                v->setValueAt(v->index(i, j, k), static_cast<float>(value));
            }
        }
    }
    return v;
}

/// The camera OffscreenRenderer uses for `options` without a camera.
Camera fittedCamera(const vv::scene::Volume& volume, int width, int height) {
    Camera camera;
    camera.setViewport(width, height);
    camera.fit(volume.worldBounds());
    return camera;
}

/// The world ray through the centre of pixel (x, y), row 0 at the top.
std::pair<glm::dvec3, glm::dvec3> pixelRay(const Camera& camera, int x, int y, int w, int h) {
    const glm::dmat4 inverse =
        glm::inverse(glm::dmat4(camera.projectionMatrix()) * glm::dmat4(camera.viewMatrix()));
    const double nx = (x + 0.5) / w * 2.0 - 1.0;
    const double ny = 1.0 - (y + 0.5) / h * 2.0;
    glm::dvec4 a = inverse * glm::dvec4(nx, ny, -1.0, 1.0);
    glm::dvec4 b = inverse * glm::dvec4(nx, ny, 1.0, 1.0);
    const glm::dvec3 origin = glm::dvec3(a) / a.w;
    return {origin, glm::normalize(glm::dvec3(b) / b.w - origin)};
}

/// Linear (view-axis) depth of the first hit of the pixel's ray with `ball`,
/// and how far inside the disk the ray passes (<0: it misses by that much).
std::pair<std::optional<double>, double> analyticDepth(const Camera& camera, const Ball& ball,
                                                       int x, int y, int w, int h) {
    const auto [o, d] = pixelRay(camera, x, y, w, h);
    const glm::dvec3 oc = o - ball.centre;
    const double b = glm::dot(oc, d);
    const double closest = std::sqrt(std::max(0.0, glm::dot(oc, oc) - b * b));
    const double margin = ball.radius - closest;
    if (margin < 0.0) {
        return {std::nullopt, margin};
    }
    const double t = -b - std::sqrt(ball.radius * ball.radius - closest * closest);
    const glm::dvec3 hit = o + t * d;
    const glm::dvec4 view = glm::dmat4(camera.viewMatrix()) * glm::dvec4(hit, 1.0);
    return {-view.z, margin};
}

class VolumeRaycastTest : public vv::render::test::GlRenderTest {
  protected:
    static constexpr int kW = 160;
    static constexpr int kH = 120;

    [[nodiscard]] OffscreenOptions options(std::shared_ptr<const vv::scene::Volume> volume) const {
        OffscreenOptions o = vv::render::test::exactOptions(kW, kH);
        o.volume = std::move(volume);
        o.isoValue = static_cast<float>(kIso);
        return o;
    }
};

class VolumeRaycastGridTest : public VolumeRaycastTest,
                              public ::testing::WithParamInterface<bool> {};

TEST_P(VolumeRaycastGridTest, BallDepthMatchesTheAnalyticSphere) {
    auto renderer = makeRenderer();
    ASSERT_TRUE(renderer);
    const Ball ball{{1.0, -2.0, 3.0}, 12.0};
    const bool sheared = GetParam();
    const auto volume = ballVolume({ball}, sheared);
    const QImage image = renderer->render(vv::scene::Scene{}, options(volume));
    vv::render::test::saveImage(image, "raycast-", sheared ? "ball-sheared" : "ball");
    const auto depth = renderer->lastLinearDepth();
    ASSERT_EQ(depth.width(), kW);
    ASSERT_EQ(depth.height(), kH);
    const Camera camera = fittedCamera(*volume, kW, kH);
    const double voxel = std::max({kSpacing.x, kSpacing.y, kSpacing.z});
    int inside = 0;
    int outside = 0;
    double worst = 0.0;
    for (int y = 0; y < kH; ++y) {
        for (int x = 0; x < kW; ++x) {
            const auto [expected, margin] = analyticDepth(camera, ball, x, y, kW, kH);
            const float got = depth.row(y)[x];
            if (expected && margin > 0.15 * ball.radius) {
                ++inside;
                ASSERT_TRUE(std::isfinite(got)) << x << "," << y;
                worst = std::max(worst, std::abs(static_cast<double>(got) - *expected));
            } else if (margin < -voxel) {
                ++outside;
                ASSERT_TRUE(std::isinf(got) && got > 0.0F) << x << "," << y << ": " << got;
            }
        }
    }
    EXPECT_GT(inside, 500);
    EXPECT_GT(outside, 1000);
    EXPECT_LT(worst, 0.5 * voxel) << "largest depth error over the disk (mm)";
    RecordProperty("worst_depth_error_mm", std::to_string(worst));
    std::printf("worst depth error %.4f mm over %d pixels\n", worst, inside);
    // The VSS of a volume without meshes is solved like a mesh's.
    EXPECT_TRUE(renderer->vssStatus().shown);
}

// Anisotropic axis-aligned voxels; rotated, anisotropic and sheared voxels.
INSTANTIATE_TEST_SUITE_P(Grids, VolumeRaycastGridTest, ::testing::Values(false, true),
                         [](const ::testing::TestParamInfo<bool>& param) {
                             return param.param ? std::string("Sheared")
                                                : std::string("Anisotropic");
                         });

TEST_F(VolumeRaycastTest, VssSpansTheVoidBetweenTwoBalls) {
    auto renderer = makeRenderer();
    ASSERT_TRUE(renderer);
    // Seen down -z: the left ball near (z = +10), the right one far (z = -10).
    const Ball nearBall{{-9.0, 0.0, 10.0}, 7.0};
    const Ball farBall{{9.0, 0.0, -10.0}, 7.0};
    const auto volume = ballVolume({nearBall, farBall});
    auto o = options(volume);
    o.display.vss.enabled = false;
    const QImage off = renderer->render(vv::scene::Scene{}, o);
    o.display.vss.enabled = true;
    const QImage on = renderer->render(vv::scene::Scene{}, o);
    vv::render::test::saveImage(off, "raycast-", "two-balls-off");
    vv::render::test::saveImage(on, "raycast-", "two-balls-vss");
    const Camera camera = fittedCamera(*volume, kW, kH);
    // The pixel of the world point midway between the balls.
    const glm::dvec4 clip = glm::dmat4(camera.projectionMatrix()) *
                            glm::dmat4(camera.viewMatrix()) * glm::dvec4(0.0, 0.0, 0.0, 1.0);
    const int mx = static_cast<int>((clip.x / clip.w * 0.5 + 0.5) * kW);
    const int my = static_cast<int>((0.5 - clip.y / clip.w * 0.5) * kH);
    EXPECT_EQ(off.pixel(mx, my), backgroundRgb_) << "no VSS: the void shows the background";
    EXPECT_NE(on.pixel(mx, my), backgroundRgb_) << "the VSS fills the void between the balls";
    const auto& status = renderer->vssStatus();
    ASSERT_TRUE(status.shown);
    // dmin is the near ball's front, dmax lies between the far ball's front
    // and centre (its silhouette).
    const glm::dvec4 nearC = glm::dmat4(camera.viewMatrix()) * glm::dvec4(nearBall.centre, 1.0);
    const glm::dvec4 farC = glm::dmat4(camera.viewMatrix()) * glm::dvec4(farBall.centre, 1.0);
    EXPECT_NEAR(status.dmin, -nearC.z - nearBall.radius, 1.5);
    EXPECT_GT(status.dmax, -farC.z - farBall.radius);
    EXPECT_LT(status.dmax, -farC.z + 1.5);
    // Between the balls the G-buffer is void: the colour there is the VSS's.
    const auto depth = renderer->lastLinearDepth();
    EXPECT_TRUE(std::isinf(depth.row(my)[mx]));
}

TEST_F(VolumeRaycastTest, MeshesAndTheVolumeDepthTestTogether) {
    auto renderer = makeRenderer();
    ASSERT_TRUE(renderer);
    const Ball ball{{0.0, 0.0, 0.0}, 10.0};
    const auto volume = ballVolume({ball});
    const Camera camera = fittedCamera(*volume, kW, kH);
    const glm::dmat4 view(camera.viewMatrix());
    const double ballFront = -(view * glm::dvec4(0.0, 0.0, 0.0, 1.0)).z - ball.radius;
    const int cx = kW / 2;
    const int cy = kH / 2;
    for (const double tubeZ : {15.0, -20.0}) {
        // A tube along x through the view axis, in front of or behind the ball.
        vv::scene::Scene scene;
        scene.meshes.push_back(vv::render::test::makeTube(2.0F, -20.0F, 40.0F, 0.0F,
                                                          static_cast<float>(tubeZ), 32, 16));
        auto o = options(volume);
        o.camera = camera;  // the ball's view, whatever the tube adds to the bounds
        const QImage image = renderer->render(scene, o);
        vv::render::test::saveImage(image, "raycast-", tubeZ > 0 ? "tube-front" : "tube-behind");
        const auto depth = renderer->lastLinearDepth();
        ASSERT_EQ(depth.width(), kW);
        const float got = depth.row(cy)[cx];
        const double tubeFront = -(view * glm::dvec4(0.0, 0.0, tubeZ, 1.0)).z - 2.0;
        const double expected = tubeZ > 0 ? tubeFront : ballFront;
        EXPECT_NEAR(got, expected, 1.0) << "tube at z = " << tubeZ;
    }
}

TEST_F(VolumeRaycastTest, TheGeometryPassIsCachedUntilVolumeOrIsoChange) {
    auto renderer = makeRenderer();
    ASSERT_TRUE(renderer);
    const auto volume = ballVolume({Ball{{0.0, 0.0, 0.0}, 10.0}});
    auto o = options(volume);
    const Camera camera = fittedCamera(*volume, kW, kH);
    o.camera = camera;
    static_cast<void>(renderer->render(vv::scene::Scene{}, o));
    EXPECT_EQ(state(*renderer, "geometry"), vv::render::PassState::Executed);
    static_cast<void>(renderer->render(vv::scene::Scene{}, o));
    EXPECT_EQ(state(*renderer, "geometry"), vv::render::PassState::Cached);
    const float before = renderer->lastLinearDepth().row(kH / 2)[kW / 2];
    // A higher iso value shrinks the ball (1000 * (0.5 - (r - 10) / 2) = 900 at r = 9.2).
    o.isoValue = 900.0F;
    static_cast<void>(renderer->render(vv::scene::Scene{}, o));
    EXPECT_EQ(state(*renderer, "geometry"), vv::render::PassState::Executed);
    const float after = renderer->lastLinearDepth().row(kH / 2)[kW / 2];
    EXPECT_NEAR(after - before, 0.8F, 0.2F);
    // Another volume object re-runs it too.
    o.volume = ballVolume({Ball{{0.0, 0.0, 0.0}, 10.0}});
    static_cast<void>(renderer->render(vv::scene::Scene{}, o));
    EXPECT_EQ(state(*renderer, "geometry"), vv::render::PassState::Executed);
}

TEST_F(VolumeRaycastTest, RefusesVolumesBeyondTheThreeDTextureLimit) {
    auto renderer = makeRenderer();
    ASSERT_TRUE(renderer);
    auto o = options(
        std::make_shared<vv::scene::Volume>(glm::ivec3(70000, 1, 1), vv::scene::VoxelType::Int16));
    try {
        static_cast<void>(renderer->render(vv::scene::Scene{}, o));
        FAIL() << "expected a RenderError";
    } catch (const vv::RenderError& e) {
        EXPECT_NE(std::string(e.what()).find("3-D texture limit"), std::string::npos) << e.what();
    }
    // The renderer still works afterwards with a volume that fits.
    o.volume = ballVolume({Ball{{0.0, 0.0, 0.0}, 8.0}});
    const QImage image = renderer->render(vv::scene::Scene{}, o);
    EXPECT_NE(image.pixel(kW / 2, kH / 2), backgroundRgb_);
}

}  // namespace
