// SPDX-License-Identifier: GPL-3.0-or-later
// A phantom for the slice tests: balls of known radius at known LPS centres
// in a volume of any (oblique, sheared) geometry.
#pragma once

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <vector>

#include "vv/scene/Volume.h"

namespace vv::test {

struct Ball {
    glm::dvec3 centre;  ///< LPS mm
    double radius;      ///< mm
};

/// A `dims` Int16 CT volume with geometry `indexToWorld`: 1000 HU inside the
/// balls, 0 HU elsewhere.
inline scene::Volume ballPhantom(glm::ivec3 dims, const glm::dmat4& indexToWorld,
                                 const std::vector<Ball>& balls) {
    scene::Volume volume(dims, scene::VoxelType::Int16);
    volume.setIndexToWorld(indexToWorld);
    volume.setModality("CT");
    volume.setUnit("HU");
    for (int k = 0; k < dims.z; ++k) {
        for (int j = 0; j < dims.y; ++j) {
            for (int i = 0; i < dims.x; ++i) {
                const glm::dvec3 p = volume.worldPosition({i, j, k});
                for (const Ball& b : balls) {
                    if (glm::distance(p, b.centre) <= b.radius) {
                        volume.setValueAt(volume.index(i, j, k), 1000.0F);
                    }
                }
            }
        }
    }
    return volume;
}

/// indexToWorld of a grid with `spacing`, rotated by `rotation` (columns: row
/// direction, column direction, normal), slice step sheared by `shear` mm
/// along the row direction, voxel (0, 0, 0) at `origin`.
inline glm::dmat4 gridGeometry(const glm::dvec3& spacing, const glm::dmat3& rotation, double shear,
                               const glm::dvec3& origin) {
    glm::dmat4 m(1.0);
    m[0] = glm::dvec4(rotation[0] * spacing.x, 0.0);
    m[1] = glm::dvec4(rotation[1] * spacing.y, 0.0);
    m[2] = glm::dvec4(rotation[2] * spacing.z + rotation[0] * shear, 0.0);
    m[3] = glm::dvec4(origin, 1.0);
    return m;
}

/// A rotation by `degrees` about the unit `axis`.
inline glm::dmat3 rotationAbout(const glm::dvec3& axis, double degrees) {
    return glm::dmat3(glm::rotate(glm::dmat4(1.0), glm::radians(degrees), glm::normalize(axis)));
}

}  // namespace vv::test
