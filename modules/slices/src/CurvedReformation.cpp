// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/slices/CurvedReformation.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include "vv/core/Error.h"
#include "vv/slices/Reslice.h"

namespace vv::slices {

namespace {

constexpr int kMaxSide = 16384;

/// Any unit vector perpendicular to the unit `t`.
glm::dvec3 perpendicular(const glm::dvec3& t) {
    const glm::dvec3 axis = std::abs(t.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    return glm::normalize(glm::cross(t, axis));
}

bool finite(const glm::dvec3& p) {
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

}  // namespace

Image<float> curvedReformation(const scene::Volume& volume, const std::vector<glm::dvec3>& points,
                               double halfWidthMm, double rowSpacingMm, double degrees,
                               const std::stop_token& stop) {
    if (points.size() < 2 || points.size() > static_cast<std::size_t>(kMaxSide)) {
        throw InvalidArgumentError("a curved reformation needs 2 to 16384 path points");
    }
    if (!(halfWidthMm > 0.0) || !std::isfinite(halfWidthMm) || !(rowSpacingMm > 0.0) ||
        !std::isfinite(rowSpacingMm) || !std::isfinite(degrees)) {
        throw InvalidArgumentError(
            "a curved reformation needs a positive, finite width and row spacing");
    }
    for (const glm::dvec3& p : points) {
        if (!finite(p)) {
            throw InvalidArgumentError("a curved reformation's path is not finite");
        }
    }
    const double rowsExact = 2.0 * halfWidthMm / rowSpacingMm + 1.0;
    if (rowsExact > kMaxSide) {
        throw InvalidArgumentError("a curved reformation of more than 16384 rows");
    }
    const int rows = static_cast<int>(std::lround(rowsExact));
    const auto tangentAt = [&points](std::size_t i) {
        const glm::dvec3 d =
            points[std::min(points.size() - 1, i + 1)] - points[i == 0 ? 0 : i - 1];
        return glm::length(d) > 0.0 ? glm::normalize(d) : glm::dvec3(0, 0, 1);
    };
    Image<float> out(static_cast<int>(points.size()), rows);
    glm::dvec3 across = perpendicular(tangentAt(0));
    const double angle = degrees * glm::pi<double>() / 180.0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const glm::dvec3 t = tangentAt(i);
        const glm::dvec3 projected = across - glm::dot(across, t) * t;
        across = glm::length(projected) > 1e-9 ? glm::normalize(projected) : perpendicular(t);
        const glm::dvec3 d = std::cos(angle) * across + std::sin(angle) * glm::cross(t, across);
        SlicePlane column;
        column.width = 1;
        column.height = rows;
        column.pixelSpacing = rowSpacingMm;
        column.right = t;
        column.down = -d;
        column.origin = points[i] + halfWidthMm * d;
        const Image<float> line = reslice(volume, column, Interpolation::Linear, stop);
        for (int r = 0; r < rows; ++r) {
            out(static_cast<int>(i), r) = line(0, r);
        }
    }
    return out;
}

SlicePlane sectionPlane(const glm::dvec3& centre, const glm::dvec3& right, const glm::dvec3& up,
                        double fieldMm, int pixels) {
    SlicePlane plane;
    plane.width = pixels;
    plane.height = pixels;
    plane.pixelSpacing = fieldMm / pixels;
    plane.right = right;
    plane.down = -up;
    const double half = 0.5 * (pixels - 1) * plane.pixelSpacing;
    plane.origin = centre - half * plane.right - half * plane.down;
    return plane;
}

}  // namespace vv::slices
