// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <vector>

#include "vv/core/Error.h"
#include "vv/core/Parallel.h"

namespace {

TEST(Parallel, EveryIndexExactlyOnce) {
    std::vector<std::atomic<int>> hits(10007);
    vv::parallelFor(0, 10007, 13, [&](long b, long e) {
        for (long i = b; i < e; ++i) {
            hits[static_cast<std::size_t>(i)]++;
        }
    });
    for (const auto& h : hits) {
        ASSERT_EQ(h.load(), 1);
    }
}

TEST(Parallel, EmptyAndReversedRangesDoNothing) {
    int calls = 0;
    vv::parallelFor(5, 5, 1, [&](long, long) { ++calls; });
    vv::parallelFor(9, 2, 1, [&](long, long) { ++calls; });
    EXPECT_EQ(calls, 0);
}

TEST(Parallel, ExceptionIsRethrownAfterJoin) {
    EXPECT_THROW(vv::parallelFor(0, 1000, 1,
                                 [](long b, long) {
                                     if (b == 500) {
                                         throw std::runtime_error("boom");
                                     }
                                 }),
                 std::runtime_error);
}

TEST(Parallel, StopRequestedThrowsCancelled) {
    std::stop_source stop;
    stop.request_stop();
    int calls = 0;
    EXPECT_THROW(vv::parallelFor(
                     0, 100, 1, [&](long, long) { ++calls; }, stop.get_token()),
                 vv::CancelledError);
    EXPECT_EQ(calls, 0);
}

TEST(Parallel, TilesCoverImageOnce) {
    const int w = 37;
    const int h = 23;
    std::vector<std::atomic<int>> hits(static_cast<std::size_t>(w * h));
    vv::parallelForTiles(w, h, 8, [&](const vv::Tile& t) {
        EXPECT_LE(t.x1 - t.x0, 8);
        EXPECT_LE(t.y1 - t.y0, 8);
        for (int y = t.y0; y < t.y1; ++y) {
            for (int x = t.x0; x < t.x1; ++x) {
                hits[static_cast<std::size_t>(y * w + x)]++;
            }
        }
    });
    for (const auto& hit : hits) {
        ASSERT_EQ(hit.load(), 1);
    }
    EXPECT_THROW(vv::parallelForTiles(4, 4, 0, [](const vv::Tile&) {}), vv::InvalidArgumentError);
}

TEST(Parallel, WorkerCountHonoursEnvironment) {
    ::setenv("VV_THREADS", "3", 1);
    EXPECT_EQ(vv::workerCount(), 3);
    ::setenv("VV_THREADS", "junk", 1);
    EXPECT_GE(vv::workerCount(), 1);
    ::unsetenv("VV_THREADS");
}

}  // namespace
