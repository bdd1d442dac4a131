// SPDX-License-Identifier: GPL-3.0-or-later
// Private to vv::meshio: the checks a mesh passes before a VTK filter
// touches it.
#pragma once

#include <string>

#include "vv/scene/Mesh.h"

namespace vv::meshio::detail {

/// The mesh's file, else its name, for messages.
[[nodiscard]] std::string describeMesh(const scene::Mesh& mesh);

/// Throws FormatError naming the mesh when it has no triangles ("there are
/// no triangles to <doing>"), a triangle refers to a vertex that does not
/// exist, or a point's coordinates are not finite.
void checkTriangleMesh(const scene::Mesh& mesh, const std::string& doing);

}  // namespace vv::meshio::detail
