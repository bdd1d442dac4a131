// SPDX-License-Identifier: GPL-3.0-or-later
#include "passes/FxaaPass.h"

#include <QOpenGLFunctions_4_1_Core>

#include "passes/FrameResources.h"

namespace vv::render {

FxaaOutputs addFxaaPass(RenderGraph& graph, const FxaaInputs& inputs) {
    struct Data {
        Handle<Texture> input;
        FxaaOutputs out;
        RenderTargetId target;
    };
    const Data& data = graph.addPass<Data>(
        "fxaa",
        [&](RenderGraph::Builder& b, Data& d) {
            d.input = b.read<Texture>(board::kComposited);
            d.out.output = b.write(graph.blackboard().get<Texture>(board::kOutput));
            d.target = b.declareRenderTarget("output", RenderTargetAttachments{{d.out.output}, {}});
        },
        [inputs](const RenderGraph::Resources& r, const Data& d) {
            const PassContext& context = inputs.context;
            auto& g = *context.gl;
            const int w = inputs.targetSize.x;
            const int h = inputs.targetSize.y;
            context.bindRenderTarget(r, d.target);
            g.glViewport(0, 0, w, h);
            g.glDisable(GL_DEPTH_TEST);
            g.glDisable(GL_BLEND);
            const Program& program = context.programs->fxaa;
            program.use();
            g.glActiveTexture(GL_TEXTURE0);
            // Bilinear taps here only; pooled textures are nearest otherwise.
            g.glBindTexture(GL_TEXTURE_2D, glTex(r.get(d.input)).texture());
            g.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
            g.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
            program.set("uColor", 0);
            program.set("uTexel",
                        glm::vec2(1.0F / static_cast<float>(w), 1.0F / static_cast<float>(h)));
            g.glBindVertexArray(context.emptyVao);
            g.glDrawArrays(GL_TRIANGLES, 0, 3);
            g.glBindVertexArray(0);
            g.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
            g.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
            g.glBindTexture(GL_TEXTURE_2D, 0);
            g.glUseProgram(0);
            g.glEnable(GL_DEPTH_TEST);
            checkGlError(g, "FXAA pass");
        });
    graph.blackboard().put(board::kOutput, data.out.output);
    return data.out;
}

}  // namespace vv::render
