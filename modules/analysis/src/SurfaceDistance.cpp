// SPDX-License-Identifier: GPL-3.0-or-later
#include "SurfaceDistance.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>
#include <vector>

namespace vv::analysis::detail {
namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Triangle3 = Kernel::Triangle_3;
using Iterator = std::vector<Triangle3>::const_iterator;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, Iterator>;
using Traits = CGAL::AABB_traits<Kernel, Primitive>;
using AabbTree = CGAL::AABB_tree<Traits>;

Kernel::Point_3 toPoint(const glm::dvec3& p) {
    return {p.x, p.y, p.z};
}
}  // namespace

struct SurfaceDistance::Tree {
    std::vector<Triangle3> triangles;
    AabbTree tree;
};

SurfaceDistance::SurfaceDistance(const PreparedSurface& surface) : tree_(std::make_unique<Tree>()) {
    tree_->triangles.reserve(surface.triangles.size());
    for (const Triangle& t : surface.triangles) {
        tree_->triangles.emplace_back(toPoint(surface.positions[t[0]]),
                                      toPoint(surface.positions[t[1]]),
                                      toPoint(surface.positions[t[2]]));
    }
    tree_->tree.insert(tree_->triangles.cbegin(), tree_->triangles.cend());
    tree_->tree.build();
    tree_->tree.accelerate_distance_queries();
}

SurfaceDistance::~SurfaceDistance() = default;

SurfaceDistance::Nearest SurfaceDistance::nearest(const glm::dvec3& p) const {
    const auto [point, primitive] = tree_->tree.closest_point_and_primitive(toPoint(p));
    Nearest n;
    n.point = {point.x(), point.y(), point.z()};
    n.distance = glm::length(n.point - p);
    n.triangle = static_cast<std::uint32_t>(primitive - tree_->triangles.cbegin());
    return n;
}

double SurfaceDistance::distance(const glm::dvec3& p) const {
    return std::sqrt(tree_->tree.squared_distance(toPoint(p)));
}

std::optional<glm::dvec3> SurfaceDistance::firstHit(const glm::dvec3& origin,
                                                    const glm::dvec3& direction) const {
    const Kernel::Ray_3 ray(toPoint(origin),
                            Kernel::Vector_3(direction.x, direction.y, direction.z));
    const auto hit = tree_->tree.first_intersection(ray);
    if (!hit) {
        return std::nullopt;
    }
    if (const auto* point = boost::get<Kernel::Point_3>(&hit->first)) {
        return glm::dvec3(point->x(), point->y(), point->z());
    }
    if (const auto* segment = boost::get<Kernel::Segment_3>(&hit->first)) {
        // The ray runs in a triangle's plane: its nearer end.
        const auto& p = segment->source();
        return glm::dvec3(p.x(), p.y(), p.z());
    }
    return std::nullopt;
}

}  // namespace vv::analysis::detail
