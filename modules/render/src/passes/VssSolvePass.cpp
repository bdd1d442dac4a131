// SPDX-License-Identifier: GPL-3.0-or-later
#include "passes/VssSolvePass.h"

#include <QOpenGLFunctions_4_1_Core>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

namespace vv::render {

namespace {

/// The height texture's mark for "no VSS here" (NaN is not portable in GLSL).
constexpr float kNoVss = -1.0F;

/// Uploads `frame`'s height (or "no VSS" when null or of another size);
/// returns the frame when it is now shown (fits, finite range), else null.
std::shared_ptr<const SolvedFrame> uploadHeight(QOpenGLFunctions_4_1_Core& g,
                                                const GlTexture& texture,
                                                const std::shared_ptr<const SolvedFrame>& frame) {
    const auto& d = texture.descriptor();
    const bool fits =
        frame != nullptr && frame->height.width() == d.width && frame->height.height() == d.height;
    std::vector<float> texels(
        static_cast<std::size_t>(d.width) * static_cast<std::size_t>(d.height), kNoVss);
    if (fits) {
        for (int y = 0; y < d.height; ++y) {
            const float* row = frame->height.row(y);
            for (int x = 0; x < d.width; ++x) {
                const float v = row[x];
                texels[static_cast<std::size_t>(y) * static_cast<std::size_t>(d.width) +
                       static_cast<std::size_t>(x)] = std::isfinite(v) ? v : kNoVss;
            }
        }
    }
    g.glBindTexture(GL_TEXTURE_2D, texture.texture());
    g.glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    g.glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, d.width, d.height, GL_RED, GL_FLOAT, texels.data());
    g.glBindTexture(GL_TEXTURE_2D, 0);
    checkGlError(g, "uploading the VSS");
    const bool shown = fits && std::isfinite(frame->dmin) && std::isfinite(frame->dmax);
    return shown ? frame : nullptr;
}

/// Uploads the shown frame's slopes when it has them at the texture's size;
/// returns whether it did.
bool uploadSlopes(QOpenGLFunctions_4_1_Core& g, const GlTexture& texture,
                  const std::shared_ptr<const SolvedFrame>& shown) {
    const auto& d = texture.descriptor();
    if (shown == nullptr || shown->slopes.width() != d.width ||
        shown->slopes.height() != d.height) {
        return false;
    }
    g.glBindTexture(GL_TEXTURE_2D, texture.texture());
    g.glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    g.glPixelStorei(GL_UNPACK_ROW_LENGTH, static_cast<GLint>(shown->slopes.stride()));
    g.glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, d.width, d.height, GL_RGBA, GL_FLOAT,
                      shown->slopes.row(0));
    g.glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    g.glBindTexture(GL_TEXTURE_2D, 0);
    checkGlError(g, "uploading the VSS slopes");
    return true;
}

/// Uploads the depth the shown frame's VSS was solved from (+Inf, no
/// vessel, where it has none of the texture's size).
void uploadSolvedDepth(QOpenGLFunctions_4_1_Core& g, const GlTexture& texture,
                       const std::shared_ptr<const SolvedFrame>& shown) {
    const auto& d = texture.descriptor();
    const Image<float>* depth = shown != nullptr ? shown->solvedDepth.get() : nullptr;
    const bool fits = depth != nullptr && depth->width() == d.width && depth->height() == d.height;
    const Image<float> none =
        fits ? Image<float>{}
             : Image<float>(d.width, d.height, std::numeric_limits<float>::infinity());
    const Image<float>& source = fits ? *depth : none;
    g.glBindTexture(GL_TEXTURE_2D, texture.texture());
    g.glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    g.glPixelStorei(GL_UNPACK_ROW_LENGTH, static_cast<GLint>(source.stride()));
    g.glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, d.width, d.height, GL_RED, GL_FLOAT, source.row(0));
    g.glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    g.glBindTexture(GL_TEXTURE_2D, 0);
    checkGlError(g, "uploading the VSS's depth");
}

struct VssSolveData {
    Handle<CpuValue<DepthImage>> depth;
    Handle<SolvedFrameRef> solved;
    Handle<ExternalFrame> external;
    VssSolveOutputs out;
};

/// The execute callback: shows the external VSS, a solve made now, or the
/// worker's latest (submitting this view's solve when nobody asked for it).
void solve(const VssSolveInputs& in, const RenderGraph::Resources& r, const VssSolveData& d) {
    auto& g = *in.context.gl;
    const GlTexture& heightTexture = glTex(r.get(d.out.height));
    const GlTexture& slopeTexture = glTex(r.get(d.out.slope));
    ShownVss shown;
    SolveInput input;
    VssFrameStatus& status = shown.status;
    const auto upload = [&](const std::shared_ptr<const SolvedFrame>& frame) {
        shown.frame = uploadHeight(g, heightTexture, frame);
        // Previews use quick normals: their slopes are never read.
        shown.slopes = !in.preview && uploadSlopes(g, slopeTexture, shown.frame);
        if (in.reduced) {
            uploadSolvedDepth(g, glTex(r.get(d.out.depth)), shown.frame);
        }
    };
    const std::shared_ptr<const SolvedFrame> external = r.get(d.external).vss;
    if (in.external && external) {
        upload(external);
        status.solveMilliseconds = external->milliseconds;
        status.current = true;
    } else if (in.worker == nullptr) {
        input = SolveInput{r.get(d.depth).value().image, in.depthView};
        const auto frame = std::make_shared<const SolvedFrame>(
            solveFrame(in.request, *input.depth, in.options, in.preview, in.range, in.pixelScale,
                       in.reduction, in.reduced ? in.size : glm::ivec2(0), {}));
        upload(frame);
        status.solveMilliseconds = frame->milliseconds;
        status.current = true;
    } else if (const auto& latest = r.get(d.solved).frame; latest && latest->key == in.request) {
        upload(latest);
        status.solveMilliseconds = latest->milliseconds;
        status.current = true;
    } else {
        if (!in.worker->requested(in.request)) {
            input = SolveInput{r.get(d.depth).value().image, in.depthView};
            in.worker->submit(SolveWorker::Job{in.request, input.depth, in.options, in.preview,
                                               in.range, in.pixelScale, in.reduction,
                                               in.reduced ? in.size : glm::ivec2(0)});
        }
        status.pending = true;
        upload(latest);  // the previous VSS, or none
        status.solveMilliseconds = latest ? latest->milliseconds : 0.0;
    }
    status.shown = shown.frame != nullptr;
    status.dmin = status.shown ? shown.frame->dmin : 0.0;
    status.dmax = status.shown ? shown.frame->dmax : 0.0;
    status.preview = status.shown && shown.frame->preview;
    status.errorBound =
        status.shown ? shown.frame->errorBound : std::numeric_limits<double>::quiet_NaN();
    r.getForWrite(d.out.shown).set(std::move(shown));
    r.getForWrite(d.out.input).set(std::move(input));
}

}  // namespace

SolverKey solverKey(const vss::SolverOptions& options, const vss::DepthRange& range) noexcept {
    SolverKey key;
    key.p = options.p;
    key.tolerance = options.tolerance;
    key.kind = static_cast<std::int32_t>(options.kind);
    key.step = options.step;
    key.rangeMode = static_cast<std::int32_t>(range.mode);
    if (range.mode == vss::RangeMode::Fixed) {
        key.rangeMin = range.dmin;
        key.rangeMax = range.dmax;
    }
    return key;
}

VssSolveOutputs addVssSolvePass(RenderGraph& graph, const VssSolveInputs& inputs) {
    const auto& data = graph.addPass<VssSolveData>(
        "vss-solve",
        [&](RenderGraph::Builder& b, VssSolveData& d) {
            b.dependsOn("solver", solverKey(inputs.options, inputs.range));
            b.dependsOn("preview", inputs.preview);
            b.dependsOn("reduction", inputs.reduction);
            b.dependsOn("reduced", inputs.reduced);
            d.external = b.read<ExternalFrame>(board::kExternalVss);
            if (!inputs.external) {
                d.depth = b.read(inputs.depth);
            }
            if (inputs.worker != nullptr) {
                d.solved = b.read<SolvedFrameRef>(board::kSolvedImport);
            }
            VssSolveOutputs& out = d.out;
            out.height = b.write(
                b.createPersistent<Texture>("vss-height", sized(inputs.size, TextureFormat::R32F)));
            out.slope = b.write(b.createPersistent<Texture>(
                "vss-slope", inputs.cpuSlopes
                                 ? sized(inputs.size, TextureFormat::RGBA32F)
                                 : TextureDescriptor{1, 1, TextureFormat::RGBA32F, 1}));
            if (inputs.reduced) {
                out.depth = b.write(b.createPersistent<Texture>(
                    "vss-depth", sized(inputs.size, TextureFormat::R32F)));
            }
            out.shown = b.write(b.createPersistent<CpuValue<ShownVss>>("shown-vss", {}));
            out.input = b.write(b.createPersistent<CpuValue<SolveInput>>("solve-input", {}));
        },
        [inputs](const RenderGraph::Resources& r, const VssSolveData& d) { solve(inputs, r, d); });
    return data.out;
}

}  // namespace vv::render
