// SPDX-License-Identifier: GPL-3.0-or-later
#include "passes/CompositePass.h"

#include <QOpenGLFunctions_4_1_Core>
#include <algorithm>
#include <string_view>

#include "passes/FrameResources.h"

namespace vv::render {

namespace {

/// Sets the minification and magnification filter of the texture bound to
/// the active unit's 2-D target.
void setTextureFilter(QOpenGLFunctions_4_1_Core& g, GLint filter) {
    g.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
    g.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
}

constexpr std::string_view kCompositeFragment[] = {":/vv/shaders/composite.frag"};
constexpr std::string_view kReducedVss[] = {"REDUCED_VSS"};
constexpr ProgramSpec kCompositeProgram{kFullscreenVertex, kCompositeFragment, "composite", {}};
/// The VSS's colour below the render size.
constexpr ProgramSpec kReducedVssProgram{kFullscreenVertex, kCompositeFragment,
                                         "composite (reduced VSS)", kReducedVss};

struct CompositeData {
    Handle<Texture> vessels;
    Handle<Texture> vss;
    Handle<Texture> ao;
    Handle<Texture> translucent;
    CompositeOutputs out;
    RenderTargetId target;
};

void composite(const CompositeInputs& in, const RenderGraph::Resources& r, const CompositeData& d) {
    const PassContext& context = in.context;
    auto& g = *context.gl;
    context.beginFullscreen(r, d.target, in.size);
    const bool reduced = in.useVss && in.reducedVss;
    const Program& program =
        context.programs->get(reduced ? kReducedVssProgram : kCompositeProgram);
    program.use();
    g.glActiveTexture(GL_TEXTURE0);
    g.glBindTexture(GL_TEXTURE_2D, glTex(r.get(d.vessels)).texture());
    g.glActiveTexture(GL_TEXTURE1);
    g.glBindTexture(GL_TEXTURE_2D, in.useVss ? glTex(r.get(d.vss)).texture() : 0U);
    program.set("uVessels", 0);
    program.set("uVss", 1);
    program.set("uUseVss", in.useVss ? 1 : 0);
    g.glActiveTexture(GL_TEXTURE2);
    g.glBindTexture(GL_TEXTURE_2D, in.useAo ? glTex(r.get(d.ao)).texture() : 0U);
    if (in.useAo) {
        // Bilinear: a half-resolution AO is read between its texels (at a
        // texel's centre, as at full resolution, it is the texel itself).
        g.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        g.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        g.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        g.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    }
    program.set("uAo", 2);
    program.set("uAoStep", static_cast<float>(in.aoStep));
    program.set("uUseAo", in.useAo ? 1 : 0);
    program.set("uAoStrength", in.aoStrength);
    program.set("uBackground", in.background);
    g.glActiveTexture(GL_TEXTURE3);
    g.glBindTexture(GL_TEXTURE_2D, in.useTranslucent ? glTex(r.get(d.translucent)).texture() : 0U);
    program.set("uTranslucent", 3);
    program.set("uUseTranslucent", in.useTranslucent ? 1 : 0);
    program.set("uVssVisibility", in.toTexture && in.vssVisibilityAlpha ? 1 : 0);
    if (reduced) {
        // Bilinear taps of the premultiplied VSS (pooled textures are nearest otherwise).
        g.glActiveTexture(GL_TEXTURE1);
        setTextureFilter(g, GL_LINEAR);
        program.set("uVssOpacity", std::clamp(in.vssOpacity, 0.0F, 1.0F));
    }
    drawFullscreenAndUnbind(g, context.emptyVao, 4);
    if (reduced) {
        g.glActiveTexture(GL_TEXTURE1);
        g.glBindTexture(GL_TEXTURE_2D, glTex(r.get(d.vss)).texture());
        setTextureFilter(g, GL_NEAREST);
        g.glBindTexture(GL_TEXTURE_2D, 0);
        g.glActiveTexture(GL_TEXTURE0);
    }
    g.glEnable(GL_DEPTH_TEST);
    checkGlError(g, "composite pass");
}

}  // namespace

CompositeOutputs addCompositePass(RenderGraph& graph, const CompositeInputs& inputs) {
    const auto& data = graph.addPass<CompositeData>(
        "composite",
        [&](RenderGraph::Builder& b, CompositeData& d) {
            d.vessels = b.read(inputs.vessels);
            if (inputs.useVss) {
                d.vss = b.read(inputs.vss);
            }
            if (inputs.useAo) {
                d.ao = b.read(inputs.ao);
            }
            if (inputs.useTranslucent) {
                d.translucent = b.read(inputs.translucent);
            }
            d.out.color = b.write(
                inputs.toTexture
                    ? b.create<Texture>("composited", sized(inputs.size, TextureFormat::RGBA8))
                    : graph.blackboard().get<Texture>(board::kOutput));
            d.target =
                b.declareRenderTarget("composite", RenderTargetAttachments{{d.out.color}, {}});
        },
        [inputs](const RenderGraph::Resources& r, const CompositeData& d) {
            composite(inputs, r, d);
        });
    if (!inputs.toTexture) {
        graph.blackboard().put(board::kOutput, data.out.color);
    }
    return data.out;
}

}  // namespace vv::render
