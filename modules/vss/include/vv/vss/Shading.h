// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <stop_token>

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

/// The slope of the VSS that its lighting uses, per pixel, as (dz'/dx,
/// dz'/dy, support, 1) on void pixels with a VSS and (0, 0, 0, 0) elsewhere
/// (vessel pixels, no VSS). Pixel units; x along columns, y along rows.
///
/// The slope is the weighted least-squares plane (offset and slope) through
/// the void VSS pixels of the 5x5 window around (Gaussian weights
/// exp(-(dx^2 + dy^2) / 4); vessel pixels never count, so the fit never
/// reaches across a contour, where z' meets the vessel's depth). `support` is
/// the weight of those pixels over the weight of the window's pixels inside
/// the image (the border is no contour). Where the same 5x5 window with
/// samples four pixels apart has support < 0.999 (a vessel pixel or one
/// without VSS among its samples: within 8 px of a contour), its fit is taken
/// instead where it determines a plane, each of its samples being the mean
/// offset and z' of the void VSS pixels among the 5x5 around it (the sample
/// sits at their centroid, so a plane stays exact): this smooths the ripples
/// that the silhouette's pixel staircase leaves in z' there (the "teeth"
/// along contours, docs/benchmarks/artefacts.md). Where a fit is
/// ill-conditioned (det < 0.05 of its diagonal product) or empty, the slope is
/// the one-pixel difference (central where both neighbours have a VSS,
/// one-sided where one has, 0 where none has; vessel pixels count here).
/// This is what the VSS shader computed per pixel; computed once per solve
/// here (separable sums, O(25) per pixel), it spares the shader ~100 texture
/// reads per pixel.
///
/// `height`: z' on void pixels, z on vessel pixels, non-finite = no VSS.
/// `vessels`: nonzero = vessel pixel, same size. Throws InvalidArgumentError
/// when the sizes differ, CancelledError when `stop` is requested.
[[nodiscard]] Image<glm::vec4> fittedSlopes(ImageView<const float> height,
                                            ImageView<const std::uint8_t> vessels,
                                            const std::stop_token& stop = {});

/// What turns a slope in z' per pixel into a slope in scene units: the
/// depth range z is normalised over and the pixel size per unit of depth
/// (2 tan(fov / 2) / image height for a perspective view).
struct SlopeScale {
    double dmin = 0.0;
    double dmax = 0.0;
    double pixelScale = 0.0;
};

/// Toksvig's coherence of the VSS normals around each void pixel of
/// `slopes` (from fittedSlopes), written into its w: |mean of the normal and
/// the four normals 3 pixels away| in [1e-3, 1] (1 = a flat neighbourhood);
/// the shader widens and dims the highlight where it is below 1. A
/// neighbour's normal is its central difference when it and its four
/// neighbours have a VSS and it is no vessel pixel, else it counts as a zero
/// normal (turned away); neighbours within a pixel of the image border are
/// left out. Normals in scene units: slope * (dmax - dmin) / (depth *
/// pixelScale) with depth = dmin + z' (dmax - dmin) at the centre pixel.
/// Pixels with w = 0 (no fitted slope) stay 0. Throws InvalidArgumentError
/// when the sizes differ or `scale` is not finite with pixelScale > 0.
void addNormalCoherence(Image<glm::vec4>& slopes, ImageView<const float> height,
                        ImageView<const std::uint8_t> vessels, const SlopeScale& scale);

}  // namespace vv::vss
