// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <glm/glm.hpp>

#include "vv/core/Math.h"
#include "vv/scene/Mesh.h"
#include "vv/scene/MeshTopology.h"

namespace vv::render {

/// Which triangles a draw may skip (glCullFace) without changing a pixel.
enum class CullFace {
    None,   ///< draw both sides
    Back,   ///< skip the triangles wound clockwise on screen
    Front,  ///< skip the triangles wound counter-clockwise on screen
};

/// The faces of `mesh` that a draw with `view` and `projection` (OpenGL
/// conventions, counter-clockwise front faces) may cull, given its closure
/// (scene::surfaceClosure) and its bounds.
///
/// Culling the far side of a closed surface changes nothing only when every
/// pixel's ray starts outside the solid: then the first surface it meets is
/// one it enters. So this answers None for an open surface, and also when
/// the near plane may cut the solid or lie inside it (a camera flown into a
/// vessel, a close-up clipped by the near plane): it looks for triangles
/// near the near-plane rectangle and counts the surface's signed crossings
/// (its winding number) along rays from that rectangle. It is conservative:
/// wherever it cannot be sure (a ray grazing an edge, a non-finite matrix)
/// it answers None. A mirroring transform swaps Back and Front.
///
/// O(1) when the near-plane rectangle is outside `bounds`, else O(triangles).
/// Assumes, like surfaceClosure, that the surface does not pass through itself.
[[nodiscard]] CullFace cullableFaces(const scene::Mesh& mesh, scene::SurfaceClosure closure,
                                     const Aabb& bounds, const glm::mat4& view,
                                     const glm::mat4& projection) noexcept;

}  // namespace vv::render
