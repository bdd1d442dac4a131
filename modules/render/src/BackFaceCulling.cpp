// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/render/BackFaceCulling.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

namespace vv::render {
namespace {

struct Box {
    glm::dvec3 min{0.0};
    glm::dvec3 max{0.0};
    [[nodiscard]] bool overlaps(const Box& other) const noexcept {
        return min.x <= other.max.x && other.min.x <= max.x && min.y <= other.max.y &&
               other.min.y <= max.y && min.z <= other.max.z && other.min.z <= max.z;
    }
};

bool finite(const glm::dvec3& v) noexcept {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

/// The near-plane rectangle's corners in world space, or nullopt when the
/// matrices cannot be inverted into finite points.
std::optional<std::array<glm::dvec3, 4>> nearRectangle(const glm::dmat4& viewProjection) noexcept {
    const glm::dmat4 inverse = glm::inverse(viewProjection);
    std::array<glm::dvec3, 4> corners{};
    const std::array<glm::dvec2, 4> ndc{glm::dvec2{-1, -1}, glm::dvec2{1, -1}, glm::dvec2{1, 1},
                                        glm::dvec2{-1, 1}};
    for (std::size_t i = 0; i < 4; ++i) {
        const glm::dvec4 p = inverse * glm::dvec4(ndc[i], -1.0, 1.0);
        if (!std::isfinite(p.w) || std::abs(p.w) < 1e-300) {
            return std::nullopt;
        }
        corners[i] = glm::dvec3(p) / p.w;
        if (!finite(corners[i])) {
            return std::nullopt;
        }
    }
    return corners;
}

/// The winding number of the mesh's surface around `origin`, counted along
/// the ray origin + t * direction (t > 0): +1 for each crossing along a
/// triangle's normal (leaving), -1 against it (entering). nullopt when the
/// ray grazes an edge or a triangle's plane, or starts on the surface.
std::optional<int> windingAlong(const scene::Mesh& mesh, const glm::dvec3& origin,
                                const glm::dvec3& direction) noexcept {
    constexpr double kEdge = 1e-9;  // barycentric margin that counts as "on an edge"
    int winding = 0;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const glm::dvec3 p0(mesh.positions[mesh.indices[t]]);
        const glm::dvec3 e1 = glm::dvec3(mesh.positions[mesh.indices[t + 1]]) - p0;
        const glm::dvec3 e2 = glm::dvec3(mesh.positions[mesh.indices[t + 2]]) - p0;
        const glm::dvec3 h = glm::cross(direction, e2);
        const double a = glm::dot(e1, h);
        const glm::dvec3 s = origin - p0;
        if (a * a <= 1e-24 * glm::dot(e1, e1) * glm::dot(e2, e2)) {
            // Parallel to the triangle's plane: unsure only if the ray lies in it.
            const glm::dvec3 normal = glm::cross(e1, e2);
            const double side = glm::dot(s, normal);
            if (side * side <= 1e-24 * glm::dot(normal, normal) * (glm::dot(s, s) + 1.0)) {
                return std::nullopt;
            }
            continue;
        }
        const double f = 1.0 / a;
        const double u = f * glm::dot(s, h);
        if (u < -kEdge || u > 1.0 + kEdge) {
            continue;  // most triangles leave here
        }
        const glm::dvec3 q = glm::cross(s, e1);
        const double v = f * glm::dot(direction, q);
        const double w = 1.0 - u - v;
        if (v < -kEdge || w < -kEdge) {
            continue;
        }
        const double along = f * glm::dot(e2, q);
        const double reach = glm::length(s) + glm::length(e1) + glm::length(e2);
        if (std::abs(along) <= 1e-12 * reach || u <= kEdge || v <= kEdge || w <= kEdge) {
            return std::nullopt;  // starts on the surface, or passes (too) near an edge
        }
        if (along > 0.0) {
            // The crossing's direction: a > 0 means the ray runs against the
            // normal cross(e1, e2) (entering), a < 0 along it (leaving).
            winding += a < 0.0 ? 1 : -1;
        }
    }
    return winding;
}

/// True when some triangle's bounding box meets `box` (float, the margin is in `box`).
bool anyTriangleMeets(const scene::Mesh& mesh, const glm::vec3& lo, const glm::vec3& hi) noexcept {
    const auto& p = mesh.positions;
    const auto& index = mesh.indices;
    for (std::size_t t = 0; t + 2 < index.size(); t += 3) {
        const glm::vec3& a = p[index[t]];
        const glm::vec3& b = p[index[t + 1]];
        const glm::vec3& c = p[index[t + 2]];
        const glm::vec3 tmin = glm::min(a, glm::min(b, c));
        const glm::vec3 tmax = glm::max(a, glm::max(b, c));
        if (tmin.x <= hi.x && lo.x <= tmax.x && tmin.y <= hi.y && lo.y <= tmax.y &&
            tmin.z <= hi.z && lo.z <= tmax.z) {
            return true;
        }
    }
    return false;
}

}  // namespace

CullFace cullableFaces(const scene::Mesh& mesh, scene::SurfaceClosure closure, const Aabb& bounds,
                       const glm::mat4& view, const glm::mat4& projection) noexcept {
    if (closure == scene::SurfaceClosure::Open || bounds.empty()) {
        return CullFace::None;
    }
    const glm::dmat4 viewProjection = glm::dmat4(projection) * glm::dmat4(view);
    // glm::perspective turns the right-handed eye space into left-handed
    // clip space, so an unmirrored view-projection has a negative determinant.
    const double determinant = glm::determinant(viewProjection);
    if (!std::isfinite(determinant) || determinant == 0.0) {
        return CullFace::None;
    }
    const auto corners = nearRectangle(viewProjection);
    if (!corners) {
        return CullFace::None;
    }
    Box rectangle{(*corners)[0], (*corners)[0]};
    for (const glm::dvec3& c : *corners) {
        rectangle.min = glm::min(rectangle.min, c);
        rectangle.max = glm::max(rectangle.max, c);
    }
    const Box meshBox{glm::dvec3(bounds.min), glm::dvec3(bounds.max)};
    // A margin for round-off in the matrices and the float positions.
    const double margin = 1e-5 * (glm::length(meshBox.max - meshBox.min) +
                                  glm::length(rectangle.max - rectangle.min) +
                                  glm::length(glm::abs(meshBox.min) + glm::abs(meshBox.max)));
    rectangle.min -= glm::dvec3(margin);
    rectangle.max += glm::dvec3(margin);
    if (rectangle.overlaps(meshBox)) {
        // The solid's box reaches the near plane: no triangle may come near
        // the rectangle, and the rectangle must lie outside every part.
        if (anyTriangleMeets(mesh, glm::vec3(rectangle.min), glm::vec3(rectangle.max))) {
            return CullFace::None;
        }
        const glm::dvec3 centre = ((*corners)[0] + (*corners)[2]) * 0.5;
        // Generic directions, so that a ray through a vertex or along an edge
        // is unlikely; a second and third try if it happens anyway.
        const std::array<glm::dvec3, 3> directions{glm::dvec3(0.5773, 0.6124, -0.5401),
                                                   glm::dvec3(-0.3338, 0.8419, 0.4241),
                                                   glm::dvec3(0.7071, -0.2929, 0.6436)};
        std::optional<int> winding;
        for (const glm::dvec3& d : directions) {
            winding = windingAlong(mesh, centre, glm::normalize(d));
            if (winding) {
                break;
            }
        }
        if (!winding || *winding != 0) {
            return CullFace::None;
        }
    }
    const bool mirrored = determinant > 0.0;
    const bool outward = closure == scene::SurfaceClosure::ClosedOutward;
    return outward != mirrored ? CullFace::Back : CullFace::Front;
}

}  // namespace vv::render
