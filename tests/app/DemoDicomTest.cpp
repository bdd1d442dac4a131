// SPDX-License-Identifier: GPL-3.0-or-later
// `vesselview-cli demo --dicom DIR`: the voxelised demo tree as a CT series,
// listed by `info DIR` and rendered by `render DIR`. Needs OpenGL for the
// render: run under `xvfb-run -a` (QT_QPA_PLATFORM=xcb).
#include <gtest/gtest.h>
#include <unistd.h>

#include <QImage>
#include <QString>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "CliRun.h"
#include "cli/Cli.h"
#include "vv/dicom/Dicom.h"

namespace {

namespace fs = std::filesystem;

fs::path testDir() {
    return vv::test::processTestDir("demo-dicom");
}

using RunResult = vv::test::CliRunResult;

RunResult run(const std::vector<std::string>& args) {
    return vv::test::runCli(args);
}

using vv::test::litPixels;

class DemoDicomTest : public ::testing::Test {
  protected:
    static void SetUpTestSuite() {
        fs::remove_all(testDir());
        fs::create_directories(testDir());
        const RunResult r = run({"demo", "--dicom", series().string()});
        code_ = r.code;
        out_ = r.out + r.err;
    }
    static void TearDownTestSuite() {
        std::error_code ec;
        fs::remove_all(testDir(), ec);
    }
    static fs::path series() { return testDir() / "demo-ct"; }
    static inline int code_ = -1;
    static inline std::string out_;
};

TEST_F(DemoDicomTest, WritesAValidCtSeries) {
    ASSERT_EQ(code_, 0) << out_;
    EXPECT_NE(out_.find("CT series of 80 slices"), std::string::npos) << out_;
    std::size_t files = 0;
    for (const auto& entry : fs::directory_iterator(series())) {
        EXPECT_EQ(entry.path().extension(), ".dcm") << entry.path();  // no temporaries left
        ++files;
    }
    EXPECT_EQ(files, 80U);

    const vv::dicom::DicomScanResult scan = vv::dicom::scanDicom(series());
    ASSERT_EQ(scan.patients.size(), 1U);
    ASSERT_EQ(scan.patients[0].studies.size(), 1U);
    ASSERT_EQ(scan.patients[0].studies[0].series.size(), 1U);
    EXPECT_TRUE(scan.skipped.empty());
    const vv::dicom::DicomSeries& s = scan.patients[0].studies[0].series[0];
    EXPECT_EQ(s.modality, "CT");
    EXPECT_EQ(s.imageCount, 80U);
    EXPECT_TRUE(s.unsupportedReason.empty()) << s.unsupportedReason;

    const vv::dicom::DicomVolume loaded = vv::dicom::loadDicomVolume(series());
    EXPECT_TRUE(loaded.warnings.empty());
    const vv::scene::Volume& v = loaded.volume;
    EXPECT_EQ(v.dims(), glm::ivec3(96, 96, 80));
    // Tissue ~40 HU, lumen ~400 HU, bone ~1000 HU: the extremes are present.
    float lo = 1e9F;
    float hi = -1e9F;
    for (std::size_t n = 0; n < v.voxelCount(); ++n) {
        lo = std::min(lo, v.valueAt(n));
        hi = std::max(hi, v.valueAt(n));
    }
    EXPECT_LT(lo, 0.0F);
    EXPECT_GT(hi, 950.0F);
}

TEST_F(DemoDicomTest, InfoListsOneCtSeries) {
    ASSERT_EQ(code_, 0) << out_;
    const RunResult r = run({"info", series().string(), "--json"});
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("\"CT\""), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("synthetic CTA"), std::string::npos) << r.out;
    // The (synthetic) patient name is never printed.
    EXPECT_EQ(r.out.find("VesselView^Demo"), std::string::npos) << r.out;
    const RunResult text = run({"info", series().string()});
    ASSERT_EQ(text.code, 0) << text.err;
    EXPECT_NE(text.out.find("CT"), std::string::npos) << text.out;
    EXPECT_NE(text.out.find("80"), std::string::npos) << text.out;
}

TEST_F(DemoDicomTest, RenderShowsVessels) {
    ASSERT_EQ(code_, 0) << out_;
    const fs::path output = testDir() / "demo.png";
    const RunResult r =
        run({"render", series().string(), "-o", output.string(), "--size", "320x240", "--vss",
             "off", "--legends", "off", "--background", "#000000", "--triangles", "20000"});
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("kept 1 of"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("1 bone-like removed"), std::string::npos) << r.out;
    const QImage image(QString::fromStdString(output.string()));
    ASSERT_FALSE(image.isNull());
    const long lit = litPixels(image);
    EXPECT_GT(lit, 320L * 240L / 50L);
    EXPECT_LT(lit, 320L * 240L * 3L / 4L);
}

TEST_F(DemoDicomTest, RefusesBadArguments) {
    EXPECT_EQ(run({"demo", "--dicom"}).code, 2);
    EXPECT_EQ(run({"demo", "--dicom", (testDir() / "x").string(), "-o", "a.vtp"}).code, 2);
    EXPECT_EQ(run({"demo", "--dicom", (testDir() / "x").string(), "--generations", "3"}).code, 2);
    // A file where the folder should be.
    const fs::path file = testDir() / "a-file";
    { std::ofstream(file) << "x"; }
    EXPECT_NE(run({"demo", "--dicom", file.string()}).code, 0);
}

}  // namespace
