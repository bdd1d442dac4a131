// SPDX-License-Identifier: GPL-3.0-or-later
// `vesselview-cli render` through vv::cli::run. Rendering needs OpenGL: run
// under `xvfb-run -a` (QT_QPA_PLATFORM=xcb); without it the rendering tests fail.
#include <gtest/gtest.h>
#include <unistd.h>

#include <QColor>
#include <QImage>
#include <QString>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "ImageStats.h"
#include "cli/Cli.h"

namespace {

namespace fs = std::filesystem;

/// This process's own folder (ctest may run test cases in parallel).
fs::path testDir() {
    const fs::path dir =
        fs::path(VV_TEST_TMP) / "render-command" / ("run-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return dir;
}

/// An open tube along x (length 20, radius 1) as legacy ASCII VTK polydata
/// with a point array "wss" [rising 0..10 along x] and "pressure".
fs::path writeTubeVtk() {
    const fs::path file = testDir() / "tube.vtk";
    constexpr int kSegments = 24;
    constexpr int kRings = 20;
    std::ofstream out(file);
    out << "# vtk DataFile Version 3.0\ntube\nASCII\nDATASET POLYDATA\n";
    out << "POINTS " << (kRings + 1) * kSegments << " float\n";
    for (int i = 0; i <= kRings; ++i) {
        for (int j = 0; j < kSegments; ++j) {
            const double phi = 2.0 * std::numbers::pi * j / kSegments;
            out << 20.0 * i / kRings << " " << std::cos(phi) << " " << std::sin(phi) << "\n";
        }
    }
    out << "POLYGONS " << kRings * kSegments * 2 << " " << kRings * kSegments * 2 * 4 << "\n";
    for (int i = 0; i < kRings; ++i) {
        for (int j = 0; j < kSegments; ++j) {
            const int a = i * kSegments + j;
            const int b = i * kSegments + (j + 1) % kSegments;
            out << "3 " << a << " " << a + kSegments << " " << b << "\n";
            out << "3 " << b << " " << a + kSegments << " " << b + kSegments << "\n";
        }
    }
    out << "POINT_DATA " << (kRings + 1) * kSegments << "\n";
    out << "SCALARS wss float 1\nLOOKUP_TABLE default\n";
    for (int i = 0; i <= kRings; ++i) {
        for (int j = 0; j < kSegments; ++j) {
            out << 10.0 * i / kRings << "\n";
        }
    }
    out << "SCALARS pressure float 1\nLOOKUP_TABLE default\n";
    for (int i = 0; i <= kRings; ++i) {
        for (int j = 0; j < kSegments; ++j) {
            out << 100.0 - i << "\n";
        }
    }
    return file;
}

/// A closed tetrahedron as ASCII STL (no arrays).
fs::path writeTetraStl() {
    const fs::path file = testDir() / "tetra.stl";
    std::ofstream out(file);
    const float v[4][3] = {{0, 0, 0}, {10, 0, 0}, {0, 10, 0}, {0, 0, 10}};
    const int faces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    out << "solid tetra\n";
    for (const auto& f : faces) {
        out << " facet normal 0 0 0\n  outer loop\n";
        for (const int k : f) {
            out << "   vertex " << v[k][0] << " " << v[k][1] << " " << v[k][2] << "\n";
        }
        out << "  endloop\n endfacet\n";
    }
    out << "endsolid tetra\n";
    return file;
}

struct RunResult {
    int code;
    std::string out;
    std::string err;
};

RunResult render(const std::vector<std::string>& rest) {
    std::vector<std::string> args{"render"};
    args.insert(args.end(), rest.begin(), rest.end());
    std::ostringstream out;
    std::ostringstream err;
    const int code = vv::cli::run(args, out, err);
    return {code, out.str(), err.str()};
}

long countNot(const QImage& image, QRgb background) {
    long count = 0;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            count += (image.pixel(x, y) & 0xFFFFFFU) != (background & 0xFFFFFFU) ? 1 : 0;
        }
    }
    return count;
}

using vv::test::hueBins;

class RenderCommandTest : public ::testing::Test {
  protected:
    static void TearDownTestSuite() {
        std::error_code ec;
        fs::remove_all(testDir(), ec);
    }
};

TEST_F(RenderCommandTest, RendersAMeshToPngWithVesselPixels) {
    const fs::path input = writeTubeVtk();
    const fs::path output = testDir() / "tube.png";
    fs::remove(output);
    // The frame alone: no orientation marker or scale bar in the pixel counts.
    const auto r =
        render({input.string(), "-o", output.string(), "--size", "240x120", "--background",
                "#ffffff", "--vss", "off", "--orientation-marker", "off", "--scale-bar", "off"});
    ASSERT_EQ(r.code, vv::cli::kOk) << r.err;
    EXPECT_NE(r.out.find("wss"), std::string::npos) << r.out;  // the default array

    QImage image;
    ASSERT_TRUE(image.load(QString::fromStdString(output.string()), "PNG"));
    EXPECT_EQ(image.size(), QSize(240, 120));
    const long vessel = countNot(image, qRgb(255, 255, 255));
    EXPECT_GT(vessel, 240 * 120 / 20);  // > 5 %
    EXPECT_LT(vessel, 240 * 120 / 2);   // < 50 %
    EXPECT_EQ(image.pixel(0, 0), qRgb(255, 255, 255));
    EXPECT_GE(hueBins(image), 4U);  // wss through viridis: purple .. yellow
    // No temporary files are left next to the output.
    for (const auto& entry : fs::directory_iterator(testDir())) {
        EXPECT_EQ(entry.path().filename().string().find(".tmp-"), std::string::npos)
            << entry.path();
    }
}

TEST_F(RenderCommandTest, ArrayNoneGivesTheNeutralMaterial) {
    const fs::path input = writeTubeVtk();
    const fs::path output = testDir() / "tube-none.png";
    const auto r = render({input.string(), "-o", output.string(), "--size", "240x120", "--array",
                           "none", "--background", "#000000", "--vss", "off",
                           "--orientation-marker", "off", "--scale-bar", "off"});
    ASSERT_EQ(r.code, vv::cli::kOk) << r.err;
    QImage image;
    ASSERT_TRUE(image.load(QString::fromStdString(output.string()), "PNG"));
    EXPECT_GT(countNot(image, qRgb(0, 0, 0)), 240 * 120 / 20);
    EXPECT_LE(hueBins(image), 2U);
}

TEST_F(RenderCommandTest, ChosenArrayAndColourMapAreUsed) {
    const fs::path input = writeTubeVtk();
    const fs::path output = testDir() / "tube-pressure.png";
    const auto r = render({input.string(), "-o", output.string(), "--size", "160x80", "--array",
                           "pressure", "--colormap", "cividis"});
    ASSERT_EQ(r.code, vv::cli::kOk) << r.err;
    EXPECT_NE(r.out.find("pressure through cividis"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("[80, 100]"), std::string::npos) << r.out;
}

TEST_F(RenderCommandTest, StlWithoutArraysRenders) {
    const fs::path input = writeTetraStl();
    const fs::path output = testDir() / "tetra.png";
    const auto r =
        render({input.string(), "-o", output.string(), "--size", "100x100", "--vss", "off"});
    ASSERT_EQ(r.code, vv::cli::kOk) << r.err;
    EXPECT_NE(r.out.find("no array"), std::string::npos) << r.out;
    QImage image;
    ASSERT_TRUE(image.load(QString::fromStdString(output.string()), "PNG"));
    const QRgb background = image.pixel(0, 0);
    EXPECT_GT(countNot(image, background), 100 * 100 / 10);
}

/// Two tubes at different depths (legacy ASCII VTK, no arrays): the void
/// between them gets a VSS.
fs::path writeTwoTubesVtk() {
    const fs::path file = testDir() / "two-tubes.vtk";
    constexpr int kSegments = 24;
    constexpr int kRings = 10;
    constexpr int kPerTube = (kRings + 1) * kSegments;
    std::ofstream out(file);
    out << "# vtk DataFile Version 3.0\ntwo tubes\nASCII\nDATASET POLYDATA\n";
    out << "POINTS " << 2 * kPerTube << " float\n";
    for (const auto& [y, z] : {std::pair{3.0, 4.0}, std::pair{-3.0, -4.0}}) {
        for (int i = 0; i <= kRings; ++i) {
            for (int j = 0; j < kSegments; ++j) {
                const double phi = 2.0 * std::numbers::pi * j / kSegments;
                out << -10.0 + 20.0 * i / kRings << " " << y + std::cos(phi) << " "
                    << z + std::sin(phi) << "\n";
            }
        }
    }
    out << "POLYGONS " << 2 * kRings * kSegments * 2 << " " << 2 * kRings * kSegments * 2 * 4
        << "\n";
    for (int t = 0; t < 2; ++t) {
        for (int i = 0; i < kRings; ++i) {
            for (int j = 0; j < kSegments; ++j) {
                const int a = t * kPerTube + i * kSegments + j;
                const int b = t * kPerTube + i * kSegments + (j + 1) % kSegments;
                out << "3 " << a << " " << a + kSegments << " " << b << "\n";
                out << "3 " << b << " " << a + kSegments << " " << b + kSegments << "\n";
            }
        }
    }
    return file;
}

TEST_F(RenderCommandTest, VssOnColoursTheVoidAndVssOffLeavesTheBackground) {
    const fs::path input = writeTwoTubesVtk();
    const fs::path on = testDir() / "two-tubes-vss.png";
    const fs::path off = testDir() / "two-tubes-plain.png";
    const auto r = render({input.string(), "-o", on.string(), "--size", "200x150", "--background",
                           "#000000", "--vss", "on", "--scale", "dmd", "--p", "4", "--isolines",
                           "5", "--solver", "fast", "--tolerance", "0.002"});
    ASSERT_EQ(r.code, vv::cli::kOk) << r.err;
    EXPECT_NE(r.out.find("dark-means-deep"), std::string::npos) << r.out;
    const auto r2 = render({input.string(), "-o", off.string(), "--size", "200x150", "--background",
                            "#000000", "--vss", "off"});
    ASSERT_EQ(r2.code, vv::cli::kOk) << r2.err;
    QImage withVss;
    QImage without;
    ASSERT_TRUE(withVss.load(QString::fromStdString(on.string()), "PNG"));
    ASSERT_TRUE(without.load(QString::fromStdString(off.string()), "PNG"));
    long voidPixels = 0;
    long shaded = 0;
    for (int y = 0; y < without.height(); ++y) {
        for (int x = 0; x < without.width(); ++x) {
            if ((without.pixel(x, y) & 0xFFFFFFU) == 0U) {
                ++voidPixels;
                shaded += (withVss.pixel(x, y) & 0xFFFFFFU) != 0U ? 1 : 0;
            }
        }
    }
    EXPECT_GT(voidPixels, 200 * 150 / 2);
    // Dark-means-deep is black only at the far end: most void pixels are not.
    EXPECT_GT(shaded, voidPixels * 8 / 10) << shaded << " of " << voidPixels;
}

TEST_F(RenderCommandTest, TimingsPrintPerPassJson) {
    const fs::path input = writeTwoTubesVtk();
    const fs::path output = testDir() / "timed.png";
    const auto r =
        render({input.string(), "-o", output.string(), "--size", "160x120", "--timings"});
    ASSERT_EQ(r.code, vv::cli::kOk) << r.err;
    EXPECT_EQ(r.out.front(), '{') << r.out;
    for (const char* pass :
         {"geometry", "vessel-shading", "vss-solve", "vss-shading", "composite"}) {
        EXPECT_NE(r.out.find("\"name\": \"" + std::string(pass) + "\""), std::string::npos)
            << pass << ": " << r.out;
    }
    EXPECT_NE(r.out.find("\"cpu_ms\""), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("\"shown\": true"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("wrote"), std::string::npos) << r.out;  // the summary went to stderr
    EXPECT_NE(r.err.find("wrote"), std::string::npos) << r.err;

    const auto off = render(
        {input.string(), "-o", output.string(), "--size", "160x120", "--timings", "--vss", "off"});
    ASSERT_EQ(off.code, vv::cli::kOk) << off.err;
    EXPECT_NE(off.out.find("\"name\": \"vss-solve\", \"state\": \"culled\""), std::string::npos)
        << off.out;
}

TEST_F(RenderCommandTest, BadVssArgumentsAreUsageErrors) {
    const fs::path input = writeTubeVtk();
    const fs::path output = testDir() / "never.png";
    for (const std::vector<std::string>& extra : {std::vector<std::string>{"--vss", "maybe"},
                                                  {"--scale", "rainbow"},
                                                  {"--p", "0"},
                                                  {"--p", "x"},
                                                  {"--p", "100"},
                                                  {"--isolines", "-1"},
                                                  {"--solver", "magic"},
                                                  {"--tolerance", "0"},
                                                  {"--tolerance", "nan"},
                                                  {"--vss"}}) {
        std::vector<std::string> args{input.string(), "-o", output.string()};
        args.insert(args.end(), extra.begin(), extra.end());
        const auto r = render(args);
        EXPECT_EQ(r.code, vv::cli::kUsage) << extra.front() << ": " << r.err;
    }
    EXPECT_FALSE(fs::exists(output));
}

TEST_F(RenderCommandTest, BadSizeIsAUsageError) {
    const fs::path input = writeTubeVtk();
    const fs::path output = testDir() / "never.png";
    for (const char* size : {"0x100", "100x0", "abc", "100", "100x", "x100", "-5x10", "20000x10",
                             "10x10x10", "1.5x2"}) {
        const auto r = render({input.string(), "-o", output.string(), "--size", size});
        EXPECT_EQ(r.code, vv::cli::kUsage) << size;
        EXPECT_NE(r.err.find("--size"), std::string::npos) << size << ": " << r.err;
    }
    EXPECT_FALSE(fs::exists(output));
}

TEST_F(RenderCommandTest, OtherBadArgumentsAreUsageErrors) {
    const fs::path input = writeTubeVtk();
    const fs::path output = testDir() / "never.png";
    EXPECT_EQ(render({}).code, vv::cli::kUsage);                      // no input
    EXPECT_EQ(render({input.string()}).code, vv::cli::kUsage);        // no -o
    EXPECT_EQ(render({input.string(), "-o"}).code, vv::cli::kUsage);  // -o without value
    EXPECT_EQ(render({input.string(), "-o", output.string(), "--frobnicate"}).code,
              vv::cli::kUsage);
    EXPECT_EQ(render({input.string(), input.string(), "-o", output.string()}).code,
              vv::cli::kUsage);
    EXPECT_EQ(render({input.string(), "-o", output.string(), "--background", "red"}).code,
              vv::cli::kUsage);
    EXPECT_EQ(render({input.string(), "-o", output.string(), "--background", "#12345g"}).code,
              vv::cli::kUsage);
    EXPECT_EQ(render({input.string(), "-o", output.string(), "--colormap", "jet"}).code,
              vv::cli::kUsage);
    const auto unknownArray = render({input.string(), "-o", output.string(), "--array", "speed"});
    EXPECT_EQ(unknownArray.code, vv::cli::kUsage);
    EXPECT_NE(unknownArray.err.find("wss"), std::string::npos) << unknownArray.err;  // lists arrays
    EXPECT_FALSE(fs::exists(output));
}

TEST_F(RenderCommandTest, UnwritableOutputExitsWithCode4) {
    const fs::path input = writeTubeVtk();
    const auto missingFolder =
        render({input.string(), "-o", (testDir() / "no-such-folder" / "x.png").string()});
    EXPECT_EQ(missingFolder.code, vv::cli::kCannotWrite) << missingFolder.err;
    EXPECT_NE(missingFolder.err.find("no-such-folder"), std::string::npos) << missingFolder.err;

    const fs::path folder = testDir() / "a-folder.png";
    fs::create_directories(folder);
    const auto isFolder = render({input.string(), "-o", folder.string()});
    EXPECT_EQ(isFolder.code, vv::cli::kCannotWrite) << isFolder.err;
}

TEST_F(RenderCommandTest, MissingOrBadInputExitsWithCode3) {
    const fs::path output = testDir() / "never.png";
    const auto missing = render({(testDir() / "missing.vtk").string(), "-o", output.string()});
    EXPECT_EQ(missing.code, vv::cli::kInvalidInput) << missing.err;
    EXPECT_NE(missing.err.find("missing.vtk"), std::string::npos) << missing.err;

    const fs::path garbage = testDir() / "garbage.stl";
    std::ofstream(garbage) << "this is not a mesh\n";
    const auto bad = render({garbage.string(), "-o", output.string()});
    EXPECT_EQ(bad.code, vv::cli::kInvalidInput) << bad.err;
    EXPECT_FALSE(fs::exists(output));
}

}  // namespace

namespace {

/// Pixels whose largest channel differs by more than 8 levels.
long countDifferent(const QImage& a, const QImage& b) {
    long count = 0;
    for (int y = 0; y < a.height(); ++y) {
        for (int x = 0; x < a.width(); ++x) {
            const QRgb p = a.pixel(x, y);
            const QRgb q = b.pixel(x, y);
            count += std::max({std::abs(qRed(p) - qRed(q)), std::abs(qGreen(p) - qGreen(q)),
                               std::abs(qBlue(p) - qBlue(q))}) > 8
                         ? 1
                         : 0;
        }
    }
    return count;
}

TEST_F(RenderCommandTest, TileRendersInTilesTheSameImage) {
    const fs::path input = writeTubeVtk();
    const fs::path whole = testDir() / "whole.png";
    const fs::path tiled = testDir() / "tiled.png";
    const std::vector<std::string> common{input.string(), "--size", "700x500", "--isolines", "8"};
    std::vector<std::string> args = common;
    args.insert(args.end(), {"-o", whole.string()});
    const auto one = render(args);
    ASSERT_EQ(one.code, vv::cli::kOk) << one.err;
    EXPECT_EQ(one.out.find("tiles"), std::string::npos) << one.out;
    args = common;
    args.insert(args.end(), {"-o", tiled.string(), "--tile", "256"});
    const auto parts = render(args);
    ASSERT_EQ(parts.code, vv::cli::kOk) << parts.err;
    EXPECT_NE(parts.out.find(" tiles"), std::string::npos) << parts.out;  // "in N tiles"
    const QImage a(QString::fromStdString(whole.string()));
    const QImage b(QString::fromStdString(tiled.string()));
    ASSERT_EQ(a.size(), QSize(700, 500));
    ASSERT_EQ(b.size(), a.size());
    EXPECT_GT(countNot(a, a.pixel(0, 0)), 1000);  // not an empty view
    // Fewer than 0.1 % of the pixels differ visibly.
    EXPECT_LT(countDifferent(a, b), 350);

    // Too small, not a number, or with options that describe one frame.
    const fs::path never = testDir() / "never-tiled.png";
    for (const std::vector<std::string>& extra :
         {std::vector<std::string>{"--tile", "10"}, std::vector<std::string>{"--tile", "big"},
          std::vector<std::string>{"--tile", "256", "--timings"},
          std::vector<std::string>{"--tile", "256", "--depth-out",
                                   (testDir() / "d.pfm").string()}}) {
        args = {input.string(), "-o", never.string()};
        args.insert(args.end(), extra.begin(), extra.end());
        EXPECT_EQ(render(args).code, vv::cli::kUsage) << extra.front() << " " << extra[1];
    }
    EXPECT_FALSE(fs::exists(never));
}

}  // namespace
