// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
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

/// Sets VV_THREADS for the life of the object.
class ThreadsEnv {
  public:
    explicit ThreadsEnv(const char* n) { ::setenv("VV_THREADS", n, 1); }
    ThreadsEnv(const ThreadsEnv&) = delete;
    ThreadsEnv& operator=(const ThreadsEnv&) = delete;
    ThreadsEnv(ThreadsEnv&&) = delete;
    ThreadsEnv& operator=(ThreadsEnv&&) = delete;
    ~ThreadsEnv() { ::unsetenv("VV_THREADS"); }
};

long kernelThreadId() {
    return ::gettid();
}

/// Runs two chunks that each wait (polling) until both have started, so two
/// threads run them; returns the kernel id of the one that is not the caller.
long helperOfTwoChunks() {
    std::atomic<int> started{0};
    std::atomic<long> helper{0};
    const long caller = kernelThreadId();
    vv::parallelFor(0, 2, 1, [&](long, long) {
        ++started;
        while (started.load() < 2) {
            std::this_thread::yield();
        }
        if (kernelThreadId() != caller) {
            helper = kernelThreadId();
        }
    });
    return helper.load();
}

TEST(Parallel, CallsShareTheSameThreads) {
    // a thread per call cost ~40 us, several times per frame: the helpers
    // stay (kernel thread ids are not reused soon, unlike std::thread::id)
    const ThreadsEnv two("2");
    const long first = helperOfTwoChunks();
    ASSERT_NE(first, 0);
    for (int i = 0; i < 20; ++i) {
        EXPECT_EQ(helperOfTwoChunks(), first);
    }
}

TEST(Parallel, NestedCallsFinishAndCoverEveryIndex) {
    const ThreadsEnv two("2");
    constexpr long kOuter = 16;
    constexpr long kInner = 101;
    std::vector<std::atomic<int>> hits(static_cast<std::size_t>(kOuter * kInner));
    std::set<long> threads;
    std::mutex threadsMutex;
    vv::parallelFor(0, kOuter, 1, [&](long b, long e) {
        for (long o = b; o < e; ++o) {
            vv::parallelFor(0, kInner, 3, [&](long ib, long ie) {
                {
                    const std::scoped_lock lock(threadsMutex);
                    threads.insert(kernelThreadId());
                }
                for (long i = ib; i < ie; ++i) {
                    hits[static_cast<std::size_t>(o * kInner + i)]++;
                }
            });
        }
    });
    for (const auto& h : hits) {
        ASSERT_EQ(h.load(), 1);
    }
    EXPECT_LE(threads.size(), 2U);  // nested calls add no threads beyond the workers
}

TEST(Parallel, ErrorInOneCallLeavesTheNextIntact) {
    const ThreadsEnv two("2");
    EXPECT_THROW(vv::parallelFor(0, 64, 1,
                                 [](long b, long) {
                                     if (b % 2 == 1) {
                                         throw std::runtime_error("odd");
                                     }
                                 }),
                 std::runtime_error);
    std::atomic<long> sum{0};
    vv::parallelFor(0, 1000, 7, [&](long b, long e) {
        for (long i = b; i < e; ++i) {
            sum += i;
        }
    });
    EXPECT_EQ(sum.load(), 999L * 1000L / 2L);
}

TEST(Parallel, WorkerCountHonoursEnvironment) {
    ::setenv("VV_THREADS", "3", 1);
    EXPECT_EQ(vv::workerCount(), 3);
    ::setenv("VV_THREADS", "junk", 1);
    EXPECT_GE(vv::workerCount(), 1);
    ::unsetenv("VV_THREADS");
}

}  // namespace
