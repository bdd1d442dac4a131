// SPDX-License-Identifier: GPL-3.0-or-later
#include "MeshChecks.h"

#include <cmath>
#include <cstdint>

#include "vv/core/Error.h"

namespace vv::meshio::detail {

std::string describeMesh(const scene::Mesh& mesh) {
    return mesh.source.empty() ? "mesh '" + mesh.name + "'" : mesh.source.string();
}

void checkTriangleMesh(const scene::Mesh& mesh, const std::string& doing) {
    if (mesh.triangleCount() == 0) {
        throw FormatError(describeMesh(mesh), "there are no triangles to " + doing);
    }
    for (const std::uint32_t index : mesh.indices) {
        if (index >= mesh.vertexCount()) {
            throw FormatError(describeMesh(mesh), "a triangle refers to vertex " +
                                                      std::to_string(index) + " of " +
                                                      std::to_string(mesh.vertexCount()));
        }
    }
    for (const glm::vec3& p : mesh.positions) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
            throw FormatError(describeMesh(mesh), "a point's coordinates are not finite");
        }
    }
}

}  // namespace vv::meshio::detail
