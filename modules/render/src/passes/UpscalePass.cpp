// SPDX-License-Identifier: GPL-3.0-or-later
#include "passes/UpscalePass.h"

#include <QOpenGLFunctions_4_1_Core>

#include "passes/FrameResources.h"

namespace vv::render {

UpscaleOutputs addUpscalePass(RenderGraph& graph, const UpscaleInputs& inputs) {
    struct Data {
        Handle<Texture> input;
        UpscaleOutputs out;
        RenderTargetId target;
    };
    const Data& data = graph.addPass<Data>(
        "upscale",
        [&](RenderGraph::Builder& b, Data& d) {
            d.input = b.read<Texture>(board::kComposited);
            d.out.output = b.write(graph.blackboard().get<Texture>(board::kOutput));
            d.target = b.declareRenderTarget("output", RenderTargetAttachments{{d.out.output}, {}});
        },
        [inputs](const RenderGraph::Resources& r, const Data& d) {
            const PassContext& context = inputs.context;
            auto& g = *context.gl;
            const unsigned output = context.framebuffers->framebuffer(r.renderTarget(d.target));
            g.glBindFramebuffer(GL_READ_FRAMEBUFFER, glTex(r.get(d.input)).framebuffer());
            g.glBindFramebuffer(GL_DRAW_FRAMEBUFFER, output);
            g.glBlitFramebuffer(0, 0, inputs.size.x, inputs.size.y, 0, 0, inputs.targetSize.x,
                                inputs.targetSize.y, GL_COLOR_BUFFER_BIT, GL_LINEAR);
            g.glBindFramebuffer(GL_FRAMEBUFFER, output);
            checkGlError(g, "upscale pass");
        });
    graph.blackboard().put(board::kOutput, data.out.output);
    return data.out;
}

}  // namespace vv::render
