// SPDX-License-Identifier: GPL-3.0-or-later
// Private to vv::analysis: the differential geometry of a sampled curve:
// resampling by arc length, smoothing at a scale that follows the vessel's
// radius, rotation-minimising frames, curvature and torsion measured over a
// stated length.
#pragma once

#include <glm/glm.hpp>
#include <vector>

namespace vv::analysis::detail {

/// Arc lengths of the polyline's points from its first; same size.
[[nodiscard]] std::vector<double> arcLengths(const std::vector<glm::dvec3>& points);

/// The polyline sampled every `step` along its arc length from its first
/// point, plus its last point (the last interval may be shorter). Keeps at
/// least the two ends. Points closer than 1e-9 mm to the previous are dropped.
[[nodiscard]] std::vector<glm::dvec3> resample(const std::vector<glm::dvec3>& input, double step);

/// Linear interpolation of `values` (given at `at`, increasing) at `s`.
[[nodiscard]] double interpolate(const std::vector<double>& at, const std::vector<double>& values,
                                 double s);

/// Smoothing along the arc length by locally weighted quadratic regression:
/// point i becomes the value at i of the parabola (in arc length) fitted to
/// the points within 3 sigma[i] of it with Gaussian weights, the window made
/// symmetric (it shrinks near the ends, so the ends stay where they are).
/// Unlike a weighted mean it does not pull a bend inwards: its bias on a
/// circle of radius R is O(sigma^4 / R^3), not sigma^2 / (2 R).
[[nodiscard]] std::vector<glm::dvec3> smoothAlong(const std::vector<glm::dvec3>& points,
                                                  const std::vector<double>& sigma);

/// Unit tangents by central differences (one-sided at the ends).
[[nodiscard]] std::vector<glm::dvec3> tangents(const std::vector<glm::dvec3>& points);

/// Rotation-minimising normals along the tangents (the double reflection
/// method, Wang, Jüttler, Zheng & Liu 2008), starting from a normal
/// perpendicular to the first tangent.
[[nodiscard]] std::vector<glm::dvec3> rotationMinimisingNormals(
    const std::vector<glm::dvec3>& points, const std::vector<glm::dvec3>& tangents);

/// Curvature at each point from the circle through the points `scale[i]`
/// before and after it along the arc (Menger curvature: exact on a circle of
/// any size), the reach shortened near the ends; 1/mm.
[[nodiscard]] std::vector<double> curvatures(const std::vector<glm::dvec3>& points,
                                             const std::vector<double>& scale);

/// Torsion at each point from finite differences over `scale[i]`; 0 where
/// the curve is too straight for the binormal to be defined; 1/mm.
[[nodiscard]] std::vector<double> torsions(const std::vector<glm::dvec3>& points,
                                           const std::vector<double>& scale);

}  // namespace vv::analysis::detail
