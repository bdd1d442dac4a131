// SPDX-License-Identifier: GPL-3.0-or-later
#include "ContourSize.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>

namespace vv::analysis::detail {
namespace {

/// OpenCV's 2-D geometry works on float points; the contour is moved to
/// `origin` (near its centre) first, so that float keeps micrometres.
std::vector<cv::Point2f> toCvFloat(const std::vector<glm::dvec2>& contour,
                                   const glm::dvec2& origin) {
    std::vector<cv::Point2f> points;
    points.reserve(contour.size());
    for (const glm::dvec2& p : contour) {
        points.emplace_back(static_cast<float>(p.x - origin.x), static_cast<float>(p.y - origin.y));
    }
    return points;
}

/// Smallest and largest width of a convex polygon: the largest is the
/// largest distance between two of its points; the smallest is found with
/// one side of the calipers on an edge (rotating calipers, Toussaint 1983).
std::pair<double, double> feretWidths(const std::vector<cv::Point2f>& hull) {
    const std::size_t n = hull.size();
    double largest = 0.0;
    double smallest = std::numeric_limits<double>::max();
    for (std::size_t i = 0; i < n; ++i) {
        const cv::Point2d a = hull[i];
        const cv::Point2d b = hull[(i + 1) % n];
        const cv::Point2d edge = b - a;
        const double length = std::hypot(edge.x, edge.y);
        double farthest = 0.0;
        for (std::size_t j = 0; j < n; ++j) {
            const cv::Point2d p = hull[j];
            largest = std::max(largest, std::hypot(p.x - a.x, p.y - a.y));
            if (length > 0.0) {
                const cv::Point2d d = p - a;
                farthest = std::max(farthest, std::abs(edge.x * d.y - edge.y * d.x) / length);
            }
        }
        if (length > 0.0) {
            smallest = std::min(smallest, farthest);
        }
    }
    return {smallest == std::numeric_limits<double>::max() ? 0.0 : smallest, largest};
}

}  // namespace

ContourSize measureContour(const std::vector<glm::dvec2>& contour) {
    ContourSize size;
    if (contour.size() < 3) {
        return size;
    }
    glm::dvec2 origin(0.0);
    for (const glm::dvec2& p : contour) {
        origin += p;
    }
    origin /= static_cast<double>(contour.size());
    const std::vector<cv::Point2f> local = toCvFloat(contour, origin);
    size.area = std::abs(cv::contourArea(local));
    size.perimeter = cv::arcLength(local, true);
    const cv::Moments moments = cv::moments(local);
    size.centroid = moments.m00 != 0.0
                        ? origin + glm::dvec2(moments.m10 / moments.m00, moments.m01 / moments.m00)
                        : origin;
    std::vector<cv::Point2f> hull;
    cv::convexHull(local, hull);
    const auto [smallest, largest] = feretWidths(hull);
    size.minFeret = smallest;
    size.maxFeret = largest;
    return size;
}

bool contourHolds(const std::vector<glm::dvec2>& contour, const glm::dvec2& point) {
    if (contour.size() < 3) {
        return false;
    }
    return cv::pointPolygonTest(toCvFloat(contour, point), cv::Point2f(0.0F, 0.0F), false) >= 0.0;
}

}  // namespace vv::analysis::detail
