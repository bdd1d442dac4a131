// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/slices/OrientationLetters.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace vv::slices {

namespace {

// Letters of the positive and negative direction of each LPS axis.
constexpr std::array<char, 3> kPositive{'L', 'P', 'S'};
constexpr std::array<char, 3> kNegative{'R', 'A', 'I'};
constexpr double kSecondaryFraction = 0.25;

}  // namespace

std::string directionLetters(const glm::dvec3& direction) {
    const glm::dvec3 m = glm::abs(direction);
    const double largest = std::max({m.x, m.y, m.z});
    if (!std::isfinite(largest) || largest <= 0.0) {
        return {};
    }
    std::array<int, 3> order{0, 1, 2};
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return m[a] > m[b]; });
    std::string letters;
    for (const int a : order) {
        if (m[a] >= kSecondaryFraction * largest) {
            const auto u = static_cast<std::size_t>(a);
            letters += direction[a] > 0.0 ? kPositive[u] : kNegative[u];
        }
    }
    return letters;
}

EdgeLetters edgeLetters(const SlicePlane& plane) {
    return {directionLetters(-plane.right), directionLetters(plane.right),
            directionLetters(-plane.down), directionLetters(plane.down)};
}

PositionText slicePositionText(int axis, double mm) noexcept {
    const auto u = static_cast<std::size_t>(std::clamp(axis, 0, 2));
    return {mm >= 0.0 ? kPositive[u] : kNegative[u], std::abs(mm)};
}

}  // namespace vv::slices
