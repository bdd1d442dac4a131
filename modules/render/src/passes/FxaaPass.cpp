// SPDX-License-Identifier: GPL-3.0-or-later
#include "passes/FxaaPass.h"

#include <QOpenGLFunctions_4_1_Core>
#include <string_view>
#include <utility>

#include "passes/FrameResources.h"

namespace vv::render {

namespace {

struct FinalData {
    Handle<Texture> input;
    FinalOutputs out;
    RenderTargetId target;
};

/// A pass named `name` from board::kComposited into board::kOutput.
template <class Execute>
FinalOutputs addFinalPass(RenderGraph& graph, std::string_view name, Execute execute) {
    const auto& data = graph.addPass<FinalData>(
        name,
        [&](RenderGraph::Builder& b, FinalData& d) {
            d.input = b.read<Texture>(board::kComposited);
            d.out.output = b.write(graph.blackboard().get<Texture>(board::kOutput));
            d.target = b.declareRenderTarget("output", RenderTargetAttachments{{d.out.output}, {}});
        },
        std::move(execute));
    graph.blackboard().put(board::kOutput, data.out.output);
    return data.out;
}

}  // namespace

FinalOutputs addFxaaPass(RenderGraph& graph, const FxaaInputs& inputs) {
    return addFinalPass(graph, "fxaa",
                        [inputs](const RenderGraph::Resources& r, const FinalData& d) {
                            const PassContext& context = inputs.context;
                            auto& g = *context.gl;
                            const glm::ivec2 size = inputs.targetSize;
                            context.beginFullscreen(r, d.target, size);
                            const Program& program = context.programs->fxaa;
                            program.use();
                            g.glActiveTexture(GL_TEXTURE0);
                            // Bilinear taps here only; pooled textures are nearest otherwise.
                            g.glBindTexture(GL_TEXTURE_2D, glTex(r.get(d.input)).texture());
                            g.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
                            g.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
                            program.set("uColor", 0);
                            program.set("uTexel", glm::vec2(1.0F) / glm::vec2(size));
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
}

FinalOutputs addUpscalePass(RenderGraph& graph, const UpscaleInputs& inputs) {
    return addFinalPass(
        graph, "upscale", [inputs](const RenderGraph::Resources& r, const FinalData& d) {
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
}

}  // namespace vv::render
