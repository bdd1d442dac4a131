// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/vss/Vss.h"

#include <algorithm>
#include <chrono>
#include <numeric>
#include <optional>
#include <vector>

#include "RegionReuse.h"
#include "vv/core/Error.h"
#include "vv/core/Parallel.h"
#include "vv/vss/VoidRegions.h"

namespace vv::vss {

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

void throwIfStopped(const std::stop_token& stop) {
    if (stop.stop_requested()) {
        throw CancelledError();
    }
}

}  // namespace

VssResult solve(ImageView<const float> depth, ImageView<const std::uint8_t> mask,
                const Solver& solver, const DepthRange& range, const std::stop_token& stop,
                const PreviousSolve* previous) {
    VssResult result;
    throwIfStopped(stop);

    auto start = Clock::now();
    NormalizedDepth normalized = normalizeDepth(depth, mask, range);
    result.dmin = normalized.dmin;
    result.dmax = normalized.dmax;
    result.flat = normalized.flat;
    result.stats.normalizeMs = msSince(start);
    throwIfStopped(stop);

    start = Clock::now();
    VoidRegionSet regions = findVoidRegions(normalized.vessel.view(), normalized.z.view());
    normalized.vessel = Image<std::uint8_t>();
    result.stats.regionsMs = msSince(start);
    throwIfStopped(stop);

    start = Clock::now();
    // z on vessel pixels (NaN elsewhere until solved).
    result.height = std::move(normalized.z);
    result.labels = std::move(regions.labels);
    result.regions = std::move(regions.regions);
    result.errorBound = solver.errorBound();

    std::vector<std::size_t> order(result.regions.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return result.regions[a].pixelCount > result.regions[b].pixelCount;
    });
    const ImageView<const std::int32_t> labels = result.labels.view();
    const ImageView<float> out = result.height.view();
    // Largest first, a region per thread at a time. A region's own parallel
    // work (the solver's parallelFor) is joined by the threads that run out of
    // regions (parallelFor's pool takes nested calls), so one large region
    // and several middle-sized ones keep every core busy to the end.
    std::optional<detail::PreviousRegions> before;
    if (previous != nullptr && previous->regions != nullptr) {
        before.emplace(*previous);
    }
    std::vector<char> reused(result.regions.size(), 0);
    parallelFor(
        0, static_cast<long>(order.size()), 1,
        [&](long b, long e) {
            for (long i = b; i < e; ++i) {
                const std::size_t k = order[static_cast<std::size_t>(i)];
                const VoidRegion& region = result.regions[k];
                if (before && before->copyIfSame(labels, region, out)) {
                    reused[k] = 1;
                    continue;
                }
                solver.solveRegion(labels, region, out, stop);
            }
        },
        stop);
    result.stats.interpolateMs = msSince(start);
    throwIfStopped(stop);

    result.stats.regionCount = result.regions.size();
    result.stats.contourPixels.reserve(result.regions.size());
    for (const VoidRegion& r : result.regions) {
        const auto n = static_cast<std::int64_t>(r.contour.size());
        result.stats.contourPixels.push_back(n);
        result.stats.maxContourPixels = std::max(result.stats.maxContourPixels, n);
        result.stats.voidPixels += r.pixelCount;
        if (reused[static_cast<std::size_t>(r.id)] != 0) {
            ++result.stats.reusedRegions;
            result.stats.reusedPixels += r.pixelCount;
        }
    }
    return result;
}

VssResult solve(ImageView<const float> depth, ImageView<const std::uint8_t> mask,
                const VssOptions& options) {
    const auto solver = makeSolver(options.solver);
    return solve(depth, mask, *solver, options.range, options.stop);
}

}  // namespace vv::vss
