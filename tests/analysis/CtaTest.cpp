// SPDX-License-Identifier: GPL-3.0-or-later
// The synthetic CTA (the demo tree voxelised, vv/demo/DemoCtSeries.h)
// written as a CT series, segmented as `vesselview-cli render` segments a
// DICOM folder, and analysed: every leaf of the tree it was built from has
// its end, and the centrelines and the sections' equivalent diameters agree
// with the construction to within what the voxels allow.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include "AnalysisAgreement.h"
#include "vv/analysis/Centerlines.h"
#include "vv/analysis/Sections.h"
#include "vv/demo/DemoCtSeries.h"
#include "vv/demo/DemoTree.h"
#include "vv/meshio/MeshSimplify.h"

namespace {

TEST(CtaAnalysis, SegmentedSeriesAgreesWithItsTree) {
    vv::demo::DemoCtOptions options;
    options.generations = 3;
    options.dims = {64, 64, 64};
    const vv::demo::DemoCt ct = vv::demo::generateDemoCt(options);
    const std::filesystem::path folder = std::filesystem::path(VV_TEST_TMP) / "cta-analysis";
    std::filesystem::remove_all(folder);
    const auto mesh = vv::bench::segmentAsRenderDoes(ct, folder);
    std::filesystem::remove_all(folder);
    const auto tree = vv::analysis::computeCenterlines(mesh);
    const auto sections = vv::analysis::computeSections(mesh, tree);

    const glm::dvec3 spacing = ct.volume.spacing();
    const double voxel = std::cbrt(spacing.x * spacing.y * spacing.z);
    const auto a = vv::bench::compareWithConstruction(ct.tree, tree, sections,
                                                      std::max({spacing.x, spacing.y, spacing.z}));
    ASSERT_GE(a.leaves, 4U);
    EXPECT_GE(static_cast<double>(a.leavesFound), 0.9 * static_cast<double>(a.leaves));
    EXPECT_LE(a.endsElsewhere, 1U);
    EXPECT_GE(static_cast<double>(a.sectionsOk), 0.95 * static_cast<double>(a.sectionsAll));
    EXPECT_GT(a.compared, 100U);

    // The segmented wall lies within about half a voxel of the built one
    // (the threshold sits near half the lumen's contrast; the surface of
    // the binary mask is smoothed back towards it), so a section's radius is
    // within about h / 2 of the built radius: per the thinnest vessel's
    // radius, the most a typical section may be off; the median must keep
    // inside it. The same for the centreline's distance from the built axis.
    double thinnest = ct.tree.segments.front().radiusMm;
    for (const auto& segment : ct.tree.segments) {
        thinnest = std::min(thinnest, segment.radiusMm);
    }
    const double halfVoxel = 0.5 * voxel / thinnest;
    EXPECT_LT(std::abs(a.diameterErrorMedian), halfVoxel);
    EXPECT_LT(a.offAxisMedian, halfVoxel);
    RecordProperty("half_voxel_per_thinnest_r", std::to_string(halfVoxel));
    RecordProperty("diameter_error_median", std::to_string(a.diameterErrorMedian));
    RecordProperty("off_axis_median_per_r", std::to_string(a.offAxisMedian));
}

// The demo tree as a coarse segmentation comes: decimated from 300k to 20k
// triangles (quadric edge collapse; facets up to several radii of its thin
// vessels long). Every leaf keeps its end, no false end appears, and the
// sections agree with the construction as on the fine surface.
TEST(CoarseAnalysis, TheDecimatedDemoTreeKeepsEveryVesselAndNoOther) {
    const vv::demo::DemoTreeOptions options;
    const vv::demo::VesselTree truth = vv::demo::generateVesselTree(options);
    const auto fine = vv::demo::buildVesselSurface(truth, options);
    const auto mesh = vv::meshio::simplifiedMesh(fine, 20'000);
    ASSERT_LE(mesh.triangleCount(), 20'000U);
    const auto analysed = vv::analysis::analyseVessels(mesh);
    const auto a = vv::bench::compareWithConstruction(truth, analysed.tree, analysed.sections);
    ASSERT_GE(a.leaves, 30U);
    EXPECT_EQ(a.leavesFound, a.leaves);
    EXPECT_EQ(a.endsElsewhere, 0U);
    EXPECT_GE(static_cast<double>(a.sectionsOk), 0.97 * static_cast<double>(a.sectionsAll));
    EXPECT_LT(std::abs(a.diameterErrorMedian), 0.02);
    EXPECT_LT(a.diameterErrorP95, 0.05);
    EXPECT_LT(a.offAxisMedian, 0.12);
    RecordProperty("off_axis_p95_per_r", std::to_string(a.offAxisP95));
}

}  // namespace
