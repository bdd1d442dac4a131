// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <glm/glm.hpp>

#include "passes/PassContext.h"
#include "vv/render/RenderGraph.h"

namespace vv::render {

struct CompositeInputs {
    PassContext context;
    bool useVss = false;          ///< lay the vessels over board::kVssColor
    bool useAo = false;           ///< darken by board::kAo
    bool useTranslucent = false;  ///< lay board::kTranslucentColor over all
    /// Composite into a new texture board::kComposited (for "fxaa" or
    /// "upscale"), else into board::kOutput.
    bool toTexture = false;
    /// With toTexture: the alpha of board::kComposited is how visible the
    /// VSS is at each pixel (0..1) instead of 1, for "upscale"'s iso-lines.
    bool vssVisibilityAlpha = false;
    /// board::kVssColor is below the render size (VssSolveInputs::reduced,
    /// premultiplied, transparent on its vessel pixels): it is read
    /// bilinearly from its void pixels only and laid down at `vssOpacity`.
    bool reducedVss = false;
    float vssOpacity = 1.0F;
    float aoStrength = 0.0F;
    int aoStep = 1;  ///< board::kAo holds every aoStep-th pixel per axis (SsaoInputs::step)
    glm::vec3 background{0.0F};  ///< sRGB
    glm::ivec2 size{1, 1};       ///< render size
};

struct CompositeOutputs {
    Handle<Texture> color;  ///< board::kComposited, or the new version of board::kOutput
};

/// "composite": the translucent layer over the vessels (board::kVesselColor)
/// over the VSS over the background, darkened by the AO. Puts its output
/// under its name (board::kComposited or board::kOutput).
CompositeOutputs addCompositePass(RenderGraph& graph, const CompositeInputs& inputs);

}  // namespace vv::render
