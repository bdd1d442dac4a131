// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// An abdominal aortic aneurysm of known geometry for measuring vessel
// analysis (diameters, centrelines, lengths, the bifurcation angle) against
// analytic truth: a straight trunk (the aorta) along +z from the origin to
// the bifurcation point (0, 0, trunkLength), of radius r that swells
// smoothly to a maximum radius (a fusiform bulge: the radius r + (R - r)
// (1 + cos(2 pi (s - c) / bulgeLength)) / 2 within bulgeLength / 2 of the
// abscissa c, r elsewhere), and two straight branches (the iliacs) leaving
// the bifurcation point in the x-z plane, each at half the bifurcation angle
// from +z. The surface is the zero level of a field whose zero set is the
// trunk's surface of revolution and the branches' round tubes exactly,
// blended where they meet (within about one trunk radius of the bifurcation
// point), extracted as the demo tree's surface is (flying edges,
// windowed-sinc smoothing) at about a chosen triangle count (under 20k
// extracted at 20k and decimated, as coarse segmentations are made), every
// vertex then moved onto the zero level (before any jitter), so that only
// the facets' chords depart from the truth. Every section of the trunk
// perpendicular to +z away from the bifurcation is a circle of the
// profile's radius centred on the axis (the facets' polygon inscribed in it). Used by tests/analysis and
// bench/analysis_accuracy (docs/benchmarks/analysis.md).

#include <array>
#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>

#include "vv/core/Progress.h"
#include "vv/scene/Mesh.h"

namespace vv::demo {

struct AneurysmPhantomOptions {
    double radiusMm = 10.0;     ///< the trunk's radius away from the bulge; > 0
    double maxRadiusMm = 20.0;  ///< the bulge's widest radius; in (radiusMm, 4 radiusMm]
    /// The bulge's length along the axis; at least pi sqrt(2 (R - r) R), so
    /// that the profile's radius of curvature at the widest point exceeds R
    /// (then the lumen's medial axis is the straight axis, as in a real
    /// fusiform aneurysm).
    double bulgeLengthMm = 90.0;
    /// The abscissa of the widest point (from the trunk's start); the bulge
    /// must lie 2 radiusMm clear of the trunk's start and 4 radiusMm clear
    /// of the bifurcation point.
    double bulgeCentreMm = 80.0;
    double trunkLengthMm = 170.0;  ///< from the origin to the bifurcation point
    double iliacRadiusMm = 6.0;    ///< both branches; in (0, radiusMm]
    /// Between the two branches, degrees in [20, 120]; each is half of it
    /// from +z, towards +x and towards -x.
    double bifurcationAngleDeg = 60.0;
    /// Each branch's axis, from the bifurcation point; >= 4 radiusMm (the
    /// bifurcation angle is measured 2 to 4 trunk radii along them).
    double iliacLengthMm = 80.0;
    /// About this many triangles, in [1000, 5'000'000]; with open ends,
    /// before they are cut (the cut takes the caps and the tubes past it:
    /// about 14 % of them), except under 20k, where the cut surface is
    /// decimated to this many.
    std::size_t targetTriangles = 50'000;
    /// Each vertex moved by a uniform random offset in [-j, j] per axis, j =
    /// jitterFraction * radiusMm (of the trunk); in [0, 0.2].
    double jitterFraction = 0.0;
    std::uint32_t seed = 20261204U;  ///< the jitter's generator
    /// false: each end closed by a hemisphere of its radius around the end of
    /// its axis (the surface reaches one radius past it). true: cut open by
    /// the plane through the axis' end perpendicular to it (a CFD-like
    /// surface whose boundary loops are circles around the axes' ends).
    bool openEnds = false;
};

/// The parts of the phantom, as AneurysmPhantom::nearestAxisPoint names them.
enum class AneurysmPart : std::uint8_t {
    Trunk,        ///< from the origin along +z to the bifurcation point
    IliacPlusX,   ///< from the bifurcation point towards +x
    IliacMinusX,  ///< from the bifurcation point towards -x
};

/// The point of a part's axis nearest to a given point.
struct AneurysmAxisPoint {
    AneurysmPart part = AneurysmPart::Trunk;
    /// Along the part's axis from its start (the origin for the trunk, the
    /// bifurcation point for a branch), clamped to the axis, mm.
    double abscissaMm = 0.0;
    glm::dvec3 position{0.0};  ///< on the axis, mm
    double distanceMm = 0.0;   ///< from the given point, mm
    double radiusMm = 0.0;     ///< the part's true radius at that abscissa, mm
};

struct AneurysmPhantom {
    AneurysmPhantomOptions options;
    /// Outward-facing triangles with point normals, no arrays; named
    /// "aneurysm phantom".
    scene::Mesh mesh;
    glm::dvec3 bifurcationPoint{0.0};  ///< (0, 0, trunkLengthMm)
    glm::dvec3 trunkDirection{0.0, 0.0, 1.0};
    /// Unit; [0] towards +x, [1] towards -x.
    std::array<glm::dvec3, 2> iliacDirections{};
    double maxDiameterMm = 0.0;          ///< 2 maxRadiusMm: the widest section's diameter
    double maxDiameterAbscissaMm = 0.0;  ///< bulgeCentreMm: where it is, along the trunk
    double voxelSizeMm = 0.0;            ///< of the grid the surface was extracted on

    /// The trunk's true radius at abscissa `s` (clamped to [0, trunkLengthMm]).
    [[nodiscard]] double trunkRadiusAt(double s) const noexcept;
    /// The nearest point of the three axes (each clamped to its length) to
    /// `point`; of equally near ones the trunk's, then the +x branch's.
    [[nodiscard]] AneurysmAxisPoint nearestAxisPoint(const glm::dvec3& point) const noexcept;
};

/// Builds the phantom. Deterministic for the same options. Reports progress;
/// throws InvalidArgumentError naming the first option out of its range,
/// CancelledError on a stop request.
[[nodiscard]] AneurysmPhantom makeAneurysmPhantom(const AneurysmPhantomOptions& options,
                                                  const Progress& progress = {});

}  // namespace vv::demo
