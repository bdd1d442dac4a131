// SPDX-License-Identifier: GPL-3.0-or-later
// Small closed meshes for the tests of mesh topology and back-face culling
// (header only, so each test executable builds its own copy).
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <utility>

#include "vv/scene/Mesh.h"

namespace vv::test {

/// An axis-aligned cube from `lo` to `lo + size`, its triangles
/// counter-clockwise seen from outside (normals outward).
inline scene::Mesh cube(glm::vec3 lo = glm::vec3(0.0F), float size = 1.0F) {
    scene::Mesh mesh;
    mesh.name = "cube";
    for (int i = 0; i < 8; ++i) {
        mesh.positions.push_back(lo + size * glm::vec3(static_cast<float>(i & 1),
                                                       static_cast<float>((i >> 1) & 1),
                                                       static_cast<float>((i >> 2) & 1)));
    }
    // Quads, counter-clockwise from outside: -z, +z, -y, +y, -x, +x.
    const std::uint32_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                       {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& q : quads) {
        mesh.indices.insert(mesh.indices.end(), {q[0], q[1], q[2], q[0], q[2], q[3]});
    }
    return mesh;
}

/// Turns triangle `triangle` around (swaps two of its corners).
inline void flip(scene::Mesh& mesh, std::size_t triangle) {
    std::swap(mesh.indices[3 * triangle + 1], mesh.indices[3 * triangle + 2]);
}

/// Turns every triangle around.
inline void flipAll(scene::Mesh& mesh) {
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        flip(mesh, t);
    }
}

/// `b`'s vertices and triangles appended to `a`'s (no welding).
inline scene::Mesh merged(scene::Mesh a, const scene::Mesh& b) {
    const auto offset = static_cast<std::uint32_t>(a.positions.size());
    a.positions.insert(a.positions.end(), b.positions.begin(), b.positions.end());
    for (const std::uint32_t i : b.indices) {
        a.indices.push_back(i + offset);
    }
    return a;
}

}  // namespace vv::test
