// SPDX-License-Identifier: GPL-3.0-or-later
// The fast VSS solver's counters and test hooks (FastCounters.h, FastStats.h).
#include "FastCounters.h"

#include "FastStats.h"

namespace vv::vss::detail::fast {

AtomicStats& stats() {
    static AtomicStats s;
    return s;
}

// NOLINTBEGIN(cppcoreguidelines-avoid-non-const-global-variables): the hooks (FastCounters.h)
std::atomic<double> gBudgetScale{1.0};
std::atomic<bool> gCoarseBoxes{true};
std::atomic<bool> gNearBoxes{true};
std::atomic<bool> gNearSplit{false};
std::atomic<bool> gBandBoxes{true};
std::atomic<double> gBandBoundScale{1.0};
std::atomic<double> gNearSplitBudgetScale{1.0};
std::atomic<bool> gDistanceTable{true};
// NOLINTEND(cppcoreguidelines-avoid-non-const-global-variables)

}  // namespace vv::vss::detail::fast

namespace vv::vss::detail {

FastSolverStats fastSolverStats() {
    const fast::AtomicStats& s = fast::stats();
    FastSolverStats r;
    r.pixels = s.pixels.load();
    r.fallbackPixels = s.fallbackPixels.load();
    r.leaves = s.leaves.load();
    r.nearPairs = s.nearPairs.load();
    r.m2l = s.m2l.load();
    r.dropped = s.dropped.load();
    r.perPixelLeaves = s.perPixelLeaves.load();
    r.exactTiles = s.exactTiles.load();
    r.coarseBoxes = s.coarseBoxes.load();
    r.coarsePixels = s.coarsePixels.load();
    r.nearLeaves = s.nearLeaves.load();
    r.nearLeafPixels = s.nearLeafPixels.load();
    r.tableLeaves = s.tableLeaves.load();
    r.tablePairs = s.tablePairs.load();
    r.nearBoxes = s.nearBoxes.load();
    r.nearBoxPixels = s.nearBoxPixels.load();
    r.nearBoxPoints = s.nearBoxPoints.load();
    r.bandBoxes = s.bandBoxes.load();
    r.bandBoxPixels = s.bandBoxPixels.load();
    r.bandExactPixels = s.bandExactPixels.load();
    r.bandSamples = s.bandSamples.load();
    return r;
}

void resetFastSolverStats() {
    fast::AtomicStats& s = fast::stats();
    s.pixels = 0;
    s.fallbackPixels = 0;
    s.leaves = 0;
    s.nearPairs = 0;
    s.m2l = 0;
    s.dropped = 0;
    s.perPixelLeaves = 0;
    s.exactTiles = 0;
    s.coarseBoxes = 0;
    s.coarsePixels = 0;
    s.nearLeaves = 0;
    s.nearLeafPixels = 0;
    s.tableLeaves = 0;
    s.tablePairs = 0;
    s.nearBoxes = 0;
    s.nearBoxPixels = 0;
    s.nearBoxPoints = 0;
    s.bandBoxes = 0;
    s.bandBoxPixels = 0;
    s.bandExactPixels = 0;
    s.bandSamples = 0;
}

void setFastSolverBudgetScaleForTesting(double scale) {
    fast::gBudgetScale = scale;
}

void setFastSolverCoarseBoxesForTesting(bool on) {
    fast::gCoarseBoxes = on;
}

void setFastSolverNearSplitBudgetScaleForTesting(double scale) {
    fast::gNearSplitBudgetScale = scale;
}

void setFastSolverNearSplitForTesting(bool on) {
    fast::gNearSplit = on;
}

void setFastSolverNearBoxesForTesting(bool on) {
    fast::gNearBoxes = on;
}

void setFastSolverBandBoxesForTesting(bool on) {
    fast::gBandBoxes = on;
}

void setFastSolverDistanceTableForTesting(bool on) {
    fast::gDistanceTable = on;
}

void setFastSolverBandBoundScaleForTesting(double scale) {
    fast::gBandBoundScale = scale;
}

}  // namespace vv::vss::detail
