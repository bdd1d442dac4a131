// SPDX-License-Identifier: GPL-3.0-or-later
// vesselview-cli vss and artefacts, through vv::cli::run.
#include <gtest/gtest.h>

#include <QImage>
#include <QString>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "VssTestUtil.h"
#include "cli/Cli.h"
#include "vv/vss/Pfm.h"

namespace vv::cli {
namespace {

namespace fs = std::filesystem;

fs::path tempDir() {
    const fs::path dir = fs::path(VV_TEST_TMP) / "vss-cli";
    fs::create_directories(dir);
    return dir;
}

struct Outcome {
    int code;
    std::string out;
    std::string err;
};

Outcome runCli(const std::vector<std::string>& args) {
    std::ostringstream out;
    std::ostringstream err;
    const int code = run(args, out, err);
    return {code, out.str(), err.str()};
}

/// A depth PFM: random vessels, background +Inf (and a few NaN).
fs::path makeDepth(const std::string& name, int w = 48, int h = 36) {
    const auto mask = vss::test::randomMask(w, h, 21);
    auto depth = vss::test::randomDepth(w, h, 21, 50.0, 80.0);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            if (mask(x, y) == 0) {
                depth(x, y) = (x + y) % 7 == 0 ? std::numeric_limits<float>::quiet_NaN()
                                               : std::numeric_limits<float>::infinity();
            }
        }
    }
    const fs::path file = tempDir() / name;
    vss::writePfm(file, depth.view());
    return file;
}

TEST(VssCliTest, RoundTripPfm) {
    const fs::path in = makeDepth("in.pfm");
    const fs::path out = tempDir() / "out.pfm";
    fs::remove(out);
    const auto r = runCli(
        {"vss", "--depth", in.string(), "-o", out.string(), "--p", "4", "--solver", "brute"});
    ASSERT_EQ(r.code, kOk) << r.err;
    EXPECT_NE(r.out.find("wrote"), std::string::npos);
    const auto depth = vss::readPfm(in);
    const auto height = vss::readPfm(out);
    ASSERT_EQ(height.width(), depth.width());
    ASSERT_EQ(height.height(), depth.height());
    float lo = std::numeric_limits<float>::infinity();
    float hi = -lo;
    for (int y = 0; y < depth.height(); ++y) {
        for (int x = 0; x < depth.width(); ++x) {
            if (std::isfinite(depth(x, y))) {
                lo = std::min(lo, depth(x, y));
                hi = std::max(hi, depth(x, y));
            }
        }
    }
    for (int y = 0; y < depth.height(); ++y) {
        for (int x = 0; x < depth.width(); ++x) {
            const float v = height(x, y);
            ASSERT_TRUE(std::isfinite(v) && v >= 0.0F && v <= 1.0F) << x << ", " << y;
            if (std::isfinite(depth(x, y))) {
                EXPECT_NEAR(v, (depth(x, y) - lo) / (hi - lo), 1e-6);
            }
        }
    }
}

TEST(VssCliTest, StatsJsonAndLabels) {
    const fs::path in = makeDepth("stats.pfm");
    const fs::path out = tempDir() / "stats-out.pfm";
    const fs::path labels = tempDir() / "labels.png";
    const auto r =
        runCli({"vss", "--depth", in.string(), "-o", out.string(), "--stats", "--labels",
                labels.string(), "--solver", "step", "--step", "2", "--fixed-range", "40,90"});
    ASSERT_EQ(r.code, kOk) << r.err;
    for (const char* key :
         {"\"regions\":", "\"contourPixels\":", "\"maxContourPixels\":", "\"dmin\": 40",
          "\"dmax\": 90", "\"timeMs\":", "\"normalize\":", "\"interpolate\":",
          "\"nonFiniteVoidPixels\": 0", "\"solver\": \"step\""}) {
        EXPECT_NE(r.out.find(key), std::string::npos) << key << " in " << r.out;
    }
    EXPECT_EQ(r.out.front(), '{');
    EXPECT_EQ(r.out.substr(r.out.size() - 2), "}\n");
    QImage image;
    ASSERT_TRUE(image.load(QString::fromStdString(labels.string()), "PNG"));
    EXPECT_EQ(image.width(), 48);
    EXPECT_EQ(image.height(), 36);
}

TEST(VssCliTest, EmptyMaskGivesNaNAndCountsIt) {
    const Image<float> depth(6, 4, std::numeric_limits<float>::infinity());
    const fs::path in = tempDir() / "nothing.pfm";
    vss::writePfm(in, depth.view());
    const fs::path out = tempDir() / "nothing-out.pfm";
    const auto r = runCli(
        {"vss", "--depth", in.string(), "-o", out.string(), "--stats", "--solver", "reference"});
    ASSERT_EQ(r.code, kOk) << r.err;
    EXPECT_NE(r.out.find("\"nonFiniteVoidPixels\": 24"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("\"dmin\": null"), std::string::npos) << r.out;
    EXPECT_TRUE(std::isnan(vss::readPfm(out)(0, 0)));
}

void writeBytes(const fs::path& file, const std::string& bytes) {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

TEST(VssCliTest, BadPfmExitsThreeNamingTheFile) {
    const std::string pixel(4, '\0');
    const std::pair<const char*, std::string> cases[] = {
        {"truncated.pfm", "Pf\n4 4\n-1.0\n" + pixel},
        {"header.pfm", "P6\n4 4\n255\n" + pixel},
        {"huge.pfm", "Pf\n100000 100000\n-1.0\n" + pixel},
        {"negative.pfm", "Pf\n-3 2\n-1.0\n" + pixel},
    };
    for (const auto& [name, bytes] : cases) {
        const fs::path file = tempDir() / name;
        writeBytes(file, bytes);
        const auto r =
            runCli({"vss", "--depth", file.string(), "-o", (tempDir() / "never.pfm").string()});
        EXPECT_EQ(r.code, kInvalidInput) << name << ": " << r.err;
        EXPECT_NE(r.err.find(file.string()), std::string::npos) << r.err;
    }
    const auto missing = runCli({"vss", "--depth", (tempDir() / "missing.pfm").string(), "-o",
                                 (tempDir() / "never.pfm").string()});
    EXPECT_EQ(missing.code, kInvalidInput);
    EXPECT_NE(missing.err.find("missing.pfm"), std::string::npos);
    EXPECT_FALSE(fs::exists(tempDir() / "never.pfm"));
}

TEST(VssCliTest, BadOptionsExitTwo) {
    const fs::path in = makeDepth("opts.pfm", 8, 8);
    const std::string o = (tempDir() / "opts-out.pfm").string();
    const std::vector<std::vector<std::string>> bad = {
        {"vss", "-o", o},
        {"vss", "--depth", in.string()},
        {"vss", "--depth", in.string(), "-o", o, "--p", "abc"},
        {"vss", "--depth", in.string(), "-o", o, "--p", "0"},
        {"vss", "--depth", in.string(), "-o", o, "--p", "-2"},
        {"vss", "--depth", in.string(), "-o", o, "--solver", "magic"},
        {"vss", "--depth", in.string(), "-o", o, "--step", "0"},
        {"vss", "--depth", in.string(), "-o", o, "--step", "1.5"},
        {"vss", "--depth", in.string(), "-o", o, "--tolerance", "-1"},
        {"vss", "--depth", in.string(), "-o", o, "--fixed-range", "5"},
        {"vss", "--depth", in.string(), "-o", o, "--fixed-range", "9,5"},
        {"vss", "--depth", in.string(), "-o", o, "--frobnicate"},
        {"vss", "--depth", in.string(), "-o", o, "--p"},
    };
    for (const auto& args : bad) {
        const auto r = runCli(args);
        std::string joined;
        for (const auto& a : args) {
            joined += a + " ";
        }
        EXPECT_EQ(r.code, kUsage) << joined << ": " << r.err;
    }
}

TEST(VssCliTest, UnwritableOutputExitsFour) {
    const fs::path in = makeDepth("w.pfm", 8, 8);
    const auto r =
        runCli({"vss", "--depth", in.string(), "-o", (tempDir() / "no-folder" / "x.pfm").string()});
    EXPECT_EQ(r.code, kCannotWrite) << r.err;
    const auto folder = runCli({"vss", "--depth", in.string(), "-o", tempDir().string()});
    EXPECT_EQ(folder.code, kCannotWrite) << folder.err;
    const auto labels =
        runCli({"vss", "--depth", in.string(), "-o", (tempDir() / "w-out.pfm").string(), "--labels",
                (tempDir() / "no-folder" / "l.png").string()});
    EXPECT_EQ(labels.code, kCannotWrite) << labels.err;
}

TEST(VssCliTest, UsageMentionsVss) {
    const auto r = runCli({"--help"});
    EXPECT_NE(r.out.find("vss --depth"), std::string::npos);
}

// vesselview-cli artefacts (app/evaluation/ArtefactBenchmark.h).
TEST(ArtefactsCliTest, PrintsOneRowPerMesh) {
    const Outcome o = runCli({"artefacts", "--size", "160x90", "--triangles", "20000"});
    ASSERT_EQ(o.code, kOk) << o.err;
    EXPECT_NE(o.out.find("View close, 160x90, p = 2"), std::string::npos) << o.out;
    EXPECT_NE(o.out.find("| demo (smooth control) | 300884 | "), std::string::npos) << o.out;
    EXPECT_NE(o.out.find("| 1.00 |"), std::string::npos) << o.out;
    EXPECT_NE(o.out.find("| demo decimated to 20000 | "), std::string::npos) << o.out;
    // The reference (3x by default) and the score over it.
    EXPECT_NE(o.out.find("reference: the same view at 3x the size"), std::string::npos) << o.out;
    EXPECT_NE(o.out.find("| score / reference |"), std::string::npos) << o.out;
    EXPECT_EQ(o.out.find("| - | - |"), std::string::npos) << o.out;
    const Outcome none = runCli(
        {"artefacts", "--size", "160x90", "--triangles", "none", "--reference-scale", "none"});
    ASSERT_EQ(none.code, kOk) << none.err;
    EXPECT_NE(none.out.find("no reference"), std::string::npos) << none.out;
    EXPECT_NE(none.out.find("| - | - | 1.00 |"), std::string::npos) << none.out;
}

/// The cells of the table row whose label starts with `label`.
std::vector<std::string> rowOf(const std::string& table, const std::string& label) {
    std::istringstream lines(table);
    for (std::string line; std::getline(lines, line);) {
        if (line.rfind("| " + label, 0) == 0) {
            std::vector<std::string> cells;
            std::istringstream row(line.substr(1));
            for (std::string cell; std::getline(row, cell, '|');) {
                cells.push_back(cell.substr(1, cell.size() > 1 ? cell.size() - 2 : 0));
            }
            return cells;
        }
    }
    return {};
}

// Issue 36: the aorta's coarse copy shows bumps along its silhouettes (the
// near score 2-6 px from the vessels), its subdivided copy does not; the
// deviation is stated, the light named, the meshes saved as made.
TEST(ArtefactsCliTest, FacetBumpsOfACoarseAortaAndItsSubdividedCopy) {
    const fs::path dir = tempDir() / "aorta";
    fs::remove_all(dir);
    fs::create_directories(dir);
    const Outcome o =
        runCli({"artefacts", "--aorta", "--triangles", "2000", "--subdivide", "1", "--view", "far",
                "--reference-scale", "none", "--light", "40,30", "--save", dir.string()});
    ASSERT_EQ(o.code, kOk) << o.err;
    EXPECT_NE(o.out.find("key light at azimuth 40.0, elevation 30.0 degrees"), std::string::npos)
        << o.out;
    EXPECT_NE(o.out.find("| 2-6 px (1/1000) | 12-30 px (1/1000) | 2-6 px / 12-30 px |"),
              std::string::npos)
        << o.out;
    const auto control = rowOf(o.out, "aorta (smooth control)");
    const auto coarse = rowOf(o.out, "aorta decimated to 2000 |");
    const auto refined = rowOf(o.out, "aorta decimated to 2000, subdivided 1x (within ");
    ASSERT_EQ(control.size(), 11U) << o.out;
    ASSERT_EQ(coarse.size(), 11U) << o.out;
    ASSERT_EQ(refined.size(), 11U) << o.out;
    EXPECT_EQ(coarse[1], "2000");
    EXPECT_EQ(refined[1], "8000");
    const double controlNear = std::stod(control[7]);
    const double coarseNear = std::stod(coarse[7]);
    const double refinedNear = std::stod(refined[7]);
    EXPECT_GT(coarseNear, 1.3 * controlNear) << o.out;
    EXPECT_LT(refinedNear, 0.8 * coarseNear) << o.out;
    // The coarse copy's facets are longer on screen, the subdivided copy's
    // a half of them (each edge split once).
    const double controlEdge = std::stod(control[10]);
    const double coarseEdge = std::stod(coarse[10]);
    const double refinedEdge = std::stod(refined[10]);
    EXPECT_GT(coarseEdge, 3.0 * controlEdge) << o.out;
    EXPECT_NEAR(refinedEdge, 0.5 * coarseEdge, 0.15 * coarseEdge) << o.out;
    // The far band sees the VSS away from the silhouettes: alike for all.
    EXPECT_NEAR(std::stod(coarse[8]), std::stod(control[8]), 0.3 * std::stod(control[8]));
    const auto within = refined[0].find("within ");
    ASSERT_NE(within, std::string::npos);
    const double deviation = std::stod(refined[0].substr(within + 7));
    EXPECT_GT(deviation, 0.0);
    EXPECT_LT(deviation, 1.0);
    for (const char* name : {"aorta.vtp", "aorta-decimated-to-2000.vtp",
                             "aorta-decimated-to-2000-subdivided-1x.vtp"}) {
        EXPECT_TRUE(fs::is_regular_file(dir / name)) << name;
    }
}

TEST(ArtefactsCliTest, RejectsBadOptions) {
    EXPECT_EQ(runCli({"artefacts", "--view", "sideways"}).code, kUsage);
    EXPECT_EQ(runCli({"artefacts", "--p", "0"}).code, kUsage);
    EXPECT_EQ(runCli({"artefacts", "--triangles", "2"}).code, kUsage);
    EXPECT_EQ(runCli({"artefacts", "--bogus"}).code, kUsage);
    EXPECT_EQ(runCli({"artefacts", "--reference-scale", "4"}).code, kUsage);
    EXPECT_EQ(runCli({"artefacts", "--subdivide", "0"}).code, kUsage);
    EXPECT_EQ(runCli({"artefacts", "--subdivide", "4"}).code, kUsage);
    EXPECT_EQ(runCli({"artefacts", "--light", "400,0"}).code, kUsage);
    EXPECT_EQ(runCli({"artefacts", "--reference-scale", "9"}).code, kUsage);
    EXPECT_EQ(runCli({"artefacts", "--mesh", "/nonexistent/tree.stl", "--triangles", "none",
                      "--size", "32x32"})
                  .code,
              kInvalidInput);
}

// The VSS exponent is the display setting "vss.p" (app/common/SettingsSchema.h)
// wherever the command line takes it: one range, one message.
TEST(ArtefactsCliTest, ExponentHasTheSettingsRangeAndMessage) {
    const std::string problem = "--p must be a number within 0.25..64, not 100";
    const std::vector<std::vector<std::string>> commands{
        {"render", "in.vtp", "-o", "out.png", "--p", "100"},
        {"vss", "--depth", "in.pfm", "-o", "out.pfm", "--p", "100"},
        {"artefacts", "--p", "100"},
        {"bench", "--quick", "--p", "2,100"},
    };
    for (const auto& args : commands) {
        const Outcome o = runCli(args);
        EXPECT_EQ(o.code, kUsage) << args.front() << ": " << o.err;
        EXPECT_NE(o.err.find(problem), std::string::npos) << args.front() << ": " << o.err;
    }
    // Below the range too, where bench took any p > 0 before.
    EXPECT_EQ(runCli({"bench", "--quick", "--p", "0.1"}).code, kUsage);
    EXPECT_EQ(runCli({"artefacts", "--p", "0.1"}).code, kUsage);
}

}  // namespace
}  // namespace vv::cli
