// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <glm/glm.hpp>

#include "passes/PassContext.h"
#include "vv/render/RenderGraph.h"

namespace vv::render {

struct CompositeInputs {
    PassContext context;
    Handle<Texture> vessels;      ///< VesselShadingOutputs::color
    bool useVss = false;          ///< lay the vessels over `vss`
    Handle<Texture> vss;          ///< VssShadingOutputs::color, read when useVss
    bool useAo = false;           ///< darken by `ao`
    Handle<Texture> ao;           ///< AoBlurOutputs::ao, read when useAo
    bool useTranslucent = false;  ///< lay `translucent` over all
    Handle<Texture> translucent;  ///< TranslucentOutputs::layer, read when useTranslucent
    /// Composite into a new texture "composited" (for "fxaa" or "upscale"),
    /// else into the imported board::kOutput.
    bool toTexture = false;
    /// With toTexture: the alpha of "composited" is how visible the VSS is
    /// at each pixel (0..1) instead of 1, for "upscale"'s iso-lines.
    bool vssVisibilityAlpha = false;
    /// `vss` is below the render size (VssSolveInputs::reduced,
    /// premultiplied, transparent on its vessel pixels): it is read
    /// bilinearly from its void pixels only and laid down at `vssOpacity`.
    bool reducedVss = false;
    float vssOpacity = 1.0F;
    float aoStrength = 0.0F;
    int aoStep = 1;              ///< `ao` holds every aoStep-th pixel per axis (SsaoInputs::step)
    glm::vec3 background{0.0F};  ///< sRGB
    glm::ivec2 size{1, 1};       ///< render size
};

struct CompositeOutputs {
    Handle<Texture> color;  ///< "composited", or the new version of board::kOutput
};

/// "composite": the translucent layer over the vessels over the VSS over
/// the background, darkened by the AO. Writing board::kOutput, it puts the
/// new version there.
CompositeOutputs addCompositePass(RenderGraph& graph, const CompositeInputs& inputs);

}  // namespace vv::render
