// SPDX-License-Identifier: GPL-3.0-or-later
// The curved reformation along a path and a section's plane, on a phantom
// whose truth is known: a tube of radius 3 mm bent along a quarter circle,
// on an oblique, sheared grid. The path straightened keeps the lumen in the
// middle row at every turn about it; rows beyond the wall are background; a
// section across the tube shows a disc of the tube's area.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <limits>
#include <vector>

#include "Phantom.h"
#include "vv/core/Error.h"
#include "vv/slices/CurvedReformation.h"
#include "vv/slices/Reslice.h"

namespace vv::slices {
namespace {

constexpr double kBend = 25.0;   // the arc's radius, mm
constexpr double kRadius = 3.0;  // the tube's

/// The arc in the plane z = 20 around (0, 0, 20), from angle 0 to 90 degrees.
glm::dvec3 arcAt(double angle) {
    return {kBend * std::cos(angle), kBend * std::sin(angle), 20.0};
}

double distanceToArc(const glm::dvec3& p) {
    const double angle = std::clamp(std::atan2(p.y, p.x), 0.0, glm::half_pi<double>());
    return glm::distance(p, arcAt(angle));
}

scene::Volume bentTube() {
    const glm::ivec3 dims(64, 64, 24);
    const glm::dmat4 geometry = test::gridGeometry(
        {0.6, 0.6, 0.8}, test::rotationAbout({0.2, 0.1, 1.0}, 12.0), 0.05, {-6.0, -6.0, 10.0});
    scene::Volume volume(dims, scene::VoxelType::Int16);
    volume.setIndexToWorld(geometry);
    for (int k = 0; k < dims.z; ++k) {
        for (int j = 0; j < dims.y; ++j) {
            for (int i = 0; i < dims.x; ++i) {
                if (distanceToArc(volume.worldPosition({i, j, k})) <= kRadius) {
                    volume.setValueAt(volume.index(i, j, k), 1000.0F);
                }
            }
        }
    }
    return volume;
}

std::vector<glm::dvec3> arcPath() {
    std::vector<glm::dvec3> points;
    const int steps = static_cast<int>(kBend * glm::half_pi<double>() / 0.5);
    for (int s = 0; s <= steps; ++s) {
        points.push_back(arcAt(glm::half_pi<double>() * s / steps));
    }
    return points;
}

TEST(CurvedReformation, TheLumenRunsDownTheMiddleRowAtEveryTurn) {
    const scene::Volume volume = bentTube();
    const std::vector<glm::dvec3> path = arcPath();
    const double half = 10.0;
    const double spacing = 0.5;
    for (const double degrees : {0.0, 45.0, 90.0, 150.0}) {
        const Image<float> cpr = curvedReformation(volume, path, half, spacing, degrees);
        ASSERT_EQ(static_cast<std::size_t>(cpr.width()), path.size());
        ASSERT_EQ(cpr.height(), 41);
        const int middle = cpr.height() / 2;
        // Away from the ends (where the tube's caps are), the middle row is
        // lumen; two voxels beyond the wall is background on both sides.
        const int off = static_cast<int>(std::ceil((kRadius + 1.6) / spacing));
        for (int c = 10; c < cpr.width() - 10; ++c) {
            EXPECT_GT(cpr(c, middle), 900.0F) << degrees << " deg, column " << c;
            EXPECT_LT(cpr(c, middle - off), 100.0F) << degrees << " deg, column " << c;
            EXPECT_LT(cpr(c, middle + off), 100.0F) << degrees << " deg, column " << c;
        }
        // The lumen's width across it is the tube's diameter (within a row
        // and the grid's partial voxels).
        int inside = 0;
        for (int r = 0; r < cpr.height(); ++r) {
            inside += cpr(cpr.width() / 2, r) > 500.0F ? 1 : 0;
        }
        EXPECT_NEAR(inside * spacing, 2.0 * kRadius, 1.2) << degrees << " deg";
    }
}

TEST(CurvedReformation, ASectionPlaneAcrossTheTubeShowsItsDisc) {
    const scene::Volume volume = bentTube();
    const auto angle = glm::quarter_pi<double>();
    const glm::dvec3 centre = arcAt(angle);
    const glm::dvec3 tangent(-std::sin(angle), std::cos(angle), 0.0);
    const glm::dvec3 up(0.0, 0.0, 1.0);
    const glm::dvec3 right = glm::cross(up, tangent);
    const SlicePlane plane = sectionPlane(centre, right, up, 16.0, 160);
    EXPECT_NEAR(glm::distance(plane.worldAt(79.5, 79.5), centre), 0.0, 1e-9) << "centred";
    EXPECT_NEAR(std::abs(glm::dot(plane.normal(), tangent)), 1.0, 1e-9) << "across the tube";
    const Image<float> section = reslice(volume, plane);
    double area = 0.0;
    for (int y = 0; y < section.height(); ++y) {
        for (int x = 0; x < section.width(); ++x) {
            area += section(x, y) > 500.0F ? plane.pixelSpacing * plane.pixelSpacing : 0.0;
        }
    }
    const double truth = glm::pi<double>() * kRadius * kRadius;
    EXPECT_NEAR(area, truth, 0.12 * truth);
    EXPECT_GT(section(80, 80), 900.0F);
    EXPECT_LT(section(2, 2), 100.0F);
}

TEST(CurvedReformation, BadPathsAndSizesAreClearErrors) {
    const scene::Volume volume = bentTube();
    std::vector<glm::dvec3> path = arcPath();
    EXPECT_THROW((void)curvedReformation(volume, {path.front()}, 10.0, 0.5, 0.0),
                 InvalidArgumentError);
    EXPECT_THROW((void)curvedReformation(volume, path, 0.0, 0.5, 0.0), InvalidArgumentError);
    EXPECT_THROW((void)curvedReformation(volume, path, 10.0, -1.0, 0.0), InvalidArgumentError);
    EXPECT_THROW((void)curvedReformation(volume, path, 1e9, 0.5, 0.0), InvalidArgumentError);
    path[3].y = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW((void)curvedReformation(volume, path, 10.0, 0.5, 0.0), InvalidArgumentError);
}

}  // namespace
}  // namespace vv::slices
