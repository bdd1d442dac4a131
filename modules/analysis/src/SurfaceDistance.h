// SPDX-License-Identifier: GPL-3.0-or-later
// Private to vv::analysis: nearest points on a prepared surface (its own
// triangles, without the caps), through CGAL's AABB tree.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <optional>

#include "PreparedSurface.h"

namespace vv::analysis::detail {

class SurfaceDistance {
  public:
    /// Indexes `surface`'s triangles; the surface must outlive this object.
    explicit SurfaceDistance(const PreparedSurface& surface);
    ~SurfaceDistance();
    SurfaceDistance(const SurfaceDistance&) = delete;
    SurfaceDistance& operator=(const SurfaceDistance&) = delete;
    SurfaceDistance(SurfaceDistance&&) = delete;
    SurfaceDistance& operator=(SurfaceDistance&&) = delete;

    struct Nearest {
        glm::dvec3 point{0.0};
        double distance = 0.0;
        std::uint32_t triangle = 0;  ///< index into surface.triangles
    };
    /// The surface point nearest to `p`.
    [[nodiscard]] Nearest nearest(const glm::dvec3& p) const;
    /// Distance from `p` to the surface (the radius of the largest sphere
    /// centred at `p` that no triangle enters).
    [[nodiscard]] double distance(const glm::dvec3& p) const;
    /// Where the ray from `origin` along `direction` (non-zero) first meets
    /// the surface; nullopt when it meets none.
    [[nodiscard]] std::optional<glm::dvec3> firstHit(const glm::dvec3& origin,
                                                     const glm::dvec3& direction) const;

  private:
    struct Tree;
    std::unique_ptr<Tree> tree_;
};

}  // namespace vv::analysis::detail
