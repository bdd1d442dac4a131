// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Landmarks on a centreline tree: named places a planner marks along a
// path (free names, or one of the presets of aortic planning), and the
// sizes of the vessel's section at each.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "vv/analysis/Sections.h"
#include "vv/planning/VesselPath.h"

namespace vv::planning {

/// The presets of aortic planning (EVAR): each names one landmark that the
/// sizing table (AorticSizing.h) reads. Free: a name the user chose.
enum class LandmarkKind : std::uint8_t {
    Free,
    LowestRenalArtery,        ///< the lowest renal artery's origin: the neck's top
    AneurysmStart,            ///< where the aneurysm starts: the neck's bottom
    LargestAneurysmDiameter,  ///< the aneurysm's widest section
    AorticBifurcation,        ///< where the aorta divides into the common iliacs
    LeftInternalIliacOrigin,  ///< the end of the left common iliac
    RightInternalIliacOrigin,
};

/// Every preset, in the order of planning (LandmarkKind::Free left out).
[[nodiscard]] const std::vector<LandmarkKind>& landmarkPresets();

/// The kind's key in measurement files and sessions ("lowest_renal_artery";
/// "free" for Free). Stable across versions.
[[nodiscard]] std::string_view landmarkKey(LandmarkKind kind);
/// The kind of a key; nullopt for an unknown key.
[[nodiscard]] std::optional<LandmarkKind> landmarkKindOfKey(std::string_view key);
/// The preset's name in English ("Lowest renal artery"); empty for Free. The
/// GUI shows its own translation of it.
[[nodiscard]] std::string_view landmarkEnglishName(LandmarkKind kind);

struct Landmark {
    std::string name;  ///< as shown; for a preset its name unless renamed
    LandmarkKind kind = LandmarkKind::Free;
    TreeLocation location;
};

/// The sizes of the vessel at a place: its nearest section's.
struct SectionSizes {
    TreeLocation location;              ///< of the section's centreline point
    double equivalentDiameterMm = 0.0;  ///< 2 sqrt(area / pi)
    double minDiameterMm = 0.0;         ///< the smallest Feret (caliper) width
    double maxDiameterMm = 0.0;         ///< the largest Feret width
    double areaMm2 = 0.0;
    /// The section lies where lumens merge or at a vessel's end
    /// (CrossSection::inEndZone): its contour holds part of the other
    /// lumen, and a table says so.
    bool atAJunction = false;
};

/// The sizes at the section nearest to `at` (of the branch's centreline
/// points, by abscissa); nullopt where that section has no closed contour
/// (never a neighbour's size instead: a table leaves it blank). `sections`
/// as computeSections returns them. Throws InvalidArgumentError for a place
/// off the tree or sections that do not match it.
[[nodiscard]] std::optional<SectionSizes> sectionSizesAt(
    const analysis::CenterlineTree& tree,
    const std::vector<std::vector<analysis::CrossSection>>& sections, const TreeLocation& at);

/// Whether a landmark of `kind` names a bifurcation (the aortic
/// bifurcation, an internal iliac origin).
[[nodiscard]] bool namesABifurcation(LandmarkKind kind) noexcept;

/// Where a landmark of `kind` goes for a point the user chose (a click on
/// the vessel or near its centreline): the nearest centreline place; for a
/// kind that names a bifurcation, the bifurcation itself (where its parent
/// branch ends) when the point lies within the inscribed radius there of
/// it, so that every path through it measures from the same place. Throws
/// as nearestLocation.
[[nodiscard]] TreeLocation placeLandmark(const analysis::CenterlineTree& tree, LandmarkKind kind,
                                         const glm::dvec3& point);

/// The landmark of `kind` among `landmarks` (the first), nullptr if none.
[[nodiscard]] const Landmark* findLandmark(const std::vector<Landmark>& landmarks,
                                           LandmarkKind kind);

}  // namespace vv::planning
