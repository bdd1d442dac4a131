// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <glm/gtc/quaternion.hpp>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "vv/core/Math.h"
#include "vv/render/Camera.h"
#include "vv/scene/Mesh.h"

namespace vv::render {

/// The benchmark views of the VSS paper (Kreiser et al. 2018), see VSS.md,
/// "Error against run time". Anatomical views (AnatomicalView below) are
/// separate so that code switching over these three stays complete.
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

/// Anatomical views: the camera looks at the scene from one side of the
/// patient. Patient coordinates are DICOM's LPS: +x towards the patient's
/// Left, +y Posterior (so -y is anterior), +z Superior (towards the head);
/// millimetres, right-handed. Data in RAS (3D Slicer) has x and y negated:
/// its "anterior" view is shown by the posterior one here.
///
/// Screen orientation (the usual radiological conventions):
///  - anterior, posterior, left, right: superior (+z) is up on screen;
///    the anterior view shows the patient's left on the screen's right.
///  - superior, inferior: anterior (-y) is up on screen; the inferior view
///    (from the feet, like axial CT slices) shows the patient's left on the
///    screen's right.
/// The ViewPreset enum is kept to the three benchmark views; an anatomical
/// view is the Far preset with anatomicalRotation() as orientation.
enum class AnatomicalView {
    Anterior,   ///< camera in front of the patient (at -y), looking along +y
    Posterior,  ///< camera behind (at +y), looking along -y
    Left,       ///< camera at the patient's left (+x), looking along -x
    Right,      ///< camera at the patient's right (-x), looking along +x
    Superior,   ///< camera above the head (+z), looking along -z
    Inferior,   ///< camera below the feet (-z), looking along +z
};

/// Every anatomical view, in the order of the enum.
[[nodiscard]] std::span<const AnatomicalView> allAnatomicalViews() noexcept;

/// "anterior", "posterior", "left", "right", "superior", "inferior".
[[nodiscard]] std::string_view toString(AnatomicalView view) noexcept;

/// The view named `name` (ASCII case-insensitive); nullopt if unknown.
[[nodiscard]] std::optional<AnatomicalView> anatomicalViewFromName(std::string_view name) noexcept;

/// Unit vector in patient (LPS) coordinates from the scene towards the camera
/// of `view`: e.g. anterior (0, -1, 0), left (+1, 0, 0), superior (0, 0, +1).
[[nodiscard]] glm::vec3 anatomicalSide(AnatomicalView view) noexcept;

/// Unit vector in patient (LPS) coordinates that is up on screen in `view`.
[[nodiscard]] glm::vec3 anatomicalUp(AnatomicalView view) noexcept;

/// The camera-to-world rotation of `view` (for presetCamera / Camera::setRotation):
/// forward = -anatomicalSide(view), up = anatomicalUp(view).
[[nodiscard]] glm::quat anatomicalRotation(AnatomicalView view) noexcept;

/// The orientation a scene of `frame` opens in (its home view, what
/// Camera::reset() returns to): for the patient frame the anterior view
/// (anatomicalRotation(Anterior): head up, the patient's left on the
/// screen's right, as on the coronal slice; 3D Slicer opens so too); for
/// scenes without anatomy the identity (looking down -z, +y up).
[[nodiscard]] glm::quat homeRotation(scene::SceneFrame frame) noexcept;

/// A view by name, as the CLI's --view takes it: a distance preset and an orientation.
struct NamedView {
    ViewPreset preset = ViewPreset::Far;
    /// Camera-to-world; nullopt for far / medium / close: the scene's home
    /// orientation (homeRotation() of its frame).
    std::optional<glm::quat> rotation;
};

/// "far", "medium", "close" (the scene's home orientation) or an anatomical
/// view name (the Far distance, anatomicalRotation()); ASCII
/// case-insensitive; nullopt if unknown.
[[nodiscard]] std::optional<NamedView> namedViewFromName(std::string_view name) noexcept;

/// Every name namedViewFromName() knows, comma separated (for messages and usage text).
[[nodiscard]] std::string namedViewNames();

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
/// vertices behaves as an empty box. `rotation` nullopt: the scene's home
/// orientation (homeRotation(scene.frame)), which is also the camera's
/// homeRotation().
[[nodiscard]] Camera presetCamera(const scene::Scene& scene, int width, int height,
                                  ViewPreset preset,
                                  const std::optional<glm::quat>& rotation = std::nullopt);

}  // namespace vv::render
