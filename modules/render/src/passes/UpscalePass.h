// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <glm/glm.hpp>

#include "passes/PassContext.h"
#include "vv/render/RenderGraph.h"

namespace vv::render {

struct UpscaleInputs {
    PassContext context;
    glm::ivec2 size{1, 1};  ///< render size
    glm::ivec2 targetSize{1, 1};
};

struct UpscaleOutputs {
    Handle<Texture> output;  ///< the new version of board::kOutput
};

/// "upscale": a bilinear blit of board::kComposited into board::kOutput, for
/// a reduced render size without anti-aliasing — far cheaper than a shader
/// pass at the target size on software rasterisers (frames that favour
/// speed: the camera moving). Leaves the output's framebuffer bound.
UpscaleOutputs addUpscalePass(RenderGraph& graph, const UpscaleInputs& inputs);

}  // namespace vv::render
