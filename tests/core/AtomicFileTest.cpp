// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <stdexcept>

#include "vv/core/AtomicFile.h"
#include "vv/core/CsvField.h"
#include "vv/core/Error.h"

namespace fs = std::filesystem;

namespace {

fs::path freshDir(const std::string& name) {
    const fs::path dir = fs::path(VV_TEST_TMP) / ("core-" + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(AtomicFile, WritesAndReplaces) {
    const fs::path dir = freshDir("atomic-ok");
    const fs::path target = dir / "out.txt";
    vv::writeAtomically(target, [](const fs::path& tmp) { std::ofstream(tmp) << "first"; });
    EXPECT_EQ(slurp(target), "first");
    vv::writeAtomically(target, [](const fs::path& tmp) { std::ofstream(tmp) << "second"; });
    EXPECT_EQ(slurp(target), "second");
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

// The bytes as given (a NUL, a carriage return), replacing the old file.
TEST(AtomicFile, WritesBytesAsGiven) {
    const fs::path dir = freshDir("atomic-bytes");
    const fs::path target = dir / "out.bin";
    vv::writeFileAtomically(target, "old");
    const std::string bytes("a\0b\r\nc", 6);
    vv::writeFileAtomically(target, bytes);
    EXPECT_EQ(slurp(target), bytes);
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
    EXPECT_THROW(vv::writeFileAtomically(dir / "missing" / "x.txt", "x"), vv::IoError);
}

TEST(CsvField, QuotesOnlyWhatNeedsIt) {
    EXPECT_EQ(vv::csvField("VSS-CD"), "VSS-CD");
    EXPECT_EQ(vv::csvField(""), "");
    EXPECT_EQ(vv::csvField("Doe, J"), "\"Doe, J\"");
    EXPECT_EQ(vv::csvField("say \"hi\""), "\"say \"\"hi\"\"\"");
    EXPECT_EQ(vv::csvField("two\nlines"), "\"two\nlines\"");
    EXPECT_EQ(vv::csvField("cr\r"), "\"cr\r\"");
}

TEST(AtomicFile, FailedWriteKeepsOldFileAndLeavesNoTemporary) {
    const fs::path dir = freshDir("atomic-fail");
    const fs::path target = dir / "out.txt";
    std::ofstream(target) << "old";
    EXPECT_THROW(vv::writeAtomically(target,
                                     [](const fs::path& tmp) {
                                         std::ofstream(tmp) << "partial";
                                         throw std::runtime_error("disk full");
                                     }),
                 std::runtime_error);
    EXPECT_EQ(slurp(target), "old");
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

TEST(AtomicFile, MissingFolderIsIoErrorNamingTarget) {
    const fs::path target = fs::path(VV_TEST_TMP) / "no-such-folder" / "out.txt";
    try {
        vv::writeAtomically(target, [](const fs::path& tmp) { std::ofstream(tmp) << "x"; });
        FAIL() << "expected IoError";
    } catch (const vv::IoError& e) {
        EXPECT_NE(std::string(e.what()).find("out.txt"), std::string::npos);
    }
}

TEST(AtomicFile, WriterThatWritesNothingIsAnError) {
    const fs::path dir = freshDir("atomic-nothing");
    EXPECT_THROW(vv::writeAtomically(dir / "out.txt", [](const fs::path&) {}), vv::IoError);
    EXPECT_FALSE(fs::exists(dir / "out.txt"));
}

}  // namespace
