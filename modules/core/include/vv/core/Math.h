// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <limits>
#include <span>

namespace vv {

/// Axis-aligned bounding box. A default box is empty (min > max) and grows
/// with extend(); an empty box has no centre or size.
struct Aabb {
    glm::vec3 min{std::numeric_limits<float>::max()};
    glm::vec3 max{std::numeric_limits<float>::lowest()};

    [[nodiscard]] bool empty() const noexcept {
        return min.x > max.x || min.y > max.y || min.z > max.z;
    }
    void extend(const glm::vec3& p) noexcept {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
    void extend(const Aabb& other) noexcept {
        if (!other.empty()) {
            extend(other.min);
            extend(other.max);
        }
    }
    [[nodiscard]] glm::vec3 center() const noexcept { return 0.5F * (min + max); }
    [[nodiscard]] glm::vec3 size() const noexcept { return empty() ? glm::vec3(0) : max - min; }
    /// Radius of the sphere around center() that holds the box.
    [[nodiscard]] float radius() const noexcept { return 0.5F * glm::length(size()); }
};

/// True when every component of v is finite.
[[nodiscard]] inline bool isFinite(const glm::vec3& v) noexcept {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

/// Bounding box of points (empty box for no points).
[[nodiscard]] inline Aabb boundsOf(std::span<const glm::vec3> points) noexcept {
    Aabb box;
    for (const auto& p : points) {
        box.extend(p);
    }
    return box;
}

/// Twice the area of triangle (a, b, c) as the length of the cross product.
[[nodiscard]] inline float doubleTriangleArea(const glm::vec3& a, const glm::vec3& b,
                                              const glm::vec3& c) noexcept {
    return glm::length(glm::cross(b - a, c - a));
}

/// Linear interpolation between a and b by t in [0, 1].
template <typename T>
[[nodiscard]] constexpr T lerp(const T& a, const T& b, float t) noexcept {
    return a + (b - a) * t;
}

}  // namespace vv
