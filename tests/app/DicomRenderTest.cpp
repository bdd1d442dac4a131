// SPDX-License-Identifier: GPL-3.0-or-later
// `vesselview-cli render DICOM_DIR`: the synthetic CTA round-trip series
// (tests/support/SyntheticCta.h, written with DCMTK) segmented, extracted and
// rendered headlessly. Needs OpenGL: run under `xvfb-run -a` (QT_QPA_PLATFORM=xcb).
#include <gtest/gtest.h>
#include <unistd.h>

#include <QImage>
#include <QString>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "CliRun.h"
#include "DicomSegTestUtil.h"
#include "DicomTestUtil.h"
#include "SyntheticCta.h"
#include "cli/Cli.h"
#include "common/Session.h"

namespace {

namespace fs = std::filesystem;

fs::path testDir() {
    return vv::test::processTestDir("dicom-render");
}

using RunResult = vv::test::CliRunResult;

RunResult run(const std::vector<std::string>& args) {
    return vv::test::runCli(args);
}

using vv::test::litPixels;

class DicomRenderTest : public ::testing::Test {
  protected:
    static void SetUpTestSuite() {
        fs::remove_all(testDir());
        // Smaller than the io round trip: the CLI path, not the accuracy.
        const auto cta = vv::test::makeSyntheticCta({64, 64, 48}, 3);
        uid_ = vv::test::writeCtSeries(testDir() / "series", cta.volume);
        // A DICOM SEG on the same grid: one ball.
        const auto& v = cta.volume;
        const glm::dvec3 centre = v.worldPosition(glm::dvec3(v.dims()) * 0.5);
        vv::test::TestSegment ball{"ball", std::vector<std::uint8_t>(v.voxelCount(), 0)};
        for (int k = 0; k < v.dims().z; ++k) {
            for (int j = 0; j < v.dims().y; ++j) {
                for (int i = 0; i < v.dims().x; ++i) {
                    const glm::dvec3 p = v.worldPosition(glm::dvec3(i, j, k));
                    ball.mask[v.index(i, j, k)] = glm::length(p - centre) < 10.0 ? 1 : 0;
                }
            }
        }
        vv::test::writeBinarySeg(testDir() / "ball-seg.dcm", v.dims(), v.indexToWorld(), {ball});
    }
    static void TearDownTestSuite() {
        std::error_code ec;
        fs::remove_all(testDir(), ec);
    }
    static std::vector<std::string> renderArgs(const fs::path& output) {
        return {"render",       (testDir() / "series").string(),
                "-o",           output.string(),
                "--size",       "320x240",
                "--vss",        "off",
                "--legends",    "off",
                "--background", "#000000"};
    }
    static inline std::string uid_;
};

TEST_F(DicomRenderTest, RendersTheSegmentedSeries) {
    const fs::path output = testDir() / "vessels.png";
    auto args = renderArgs(output);
    args.insert(args.end(), {"--series", uid_, "--threshold", "200:700", "--triangles", "20000"});
    const RunResult r = run(args);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("segmented series " + uid_), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("kept 1 of"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("1 bone-like removed"), std::string::npos) << r.out;
    const QImage image(QString::fromStdString(output.string()));
    ASSERT_FALSE(image.isNull());
    ASSERT_EQ(image.size(), QSize(320, 240));
    const long lit = litPixels(image);
    // The tree covers a fair part of the view, but not all of it.
    EXPECT_GT(lit, 320L * 240L / 50L);
    EXPECT_LT(lit, 320L * 240L * 3L / 4L);
}

TEST_F(DicomRenderTest, SegmentationOptionsReachTheSegmentation) {
    const fs::path output = testDir() / "with-bone.png";
    auto args = renderArgs(output);
    args.insert(args.end(), {"--bone-removal", "off", "--components", "2"});
    const RunResult r = run(args);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("kept 2 of"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("0 bone-like removed"), std::string::npos) << r.out;
}

TEST_F(DicomRenderTest, RendersADicomSegObject) {
    const fs::path output = testDir() / "seg.png";
    auto args = renderArgs(output);
    args[1] = (testDir() / "ball-seg.dcm").string();
    const RunResult r = run(args);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("read 1 segment(s) from the DICOM SEG: 'ball'"), std::string::npos)
        << r.out;
    const QImage image(QString::fromStdString(output.string()));
    ASSERT_FALSE(image.isNull());
    EXPECT_GT(litPixels(image), 320L * 240L / 50L);
}

TEST_F(DicomRenderTest, RefusesBadDicomOptions) {
    const fs::path output = testDir() / "bad.png";
    for (const std::vector<std::string>& extra :
         {std::vector<std::string>{"--threshold", "700:200"},
          {"--threshold", "200"},
          {"--components", "0"},
          {"--seed", "1,2"},
          {"--bone-removal", "maybe"},
          {"--triangles", "2"}}) {
        auto args = renderArgs(output);
        args.insert(args.end(), extra.begin(), extra.end());
        EXPECT_EQ(run(args).code, 2) << extra[0] << " " << extra[1];
    }
    auto args = renderArgs(output);
    args.insert(args.end(), {"--series", "1.2.3.4"});  // no such series
    const RunResult r = run(args);
    EXPECT_EQ(r.code, 3);
    EXPECT_NE(r.err.find("1.2.3.4"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(output));
}

// A session of DICOM data reopens with its series and segmentation: the same
// vessels as the command line's options give.
TEST_F(DicomRenderTest, SessionsReloadTheStoredSeriesAndSegmentation) {
    vv::app::Session session;
    session.files = {QString::fromStdString((testDir() / "series").string())};
    vv::segmentation::SceneSourceOptions dicom;
    dicom.seriesInstanceUid = uid_;
    dicom.segmentation.range = vv::segmentation::ThresholdRange{250.0F, 700.0F, "chosen"};
    dicom.segmentation.keepComponents = 2;
    dicom.segmentation.removeBone = false;
    dicom.surface.targetTriangles = 20000;
    session.dicom = dicom;
    session.vss.enabled = false;
    session.legends = false;
    session.background = glm::vec3(0.0F);
    // `session` saved as `name`.vvs, rendered to `name`.png.
    const auto renderSaved = [&](const std::string& name) {
        const fs::path file = testDir() / (name + ".vvs");
        vv::app::saveSession(file, session);
        return run({"render", "--session", file.string(), "-o",
                    (testDir() / (name + ".png")).string(), "--size", "320x240", "--view",
                    "anterior"});
    };
    const fs::path fromSession = testDir() / "session.png";
    const RunResult r = renderSaved("session");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("segmented series " + uid_), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("saved in the session"), std::string::npos) << r.out;  // its threshold
    EXPECT_NE(r.out.find("0 bone-like removed"), std::string::npos) << r.out;
    const fs::path direct = testDir() / "direct.png";
    auto args = renderArgs(direct);
    args.insert(args.end(),
                {"--series", uid_, "--threshold", "250:700", "--components", "2", "--bone-removal",
                 "off", "--triangles", "20000", "--view", "anterior"});
    ASSERT_EQ(run(args).code, 0);
    const QImage a(QString::fromStdString(fromSession.string()));
    const QImage b(QString::fromStdString(direct.string()));
    ASSERT_FALSE(a.isNull());
    EXPECT_GT(litPixels(a), 320L * 240L / 50L);
    EXPECT_EQ(a, b) << "the session's DICOM options did not reach the segmentation";

    // With the series' title (a session saved since titles are kept) the
    // command line renders the same: the title changes nothing it draws.
    session.seriesTitle = QStringLiteral("Run-off CTA 1.0 mm");
    const RunResult t = renderSaved("session-titled");
    ASSERT_EQ(t.code, 0) << t.err;
    EXPECT_EQ(QImage(QString::fromStdString((testDir() / "session-titled.png").string())), a);
}

}  // namespace
