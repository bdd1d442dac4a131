// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <optional>

#include "vv/core/Math.h"
#include "vv/render/TileProjection.h"

namespace vv::render {

/// An orbit ("trackball") camera around a target point: pure math, no GL.
///
/// The camera sits at `distance` from `target`, oriented by `rotation` (the
/// camera-to-world rotation; identity looks down -z with +y up). Mouse
/// gestures map to rotate() (arcball), pan() and zoom(). Near and far planes
/// follow from the scene bounds given to fit() / setSceneBounds(), so the
/// whole scene is never clipped by the far plane and the near plane stays as
/// far out as the scene allows (depth precision).
///
/// Pixel coordinates have their origin at the top-left of the viewport, +y down.
class Camera {
  public:
    Camera() = default;

    /// Viewport size in pixels; values below 1 are taken as 1.
    void setViewport(int width, int height) noexcept;
    [[nodiscard]] int viewportWidth() const noexcept { return width_; }
    [[nodiscard]] int viewportHeight() const noexcept { return height_; }
    [[nodiscard]] float aspect() const noexcept;

    /// Vertical field of view in degrees. Throws InvalidArgumentError outside (1, 170).
    void setFieldOfView(float degrees);
    [[nodiscard]] float fieldOfView() const noexcept { return fovDegrees_; }

    /// Bounds of everything that is drawn; they decide the near and far planes
    /// and the zoom limits. An empty box means a unit sphere at the origin.
    void setSceneBounds(const Aabb& bounds) noexcept;
    [[nodiscard]] const Aabb& sceneBounds() const noexcept { return scene_; }

    /// Keeps the orientation and moves target (to the box centre) and
    /// distance so that the whole box (every corner) is inside the view
    /// frustum at the current aspect and field of view, tightly with a small
    /// margin. Also makes `box` the scene bounds. An empty box fits a unit
    /// sphere at the origin.
    void fit(const Aabb& box) noexcept;

    /// Back to the home view: the home orientation (setHomeRotation()),
    /// fitted to the scene bounds (the unit sphere at the origin when there
    /// are none).
    void reset() noexcept;
    /// The orientation reset() returns to (camera-to-world, normalised; a
    /// zero quaternion is ignored): the identity unless set, e.g.
    /// homeRotation() of the scene's frame (ViewPresets.h).
    void setHomeRotation(const glm::quat& rotation) noexcept;
    [[nodiscard]] const glm::quat& homeRotation() const noexcept { return home_; }

    /// Arcball rotation for a mouse drag from pixel `from` to pixel `to`: the
    /// scene turns with the mouse about the target. Keeps target and distance.
    void rotate(const glm::vec2& from, const glm::vec2& to) noexcept;

    /// Turns the scene by `angleRadians` about `axis` given in view space
    /// (x right, y up, z towards the viewer). Keeps target and distance.
    void rotateView(float angleRadians, const glm::vec3& axis) noexcept;

    /// Moves the target in the view plane so that the scene point under the
    /// target follows a mouse move of `deltaPixels`.
    void pan(const glm::vec2& deltaPixels) noexcept;

    /// Dolly: divides the distance by `factor` (> 1 moves closer, < 1 away),
    /// within [1e-3, 1e3] scene radii. Non-positive or non-finite factors are ignored.
    void zoom(float factor) noexcept;

    [[nodiscard]] const glm::vec3& target() const noexcept { return target_; }
    [[nodiscard]] float distance() const noexcept { return distance_; }
    [[nodiscard]] const glm::quat& rotation() const noexcept { return rotation_; }
    void setTarget(const glm::vec3& target) noexcept { target_ = target; }
    /// Clamped like zoom().
    void setDistance(float distance) noexcept;
    /// Normalised; a zero quaternion is ignored.
    void setRotation(const glm::quat& rotation) noexcept;

    /// Camera position in world space.
    [[nodiscard]] glm::vec3 eye() const noexcept;
    /// World-space unit vectors of the view's right, up and forward (viewing) directions.
    [[nodiscard]] glm::vec3 right() const noexcept;
    [[nodiscard]] glm::vec3 up() const noexcept;
    [[nodiscard]] glm::vec3 forward() const noexcept;

    [[nodiscard]] glm::mat4 viewMatrix() const noexcept;
    /// OpenGL-style perspective projection (clip z in [-w, w]).
    [[nodiscard]] glm::mat4 projectionMatrix() const noexcept;
    /// Tiled rendering: restricts projectionMatrix() to the rectangle `window`
    /// of the viewport (an off-axis sub-frustum, tileProjection()), so that a
    /// frame of window.width x window.height pixels shows exactly those pixels
    /// of the full view. Nothing else (fit, gestures, near / far) changes.
    /// Throws InvalidArgumentError for a width or height below 1.
    void setWindow(const PixelRect& window);
    void clearWindow() noexcept { window_.reset(); }
    /// The window set by setWindow(); nullopt = the whole viewport.
    [[nodiscard]] const std::optional<PixelRect>& window() const noexcept { return window_; }
    /// Near and far plane distances from the eye, derived from the scene bounds.
    [[nodiscard]] float nearPlane() const noexcept;
    [[nodiscard]] float farPlane() const noexcept;

  private:
    [[nodiscard]] glm::vec3 sceneCenter() const noexcept;
    [[nodiscard]] float sceneRadius() const noexcept;
    [[nodiscard]] glm::vec3 arcballVector(const glm::vec2& pixel) const noexcept;
    [[nodiscard]] float clampDistance(float distance) const noexcept;
    [[nodiscard]] float fittingDistance(const Aabb& box) const noexcept;

    int width_ = 1;
    int height_ = 1;
    float fovDegrees_ = 30.0F;
    Aabb scene_;
    glm::vec3 target_{0.0F};
    float distance_ = 4.0F;
    glm::quat rotation_{1.0F, 0.0F, 0.0F, 0.0F};
    glm::quat home_{1.0F, 0.0F, 0.0F, 0.0F};
    std::optional<PixelRect> window_;  ///< tiled rendering: the part of the viewport drawn
};

}  // namespace vv::render
