// SPDX-License-Identifier: GPL-3.0-or-later
// Coarse meshes drawn smooth up close (issue 36): app::smoothCopyOf makes
// the copy for a coarse scene and none for a fine one or one it would
// deform; `render --smooth-coarse on` draws it where the facets are large
// on screen, and the depth the renderer writes shows a round tube where the
// mesh is an octagon (seen end-on: the "left" view looks along x); off, or
// with facets small on screen, the mesh as it is.
// Rendering needs OpenGL: run under `xvfb-run -a` (QT_QPA_PLATFORM=xcb).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "CliRun.h"
#include "ReportTestUtil.h"
#include "TestMeshes.h"
#include "common/SmoothCopy.h"
#include "vv/demo/AneurysmPhantom.h"
#include "vv/meshio/MeshLoader.h"
#include "vv/meshio/MeshWriter.h"
#include "vv/scene/Mesh.h"
#include "vv/vss/Pfm.h"

namespace {

namespace fs = std::filesystem;
using vv::scene::Mesh;
using vv::scene::Scene;

fs::path testDir() {
    fs::path dir = vv::test::processTestDir("smooth-coarse");
    fs::create_directories(dir);
    return dir;
}

/// A tube along x of radius 10 mm and length 60 mm (open: its rims are
/// its outline seen end-on), `around` points per ring on the circle.
Mesh tube(int around, int along) {
    return vv::test::tube({.radius = 10.0F,
                           .start = glm::vec3(0.0F),
                           .length = 60.0F,
                           .segments = around,
                           .rings = along});
}

using Result = vv::test::CliRunResult;

Result cli(const std::vector<std::string>& args) {
    return vv::test::runCli(args);
}

/// The spread of the outline's radius about its centroid, over its mean,
/// in the depth image of a tube seen end-on (finite depth: the tube).
double outlineSpread(const vv::Image<float>& depth) {
    double sx = 0.0;
    double sy = 0.0;
    double n = 0.0;
    for (int y = 0; y < depth.height(); ++y) {
        for (int x = 0; x < depth.width(); ++x) {
            if (std::isfinite(depth(x, y))) {
                sx += x;
                sy += y;
                n += 1.0;
            }
        }
    }
    EXPECT_GT(n, 1000.0);
    const double cx = sx / n;
    const double cy = sy / n;
    std::vector<double> radii;
    for (int k = 0; k < 720; ++k) {
        const double a = 2.0 * std::numbers::pi * k / 720.0;
        double r = 0.0;
        for (double t = 0.0; t < depth.width(); t += 0.25) {
            const int x = static_cast<int>(std::lround(cx + t * std::cos(a)));
            const int y = static_cast<int>(std::lround(cy + t * std::sin(a)));
            if (x < 0 || y < 0 || x >= depth.width() || y >= depth.height()) {
                break;
            }
            if (std::isfinite(depth(x, y))) {
                r = t;
            }
        }
        radii.push_back(r);
    }
    const auto [lo, hi] = std::minmax_element(radii.begin(), radii.end());
    double mean = 0.0;
    for (const double r : radii) {
        mean += r / static_cast<double>(radii.size());
    }
    return (*hi - *lo) / mean;
}

TEST(SmoothCopy, ACoarseAortaGetsACopyNearItAndAFineSceneNone) {
    vv::demo::AneurysmPhantomOptions options;
    options.targetTriangles = 2'000;
    Scene coarse;
    coarse.meshes.push_back(vv::demo::makeAneurysmPhantom(options).mesh);
    const auto copy = vv::app::smoothCopyOf(coarse);
    ASSERT_TRUE(copy.has_value());
    ASSERT_TRUE(copy->scene);
    EXPECT_EQ(copy->scene->triangleCount(), 4 * coarse.triangleCount());
    EXPECT_DOUBLE_EQ(copy->sourceEdgeMm, vv::app::medianEdgeLength(coarse));
    EXPECT_GT(copy->largestDeviationMm, 0.0);
    EXPECT_LE(copy->largestDeviationMm, vv::app::kMaxSmoothDeviationEdges * copy->sourceEdgeMm);
    EXPECT_LT(copy->meanDeviationMm, copy->largestDeviationMm);
    EXPECT_NE(vv::app::smoothCopyNote(*copy).find(" mm"), std::string::npos);

    options.targetTriangles = 2 * vv::app::kMaxSmoothedTriangles;
    Scene fine;
    fine.meshes.push_back(vv::demo::makeAneurysmPhantom(options).mesh);
    std::string why;
    EXPECT_FALSE(vv::app::smoothCopyOf(fine, {}, &why).has_value());
    EXPECT_NE(why.find("fine enough"), std::string::npos) << why;
}

TEST(SmoothCopy, ACopyThatWouldMoveTheWallFarIsRefused) {
    // Fine facets (the median edge, 1 mm) beside a big sharp tetrahedron,
    // which subdivision rounds by many of those edges.
    Scene scene;
    scene.meshes.push_back(tube(64, 60));
    Mesh spike;
    spike.name = "spike";
    spike.positions = {{100, 0, 0}, {200, 0, 0}, {150, 87, 0}, {150, 29, 82}};
    spike.indices = {0, 2, 1, 0, 1, 3, 1, 2, 3, 2, 0, 3};
    vv::scene::computeNormals(spike);
    scene.meshes.push_back(spike);
    std::string why;
    EXPECT_FALSE(vv::app::smoothCopyOf(scene, {}, &why).has_value());
    EXPECT_NE(why.find("would move the wall"), std::string::npos) << why;
}

TEST(SmoothCoarseRender, AnOctagonalTubeEndOnIsDrawnRoundWhereItsFacetsAreLarge) {
    const fs::path dir = testDir();
    const fs::path file = dir / "octagon.vtp";
    vv::meshio::writeVtp(tube(8, 6), file);
    std::array<double, 2> spread{0.0, 0.0};
    for (const bool on : {false, true}) {
        const fs::path depth = dir / (on ? "on.pfm" : "off.pfm");
        const Result r = cli({"render", file.string(), "-o", (dir / "image.png").string(), "--size",
                              "400x400", "--view", "left", "--depth-out", depth.string(),
                              "--smooth-coarse", on ? "on" : "off"});
        ASSERT_EQ(r.code, vv::cli::kOk) << r.err;
        // The note says so, with how far the wall moved; off, nothing.
        EXPECT_EQ(r.out.find("drawn smoothed") != std::string::npos, on) << r.out;
        spread.at(on ? 1 : 0) = outlineSpread(vv::vss::readPfm(depth));
    }
    // An octagon's outline: its radius from 0.924 to 1 of the circle's
    // (7.9 % of the mean); the smooth copy's is round within a fraction.
    EXPECT_GT(spread[0], 0.06);
    EXPECT_LT(spread[1], 0.4 * spread[0]);
}

TEST(SmoothCoarseRender, FacetsSmallOnScreenAreDrawnAsTheyAre) {
    const fs::path dir = testDir();
    const fs::path file = dir / "fine.vtp";
    vv::meshio::writeVtp(tube(64, 40), file);  // edges about 1-1.5 mm
    // 48 px across a 20 mm tube: 2-3 px per mm, a median edge of a few px.
    const Result small = cli({"render", file.string(), "-o", (dir / "small.png").string(), "--size",
                              "64x64", "--view", "left"});
    ASSERT_EQ(small.code, vv::cli::kOk) << small.err;
    EXPECT_EQ(small.out.find("drawn smoothed"), std::string::npos) << small.out;
    // The same tube filling 400 px: 15 px per mm, smoothed.
    const Result large = cli({"render", file.string(), "-o", (dir / "large.png").string(), "--size",
                              "400x400", "--view", "left"});
    ASSERT_EQ(large.code, vv::cli::kOk) << large.err;
    EXPECT_NE(large.out.find("drawn smoothed"), std::string::npos) << large.out;
}

TEST(SmoothCoarseReport, TheReportSaysItsViewIsSmoothedAndByHowMuch) {
    const fs::path dir = testDir();
    const fs::path aorta = dir / "aorta-2k.vtp";
    const Result made = cli({"demo", "--aorta", "--triangles", "2000", "-o", aorta.string()});
    ASSERT_EQ(made.code, vv::cli::kOk) << made.err;
    EXPECT_NE(made.out.find("2000 triangles"), std::string::npos) << made.out;
    for (const bool on : {false, true}) {
        const fs::path pdf = dir / (on ? "on.pdf" : "off.pdf");
        const Result r = cli(
            {"report", aorta.string(), "-o", pdf.string(), "--smooth-coarse", on ? "on" : "off"});
        ASSERT_EQ(r.code, vv::cli::kOk) << r.err;
        std::string text;
        for (const vv::report::test::PdfWord& word : vv::report::test::pdfWords(pdf)) {
            text += word.text + " ";
        }
        // The settings table's row.
        EXPECT_EQ(text.find("Coarse facets") != std::string::npos, on) << text;
        // The row gives the copy's Hausdorff distance from the mesh.
        const std::string row = "smoothed up close (the wall moved by at most ";
        const std::size_t inReport = text.find(row);
        ASSERT_EQ(inReport != std::string::npos, on) << text;
        if (on) {
            Scene scene;
            scene.meshes.push_back(vv::meshio::loadMesh(aorta));
            const auto copy = vv::app::smoothCopyOf(scene);
            ASSERT_TRUE(copy.has_value());
            EXPECT_NEAR(std::stod(text.substr(inReport + row.size())), copy->largestDeviationMm,
                        0.005)
                << text;
        }
    }
}

}  // namespace
