// SPDX-License-Identifier: GPL-3.0-or-later
// Private to the fast VSS solver: one leaf tile of 16 x 16 target pixels. The
// local expansion becomes a polynomial, the near points are summed exactly
// (FastKernel.cpp), every pixel's error bound is checked a posteriori against
// the tolerance, and the pixels that fail it are recomputed exactly (the error
// bound and the check: the comment at the top of FastSolver.cpp).
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "FastExpansion.h"
#include "FastRegion.h"

namespace vv::vss::detail::fast {

/// What the traversal hands a leaf tile besides its near points and its local
/// expansion. S is the box scale (a lower bound of every pixel-point
/// distance, >= 1); E and W hold true values times S^p.
struct LeafBounds {
    double S = 1.0;
    double E = 0.0;  ///< bound of sum_i dz_i |remainder_i| over the box (the z' error is E / D)
    double W = 0.0;  ///< bound of the weights in the expansion (its round-off bound)
    double Sexp =
        std::numeric_limits<double>::infinity();  ///< distance bound to the expanded clusters
};

/// What one leaf tile did, for the solver's statistics (FastStats.h).
struct LeafCounts {
    std::int64_t pixels = 0;          ///< region pixels written
    std::int64_t fallbackPixels = 0;  ///< of which failed the kernel's check
    std::int64_t nearPairs = 0;       ///< near points x computed rows
    std::int64_t tablePairs = 0;      ///< of those, with the weight from the distance table
    bool perPixel = false;            ///< per-pixel scale mode (large p, far from the points)
    bool exactTile = false;           ///< the tile was re-evaluated with every contour point
};

/// z' of pixel (x, y) of region rg by a double-precision sum over every
/// contour point, clamped to the contour depth range (the exact fall-back).
/// Throws nothing.
float exactPixel(const Region& rg, int x, int y);

/// Writes z' to rg.out for the pixels of region rg.id in leaf tile (ix, iy) of
/// level 0, within rg.tol of the exact value and clamped to the contour
/// depth range: the clusters of nearNodes (source leaves) exactly, the rest
/// through far (the tile's local expansion, nullptr when there is none) and
/// charged to bounds.E. Pixels failing the check are recomputed: the whole
/// tile with every contour point when more than 16 fail, else (or if that
/// fails too) one pixel at a time in double precision. Throws nothing.
LeafCounts evalLeaf(const Region& rg, int ix, int iy, const BoxGeo& geo,
                    const std::vector<int>& nearNodes, const Local* far, const LeafBounds& bounds);

}  // namespace vv::vss::detail::fast
