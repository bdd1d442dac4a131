// SPDX-License-Identifier: GPL-3.0-or-later
// The solver factory and the three direct solvers: reference (double), brute
// (float, vectorised) and step (brute over every k-th contour pixel, in
// border-following order).
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "ContourOrder.h"
#include "FastMath.h"
#include "FastSolver.h"
#include "SolverCommon.h"
#include "vv/core/Error.h"
#include "vv/core/Parallel.h"
#include "vv/vss/Solver.h"

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
// An AVX2 + FMA clone next to the baseline x86-64 one, picked at load time.
#define VV_VSS_CLONES __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#define VV_VSS_CLONES
#endif

namespace vv::vss {

namespace detail {

void forEachRegionRow(ImageView<const std::int32_t> labels, const VoidRegion& region,
                      double pairsPerPixel, const std::stop_token& stop,
                      const std::function<void(int y)>& row) {
    if (region.x0 < 0 || region.y0 < 0 || region.x1 > labels.width() ||
        region.y1 > labels.height() || region.x0 > region.x1 || region.y0 > region.y1) {
        throw InvalidArgumentError("solveRegion: the bounding box of region " +
                                   std::to_string(region.id) + " is outside the label image");
    }
    const double work = static_cast<double>(region.pixelCount) * std::max(1.0, pairsPerPixel);
    if (work < kSerialPairs || workerCount() == 1) {
        for (int y = region.y0; y < region.y1; ++y) {
            if (stop.stop_requested()) {
                throw CancelledError();
            }
            row(y);
        }
        return;
    }
    parallelFor(
        region.y0, region.y1, 1,
        [&](long b, long e) {
            for (long y = b; y < e; ++y) {
                row(static_cast<int>(y));
            }
        },
        stop);
}

void fillRegion(ImageView<const std::int32_t> labels, const VoidRegion& region,
                ImageView<float> out, float value, const std::stop_token& stop) {
    forEachRegionRow(labels, region, 1.0, stop, [&](int y) {
        const std::int32_t* l = labels.row(y);
        float* o = out.row(y);
        for (int x = region.x0; x < region.x1; ++x) {
            if (l[x] == region.id) {
                o[x] = value;
            }
        }
    });
}

}  // namespace detail

namespace {

using detail::fillRegion;
using detail::forEachRegionRow;

void checkSizes(ImageView<const std::int32_t> labels, ImageView<float> out) {
    if (labels.width() != out.width() || labels.height() != out.height()) {
        throw InvalidArgumentError("solveRegion: the label image and the output differ in size");
    }
}

// ---------------------------------------------------------------------------
// reference: double precision, every contour pixel, w_i = (dmin / d_i)^p
// computed as exp(p/2 * log(dmin^2 / d_i^2)) so the largest weight is 1.

class ReferenceSolver final : public Solver {
  public:
    explicit ReferenceSolver(double p) : halfP_(0.5 * p) {}

    void solveRegion(ImageView<const std::int32_t> labels, const VoidRegion& region,
                     ImageView<float> out, const std::stop_token& stop) const override {
        checkSizes(labels, out);
        const auto& c = region.contour;
        if (c.empty()) {
            fillRegion(labels, region, out, std::numeric_limits<float>::quiet_NaN(), stop);
            return;
        }
        const std::size_t n = c.size();
        forEachRegionRow(labels, region, static_cast<double>(n), stop, [&](int y) {
            const std::int32_t* l = labels.row(y);
            float* o = out.row(y);
            for (int x = region.x0; x < region.x1; ++x) {
                if (l[x] != region.id) {
                    continue;
                }
                double dmin2 = std::numeric_limits<double>::infinity();
                for (const ContourPoint& q : c) {
                    const double dx = static_cast<double>(q.x) - x;
                    const double dy = static_cast<double>(q.y) - y;
                    dmin2 = std::min(dmin2, dx * dx + dy * dy);
                }
                double sw = 0.0;
                double swz = 0.0;
                if (dmin2 == 0.0) {
                    // Only with a hand-made contour: the coincident points decide.
                    for (const ContourPoint& q : c) {
                        if (q.x == x && q.y == y) {
                            sw += 1.0;
                            swz += q.z;
                        }
                    }
                } else {
                    for (const ContourPoint& q : c) {
                        const double dx = static_cast<double>(q.x) - x;
                        const double dy = static_cast<double>(q.y) - y;
                        const double w = std::exp(halfP_ * std::log(dmin2 / (dx * dx + dy * dy)));
                        sw += w;
                        swz += w * q.z;
                    }
                }
                o[x] = static_cast<float>(swz / sw);
            }
        });
    }

    [[nodiscard]] double errorBound() const noexcept override { return 0.0; }

  private:
    double halfP_;
};

// ---------------------------------------------------------------------------
// brute / step: float, structure-of-arrays contour. Weights are taken
// relative to a scale near the nearest squared distance dmin^2, so that
// nothing overflows or underflows:
// - any p: two passes per pixel, dmin^2 and then
//   w = exp2(-p/2 * log2(d^2 / dmin^2)) with FastMath.h: all <= 1 (up to
//   round-off), about 1 for the nearest;
// - p = 2^(K+1), K in [-3, 5] (p = 0.25 ... 64, every power of the tests):
//   w = r^(2^K), r = s / d^2, by K squarings or -K square roots, in one pass
//   per pixel (see bruteRowKernel for the scale s); r is clamped below so that
//   r^(2^K) stays a normal float (>= 2^-126: a far point's weight is then
//   overestimated by at most 2^-126, nothing next to the nearest weight).
// The loops over the contour are `omp simd` reductions (-fopenmp-simd: no
// OpenMP runtime), which lets GCC vectorise the float sums; only integer
// selects inside them (a float compare would keep GCC from vectorising).

/// Contour points per block of the weighted sums: float partial sums over a
/// block (a vectorised `omp simd` reduction), blocks added in double. The
/// round-off of a sum then grows with the block, not with the contour, and
/// does not depend on how many lanes the compiler splits the reduction into
/// (one at -O0: a million float additions in a row missed the brute solver's
/// tolerance in the asan build; the baseline and AVX2 clones differ too).
constexpr std::size_t kSumBlock = 1024;

struct SoaContour {
    std::vector<float> x;
    std::vector<float> y;
    std::vector<float> z;
};

/// The weight kernels, selected once per row.
constexpr int kGenericPower = 100;

/// p = 2^(K+1) when p is such a power with K in [-3, 5], else kGenericPower.
int powerMode(double p) {
    for (int k = -3; k <= 5; ++k) {
        if (p == std::ldexp(1.0, k + 1)) {
            return k;
        }
    }
    return kGenericPower;
}

template <int K>
[[gnu::always_inline]] inline float powerOfTwoWeight(float r) {
    if constexpr (K >= 0) {
        // r >= 2^-(126 >> K), so r^(2^K) >= 2^-126 is normal (no slow denormals).
        constexpr std::int32_t floorBits = (127 - (126 >> K)) << 23;
        r = std::bit_cast<float>(std::max(std::bit_cast<std::int32_t>(r), floorBits));
        for (int k = 0; k < K; ++k) {
            r *= r;
        }
    } else {
        for (int k = 0; k < -K; ++k) {
            r = std::sqrt(r);
        }
    }
    return r;
}

/// The weighted mean with weights exp2(-p/2 * log2(d^2 / dmin^2)).
[[gnu::always_inline]] inline float weightedMeanLog(const float* __restrict cx,
                                                    const float* __restrict cy,
                                                    const float* __restrict cz, std::size_t n,
                                                    float px, float py, float dmin2,
                                                    float negHalfP) {
    double sw = 0.0;
    double swz = 0.0;
    const float inv = 1.0F / dmin2;
    for (std::size_t b = 0; b < n; b += kSumBlock) {
        const std::size_t e = std::min(n, b + kSumBlock);
        float bw = 0.0F;
        float bwz = 0.0F;
#pragma omp simd reduction(+ : bw, bwz)
        for (std::size_t i = b; i < e; ++i) {
            const float dx = cx[i] - px;
            const float dy = cy[i] - py;
            const float t = (dx * dx + dy * dy) * inv;
            const float w = detail::fastExp2(negHalfP * detail::fastLog2(t));
            bw += w;
            bwz += w * cz[i];
        }
        sw += bw;
        swz += bwz;
    }
    return static_cast<float>(swz / sw);
}

/// The nearest squared distance from (px, py) to the contour.
[[gnu::always_inline]] inline float nearest2(const float* __restrict cx, const float* __restrict cy,
                                             std::size_t n, float px, float py) {
    float dmin2 = std::numeric_limits<float>::infinity();
#pragma omp simd reduction(min : dmin2)
    for (std::size_t i = 0; i < n; ++i) {
        const float dx = cx[i] - px;
        const float dy = cy[i] - py;
        const float d2 = dx * dx + dy * dy;
        dmin2 = d2 < dmin2 ? d2 : dmin2;
    }
    return dmin2;
}

/// The mean of the contour depths at distance 0 (only a hand-made contour has
/// such points: a void pixel is never a vessel pixel).
[[gnu::always_inline]] inline float coincidentMean(const float* cx, const float* cy,
                                                   const float* cz, std::size_t n, float px,
                                                   float py) {
    float sw = 0.0F;
    float swz = 0.0F;
    for (std::size_t i = 0; i < n; ++i) {
        if (cx[i] == px && cy[i] == py) {
            sw += 1.0F;
            swz += cz[i];
        }
    }
    return swz / sw;
}

template <int K>
[[gnu::always_inline]] inline void bruteRowKernel(const float* __restrict cx,
                                                  const float* __restrict cy,
                                                  const float* __restrict cz, std::size_t n,
                                                  const std::int32_t* labels, std::int32_t id,
                                                  int x0, int x1, int y, float negHalfP,
                                                  float* __restrict out) {
    const float py = static_cast<float>(y);
    // Power-of-two modes run one pass per pixel: the scale s is the previous
    // pixel's dmin^2 (the nearest distance changes by at most 1 from one pixel
    // to the next, and d >= 1, so s / d^2 <= 4 and r^(2^K) <= 4^32 = 2^64:
    // no overflow), and that pass finds this pixel's dmin^2 for the next one.
    bool chained = false;
    float s = 0.0F;
    for (int x = x0; x < x1; ++x) {
        if (labels[x] != id) {
            chained = false;
            continue;
        }
        const float px = static_cast<float>(x);
        if constexpr (K == kGenericPower) {
            static_cast<void>(s);
            const float dmin2 = nearest2(cx, cy, n, px, py);
            out[x] = dmin2 == 0.0F ? coincidentMean(cx, cy, cz, n, px, py)
                                   : weightedMeanLog(cx, cy, cz, n, px, py, dmin2, negHalfP);
        } else {
            if (!chained) {
                s = nearest2(cx, cy, n, px, py);
                if (s == 0.0F) {
                    out[x] = coincidentMean(cx, cy, cz, n, px, py);
                    continue;
                }
            }
            float dmin2 = std::numeric_limits<float>::infinity();
            double sw = 0.0;
            double swz = 0.0;
            for (std::size_t b = 0; b < n; b += kSumBlock) {
                const std::size_t e = std::min(n, b + kSumBlock);
                float bmin2 = std::numeric_limits<float>::infinity();
                float bw = 0.0F;
                float bwz = 0.0F;
#pragma omp simd reduction(min : bmin2) reduction(+ : bw, bwz)
                for (std::size_t i = b; i < e; ++i) {
                    const float dx = cx[i] - px;
                    const float dy = cy[i] - py;
                    const float d2 = dx * dx + dy * dy;
                    bmin2 = d2 < bmin2 ? d2 : bmin2;
                    const float w = powerOfTwoWeight<K>(s / d2);
                    bw += w;
                    bwz += w * cz[i];
                }
                dmin2 = std::min(dmin2, bmin2);
                sw += bw;
                swz += bwz;
            }
            if (dmin2 == 0.0F) {
                out[x] = coincidentMean(cx, cy, cz, n, px, py);
                chained = false;
                continue;
            }
            out[x] = static_cast<float>(swz / sw);
            s = dmin2;
            chained = true;
        }
    }
}

/// Evaluates one row segment [x0, x1) of row y for the pixels labelled `id`.
VV_VSS_CLONES void bruteRow(const float* __restrict cx, const float* __restrict cy,
                            const float* __restrict cz, std::size_t n, const std::int32_t* labels,
                            std::int32_t id, int x0, int x1, int y, int mode, float negHalfP,
                            float* __restrict out) {
    switch (mode) {
        case -3:
            bruteRowKernel<-3>(cx, cy, cz, n, labels, id, x0, x1, y, negHalfP, out);
            break;
        case -2:
            bruteRowKernel<-2>(cx, cy, cz, n, labels, id, x0, x1, y, negHalfP, out);
            break;
        case -1:
            bruteRowKernel<-1>(cx, cy, cz, n, labels, id, x0, x1, y, negHalfP, out);
            break;
        case 0:
            bruteRowKernel<0>(cx, cy, cz, n, labels, id, x0, x1, y, negHalfP, out);
            break;
        case 1:
            bruteRowKernel<1>(cx, cy, cz, n, labels, id, x0, x1, y, negHalfP, out);
            break;
        case 2:
            bruteRowKernel<2>(cx, cy, cz, n, labels, id, x0, x1, y, negHalfP, out);
            break;
        case 3:
            bruteRowKernel<3>(cx, cy, cz, n, labels, id, x0, x1, y, negHalfP, out);
            break;
        case 4:
            bruteRowKernel<4>(cx, cy, cz, n, labels, id, x0, x1, y, negHalfP, out);
            break;
        case 5:
            bruteRowKernel<5>(cx, cy, cz, n, labels, id, x0, x1, y, negHalfP, out);
            break;
        default:
            bruteRowKernel<kGenericPower>(cx, cy, cz, n, labels, id, x0, x1, y, negHalfP, out);
            break;
    }
}

class BruteSolver final : public Solver {
  public:
    BruteSolver(double p, int step)
        : negHalfP_(static_cast<float>(-0.5 * p)), mode_(powerMode(p)), step_(step) {}

    void solveRegion(ImageView<const std::int32_t> labels, const VoidRegion& region,
                     ImageView<float> out, const std::stop_token& stop) const override {
        checkSizes(labels, out);
        if (region.contour.empty()) {
            fillRegion(labels, region, out, std::numeric_limits<float>::quiet_NaN(), stop);
            return;
        }
        // k = 1 (brute): every contour pixel, in list order. k > 1 (step):
        // every k-th pixel of the contour in border-following order
        // (orderAlongBorders: chains of 8-connected pixels walked along the
        // silhouettes, as the paper's Suzuki contours are), starting with the
        // first, so every silhouette is sampled evenly along its length. The
        // list's own row-major order would interleave the walls of different
        // vessels row by row and could drop a whole wall (docs/benchmarks/vss.md).
        SoaContour c;
        const std::size_t k = static_cast<std::size_t>(step_);
        const std::size_t n = (region.contour.size() + k - 1) / k;
        std::vector<std::uint32_t> ordered;
        if (k > 1) {
            ordered = detail::orderAlongBorders(region.contour).index;
        }
        c.x.reserve(n);
        c.y.reserve(n);
        c.z.reserve(n);
        float zlo = std::numeric_limits<float>::infinity();
        float zhi = -std::numeric_limits<float>::infinity();
        for (std::size_t i = 0; i < region.contour.size(); i += k) {
            const ContourPoint& q = region.contour[k > 1 ? ordered[i] : i];
            c.x.push_back(static_cast<float>(q.x));
            c.y.push_back(static_cast<float>(q.y));
            c.z.push_back(q.z);
            zlo = std::min(zlo, q.z);
            zhi = std::max(zhi, q.z);
        }
        forEachRegionRow(labels, region, static_cast<double>(n), stop, [&](int y) {
            float* o = out.row(y);
            bruteRow(c.x.data(), c.y.data(), c.z.data(), n, labels.row(y), region.id, region.x0,
                     region.x1, y, mode_, negHalfP_, o);
            // z' is a convex combination of the contour depths: clamp the last
            // bits of float round-off back into their range.
            for (int x = region.x0; x < region.x1; ++x) {
                if (labels.row(y)[x] == region.id) {
                    o[x] = std::clamp(o[x], zlo, zhi);
                }
            }
        });
    }

    [[nodiscard]] double errorBound() const noexcept override {
        return step_ == 1 ? 0.0 : std::numeric_limits<double>::quiet_NaN();
    }

  private:
    float negHalfP_;
    int mode_;
    int step_;
};

}  // namespace

SolverKind parseSolverKind(std::string_view name) {
    if (name == "reference") {
        return SolverKind::Reference;
    }
    if (name == "brute") {
        return SolverKind::Brute;
    }
    if (name == "step") {
        return SolverKind::Step;
    }
    if (name == "fast") {
        return SolverKind::Fast;
    }
    throw InvalidArgumentError("unknown solver '" + std::string(name) +
                               "' (known: reference, brute, step, fast)");
}

std::string_view toString(SolverKind kind) noexcept {
    switch (kind) {
        case SolverKind::Reference:
            return "reference";
        case SolverKind::Brute:
            return "brute";
        case SolverKind::Step:
            return "step";
        case SolverKind::Fast:
            return "fast";
    }
    return "unknown";
}

std::unique_ptr<Solver> makeSolver(const SolverOptions& options) {
    if (!std::isfinite(options.p) || options.p <= 0.0) {
        throw InvalidArgumentError("solver: p must be a finite number > 0, got " +
                                   std::to_string(options.p));
    }
    if (options.step < 1) {
        throw InvalidArgumentError("solver: step must be >= 1, got " +
                                   std::to_string(options.step));
    }
    if (!std::isfinite(options.tolerance) || options.tolerance <= 0.0) {
        throw InvalidArgumentError("solver: tolerance must be a finite number > 0, got " +
                                   std::to_string(options.tolerance));
    }
    switch (options.kind) {
        case SolverKind::Reference:
            return std::make_unique<ReferenceSolver>(options.p);
        case SolverKind::Brute:
            return std::make_unique<BruteSolver>(options.p, 1);
        case SolverKind::Step:
            return std::make_unique<BruteSolver>(options.p, options.step);
        case SolverKind::Fast:
            return detail::makeFastSolver(options);
    }
    throw InvalidArgumentError("solver: unknown kind");
}

}  // namespace vv::vss
