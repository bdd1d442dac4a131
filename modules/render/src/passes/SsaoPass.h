// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <glm/glm.hpp>

#include "passes/FrameResources.h"
#include "passes/PassContext.h"
#include "vv/render/RenderGraph.h"

namespace vv::render {

struct SsaoInputs {
    PassContext context;
    Handle<Texture> linearDepth;  ///< GeometryOutputs::linearDepth
    Handle<Texture> normal;       ///< GeometryOutputs::normal
    /// The VSS occludes too: read `vssHeight` and `shownVss`.
    bool useVss = false;
    Handle<Texture> vssHeight;            ///< VssSolveOutputs::height, read when useVss
    Handle<CpuValue<ShownVss>> shownVss;  ///< VssSolveOutputs::shown, read when useVss
    float radius = 1.0F;                  ///< scene units (> 0)
    float pixelScale = 0.0F;
    glm::vec2 axisOffset{0.0F};  ///< where the view axis meets the frame, pixels from its centre
    glm::ivec2 size{1, 1};       ///< the frame's (full) size
    /// 1, or 2: the occlusion of every second pixel per axis (aoStepFor()),
    /// into a target of size / step (rounded up).
    int step = 1;
};

/// The size of the SSAO's target for a frame of `size` and `step`.
[[nodiscard]] inline glm::ivec2 aoSize(glm::ivec2 size, int step) noexcept {
    return (size + glm::ivec2(step - 1)) / step;
}

struct SsaoOutputs {
    Handle<Texture> raw;  ///< RG32F, persistent
};

/// "ssao": occlusion from the G-buffer's linear depth and normals and
/// (useVss) the VSS height, into "ao-raw"; cached while they and the radius
/// stay.
SsaoOutputs addSsaoPass(RenderGraph& graph, const SsaoInputs& inputs);

}  // namespace vv::render
