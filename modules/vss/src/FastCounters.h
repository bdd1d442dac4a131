// SPDX-License-Identifier: GPL-3.0-or-later
// Private to the fast VSS solver: its shared counters (FastStats.h reads and
// resets them) and the test / benchmark hooks' settings, read by each solver
// when it is created.
#pragma once

#include <atomic>
#include <cstdint>

namespace vv::vss::detail::fast {

struct AtomicStats {
    std::atomic<std::int64_t> pixels{0}, fallbackPixels{0}, leaves{0}, nearPairs{0}, m2l{0},
        dropped{0}, perPixelLeaves{0}, exactTiles{0}, coarseBoxes{0}, coarsePixels{0},
        nearLeaves{0}, nearLeafPixels{0}, nearBoxes{0}, nearBoxPixels{0}, nearBoxPoints{0},
        bandBoxes{0}, bandBoxPixels{0}, bandExactPixels{0}, bandSamples{0}, tableLeaves{0},
        tablePairs{0};
};

/// The counters of every solve since the last reset.
AtomicStats& stats();

// Test / benchmark hooks (FastStats.h): set by tests and benchmarks, read
// when a solver is created.
// NOLINTBEGIN(cppcoreguidelines-avoid-non-const-global-variables)
extern std::atomic<double> gBudgetScale;
extern std::atomic<bool> gCoarseBoxes;
extern std::atomic<bool> gNearBoxes;
extern std::atomic<bool> gNearSplit;
extern std::atomic<bool> gBandBoxes;
extern std::atomic<double> gBandBoundScale;
extern std::atomic<double> gNearSplitBudgetScale;
extern std::atomic<bool> gDistanceTable;
// NOLINTEND(cppcoreguidelines-avoid-non-const-global-variables)

}  // namespace vv::vss::detail::fast
