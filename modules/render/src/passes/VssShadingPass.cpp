// SPDX-License-Identifier: GPL-3.0-or-later
#include "passes/VssShadingPass.h"

#include <QOpenGLFunctions_4_1_Core>
#include <algorithm>
#include <array>
#include <string_view>

namespace vv::render {

namespace {

constexpr std::string_view kVssFragment[] = {":/vv/shaders/vss.frag"};
constexpr std::string_view kQuickNormals[] = {"QUICK_NORMALS"};
constexpr std::string_view kSlopeTexture[] = {"SLOPE_TEXTURE"};
/// The shader fits the height field's slopes.
constexpr ProgramSpec kVssProgram{kFullscreenVertex, kVssFragment, "VSS shading", {}};
/// One-pixel differences (preview frames).
constexpr ProgramSpec kQuickProgram{kFullscreenVertex, kVssFragment, "VSS shading (quick normals)",
                                    kQuickNormals};
/// The slopes the solver fitted, from a texture.
constexpr ProgramSpec kSlopeProgram{kFullscreenVertex, kVssFragment, "VSS shading (fitted slopes)",
                                    kSlopeTexture};

struct VssShadingData {
    Handle<Texture> height;
    Handle<Texture> slope;
    Handle<Texture> linearDepth;
    Handle<CpuValue<ShownVss>> shown;
    VssShadingOutputs out;
    RenderTargetId target;
};

void shade(const VssShadingInputs& in, const RenderGraph::Resources& r, const VssShadingData& d) {
    const PassContext& context = in.context;
    auto& g = *context.gl;
    const VssSettings& settings = in.settings;
    context.scaleLut->upload(settings.scale);
    context.beginFullscreen(r, d.target, in.size);
    const ShownVss& shown = r.get(d.shown).value();
    if (shown.frame == nullptr) {
        // No VSS: transparent. (Otherwise the draw below writes every pixel,
        // no blending: a clear first would only be a redundant pass over it.)
        const std::array<float, 4> clear{};
        g.glClearBufferfv(GL_COLOR, 0, clear.data());
        return;
    }
    // Preview frames (camera moving): one-pixel differences, no fit; exact
    // ones: the slopes the solver's thread fitted, or (none, e.g. an
    // external VSS or a huge frame) the shader fits them itself.
    const bool slopes = !settings.preview && shown.slopes;
    const Program& program = context.programs->get(settings.preview ? kQuickProgram
                                                   : slopes         ? kSlopeProgram
                                                                    : kVssProgram);
    const Lighting& light = in.light;
    program.use();
    g.glActiveTexture(GL_TEXTURE0);
    g.glBindTexture(GL_TEXTURE_2D, glTex(r.get(d.height)).texture());
    g.glActiveTexture(GL_TEXTURE1);
    g.glBindTexture(GL_TEXTURE_1D, context.scaleLut->texture());
    g.glActiveTexture(GL_TEXTURE2);
    g.glBindTexture(GL_TEXTURE_2D, glTex(r.get(d.linearDepth)).texture());
    program.set("uHeight", 0);
    program.set("uScale", 1);
    program.set("uLinearDepth", 2);
    if (slopes) {
        g.glActiveTexture(GL_TEXTURE3);
        g.glBindTexture(GL_TEXTURE_2D, glTex(r.get(d.slope)).texture());
        program.set("uSlope", 3);
    }
    program.set("uScaleSize", static_cast<float>(DepthScaleLut::kSize));
    program.set("uDmin", static_cast<float>(shown.frame->dmin));
    program.set("uDmax", static_cast<float>(shown.frame->dmax));
    program.set("uPixelScale", in.pixelScale);
    program.set("uIsoLines", std::max(settings.isoLines, 0));
    program.set("uIsoWidth", std::max(settings.isoLineWidth, 0.0F));
    program.set("uIsoStrength", settings.isoLineStrength);
    program.set("uLighting", settings.lighting);
    program.set("uOpacity", settings.opacity);
    program.set("uVoidPremultiplied", in.reduced ? 1 : 0);
    program.set("uLightDirection", light.direction);
    program.set("uAmbient", light.ambient);
    program.set("uDiffuse", light.diffuse);
    program.set("uSpecular", light.specular);
    program.set("uShininess", light.shininess);
    drawFullscreenAndUnbind(g, context.emptyVao, 3);
    checkGlError(g, "VSS shading pass");
}

}  // namespace

VssShadingOutputs addVssShadingPass(RenderGraph& graph, const VssShadingInputs& inputs) {
    const auto& data = graph.addPass<VssShadingData>(
        "vss-shading",
        [&](RenderGraph::Builder& b, VssShadingData& d) {
            d.height = b.read(inputs.vss.height);
            d.slope = b.read(inputs.vss.slope);
            d.linearDepth = b.read(inputs.reduced ? inputs.vss.depth : inputs.linearDepth);
            d.shown = b.read(inputs.vss.shown);
            d.out.color =
                b.write(b.create<Texture>("vss-color", sized(inputs.size, TextureFormat::RGBA8)));
            d.target = b.declareRenderTarget("vss", RenderTargetAttachments{{d.out.color}, {}});
        },
        [inputs](const RenderGraph::Resources& r, const VssShadingData& d) {
            shade(inputs, r, d);
        });
    return data.out;
}

}  // namespace vv::render
