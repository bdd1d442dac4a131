// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "passes/FrameResources.h"
#include "vv/render/RenderGraph.h"

namespace vv::render {

struct DepthRangeInputs {
    /// Take the whole frame's range from board::kExternalVss (tiled
    /// rendering: a tile's own range would differ) instead of the depth.
    bool external = false;
};

struct DepthRangeOutputs {
    Handle<CpuValue<VisibleDepthRange>> range;  ///< persistent: cached while the view stays
};

/// "depth-range": the visible vessels' linear depth range from
/// board::kLinearDepthImage (finite texels), for a vessel cue without a
/// shown VSS. Puts board::kVisibleDepthRange.
DepthRangeOutputs addDepthRangePass(RenderGraph& graph, const DepthRangeInputs& inputs);

}  // namespace vv::render
