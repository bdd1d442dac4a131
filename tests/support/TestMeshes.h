// SPDX-License-Identifier: GPL-3.0-or-later
// Small meshes the test folders share: closed cubes for mesh topology and
// back-face culling, open tubes for rendering, reports and the GUI (header
// only, so each test executable builds its own copy).
#pragma once

#include <cmath>
#include <cstdint>
#include <functional>
#include <glm/glm.hpp>
#include <numbers>
#include <string>
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

/// An open tube (no caps) along +x: radius, where its axis starts, length,
/// and its tessellation.
struct TubeShape {
    float radius = 1.0F;
    glm::vec3 start{0.0F};
    float length = 20.0F;
    int segments = 32;  ///< around
    int rings = 40;     ///< along: rings + 1 circles of vertices
};

/// The tube of `shape`, named "tube": vertex (ring i, segment j) at
/// start + (length i / rings, radius cos phi_j, radius sin phi_j), with its
/// exact outward normal; triangles wound clockwise seen from outside.
inline scene::Mesh tube(const TubeShape& shape = {}) {
    scene::Mesh mesh;
    mesh.name = "tube";
    for (int i = 0; i <= shape.rings; ++i) {
        const float x = shape.length * static_cast<float>(i) / static_cast<float>(shape.rings);
        for (int j = 0; j < shape.segments; ++j) {
            const float phi = 2.0F * std::numbers::pi_v<float> * static_cast<float>(j) /
                              static_cast<float>(shape.segments);
            const glm::vec3 n{0.0F, std::cos(phi), std::sin(phi)};
            mesh.positions.push_back(shape.start + glm::vec3(x, 0.0F, 0.0F) + shape.radius * n);
            mesh.normals.push_back(n);
        }
    }
    const auto segs = static_cast<std::uint32_t>(shape.segments);
    for (std::uint32_t i = 0; i < static_cast<std::uint32_t>(shape.rings); ++i) {
        for (std::uint32_t j = 0; j < segs; ++j) {
            const std::uint32_t a = i * segs + j;
            const std::uint32_t b = i * segs + (j + 1) % segs;
            mesh.indices.insert(mesh.indices.end(), {a, a + segs, b, b, a + segs, b + segs});
        }
    }
    return mesh;
}

/// Adds the point array `name` [`unit`] with value(x) at every vertex, x its
/// distance along the tube's axis from `start` (a value rising or falling
/// along the vessel, like a parameter of a CFD result).
inline void addAxialArray(scene::Mesh& mesh, const std::string& name, const std::string& unit,
                          float startX, const std::function<float(float)>& value) {
    scene::DataArray array{.name = name,
                           .unit = unit,
                           .components = 1,
                           .values = {},
                           .integer = false,
                           .fromCells = false};
    array.values.reserve(mesh.positions.size());
    for (const glm::vec3& p : mesh.positions) {
        array.values.push_back(value(p.x - startX));
    }
    mesh.pointArrays.push_back(std::move(array));
}

}  // namespace vv::test
