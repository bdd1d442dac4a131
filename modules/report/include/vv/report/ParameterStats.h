// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "vv/scene/Mesh.h"

namespace vv::report {

/// Thresholds for the area fractions of ParameterStats (in the array's unit).
struct StatsThresholds {
    std::optional<double> below;  ///< e.g. 0.4 for "WSS < 0.4 Pa"
    std::optional<double> above;  ///< e.g. a high-WSS threshold
};

/// Statistics of one point array over one object (mesh) surface. The value is
/// interpolated linearly over each triangle (vector arrays: the magnitude), so
/// the mean and the fractions are surface integrals: triangle-area weighted.
struct ParameterStats {
    std::string object;            ///< the mesh's name
    std::size_t triangles = 0;     ///< triangles with a finite value at all 3 corners
    double area = 0.0;             ///< their area, scene units squared
    double coveredFraction = 0.0;  ///< that area over the whole surface area (0..1)
    double min = 0.0;              ///< over those triangles' corners
    double mean = 0.0;             ///< area-weighted mean
    double max = 0.0;
    /// Share (0..1) of the area where value < thresholds.below; nullopt without it.
    std::optional<double> fractionBelow;
    /// Share (0..1) of the area where value > thresholds.above; nullopt without it.
    std::optional<double> fractionAbove;
};

/// The statistics of point array `array` on each mesh of `scene` that has it
/// (meshes without it, or without a triangle with finite values, are left out).
/// Throws InvalidArgumentError when `array` is empty or a threshold is not finite.
[[nodiscard]] std::vector<ParameterStats> parameterStats(const scene::Scene& scene,
                                                         const std::string& array,
                                                         const StatsThresholds& thresholds);

/// The unit of point array `array` (as the first mesh of `scene` that has it
/// gives it, e.g. "Pa"); empty when no mesh has it or its unit is unknown.
[[nodiscard]] std::string arrayUnit(const scene::Scene& scene, const std::string& array);

/// Share of a triangle's area where the linear function with corner values
/// a, b, c is below `threshold` (0..1); exact.
[[nodiscard]] double areaFractionBelow(double a, double b, double c, double threshold) noexcept;

}  // namespace vv::report
