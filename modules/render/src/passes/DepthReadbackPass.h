// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "passes/FrameResources.h"
#include "passes/PassContext.h"
#include "vv/render/RenderGraph.h"

namespace vv::render {

struct DepthReadbackInputs {
    PassContext context;
};

struct DepthReadbackOutputs {
    Handle<CpuValue<DepthImage>> image;  ///< persistent: re-read only when the depth changes
};

/// "depth-readback": reads board::kLinearDepth back to the CPU once per
/// G-buffer, for every pass that needs it there (the solve, the depth range)
/// and for renderDepth(); puts board::kLinearDepthImage.
DepthReadbackOutputs addDepthReadbackPass(RenderGraph& graph, const DepthReadbackInputs& inputs);

}  // namespace vv::render
