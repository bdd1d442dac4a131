// SPDX-License-Identifier: GPL-3.0-or-later
#include "SegmentationAccuracy.h"

#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkStaticCellLocator.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "vv/core/Error.h"
#include "vv/meshio/vtkext/VtkConvert.h"

namespace vv::bench {

namespace {

constexpr double kBorderVoxels = 1.5;
constexpr int kAround = 32;

/// True when `world` lies at least kBorderVoxels voxels inside the volume's faces.
bool inside(const scene::Volume& volume, const glm::dvec3& world) {
    const glm::dvec3 ijk(volume.worldToIndex() * glm::dvec4(world, 1.0));
    const glm::dvec3 last(volume.dims() - 1);
    return glm::all(glm::greaterThanEqual(ijk, glm::dvec3(kBorderVoxels))) &&
           glm::all(glm::lessThanEqual(ijk, last - kBorderVoxels));
}

/// Two unit vectors perpendicular to `axis` and to each other.
std::pair<glm::dvec3, glm::dvec3> perpendiculars(const glm::dvec3& axis) {
    const glm::dvec3 helper =
        std::abs(axis.x) < 0.9 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0);
    const glm::dvec3 u = glm::normalize(glm::cross(axis, helper));
    return {u, glm::cross(axis, u)};
}

}  // namespace

SegmentationAccuracy measureSegmentation(const demo::VesselPhantom& phantom,
                                         const scene::LabelMap& labels,
                                         const scene::Mesh& surface) {
    const scene::Volume& volume = phantom.volume;
    if (labels.dims != volume.dims() || labels.labels.size() != phantom.truth.size()) {
        throw InvalidArgumentError("the label map is not on the phantom's grid");
    }
    SegmentationAccuracy result;
    std::size_t both = 0;
    std::size_t segmented = 0;
    std::size_t truth = 0;
    for (std::size_t n = 0; n < phantom.truth.size(); ++n) {
        const bool s = labels.labels[n] != 0;
        const bool t = phantom.truth[n] != 0;
        both += s && t ? 1 : 0;
        segmented += s ? 1 : 0;
        truth += t ? 1 : 0;
    }
    result.dice = segmented + truth > 0
                      ? 2.0 * static_cast<double>(both) / static_cast<double>(segmented + truth)
                      : 0.0;

    // Surface distances, both ways.
    std::vector<double> distances;
    for (const glm::vec3& p : surface.positions) {
        if (inside(volume, glm::dvec3(p))) {
            distances.push_back(std::abs(phantom.signedDistance(glm::dvec3(p))));
        }
    }
    if (surface.triangleCount() > 0) {
        const vtkSmartPointer<vtkPolyData> poly = meshio::detail::polyDataFromMesh(surface);
        vtkNew<vtkStaticCellLocator> locator;
        locator->SetDataSet(poly);
        locator->BuildLocator();
        const glm::dvec3 spacing = volume.spacing();
        const double step = 0.5 * std::min({spacing.x, spacing.y, spacing.z});
        for (const demo::PhantomVessel& vessel : phantom.vessels) {
            for (std::size_t i = 0; i + 1 < vessel.centerline.size(); ++i) {
                const glm::dvec3 a = vessel.centerline[i];
                const glm::dvec3 b = vessel.centerline[i + 1];
                const double length = glm::length(b - a);
                if (!(length > 0.0)) {
                    continue;
                }
                const glm::dvec3 axis = (b - a) / length;
                const auto [u, v] = perpendiculars(axis);
                const int steps = std::max(1, static_cast<int>(std::ceil(length / step)));
                for (int s = 0; s < steps; ++s) {
                    const glm::dvec3 centre = a + (length * s / steps) * axis;
                    for (int k = 0; k < kAround; ++k) {
                        const double angle = 2.0 * std::numbers::pi * k / kAround;
                        const glm::dvec3 p =
                            centre + vessel.radiusMm * (std::cos(angle) * u + std::sin(angle) * v);
                        if (!inside(volume, p) || phantom.signedDistance(p) < -0.05) {
                            continue;  // outside the grid, or inside another vessel
                        }
                        std::array<double, 3> x = {p.x, p.y, p.z};
                        std::array<double, 3> closest{};
                        vtkIdType cell = 0;
                        int sub = 0;
                        double d2 = 0.0;
                        locator->FindClosestPoint(x.data(), closest.data(), cell, sub, d2);
                        distances.push_back(std::sqrt(d2));
                    }
                }
            }
        }
    }
    if (!distances.empty()) {
        double sum = 0.0;
        for (const double d : distances) {
            sum += d;
        }
        result.meanDistanceMm = sum / static_cast<double>(distances.size());
        const auto at =
            static_cast<std::ptrdiff_t>(0.95 * static_cast<double>(distances.size() - 1));
        std::nth_element(distances.begin(), distances.begin() + at, distances.end());
        result.p95DistanceMm = distances[static_cast<std::size_t>(at)];
    }

    // The aorta's centre line, piece by piece.
    const demo::PhantomVessel& aorta = phantom.vessels.front();
    const glm::dmat4 toIndex = volume.worldToIndex();
    for (std::size_t i = 0; i + 1 < aorta.centerline.size(); ++i) {
        const glm::dvec3 a = aorta.centerline[i];
        const glm::dvec3 b = aorta.centerline[i + 1];
        constexpr int kPieces = 8;
        for (int s = 0; s < kPieces; ++s) {
            const glm::dvec3 p = a + (b - a) * ((s + 0.5) / kPieces);
            if (!inside(volume, p)) {
                continue;
            }
            const double piece = glm::length(b - a) / kPieces;
            result.aortaLengthMm += piece;
            const glm::ivec3 ijk(glm::round(glm::dvec3(toIndex * glm::dvec4(p, 1.0))));
            if (labels.labels[labels.index(ijk.x, ijk.y, ijk.z)] == 0) {
                result.aortaMissedMm += piece;
            }
        }
    }
    return result;
}

}  // namespace vv::bench
