// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <glm/glm.hpp>

#include "passes/FrameResources.h"
#include "passes/PassContext.h"
#include "vv/render/RenderGraph.h"

namespace vv::render {

struct UpscaleInputs {
    PassContext context;
    Handle<Texture> color;  ///< CompositeOutputs::color ("composited")
    glm::ivec2 targetSize{1, 1};
    glm::ivec2 renderSize{1, 1};  ///< `color`'s
    /// The VSS's iso-lines, drawn at the target size from `vssHeight` where
    /// `color`'s alpha says the VSS shows (CompositeInputs::vssVisibilityAlpha);
    /// 0 = none (nothing else read).
    int isoLines = 0;
    float isoLineWidth = 1.5F;  ///< target pixels
    float isoLineStrength = 0.0F;
    Handle<Texture> vssHeight;            ///< VssSolveOutputs::height, read with isoLines
    Handle<CpuValue<ShownVss>> shownVss;  ///< VssSolveOutputs::shown, read with isoLines
    /// The vessels' silhouettes redrawn at the target's resolution
    /// (upscale.frag's EDGES variant, in the rectangles along them that
    /// `depthImage` gives, SilhouetteRuns.h; reads `linearDepth` too);
    /// false = every pixel bilinear.
    bool sharpEdges = true;
    Handle<Texture> linearDepth;              ///< GeometryOutputs::linearDepth
    Handle<CpuValue<DepthImage>> depthImage;  ///< DepthReadbackOutputs::image
};

struct UpscaleOutputs {
    Handle<Texture> output;  ///< the new version of board::kOutput
};

/// "upscale": the last step of a frame at a reduced render size without
/// anti-aliasing: `color` into the imported board::kOutput with bilinear
/// interpolation (four texel fetches a pixel: about what a blit costs on
/// software rasterisers, where FXAA at the target size costs twice that),
/// the VSS iso-lines and the vessels' silhouettes drawn at the target's
/// resolution (upscale.frag): frames that favour speed (the camera moving).
/// Puts the output's new version on the blackboard and leaves its
/// framebuffer bound.
UpscaleOutputs addUpscalePass(RenderGraph& graph, const UpscaleInputs& inputs);

}  // namespace vv::render
