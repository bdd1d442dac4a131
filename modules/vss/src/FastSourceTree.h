// SPDX-License-Identifier: GPL-3.0-or-later
// Private to the fast VSS solver: the source tree of one void region, a k-d
// tree over its contour points (median split of the longer side, <= 16 points
// per leaf) with, per node, its box, centre c, radius s, z-range and complex
// moments M_{r,r'} = sum_i w_i (v_i/sn)^r conj(v_i/sn)^r', v_i = y_i - c,
// r + r' <= degree, for w = 1 (D) and w = z - zref (N).
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "FastMath.h"
#include "FastTables.h"

namespace vv::vss::detail::fast {

/// One contour point: pixel position and depth relative to the region's zref.
struct Point {
    int x = 0;
    int y = 0;
    float z = 0.0F;  // z - zref
};

/// One node of the source tree: points [begin, end) of SourceTree::pts.
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

/// Hermitian packing of the moments: (r, r') with r >= r', r + r' <= degree,
/// at index idx[r][r'] (-1 elsewhere); M_{r',r} = conj(M_{r,r'}).
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

/// The tree of one region: nodes[k]'s moments at momD / momN[k * layout.count].
struct SourceTree {
    std::vector<Point> pts;
    std::vector<SrcNode> nodes;
    std::vector<Cx> momD;  // nodes.size() * layout.count
    std::vector<Cx> momN;
};

/// Points of the given nodes of tree (their count() summed). Throws nothing.
inline std::size_t pointCount(const SourceTree& tree, const std::vector<int>& nodes) {
    std::size_t n = 0;
    for (const int nd : nodes) {
        n += static_cast<std::size_t>(tree.nodes[static_cast<std::size_t>(nd)].count());
    }
    return n;
}

/// Builds the tree over tree.pts (the region's contour points, at least one;
/// their order changes): tree.nodes (root 0, the children of a node next to
/// each other, every node after its parent) and the moments of every node
/// about its centre, for lay.degree. Leaves directly, inner nodes by exact
/// binomial shifts (M2M). Dispatched at run time (AVX2 / baseline).
void buildSourceTree(SourceTree& tree, const MomentLayout& lay, const PowerTables& tab);

}  // namespace vv::vss::detail::fast
