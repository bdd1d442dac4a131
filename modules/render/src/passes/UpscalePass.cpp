// SPDX-License-Identifier: GPL-3.0-or-later
#include "passes/UpscalePass.h"

#include <QOpenGLFunctions_4_1_Core>
#include <algorithm>
#include <string_view>
#include <vector>

#include "passes/RectBatch.h"
#include "passes/SilhouetteRuns.h"
#include "passes/UpscaleTiles.h"

namespace vv::render {

namespace {

constexpr std::string_view kUpscaleFragment[] = {":/vv/shaders/upscale.frag"};
constexpr std::string_view kRectsVertex = ":/vv/shaders/rects.vert";
constexpr std::string_view kColorOnly[] = {"COLOR_ONLY"};
constexpr std::string_view kEdges[] = {"EDGES"};
constexpr std::string_view kEdgesColorOnly[] = {"EDGES", "COLOR_ONLY"};
/// A reduced frame into the target, the iso-lines at its size.
constexpr ProgramSpec kUpscaleProgram{kFullscreenVertex, kUpscaleFragment, "upscale", {}};
/// Where no iso-line reaches (UpscaleTiles.h).
constexpr ProgramSpec kColorProgram{kFullscreenVertex, kUpscaleFragment, "upscale (colour only)",
                                    kColorOnly};
/// Along the vessels' silhouettes, over rects.vert: with the iso-lines, and without any.
constexpr ProgramSpec kEdgesProgram{kRectsVertex, kUpscaleFragment, "upscale (edges)", kEdges};
constexpr ProgramSpec kEdgesColorProgram{kRectsVertex, kUpscaleFragment,
                                         "upscale (edges, colour only)", kEdgesColorOnly};

struct UpscaleData {
    Handle<Texture> input;
    UpscaleOutputs out;
    RenderTargetId target;
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
    const auto& color = r.get(d.input).descriptor();
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
    const Program& program =
        inputs.context.programs->get(lines ? kEdgesProgram : kEdgesColorProgram);
    useUpscale(inputs, program, lines);
    const auto& size = r.get(d.input).descriptor();
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
    context.beginFullscreen(r, d.target, inputs.targetSize);
    // Bilinear taps here only; pooled textures are nearest otherwise.
    const unsigned color = glTex(r.get(d.input)).texture();
    const unsigned height = inputs.isoLines > 0 ? glTex(r.get(d.height)).texture() : 0U;
    g.glActiveTexture(GL_TEXTURE0);
    bindFiltered(g, color, true);
    g.glActiveTexture(GL_TEXTURE1);
    bindFiltered(g, height, true);
    g.glEnable(GL_SCISSOR_TEST);
    if (!tiles.plain.empty()) {
        useUpscale(inputs, context.programs->get(kColorProgram), false);
        drawRects(g, context.emptyVao, tiles.plain);
    }
    if (!tiles.lines.empty()) {
        useUpscale(inputs, context.programs->get(kUpscaleProgram), true);
        drawRects(g, context.emptyVao, tiles.lines);
    }
    g.glDisable(GL_SCISSOR_TEST);
    if (depth != nullptr) {
        drawSilhouettes(inputs, r, d, vessels);
    }
    g.glActiveTexture(GL_TEXTURE1);
    bindFiltered(g, height, false);
    g.glBindTexture(GL_TEXTURE_2D, 0);
    g.glActiveTexture(GL_TEXTURE0);
    endBilinearPass(g, color, "upscale pass");
}

}  // namespace

UpscaleOutputs addUpscalePass(RenderGraph& graph, const UpscaleInputs& inputs) {
    const auto& data = graph.addPass<UpscaleData>(
        "upscale",
        [&](RenderGraph::Builder& b, UpscaleData& d) {
            d.input = b.read(inputs.color);
            if (inputs.isoLines > 0) {
                d.height = b.read(inputs.vssHeight);
                d.shown = b.read(inputs.shownVss);
            }
            if (inputs.sharpEdges) {
                d.depth = b.read(inputs.linearDepth);
                d.depthImage = b.read(inputs.depthImage);
                d.runs = b.write(b.createPersistent<Texture>(
                    "silhouette-runs", sized(inputs.renderSize, TextureFormat::RGBA8)));
            }
            d.out.output = b.write(graph.blackboard().get<Texture>(board::kOutput));
            d.target = b.declareRenderTarget("output", RenderTargetAttachments{{d.out.output}, {}});
        },
        [inputs](const RenderGraph::Resources& r, const UpscaleData& d) { upscale(inputs, r, d); });
    graph.blackboard().put(board::kOutput, data.out.output);
    return data.out;
}

}  // namespace vv::render
