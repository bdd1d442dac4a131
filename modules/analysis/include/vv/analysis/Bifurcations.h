// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Angles where a centreline tree branches, and between two stretches of
// centreline the user chooses.

#include <glm/glm.hpp>
#include <vector>

#include "vv/analysis/Centerlines.h"

namespace vv::analysis {

/// Where a branch ends in two or more children.
struct Bifurcation {
    int parent = 0;             ///< CenterlineTree::branches index
    std::vector<int> children;  ///< in branch order
    glm::dvec3 position{0.0};   ///< where the paths part (the parent's last point), mm
    /// Unit directions, all pointing away from the parent's source: the
    /// parent's over the stretch from 3 to 1 of its radii before the
    /// bifurcation; each child's from 2 to 4 parent radii after it, so the
    /// centreline's swing from the shared lumen onto the child's axis does
    /// not count.
    glm::dvec3 parentDirection{0.0};
    std::vector<glm::dvec3> childDirections;
    /// Between the first two children's directions, degrees in [0, 180].
    double angleDeg = 0.0;
    /// Each child's direction against the parent's, degrees in [0, 180].
    std::vector<double> deviationDeg;
};

/// The bifurcations of `tree`, parents before children.
[[nodiscard]] std::vector<Bifurcation> findBifurcations(const CenterlineTree& tree);

/// The direction of branch `branch` over its abscissae [from, to] (the
/// principal axis of its points there, oriented from `from` to `to`).
/// Throws InvalidArgumentError for a branch index out of range or a stretch
/// with fewer than two points.
[[nodiscard]] glm::dvec3 directionOver(const CenterlineTree& tree, int branch, double from,
                                       double to);

/// The principal axis of `points` (the direction of their largest spread,
/// by power iteration on their covariance), unit, oriented from the first
/// point towards the last; zero for fewer than two points or where the first
/// and the last coincide.
[[nodiscard]] glm::dvec3 principalDirection(const std::vector<glm::dvec3>& points);

/// The angle in degrees ([0, 180]) between two directions.
[[nodiscard]] double angleBetweenDeg(const glm::dvec3& a, const glm::dvec3& b);

}  // namespace vv::analysis
