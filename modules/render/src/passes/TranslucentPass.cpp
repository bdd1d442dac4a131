// SPDX-License-Identifier: GPL-3.0-or-later
#include "passes/TranslucentPass.h"

#include <QOpenGLFunctions_4_1_Core>

namespace vv::render {

TranslucentOutputs addTranslucentPass(RenderGraph& graph, const TranslucentInputs& inputs) {
    struct Data {
        Handle<Texture> opaqueDepth;
        Handle<CpuValue<ShadedCue>> cue;
        Handle<Texture> depth;
        TranslucentOutputs out;
        RenderTargetId target;
    };
    const auto& data = graph.addPass<Data>(
        "translucent",
        [&](RenderGraph::Builder& b, Data& d) {
            d.opaqueDepth = b.read(inputs.opaqueDepth);
            d.cue = b.read(inputs.cue);
            d.depth = b.write(b.create<Texture>("translucent-depth",
                                                sized(inputs.size, TextureFormat::Depth32F)));
            d.out.layer = b.write(
                b.create<Texture>("translucent-color", sized(inputs.size, TextureFormat::RGBA16F)));
            d.target = b.declareRenderTarget("translucent",
                                             RenderTargetAttachments{{d.out.layer}, d.depth});
        },
        [inputs](const RenderGraph::Resources& r, const Data& d) {
            const PassContext& context = inputs.context;
            auto& g = *context.gl;
            const int w = inputs.size.x;
            const int h = inputs.size.y;
            context.bindRenderTarget(r, d.target);
            g.glBindFramebuffer(GL_READ_FRAMEBUFFER, glTex(r.get(d.opaqueDepth)).framebuffer());
            g.glBlitFramebuffer(0, 0, w, h, 0, 0, w, h, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
            g.glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
            g.glViewport(0, 0, w, h);
            const float clear[4] = {0.0F, 0.0F, 0.0F, 0.0F};
            g.glClearBufferfv(GL_COLOR, 0, clear);
            context.meshes->drawTranslucent(inputs.camera, r.get(d.cue).value().cue,
                                            inputs.meshLevel);
            checkGlError(g, "translucent pass");
        });
    return data.out;
}

}  // namespace vv::render
