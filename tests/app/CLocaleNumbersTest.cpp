// SPDX-License-Identifier: GPL-3.0-or-later
// Numbers that machines read (CSV, JSON, the CLI's output) are written in the
// C locale whatever the process locale: a Qt application sets LC_NUMERIC from
// the environment, and std::snprintf would then write "0,5" under de_DE.
//
// The German locale comes from tests/support/GermanLocale.h.
#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <charconv>
#include <clocale>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <optional>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "CliRun.h"
#include "GermanLocale.h"
#include "TestMeshes.h"
#include "evaluation/VssBenchmark.h"
#include "vv/core/NumberText.h"
#include "vv/demo/DemoTree.h"
#include "vv/meshio/MeshWriter.h"

namespace vv::test {
namespace {

namespace fs = std::filesystem;

fs::path testDir() {
    const fs::path dir = processTestDir("c-locale-numbers");
    fs::create_directories(dir);
    return dir;
}

std::string printfText(const char* pattern, int digits, double value) {
    std::array<char, 512> buffer{};
    std::snprintf(buffer.data(), buffer.size(), pattern, digits, value);
    return buffer.data();
}

/// The shell prefix that runs a command in German.
std::string inGerman(const std::string& locpath) {
    std::string prefix = "env LC_ALL=" + std::string(kGerman) + " LANG=" + kGerman;
    if (!locpath.empty()) {
        prefix += " LOCPATH='" + locpath + "'";
    }
    return prefix + " ";
}

struct ShellRun {
    int code = -1;
    std::string out;
};

ShellRun shell(const std::string& command) {
    ShellRun run;
    std::FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
    if (pipe == nullptr) {
        return run;
    }
    std::array<char, 4096> buffer{};
    std::size_t n = 0;
    while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) {
        run.out.append(buffer.data(), n);
    }
    const int status = ::pclose(pipe);
    run.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return run;
}

std::string quote(const fs::path& path) {
    return "'" + path.string() + "'";
}

/// A tube off the grid (coordinates and array values with decimals), as VTP.
const fs::path& decimalTube() {
    static const fs::path file = [] {
        scene::Mesh mesh = tube({.radius = 2.5F,
                                 .start = glm::vec3(0.25F, -1.5F, 0.75F),
                                 .length = 12.5F,
                                 .segments = 12,
                                 .rings = 6});
        addAxialArray(mesh, "wss", "Pa", 0.25F, [](float x) { return 0.5F + 0.1F * x; });
        const fs::path f = testDir() / "decimal-tube.vtp";
        meshio::writeVtp(mesh, f);
        return f;
    }();
    return file;
}

/// True when `text` is all of one finite number in the C locale.
bool isCNumber(const std::string& text) {
    return vv::parseFiniteNumber(text).has_value();
}

/// The fields of a CSV line without quoted commas.
std::vector<std::string> csvFields(const std::string& line) {
    std::vector<std::string> fields;
    std::string field;
    std::istringstream in(line);
    while (std::getline(in, field, ',')) {
        fields.push_back(field);
    }
    if (!line.empty() && line.back() == ',') {
        fields.emplace_back();
    }
    return fields;
}

TEST(CLocaleNumbers, FormattersGivePrintfsTextInTheCLocale) {
    const double values[] = {0.0,   0.5,     -0.5,   1.0 / 3.0,         1234.5678,
                             1e-7,  1e20,    -0.0,   2.5e-310,          0.125,
                             999.5, 0.00995, 123456, 0.1 + 0.2 - 1e-17, 65504.0};
    for (const double v : values) {
        for (const int digits : {0, 1, 2, 3, 4, 6, 9}) {
            EXPECT_EQ(vv::fixedText(v, digits), printfText("%.*f", digits, v))
                << v << " " << digits;
            EXPECT_EQ(vv::significantText(v, digits), printfText("%.*g", digits, v))
                << v << " " << digits;
            EXPECT_EQ(vv::scientificText(v, digits), printfText("%.*e", digits, v))
                << v << " " << digits;
        }
    }
    EXPECT_EQ(vv::fixedText(std::numeric_limits<double>::quiet_NaN(), 2), "nan");
    EXPECT_EQ(vv::significantText(std::numeric_limits<double>::infinity(), 6), "inf");
    EXPECT_EQ(vv::scientificText(-std::numeric_limits<double>::infinity(), 2), "-inf");
    EXPECT_EQ(vv::fixedText(0.5, -3), "0");  // no digits: as 0
    EXPECT_EQ(vv::readableText(1.0 / 3.0), "0.333333");
}

TEST(CLocaleNumbers, FormattersAndTheBenchmarkCsvIgnoreAGermanProcessLocale) {
    std::string why;
    if (!germanLocalePath(why)) {
        GTEST_SKIP() << why;
    }
    evaluation::VssBenchmarkResult result;
    result.sizes = {evaluation::BenchSize{64, 48}};
    evaluation::VssBenchmarkRow row;
    row.size = result.sizes.front();
    row.p = 2.5;
    row.solver = "fast 0.5/255";
    row.series = "fast";
    row.options.kind = vss::SolverKind::Fast;
    row.options.tolerance = 0.5 / 255.0;
    row.runs = 1;
    row.medianMs = 1.25;
    row.minMs = 1.125;
    row.error.rmse = 0.0015;
    row.error.maxAbs = 0.0025;
    row.errorBound = 0.5 / 255.0;
    result.rows.push_back(row);
    evaluation::ViewSummary view;
    view.cameraDistance = 12.5F;
    view.dmin = 0.5;
    view.dmax = 1.5;
    result.views.push_back(view);

    const GermanNumbers german;
    ASSERT_EQ(printfText("%.*f", 1, 0.5), "0,5");  // the locale is in effect
    EXPECT_EQ(vv::fixedText(0.5, 1), "0.5");
    EXPECT_EQ(vv::significantText(2.5, 6), "2.5");
    EXPECT_EQ(vv::scientificText(1234.5, 2), "1.23e+03");
    EXPECT_EQ(vv::shortestText(0.1), "0.1");
    EXPECT_EQ(vv::readableText(0.55), "0.55");
    EXPECT_EQ(vv::parseFiniteNumber("0.5"), 0.5);
    EXPECT_FALSE(vv::parseFiniteNumber("0,5").has_value());

    const std::string csv = evaluation::csvText(result);
    std::istringstream lines(csv);
    std::string header;
    std::string line;
    ASSERT_TRUE(std::getline(lines, header));
    ASSERT_TRUE(std::getline(lines, line));
    const auto names = csvFields(header);
    const auto fields = csvFields(line);
    ASSERT_EQ(fields.size(), names.size()) << line;  // "2,5" would add a field
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (names[i] == "p" || names[i] == "tolerance" || names[i] == "median_ms" ||
            names[i] == "rmse" || names[i] == "error_bound") {
            EXPECT_TRUE(isCNumber(fields[i])) << names[i] << " = " << fields[i];
        }
    }
    EXPECT_NE(line.find(",2.5,"), std::string::npos) << line;
    EXPECT_NE(line.find(",1.2500,"), std::string::npos) << line;
    const std::string table = evaluation::markdownTable(result);
    EXPECT_FALSE(std::regex_search(table, std::regex("[0-9],[0-9]"))) << table;
}

/// vesselview-cli and vesselview run as processes in German.
class ProcessInGerman : public ::testing::Test {
  protected:
    void SetUp() override {
        std::string why;
        const auto path = germanLocalePath(why);
        if (!path) {
            GTEST_SKIP() << why;
        }
        german_ = inGerman(*path);
    }

    /// `vesselview-cli ARGS` in the C locale and in German.
    [[nodiscard]] static ShellRun inC(const std::string& args) {
        return shell("env LC_ALL=C " + quote(VV_CLI_EXE) + " " + args);
    }
    [[nodiscard]] ShellRun inGermanLocale(const std::string& args) const {
        return shell(german_ + quote(VV_CLI_EXE) + " " + args);
    }

    std::string german_;
};

TEST_F(ProcessInGerman, InfoPrintsTheSameNumbersAsInTheCLocale) {
    for (const std::string& args :
         {"info " + quote(decimalTube()), "info --json " + quote(decimalTube())}) {
        const ShellRun c = inC(args);
        const ShellRun de = inGermanLocale(args);
        ASSERT_EQ(c.code, 0) << c.out;
        ASSERT_EQ(de.code, 0) << de.out;
        EXPECT_EQ(de.out, c.out) << args;
        EXPECT_NE(c.out.find("0.25"), std::string::npos) << c.out;  // decimals were printed
    }
}

TEST_F(ProcessInGerman, RenderedLegendsDoNotMixEnglishWordsWithGermanNumbers) {
    // The image's legend titles are English (render has no --lang), so its
    // numbers are English too: a German system locale changes no pixel.
    // Before, the ticks read "0,45" under the English title.
    const fs::path c = testDir() / "legend-c.png";
    const fs::path de = testDir() / "legend-de.png";
    const std::string args = "render " + quote(decimalTube()) +
                             " --size 480x320 --vss off --bins 5 --ao off --aa off -o ";
    const ShellRun inCLocale = inC(args + quote(c));
    const ShellRun inGerman = inGermanLocale(args + quote(de));
    ASSERT_EQ(inCLocale.code, 0) << inCLocale.out;
    ASSERT_EQ(inGerman.code, 0) << inGerman.out;
    const auto bytes = [](const fs::path& file) {
        std::ifstream in(file, std::ios::binary);
        return std::string(std::istreambuf_iterator<char>(in), {});
    };
    ASSERT_FALSE(bytes(c).empty());
    EXPECT_TRUE(bytes(c) == bytes(de)) << "the German locale changed the rendered legend";
}

TEST_F(ProcessInGerman, BenchWritesItsCsvAndTableInTheCLocale) {
    vv::demo::DemoTreeOptions options;
    options.generations = 3;
    options.maxTriangles = 10000;
    const fs::path tree = testDir() / "bench-tree.vtp";
    meshio::writeVtp(vv::demo::generateDemoMesh(options), tree);
    const fs::path out = testDir() / "bench-de";
    fs::remove_all(out);
    const ShellRun de =
        inGermanLocale("bench --quick --mesh " + quote(tree) + " --out " + quote(out) +
                       " --views close --p 2.5 --solvers brute,fast --tolerances 0.5"
                       " --size 64x48 --runs 1");
    ASSERT_EQ(de.code, 0) << de.out;

    std::ifstream csv(out / "vss.csv");
    std::string header;
    ASSERT_TRUE(std::getline(csv, header));
    const auto names = csvFields(header);
    int rows = 0;
    for (std::string line; std::getline(csv, line); ++rows) {
        const auto fields = csvFields(line);
        ASSERT_EQ(fields.size(), names.size()) << line;  // "2,5" would add a field
        for (std::size_t i = 0; i < names.size(); ++i) {
            if (names[i] == "p") {
                EXPECT_EQ(fields[i], "2.5");
            } else if (names[i] == "median_ms" || names[i] == "min_ms" || names[i] == "rmse" ||
                       names[i] == "max_abs_error") {
                EXPECT_TRUE(isCNumber(fields[i])) << names[i] << " = " << fields[i];
            } else if (names[i] == "solver" && fields[i].rfind("fast", 0) == 0) {
                EXPECT_EQ(fields[i], "fast 0.5/255");
            }
        }
    }
    EXPECT_EQ(rows, 2);
    std::ifstream tableFile(out / "vss-table.md");
    const std::string table((std::istreambuf_iterator<char>(tableFile)),
                            std::istreambuf_iterator<char>());
    EXPECT_FALSE(table.empty());
    EXPECT_FALSE(std::regex_search(table, std::regex("[0-9],[0-9]"))) << table;
}

#ifdef VV_GUI_EXE
// The GUI's QApplication sets the C library's locale from the environment;
// the mesh readers' checks read numbers with std::strtod. In German they
// refused "0.5" ("vertex 1 has '0.5' where a coordinate belongs") until the
// application set LC_NUMERIC back to C.
TEST_F(ProcessInGerman, TheGuiOpensAsciiMeshesWithDecimalPoints) {
    const fs::path obj = testDir() / "decimal-tetra.obj";
    std::ofstream(obj) << "v 0.5 0.25 0\nv 10.5 0 0.125\nv 0 10.75 0\nv 0.5 0 10.5\n"
                          "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
    const fs::path png = testDir() / "decimal-tetra.png";
    fs::remove(png);
    const ShellRun run =
        shell(german_ + "XDG_CONFIG_HOME=" + quote(testDir() / "gui-config") + " " +
              quote(VV_GUI_EXE) + " --screenshot " + quote(png) + " " + quote(obj));
    EXPECT_EQ(run.code, 0) << run.out;
    EXPECT_TRUE(fs::exists(png)) << run.out;
}

// A copy of the GUI started outside its build or install tree finds no
// translations: it says so (here: its log on stderr; in the window a message
// box) instead of showing English without a word. In its tree it says nothing.
TEST(GuiLanguage, AProgramOutsideItsTreeSaysItsTranslationIsMissing) {
    const fs::path loose = testDir() / "loose-program";
    fs::remove_all(loose);
    fs::create_directories(loose);
    const fs::path program = loose / "vesselview";
    fs::copy_file(VV_GUI_EXE, program);
    fs::permissions(program, fs::perms::owner_all, fs::perm_options::add);
    const fs::path obj = testDir() / "language-tetra.obj";
    std::ofstream(obj) << "v 0 0 0\nv 10 0 0\nv 0 10 0\nv 0 0 10\n"
                          "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
    const auto run = [&](const fs::path& exe) {
        const fs::path png = testDir() / "language-tetra.png";
        fs::remove(png);
        const ShellRun result =
            shell("env XDG_CONFIG_HOME=" + quote(testDir() / "language-config") + " " + quote(exe) +
                  " --lang de --screenshot " + quote(png) + " " + quote(obj));
        EXPECT_EQ(result.code, 0) << result.out;
        EXPECT_TRUE(fs::exists(png)) << result.out;
        return result.out;
    };
    const std::string outside = run(program);
    EXPECT_NE(outside.find("German translation was not found"), std::string::npos) << outside;
    EXPECT_NE(outside.find("in English"), std::string::npos) << outside;
    EXPECT_NE(outside.find((loose.parent_path() / "share").string()), std::string::npos)
        << "the folders searched are named: " << outside;
    const std::string inside = run(VV_GUI_EXE);
    EXPECT_EQ(inside.find("translation"), std::string::npos) << inside;
}
#endif

}  // namespace
}  // namespace vv::test
