// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/render/MeshStyle.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <string>
#include <vector>

#include "vv/core/AsciiText.h"
#include "vv/core/Error.h"
#include "vv/core/Hash.h"

namespace vv::render {

namespace {

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

constexpr std::array kAllValues{ArrayValues::Auto, ArrayValues::Continuous,
                                ArrayValues::Categories};

constexpr std::array kAllCues{VesselCue::None, VesselCue::Chromadepth, VesselCue::PseudoChromadepth,
                              VesselCue::Fog, VesselCue::Fresnel};

/// Widens `range` by the finite range of `mesh`'s point array `name`, if any.
void widenRange(std::optional<std::pair<float, float>>& range, const scene::Mesh& mesh,
                const std::string& name) {
    const scene::DataArray* array = mesh.pointArray(name);
    const auto r = array != nullptr ? array->finiteRange() : std::nullopt;
    if (!r) {
        return;
    }
    if (!range) {
        range = r;
    } else {
        range->first = std::min(range->first, r->first);
        range->second = std::max(range->second, r->second);
    }
}

bool inUnitRange(float v) noexcept {
    return std::isfinite(v) && v >= 0.0F && v <= 1.0F;
}

}  // namespace

std::span<const ArrayValues> allArrayValues() noexcept {
    return kAllValues;
}

std::string_view name(ArrayValues values) noexcept {
    switch (values) {
        case ArrayValues::Auto:
            return "auto";
        case ArrayValues::Continuous:
            return "continuous";
        case ArrayValues::Categories:
            return "categories";
    }
    return "auto";
}

std::optional<ArrayValues> arrayValuesFromName(std::string_view text) noexcept {
    for (const ArrayValues values : kAllValues) {
        if (equalsIgnoringCase(name(values), text)) {
            return values;
        }
    }
    if (equalsIgnoringCase("labels", text)) {
        return ArrayValues::Categories;
    }
    return std::nullopt;
}

std::optional<std::vector<scene::Label>> shownLabels(const scene::Scene& scene,
                                                     const MeshStyle& style,
                                                     const std::string& name) {
    const ArrayValues mode = name == style.array ? style.values : ArrayValues::Auto;
    if (name.empty() || mode == ArrayValues::Continuous) {
        return std::nullopt;
    }
    if (mode == ArrayValues::Categories) {
        return scene::distinctLabels(scene, name, scene::kMaxLabels);
    }
    return scene::categoricalLabels(scene, name);
}

const ShownLabels& ShownLabelsCache::get(const scene::Scene& scene, const MeshStyle& style) {
    std::vector<std::string> arrays = shownArrays(scene, style);
    if (!valid_ || arrays != arrays_ || style.array != array_ || style.values != values_) {
        labels_.clear();
        for (const std::string& name : arrays) {
            labels_.emplace_back(name, shownLabels(scene, style, name));
        }
        arrays_ = std::move(arrays);
        array_ = style.array;
        values_ = style.values;
        valid_ = true;
        ++computations_;
    }
    return labels_;
}

const std::vector<scene::Label>* labelsOf(const ShownLabels& labels, const std::string& name) {
    for (const auto& [array, shown] : labels) {
        if (array == name && !name.empty()) {
            return shown ? &*shown : nullptr;
        }
    }
    return nullptr;
}

std::span<const VesselCue> allVesselCues() noexcept {
    return kAllCues;
}

std::string_view name(VesselCue cue) noexcept {
    switch (cue) {
        case VesselCue::None:
            return "none";
        case VesselCue::Chromadepth:
            return "vessel-cd";
        case VesselCue::PseudoChromadepth:
            return "vessel-pcd";
        case VesselCue::Fog:
            return "fog";
        case VesselCue::Fresnel:
            return "fresnel";
    }
    return "none";
}

std::string_view displayName(VesselCue cue) noexcept {
    switch (cue) {
        case VesselCue::None:
            return "None";
        case VesselCue::Chromadepth:
            return "Vessel chromadepth";
        case VesselCue::PseudoChromadepth:
            return "Vessel pseudo-chromadepth";
        case VesselCue::Fog:
            return "Depth fog";
        case VesselCue::Fresnel:
            return "Fresnel-edge pseudo-chromadepth";
    }
    return "None";
}

std::optional<VesselCue> vesselCueFromName(std::string_view text) noexcept {
    for (const VesselCue cue : kAllCues) {
        if (equalsIgnoringCase(name(cue), text)) {
            return cue;
        }
    }
    return std::nullopt;
}

std::optional<colormaps::DepthScale> cueDepthScale(VesselCue cue) noexcept {
    switch (cue) {
        case VesselCue::Chromadepth:
            return colormaps::DepthScale::Chromadepth;
        case VesselCue::PseudoChromadepth:
        case VesselCue::Fresnel:
            return colormaps::DepthScale::PseudoChromadepth;
        case VesselCue::None:
        case VesselCue::Fog:
            return std::nullopt;
    }
    return std::nullopt;
}

glm::vec3 lightDirection(const LightAngles& angles) {
    if (!std::isfinite(angles.azimuth) || !std::isfinite(angles.elevation) ||
        std::abs(angles.azimuth) > 180.0F || std::abs(angles.elevation) > 90.0F) {
        throw InvalidArgumentError(
            "the light direction must have an azimuth within -180..180 and "
            "an elevation within -90..90 degrees, got " +
            std::to_string(angles.azimuth) + ", " + std::to_string(angles.elevation));
    }
    const float a = glm::radians(angles.azimuth);
    const float e = glm::radians(angles.elevation);
    return glm::normalize(
        glm::vec3(std::cos(e) * std::sin(a), std::sin(e), std::cos(e) * std::cos(a)));
}

const Lighting& sceneLighting() noexcept {
    static const Lighting lighting = [] {
        Lighting l;
        l.direction = glm::normalize(glm::vec3(-0.25F, 0.35F, 1.0F));
        return l;
    }();
    return lighting;
}

Lighting lightingFor(const LightAngles& angles) {
    Lighting l = sceneLighting();
    if (!(angles == LightAngles{})) {
        l.direction = lightDirection(angles);
    }
    return l;
}

void validateStyle(const MeshStyle& style) {
    static_cast<void>(lightDirection(style.light));
    for (std::size_t i = 0; i < style.objects.size(); ++i) {
        const ObjectStyle& o = style.objects[i];
        const bool colorOk = !o.color || (inUnitRange(o.color->r) && inUnitRange(o.color->g) &&
                                          inUnitRange(o.color->b));
        if (!inUnitRange(o.opacity) || !colorOk) {
            throw InvalidArgumentError("object " + std::to_string(i) +
                                       ": opacity and colour components must be within 0..1");
        }
    }
}

std::vector<std::string> shownArrays(const scene::Scene& scene, const MeshStyle& style) {
    std::vector<std::string> arrays;
    for (std::size_t i = 0; i < scene.meshes.size(); ++i) {
        const std::string& a = style.arrayOf(i);
        if (!style.visible(i) || a.empty() || scene.meshes[i].pointArray(a) == nullptr ||
            std::find(arrays.begin(), arrays.end(), a) != arrays.end()) {
            continue;
        }
        if (a == style.array) {
            arrays.insert(arrays.begin(), a);
        } else {
            arrays.push_back(a);
        }
    }
    return arrays;
}

std::optional<std::pair<float, float>> objectArrayRange(const scene::Scene& scene,
                                                        const MeshStyle& style,
                                                        const std::string& name) {
    std::optional<std::pair<float, float>> range;
    for (std::size_t i = 0; i < scene.meshes.size(); ++i) {
        if (style.arrayOf(i) == name) {
            widenRange(range, scene.meshes[i], name);
        }
    }
    return range;
}

std::string defaultArrayName(const scene::Scene& scene) {
    for (const auto& wanted : {"wss", "wall_shear_stress", "wallshearstress"}) {
        for (const auto& mesh : scene.meshes) {
            for (const auto& array : mesh.pointArrays) {
                if (lower(array.name) == wanted) {
                    return array.name;
                }
            }
        }
    }
    return {};
}

std::vector<std::string> pointArrayNames(const scene::Scene& scene) {
    std::vector<std::string> names;
    for (const auto& mesh : scene.meshes) {
        for (const auto& array : mesh.pointArrays) {
            if (std::find(names.begin(), names.end(), array.name) == names.end()) {
                names.push_back(array.name);
            }
        }
    }
    return names;
}

std::optional<std::pair<float, float>> arrayRange(const scene::Scene& scene,
                                                  const std::string& name) {
    std::optional<std::pair<float, float>> range;
    for (const auto& mesh : scene.meshes) {
        widenRange(range, mesh, name);
    }
    return range;
}

bool MeshStyle::visible(std::size_t mesh) const noexcept {
    return std::find(hidden.begin(), hidden.end(), mesh) == hidden.end() &&
           object(mesh).opacity > 0.0F;
}

const ObjectStyle& MeshStyle::object(std::size_t mesh) const noexcept {
    static const ObjectStyle defaults;
    return mesh < objects.size() ? objects[mesh] : defaults;
}

const std::string& MeshStyle::arrayOf(std::size_t mesh) const noexcept {
    const ObjectStyle& o = object(mesh);
    return o.array ? *o.array : array;
}

bool MeshStyle::translucent(std::size_t mesh) const noexcept {
    return visible(mesh) && object(mesh).opacity < 1.0F;
}

bool MeshStyle::opaque(std::size_t mesh) const noexcept {
    return visible(mesh) && object(mesh).opacity >= 1.0F;
}

std::uint64_t MeshStyle::geometryKey() const noexcept {
    Hasher hash;
    hash.text(array);
    hash.value(static_cast<int>(values));
    for (const std::size_t index : hidden) {
        hash.value(index);
    }
    for (std::size_t i = 0; i < objects.size(); ++i) {
        if (!objects[i].array && objects[i].opacity >= 1.0F) {
            continue;  // as if it were not listed (its colour is not in the G-buffer)
        }
        const std::string& shown = arrayOf(i);
        const std::uint64_t size = shown.size();
        const bool drawn = opaque(i);
        hash.value(i).value(size).text(shown).value(drawn);
    }
    return hash.result();
}

std::uint64_t MeshStyle::depthKey() const {
    std::vector<std::size_t> notOpaque(hidden);
    for (std::size_t i = 0; i < objects.size(); ++i) {
        if (!opaque(i)) {
            notOpaque.push_back(i);
        }
    }
    std::sort(notOpaque.begin(), notOpaque.end());
    notOpaque.erase(std::unique(notOpaque.begin(), notOpaque.end()), notOpaque.end());
    Hasher hash;
    hash.value(notOpaque.size());
    for (const std::size_t index : notOpaque) {
        hash.value(index);
    }
    return hash.result();
}

}  // namespace vv::render
