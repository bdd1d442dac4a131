// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "vv/core/Error.h"
#include "vv/core/Progress.h"

namespace {

TEST(Progress, DefaultReportsNowhereAndNeverStops) {
    const vv::Progress p;
    EXPECT_NO_THROW(p.report(0.5, "x"));
    EXPECT_FALSE(p.cancelled());
}

TEST(Progress, ClampsAndMapsSubRanges) {
    std::vector<double> seen;
    const vv::Progress p([&](double f, std::string_view) { seen.push_back(f); }, {});
    p.report(2.0, "a");
    const vv::Progress half = p.sub(0.5, 1.0);
    half.report(0.0, "b");
    half.report(0.5, "b");
    half.report(-1.0, "b");
    ASSERT_EQ(seen.size(), 4U);
    EXPECT_DOUBLE_EQ(seen[0], 1.0);
    EXPECT_DOUBLE_EQ(seen[1], 0.5);
    EXPECT_DOUBLE_EQ(seen[2], 0.75);
    EXPECT_DOUBLE_EQ(seen[3], 0.5);
}

TEST(Progress, StopMakesReportThrow) {
    std::stop_source stop;
    const vv::Progress p([](double, std::string_view) {}, stop.get_token());
    EXPECT_NO_THROW(p.report(0.1, "a"));
    stop.request_stop();
    EXPECT_TRUE(p.cancelled());
    EXPECT_THROW(p.report(0.2, "a"), vv::CancelledError);
    EXPECT_THROW(p.sub(0, 1).throwIfCancelled(), vv::CancelledError);
}

}  // namespace
