// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "vv/core/Error.h"
#include "vv/render/Camera.h"

namespace {

using vv::Aabb;
using vv::render::Camera;

Aabb box(glm::vec3 min, glm::vec3 max) {
    Aabb b;
    b.extend(min);
    b.extend(max);
    return b;
}

std::array<glm::vec3, 8> corners(const Aabb& b) {
    std::array<glm::vec3, 8> c{};
    for (int i = 0; i < 8; ++i) {
        c[static_cast<std::size_t>(i)] = {(i & 1) != 0 ? b.max.x : b.min.x,
                                          (i & 2) != 0 ? b.max.y : b.min.y,
                                          (i & 4) != 0 ? b.max.z : b.min.z};
    }
    return c;
}

glm::vec3 toNdc(const Camera& camera, const glm::vec3& p) {
    const glm::vec4 clip = camera.projectionMatrix() * camera.viewMatrix() * glm::vec4(p, 1.0F);
    return glm::vec3(clip) / clip.w;
}

void expectAllCornersInside(const Camera& camera, const Aabb& b) {
    for (const auto& c : corners(b)) {
        const glm::vec3 ndc = toNdc(camera, c);
        EXPECT_GT(ndc.x, -1.0F);
        EXPECT_LT(ndc.x, 1.0F);
        EXPECT_GT(ndc.y, -1.0F);
        EXPECT_LT(ndc.y, 1.0F);
        EXPECT_GT(ndc.z, -1.0F);
        EXPECT_LT(ndc.z, 1.0F);
    }
}

TEST(CameraTest, FitPutsEveryBoxCornerInsideTheNdcCube) {
    const std::array boxes{box({-1, -1, -1}, {1, 1, 1}), box({10, 20, 30}, {110, 25, 31}),
                           box({-0.001F, 0, 0}, {0.001F, 0.002F, 0.0005F}),
                           box({-500, -20, -3}, {-400, 400, 3})};
    const std::array<std::array<int, 2>, 3> viewports{{{800, 600}, {300, 900}, {1, 1}}};
    for (const auto& b : boxes) {
        for (const auto& vp : viewports) {
            Camera camera;
            camera.setViewport(vp[0], vp[1]);
            camera.rotateView(0.7F, {0.3F, 1.0F, 0.2F});
            camera.fit(b);
            expectAllCornersInside(camera, b);
            // The box fills a good part of the view: not fitted absurdly far away.
            float maxExtent = 0.0F;
            for (const auto& c : corners(b)) {
                const glm::vec3 ndc = toNdc(camera, c);
                maxExtent = std::max({maxExtent, std::abs(ndc.x), std::abs(ndc.y)});
            }
            EXPECT_GT(maxExtent, 0.3F);
        }
    }
}

TEST(CameraTest, FitTargetsTheBoxCentre) {
    Camera camera;
    camera.setViewport(640, 480);
    const Aabb b = box({2, 4, 6}, {4, 8, 12});
    camera.fit(b);
    EXPECT_FLOAT_EQ(camera.target().x, 3.0F);
    EXPECT_FLOAT_EQ(camera.target().y, 6.0F);
    EXPECT_FLOAT_EQ(camera.target().z, 9.0F);
    const glm::vec3 ndc = toNdc(camera, b.center());
    EXPECT_NEAR(ndc.x, 0.0F, 1e-5F);
    EXPECT_NEAR(ndc.y, 0.0F, 1e-5F);
}

TEST(CameraTest, EmptyBoxFitsTheUnitSphere) {
    Camera camera;
    camera.setViewport(100, 100);
    camera.fit(Aabb{});
    expectAllCornersInside(camera, box({-0.5F, -0.5F, -0.5F}, {0.5F, 0.5F, 0.5F}));
    EXPECT_GT(camera.distance(), 1.0F);
    EXPECT_TRUE(std::isfinite(camera.nearPlane()));
    EXPECT_GT(camera.nearPlane(), 0.0F);
}

TEST(CameraTest, RotationPreservesDistanceAndTarget) {
    Camera camera;
    camera.setViewport(800, 600);
    camera.fit(box({0, 0, 0}, {10, 20, 30}));
    const float distance = camera.distance();
    const glm::vec3 target = camera.target();
    const glm::vec3 eyeBefore = camera.eye();
    camera.rotate({400, 300}, {550, 200});
    camera.rotate({10, 10}, {790, 590});  // outside the ball: hyperbolic sheet
    EXPECT_FLOAT_EQ(camera.distance(), distance);
    EXPECT_NEAR(glm::length(camera.eye() - camera.target()), distance, 1e-3F * distance);
    EXPECT_EQ(camera.target(), target);
    EXPECT_GT(glm::length(camera.eye() - eyeBefore), 0.1F * distance);  // it did turn
}

TEST(CameraTest, HorizontalDragTurnsAboutTheViewUpAxis) {
    Camera camera;
    camera.setViewport(800, 800);
    camera.fit(box({-1, -1, -1}, {1, 1, 1}));
    const glm::vec3 upBefore = camera.up();
    camera.rotate({400, 400}, {500, 400});
    // Up stays up; dragging right turns the scene right, so the eye moves left (-x).
    EXPECT_NEAR(glm::dot(camera.up(), upBefore), 1.0F, 1e-5F);
    EXPECT_LT(camera.eye().x, -0.1F);
}

TEST(CameraTest, DragBackRestoresOrientation) {
    Camera camera;
    camera.setViewport(800, 600);
    camera.fit(box({0, 0, 0}, {1, 1, 1}));
    const glm::quat before = camera.rotation();
    camera.rotate({400, 300}, {450, 320});
    camera.rotate({450, 320}, {400, 300});
    EXPECT_NEAR(std::abs(glm::dot(camera.rotation(), before)), 1.0F, 1e-5F);
}

TEST(CameraTest, ZoomIsMonotonic) {
    Camera camera;
    camera.setViewport(800, 600);
    camera.fit(box({-5, -5, -5}, {5, 5, 5}));
    float previous = camera.distance();
    for (int i = 0; i < 20; ++i) {
        camera.zoom(1.1F);
        EXPECT_LT(camera.distance(), previous);
        previous = camera.distance();
    }
    for (int i = 0; i < 40; ++i) {
        camera.zoom(1.0F / 1.1F);
        EXPECT_GT(camera.distance(), previous);
        previous = camera.distance();
    }
    // Nonsense factors change nothing.
    camera.zoom(0.0F);
    camera.zoom(-2.0F);
    camera.zoom(std::nanf(""));
    EXPECT_EQ(camera.distance(), previous);
}

TEST(CameraTest, ZoomIsClampedToTheSceneScale) {
    Camera camera;
    camera.setViewport(800, 600);
    camera.fit(box({-1, -1, -1}, {1, 1, 1}));
    for (int i = 0; i < 1000; ++i) {
        camera.zoom(2.0F);
    }
    EXPECT_GT(camera.distance(), 0.0F);
    EXPECT_GT(camera.nearPlane(), 0.0F);
    EXPECT_LT(camera.nearPlane(), camera.farPlane());
    for (int i = 0; i < 1000; ++i) {
        camera.zoom(0.5F);
    }
    EXPECT_TRUE(std::isfinite(camera.distance()));
    EXPECT_LT(camera.distance(), 1e4F);
}

TEST(CameraTest, PanMovesTargetInTheViewPlane) {
    Camera camera;
    camera.setViewport(800, 600);
    camera.fit(box({-1, -1, -1}, {1, 1, 1}));
    camera.rotateView(0.5F, {1, 1, 0});
    const glm::vec3 before = camera.target();
    const float distance = camera.distance();
    camera.pan({100, 0});
    const glm::vec3 moved = camera.target() - before;
    EXPECT_GT(glm::length(moved), 0.0F);
    EXPECT_NEAR(glm::dot(moved, camera.forward()), 0.0F, 1e-5F);
    EXPECT_LT(glm::dot(moved, camera.right()), 0.0F);  // scene follows the mouse to the right
    EXPECT_FLOAT_EQ(camera.distance(), distance);

    // The point that was at the centre follows the mouse: 100 px right of centre.
    const glm::vec3 ndc = toNdc(camera, before);
    EXPECT_NEAR(ndc.x * 400.0F, 100.0F, 0.5F);
    EXPECT_NEAR(ndc.y, 0.0F, 1e-4F);

    camera.pan({0, 50});  // mouse down: scene moves down
    const glm::vec3 ndc2 = toNdc(camera, before);
    EXPECT_NEAR(ndc2.y * 300.0F, -50.0F, 0.5F);
}

TEST(CameraTest, ResetRestoresTheHomeView) {
    Camera camera;
    camera.setViewport(800, 600);
    const Aabb b = box({0, 0, 0}, {4, 2, 8});
    camera.fit(b);
    const glm::vec3 target = camera.target();
    const float distance = camera.distance();
    const glm::mat4 view = camera.viewMatrix();

    camera.rotate({400, 300}, {600, 100});
    camera.pan({30, -40});
    camera.zoom(3.0F);
    camera.reset();

    EXPECT_EQ(camera.target(), target);
    EXPECT_FLOAT_EQ(camera.distance(), distance);
    const glm::mat4 after = camera.viewMatrix();
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            EXPECT_NEAR(after[c][r], view[c][r], 1e-5F);
        }
    }
    expectAllCornersInside(camera, b);
}

TEST(CameraTest, NearAndFarEncloseTheScene) {
    Camera camera;
    camera.setViewport(800, 600);
    const Aabb b = box({-3, -3, -3}, {3, 3, 3});
    camera.fit(b);
    camera.rotate({100, 100}, {700, 500});
    for (const auto& c : corners(b)) {
        const float depth = -(camera.viewMatrix() * glm::vec4(c, 1.0F)).z;
        EXPECT_GT(depth, camera.nearPlane());
        EXPECT_LT(depth, camera.farPlane());
    }
}

TEST(CameraTest, FieldOfViewIsValidated) {
    Camera camera;
    EXPECT_THROW(camera.setFieldOfView(0.0F), vv::InvalidArgumentError);
    EXPECT_THROW(camera.setFieldOfView(180.0F), vv::InvalidArgumentError);
    EXPECT_THROW(camera.setFieldOfView(std::nanf("")), vv::InvalidArgumentError);
    camera.setFieldOfView(60.0F);
    EXPECT_FLOAT_EQ(camera.fieldOfView(), 60.0F);
}

}  // namespace
