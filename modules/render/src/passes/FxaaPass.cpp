// SPDX-License-Identifier: GPL-3.0-or-later
#include "passes/FxaaPass.h"

#include <QOpenGLFunctions_4_1_Core>
#include <string_view>

#include "passes/FrameResources.h"

namespace vv::render {

namespace {

constexpr std::string_view kFxaaFragment[] = {":/vv/shaders/fxaa.frag"};
constexpr ProgramSpec kFxaaProgram{kFullscreenVertex, kFxaaFragment, "FXAA", {}};

struct FxaaData {
    Handle<Texture> input;
    FxaaOutputs out;
    RenderTargetId target;
};

void fxaa(const FxaaInputs& inputs, const RenderGraph::Resources& r, const FxaaData& d) {
    const PassContext& context = inputs.context;
    auto& g = *context.gl;
    const glm::ivec2 size = inputs.targetSize;
    context.beginFullscreen(r, d.target, size);
    const Program& program = context.programs->get(kFxaaProgram);
    program.use();
    g.glActiveTexture(GL_TEXTURE0);
    // Bilinear taps here only; pooled textures are nearest otherwise.
    const unsigned input = glTex(r.get(d.input)).texture();
    bindFiltered(g, input, true);
    program.set("uColor", 0);
    program.set("uTexel", glm::vec2(1.0F) / glm::vec2(size));
    g.glBindVertexArray(context.emptyVao);
    g.glDrawArrays(GL_TRIANGLES, 0, 3);
    g.glBindVertexArray(0);
    endBilinearPass(g, input, "FXAA pass");
}

}  // namespace

FxaaOutputs addFxaaPass(RenderGraph& graph, const FxaaInputs& inputs) {
    const auto& data = graph.addPass<FxaaData>(
        "fxaa",
        [&](RenderGraph::Builder& b, FxaaData& d) {
            d.input = b.read(inputs.color);
            d.out.output = b.write(graph.blackboard().get<Texture>(board::kOutput));
            d.target = b.declareRenderTarget("output", RenderTargetAttachments{{d.out.output}, {}});
        },
        [inputs](const RenderGraph::Resources& r, const FxaaData& d) { fxaa(inputs, r, d); });
    graph.blackboard().put(board::kOutput, data.out.output);
    return data.out;
}

}  // namespace vv::render
