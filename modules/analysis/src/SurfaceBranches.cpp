// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/analysis/SurfaceBranches.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <utility>

namespace vv::analysis {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Indexed = std::tuple<Point, std::uint32_t>;
using Traits = CGAL::Search_traits_adapter<Indexed, CGAL::Nth_of_tuple_property_map<0, Indexed>,
                                           CGAL::Search_traits_3<Kernel>>;
using Search = CGAL::Orthogonal_k_neighbor_search<Traits>;
using Tree = Search::Tree;

/// Candidates per vertex among which the tube test decides.
constexpr unsigned kCandidates = 8;
/// Beyond this many inscribed radii from every centreline point: no branch.
constexpr double kFarthest = 4.0;

struct CentrelinePoint {
    glm::dvec3 position;
    double radius;
    int branch;
};

}  // namespace

std::vector<std::int32_t> surfaceBranchIds(const scene::Mesh& mesh, const CenterlineTree& tree) {
    std::vector<CentrelinePoint> points;
    std::vector<Indexed> indexed;
    for (const Branch& b : tree.branches) {
        for (const CenterlinePoint& p : b.points) {
            indexed.emplace_back(Point(p.position.x, p.position.y, p.position.z),
                                 static_cast<std::uint32_t>(points.size()));
            points.push_back({p.position, std::max(p.radiusMm, 1e-6), b.id});
        }
    }
    std::vector<std::int32_t> ids(mesh.positions.size(), -1);
    if (points.empty()) {
        return ids;
    }
    const Tree search(indexed.begin(), indexed.end());
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        const glm::dvec3 p(mesh.positions[v]);
        const Search nearest(search, Point(p.x, p.y, p.z), kCandidates);
        double best = std::numeric_limits<double>::max();
        for (const auto& [candidate, distance2] : nearest) {
            const CentrelinePoint& c = points[std::get<1>(candidate)];
            const double tube = std::sqrt(distance2) / c.radius;
            if (tube < best) {
                best = tube;
                ids[v] = c.branch;
            }
        }
        if (best > kFarthest) {
            ids[v] = -1;
        }
    }
    return ids;
}

scene::Mesh withBranchIds(scene::Mesh mesh, const CenterlineTree& tree) {
    const std::vector<std::int32_t> ids = surfaceBranchIds(mesh, tree);
    std::erase_if(mesh.pointArrays,
                  [](const scene::DataArray& a) { return a.name == "branch_id"; });
    scene::DataArray array;
    array.name = "branch_id";
    array.integer = true;
    array.values.reserve(ids.size());
    for (const std::int32_t id : ids) {
        array.values.push_back(id < 0 ? std::numeric_limits<float>::quiet_NaN()
                                      : static_cast<float>(id));
    }
    mesh.pointArrays.push_back(std::move(array));
    auto& names = mesh.labelNames["branch_id"];
    names.clear();
    for (const Branch& b : tree.branches) {
        names[b.id] = "branch " + std::to_string(b.id);
    }
    return mesh;
}

}  // namespace vv::analysis
