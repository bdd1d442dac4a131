// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "passes/FrameResources.h"
#include "passes/PassContext.h"
#include "vv/render/RenderGraph.h"

namespace vv::render {

struct DepthReadbackInputs {
    PassContext context;
    Handle<Texture> linearDepth;  ///< GeometryOutputs::linearDepth
};

struct DepthReadbackOutputs {
    Handle<CpuValue<DepthImage>> image;  ///< persistent: re-read only when the depth changes
};

/// "depth-readback": reads the linear depth back to the CPU once per
/// G-buffer ("linear-depth-image"), for every pass that needs it there (the
/// solve, the depth range, the upscale's silhouettes) and for renderDepth().
DepthReadbackOutputs addDepthReadbackPass(RenderGraph& graph, const DepthReadbackInputs& inputs);

}  // namespace vv::render
