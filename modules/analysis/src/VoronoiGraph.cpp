// SPDX-License-Identifier: GPL-3.0-or-later
#include "VoronoiGraph.h"

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Delaunay_triangulation_cell_base_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <cmath>
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

/// The circumcentre of the tetrahedron (a, b, c, d), computed relative to
/// `a` (which keeps the digits of small tetrahedra far from the origin);
/// nullopt when it is flat.
std::optional<glm::dvec3> circumcentre(const glm::dvec3& a, const glm::dvec3& b,
                                       const glm::dvec3& c, const glm::dvec3& d) {
    const glm::dvec3 u = b - a;
    const glm::dvec3 v = c - a;
    const glm::dvec3 w = d - a;
    const double det = 2.0 * glm::dot(u, glm::cross(v, w));
    if (det == 0.0 || !std::isfinite(det)) {
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

Delaunay triangulate(const PreparedSurface& s, const std::vector<std::uint32_t>& kept) {
    std::vector<std::pair<Kernel::Point_3, std::uint32_t>> points;
    points.reserve(kept.size());
    for (const std::uint32_t i : kept) {
        const glm::dvec3& p = s.cappedPositions[i];
        points.emplace_back(Kernel::Point_3(p.x, p.y, p.z), i);
    }
    return {points.begin(), points.end()};
}

}  // namespace

VoronoiGraph buildVoronoiGraph(const PreparedSurface& s, const VoronoiSamples& samples,
                               const Progress& progress) {
    progress.report(0.0, "Tetrahedralising the surface");
    Delaunay delaunay = triangulate(s, samples.kept);
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
        const auto& p = s.cappedPositions;
        const auto centre = circumcentre(p[ids[0]], p[ids[1]], p[ids[2]], p[ids[3]]);
        if (!centre) {
            continue;
        }
        const double radius = glm::length(*centre - p[ids[0]]);
        if (!(radius < s.diagonalMm)) {
            continue;
        }
        bool inside = true;
        for (const std::uint32_t id : ids) {
            inside = inside && glm::dot(s.cappedNormals[id], *centre - p[id]) < 0.0;
        }
        if (!inside) {
            continue;
        }
        const auto index = static_cast<std::uint32_t>(graph.centres.size());
        cell->info() = index;
        graph.centres.push_back(*centre);
        graph.radii.push_back(radius);
        for (const std::uint32_t id : ids) {
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
    // A vertex left out of the diagram has its representative's pole.
    for (std::size_t v = 0; v < graph.poles.size(); ++v) {
        const std::uint32_t r = samples.representative[v];
        if (r != v) {
            graph.poles[v] = graph.poles[r];
        }
    }
    progress.report(0.8, "Joining the Voronoi diagram");
    graph.offsets.assign(graph.centres.size() + 1, 0);
    std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
    edges.reserve(graph.centres.size() * 4);
    for (auto cell = delaunay.finite_cells_begin(); cell != delaunay.finite_cells_end(); ++cell) {
        const std::uint32_t a = cell->info();
        if (a == kOutside) {
            continue;
        }
        for (int i = 0; i < 4; ++i) {
            const auto neighbour = cell->neighbor(i);
            if (delaunay.is_infinite(neighbour) || neighbour->info() == kOutside) {
                continue;
            }
            edges.emplace_back(a, neighbour->info());
            ++graph.offsets[a + 1];
        }
    }
    for (std::size_t v = 1; v < graph.offsets.size(); ++v) {
        graph.offsets[v] += graph.offsets[v - 1];
    }
    graph.neighbours.resize(edges.size());
    std::vector<std::uint32_t> fill(graph.offsets.begin(), graph.offsets.end() - 1);
    for (const auto& [a, b] : edges) {
        graph.neighbours[fill[a]++] = b;
    }
    return graph;
}

}  // namespace vv::analysis::detail
