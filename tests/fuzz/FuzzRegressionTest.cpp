// SPDX-License-Identifier: GPL-3.0-or-later
// Fuzz regressions (docs/reliability.md, "Fuzzing"): every file in
// tests/fuzz/regressions/<target>/ — the minimised inputs that crashed a
// fuzz target before its fix, and interesting corpus entries — goes through
// the target's body (fuzz/FuzzBodies.h), as under libFuzzer. Each must end in
// a load or in a vv::Error that names the file and a problem; a crash, a
// sanitizer report or any other exception fails the test (or the process).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "FuzzBodies.h"

namespace fs = std::filesystem;

namespace {

const fs::path kRegressions = fs::path(VV_SOURCE_DIR) / "tests" / "fuzz" / "regressions";

std::vector<fs::path> inputsOf(const std::string& target) {
    std::vector<fs::path> files;
    const fs::path dir = kRegressions / target;
    if (fs::is_directory(dir)) {
        for (const auto& entry : fs::directory_iterator(dir)) {
            if (entry.is_regular_file()) {
                files.push_back(entry.path());
            }
        }
    }
    std::sort(files.begin(), files.end());
    return files;
}

std::vector<std::uint8_t> readBytes(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

vv::fuzz::Outcome feed(const std::string& target, vv::fuzz::Bytes bytes) {
    if (target == "dicom") {
        return vv::fuzz::feedDicom(bytes);
    }
    if (target == "pfm") {
        return vv::fuzz::feedPfm(bytes);
    }
    if (target == "session") {
        return vv::fuzz::feedSession(bytes);
    }
    if (target == "analysis") {
        return vv::fuzz::feedAnalysis(bytes);
    }
    if (target == "study") {
        return vv::fuzz::feedStudy(bytes);
    }
    return vv::fuzz::feedMesh(bytes, "." + target);
}

class FuzzRegression : public ::testing::TestWithParam<std::string> {};

TEST_P(FuzzRegression, EveryFileLoadsOrFailsWithAMessageNamingIt) {
    const std::string target = GetParam();
    const std::vector<fs::path> files = inputsOf(target);
    ASSERT_FALSE(files.empty()) << "no regression inputs in " << (kRegressions / target);
    for (const fs::path& file : files) {
        SCOPED_TRACE(file.string());
        const std::vector<std::uint8_t> bytes = readBytes(file);
        const auto start = std::chrono::steady_clock::now();
        vv::fuzz::Outcome outcome;
        // Anything but a vv::Error escapes feed() and fails here.
        EXPECT_NO_THROW(outcome = feed(target, bytes));
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        // Recorded, not judged: a hang ends at ctest's timeout, and load on
        // CI must not fail a slow but finished load.
        RecordProperty(file.filename().string(), std::to_string(seconds));
        if (!outcome.loaded) {
            const std::string& error = outcome.error;
            EXPECT_NE(error.find(outcome.file.string()), std::string::npos)
                << "the message does not name the file: " << error;
            EXPECT_GT(error.size(), outcome.file.string().size() + 2)
                << "the message names no problem: " << error;
        }
    }
}

std::vector<std::string> targets() {
    return vv::fuzz::targetNames();
}

INSTANTIATE_TEST_SUITE_P(Targets, FuzzRegression, ::testing::ValuesIn(targets()),
                         [](const ::testing::TestParamInfo<std::string>& param) {
                             return param.param;
                         });

/// The expected outcomes of the crash reproducers (regressions/EXPECTED):
/// "<target>/<file> <loads|fails> [text the message must contain]".
TEST(FuzzRegression, ReproducersEndAsRecorded) {
    std::ifstream in(kRegressions / "EXPECTED");
    ASSERT_TRUE(in) << "missing " << (kRegressions / "EXPECTED");
    std::string line;
    int checked = 0;
    while (std::getline(in, line)) {
        if (line.empty() || line.front() == '#') {
            continue;
        }
        const auto space = line.find(' ');
        ASSERT_NE(space, std::string::npos) << line;
        const std::string name = line.substr(0, space);
        std::string rest = line.substr(space + 1);
        const bool loads = rest.starts_with("loads");
        ASSERT_TRUE(loads || rest.starts_with("fails")) << line;
        const std::string expected = rest.size() > 6 ? rest.substr(6) : std::string();
        const std::string target = name.substr(0, name.find('/'));
        SCOPED_TRACE(name);
        const vv::fuzz::Outcome outcome = feed(target, readBytes(kRegressions / name));
        EXPECT_EQ(outcome.loaded, loads) << outcome.error;
        if (!loads) {
            EXPECT_NE(outcome.error.find(expected), std::string::npos) << outcome.error;
        }
        ++checked;
    }
    EXPECT_GT(checked, 0);
}

}  // namespace
