// SPDX-License-Identifier: GPL-3.0-or-later
#include "passes/FxaaPass.h"

#include <QOpenGLFunctions_4_1_Core>
#include <algorithm>

#include "passes/FrameResources.h"

namespace vv::render {

namespace {

struct FinalData {
    Handle<Texture> input;
    FinalOutputs out;
    RenderTargetId target;
};

/// Binds `texture` (0: none) to the active unit with `filter` for
/// minification and magnification.
void setFilter(QOpenGLFunctions_4_1_Core& g, unsigned texture, GLint filter) {
    g.glBindTexture(GL_TEXTURE_2D, texture);
    if (texture != 0U) {
        g.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
        g.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
    }
}

void fxaa(const FxaaInputs& inputs, const RenderGraph::Resources& r, const FinalData& d) {
    const PassContext& context = inputs.context;
    auto& g = *context.gl;
    const glm::ivec2 size = inputs.targetSize;
    context.beginFullscreen(r, d.target, size);
    const Program& program = context.programs->fxaa;
    program.use();
    g.glActiveTexture(GL_TEXTURE0);
    // Bilinear taps here only; pooled textures are nearest otherwise.
    const unsigned input = glTex(r.get(d.input)).texture();
    setFilter(g, input, GL_LINEAR);
    program.set("uColor", 0);
    program.set("uTexel", glm::vec2(1.0F) / glm::vec2(size));
    g.glBindVertexArray(context.emptyVao);
    g.glDrawArrays(GL_TRIANGLES, 0, 3);
    g.glBindVertexArray(0);
    setFilter(g, input, GL_NEAREST);
    g.glBindTexture(GL_TEXTURE_2D, 0);
    g.glUseProgram(0);
    g.glEnable(GL_DEPTH_TEST);
    checkGlError(g, "FXAA pass");
}

}  // namespace

FinalOutputs addFxaaPass(RenderGraph& graph, const FxaaInputs& inputs) {
    const auto& data = graph.addPass<FinalData>(
        "fxaa",
        [&](RenderGraph::Builder& b, FinalData& d) {
            d.input = b.read<Texture>(board::kComposited);
            d.out.output = b.write(graph.blackboard().get<Texture>(board::kOutput));
            d.target = b.declareRenderTarget("output", RenderTargetAttachments{{d.out.output}, {}});
        },
        [inputs](const RenderGraph::Resources& r, const FinalData& d) { fxaa(inputs, r, d); });
    graph.blackboard().put(board::kOutput, data.out.output);
    return data.out;
}

FinalOutputs addUpscalePass(RenderGraph& graph, const UpscaleInputs& inputs) {
    struct UpscaleData {
        FinalData final;
        Handle<Texture> height;
    };
    const auto& data = graph.addPass<UpscaleData>(
        "upscale",
        [&](RenderGraph::Builder& b, UpscaleData& d) {
            d.final.input = b.read<Texture>(board::kComposited);
            if (inputs.isoLines > 0) {
                d.height = b.read<Texture>(board::kVssHeight);
            }
            d.final.out.output = b.write(graph.blackboard().get<Texture>(board::kOutput));
            d.final.target =
                b.declareRenderTarget("output", RenderTargetAttachments{{d.final.out.output}, {}});
        },
        [inputs](const RenderGraph::Resources& r, const UpscaleData& d) {
            const PassContext& context = inputs.context;
            auto& g = *context.gl;
            context.beginFullscreen(r, d.final.target, inputs.targetSize);
            const Program& program = context.programs->upscale;
            program.use();
            // Bilinear taps here only; pooled textures are nearest otherwise.
            const unsigned color = glTex(r.get(d.final.input)).texture();
            const unsigned height = inputs.isoLines > 0 ? glTex(r.get(d.height)).texture() : 0U;
            g.glActiveTexture(GL_TEXTURE0);
            setFilter(g, color, GL_LINEAR);
            g.glActiveTexture(GL_TEXTURE1);
            setFilter(g, height, GL_LINEAR);
            program.set("uColor", 0);
            program.set("uHeight", 1);
            program.set("uIsoLines", std::max(inputs.isoLines, 0));
            program.set("uIsoWidth", std::max(inputs.isoLineWidth, 0.0F));
            program.set("uIsoStrength", inputs.isoLineStrength);
            g.glBindVertexArray(context.emptyVao);
            g.glDrawArrays(GL_TRIANGLES, 0, 3);
            g.glBindVertexArray(0);
            setFilter(g, height, GL_NEAREST);
            g.glBindTexture(GL_TEXTURE_2D, 0);
            g.glActiveTexture(GL_TEXTURE0);
            setFilter(g, color, GL_NEAREST);
            g.glBindTexture(GL_TEXTURE_2D, 0);
            g.glUseProgram(0);
            g.glEnable(GL_DEPTH_TEST);
            checkGlError(g, "upscale pass");
        });
    graph.blackboard().put(board::kOutput, data.final.out.output);
    return data.final.out;
}

}  // namespace vv::render
