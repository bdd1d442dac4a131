// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "vv/core/Image.h"
#include "vv/core/PixelAllocator.h"

namespace {

// Kilobytes of AnonHugePages in the mapping of /proc/self/smaps that holds p
// (-1 when the file or the mapping is not found, e.g. not Linux).
long hugeKbAt(const void* p) {
    std::ifstream smaps("/proc/self/smaps");
    if (!smaps) {
        return -1;
    }
    const auto addr = reinterpret_cast<std::uintptr_t>(p);
    std::string line;
    bool inside = false;
    bool found = false;
    while (std::getline(smaps, line)) {
        std::uintptr_t lo = 0;
        std::uintptr_t hi = 0;
        char dash = 0;
        std::istringstream head(line);
        if (head >> std::hex >> lo >> dash >> hi && dash == '-') {
            inside = addr >= lo && addr < hi;
            found = found || inside;
            continue;
        }
        if (inside && line.rfind("AnonHugePages:", 0) == 0) {
            return std::stol(line.substr(14));
        }
    }
    return found ? 0 : -1;
}

// The kernel's count of huge page faults that fell back to small pages
// (/proc/vmstat; -1 when not there).
long thpFallbacks() {
    std::ifstream vmstat("/proc/vmstat");
    std::string key;
    long value = 0;
    while (vmstat >> key >> value) {
        if (key == "thp_fault_fallback") {
            return value;
        }
    }
    return -1;
}

TEST(PixelAllocator, LargeImagesAreHugePageAlignedAndKeepTheirValues) {
    // a 3840x2160 float image: 33 MB
    vv::Image<float> big(3840, 2160, 0.25F);
#if defined(__linux__)
    // on Linux the buffer is 2 MiB aligned (the huge page path)
    const auto addr = reinterpret_cast<std::uintptr_t>(big.data());
    EXPECT_EQ(addr % vv::PixelAllocator<float>::kHugePage, 0U);
#endif
    EXPECT_FLOAT_EQ(big(0, 0), 0.25F);
    EXPECT_FLOAT_EQ(big(3839, 2159), 0.25F);
    big(17, 1000) = 2.0F;
    const vv::Image<float> copy = big;  // copies go through the allocator too
    EXPECT_FLOAT_EQ(copy(17, 1000), 2.0F);
#if defined(__linux__)
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(copy.data()) % vv::PixelAllocator<float>::kHugePage,
              0U);
#endif
}

TEST(PixelAllocator, LargeImagesGetHugePagesWhenTheKernelGivesThem) {
    std::ifstream mode("/sys/kernel/mm/transparent_hugepage/enabled");
    std::string modes;
    std::getline(mode, modes);
    if (modes.find("[never]") != std::string::npos || modes.empty()) {
        GTEST_SKIP() << "transparent huge pages are off here";
    }
    const long fallbacksBefore = thpFallbacks();
    const vv::Image<float> big(3840, 2160, 1.0F);  // touched by the fill
    const long kb = hugeKbAt(big.data());
    if (kb < 0) {
        GTEST_SKIP() << "no /proc/self/smaps";
    }
    if (kb < 16L * 1024L && thpFallbacks() > fallbacksBefore) {
        GTEST_SKIP() << "the kernel had no free huge pages (it fell back to small ones)";
    }
    // madvise mode: only the hinted buffer gets them; at least half of 33 MB
    EXPECT_GE(kb, 16L * 1024L) << "THP mode: " << modes;
}

TEST(PixelAllocator, TheImagesOfA1280x720SolveTakeThePooledPath) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    // a solve at 1280x720 makes float, label and mask images each time; from
    // malloc's fresh mappings they cost ~1 800 page faults a solve
    const vv::Image<float> z(1280, 720, 0.5F);
    const vv::Image<std::uint8_t> mask(1280, 720, 1);
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(z.data()) % vv::PixelAllocator<float>::kHugePage,
              0U);
    EXPECT_EQ(
        reinterpret_cast<std::uintptr_t>(mask.data()) % vv::PixelAllocator<std::uint8_t>::kHugePage,
        0U);
    EXPECT_FLOAT_EQ(z(1279, 719), 0.5F);
    EXPECT_EQ(mask(1279, 719), 1);
#else
    GTEST_SKIP() << "the pool serves the huge-page path (Linux) only";
#endif
}

TEST(PixelAllocator, SmallImagesStayOrdinary) {
    const vv::Image<std::uint8_t> small(64, 64, 7);
    EXPECT_EQ(small(63, 63), 7);
    vv::PixelAllocator<double> a;
    double* p = a.allocate(10);
    p[9] = 1.0;
    a.deallocate(p, 10);
    EXPECT_THROW((void)a.allocate(static_cast<std::size_t>(-1) / 4), std::bad_alloc);
}

TEST(PixelAllocator, FreedLargeBuffersAreReusedAndNewImagesStillInitialised) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    const void* first = nullptr;
    {
        vv::Image<float> a(3840, 2160, 2.0F);
        first = a.data();
    }
    EXPECT_GE(vv::LargeBufferPool::instance().heldBytes(), std::size_t{3840} * 2160 * 4);
    // the same rounded size (int32 and float have the same bytes): the kept buffer
    const vv::Image<std::int32_t> b(3840, 2160, 0);
    EXPECT_EQ(static_cast<const void*>(b.data()), first);
    // its pixels are those of the new image, not the left-over 2.0F
    for (int y = 0; y < b.height(); y += 7) {
        for (int x = 0; x < b.width(); x += 5) {
            ASSERT_EQ(b(x, y), 0) << x << "," << y;
        }
    }
    EXPECT_EQ(b(3839, 2159), 0);
#else
    GTEST_SKIP() << "the pool serves the huge-page path (Linux) only";
#endif
}

TEST(PixelAllocator, ThePoolKeepsAtMostItsCap) {
    {
        std::vector<vv::Image<float>> many;
        many.reserve(12);
        for (int i = 0; i < 12; ++i) {
            many.emplace_back(3840, 2160, static_cast<float>(i));
        }
        for (int i = 0; i < 12; ++i) {
            EXPECT_FLOAT_EQ(many[static_cast<std::size_t>(i)](100, 100), static_cast<float>(i));
        }
    }
    EXPECT_LE(vv::LargeBufferPool::instance().heldBytes(), vv::LargeBufferPool::kMaxBytes);
    EXPECT_GT(vv::LargeBufferPool::instance().heldBytes(), 0U);
}

}  // namespace
