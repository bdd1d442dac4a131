// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Cross-sections of a vessel surface perpendicular to its centrelines: at
// every centreline point, the closed lumen contour around the point in the
// plane normal to the tangent (never a neighbouring vessel's contour, which
// does not hold the point), and its size.
//
// Which diameter is which (every table, JSON and tooltip names them so):
// - equivalent diameter: 2 sqrt(A / pi), of the circle with the section's
//   area A; what "the diameter" of a round vessel means, and what stenosis
//   grading by area uses;
// - minimum / maximum diameter: the smallest and the largest Feret width of
//   the contour (the distance between two parallel lines that touch it, over
//   all directions): what calipers measure; for an oval lumen they differ;
// - inscribed diameter: twice the radius of the largest sphere centred on
//   the centreline that stays inside the surface (VMTK's
//   MaximumInscribedSphereRadius); at most the minimum diameter.

#include <array>
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "vv/analysis/Centerlines.h"
#include "vv/core/Progress.h"
#include "vv/scene/Mesh.h"

namespace vv::analysis {

struct CrossSection {
    enum class Status : std::uint8_t {
        Ok,
        /// The plane cuts no closed contour around the centreline point (at
        /// an open end, or where the surface has a hole): no size.
        NoContour,
    };
    Status status = Status::NoContour;
    int branch = 0;              ///< CenterlineTree::branches index
    std::size_t pointIndex = 0;  ///< into that branch's points
    double abscissaMm = 0.0;     ///< the point's abscissa
    glm::dvec3 centre{0.0};      ///< the centreline point, mm
    glm::dvec3 normal{0.0};      ///< the plane's normal: the centreline's tangent
    /// In-plane axes: the centreline's rotation-minimising normal and
    /// binormal, so consecutive sections do not twist.
    glm::dvec3 axisU{0.0};
    glm::dvec3 axisV{0.0};
    /// The lumen contour in (u, v) mm about the centre, counter-clockwise
    /// seen along the normal, not repeating its first point.
    std::vector<glm::dvec2> contour;
    double areaMm2 = 0.0;
    double perimeterMm = 0.0;
    double equivalentDiameterMm = 0.0;  ///< 2 sqrt(area / pi)
    double minDiameterMm = 0.0;         ///< the smallest Feret width
    double maxDiameterMm = 0.0;         ///< the largest Feret width
    double inscribedDiameterMm = 0.0;   ///< 2 x the maximal inscribed sphere's radius
    double circularity = 0.0;           ///< 4 pi area / perimeter^2: 1 for a circle
    /// The distance from the centreline point to the contour's centroid, mm
    /// (how far off centre the centreline runs here).
    double centreOffsetMm = 0.0;
    /// Within an end zone of its branch: at a vessel's end (the rounded cap
    /// of a closed tip, an open end's rim) or where the branch meets its
    /// parent or children (the lumens merge there). Such a section is not
    /// a vessel's cross-section: narrowest / widest points and stenosis
    /// grading leave it out. A zone is twice the branch's median inscribed
    /// radius long, or 1.5 times the radius at its end point where that is
    /// larger (a junction's merged lumen).
    bool inEndZone = false;

    /// A size of the vessel itself: a closed contour outside the end zones.
    /// What narrowest / widest points and stenosis grading use.
    [[nodiscard]] bool measuresTheVessel() const noexcept {
        return status == Status::Ok && !inEndZone;
    }
};

/// Where a contour's Feret widths lie (in its own coordinates, mm): the
/// smallest from a point of the contour's hull straight across to the
/// opposite edge's line, the largest between two points of the hull. What a
/// cross-section view draws as the calipers of its minimum and maximum
/// diameter.
struct FeretCalipers {
    double minMm = 0.0;
    double maxMm = 0.0;
    std::array<glm::dvec2, 2> minSegment{};
    std::array<glm::dvec2, 2> maxSegment{};
};

/// The calipers of the closed polygon `contour` (>= 3 points, first not
/// repeated; fewer: all zero). Their widths are the section's
/// minDiameterMm / maxDiameterMm for its contour.
[[nodiscard]] FeretCalipers feretCalipers(const std::vector<glm::dvec2>& contour);

/// A branch's end zones (CrossSection::inEndZone): each twice the branch's
/// median inscribed radius long, or 1.5 times the radius at its end point
/// where that is larger.
struct EndZones {
    double startMm = 0.0;  ///< length from the branch's first point
    double endMm = 0.0;    ///< length back from its last point
    /// Whether point `i` of `branch` (the branch these zones are of) lies in one.
    [[nodiscard]] bool contains(const Branch& branch, std::size_t i) const noexcept;
};
[[nodiscard]] EndZones endZones(const Branch& branch);

/// The sections of every branch of `tree` (made from `mesh`), one per
/// centreline point: result[b][i] is branch b's point i. Progress is
/// reported; a stop request throws CancelledError. Throws AnalysisError for
/// a mesh that cannot be prepared (as computeCenterlines). A mesh of more
/// than kDefaultMaxTriangles is coarsened as computeCenterlines coarsens it,
/// and a wall that folds over itself is smoothed as computeCenterlines
/// smooths it by default (analyseVessels() takes CenterlineOptions'
/// maxTriangles and smoothFoldedWall for both).
[[nodiscard]] std::vector<std::vector<CrossSection>> computeSections(const scene::Mesh& mesh,
                                                                     const CenterlineTree& tree,
                                                                     const Progress& progress = {});

/// A surface's centrelines and their sections.
struct VesselAnalysis {
    CenterlineTree tree;
    /// sections[b][i]: branch b's point i (computeSections()).
    std::vector<std::vector<CrossSection>> sections;
};

/// computeCenterlines() and computeSections() with the surface prepared
/// (welded, cleaned, indexed) once for both: the same results, sooner.
/// Throws as they do.
[[nodiscard]] VesselAnalysis analyseVessels(const scene::Mesh& mesh,
                                            const CenterlineOptions& options = {},
                                            const Progress& progress = {});

}  // namespace vv::analysis
