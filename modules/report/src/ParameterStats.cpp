// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/report/ParameterStats.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/glm.hpp>
#include <limits>

#include "vv/core/Error.h"

namespace vv::report {

namespace {

/// The value of tuple `i` (the magnitude for vectors).
double valueAt(const scene::DataArray& array, std::size_t i) {
    const auto n = static_cast<std::size_t>(std::max(array.components, 1));
    if (n == 1) {
        return static_cast<double>(array.values[i]);
    }
    double sum = 0.0;
    for (std::size_t c = 0; c < n; ++c) {
        const auto v = static_cast<double>(array.values[i * n + c]);
        sum += v * v;
    }
    return std::sqrt(sum);
}

}  // namespace

double areaFractionBelow(double a, double b, double c, double threshold) noexcept {
    std::array<double, 3> f{a, b, c};
    std::sort(f.begin(), f.end());
    if (threshold <= f[0]) {
        return 0.0;
    }
    if (threshold > f[2]) {
        return 1.0;
    }
    if (threshold <= f[1]) {
        // The corner triangle at the lowest vertex: both edges from it are cut
        // at (t - f0) / (f1 - f0) and (t - f0) / (f2 - f0).
        return (threshold - f[0]) * (threshold - f[0]) / ((f[1] - f[0]) * (f[2] - f[0]));
    }
    // f1 < t <= f2: everything but the corner triangle at the highest vertex.
    if (f[2] == f[1]) {
        return 1.0;
    }
    return 1.0 - (f[2] - threshold) * (f[2] - threshold) / ((f[2] - f[1]) * (f[2] - f[0]));
}

std::vector<ParameterStats> parameterStats(const scene::Scene& scene, const std::string& array,
                                           const StatsThresholds& thresholds) {
    if (array.empty()) {
        throw InvalidArgumentError("parameter statistics need an array name");
    }
    for (const auto& t : {thresholds.below, thresholds.above}) {
        if (t && !std::isfinite(*t)) {
            throw InvalidArgumentError("parameter statistics: threshold is not finite");
        }
    }
    std::vector<ParameterStats> result;
    for (const scene::Mesh& mesh : scene.meshes) {
        const scene::DataArray* data = mesh.pointArray(array);
        if (data == nullptr || data->tupleCount() != mesh.positions.size()) {
            continue;
        }
        ParameterStats stats;
        stats.object = mesh.name;
        double totalArea = 0.0;
        double integral = 0.0;
        double below = 0.0;
        double above = 0.0;
        stats.min = std::numeric_limits<double>::infinity();
        stats.max = -std::numeric_limits<double>::infinity();
        for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
            const std::uint32_t i0 = mesh.indices[t];
            const std::uint32_t i1 = mesh.indices[t + 1];
            const std::uint32_t i2 = mesh.indices[t + 2];
            const glm::dvec3 p0(mesh.positions[i0]);
            const double area = 0.5 * glm::length(glm::cross(glm::dvec3(mesh.positions[i1]) - p0,
                                                             glm::dvec3(mesh.positions[i2]) - p0));
            totalArea += area;
            const double a = valueAt(*data, i0);
            const double b = valueAt(*data, i1);
            const double c = valueAt(*data, i2);
            if (!std::isfinite(a) || !std::isfinite(b) || !std::isfinite(c)) {
                continue;
            }
            ++stats.triangles;
            stats.area += area;
            integral += area * (a + b + c) / 3.0;
            stats.min = std::min({stats.min, a, b, c});
            stats.max = std::max({stats.max, a, b, c});
            if (thresholds.below) {
                below += area * areaFractionBelow(a, b, c, *thresholds.below);
            }
            if (thresholds.above) {
                // Above t = not below-or-equal; the level set has no area.
                above += area * (1.0 - areaFractionBelow(a, b, c, *thresholds.above));
            }
        }
        if (stats.triangles == 0) {
            continue;
        }
        if (stats.area > 0.0) {
            stats.mean = integral / stats.area;
            if (thresholds.below) {
                stats.fractionBelow = below / stats.area;
            }
            if (thresholds.above) {
                stats.fractionAbove = above / stats.area;
            }
        } else {
            stats.mean = 0.5 * (stats.min + stats.max);
        }
        stats.coveredFraction = totalArea > 0.0 ? stats.area / totalArea : 0.0;
        result.push_back(std::move(stats));
    }
    return result;
}

std::string arrayUnit(const scene::Scene& scene, const std::string& array) {
    for (const scene::Mesh& mesh : scene.meshes) {
        if (const scene::DataArray* data = mesh.pointArray(array)) {
            return data->unit;
        }
    }
    return {};
}

}  // namespace vv::report
