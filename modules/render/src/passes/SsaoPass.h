// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <glm/glm.hpp>

#include "passes/PassContext.h"
#include "vv/render/RenderGraph.h"

namespace vv::render {

struct SsaoInputs {
    PassContext context;
    /// The VSS occludes too: read board::kVssHeight and kShownVss.
    bool useVss = false;
    float radius = 1.0F;  ///< scene units (> 0)
    float pixelScale = 0.0F;
    glm::vec2 axisOffset{0.0F};  ///< where the view axis meets the frame, pixels from its centre
    glm::ivec2 size{1, 1};       ///< the frame's (full) size
    /// 1, or 2: the occlusion of every second pixel per axis (aoStepFor()),
    /// into a target of size / step (rounded up).
    int step = 1;
};

struct SsaoOutputs {
    Handle<Texture> raw;  ///< RG32F, persistent
};

/// "ssao": occlusion from board::kLinearDepth, kNormal and (useVss) the VSS
/// height; cached while they and the radius stay. Puts board::kAoRaw.
SsaoOutputs addSsaoPass(RenderGraph& graph, const SsaoInputs& inputs);

struct AoBlurInputs {
    PassContext context;
    glm::ivec2 size{1, 1};  ///< the size of board::kAoRaw (the frame's / the SSAO's step)
};

/// The size of the SSAO's target for a frame of `size` and `step`.
[[nodiscard]] inline glm::ivec2 aoSize(glm::ivec2 size, int step) noexcept {
    return (size + glm::ivec2(step - 1)) / step;
}

struct AoBlurOutputs {
    Handle<Texture> ao;  ///< R8, persistent
};

/// "ao-blur": a depth-aware blur of board::kAoRaw; puts board::kAo.
AoBlurOutputs addAoBlurPass(RenderGraph& graph, const AoBlurInputs& inputs);

}  // namespace vv::render
