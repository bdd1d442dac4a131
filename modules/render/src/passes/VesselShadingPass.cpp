// SPDX-License-Identifier: GPL-3.0-or-later
#include "passes/VesselShadingPass.h"

#include <QOpenGLFunctions_4_1_Core>
#include <string_view>

namespace vv::render {

namespace {

/// The cue settings as plain bytes for dependsOn.
struct CueKey {
    std::int32_t cue = 0;
    float fogStrength = 0.0F;
    float fresnelExponent = 0.0F;
    glm::vec3 background{0.0F};
};

struct VesselShadingData {
    Handle<Texture> linearDepth;
    Handle<Texture> normal;
    Handle<Texture> objectId;
    Handle<Texture> parameter;
    Handle<CpuValue<VisibleDepthRange>> visible;
    Handle<CpuValue<ShownVss>> shown;
    VesselShadingOutputs out;
    RenderTargetId target;
};

/// The cue of this frame, normalised with the VSS's range when one is shown
/// and the cue uses it, else with the visible range.
ShadedCue shadedCue(const VesselShadingInputs& in, const RenderGraph::Resources& r,
                    const VesselShadingData& d) {
    ShadedCue shaded;
    VesselCueParameters& cue = shaded.cue;
    cue.cue = in.cue.cue;
    cue.fogColor = in.background;
    cue.fogStrength = in.cue.fogStrength;
    cue.fresnelExponent = in.cue.fresnelExponent;
    if (in.cueUsesDepth) {
        const SolvedFrame* vss = in.cueUsesVss ? r.get(d.shown).value().frame.get() : nullptr;
        const auto& visible = r.get(d.visible).value().range;
        const double lo = vss != nullptr ? vss->dmin : visible ? visible->first : 0.0;
        const double hi = vss != nullptr ? vss->dmax : visible ? visible->second : 0.0;
        cue.dmin = static_cast<float>(lo);
        cue.dmax = static_cast<float>(hi);
        shaded.range = std::make_pair(lo, hi);
    }
    return shaded;
}

}  // namespace

VesselShadingOutputs addVesselShadingPass(RenderGraph& graph, const VesselShadingInputs& inputs) {
    CueKey cueKey;
    cueKey.cue = static_cast<std::int32_t>(inputs.cue.cue);
    cueKey.fogStrength = inputs.cue.fogStrength;
    cueKey.fresnelExponent = inputs.cue.fresnelExponent;
    cueKey.background = inputs.background;
    const TextureDescriptor colorFormat = sized(inputs.size, TextureFormat::RGBA8);
    const auto& data = graph.addPass<VesselShadingData>(
        "vessel-shading",
        [&](RenderGraph::Builder& b, VesselShadingData& d) {
            b.dependsOn("cue", cueKey);
            b.dependsOn("shading", inputs.shadingRevision);  // style, light, scene
            const GeometryOutputs& gbuffer = inputs.gbuffer;
            d.linearDepth = b.read(gbuffer.linearDepth);
            d.normal = b.read(gbuffer.normal);
            d.objectId = b.read(gbuffer.objectId);
            d.parameter = b.read(gbuffer.parameter);
            if (inputs.cueUsesDepth) {
                d.visible = b.read(inputs.visibleRange);
            }
            if (inputs.cueUsesVss) {
                d.shown = b.read(inputs.shownVss);
            }
            constexpr std::string_view kColor = "vessel-color";
            d.out.color =
                b.write(inputs.keepColor ? b.createPersistent<Texture>(kColor, colorFormat)
                                         : b.create<Texture>(kColor, colorFormat));
            d.out.cue = b.write(b.createPersistent<CpuValue<ShadedCue>>("vessel-cue", {}));
            d.target = b.declareRenderTarget("vessels", RenderTargetAttachments{{d.out.color}, {}});
        },
        [inputs](const RenderGraph::Resources& r, const VesselShadingData& d) {
            const PassContext& context = inputs.context;
            auto& g = *context.gl;
            const ShadedCue shaded = shadedCue(inputs, r, d);
            context.bindRenderTarget(r, d.target);
            g.glViewport(0, 0, inputs.size.x, inputs.size.y);
            context.meshes->shadeGBuffer(
                inputs.camera,
                MeshRenderer::GBufferTextures{.linearDepth = glTex(r.get(d.linearDepth)).texture(),
                                              .normal = glTex(r.get(d.normal)).texture(),
                                              .parameter = glTex(r.get(d.parameter)).texture(),
                                              .objectId = glTex(r.get(d.objectId)).texture()},
                shaded.cue);
            checkGlError(g, "vessel shading pass");
            r.getForWrite(d.out.cue).set(shaded);
        });
    return data.out;
}

}  // namespace vv::render
