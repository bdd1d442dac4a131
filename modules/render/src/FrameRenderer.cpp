// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/render/FrameRenderer.h"

#include <QOpenGLContext>
#include <QOpenGLFunctions_4_1_Core>
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "GBufferProbe.h"
#include "SolveWorker.h"
#include "passes/AoBlurPass.h"
#include "passes/CompositePass.h"
#include "passes/DepthRangePass.h"
#include "passes/DepthReadbackPass.h"
#include "passes/FrameResources.h"
#include "passes/FxaaPass.h"
#include "passes/GeometryPass.h"
#include "passes/PassContext.h"
#include "passes/RectBatch.h"
#include "passes/SsaoPass.h"
#include "passes/TranslucentPass.h"
#include "passes/UpscalePass.h"
#include "passes/VesselShadingPass.h"
#include "passes/VssShadingPass.h"
#include "passes/VssSolvePass.h"
#include "vv/core/Error.h"
#include "vv/core/Hash.h"
#include "vv/core/Image.h"
#include "vv/render/GlFramebufferCache.h"
#include "vv/render/RenderGraphCache.h"
#include "vv/vss/Vss.h"

namespace vv::render {

namespace {

/// Scene units per pixel per unit of depth of `camera` at a render height of
/// `height` pixels; a tile (Camera::window) keeps the full view's pixel size:
/// P[1][1] grew by the full height / the tile's.
float pixelScaleOf(const Camera& camera, int height) {
    return camera.window() ? 2.0F / (camera.projectionMatrix()[1][1] * static_cast<float>(height))
                           : 2.0F * std::tan(glm::radians(camera.fieldOfView()) * 0.5F) /
                                 static_cast<float>(height);
}

/// The size the passes of a frame run at (FrameSettings::resolutionScale).
glm::ivec2 renderSizeFor(const FrameSettings& settings, const FrameTarget& target) noexcept {
    const float scale = std::isfinite(settings.resolutionScale)
                            ? std::clamp(settings.resolutionScale, 0.1F, 1.0F)
                            : 1.0F;
    const auto scaledSize = [scale](int n) {
        return std::max(1, static_cast<int>(std::lround(static_cast<float>(n) * scale)));
    };
    return {scaledSize(target.width), scaledSize(target.height)};
}

/// The size the VSS of a frame rendered at `renderSize` is solved and shaded
/// at (FrameSettings::vssResolutionScale): `renderSize` with the occlusion on
/// or an external VSS.
glm::ivec2 vssSizeFor(const FrameSettings& settings, glm::ivec2 renderSize,
                      bool external) noexcept {
    const float scale = settings.vssResolutionScale;
    if (external || (settings.ao.enabled && settings.ao.strength > 0.0F) || !std::isfinite(scale) ||
        scale >= 1.0F) {
        return renderSize;
    }
    const float clamped = std::max(scale, 0.25F);
    const auto scaledSize = [clamped](int n) {
        return std::clamp(static_cast<int>(std::lround(static_cast<float>(n) * clamped)), 1, n);
    };
    return {scaledSize(renderSize.x), scaledSize(renderSize.y)};
}

/// What a solve request depends on besides the solver: view, render size, scene.
std::uint64_t viewKey(const glm::mat4& view, const glm::mat4& projection,
                      const glm::ivec2& viewport, std::uint64_t sceneRevision) noexcept {
    Hasher h;
    h.value(view);
    h.value(projection);
    h.value(viewport);
    h.value(sceneRevision);
    return h.result();
}

/// The key of a solve of the view `view` with `options` (preview or exact),
/// drawn at `reduction` window pixels per render pixel, solved at `vssSize`.
std::uint64_t requestKey(std::uint64_t view, const SolverKey& options, bool preview,
                         float reduction, glm::ivec2 vssSize) noexcept {
    Hasher h;
    h.value(view);
    h.value(vssSize);
    h.value(options);
    h.value(preview);
    h.value(reduction);
    return h.result();
}

/// Window pixels per render pixel (solveFrame()): 1 at full size.
float reductionOf(const FrameTarget& target, const glm::ivec2& renderSize) noexcept {
    return static_cast<float>(target.height) / static_cast<float>(std::max(renderSize.y, 1));
}

/// Throws InvalidArgumentError for a target below 1x1 and, with the VSS on,
/// for bad solver options or a bad fixed depth range.
void checkFrame(const FrameSettings& settings, const FrameTarget& target) {
    if (target.width < 1 || target.height < 1) {
        throw InvalidArgumentError("frame size must be at least 1x1, got " +
                                   std::to_string(target.width) + "x" +
                                   std::to_string(target.height));
    }
    const VssSettings& vssSettings = settings.vss;
    if (!vssSettings.enabled) {
        return;
    }
    static_cast<void>(
        vss::makeSolver(effectiveSolverOptions(vssSettings)));  // throws for bad options
    const vss::DepthRange& range = vssSettings.range;
    if (range.mode == vss::RangeMode::Fixed &&
        (!std::isfinite(range.dmin) || !std::isfinite(range.dmax) || range.dmin > range.dmax)) {
        throw InvalidArgumentError("a fixed VSS depth range needs finite min <= max, got [" +
                                   std::to_string(range.dmin) + ", " + std::to_string(range.dmax) +
                                   "]");
    }
}

/// The content of a CPU value the frame produced; null when its writer did not run.
template <class T>
const T* resultValue(const RenderGraph& graph, Handle<CpuValue<T>> handle) {
    if (!handle.valid()) {
        return nullptr;
    }
    const CpuValue<T>* value = graph.result(handle);
    return value != nullptr && value->hasValue() ? &value->value() : nullptr;
}

}  // namespace

vss::SolverOptions effectiveSolverOptions(const VssSettings& settings) noexcept {
    vss::SolverOptions options = settings.solver;
    if (settings.preview) {
        options.kind = vss::SolverKind::Fast;
        if (!(options.tolerance >= settings.previewTolerance)) {
            options.tolerance = settings.previewTolerance;
        }
    }
    return options;
}

std::uint64_t sceneFingerprint(const scene::Scene& scene) noexcept {
    // bulk(): a scene's arrays are megabytes, hashed on every offscreen render.
    Hasher h;
    h.value(scene.meshes.size());
    for (const auto& mesh : scene.meshes) {
        h.bulk(mesh.positions.data(), mesh.positions.size() * sizeof(glm::vec3));
        h.bulk(mesh.indices.data(), mesh.indices.size() * sizeof(std::uint32_t));
        h.bulk(mesh.normals.data(), mesh.normals.size() * sizeof(glm::vec3));
        // The per-vertex values the renderer uploads from the point arrays.
        h.value(mesh.pointArrays.size());
        for (const scene::DataArray& array : mesh.pointArrays) {
            h.value(array.name.size()).text(array.name).value(array.components);
            h.bulk(array.values.data(), array.values.size() * sizeof(float));
        }
    }
    return h.result();
}

struct FrameRenderer::Impl {
    QOpenGLFunctions_4_1_Core* gl = nullptr;
    QOpenGLContext* context = nullptr;
    std::unique_ptr<GlResourceAllocator> allocator;
    std::unique_ptr<RenderGraphCache> cache;
    std::unique_ptr<GlPassObserver> observer;
    std::unique_ptr<PassPrograms> programs;
    std::unique_ptr<DepthScaleLut> scaleLut;
    GLuint emptyVao = 0;
    std::unique_ptr<RectBatch> rects;
    std::unique_ptr<SolveWorker> worker;
    std::function<void()> onSolved;
    /// Tiled rendering: the frame's VSS solved outside (setExternalVss), its
    /// version (0 = none) and the frame's visible depth range.
    std::shared_ptr<const SolvedFrame> external;
    std::uint64_t externalVersion = 0;
    std::optional<std::pair<double, double>> externalVisible;

    // What the last frames' graphs produced for the renderer's API, taken
    // from their results after execute() (no pass writes these).
    /// The depth the last solve read, and the view (viewKey) it shows.
    std::shared_ptr<const Image<float>> lastDepth;
    std::optional<std::uint64_t> lastDepthView;
    /// The VSS the last solve pass left in the height texture.
    std::shared_ptr<const SolvedFrame> shownFrame;
    /// renderDepth(): the linear depth the "depth-readback" pass read.
    Image<float> depthReadback;
    /// The last frame's G-buffer, for probe() and visibleDepthRange().
    GBufferProbe probe;

    [[nodiscard]] QOpenGLFunctions_4_1_Core& f() const {
        if (gl == nullptr) {
            throw RenderError("FrameRenderer used before initialize()");
        }
        if (QOpenGLContext::currentContext() != context) {
            throw RenderError("FrameRenderer used without its OpenGL context current");
        }
        return *gl;
    }

    [[nodiscard]] PassContext passContext(MeshRenderer& meshes, VolumeRenderer& volume) const {
        return PassContext{.gl = gl,
                           .programs = programs.get(),
                           .framebuffers = &allocator->framebuffers(),
                           .scaleLut = scaleLut.get(),
                           .emptyVao = emptyVao,
                           .rects = rects.get(),
                           .meshes = &meshes,
                           .volume = &volume};
    }

    /// Puts the frame's target on the blackboard (board::kOutput).
    void importTarget(RenderGraph& graph, const FrameTarget& target) const {
        const TextureDescriptor descriptor{target.width, target.height, TextureFormat::RGBA8, 1};
        graph.blackboard().put(
            board::kOutput,
            graph.importResource(
                board::kOutput,
                Texture(descriptor, std::make_shared<GlTexture>(descriptor, target.framebuffer)),
                ImportOptions{.target = true, .revision = 0}));
    }

    /// Puts what the solve takes from outside on the blackboard: the
    /// worker's latest solve (asynchronous mode) and the external VSS.
    void importSolveInputs(RenderGraph& graph, bool async) const {
        if (async) {
            auto [latest, revision] = worker->latest();
            graph.blackboard().put(
                board::kSolvedImport,
                graph.importResource(board::kSolvedImport, SolvedFrameRef{std::move(latest)},
                                     ImportOptions{.target = false, .revision = revision}));
        }
        graph.blackboard().put(
            board::kExternalVss,
            graph.importResource(board::kExternalVss, ExternalFrame{external, externalVisible},
                                 ImportOptions{.revision = externalVersion}));
    }

    /// Takes what a frame's graph produced for the renderer's API.
    void keepResults(const RenderGraph& graph, const GeometryOutputs& geometry,
                     Handle<CpuValue<DepthImage>> depth, const VssSolveOutputs* solve) {
        const Texture* linearDepth = graph.result(geometry.linearDepth);
        const Texture* objectId = graph.result(geometry.objectId);
        const Texture* parameter = graph.result(geometry.parameter);
        const DepthImage* image = resultValue(graph, depth);
        if (linearDepth != nullptr && objectId != nullptr && parameter != nullptr) {
            probe.setFrame(*linearDepth, *objectId, *parameter,
                           image != nullptr ? image->image : nullptr);
        }
        if (solve == nullptr) {
            return;
        }
        if (const ShownVss* shown = resultValue(graph, solve->shown)) {
            shownFrame = shown->frame;
        }
        if (const SolveInput* input = resultValue(graph, solve->input);
            input != nullptr && input->depth) {
            lastDepth = input->depth;
            lastDepthView = input->view;
        }
    }
};

FrameRenderer::FrameRenderer() : impl_(std::make_unique<Impl>()) {}

FrameRenderer::~FrameRenderer() {
    if (impl_->context != nullptr && QOpenGLContext::currentContext() == impl_->context) {
        release();
    }
    impl_->worker.reset();
}

bool FrameRenderer::initialized() const noexcept {
    return impl_->gl != nullptr && impl_->programs != nullptr && meshes_.initialized();
}

void FrameRenderer::initialize() {
    auto& gl = currentGl41();
    if (impl_->gl != nullptr && impl_->context == QOpenGLContext::currentContext()) {
        release();
    }
    meshes_.initialize();
    volume_.initialize();
    impl_->gl = &gl;
    impl_->context = QOpenGLContext::currentContext();
    impl_->probe.clear();
    impl_->cache.reset();
    impl_->allocator = std::make_unique<GlResourceAllocator>();
    impl_->cache = std::make_unique<RenderGraphCache>(*impl_->allocator);
    impl_->observer = std::make_unique<GlPassObserver>();
    impl_->programs = std::make_unique<PassPrograms>(gl);
    gl.glGenVertexArrays(1, &impl_->emptyVao);
    impl_->rects = std::make_unique<RectBatch>(gl);
    impl_->scaleLut = std::make_unique<DepthScaleLut>(gl);
    impl_->shownFrame.reset();
    checkGlError(gl, "FrameRenderer::initialize");
}

void FrameRenderer::release() noexcept {
    impl_->worker.reset();
    if (impl_->gl == nullptr || QOpenGLContext::currentContext() != impl_->context) {
        return;
    }
    auto& g = *impl_->gl;
    impl_->probe.clear();
    impl_->cache.reset();  // GL textures die with the context current
    impl_->allocator.reset();
    if (impl_->observer) {
        impl_->observer->release();
        impl_->observer.reset();
    }
    impl_->programs.reset();
    impl_->scaleLut.reset();
    g.glDeleteVertexArrays(1, &impl_->emptyVao);
    impl_->rects.reset();
    impl_->emptyVao = 0;
    impl_->shownFrame.reset();
    meshes_.release();
    volume_.release();
    impl_->gl = nullptr;
    impl_->context = nullptr;
}

void FrameRenderer::setSolveMode(SolveMode mode, std::function<void()> onSolved) {
    impl_->worker.reset();
    mode_ = mode;
    impl_->onSolved = std::move(onSolved);
    if (mode_ == SolveMode::Asynchronous) {
        impl_->worker = std::make_unique<SolveWorker>(impl_->onSolved);
    }
}

const Image<float>& FrameRenderer::lastSolvedDepth() const noexcept {
    static const Image<float> none;
    return impl_->lastDepth ? *impl_->lastDepth : none;
}

bool FrameRenderer::solveInProgress() const {
    return impl_->worker != nullptr && impl_->worker->busy();
}

void FrameRenderer::waitForSolves() {
    if (impl_->worker) {
        impl_->worker->waitIdle();
    }
}

void FrameRenderer::clearCache() {
    if (impl_->cache) {
        impl_->cache->clear();
    }
    impl_->shownFrame.reset();
    impl_->lastDepthView.reset();
}

std::size_t FrameRenderer::geometryLevel(const Camera& camera, const FrameSettings& settings,
                                         glm::ivec2 renderSize) const noexcept {
    if (settings.simplifiedGeometry && meshes_.hasPreviewScene()) {
        return meshes_.previewLevelFor(static_cast<long long>(renderSize.x) * renderSize.y);
    }
    if (settings.smoothCoarseMeshes && meshes_.refinedWanted(camera)) {
        return kRefinedLevel;
    }
    return 0;
}

std::uint64_t FrameRenderer::geometryRevision(std::size_t level) const noexcept {
    // Up to 6 preview levels told apart (there are two); the refined copy
    // (kRefinedLevel) is 7.
    std::uint64_t revision = sceneRevision_ * 8U + std::min<std::uint64_t>(level, 7U);
    if (volume_.volume()) {
        // Volume depth source: its revision tells depth views apart too.
        revision ^= (volumeRevision_ + 1U) * 0x9E3779B97F4A7C15ULL;
    }
    return revision;
}

std::uint64_t FrameRenderer::depthRevision(std::size_t level) const {
    Hasher hash;
    hash.value(geometryRevision(level)).value(meshes_.style().depthKey());
    return hash.result();
}

// --- Volume depth source (issue 5) ------------------------------------------
void FrameRenderer::setVolume(std::shared_ptr<const scene::Volume> volume, float isoValue) {
    if (volume == volume_.volume() && (!volume || isoValue == volumeIso_)) {
        return;
    }
    volume_.setVolume(std::move(volume));
    volumeIso_ = isoValue;
    ++volumeRevision_;
}
// --- end volume depth source -------------------------------------------------

bool FrameRenderer::requestSolve(const Camera& camera, const FrameSettings& settings,
                                 const FrameTarget& target) {
    const VssSettings& vssSettings = settings.vss;
    if (mode_ != SolveMode::Asynchronous || impl_->worker == nullptr || !vssSettings.enabled ||
        !impl_->lastDepthView || impl_->lastDepth == nullptr || impl_->lastDepth->width() == 0) {
        return false;
    }
    const glm::ivec2 renderSize = renderSizeFor(settings, target);
    const std::uint64_t depthView =
        viewKey(camera.viewMatrix(), camera.projectionMatrix(), renderSize,
                depthRevision(geometryLevel(camera, settings, renderSize)));
    if (depthView != *impl_->lastDepthView || impl_->lastDepth->width() != renderSize.x ||
        impl_->lastDepth->height() != renderSize.y) {
        return false;  // the depth shows another view: the next frame reads it back
    }
    const vss::SolverOptions options = effectiveSolverOptions(vssSettings);
    static_cast<void>(vss::makeSolver(options));  // throws for bad options, like render()
    const float reduction = reductionOf(target, renderSize);
    const glm::ivec2 vssSize = vssSizeFor(settings, renderSize, impl_->external != nullptr);
    const std::uint64_t request = requestKey(depthView, solverKey(options, vssSettings.range),
                                             vssSettings.preview, reduction, vssSize);
    const auto latest = impl_->worker->latest().first;
    if ((latest && latest->key == request) || impl_->worker->requested(request)) {
        return true;
    }
    impl_->worker->submit(SolveWorker::Job{request, impl_->lastDepth, options, vssSettings.preview,
                                           vssSettings.range, pixelScaleOf(camera, renderSize.y),
                                           reduction,
                                           vssSize != renderSize ? vssSize : glm::ivec2(0)});
    return true;
}

SolveCounters FrameRenderer::solveCounters() const {
    return impl_->worker ? impl_->worker->counters() : SolveCounters{};
}

Image<float> FrameRenderer::shownHeight() const {
    return impl_->shownFrame ? impl_->shownFrame->height : Image<float>{};
}

const std::vector<GlPassTiming>& FrameRenderer::lastTimings() {
    static const std::vector<GlPassTiming> none;
    if (!impl_->observer) {
        return none;
    }
    return impl_->observer->timings();
}

void FrameRenderer::render(const Camera& camera, const FrameSettings& settings,
                           const FrameTarget& target) {
    renderGraph(camera, settings, target, GraphMode::Frame);
}

Image<float> FrameRenderer::renderDepth(const Camera& camera, const FrameSettings& settings,
                                        const FrameTarget& target) {
    renderGraph(camera, settings, target, GraphMode::DepthOnly);
    return std::move(impl_->depthReadback);
}

void FrameRenderer::setExternalVss(std::optional<ExternalVss> external) {
    if (!external) {
        impl_->external.reset();
        impl_->externalVersion = 0;
        impl_->externalVisible.reset();
        return;
    }
    auto frame = std::make_shared<SolvedFrame>();
    frame->height = std::move(external->height);
    frame->dmin = external->dmin;
    frame->dmax = external->dmax;
    frame->milliseconds = external->solveMilliseconds;
    frame->errorBound = external->errorBound;
    impl_->external = std::move(frame);
    // Never 0, so that "none" and an external VSS are told apart.
    impl_->externalVersion = external->version * 2U + 1U;
    impl_->externalVisible = external->visibleRange;
}

bool FrameRenderer::prepareSolve(const Camera& camera, const FrameSettings& settings,
                                 const FrameTarget& target) {
    if (mode_ != SolveMode::Asynchronous || impl_->worker == nullptr || !settings.vss.enabled) {
        return false;
    }
    renderGraph(camera, settings, target, GraphMode::SolveOnly);
    return true;
}

// --- Probe (G-buffer read-back of single pixels) ---------------------------

std::optional<ProbeSample> FrameRenderer::probe(const Camera& camera, int x, int y) const {
    if (!initialized() || renderSize_.x < 1 || renderSize_.y < 1 || x < 0 || y < 0 ||
        x >= renderSize_.x || y >= renderSize_.y) {
        return std::nullopt;
    }
    return impl_->probe.probe(impl_->f(), camera, renderSize_, x, y);
}

std::optional<std::pair<float, float>> FrameRenderer::visibleDepthRange() const {
    if (!initialized() || renderSize_.x < 1 || renderSize_.y < 1) {
        return std::nullopt;
    }
    return impl_->probe.visibleDepthRange(impl_->f());
}

// --- end probe -------------------------------------------------------------

namespace {

/// The sizes and scales of one frame that its passes share.
struct FrameShape {
    glm::ivec2 size{1, 1};        ///< the render size (the passes')
    glm::ivec2 targetSize{1, 1};  ///< the target's
    glm::ivec2 vssSize{1, 1};     ///< the VSS's: the render size, or below it
    glm::mat4 projection{1.0F};
    float pixelScale = 0.0F;  ///< of a pixel at the render size
    std::size_t meshLevel = 0;
};

/// Where the solve's depth and result come from.
struct SolveSources {
    Handle<CpuValue<DepthImage>> depth;  ///< the depth read back
    SolveWorker* worker = nullptr;       ///< asynchronous: the worker; null = inline
    bool external = false;               ///< show the imported external VSS instead
    std::uint64_t depthView = 0;         ///< viewKey() of the depth
};

/// The inputs of the frame's "vss-solve".
VssSolveInputs solveInputs(const PassContext& context, const FrameSettings& settings,
                           const FrameShape& shape, const FrameTarget& target,
                           const SolveSources& from) {
    const VssSettings& vssSettings = settings.vss;
    const vss::SolverOptions solverOptions = effectiveSolverOptions(vssSettings);
    const glm::ivec2 vssSize = shape.vssSize;
    const float reduction = reductionOf(target, shape.size);
    return VssSolveInputs{
        .context = context,
        .depth = from.depth,
        .worker = from.worker,
        .external = from.external,
        .options = solverOptions,
        .range = vssSettings.range,
        .preview = vssSettings.preview,
        .depthView = from.depthView,
        .request = requestKey(from.depthView, solverKey(solverOptions, vssSettings.range),
                              vssSettings.preview, reduction, vssSize),
        .pixelScale = shape.pixelScale,
        .reduction = reduction,
        .size = vssSize,
        .reduced = vssSize != shape.size,
        // The slopes the solver's thread fits for the lighting: at the render
        // size up to kMaxCpuSlopePixels, else (and for an external VSS, which
        // brings none) a stand-in texel: the shader fits them.
        .cpuSlopes =
            !from.external && static_cast<long long>(vssSize.x) * vssSize.y <= kMaxCpuSlopePixels,
    };
}

/// What the passes after the vessels' shading read from the passes before.
struct Upstream {
    const GeometryOutputs& geometry;
    const DepthReadbackOutputs& readback;
    const VssSolveOutputs& solve;
    const VesselShadingOutputs& vessels;
};

/// The picture from the shaded vessels on: the VSS's shading, the
/// translucent objects, the AO, the composite and, when the composite goes
/// into a texture, "fxaa" or "upscale" into the target.
void addPicturePasses(RenderGraph& graph, const PassContext& context, const Camera& camera,
                      const FrameSettings& settings, const FrameShape& shape, const Upstream& up,
                      const Lighting& light, bool translucent) {
    const VssSettings& vssSettings = settings.vss;
    const glm::ivec2 size = shape.size;
    const bool reducedVss = shape.vssSize != size;
    // With anti-aliasing the FXAA pass draws into the target (upscaling a
    // reduced render size with its bilinear taps); without it, a reduced
    // render size ends with "upscale", which draws the VSS's iso-lines at the
    // target's size (the VSS shading leaves them out then).
    const bool scaled = size != shape.targetSize;
    const bool useAa = settings.antialiasing || scaled;
    const bool upscale = scaled && !settings.antialiasing;
    const int targetIsoLines = upscale && vssSettings.enabled && vssSettings.isoLineStrength > 0.0F
                                   ? std::max(vssSettings.isoLines, 0)
                                   : 0;
    VssSettings shadedVss = vssSettings;
    if (targetIsoLines > 0) {
        shadedVss.isoLines = 0;
    }
    const VssShadingOutputs vss = addVssShadingPass(
        graph, VssShadingInputs{.context = context,
                                .settings = shadedVss,
                                .light = light,
                                .pixelScale = pixelScaleOf(camera, shape.vssSize.y),
                                .size = shape.vssSize,
                                .vss = up.solve,
                                .linearDepth = up.geometry.linearDepth,
                                .reduced = reducedVss});
    // Declared always: with no translucent object, or AO off, nothing reads
    // them and the graph culls them.
    const TranslucentOutputs layer =
        addTranslucentPass(graph, TranslucentInputs{.context = context,
                                                    .camera = camera,
                                                    .meshLevel = shape.meshLevel,
                                                    .size = size,
                                                    .opaqueDepth = up.geometry.depth,
                                                    .cue = up.vessels.cue});
    const AoSettings& ao = settings.ao;
    const int aoStep = aoStepFor(ao, static_cast<long long>(size.x) * size.y);
    const SsaoOutputs occlusion = addSsaoPass(
        graph, SsaoInputs{.context = context,
                          .linearDepth = up.geometry.linearDepth,
                          .normal = up.geometry.normal,
                          .useVss = vssSettings.enabled,
                          .vssHeight = up.solve.height,
                          .shownVss = up.solve.shown,
                          .radius = std::max(ao.radius, 1e-6F),
                          .pixelScale = shape.pixelScale,
                          // Where the view axis meets the frame, in pixels from its
                          // centre: 0 except for off-axis tiles (P[2][0], P[2][1]).
                          .axisOffset = glm::vec2(
                              -0.5F * shape.projection[2][0] * static_cast<float>(size.x),
                              -0.5F * shape.projection[2][1] * static_cast<float>(size.y)),
                          .size = size,
                          .step = aoStep});
    const AoBlurOutputs blurred = addAoBlurPass(
        graph,
        AoBlurInputs{.context = context, .raw = occlusion.raw, .size = aoSize(size, aoStep)});
    const CompositeOutputs composited =
        addCompositePass(graph, CompositeInputs{.context = context,
                                                .vessels = up.vessels.color,
                                                .useVss = vssSettings.enabled,
                                                .vss = vss.color,
                                                .useAo = ao.enabled && ao.strength > 0.0F,
                                                .ao = blurred.ao,
                                                .useTranslucent = translucent,
                                                .translucent = layer.layer,
                                                .toTexture = useAa,
                                                .vssVisibilityAlpha = targetIsoLines > 0,
                                                .reducedVss = reducedVss,
                                                .vssOpacity = vssSettings.opacity,
                                                .aoStrength = ao.strength,
                                                .aoStep = aoStep,
                                                .background = settings.background,
                                                .size = size});
    if (settings.antialiasing) {
        addFxaaPass(graph, FxaaInputs{.context = context,
                                      .color = composited.color,
                                      .targetSize = shape.targetSize});
    } else if (upscale) {
        addUpscalePass(graph, UpscaleInputs{.context = context,
                                            .color = composited.color,
                                            .targetSize = shape.targetSize,
                                            .renderSize = size,
                                            .isoLines = targetIsoLines,
                                            .isoLineWidth = vssSettings.isoLineWidth,
                                            .isoLineStrength = vssSettings.isoLineStrength,
                                            .vssHeight = up.solve.height,
                                            .shownVss = up.solve.shown,
                                            .linearDepth = up.geometry.linearDepth,
                                            .depthImage = up.readback.image});
    }
}

}  // namespace

void FrameRenderer::renderGraph(const Camera& camera, const FrameSettings& settings,
                                const FrameTarget& target, GraphMode mode) {
    if (!initialized()) {
        throw RenderError("FrameRenderer::render before initialize()");
    }
    auto& gl = impl_->f();
    checkFrame(settings, target);
    Impl& impl = *impl_;
    // The passes run at the (possibly reduced) render size; the last pass
    // draws into the target at its full size.
    FrameShape shape;
    shape.size = renderSizeFor(settings, target);
    shape.targetSize = glm::ivec2(target.width, target.height);
    const glm::ivec2 size = shape.size;
    renderSize_ = size;
    shape.meshLevel = geometryLevel(camera, settings, size);
    lastGeometryLevel_ = shape.meshLevel;
    // The scene's revision, told apart for each simplified (preview) level.
    const std::uint64_t sceneRevision = geometryRevision(shape.meshLevel);
    const VssSettings& vssSettings = settings.vss;
    const std::shared_ptr<const SolvedFrame> external = impl.external;
    if (external && vssSettings.enabled && external->height.width() != 0 &&
        (external->height.width() != size.x || external->height.height() != size.y)) {
        throw InvalidArgumentError(
            "the external VSS is " + std::to_string(external->height.width()) + "x" +
            std::to_string(external->height.height()) + ", the frame renders at " +
            std::to_string(size.x) + "x" + std::to_string(size.y));
    }
    const PassContext context = impl.passContext(meshes_, volume_);
    shape.projection = camera.projectionMatrix();
    shape.pixelScale = pixelScaleOf(camera, size.y);

    RenderGraph graph(*impl.cache);
    impl.importTarget(graph, target);
    const auto& scene = meshes_.scene();
    const GeometryOutputs geometry = addGeometryPass(
        graph, GeometryInputs{.context = context,
                              .camera = camera,
                              .size = size,
                              .sceneRevision = sceneRevision,
                              .arrayKey = meshes_.style().geometryKey(),
                              .volumeRevision = volume_.volume() ? volumeRevision_ : 0U,
                              .volumeIso = volumeIso_,
                              .meshLevel = shape.meshLevel,
                              .volumeObjectId =
                                  static_cast<unsigned>(scene ? scene->meshes.size() : 0U) + 1U});
    const DepthReadbackOutputs readback = addDepthReadbackPass(
        graph, DepthReadbackInputs{.context = context, .linearDepth = geometry.linearDepth});
    const auto finish = [&](const VssSolveOutputs* solve) {
        graph.execute(impl.observer.get());
        passes_ = graph.passes();
        graphText_ = graph.toText();
        impl.keepResults(graph, geometry, readback.image, solve);
    };
    if (mode == GraphMode::DepthOnly) {
        // renderDepth(): the G-buffer's linear depth read back, nothing shaded.
        graph.markTarget(readback.image);
        finish(nullptr);
        impl.depthReadback = *resultValue(graph, readback.image)->image;
        gl.glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer);
        return;
    }

    // The solve: inline, or on the worker (whose latest solve is an import).
    const bool async = mode_ == SolveMode::Asynchronous && impl.worker != nullptr;
    impl.importSolveInputs(graph, async);
    const std::uint64_t depthView =
        viewKey(camera.viewMatrix(), shape.projection, size, depthRevision(shape.meshLevel));
    // The VSS's size: the render size, or below it for a moving frame.
    shape.vssSize = vssSettings.enabled ? vssSizeFor(settings, size, external != nullptr) : size;
    vssSize_ = shape.vssSize;
    const VssSolveOutputs solve = addVssSolvePass(
        graph, solveInputs(context, settings, shape, target,
                           SolveSources{.depth = readback.image,
                                        .worker = async ? impl.worker.get() : nullptr,
                                        .external = external != nullptr,
                                        .depthView = depthView}));

    // A vessel cue normalises depth with the VSS's dmin / dmax when a VSS is
    // shown, else with the visible vessels' range ("depth-range").
    const bool cueUsesDepth = settings.cue.cue != VesselCue::None;
    const bool cueUsesVss = cueUsesDepth && vssSettings.enabled;
    const DepthRangeOutputs visible =
        cueUsesDepth ? addDepthRangePass(graph, DepthRangeInputs{.external = external != nullptr,
                                                                 .depth = readback.image})
                     : DepthRangeOutputs{};
    // The viewer's vessel colours are kept across frames: prepareSolve()
    // shades them while the solve runs, and the frame that shows the solve
    // reuses them. Elsewhere (exports, the CLI) their storage is pooled.
    const bool keepVesselColor = async;
    const VesselShadingOutputs vessels = addVesselShadingPass(
        graph, VesselShadingInputs{.context = context,
                                   .camera = camera,
                                   .cue = settings.cue,
                                   .background = settings.background,
                                   .gbuffer = geometry,
                                   .cueUsesDepth = cueUsesDepth,
                                   .cueUsesVss = cueUsesVss,
                                   .visibleRange = visible.range,
                                   .shownVss = solve.shown,
                                   .keepColor = keepVesselColor,
                                   .shadingRevision = meshes_.shadingRevision(),
                                   .size = size});
    if (mode == GraphMode::SolveOnly) {
        // prepareSolve(): the G-buffer and the solve's submission, and the
        // vessels' shading when it does not read the VSS (its colours are
        // then reused by the frame that shows the solve).
        graph.markTarget(solve.height);
        if (keepVesselColor && !cueUsesVss) {
            graph.markTarget(vessels.color);
        }
        finish(&solve);
        gl.glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer);
        return;
    }

    addPicturePasses(
        graph, context, camera, settings, shape,
        Upstream{.geometry = geometry, .readback = readback, .solve = solve, .vessels = vessels},
        lightingFor(meshes_.style().light), meshes_.hasTranslucent());
    finish(&solve);
    gl.glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer);
    gl.glViewport(0, 0, target.width, target.height);
    // A cached solve pass keeps what it showed last.
    const ShownVss* shown = vssSettings.enabled ? resultValue(graph, solve.shown) : nullptr;
    status_ = shown != nullptr ? shown->status : VssFrameStatus{};
    const ShadedCue* shaded = resultValue(graph, vessels.cue);
    cueRange_ = shaded != nullptr ? shaded->range : std::nullopt;
}

}  // namespace vv::render
