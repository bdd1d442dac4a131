// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <glm/gtc/quaternion.hpp>
#include <optional>
#include <span>
#include <string_view>

#include "vv/core/Math.h"
#include "vv/io/Mesh.h"
#include "vv/render/Camera.h"

namespace vv::render {

/// The benchmark views of the VSS paper (Kreiser et al. 2018), see VSS.md,
/// "Error against run time". More (anatomical views) may follow; code that
/// switches over them should keep a default.
enum class ViewPreset {
    Far,     ///< the whole tree inside the image with a 10 % margin on every side
    Medium,  ///< closer: the tree crosses the image border in a few places
    Close,   ///< much closer: the tree crosses the border in many places
};

/// Every preset, in the order Far, Medium, Close.
[[nodiscard]] std::span<const ViewPreset> allViewPresets() noexcept;

/// "far", "medium", "close".
[[nodiscard]] std::string_view toString(ViewPreset preset) noexcept;

/// The preset named `name` (ASCII case-insensitive: "far", "Medium", ...); nullopt if unknown.
[[nodiscard]] std::optional<ViewPreset> viewPresetFromName(std::string_view name) noexcept;

/// As viewPresetFromName; throws InvalidArgumentError (listing the known names)
/// for an unknown name.
[[nodiscard]] ViewPreset parseViewPreset(std::string_view name);

/// Fraction of the image width / height left free on each side in the Far view.
inline constexpr float kFarViewMargin = 0.10F;

/// The camera distance of a preset as a fraction of the Far distance
/// (Far 1, Medium and Close smaller). The camera always looks at the centre of
/// the bounds, so a closer camera crops the tree around that centre.
[[nodiscard]] float presetDistanceFactor(ViewPreset preset) noexcept;

/// A camera for `preset`: viewport width × height (values below 1 become 1),
/// the default field of view, orientation `rotation` (camera-to-world; the
/// identity looks down -z with +y up), target at the centre of `bounds`, and
/// scene bounds `bounds` (so near and far planes hold the whole box).
/// The Far distance is the smallest one at which every corner of the box lies
/// inside the central (1 - 2 kFarViewMargin) part of the image in both
/// directions; the other presets scale it by presetDistanceFactor().
/// An empty box is taken as the unit sphere at the origin, as Camera::fit does.
[[nodiscard]] Camera presetCamera(const Aabb& bounds, int width, int height, ViewPreset preset,
                                  const glm::quat& rotation = glm::quat(1.0F, 0.0F, 0.0F, 0.0F));

/// As above, but the Far distance fits the scene's vertices rather than the
/// corners of its bounding box (tighter: the tree then just keeps the 10 %
/// margin). The target is still the centre of scene.bounds(). A scene without
/// vertices behaves as an empty box.
[[nodiscard]] Camera presetCamera(const io::Scene& scene, int width, int height, ViewPreset preset,
                                  const glm::quat& rotation = glm::quat(1.0F, 0.0F, 0.0F, 0.0F));

}  // namespace vv::render
