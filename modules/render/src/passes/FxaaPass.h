// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <glm/glm.hpp>

#include "passes/PassContext.h"
#include "vv/render/RenderGraph.h"

namespace vv::render {

struct FxaaInputs {
    PassContext context;
    Handle<Texture> color;  ///< CompositeOutputs::color ("composited")
    glm::ivec2 targetSize{1, 1};
};

struct FxaaOutputs {
    Handle<Texture> output;  ///< the new version of board::kOutput
};

/// "fxaa": the last step of a frame whose composite went into a texture:
/// FXAA of `color` into the imported board::kOutput at the target's size
/// (bilinear taps, so a reduced render size is upscaled on the way); puts
/// the output's new version there.
FxaaOutputs addFxaaPass(RenderGraph& graph, const FxaaInputs& inputs);

}  // namespace vv::render
