// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// A label map on a volume's grid: what segmentation produces and what the
// surface extraction and the DICOM SEG reader work on.

#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace vv::scene {

/// One kept component.
struct SegmentComponent {
    std::uint8_t label = 0;  ///< its value in the label map (1 = largest)
    std::size_t voxels = 0;  ///< voxel count
    double volumeMm3 = 0.0;  ///< voxels x voxel volume
};

/// A label map aligned with the volume it came from: same dims, same
/// indexToWorld; 0 = background, 1..n = kept components by decreasing size.
struct LabelMap {
    glm::ivec3 dims{0};
    glm::dmat4 indexToWorld{1.0};      ///< as Volume::indexToWorld()
    std::vector<std::uint8_t> labels;  ///< x fastest, as Volume::index()
    std::vector<SegmentComponent> components;
    std::vector<std::string> segmentNames;  ///< per label - 1; may be empty

    [[nodiscard]] std::size_t index(int i, int j, int k) const noexcept {
        return (static_cast<std::size_t>(k) * static_cast<std::size_t>(dims.y) +
                static_cast<std::size_t>(j)) *
                   static_cast<std::size_t>(dims.x) +
               static_cast<std::size_t>(i);
    }
};

}  // namespace vv::scene
