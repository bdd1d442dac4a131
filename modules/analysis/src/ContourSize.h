// SPDX-License-Identifier: GPL-3.0-or-later
// Private to vv::analysis: the size of a closed plane contour, by OpenCV's
// 2-D geometry (area, perimeter, convex hull, point in polygon) plus the
// rotating calipers over the hull for the Feret widths, which OpenCV lacks.
#pragma once

#include <glm/glm.hpp>
#include <vector>

namespace vv::analysis::detail {

struct ContourSize {
    double area = 0.0;
    double perimeter = 0.0;
    double minFeret = 0.0;  ///< smallest width over all directions
    double maxFeret = 0.0;  ///< largest width (the hull's diameter)
    /// Where they lie: the smallest width from a hull vertex to its foot on
    /// the opposite edge's line, the largest between two hull vertices.
    glm::dvec2 minFrom{0.0}, minTo{0.0}, maxFrom{0.0}, maxTo{0.0};
    glm::dvec2 centroid{0.0};
};

/// The size of the closed polygon `contour` (>= 3 points, first not repeated).
[[nodiscard]] ContourSize measureContour(const std::vector<glm::dvec2>& contour);

/// Whether `point` lies inside or on the closed polygon `contour`.
[[nodiscard]] bool contourHolds(const std::vector<glm::dvec2>& contour, const glm::dvec2& point);

}  // namespace vv::analysis::detail
