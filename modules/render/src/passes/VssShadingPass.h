// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <glm/glm.hpp>

#include "passes/FrameResources.h"
#include "passes/PassContext.h"
#include "vv/render/FrameRenderer.h"
#include "vv/render/MeshStyle.h"
#include "vv/render/RenderGraph.h"

namespace vv::render {

struct VssShadingInputs {
    PassContext context;
    VssSettings settings;  ///< scale, iso-lines, lighting, opacity, preview
    Lighting light;        ///< the vessels' key light
    float pixelScale = 0.0F;
    glm::ivec2 size{1, 1};
};

struct VssShadingOutputs {
    Handle<Texture> color;  ///< RGBA8, transparent where no VSS is shown
};

/// "vss-shading": the depth colour scale, iso-lines and height-field
/// lighting of the shown VSS. Reads board::kVssHeight, kVssSlope,
/// kLinearDepth and kShownVss; puts board::kVssColor (transient).
VssShadingOutputs addVssShadingPass(RenderGraph& graph, const VssShadingInputs& inputs);

}  // namespace vv::render
