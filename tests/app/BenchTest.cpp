// SPDX-License-Identifier: GPL-3.0-or-later
// `vesselview-cli bench` through vv::cli::run: a quick run on a small tree.
#include <gtest/gtest.h>
#include <unistd.h>

#include <QImage>
#include <QString>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "cli/BenchSizes.h"
#include "cli/Cli.h"
#include "evaluation/VssBenchmark.h"
#include "vv/demo/DemoTree.h"
#include "vv/meshio/MeshWriter.h"
#include "vv/vss/Pfm.h"

namespace bench_test {

namespace {

namespace fs = std::filesystem;

fs::path testDir() {
    const fs::path dir =
        fs::path(VV_TEST_TMP) / "bench-command" / ("run-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return dir;
}

/// A small demo tree written once as VTP.
const fs::path& smallTree() {
    static const fs::path file = [] {
        vv::demo::DemoTreeOptions options;
        options.generations = 4;
        options.maxTriangles = 20000;
        const fs::path f = testDir() / "small-tree.vtp";
        vv::meshio::writeVtp(vv::demo::generateDemoMesh(options), f);
        return f;
    }();
    return file;
}

struct BenchRun {
    int code = -1;
    std::string out;
    std::string err;
};

BenchRun bench(std::vector<std::string> args) {
    args.insert(args.begin(), "bench");
    std::ostringstream out;
    std::ostringstream err;
    BenchRun r;
    r.code = vv::cli::run(args, out, err);
    r.out = out.str();
    r.err = err.str();
    return r;
}

/// CSV without quoted commas in the fields this test reads.
std::vector<std::map<std::string, std::string>> readCsv(const fs::path& file) {
    std::ifstream in(file);
    std::string line;
    std::vector<std::string> header;
    std::vector<std::map<std::string, std::string>> rows;
    const auto split = [](const std::string& text) {
        std::vector<std::string> fields;
        std::string field;
        std::istringstream s(text);
        while (std::getline(s, field, ',')) {
            fields.push_back(field);
        }
        if (!text.empty() && text.back() == ',') {
            fields.emplace_back();
        }
        return fields;
    };
    while (std::getline(in, line)) {
        if (header.empty()) {
            header = split(line);
            continue;
        }
        const auto fields = split(line);
        std::map<std::string, std::string> row;
        for (std::size_t i = 0; i < header.size() && i < fields.size(); ++i) {
            row[header[i]] = fields[i];
        }
        rows.push_back(row);
    }
    return rows;
}

TEST(BenchCommandTest, QuickRunWritesTableCsvPlotAndDepthImages) {
    const fs::path out = testDir() / "quick";
    const fs::path depthOut = testDir() / "depth";
    fs::remove_all(out);
    fs::remove_all(depthOut);
    const BenchRun r = bench({"--quick", "--mesh", smallTree().string(), "--out", out.string(),
                              "--depth-out", depthOut.string()});
    ASSERT_EQ(r.code, vv::cli::kOk) << r.err;
    EXPECT_NE(r.out.find("| view | p | solver |"), std::string::npos) << r.out;

    const auto rows = readCsv(out / "vss.csv");
    // 3 views x 3 p x 7 settings (reference, brute, step 3, step 5, fast x 3).
    ASSERT_EQ(rows.size(), 3U * 3U * 7U);
    std::set<std::string> cases;
    std::map<std::string, int> perSolver;
    for (const auto& row : rows) {
        cases.insert(row.at("view") + " " + row.at("p") + " " + row.at("solver"));
        ++perSolver[row.at("solver")];
        EXPECT_EQ(row.at("width"), "256");
        EXPECT_EQ(row.at("height"), "144");
        EXPECT_EQ(row.at("failure"), "") << row.at("solver");
        const std::string& kind = row.at("kind");
        const double maxError = std::stod(row.at("max_abs_error"));
        EXPECT_GT(std::stoll(row.at("compared_pixels")), 0);
        EXPECT_GT(std::stoll(row.at("regions")), 0);
        EXPECT_GT(std::stod(row.at("median_ms")), 0.0);
        if (kind == "reference") {
            EXPECT_EQ(maxError, 0.0);
            EXPECT_EQ(std::stod(row.at("rmse")), 0.0);
        } else if (kind == "brute") {
            EXPECT_LT(maxError, 1e-4) << row.at("view") << " p=" << row.at("p");
        } else if (kind == "fast") {
            EXPECT_LE(maxError, std::stod(row.at("tolerance")))
                << row.at("view") << " p=" << row.at("p") << " " << row.at("solver");
        }
        EXPECT_LE(std::stod(row.at("rmse")), maxError);
    }
    EXPECT_EQ(cases.size(), rows.size());  // one row per view x p x solver
    for (const char* solver :
         {"reference", "brute", "step 3", "step 5", "fast 0.5/255", "fast 2/255", "fast 8/255"}) {
        EXPECT_EQ(perSolver[solver], 9) << solver;
    }

    const QImage plot(QString::fromStdString((out / "vss-error-vs-time.png").string()));
    ASSERT_FALSE(plot.isNull());
    EXPECT_EQ(plot.width(), 1400);
    EXPECT_EQ(plot.height(), 900);
    EXPECT_TRUE(fs::is_regular_file(out / "vss-table.md"));

    for (const char* view : {"far", "medium", "close"}) {
        const auto depth = vv::vss::readPfm(depthOut / (std::string("depth-") + view + ".pfm"));
        ASSERT_EQ(depth.width(), 256);
        ASSERT_EQ(depth.height(), 144);
        int finite = 0;
        for (int y = 0; y < depth.height(); ++y) {
            for (int x = 0; x < depth.width(); ++x) {
                finite += std::isfinite(depth(x, y)) ? 1 : 0;
            }
        }
        EXPECT_GT(finite, 100) << view;
        EXPECT_LT(finite, 256 * 144) << view;
    }
}

TEST(BenchCommandTest, SelectedViewsPowersAndSolvers) {
    const fs::path out = testDir() / "selected";
    const BenchRun r =
        bench({"--quick", "--mesh", smallTree().string(), "--out", out.string(), "--views", "close",
               "--p", "3", "--solvers", "brute,step2", "--size", "96x64", "--runs", "2"});
    ASSERT_EQ(r.code, vv::cli::kOk) << r.err;
    const auto rows = readCsv(out / "vss.csv");
    ASSERT_EQ(rows.size(), 2U);
    EXPECT_EQ(rows[0].at("solver"), "brute");
    EXPECT_EQ(rows[1].at("solver"), "step 2");
    for (const auto& row : rows) {
        EXPECT_EQ(row.at("view"), "close");
        EXPECT_EQ(row.at("p"), "3");
        EXPECT_EQ(row.at("runs"), "2");
        EXPECT_EQ(row.at("width"), "96");
    }
}

TEST(BenchCommandTest, SeveralSizesInOneRunWithTheBruteSolverAsTruthAboveTheLimit) {
    // Both sizes are below the reference's limit (1280x720 pixels): the
    // reference is the truth at both; the rows carry their size, the depth
    // images are named by size, and the table ends with the size ratios.
    const fs::path out = testDir() / "sizes";
    const fs::path depthOut = testDir() / "sizes-depth";
    fs::remove_all(depthOut);
    fs::create_directories(depthOut);
    const BenchRun r =
        bench({"--quick", "--mesh", smallTree().string(), "--out", out.string(), "--views", "far",
               "--p", "2", "--solvers", "reference,brute,fast", "--tolerances", "0.5", "--sizes",
               "96x54,192x108", "--depth-out", depthOut.string()});
    ASSERT_EQ(r.code, vv::cli::kOk) << r.err;
    const auto rows = readCsv(out / "vss.csv");
    ASSERT_EQ(rows.size(), 2U * 3U);
    for (std::size_t i = 0; i < rows.size(); ++i) {
        EXPECT_EQ(rows[i].at("width"), i < 3 ? "96" : "192");
        EXPECT_EQ(rows[i].at("height"), i < 3 ? "54" : "108");
        EXPECT_EQ(rows[i].at("truth"), "reference");
        EXPECT_EQ(rows[i].at("failure"), "");
    }
    EXPECT_NE(r.out.find("| size | view | p | solver |"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("| 192×108 | far | 2 | fast 0.5/255 |"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("Time against image size"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("| fast 0.5/255 | 192×108 | 4.00 | 1 |"), std::string::npos) << r.out;
    EXPECT_TRUE(fs::is_regular_file(depthOut / "depth-far-96x54.pfm"));
    EXPECT_TRUE(fs::is_regular_file(depthOut / "depth-far-192x108.pfm"));
}

TEST(VssBenchmarkTest, AboveTheReferenceLimitTheBruteSolverIsTheTruth) {
    vv::scene::Scene scene;
    vv::demo::DemoTreeOptions tree;
    tree.generations = 3;
    tree.maxTriangles = 10000;
    scene.meshes.push_back(vv::demo::generateDemoMesh(tree));
    vv::evaluation::VssBenchmarkOptions options;
    options.sizes = {{64, 36}, {128, 72}};
    options.referenceMaxPixels = 64 * 36;
    options.views = {vv::render::ViewPreset::Medium};
    options.powers = {4.0};
    options.runs = 1;
    std::vector<vv::evaluation::SolverSetting> settings = vv::evaluation::defaultSolverSettings();
    options.solvers = {settings[0], settings[1], settings[4]};  // reference, brute, fast
    const vv::evaluation::VssBenchmarkResult result =
        vv::evaluation::runVssBenchmark(scene, options);
    ASSERT_EQ(result.rows.size(), 6U);
    for (const auto& row : result.rows) {
        const bool large = row.size.width == 128;
        EXPECT_EQ(row.truth, large ? "brute" : "reference");
        if (large && row.solver == "reference") {
            EXPECT_NE(row.failure.find("ground truth"), std::string::npos) << row.failure;
            continue;
        }
        EXPECT_EQ(row.failure, "") << row.solver;
        EXPECT_GT(row.error.compared, 0);
        EXPECT_LE(row.error.maxAbs, 0.5 / 255.0 + 1e-5) << row.solver;
        if (large && row.solver == "brute") {
            EXPECT_EQ(row.error.maxAbs, 0.0);  // brute against its own (untimed) run
        }
    }
    const std::string table = vv::evaluation::markdownTable(result);
    EXPECT_NE(table.find("truth brute"), std::string::npos) << table;
    EXPECT_NE(table.find("| 128×72 | medium | 4 | reference | – | not measured"), std::string::npos)
        << table;
}

TEST(VssBenchmarkTest, SizeRatiosSumTheCasesMeasuredAtBothSizes) {
    vv::evaluation::VssBenchmarkResult result;
    result.sizes = {{100, 50}, {200, 100}, {400, 200}};
    const auto add = [&](vv::evaluation::BenchSize size, vv::render::ViewPreset view, double p,
                         const char* solver, double ms, double cpu, const char* failure = "") {
        vv::evaluation::VssBenchmarkRow row;
        row.size = size;
        row.view = view;
        row.p = p;
        row.solver = solver;
        row.medianMs = ms;
        row.medianCpuMs = cpu;
        row.failure = failure;
        result.rows.push_back(row);
    };
    using vv::render::ViewPreset;
    add({100, 50}, ViewPreset::Far, 2.0, "fast", 10.0, 20.0);
    add({100, 50}, ViewPreset::Far, 4.0, "fast", 30.0, 40.0);
    add({100, 50}, ViewPreset::Far, 2.0, "brute", 5.0, 5.0);
    add({200, 100}, ViewPreset::Far, 2.0, "fast", 20.0, 30.0);
    add({200, 100}, ViewPreset::Far, 4.0, "fast", 90.0, 100.0);
    add({200, 100}, ViewPreset::Far, 2.0, "brute", 7.0, 8.0, "not available");
    add({400, 200}, ViewPreset::Close, 2.0, "fast", 50.0, 50.0);  // no base case
    const auto ratios = vv::evaluation::sizeRatios(result);
    ASSERT_EQ(ratios.size(), 6U);  // 2 solvers x 3 sizes, in row / size order
    EXPECT_EQ(ratios[0].solver, "fast");
    EXPECT_EQ(ratios[0].size, (vv::evaluation::BenchSize{100, 50}));
    EXPECT_EQ(ratios[0].cases, 2);
    EXPECT_DOUBLE_EQ(ratios[0].ratio, 1.0);
    EXPECT_EQ(ratios[1].size, (vv::evaluation::BenchSize{200, 100}));
    EXPECT_EQ(ratios[1].cases, 2);
    EXPECT_DOUBLE_EQ(ratios[1].totalMs, 110.0);
    EXPECT_DOUBLE_EQ(ratios[1].baseMs, 40.0);
    EXPECT_DOUBLE_EQ(ratios[1].ratio, 110.0 / 40.0);
    EXPECT_DOUBLE_EQ(ratios[1].cpuRatio, 130.0 / 60.0);
    EXPECT_DOUBLE_EQ(ratios[1].maxCaseRatio, 3.0);
    EXPECT_EQ(ratios[2].cases, 0);  // the close view was not measured at the base size
    EXPECT_TRUE(std::isnan(ratios[2].ratio));
    EXPECT_EQ(ratios[3].solver, "brute");
    EXPECT_DOUBLE_EQ(ratios[3].ratio, 1.0);
    EXPECT_EQ(ratios[4].cases, 0);  // failed rows do not count
    const std::string table = vv::evaluation::markdownTable(result);
    EXPECT_NE(table.find("| fast | 200×100 | 4.00 | 2 | 110.0 | 40.0 | 2.75 | 2.17 | 3.00 |"),
              std::string::npos)
        << table;
    EXPECT_NE(table.find("| fast | 400×200 | 16.00 | 0 | – | – | – | – | – |"), std::string::npos)
        << table;
}

TEST(BenchSizesTest, ParsesOneOrSeveralSizes) {
    EXPECT_EQ(vv::cli::parseBenchSize("1280x720", "s"), (vv::evaluation::BenchSize{1280, 720}));
    const auto sizes = vv::cli::parseBenchSizes("1280x720,1920x1080,3840x2160");
    ASSERT_EQ(sizes.size(), 3U);
    EXPECT_EQ(sizes[1], (vv::evaluation::BenchSize{1920, 1080}));
    EXPECT_EQ(sizes[2], (vv::evaluation::BenchSize{3840, 2160}));
    EXPECT_EQ(vv::cli::parseBenchSizes("8x8").size(), 1U);
    for (const char* bad : {"", "1280x720,", ",1280x720", "1280x720,1280x720", "0x10", "8193x10",
                            "1280", "1280x720x3", "axb", "1280x720;640x360"}) {
        EXPECT_THROW((void)vv::cli::parseBenchSizes(bad), vv::cli::UsageError) << bad;
    }
}

TEST(BenchCommandTest, BadOptionsExitWithUsage) {
    const std::string out = (testDir() / "bad").string();
    const std::vector<std::vector<std::string>> bad{
        {"--size", "0x5"},
        {"--size", "100"},
        {"--sizes", "100x50,100x50"},
        {"--sizes", "100x50,0x5"},
        {"--size", "100x50", "--sizes", "200x100"},
        {"--views", "sideways"},
        {"--views", "far,,close"},
        {"--p", "-1"},
        {"--p", "two"},
        {"--runs", "0"},
        {"--runs", "1.5"},
        {"--solvers", "magic"},
        {"--solvers", "step0"},
        {"--solvers", "brute,brute"},
        {"--tolerances", "0"},
        {"--bogus"},
        {"--p"},
        {"--out"},
    };
    for (auto args : bad) {
        args.insert(args.end(), {"--quick", "--out", out});
        if (args[0] == "--p" && args.size() == 4) {
            args = {"--quick", "--out", out, "--p"};  // the value is missing
        }
        if (args[0] == "--out" && args.size() == 4) {
            args = {"--quick", "--out"};
        }
        const BenchRun r = bench(args);
        EXPECT_EQ(r.code, vv::cli::kUsage) << args[0] << " " << (args.size() > 1 ? args[1] : "");
        EXPECT_NE(r.err.find("bench"), std::string::npos) << r.err;
    }
    // A missing mesh is bad input, not a usage error.
    const BenchRun missing =
        bench({"--quick", "--mesh", (testDir() / "nope.vtp").string(), "--out", out});
    EXPECT_EQ(missing.code, vv::cli::kInvalidInput) << missing.err;
}

}  // namespace

}  // namespace bench_test
