// SPDX-License-Identifier: GPL-3.0-or-later
// Private to the fast VSS solver: how the traversal places the source
// clusters a target box receives (drop, expand into its local expansion, defer
// to its children, or split down to near points), shared by the boxes of
// FastSolver.cpp and the split at a near box (FastSolver.cpp, tryNearBox).
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "FastExpansion.h"
#include "FastLeaf.h"
#include "FastRegion.h"

namespace vv::vss::detail::fast {

/// The geometry of a target box: the bounding box of its region pixels.
BoxGeo geometry(const TileInfo& t);

/// A source cluster seen from a target box.
struct Cand {
    int node = 0;
    double R = 0.0;     // centre distance
    double q = 0.0;     // (a + s) / R
    double mind = 1.0;  // lower bound of pixel-point distances (>= 1)
    double maxd = 1.0;  // upper bound
};

/// The candidate node `node` (c) seen from the box with geometry g.
Cand makeCand(int node, const SrcNode& c, const BoxGeo& g);

/// What placing clusters at a box adds to what it inherited.
struct Placed {
    bool hasLocal = false;
    double E = 0.0;       // truncation / drop bound (BoxState::E)
    double W = 0.0;       // expanded weights (round-off bound)
    double DloAcc = 0.0;  // lower bound of D from the clusters placed here
    double Sacc = std::numeric_limits<double>::infinity();
    double Sexp = std::numeric_limits<double>::infinity();
    std::int64_t m2l = 0;
    std::int64_t dropped = 0;
};

/// Places the candidate clusters cands of a box (geometry geo, scale S, lower
/// bound DloBox of D over it; wLo[k] the weight lower bound of cands[k] for
/// the first wLo.size() of them): drops them (charged to pl.E), expands them
/// into loc (M2L), or, when exactCost < 0, defers them to the children; with
/// exactCost >= 0 (the cost of summing one point exactly at every pixel or
/// sample of the box, in the kernel's cycles) a cluster that is cheaper to sum
/// than to translate, or that does not fit the budget, is split down to the
/// tree's leaves, which go to nearNodes. budgetScale: a test hook (1 but in
/// tests) that loosens the budget.
/// Throws nothing but std::bad_alloc.
void placeClusters(const Region& rg, const BoxGeo& geo, double S, double DloBox, double budgetScale,
                   std::vector<Cand>& cands, const std::vector<double>& wLo, double exactCost,
                   Local& loc, Placed& pl, std::vector<int>& deferred, std::vector<int>& nearNodes);

}  // namespace vv::vss::detail::fast
