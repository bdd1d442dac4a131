// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Resampling a volume along a vessel's centreline (issue 35): the stretched
// curved planar reformation along a path, and the plane of a cross-section.

#include <glm/vec3.hpp>
#include <stop_token>
#include <vector>

#include "vv/core/Image.h"
#include "vv/scene/Volume.h"
#include "vv/slices/SlicePlane.h"

namespace vv::slices {

/// The stretched curved planar reformation of `volume` along `points` (a
/// path's centreline points in order, LPS mm): column i samples the line
/// through points[i] across the path, from +halfWidthMm (row 0) to
/// -halfWidthMm, rows rowSpacingMm apart, as reslice() samples (linear,
/// NaN outside the volume). The across direction is rotation-minimising
/// along the path (the previous one projected off each new tangent,
/// starting perpendicular to the first), turned by `degrees` about the
/// path, so that a straight vessel does not twist and the picture turns as
/// one. The path is straightened: the columns stand for the points, the
/// distances along the path are the caller's. Throws InvalidArgumentError
/// for fewer than 2 points, a non-finite point, a half width or spacing
/// that is not positive and finite, more than 16384 rows or columns;
/// CancelledError when `stop` is requested.
[[nodiscard]] Image<float> curvedReformation(const scene::Volume& volume,
                                             const std::vector<glm::dvec3>& points,
                                             double halfWidthMm, double rowSpacingMm,
                                             double degrees, const std::stop_token& stop = {});

/// The square plane of `pixels` x `pixels` covering `fieldMm` around
/// `centre` in the plane of `right` and `up` (unit, orthogonal): a
/// cross-section as a person looks at it, `up` up. For reslice().
[[nodiscard]] SlicePlane sectionPlane(const glm::dvec3& centre, const glm::dvec3& right,
                                      const glm::dvec3& up, double fieldMm, int pixels);

}  // namespace vv::slices
