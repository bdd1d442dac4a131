// SPDX-License-Identifier: GPL-3.0-or-later
// Private to vv::analysis: how far past one cut between two slabs of the
// Voronoi diagram a slab takes points, per column of the plane across the
// slab's axis. A wide vessel needs a wide margin (its inscribed spheres
// reach far past the cut); a thin one beside it, at the same height, only
// a narrow one. One margin for the whole cut, set by its widest vessel,
// made the demo tree's middle slabs twice their core's points.
#pragma once

#include <array>
#include <glm/glm.hpp>
#include <vector>

namespace vv::analysis::detail {

class CutMargins {
  public:
    /// No columns: every margin is 0.
    CutMargins() = default;
    /// A grid of square columns over [lo, hi] in the two axes other than
    /// `axis`, `columnsPerSide` along the longer one (at least 1), each with
    /// margin `initial` (>= 0).
    CutMargins(int axis, const glm::dvec3& lo, const glm::dvec3& hi, int columnsPerSide,
               double initial);

    /// The margin of the column `p` lies in (a point beyond the grid: its
    /// nearest column's).
    [[nodiscard]] double at(const glm::dvec3& p) const;
    /// The smallest margin of the columns that the box of the sphere of
    /// `radius` about `centre` covers, across the axis: a point inside that
    /// sphere lies in one of them.
    [[nodiscard]] double leastOver(const glm::dvec3& centre, double radius) const;
    /// Raises the margin of every column the sphere's box covers to at least `to`.
    void raise(const glm::dvec3& centre, double radius, double to);
    /// Raises every column to at least `to`.
    void raiseAll(double to);
    /// The largest margin of any column (0 without columns).
    [[nodiscard]] double largest() const;

  private:
    /// The column range [first, last] along the grid's axis `k` that the
    /// interval [a - r, a + r] covers, clamped to the grid.
    [[nodiscard]] std::array<int, 2> span(int k, double a, double r) const;
    template <class Visit>
    void forEachColumn(const glm::dvec3& centre, double radius, const Visit& visit) const;

    std::array<int, 2> axes_{0, 0};
    glm::dvec2 origin_{0.0};
    double cell_ = 1.0;
    std::array<int, 2> count_{0, 0};
    std::vector<double> margin_;
};

}  // namespace vv::analysis::detail
