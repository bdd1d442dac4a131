// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>
#include <sys/mman.h>

#include <cstddef>
#include <cstring>

#include "vv/core/ProcessMemory.h"

namespace {

TEST(ProcessMemory, ResidentAndPeakFollowAnAllocation) {
    const auto before = vv::residentKiB();
    ASSERT_TRUE(before.has_value()) << "/proc/self/status has no VmRSS";
    EXPECT_GT(*before, 100U);  // a process with a C++ runtime
    ASSERT_TRUE(vv::resetPeakResident());
    {
        // 64 MiB, touched, straight from the kernel and given back to it:
        // malloc may keep freed memory (and AddressSanitizer's quarantine
        // does), which would leave the resident size up after the block.
        const std::size_t size = 64U << 20U;
        void* block =
            mmap(nullptr, size, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
        ASSERT_NE(block, MAP_FAILED);
        std::memset(block, 1, size);
        const auto during = vv::residentKiB();
        munmap(block, size);
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
