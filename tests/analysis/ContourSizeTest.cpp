// SPDX-License-Identifier: GPL-3.0-or-later
// The Feret widths of a section's contour: an ellipse's are its axes, a
// rotated square's its side and diagonal, and on random convex and
// star-shaped polygons they are what trying every direction and every pair
// of points gives.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>
#include <random>
#include <vector>

#include "ContourSize.h"

namespace vv::analysis::detail {
namespace {

std::vector<glm::dvec2> ellipse(double a, double b, int points, double turn) {
    std::vector<glm::dvec2> contour;
    for (int i = 0; i < points; ++i) {
        const double t = glm::two_pi<double>() * i / points;
        const glm::dvec2 p(a * std::cos(t), b * std::sin(t));
        contour.emplace_back(p.x * std::cos(turn) - p.y * std::sin(turn) + 30.0,
                             p.x * std::sin(turn) + p.y * std::cos(turn) - 12.0);
    }
    return contour;
}

/// The widths by brute force: the largest distance between two points, and
/// the smallest extent over 20 000 directions (a polygon's smallest width
/// lies across one of its edges, so this is within the directions' spacing).
std::pair<double, double> bruteWidths(const std::vector<glm::dvec2>& contour) {
    double largest = 0.0;
    for (const glm::dvec2& p : contour) {
        for (const glm::dvec2& q : contour) {
            largest = std::max(largest, glm::length(p - q));
        }
    }
    double smallest = 1e300;
    constexpr int kDirections = 20'000;
    for (int k = 0; k < kDirections; ++k) {
        const double t = glm::pi<double>() * k / kDirections;
        const glm::dvec2 u(std::cos(t), std::sin(t));
        double lo = 1e300;
        double hi = -1e300;
        for (const glm::dvec2& p : contour) {
            lo = std::min(lo, glm::dot(p, u));
            hi = std::max(hi, glm::dot(p, u));
        }
        smallest = std::min(smallest, hi - lo);
    }
    return {smallest, largest};
}

TEST(ContourSize, AnEllipsesFeretWidthsAreItsAxes) {
    const ContourSize size = measureContour(ellipse(10.0, 4.0, 3000, 0.7));
    EXPECT_NEAR(size.minFeret, 8.0, 1e-3);
    EXPECT_NEAR(size.maxFeret, 20.0, 1e-3);
    // The calipers lie along the axes, through the centre (30, -12): the
    // major one turned by 0.7, the minor one across it.
    const glm::dvec2 centre(30.0, -12.0);
    const glm::dvec2 major(std::cos(0.7), std::sin(0.7));
    const glm::dvec2 maxMid = 0.5 * (size.maxFrom + size.maxTo);
    const glm::dvec2 minMid = 0.5 * (size.minFrom + size.minTo);
    EXPECT_NEAR(glm::length(size.maxTo - size.maxFrom), size.maxFeret, 1e-9);
    EXPECT_NEAR(glm::length(size.minTo - size.minFrom), size.minFeret, 1e-6);
    EXPECT_NEAR(glm::length(maxMid - centre), 0.0, 0.02);
    EXPECT_NEAR(glm::length(minMid - centre), 0.0, 0.02);
    EXPECT_NEAR(std::abs(glm::dot(glm::normalize(size.maxTo - size.maxFrom), major)), 1.0, 1e-4);
    EXPECT_NEAR(std::abs(glm::dot(glm::normalize(size.minTo - size.minFrom), major)), 0.0, 1e-2);
}

TEST(ContourSize, ASquaresFeretWidthsAreItsSideAndDiagonal) {
    const double turn = 0.3;
    std::vector<glm::dvec2> square;
    for (const glm::dvec2 corner :
         {glm::dvec2(-1, -1), glm::dvec2(1, -1), glm::dvec2(1, 1), glm::dvec2(-1, 1)}) {
        square.emplace_back(corner.x * std::cos(turn) - corner.y * std::sin(turn),
                            corner.x * std::sin(turn) + corner.y * std::cos(turn));
    }
    const ContourSize size = measureContour(square);
    EXPECT_NEAR(size.minFeret, 2.0, 1e-5);
    EXPECT_NEAR(size.maxFeret, 2.0 * std::sqrt(2.0), 1e-5);
}

TEST(ContourSize, RandomPolygonsWidthsAreTheBruteForceOnes) {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> radius(2.0, 9.0);
    std::uniform_int_distribution<int> count(3, 60);
    for (int polygon = 0; polygon < 40; ++polygon) {
        // Star-shaped around the origin: points at increasing angles.
        const int n = count(random);
        std::vector<glm::dvec2> contour;
        for (int i = 0; i < n; ++i) {
            const double t = glm::two_pi<double>() * (i + 0.5) / n;
            const double r = polygon % 2 == 0 ? 5.0 : radius(random);
            contour.emplace_back(r * std::cos(t), 0.4 * r * std::sin(t));
        }
        const ContourSize size = measureContour(contour);
        const auto [smallest, largest] = bruteWidths(contour);
        EXPECT_NEAR(size.maxFeret, largest, 1e-4) << polygon;
        EXPECT_NEAR(size.minFeret, smallest, 2e-3 * largest) << polygon;
        EXPECT_LE(size.minFeret, smallest + 1e-4) << polygon;
        // The largest caliper joins two of the polygon's points; the smallest
        // runs from one of them, as long as the width.
        const auto isVertex = [&contour](const glm::dvec2& p) {
            return std::any_of(contour.begin(), contour.end(),
                               [&p](const glm::dvec2& q) { return glm::length(p - q) < 1e-4; });
        };
        EXPECT_TRUE(isVertex(size.maxFrom) && isVertex(size.maxTo)) << polygon;
        EXPECT_TRUE(isVertex(size.minFrom)) << polygon;
        EXPECT_NEAR(glm::length(size.minTo - size.minFrom), size.minFeret, 1e-4) << polygon;
    }
}

}  // namespace
}  // namespace vv::analysis::detail
