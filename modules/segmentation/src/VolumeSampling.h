// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// A volume's voxels sampled on a regular lattice: statistics that need a few
// hundred thousand voxels, not all of them (the intensity correction, the
// cut-off check).

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <glm/glm.hpp>

#include "vv/scene/Volume.h"

namespace vv::segmentation::detail {

/// Voxels a sampled statistic reads at most (about).
inline constexpr std::size_t kSampledVoxels = 262144;

/// The lattice step along every axis that leaves at most about kSampledVoxels
/// of a `dims` volume (1 for small volumes).
[[nodiscard]] inline int samplingStep(glm::ivec3 dims) {
    const double count = static_cast<double>(dims.x) * dims.y * dims.z;
    return std::max(1, static_cast<int>(std::ceil(std::cbrt(count / kSampledVoxels))));
}

/// Calls visit(ijk, value) for every samplingStep()-th voxel along each axis.
template <typename Visit>
void forSampledVoxels(const scene::Volume& volume, Visit&& visit) {
    const glm::ivec3 dims = volume.dims();
    const int step = samplingStep(dims);
    for (int k = 0; k < dims.z; k += step) {
        for (int j = 0; j < dims.y; j += step) {
            for (int i = 0; i < dims.x; i += step) {
                visit(glm::ivec3(i, j, k), volume.value(i, j, k));
            }
        }
    }
}

}  // namespace vv::segmentation::detail
