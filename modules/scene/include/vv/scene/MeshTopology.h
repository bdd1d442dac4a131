// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <vector>

#include "vv/scene/Mesh.h"

namespace vv::scene {

/// Whether a triangle surface encloses space, and which way its triangles
/// face: what a renderer needs to know before it may skip the triangles
/// that face away from the eye (back-face culling).
enum class SurfaceClosure {
    /// A boundary or non-manifold edge, two neighbours wound against each
    /// other, a degenerate triangle, a part without volume or parts facing
    /// different ways, or no triangle at all. The inside can be seen.
    Open,
    /// Every edge is shared by exactly two triangles that run along it in
    /// opposite directions, and every connected part encloses a positive
    /// volume: the triangles are counter-clockwise seen from outside.
    ClosedOutward,
    /// Closed as above, every part with a negative volume: clockwise seen
    /// from outside.
    ClosedInward,
};

/// The closure of `mesh` from its indices and positions, in O(triangles).
/// Self-intersections are not looked for: a closed surface that passes
/// through itself is reported as closed.
/// Throws InvalidArgumentError (naming the mesh's source) for an index out
/// of range or an index count that is not a multiple of 3.
[[nodiscard]] SurfaceClosure surfaceClosure(const Mesh& mesh);

/// surfaceClosure() of each of the scene's meshes, in order. Throws like it.
[[nodiscard]] std::vector<SurfaceClosure> surfaceClosures(const Scene& scene);

/// The volume the triangles enclose, signed: positive when they wind
/// counter-clockwise seen from outside (cubic scene units; meaningful for a
/// closed surface). Indices must be in range (surfaceClosure() checks them).
[[nodiscard]] double signedVolume(const Mesh& mesh) noexcept;

/// Makes the triangles wind counter-clockwise seen from outside: when
/// signedVolume() is negative, every triangle is flipped and every normal
/// negated. Returns true when it flipped. Indices must be in range.
bool orientOutward(Mesh& mesh) noexcept;

}  // namespace vv::scene
