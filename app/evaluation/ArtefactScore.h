// SPDX-License-Identifier: GPL-3.0-or-later
// The artefact score of a lit VSS (issue 19, part 1): how much the shading
// next to vessel silhouettes varies from pixel to pixel ("teeth" along the
// contours, specks), and the CPU copy of the VSS shader's lighting that the
// score is taken of. Used by `vesselview-cli artefacts` and the tests.
#pragma once

#include <cstdint>
#include <glm/vec4.hpp>

#include "vv/core/Image.h"

namespace vv::evaluation {

/// Where and how finely the score looks.
struct ArtefactScoreOptions {
    double bandNear =
        1.0;               ///< the band: void pixels this far (px) from the nearest vessel pixel...
    double bandFar = 8.0;  ///< ...up to this far, both inclusive; 0 < bandNear <= bandFar
    double spacing = 3.0;  ///< px between the samples of the second difference along the contour
    double smoothing = 3.0;  ///< sigma (px) of the Gaussian that smooths the contour's direction
};

struct ArtefactScore {
    /// sqrt(mean over the band of (L(x) - (L(x + s t) + L(x - s t)) / 2)^2),
    /// t the contour's direction, s the spacing: the RMS second difference of
    /// the luminance along the contours, in luminance units (0..1).
    double rms = 0.0;
    std::int64_t bandPixels = 0;  ///< pixels averaged (0: no band; rms is then 0)
};

/// Chamfer distance (1, sqrt 2) of every pixel to the nearest pixel where
/// `vessels` is nonzero: 0 on vessel pixels, +Inf in an image without one.
/// Throws nothing.
[[nodiscard]] Image<float> distanceToVessels(ImageView<const std::uint8_t> vessels);

/// The score of `luminance` (finite = shaded VSS, non-finite = none) over the
/// void pixels (vessels == 0) whose distance to a vessel pixel
/// (distanceToVessels) lies in the band: the high-frequency part of the
/// luminance ALONG the contours (teeth, specks), blind to how it changes
/// across them (the VSS is steep next to a contour on any mesh). The
/// contour's direction t at a pixel is perpendicular to the gradient of the
/// distance (clipped at 2 bandFar) smoothed by a Gaussian of `smoothing`;
/// L(x +- s t) are bilinear samples. A pixel is left out when a sample
/// touches a vessel, a pixel without luminance or the image border, or the
/// direction is undefined (flat distance). Throws InvalidArgumentError when the sizes differ or the
/// options are out of range.
[[nodiscard]] ArtefactScore artefactScore(ImageView<const float> luminance,
                                          ImageView<const std::uint8_t> vessels,
                                          const ArtefactScoreOptions& options = {});

/// What the VSS shader (resources/shaders/vss.frag, slope-texture variant)
/// lights a void pixel with: the light, the depth range and pixel size.
struct VssLight {
    double dmin = 0.0;  ///< depth range of z' in scene units
    double dmax = 1.0;
    double pixelScale = 0.0;  ///< 2 tan(fov / 2) / image height, > 0
    double lightX = 0.0;      ///< towards the light (view space: y up; unit length)
    double lightY = 0.0;
    double lightZ = 1.0;
    double ambient = 0.30;
    double diffuse = 0.70;
    double specular = 0.25;
    double shininess = 48.0;
    double base = 0.5;  ///< the surface's grey (the colour scale left out)
};

/// The luminance of the lit VSS on every void pixel with a slope (slopes.w >
/// 0, from vss::fittedSlopes + vss::addNormalCoherence): base * (ambient +
/// diffuse max(n.l, 0)) + specular * Blinn-Phong, with the shader's specular
/// fade where the support is low and its Toksvig widening, clamped to 1;
/// NaN elsewhere (vessels, no VSS). Row 0 is the top of the image (as
/// render::rasterizeDepth gives it); the light is in view space (x right,
/// y up, z towards the viewer). Throws InvalidArgumentError when the
/// sizes differ or pixelScale is not > 0.
[[nodiscard]] Image<float> vssLuminance(ImageView<const float> height,
                                        ImageView<const glm::vec4> slopes,
                                        ImageView<const std::uint8_t> vessels,
                                        const VssLight& light);

}  // namespace vv::evaluation
