// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/slices/VoxelProbe.h"

#include <cmath>

#include "vv/core/Error.h"

namespace vv::slices {

std::string valueUnit(const scene::Volume& volume) {
    if (!volume.unit().empty()) {
        return volume.unit();
    }
    return volume.modality() == "CT" ? std::string("HU") : std::string();
}

std::optional<VoxelSample> voxelAt(const scene::Volume& volume, const glm::dvec3& world) {
    if (volume.empty()) {
        return std::nullopt;
    }
    const double det = glm::determinant(glm::dmat3(volume.indexToWorld()));
    if (!std::isfinite(det) || std::abs(det) < 1e-12) {
        throw InvalidArgumentError("volume geometry is singular or not finite");
    }
    const glm::dvec3 ijk(volume.worldToIndex() * glm::dvec4(world, 1.0));
    glm::ivec3 voxel{0};
    for (int a = 0; a < 3; ++a) {
        if (!std::isfinite(ijk[a]) || ijk[a] < -0.5 || ijk[a] >= volume.dims()[a] - 0.5) {
            return std::nullopt;
        }
        voxel[a] = static_cast<int>(std::floor(ijk[a] + 0.5));
    }
    return VoxelSample{voxel, volume.value(voxel.x, voxel.y, voxel.z), valueUnit(volume)};
}

}  // namespace vv::slices
