// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "vv/core/Image.h"

namespace vv::render {

/// The depth of a frame drawn at `depth`'s size (the render size) reduced to
/// width x height (the VSS's size, at most the render size per axis), for a
/// VSS solved below the render size: each reduced pixel covers the block of
/// render pixels whose centres fall in it, and is a vessel pixel (finite)
/// when any of them is, with the depth of the farthest of those. So the
/// reduced contour keeps the render size's silhouette: no vessel thinner
/// than a reduced pixel disappears, and a contour pixel's depth is the one
/// outermost on the vessel's flank (where the render size's contour lies),
/// not the one at the reduced pixel's centre, a round vessel's flank nearer
/// the viewer. Background (non-finite) elsewhere. Works in GL and image row
/// order alike. Throws InvalidArgumentError for a size below 1 or above
/// `depth`'s.
[[nodiscard]] Image<float> reduceDepth(const Image<float>& depth, int width, int height);

/// The steepest depth slope (depth per pixel, in units of a pixel's width at
/// that depth) silhouetteDepth() extrapolates along; a steeper step between
/// a contour pixel and the pixel inside it is an occlusion edge, not the
/// flank of one vessel, and is extrapolated only this far.
inline constexpr float kMaxSilhouetteSlope = 4.0F;

/// How far silhouetteDepth() extrapolates a contour pixel's depth outward, in
/// render pixels, at `reduction` window pixels per render pixel: 0 up to 2
/// (half size, where the bias is within the solver's noise), rising to 0.75
/// at 4 (a quarter; calibrated on the bundled demo and a smaller demo tree:
/// the far field's mean error against the window-size solve is smallest
/// there) and capped at 1.
[[nodiscard]] float silhouetteReach(float reduction) noexcept;

/// The depth a frame drawn at a reduced size (`reduction` window pixels per
/// render pixel) solves its VSS from, so that its iso-lines lie where the
/// window-size solve puts them.
///
/// Why: the contour of a void region is the row of vessel pixels next to it,
/// and the far field of the VSS is a weighted mean of their depths, weighted
/// by how many there are. At the window's size a contour pixel's centre lies
/// on average half a window pixel inside the silhouette, at a quarter of the
/// size two window pixels, where a round vessel's flank has turned toward
/// the viewer: every contour depth is nearer, and the far field moves toward
/// 0 by 0.5–0.8 % of the depth range, which in its flat parts moves an
/// iso-line by tens of window pixels. And a vessel one render pixel wide has
/// one contour row instead of the two it has at the window's size.
///
/// What, with reach = silhouetteReach(reduction) > 0 (else `depth` is
/// returned unchanged: the settled frame's solve reads the G-buffer as it
/// is):
/// - every vessel pixel (finite depth) with a background neighbour (8
///   neighbours) gets depth + reach * step, where step is its largest depth
///   rise toward a background neighbour (depth minus the depth of the pixel
///   opposite it), at most kMaxSilhouetteSlope * pixelScale * |depth|; where
///   the opposite pixel is background too (a vessel one pixel wide), step is
///   half a pixel's width, 0.5 * pixelScale * |depth|;
/// - a vessel pixel with background left and right gets its right neighbour
///   set to its (extrapolated) depth, one with background above and below
///   its next row's neighbour: the pixel becomes a vessel pixel of the solve,
///   so the thin vessel has two contour rows, as at the window's size.
/// `pixelScale`: scene units per render pixel per unit of depth; <= 0 or not
/// finite: returned unchanged. Works in GL and image row order alike.
[[nodiscard]] Image<float> silhouetteDepth(const Image<float>& depth, float reduction,
                                           float pixelScale);

}  // namespace vv::render
