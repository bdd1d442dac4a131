// SPDX-License-Identifier: GPL-3.0-or-later
//
// The `fast` VSS solver: a dual-tree treecode / FMM with rigorous error bounds
// and an exact a-posteriori check on every pixel.
//
// PROBLEM. For every void pixel x of a region with contour points y_i (depth
// z_i): z'(x) = N/D, D = sum_i w_i, N = sum_i w_i z_i, w_i = |x - y_i|^-p.
// Required: |z~' - z'| <= tol on every pixel, for every p, never NaN / Inf,
// z~' inside [min z_i, max z_i].
//
// DESIGN (per region, solveRegion):
//  1. Source tree: a k-d tree over the contour points (median split of the
//     longer side, <= 16 points per leaf). Per node: box, centre c, radius s,
//     z-range, and complex moments M_{r,r'} = sum_i w_i (v_i/s)^r conj(v_i/s)^r',
//     v_i = y_i - c, r + r' <= m, for w = 1 (D) and w = z - zref (N); leaves
//     directly, inner nodes by exact binomial shifts (M2M). m = 10 for p <= 16,
//     8 above (measured: fewer, larger clusters outweigh O(m^3) translations).
//  2. Target tree: the region's bounding box cut into 16x16 leaf tiles, a
//     quadtree above them; boxes without pixels of the region are skipped; the
//     geometry of a box is the bounding box of ITS REGION PIXELS (centre t,
//     half-diagonal a).
//  3. Dual traversal, top-down over target boxes (parallel over 64x64 boxes
//     for large regions). A box receives a list of source clusters; clusters
//     larger than the box are split; each cluster is then
//       - dropped (its whole weight charged to the error bound), or
//       - translated into the box's local expansion (M2L, truncated at the
//         cheapest order m' <= m that fits the budget), or
//       - deferred to the child boxes, or, at a leaf tile, split further or
//         evaluated exactly (the "near" points).
//     Local expansions F(zeta) = sum_{l+l'<=m} L_{l,l'} (zeta/a)^l conj(zeta/a)^l'
//     (zeta = x - t) are re-centred exactly to the children (L2L). M2L rotates
//     the cluster to the real axis (the coefficients become real), prefix sums
//     give O(m^3) per translation, D and N travel side by side in 4-wide vectors.
//  4. Leaf tile (FastKernel.cpp): the local expansion becomes a real bivariate
//     polynomial in (u, v) evaluated per row (Horner), the near points are
//     summed exactly; 16 lanes = one tile row; AVX-512 / AVX2 / baseline builds
//     dispatched at run time. p/2 in {1, 2, 4, ..., 32}: r = S^2/d^2 raised by
//     squarings (one division per two points); other p: own log2 / exp2.
//
// ERROR BOUND. Write x - y = W + zeta - v (W = t - c, R = |W|, |zeta| <= a,
// |v| <= s). Then |x-y|^-p = R^-p (1+u)^(-p/2) (1+conj u)^(-p/2) with
// u = (zeta' - v')/R in the frame rotated so that W is real, |u| <= q = (a+s)/R.
// Expanding both binomial series and truncating at total degree m in
// (zeta, v) leaves, for every point, a remainder of at most
//     R^-p tau_m(q),  tau_m(q) = sum_{n>m} c_n q^n,  c_n = (p)_n / n!,
// because sum_{k+k'=n} |binom(-p/2,k)| |binom(-p/2,k')| = c_n, the coefficient
// of q^n in (1-q)^-p. tau is summed explicitly, its tail bounded by a
// geometric series (term ratio q (p+n)/(n+1), decreasing towards q). A
// dropped cluster's remainder is its weight, <= mindist^-p. With Dt, Nt the
// computed sums and r_i the per-point remainders (the SAME for D and N, the
// expansion being linear in the weights):
//     z~' - z' = sum_i r_i (z_i - z') / Dt,  so  |z~' - z'| <= E / Dt,
//     E = sum_clusters n_C dz_C R^-p tau (or n_C dz_C mindist^-p if dropped),
// dz_C = max(zmax_C - zmin, zmax - zmin_C) >= |z_i - z'| (z' lies in the
// region's range). Each leaf carries E (valid over its whole box) and the kernel
// checks, per pixel, with Dt computed there:
//     E + (polynomial round-off) <= (tol - dz (delta_w + gamma_K) - 16u) Dt,
// delta_w: relative error of a kernel weight ((8 p/2 + 8) u for squarings; from
// the measured log2 / exp2 bounds otherwise), gamma_K = (K + 8) u: float sums of
// K near points (a relative weight error delta moves z' by at most dz delta),
// polynomial: (3m + 12) u sum |coefficients| + 1e-11 of the expanded weights
// (double round-off of M2L / L2L). Pixels failing the check (none in the
// benchmarks) are recomputed: the whole tile with every contour point in the
// kernel when > 16 pixels fail, else (or if that fails too) one pixel at a
// time by a double-precision sum. Finally z~' is clamped to [zmin, zmax] (only
// reduces the error: the exact z' is in there). So the tolerance holds on
// EVERY pixel whatever the a-priori choices below; a region whose contour
// depth range is <= 2 tol gets its mid-range (exact within tol).
//
// A-PRIORI BUDGET (efficiency only). Over a box B, D >= Dlo(B) =
// sum over the placed clusters of n_C maxdist(B,C)^-p. A cluster may use
//     dz_C (err per point) <= 0.75 tol (1/2 maxdist^-p + 1/2 Dlo(B) / n)
// which sums, over the clusters any pixel sees, to <= 0.75 tol D. Loosening
// it 10x sends most pixels to the fall-back (FastSolverTest checks that a 30x
// looser budget still meets the tolerance through the check): the bounds are
// tight for worst-case geometry, though the measured errors are ~1000x smaller.
//
// SCALING (VSS.md "stiff cases"). Every box has a scale S = a lower bound of
// all its pixel-point distances (>= 1); its expansion, E and Dlo hold true
// values times S^p, so every point contributes <= 1 (no overflow: p <= 64,
// distances <= 9000 give >= 1e-253, no underflow in double). Leaves use one
// float scale per tile when p log2((d_near + diag)/S) <= 60, else a scale per
// pixel S_x = min(nearest near point, far-cluster bound) with the check done
// in log2; weights are then (S_x/d)^p <= 1 and the nearest is 1.
//
// MEASURED: docs/benchmarks/vss.md, "Fast solver: design log" (timings of
// bench/vss_fast_micro, what was tried and dropped, what is next).
//
#include "FastSolver.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <stop_token>
#include <utility>
#include <vector>

#include "FastKernel.h"
#include "FastMath.h"
#include "FastStats.h"
#include "vv/core/Error.h"
#include "vv/core/Parallel.h"

namespace vv::vss::detail {
namespace {

constexpr int kM = kMaxPolyDegree;  // highest expansion degree
constexpr int kS = kM + 1;          // stride of square coefficient arrays
constexpr double kU = 0x1p-24;      // unit round-off of float
constexpr int kMaxTerms = 512;      // terms of the remainder series we tabulate
constexpr int kLeafPoints = 16;     // contour points per source leaf

// ---------------------------------------------------------------- statistics
struct AtomicStats {
    std::atomic<std::int64_t> pixels{0}, fallbackPixels{0}, leaves{0}, nearPairs{0}, m2l{0},
        dropped{0}, perPixelLeaves{0}, exactTiles{0};
};
AtomicStats& stats() {
    static AtomicStats s;
    return s;
}
std::atomic<double> gBudgetScale{1.0};  // test hook, see FastStats.h

// Per-thread counters, added to the shared atomics once per task / region (atomic
// updates per leaf from both threads would bounce one cache line between the cores).
struct LocalStats {
    std::int64_t pixels = 0, fallbackPixels = 0, leaves = 0, nearPairs = 0, m2l = 0, dropped = 0,
                 perPixelLeaves = 0, exactTiles = 0;
};
thread_local LocalStats tlStats;
void flushStats() {
    LocalStats& l = tlStats;
    AtomicStats& s = stats();
    s.pixels += l.pixels;
    s.fallbackPixels += l.fallbackPixels;
    s.leaves += l.leaves;
    s.nearPairs += l.nearPairs;
    s.m2l += l.m2l;
    s.dropped += l.dropped;
    s.perPixelLeaves += l.perPixelLeaves;
    s.exactTiles += l.exactTiles;
    l = LocalStats{};
}
struct StatsFlush {  // flushes on every exit, cancellation included
    StatsFlush() = default;
    StatsFlush(const StatsFlush&) = delete;
    StatsFlush& operator=(const StatsFlush&) = delete;
    ~StatsFlush() { flushStats(); }
};

using Square = std::array<Cx, kS * kS>;

// ---------------------------------------------------------------- per-p tables
struct PowerTables {
    double p = 2.0;
    double halfP = 1.0;
    int degree = kM;                             // local expansion degree used
    std::vector<double> c;                       // c_n = (p)_n / n!: coefficients of (1-q)^-p
    std::vector<double> ratio;                   // max(1, (p+n)/(n+1)) >= t[n+1]/(q t[n])
    std::array<std::array<double, kS>, kS> h{};  // h[l][r] = (-1)^l (p/2)_{l+r} / (l! r!)
    std::array<std::array<double, kS>, kS> binom{};
    // poly[(l * kS + l') * kS + a]: (u+iv)^l (u-iv)^l' = sum_a coefficient * u^(l+l'-a) v^a
    // (complex, for l + l' <= kM)
    std::vector<Cx> poly;

    int squarings = -1;  // p/2 = 2^squarings exactly (0..5), else -1

    // ratio2^(p/2): by squarings when p/2 is a power of two (exact up to
    // rounding), else exp2 / log2 (relative error < 1e-13, see above)
    [[nodiscard]] double pw(double ratio2) const {
        if (squarings >= 0) {
            double w = ratio2;
            for (int i = 0; i < squarings; ++i) {
                w *= w;
            }
            return w;
        }
        return powHalf(ratio2, halfP);
    }

    explicit PowerTables(double pIn) : p(pIn), halfP(pIn / 2.0) {
        for (int e = 0; e <= 5; ++e) {
            if (halfP == static_cast<double>(1 << e)) {
                squarings = e;
            }
        }
        // measured on the micro-benchmark: 10 is fastest for p <= 16 (fewer,
        // larger clusters outweigh the O(degree^3) translations), 8 above
        degree = p <= 16.0 ? 10 : 8;
        c.resize(kMaxTerms + 1);
        c[0] = 1.0;
        for (int n = 1; n <= kMaxTerms; ++n) {
            c[n] = c[n - 1] * (p + n - 1) / n;
        }
        ratio.resize(kMaxTerms + 1);
        for (int n = 0; n <= kMaxTerms; ++n) {
            ratio[static_cast<std::size_t>(n)] = std::max(1.0, (p + n) / (n + 1.0));
        }
        std::array<double, 2 * kS> poch{};
        poch[0] = 1.0;
        for (int k = 1; k < 2 * kS; ++k) {
            poch[k] = poch[k - 1] * (halfP + k - 1);
        }
        std::array<double, kS> fact{};
        fact[0] = 1.0;
        for (int k = 1; k < kS; ++k) {
            fact[k] = fact[k - 1] * k;
        }
        for (int l = 0; l < kS; ++l) {
            for (int r = 0; l + r < kS; ++r) {
                h[l][r] = ((l % 2 == 0) ? 1.0 : -1.0) * poch[l + r] / (fact[l] * fact[r]);
            }
        }
        for (int n = 0; n < kS; ++n) {
            binom[n][0] = 1.0;
            for (int k = 1; k <= n; ++k) {
                binom[n][k] = binom[n - 1][k - 1] + (k <= n - 1 ? binom[n - 1][k] : 0.0);
            }
        }
        poly.assign(static_cast<std::size_t>(kS * kS * kS), Cx{0.0, 0.0});
        const Cx ipow[4] = {{1.0, 0.0}, {0.0, 1.0}, {-1.0, 0.0}, {0.0, -1.0}};
        for (int l = 0; l < kS; ++l) {
            for (int lp = 0; l + lp < kS; ++lp) {
                for (int ea = 0; ea <= l; ++ea) {
                    for (int eb = 0; eb <= lp; ++eb) {
                        // C(l,a) C(l',b) u^{l+l'-a-b} v^{a+b} i^{a+b} (-1)^b
                        const double coef =
                            binom[l][ea] * binom[lp][eb] * ((eb % 2 == 0) ? 1.0 : -1.0);
                        poly[static_cast<std::size_t>((l * kS + lp) * kS + ea + eb)] +=
                            coef * ipow[(ea + eb) % 4];
                    }
                }
            }
        }
    }

    // Smallest order m' in [0, degree] whose remainder tail
    // tau_m'(q) = sum_{n>m'} c_n q^n is <= limit; -1 if none. tauOut = tau_m'(q).
    // The terms beyond the last one summed are bounded by a geometric series:
    // t[n+1] / t[n] = q (p+n)/(n+1) <= q ratio[n] for every later n.
    int chooseOrder(double q, double limit, double& tauOut) const {
        if (!(q < 1.0) || limit <= 0.0) {
            return -1;
        }
        std::array<double, kS + 1> t;  // t[n] = c_n q^n, n <= degree + 1 (hot: no fill)
        t[0] = 1.0;
        double qn = 1.0;
        for (int n = 1; n <= degree + 1; ++n) {
            qn *= q;
            t[static_cast<std::size_t>(n)] = c[static_cast<std::size_t>(n)] * qn;
        }
        double term = t[static_cast<std::size_t>(degree + 1)];
        double tail = 0.0;
        for (int n = degree + 1;; ++n) {
            tail += term;
            if (tail > limit) {
                return -1;  // the tail is at least this partial sum
            }
            const double r = q * ratio[static_cast<std::size_t>(n)];
            if (r < 0.875) {
                tail += term * r / (1.0 - r);
                break;
            }
            if (n >= kMaxTerms) {
                return -1;
            }
            qn *= q;
            term = c[static_cast<std::size_t>(n + 1)] * qn;
        }
        tail *= 1.0 + 1e-12;
        if (!(tail <= limit)) {
            return -1;
        }
        // tail(m'-1) = tail(m') + t[m']: walk down while it still fits
        int m = degree;
        while (m > 0 && tail + t[static_cast<std::size_t>(m)] <= limit) {
            tail += t[static_cast<std::size_t>(m)];
            --m;
        }
        tauOut = tail;
        return m;
    }
};

// ---------------------------------------------------------------- source tree
struct Point {
    int x = 0;
    int y = 0;
    float z = 0.0F;  // z - zref
};

struct SrcNode {
    double cx = 0.0;  // centre of the bounding box
    double cy = 0.0;
    double s = 0.0;                          // radius: max |y_i - c|
    double sn = 1.0;                         // normalisation of the moments: max(s, 0.5)
    int bx0 = 0, by0 = 0, bx1 = 0, by1 = 0;  // bounding box, inclusive
    int begin = 0;
    int end = 0;
    int child = -1;  // first child (second is child + 1), -1 for a leaf
    float zmin = 0.0F;
    float zmax = 0.0F;
    [[nodiscard]] int count() const { return end - begin; }
};

// Hermitian packing of moments: (r, r') with r >= r', r + r' <= degree.
struct MomentLayout {
    int degree = 0;
    int count = 0;
    std::array<std::array<int, kS>, kS> idx{};
    explicit MomentLayout(int d) : degree(d) {
        for (auto& row : idx) {
            row.fill(-1);
        }
        for (int r = 0; r <= d; ++r) {
            for (int rp = 0; rp <= r && r + rp <= d; ++rp) {
                idx[r][rp] = count++;
            }
        }
    }
};

struct SourceTree {
    std::vector<Point> pts;
    std::vector<SrcNode> nodes;
    std::vector<Cx> momD;  // nodes.size() * layout.count
    std::vector<Cx> momN;
};

void buildNode(SourceTree& tree, int node) {
    SrcNode& nd = tree.nodes[static_cast<std::size_t>(node)];
    int bx0 = std::numeric_limits<int>::max();
    int by0 = bx0;
    int bx1 = std::numeric_limits<int>::min();
    int by1 = bx1;
    float zmin = std::numeric_limits<float>::infinity();
    float zmax = -zmin;
    for (int i = nd.begin; i < nd.end; ++i) {
        const Point& q = tree.pts[static_cast<std::size_t>(i)];
        bx0 = std::min(bx0, q.x);
        by0 = std::min(by0, q.y);
        bx1 = std::max(bx1, q.x);
        by1 = std::max(by1, q.y);
        zmin = std::min(zmin, q.z);
        zmax = std::max(zmax, q.z);
    }
    nd.bx0 = bx0;
    nd.by0 = by0;
    nd.bx1 = bx1;
    nd.by1 = by1;
    nd.zmin = zmin;
    nd.zmax = zmax;
    nd.cx = 0.5 * (static_cast<double>(bx0) + bx1);
    nd.cy = 0.5 * (static_cast<double>(by0) + by1);
    double s2 = 0.0;
    for (int i = nd.begin; i < nd.end; ++i) {
        const Point& q = tree.pts[static_cast<std::size_t>(i)];
        const double dx = q.x - nd.cx;
        const double dy = q.y - nd.cy;
        s2 = std::max(s2, dx * dx + dy * dy);
    }
    nd.s = std::sqrt(s2) * (1.0 + 1e-15);
    nd.sn = std::max(nd.s, 0.5);
    if (nd.count() <= kLeafPoints) {
        return;
    }
    const bool splitX = (bx1 - bx0) >= (by1 - by0);
    const int mid = nd.begin + nd.count() / 2;
    const auto first = tree.pts.begin() + nd.begin;
    std::nth_element(first, tree.pts.begin() + mid, tree.pts.begin() + nd.end,
                     [splitX](const Point& a, const Point& b) {
                         return splitX ? (a.x < b.x || (a.x == b.x && a.y < b.y))
                                       : (a.y < b.y || (a.y == b.y && a.x < b.x));
                     });
    const int begin = nd.begin;
    const int end = nd.end;
    const int child = static_cast<int>(tree.nodes.size());
    tree.nodes[static_cast<std::size_t>(node)].child = child;  // nd may dangle after push_back
    SrcNode left;
    left.begin = begin;
    left.end = mid;
    SrcNode right;
    right.begin = mid;
    right.end = end;
    tree.nodes.push_back(left);
    tree.nodes.push_back(right);
    buildNode(tree, child);
    buildNode(tree, child + 1);
}

// Moments of every node about its centre, normalised by sn:
// M_{r,r'} = sum_i w_i (v_i / sn)^r conj(v_i / sn)^r', v_i = y_i - c, for
// w = 1 (D) and w = z - zref (N). Leaves directly, inner nodes by exact shifts.
__attribute__((target_clones("arch=x86-64-v3", "default"))) void buildMoments(
    SourceTree& tree, const MomentLayout& lay, const PowerTables& tab) {
    const int d = lay.degree;
    const std::size_t mc = static_cast<std::size_t>(lay.count);
    tree.momD.assign(tree.nodes.size() * mc, Cx{});
    tree.momN.assign(tree.nodes.size() * mc, Cx{});
    for (std::size_t k = tree.nodes.size(); k-- > 0;) {
        const SrcNode& nd = tree.nodes[k];
        Cx* mD = &tree.momD[k * mc];
        Cx* mN = &tree.momN[k * mc];
        if (nd.child < 0) {
            std::array<V4, kS * kS> acc;
            for (int i = 0; i < lay.count; ++i) {
                acc[static_cast<std::size_t>(i)] = V4{0.0, 0.0, 0.0, 0.0};
            }
            for (int i = nd.begin; i < nd.end; ++i) {
                const Point& q = tree.pts[static_cast<std::size_t>(i)];
                const Cx v{(q.x - nd.cx) / nd.sn, (q.y - nd.cy) / nd.sn};
                std::array<Cx, kS> pw{};
                pw[0] = {1.0, 0.0};
                for (int r = 1; r <= d; ++r) {
                    pw[r] = pw[r - 1] * v;
                }
                const V4 zw{1.0, 1.0, static_cast<double>(q.z), static_cast<double>(q.z)};
                for (int r = 0; r <= d; ++r) {
                    for (int rp = 0; rp <= r && r + rp <= d; ++rp) {
                        const Cx t = pw[r] * conj(pw[rp]);
                        acc[lay.idx[r][rp]] += V4{t.re, t.im, t.re, t.im} * zw;
                    }
                }
            }
            for (int i = 0; i < lay.count; ++i) {
                const V4 v = acc[static_cast<std::size_t>(i)];
                mD[i] = Cx{v[0], v[1]};
                mN[i] = Cx{v[2], v[3]};
            }
            continue;
        }
        for (int c = 0; c < 2; ++c) {
            const std::size_t ck = static_cast<std::size_t>(nd.child + c);
            const SrcNode& ch = tree.nodes[ck];
            const double alpha = ch.sn / nd.sn;
            const Cx beta{(ch.cx - nd.cx) / nd.sn, (ch.cy - nd.cy) / nd.sn};
            std::array<Cx, kS> bp;
            std::array<double, kS> ap;
            bp[0] = {1.0, 0.0};
            ap[0] = 1.0;
            for (int r = 1; r <= d; ++r) {
                bp[r] = bp[r - 1] * beta;
                ap[r] = ap[r - 1] * alpha;
            }
            // (alpha v + beta)^r = sum_j coef[r][j] v^j
            std::array<Cx, kS * kS> coef;
            for (int r = 0; r <= d; ++r) {
                for (int j = 0; j <= r; ++j) {
                    coef[r * kS + j] = (tab.binom[r][j] * ap[j]) * bp[r - j];
                }
            }
            const Cx* srcD = &tree.momD[ck * mc];
            const Cx* srcN = &tree.momN[ck * mc];
            std::array<V4, kS * kS> full;  // full child moments (D, N), r + r' <= d
            for (int r = 0; r <= d; ++r) {
                for (int rp = 0; r + rp <= d; ++rp) {
                    const bool lower = r >= rp;
                    const int ix = lower ? lay.idx[r][rp] : lay.idx[rp][r];
                    const double sg = lower ? 1.0 : -1.0;
                    full[r * kS + rp] =
                        V4{srcD[ix].re, sg * srcD[ix].im, srcN[ix].re, sg * srcN[ix].im};
                }
            }
            std::array<V4, kS * kS> t;
            for (int r = 0; r <= d; ++r) {
                for (int jp = 0; r + jp <= d; ++jp) {
                    V4 acc{0.0, 0.0, 0.0, 0.0};
                    for (int j = 0; j <= r; ++j) {
                        cmulAdd4(acc, full[j * kS + jp], coef[r * kS + j]);
                    }
                    t[r * kS + jp] = acc;
                }
            }
            for (int r = 0; r <= d; ++r) {
                for (int rp = 0; rp <= r && r + rp <= d; ++rp) {
                    V4 acc{0.0, 0.0, 0.0, 0.0};
                    for (int jp = 0; jp <= rp; ++jp) {
                        cmulAdd4(acc, t[r * kS + jp], conj(coef[rp * kS + jp]));
                    }
                    mD[lay.idx[r][rp]] += Cx{acc[0], acc[1]};
                    mN[lay.idx[r][rp]] += Cx{acc[2], acc[3]};
                }
            }
        }
    }
}

// ---------------------------------------------------------------- local expansions
// F(zeta) = sum_{l+l'<=degree} L[l][l'] (zeta/a)^l conj(zeta/a)^l', zeta = x - t,
// stored in full (L[l'][l] = conj(L[l][l']) since F is real).
struct Local {
    Square d{};
    Square n{};
};

// Shift (exactly) a local expansion from centre/scale (t0, a0) to (t1, a1).
__attribute__((target_clones("arch=x86-64-v3", "default"))) void shiftLocal(
    const Local& src, Local& loc, int deg, const PowerTables& tab, double t0x, double t0y,
    double a0, double t1x, double t1y, double a1, double f) {
    const double alpha = a1 / a0;
    const Cx beta{(t1x - t0x) / a0, (t1y - t0y) / a0};
    std::array<Cx, kS> bp;
    std::array<double, kS> ap;
    bp[0] = {1.0, 0.0};
    ap[0] = 1.0;
    for (int r = 1; r <= deg; ++r) {
        bp[r] = bp[r - 1] * beta;
        ap[r] = ap[r - 1] * alpha;
    }
    // coef[l][j] = binom(l,j) alpha^j beta^(l-j), shared by D and N and both passes
    std::array<Cx, kS * kS> coef;
    for (int l = 0; l <= deg; ++l) {
        for (int j = 0; j <= l; ++j) {
            coef[l * kS + j] = (tab.binom[l][j] * ap[j]) * bp[l - j];
        }
    }
    // t[j][l'] = sum_{l>=j} coef[l][j] L[l][l'];  L'[j][j'] = sum_{l'>=j'} conj(coef[l'][j'])
    // t[j][l'] with D and N side by side in V4
    std::array<V4, kS * kS> in;
    for (int l = 0; l <= deg; ++l) {
        for (int lp = 0; l + lp <= deg; ++lp) {
            const Cx d = src.d[l * kS + lp];
            const Cx n = src.n[l * kS + lp];
            in[l * kS + lp] = V4{d.re, d.im, n.re, n.im};
        }
    }
    std::array<V4, kS * kS> t;  // written and read for j + l' <= deg only
    for (int lp = 0; lp <= deg; ++lp) {
        for (int j = 0; j + lp <= deg; ++j) {
            V4 acc{0.0, 0.0, 0.0, 0.0};
            for (int l = j; l + lp <= deg; ++l) {
                cmulAdd4(acc, in[l * kS + lp], coef[l * kS + j]);
            }
            t[j * kS + lp] = acc;
        }
    }
    for (int j = 0; j <= deg; ++j) {
        for (int jp = 0; j + jp <= deg; ++jp) {
            V4 acc{0.0, 0.0, 0.0, 0.0};
            for (int lp = jp; j + lp <= deg; ++lp) {
                cmulAdd4(acc, t[j * kS + lp], conj(coef[lp * kS + jp]));
            }
            acc *= f;
            loc.d[j * kS + jp] = Cx{acc[0], acc[1]};
            loc.n[j * kS + jp] = Cx{acc[2], acc[3]};
        }
    }
}

// Multipole-to-local of source node C into the local expansion at (t, a), truncated
// at total degree mo in (zeta, v), times wR = (S/R)^p.
__attribute__((target_clones("arch=x86-64-v3", "default"))) void m2l(
    Local& loc, int mo, const PowerTables& tab, const MomentLayout& lay, const Cx* mD, const Cx* mN,
    const SrcNode& C, double tx, double ty, double a, double R, double wR) {
    const double wx = tx - C.cx;
    const double wy = ty - C.cy;
    const Cx er{wx / R, -wy / R};  // e^{-i theta}
    std::array<Cx, 2 * kS> rot{};  // rot[k] = e^{-i k theta}
    rot[0] = {1.0, 0.0};
    for (int k = 1; k <= mo; ++k) {
        rot[k] = rot[k - 1] * er;
    }
    const double ra = a / R;
    const double rs = C.sn / R;
    std::array<double, kS> pa{};
    std::array<double, kS> ps{};
    pa[0] = 1.0;
    ps[0] = 1.0;
    for (int k = 1; k <= mo; ++k) {
        pa[k] = pa[k - 1] * ra;
        ps[k] = ps[k - 1] * rs;
    }
    // g[l][r] = h[l][r] (a/R)^l (sn/R)^r
    std::array<std::array<double, kS>, kS> g{};
    for (int l = 0; l <= mo; ++l) {
        for (int r = 0; l + r <= mo; ++r) {
            g[l][r] = tab.h[l][r] * pa[l] * ps[r];
        }
    }
    // rotated full moments Mt[r][r'] = M[r][r'] e^{-i(r-r')theta}, D and N side
    // by side as [D.re, D.im, N.re, N.im] (g is real: one 4-wide FMA per term)
    std::array<V4, kS * kS> mt;  // entries with r + r' <= mo are all written (hot: no fill)
    for (int r = 0; r <= mo; ++r) {
        for (int rp = 0; rp <= r && r + rp <= mo; ++rp) {
            const int ix = lay.idx[r][rp];
            V4 v;
            cmul4(v, V4{mD[ix].re, mD[ix].im, mN[ix].re, mN[ix].im}, rot[r - rp]);
            mt[r * kS + rp] = v;
            mt[rp * kS + r] = v * V4{1.0, -1.0, 1.0, -1.0};
        }
    }
    // prefix sums P[l][r'][j] = sum_{r<=j} g[l][r] Mt[r][r'] (only the prefixes used are written)
    std::array<V4, kS * kS * kS> pre;
    for (int l = 0; l <= mo; ++l) {
        for (int rp = 0; l + rp <= mo; ++rp) {
            V4 acc{0.0, 0.0, 0.0, 0.0};
            for (int r = 0; l + rp + r <= mo; ++r) {
                acc += g[l][r] * mt[r * kS + rp];
                pre[(l * kS + rp) * kS + r] = acc;
            }
        }
    }
    for (int l = 0; l <= mo; ++l) {
        for (int lp = 0; lp <= l && l + lp <= mo; ++lp) {
            V4 acc{0.0, 0.0, 0.0, 0.0};
            for (int rp = 0; l + lp + rp <= mo; ++rp) {
                acc += g[lp][rp] *
                       pre[static_cast<std::size_t>((l * kS + rp) * kS + (mo - l - lp - rp))];
            }
            V4 v;
            cmul4(v, acc, rot[l - lp]);
            v *= wR;
            loc.d[l * kS + lp] += Cx{v[0], v[1]};
            loc.n[l * kS + lp] += Cx{v[2], v[3]};
            if (lp != l) {
                loc.d[lp * kS + l] += Cx{v[0], -v[1]};
                loc.n[lp * kS + l] += Cx{v[2], -v[3]};
            }
        }
    }
}

// Real polynomial sum c[i][j] u^i v^j of F(u + iv) (u, v in units of a):
// F = sum_{l,l'} L[l][l'] (u+iv)^l (u-iv)^l', real, so the l < l' half is the
// conjugate of the l > l' half: F = sum_{l>=l'} (l == l' ? 1 : 2) Re(L (u+iv)^l (u-iv)^l').
void localToPoly(const Square& L, int deg, const PowerTables& tab, std::array<double, kS * kS>& c) {
    c.fill(0.0);
    for (int l = 0; l <= deg; ++l) {
        for (int lp = 0; lp <= l && l + lp <= deg; ++lp) {
            const Cx Lv = (l == lp ? 1.0 : 2.0) * L[l * kS + lp];
            const Cx* pc = &tab.poly[static_cast<std::size_t>((l * kS + lp) * kS)];
            const int n = l + lp;
            for (int a = 0; a <= n; ++a) {
                c[(n - a) * kS + a] += Lv.re * pc[a].re - Lv.im * pc[a].im;
            }
        }
    }
}

// ---------------------------------------------------------------- target boxes
struct TileInfo {
    int count = 0;  // region pixels in the box
    int minx = std::numeric_limits<int>::max();
    int miny = std::numeric_limits<int>::max();
    int maxx = std::numeric_limits<int>::min();
    int maxy = std::numeric_limits<int>::min();
    void add(const TileInfo& o) {
        count += o.count;
        minx = std::min(minx, o.minx);
        miny = std::min(miny, o.miny);
        maxx = std::max(maxx, o.maxx);
        maxy = std::max(maxy, o.maxy);
    }
};

struct BoxGeo {
    double tx = 0.0;  // centre of the region pixels' bounding box
    double ty = 0.0;
    double a = 0.0;   // half diagonal
    double an = 0.5;  // polynomial scale: max(a, 0.5)
    int minx = 0, miny = 0, maxx = 0, maxy = 0;
};

BoxGeo geometry(const TileInfo& t) {
    BoxGeo g;
    g.minx = t.minx;
    g.miny = t.miny;
    g.maxx = t.maxx;
    g.maxy = t.maxy;
    g.tx = 0.5 * (static_cast<double>(t.minx) + t.maxx);
    g.ty = 0.5 * (static_cast<double>(t.miny) + t.maxy);
    g.a = 0.5 *
          std::hypot(static_cast<double>(t.maxx - t.minx), static_cast<double>(t.maxy - t.miny)) *
          (1.0 + 1e-15);
    g.an = std::max(g.a, 0.5);
    return g;
}

struct Cand {
    int node = 0;
    double R = 0.0;     // centre distance
    double q = 0.0;     // (a + s) / R
    double mind = 1.0;  // lower bound of pixel-point distances (>= 1)
    double maxd = 1.0;  // upper bound
};

Cand makeCand(int node, const SrcNode& c, const BoxGeo& g) {
    Cand k;
    k.node = node;
    k.R = std::sqrt((g.tx - c.cx) * (g.tx - c.cx) + (g.ty - c.cy) * (g.ty - c.cy));
    const double rho = g.a + c.s;
    k.q = k.R > 0.0 ? rho / k.R : std::numeric_limits<double>::infinity();
    const double gx = std::max({0, c.bx0 - g.maxx, g.minx - c.bx1});
    const double gy = std::max({0, c.by0 - g.maxy, g.miny - c.by1});
    const double hx = std::max(std::abs(c.bx1 - g.minx), std::abs(g.maxx - c.bx0));
    const double hy = std::max(std::abs(c.by1 - g.miny), std::abs(g.maxy - c.by0));
    // distinct integer points are >= 1 apart (void pixels are never contour pixels)
    k.mind = std::max({1.0, std::sqrt(gx * gx + gy * gy), (k.R - rho) * (1.0 - 1e-14)});
    k.maxd = std::max(k.mind, std::min(std::sqrt(hx * hx + hy * hy), (k.R + rho) * (1.0 + 1e-14)));
    return k;
}

struct BoxState {
    int level = 0;
    int ix = 0;
    int iy = 0;
    // source nodes still to place and the parent's local expansion: the
    // parent's own (listRef / locRef, depth-first recursion: no copies) or,
    // for parallel tasks, owned copies (list / loc)
    const std::vector<int>* listRef = nullptr;
    const Local* locRef = nullptr;
    std::vector<int> list;
    bool hasLocal = false;
    std::unique_ptr<Local> loc;
    double lx = 0.0, ly = 0.0, la = 1.0;  // centre / scale of loc
    double S = 1.0;                       // scale: loc, E, Dlo, W hold true values times S^p
    double E = 0.0;    // bound of sum_i dz_i |remainder_i| (the z' error is E / D)
    double Dlo = 0.0;  // lower bound of D from the placed clusters
    double W = 0.0;    // bound of the weights in the expansion (round-off bound)
    double Sacc = std::numeric_limits<double>::infinity();  // distance bound to placed clusters
    double Sexp = std::numeric_limits<double>::infinity();  // ... to expanded clusters
};

struct Region {
    const PowerTables* tab = nullptr;
    const MomentLayout* lay = nullptr;
    SourceTree tree;
    ImageView<const std::int32_t> labels;
    ImageView<float> out;
    std::int32_t id = 0;
    int rx0 = 0, ry0 = 0, rx1 = 0, ry1 = 0;
    std::vector<std::vector<TileInfo>> lv;
    std::vector<int> lvNx;
    std::vector<int> lvNy;
    double n = 0.0;
    double zref = 0.0;   // float value, as double
    double zminH = 0.0;  // zmin - zref, zmax - zref (of the stored float z - zref)
    double zmaxH = 0.0;
    float zminOut = 0.0F;  // clamp range of the output
    float zmaxOut = 0.0F;
    double dz = 0.0;  // zmaxH - zminH
    double tol = 0.0;
    double tolA = 0.0;    // a-priori budget
    double deltaW = 0.0;  // relative error bound of one kernel weight
    KernelPower kp;
    std::stop_token stop;
};

constexpr double kLambda = 0.5;

__attribute__((noinline)) float exactPixel(const Region& rg, int x, int y) {
    double dmin2 = std::numeric_limits<double>::infinity();
    for (const Point& q : rg.tree.pts) {
        const double dx = static_cast<double>(x) - q.x;
        const double dy = static_cast<double>(y) - q.y;
        dmin2 = std::min(dmin2, dx * dx + dy * dy);
    }
    dmin2 = std::max(dmin2, 1e-300);
    double D = 0.0;
    double N = 0.0;
    for (const Point& q : rg.tree.pts) {
        const double dx = static_cast<double>(x) - q.x;
        const double dy = static_cast<double>(y) - q.y;
        const double d2 = std::max(dx * dx + dy * dy, 1e-300);
        const double w = rg.tab->pw(dmin2 / d2);
        D += w;
        N += w * static_cast<double>(q.z);
    }
    const double z = rg.zref + N / D;
    return std::clamp(static_cast<float>(z), rg.zminOut, rg.zmaxOut);
}

void evalLeaf(const Region& rg, const BoxState& st, const BoxGeo& geo,
              const std::vector<int>& nearNodes, bool hasLocal, const Local& loc, double S,
              double E, double W, double Sexp) {
    const PowerTables& tab = *rg.tab;
    const int X0 = rg.rx0 + st.ix * kLeafTile;
    const int Y0 = rg.ry0 + st.iy * kLeafTile;
    const int cols = std::min(kLeafTile, rg.rx1 - X0);
    const int rows = std::min(kLeafTile, rg.ry1 - Y0);
    std::uint32_t rowMask = 0;
    for (int r = 0; r < rows; ++r) {
        const std::int32_t* lab = rg.labels.row(Y0 + r) + X0;
        for (int c = 0; c < cols; ++c) {
            if (lab[c] == rg.id) {
                rowMask |= 1U << r;
                break;
            }
        }
    }
    // near points, relative to the tile origin
    std::size_t K = 0;
    for (int nd : nearNodes) {
        K += static_cast<std::size_t>(rg.tree.nodes[static_cast<std::size_t>(nd)].count());
    }
    thread_local std::vector<float> px;  // scratch, reused by every leaf of this thread
    thread_local std::vector<float> py;
    thread_local std::vector<float> pz;
    if (px.size() < K) {
        px.resize(K);
        py.resize(K);
        pz.resize(K);
    }
    double dbm2 = std::numeric_limits<double>::infinity();  // nearest point to the pixel box
    std::size_t k = 0;
    for (int nd : nearNodes) {
        const SrcNode& c = rg.tree.nodes[static_cast<std::size_t>(nd)];
        for (int i = c.begin; i < c.end; ++i) {
            const Point& q = rg.tree.pts[static_cast<std::size_t>(i)];
            px[k] = static_cast<float>(q.x - X0);
            py[k] = static_cast<float>(q.y - Y0);
            pz[k] = q.z;
            ++k;
            const double gx = std::max({0, q.x - geo.maxx, geo.minx - q.x});
            const double gy = std::max({0, q.y - geo.maxy, geo.miny - q.y});
            dbm2 = std::min(dbm2, gx * gx + gy * gy);
        }
    }
    const int deg = tab.degree;
    std::array<double, kS * kS> cD{};
    std::array<double, kS * kS> cN{};
    double sumD = 0.0;
    double sumN = 0.0;
    if (hasLocal) {
        localToPoly(loc.d, deg, tab, cD);
        localToPoly(loc.n, deg, tab, cN);
        for (int i = 0; i < kS * kS; ++i) {
            sumD += std::abs(cD[static_cast<std::size_t>(i)]);
            sumN += std::abs(cN[static_cast<std::size_t>(i)]);
        }
    }
    const double diag = std::hypot(static_cast<double>(geo.maxx - geo.minx),
                                   static_cast<double>(geo.maxy - geo.miny));
    const bool tileMode = K > 0 && tab.p * std::log2((std::sqrt(dbm2) + diag + 1.0) / S) <= 60.0;
    const double gammaK = (static_cast<double>(K) + 8.0) * kU * 1.01;
    const double gammaPoly = (3.0 * deg + 12.0) * kU * 1.01;
    const double deltaAll = rg.deltaW * (tileMode ? 1.0 : 2.0);
    const double tolRem = rg.tol * (1.0 - 1e-6) - rg.dz * (deltaAll + gammaK) - 16.0 * kU;
    const double farArith =
        gammaPoly * (sumN + (0.5 * rg.dz + kU) * sumD) + 1e-11 * W * (1.0 + rg.dz);
    // coefficients below float's normal range lose at most 2^-149 each (<= 169 of them)
    constexpr double kUnderflow = 1e-40;

    LeafKernelArgs a;
    a.rows = rows;
    a.rowMask = rowMask;
    a.px = px.data();
    a.py = py.data();
    a.pz = pz.data();
    a.count = static_cast<int>(K);
    a.zref = static_cast<float>(rg.zref);
    a.zmin = rg.zminOut;
    a.zmax = rg.zmaxOut;
    a.power = rg.kp;
    a.tolRemaining = static_cast<float>(tolRem);
    std::array<float, kS * kS> fD{};
    std::array<float, kS * kS> fN{};
    bool allFail = tolRem <= 0.0;
    double polyScale = 1.0;
    if (tileMode) {
        a.perPixel = false;
        a.s2 = static_cast<float>(S * S);
        // (1 + p u): the near weights use S^2 rounded to float
        a.errAbs = static_cast<float>((E + farArith) * (1.0 + 1e-6 + tab.p * kU) + kUnderflow);
    } else {
        a.perPixel = true;
        if (hasLocal) {
            polyScale = tab.pw((Sexp * Sexp) / (S * S));
            a.s2 = static_cast<float>(Sexp * Sexp);
            if (!std::isfinite(polyScale) || !std::isfinite(a.s2)) {
                allFail = true;
            }
        } else {
            a.s2 = std::numeric_limits<float>::infinity();
        }
        a.farArith = static_cast<float>(farArith * polyScale * (1.0 + 1e-6) + kUnderflow);
        if (!std::isfinite(a.farArith)) {
            allFail = true;
        }
        const double margin = 1e-4 + tab.halfP * 4e-6;
        a.log2DzE = E > 0.0 ? static_cast<float>(std::log2(E) + margin) : -1000.0F;
        a.log2LeafS2 = static_cast<float>(std::log2(S * S));
    }
    if (hasLocal && (sumD + sumN) * polyScale > 1e30) {
        allFail = true;  // would not fit in float (not seen in practice): be exact
    }
    if (hasLocal) {
        a.degree = deg;
        for (int i = 0; i < kS * kS; ++i) {
            fD[static_cast<std::size_t>(i)] =
                static_cast<float>(cD[static_cast<std::size_t>(i)] * polyScale);
            fN[static_cast<std::size_t>(i)] =
                static_cast<float>(cN[static_cast<std::size_t>(i)] * polyScale);
        }
        a.polyD = fD.data();
        a.polyN = fN.data();
        a.tu = static_cast<float>(geo.tx - X0);
        a.tv = static_cast<float>(geo.ty - Y0);
        a.invA = static_cast<float>(1.0 / geo.an);
    }
    std::array<float, kLeafTile * kLeafTile> z{};
    std::array<std::uint32_t, kLeafTile> fail{};
    if (!allFail) {
        leafKernel(a, z.data(), fail.data());
    }
    // Safety net: when many pixels of the tile fail the check, evaluate the whole
    // tile exactly (every contour point of the region, no expansion) with the
    // kernel before falling back to the per-pixel double-precision sum.
    std::array<float, kLeafTile * kLeafTile> z2{};
    std::array<std::uint32_t, kLeafTile> fail2{};
    bool haveExactTile = false;
    {
        int nFail = 0;
        for (int r = 0; r < rows; ++r) {
            if (((rowMask >> r) & 1U) == 0) {
                continue;
            }
            const std::int32_t* lab = rg.labels.row(Y0 + r) + X0;
            for (int c = 0; c < cols; ++c) {
                nFail += (lab[c] == rg.id &&
                          (allFail || ((fail[static_cast<std::size_t>(r)] >> c) & 1U) != 0))
                             ? 1
                             : 0;
            }
        }
        const double nAll = rg.n;
        const double tolAll = rg.tol * (1.0 - 1e-6) -
                              rg.dz * (2.0 * rg.deltaW + (nAll + 8.0) * kU * 1.01) - 16.0 * kU;
        if (nFail > 16 && tolAll > 0.0 && nAll < 1e7) {
            thread_local std::vector<float> ax;
            thread_local std::vector<float> ay;
            thread_local std::vector<float> az;
            const std::size_t nn = rg.tree.pts.size();
            ax.resize(nn);
            ay.resize(nn);
            az.resize(nn);
            for (std::size_t i = 0; i < nn; ++i) {
                const Point& q = rg.tree.pts[i];
                ax[i] = static_cast<float>(q.x - X0);
                ay[i] = static_cast<float>(q.y - Y0);
                az[i] = q.z;
            }
            LeafKernelArgs b = a;
            b.px = ax.data();
            b.py = ay.data();
            b.pz = az.data();
            b.count = static_cast<int>(nn);
            b.degree = -1;
            b.perPixel = true;
            b.s2 = std::numeric_limits<float>::infinity();
            b.farArith = 0.0F;
            b.log2DzE = -1000.0F;
            b.tolRemaining = static_cast<float>(tolAll);
            leafKernel(b, z2.data(), fail2.data());
            haveExactTile = true;
            tlStats.exactTiles += 1;
        }
    }
    std::int64_t pixels = 0;
    std::int64_t fallbacks = 0;
    for (int r = 0; r < rows; ++r) {
        if (((rowMask >> r) & 1U) == 0) {
            continue;
        }
        const std::int32_t* lab = rg.labels.row(Y0 + r) + X0;
        float* o = rg.out.row(Y0 + r) + X0;
        for (int c = 0; c < cols; ++c) {
            if (lab[c] != rg.id) {
                continue;
            }
            ++pixels;
            if (allFail || ((fail[static_cast<std::size_t>(r)] >> c) & 1U) != 0) {
                ++fallbacks;
                if (haveExactTile && ((fail2[static_cast<std::size_t>(r)] >> c) & 1U) == 0) {
                    o[c] = z2[static_cast<std::size_t>(r * kLeafTile + c)];
                } else {
                    o[c] = exactPixel(rg, X0 + c, Y0 + r);
                }
            } else {
                o[c] = z[static_cast<std::size_t>(r * kLeafTile + c)];
            }
        }
    }
    LocalStats& s = tlStats;
    s.pixels += pixels;
    s.fallbackPixels += fallbacks;
    s.leaves += 1;
    s.nearPairs += static_cast<std::int64_t>(K) * std::popcount(rowMask);
    if (!tileMode) {
        s.perPixelLeaves += 1;
    }
}

void processBox(const Region& rg, BoxState& st, std::vector<BoxState>* tasks, int taskLevel) {
    const TileInfo& ti = rg.lv[static_cast<std::size_t>(st.level)][static_cast<std::size_t>(
        st.iy * rg.lvNx[static_cast<std::size_t>(st.level)] + st.ix)];
    if (ti.count == 0) {
        return;
    }
    if (rg.stop.stop_requested()) {
        throw CancelledError();
    }
    const PowerTables& tab = *rg.tab;
    const SourceTree& tree = rg.tree;
    const BoxGeo geo = geometry(ti);
    const bool leaf = st.level == 0;

    // 1. Clusters larger than the box are split (the "split the larger" rule).
    // Scratch reused by every box of this thread (used before the recursion only).
    thread_local std::vector<Cand> cands;
    thread_local std::vector<int> stack;
    thread_local std::vector<double> wLo;
    thread_local std::vector<int> nearNodes;
    cands.clear();
    {
        const std::vector<int>& list = st.listRef != nullptr ? *st.listRef : st.list;
        stack.assign(list.rbegin(), list.rend());
        while (!stack.empty()) {
            const int nd = stack.back();
            stack.pop_back();
            const SrcNode& c = tree.nodes[static_cast<std::size_t>(nd)];
            if (c.child >= 0 && c.s > geo.a) {
                stack.push_back(c.child + 1);
                stack.push_back(c.child);
            } else {
                cands.push_back(makeCand(nd, c, geo));
            }
        }
    }
    // 2. Scale of this box: a lower bound of every pixel-point distance.
    double S = st.Sacc;
    for (const Cand& c : cands) {
        S = std::min(S, c.mind);
    }
    if (!std::isfinite(S)) {
        S = 1.0;
    }
    S = std::max(S, 1.0);
    const double f = S == st.S ? 1.0 : tab.pw((S * S) / (st.S * st.S));
    double E = st.E * f;
    double Dlo = st.Dlo * f;
    double W = st.W * f;
    Local loc;
    bool hasLocal = st.hasLocal;
    if (hasLocal) {
        shiftLocal(st.locRef != nullptr ? *st.locRef : *st.loc, loc, tab.degree, tab, st.lx, st.ly,
                   st.la, geo.tx, geo.ty, geo.an, f);
    }
    // 3. Lower bound of D over the box from the whole partition.
    const std::size_t nInitial = cands.size();
    wLo.resize(nInitial);
    double DloBox = Dlo;
    for (std::size_t k = 0; k < nInitial; ++k) {
        const Cand& c = cands[k];
        wLo[k] = tab.pw((S * S) / (c.maxd * c.maxd)) * (1.0 - 1e-9);
        DloBox += tree.nodes[static_cast<std::size_t>(c.node)].count() * wLo[k];
    }
    // 4. Place every cluster: drop, expand, defer, split or evaluate exactly.
    double DloAcc = 0.0;
    double Sacc = st.Sacc;
    double Sexp = st.Sexp;
    std::vector<int> deferred;
    nearNodes.clear();
    std::int64_t nM2l = 0;
    std::int64_t nDrop = 0;
    for (std::size_t k = 0; k < cands.size(); ++k) {
        const Cand c = cands[k];
        const SrcNode& nd = tree.nodes[static_cast<std::size_t>(c.node)];
        const double nC = nd.count();
        const double lo =
            k < nInitial ? wLo[k] : tab.pw((S * S) / (c.maxd * c.maxd)) * (1.0 - 1e-9);
        const double dzC = std::max(static_cast<double>(nd.zmax) - rg.zminH,
                                    rg.zmaxH - static_cast<double>(nd.zmin));
        const double budget = rg.tolA * (kLambda * lo + (1.0 - kLambda) * DloBox / rg.n);
        const double hi = tab.pw((S * S) / (c.mind * c.mind)) * (1.0 + 1e-9);
        if (dzC * hi <= budget) {
            E += nC * dzC * hi;
            DloAcc += nC * lo;
            Sacc = std::min(Sacc, c.mind);
            ++nDrop;
            continue;
        }
        int mo = -1;
        double tau = 0.0;
        double wR = 0.0;
        if (c.q < 1.0) {
            wR = tab.pw((S * S) / (c.R * c.R)) * (1.0 + 1e-9);
            mo = tab.chooseOrder(c.q, budget / (dzC * wR), tau);
            if (mo >= 0 && leaf) {
                // measured: ~1.2 (mo+1)(mo+2)(mo+3) cycles per translation against
                // ~0.3 cycles per pixel and point in the kernel
                const double costM2l = 1.2 * (mo + 1) * (mo + 2) * (mo + 3);
                const double costExact = nC * (16.0 * (ti.maxy - ti.miny + 1)) * 0.3;
                if (costExact < costM2l) {
                    mo = -1;
                }
            }
        }
        if (mo >= 0) {
            const std::size_t mc = static_cast<std::size_t>(rg.lay->count);
            const std::size_t off = static_cast<std::size_t>(c.node) * mc;
            m2l(loc, mo, tab, *rg.lay, &tree.momD[off], &tree.momN[off], nd, geo.tx, geo.ty, geo.an,
                c.R, wR);
            hasLocal = true;
            E += nC * dzC * wR * tau;
            W += nC * wR * tab.pw(1.0 / ((1.0 - c.q) * (1.0 - c.q)));
            DloAcc += nC * lo;
            Sacc = std::min(Sacc, c.mind);
            Sexp = std::min(Sexp, c.mind);
            ++nM2l;
            continue;
        }
        if (!leaf) {
            deferred.push_back(c.node);
            continue;
        }
        if (nd.child >= 0) {
            cands.push_back(
                makeCand(nd.child, tree.nodes[static_cast<std::size_t>(nd.child)], geo));
            cands.push_back(
                makeCand(nd.child + 1, tree.nodes[static_cast<std::size_t>(nd.child + 1)], geo));
            continue;
        }
        nearNodes.push_back(c.node);
    }
    tlStats.m2l += nM2l;
    tlStats.dropped += nDrop;
    if (leaf) {
        evalLeaf(rg, st, geo, nearNodes, hasLocal, loc, S, E, W, Sexp);
        return;
    }
    // 5. Children.
    for (int dy = 0; dy < 2; ++dy) {
        for (int dx = 0; dx < 2; ++dx) {
            const int cx = st.ix * 2 + dx;
            const int cy = st.iy * 2 + dy;
            const std::size_t cl = static_cast<std::size_t>(st.level - 1);
            if (cx >= rg.lvNx[cl] || cy >= rg.lvNy[cl]) {
                continue;
            }
            if (rg.lv[cl][static_cast<std::size_t>(cy * rg.lvNx[cl] + cx)].count == 0) {
                continue;
            }
            BoxState ch;
            ch.level = st.level - 1;
            ch.ix = cx;
            ch.iy = cy;
            ch.hasLocal = hasLocal;
            const bool task = tasks != nullptr && ch.level == taskLevel;
            if (task) {
                ch.list = deferred;
                if (hasLocal) {
                    ch.loc = std::make_unique<Local>(loc);
                }
            } else {
                ch.listRef = &deferred;
                ch.locRef = &loc;
            }
            ch.lx = geo.tx;
            ch.ly = geo.ty;
            ch.la = geo.an;
            ch.S = S;
            ch.E = E;
            ch.Dlo = Dlo + DloAcc;
            ch.W = W;
            ch.Sacc = Sacc;
            ch.Sexp = Sexp;
            if (task) {
                tasks->push_back(std::move(ch));
            } else {
                processBox(rg, ch, tasks, taskLevel);
            }
        }
    }
}

// ---------------------------------------------------------------- the solver
class FastSolver final : public Solver {
  public:
    explicit FastSolver(const SolverOptions& o) : options_(o), tab_(o.p), lay_(tab_.degree) {
        const double halfP = o.p / 2.0;
        kp_.halfP = static_cast<float>(halfP);
        kp_.squarings = -1;
        for (int e = 0; e <= 5; ++e) {
            if (halfP == static_cast<double>(1 << e)) {
                kp_.squarings = e;
            }
        }
        if (kp_.squarings >= 0) {
            // S^2, d^2 (above 2^24), d2a * d2b, the division, the product with
            // d2b: <= 6 roundings in r, amplified by the squarings, plus theirs
            deltaW_ = (8.0 * halfP + 8.0) * kU * 1.01;
        } else {
            deltaW_ = (0.7 * (halfP * (2.0 * kKernelLog2Error + 2.0 * kU) + 260.0 * kU) +
                       kKernelExp2Error) *
                      1.1;
        }
    }

    void solveRegion(ImageView<const std::int32_t> labels, const VoidRegion& region,
                     ImageView<float> out, const std::stop_token& stop) const override;

    [[nodiscard]] double errorBound() const noexcept override { return options_.tolerance; }

  private:
    SolverOptions options_;
    PowerTables tab_;
    MomentLayout lay_;
    KernelPower kp_;
    double deltaW_ = 0.0;
    double budgetScale_ = gBudgetScale.load();
};

void FastSolver::solveRegion(ImageView<const std::int32_t> labels, const VoidRegion& region,
                             ImageView<float> out, const std::stop_token& stop) const {
    if (stop.stop_requested()) {
        throw CancelledError();
    }
    if (labels.width() != out.width() || labels.height() != out.height()) {
        throw InvalidArgumentError("fast VSS solver: label and output images differ in size");
    }
    const int x0 = std::max(0, region.x0);
    const int y0 = std::max(0, region.y0);
    const int x1 = std::min(labels.width(), region.x1);
    const int y1 = std::min(labels.height(), region.y1);
    if (x1 <= x0 || y1 <= y0) {
        return;
    }
    const std::int32_t id = region.id;
    auto fill = [&](float v) {
        for (int y = y0; y < y1; ++y) {
            const std::int32_t* lab = labels.row(y);
            float* o = out.row(y);
            for (int x = x0; x < x1; ++x) {
                if (lab[x] == id) {
                    o[x] = v;
                }
            }
        }
    };
    if (region.contour.empty()) {
        fill(std::numeric_limits<float>::quiet_NaN());
        return;
    }
    float zmin = std::numeric_limits<float>::infinity();
    float zmax = -zmin;
    for (const ContourPoint& c : region.contour) {
        if (!std::isfinite(c.z)) {
            throw InvalidArgumentError("fast VSS solver: non-finite contour depth");
        }
        if (c.x >= 0 && c.y >= 0 && c.x < labels.width() && c.y < labels.height() &&
            labels(c.x, c.y) == id) {
            throw InvalidArgumentError(
                "fast VSS solver: a contour point lies inside its void region");
        }
        zmin = std::min(zmin, c.z);
        zmax = std::max(zmax, c.z);
    }
    const float zref = zmin + 0.5F * (zmax - zmin);
    const double tol = options_.tolerance;
    const double halfRange =
        std::max(static_cast<double>(zmax) - zref, zref - static_cast<double>(zmin));
    if (halfRange <= tol * (1.0 - 1e-6) - 4.0 * kU) {
        fill(zref);  // every convex combination is within tol of the mid-range
        return;
    }

    Region rg;
    rg.tab = &tab_;
    rg.lay = &lay_;
    rg.labels = labels;
    rg.out = out;
    rg.id = id;
    rg.rx0 = x0;
    rg.ry0 = y0;
    rg.rx1 = x1;
    rg.ry1 = y1;
    rg.stop = stop;
    rg.kp = kp_;
    rg.deltaW = deltaW_;
    rg.tol = tol;
    rg.zref = zref;
    rg.zminOut = zmin;
    rg.zmaxOut = zmax;
    // Source tree.
    rg.tree.pts.resize(region.contour.size());
    double zminH = std::numeric_limits<double>::infinity();
    double zmaxH = -zminH;
    for (std::size_t i = 0; i < region.contour.size(); ++i) {
        const ContourPoint& c = region.contour[i];
        const float zh = c.z - zref;
        rg.tree.pts[i] = {c.x, c.y, zh};
        zminH = std::min(zminH, static_cast<double>(zh));
        zmaxH = std::max(zmaxH, static_cast<double>(zh));
    }
    rg.zminH = zminH;
    rg.zmaxH = zmaxH;
    rg.dz = zmaxH - zminH;
    rg.n = static_cast<double>(rg.tree.pts.size());
    rg.tolA = (0.75 * tol - rg.dz * (2.0 * deltaW_ + 2048.0 * kU)) * budgetScale_;
    rg.tree.nodes.reserve(4 * rg.tree.pts.size() / kLeafPoints + 4);
    SrcNode root;
    root.begin = 0;
    root.end = static_cast<int>(rg.tree.pts.size());
    rg.tree.nodes.push_back(root);
    buildNode(rg.tree, 0);
    buildMoments(rg.tree, lay_, tab_);

    // Target boxes: leaf tiles of 16 x 16 pixels and a quadtree above them.
    const int nx0 = (x1 - x0 + kLeafTile - 1) / kLeafTile;
    const int ny0 = (y1 - y0 + kLeafTile - 1) / kLeafTile;
    rg.lv.emplace_back(static_cast<std::size_t>(nx0) * static_cast<std::size_t>(ny0));
    rg.lvNx.push_back(nx0);
    rg.lvNy.push_back(ny0);
    for (int y = y0; y < y1; ++y) {
        const std::int32_t* lab = labels.row(y);
        const int ty = (y - y0) / kLeafTile;
        for (int tx = 0; tx < nx0; ++tx) {
            const int xa = x0 + tx * kLeafTile;
            const int xb = std::min(x1, xa + kLeafTile);
            int cnt = 0;
            for (int x = xa; x < xb; ++x) {
                cnt += lab[x] == id ? 1 : 0;
            }
            if (cnt == 0) {
                continue;
            }
            int first = xa;
            while (lab[first] != id) {
                ++first;
            }
            int last = xb - 1;
            while (lab[last] != id) {
                --last;
            }
            TileInfo& t = rg.lv[0][static_cast<std::size_t>(ty * nx0 + tx)];
            t.count += cnt;
            t.minx = std::min(t.minx, first);
            t.maxx = std::max(t.maxx, last);
            t.miny = std::min(t.miny, y);
            t.maxy = std::max(t.maxy, y);
        }
    }
    while (rg.lvNx.back() > 1 || rg.lvNy.back() > 1) {
        const std::size_t l = rg.lv.size() - 1;
        const int nx = (rg.lvNx[l] + 1) / 2;
        const int ny = (rg.lvNy[l] + 1) / 2;
        std::vector<TileInfo> up(static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny));
        for (int j = 0; j < rg.lvNy[l]; ++j) {
            for (int i = 0; i < rg.lvNx[l]; ++i) {
                const TileInfo& t = rg.lv[l][static_cast<std::size_t>(j * rg.lvNx[l] + i)];
                if (t.count > 0) {
                    up[static_cast<std::size_t>((j / 2) * nx + i / 2)].add(t);
                }
            }
        }
        rg.lv.push_back(std::move(up));
        rg.lvNx.push_back(nx);
        rg.lvNy.push_back(ny);
    }
    const int top = static_cast<int>(rg.lv.size()) - 1;
    if (rg.lv[static_cast<std::size_t>(top)][0].count == 0) {
        return;
    }
    BoxState root0;
    root0.level = top;
    root0.list.push_back(0);
    // Parallel over boxes of 64 x 64 pixels (level 2) for large regions.
    const int taskLevel = (region.pixelCount >= 8192 && top > 2) ? 2 : -1;
    const StatsFlush flushThis;
    if (taskLevel < 0) {
        processBox(rg, root0, nullptr, -1);
        return;
    }
    std::vector<BoxState> tasks;
    processBox(rg, root0, &tasks, taskLevel);
    parallelFor(
        0, static_cast<long>(tasks.size()), 1,
        [&](long b, long e) {
            const StatsFlush flushTask;
            for (long i = b; i < e; ++i) {
                processBox(rg, tasks[static_cast<std::size_t>(i)], nullptr, -1);
            }
        },
        stop);
}

}  // namespace

FastSolverStats fastSolverStats() {
    const AtomicStats& s = stats();
    FastSolverStats r;
    r.pixels = s.pixels.load();
    r.fallbackPixels = s.fallbackPixels.load();
    r.leaves = s.leaves.load();
    r.nearPairs = s.nearPairs.load();
    r.m2l = s.m2l.load();
    r.dropped = s.dropped.load();
    r.perPixelLeaves = s.perPixelLeaves.load();
    r.exactTiles = s.exactTiles.load();
    return r;
}

void resetFastSolverStats() {
    AtomicStats& s = stats();
    s.pixels = 0;
    s.fallbackPixels = 0;
    s.leaves = 0;
    s.nearPairs = 0;
    s.m2l = 0;
    s.dropped = 0;
    s.perPixelLeaves = 0;
    s.exactTiles = 0;
}

void setFastSolverBudgetScaleForTesting(double scale) {
    gBudgetScale = scale;
}

std::unique_ptr<Solver> makeFastSolver(const SolverOptions& options) {
    if (!(options.p > 0.0) || !std::isfinite(options.p)) {
        throw InvalidArgumentError("fast VSS solver: p must be positive and finite");
    }
    if (!(options.tolerance > 0.0) || !std::isfinite(options.tolerance)) {
        throw InvalidArgumentError("fast VSS solver: tolerance must be positive and finite");
    }
    return std::make_unique<FastSolver>(options);
}

}  // namespace vv::vss::detail
