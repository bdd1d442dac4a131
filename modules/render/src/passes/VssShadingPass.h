// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <glm/glm.hpp>

#include "passes/FrameResources.h"
#include "passes/PassContext.h"
#include "passes/VssSolvePass.h"
#include "vv/render/FrameRenderer.h"
#include "vv/render/MeshStyle.h"
#include "vv/render/RenderGraph.h"

namespace vv::render {

struct VssShadingInputs {
    PassContext context;
    VssSettings settings;         ///< scale, iso-lines, lighting, opacity, preview
    Lighting light;               ///< the vessels' key light
    float pixelScale = 0.0F;      ///< of a pixel at `size`
    glm::ivec2 size{1, 1};        ///< the VSS's size (VssSolveInputs::size)
    VssSolveOutputs vss;          ///< reads its height, slope, shown VSS (and, reduced, depth)
    Handle<Texture> linearDepth;  ///< the G-buffer's (not read when `reduced`)
    /// The VSS is below the render size (VssSolveInputs::reduced): its
    /// vessel pixels are those of `vss.depth`, not the G-buffer's, and
    /// its colour is premultiplied and transparent on them (for the
    /// composite's bilinear tap over its void pixels, REDUCED_VSS).
    bool reduced = false;
};

struct VssShadingOutputs {
    Handle<Texture> color;  ///< RGBA8, transparent where no VSS is shown
};

/// "vss-shading": the depth colour scale, iso-lines and height-field
/// lighting of the shown VSS, at the VSS's size, into "vss-color"
/// (transient).
VssShadingOutputs addVssShadingPass(RenderGraph& graph, const VssShadingInputs& inputs);

}  // namespace vv::render
