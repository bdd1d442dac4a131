// SPDX-License-Identifier: GPL-3.0-or-later
#include "CutMargins.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vv::analysis::detail {

CutMargins::CutMargins(int axis, const glm::dvec3& lo, const glm::dvec3& hi, int columnsPerSide,
                       double initial)
    : axes_{(axis + 1) % 3, (axis + 2) % 3} {
    const glm::dvec2 low(lo[axes_[0]], lo[axes_[1]]);
    const glm::dvec2 size = glm::max(glm::dvec2(hi[axes_[0]], hi[axes_[1]]) - low, 0.0);
    const int perSide = std::max(columnsPerSide, 1);
    origin_ = low;
    cell_ = std::max(std::max(size.x, size.y) / perSide, std::numeric_limits<double>::min());
    for (int k = 0; k < 2; ++k) {
        const double columns = std::isfinite(size[k] / cell_) ? std::ceil(size[k] / cell_) : 1.0;
        count_[k] = std::clamp(static_cast<int>(columns), 1, perSide);
    }
    margin_.assign(static_cast<std::size_t>(count_[0]) * static_cast<std::size_t>(count_[1]),
                   std::max(initial, 0.0));
}

std::array<int, 2> CutMargins::span(int k, double a, double r) const {
    const auto column = [&](double x) {
        const double c = std::floor((x - origin_[k]) / cell_);
        // NaN and the far side of the grid go to its last column.
        return !(c < count_[k] - 1) ? count_[k] - 1 : (c < 0.0 ? 0 : static_cast<int>(c));
    };
    return {column(a - r), column(a + r)};
}

template <class Visit>
void CutMargins::forEachColumn(const glm::dvec3& centre, double radius, const Visit& visit) const {
    if (margin_.empty()) {
        return;
    }
    const auto u = span(0, centre[axes_[0]], radius);
    const auto v = span(1, centre[axes_[1]], radius);
    for (int j = v[0]; j <= v[1]; ++j) {
        for (int i = u[0]; i <= u[1]; ++i) {
            visit(static_cast<std::size_t>(j) * static_cast<std::size_t>(count_[0]) +
                  static_cast<std::size_t>(i));
        }
    }
}

double CutMargins::at(const glm::dvec3& p) const {
    double margin = 0.0;
    forEachColumn(p, 0.0, [&](std::size_t c) { margin = margin_[c]; });
    return margin;
}

double CutMargins::leastOver(const glm::dvec3& centre, double radius) const {
    double least = margin_.empty() ? 0.0 : std::numeric_limits<double>::infinity();
    forEachColumn(centre, radius, [&](std::size_t c) { least = std::min(least, margin_[c]); });
    return least;
}

void CutMargins::raise(const glm::dvec3& centre, double radius, double to) {
    forEachColumn(centre, radius, [&](std::size_t c) { margin_[c] = std::max(margin_[c], to); });
}

void CutMargins::raiseAll(double to) {
    for (double& m : margin_) {
        m = std::max(m, to);
    }
}

double CutMargins::largest() const {
    return margin_.empty() ? 0.0 : *std::max_element(margin_.begin(), margin_.end());
}

}  // namespace vv::analysis::detail
