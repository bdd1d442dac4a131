// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>
#include <memory>
#include <stop_token>
#include <string>
#include <string_view>
#include <vector>

#include "vv/core/Image.h"

namespace vv::vss {

/// A contour pixel of a void region: a vessel pixel 8-adjacent to the region,
/// at pixel centre (x, y), with its normalised depth z in [0, 1].
struct ContourPoint {
    int x = 0;
    int y = 0;
    float z = 0.0F;
};

/// One void region: a 4-connected component of background pixels.
struct VoidRegion {
    std::int32_t id = 0;                ///< its value in the label image
    std::vector<ContourPoint> contour;  ///< may be empty (no vessel at all: no VSS)
    std::int64_t pixelCount = 0;        ///< number of background pixels in the region
    int x0 = 0;                         ///< bounding box of its pixels: [x0, x1) × [y0, y1)
    int y0 = 0;
    int x1 = 0;
    int y1 = 0;
};

/// Label image value of vessel pixels (every void pixel has its region id >= 0).
inline constexpr std::int32_t kVesselLabel = -1;

enum class SolverKind {
    Reference,  ///< double precision, every contour pixel: the exact answer
    Brute,      ///< float, vectorisable, threaded, every contour pixel
    Step,       ///< the paper's variant: every k-th contour pixel along the borders
    Fast,       ///< the product default: accelerated, meets a tolerance
};

// How the direct solvers work (Solvers.cpp):
// - Reference: per void pixel, dmin^2 = the nearest squared contour distance,
//   then w_i = exp(p/2 * log(dmin^2 / d_i^2)) in double (largest weight 1).
//   Threaded over the rows of a region.
// - Brute: the same in float, vectorised (AVX2 + FMA clone and a baseline
//   x86-64 clone, chosen at load time), threaded over rows. Powers p = 2^k,
//   k = -2..6, use squarings / square roots, any other p a polynomial
//   log2 / exp2; measured within 1e-6 of Reference (max abs error of z').
// - Step: Brute over every k-th pixel of VoidRegion::contour taken in
//   border-following order, starting with the first (so a region always keeps
//   at least one): the contour is first ordered into chains of 8-connected
//   pixels walked along the silhouettes (a chain starts at the first unvisited
//   pixel in row-major order and steps to an unvisited 8-neighbour, preferring
//   the one with the fewest unvisited neighbours, then 4-neighbours; stuck, it
//   is extended backwards from its start, then the next chain starts), like the
//   paper's Suzuki contours, so that each silhouette is sampled evenly along its
//   length. (The list's own row-major order interleaves the walls of different
//   vessels row by row, and every k-th of it can drop a whole wall.) k = 1 uses
//   the list order and is Brute. errorBound() is 0 for k = 1, NaN else.
// Pixels within the region's bounding box are visited row by row; a region
// with little work (pixels x contour pixels) is solved on the calling thread.

/// Parses "reference", "brute", "step", "fast"; throws InvalidArgumentError otherwise.
[[nodiscard]] SolverKind parseSolverKind(std::string_view name);
[[nodiscard]] std::string_view toString(SolverKind kind) noexcept;

struct SolverOptions {
    SolverKind kind = SolverKind::Fast;
    double p = 2.0;                  ///< IDW power, 0.25 <= p <= 64 (wider is allowed but untested)
    int step = 3;                    ///< Step solver: every k-th contour pixel, k >= 1
    double tolerance = 0.5 / 255.0;  ///< Fast solver: max abs error of z' (normalised depth)

    bool operator==(const SolverOptions&) const = default;
};

/// Interpolates z' (VSS.md, "Interpolation") for the void pixels of regions.
/// Implementations must keep the properties of VSS.md: bounded by the
/// region's contour depths, no NaN / Inf for any p in range, weights scaled
/// by the nearest contour distance (computed in log space), invariance.
class Solver {
  public:
    Solver() = default;
    Solver(const Solver&) = delete;
    Solver& operator=(const Solver&) = delete;
    Solver(Solver&&) = delete;
    Solver& operator=(Solver&&) = delete;
    virtual ~Solver() = default;

    /// Writes z' into out(x, y) for every pixel with labels(x, y) == region.id
    /// and leaves every other pixel of `out` untouched. A region with an empty
    /// contour gets NaN (no VSS). May run in parallel internally (vv::parallelFor)
    /// and may be called concurrently for different regions.
    /// Throws CancelledError when `stop` is requested.
    virtual void solveRegion(ImageView<const std::int32_t> labels, const VoidRegion& region,
                             ImageView<float> out, const std::stop_token& stop) const = 0;

    /// An upper bound of the max abs error of z' this solver guarantees
    /// (0 for reference / brute up to round-off; the tolerance for fast;
    /// NaN when there is no guarantee, as for step).
    [[nodiscard]] virtual double errorBound() const noexcept = 0;
};

/// Makes the solver selected by `options`. Throws InvalidArgumentError for
/// p <= 0 or non-finite, step < 1, tolerance <= 0 or non-finite.
[[nodiscard]] std::unique_ptr<Solver> makeSolver(const SolverOptions& options);

}  // namespace vv::vss
