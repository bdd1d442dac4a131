// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "vv/core/Log.h"

namespace {

std::vector<std::string> gSeen;

void captureSink(vv::log::Level, std::string_view category, std::string_view message) {
    gSeen.push_back(std::string(category) + "|" + std::string(message));
}

class LogTest : public ::testing::Test {
  protected:
    void SetUp() override {
        gSeen.clear();
        vv::log::setSink(&captureSink);
    }
    void TearDown() override {
        vv::log::setSink(nullptr);
        ::unsetenv("VV_LOG");
    }
};

constexpr vv::log::Category kIo("vv.io");
constexpr vv::log::Category kVss("vv.vss");

TEST_F(LogTest, DefaultThresholdIsInfo) {
    ::unsetenv("VV_LOG");
    vv::log::debug(kIo, "hidden");
    vv::log::info(kIo, "shown");
    ASSERT_EQ(gSeen.size(), 1U);
    EXPECT_EQ(gSeen[0], "vv.io|shown");
}

TEST_F(LogTest, PerCategoryThresholds) {
    ::setenv("VV_LOG", "warning,vv.vss=debug", 1);
    vv::log::info(kIo, "io info");
    vv::log::warning(kIo, "io warning");
    vv::log::debug(kVss, "vss debug");
    ASSERT_EQ(gSeen.size(), 2U);
    EXPECT_EQ(gSeen[0], "vv.io|io warning");
    EXPECT_EQ(gSeen[1], "vv.vss|vss debug");
}

TEST_F(LogTest, ParseLevel) {
    EXPECT_EQ(vv::log::parseLevel("debug"), vv::log::Level::Debug);
    EXPECT_EQ(vv::log::parseLevel("off"), vv::log::Level::Off);
    EXPECT_EQ(vv::log::parseLevel("nonsense"), vv::log::Level::Info);
}

}  // namespace
