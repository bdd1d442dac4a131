// SPDX-License-Identifier: GPL-3.0-or-later
#include "SurfaceIndex.h"

#include <CGAL/AABB_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <boost/iterator/counting_iterator.hpp>
#include <boost/property_map/property_map.hpp>
#include <chrono>
#include <cmath>
#include <future>
#include <iterator>
#include <limits>
#include <mutex>
#include <vector>

#include "vv/core/Parallel.h"

namespace vv::analysis::detail {
namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Triangle3 = Kernel::Triangle_3;

Kernel::Point_3 toPoint(const glm::dvec3& p) {
    return {p.x, p.y, p.z};
}

/// A triangle of the surface by its index, made from the surface's own
/// positions when the tree asks for it: the tree keeps no copy of them.
struct TriangleMap {
    using key_type = std::uint32_t;
    using value_type = Triangle3;
    using reference = Triangle3;
    using category = boost::readable_property_map_tag;
    const PreparedSurface* surface = nullptr;

    friend Triangle3 get(const TriangleMap& map, std::uint32_t id) {
        const Triangle& t = map.surface->triangles[id];
        const auto& p = map.surface->positions;
        return {toPoint(p[t[0]]), toPoint(p[t[1]]), toPoint(p[t[2]])};
    }
};

/// A point of each triangle (its first corner), as CGAL's reference point.
struct CornerMap {
    using key_type = std::uint32_t;
    using value_type = Kernel::Point_3;
    using reference = Kernel::Point_3;
    using category = boost::readable_property_map_tag;
    const PreparedSurface* surface = nullptr;

    friend Kernel::Point_3 get(const CornerMap& map, std::uint32_t id) {
        return toPoint(map.surface->positions[map.surface->triangles[id][0]]);
    }
};

using Primitive =
    CGAL::AABB_primitive<std::uint32_t, TriangleMap, CornerMap, CGAL::Tag_true, CGAL::Tag_false>;
using Traits = CGAL::AABB_traits<Kernel, Primitive>;
using AabbTree = CGAL::AABB_tree<Traits>;

constexpr std::uint32_t kHintStride = 8;
/// The triangles scanned by one task of a scan.
constexpr long kScanGrain = 16384;

/// SurfaceIndex::nearest by a scan of every triangle: the nearest point of
/// each (CGAL's projection onto a triangle), the least distance, the lowest
/// triangle id among equals.
SurfaceIndex::Nearest nearestByScan(const PreparedSurface& s, const glm::dvec3& p) {
    const Kernel::Point_3 query = toPoint(p);
    const auto project = Kernel().construct_projected_point_3_object();
    std::mutex mutex;
    SurfaceIndex::Nearest best;
    best.distance = std::numeric_limits<double>::infinity();
    parallelFor(0, static_cast<long>(s.triangles.size()), kScanGrain, [&](long begin, long end) {
        SurfaceIndex::Nearest local;
        local.distance = std::numeric_limits<double>::infinity();
        const TriangleMap triangles{&s};
        for (long id = begin; id < end; ++id) {
            const auto point = project(get(triangles, static_cast<std::uint32_t>(id)), query);
            const double d = CGAL::squared_distance(point, query);  // squared until the end
            if (d < local.distance) {
                local = {{point.x(), point.y(), point.z()}, d, static_cast<std::uint32_t>(id)};
            }
        }
        const std::scoped_lock lock(mutex);
        if (local.distance < best.distance ||
            (local.distance == best.distance && local.triangle < best.triangle)) {
            best = local;
        }
    });
    best.distance = glm::length(best.point - p);
    return best;
}

/// SurfaceIndex::firstHit by a scan of every triangle: the hit nearest the
/// ray's origin (a segment's nearer end where the ray runs in a triangle's
/// plane).
std::optional<glm::dvec3> firstHitByScan(const PreparedSurface& s, const Kernel::Ray_3& ray) {
    std::mutex mutex;
    std::optional<glm::dvec3> best;
    double bestDistance = std::numeric_limits<double>::infinity();
    const glm::dvec3 origin(ray.source().x(), ray.source().y(), ray.source().z());
    parallelFor(0, static_cast<long>(s.triangles.size()), kScanGrain, [&](long begin, long end) {
        std::optional<glm::dvec3> local;
        double localDistance = std::numeric_limits<double>::infinity();
        const TriangleMap triangles{&s};
        for (long id = begin; id < end; ++id) {
            const auto hit =
                CGAL::intersection(ray, get(triangles, static_cast<std::uint32_t>(id)));
            if (!hit) {
                continue;
            }
            std::optional<glm::dvec3> point;
            if (const auto* p = boost::get<Kernel::Point_3>(&*hit)) {
                point = glm::dvec3(p->x(), p->y(), p->z());
            } else if (const auto* segment = boost::get<Kernel::Segment_3>(&*hit)) {
                const glm::dvec3 a(segment->source().x(), segment->source().y(),
                                   segment->source().z());
                const glm::dvec3 b(segment->target().x(), segment->target().y(),
                                   segment->target().z());
                point = glm::length(a - origin) <= glm::length(b - origin) ? a : b;
            }
            if (point && glm::length(*point - origin) < localDistance) {
                localDistance = glm::length(*point - origin);
                local = point;
            }
        }
        const std::scoped_lock lock(mutex);
        if (local && localDistance < bestDistance) {
            bestDistance = localDistance;
            best = local;
        }
    });
    return best;
}

}  // namespace

struct SurfaceIndex::Tree {
    const PreparedSurface* surface = nullptr;
    AabbTree tree;

    void fill(const PreparedSurface& s) {
        surface = &s;
        const auto count = static_cast<std::uint32_t>(s.triangles.size());
        tree.insert(boost::counting_iterator<std::uint32_t>(0),
                    boost::counting_iterator<std::uint32_t>(count), TriangleMap{&s}, CornerMap{&s});
        tree.build();
        // The hints of the distance queries (a start near the answer; the
        // answer is exact whatever the hint): the first corner of every
        // kHintStride-th triangle, not CGAL's default of one point per
        // triangle, whose kd-tree held some 40 bytes per triangle at the
        // analysis' peak for hints a few triangles nearer.
        std::vector<AabbTree::Point_and_primitive_id> hints;
        hints.reserve(count / kHintStride + 1);
        for (std::uint32_t id = 0; id < count; id += kHintStride) {
            hints.emplace_back(toPoint(s.positions[s.triangles[id][0]]), id);
        }
        if (!hints.empty()) {
            tree.accelerate_distance_queries(hints.cbegin(), hints.cend());
        }
    }
};

SurfaceIndex::SurfaceIndex(const PreparedSurface& surface, Build build)
    : surface_(&surface), tree_(std::make_unique<Tree>()) {
    if (build == Build::Now) {
        tree_->fill(surface);
        return;
    }
    scansLeft_ = kScanQueries;
    Tree* tree = tree_.get();
    built_ = std::async(build == Build::InBackground ? std::launch::async : std::launch::deferred,
                        [tree, &surface] { tree->fill(surface); })
                 .share();
}

SurfaceIndex::~SurfaceIndex() {
    // A thread may still write to tree_; a build never asked for is not run.
    if (built_.valid() &&
        built_.wait_for(std::chrono::seconds(0)) != std::future_status::deferred) {
        built_.wait();
    }
}

const SurfaceIndex::Tree& SurfaceIndex::tree() const {
    if (built_.valid()) {
        built_.get();  // waits; rethrows what the building threw
    }
    return *tree_;
}

bool SurfaceIndex::built() const {
    return !built_.valid() || built_.wait_for(std::chrono::seconds(0)) == std::future_status::ready;
}

bool SurfaceIndex::scanInstead(Lookup lookup) const {
    return lookup == Lookup::ScanUnlessBuilt && built_.valid() &&
           built_.wait_for(std::chrono::seconds(0)) == std::future_status::deferred &&
           scansLeft_.fetch_sub(1) > 0;
}

SurfaceIndex::Nearest SurfaceIndex::nearest(const glm::dvec3& p, Lookup lookup) const {
    if (scanInstead(lookup)) {
        return nearestByScan(*surface_, p);
    }
    const Tree& t = tree();
    const auto [point, primitive] = t.tree.closest_point_and_primitive(toPoint(p));
    Nearest n;
    n.point = {point.x(), point.y(), point.z()};
    n.distance = glm::length(n.point - p);
    n.triangle = primitive;
    return n;
}

double SurfaceIndex::distance(const glm::dvec3& p, glm::dvec3& hint) const {
    const Kernel::Point_3 nearest = tree().tree.closest_point(toPoint(p), toPoint(hint));
    hint = {nearest.x(), nearest.y(), nearest.z()};
    return glm::length(hint - p);
}

std::optional<glm::dvec3> SurfaceIndex::firstHit(const glm::dvec3& origin,
                                                 const glm::dvec3& direction, Lookup lookup) const {
    const Kernel::Ray_3 ray(toPoint(origin),
                            Kernel::Vector_3(direction.x, direction.y, direction.z));
    if (scanInstead(lookup)) {
        return firstHitByScan(*surface_, ray);
    }
    const auto hit = tree().tree.first_intersection(ray);
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

namespace {

/// A plane cut limited to a box: CGAL's AABB traversal opens only the nodes
/// whose boxes meet the box and straddle the plane, and lists the triangles
/// whose corners lie on both sides of it (a corner on the plane counts as
/// above, as the cut that uses them counts it) and whose boxes meet the box.
struct PlaneInBox {
    glm::dvec3 point;
    glm::dvec3 normal;
    CGAL::Bbox_3 box;
};

class PlaneInBoxTraversal {
  public:
    PlaneInBoxTraversal(const PreparedSurface& surface, std::vector<std::uint32_t>& out)
        : triangles_{&surface}, out_(out) {}

    // The names below are the ones CGAL's AABB traversal calls.
    // NOLINTNEXTLINE(readability-identifier-naming)
    [[nodiscard]] static constexpr bool go_further() { return true; }

    void intersection(const PlaneInBox& q, const Primitive& primitive) {
        const Triangle3 t = get(triangles_, primitive.id());
        if (!CGAL::do_overlap(q.box, t.bbox())) {
            return;
        }
        int above = 0;
        for (int k = 0; k < 3; ++k) {
            const auto& v = t.vertex(k);
            above += glm::dot(glm::dvec3(v.x(), v.y(), v.z()) - q.point, q.normal) >= 0.0 ? 1 : 0;
        }
        if (above == 1 || above == 2) {
            out_.push_back(primitive.id());
        }
    }

    // NOLINTNEXTLINE(readability-identifier-naming)
    [[nodiscard]] static bool do_intersect(const PlaneInBox& q,
                                           const CGAL::AABB_node<Traits>& node) {
        const CGAL::Bbox_3& b = node.bbox();
        if (!CGAL::do_overlap(q.box, b)) {
            return false;
        }
        const glm::dvec3 lo(b.xmin(), b.ymin(), b.zmin());
        const glm::dvec3 hi(b.xmax(), b.ymax(), b.zmax());
        const glm::dvec3 centre = 0.5 * (lo + hi);
        const glm::dvec3 half = 0.5 * (hi - lo);
        const double reach = glm::dot(glm::abs(q.normal), half);
        const double offset = std::abs(glm::dot(centre - q.point, q.normal));
        // A margin for rounding: a node that only grazes the plane is opened.
        return offset <= reach * (1.0 + 1e-9) + 1e-9 * glm::length(centre - q.point);
    }

  private:
    TriangleMap triangles_;
    std::vector<std::uint32_t>& out_;
};

}  // namespace

std::vector<std::uint32_t> SurfaceIndex::trianglesOnPlane(const glm::dvec3& point,
                                                          const glm::dvec3& normal,
                                                          const glm::dvec3& lo,
                                                          const glm::dvec3& hi) const {
    std::vector<std::uint32_t> crossing;
    const Tree& t = tree();
    PlaneInBoxTraversal traversal(*t.surface, crossing);
    t.tree.traversal(
        PlaneInBox{.point = point, .normal = normal, .box = {lo.x, lo.y, lo.z, hi.x, hi.y, hi.z}},
        traversal);
    return crossing;
}

}  // namespace vv::analysis::detail
