// SPDX-License-Identifier: GPL-3.0-or-later
#include "passes/FxaaPass.h"

#include <QOpenGLFunctions_4_1_Core>
#include <algorithm>
#include <vector>

#include "passes/FrameResources.h"
#include "passes/RectBatch.h"
#include "passes/SilhouetteRuns.h"
#include "passes/UpscaleTiles.h"

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

/// Ends a pass that read `texture` on the active unit with bilinear taps:
/// nearest again and unbound, no program, the depth test back on; then
/// checks GL (RenderError naming `what`).
void finishPass(QOpenGLFunctions_4_1_Core& g, unsigned texture, const char* what) {
    setFilter(g, texture, GL_NEAREST);
    g.glBindTexture(GL_TEXTURE_2D, 0);
    g.glUseProgram(0);
    g.glEnable(GL_DEPTH_TEST);
    checkGlError(g, what);
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
    finishPass(g, input, "FXAA pass");
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

namespace {

struct UpscaleData {
    FinalData final;
    Handle<Texture> height;
    Handle<CpuValue<ShownVss>> shown;
    Handle<Texture> depth;
    Handle<CpuValue<DepthImage>> depthImage;
    /// silhouetteRuns() of the depth image, uploaded here. Persistent: a
    /// pooled texture may still be in use by this frame's earlier passes,
    /// and the upload would wait for them (2-7 ms on llvmpipe, 0.05 here).
    Handle<Texture> runs;
};

/// The render size's depth when it is the colour's size (what the
/// silhouettes are drawn from), else null: no silhouettes.
const Image<float>* edgeDepth(const UpscaleInputs& inputs, const RenderGraph::Resources& r,
                              const UpscaleData& d) {
    if (!inputs.sharpEdges) {
        return nullptr;
    }
    const Image<float>* depth = r.get(d.depthImage).value().image.get();
    const auto& color = r.get(d.final.input).descriptor();
    return depth != nullptr && depth->width() == color.width && depth->height() == color.height
               ? depth
               : nullptr;
}

/// Uploads the silhouettes rebuilt from `vessels` into `texture` (its size).
void uploadRuns(QOpenGLFunctions_4_1_Core& g, const GlTexture& texture,
                const Image<std::uint8_t>& vessels) {
    const Image<glm::u8vec4> runs = silhouetteRuns(vessels);
    g.glBindTexture(GL_TEXTURE_2D, texture.texture());
    g.glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    g.glPixelStorei(GL_UNPACK_ROW_LENGTH, static_cast<GLint>(runs.stride()));
    g.glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, runs.width(), runs.height(), GL_RGBA,
                      GL_UNSIGNED_BYTE, runs.data());
    g.glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    g.glBindTexture(GL_TEXTURE_2D, 0);
    checkGlError(g, "uploading the silhouettes");
}

/// The upscale's rectangles: split by the shown VSS's heights
/// (UpscaleTiles.h) when they are what the height texture holds; else the
/// whole target, with iso-lines when there are any.
UpscaleTiles upscaleTiles(const UpscaleInputs& inputs, const RenderGraph::Resources& r,
                          const UpscaleData& d) {
    // Target pixels: llvmpipe's bins (scissors on their edges leave whole
    // bins to one program). Against one full-screen draw with the iso-lines,
    // 3.0 against 3.9 ms wall, 5.7 against 7.6 ms CPU at 1280x720 (the
    // rotating benchmark's frames at 0.5, interleaved; 32 px: 3.2 / 5.7,
    // 16 px: 4.2 / 6.8): half the target needed the iso-lines.
    constexpr int kTile = 64;
    if (inputs.isoLines > 0) {
        const ShownVss& shown = r.get(d.shown).value();
        const auto& texture = r.get(d.height).descriptor();
        if (shown.frame != nullptr && shown.frame->height.width() == texture.width &&
            shown.frame->height.height() == texture.height) {
            return splitUpscaleTiles(shown.frame->height, inputs.targetSize, inputs.isoLines,
                                     std::max(inputs.isoLineWidth, 0.0F), kTile);
        }
    }
    UpscaleTiles all;
    (inputs.isoLines > 0 ? all.lines : all.plain)
        .emplace_back(0, 0, inputs.targetSize.x, inputs.targetSize.y);
    return all;
}

/// Draws the full-screen triangle with `program` (bound, its uniforms
/// set) into each of `rects` (scissored).
void drawRects(QOpenGLFunctions_4_1_Core& g, unsigned vao, const std::vector<glm::ivec4>& rects) {
    g.glBindVertexArray(vao);
    for (const glm::ivec4& rect : rects) {
        g.glScissor(rect.x, rect.y, rect.z - rect.x, rect.w - rect.y);
        g.glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    g.glBindVertexArray(0);
}

/// Binds `program` (upscale.frag) and sets its uniforms: the colour on unit
/// 0, with `lines` the iso-lines' (height on unit 1).
void useUpscale(const UpscaleInputs& inputs, const Program& program, bool lines) {
    program.use();
    program.set("uColor", 0);
    if (lines) {
        program.set("uHeight", 1);
        program.set("uIsoLines", std::max(inputs.isoLines, 0));
        program.set("uIsoWidth", std::max(inputs.isoLineWidth, 0.0F));
        program.set("uIsoStrength", inputs.isoLineStrength);
    }
}

/// Draws the silhouettes of `vessels` over the upscaled frame (upscale.frag's
/// EDGES variant, the depth texture on unit 2, the runs on unit 3) in the
/// rectangles that need it (silhouetteRects()).
void drawSilhouettes(const UpscaleInputs& inputs, const RenderGraph::Resources& r,
                     const UpscaleData& d, const Image<std::uint8_t>& vessels) {
    auto& g = *inputs.context.gl;
    const std::vector<glm::ivec4> rects = silhouetteRects(vessels, inputs.targetSize);
    if (rects.empty()) {
        return;
    }
    g.glActiveTexture(GL_TEXTURE2);
    g.glBindTexture(GL_TEXTURE_2D, glTex(r.get(d.depth)).texture());
    g.glActiveTexture(GL_TEXTURE3);
    g.glBindTexture(GL_TEXTURE_2D, glTex(r.get(d.runs)).texture());
    const bool lines = inputs.isoLines > 0;
    const FullscreenPrograms& programs = *inputs.context.programs;
    const Program& program = lines ? programs.upscaleEdges : programs.upscaleEdgesColor;
    useUpscale(inputs, program, lines);
    const auto& size = r.get(d.final.input).descriptor();
    program.set("uDepth", 2);
    program.set("uRuns", 3);
    program.set("uTexelsPerPixel",
                glm::vec2(static_cast<float>(size.width), static_cast<float>(size.height)) /
                    glm::vec2(inputs.targetSize));
    program.set("uTargetSize", glm::vec2(inputs.targetSize));
    inputs.context.rects->draw(rects);
    g.glBindTexture(GL_TEXTURE_2D, 0);
    g.glActiveTexture(GL_TEXTURE2);
    g.glBindTexture(GL_TEXTURE_2D, 0);
}

void upscale(const UpscaleInputs& inputs, const RenderGraph::Resources& r, const UpscaleData& d) {
    const PassContext& context = inputs.context;
    auto& g = *context.gl;
    const UpscaleTiles tiles = upscaleTiles(inputs, r, d);
    const Image<float>* depth = edgeDepth(inputs, r, d);
    const Image<std::uint8_t> vessels =
        depth != nullptr ? vesselMask(*depth) : Image<std::uint8_t>{};
    if (depth != nullptr) {
        uploadRuns(g, glTex(r.get(d.runs)), vessels);
    }
    context.beginFullscreen(r, d.final.target, inputs.targetSize);
    // Bilinear taps here only; pooled textures are nearest otherwise.
    const unsigned color = glTex(r.get(d.final.input)).texture();
    const unsigned height = inputs.isoLines > 0 ? glTex(r.get(d.height)).texture() : 0U;
    g.glActiveTexture(GL_TEXTURE0);
    setFilter(g, color, GL_LINEAR);
    g.glActiveTexture(GL_TEXTURE1);
    setFilter(g, height, GL_LINEAR);
    g.glEnable(GL_SCISSOR_TEST);
    if (!tiles.plain.empty()) {
        useUpscale(inputs, context.programs->upscaleColor, false);
        drawRects(g, context.emptyVao, tiles.plain);
    }
    if (!tiles.lines.empty()) {
        useUpscale(inputs, context.programs->upscale, true);
        drawRects(g, context.emptyVao, tiles.lines);
    }
    g.glDisable(GL_SCISSOR_TEST);
    if (depth != nullptr) {
        drawSilhouettes(inputs, r, d, vessels);
    }
    g.glActiveTexture(GL_TEXTURE1);
    setFilter(g, height, GL_NEAREST);
    g.glBindTexture(GL_TEXTURE_2D, 0);
    g.glActiveTexture(GL_TEXTURE0);
    finishPass(g, color, "upscale pass");
}

}  // namespace

FinalOutputs addUpscalePass(RenderGraph& graph, const UpscaleInputs& inputs) {
    const auto& data = graph.addPass<UpscaleData>(
        "upscale",
        [&](RenderGraph::Builder& b, UpscaleData& d) {
            d.final.input = b.read<Texture>(board::kComposited);
            if (inputs.isoLines > 0) {
                d.height = b.read<Texture>(board::kVssHeight);
                d.shown = b.read<CpuValue<ShownVss>>(board::kShownVss);
            }
            if (inputs.sharpEdges) {
                d.depth = b.read<Texture>(board::kLinearDepth);
                d.depthImage = b.read<CpuValue<DepthImage>>(board::kLinearDepthImage);
                d.runs = b.write(b.createPersistent<Texture>(
                    "silhouette-runs", sized(inputs.renderSize, TextureFormat::RGBA8)));
            }
            d.final.out.output = b.write(graph.blackboard().get<Texture>(board::kOutput));
            d.final.target =
                b.declareRenderTarget("output", RenderTargetAttachments{{d.final.out.output}, {}});
        },
        [inputs](const RenderGraph::Resources& r, const UpscaleData& d) { upscale(inputs, r, d); });
    graph.blackboard().put(board::kOutput, data.final.out.output);
    return data.final.out;
}

}  // namespace vv::render
