// SPDX-License-Identifier: GPL-3.0-or-later
// Private to vv::analysis: a prepared surface's triangles (without the
// caps) in CGAL's AABB tree: nearest points, rays, and the triangles a
// section plane crosses.
#pragma once

#include <atomic>
#include <cstdint>
#include <future>
#include <glm/glm.hpp>
#include <memory>
#include <optional>
#include <vector>

#include "PreparedSurface.h"

namespace vv::analysis::detail {

class SurfaceIndex {
  public:
    /// Where the index is built: here; on a thread of its own from here
    /// on (the first query waits for it, and rethrows what building threw,
    /// e.g. std::bad_alloc; the destructor waits for it too); or by the
    /// first query, on its thread (queries on other threads wait for it;
    /// never, when nothing asks).
    enum class Build : std::uint8_t { Now, InBackground, OnFirstQuery };

    /// How a nearest() or firstHit() query is answered. ScanUnlessBuilt:
    /// while the tree is not built (OnFirstQuery), by a scan of every
    /// triangle (on every core; a few ms on 300k triangles, the tree's
    /// answers), for at most kScanQueries such queries; then, or once the
    /// tree is built, by the tree. For the queries that come while building
    /// the tree would hold it beside other large arrays: a given source or
    /// a few given targets, resolved before the minimal paths (the tree
    /// built then was held beside the paths' tree, 16 MiB more at the demo
    /// tree's peak).
    enum class Lookup : std::uint8_t { Tree, ScanUnlessBuilt };
    static constexpr int kScanQueries = 8;

    /// Indexes `surface`'s triangles; the surface must outlive this object,
    /// and its positions and triangles must not change while it lives (the
    /// tree reads each triangle from them when a query needs it).
    /// Built whole before the first query answers: its queries may run on
    /// several threads at once.
    explicit SurfaceIndex(const PreparedSurface& surface, Build build = Build::Now);
    ~SurfaceIndex();
    SurfaceIndex(const SurfaceIndex&) = delete;
    SurfaceIndex& operator=(const SurfaceIndex&) = delete;
    SurfaceIndex(SurfaceIndex&&) = delete;
    SurfaceIndex& operator=(SurfaceIndex&&) = delete;

    struct Nearest {
        glm::dvec3 point{0.0};
        double distance = 0.0;
        std::uint32_t triangle = 0;  ///< index into surface.triangles
    };
    /// The surface point nearest to `p`.
    [[nodiscard]] Nearest nearest(const glm::dvec3& p, Lookup lookup = Lookup::Tree) const;
    /// Distance from `p` to the surface (the radius of the largest sphere
    /// centred at `p` that no triangle enters), the search starting from
    /// `hint`, a surface point near the answer (the nearest point of the
    /// previous query along a path). Returns the nearest point in `hint`.
    [[nodiscard]] double distance(const glm::dvec3& p, glm::dvec3& hint) const;
    /// Where the ray from `origin` along `direction` (non-zero) first meets
    /// the surface; nullopt when it meets none.
    [[nodiscard]] std::optional<glm::dvec3> firstHit(const glm::dvec3& origin,
                                                     const glm::dvec3& direction,
                                                     Lookup lookup = Lookup::Tree) const;

    /// The triangles that have corners on both sides of the plane through
    /// `point` with normal `normal` (a corner on the plane counts as on the
    /// side the normal points to, as the section's cut counts it) and whose
    /// bounding boxes meet the box [lo, hi]; indices into
    /// surface.triangles, in no order. Only the tree's nodes that meet the
    /// box and straddle the plane are opened.
    [[nodiscard]] std::vector<std::uint32_t> trianglesOnPlane(const glm::dvec3& point,
                                                              const glm::dvec3& normal,
                                                              const glm::dvec3& lo,
                                                              const glm::dvec3& hi) const;

    /// Whether the tree has been built (false until a query builds it when
    /// built OnFirstQuery).
    [[nodiscard]] bool built() const;

  private:
    struct Tree;
    [[nodiscard]] const Tree& tree() const;
    /// Whether a query looked up as `lookup` is answered by a scan (Lookup).
    [[nodiscard]] bool scanInstead(Lookup lookup) const;
    const PreparedSurface* surface_;
    std::unique_ptr<Tree> tree_;
    std::shared_future<void> built_;  ///< valid unless built Now
    mutable std::atomic<int> scansLeft_{0};
};

}  // namespace vv::analysis::detail
