// SPDX-License-Identifier: GPL-3.0-or-later
// Vessels from volumes: segmentation, surface extraction and the DICOM
// round trip of the synthetic demo tree (written as a CT series with DCMTK).
#include <gtest/gtest.h>
#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStaticCellLocator.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numeric>
#include <optional>
#include <stop_token>

#include "DicomSegTestUtil.h"
#include "DicomTestUtil.h"
#include "SyntheticCta.h"
#include "vv/core/Error.h"
#include "vv/dicom/Dicom.h"
#include "vv/dicom/DicomSeg.h"
#include "vv/dicom/SeriesWriter.h"
#include "vv/meshio/MeshWriter.h"
#include "vv/segmentation/SceneSource.h"
#include "vv/segmentation/VolumeSegmentation.h"
#include "vv/segmentation/VolumeSurface.h"

namespace fs = std::filesystem;
using namespace vv;
using namespace vv::scene;
using namespace vv::dicom;
using namespace vv::segmentation;
using namespace vv::demo;

namespace {

fs::path freshDir(const std::string& name) {
    const fs::path dir = fs::path(VV_TEST_TMP) / "vessels-from-volume" / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

vtkSmartPointer<vtkPolyData> toPolyData(const Mesh& mesh) {
    vtkNew<vtkPoints> points;
    for (const glm::vec3& p : mesh.positions) {
        points->InsertNextPoint(p.x, p.y, p.z);
    }
    vtkNew<vtkCellArray> cells;
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const vtkIdType ids[3] = {mesh.indices[3 * t], mesh.indices[3 * t + 1],
                                  mesh.indices[3 * t + 2]};
        cells->InsertNextCell(3, ids);
    }
    auto poly = vtkSmartPointer<vtkPolyData>::New();
    poly->SetPoints(points);
    poly->SetPolys(cells);
    return poly;
}

/// Distances from every vertex of `from` to the surface `to`.
std::vector<double> distances(const Mesh& from, const Mesh& to) {
    const auto poly = toPolyData(to);
    vtkNew<vtkStaticCellLocator> locator;
    locator->SetDataSet(poly);
    locator->BuildLocator();
    std::vector<double> out;
    out.reserve(from.vertexCount());
    for (const glm::vec3& p : from.positions) {
        double x[3] = {p.x, p.y, p.z};
        double closest[3];
        vtkIdType cell = 0;
        int sub = 0;
        double d2 = 0.0;
        locator->FindClosestPoint(x, closest, cell, sub, d2);
        out.push_back(std::sqrt(d2));
    }
    return out;
}

double mean(const std::vector<double>& v) {
    return std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
}

double percentile(std::vector<double> v, double q) {
    std::sort(v.begin(), v.end());
    return v[static_cast<std::size_t>(q * static_cast<double>(v.size() - 1))];
}

/// The synthetic CTA, built once per test program.
const test::SyntheticCta& cta() {
    static const test::SyntheticCta instance = test::makeSyntheticCta();
    return instance;
}

double voxelSize(const Volume& v) {
    const glm::dvec3 s = v.spacing();
    return std::cbrt(s.x * s.y * s.z);
}

}  // namespace

// The round trip of issue 5: demo tree -> CT series (DCMTK) -> load ->
// segment with the CTA defaults -> surface -> compare with the tree's surface.
TEST(VesselsFromVolume, DicomRoundTripMatchesTheDemoTree) {
    const fs::path dir = freshDir("round-trip");
    const std::string uid = test::writeCtSeries(dir, cta().volume);
    const DicomVolume loaded = loadDicomVolume(dir);
    EXPECT_EQ(loaded.seriesInstanceUid, uid);
    const Volume& volume = loaded.volume;
    ASSERT_EQ(volume.dims(), cta().volume.dims());
    EXPECT_EQ(volume.modality(), "CT");
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 3; ++r) {
            EXPECT_NEAR(volume.indexToWorld()[c][r], cta().volume.indexToWorld()[c][r], 1e-4);
        }
    }
    EXPECT_EQ(volume.value(5, 6, 7), cta().volume.value(5, 6, 7));

    const Segmentation seg = segmentVessels(volume);
    EXPECT_FLOAT_EQ(seg.range.lower, 200.0F);
    EXPECT_FLOAT_EQ(seg.range.upper, 700.0F);
    EXPECT_TRUE(seg.boneRemoved);
    EXPECT_EQ(seg.boneComponents, 1U);
    ASSERT_EQ(seg.labelMap.components.size(), 1U);
    EXPECT_EQ(seg.labelMap.dims, volume.dims());
    // No kept voxel in or next to the bone block.
    const double h = voxelSize(volume);
    std::size_t inBone = 0;
    for (int k = 0; k < volume.dims().z; ++k) {
        for (int j = 0; j < volume.dims().y; ++j) {
            for (int i = 0; i < volume.dims().x; ++i) {
                if (seg.labelMap.labels[seg.labelMap.index(i, j, k)] != 0 &&
                    cta().inBone(volume.worldPosition(glm::dvec3(i, j, k)), 2.0 * h)) {
                    ++inBone;
                }
            }
        }
    }
    EXPECT_EQ(inBone, 0U);

    const Mesh surface = extractSurface(seg.labelMap, {}, {.targetTriangles = 60000});
    EXPECT_LE(surface.triangleCount(), 60000U);
    EXPECT_GT(surface.triangleCount(), 5000U);
    ASSERT_EQ(surface.normals.size(), surface.vertexCount());

    DemoTreeOptions reference = cta().treeOptions;
    reference.maxTriangles = 200000;
    const Mesh tree = buildVesselSurface(cta().tree, reference);
    const auto toTree = distances(surface, tree);
    const auto fromTree = distances(tree, surface);
    const double meanSymmetric = (mean(toTree) * static_cast<double>(toTree.size()) +
                                  mean(fromTree) * static_cast<double>(fromTree.size())) /
                                 static_cast<double>(toTree.size() + fromTree.size());
    const double p95 = std::max(percentile(toTree, 0.95), percentile(fromTree, 0.95));
    const double maxToTree = percentile(toTree, 1.0);
    std::printf(
        "voxel %.3f mm: mean symmetric %.3f mm, p95 %.3f mm, max extracted->tree %.3f, "
        "max tree->extracted %.3f mm\n",
        h, meanSymmetric, p95, maxToTree, percentile(fromTree, 1.0));
    EXPECT_LT(meanSymmetric, 0.5 * h);
    EXPECT_LT(p95, 1.5 * h);
    EXPECT_LT(maxToTree, 3.0 * h);  // nothing extracted far from the tree
    // Outward normals: the surface encloses a positive volume.
    double volume6 = 0.0;
    for (std::size_t t = 0; t < surface.triangleCount(); ++t) {
        const glm::dvec3 a(surface.positions[surface.indices[3 * t]]);
        const glm::dvec3 b(surface.positions[surface.indices[3 * t + 1]]);
        const glm::dvec3 c(surface.positions[surface.indices[3 * t + 2]]);
        volume6 += glm::dot(a, glm::cross(b, c));
    }
    EXPECT_NEAR(volume6 / 6.0, seg.labelMap.components[0].volumeMm3,
                0.15 * seg.labelMap.components[0].volumeMm3);

    // The same through the one-call scene source (folder and single file).
    SceneSourceOptions options;
    options.surface.targetTriangles = 20000;
    SceneSourceReport report;
    const Scene scene = loadSceneSource(dir / "slice3.dcm", options, {}, &report);
    ASSERT_EQ(scene.meshes.size(), 1U);
    EXPECT_TRUE(report.fromVolume);
    EXPECT_EQ(report.seriesInstanceUid, uid);
    EXPECT_EQ(report.volumeDims, volume.dims());
    EXPECT_EQ(report.componentsKept, 1U);
    EXPECT_LE(scene.meshes[0].triangleCount(), 20000U);
    EXPECT_EQ(scene.meshes[0].source, dir / "slice3.dcm");
    // What the series says of itself, to name it by (never its UID).
    EXPECT_EQ(report.seriesDescription, "synthetic CTA");
    EXPECT_EQ(report.modality, "CT");
    EXPECT_EQ(report.seriesNumber, std::optional<int>(1));
    EXPECT_EQ(report.studyDate, "20250101");
    // A mesh loaded with the same report afterwards leaves nothing of it.
    const fs::path mesh = dir.parent_path() / "round-trip-mesh.vtp";
    meshio::writeVtp(scene.meshes[0], mesh);
    (void)loadSceneSource(mesh, {}, {}, &report);
    EXPECT_FALSE(report.fromVolume);
    EXPECT_TRUE(report.seriesDescription.empty());
    EXPECT_FALSE(report.seriesNumber.has_value());
}

TEST(VesselsFromVolume, WithoutBoneRemovalTheBoneRimIsAComponent) {
    SegmentationOptions options;
    options.removeBone = false;
    options.keepComponents = 2;
    const Segmentation seg = segmentVessels(cta().volume, options);
    EXPECT_FALSE(seg.boneRemoved);
    ASSERT_EQ(seg.labelMap.components.size(), 2U);
    const Volume& v = cta().volume;
    std::size_t boneVoxels = 0;
    for (int k = 0; k < v.dims().z; ++k) {
        for (int j = 0; j < v.dims().y; ++j) {
            for (int i = 0; i < v.dims().x; ++i) {
                const auto l = seg.labelMap.labels[seg.labelMap.index(i, j, k)];
                if (l != 0 && cta().inBone(v.worldPosition(glm::dvec3(i, j, k)), 2.0)) {
                    ++boneVoxels;
                }
            }
        }
    }
    EXPECT_GT(boneVoxels, 100U);
    EXPECT_GE(seg.labelMap.components[0].voxels, seg.labelMap.components[1].voxels);
}

TEST(VesselsFromVolume, SeedKeepsTheComponentUnderIt) {
    const Volume& v = cta().volume;
    const glm::vec3 root = cta().tree.segments[0].centerline[1];
    const glm::dvec3 ijk = glm::round(glm::dvec3(v.worldToIndex() * glm::dvec4(root, 1.0)));
    SegmentationOptions options;
    options.seed = glm::ivec3(ijk);
    const Segmentation bySeed = segmentVessels(v, options);
    const Segmentation largest = segmentVessels(v);
    ASSERT_EQ(bySeed.labelMap.components.size(), 1U);
    EXPECT_EQ(bySeed.labelMap.components[0].voxels, largest.labelMap.components[0].voxels);
    EXPECT_EQ(bySeed.labelMap.labels, largest.labelMap.labels);

    options.seed = glm::ivec3(0, 0, 0);  // tissue: outside the range
    EXPECT_THROW((void)segmentVessels(v, options), InvalidArgumentError);
    options.seed = glm::ivec3(0, 0, v.dims().z);
    EXPECT_THROW((void)segmentVessels(v, options), InvalidArgumentError);
}

TEST(VesselsFromVolume, RefusesBadOptionsAndCancels) {
    const Volume& v = cta().volume;
    SegmentationOptions options;
    options.range = ThresholdRange{700.0F, 200.0F, "reversed"};
    EXPECT_THROW((void)segmentVessels(v, options), InvalidArgumentError);
    options.range = ThresholdRange{5000.0F, 6000.0F, "empty"};
    EXPECT_THROW((void)segmentVessels(v, options), FormatError);
    options = {};
    options.keepComponents = 0;
    EXPECT_THROW((void)segmentVessels(v, options), InvalidArgumentError);
    EXPECT_THROW((void)segmentVessels(Volume{}), InvalidArgumentError);

    std::stop_source stop;
    stop.request_stop();
    EXPECT_THROW((void)segmentVessels(v, {}, Progress({}, stop.get_token())), CancelledError);
    const Segmentation seg = segmentVessels(v);
    EXPECT_THROW((void)extractSurface(seg.labelMap, {}, {}, Progress({}, stop.get_token())),
                 CancelledError);
    EXPECT_THROW((void)extractSurface(seg.labelMap, {7}), FormatError);
    LabelMap broken = seg.labelMap;
    broken.labels.pop_back();
    EXPECT_THROW((void)extractSurface(broken), InvalidArgumentError);
}

TEST(VesselsFromVolume, MrThresholdComesFromTheHistogram) {
    // MR-like: no bright bone; tissue ~40, lumen ~400.
    Volume v = cta().volume;
    v.setModality("MR");
    v.setUnit("");
    for (std::size_t n = 0; n < v.voxelCount(); ++n) {
        if (v.valueAt(n) > 800.0F) {
            v.setValueAt(n, 40.0F);
        }
    }
    const auto check = [](const Volume& volume, const char* what) {
        SCOPED_TRACE(what);
        const ThresholdRange range = defaultThresholdRange(volume);
        // Between tissue (~40) and lumen (~400), the upper bound the maximum.
        EXPECT_GT(range.lower, 120.0F) << range.rule;
        EXPECT_LT(range.lower, 330.0F) << range.rule;
        EXPECT_FLOAT_EQ(range.upper, volume.valueRange().second);
        EXPECT_NE(range.rule.find("Otsu"), std::string::npos);
        const Segmentation seg = segmentVessels(volume);
        EXPECT_FALSE(seg.boneRemoved);  // MR: off by default
        EXPECT_EQ(seg.labelMap.components.size(), 1U);
    };
    check(v, "body only");
    // Air (~0) in the lower half of the slices, where there is no lumen.
    for (int k = 0; k < v.dims().z / 2; ++k) {
        for (int j = 0; j < v.dims().y; ++j) {
            for (int i = 0; i < v.dims().x; ++i) {
                const std::size_t n = v.index(i, j, k);
                if (v.valueAt(n) < 120.0F) {
                    v.setValueAt(n, v.valueAt(n) - 40.0F);
                }
            }
        }
    }
    check(v, "with air");
}

// A ball on a sheared, mirrored, anisotropic grid: the surface lands on the
// ball in world space with outward normals.
TEST(VesselsFromVolume, SurfaceOnAShearedMirroredGrid) {
    const glm::ivec3 dims(40, 36, 30);
    glm::dmat4 m(1.0);
    m[0] = glm::dvec4(-0.8, 0.0, 0.0, 0.0);  // mirrored rows
    m[1] = glm::dvec4(0.0, 0.9, 0.0, 0.0);
    m[2] = glm::dvec4(0.0, 0.3, 1.1, 0.0);  // gantry-tilt shear
    m[3] = glm::dvec4(10.0, -5.0, 20.0, 1.0);
    const glm::dvec3 centre(glm::dvec4(m * glm::dvec4(20.0, 14.0, 15.0, 1.0)));
    const double radius = 9.0;
    LabelMap map;
    map.dims = dims;
    map.indexToWorld = m;
    map.labels.assign(static_cast<std::size_t>(dims.x * dims.y * dims.z), 0);
    for (int k = 0; k < dims.z; ++k) {
        for (int j = 0; j < dims.y; ++j) {
            for (int i = 0; i < dims.x; ++i) {
                const glm::dvec3 p(m * glm::dvec4(i, j, k, 1.0));
                if (glm::length(p - centre) <= radius) {
                    map.labels[map.index(i, j, k)] = 1;
                }
            }
        }
    }
    const Mesh mesh = extractSurface(map, {1}, {.targetTriangles = 0});
    ASSERT_GT(mesh.vertexCount(), 100U);
    double worst = 0.0;
    std::size_t outward = 0;
    for (std::size_t n = 0; n < mesh.vertexCount(); ++n) {
        const glm::dvec3 d = glm::dvec3(mesh.positions[n]) - centre;
        worst = std::max(worst, std::abs(glm::length(d) - radius));
        outward += glm::dot(glm::dvec3(mesh.normals[n]), d) > 0.0 ? 1 : 0;
    }
    EXPECT_LT(worst, 1.0);  // about a voxel
    EXPECT_EQ(outward, mesh.vertexCount());
}

// DICOM SEG: two segments written with dcmseg on the oblique CTA grid (frames
// in reverse slice order) come back as two label maps on the same world grid
// and as two meshes named after the segments.
TEST(VesselsFromVolume, DicomSegLoadsAsLabelMapsAndMeshes) {
    const Volume& v = cta().volume;
    const glm::ivec3 dims = v.dims();
    const glm::dvec3 ballCentre = v.worldPosition(glm::dvec3(30.0, 40.0, 35.0));
    const double radius = 8.0;
    test::TestSegment ball{"ball", std::vector<std::uint8_t>(v.voxelCount(), 0)};
    test::TestSegment slab{"slab", std::vector<std::uint8_t>(v.voxelCount(), 0)};
    glm::dvec3 ballSum(0.0);
    std::size_t ballCount = 0;
    std::size_t slabCount = 0;
    for (int k = 0; k < dims.z; ++k) {
        for (int j = 0; j < dims.y; ++j) {
            for (int i = 0; i < dims.x; ++i) {
                const glm::dvec3 p = v.worldPosition(glm::dvec3(i, j, k));
                if (glm::length(p - ballCentre) <= radius) {
                    ball.mask[v.index(i, j, k)] = 1;
                    ballSum += p;
                    ++ballCount;
                }
                if (i >= 60 && i < 70 && j >= 10 && j < 80 && k >= 50 && k < 60) {
                    slab.mask[v.index(i, j, k)] = 1;
                    ++slabCount;
                }
            }
        }
    }
    ASSERT_GT(ballCount, 100U);
    ASSERT_GT(slabCount, 100U);
    const fs::path file = freshDir("seg") / "two-segments.dcm";
    test::writeBinarySeg(file, dims, v.indexToWorld(), {ball, slab});
    EXPECT_TRUE(isDicomSegFile(file));
    EXPECT_FALSE(isDicomSegFile(freshDir("seg-none") / "missing.dcm"));

    const std::vector<LabelMap> maps = loadDicomSegLabelMaps(file);
    ASSERT_EQ(maps.size(), 2U);
    EXPECT_EQ(maps[0].segmentNames, std::vector<std::string>{"ball"});
    EXPECT_EQ(maps[1].segmentNames, std::vector<std::string>{"slab"});
    EXPECT_EQ(maps[0].components[0].voxels, ballCount);
    EXPECT_EQ(maps[1].components[0].voxels, slabCount);
    EXPECT_EQ(maps[0].dims, maps[1].dims);
    // The same voxels in world space: the centroid of the ball.
    glm::dvec3 sum(0.0);
    const LabelMap& m = maps[0];
    for (int k = 0; k < m.dims.z; ++k) {
        for (int j = 0; j < m.dims.y; ++j) {
            for (int i = 0; i < m.dims.x; ++i) {
                if (m.labels[m.index(i, j, k)] != 0) {
                    sum += glm::dvec3(m.indexToWorld * glm::dvec4(i, j, k, 1.0));
                }
            }
        }
    }
    EXPECT_LT(glm::length(sum / static_cast<double>(ballCount) -
                          ballSum / static_cast<double>(ballCount)),
              1e-3);

    const Scene scene = loadDicomSegMeshes(file, {.targetTriangles = 0});
    ASSERT_EQ(scene.meshes.size(), 2U);
    EXPECT_EQ(scene.meshes[0].name, "ball");
    EXPECT_EQ(scene.meshes[1].name, "slab");
    double worst = 0.0;
    for (const glm::vec3& p : scene.meshes[0].positions) {
        worst = std::max(worst, std::abs(glm::length(glm::dvec3(p) - ballCentre) - radius));
    }
    EXPECT_LT(worst, voxelSize(v));

    SceneSourceReport report;
    const Scene viaSource = loadSceneSource(file, {}, {}, &report);
    EXPECT_EQ(viaSource.meshes.size(), 2U);
    EXPECT_TRUE(report.fromSegmentationObject);

    // Truncated: refused, no crash.
    const fs::path truncated = freshDir("seg-truncated") / "half.dcm";
    fs::copy_file(file, truncated);
    fs::resize_file(truncated, fs::file_size(file) / 2);
    EXPECT_THROW((void)loadDicomSegLabelMaps(truncated), FormatError);

    // A folder holding the SEG only, and one holding a CT series and the SEG.
    EXPECT_EQ(loadSceneSource(file.parent_path(), {}, {}, &report).meshes.size(), 2U);
    EXPECT_TRUE(report.fromSegmentationObject);
    const fs::path ct = freshDir("seg-ct");
    const std::string ctUid = test::writeCtSeries(ct, cta().volume);
    fs::copy_file(file, ct / "seg.dcm");
    EXPECT_THROW((void)loadSceneSource(ct), FormatError);  // two series, none chosen
    SceneSourceOptions choose;
    choose.seriesInstanceUid = scanDicom(file).allSeries().at(0)->seriesInstanceUid;
    EXPECT_EQ(loadSceneSource(ct, choose, {}, &report).meshes.size(), 2U);
    EXPECT_TRUE(report.fromSegmentationObject);
    choose.seriesInstanceUid = ctUid;
    choose.surface.targetTriangles = 5000;
    EXPECT_EQ(loadSceneSource(ct, choose, {}, &report).meshes.size(), 1U);
    EXPECT_TRUE(report.fromVolume);
    fs::remove(ct / "seg.dcm");

    // Not a SEG: a CT slice.
    EXPECT_FALSE(isDicomSegFile(ct / "slice0.dcm"));
    EXPECT_THROW((void)loadDicomSegLabelMaps(ct / "slice0.dcm"), FormatError);
    EXPECT_THROW((void)loadDicomSegLabelMaps(ct / "missing.dcm"), IoError);
}
