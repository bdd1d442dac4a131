// SPDX-License-Identifier: GPL-3.0-or-later
// Private to the fast VSS solver: one void region as its traversal
// (FastSolver.cpp) and its leaf tiles (FastLeaf.cpp) see it: the source tree,
// the target boxes, the images, the depth range and the error budget.
#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>
#include <stop_token>
#include <vector>

#include "FastKernel.h"
#include "FastSourceTree.h"
#include "FastTables.h"
#include "vv/core/Image.h"

namespace vv::vss::detail::fast {

/// The region pixels of one target box: their count and bounding box
/// (inclusive; empty boxes keep the initial extremes).
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

/// Geometry of a target box: the bounding box of ITS REGION PIXELS.
struct BoxGeo {
    double tx = 0.0;  // centre of the region pixels' bounding box
    double ty = 0.0;
    double a = 0.0;   // half diagonal
    double an = 0.5;  // polynomial scale: max(a, 0.5)
    int minx = 0, miny = 0, maxx = 0, maxy = 0;
};

/// One region's solve, shared by every box and thread: read-only but for the
/// output pixels, which each leaf tile writes for its own pixels.
struct Region {
    const PowerTables* tab = nullptr;
    const MomentLayout* lay = nullptr;
    SourceTree tree;
    ImageView<const std::int32_t> labels;
    ImageView<float> out;
    std::int32_t id = 0;
    int rx0 = 0, ry0 = 0, rx1 = 0, ry1 = 0;  // the region's box in the images, x1 / y1 exclusive
    // target boxes: lv[level] holds lvNx[level] x lvNy[level] boxes, row-major;
    // level 0 = the leaf tiles of kLeafTile x kLeafTile pixels from (rx0, ry0)
    std::vector<std::vector<TileInfo>> lv;
    std::vector<int> lvNx;
    std::vector<int> lvNy;
    double n = 0.0;      // contour points
    double zref = 0.0;   // float value, as double
    double zminH = 0.0;  // zmin - zref, zmax - zref (of the stored float z - zref)
    double zmaxH = 0.0;
    float zminOut = 0.0F;  // clamp range of the output
    float zmaxOut = 0.0F;
    double dz = 0.0;              // zmaxH - zminH
    double tol = 0.0;             // tolerance of every pixel's z'
    double tolA = 0.0;            // a-priori budget
    double deltaW = 0.0;          // relative error bound of one kernel weight
    bool coarse = true;           // coarse boxes allowed (FastCoarse.h)
    bool nearBoxesOn = true;      // near-band boxes on a coarse grid allowed (FastNearBox.h)
    bool nearSplit = false;       // near boxes split their clusters (FastSolver.cpp, tryNearBox)
    bool bandBoxesOn = true;      // band boxes on an adaptive grid allowed (FastBandBox.h)
    double bandBoundScale = 1.0;  // test hook: scales their interpolation bound (FastStats.h)
    double nearSplitBudgetScale = 1.0;  // test hook: loosens the budget of that split
    double budgetScale = 1.0;           // test hook: loosens the a-priori choices (FastStats.h)
    KernelPower kp;
    // the leaves' weights by lattice offset (FastTables.h); nullptr: computed
    const float* dist = nullptr;
    std::stop_token stop;
};

}  // namespace vv::vss::detail::fast
