// SPDX-License-Identifier: GPL-3.0-or-later
#include "passes/SsaoPass.h"

#include <QOpenGLFunctions_4_1_Core>
#include <string_view>

namespace vv::render {

namespace {

constexpr int kSsaoSamples = 12;
constexpr std::string_view kSsaoFragment[] = {":/vv/shaders/ssao.frag"};
constexpr ProgramSpec kSsaoProgram{kFullscreenVertex, kSsaoFragment, "SSAO", {}};

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
    const Program& program = context.programs->get(kSsaoProgram);
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
            d.linearDepth = b.read(inputs.linearDepth);
            d.normal = b.read(inputs.normal);
            if (inputs.useVss) {
                d.height = b.read(inputs.vssHeight);
                d.shown = b.read(inputs.shownVss);
            }
            d.out.raw = b.write(b.createPersistent<Texture>(
                "ao-raw", sized(aoSize(inputs.size, inputs.step), TextureFormat::RG32F)));
            d.target = b.declareRenderTarget("ssao", RenderTargetAttachments{{d.out.raw}, {}});
        },
        [inputs](const RenderGraph::Resources& r, const SsaoData& d) { occlude(inputs, r, d); });
    return data.out;
}

}  // namespace vv::render
