// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The voxel under a point of a slice view: its index, value and unit.

#include <glm/glm.hpp>
#include <optional>
#include <string>

#include "vv/scene/Volume.h"

namespace vv::slices {

/// The unit of `volume`'s values: unit() when set, "HU" for modality "CT",
/// else empty (unknown, e.g. MR signal).
[[nodiscard]] std::string valueUnit(const scene::Volume& volume);

struct VoxelSample {
    glm::ivec3 voxel{0};  ///< the nearest voxel (i, j, k)
    float value = 0.0F;   ///< its value as stored (HU for CT)
    std::string unit;     ///< valueUnit(volume)
};

/// The voxel of `volume` that contains the world point `world` (LPS mm):
/// the nearest voxel centre in index space; nullopt when the point lies
/// outside the voxels (continuous index outside [-0.5, dims - 0.5)) or is not
/// finite. Throws InvalidArgumentError for a singular geometry.
[[nodiscard]] std::optional<VoxelSample> voxelAt(const scene::Volume& volume,
                                                 const glm::dvec3& world);

}  // namespace vv::slices
