// SPDX-License-Identifier: GPL-3.0-or-later
// The fast VSS solver's source tree (FastSourceTree.h): the k-d tree over a
// region's contour points and the moments of its nodes.
#include "FastSourceTree.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

namespace vv::vss::detail::fast {
namespace {

constexpr int kLeafPoints = 16;  // contour points per source leaf

// Fills the node's box, centre, radius and z-range from its points and splits
// it (median of the longer side, children appended) while it has more than
// kLeafPoints points.
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
    if (splitX) {
        std::nth_element(
            first, tree.pts.begin() + mid, tree.pts.begin() + nd.end,
            [](const Point& a, const Point& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    } else {
        std::nth_element(
            first, tree.pts.begin() + mid, tree.pts.begin() + nd.end,
            [](const Point& a, const Point& b) { return a.y < b.y || (a.y == b.y && a.x < b.x); });
    }
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
            // (alpha v + beta)^r = sum_j coef[r][j] v^j
            std::array<Cx, kS * kS> coef;
            tab.shiftCoefficients(alpha, beta, d, coef);
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

}  // namespace

void buildSourceTree(SourceTree& tree, const MomentLayout& lay, const PowerTables& tab) {
    tree.nodes.clear();
    tree.nodes.reserve(4 * tree.pts.size() / kLeafPoints + 4);
    SrcNode root;
    root.begin = 0;
    root.end = static_cast<int>(tree.pts.size());
    tree.nodes.push_back(root);
    buildNode(tree, 0);
    buildMoments(tree, lay, tab);
}

}  // namespace vv::vss::detail::fast
