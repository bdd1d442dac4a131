// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/render/Camera.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <string>

#include "vv/core/Error.h"

namespace vv::render {

namespace {

/// Extra room around a fitted box, as a factor on its projected size.
constexpr float kFitMargin = 1.06F;
/// Near/far planes keep this much clearance around the scene sphere.
constexpr float kDepthMargin = 1.02F;
/// The near plane never comes closer than far / kMaxDepthRatio.
constexpr float kMaxDepthRatio = 2000.0F;

/// Distance at which a sphere of `radius` fills the narrower of the two
/// half-angles of the frustum (the sphere, and so the box it holds, is then
/// inside all four side planes).
float fitDistance(float radius, float fovyRadians, float aspect) {
    const float halfY = 0.5F * fovyRadians;
    const float halfX = std::atan(std::tan(halfY) * aspect);
    const float half = std::min(halfX, halfY);
    return radius / std::sin(half);
}

}  // namespace

void Camera::setViewport(int width, int height) noexcept {
    width_ = std::max(1, width);
    height_ = std::max(1, height);
}

float Camera::aspect() const noexcept {
    return static_cast<float>(width_) / static_cast<float>(height_);
}

void Camera::setFieldOfView(float degrees) {
    if (!(degrees > 1.0F && degrees < 170.0F)) {
        throw InvalidArgumentError("field of view must be in (1, 170) degrees, got " +
                                   std::to_string(degrees));
    }
    fovDegrees_ = degrees;
}

void Camera::setSceneBounds(const Aabb& bounds) noexcept {
    scene_ = bounds;
}

glm::vec3 Camera::sceneCenter() const noexcept {
    return scene_.empty() ? glm::vec3(0.0F) : scene_.center();
}

float Camera::sceneRadius() const noexcept {
    const float r = scene_.empty() ? 1.0F : scene_.radius();
    // A single point (or a degenerate box) still needs a non-zero scale.
    return r > 0.0F && std::isfinite(r) ? r : 1.0F;
}

float Camera::clampDistance(float distance) const noexcept {
    const float r = sceneRadius();
    return std::clamp(distance, 1e-3F * r, 1e3F * r);
}

void Camera::fit(const Aabb& box) noexcept {
    scene_ = box;
    target_ = sceneCenter();
    distance_ = fittingDistance(box);
}

float Camera::fittingDistance(const Aabb& box) const noexcept {
    const float tanY = std::tan(0.5F * glm::radians(fovDegrees_));
    const float tanX = tanY * aspect();
    if (box.empty()) {
        return kFitMargin * fitDistance(1.0F, glm::radians(fovDegrees_), aspect());
    }
    // Every corner c (relative to the centre, in view axes x right, y up, z
    // towards the viewer) lies at depth d - z; it is inside the side planes
    // when |x| <= (d - z) tan(halfX) and |y| <= (d - z) tan(halfY). The
    // smallest d that satisfies all corners frames the box tightly in the
    // current orientation; the margin shrinks the usable tangents.
    const glm::vec3 c = box.center();
    const glm::vec3 axisX = right();
    const glm::vec3 axisY = up();
    const glm::vec3 axisZ = -forward();
    float d = 0.0F;
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 corner{(i & 1) != 0 ? box.max.x : box.min.x,
                               (i & 2) != 0 ? box.max.y : box.min.y,
                               (i & 4) != 0 ? box.max.z : box.min.z};
        const glm::vec3 p = corner - c;
        const float x = std::abs(glm::dot(p, axisX));
        const float y = std::abs(glm::dot(p, axisY));
        const float z = glm::dot(p, axisZ);
        d = std::max({d, z + kFitMargin * x / tanX, z + kFitMargin * y / tanY});
    }
    // A flat or point-like box still gets a sensible, non-zero distance.
    const float r = box.radius();
    d = std::max(d, r > 0.0F ? 1.01F * r : 1.0F);
    return d;
}

void Camera::reset() noexcept {
    rotation_ = home_;
    fit(scene_);
}

void Camera::setHomeRotation(const glm::quat& rotation) noexcept {
    if (glm::length(rotation) > 0.0F) {
        home_ = glm::normalize(rotation);
    }
}

glm::vec3 Camera::arcballVector(const glm::vec2& pixel) const noexcept {
    // Pixel -> [-1, 1] over the shorter side, +y up.
    const float scale = 2.0F / static_cast<float>(std::min(width_, height_));
    const glm::vec2 p{(pixel.x - 0.5F * static_cast<float>(width_)) * scale,
                      (0.5F * static_cast<float>(height_) - pixel.y) * scale};
    const float r2 = glm::dot(p, p);
    // Sphere in the middle, hyperbolic sheet outside (Holroyd): continuous,
    // so drags that leave the ball do not jump.
    const float z = r2 <= 0.5F ? std::sqrt(1.0F - r2) : 0.5F / std::sqrt(r2);
    return glm::normalize(glm::vec3(p, z));
}

void Camera::rotate(const glm::vec2& from, const glm::vec2& to) noexcept {
    const glm::vec3 a = arcballVector(from);
    const glm::vec3 b = arcballVector(to);
    const glm::vec3 axis = glm::cross(a, b);
    const float axisLength = glm::length(axis);
    if (!(axisLength > 1e-7F)) {
        return;
    }
    const float angle = std::atan2(axisLength, glm::dot(a, b));
    rotateView(angle, axis / axisLength);
}

void Camera::rotateView(float angleRadians, const glm::vec3& axis) noexcept {
    const float len = glm::length(axis);
    if (!(len > 0.0F) || !std::isfinite(angleRadians)) {
        return;
    }
    // The scene turns by q in view space, so the camera turns by q^-1.
    const glm::quat q = glm::angleAxis(angleRadians, axis / len);
    rotation_ = glm::normalize(rotation_ * glm::inverse(q));
}

void Camera::pan(const glm::vec2& deltaPixels) noexcept {
    const float worldPerPixel =
        2.0F * distance_ * std::tan(0.5F * glm::radians(fovDegrees_)) / static_cast<float>(height_);
    target_ += (-deltaPixels.x * right() + deltaPixels.y * up()) * worldPerPixel;
}

void Camera::zoom(float factor) noexcept {
    if (!(factor > 0.0F) || !std::isfinite(factor)) {
        return;
    }
    distance_ = clampDistance(distance_ / factor);
}

void Camera::setDistance(float distance) noexcept {
    if (distance > 0.0F && std::isfinite(distance)) {
        distance_ = clampDistance(distance);
    }
}

void Camera::setRotation(const glm::quat& rotation) noexcept {
    if (glm::length(rotation) > 0.0F) {
        rotation_ = glm::normalize(rotation);
    }
}

glm::vec3 Camera::right() const noexcept {
    return rotation_ * glm::vec3(1.0F, 0.0F, 0.0F);
}
glm::vec3 Camera::up() const noexcept {
    return rotation_ * glm::vec3(0.0F, 1.0F, 0.0F);
}
glm::vec3 Camera::forward() const noexcept {
    return rotation_ * glm::vec3(0.0F, 0.0F, -1.0F);
}

glm::vec3 Camera::eye() const noexcept {
    return target_ - distance_ * forward();
}

glm::mat4 Camera::viewMatrix() const noexcept {
    // Inverse of the camera's world transform (translate(eye) * rotation).
    const glm::mat4 inverseRotation = glm::mat4_cast(glm::conjugate(rotation_));
    return glm::translate(inverseRotation, -eye());
}

float Camera::farPlane() const noexcept {
    const float d = glm::length(eye() - sceneCenter());
    return (d + sceneRadius()) * kDepthMargin;
}

float Camera::nearPlane() const noexcept {
    const float d = glm::length(eye() - sceneCenter());
    const float farDistance = farPlane();
    return std::max(d - kDepthMargin * sceneRadius(), farDistance / kMaxDepthRatio);
}

glm::mat4 Camera::projectionMatrix() const noexcept {
    const glm::mat4 full =
        glm::perspective(glm::radians(fovDegrees_), aspect(), nearPlane(), farPlane());
    // setWindow() checked the window's size, so tileProjection() cannot throw.
    return window_ ? tileProjection(full, width_, height_, *window_) : full;
}

void Camera::setWindow(const PixelRect& window) {
    if (window.width < 1 || window.height < 1) {
        throw InvalidArgumentError("a camera window needs at least 1x1 pixels, got " +
                                   std::to_string(window.width) + "x" +
                                   std::to_string(window.height));
    }
    window_ = window;
}

}  // namespace vv::render
