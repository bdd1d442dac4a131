// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "vv/core/ProcessMemory.h"

namespace {

TEST(ProcessMemory, ResidentAndPeakFollowAnAllocation) {
    const auto before = vv::residentKiB();
    ASSERT_TRUE(before.has_value()) << "/proc/self/status has no VmRSS";
    EXPECT_GT(*before, 100U);  // a process with a C++ runtime
    ASSERT_TRUE(vv::resetPeakResident());
    {
        std::vector<char> block(64U << 20U);  // 64 MiB, touched
        std::memset(block.data(), 1, block.size());
        const auto during = vv::residentKiB();
        ASSERT_TRUE(during.has_value());
        EXPECT_GE(*during, *before + 60U * 1024U);
    }
    const auto peak = vv::peakResidentKiB();
    ASSERT_TRUE(peak.has_value());
    EXPECT_GE(*peak, *before + 60U * 1024U);
    // After a reset the peak starts again from what is resident now.
    ASSERT_TRUE(vv::resetPeakResident());
    EXPECT_LT(*vv::peakResidentKiB(), *peak);
}

}  // namespace
