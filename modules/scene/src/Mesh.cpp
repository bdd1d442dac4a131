// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/scene/Mesh.h"

#include <cmath>

namespace vv::scene {

std::size_t DataArray::nonFiniteCount() const noexcept {
    std::size_t count = 0;
    const auto n = tupleCount();
    for (std::size_t i = 0; i < n; ++i) {
        for (int c = 0; c < components; ++c) {
            if (!std::isfinite(values[i * static_cast<std::size_t>(components) +
                                      static_cast<std::size_t>(c)])) {
                ++count;
                break;
            }
        }
    }
    return count;
}

std::optional<std::pair<float, float>> DataArray::finiteRange() const {
    bool any = false;
    float lo = 0.0F;
    float hi = 0.0F;
    const auto n = tupleCount();
    for (std::size_t i = 0; i < n; ++i) {
        double sum = 0.0;
        bool finite = true;
        for (int c = 0; c < components; ++c) {
            const float v =
                values[i * static_cast<std::size_t>(components) + static_cast<std::size_t>(c)];
            finite = finite && std::isfinite(v);
            sum += static_cast<double>(v) * v;
        }
        if (!finite) {
            continue;
        }
        const float v = components == 1 ? values[i] : static_cast<float>(std::sqrt(sum));
        if (!any) {
            lo = hi = v;
            any = true;
        } else {
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
    }
    if (!any) {
        return std::nullopt;
    }
    return std::make_pair(lo, hi);
}

Aabb Mesh::bounds() const noexcept {
    return boundsOf(positions);
}

const DataArray* Mesh::pointArray(const std::string& arrayName) const noexcept {
    for (const auto& a : pointArrays) {
        if (a.name == arrayName) {
            return &a;
        }
    }
    return nullptr;
}

Aabb Scene::bounds() const noexcept {
    Aabb box;
    for (const auto& m : meshes) {
        box.extend(m.bounds());
    }
    return box;
}

void computeNormals(Mesh& mesh) {
    mesh.normals.assign(mesh.positions.size(), glm::vec3(0.0F));
    const auto n = mesh.positions.size();
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const auto a = mesh.indices[t];
        const auto b = mesh.indices[t + 1];
        const auto c = mesh.indices[t + 2];
        if (a >= n || b >= n || c >= n) {
            continue;
        }
        // Cross product length is twice the area: area weighting for free.
        const glm::vec3 face = glm::cross(mesh.positions[b] - mesh.positions[a],
                                          mesh.positions[c] - mesh.positions[a]);
        mesh.normals[a] += face;
        mesh.normals[b] += face;
        mesh.normals[c] += face;
    }
    for (auto& normal : mesh.normals) {
        const float len = glm::length(normal);
        normal = (len > 0.0F && std::isfinite(len)) ? normal / len : glm::vec3(0.0F, 0.0F, 1.0F);
    }
}

}  // namespace vv::scene
