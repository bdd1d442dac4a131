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
    glm::ivec2 size{1, 1};  ///< render size
    glm::ivec2 targetSize{1, 1};
};

struct FinalOutputs {
    Handle<Texture> output;  ///< the new version of board::kOutput
};

/// "fxaa": FXAA of board::kComposited into board::kOutput (bilinear taps,
/// so a reduced render size is upscaled on the way).
FinalOutputs addFxaaPass(RenderGraph& graph, const FxaaInputs& inputs);

/// "upscale": a bilinear blit of board::kComposited into board::kOutput —
/// far cheaper than a shader pass at the target size on software
/// rasterisers (frames that favour speed: the camera moving). Leaves the
/// output's framebuffer bound.
FinalOutputs addUpscalePass(RenderGraph& graph, const UpscaleInputs& inputs);

}  // namespace vv::render
