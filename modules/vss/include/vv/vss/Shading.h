// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <glm/vec3.hpp>

#include "vv/core/Image.h"

namespace vv::vss {

/// Where a normalised depth z' lies among N iso-lines.
/// The iso-lines are at the levels z' = k / N for k = 0..N (so 0 and 1, the
/// nearest and farthest vessel depth, are lines); they cut [0, 1] into N bands.
struct IsoLevel {
    int band = -1;          ///< floor(z' * N) clamped to 0..N-1; -1 for a non-finite z'
    float distance = 0.0F;  ///< distance to the nearest line in band widths, in [0, 0.5]; NaN for a
                            ///< non-finite z'
};

/// The iso-line position of z (values outside [0, 1] are clamped into it).
/// A shader draws a line where distance * N / |grad z'| is below half the
/// line width in pixels. Throws InvalidArgumentError for lineCount < 1.
[[nodiscard]] IsoLevel isoLevel(float z, int lineCount);

/// Unit normals of the height field h(x, y) = height(x, y) * depthScale, where
/// depthScale = dmax - dmin turns normalised depth into scene units, and
/// neighbouring pixel centres are pixelSize scene units apart.
/// Derivatives: central differences; one-sided at the image border and next to
/// a non-finite neighbour; 0 when neither neighbour is finite.
/// Frame: x along columns (right), y along rows (down), z along the depth (away
/// from the viewer); the normal faces the viewer: n = normalize(dh/dx, dh/dy, -1).
/// A non-finite height (no VSS there) gets (0, 0, -1). Never NaN.
/// Throws InvalidArgumentError unless depthScale is finite and >= 0 and
/// pixelSize is finite and > 0.
[[nodiscard]] Image<glm::vec3> heightFieldNormals(ImageView<const float> height, double depthScale,
                                                  double pixelSize);

}  // namespace vv::vss
