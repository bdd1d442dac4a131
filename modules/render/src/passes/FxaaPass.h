// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <glm/glm.hpp>

#include "passes/PassContext.h"
#include "vv/render/RenderGraph.h"

namespace vv::render {

// The last step of a frame whose composite went into a texture
// (board::kComposited): "fxaa" or, for a reduced render size without
// anti-aliasing, "upscale". Both write board::kOutput at the target's size.

struct FxaaInputs {
    PassContext context;
    glm::ivec2 targetSize{1, 1};
};

struct UpscaleInputs {
    PassContext context;
    glm::ivec2 targetSize{1, 1};
    glm::ivec2 renderSize{1, 1};  ///< board::kComposited's
    /// The VSS's iso-lines, drawn at the target size from board::kVssHeight
    /// where board::kComposited's alpha says the VSS shows
    /// (CompositeInputs::vssVisibilityAlpha); 0 = none (nothing else read).
    int isoLines = 0;
    float isoLineWidth = 1.5F;  ///< target pixels
    float isoLineStrength = 0.0F;
    /// The vessels' silhouettes redrawn at the target's resolution
    /// (upscale.frag's EDGES variant, in the rectangles along them that
    /// board::kLinearDepthImage gives, SilhouetteRuns.h; reads
    /// board::kLinearDepth too); false = every pixel bilinear.
    bool sharpEdges = true;
};

struct FinalOutputs {
    Handle<Texture> output;  ///< the new version of board::kOutput
};

/// "fxaa": FXAA of board::kComposited into board::kOutput (bilinear taps,
/// so a reduced render size is upscaled on the way).
FinalOutputs addFxaaPass(RenderGraph& graph, const FxaaInputs& inputs);

/// "upscale": board::kComposited into board::kOutput with bilinear
/// interpolation (four texel fetches a pixel: about what a blit costs on
/// software rasterisers, where FXAA at the target size costs twice that),
/// the VSS iso-lines and the vessels' silhouettes drawn at the target's
/// resolution (upscale.frag): frames that favour speed (the camera moving).
/// Leaves the output's framebuffer bound.
FinalOutputs addUpscalePass(RenderGraph& graph, const UpscaleInputs& inputs);

}  // namespace vv::render
