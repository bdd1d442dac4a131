// SPDX-License-Identifier: GPL-3.0-or-later
#include "MinimalPaths.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>
#include <queue>
#include <unordered_map>
#include <utility>

namespace vv::analysis::detail {
namespace {

constexpr std::uint32_t kNone = UINT32_MAX;

/// Voronoi vertices bucketed on a uniform grid, for "all vertices within a
/// ball" queries.
class VertexGrid {
  public:
    VertexGrid(const std::vector<glm::dvec3>& points, double cell) : points_(points), cell_(cell) {
        for (std::uint32_t i = 0; i < points.size(); ++i) {
            buckets_[key(glm::ivec3(cellOf(points[i])))].push_back(i);
        }
    }

    void forEachWithin(const glm::dvec3& centre, double radius,
                       const std::function<void(std::uint32_t)>& visit) const {
        const glm::dvec3 lo = cellOf(centre - glm::dvec3(radius));
        const glm::dvec3 hi = cellOf(centre + glm::dvec3(radius));
        const double radius2 = radius * radius;
        const auto visitBucket = [&](const std::vector<std::uint32_t>& bucket) {
            for (const std::uint32_t i : bucket) {
                const glm::dvec3 d = points_[i] - centre;
                if (glm::dot(d, d) <= radius2) {
                    visit(i);
                }
            }
        };
        // A ball over more cells than are occupied (a sphere far wider than
        // the cell): every occupied cell instead.
        const glm::dvec3 cells = hi - lo + 1.0;
        if (cells.x * cells.y * cells.z > static_cast<double>(buckets_.size())) {
            for (const auto& [cell, bucket] : buckets_) {
                visitBucket(bucket);
            }
            return;
        }
        const glm::ivec3 from(lo);
        const glm::ivec3 to(hi);
        for (int x = from.x; x <= to.x; ++x) {
            for (int y = from.y; y <= to.y; ++y) {
                for (int z = from.z; z <= to.z; ++z) {
                    const auto it = buckets_.find(key({x, y, z}));
                    if (it != buckets_.end()) {
                        visitBucket(it->second);
                    }
                }
            }
        }
    }

  private:
    static constexpr std::int64_t kSpan = 1 << 20;

    /// The cell of `p`, clamped to [-kSpan, kSpan) per axis: far points
    /// share the border cells, which keeps queries exact (the distance is
    /// checked per point) and the cast in range.
    [[nodiscard]] glm::dvec3 cellOf(const glm::dvec3& p) const {
        return glm::clamp(glm::floor(p / cell_), glm::dvec3(-kSpan), glm::dvec3(kSpan - 1));
    }
    static std::int64_t key(const glm::ivec3& c) {
        return ((static_cast<std::int64_t>(c.x) + kSpan) * 2 * kSpan +
                (static_cast<std::int64_t>(c.y) + kSpan)) *
                   2 * kSpan +
               (static_cast<std::int64_t>(c.z) + kSpan);
    }

    const std::vector<glm::dvec3>& points_;
    double cell_;
    std::unordered_map<std::int64_t, std::vector<std::uint32_t>> buckets_;
};

double medianRadius(const VoronoiGraph& graph) {
    std::vector<double> radii = graph.radii;
    const auto middle = radii.begin() + static_cast<std::ptrdiff_t>(radii.size() / 2);
    std::nth_element(radii.begin(), middle, radii.end());
    return *middle;
}

}  // namespace

bool PathTree::reaches(std::uint32_t v) const {
    return v < cost.size() && std::isfinite(cost[v]);
}

std::vector<std::uint32_t> PathTree::pathTo(std::uint32_t v) const {
    std::vector<std::uint32_t> path;
    for (std::uint32_t at = v; at != kNone; at = previous[at]) {
        path.push_back(at);
    }
    std::reverse(path.begin(), path.end());
    return path;
}

PathTree minimalPaths(const VoronoiGraph& graph, std::uint32_t source, const Progress& progress) {
    const std::size_t n = graph.size();
    // One record per vertex (a relaxation touches one cache line, not
    // three), split into the tree's arrays at the end.
    struct Label {
        double cost;
        double lengthMm;
        std::uint32_t previous;
    };
    std::vector<Label> labels(n, Label{std::numeric_limits<double>::infinity(), 0.0, kNone});
    std::vector<double> inverseRadius(n);
    for (std::size_t v = 0; v < n; ++v) {
        inverseRadius[v] = 0.5 / graph.radii[v];
    }
    using Entry = std::pair<double, std::uint32_t>;
    std::vector<Entry> heap;
    heap.reserve(n);
    const auto push = [&](double cost, std::uint32_t v) {
        heap.emplace_back(cost, v);
        std::push_heap(heap.begin(), heap.end(), std::greater<>());
    };
    labels[source].cost = 0.0;
    push(0.0, source);
    std::size_t settled = 0;
    while (!heap.empty()) {
        std::pop_heap(heap.begin(), heap.end(), std::greater<>());
        const auto [cost, v] = heap.back();
        heap.pop_back();
        if (cost > labels[v].cost) {
            continue;
        }
        if (++settled % 65536 == 0) {
            progress.throwIfCancelled();
        }
        const glm::dvec3 at = graph.centres[v];
        const double length0 = labels[v].lengthMm;
        const double inverse0 = inverseRadius[v];
        for (std::uint32_t e = graph.offsets[v]; e < graph.offsets[v + 1]; ++e) {
            const std::uint32_t w = graph.neighbours[e];
            const double length = glm::length(graph.centres[w] - at);
            const double next = cost + length * (inverse0 + inverseRadius[w]);
            Label& label = labels[w];
            if (next < label.cost) {
                label = Label{next, length0 + length, v};
                push(next, w);
            }
        }
    }
    PathTree tree;
    tree.source = source;
    tree.cost.resize(n);
    tree.lengthMm.resize(n);
    tree.previous.resize(n);
    for (std::size_t v = 0; v < n; ++v) {
        tree.cost[v] = labels[v].cost;
        tree.lengthMm[v] = labels[v].lengthMm;
        tree.previous[v] = labels[v].previous;
    }
    return tree;
}

std::vector<std::uint32_t> uncoveredTips(const VoronoiGraph& graph, const PathTree& tree,
                                         const std::vector<std::vector<std::uint32_t>>& known,
                                         double coverFactor, double minLengthFactor,
                                         const Progress& progress) {
    const VertexGrid grid(graph.centres, std::max(medianRadius(graph), 1e-6));
    std::vector<char> covered(graph.size(), 0);
    // Covers the inscribed spheres (grown by coverFactor) along `path` from
    // index `from` on, querying only every quarter radius.
    const auto cover = [&](const std::vector<std::uint32_t>& path, std::size_t from) {
        glm::dvec3 last(std::numeric_limits<double>::max());
        for (std::size_t i = from; i < path.size(); ++i) {
            const std::uint32_t p = path[i];
            covered[p] = 1;
            const double step = glm::length(graph.centres[p] - last);
            if (step < 0.25 * graph.radii[p] && i + 1 < path.size()) {
                continue;
            }
            last = graph.centres[p];
            grid.forEachWithin(graph.centres[p],
                               coverFactor * graph.radii[p] + 0.25 * graph.radii[p],
                               [&](std::uint32_t v) { covered[v] = 1; });
        }
    };
    cover({tree.source}, 0);
    for (const auto& path : known) {
        cover(path, 0);
    }
    std::vector<std::uint32_t> order;
    order.reserve(graph.size());
    for (std::uint32_t v = 0; v < graph.size(); ++v) {
        if (tree.reaches(v)) {
            order.push_back(v);
        }
    }
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
        return tree.lengthMm[a] > tree.lengthMm[b];
    });
    std::vector<std::uint32_t> tips;
    for (const std::uint32_t v : order) {
        if (covered[v] != 0) {
            continue;
        }
        progress.throwIfCancelled();
        const std::vector<std::uint32_t> path = tree.pathTo(v);
        std::size_t leave = 0;  // first index outside the covered part
        for (std::size_t i = 0; i < path.size(); ++i) {
            if (covered[path[i]] != 0) {
                leave = i + 1;
            }
        }
        const std::uint32_t junction = leave > 0 ? path[leave - 1] : tree.source;
        const double outside = tree.lengthMm[v] - tree.lengthMm[junction];
        if (outside >= minLengthFactor * graph.radii[junction]) {
            tips.push_back(v);
        }
        cover(path, leave > 0 ? leave - 1 : 0);
    }
    return tips;
}

}  // namespace vv::analysis::detail
