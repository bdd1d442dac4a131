// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>
#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <thread>
#include <vector>

#include "vv/core/ProcessMemory.h"

namespace {

// What the vessel analysis does to glibc, in a forked child: a large mapped
// block freed (by default glibc then maps no block up to its size on its
// own any more), then a worker thread that touches 24 MiB in blocks of 256
// KiB (the size of a slab's larger tetrahedra blocks) and frees them. Exits
// 0 when the worker's freed memory left the resident size, 1 when it
// stayed, 2 when the policy could not be set.
[[noreturn]] void freeOnAWorkerThread(bool atOnce) {
    if (atOnce && !vv::handFreedMemoryBackAtOnce()) {
        ::_exit(2);
    }
    {
        const std::size_t size = 16U << 20U;
        const std::vector<char> big(size, 1);  // touched
    }
    bool handedBack = false;
    std::thread worker([&handedBack] {
        const std::size_t block = 256U << 10U;
        std::vector<std::vector<char>> blocks;
        for (std::size_t i = 0; i < (24U << 20U) / block; ++i) {
            blocks.emplace_back(block, 1);  // touched
        }
        const auto during = vv::residentKiB().value_or(0);
        while (!blocks.empty()) {
            blocks.pop_back();
        }
        const auto after = vv::residentKiB().value_or(0);
        handedBack = after + std::uint64_t{20} * 1024 < during;
    });
    worker.join();
    ::_exit(handedBack ? 0 : 1);
}

TEST(ProcessMemory, FreedMemoryLeavesAtOnceFromAWorkerThreadWhenAsked) {
#if defined(__SANITIZE_ADDRESS__)
    GTEST_SKIP() << "AddressSanitizer's allocator keeps freed memory in its quarantine and "
                    "ignores mallopt";
#endif
    // glibc's default keeps it (the control: without it the case proves
    // nothing); the policy hands it back.
    EXPECT_EXIT(freeOnAWorkerThread(false), ::testing::ExitedWithCode(1), "");
    EXPECT_EXIT(freeOnAWorkerThread(true), ::testing::ExitedWithCode(0), "");
}

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

// Another process's figures (a benchmark watches its listener process): a
// child touches 64 MiB, says so, gives them back and waits to be ended.
TEST(ProcessMemory, AnotherProcessIsReadByItsId) {
    int toParent[2];
    int toChild[2];
    ASSERT_EQ(::pipe(toParent), 0);
    ASSERT_EQ(::pipe(toChild), 0);
    const std::size_t size = 64U << 20U;
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        ::close(toChild[1]);  // else its read below never sees the parent's end
        ::close(toParent[0]);
        void* block =
            mmap(nullptr, size, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
        if (block != MAP_FAILED) {
            std::memset(block, 1, size);
            munmap(block, size);
        }
        char byte = block == MAP_FAILED ? 'f' : 't';
        (void)::write(toParent[1], &byte, 1);
        (void)::read(toChild[0], &byte, 1);  // until the parent closes its end
        ::_exit(0);
    }
    ::close(toParent[1]);
    ::close(toChild[0]);
    char byte = 0;
    ASSERT_EQ(::read(toParent[0], &byte, 1), 1);
    EXPECT_EQ(byte, 't');
    const auto resident = vv::residentKiB(child);
    const auto peak = vv::peakResidentKiB(child);
    ASSERT_TRUE(resident.has_value());
    ASSERT_TRUE(peak.has_value());
    EXPECT_GE(*peak, *resident + std::uint64_t{60} * 1024)
        << "the child's peak holds its 64 MiB block";
    ASSERT_TRUE(vv::resetPeakResident(child));
    EXPECT_LT(*vv::peakResidentKiB(child), *resident + std::uint64_t{30} * 1024);
    ::close(toChild[1]);
    ::close(toParent[0]);
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    EXPECT_FALSE(vv::residentKiB(child).has_value()) << "no such process any more";
}

}  // namespace
