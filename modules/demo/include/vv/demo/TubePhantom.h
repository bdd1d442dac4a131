// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Tube phantoms for measuring vessel analysis (centrelines, sections,
// diameters, stenoses) against analytic truth: a straight cylinder, a torus
// segment (a bend of known arc length and curvature) and a straight tube with
// a smooth stenosis, each a surface of revolution about its axis, sampled as
// rings of vertices that lie exactly on the true surface (before jitter), at
// a chosen triangle count, with optional vertex jitter (a noisy
// segmentation) and flat caps (a closed surface). Every section perpendicular
// to the axis is a circle centred on the axis, of the radius the truth gives.
// Used by tests/analysis, bench/analysis_accuracy and whoever wants to check
// a measurement (docs/benchmarks/analysis.md).

#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "vv/scene/Mesh.h"

namespace vv::demo {

enum class TubeShape : std::uint8_t {
    Cylinder,      ///< straight along +z from the origin, constant radius
    TorusSegment,  ///< a circular arc of radius bendRadiusMm in the x-z plane, from the origin
    Stenosis,      ///< straight as Cylinder, narrowed smoothly around its middle
};

struct TubePhantomOptions {
    TubeShape shape = TubeShape::Cylinder;
    double radiusMm = 5.0;  ///< the tube's radius (away from a stenosis); > 0
    /// Axis length for Cylinder and Stenosis; > 2 radiusMm. TorusSegment: the
    /// arc length follows from bendRadiusMm and bendAngleDeg.
    double lengthMm = 100.0;
    double bendRadiusMm = 50.0;   ///< TorusSegment: > radiusMm
    double bendAngleDeg = 120.0;  ///< TorusSegment: in (0, 300]
    /// Stenosis: the diameter lost at the narrowest point, percent of the
    /// diameter, in (0, 95); the narrowing is (1 + cos) / 2 shaped over
    /// stenosisLengthMm, centred on the axis' middle.
    double stenosisPercent = 50.0;
    double stenosisLengthMm = 20.0;  ///< Stenosis: in (0, lengthMm / 2]
    /// About this many triangles (rings and sides chosen for near-square
    /// quads): >= 200, <= 20'000'000.
    std::size_t targetTriangles = 50'000;
    /// Each vertex moved by a uniform random offset in [-j, j] per axis, j =
    /// jitterFraction * radiusMm (0.02: 2 % of r); in [0, 0.2].
    double jitterFraction = 0.0;
    std::uint32_t seed = 20261203U;  ///< the jitter's generator
    /// Close the ends with flat caps (a fan around the end's centre); false
    /// leaves them open, as CFD surfaces are.
    bool capped = false;
};

/// One sample of the true axis.
struct AxisSample {
    glm::dvec3 position{0.0};
    glm::dvec3 tangent{0.0, 0.0, 1.0};  ///< unit
    double abscissaMm = 0.0;            ///< arc length from the axis' start
    double radiusMm = 0.0;              ///< of the circular section here
    double curvature = 0.0;             ///< 1/mm
};

struct TubePhantom {
    TubePhantomOptions options;
    /// Outward-facing triangles, normals from the triangles, no arrays;
    /// named after the shape.
    scene::Mesh mesh;
    /// The true axis, sampled every 0.1 mm or finer, from start to end.
    std::vector<AxisSample> axis;
    double lengthMm = 0.0;  ///< arc length of the axis
    double chordMm = 0.0;   ///< distance between the axis' ends
    /// Stenosis: the narrowest point's abscissa and radius; otherwise the
    /// axis' middle and radiusMm.
    double narrowestAbscissaMm = 0.0;
    double narrowestRadiusMm = 0.0;
    /// The mesh's rings (along the axis) and sides (around it): a section
    /// perpendicular to the axis through the unjittered mesh is the regular
    /// polygon of `sides` corners on the true circle.
    int rings = 0;
    int sides = 0;

    /// The true axis at abscissa `s` (clamped to [0, lengthMm]), exactly.
    [[nodiscard]] AxisSample axisAt(double s) const;
    /// Distance from `point` to the true axis curve (its nearest point,
    /// ends included) and that point's abscissa.
    [[nodiscard]] std::pair<double, double> distanceToAxis(const glm::dvec3& point) const;
};

/// Builds the phantom. Deterministic for the same options. Throws
/// InvalidArgumentError naming the first option out of its range.
[[nodiscard]] TubePhantom makeTubePhantom(const TubePhantomOptions& options);

}  // namespace vv::demo
