// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/planning/AorticSizing.h"

#include <algorithm>
#include <string>
#include <utility>

#include "vv/analysis/Bifurcations.h"
#include "vv/core/NumberText.h"

namespace vv::planning {
namespace {

using analysis::CenterlineTree;
using Sections = std::vector<std::vector<analysis::CrossSection>>;

/// The suprarenal aorta's axis is taken over this much centreline above the
/// lowest renal artery, and over no less than kShortestAxisMm.
constexpr double kSuprarenalMm = 15.0;
constexpr double kShortestAxisMm = 5.0;

template <class T>
SizingValue<T> blank(Blank because) {
    return {std::nullopt, because};
}

template <class T>
SizingValue<T> blank(Blank::Reason reason, LandmarkKind landmark = LandmarkKind::Free,
                     LandmarkKind other = LandmarkKind::Free, double mm = 0.0) {
    return {std::nullopt, Blank{reason, landmark, other, mm}};
}

template <class T>
SizingValue<T> known(T value) {
    return {std::move(value), {}};
}

std::string nameOf(LandmarkKind kind) {
    std::string name(landmarkEnglishName(kind));
    if (!name.empty()) {
        name[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(name[0])));
    }
    return name;
}

Blank missing(LandmarkKind kind) {
    return {Blank::Reason::LandmarkMissing, kind};
}

/// The aortic path and where the aortic landmarks lie on it.
class AorticPath {
  public:
    AorticPath(const CenterlineTree& tree, const std::vector<Landmark>& landmarks)
        : tree_(tree), landmarks_(landmarks) {
        for (const LandmarkKind kind :
             {LandmarkKind::AorticBifurcation, LandmarkKind::LargestAneurysmDiameter,
              LandmarkKind::AneurysmStart}) {
            if (const Landmark* l = findLandmark(landmarks, kind)) {
                path_ = VesselPath::between(tree, endLocation(tree, 0), l->location);
                distal_ = kind;
                return;
            }
        }
    }

    [[nodiscard]] const std::optional<VesselPath>& path() const noexcept { return path_; }

    /// Where the landmark of `kind` lies along the path, or why it cannot be
    /// used.
    [[nodiscard]] SizingValue<double> at(LandmarkKind kind) const {
        const Landmark* l = findLandmark(landmarks_, kind);
        if (l == nullptr) {
            return blank<double>(missing(kind));
        }
        if (!path_) {
            return blank<double>(Blank::Reason::NoAorticPath);
        }
        const auto s = path_->abscissaOf(tree_, l->location);
        if (!s) {
            return blank<double>(Blank::Reason::NotOnAorticPath, kind, distal_);
        }
        return known(*s);
    }

    /// The principal axis of the path's centreline points over [from, to].
    [[nodiscard]] std::optional<glm::dvec3> axisOver(double from, double to) const {
        std::vector<glm::dvec3> stretch;
        for (const PathPoint& p : path_->points(tree_)) {
            if (p.pathMm >= from - 1e-9 && p.pathMm <= to + 1e-9) {
                stretch.push_back(tree_.branches[static_cast<std::size_t>(p.branch)]
                                      .points[p.pointIndex]
                                      .position);
            }
        }
        if (stretch.size() < 3 || to - from < kShortestAxisMm) {
            return std::nullopt;
        }
        return analysis::principalDirection(stretch);
    }

  private:
    const CenterlineTree& tree_;
    const std::vector<Landmark>& landmarks_;
    std::optional<VesselPath> path_;
    LandmarkKind distal_ = LandmarkKind::AorticBifurcation;
};

void fillNeck(const CenterlineTree& tree, const Sections& sections, const AorticPath& aorta,
              AorticSizing& table) {
    const auto renal = aorta.at(LandmarkKind::LowestRenalArtery);
    const auto start = aorta.at(LandmarkKind::AneurysmStart);
    for (std::size_t i = 0; i < AorticSizing::kNeckDepthsMm.size(); ++i) {
        const double depth = AorticSizing::kNeckDepthsMm[i];
        auto& cell = table.neckDiameters[i];
        if (!renal.value) {
            cell = blank<SectionSizes>(renal.blank);
        } else if (*renal.value + depth > aorta.path()->lengthMm() + 1e-9) {
            cell = blank<SectionSizes>(Blank::Reason::PathEndsTooSoon, LandmarkKind::Free,
                                       LandmarkKind::Free, depth);
        } else if (const auto sizes = sectionSizesAt(
                       tree, sections, aorta.path()->locationAt(*renal.value + depth))) {
            cell = known(*sizes);
        } else {
            cell = blank<SectionSizes>(Blank::Reason::NoContour);
        }
    }
    if (!renal.value || !start.value) {
        table.neckLengthMm = blank<double>(!renal.value ? renal.blank : start.blank);
        table.suprarenalToNeckDeg = table.neckLengthMm;
        table.neckToAneurysmDeg = table.neckLengthMm;
        return;
    }
    if (*start.value <= *renal.value) {
        table.neckLengthMm = blank<double>(Blank::Reason::AneurysmNotBelowRenal);
        table.suprarenalToNeckDeg = table.neckLengthMm;
        table.neckToAneurysmDeg = table.neckLengthMm;
        return;
    }
    table.neckLengthMm = known(*start.value - *renal.value);
    const auto neck = aorta.axisOver(*renal.value, *start.value);
    const auto above = aorta.axisOver(std::max(0.0, *renal.value - kSuprarenalMm), *renal.value);
    if (!neck) {
        table.suprarenalToNeckDeg = blank<double>(Blank::Reason::NeckTooShort, LandmarkKind::Free,
                                                  LandmarkKind::Free, kShortestAxisMm);
        table.neckToAneurysmDeg = table.suprarenalToNeckDeg;
        return;
    }
    table.suprarenalToNeckDeg =
        above ? known(analysis::angleBetweenDeg(*above, *neck))
              : blank<double>(Blank::Reason::TooLittleAboveRenal, LandmarkKind::Free,
                              LandmarkKind::Free, kShortestAxisMm);
    const auto bifurcation = aorta.at(LandmarkKind::AorticBifurcation);
    if (!bifurcation.value) {
        table.neckToAneurysmDeg = blank<double>(bifurcation.blank);
        return;
    }
    const auto sac = aorta.axisOver(*start.value, *bifurcation.value);
    table.neckToAneurysmDeg =
        sac ? known(analysis::angleBetweenDeg(*neck, *sac))
            : blank<double>(Blank::Reason::AneurysmTooShort, LandmarkKind::Free, LandmarkKind::Free,
                            kShortestAxisMm);
}

/// The length along the centreline between the landmarks of two kinds.
SizingValue<double> lengthBetween(const CenterlineTree& tree,
                                  const std::vector<Landmark>& landmarks, LandmarkKind a,
                                  LandmarkKind b) {
    const Landmark* la = findLandmark(landmarks, a);
    const Landmark* lb = findLandmark(landmarks, b);
    if (la == nullptr || lb == nullptr) {
        return blank<double>(missing(la == nullptr ? a : b));
    }
    return known(lengthAlong(tree, la->location, lb->location));
}

/// The section with the smallest minimum diameter on the path between two
/// landmarks, where it measures the vessel itself.
SizingValue<SectionSizes> narrowestBetween(const CenterlineTree& tree, const Sections& sections,
                                           const std::vector<Landmark>& landmarks, LandmarkKind a,
                                           LandmarkKind b) {
    const Landmark* la = findLandmark(landmarks, a);
    const Landmark* lb = findLandmark(landmarks, b);
    if (la == nullptr || lb == nullptr) {
        return blank<SectionSizes>(missing(la == nullptr ? a : b));
    }
    const VesselPath path = VesselPath::between(tree, la->location, lb->location);
    std::optional<SectionSizes> narrowest;
    for (const PathPoint& p : path.points(tree)) {
        const auto& s = sections.at(static_cast<std::size_t>(p.branch)).at(p.pointIndex);
        if (!s.measuresTheVessel() || (narrowest && s.minDiameterMm >= narrowest->minDiameterMm)) {
            continue;
        }
        narrowest = sectionSizesAt(
            tree, sections,
            {p.branch,
             tree.branches[static_cast<std::size_t>(p.branch)].points[p.pointIndex].abscissaMm});
    }
    if (!narrowest) {
        return blank<SectionSizes>(Blank::Reason::NoVesselSection, a, b);
    }
    return known(*narrowest);
}

}  // namespace

std::string blankText(const Blank& b) {
    const std::string mm = fixedText(b.mm, 0) + " mm";
    switch (b.reason) {
        case Blank::Reason::None:
            return {};
        case Blank::Reason::LandmarkMissing:
            return "no landmark \"" + std::string(landmarkEnglishName(b.landmark)) + "\" is placed";
        case Blank::Reason::NoAorticPath:
            return "no landmark below the neck (aortic bifurcation, largest aneurysm diameter or "
                   "start of the aneurysm) is placed to set the aortic path";
        case Blank::Reason::NotOnAorticPath:
            return "the " + nameOf(b.landmark) +
                   " is not on the centreline from the source to the " + nameOf(b.other);
        case Blank::Reason::PathEndsTooSoon:
            return "the aortic path ends less than " + mm + " below the lowest renal artery";
        case Blank::Reason::NoContour:
            return "the section there has no closed lumen contour";
        case Blank::Reason::AneurysmNotBelowRenal:
            return "the start of the aneurysm is not below the lowest renal artery";
        case Blank::Reason::NeckTooShort:
            return "the neck is shorter than " + mm + ": it has no axis";
        case Blank::Reason::TooLittleAboveRenal:
            return "less than " + mm + " of centreline above the lowest renal artery";
        case Blank::Reason::AneurysmTooShort:
            return "the aneurysm is shorter than " + mm + ": it has no axis";
        case Blank::Reason::NoVesselSection:
            return "no section between the " + nameOf(b.landmark) + " and the " + nameOf(b.other) +
                   " measures the vessel itself";
    }
    return {};
}

std::string_view blankKey(Blank::Reason reason) {
    switch (reason) {
        case Blank::Reason::None:
            return "none";
        case Blank::Reason::LandmarkMissing:
            return "landmark_missing";
        case Blank::Reason::NoAorticPath:
            return "no_aortic_path";
        case Blank::Reason::NotOnAorticPath:
            return "not_on_aortic_path";
        case Blank::Reason::PathEndsTooSoon:
            return "path_ends_too_soon";
        case Blank::Reason::NoContour:
            return "no_contour";
        case Blank::Reason::AneurysmNotBelowRenal:
            return "aneurysm_not_below_renal";
        case Blank::Reason::NeckTooShort:
            return "neck_too_short";
        case Blank::Reason::TooLittleAboveRenal:
            return "too_little_above_renal";
        case Blank::Reason::AneurysmTooShort:
            return "aneurysm_too_short";
        case Blank::Reason::NoVesselSection:
            return "no_vessel_section";
    }
    return "none";
}

std::optional<Blank::Reason> blankReasonOfKey(std::string_view key) {
    for (int r = 0; r <= static_cast<int>(Blank::Reason::NoVesselSection); ++r) {
        if (blankKey(static_cast<Blank::Reason>(r)) == key) {
            return static_cast<Blank::Reason>(r);
        }
    }
    return std::nullopt;
}

AorticSizing aorticSizing(const CenterlineTree& tree, const Sections& sections,
                          const std::vector<Landmark>& landmarks) {
    for (const Landmark& l : landmarks) {
        static_cast<void>(clampedLocation(tree, l.location));  // throws for one off the tree
    }
    AorticSizing table;
    const AorticPath aorta(tree, landmarks);
    fillNeck(tree, sections, aorta, table);
    if (const Landmark* widest = findLandmark(landmarks, LandmarkKind::LargestAneurysmDiameter)) {
        const auto sizes = sectionSizesAt(tree, sections, widest->location);
        table.largestAneurysm =
            sizes ? known(*sizes) : blank<SectionSizes>(Blank::Reason::NoContour);
    } else {
        table.largestAneurysm = blank<SectionSizes>(missing(LandmarkKind::LargestAneurysmDiameter));
    }
    table.renalToBifurcationMm = lengthBetween(tree, landmarks, LandmarkKind::LowestRenalArtery,
                                               LandmarkKind::AorticBifurcation);
    const std::array<LandmarkKind, 2> origins{LandmarkKind::LeftInternalIliacOrigin,
                                              LandmarkKind::RightInternalIliacOrigin};
    for (std::size_t side = 0; side < 2; ++side) {
        table.renalToInternalIliacMm[side] =
            lengthBetween(tree, landmarks, LandmarkKind::LowestRenalArtery, origins[side]);
        table.bifurcationToInternalIliacMm[side] =
            lengthBetween(tree, landmarks, LandmarkKind::AorticBifurcation, origins[side]);
        table.smallestIliac[side] = narrowestBetween(
            tree, sections, landmarks, LandmarkKind::AorticBifurcation, origins[side]);
    }
    return table;
}

}  // namespace vv::planning
