// SPDX-License-Identifier: GPL-3.0-or-later
#include "passes/AoBlurPass.h"

#include <QOpenGLFunctions_4_1_Core>
#include <string_view>

namespace vv::render {

namespace {
constexpr std::string_view kAoBlurFragment[] = {":/vv/shaders/aoblur.frag"};
constexpr ProgramSpec kAoBlurProgram{kFullscreenVertex, kAoBlurFragment, "AO blur", {}};
}  // namespace

AoBlurOutputs addAoBlurPass(RenderGraph& graph, const AoBlurInputs& inputs) {
    struct Data {
        Handle<Texture> raw;
        AoBlurOutputs out;
        RenderTargetId target;
    };
    const auto& data = graph.addPass<Data>(
        "ao-blur",
        [&](RenderGraph::Builder& b, Data& d) {
            d.raw = b.read(inputs.raw);
            d.out.ao =
                b.write(b.createPersistent<Texture>("ao", sized(inputs.size, TextureFormat::R8)));
            d.target = b.declareRenderTarget("ao", RenderTargetAttachments{{d.out.ao}, {}});
        },
        [inputs](const RenderGraph::Resources& r, const Data& d) {
            const PassContext& context = inputs.context;
            auto& g = *context.gl;
            context.beginFullscreen(r, d.target, inputs.size);
            const Program& program = context.programs->get(kAoBlurProgram);
            program.use();
            g.glActiveTexture(GL_TEXTURE0);
            g.glBindTexture(GL_TEXTURE_2D, glTex(r.get(d.raw)).texture());
            program.set("uAo", 0);
            drawFullscreenAndUnbind(g, context.emptyVao, 1);
            checkGlError(g, "AO blur pass");
        });
    return data.out;
}

}  // namespace vv::render
