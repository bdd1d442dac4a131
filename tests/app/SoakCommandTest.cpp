// SPDX-License-Identifier: GPL-3.0-or-later
// `vesselview-cli soak` (issue 9): a short run in-process on a small tree —
// every frame rendered at the asked size, memory figures printed and judged
// by the documented rule (floor of the last 100 frames within 5% of frames
// 1..100). The 10,000-frame run itself is scripts/soak (docs/reliability.md).
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <regex>
#include <string>

#include "CliRun.h"

namespace {

namespace fs = std::filesystem;

TEST(SoakCommand, TooFewFramesIsAUsageError) {
    const auto r = vv::test::runCli({"soak", "50"});
    EXPECT_EQ(r.code, vv::cli::kUsage) << r.err;
    EXPECT_NE(r.err.find("101"), std::string::npos) << r.err;
}

TEST(SoakCommand, ShortRunReportsMemoryInUseAndPeaks) {
    const fs::path dir = vv::test::processTestDir("soak");
    fs::create_directories(dir);
    const std::string tree = (dir / "tree.vtp").string();
    const auto demo =
        vv::test::runCli({"demo", "--generations", "1", "--voxel-size", "2", "-o", tree});
    ASSERT_EQ(demo.code, vv::cli::kOk) << demo.err;

    const auto r = vv::test::runCli({"soak", "130", "--mesh", tree, "--size", "96x64", "--every",
                                     "65", "--resize-every", "40", "--trim"});
    ASSERT_TRUE(r.code == vv::cli::kOk || r.code == vv::cli::kInternalError) << r.err;
    EXPECT_NE(r.out.find("frame 65: resident"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("frame 130: resident"), std::string::npos) << r.out;

    const std::regex summary(
        R"(floor\) over frames 1-100 ([0-9.]+) MiB, over the last 100 ([0-9.]+) MiB \(([-+0-9.]+)%\); )"
        R"(peaks ([0-9.]+) MiB and ([0-9.]+) MiB)");
    std::smatch m;
    ASSERT_TRUE(std::regex_search(r.out, m, summary)) << r.out;
    const double floorFirst = std::stod(m[1]);
    const double floorLast = std::stod(m[2]);
    const double growth = std::stod(m[3]);
    EXPECT_GT(floorFirst, 10.0);  // a process with Qt, VTK and a GL context
    EXPECT_LE(floorFirst, std::stod(m[4]));
    EXPECT_LE(floorLast, std::stod(m[5]));
    EXPECT_NEAR(growth, 100.0 * (floorLast / floorFirst - 1.0), 0.5);
    // The exit code follows the 5% rule on the floors.
    if (growth > 5.0) {
        EXPECT_EQ(r.code, vv::cli::kInternalError);
        EXPECT_NE(r.err.find("more than 5%"), std::string::npos) << r.err;
    } else {
        EXPECT_EQ(r.code, vv::cli::kOk) << r.err;
    }
}

}  // namespace
