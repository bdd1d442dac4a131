// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <glm/glm.hpp>

#include "passes/PassContext.h"
#include "vv/render/RenderGraph.h"

namespace vv::render {

struct AoBlurInputs {
    PassContext context;
    Handle<Texture> raw;    ///< SsaoOutputs::raw
    glm::ivec2 size{1, 1};  ///< the size of `raw` (aoSize() of the frame's and the SSAO's step)
};

struct AoBlurOutputs {
    Handle<Texture> ao;  ///< R8, persistent
};

/// "ao-blur": a depth-aware blur of the raw occlusion into "ao".
AoBlurOutputs addAoBlurPass(RenderGraph& graph, const AoBlurInputs& inputs);

}  // namespace vv::render
