// SPDX-License-Identifier: GPL-3.0-or-later
// Placing source clusters at a target box (FastPlace.h); the budget is the
// A-PRIORI BUDGET of the comment at the top of FastSolver.cpp.
#include "FastPlace.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "FastTables.h"

namespace vv::vss::detail::fast {
namespace {

constexpr double kLambda = 0.5;  // a cluster's budget: its own share (A-PRIORI BUDGET above)

}  // namespace

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

void placeClusters(const Region& rg, const BoxGeo& geo, double S, double DloBox, double budgetScale,
                   std::vector<Cand>& cands, const std::vector<double>& wLo, double exactCost,
                   Local& loc, Placed& pl, std::vector<int>& deferred,
                   std::vector<int>& nearNodes) {
    const PowerTables& tab = *rg.tab;
    const SourceTree& tree = rg.tree;
    const std::size_t nInitial = std::min(wLo.size(), cands.size());
    for (std::size_t k = 0; k < cands.size(); ++k) {
        const Cand c = cands[k];
        const SrcNode& nd = tree.nodes[static_cast<std::size_t>(c.node)];
        const double nC = nd.count();
        const double lo =
            k < nInitial ? wLo[k] : tab.pw((S * S) / (c.maxd * c.maxd)) * (1.0 - 1e-9);
        const double dzC = std::max(static_cast<double>(nd.zmax) - rg.zminH,
                                    rg.zmaxH - static_cast<double>(nd.zmin));
        const double budget =
            budgetScale * rg.tolA * (kLambda * lo + (1.0 - kLambda) * DloBox / rg.n);
        const double hi = tab.pw((S * S) / (c.mind * c.mind)) * (1.0 + 1e-9);
        if (dzC * hi <= budget) {
            pl.E += nC * dzC * hi;
            pl.DloAcc += nC * lo;
            pl.Sacc = std::min(pl.Sacc, c.mind);
            ++pl.dropped;
            continue;
        }
        int mo = -1;
        double tau = 0.0;
        double wR = 0.0;
        if (c.q < 1.0) {
            wR = tab.pw((S * S) / (c.R * c.R)) * (1.0 + 1e-9);
            mo = tab.chooseOrder(c.q, budget / (dzC * wR), tau);
            if (mo >= 0 && exactCost >= 0.0) {
                // measured: ~1.2 (mo+1)(mo+2)(mo+3) cycles per translation against
                // ~0.3 cycles per pixel and point in the kernel
                const double costM2l = 1.2 * (mo + 1) * (mo + 2) * (mo + 3);
                if (nC * exactCost < costM2l) {
                    mo = -1;
                }
            }
        }
        if (mo >= 0) {
            const std::size_t mc = static_cast<std::size_t>(rg.lay->count);
            const std::size_t off = static_cast<std::size_t>(c.node) * mc;
            m2l(loc, mo, tab, *rg.lay, &tree.momD[off], &tree.momN[off], nd, geo.tx, geo.ty, geo.an,
                c.R, wR);
            pl.hasLocal = true;
            pl.E += nC * dzC * wR * tau;
            pl.W += nC * wR * tab.pw(1.0 / ((1.0 - c.q) * (1.0 - c.q)));
            pl.DloAcc += nC * lo;
            pl.Sacc = std::min(pl.Sacc, c.mind);
            pl.Sexp = std::min(pl.Sexp, c.mind);
            ++pl.m2l;
            continue;
        }
        if (exactCost < 0.0) {
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
}

}  // namespace vv::vss::detail::fast
