// SPDX-License-Identifier: GPL-3.0-or-later
#include "VoronoiGraph.h"

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Delaunay_triangulation_cell_base_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "vv/analysis/AnalysisError.h"

namespace vv::analysis::detail {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_3<std::uint32_t, Kernel>;
using CellBase =
    CGAL::Triangulation_cell_base_with_info_3<std::uint32_t, Kernel,
                                              CGAL::Delaunay_triangulation_cell_base_3<Kernel>>;
using Tds = CGAL::Triangulation_data_structure_3<VertexBase, CellBase>;
using Delaunay = CGAL::Delaunay_triangulation_3<Kernel, Tds>;

constexpr std::uint32_t kOutside = UINT32_MAX;

/// Below this volume, relative to the product of its edges from one corner,
/// a tetrahedron is flat to the digits of a double: its circumcentre is
/// rounding noise (four points on one facet of a coarse surface give one
/// anywhere, e.g. 60 mm outside a 5 mm tube).
constexpr double kFlatVolume = 1e-10;

/// The circumcentre of the tetrahedron (a, b, c, d), computed relative to
/// `a` (which keeps the digits of small tetrahedra far from the origin);
/// nullopt when it is flat (kFlatVolume).
std::optional<glm::dvec3> circumcentre(const glm::dvec3& a, const glm::dvec3& b,
                                       const glm::dvec3& c, const glm::dvec3& d) {
    const glm::dvec3 u = b - a;
    const glm::dvec3 v = c - a;
    const glm::dvec3 w = d - a;
    const double det = 2.0 * glm::dot(u, glm::cross(v, w));
    if (!(std::abs(det) > 2.0 * kFlatVolume * glm::length(u) * glm::length(v) * glm::length(w))) {
        return std::nullopt;
    }
    const glm::dvec3 offset =
        (glm::dot(u, u) * glm::cross(v, w) + glm::dot(v, v) * glm::cross(w, u) +
         glm::dot(w, w) * glm::cross(u, v)) /
        det;
    if (!std::isfinite(offset.x) || !std::isfinite(offset.y) || !std::isfinite(offset.z)) {
        return std::nullopt;
    }
    return a + offset;
}

/// The samples' points and normals by id: the capped surface's vertices,
/// then the points added on coarse facets.
class SamplePoints {
  public:
    SamplePoints(const PreparedSurface& s, const VoronoiSamples& samples)
        : s_(s), samples_(samples), first_(s.cappedPositions.size()) {}

    [[nodiscard]] const glm::dvec3& position(std::uint32_t id) const {
        return id < first_ ? s_.cappedPositions[id] : samples_.addedPositions[id - first_];
    }
    [[nodiscard]] const glm::dvec3& normal(std::uint32_t id) const {
        return id < first_ ? s_.cappedNormals[id] : samples_.addedNormals[id - first_];
    }
    [[nodiscard]] bool onSurfaceVertex(std::uint32_t id) const { return id < first_; }

  private:
    const PreparedSurface& s_;
    const VoronoiSamples& samples_;
    std::size_t first_;
};

Delaunay triangulate(const SamplePoints& samplePoints, const std::vector<std::uint32_t>& kept) {
    std::vector<std::pair<Kernel::Point_3, std::uint32_t>> points;
    points.reserve(kept.size());
    for (const std::uint32_t i : kept) {
        const glm::dvec3& p = samplePoints.position(i);
        points.emplace_back(Kernel::Point_3(p.x, p.y, p.z), i);
    }
    return {points.begin(), points.end()};
}

/// Spreads the low 21 bits of `x` to every third bit.
std::uint64_t spreadBits(std::uint64_t x) {
    x &= 0x1fffffULL;
    x = (x | x << 32U) & 0x1f00000000ffffULL;
    x = (x | x << 16U) & 0x1f0000ff0000ffULL;
    x = (x | x << 8U) & 0x100f00f00f00f00fULL;
    x = (x | x << 4U) & 0x10c30c30c30c30c3ULL;
    x = (x | x << 2U) & 0x1249249249249249ULL;
    return x;
}

/// Per point, its rank along a Z-order (Morton) curve through the points'
/// bounding box, 2^21 steps per axis.
std::vector<std::uint32_t> zOrderRanks(const std::vector<glm::dvec3>& points) {
    glm::dvec3 lo(std::numeric_limits<double>::max());
    glm::dvec3 hi(std::numeric_limits<double>::lowest());
    for (const glm::dvec3& p : points) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const double extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z, 1e-300});
    const double scale = 2097151.0 / extent;
    std::vector<std::pair<std::uint64_t, std::uint32_t>> keys(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
        const glm::dvec3 q = glm::clamp((points[i] - lo) * scale, 0.0, 2097151.0);
        keys[i] = {spreadBits(static_cast<std::uint64_t>(q.x)) |
                       spreadBits(static_cast<std::uint64_t>(q.y)) << 1U |
                       spreadBits(static_cast<std::uint64_t>(q.z)) << 2U,
                   static_cast<std::uint32_t>(i)};
    }
    std::sort(keys.begin(), keys.end());
    std::vector<std::uint32_t> rank(points.size());
    for (std::size_t i = 0; i < keys.size(); ++i) {
        rank[keys[i].second] = static_cast<std::uint32_t>(i);
    }
    return rank;
}

}  // namespace

VoronoiGraph buildVoronoiGraph(const PreparedSurface& s, const VoronoiSamples& samples,
                               const Progress& progress) {
    progress.report(0.0, "Tetrahedralising the surface");
    const SamplePoints points(s, samples);
    Delaunay delaunay = triangulate(points, samples.kept);
    progress.report(0.5, "Finding the inside of the surface");
    VoronoiGraph graph;
    graph.poles.assign(s.cappedPositions.size(), kOutside);
    std::size_t visited = 0;
    for (auto cell = delaunay.finite_cells_begin(); cell != delaunay.finite_cells_end(); ++cell) {
        cell->info() = kOutside;
        if (++visited % 65536 == 0) {
            progress.throwIfCancelled();
        }
        std::array<std::uint32_t, 4> ids{};
        for (int i = 0; i < 4; ++i) {
            ids[i] = cell->vertex(i)->info();
        }
        const auto centre = circumcentre(points.position(ids[0]), points.position(ids[1]),
                                         points.position(ids[2]), points.position(ids[3]));
        if (!centre) {
            continue;
        }
        const double radius = glm::length(*centre - points.position(ids[0]));
        if (!(radius < s.diagonalMm)) {
            continue;
        }
        bool inside = true;
        for (const std::uint32_t id : ids) {
            inside = inside && glm::dot(points.normal(id), *centre - points.position(id)) < 0.0;
        }
        if (!inside) {
            continue;
        }
        const auto index = static_cast<std::uint32_t>(graph.centres.size());
        cell->info() = index;
        graph.centres.push_back(*centre);
        graph.radii.push_back(radius);
        for (const std::uint32_t id : ids) {
            if (!points.onSurfaceVertex(id)) {
                continue;  // an added point has no pole
            }
            std::uint32_t& pole = graph.poles[id];
            if (pole == kOutside || graph.radii[pole] < radius) {
                pole = index;
            }
        }
    }
    if (graph.centres.empty()) {
        throw AnalysisError(s.source, (s.source.empty() ? s.name + ": " : "") +
                                          "the surface encloses no space (no inside was found)");
    }
    // Renumbered along a Z-order curve: the walks over the graph (minimal
    // paths, tips, covering) then read neighbouring memory, not the cells'
    // order in the triangulation's storage. A cell's info keeps its old
    // number; the adjacency below maps it.
    const std::vector<std::uint32_t> rank = zOrderRanks(graph.centres);
    {
        std::vector<glm::dvec3> centres(graph.centres.size());
        std::vector<double> radii(graph.radii.size());
        for (std::size_t v = 0; v < rank.size(); ++v) {
            centres[rank[v]] = graph.centres[v];
            radii[rank[v]] = graph.radii[v];
        }
        graph.centres = std::move(centres);
        graph.radii = std::move(radii);
        for (std::uint32_t& pole : graph.poles) {
            if (pole != kOutside) {
                pole = rank[pole];
            }
        }
    }
    // A vertex left out of the diagram has its representative's pole.
    for (std::size_t v = 0; v < graph.poles.size(); ++v) {
        const std::uint32_t r = samples.representative[v];
        if (r != v) {
            graph.poles[v] = graph.poles[r];
        }
    }
    progress.report(0.8, "Joining the Voronoi diagram");
    // Compressed rows in two passes over the cells (count, then fill): no
    // list of edge pairs as large as the rows themselves.
    graph.offsets.assign(graph.centres.size() + 1, 0);
    const auto forEachEdge = [&](const auto& visit) {
        for (auto cell = delaunay.finite_cells_begin(); cell != delaunay.finite_cells_end();
             ++cell) {
            if (cell->info() == kOutside) {
                continue;
            }
            const std::uint32_t a = rank[cell->info()];
            for (int i = 0; i < 4; ++i) {
                const auto neighbour = cell->neighbor(i);
                if (!delaunay.is_infinite(neighbour) && neighbour->info() != kOutside) {
                    visit(a, rank[neighbour->info()]);
                }
            }
        }
    };
    forEachEdge([&](std::uint32_t a, std::uint32_t) { ++graph.offsets[a + 1]; });
    for (std::size_t v = 1; v < graph.offsets.size(); ++v) {
        graph.offsets[v] += graph.offsets[v - 1];
    }
    graph.neighbours.resize(graph.offsets.back());
    std::vector<std::uint32_t> fill(graph.offsets.begin(), graph.offsets.end() - 1);
    forEachEdge([&](std::uint32_t a, std::uint32_t b) { graph.neighbours[fill[a]++] = b; });
    return graph;
}

}  // namespace vv::analysis::detail
