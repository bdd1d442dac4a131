// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <functional>
#include <stop_token>

namespace vv {

/// Number of worker threads parallelFor uses: hardware concurrency, or the
/// value of the environment variable VV_THREADS when set (>= 1).
[[nodiscard]] int workerCount();

/// Calls body(begin_chunk, end_chunk) over [begin, end) split into chunks of at
/// least `grain` indices, on up to workerCount() threads: the caller's thread
/// and threads of a pool that lives as long as the process (started when first
/// needed). Calls may nest (a body may call parallelFor): the caller always
/// takes chunks itself, so a call finishes even when every pool thread is busy.
/// Returns when every chunk is done. The first exception thrown by
/// a body is rethrown here after all threads have stopped. If `stop` is
/// requested, chunks not yet started are skipped and CancelledError is thrown.
void parallelFor(long begin, long end, long grain, const std::function<void(long, long)>& body,
                 const std::stop_token& stop = {});

/// A tile of an image: [x0, x1) × [y0, y1).
struct Tile {
    int x0 = 0;
    int y0 = 0;
    int x1 = 0;
    int y1 = 0;
};

/// Calls body(tile) for every tile of a width × height image cut into tiles of
/// tileSize × tileSize (edge tiles smaller), in parallel as parallelFor.
void parallelForTiles(int width, int height, int tileSize,
                      const std::function<void(const Tile&)>& body,
                      const std::stop_token& stop = {});

}  // namespace vv
