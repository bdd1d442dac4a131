// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Places on a centreline tree and paths through it, across bifurcations:
// what a planner measures along (issue 35). A place is a branch and an
// abscissa on it, so it stays where it is whichever path is chosen; a path
// runs from one place (an end) to another through the bifurcation where the
// two places' routes from the tree's source part, and measures along the
// centrelines.

#include <glm/vec3.hpp>
#include <optional>
#include <vector>

#include "vv/analysis/Centerlines.h"

namespace vv::planning {

/// A place on a centreline tree: a branch (CenterlineTree::branches index)
/// and an abscissa on it (the tree's, from its source, as
/// CenterlinePoint::abscissaMm).
struct TreeLocation {
    int branch = 0;
    double abscissaMm = 0.0;
};

/// The centreline at a place, interpolated between its two nearest points.
struct CenterlineSample {
    glm::dvec3 position{0.0};  ///< mm
    glm::dvec3 tangent{0.0};   ///< unit, away from the tree's source
    double radiusMm = 0.0;     ///< the maximal inscribed sphere's
};

/// The place's branch checked and its abscissa clamped to the branch.
/// Throws InvalidArgumentError for a branch out of range or a non-finite
/// abscissa.
[[nodiscard]] TreeLocation clampedLocation(const analysis::CenterlineTree& tree,
                                           const TreeLocation& at);

/// The centreline at `at` (clamped to its branch). Throws as clampedLocation.
[[nodiscard]] CenterlineSample sampleAt(const analysis::CenterlineTree& tree,
                                        const TreeLocation& at);

/// The place on the tree nearest to `point`, and how far it is.
struct NearestLocation {
    TreeLocation location;
    double distanceMm = 0.0;
};
/// The centreline place nearest to `point` (on the polylines between the
/// points). Throws InvalidArgumentError for a tree without branches or a
/// non-finite point.
[[nodiscard]] NearestLocation nearestLocation(const analysis::CenterlineTree& tree,
                                              const glm::dvec3& point);

/// The length along the centrelines from `a` to `b`: through the
/// bifurcation where their routes from the source part when they lie on
/// different routes. Throws as clampedLocation.
[[nodiscard]] double lengthAlong(const analysis::CenterlineTree& tree, const TreeLocation& a,
                                 const TreeLocation& b);

/// Where the tree's end `end` (CenterlineTree::ends index) lies: the source
/// (end 0) at the first point of branch 0, any other at the last point of
/// the branch that ends there. Throws InvalidArgumentError for an end out
/// of range or one no branch reaches.
[[nodiscard]] TreeLocation endLocation(const analysis::CenterlineTree& tree, int end);

/// The end farthest from the source (end 0) along the centrelines: where the
/// path a planner measures first (the main vessel) runs to. -1 for a tree
/// with fewer than two ends or none reached by a branch.
[[nodiscard]] int farthestEnd(const analysis::CenterlineTree& tree);

/// One branch's part of a path: from abscissa `fromMm` to `toMm` of the
/// branch (fromMm > toMm: the path runs against the branch, towards the
/// source).
struct PathStretch {
    int branch = 0;
    double fromMm = 0.0;
    double toMm = 0.0;
};

/// A point of a path: a centreline point of the tree where the path passes
/// it, with the path's own abscissa.
struct PathPoint {
    int branch = 0;
    std::size_t pointIndex = 0;  ///< into the branch's points (and its sections)
    double pathMm = 0.0;         ///< along the path from its start
};

/// A path through the tree from one place to another.
class VesselPath {
  public:
    /// The path from `from` to `to` (both clamped to their branches). Throws
    /// as clampedLocation.
    [[nodiscard]] static VesselPath between(const analysis::CenterlineTree& tree,
                                            const TreeLocation& from, const TreeLocation& to);
    /// The path from end `fromEnd` to end `toEnd`. Throws InvalidArgumentError
    /// for an end out of range or the same end twice.
    [[nodiscard]] static VesselPath betweenEnds(const analysis::CenterlineTree& tree, int fromEnd,
                                                int toEnd);

    [[nodiscard]] const std::vector<PathStretch>& stretches() const noexcept { return stretches_; }
    [[nodiscard]] double lengthMm() const noexcept { return lengthMm_; }
    [[nodiscard]] TreeLocation from() const;
    [[nodiscard]] TreeLocation to() const;

    /// The place at path abscissa `s` (clamped to [0, lengthMm()]).
    [[nodiscard]] TreeLocation locationAt(double s) const;
    /// The path abscissa of `at`, nullopt when the path does not pass it. A
    /// bifurcation is the end of its parent and the start of each child: it
    /// is found as either.
    [[nodiscard]] std::optional<double> abscissaOf(const analysis::CenterlineTree& tree,
                                                   const TreeLocation& at) const;
    /// The tree's centreline points along the path, in its order, each once
    /// (a child's first point repeats its parent's last: it is left out).
    [[nodiscard]] std::vector<PathPoint> points(const analysis::CenterlineTree& tree) const;

  private:
    std::vector<PathStretch> stretches_;
    double lengthMm_ = 0.0;
};

}  // namespace vv::planning
