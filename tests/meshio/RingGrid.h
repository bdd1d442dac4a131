// SPDX-License-Identifier: GPL-3.0-or-later
// The meshio tests' tubes: rings of `around` points, `along + 1` of them,
// numbered ring by ring, joined by two triangles per quad.
#pragma once

#include <cstdint>

#include "vv/scene/Mesh.h"

namespace vv::meshio::test {

/// Appends to `mesh` the triangles of the ring grid whose first point is
/// `first` (ring j, point i at first + j * around + i % around).
inline void addRingGridTriangles(scene::Mesh& mesh, int around, int along,
                                 std::uint32_t first = 0) {
    const auto at = [&](int j, int i) {
        return first + static_cast<std::uint32_t>(j * around + (i % around));
    };
    for (int j = 0; j < along; ++j) {
        for (int i = 0; i < around; ++i) {
            mesh.indices.insert(mesh.indices.end(), {at(j, i), at(j, i + 1), at(j + 1, i)});
            mesh.indices.insert(mesh.indices.end(), {at(j, i + 1), at(j + 1, i + 1), at(j + 1, i)});
        }
    }
}

}  // namespace vv::meshio::test
