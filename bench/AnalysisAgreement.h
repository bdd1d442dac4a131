// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// How well vessel analysis (vv/analysis) of a surface agrees with the vessel
// tree it was built from (vv/demo/DemoTree.h): the leaves whose ends are
// found, the centreline's distance from the constructed axes and the
// sections' equivalent diameters against the constructed radii. And the
// synthetic CTA (vv/demo/DemoCtSeries.h) segmented as `vesselview-cli
// render` segments a DICOM series; and the aneurysm phantom's measures
// against its analytic truth. Used by bench/analysis_accuracy (--demo,
// --cta; docs/benchmarks/analysis.md) and tests/analysis.

#include <cstddef>
#include <filesystem>
#include <functional>
#include <vector>

#include "vv/analysis/Centerlines.h"
#include "vv/analysis/Sections.h"
#include "vv/demo/AneurysmPhantom.h"
#include "vv/demo/DemoCtSeries.h"
#include "vv/demo/DemoTree.h"
#include "vv/scene/Mesh.h"

namespace vv::bench {

struct ConstructionAgreement {
    std::size_t segments = 0;  ///< of the constructed tree
    std::size_t leaves = 0;    ///< its segments without children
    /// Leaves with an end of the centreline tree within 2 r + slack of
    /// their tip (a closed tip's surface is r past it).
    std::size_t leavesFound = 0;
    /// Ends near neither a leaf's tip nor the root's start (2 r + slack).
    std::size_t endsElsewhere = 0;
    std::size_t sectionsOk = 0;   ///< sections with a closed contour
    std::size_t sectionsAll = 0;  ///< one per centreline point
    /// Centreline points compared: those whose section lies outside the end
    /// zones (caps and junctions, where the construction has no axis).
    std::size_t compared = 0;
    /// The distance from each compared point to the nearest constructed
    /// centreline, per that segment's radius: median and 95th percentile.
    double offAxisMedian = 0.0;
    double offAxisP95 = 0.0;
    /// The same for the centroid of each compared point's closed contour
    /// (the lumen's centre as the surface has it): near offAxisMedian when
    /// the surface itself lies off the constructed axes, near 0 when the
    /// centreline strays from a well-placed lumen.
    double centroidOffAxisMedian = 0.0;
    /// The equivalent diameter of each compared point's closed section
    /// against twice the nearest segment's radius, relative (d / 2r - 1):
    /// the median (signed) and the 95th percentile of its magnitude.
    double diameterErrorMedian = 0.0;
    double diameterErrorP95 = 0.0;
};

/// Compares `tree` and `sections` (computeSections of it) with the
/// construction `truth`. `slackMm` widens the end matching (a voxel of a
/// segmented volume). Percentiles are NaN where nothing was compared.
[[nodiscard]] ConstructionAgreement compareWithConstruction(
    const demo::VesselTree& truth, const analysis::CenterlineTree& tree,
    const std::vector<std::vector<analysis::CrossSection>>& sections, double slackMm = 0.0);

/// The aneurysm phantom (vv/demo/AneurysmPhantom.h) measured.
struct AneurysmAgreement {
    std::size_t branches = 0;
    std::size_t ends = 0;
    /// The widest trunk section that measures the vessel: its equivalent
    /// diameter against the true maximum (relative, d / D - 1), where it is
    /// (its centre's abscissa along the true trunk axis) and the true radius
    /// there; NaN without one.
    double maxDiameterError = 0.0;
    double widestAbscissaMm = 0.0;
    double widestTrueRadiusMm = 0.0;
    /// The largest distance from the true axes of a centreline point two
    /// radii clear of the ends and the bifurcation point, per its part's
    /// radius (the trunk's r on the trunk, the bulge included); how many
    /// points that took in.
    double worstAxisDistancePerR = 0.0;
    std::size_t axisPoints = 0;
    /// The mesh's own largest distance from the true wall over the same
    /// stretch (along the radius of the nearest part's axis, sampled 45
    /// times a facet), per its part's radius: how far the input itself is
    /// from the analytic surface. A centreline is only as near the true axis
    /// as its wall is near the true wall: on a coarse mesh the facets' chords
    /// lie inside the circle and a decimated mesh's are uneven around it.
    double worstWallDistancePerR = 0.0;
    /// The abscissa where branch 0's path crosses the bifurcation point's
    /// plane (continued straight when the paths part before it) against the
    /// true distance from the source's end (trunk length, plus the trunk's
    /// radius for a closed tip), relative.
    double trunkLengthError = 0.0;
    /// The root branch's children: the largest and the smallest x of their
    /// last points (the ends towards +x and -x).
    double childEndMaxX = 0.0;
    double childEndMinX = 0.0;
    std::size_t bifurcations = 0;
    /// The first bifurcation's angle minus the true one, degrees; NaN without one.
    double angleErrorDeg = 0.0;
};

/// The largest of `distance(q)` over points q on every facet of `mesh` (a
/// barycentric lattice of 8 steps along each edge: corners, edges and
/// inside, 45 points a facet), NaNs (points left out) skipped; 0 when none
/// is counted. How far a mesh's own facets lie from a phantom's true wall.
[[nodiscard]] double worstOverFacets(const scene::Mesh& mesh,
                                     const std::function<double(const glm::dvec3&)>& distance);

/// Measures `tree` and `sections` (computeSections of it) of `phantom`'s mesh.
[[nodiscard]] AneurysmAgreement measureAneurysm(
    const demo::AneurysmPhantom& phantom, const analysis::CenterlineTree& tree,
    const std::vector<std::vector<analysis::CrossSection>>& sections);

/// Writes `ct`'s volume as a CT series into `folder` (dicom::writeCtSeries)
/// and loads it back as `vesselview-cli render FOLDER` does:
/// segmentation::loadSceneSource with the default options (the CT
/// threshold range, the largest component, bone removal, the surface's
/// smoothing and decimation). Returns the segmented surface ("vessels", LPS
/// mm, the frame the tree is built in). Throws as both (IoError,
/// FormatError, InvalidArgumentError).
[[nodiscard]] scene::Mesh segmentAsRenderDoes(const demo::DemoCt& ct,
                                              const std::filesystem::path& folder);

}  // namespace vv::bench
