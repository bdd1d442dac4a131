// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/planning/VesselPath.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <string>

#include "vv/core/Error.h"

namespace vv::planning {
namespace {

using analysis::Branch;
using analysis::CenterlineTree;

const Branch& branchOf(const CenterlineTree& tree, int branch) {
    if (branch < 0 || static_cast<std::size_t>(branch) >= tree.branches.size()) {
        throw InvalidArgumentError("centrelines: no branch " + std::to_string(branch) + " (of " +
                                   std::to_string(tree.branches.size()) + ")");
    }
    const Branch& b = tree.branches[static_cast<std::size_t>(branch)];
    if (b.points.empty()) {
        throw InvalidArgumentError("centrelines: branch " + std::to_string(branch) +
                                   " has no points");
    }
    return b;
}

double startOf(const Branch& b) {
    return b.points.front().abscissaMm;
}
double endOf(const Branch& b) {
    return b.points.back().abscissaMm;
}

/// The branches from branch 0 down to `branch`, in that order.
std::vector<int> routeTo(const CenterlineTree& tree, int branch) {
    std::vector<int> route;
    for (int b = branch; b >= 0; b = tree.branches[static_cast<std::size_t>(b)].parent) {
        route.push_back(b);
        if (route.size() > tree.branches.size()) {
            throw InvalidArgumentError("centrelines: the branches' parents form a loop");
        }
    }
    std::reverse(route.begin(), route.end());
    return route;
}

/// The index of the last point of `b` at or before abscissa `s` (clamped).
std::size_t segmentAt(const Branch& b, double s) {
    const auto after = std::upper_bound(
        b.points.begin(), b.points.end(), s,
        [](double value, const analysis::CenterlinePoint& p) { return value < p.abscissaMm; });
    const auto i = static_cast<std::size_t>(
        std::max<std::ptrdiff_t>(0, std::distance(b.points.begin(), after) - 1));
    return std::min(i, b.points.size() >= 2 ? b.points.size() - 2 : 0);
}

}  // namespace

TreeLocation clampedLocation(const CenterlineTree& tree, const TreeLocation& at) {
    const Branch& b = branchOf(tree, at.branch);
    if (!std::isfinite(at.abscissaMm)) {
        throw InvalidArgumentError("centrelines: a place's abscissa is not a number");
    }
    return {at.branch, std::clamp(at.abscissaMm, startOf(b), endOf(b))};
}

CenterlineSample sampleAt(const CenterlineTree& tree, const TreeLocation& at) {
    const TreeLocation c = clampedLocation(tree, at);
    const Branch& b = tree.branches[static_cast<std::size_t>(c.branch)];
    if (b.points.size() == 1) {
        return {b.points[0].position, b.points[0].tangent, b.points[0].radiusMm};
    }
    const std::size_t i = segmentAt(b, c.abscissaMm);
    const auto& p = b.points[i];
    const auto& q = b.points[i + 1];
    const double span = q.abscissaMm - p.abscissaMm;
    const double t = span > 0.0 ? std::clamp((c.abscissaMm - p.abscissaMm) / span, 0.0, 1.0) : 0.0;
    CenterlineSample sample;
    sample.position = p.position + t * (q.position - p.position);
    const glm::dvec3 tangent = p.tangent + t * (q.tangent - p.tangent);
    sample.tangent = glm::length(tangent) > 0.0 ? glm::normalize(tangent) : p.tangent;
    sample.radiusMm = p.radiusMm + t * (q.radiusMm - p.radiusMm);
    return sample;
}

NearestLocation nearestLocation(const CenterlineTree& tree, const glm::dvec3& point) {
    if (!std::isfinite(point.x) || !std::isfinite(point.y) || !std::isfinite(point.z)) {
        throw InvalidArgumentError("centrelines: the point is not a number");
    }
    NearestLocation best{{}, std::numeric_limits<double>::infinity()};
    for (const Branch& b : tree.branches) {
        for (std::size_t i = 0; i < b.points.size(); ++i) {
            const auto& p = b.points[i];
            double t = 0.0;
            glm::dvec3 onLine = p.position;
            if (i + 1 < b.points.size()) {
                const glm::dvec3 d = b.points[i + 1].position - p.position;
                const double dd = glm::dot(d, d);
                t = dd > 0.0 ? std::clamp(glm::dot(point - p.position, d) / dd, 0.0, 1.0) : 0.0;
                onLine = p.position + t * d;
            }
            const double distance = glm::length(point - onLine);
            if (distance < best.distanceMm) {
                const double next =
                    i + 1 < b.points.size() ? b.points[i + 1].abscissaMm : p.abscissaMm;
                best = {{b.id, p.abscissaMm + t * (next - p.abscissaMm)}, distance};
            }
        }
    }
    if (!std::isfinite(best.distanceMm)) {
        throw InvalidArgumentError("centrelines: the tree has no points");
    }
    return best;
}

double lengthAlong(const CenterlineTree& tree, const TreeLocation& a, const TreeLocation& b) {
    return VesselPath::between(tree, a, b).lengthMm();
}

TreeLocation endLocation(const CenterlineTree& tree, int end) {
    if (end < 0 || static_cast<std::size_t>(end) >= tree.ends.size()) {
        throw InvalidArgumentError("centrelines: no end " + std::to_string(end) + " (of " +
                                   std::to_string(tree.ends.size()) + ")");
    }
    if (end == 0) {
        return {0, startOf(branchOf(tree, 0))};
    }
    for (const Branch& b : tree.branches) {
        if (b.endIndex == end && !b.points.empty()) {
            return {b.id, endOf(b)};
        }
    }
    throw InvalidArgumentError("centrelines: no branch reaches end " + std::to_string(end));
}

VesselPath VesselPath::between(const CenterlineTree& tree, const TreeLocation& from,
                               const TreeLocation& to) {
    const TreeLocation a = clampedLocation(tree, from);
    const TreeLocation b = clampedLocation(tree, to);
    VesselPath path;
    auto& s = path.stretches_;
    if (a.branch == b.branch) {
        s.push_back({a.branch, a.abscissaMm, b.abscissaMm});
    } else {
        const std::vector<int> routeA = routeTo(tree, a.branch);
        const std::vector<int> routeB = routeTo(tree, b.branch);
        std::size_t k = 0;  // the routes' common part
        while (k < routeA.size() && k < routeB.size() && routeA[k] == routeB[k]) {
            ++k;
        }
        // Up from `a` to where the routes part...
        if (k == routeA.size()) {  // a's branch leads to b's
            s.push_back(
                {a.branch, a.abscissaMm, endOf(tree.branches[static_cast<std::size_t>(a.branch)])});
        } else {
            for (std::size_t i = routeA.size(); i-- > k;) {
                const Branch& br = tree.branches[static_cast<std::size_t>(routeA[i])];
                s.push_back({br.id, br.id == a.branch ? a.abscissaMm : endOf(br), startOf(br)});
            }
        }
        // ... and down to `b`.
        if (k == routeB.size()) {  // b's branch leads to a's
            s.push_back(
                {b.branch, endOf(tree.branches[static_cast<std::size_t>(b.branch)]), b.abscissaMm});
        } else {
            for (std::size_t i = k; i < routeB.size(); ++i) {
                const Branch& br = tree.branches[static_cast<std::size_t>(routeB[i])];
                s.push_back({br.id, startOf(br), br.id == b.branch ? b.abscissaMm : endOf(br)});
            }
        }
    }
    for (const PathStretch& stretch : s) {
        path.lengthMm_ += std::abs(stretch.toMm - stretch.fromMm);
    }
    return path;
}

int farthestEnd(const CenterlineTree& tree) {
    if (tree.ends.size() < 2 || tree.branches.empty()) {
        return -1;
    }
    const TreeLocation source = endLocation(tree, 0);
    int best = -1;
    double farthest = -1.0;
    for (const auto& branch : tree.branches) {
        if (branch.endIndex <= 0) {
            continue;  // ends at a bifurcation, or at the source
        }
        const double length = lengthAlong(tree, source, endLocation(tree, branch.endIndex));
        if (length > farthest) {
            farthest = length;
            best = branch.endIndex;
        }
    }
    return best;
}

VesselPath VesselPath::betweenEnds(const CenterlineTree& tree, int fromEnd, int toEnd) {
    if (fromEnd == toEnd) {
        throw InvalidArgumentError("centrelines: a path needs two different ends (both are end " +
                                   std::to_string(fromEnd) + ")");
    }
    return between(tree, endLocation(tree, fromEnd), endLocation(tree, toEnd));
}

TreeLocation VesselPath::from() const {
    return stretches_.empty() ? TreeLocation{}
                              : TreeLocation{stretches_.front().branch, stretches_.front().fromMm};
}

TreeLocation VesselPath::to() const {
    return stretches_.empty() ? TreeLocation{}
                              : TreeLocation{stretches_.back().branch, stretches_.back().toMm};
}

TreeLocation VesselPath::locationAt(double s) const {
    if (stretches_.empty()) {
        return {};
    }
    double left = std::isfinite(s) ? std::clamp(s, 0.0, lengthMm_) : 0.0;
    for (const PathStretch& stretch : stretches_) {
        const double length = std::abs(stretch.toMm - stretch.fromMm);
        if (left <= length || &stretch == &stretches_.back()) {
            const double along = std::min(left, length);
            return {stretch.branch, stretch.toMm >= stretch.fromMm ? stretch.fromMm + along
                                                                   : stretch.fromMm - along};
        }
        left -= length;
    }
    return to();
}

std::optional<double> VesselPath::abscissaOf(const CenterlineTree& tree,
                                             const TreeLocation& at) const {
    const TreeLocation c = clampedLocation(tree, at);
    const Branch& b = tree.branches[static_cast<std::size_t>(c.branch)];
    // A bifurcation, found as the parent's end or as a child's start.
    std::vector<TreeLocation> same{c};
    constexpr double kAtEnd = 1e-9;
    if (c.abscissaMm <= startOf(b) + kAtEnd && b.parent >= 0) {
        same.push_back({b.parent, endOf(tree.branches[static_cast<std::size_t>(b.parent)])});
    }
    if (c.abscissaMm >= endOf(b) - kAtEnd) {
        for (const int child : b.children) {
            same.push_back({child, startOf(tree.branches[static_cast<std::size_t>(child)])});
        }
    }
    double before = 0.0;
    for (const PathStretch& stretch : stretches_) {
        const double lo = std::min(stretch.fromMm, stretch.toMm);
        const double hi = std::max(stretch.fromMm, stretch.toMm);
        for (const TreeLocation& l : same) {
            if (l.branch == stretch.branch && l.abscissaMm >= lo - kAtEnd &&
                l.abscissaMm <= hi + kAtEnd) {
                return before + std::abs(l.abscissaMm - stretch.fromMm);
            }
        }
        before += hi - lo;
    }
    return std::nullopt;
}

std::vector<PathPoint> VesselPath::points(const CenterlineTree& tree) const {
    std::vector<PathPoint> out;
    double before = 0.0;
    for (std::size_t k = 0; k < stretches_.size(); ++k) {
        const PathStretch& stretch = stretches_[k];
        const Branch& b = branchOf(tree, stretch.branch);
        const double lo = std::min(stretch.fromMm, stretch.toMm);
        const double hi = std::max(stretch.fromMm, stretch.toMm);
        std::vector<std::size_t> within;
        for (std::size_t i = 0; i < b.points.size(); ++i) {
            const double s = b.points[i].abscissaMm;
            if (s >= lo - 1e-9 && s <= hi + 1e-9) {
                within.push_back(i);
            }
        }
        if (stretch.toMm < stretch.fromMm) {
            std::reverse(within.begin(), within.end());
        }
        // A later stretch starts at a bifurcation, which the one before ended at.
        const bool startsAtAJunction = std::abs(stretch.fromMm - startOf(b)) <= 1e-9 ||
                                       std::abs(stretch.fromMm - endOf(b)) <= 1e-9;
        for (std::size_t j = 0; j < within.size(); ++j) {
            if (k > 0 && j == 0 && startsAtAJunction) {
                continue;
            }
            const std::size_t i = within[j];
            out.push_back({b.id, i, before + std::abs(b.points[i].abscissaMm - stretch.fromMm)});
        }
        before += hi - lo;
    }
    return out;
}

}  // namespace vv::planning
