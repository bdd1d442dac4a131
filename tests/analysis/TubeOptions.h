// SPDX-License-Identifier: GPL-3.0-or-later
// The tube phantoms the analysis tests share: proportions that scale with
// the radius (20 radii long, bent at 10 radii, a stenosis over 4 radii).
#pragma once

#include <cstddef>

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

}  // namespace vv::test
