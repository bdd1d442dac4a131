// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>
#include <stop_token>
#include <vector>

#include "vv/core/Image.h"
#include "vv/vss/DepthNormalization.h"
#include "vv/vss/Solver.h"

namespace vv::vss {

struct VssOptions {
    SolverOptions solver;
    DepthRange range;      ///< visible min/max (default) or a fixed range
    std::stop_token stop;  ///< requested -> CancelledError
};

struct VssStatistics {
    std::size_t regionCount = 0;
    std::vector<std::int64_t> contourPixels;  ///< per region, indexed by region id
    std::int64_t maxContourPixels = 0;        ///< over all regions (0 without regions)
    std::int64_t voidPixels = 0;              ///< background pixels (all regions)
    std::size_t reusedRegions = 0;            ///< regions taken from `previous` (solve)
    std::int64_t reusedPixels = 0;            ///< their void pixels
    double normalizeMs = 0.0;                 ///< wall time per stage
    double regionsMs = 0.0;
    double interpolateMs = 0.0;
};

struct VssResult {
    /// z on vessel pixels, z' on void pixels, NaN where no VSS exists (a region
    /// without contour, i.e. an image without any vessel pixel).
    Image<float> height;
    Image<std::int32_t> labels;       ///< kVesselLabel on vessel pixels, else region id
    std::vector<VoidRegion> regions;  ///< regions[i].id == i, contours with z
    double dmin = 0.0;                ///< the depth range in scene units (NaN: no vessel pixel)
    double dmax = 0.0;
    bool flat = false;        ///< flat range: every z is 0
    double errorBound = 0.0;  ///< the solver's errorBound()
    VssStatistics stats;
};

/// A finished solve (its VssResult's height, labels and regions) that the
/// next solve may take whole regions from. It must come from a solver with
/// the same options (kind, p, step, tolerance) as the next one; a solve of
/// another size is ignored.
struct PreviousSolve {
    ImageView<const float> height;
    ImageView<const std::int32_t> labels;
    const std::vector<VoidRegion>* regions = nullptr;
};

/// The whole pipeline: normalise the depth (normalizeDepth: mask nonzero =
/// vessel, non-finite depth = background), find the void regions and their
/// contours (findVoidRegions), interpolate every region with `solver`: the
/// regions largest first, one per thread at a time, each solve parallel inside
/// (threads that run out of regions join the solves still running).
/// With `previous`, a region with the same pixels and the same contour (the
/// same positions and normalised depths, bit for bit) as one of the previous
/// solve's takes that region's z' instead of being solved: the solver's
/// result for it would be the same, and a view whose depth changed in one
/// place (an object hidden, made translucent or shown again) re-solves only
/// the regions next to that place (stats.reusedRegions, reusedPixels).
/// A full mask gives no region and no error; an empty mask gives NaN everywhere.
/// Throws InvalidArgumentError (sizes differ, bad fixed range), CancelledError
/// when `stop` is requested.
[[nodiscard]] VssResult solve(ImageView<const float> depth, ImageView<const std::uint8_t> mask,
                              const Solver& solver, const DepthRange& range = {},
                              const std::stop_token& stop = {},
                              const PreviousSolve* previous = nullptr);

/// As above with the solver made by makeSolver(options.solver) (which throws
/// InvalidArgumentError for bad solver options).
[[nodiscard]] VssResult solve(ImageView<const float> depth, ImageView<const std::uint8_t> mask,
                              const VssOptions& options);

}  // namespace vv::vss
