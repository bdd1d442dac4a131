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
//     DISTANCE TABLE (FastTables.h): pixels and contour points lie on the
//     integer lattice, so the weight of a point at a tile row's 16 pixels is 16
//     consecutive entries of a table of d^-p over the offsets |dx|, |dy| <= 128
//     (+15), fetched when the solver is made and kept for the process per p
//     (p <= ~12: its far entries must stay normal floats). A tile in tile
//     mode reads the weights of its near points within the table there (one
//     load per point and row instead of a division's share, the squarings or
//     log2 / exp2) and computes the others with S = 1, so the whole tile
//     (polynomial, E) is in absolute scale. Each entry is pw(1/d^2) rounded
//     once: relative error <= u + 1e-13, within delta_w below. Measured: the
//     near sums 38 -> 23 % of a p = 8 solve (docs/benchmarks/vss.md, "Part 2,
//     third step").
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
// COARSE BOXES (FastCoarse.cpp; issue 19: cost growing slower than the
// screen). z' is smooth away from the contours, and at 4K most void pixels
// are far from them. A box of level 1 or 2 (32 or 64 pixels) that passes no
// cluster on to its children (every cluster expanded or dropped: the box sees
// only its local expansion) is evaluated on a grid of 16 x 16 samples with
// spacing h = (longer side of its pixels' bounding box) / 15, centred on the
// box, by the leaf kernel (no near points; it returns the float sums D~, N~),
// and each pixel gets the bilinear interpolation of F~ = N~ / D~ there. The
// error at a region pixel x, with P_D, P_N the polynomials and F = P_N / P_D:
//     |I F~ - z'| <= |I (F~ - F)| + |I F - F| + |F(x) - z'(x)|
//                 <= farArith / Dlow + (h^2 / 8)(max|F_xx| + max|F_yy|) + E / Dlow,
// I bilinear on the cell of x (convex weights; the second term is the
// tensor-product interpolation error of a C^2 function), Dlow a lower bound
// of P_D over the sample square: min over the samples of D~, less the
// evaluation round-off, less (h^2/8)(max|D_xx| + max|D_yy|) (P_D's own
// interpolation error). The derivative bounds come from the coefficients
// c_ij of the polynomials in u = (x - t)/a, v (|u|, |v| <= 1 on the square):
// |P| <= sum |c_ij|, |P_x| <= sum i |c_ij| / a, |P_xx| <= sum i(i-1) |c_ij| / a^2,
// and with |F| <= sum |c^N_ij| / Dlow =: Fb, F_x = (N_x - F D_x) / D,
// F_xx = (N_xx - 2 F_x D_x - F D_xx) / D:
//     |F_x| <= (|N_x| + Fb |D_x|) / Dlow =: G,  |F_xx| <= (|N_xx| + 2 G |D_x| + Fb |D_xx|) / Dlow.
// farArith is the leaf's polynomial round-off bound (FastLeaf.cpp) counted
// twice (the samples' evaluation and the coefficients' rounding to float).
// The box is taken only when the sum, with 16 u for the final roundings, is
// <= tol; the result is clamped to [zmin, zmax] like every pixel. Else (and
// for the a-priori skip: the bound with Dlow = P_D(centre) already too big)
// the traversal descends as before. Counters: coarseBoxes, coarsePixels
// (FastStats.h). Measured: the coarse path takes 19-62 % of the pixels at
// 3840x2160 for p = 2 and 4, fewer for p = 8 (whose bound needs the contours
// farther away); docs/benchmarks/vss.md, "Cost against image size".
//
// NEAR BOXES (FastNearBox.cpp; issue 19). In the band next to the contours
// a box of level 1 or 2 passes clusters on to its children, and its leaves
// pay M2L, L2L and near sums per pixel. When the nearest of those clusters'
// points is some pixels away, the box is evaluated on a grid of samples
// every 2-8 pixels, those points summed exactly at the samples and the rest
// through the box's expansion, and interpolated bilinearly, under a rigorous
// bound of the interpolation error from the points' distances rho_i, the
// LOCAL depth spread G = max |z_i - z_c| / rho_i^2 and p (second derivatives
// <= p (p + 1) w / rho^2), the polynomial's coefficients and the samples'
// round-off, plus E; every pixel is checked, else the traversal descends.
// Optionally (off by default: no faster at these box sizes, measured in
// docs/benchmarks/vss.md "Fourth step") the clusters a near box would pass on
// are first split at the box like at a leaf (tryNearBox): the parts far enough
// are expanded into a copy of its expansion (their truncation added to E,
// which the check charges), so only the points near the box are summed.
// Counters: nearBoxes, nearBoxPixels, nearBoxPoints (FastStats.h).
//
// BAND BOXES (FastBandBox.cpp; issue 19, part 3). A near box is all or
// nothing and needs its near points >= 4 pixels away, so a 32-pixel box with
// a contour inside or next to it went down to its leaf tiles whole, although
// most of its pixels lie tens of pixels from those points. For p <= 4
// (kBandMaxP; at p = 8 measured no faster) such a box of level 1 is, when
// the near box is not taken, evaluated on an adaptive grid: cells of 4, then 2
// pixels, each checked with a bound whose near part comes from sums computed
// at the samples (A = sum w / d^2, T = sum w |z - c| / d^2, and the nearest
// point's distance); cells that fail are split, and the pixels of failing
// cells of 2 are summed exactly (the box's near points and its expansion,
// the leaf's check, the exact fall-back). No leaf tile, M2L or L2L below it.
// Counters: bandBoxes, bandBoxPixels, bandExactPixels, bandSamples.
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
// FILES (namespace vv::vss::detail::fast). This file: the statistics, the
// traversal (step 3) and the solver (solveRegion); FastTables: the per-p
// tables (the series c_n, tau, chooseOrder, the weight pw); FastSourceTree:
// step 1; FastExpansion: M2L, L2L and the leaf polynomial; FastRegion.h: what
// the traversal and the leaves share; FastLeaf: step 4 with the check and the
// fall-backs; FastCoarse: the coarse boxes; FastNearBox: the near boxes; FastBandBox:
// the band boxes; FastPlace: placing clusters at a box; FastKernel: the SIMD kernel of
// step 4; FastPointKernel: the same sums one point per lane (band boxes);
// FastKernelSimd.h: their vector math; FastMath.h: the math.
//
#include "FastSolver.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <stop_token>
#include <utility>
#include <vector>

#include "FastBandBox.h"
#include "FastCoarse.h"
#include "FastCounters.h"
#include "FastExpansion.h"
#include "FastKernel.h"
#include "FastLeaf.h"
#include "FastNearBox.h"
#include "FastPlace.h"
#include "FastRegion.h"
#include "FastSourceTree.h"
#include "FastStats.h"
#include "FastTables.h"
#include "vv/core/Error.h"
#include "vv/core/Parallel.h"

namespace vv::vss::detail::fast {
namespace {

// ---------------------------------------------------------------- statistics
// Per-thread counters, added to the shared atomics once per task / region (atomic
// updates per leaf from both threads would bounce one cache line between the cores).
struct LocalStats {
    std::int64_t pixels = 0, fallbackPixels = 0, leaves = 0, nearPairs = 0, m2l = 0, dropped = 0,
                 perPixelLeaves = 0, exactTiles = 0, coarseBoxes = 0, coarsePixels = 0,
                 nearLeaves = 0, nearLeafPixels = 0, nearBoxes = 0, nearBoxPixels = 0,
                 nearBoxPoints = 0, bandBoxes = 0, bandBoxPixels = 0, bandExactPixels = 0,
                 bandSamples = 0, tableLeaves = 0, tablePairs = 0;
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
    s.coarseBoxes += l.coarseBoxes;
    s.coarsePixels += l.coarsePixels;
    s.nearLeaves += l.nearLeaves;
    s.nearLeafPixels += l.nearLeafPixels;
    s.tableLeaves += l.tableLeaves;
    s.tablePairs += l.tablePairs;
    s.nearBoxes += l.nearBoxes;
    s.nearBoxPixels += l.nearBoxPixels;
    s.nearBoxPoints += l.nearBoxPoints;
    s.bandBoxes += l.bandBoxes;
    s.bandBoxPixels += l.bandBoxPixels;
    s.bandExactPixels += l.bandExactPixels;
    s.bandSamples += l.bandSamples;
    l = LocalStats{};
}
struct StatsFlush {  // flushes on every exit, cancellation included
    StatsFlush() = default;
    StatsFlush(const StatsFlush&) = delete;
    StatsFlush& operator=(const StatsFlush&) = delete;
    ~StatsFlush() { flushStats(); }
};

// ---------------------------------------------------------------- traversal
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

// Cost of summing one point exactly at a near box's samples (at most 16 x 17
// of them; ~0.3 cycles per sample and point in the kernel, as the leaves').
constexpr double kNearBoxExactCost = 16.0 * 17.0 * 0.3;

// A near box (FastNearBox.h) of the given level: with rg.nearSplit, the
// clusters it would pass on are split at the box like at a leaf (expanded into
// a copy of its local expansion when far enough and cheaper than summing
// them at the samples, dropped when within the budget, their truncation
// charged to E), so that only the points near the box are summed at its
// samples; when none is left, the box is a coarse box (FastCoarse.h) of that
// expansion. Returns the pixels written (0: not taken; see evalNearBox).
std::int64_t tryNearBox(const Region& rg, int level, const BoxGeo& geo, double S, double DloBox,
                        const std::vector<int>& deferred, const Local* loc,
                        const LeafBounds& bounds) {
    const auto points = [&rg](const std::vector<int>& nodes) {
        std::int64_t n = 0;
        for (const int nd : nodes) {
            n += rg.tree.nodes[static_cast<std::size_t>(nd)].count();
        }
        return n;
    };
    if (!rg.nearSplit) {
        const std::int64_t written = evalNearBox(rg, geo, level, deferred, loc, bounds);
        tlStats.nearBoxPoints += written > 0 ? points(deferred) : 0;
        return written;
    }
    if (!nearBoxHasRoom(rg, geo, level, deferred)) {
        return 0;  // as without the split; spares the translations of a box not taken
    }
    thread_local std::vector<Cand> split;
    thread_local std::vector<int> nearPts;
    thread_local std::vector<int> none;  // stays empty: nothing is deferred in split mode
    split.clear();
    nearPts.clear();
    for (const int nd : deferred) {
        split.push_back(makeCand(nd, rg.tree.nodes[static_cast<std::size_t>(nd)], geo));
    }
    Local far = loc != nullptr ? *loc : Local{};
    Placed pl;
    pl.hasLocal = loc != nullptr;
    pl.E = bounds.E;
    pl.W = bounds.W;
    pl.Sexp = bounds.Sexp;
    placeClusters(rg, geo, S, DloBox, rg.nearSplitBudgetScale, split, {}, kNearBoxExactCost, far,
                  pl, none, nearPts);
    tlStats.m2l += pl.m2l;
    tlStats.dropped += pl.dropped;
    const LeafBounds b{S, pl.E, pl.W, pl.Sexp};
    if (nearPts.empty()) {
        return pl.hasLocal && level <= kCoarseMaxLevel ? evalCoarseBox(rg, geo, far, b) : 0;
    }
    const std::int64_t written =
        evalNearBox(rg, geo, level, nearPts, pl.hasLocal ? &far : nullptr, b);
    tlStats.nearBoxPoints += written > 0 ? points(nearPts) : 0;
    return written;
}

// Adds what a leaf tile did to this thread's counters.
void countLeaf(const LeafCounts& n, bool hasNearPoints) {
    LocalStats& s = tlStats;
    s.pixels += n.pixels;
    s.fallbackPixels += n.fallbackPixels;
    s.leaves += 1;
    s.nearPairs += n.nearPairs;
    s.perPixelLeaves += n.perPixel ? 1 : 0;
    s.exactTiles += n.exactTile ? 1 : 0;
    if (hasNearPoints) {
        s.nearLeaves += 1;
        s.nearLeafPixels += n.pixels;
        s.tableLeaves += n.tablePairs > 0 ? 1 : 0;
        s.tablePairs += n.tablePairs;
    }
}

// What a box hands its children: the clusters it deferred, its local
// expansion (centre tx, ty, scale an) and its bounds (BoxState).
struct Handed {
    const std::vector<int>* deferred = nullptr;
    const Local* loc = nullptr;
    bool hasLocal = false;
    double tx = 0.0, ty = 0.0, an = 1.0;
    double S = 1.0, E = 0.0, Dlo = 0.0, W = 0.0;
    double Sacc = 0.0, Sexp = 0.0;
};

// Processes the children of box st (level >= 1) with what it hands them; with
// tasks, those of taskLevel are queued there instead.
void processChildren(const Region& rg, const BoxState& st, const Handed& h,
                     std::vector<BoxState>* tasks, int taskLevel);

// Places the source clusters box st inherits (drop, expand, defer to the
// children, or near points of a leaf), then evaluates the leaf tile or
// recurses into the children; with tasks, the boxes of taskLevel are queued
// there instead. Throws CancelledError once rg.stop is requested.
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
    Placed pl;
    pl.hasLocal = hasLocal;
    pl.E = E;
    pl.W = W;
    pl.Sacc = st.Sacc;
    pl.Sexp = st.Sexp;
    std::vector<int> deferred;
    nearNodes.clear();
    const double exactCost = leaf ? 16.0 * (ti.maxy - ti.miny + 1) * 0.3 : -1.0;
    placeClusters(rg, geo, S, DloBox, 1.0, cands, wLo, exactCost, loc, pl, deferred, nearNodes);
    hasLocal = pl.hasLocal;
    E = pl.E;
    W = pl.W;
    const double DloAcc = pl.DloAcc;
    const double Sacc = pl.Sacc;
    const double Sexp = pl.Sexp;
    const std::int64_t nM2l = pl.m2l;
    const std::int64_t nDrop = pl.dropped;
    tlStats.m2l += nM2l;
    tlStats.dropped += nDrop;
    if (leaf) {
        countLeaf(evalLeaf(rg, st.ix, st.iy, geo, nearNodes, hasLocal ? &loc : nullptr,
                           LeafBounds{S, E, W, Sexp}),
                  !nearNodes.empty());
        return;
    }
    // 5. A box far from every contour point: a coarse grid when the bound allows.
    if (rg.coarse && st.level <= kCoarseMaxLevel && deferred.empty() && hasLocal) {
        const std::int64_t written = evalCoarseBox(rg, geo, loc, LeafBounds{S, E, W, Sexp});
        if (written > 0) {
            tlStats.coarseBoxes += 1;
            tlStats.coarsePixels += written;
            tlStats.pixels += written;
            return;
        }
    }
    // 5b. A box of the near band whose near points are some pixels away: a
    // grid with those points summed exactly, when the bound allows.
    if (rg.nearBoxesOn && st.level >= 1 && st.level <= kNearBoxMaxLevel && !deferred.empty()) {
        const std::int64_t written =
            tryNearBox(rg, st.level, geo, S, DloBox, deferred, hasLocal ? &loc : nullptr,
                       LeafBounds{S, E, W, Sexp});
        if (written > 0) {
            tlStats.nearBoxes += 1;
            tlStats.nearBoxPixels += written;
            tlStats.pixels += written;
            return;
        }
    }
    // 5c. Else, a box of 32 pixels of the near band (p <= kBandMaxP): an
    // adaptive grid, cell by cell (the near points summed exactly at the
    // samples and where a cell fails).
    if (rg.bandBoxesOn && st.level == 1 && !deferred.empty() && tab.p <= kBandMaxP) {
        const BandCounts n =
            evalBandBox(rg, geo, deferred, hasLocal ? &loc : nullptr, LeafBounds{S, E, W, Sexp});
        if (n.pixels > 0) {
            LocalStats& s = tlStats;
            s.bandBoxes += 1;
            s.bandBoxPixels += n.pixels;
            s.bandExactPixels += n.exactPixels;
            s.bandSamples += n.samples;
            s.fallbackPixels += n.fallbackPixels;
            s.pixels += n.pixels;
            return;
        }
    }
    // 6. Children.
    processChildren(rg, st,
                    Handed{&deferred, &loc, hasLocal, geo.tx, geo.ty, geo.an, S, E, Dlo + DloAcc, W,
                           Sacc, Sexp},
                    tasks, taskLevel);
}

void processChildren(const Region& rg, const BoxState& st, const Handed& h,
                     std::vector<BoxState>* tasks, int taskLevel) {
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
            ch.hasLocal = h.hasLocal;
            const bool task = tasks != nullptr && ch.level == taskLevel;
            if (task) {
                ch.list = *h.deferred;
                if (h.hasLocal) {
                    ch.loc = std::make_unique<Local>(*h.loc);
                }
            } else {
                ch.listRef = h.deferred;
                ch.locRef = h.loc;
            }
            ch.lx = h.tx;
            ch.ly = h.ty;
            ch.la = h.an;
            ch.S = h.S;
            ch.E = h.E;
            ch.Dlo = h.Dlo;
            ch.W = h.W;
            ch.Sacc = h.Sacc;
            ch.Sexp = h.Sexp;
            if (task) {
                tasks->push_back(std::move(ch));
            } else {
                processBox(rg, ch, tasks, taskLevel);
            }
        }
    }
}

// Target boxes of the region (rg: images, id and box set): leaf tiles of 16 x
// 16 pixels and a quadtree above them, each with its region pixels' count and
// bounding box (rg.lv, rg.lvNx, rg.lvNy).
void buildTargetBoxes(Region& rg) {
    const ImageView<const std::int32_t> labels = rg.labels;
    const std::int32_t id = rg.id;
    const int x0 = rg.rx0;
    const int y0 = rg.ry0;
    const int x1 = rg.rx1;
    const int y1 = rg.ry1;
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
    bool coarse_ = gCoarseBoxes.load();
    bool nearBoxes_ = gNearBoxes.load();
    bool nearSplit_ = gNearSplit.load();
    bool bandBoxes_ = gBandBoxes.load();
    double bandBoundScale_ = gBandBoundScale.load();
    double nearSplitBudgetScale_ = gNearSplitBudgetScale.load();
    // the leaves' weights by lattice offset (FastTables.h); nullptr: computed
    std::shared_ptr<const std::vector<float>> dist_ =
        gDistanceTable.load() ? distanceTable(tab_) : nullptr;
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
    rg.dist = dist_ != nullptr ? dist_->data() : nullptr;
    rg.coarse = coarse_;
    rg.nearBoxesOn = nearBoxes_;
    rg.nearSplit = nearSplit_;
    rg.bandBoxesOn = bandBoxes_;
    rg.bandBoundScale = bandBoundScale_;
    rg.nearSplitBudgetScale = nearSplitBudgetScale_;
    rg.budgetScale = budgetScale_;
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
    buildSourceTree(rg.tree, lay_, tab_);

    buildTargetBoxes(rg);
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
}  // namespace vv::vss::detail::fast

namespace vv::vss::detail {

std::unique_ptr<Solver> makeFastSolver(const SolverOptions& options) {
    if (!(options.p > 0.0) || !std::isfinite(options.p)) {
        throw InvalidArgumentError("fast VSS solver: p must be positive and finite");
    }
    if (!(options.tolerance > 0.0) || !std::isfinite(options.tolerance)) {
        throw InvalidArgumentError("fast VSS solver: tolerance must be positive and finite");
    }
    return std::make_unique<fast::FastSolver>(options);
}

}  // namespace vv::vss::detail
