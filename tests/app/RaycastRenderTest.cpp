// SPDX-License-Identifier: GPL-3.0-or-later
// `vesselview-cli render DICOM_DIR --raycast [--iso HU]`: the synthetic CTA
// series (tests/support/SyntheticCta.h, written with DCMTK) ray cast directly as an
// iso-surface (volume depth source, no segmentation) with the VSS.
// Needs OpenGL: run under `xvfb-run -a` (QT_QPA_PLATFORM=xcb).
#include <gtest/gtest.h>
#include <unistd.h>

#include <QImage>
#include <QString>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "CliRun.h"
#include "DicomTestUtil.h"
#include "SyntheticCta.h"
#include "cli/Cli.h"
#include "vv/dicom/SeriesWriter.h"
#include "vv/vss/Pfm.h"

namespace {

namespace fs = std::filesystem;

fs::path testDir() {
    return vv::test::processTestDir("raycast-render");
}

using RunResult = vv::test::CliRunResult;

RunResult run(const std::vector<std::string>& args) {
    return vv::test::runCli(args);
}

class RaycastRenderTest : public ::testing::Test {
  protected:
    static void SetUpTestSuite() {
        fs::remove_all(testDir());
        const auto cta = vv::test::makeSyntheticCta({64, 64, 48}, 3);
        uid_ = vv::test::writeCtSeries(testDir() / "series", cta.volume);
    }
    static void TearDownTestSuite() {
        std::error_code ec;
        fs::remove_all(testDir(), ec);
    }
    static std::vector<std::string> args(const fs::path& output) {
        return {"render",    (testDir() / "series").string(),
                "-o",        output.string(),
                "--size",    "320x240",
                "--legends", "off",
                "--ao",      "off",
                "--aa",      "off",
                "--raycast"};
    }
    static inline std::string uid_;
};

TEST_F(RaycastRenderTest, RayCastsTheSeriesWithTheVss) {
    const fs::path output = testDir() / "raycast.png";
    const fs::path depthOut = testDir() / "raycast.pfm";
    auto a = args(output);
    a.insert(a.end(), {"--iso", "250", "--depth-out", depthOut.string()});
    const RunResult r = run(a);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("ray cast series " + uid_), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("at iso 250"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("VSS"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("segmented"), std::string::npos) << "no segmentation: " << r.out;
    const QImage image(QString::fromStdString(output.string()));
    ASSERT_FALSE(image.isNull());
    ASSERT_EQ(image.size(), QSize(320, 240));
    // The iso-surface (vessels and the bone-like structure) covers a fair part
    // of the view, not all of it; the rest is void (VSS or background).
    const auto depth = vv::vss::readPfm(depthOut);
    ASSERT_EQ(depth.width(), 320);
    ASSERT_EQ(depth.height(), 240);
    long hits = 0;
    for (int y = 0; y < depth.height(); ++y) {
        for (int x = 0; x < depth.width(); ++x) {
            const float d = depth.row(y)[x];
            EXPECT_TRUE(std::isinf(d) || (std::isfinite(d) && d > 0.0F)) << x << "," << y;
            hits += std::isfinite(d) ? 1 : 0;
        }
    }
    EXPECT_GT(hits, 320L * 240L / 50L);
    EXPECT_LT(hits, 320L * 240L * 3L / 4L);
}

TEST_F(RaycastRenderTest, TheIsoValueDefaultsToTheLowerThreshold) {
    const fs::path output = testDir() / "raycast-default.png";
    const RunResult r = run(args(output));
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("at iso 200 HU"), std::string::npos) << r.out;  // CTA default 200..700
    auto a = args(output);
    a.insert(a.end(), {"--threshold", "300:700"});
    const RunResult t = run(a);
    ASSERT_EQ(t.code, 0) << t.err;
    EXPECT_NE(t.out.find("at iso 300 HU"), std::string::npos) << t.out;
}

TEST_F(RaycastRenderTest, RefusesIsoWithoutRaycastAndNonDicomInput) {
    const fs::path output = testDir() / "bad.png";
    auto a = args(output);
    a.pop_back();  // no --raycast
    a.insert(a.end(), {"--iso", "200"});
    EXPECT_EQ(run(a).code, 2);
    auto b = args(output);
    b[1] = (testDir() / "no-such-mesh.vtp").string();
    EXPECT_EQ(run(b).code, 2);
    // The depth comes from the VSS solve: --depth-out with the VSS off is refused.
    auto c = args(output);
    c.insert(c.end(), {"--vss", "off", "--depth-out", (testDir() / "d.pfm").string()});
    EXPECT_EQ(run(c).code, 2);
    EXPECT_FALSE(fs::exists(output));
}

}  // namespace
