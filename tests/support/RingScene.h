// SPDX-License-Identifier: GPL-3.0-or-later
// A depth image of vessel rings, each enclosing a void region of its own,
// for tests of what a change in one place of the depth re-solves.
#pragma once

#include <array>
#include <cmath>
#include <limits>

#include "vv/core/Image.h"

namespace vv::test {

inline constexpr int kRingSceneWidth = 240;
inline constexpr int kRingSceneHeight = 120;

/// A ring of vessel pixels (radii 12 to 16) around (cx, cy), its depth
/// varying around it by +-0.08.
struct Ring {
    int cx = 0;
    int cy = 0;
    float depth = 0.5F;
    bool shown = true;
};

/// Four rings that do not touch.
inline std::array<Ring, 4> baseRings() {
    return {Ring{30, 40, 0.3F}, Ring{90, 70, 0.5F}, Ring{150, 45, 0.6F}, Ring{205, 75, 0.4F}};
}

/// Background +Inf; the rings shown; two single pixels holding the depth
/// range at 0.1 and 0.9 whatever the rings do, so that the visible-range
/// normalisation of the depth stays the same.
inline Image<float> ringSceneDepth(const std::array<Ring, 4>& rings) {
    Image<float> d(kRingSceneWidth, kRingSceneHeight, std::numeric_limits<float>::infinity());
    d(5, 5) = 0.1F;
    d(kRingSceneWidth - 6, kRingSceneHeight - 6) = 0.9F;
    for (const Ring& r : rings) {
        if (!r.shown) {
            continue;
        }
        for (int y = 0; y < kRingSceneHeight; ++y) {
            for (int x = 0; x < kRingSceneWidth; ++x) {
                const double dx = x - r.cx;
                const double dy = y - r.cy;
                const double rho = std::hypot(dx, dy);
                if (rho >= 12.0 && rho <= 16.0) {
                    d(x, y) = r.depth + 0.08F * static_cast<float>(std::cos(std::atan2(dy, dx)));
                }
            }
        }
    }
    return d;
}

}  // namespace vv::test
