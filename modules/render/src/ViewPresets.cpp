// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/render/ViewPresets.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <limits>
#include <string>

#include "vv/core/AsciiText.h"
#include "vv/core/Error.h"

namespace vv::render {

namespace {

constexpr std::array<ViewPreset, 3> kPresets{ViewPreset::Far, ViewPreset::Medium,
                                             ViewPreset::Close};

/// A camera with everything but the distance set up: viewport, orientation,
/// target at the box centre, scene bounds.
Camera baseCamera(const Aabb& bounds, int width, int height, const glm::quat& rotation) {
    Camera camera;
    camera.setViewport(width, height);
    camera.setRotation(rotation);
    camera.fit(bounds);  // target, scene bounds, and a fallback distance
    return camera;
}

/// The smallest distance at which every point lies inside the central
/// (1 - 2 margin) part of the image (visitor over the points).
template <typename ForEachPoint>
float farDistance(const Camera& camera, ForEachPoint&& forEachPoint) {
    const float usable = 1.0F - 2.0F * kFarViewMargin;
    const double tanY = std::tan(0.5 * glm::radians(static_cast<double>(camera.fieldOfView()))) *
                        static_cast<double>(usable);
    const double tanX = tanY * static_cast<double>(camera.aspect());
    const glm::dvec3 c(camera.target());
    const glm::dvec3 axisX(camera.right());
    const glm::dvec3 axisY(camera.up());
    const glm::dvec3 axisZ(-camera.forward());  // towards the viewer
    double d = 0.0;
    double nearest = -std::numeric_limits<double>::infinity();
    bool any = false;
    forEachPoint([&](const glm::vec3& point) {
        const glm::dvec3 p = glm::dvec3(point) - c;
        const double x = std::abs(glm::dot(p, axisX));
        const double y = std::abs(glm::dot(p, axisY));
        const double z = glm::dot(p, axisZ);
        d = std::max({d, z + x / tanX, z + y / tanY});
        nearest = std::max(nearest, z);
        any = true;
    });
    if (!any || !(d > 0.0) || !std::isfinite(d)) {
        return camera.distance();
    }
    // Points exactly on the axis need the eye in front of them as well.
    d = std::max(d, nearest + 1e-3 * std::max(1.0, std::abs(nearest)));
    return static_cast<float>(d);
}

Camera finish(Camera camera, float far, ViewPreset preset) {
    camera.setDistance(far * presetDistanceFactor(preset));
    return camera;
}

constexpr std::array<AnatomicalView, 6> kAnatomicalViews{
    AnatomicalView::Anterior, AnatomicalView::Posterior, AnatomicalView::Left,
    AnatomicalView::Right,    AnatomicalView::Superior,  AnatomicalView::Inferior};

}  // namespace

std::span<const AnatomicalView> allAnatomicalViews() noexcept {
    return kAnatomicalViews;
}

std::string_view toString(AnatomicalView view) noexcept {
    switch (view) {
        case AnatomicalView::Anterior:
            return "anterior";
        case AnatomicalView::Posterior:
            return "posterior";
        case AnatomicalView::Left:
            return "left";
        case AnatomicalView::Right:
            return "right";
        case AnatomicalView::Superior:
            return "superior";
        case AnatomicalView::Inferior:
            return "inferior";
    }
    return "unknown";
}

std::optional<AnatomicalView> anatomicalViewFromName(std::string_view name) noexcept {
    for (const AnatomicalView view : kAnatomicalViews) {
        if (equalsIgnoringCase(name, toString(view))) {
            return view;
        }
    }
    return std::nullopt;
}

glm::vec3 anatomicalSide(AnatomicalView view) noexcept {
    // LPS: +x left, +y posterior, +z superior.
    switch (view) {
        case AnatomicalView::Anterior:
            return {0.0F, -1.0F, 0.0F};
        case AnatomicalView::Posterior:
            return {0.0F, 1.0F, 0.0F};
        case AnatomicalView::Left:
            return {1.0F, 0.0F, 0.0F};
        case AnatomicalView::Right:
            return {-1.0F, 0.0F, 0.0F};
        case AnatomicalView::Superior:
            return {0.0F, 0.0F, 1.0F};
        case AnatomicalView::Inferior:
            return {0.0F, 0.0F, -1.0F};
    }
    return {0.0F, -1.0F, 0.0F};
}

glm::vec3 anatomicalUp(AnatomicalView view) noexcept {
    switch (view) {
        case AnatomicalView::Superior:
        case AnatomicalView::Inferior:
            return {0.0F, -1.0F, 0.0F};  // anterior
        case AnatomicalView::Anterior:
        case AnatomicalView::Posterior:
        case AnatomicalView::Left:
        case AnatomicalView::Right:
            break;
    }
    return {0.0F, 0.0F, 1.0F};  // superior
}

glm::quat anatomicalRotation(AnatomicalView view) noexcept {
    // Columns of the camera-to-world rotation: the camera's x (right), y (up)
    // and z (towards the viewer, i.e. -forward) axes in world coordinates.
    const glm::vec3 back = anatomicalSide(view);
    const glm::vec3 up = anatomicalUp(view);
    const glm::vec3 right = glm::cross(up, back);
    return glm::normalize(glm::quat_cast(glm::mat3(right, up, back)));
}

glm::quat homeRotation(scene::SceneFrame frame) noexcept {
    switch (frame) {
        case scene::SceneFrame::PatientLps:
            return anatomicalRotation(AnatomicalView::Anterior);
        case scene::SceneFrame::Unknown:
            break;
    }
    return {1.0F, 0.0F, 0.0F, 0.0F};
}

std::optional<NamedView> namedViewFromName(std::string_view name) noexcept {
    if (const auto preset = viewPresetFromName(name)) {
        return NamedView{*preset, std::nullopt};
    }
    if (const auto view = anatomicalViewFromName(name)) {
        return NamedView{ViewPreset::Far, anatomicalRotation(*view)};
    }
    return std::nullopt;
}

std::string namedViewNames() {
    std::string names;
    for (const ViewPreset preset : kPresets) {
        names += (names.empty() ? "" : ", ") + std::string(toString(preset));
    }
    for (const AnatomicalView view : kAnatomicalViews) {
        names += ", " + std::string(toString(view));
    }
    return names;
}

std::span<const ViewPreset> allViewPresets() noexcept {
    return kPresets;
}

std::string_view toString(ViewPreset preset) noexcept {
    switch (preset) {
        case ViewPreset::Far:
            return "far";
        case ViewPreset::Medium:
            return "medium";
        case ViewPreset::Close:
            return "close";
    }
    return "unknown";
}

std::optional<ViewPreset> viewPresetFromName(std::string_view name) noexcept {
    for (const ViewPreset preset : kPresets) {
        if (equalsIgnoringCase(name, toString(preset))) {
            return preset;
        }
    }
    return std::nullopt;
}

ViewPreset parseViewPreset(std::string_view name) {
    if (const auto preset = viewPresetFromName(name)) {
        return *preset;
    }
    std::string known;
    for (const ViewPreset preset : kPresets) {
        known += (known.empty() ? "" : ", ") + std::string(toString(preset));
    }
    throw InvalidArgumentError("unknown view '" + std::string(name) + "' (known: " + known + ")");
}

float presetDistanceFactor(ViewPreset preset) noexcept {
    switch (preset) {
        case ViewPreset::Far:
            return 1.0F;
        // Tuned on the demo tree at 1280x720 so that the void regions resemble
        // the paper's views (VSS.md): Far 16 regions / 5.7K contour pixels in
        // the largest, Medium 17 / 4.7K, Close 25 / 2.7K (paper: 15 / 10K,
        // 17 / 5K, 35 / 2.5K). See docs/benchmarks/vss.md.
        case ViewPreset::Medium:
            return 0.46F;
        case ViewPreset::Close:
            return 0.42F;
    }
    return 1.0F;
}

Camera presetCamera(const Aabb& bounds, int width, int height, ViewPreset preset,
                    const glm::quat& rotation) {
    Camera camera = baseCamera(bounds, width, height, rotation);
    Aabb box = bounds;
    if (box.empty()) {
        box.extend(glm::vec3(-1.0F));
        box.extend(glm::vec3(1.0F));
    }
    const float far = farDistance(camera, [&](const auto& visit) {
        for (int i = 0; i < 8; ++i) {
            visit(glm::vec3{(i & 1) != 0 ? box.max.x : box.min.x,
                            (i & 2) != 0 ? box.max.y : box.min.y,
                            (i & 4) != 0 ? box.max.z : box.min.z});
        }
    });
    return finish(camera, far, preset);
}

Camera presetCamera(const scene::Scene& scene, int width, int height, ViewPreset preset,
                    const std::optional<glm::quat>& rotation) {
    const Aabb bounds = scene.bounds();
    const glm::quat home = homeRotation(scene.frame);
    Camera camera = baseCamera(bounds, width, height, rotation.value_or(home));
    camera.setHomeRotation(home);
    bool anyVertex = false;
    for (const scene::Mesh& mesh : scene.meshes) {
        anyVertex = anyVertex || !mesh.positions.empty();
    }
    if (!anyVertex) {
        camera = presetCamera(bounds, width, height, preset, rotation.value_or(home));
        camera.setHomeRotation(home);
        return camera;
    }
    const float far = farDistance(camera, [&](const auto& visit) {
        for (const scene::Mesh& mesh : scene.meshes) {
            for (const glm::vec3& p : mesh.positions) {
                if (isFinite(p)) {
                    visit(p);
                }
            }
        }
    });
    return finish(camera, far, preset);
}

}  // namespace vv::render
