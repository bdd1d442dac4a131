// SPDX-License-Identifier: GPL-3.0-or-later
#include "MinimalPaths.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>
#include <queue>
#include <utility>

namespace vv::analysis::detail {
namespace {

constexpr std::uint32_t kNone = UINT32_MAX;

/// Voronoi vertices bucketed on uniform grids, for "all vertices within a
/// ball" queries: the finest grid's cell is `cell`, each coarser one's 4
/// times its finer one's, built when a query first needs it. A query uses
/// the finest grid on which its ball spans at most kMaxCells cells. (One
/// grid sized by the median radius served the smooth surfaces, but on a
/// rough wall the median sphere is tiny, and a sphere of a wide vessel then
/// spanned more cells than were occupied: every such query visited every
/// vertex, 5-8 s on a jittered 1M aneurysm. CGAL's kd-tree did that in
/// 1 s, but cost the demo tree 0.35 s and 12 MiB more than the grid.)
class VertexGrid {
  public:
    VertexGrid(const VoronoiGraph& graph, double cell) : graph_(graph) {
        levels_.emplace_back(graph, cell);
    }

    void forEachWithin(const glm::dvec3& centre, double radius,
                       const std::function<void(std::uint32_t)>& visit) {
        std::size_t k = 0;
        while (spannedCells(levels_[k].cell, radius) > kMaxCells && k + 1 < kMaxLevels) {
            if (++k == levels_.size()) {
                levels_.emplace_back(graph_, 4.0 * levels_.back().cell);
            }
        }
        const Level& level = levels_[k];
        const glm::dvec3 lo = level.cellOf(centre - glm::dvec3(radius));
        const glm::dvec3 hi = level.cellOf(centre + glm::dvec3(radius));
        const double radius2 = radius * radius;
        const auto visitCells = [&](std::size_t first, std::size_t last) {
            for (std::uint32_t at = level.starts[first]; at < level.starts[last]; ++at) {
                const std::uint32_t i = level.ids[at];
                const glm::dvec3 d = graph_.centre(i) - centre;
                if (glm::dot(d, d) <= radius2) {
                    visit(i);
                }
            }
        };
        // A ball over more cells than are occupied: every occupied cell.
        const glm::dvec3 cells = hi - lo + 1.0;
        if (cells.x * cells.y * cells.z > static_cast<double>(level.keys.size())) {
            visitCells(0, level.keys.size());
            return;
        }
        // The cells of one (x, y) column have consecutive keys: one search
        // per column.
        const glm::ivec3 from(lo);
        const glm::ivec3 to(hi);
        for (int x = from.x; x <= to.x; ++x) {
            for (int y = from.y; y <= to.y; ++y) {
                const auto begin = std::lower_bound(level.keys.begin(), level.keys.end(),
                                                    Level::key({x, y, from.z}));
                const auto end =
                    std::upper_bound(begin, level.keys.end(), Level::key({x, y, to.z}));
                visitCells(static_cast<std::size_t>(begin - level.keys.begin()),
                           static_cast<std::size_t>(end - level.keys.begin()));
            }
        }
    }

  private:
    static constexpr double kMaxCells = 512.0;
    static constexpr std::size_t kMaxLevels = 12;
    static constexpr std::int64_t kSpan = 1 << 20;

    static double spannedCells(double cell, double radius) {
        const double side = 2.0 * radius / cell + 1.0;
        return side * side * side;
    }

    /// The points sorted by their cells' keys: `ids[starts[c] .. starts[c + 1])`
    /// are the points of the occupied cell `keys[c]` (4 bytes per point and
    /// 12 per occupied cell; a hash map of buckets took several times that).
    struct Level {
        Level(const VoronoiGraph& graph, double size) : cell(size) {
            std::vector<std::int64_t> pointKeys(graph.size());
            for (std::size_t i = 0; i < graph.size(); ++i) {
                pointKeys[i] = key(glm::ivec3(cellOf(graph.centre(i))));
            }
            ids.resize(graph.size());
            std::iota(ids.begin(), ids.end(), 0U);
            std::sort(ids.begin(), ids.end(), [&](std::uint32_t a, std::uint32_t b) {
                return pointKeys[a] < pointKeys[b] || (pointKeys[a] == pointKeys[b] && a < b);
            });
            for (std::uint32_t k = 0; k < ids.size(); ++k) {
                const std::int64_t c = pointKeys[ids[k]];
                if (keys.empty() || keys.back() != c) {
                    keys.push_back(c);
                    starts.push_back(k);
                }
            }
            starts.push_back(static_cast<std::uint32_t>(ids.size()));
            keys.shrink_to_fit();
            starts.shrink_to_fit();
        }
        /// The cell of `p`, clamped to [-kSpan, kSpan) per axis: far points
        /// share the border cells, which keeps queries exact (the distance
        /// is checked per point) and the cast in range.
        [[nodiscard]] glm::dvec3 cellOf(const glm::dvec3& p) const {
            return glm::clamp(glm::floor(p / cell), glm::dvec3(-kSpan), glm::dvec3(kSpan - 1));
        }
        static std::int64_t key(const glm::ivec3& c) {
            return ((static_cast<std::int64_t>(c.x) + kSpan) * 2 * kSpan +
                    (static_cast<std::int64_t>(c.y) + kSpan)) *
                       2 * kSpan +
                   (static_cast<std::int64_t>(c.z) + kSpan);
        }

        double cell;
        std::vector<std::int64_t> keys;
        std::vector<std::uint32_t> starts;
        std::vector<std::uint32_t> ids;
    };

    const VoronoiGraph& graph_;
    std::vector<Level> levels_;
};

/// The median radius of at most about 65k vertices spread over the graph
/// (it sizes the grid's cells: a sample serves, and a copy of every radius
/// would cost 8 bytes per vertex at the analysis' peak).
double medianRadius(const VoronoiGraph& graph) {
    const std::size_t stride = std::max<std::size_t>(1, graph.radii.size() / 65536);
    std::vector<double> radii;
    radii.reserve(graph.radii.size() / stride + 1);
    for (std::size_t v = 0; v < graph.radii.size(); v += stride) {
        radii.push_back(graph.radius(v));
    }
    const auto middle = radii.begin() + static_cast<std::ptrdiff_t>(radii.size() / 2);
    std::nth_element(radii.begin(), middle, radii.end());
    return *middle;
}

}  // namespace

bool PathTree::reaches(std::uint32_t v) const {
    return v < labels.size() && std::isfinite(labels[v].cost);
}

std::vector<std::uint32_t> PathTree::pathTo(std::uint32_t v) const {
    std::vector<std::uint32_t> path;
    for (std::uint32_t at = v; at != kNone; at = labels[at].previous) {
        path.push_back(at);
    }
    std::reverse(path.begin(), path.end());
    return path;
}

PathTree minimalPaths(const VoronoiGraph& graph, std::uint32_t source, const Progress& progress) {
    const std::size_t n = graph.size();
    PathTree tree;
    tree.source = source;
    tree.scale = graph.frame.scale;
    tree.labels.resize(n);
    std::vector<PathTree::Label>& labels = tree.labels;
    for (std::size_t v = 0; v < n; ++v) {
        labels[v] = {
            .cost = std::numeric_limits<double>::infinity(), .length = 0.0F, .previous = kNone};
    }
    using Entry = std::pair<double, std::uint32_t>;
    std::vector<Entry> heap;
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
        const glm::dvec3 at = graph.centre(v);
        const double length0 = labels[v].length;
        const double inverse0 = 0.5 / graph.radius(v);
        for (std::uint32_t e = graph.offsets[v]; e < graph.offsets[v + 1]; ++e) {
            const std::uint32_t w = graph.neighbours[e];
            const double length = glm::length(graph.centre(w) - at);
            PathTree::Label& label = labels[w];
            const double next = cost + length * (inverse0 + 0.5 / graph.radius(w));
            if (next < label.cost) {
                label.cost = next;
                label.length = static_cast<float>(length0 + length / graph.frame.scale);
                label.previous = v;
                push(next, w);
            }
        }
    }
    return tree;
}

std::vector<std::uint32_t> uncoveredTips(const VoronoiGraph& graph, const PathTree& tree,
                                         const std::vector<std::vector<std::uint32_t>>& known,
                                         double coverFactor, double minLengthFactor,
                                         const Progress& progress) {
    VertexGrid grid(graph, std::max(medianRadius(graph), 1e-6));
    std::vector<char> covered(graph.size(), 0);
    // Whose grown sphere has been covered already: each is covered once
    // (the junction of every spike off a path would be again, and a rough
    // wall gives thousands of spikes off the same wide vessel).
    std::vector<char> applied(graph.size(), 0);
    // Covers the inscribed spheres (grown by coverFactor) along `path` from
    // index `from` on, querying only every quarter radius.
    const auto cover = [&](const std::vector<std::uint32_t>& path, std::size_t from) {
        glm::dvec3 last(std::numeric_limits<double>::max());
        for (std::size_t i = from; i < path.size(); ++i) {
            const std::uint32_t p = path[i];
            covered[p] = 1;
            const double step = glm::length(graph.centre(p) - last);
            if (step < 0.25 * graph.radius(p) && i + 1 < path.size()) {
                continue;
            }
            last = graph.centre(p);
            if (applied[p] != 0) {
                continue;
            }
            applied[p] = 1;
            grid.forEachWithin(graph.centre(p),
                               coverFactor * graph.radius(p) + 0.25 * graph.radius(p),
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
        return tree.lengthMm(a) > tree.lengthMm(b);
    });
    std::vector<std::uint32_t> tips;
    for (const std::uint32_t v : order) {
        if (covered[v] != 0) {
            continue;
        }
        progress.throwIfCancelled();
        // The path's part outside the covered one: from v back to the last
        // covered vertex along it (the junction; the source is covered),
        // walked from v: a rough wall gives thousands of short spikes off
        // a long covered path.
        std::vector<std::uint32_t> spike{v};
        while (covered[spike.back()] == 0 && tree.previous(spike.back()) != kNone) {
            spike.push_back(tree.previous(spike.back()));
        }
        std::reverse(spike.begin(), spike.end());
        const std::uint32_t junction = spike.front();
        const double outside = tree.lengthMm(v) - tree.lengthMm(junction);
        if (outside >= minLengthFactor * graph.radius(junction)) {
            tips.push_back(v);
        }
        cover(spike, 0);
    }
    return tips;
}

}  // namespace vv::analysis::detail
