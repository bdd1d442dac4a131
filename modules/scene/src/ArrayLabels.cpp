// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/scene/ArrayLabels.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <set>

namespace vv::scene {

namespace {

std::string lower(std::string_view text) {
    std::string out(text);
    std::transform(out.begin(), out.end(), out.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return out;
}

/// Whole numbers that fit an int64 exactly through a float.
bool wholeNumber(float value) noexcept {
    return std::abs(value) < 9.0e15F && std::floor(value) == value;
}

}  // namespace

bool labelLikeName(std::string_view name) noexcept {
    const std::string n = lower(name);
    if (n == "id" || n.ends_with("_id") || n.ends_with("-id") || n.ends_with(" id")) {
        return true;
    }
    constexpr std::array kWords{"label", "segment", "group", "branch", "region", "class", "part"};
    return std::any_of(kWords.begin(), kWords.end(),
                       [&](const char* word) { return n.find(word) != std::string::npos; });
}

std::optional<std::vector<Label>> distinctLabels(const Scene& scene, const std::string& name,
                                                 std::size_t limit) {
    std::set<std::int64_t> values;
    bool found = false;
    for (const Mesh& mesh : scene.meshes) {
        const DataArray* array = mesh.pointArray(name);
        if (array == nullptr) {
            continue;
        }
        if (array->components != 1) {
            return std::nullopt;
        }
        found = true;
        for (const float v : array->values) {
            if (!std::isfinite(v)) {
                continue;
            }
            if (!wholeNumber(v)) {
                return std::nullopt;
            }
            values.insert(static_cast<std::int64_t>(v));
            if (values.size() > limit) {
                return std::nullopt;
            }
        }
    }
    if (!found || values.empty()) {
        return std::nullopt;
    }
    std::vector<Label> labels;
    labels.reserve(values.size());
    for (const std::int64_t value : values) {
        Label label{value, {}};
        for (const Mesh& mesh : scene.meshes) {
            const auto names = mesh.labelNames.find(name);
            if (names == mesh.labelNames.end()) {
                continue;
            }
            const auto it = names->second.find(value);
            if (it != names->second.end() && !it->second.empty()) {
                label.name = it->second;
                break;
            }
        }
        labels.push_back(std::move(label));
    }
    return labels;
}

std::optional<std::vector<Label>> categoricalLabels(const Scene& scene, const std::string& name) {
    bool integerStorage = true;
    for (const Mesh& mesh : scene.meshes) {
        if (const DataArray* array = mesh.pointArray(name); array != nullptr && !array->integer) {
            integerStorage = false;
        }
    }
    if (integerStorage && labelLikeName(name)) {
        return distinctLabels(scene, name, kMaxLabels);
    }
    auto labels = distinctLabels(scene, name, kMaxAutoLabels);
    if (labels && (integerStorage || labelLikeName(name) || labels->size() <= kMaxUnhintedLabels)) {
        return labels;
    }
    return std::nullopt;
}

bool looksCategorical(const Scene& scene, const std::string& name) {
    return categoricalLabels(scene, name).has_value();
}

std::string labelText(const Label& label) {
    return label.name.empty() ? "Label " + std::to_string(label.value) : label.name;
}

}  // namespace vv::scene
