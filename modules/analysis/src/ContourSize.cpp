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

/// Smallest and largest width of a convex polygon (in order, either way
/// round), by rotating calipers (Shamos 1978; Toussaint 1983): for each
/// edge, the vertex farthest from its line (which moves on monotonically
/// as the edges go round) gives the width across that edge, the smallest
/// of which is the smallest width; every vertex the calipers pass on the
/// way is antipodal to the edge's first corner, and the largest width is
/// the largest distance between an antipodal pair. O(n), where the
/// sections of a 1M-triangle surface have hulls of a thousand points.
/// Also where they lie: the largest width's two vertices; the smallest
/// width's far vertex and its foot on the edge's line.
struct Calipers {
    double smallest = 0.0;
    double largest = 0.0;
    cv::Point2d smallestFrom, smallestTo, largestFrom, largestTo;
};

Calipers feretWidths(const std::vector<cv::Point2f>& hull) {
    const std::size_t n = hull.size();
    Calipers c;
    if (n < 2) {
        return c;
    }
    const auto at = [&](std::size_t i) { return cv::Point2d(hull[i % n]); };
    const auto squared = [](const cv::Point2d& d) { return d.x * d.x + d.y * d.y; };
    // Twice the area of the triangle (a, b, p): the distance of p from the
    // line ab times |ab|.
    const auto across = [](const cv::Point2d& a, const cv::Point2d& b, const cv::Point2d& p) {
        const cv::Point2d e = b - a;
        const cv::Point2d d = p - a;
        return std::abs(e.x * d.y - e.y * d.x);
    };
    double largest2 = 0.0;
    const auto pair = [&](const cv::Point2d& p, const cv::Point2d& q) {
        const double d2 = squared(q - p);
        if (d2 > largest2) {
            largest2 = d2;
            c.largestFrom = p;
            c.largestTo = q;
        }
    };
    double smallest = std::numeric_limits<double>::max();
    std::size_t j = 1;
    for (std::size_t i = 0; i < n; ++i) {
        const cv::Point2d a = at(i);
        const cv::Point2d b = at(i + 1);
        pair(a, at(j));
        // On to the farthest vertex from this edge's line; at most once
        // round (a plateau, where an edge is parallel to this one, is
        // crossed: its far end is antipodal too).
        for (std::size_t steps = 0;
             steps < n && across(a, b, at(j + 1)) >= across(a, b, at(j)) && (j + 1) % n != i;
             ++steps) {
            j = (j + 1) % n;
            pair(a, at(j));
        }
        pair(b, at(j));
        const double length = std::sqrt(squared(b - a));
        if (length > 0.0 && across(a, b, at(j)) / length < smallest) {
            smallest = across(a, b, at(j)) / length;
            const cv::Point2d p = at(j);
            const cv::Point2d e = (b - a) * (1.0 / length);
            const double t = (p - a).dot(e);
            c.smallestFrom = p;
            c.smallestTo = a + e * t;
        }
    }
    c.smallest = smallest == std::numeric_limits<double>::max() ? 0.0 : smallest;
    c.largest = std::sqrt(largest2);
    return c;
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
    const Calipers calipers = feretWidths(hull);
    size.minFeret = calipers.smallest;
    size.maxFeret = calipers.largest;
    const auto back = [&origin](const cv::Point2d& p) { return origin + glm::dvec2(p.x, p.y); };
    size.minFrom = back(calipers.smallestFrom);
    size.minTo = back(calipers.smallestTo);
    size.maxFrom = back(calipers.largestFrom);
    size.maxTo = back(calipers.largestTo);
    return size;
}

bool contourHolds(const std::vector<glm::dvec2>& contour, const glm::dvec2& point) {
    if (contour.size() < 3) {
        return false;
    }
    return cv::pointPolygonTest(toCvFloat(contour, point), cv::Point2f(0.0F, 0.0F), false) >= 0.0;
}

}  // namespace vv::analysis::detail
