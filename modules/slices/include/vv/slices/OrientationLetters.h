// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The orientation letters shown on the edges of a slice view.

#include <glm/glm.hpp>
#include <string>

#include "vv/slices/SlicePlane.h"

namespace vv::slices {

/// The patient directions a direction in LPS points to: L / R (+x / -x),
/// P / A (+y / -y), S / I (+z / -z), the dominant first: one letter per
/// component whose magnitude is at least a quarter of the largest (so a
/// direction 15 degrees or more off an axis shows a second letter, e.g. "LA"),
/// ordered by decreasing magnitude. Empty for a zero or non-finite direction.
[[nodiscard]] std::string directionLetters(const glm::dvec3& direction);

/// The letters on the four edges of a view of `plane`: each the direction
/// from the view's centre towards that edge.
struct EdgeLetters {
    std::string left;
    std::string right;
    std::string top;
    std::string bottom;
};
[[nodiscard]] EdgeLetters edgeLetters(const SlicePlane& plane);

/// The slice position `mm` along world axis `axis` (0 x, 1 y, 2 z) as a
/// patient direction and a distance: the letter of the positive axis
/// direction (L, P, S) for mm >= 0, else the opposite (R, A, I), and |mm|.
struct PositionText {
    char letter = 'S';
    double distance = 0.0;
};
[[nodiscard]] PositionText slicePositionText(int axis, double mm) noexcept;

}  // namespace vv::slices
