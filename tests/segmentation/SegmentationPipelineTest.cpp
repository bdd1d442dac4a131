// SPDX-License-Identifier: GPL-3.0-or-later
// The segmentation pipeline's helpers: downsampled previews and the seed search.
#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include "vv/core/Error.h"
#include "vv/scene/Volume.h"
#include "vv/segmentation/SegmentationPipeline.h"

namespace vv {
namespace {

TEST(SegmentationPipelineTest, DownsamplingKeepsWorldPositionsAndFindsInRangeSeeds) {
    scene::Volume volume({9, 8, 7}, scene::VoxelType::Int16);
    glm::dmat4 m(1.0);
    m[0] = glm::dvec4(0.5, 0.0, 0.0, 0.0);
    m[1] = glm::dvec4(0.0, 0.7, 0.1, 0.0);
    m[2] = glm::dvec4(0.0, 0.0, 1.5, 0.0);
    m[3] = glm::dvec4(-3.0, 2.0, 1.0, 1.0);
    volume.setIndexToWorld(m);
    volume.setModality("CT");
    for (std::size_t n = 0; n < volume.voxelCount(); ++n) {
        volume.setValueAt(n, static_cast<float>(n % 1000));
    }
    const scene::Volume coarse = segmentation::downsampledVolume(volume, 2);
    EXPECT_EQ(coarse.dims(), glm::ivec3(5, 4, 4));
    EXPECT_EQ(coarse.modality(), "CT");
    for (const glm::ivec3 c : {glm::ivec3(0, 0, 0), glm::ivec3(4, 3, 3), glm::ivec3(2, 1, 3)}) {
        EXPECT_EQ(coarse.value(c.x, c.y, c.z), volume.value(2 * c.x, 2 * c.y, 2 * c.z));
        const glm::dvec3 a = coarse.worldPosition(glm::dvec3(c));
        const glm::dvec3 b = volume.worldPosition(glm::dvec3(2 * c));
        EXPECT_LT(glm::length(a - b), 1e-9);
    }
    EXPECT_THROW((void)segmentation::downsampledVolume(volume, 0), InvalidArgumentError);

    // The seed search: the nearest in-range voxel within the radius, else none.
    scene::Volume ball({11, 11, 11}, scene::VoxelType::Int16);
    ball.setValueAt(ball.index(7, 5, 5), 400.0F);
    ball.setValueAt(ball.index(3, 5, 5), 400.0F);
    const auto near = segmentation::nearestVoxelInRange(ball, {6.2, 5.0, 5.0}, 200.0F, 700.0F, 2);
    ASSERT_TRUE(near.has_value());
    EXPECT_EQ(*near, glm::ivec3(7, 5, 5));
    EXPECT_FALSE(
        segmentation::nearestVoxelInRange(ball, {5.0, 5.0, 5.0}, 200.0F, 700.0F, 1).has_value());
    EXPECT_FALSE(
        segmentation::nearestVoxelInRange(ball, {6.2, 5.0, 5.0}, 500.0F, 700.0F, 3).has_value());

    // Previews: at least every 2nd voxel, within the budget, not below 8 voxels an axis.
    EXPECT_EQ(segmentation::previewStep({64, 64, 48}, 400000), 2);
    EXPECT_EQ(segmentation::previewStep({512, 512, 400}, 400000), 7);
    EXPECT_EQ(segmentation::previewStep({512, 512, 12}, 400000), 1);
}

}  // namespace
}  // namespace vv
