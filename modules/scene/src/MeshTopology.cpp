// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/scene/MeshTopology.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include "vv/core/Error.h"

namespace vv::scene {
namespace {

void checkIndices(const Mesh& mesh) {
    if (mesh.indices.size() % 3 != 0) {
        throw InvalidArgumentError(mesh.source, "mesh '" + mesh.name + "' has " +
                                                    std::to_string(mesh.indices.size()) +
                                                    " indices, not a multiple of 3");
    }
    const std::size_t n = mesh.vertexCount();
    for (const std::uint32_t index : mesh.indices) {
        if (index >= n) {
            throw InvalidArgumentError(
                mesh.source, "mesh '" + mesh.name + "' has a triangle index out of range");
        }
    }
}

/// True when every edge is shared by exactly two triangles running along it
/// in opposite directions (and no triangle repeats a vertex). Half-edges are
/// bucketed by their smaller vertex with a counting sort, so this is linear.
bool edgesPairUp(const Mesh& mesh) {
    const std::size_t n = mesh.vertexCount();
    std::vector<std::uint32_t> start(n + 1, 0);
    const std::size_t corners = mesh.indices.size();
    for (std::size_t t = 0; t < corners; t += 3) {
        for (std::size_t k = 0; k < 3; ++k) {
            const std::uint32_t a = mesh.indices[t + k];
            const std::uint32_t b = mesh.indices[t + (k + 1) % 3];
            if (a == b) {
                return false;
            }
            ++start[std::min(a, b) + 1];
        }
    }
    std::partial_sum(start.begin(), start.end(), start.begin());
    // Each entry: the larger vertex, shifted, and 1 when the edge runs from
    // the smaller vertex to the larger one.
    std::vector<std::uint64_t> entries(corners);
    std::vector<std::uint32_t> cursor(start.begin(), start.end() - 1);
    for (std::size_t t = 0; t < corners; t += 3) {
        for (std::size_t k = 0; k < 3; ++k) {
            const std::uint32_t a = mesh.indices[t + k];
            const std::uint32_t b = mesh.indices[t + (k + 1) % 3];
            const std::uint32_t low = std::min(a, b);
            const std::uint64_t forward = a < b ? 1U : 0U;
            entries[cursor[low]++] = (static_cast<std::uint64_t>(std::max(a, b)) << 1U) | forward;
        }
    }
    for (std::size_t v = 0; v < n; ++v) {
        const auto first = entries.begin() + start[v];
        const auto last = entries.begin() + start[v + 1];
        if ((last - first) % 2 != 0) {
            return false;
        }
        std::sort(first, last);
        for (auto it = first; it != last; it += 2) {
            // Sorted: the pair must be (other, backward), (other, forward),
            // and the next pair must lead to another vertex.
            const std::uint64_t other = *it >> 1U;
            if ((*it & 1U) != 0 || *(it + 1) != ((other << 1U) | 1U) ||
                (it + 2 != last && (*(it + 2) >> 1U) == other)) {
                return false;
            }
        }
    }
    return true;
}

std::uint32_t findRoot(std::vector<std::uint32_t>& parent, std::uint32_t v) {
    while (parent[v] != v) {
        parent[v] = parent[parent[v]];
        v = parent[v];
    }
    return v;
}

}  // namespace

SurfaceClosure surfaceClosure(const Mesh& mesh) {
    checkIndices(mesh);
    if (mesh.indices.empty() || !edgesPairUp(mesh)) {
        return SurfaceClosure::Open;
    }
    // Connected parts (union-find over the vertices), then each part's signed
    // volume: the sum of the tetrahedra from a fixed centre to each triangle.
    const std::size_t n = mesh.vertexCount();
    std::vector<std::uint32_t> parent(n);
    std::iota(parent.begin(), parent.end(), 0U);
    for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
        const std::uint32_t a = findRoot(parent, mesh.indices[t]);
        for (std::size_t k = 1; k < 3; ++k) {
            const std::uint32_t b = findRoot(parent, mesh.indices[t + k]);
            if (a != b) {
                parent[b] = a;
            }
        }
    }
    const Aabb box = mesh.bounds();
    const glm::dvec3 centre = (glm::dvec3(box.min) + glm::dvec3(box.max)) * 0.5;
    std::vector<double> volume(n, 0.0);
    std::vector<double> magnitude(n, 0.0);  // sum of |tetrahedron|: the scale of round-off
    for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
        const glm::dvec3 p0 = glm::dvec3(mesh.positions[mesh.indices[t]]) - centre;
        const glm::dvec3 p1 = glm::dvec3(mesh.positions[mesh.indices[t + 1]]) - centre;
        const glm::dvec3 p2 = glm::dvec3(mesh.positions[mesh.indices[t + 2]]) - centre;
        const double six = glm::dot(p0, glm::cross(p1, p2));
        const std::uint32_t root = findRoot(parent, mesh.indices[t]);
        volume[root] += six;
        magnitude[root] += std::abs(six);
    }
    int outward = 0;
    int inward = 0;
    for (std::size_t v = 0; v < n; ++v) {
        if (magnitude[v] == 0.0 && volume[v] == 0.0) {
            continue;  // not a root, or a part with no extent at all
        }
        if (!std::isfinite(volume[v]) || std::abs(volume[v]) <= 1e-9 * magnitude[v]) {
            return SurfaceClosure::Open;  // flat or non-finite: no side is "inside"
        }
        (volume[v] > 0.0 ? outward : inward) += 1;
    }
    if (outward > 0 && inward == 0) {
        return SurfaceClosure::ClosedOutward;
    }
    if (inward > 0 && outward == 0) {
        return SurfaceClosure::ClosedInward;
    }
    return SurfaceClosure::Open;
}

std::vector<SurfaceClosure> surfaceClosures(const Scene& scene) {
    std::vector<SurfaceClosure> closures;
    closures.reserve(scene.meshes.size());
    for (const Mesh& mesh : scene.meshes) {
        closures.push_back(surfaceClosure(mesh));
    }
    return closures;
}

double signedVolume(const Mesh& mesh) noexcept {
    double volume6 = 0.0;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const glm::dvec3 a(mesh.positions[mesh.indices[t]]);
        const glm::dvec3 b(mesh.positions[mesh.indices[t + 1]]);
        const glm::dvec3 c(mesh.positions[mesh.indices[t + 2]]);
        volume6 += glm::dot(a, glm::cross(b, c));
    }
    return volume6 / 6.0;
}

bool orientOutward(Mesh& mesh) noexcept {
    if (!(signedVolume(mesh) < 0.0)) {
        return false;
    }
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        std::swap(mesh.indices[t + 1], mesh.indices[t + 2]);
    }
    for (glm::vec3& normal : mesh.normals) {
        normal = -normal;
    }
    return true;
}

}  // namespace vv::scene
