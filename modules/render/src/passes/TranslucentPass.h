// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstddef>
#include <glm/glm.hpp>

#include "passes/FrameResources.h"
#include "passes/PassContext.h"
#include "vv/render/Camera.h"
#include "vv/render/RenderGraph.h"

namespace vv::render {

struct TranslucentInputs {
    PassContext context;
    Camera camera;
    std::size_t meshLevel = 0;  ///< as the geometry pass's
    glm::ivec2 size{1, 1};
    Handle<Texture> opaqueDepth;      ///< GeometryOutputs::depth
    Handle<CpuValue<ShadedCue>> cue;  ///< VesselShadingOutputs::cue
};

struct TranslucentOutputs {
    Handle<Texture> layer;  ///< RGBA16F, premultiplied
};

/// "translucent": objects with opacity below 1 (left out of the G-buffer),
/// drawn forward back to front (MeshRenderer::drawTranslucent) over a copy
/// of the opaque depth, with the cue the vessels were shaded with, into
/// "translucent-color"; culled when nothing reads it (no translucent object).
TranslucentOutputs addTranslucentPass(RenderGraph& graph, const TranslucentInputs& inputs);

}  // namespace vv::render
