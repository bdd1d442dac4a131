// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The aortic sizing table of endovascular aneurysm repair (EVAR) planning,
// filled from the preset landmarks (Landmarks.h). Measurements only: no
// device is chosen. A value whose landmarks are missing, or that the tree
// cannot give, is blank with the reason, never a guess.
//
// Definitions (every table states them):
// - The aortic path runs from the tree's source (the proximal aorta, the
//   widest open end unless the user chose another) to the aortic
//   bifurcation landmark (else to the largest-diameter or the
//   aneurysm-start landmark, the farthest placed); "below" is along it,
//   away from the source. The aortic landmarks must lie on it.
// - Neck diameters: the section's at the lowest renal artery and 5, 10 and
//   15 mm below it along the centreline (equivalent, minimum and maximum
//   Feret diameter of the lumen).
// - Neck length: from the lowest renal artery to the start of the aneurysm,
//   along the centreline.
// - Angulation: alpha, between the suprarenal aorta's axis (the 15 mm of
//   centreline above the lowest renal artery; at least 5 mm) and the neck's
//   (lowest renal artery to the start of the aneurysm); beta, between the
//   neck's axis and the aneurysm's (start of the aneurysm to the aortic
//   bifurcation). Each axis is the principal axis of the centreline's
//   points over its stretch.
// - Lengths along the centreline: lowest renal artery to the aortic
//   bifurcation and to each internal iliac origin; the aortic bifurcation to
//   each internal iliac origin.
// - Smallest iliac access diameter, per side: the section with the smallest
//   minimum Feret diameter from the aortic bifurcation to that side's
//   internal iliac origin (the common iliac), leaving out where lumens
//   merge.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "vv/planning/Landmarks.h"

namespace vv::planning {

/// Why a value of the table is blank: a reason and what it names, so that
/// each front end says it in its language (blankText: English).
struct Blank {
    enum class Reason : std::uint8_t {
        None,             ///< not blank
        LandmarkMissing,  ///< no landmark of kind `landmark` is placed
        /// No aortic bifurcation, largest-diameter or aneurysm-start landmark
        /// sets the aortic path.
        NoAorticPath,
        /// The `landmark` is not on the centreline from the source to the
        /// `other` (the aortic path's end).
        NotOnAorticPath,
        PathEndsTooSoon,        ///< the aortic path ends less than `mm` below the lowest renal
        NoContour,              ///< the section there has no closed lumen contour
        AneurysmNotBelowRenal,  ///< the start of the aneurysm is not below the lowest renal
        NeckTooShort,           ///< the neck is shorter than `mm`: no axis
        TooLittleAboveRenal,    ///< less than `mm` of centreline above the lowest renal
        AneurysmTooShort,       ///< the aneurysm is shorter than `mm`: no axis
        /// No section between the `landmark` and the `other` measures the
        /// vessel itself (all where lumens merge, or without a contour).
        NoVesselSection,
    };
    Reason reason = Reason::None;
    LandmarkKind landmark = LandmarkKind::Free;
    LandmarkKind other = LandmarkKind::Free;
    double mm = 0.0;
};

/// The reason in an English sentence ("no landmark \"Lowest renal artery\" is
/// placed"); empty for Reason::None.
[[nodiscard]] std::string blankText(const Blank& blank);

/// The key of a reason in measurement files ("landmark_missing"). Stable.
[[nodiscard]] std::string_view blankKey(Blank::Reason reason);
/// The reason of a key; nullopt for an unknown key.
[[nodiscard]] std::optional<Blank::Reason> blankReasonOfKey(std::string_view key);

/// A value of the table, or why it is blank.
template <class T>
struct SizingValue {
    std::optional<T> value;
    Blank blank;  ///< Reason::None when there is a value
};

struct AorticSizing {
    /// Below the lowest renal artery, mm: the neck diameters' places.
    static constexpr std::array<double, 4> kNeckDepthsMm{0.0, 5.0, 10.0, 15.0};
    std::array<SizingValue<SectionSizes>, 4> neckDiameters;  ///< at kNeckDepthsMm
    SizingValue<double> neckLengthMm;
    SizingValue<double> suprarenalToNeckDeg;  ///< alpha
    SizingValue<double> neckToAneurysmDeg;    ///< beta
    SizingValue<SectionSizes> largestAneurysm;
    SizingValue<double> renalToBifurcationMm;
    /// [0] left, [1] right.
    std::array<SizingValue<double>, 2> renalToInternalIliacMm;
    std::array<SizingValue<double>, 2> bifurcationToInternalIliacMm;
    std::array<SizingValue<SectionSizes>, 2> smallestIliac;
};

/// The table from `landmarks` (their first of each preset) on `tree` and
/// its `sections` (computeSections). Throws InvalidArgumentError for a
/// landmark off the tree or sections that do not match it.
[[nodiscard]] AorticSizing aorticSizing(
    const analysis::CenterlineTree& tree,
    const std::vector<std::vector<analysis::CrossSection>>& sections,
    const std::vector<Landmark>& landmarks);

}  // namespace vv::planning
