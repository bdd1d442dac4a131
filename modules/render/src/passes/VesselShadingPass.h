// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>
#include <glm/glm.hpp>

#include "passes/FrameResources.h"
#include "passes/GeometryPass.h"
#include "passes/PassContext.h"
#include "vv/render/Camera.h"
#include "vv/render/FrameRenderer.h"
#include "vv/render/RenderGraph.h"

namespace vv::render {

struct VesselShadingInputs {
    PassContext context;
    Camera camera;  ///< the G-buffer's
    VesselCueSettings cue;
    glm::vec3 background{0.0F};  ///< the fog's colour
    GeometryOutputs gbuffer;     ///< reads all but its depth
    /// The cue normalises depth: with `shownVss`'s range when `cueUsesVss`
    /// and a VSS is shown, else with `visibleRange`.
    bool cueUsesDepth = false;
    bool cueUsesVss = false;
    Handle<CpuValue<VisibleDepthRange>> visibleRange;  ///< read when cueUsesDepth
    Handle<CpuValue<ShownVss>> shownVss;               ///< read when cueUsesVss
    /// Keep the colours across frames (persistent), e.g. while a solve runs.
    bool keepColor = false;
    std::uint64_t shadingRevision = 0;  ///< MeshRenderer::shadingRevision()
    glm::ivec2 size{1, 1};
};

struct VesselShadingOutputs {
    Handle<Texture> color;            ///< RGBA8, transparent off the vessels
    Handle<CpuValue<ShadedCue>> cue;  ///< persistent: the cue these colours have
};

/// "vessel-shading": deferred shading of the G-buffer (MeshRenderer::
/// shadeGBuffer) with the material, the colour map and the vessel cue.
/// "vessel-color" is persistent when `keepColor`, else pooled.
VesselShadingOutputs addVesselShadingPass(RenderGraph& graph, const VesselShadingInputs& inputs);

}  // namespace vv::render
