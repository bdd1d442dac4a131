// SPDX-License-Identifier: GPL-3.0-or-later
// `vesselview-cli render --view ... --depth-out D.pfm` through vv::cli::run,
// and the round trip of the depth into `vesselview-cli vss --depth`.
// Rendering needs OpenGL: run under `xvfb-run -a` (QT_QPA_PLATFORM=xcb).
#include <gtest/gtest.h>
#include <unistd.h>

#include <QImage>
#include <QString>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "cli/Cli.h"
#include "vv/vss/Pfm.h"

namespace render_view_depth_test {

namespace {

namespace fs = std::filesystem;

fs::path testDir() {
    const fs::path dir =
        fs::path(VV_TEST_TMP) / "render-view-depth" / ("run-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return dir;
}

struct Result {
    int code = 0;
    std::string out;
    std::string err;
};

Result cli(const std::vector<std::string>& args) {
    std::ostringstream out;
    std::ostringstream err;
    const int code = vv::cli::run(args, out, err);
    return {code, out.str(), err.str()};
}

/// A small demo tree (3 generations), written once per process.
const fs::path& demoFile() {
    static const fs::path file = [] {
        const fs::path f = testDir() / "demo-g3.vtp";
        const Result r =
            cli({"demo", "--generations", "3", "--voxel-size", "0.5", "-o", f.string()});
        EXPECT_EQ(r.code, vv::cli::kOk) << r.err;
        return f;
    }();
    return file;
}

long countFinite(const vv::Image<float>& depth) {
    long n = 0;
    for (int y = 0; y < depth.height(); ++y) {
        for (int x = 0; x < depth.width(); ++x) {
            n += std::isfinite(depth(x, y)) ? 1 : 0;
        }
    }
    return n;
}

TEST(RenderViewDepthTest, UnknownViewIsAUsageErrorListingTheViews) {
    const Result r = cli({"render", demoFile().string(), "-o", (testDir() / "x.png").string(),
                          "--view", "sideways"});
    EXPECT_EQ(r.code, vv::cli::kUsage);
    EXPECT_NE(r.err.find("sideways"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("anterior"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("inferior"), std::string::npos) << r.err;
    const Result missing =
        cli({"render", demoFile().string(), "-o", (testDir() / "x.png").string(), "--depth-out"});
    EXPECT_EQ(missing.code, vv::cli::kUsage);
}

TEST(RenderViewDepthTest, DepthOutIntoAMissingFolderFailsBeforeRendering) {
    const Result r = cli({"render", demoFile().string(), "-o", (testDir() / "x.png").string(),
                          "--depth-out", (testDir() / "no-such-folder" / "d.pfm").string()});
    EXPECT_EQ(r.code, vv::cli::kCannotWrite) << r.err;
    EXPECT_NE(r.err.find("no-such-folder"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(testDir() / "x.png"));
}

TEST(RenderViewDepthTest, DepthOutRoundTripsThroughVss) {
    const fs::path image = testDir() / "anterior.png";
    const fs::path depthFile = testDir() / "anterior.pfm";
    const Result r = cli({"render", demoFile().string(), "--size", "160x120", "--view", "anterior",
                          "--vss", "on", "-o", image.string(), "--depth-out", depthFile.string()});
    ASSERT_EQ(r.code, vv::cli::kOk) << r.err;
    EXPECT_NE(r.out.find(depthFile.string()), std::string::npos) << r.out;
    const vv::Image<float> depth = vv::vss::readPfm(depthFile);
    ASSERT_EQ(depth.width(), 160);
    ASSERT_EQ(depth.height(), 120);
    // Vessels (positive finite depth) and background (+Inf), nothing else.
    const long finite = countFinite(depth);
    EXPECT_GT(finite, 200);
    EXPECT_LT(finite, 160L * 120L / 2);
    for (int y = 0; y < depth.height(); ++y) {
        for (int x = 0; x < depth.width(); ++x) {
            const float d = depth(x, y);
            ASSERT_TRUE((std::isfinite(d) && d > 0.0F) || (std::isinf(d) && d > 0.0F))
                << x << "," << y << ": " << d;
        }
    }
    const QImage png(QString::fromStdString(image.string()));
    ASSERT_EQ(png.width(), 160);
    // `vss --depth` accepts it and solves.
    const fs::path height = testDir() / "anterior-vss.pfm";
    const Result v = cli({"vss", "--depth", depthFile.string(), "-o", height.string()});
    ASSERT_EQ(v.code, vv::cli::kOk) << v.err;
    const vv::Image<float> solved = vv::vss::readPfm(height);
    EXPECT_EQ(solved.width(), 160);
    EXPECT_EQ(solved.height(), 120);
}

TEST(RenderViewDepthTest, GpuAndCpuDepthAgreeAndViewsDiffer) {
    // VSS on: the depth is the G-buffer's; VSS off: the CPU rasteriser's with
    // the same camera. They must describe the same picture.
    const auto render = [](const std::string& view, const std::string& vss) {
        const fs::path depthFile = testDir() / (view + "-" + vss + ".pfm");
        const Result r =
            cli({"render", demoFile().string(), "--size", "200x150", "--view", view, "--vss", vss,
                 "-o", (testDir() / (view + "-" + vss + ".png")).string(), "--depth-out",
                 depthFile.string()});
        EXPECT_EQ(r.code, vv::cli::kOk) << r.err;
        return vv::vss::readPfm(depthFile);
    };
    const vv::Image<float> gpu = render("close", "on");
    const vv::Image<float> cpu = render("close", "off");
    ASSERT_EQ(gpu.width(), cpu.width());
    ASSERT_EQ(gpu.height(), cpu.height());
    long both = 0;
    long mismatch = 0;
    std::vector<double> relative;
    for (int y = 0; y < gpu.height(); ++y) {
        for (int x = 0; x < gpu.width(); ++x) {
            const bool g = std::isfinite(gpu(x, y));
            const bool c = std::isfinite(cpu(x, y));
            mismatch += g != c ? 1 : 0;
            if (g && c) {
                ++both;
                relative.push_back(std::abs(gpu(x, y) - cpu(x, y)) / cpu(x, y));
            }
        }
    }
    ASSERT_GT(both, 1000);
    // Only silhouette pixels may disagree on coverage.
    EXPECT_LT(mismatch, both / 20) << mismatch << " of " << both;
    std::sort(relative.begin(), relative.end());
    EXPECT_LT(relative[relative.size() / 2], 1e-3);
    // Another view, another picture.
    const vv::Image<float> superior = render("superior", "off");
    long differ = 0;
    for (int y = 0; y < cpu.height(); ++y) {
        for (int x = 0; x < cpu.width(); ++x) {
            differ += std::isfinite(superior(x, y)) != std::isfinite(cpu(x, y)) ? 1 : 0;
        }
    }
    EXPECT_GT(differ, 500);
}

}  // namespace

}  // namespace render_view_depth_test
