// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/core/Parallel.h"

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <exception>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "vv/core/Error.h"

namespace vv {

int workerCount() {
    if (const char* env = std::getenv("VV_THREADS")) {
        try {
            const int n = std::stoi(env);
            if (n >= 1) {
                return n;
            }
        } catch (const std::exception&) {
            // fall through to the hardware count
        }
    }
    return static_cast<int>(std::max(1U, std::thread::hardware_concurrency()));
}

void parallelFor(long begin, long end, long grain, const std::function<void(long, long)>& body,
                 const std::stop_token& stop) {
    if (end <= begin) {
        return;
    }
    grain = std::max(1L, grain);
    const long count = end - begin;
    const long chunks = (count + grain - 1) / grain;
    const int threads = static_cast<int>(std::min<long>(workerCount(), chunks));

    std::atomic<long> next{0};
    std::exception_ptr firstError;
    std::mutex errorMutex;
    std::atomic<bool> failed{false};
    std::atomic<bool> cancelled{false};

    auto worker = [&] {
        for (;;) {
            if (failed.load(std::memory_order_relaxed)) {
                return;
            }
            if (stop.stop_requested()) {
                cancelled = true;
                return;
            }
            const long chunk = next.fetch_add(1, std::memory_order_relaxed);
            if (chunk >= chunks) {
                return;
            }
            const long b = begin + chunk * grain;
            const long e = std::min(end, b + grain);
            try {
                body(b, e);
            } catch (...) {
                const std::scoped_lock lock(errorMutex);
                if (!firstError) {
                    firstError = std::current_exception();
                }
                failed = true;
                return;
            }
        }
    };

    std::vector<std::jthread> pool;
    pool.reserve(static_cast<std::size_t>(threads > 0 ? threads - 1 : 0));
    for (int t = 1; t < threads; ++t) {
        pool.emplace_back(worker);
    }
    worker();
    pool.clear();  // joins

    if (firstError) {
        std::rethrow_exception(firstError);
    }
    if (cancelled) {
        throw CancelledError();
    }
}

void parallelForTiles(int width, int height, int tileSize,
                      const std::function<void(const Tile&)>& body, const std::stop_token& stop) {
    if (width <= 0 || height <= 0) {
        return;
    }
    if (tileSize <= 0) {
        throw InvalidArgumentError("tile size must be positive");
    }
    const long tilesX = (width + tileSize - 1) / tileSize;
    const long tilesY = (height + tileSize - 1) / tileSize;
    parallelFor(
        0, tilesX * tilesY, 1,
        [&](long b, long e) {
            for (long i = b; i < e; ++i) {
                Tile t;
                t.x0 = static_cast<int>(i % tilesX) * tileSize;
                t.y0 = static_cast<int>(i / tilesX) * tileSize;
                t.x1 = std::min(width, t.x0 + tileSize);
                t.y1 = std::min(height, t.y0 + tileSize);
                body(t);
            }
        },
        stop);
}

}  // namespace vv
