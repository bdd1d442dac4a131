// SPDX-License-Identifier: GPL-3.0-or-later
// The tube phantoms the analysis tests share: proportions that scale with
// the radius (20 radii long, bent at 10 radii, a stenosis over 4 radii), and
// how far a centreline strays from a phantom's axis.
#pragma once

#include <algorithm>
#include <cstddef>

#include "vv/analysis/Centerlines.h"
#include "vv/demo/TubePhantom.h"

namespace vv::test {

inline demo::TubePhantomOptions tubeOptions(demo::TubeShape shape, double radius,
                                            std::size_t triangles, double jitter = 0.0) {
    demo::TubePhantomOptions o;
    o.shape = shape;
    o.radiusMm = radius;
    o.lengthMm = 20.0 * radius;
    o.bendRadiusMm = 10.0 * radius;
    o.stenosisLengthMm = 4.0 * radius;
    o.targetTriangles = triangles;
    o.jitterFraction = jitter;
    return o;
}

/// The largest distance from the centreline to the true axis over the points
/// at least `margin` from both ends of the axis.
inline double worstAxisDistance(const analysis::CenterlineTree& tree,
                                const demo::TubePhantom& truth, double margin) {
    double worst = 0.0;
    for (const auto& branch : tree.branches) {
        for (const auto& point : branch.points) {
            const auto [distance, s] = truth.distanceToAxis(point.position);
            if (s >= margin && s <= truth.lengthMm - margin) {
                worst = std::max(worst, distance);
            }
        }
    }
    return worst;
}

}  // namespace vv::test
