// SPDX-License-Identifier: GPL-3.0-or-later
#include "passes/SsaoPass.h"

#include <QOpenGLFunctions_4_1_Core>

#include "passes/FrameResources.h"

namespace vv::render {

namespace {

constexpr int kSsaoSamples = 12;

struct SsaoData {
    Handle<Texture> linearDepth;
    Handle<Texture> normal;
    Handle<Texture> height;
    Handle<CpuValue<ShownVss>> shown;
    SsaoOutputs out;
    RenderTargetId target;
};

void occlude(const SsaoInputs& in, const RenderGraph::Resources& r, const SsaoData& d) {
    const PassContext& context = in.context;
    auto& g = *context.gl;
    context.beginFullscreen(r, d.target, aoSize(in.size, in.step));
    const SolvedFrame* vss = in.useVss ? r.get(d.shown).value().frame.get() : nullptr;
    const Program& program = context.programs->ssao;
    program.use();
    g.glActiveTexture(GL_TEXTURE0);
    g.glBindTexture(GL_TEXTURE_2D, glTex(r.get(d.linearDepth)).texture());
    g.glActiveTexture(GL_TEXTURE1);
    g.glBindTexture(GL_TEXTURE_2D, glTex(r.get(d.normal)).texture());
    g.glActiveTexture(GL_TEXTURE2);
    g.glBindTexture(GL_TEXTURE_2D, vss != nullptr ? glTex(r.get(d.height)).texture() : 0U);
    program.set("uLinearDepth", 0);
    program.set("uNormal", 1);
    program.set("uHeight", 2);
    program.set("uUseVss", vss != nullptr ? 1 : 0);
    program.set("uDmin", vss != nullptr ? static_cast<float>(vss->dmin) : 0.0F);
    program.set("uDmax", vss != nullptr ? static_cast<float>(vss->dmax) : 0.0F);
    program.set("uPixelScale", in.pixelScale);
    program.set("uAxisOffset", in.axisOffset);
    program.set("uRadius", in.radius);
    program.set("uSamples", kSsaoSamples);
    program.set("uStep", in.step);
    drawFullscreenAndUnbind(g, context.emptyVao, 3);
    checkGlError(g, "SSAO pass");
}

}  // namespace

SsaoOutputs addSsaoPass(RenderGraph& graph, const SsaoInputs& inputs) {
    const auto& data = graph.addPass<SsaoData>(
        "ssao",
        [&](RenderGraph::Builder& b, SsaoData& d) {
            b.dependsOn("radius", inputs.radius);
            b.dependsOn("pixel-scale", inputs.pixelScale);
            b.dependsOn("axis-offset", inputs.axisOffset);
            b.dependsOn("step", inputs.step);
            d.linearDepth = b.read<Texture>(board::kLinearDepth);
            d.normal = b.read<Texture>(board::kNormal);
            if (inputs.useVss) {
                d.height = b.read<Texture>(board::kVssHeight);
                d.shown = b.read<CpuValue<ShownVss>>(board::kShownVss);
            }
            d.out.raw = b.write(b.createPersistent<Texture>(
                board::kAoRaw, sized(aoSize(inputs.size, inputs.step), TextureFormat::RG32F)));
            d.target = b.declareRenderTarget("ssao", RenderTargetAttachments{{d.out.raw}, {}});
        },
        [inputs](const RenderGraph::Resources& r, const SsaoData& d) { occlude(inputs, r, d); });
    graph.blackboard().put(board::kAoRaw, data.out.raw);
    return data.out;
}

AoBlurOutputs addAoBlurPass(RenderGraph& graph, const AoBlurInputs& inputs) {
    struct Data {
        Handle<Texture> raw;
        AoBlurOutputs out;
        RenderTargetId target;
    };
    const auto& data = graph.addPass<Data>(
        "ao-blur",
        [&](RenderGraph::Builder& b, Data& d) {
            d.raw = b.read<Texture>(board::kAoRaw);
            d.out.ao = b.write(
                b.createPersistent<Texture>(board::kAo, sized(inputs.size, TextureFormat::R8)));
            d.target = b.declareRenderTarget("ao", RenderTargetAttachments{{d.out.ao}, {}});
        },
        [inputs](const RenderGraph::Resources& r, const Data& d) {
            const PassContext& context = inputs.context;
            auto& g = *context.gl;
            context.beginFullscreen(r, d.target, inputs.size);
            const Program& program = context.programs->aoBlur;
            program.use();
            g.glActiveTexture(GL_TEXTURE0);
            g.glBindTexture(GL_TEXTURE_2D, glTex(r.get(d.raw)).texture());
            program.set("uAo", 0);
            drawFullscreenAndUnbind(g, context.emptyVao, 1);
            checkGlError(g, "AO blur pass");
        });
    graph.blackboard().put(board::kAo, data.out.ao);
    return data.out;
}

}  // namespace vv::render
