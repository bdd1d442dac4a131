// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/planning/Landmarks.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <string>
#include <utility>

#include "vv/core/Error.h"

namespace vv::planning {
namespace {

struct KindText {
    LandmarkKind kind;
    std::string_view key;
    std::string_view english;
};

constexpr std::array<KindText, 7> kKinds{{
    {LandmarkKind::Free, "free", ""},
    {LandmarkKind::LowestRenalArtery, "lowest_renal_artery", "Lowest renal artery"},
    {LandmarkKind::AneurysmStart, "aneurysm_start", "Start of the aneurysm"},
    {LandmarkKind::LargestAneurysmDiameter, "largest_aneurysm_diameter",
     "Largest aneurysm diameter"},
    {LandmarkKind::AorticBifurcation, "aortic_bifurcation", "Aortic bifurcation"},
    {LandmarkKind::LeftInternalIliacOrigin, "left_internal_iliac_origin",
     "Left internal iliac origin"},
    {LandmarkKind::RightInternalIliacOrigin, "right_internal_iliac_origin",
     "Right internal iliac origin"},
}};

const KindText& textOf(LandmarkKind kind) {
    const auto* found = std::find_if(kKinds.begin(), kKinds.end(),
                                     [kind](const KindText& t) { return t.kind == kind; });
    return found != kKinds.end() ? *found : kKinds.front();
}

}  // namespace

const std::vector<LandmarkKind>& landmarkPresets() {
    static const std::vector<LandmarkKind> presets = [] {
        std::vector<LandmarkKind> kinds;
        for (const KindText& t : kKinds) {
            if (t.kind != LandmarkKind::Free) {
                kinds.push_back(t.kind);
            }
        }
        return kinds;
    }();
    return presets;
}

std::string_view landmarkKey(LandmarkKind kind) {
    return textOf(kind).key;
}

std::optional<LandmarkKind> landmarkKindOfKey(std::string_view key) {
    for (const KindText& t : kKinds) {
        if (t.key == key) {
            return t.kind;
        }
    }
    return std::nullopt;
}

std::string_view landmarkEnglishName(LandmarkKind kind) {
    return textOf(kind).english;
}

std::optional<SectionSizes> sectionSizesAt(
    const analysis::CenterlineTree& tree,
    const std::vector<std::vector<analysis::CrossSection>>& sections, const TreeLocation& at) {
    const TreeLocation c = clampedLocation(tree, at);
    const auto& points = tree.branches[static_cast<std::size_t>(c.branch)].points;
    if (static_cast<std::size_t>(c.branch) >= sections.size() ||
        sections[static_cast<std::size_t>(c.branch)].size() != points.size()) {
        throw InvalidArgumentError("centrelines: the sections do not match the branches (branch " +
                                   std::to_string(c.branch) + ")");
    }
    std::size_t nearest = 0;
    for (std::size_t i = 1; i < points.size(); ++i) {
        if (std::abs(points[i].abscissaMm - c.abscissaMm) <
            std::abs(points[nearest].abscissaMm - c.abscissaMm)) {
            nearest = i;
        }
    }
    const analysis::CrossSection& s = sections[static_cast<std::size_t>(c.branch)][nearest];
    if (s.status != analysis::CrossSection::Status::Ok) {
        return std::nullopt;
    }
    SectionSizes sizes;
    sizes.location = {c.branch, points[nearest].abscissaMm};
    sizes.equivalentDiameterMm = s.equivalentDiameterMm;
    sizes.minDiameterMm = s.minDiameterMm;
    sizes.maxDiameterMm = s.maxDiameterMm;
    sizes.areaMm2 = s.areaMm2;
    sizes.atAJunction = s.inEndZone;
    return sizes;
}

bool namesABifurcation(LandmarkKind kind) noexcept {
    return kind == LandmarkKind::AorticBifurcation ||
           kind == LandmarkKind::LeftInternalIliacOrigin ||
           kind == LandmarkKind::RightInternalIliacOrigin;
}

TreeLocation placeLandmark(const analysis::CenterlineTree& tree, LandmarkKind kind,
                           const glm::dvec3& point) {
    if (!namesABifurcation(kind)) {
        return nearestLocation(tree, point).location;
    }
    std::optional<TreeLocation> node;
    double nodeDistance = 0.0;
    for (const analysis::Branch& b : tree.branches) {
        if (b.children.size() < 2 || b.points.empty()) {
            continue;
        }
        const analysis::CenterlinePoint& end = b.points.back();
        const double d = glm::length(end.position - point);
        if (d <= end.radiusMm && (!node || d < nodeDistance)) {
            node = TreeLocation{b.id, end.abscissaMm};
            nodeDistance = d;
        }
    }
    return node ? *node : nearestLocation(tree, point).location;
}

const Landmark* findLandmark(const std::vector<Landmark>& landmarks, LandmarkKind kind) {
    const auto found = std::find_if(landmarks.begin(), landmarks.end(),
                                    [kind](const Landmark& l) { return l.kind == kind; });
    return found != landmarks.end() ? &*found : nullptr;
}

}  // namespace vv::planning
