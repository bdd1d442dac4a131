// SPDX-License-Identifier: GPL-3.0-or-later
// The overlay lines up with the surface: the synthetic CTA segmented by the
// segmentation pipeline; where its surface mesh cuts an axial, coronal or
// sagittal slice, the cut lies within one voxel of the overlay's edge.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "SyntheticCta.h"
#include "vv/segmentation/SegmentationPipeline.h"
#include "vv/slices/Reslice.h"
#include "vv/slices/SlicePlane.h"

namespace {

using vv::slices::SliceOrientation;

// Midpoints between 4-neighbour pixels of which one is labelled and the
// other not: the overlay's edge, in pixel coordinates.
std::vector<glm::dvec2> overlayEdge(const vv::Image<std::uint8_t>& labels) {
    std::vector<glm::dvec2> edge;
    for (int r = 0; r < labels.height(); ++r) {
        for (int c = 0; c < labels.width(); ++c) {
            const bool in = labels(c, r) != 0;
            if (c + 1 < labels.width() && in != (labels(c + 1, r) != 0)) {
                edge.emplace_back(c + 0.5, r);
            }
            if (r + 1 < labels.height() && in != (labels(c, r + 1) != 0)) {
                edge.emplace_back(c, r + 0.5);
            }
        }
    }
    return edge;
}

// Points every `stepMm` along the segments where the mesh's triangles cross
// `plane`, in pixel coordinates.
std::vector<glm::dvec2> meshCut(const vv::scene::Mesh& mesh, const vv::slices::SlicePlane& plane,
                                double stepMm) {
    const glm::dvec3 n = plane.normal();
    std::vector<glm::dvec2> cut;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        std::array<glm::dvec3, 3> p{};
        std::array<double, 3> d{};
        for (std::size_t v = 0; v < 3; ++v) {
            p[v] = glm::dvec3(mesh.positions[mesh.indices[t + v]]);
            d[v] = glm::dot(p[v] - plane.origin, n);
        }
        std::vector<glm::dvec3> crossing;
        for (std::size_t v = 0; v < 3; ++v) {
            const std::size_t w = (v + 1) % 3;
            if ((d[v] < 0.0) != (d[w] < 0.0)) {
                crossing.push_back(p[v] + (d[v] / (d[v] - d[w])) * (p[w] - p[v]));
            }
        }
        if (crossing.size() != 2) {
            continue;
        }
        const double len = glm::distance(crossing[0], crossing[1]);
        const int samples = 1 + static_cast<int>(len / stepMm);
        for (int s = 0; s <= samples; ++s) {
            const glm::dvec3 q =
                crossing[0] + (s / static_cast<double>(samples)) * (crossing[1] - crossing[0]);
            cut.push_back(plane.pixelAt(q));
        }
    }
    return cut;
}

double nearestDistance(const glm::dvec2& p, const std::vector<glm::dvec2>& points) {
    double best = std::numeric_limits<double>::max();
    for (const glm::dvec2& q : points) {
        best = std::min(best, glm::distance(p, q));
    }
    return best;
}

TEST(OverlayAlignmentTest, SurfaceCutLiesWithinOneVoxelOfTheOverlayEdge) {
    const vv::test::SyntheticCta cta = vv::test::makeSyntheticCta();
    vv::segmentation::SegmentationRequest request;
    request.volume = std::make_shared<const vv::scene::Volume>(cta.volume);
    const vv::segmentation::SegmentationOutcome outcome =
        vv::segmentation::runSegmentation(request);
    ASSERT_TRUE(outcome.labelMap);
    ASSERT_EQ(outcome.scene->meshes.size(), 1U);
    const vv::scene::Mesh& mesh = outcome.scene->meshes[0];
    const glm::dvec3 spacing = cta.volume.spacing();
    const double voxel = std::max({spacing.x, spacing.y, spacing.z});

    const vv::Aabb bounds = outcome.scene->bounds();
    for (const SliceOrientation o :
         {SliceOrientation::Axial, SliceOrientation::Coronal, SliceOrientation::Sagittal}) {
        const auto stack = vv::slices::sliceStack(cta.volume, o);
        for (const double fraction : {0.3, 0.5, 0.7}) {
            // Slices through the vessel tree: 30, 50, 70 % across its extent.
            const int a = stack.axis;
            const int k =
                stack.nearestIndex(bounds.min[a] + fraction * (bounds.max[a] - bounds.min[a]));
            SCOPED_TRACE(testing::Message()
                         << "orientation " << static_cast<int>(o) << " slice " << k);
            const auto plane = stack.planeAt(k);
            const auto labels = vv::slices::resliceLabels(*outcome.labelMap, plane);
            const auto edge = overlayEdge(labels);
            const auto cut = meshCut(mesh, plane, 0.5 * plane.pixelSpacing);
            ASSERT_FALSE(cut.empty());
            ASSERT_FALSE(edge.empty());
            double worst = 0.0;
            for (const glm::dvec2& p : cut) {
                worst = std::max(worst, nearestDistance(p, edge) * plane.pixelSpacing);
            }
            EXPECT_LE(worst, voxel) << "mm; voxel " << voxel << " mm";
        }
    }
}

TEST(OverlayAlignmentTest, PreviewLabelMapKeepsItsCoarseGeometry) {
    // A preview segments every second voxel: its label map has its own
    // geometry, and resliced through it the overlay still covers the lumen.
    const vv::test::SyntheticCta cta = vv::test::makeSyntheticCta();
    vv::segmentation::SegmentationRequest request;
    request.volume = std::make_shared<const vv::scene::Volume>(cta.volume);
    request.step = 2;
    const auto outcome = vv::segmentation::runSegmentation(request);
    ASSERT_TRUE(outcome.labelMap);
    EXPECT_EQ(outcome.labelMap->dims, (cta.volume.dims() + 1) / 2);
    const auto stack = vv::slices::sliceStack(cta.volume, SliceOrientation::Coronal);
    // The coronal slice with the most overlay pixels.
    vv::slices::SlicePlane plane;
    vv::Image<std::uint8_t> labels;
    std::size_t most = 0;
    for (int k = 0; k < stack.count; k += 2) {
        auto candidate = vv::slices::resliceLabels(*outcome.labelMap, stack.planeAt(k));
        const auto n = static_cast<std::size_t>(
            std::count_if(candidate.data(), candidate.data() + candidate.pixelCount(),
                          [](std::uint8_t l) { return l != 0; }));
        if (n > most) {
            most = n;
            plane = stack.planeAt(k);
            labels = std::move(candidate);
        }
    }
    const auto values = vv::slices::reslice(cta.volume, plane);
    int labelled = 0;
    int brightLabelled = 0;
    for (int r = 0; r < labels.height(); ++r) {
        for (int c = 0; c < labels.width(); ++c) {
            if (labels(c, r) != 0) {
                ++labelled;
                brightLabelled += values(c, r) >= 200.0F ? 1 : 0;
            }
        }
    }
    ASSERT_GT(labelled, 20);
    EXPECT_GT(brightLabelled, labelled * 7 / 10);
}

}  // namespace
