// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "passes/FrameResources.h"
#include "vv/render/RenderGraph.h"

namespace vv::render {

struct DepthRangeInputs {
    /// Take the whole frame's range from the imported board::kExternalVss
    /// (tiled rendering: a tile's own range would differ) instead of `depth`.
    bool external = false;
    Handle<CpuValue<DepthImage>> depth;  ///< DepthReadbackOutputs::image
};

struct DepthRangeOutputs {
    Handle<CpuValue<VisibleDepthRange>> range;  ///< persistent: cached while the view stays
};

/// "depth-range": the visible vessels' linear depth range from the depth
/// read back (finite texels), for a vessel cue without a shown VSS.
DepthRangeOutputs addDepthRangePass(RenderGraph& graph, const DepthRangeInputs& inputs);

}  // namespace vv::render
