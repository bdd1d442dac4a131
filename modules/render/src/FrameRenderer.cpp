// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/render/FrameRenderer.h"

#include <QOpenGLContext>
#include <QOpenGLFunctions_4_1_Core>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstring>
#include <functional>
#include <limits>
#include <mutex>
#include <optional>
#include <stop_token>
#include <string>
#include <thread>
#include <utility>

#include "vv/colormaps/DepthScale.h"
#include "vv/core/Error.h"
#include "vv/core/Image.h"
#include "vv/render/RenderGraphCache.h"
#include "vv/vss/DepthNormalization.h"
#include "vv/vss/Shading.h"
#include "vv/vss/Vss.h"

namespace vv::render {

namespace {

constexpr int kScaleLutSize = 256;
/// The height texture's mark for "no VSS here" (NaN is not portable in GLSL).
constexpr float kNoVss = -1.0F;

/// Draws the full-screen triangle of fullscreen.vert with `vao`, then leaves
/// no state behind: no texture (1-D or 2-D) on units 0 .. units-1 (unit 0
/// active afterwards), no program.
void drawFullscreenAndUnbind(QOpenGLFunctions_4_1_Core& g, GLuint vao, int units) {
    g.glBindVertexArray(vao);
    g.glDrawArrays(GL_TRIANGLES, 0, 3);
    g.glBindVertexArray(0);
    for (int unit = units - 1; unit >= 0; --unit) {
        g.glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
        g.glBindTexture(GL_TEXTURE_2D, 0);
        g.glBindTexture(GL_TEXTURE_1D, 0);
    }
    g.glUseProgram(0);
}

/// FNV-1a over raw bytes.
class Hasher {
  public:
    void bytes(const void* data, std::size_t size) noexcept {
        const auto* p = static_cast<const unsigned char*>(data);
        for (std::size_t i = 0; i < size; ++i) {
            hash_ = (hash_ ^ p[i]) * 1099511628211ULL;
        }
    }
    template <class T>
    void value(const T& v) noexcept {
        bytes(&v, sizeof v);
    }
    [[nodiscard]] std::uint64_t result() const noexcept { return hash_; }

  private:
    std::uint64_t hash_ = 14695981039346656037ULL;
};

/// The solver options as plain bytes for dependsOn (no padding surprises).
struct SolverKey {
    double p = 0.0;
    double tolerance = 0.0;
    double rangeMin = 0.0;  ///< fixed depth range; 0, 0 when visible
    double rangeMax = 0.0;
    std::int32_t kind = 0;
    std::int32_t step = 0;
    std::int32_t rangeMode = 0;
    std::int32_t padding = 0;
};

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

/// A solved VSS for one view.
struct SolvedFrame {
    std::uint64_t key = 0;  ///< view, viewport, scene and solver it belongs to
    Image<float> height;    ///< GL row order (bottom row first); NaN = no VSS
    double dmin = 0.0;
    double dmax = 0.0;
    double milliseconds = 0.0;
    bool preview = false;     ///< a preview-quality solve
    double errorBound = 0.0;  ///< the solver's bound on |z' error|; NaN = none
    /// The lighting's plane-fit slopes (vss::fittedSlopes), same order and
    /// size as `height`; empty for previews (quick normals) and above
    /// kMaxCpuSlopePixels (the shader fits them itself there).
    Image<glm::vec4> slopes;
};

/// Frames up to this many pixels (4K UHD) get their VSS slopes from the
/// solver's thread (16 bytes a pixel, CPU and texture); larger ones (big
/// exports) let the shader fit them, slower but without the memory.
constexpr long long kMaxCpuSlopePixels = 3840LL * 2160LL;

/// Scene units per pixel per unit of depth of `camera` at a render height of
/// `height` pixels; a tile (Camera::window) keeps the full view's pixel size:
/// P[1][1] grew by the full height / the tile's.
float pixelScaleOf(const Camera& camera, int height) {
    return camera.window() ? 2.0F / (camera.projectionMatrix()[1][1] * static_cast<float>(height))
                           : 2.0F * std::tan(glm::radians(camera.fieldOfView()) * 0.5F) /
                                 static_cast<float>(height);
}

/// Solves the VSS of `depth`; exact solves also get their lighting slopes
/// (`pixelScale`: pixelScaleOf the view, for the normals' coherence).
SolvedFrame solveFrame(std::uint64_t key, const Image<float>& depth,
                       const vss::SolverOptions& options, bool preview,
                       const vss::DepthRange& range, float pixelScale,
                       const std::stop_token& stop) {
    const auto start = std::chrono::steady_clock::now();
    const Image<std::uint8_t> mask = vss::maskFromFiniteDepth(depth.view());
    vss::VssOptions vssOptions;
    vssOptions.solver = options;
    vssOptions.range = range;
    vssOptions.stop = stop;
    vss::VssResult result = vss::solve(depth.view(), mask.view(), vssOptions);
    SolvedFrame frame;
    frame.key = key;
    frame.height = std::move(result.height);
    frame.dmin = result.dmin;
    frame.dmax = result.dmax;
    frame.preview = preview;
    frame.errorBound = result.errorBound;
    if (!preview && !frame.height.empty() &&
        static_cast<long long>(frame.height.width()) * frame.height.height() <=
            kMaxCpuSlopePixels) {
        frame.slopes = vss::fittedSlopes(frame.height.view(), mask.view(), stop);
        if (std::isfinite(frame.dmin) && std::isfinite(frame.dmax) && pixelScale > 0.0F) {
            vss::addNormalCoherence(frame.slopes, frame.height.view(), mask.view(),
                                    vss::SlopeScale{frame.dmin, frame.dmax, pixelScale});
        }
    }
    frame.milliseconds =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return frame;
}

/// The latest solved VSS as a graph import: its revision tells the solve
/// pass when a new one arrived.
struct SolvedFrameRef {
    std::shared_ptr<const SolvedFrame> frame;
};

/// One worker thread solving the latest requested view; a newer request
/// cancels a running stale one (vss::solve's stop token).
class SolveWorker {
  public:
    struct Job {
        std::uint64_t key = 0;
        Image<float> depth;
        vss::SolverOptions options;
        bool preview = false;
        vss::DepthRange range;
        float pixelScale = 0.0F;  ///< pixelScaleOf the view (slopes' normals)
    };

    explicit SolveWorker(std::function<void()> onSolved)
        : onSolved_(std::move(onSolved)),
          thread_([this](const std::stop_token& stop) { run(stop); }) {}

    ~SolveWorker() {
        {
            std::lock_guard lock(mutex_);
            runningStop_.request_stop();
            pending_.reset();
        }
        thread_.request_stop();
        wake_.notify_all();
        thread_.join();
    }
    SolveWorker(const SolveWorker&) = delete;
    SolveWorker& operator=(const SolveWorker&) = delete;
    SolveWorker(SolveWorker&&) = delete;
    SolveWorker& operator=(SolveWorker&&) = delete;

    void submit(Job job) {
        {
            std::lock_guard lock(mutex_);
            if (running_ && runningKey_ != job.key) {
                runningStop_.request_stop();
            }
            pending_ = std::move(job);
            ++counters_.submitted;
        }
        wake_.notify_all();
    }

    /// True when `key` is queued or being solved.
    [[nodiscard]] bool requested(std::uint64_t key) const {
        std::lock_guard lock(mutex_);
        return (pending_ && pending_->key == key) ||
               (running_ && runningKey_ == key && !runningStop_.stop_requested());
    }

    /// True when a solve is queued or running (and not being stopped).
    [[nodiscard]] bool busy() const {
        std::lock_guard lock(mutex_);
        return pending_.has_value() || (running_ && !runningStop_.stop_requested());
    }

    [[nodiscard]] std::pair<std::shared_ptr<const SolvedFrame>, std::uint64_t> latest() const {
        std::lock_guard lock(mutex_);
        return {latest_, revision_};
    }

    [[nodiscard]] SolveCounters counters() const {
        std::lock_guard lock(mutex_);
        return counters_;
    }

    void waitIdle() {
        std::unique_lock lock(mutex_);
        idle_.wait(lock, [this] { return !pending_ && !running_; });
    }

  private:
    void run(const std::stop_token& stop) {
        for (;;) {
            Job job;
            std::stop_token jobStop;
            {
                std::unique_lock lock(mutex_);
                wake_.wait(lock, [&] { return pending_.has_value() || stop.stop_requested(); });
                if (stop.stop_requested()) {
                    return;
                }
                job = std::move(*pending_);
                pending_.reset();
                runningStop_ = std::stop_source();
                jobStop = runningStop_.get_token();
                running_ = true;
                runningKey_ = job.key;
            }
            std::shared_ptr<const SolvedFrame> solved;
            bool cancelled = false;
            try {
                solved = std::make_shared<const SolvedFrame>(
                    solveFrame(job.key, job.depth, job.options, job.preview, job.range,
                               job.pixelScale, jobStop));
            } catch (const CancelledError&) {
                cancelled = true;
            } catch (const std::exception&) {
                // A failure: the view shows no new VSS; the next request tries again.
            }
            bool notify = false;
            {
                std::lock_guard lock(mutex_);
                running_ = false;
                if (solved) {
                    latest_ = std::move(solved);
                    ++revision_;
                    ++counters_.completed;
                    // A result that a queued request already supersedes is
                    // kept (frames show it until the newer one arrives) but
                    // wakes nobody: its repaint would be a wasted frame.
                    notify = !pending_.has_value();
                }
                if (cancelled) {
                    ++counters_.cancelled;
                }
            }
            idle_.notify_all();
            if (notify && onSolved_) {
                onSolved_();
            }
        }
    }

    std::function<void()> onSolved_;
    mutable std::mutex mutex_;
    std::condition_variable wake_;
    std::condition_variable idle_;
    std::optional<Job> pending_;
    bool running_ = false;
    std::uint64_t runningKey_ = 0;
    std::stop_source runningStop_;
    std::shared_ptr<const SolvedFrame> latest_;
    std::uint64_t revision_ = 0;
    SolveCounters counters_;
    std::jthread thread_;  // last: starts after, and joins before, the members above go
};

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

/// The key of a solve of the view `view` with `options` (preview or exact).
std::uint64_t requestKey(std::uint64_t view, const SolverKey& options, bool preview) noexcept {
    Hasher h;
    h.value(view);
    h.value(options);
    h.value(preview);
    return h.result();
}

GlTexture& glTex(const Texture& texture) {
    return texture.objectAs<GlTexture>();
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
    Hasher h;
    h.value(scene.meshes.size());
    for (const auto& mesh : scene.meshes) {
        h.value(mesh.positions.size());
        h.bytes(mesh.positions.data(), mesh.positions.size() * sizeof(glm::vec3));
        h.value(mesh.indices.size());
        h.bytes(mesh.indices.data(), mesh.indices.size() * sizeof(std::uint32_t));
        h.value(mesh.normals.size());
        h.bytes(mesh.normals.data(), mesh.normals.size() * sizeof(glm::vec3));
    }
    return h.result();
}

struct FrameRenderer::Impl {
    QOpenGLFunctions_4_1_Core* gl = nullptr;
    QOpenGLContext* context = nullptr;
    std::unique_ptr<GlResourceAllocator> allocator;
    std::unique_ptr<RenderGraphCache> cache;
    std::unique_ptr<GlPassObserver> observer;
    GLuint vssProgram = 0;
    GLuint vssQuickProgram = 0;  ///< vss.frag with QUICK_NORMALS (preview frames)
    GLuint vssSlopeProgram = 0;  ///< vss.frag with SLOPE_TEXTURE (slopes from the solver)
    GLuint compositeProgram = 0;
    GLuint ssaoProgram = 0;
    GLuint aoBlurProgram = 0;
    GLuint fxaaProgram = 0;
    GLuint emptyVao = 0;
    GLuint geometryFbo = 0;
    GLuint shadingFbo = 0;
    GLuint scaleLut = 0;
    std::optional<colormaps::DepthScale> uploadedScale;
    std::unique_ptr<SolveWorker> worker;
    std::function<void()> onSolved;
    /// The depth the last solve read, and the view (viewKey) it shows.
    Image<float> lastDepth;
    std::optional<std::uint64_t> lastDepthView;
    /// What the last run of the solve pass did.
    VssFrameStatus solveStatus;
    /// True when the slope texture holds the shown VSS's slopes (SolvedFrame::slopes).
    bool shownSlopes = false;
    /// What the height texture holds now.
    bool shown = false;
    std::shared_ptr<const SolvedFrame> shownFrame;
    double dmin = 0.0;
    double dmax = 0.0;
    /// The visible vessels' linear depth range ("depth-range" pass).
    bool visibleRange = false;
    double visibleDmin = 0.0;
    double visibleDmax = 0.0;
    /// The range the last vessel-shading pass normalised its cue with.
    std::optional<std::pair<double, double>> cueRange;
    /// The cue the last vessel-shading pass drew with (the translucent pass's too).
    VesselCueParameters shadedCue;
    /// Tiled rendering: the frame's VSS solved outside (setExternalVss), its
    /// version (0 = none) and the frame's visible depth range.
    std::shared_ptr<const SolvedFrame> external;
    std::uint64_t externalVersion = 0;
    std::optional<std::pair<double, double>> externalVisible;
    /// renderDepth(): the linear depth the "depth-readback" pass read.
    Image<float> depthReadback;

    [[nodiscard]] QOpenGLFunctions_4_1_Core& f() const {
        if (gl == nullptr) {
            throw RenderError("FrameRenderer used before initialize()");
        }
        if (QOpenGLContext::currentContext() != context) {
            throw RenderError("FrameRenderer used without its OpenGL context current");
        }
        return *gl;
    }

    void uploadScale(colormaps::DepthScale scale) {
        if (uploadedScale == scale) {
            return;
        }
        auto& g = f();
        const auto table = colormaps::lut(scale, kScaleLutSize);
        g.glBindTexture(GL_TEXTURE_1D, scaleLut);
        g.glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        g.glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA8, kScaleLutSize, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                       table.data());
        g.glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        g.glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        g.glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        g.glBindTexture(GL_TEXTURE_1D, 0);
        checkGlError(g, "uploading the depth scale");
        uploadedScale = scale;
    }

    [[nodiscard]] Image<float> readDepth(const GlTexture& texture) const {
        auto& g = f();
        const auto& d = texture.descriptor();
        Image<float> depth(d.width, d.height);
        g.glBindFramebuffer(GL_READ_FRAMEBUFFER, texture.framebuffer());
        g.glReadBuffer(GL_COLOR_ATTACHMENT0);
        g.glPixelStorei(GL_PACK_ALIGNMENT, 4);
        g.glReadPixels(0, 0, d.width, d.height, GL_RED, GL_FLOAT, depth.data());
        g.glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
        checkGlError(g, "reading the linear depth back");
        return depth;
    }

    /// Uploads `frame` (or "no VSS" when null or of another size).
    void uploadHeight(const GlTexture& texture, const std::shared_ptr<const SolvedFrame>& frame) {
        auto& g = f();
        const auto& d = texture.descriptor();
        const bool fits = frame != nullptr && frame->height.width() == d.width &&
                          frame->height.height() == d.height;
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
        g.glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, d.width, d.height, GL_RED, GL_FLOAT,
                          texels.data());
        g.glBindTexture(GL_TEXTURE_2D, 0);
        checkGlError(g, "uploading the VSS");
        shown = fits && std::isfinite(frame->dmin) && std::isfinite(frame->dmax);
        shownFrame = shown ? frame : nullptr;
        dmin = shown ? frame->dmin : 0.0;
        dmax = shown ? frame->dmax : 0.0;
    }

    /// After uploadHeight(): the shown frame's slopes into `texture` when it
    /// has them at the texture's size (shownSlopes), else nothing.
    void uploadSlopes(const GlTexture& texture) {
        const auto& d = texture.descriptor();
        shownSlopes = shown && shownFrame->slopes.width() == d.width &&
                      shownFrame->slopes.height() == d.height;
        if (!shownSlopes) {
            return;
        }
        auto& g = f();
        g.glBindTexture(GL_TEXTURE_2D, texture.texture());
        g.glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        g.glPixelStorei(GL_UNPACK_ROW_LENGTH, static_cast<GLint>(shownFrame->slopes.stride()));
        g.glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, d.width, d.height, GL_RGBA, GL_FLOAT,
                          shownFrame->slopes.row(0));
        g.glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
        g.glBindTexture(GL_TEXTURE_2D, 0);
        checkGlError(g, "uploading the VSS slopes");
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
    return impl_->gl != nullptr && impl_->vssProgram != 0 && meshes_.initialized();
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
    impl_->cache.reset();
    impl_->allocator = std::make_unique<GlResourceAllocator>();
    impl_->cache = std::make_unique<RenderGraphCache>(*impl_->allocator);
    impl_->observer = std::make_unique<GlPassObserver>();
    const std::string_view vssFragment[] = {":/vv/shaders/vss.frag"};
    const std::string_view quickNormals[] = {"QUICK_NORMALS"};
    impl_->vssProgram =
        buildProgram(gl, ":/vv/shaders/fullscreen.vert", ":/vv/shaders/vss.frag", "VSS shading");
    impl_->vssQuickProgram = buildProgram(gl, ":/vv/shaders/fullscreen.vert", vssFragment,
                                          "VSS shading (quick normals)", quickNormals);
    const std::string_view slopeTexture[] = {"SLOPE_TEXTURE"};
    impl_->vssSlopeProgram = buildProgram(gl, ":/vv/shaders/fullscreen.vert", vssFragment,
                                          "VSS shading (fitted slopes)", slopeTexture);
    impl_->compositeProgram = buildProgram(gl, ":/vv/shaders/fullscreen.vert",
                                           ":/vv/shaders/composite.frag", "composite");
    impl_->ssaoProgram =
        buildProgram(gl, ":/vv/shaders/fullscreen.vert", ":/vv/shaders/ssao.frag", "SSAO");
    impl_->aoBlurProgram =
        buildProgram(gl, ":/vv/shaders/fullscreen.vert", ":/vv/shaders/aoblur.frag", "AO blur");
    impl_->fxaaProgram =
        buildProgram(gl, ":/vv/shaders/fullscreen.vert", ":/vv/shaders/fxaa.frag", "FXAA");
    gl.glGenVertexArrays(1, &impl_->emptyVao);
    gl.glGenFramebuffers(1, &impl_->geometryFbo);
    gl.glGenFramebuffers(1, &impl_->shadingFbo);
    gl.glGenTextures(1, &impl_->scaleLut);
    impl_->uploadedScale.reset();
    impl_->shown = false;
    impl_->shownSlopes = false;
    impl_->shownFrame.reset();
    checkGlError(gl, "FrameRenderer::initialize");
}

void FrameRenderer::release() noexcept {
    impl_->worker.reset();
    if (impl_->gl == nullptr || QOpenGLContext::currentContext() != impl_->context) {
        return;
    }
    auto& g = *impl_->gl;
    impl_->cache.reset();  // GL textures die with the context current
    impl_->allocator.reset();
    if (impl_->observer) {
        impl_->observer->release();
        impl_->observer.reset();
    }
    g.glDeleteProgram(impl_->vssProgram);
    g.glDeleteProgram(impl_->vssQuickProgram);
    g.glDeleteProgram(impl_->vssSlopeProgram);
    g.glDeleteProgram(impl_->compositeProgram);
    g.glDeleteProgram(impl_->ssaoProgram);
    g.glDeleteProgram(impl_->aoBlurProgram);
    g.glDeleteProgram(impl_->fxaaProgram);
    g.glDeleteVertexArrays(1, &impl_->emptyVao);
    g.glDeleteFramebuffers(1, &impl_->geometryFbo);
    g.glDeleteFramebuffers(1, &impl_->shadingFbo);
    g.glDeleteTextures(1, &impl_->scaleLut);
    impl_->vssProgram = 0;
    impl_->vssQuickProgram = 0;
    impl_->vssSlopeProgram = 0;
    impl_->compositeProgram = 0;
    impl_->ssaoProgram = 0;
    impl_->aoBlurProgram = 0;
    impl_->fxaaProgram = 0;
    impl_->emptyVao = 0;
    impl_->geometryFbo = 0;
    impl_->shadingFbo = 0;
    impl_->scaleLut = 0;
    impl_->uploadedScale.reset();
    impl_->shown = false;
    impl_->shownSlopes = false;
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
    return impl_->lastDepth;
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
    impl_->shown = false;
    impl_->shownSlopes = false;
    impl_->shownFrame.reset();
    impl_->lastDepthView.reset();
}

std::size_t FrameRenderer::geometryLevel(const FrameSettings& settings,
                                         glm::ivec2 renderSize) const noexcept {
    if (!settings.simplifiedGeometry || !meshes_.hasPreviewScene()) {
        return 0;
    }
    return meshes_.previewLevelFor(static_cast<long long>(renderSize.x) * renderSize.y);
}

std::uint64_t FrameRenderer::geometryRevision(std::size_t level) const noexcept {
    // Up to 7 preview levels told apart (there are two).
    std::uint64_t revision = sceneRevision_ * 8U + std::min<std::uint64_t>(level, 7U);
    if (volume_.volume()) {
        // Volume depth source: its revision tells depth views apart too.
        revision ^= (volumeRevision_ + 1U) * 0x9E3779B97F4A7C15ULL;
    }
    return revision;
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
        !impl_->lastDepthView || impl_->lastDepth.width() == 0) {
        return false;
    }
    const glm::ivec2 renderSize = renderSizeFor(settings, target);
    const std::uint64_t depthView =
        viewKey(camera.viewMatrix(), camera.projectionMatrix(), renderSize,
                geometryRevision(geometryLevel(settings, renderSize)));
    if (depthView != *impl_->lastDepthView || impl_->lastDepth.width() != renderSize.x ||
        impl_->lastDepth.height() != renderSize.y) {
        return false;  // the depth shows another view: the next frame reads it back
    }
    const vss::SolverOptions options = effectiveSolverOptions(vssSettings);
    static_cast<void>(vss::makeSolver(options));  // throws for bad options, like render()
    const std::uint64_t request =
        requestKey(depthView, solverKey(options, vssSettings.range), vssSettings.preview);
    const auto latest = impl_->worker->latest().first;
    if ((latest && latest->key == request) || impl_->worker->requested(request)) {
        return true;
    }
    impl_->worker->submit(SolveWorker::Job{request, impl_->lastDepth, options, vssSettings.preview,
                                           vssSettings.range, pixelScaleOf(camera, renderSize.y)});
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

void FrameRenderer::renderGraph(const Camera& camera, const FrameSettings& settings,
                                const FrameTarget& target, GraphMode mode) {
    if (!initialized()) {
        throw RenderError("FrameRenderer::render before initialize()");
    }
    auto& gl = impl_->f();
    if (target.width < 1 || target.height < 1) {
        throw InvalidArgumentError("frame size must be at least 1x1, got " +
                                   std::to_string(target.width) + "x" +
                                   std::to_string(target.height));
    }
    const VssSettings& vssSettings = settings.vss;
    if (vssSettings.enabled) {
        // Throws for bad options.
        static_cast<void>(vss::makeSolver(effectiveSolverOptions(vssSettings)));
        const vss::DepthRange& range = vssSettings.range;
        if (range.mode == vss::RangeMode::Fixed &&
            (!std::isfinite(range.dmin) || !std::isfinite(range.dmax) || range.dmin > range.dmax)) {
            throw InvalidArgumentError("a fixed VSS depth range needs finite min <= max, got [" +
                                       std::to_string(range.dmin) + ", " +
                                       std::to_string(range.dmax) + "]");
        }
    }
    // The passes run at the (possibly reduced) render size; the last pass
    // draws into the target at its full size.
    const int targetW = target.width;
    const int targetH = target.height;
    const glm::ivec2 renderSize = renderSizeFor(settings, target);
    const int w = renderSize.x;
    const int h = renderSize.y;
    const bool scaled = w != targetW || h != targetH;
    renderSize_ = {w, h};
    const auto size = [&](TextureFormat format) { return TextureDescriptor{w, h, format, 1}; };
    const TextureDescriptor targetDescriptor{targetW, targetH, TextureFormat::RGBA8, 1};
    const glm::mat4 view = camera.viewMatrix();
    const glm::mat4 projection = camera.projectionMatrix();
    const glm::ivec2 viewport(w, h);
    // The scene's revision, told apart for each simplified (preview) level.
    const std::size_t meshLevel = geometryLevel(settings, renderSize);
    lastGeometryLevel_ = meshLevel;
    const std::uint64_t sceneRevision = geometryRevision(meshLevel);
    Impl& impl = *impl_;
    MeshRenderer& meshes = meshes_;
    VolumeRenderer& volumeRenderer = volume_;  // volume depth source
    const std::uint64_t volumeRevision = volume_.volume() ? volumeRevision_ : 0U;
    const float volumeIso = volumeIso_;

    RenderGraph graph(*impl.cache);
    // Compiles and runs the graph as built so far and keeps what it did.
    const auto runGraph = [&] {
        graph.compile();
        graph.execute(impl.observer.get());
        passes_ = graph.passes();
        graphText_ = graph.toText();
    };
    Handle<Texture> output = graph.importResource(
        "output",
        Texture(targetDescriptor,
                std::make_shared<GlTexture>(targetDescriptor, target.framebuffer)),
        ImportOptions{.target = true, .revision = 0});

    // 1. Geometry: the G-buffer.
    struct Geometry {
        Handle<Texture> linearDepth;
        Handle<Texture> normal;
        Handle<Texture> objectId;
        Handle<Texture> parameter;
        Handle<Texture> depth;
    };
    // The G-buffer's parameter values change with the arrays shown and the opaque meshes.
    const std::uint64_t arrayKey = meshes.style().geometryKey();
    const Geometry& geometry = graph.addPass<Geometry>(
        "geometry",
        [&](RenderGraph::Builder& b, Geometry& d) {
            b.dependsOn("view", view);
            b.dependsOn("projection", projection);
            b.dependsOn("viewport", viewport);
            b.dependsOn("scene", sceneRevision);
            b.dependsOn("array", arrayKey);
            b.dependsOn("volume", volumeRevision);  // volume depth source
            b.dependsOn("iso", volumeIso);
            d.linearDepth =
                b.write(b.createPersistent<Texture>("linear-depth", size(TextureFormat::R32F)));
            d.normal = b.write(b.createPersistent<Texture>("normal", size(TextureFormat::RGBA16F)));
            d.objectId =
                b.write(b.createPersistent<Texture>("object-id", size(TextureFormat::R32UI)));
            d.parameter =
                b.write(b.createPersistent<Texture>("parameter", size(TextureFormat::R32F)));
            d.depth = b.write(b.createPersistent<Texture>("depth", size(TextureFormat::Depth32F)));
        },
        [&impl, &meshes, &volumeRenderer, volumeIso, camera, meshLevel, w, h](
            const RenderGraph::Resources& r, const Geometry& d) {
            auto& g = impl.f();
            g.glBindFramebuffer(GL_FRAMEBUFFER, impl.geometryFbo);
            g.glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D,
                                     glTex(r.get(d.linearDepth)).texture(), 0);
            g.glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D,
                                     glTex(r.get(d.normal)).texture(), 0);
            g.glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT2, GL_TEXTURE_2D,
                                     glTex(r.get(d.objectId)).texture(), 0);
            g.glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT3, GL_TEXTURE_2D,
                                     glTex(r.get(d.parameter)).texture(), 0);
            g.glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D,
                                     glTex(r.get(d.depth)).texture(), 0);
            const GLenum buffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1,
                                      GL_COLOR_ATTACHMENT2, GL_COLOR_ATTACHMENT3};
            g.glDrawBuffers(4, buffers);
            if (g.glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
                throw RenderError("the G-buffer framebuffer is incomplete");
            }
            g.glViewport(0, 0, w, h);
            g.glDepthMask(GL_TRUE);
            const float far[4] = {std::numeric_limits<float>::infinity(), 0.0F, 0.0F, 0.0F};
            const float zero[4] = {0.0F, 0.0F, 0.0F, 0.0F};
            const GLuint noObject[4] = {0U, 0U, 0U, 0U};
            const float one = 1.0F;
            g.glClearBufferfv(GL_COLOR, 0, far);
            g.glClearBufferfv(GL_COLOR, 1, zero);
            const float noData[4] = {std::numeric_limits<float>::quiet_NaN(), 0.0F, 0.0F, 0.0F};
            g.glClearBufferuiv(GL_COLOR, 2, noObject);
            g.glClearBufferfv(GL_COLOR, 3, noData);
            g.glClearBufferfv(GL_DEPTH, 0, &one);
            meshes.drawGBuffer(camera, meshLevel);
            // Volume depth source: after the meshes, depth-tested against them.
            const auto& scene = meshes.scene();
            volumeRenderer.drawGBuffer(
                camera, volumeIso, static_cast<unsigned>(scene ? scene->meshes.size() : 0U) + 1U);
            checkGlError(g, "geometry pass");
        });

    if (mode == GraphMode::DepthOnly) {
        // renderDepth(): the G-buffer's linear depth read back, nothing shaded.
        struct DepthReadback {
            Handle<Texture> depth;
        };
        graph.addPass<DepthReadback>(
            "depth-readback",
            [&](RenderGraph::Builder& b, DepthReadback& d) {
                b.sideEffect();
                d.depth = b.read(geometry.linearDepth);
            },
            [&impl](const RenderGraph::Resources& r, const DepthReadback& d) {
                impl.depthReadback = impl.readDepth(glTex(r.get(d.depth)));
            });
        runGraph();
        gl.glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer);
        return;
    }

    // 3. VSS solve.
    struct Solve {
        Handle<Texture> depth;
        Handle<SolvedFrameRef> solved;
        Handle<Texture> height;
        Handle<Texture> slope;
    };
    const bool async = mode_ == SolveMode::Asynchronous && impl.worker != nullptr;
    Handle<SolvedFrameRef> solvedImport;
    if (async) {
        auto [latest, revision] = impl.worker->latest();
        solvedImport = graph.importResource("vss-result", SolvedFrameRef{std::move(latest)},
                                            ImportOptions{.target = false, .revision = revision});
    }
    const vss::SolverOptions solverOptions = effectiveSolverOptions(vssSettings);
    const bool preview = vssSettings.preview;
    const vss::DepthRange depthRange = vssSettings.range;
    const SolverKey key = solverKey(solverOptions, depthRange);
    const std::uint64_t depthView = viewKey(view, projection, viewport, sceneRevision);
    const std::uint64_t request = requestKey(depthView, key, preview);
    VssFrameStatus& status = impl.solveStatus;
    // Tiled rendering: the frame's VSS comes from outside (setExternalVss).
    const std::shared_ptr<const SolvedFrame> external = impl.external;
    const std::uint64_t externalVersion = impl.externalVersion;
    if (external && vssSettings.enabled && external->height.width() != 0 &&
        (external->height.width() != w || external->height.height() != h)) {
        throw InvalidArgumentError(
            "the external VSS is " + std::to_string(external->height.width()) + "x" +
            std::to_string(external->height.height()) + ", the frame renders at " +
            std::to_string(w) + "x" + std::to_string(h));
    }
    // The slopes the solver's thread fits for the lighting: at the render
    // size up to kMaxCpuSlopePixels, else (and for an external VSS, which
    // brings none) a stand-in texel, and the shader fits them itself.
    const bool cpuSlopes = !external && static_cast<long long>(w) * h <= kMaxCpuSlopePixels;
    // Scene units per pixel per unit of depth (slopes' normals, shading, AO).
    const float pixelScale = pixelScaleOf(camera, h);
    const Solve& solve = graph.addPass<Solve>(
        "vss-solve",
        [&](RenderGraph::Builder& b, Solve& d) {
            b.dependsOn("solver", key);
            b.dependsOn("preview", preview);
            b.dependsOn("external", externalVersion);
            d.depth = b.read(geometry.linearDepth);
            if (async) {
                d.solved = b.read(solvedImport);
            }
            d.height =
                b.write(b.createPersistent<Texture>("vss-height", size(TextureFormat::R32F)));
            d.slope = b.write(b.createPersistent<Texture>(
                "vss-slope", cpuSlopes ? size(TextureFormat::RGBA32F)
                                       : TextureDescriptor{1, 1, TextureFormat::RGBA32F, 1}));
        },
        [&impl, &status, async, request, depthView, solverOptions, preview, depthRange, external,
         pixelScale](const RenderGraph::Resources& r, const Solve& d) {
            status = VssFrameStatus{};
            const GlTexture& heightTexture = glTex(r.get(d.height));
            const GlTexture& slopeTexture = glTex(r.get(d.slope));
            const auto upload = [&](const std::shared_ptr<const SolvedFrame>& frame) {
                impl.uploadHeight(heightTexture, frame);
                if (preview) {
                    impl.shownSlopes = false;  // quick normals: the slopes are not read
                } else {
                    impl.uploadSlopes(slopeTexture);
                }
            };
            const GlTexture& depthTexture = glTex(r.get(d.depth));
            if (external) {
                upload(external);
                status.solveMilliseconds = external->milliseconds;
                status.current = true;
                return;
            }
            if (!async) {
                impl.lastDepth = impl.readDepth(depthTexture);
                impl.lastDepthView = depthView;
                const auto frame = std::make_shared<const SolvedFrame>(solveFrame(
                    request, impl.lastDepth, solverOptions, preview, depthRange, pixelScale, {}));
                upload(frame);
                status.solveMilliseconds = frame->milliseconds;
                status.current = true;
                return;
            }
            const auto& latest = r.get(d.solved).frame;
            if (latest && latest->key == request) {
                upload(latest);
                status.solveMilliseconds = latest->milliseconds;
                status.current = true;
                return;
            }
            if (!impl.worker->requested(request)) {
                impl.lastDepth = impl.readDepth(depthTexture);
                impl.lastDepthView = depthView;
                impl.worker->submit(SolveWorker::Job{request, impl.lastDepth, solverOptions,
                                                     preview, depthRange, pixelScale});
            }
            status.pending = true;
            upload(latest);  // the previous VSS, or none
            status.solveMilliseconds = latest ? latest->milliseconds : 0.0;
        });

    // 2. Vessel shading: deferred, from the G-buffer (one shaded sample per pixel).
    // Declared after the solve: a vessel cue normalises depth with the VSS's
    // dmin / dmax when a VSS is shown, else with the visible vessels' range,
    // which the "depth-range" pass reads back (cached while the view stays).
    const VesselCueSettings cueSettings = settings.cue;
    const bool cueUsesDepth = cueSettings.cue != VesselCue::None;
    const bool cueUsesVss = cueUsesDepth && vssSettings.enabled;
    struct DepthRange {
        Handle<Texture> depth;
        Handle<Texture> range;
    };
    Handle<Texture> visibleRange;
    if (cueUsesDepth) {
        visibleRange =
            graph
                .addPass<DepthRange>(
                    "depth-range",
                    [&](RenderGraph::Builder& b, DepthRange& d) {
                        b.dependsOn("external", externalVersion);
                        d.depth = b.read(geometry.linearDepth);
                        d.range = b.write(b.createPersistent<Texture>(
                            "depth-range", TextureDescriptor{1, 1, TextureFormat::RG32F, 1}));
                    },
                    [&impl, external](const RenderGraph::Resources& r, const DepthRange& d) {
                        double lo = std::numeric_limits<double>::infinity();
                        double hi = -std::numeric_limits<double>::infinity();
                        if (external) {
                            // Tiled rendering: the whole frame's range, not this part's.
                            if (impl.externalVisible) {
                                lo = impl.externalVisible->first;
                                hi = impl.externalVisible->second;
                            }
                        } else {
                            const Image<float> depth = impl.readDepth(glTex(r.get(d.depth)));
                            for (int y = 0; y < depth.height(); ++y) {
                                const float* row = depth.row(y);
                                for (int x = 0; x < depth.width(); ++x) {
                                    if (std::isfinite(row[x])) {
                                        lo = std::min(lo, static_cast<double>(row[x]));
                                        hi = std::max(hi, static_cast<double>(row[x]));
                                    }
                                }
                            }
                        }
                        impl.visibleRange = lo <= hi;
                        impl.visibleDmin = impl.visibleRange ? lo : 0.0;
                        impl.visibleDmax = impl.visibleRange ? hi : 0.0;
                        // Kept on the GPU too (dmin, dmax), for passes that want it there.
                        auto& g = impl.f();
                        const float texel[2] = {static_cast<float>(impl.visibleDmin),
                                                static_cast<float>(impl.visibleDmax)};
                        g.glBindTexture(GL_TEXTURE_2D, glTex(r.get(d.range)).texture());
                        g.glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RG, GL_FLOAT, texel);
                        g.glBindTexture(GL_TEXTURE_2D, 0);
                        checkGlError(g, "depth range pass");
                    })
                .range;
    }
    struct CueKey {
        std::int32_t cue = 0;
        float fogStrength = 0.0F;
        float fresnelExponent = 0.0F;
        glm::vec3 background{0.0F};
    };
    CueKey cueKey;
    cueKey.cue = static_cast<std::int32_t>(cueSettings.cue);
    cueKey.fogStrength = cueSettings.fogStrength;
    cueKey.fresnelExponent = cueSettings.fresnelExponent;
    cueKey.background = settings.background;
    struct VesselShading {
        Handle<Texture> linearDepth;
        Handle<Texture> normal;
        Handle<Texture> objectId;
        Handle<Texture> parameter;
        Handle<Texture> range;
        Handle<Texture> height;
        Handle<Texture> color;
    };
    std::optional<std::pair<double, double>>& cueRange = impl.cueRange;
    const glm::vec3 fogColor = settings.background;
    // The viewer's vessel colours are kept across frames: prepareSolve()
    // shades them while the solve runs, and the frame that shows the solve
    // reuses them. Elsewhere (exports, the CLI) their storage is pooled.
    const bool keepVesselColor = async;
    const VesselShading& vessels = graph.addPass<VesselShading>(
        "vessel-shading",
        [&](RenderGraph::Builder& b, VesselShading& d) {
            b.dependsOn("cue", cueKey);
            b.dependsOn("shading", meshes.shadingRevision());  // style, light, scene
            d.linearDepth = b.read(geometry.linearDepth);
            d.normal = b.read(geometry.normal);
            d.objectId = b.read(geometry.objectId);
            d.parameter = b.read(geometry.parameter);
            if (cueUsesDepth) {
                d.range = b.read(visibleRange);
            }
            if (cueUsesVss) {
                d.height = b.read(solve.height);
            }
            d.color = b.write(
                keepVesselColor
                    ? b.createPersistent<Texture>("vessel-color", size(TextureFormat::RGBA8))
                    : b.create<Texture>("vessel-color", size(TextureFormat::RGBA8)));
        },
        [&impl, &meshes, &cueRange, camera, cueSettings, cueUsesDepth, cueUsesVss, fogColor, w, h](
            const RenderGraph::Resources& r, const VesselShading& d) {
            auto& g = impl.f();
            // Set here, not while building the graph: a frame that reuses
            // these colours keeps the range they were shaded with.
            cueRange.reset();
            VesselCueParameters cue;
            cue.cue = cueSettings.cue;
            cue.fogColor = fogColor;
            cue.fogStrength = cueSettings.fogStrength;
            cue.fresnelExponent = cueSettings.fresnelExponent;
            if (cueUsesDepth) {
                // The VSS's range when one is shown, else the visible range.
                const bool fromVss = cueUsesVss && impl.shown;
                const double lo = fromVss ? impl.dmin : impl.visibleDmin;
                const double hi = fromVss ? impl.dmax : impl.visibleDmax;
                cue.dmin = static_cast<float>(lo);
                cue.dmax = static_cast<float>(hi);
                cueRange = std::make_pair(lo, hi);
            }
            g.glBindFramebuffer(GL_FRAMEBUFFER, impl.shadingFbo);
            g.glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D,
                                     glTex(r.get(d.color)).texture(), 0);
            const GLenum buffers[] = {GL_COLOR_ATTACHMENT0};
            g.glDrawBuffers(1, buffers);
            if (g.glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
                throw RenderError("the vessel shading framebuffer is incomplete");
            }
            g.glViewport(0, 0, w, h);
            impl.shadedCue = cue;
            meshes.shadeGBuffer(
                camera,
                MeshRenderer::GBufferTextures{.linearDepth = glTex(r.get(d.linearDepth)).texture(),
                                              .normal = glTex(r.get(d.normal)).texture(),
                                              .parameter = glTex(r.get(d.parameter)).texture(),
                                              .objectId = glTex(r.get(d.objectId)).texture()},
                cue);
            checkGlError(g, "vessel shading pass");
        });

    if (mode == GraphMode::SolveOnly) {
        // prepareSolve(): the G-buffer and the solve's submission, and the
        // vessels' shading when it does not read the VSS (its colours are
        // then reused by the frame that shows the solve).
        graph.markTarget(solve.height);
        if (keepVesselColor && !cueUsesVss) {
            graph.markTarget(vessels.color);
        }
        runGraph();
        gl.glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer);
        return;
    }

    // 4. VSS shading.
    struct VssShading {
        Handle<Texture> height;
        Handle<Texture> slope;
        Handle<Texture> linearDepth;
        Handle<Texture> color;
    };
    // Where the view axis meets the frame, in pixels from its centre: 0
    // except for off-axis tiles (P[2][0], P[2][1] are the NDC shift).
    const glm::vec2 axisOffset(-0.5F * projection[2][0] * static_cast<float>(w),
                               -0.5F * projection[2][1] * static_cast<float>(h));
    const Lighting vssLight = lightingFor(meshes.style().light);  // the vessels' key light
    const VssShading& vssShading = graph.addPass<VssShading>(
        "vss-shading",
        [&](RenderGraph::Builder& b, VssShading& d) {
            d.height = b.read(solve.height);
            d.slope = b.read(solve.slope);
            d.linearDepth = b.read(geometry.linearDepth);
            d.color = b.write(b.create<Texture>("vss-color", size(TextureFormat::RGBA8)));
        },
        [&impl, vssSettings, vssLight, pixelScale, w, h](const RenderGraph::Resources& r,
                                                         const VssShading& d) {
            auto& g = impl.f();
            impl.uploadScale(vssSettings.scale);
            const GlTexture& out = glTex(r.get(d.color));
            g.glBindFramebuffer(GL_FRAMEBUFFER, out.framebuffer());
            g.glViewport(0, 0, w, h);
            g.glDisable(GL_DEPTH_TEST);
            g.glDisable(GL_BLEND);
            const float clear[4] = {0.0F, 0.0F, 0.0F, 0.0F};
            g.glClearBufferfv(GL_COLOR, 0, clear);
            if (!impl.shown) {
                return;
            }
            // Preview frames (camera moving): one-pixel differences, no fit;
            // exact ones: the slopes the solver's thread fitted, or (none, e.g.
            // an external VSS or a huge frame) the shader fits them itself.
            const bool slopes = !vssSettings.preview && impl.shownSlopes;
            const GLuint program = vssSettings.preview ? impl.vssQuickProgram
                                   : slopes            ? impl.vssSlopeProgram
                                                       : impl.vssProgram;
            const auto loc = [&](const char* name) {
                return g.glGetUniformLocation(program, name);
            };
            const Lighting& light = vssLight;
            g.glUseProgram(program);
            g.glActiveTexture(GL_TEXTURE0);
            g.glBindTexture(GL_TEXTURE_2D, glTex(r.get(d.height)).texture());
            g.glActiveTexture(GL_TEXTURE1);
            g.glBindTexture(GL_TEXTURE_1D, impl.scaleLut);
            g.glActiveTexture(GL_TEXTURE2);
            g.glBindTexture(GL_TEXTURE_2D, glTex(r.get(d.linearDepth)).texture());
            g.glUniform1i(loc("uHeight"), 0);
            g.glUniform1i(loc("uScale"), 1);
            g.glUniform1i(loc("uLinearDepth"), 2);
            if (slopes) {
                g.glActiveTexture(GL_TEXTURE3);
                g.glBindTexture(GL_TEXTURE_2D, glTex(r.get(d.slope)).texture());
                g.glUniform1i(loc("uSlope"), 3);
            }
            g.glUniform1f(loc("uScaleSize"), static_cast<float>(kScaleLutSize));
            g.glUniform1f(loc("uDmin"), static_cast<float>(impl.dmin));
            g.glUniform1f(loc("uDmax"), static_cast<float>(impl.dmax));
            g.glUniform1f(loc("uPixelScale"), pixelScale);
            g.glUniform1i(loc("uIsoLines"), std::max(vssSettings.isoLines, 0));
            g.glUniform1f(loc("uIsoWidth"), std::max(vssSettings.isoLineWidth, 0.0F));
            g.glUniform1f(loc("uIsoStrength"), vssSettings.isoLineStrength);
            g.glUniform1f(loc("uLighting"), vssSettings.lighting);
            g.glUniform1f(loc("uOpacity"), vssSettings.opacity);
            g.glUniform3f(loc("uLightDirection"), light.direction.x, light.direction.y,
                          light.direction.z);
            g.glUniform1f(loc("uAmbient"), light.ambient);
            g.glUniform1f(loc("uDiffuse"), light.diffuse);
            g.glUniform1f(loc("uSpecular"), light.specular);
            g.glUniform1f(loc("uShininess"), light.shininess);
            drawFullscreenAndUnbind(g, impl.emptyVao, 3);
            checkGlError(g, "VSS shading pass");
        });

    const bool useVss = vssSettings.enabled;

    // Translucent objects (opacity < 1, not in the G-buffer): drawn forward,
    // back to front, over a copy of the opaque depth into a premultiplied
    // layer that the composite lays over the frame. Declared always; with no
    // translucent object nothing reads it and the graph culls it.
    struct Translucent {
        Handle<Texture> opaqueDepth;
        Handle<Texture> vessels;  // only to run after vessel-shading (its cue range)
        Handle<Texture> depth;
        Handle<Texture> layer;
    };
    const bool useTranslucent = meshes.hasTranslucent();
    const Translucent& translucent = graph.addPass<Translucent>(
        "translucent",
        [&](RenderGraph::Builder& b, Translucent& d) {
            d.opaqueDepth = b.read(geometry.depth);
            d.vessels = b.read(vessels.color);
            d.depth =
                b.write(b.create<Texture>("translucent-depth", size(TextureFormat::Depth32F)));
            d.layer = b.write(b.create<Texture>("translucent-color", size(TextureFormat::RGBA16F)));
        },
        [&impl, &meshes, camera, meshLevel, w, h](const RenderGraph::Resources& r,
                                                  const Translucent& d) {
            auto& g = impl.f();
            g.glBindFramebuffer(GL_FRAMEBUFFER, impl.shadingFbo);
            g.glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D,
                                     glTex(r.get(d.layer)).texture(), 0);
            g.glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D,
                                     glTex(r.get(d.depth)).texture(), 0);
            const GLenum buffers[] = {GL_COLOR_ATTACHMENT0};
            g.glDrawBuffers(1, buffers);
            if (g.glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
                throw RenderError("the translucent framebuffer is incomplete");
            }
            g.glBindFramebuffer(GL_READ_FRAMEBUFFER, glTex(r.get(d.opaqueDepth)).framebuffer());
            g.glBlitFramebuffer(0, 0, w, h, 0, 0, w, h, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
            g.glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
            g.glViewport(0, 0, w, h);
            const float clear[4] = {0.0F, 0.0F, 0.0F, 0.0F};
            g.glClearBufferfv(GL_COLOR, 0, clear);
            meshes.drawTranslucent(camera, impl.shadedCue, meshLevel);
            // shadingFbo is shared with vessel-shading, which has no depth.
            g.glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, 0, 0);
            checkGlError(g, "translucent pass");
        });

    // 6. Ambient occlusion over vessels + VSS, then a depth-aware blur. Both
    // outputs persist, so a new colour scale or AO strength reuses them.
    // Declared always; with AO off nothing reads them and the graph culls them.
    const AoSettings aoSettings = settings.ao;
    const bool useAo = aoSettings.enabled && aoSettings.strength > 0.0F;
    struct Ssao {
        Handle<Texture> linearDepth;
        Handle<Texture> normal;
        Handle<Texture> height;
        Handle<Texture> raw;
    };
    struct AoBlur {
        Handle<Texture> raw;
        Handle<Texture> ao;
    };
    Handle<Texture> aoTexture;
    {
        const float aoRadius = std::max(aoSettings.radius, 1e-6F);
        const Ssao& ssao = graph.addPass<Ssao>(
            "ssao",
            [&](RenderGraph::Builder& b, Ssao& d) {
                b.dependsOn("radius", aoRadius);
                b.dependsOn("pixel-scale", pixelScale);
                b.dependsOn("axis-offset", axisOffset);
                d.linearDepth = b.read(geometry.linearDepth);
                d.normal = b.read(geometry.normal);
                if (useVss) {
                    d.height = b.read(solve.height);
                }
                d.raw = b.write(b.createPersistent<Texture>("ao-raw", size(TextureFormat::RG32F)));
            },
            [&impl, useVss, aoRadius, pixelScale, axisOffset, w, h](const RenderGraph::Resources& r,
                                                                    const Ssao& d) {
                auto& g = impl.f();
                g.glBindFramebuffer(GL_FRAMEBUFFER, glTex(r.get(d.raw)).framebuffer());
                g.glViewport(0, 0, w, h);
                g.glDisable(GL_DEPTH_TEST);
                g.glDisable(GL_BLEND);
                const GLuint program = impl.ssaoProgram;
                const auto loc = [&](const char* name) {
                    return g.glGetUniformLocation(program, name);
                };
                const bool withVss = useVss && impl.shown;
                g.glUseProgram(program);
                g.glActiveTexture(GL_TEXTURE0);
                g.glBindTexture(GL_TEXTURE_2D, glTex(r.get(d.linearDepth)).texture());
                g.glActiveTexture(GL_TEXTURE1);
                g.glBindTexture(GL_TEXTURE_2D, glTex(r.get(d.normal)).texture());
                g.glActiveTexture(GL_TEXTURE2);
                g.glBindTexture(GL_TEXTURE_2D, withVss ? glTex(r.get(d.height)).texture() : 0U);
                g.glUniform1i(loc("uLinearDepth"), 0);
                g.glUniform1i(loc("uNormal"), 1);
                g.glUniform1i(loc("uHeight"), 2);
                g.glUniform1i(loc("uUseVss"), withVss ? 1 : 0);
                g.glUniform1f(loc("uDmin"), static_cast<float>(impl.dmin));
                g.glUniform1f(loc("uDmax"), static_cast<float>(impl.dmax));
                g.glUniform1f(loc("uPixelScale"), pixelScale);
                g.glUniform2f(loc("uAxisOffset"), axisOffset.x, axisOffset.y);
                g.glUniform1f(loc("uRadius"), aoRadius);
                g.glUniform1i(loc("uSamples"), 12);
                drawFullscreenAndUnbind(g, impl.emptyVao, 3);
                checkGlError(g, "SSAO pass");
            });
        aoTexture =
            graph
                .addPass<AoBlur>(
                    "ao-blur",
                    [&](RenderGraph::Builder& b, AoBlur& d) {
                        d.raw = b.read(ssao.raw);
                        d.ao = b.write(b.createPersistent<Texture>("ao", size(TextureFormat::R8)));
                    },
                    [&impl, w, h](const RenderGraph::Resources& r, const AoBlur& d) {
                        auto& g = impl.f();
                        g.glBindFramebuffer(GL_FRAMEBUFFER, glTex(r.get(d.ao)).framebuffer());
                        g.glViewport(0, 0, w, h);
                        g.glDisable(GL_DEPTH_TEST);
                        g.glDisable(GL_BLEND);
                        const GLuint program = impl.aoBlurProgram;
                        g.glUseProgram(program);
                        g.glActiveTexture(GL_TEXTURE0);
                        g.glBindTexture(GL_TEXTURE_2D, glTex(r.get(d.raw)).texture());
                        g.glUniform1i(g.glGetUniformLocation(program, "uAo"), 0);
                        drawFullscreenAndUnbind(g, impl.emptyVao, 1);
                        checkGlError(g, "AO blur pass");
                    })
                .ao;
    }

    // 5. Composite into the target, or into a texture for the FXAA pass.
    struct Composite {
        Handle<Texture> vessels;
        Handle<Texture> vss;
        Handle<Texture> ao;
        Handle<Texture> translucent;
        Handle<Texture> output;
    };
    // With anti-aliasing the FXAA pass draws into the target (upscaling a
    // reduced render size with its bilinear taps); without it, a reduced
    // render size ends with a bilinear blit into the target ("upscale").
    const bool useFxaa = settings.antialiasing;
    const bool useAa = useFxaa || scaled;
    const float aoStrength = aoSettings.strength;
    const glm::vec3 background = settings.background;
    const Composite& composite = graph.addPass<Composite>(
        "composite",
        [&](RenderGraph::Builder& b, Composite& d) {
            d.vessels = b.read(vessels.color);
            if (useVss) {
                d.vss = b.read(vssShading.color);
            }
            if (useAo) {
                d.ao = b.read(aoTexture);
            }
            if (useTranslucent) {
                d.translucent = b.read(translucent.layer);
            }
            d.output = b.write(useAa ? b.create<Texture>("composited", size(TextureFormat::RGBA8))
                                     : output);
        },
        [&impl, useVss, useAo, useTranslucent, aoStrength, background, w, h](
            const RenderGraph::Resources& r, const Composite& d) {
            auto& g = impl.f();
            const GlTexture& out = glTex(r.get(d.output));
            g.glBindFramebuffer(GL_FRAMEBUFFER, out.framebuffer());
            g.glViewport(0, 0, w, h);
            g.glDisable(GL_DEPTH_TEST);
            g.glDisable(GL_BLEND);
            const GLuint program = impl.compositeProgram;
            const auto loc = [&](const char* name) {
                return g.glGetUniformLocation(program, name);
            };
            g.glUseProgram(program);
            g.glActiveTexture(GL_TEXTURE0);
            g.glBindTexture(GL_TEXTURE_2D, glTex(r.get(d.vessels)).texture());
            g.glActiveTexture(GL_TEXTURE1);
            g.glBindTexture(GL_TEXTURE_2D, useVss ? glTex(r.get(d.vss)).texture() : 0U);
            g.glUniform1i(loc("uVessels"), 0);
            g.glUniform1i(loc("uVss"), 1);
            g.glUniform1i(loc("uUseVss"), useVss ? 1 : 0);
            g.glActiveTexture(GL_TEXTURE2);
            g.glBindTexture(GL_TEXTURE_2D, useAo ? glTex(r.get(d.ao)).texture() : 0U);
            g.glUniform1i(loc("uAo"), 2);
            g.glUniform1i(loc("uUseAo"), useAo ? 1 : 0);
            g.glUniform1f(loc("uAoStrength"), aoStrength);
            g.glUniform3f(loc("uBackground"), background.r, background.g, background.b);
            g.glActiveTexture(GL_TEXTURE3);
            g.glBindTexture(GL_TEXTURE_2D,
                            useTranslucent ? glTex(r.get(d.translucent)).texture() : 0U);
            g.glUniform1i(loc("uTranslucent"), 3);
            g.glUniform1i(loc("uUseTranslucent"), useTranslucent ? 1 : 0);
            drawFullscreenAndUnbind(g, impl.emptyVao, 4);
            g.glEnable(GL_DEPTH_TEST);
            checkGlError(g, "composite pass");
        });

    // 7. FXAA of the composited frame into the target.
    struct Fxaa {
        Handle<Texture> input;
        Handle<Texture> output;
    };
    if (useAa && !useFxaa) {
        // A bilinear blit: far cheaper than a shader pass at the target size
        // on software rasterisers, for frames that favour speed (moving).
        graph.addPass<Fxaa>(
            "upscale",
            [&](RenderGraph::Builder& b, Fxaa& d) {
                d.input = b.read(composite.output);
                d.output = b.write(output);
            },
            [&impl, w, h, targetW, targetH](const RenderGraph::Resources& r, const Fxaa& d) {
                auto& g = impl.f();
                g.glBindFramebuffer(GL_READ_FRAMEBUFFER, glTex(r.get(d.input)).framebuffer());
                g.glBindFramebuffer(GL_DRAW_FRAMEBUFFER, glTex(r.get(d.output)).framebuffer());
                g.glBlitFramebuffer(0, 0, w, h, 0, 0, targetW, targetH, GL_COLOR_BUFFER_BIT,
                                    GL_LINEAR);
                g.glBindFramebuffer(GL_FRAMEBUFFER, glTex(r.get(d.output)).framebuffer());
                checkGlError(g, "upscale pass");
            });
    } else if (useAa) {
        graph.addPass<Fxaa>(
            "fxaa",
            [&](RenderGraph::Builder& b, Fxaa& d) {
                d.input = b.read(composite.output);
                d.output = b.write(output);
            },
            [&impl, targetW, targetH](const RenderGraph::Resources& r, const Fxaa& d) {
                auto& g = impl.f();
                g.glBindFramebuffer(GL_FRAMEBUFFER, glTex(r.get(d.output)).framebuffer());
                g.glViewport(0, 0, targetW, targetH);
                g.glDisable(GL_DEPTH_TEST);
                g.glDisable(GL_BLEND);
                const GLuint program = impl.fxaaProgram;
                g.glUseProgram(program);
                g.glActiveTexture(GL_TEXTURE0);
                // Bilinear taps here only; pooled textures are nearest otherwise.
                g.glBindTexture(GL_TEXTURE_2D, glTex(r.get(d.input)).texture());
                g.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
                g.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
                g.glUniform1i(g.glGetUniformLocation(program, "uColor"), 0);
                g.glUniform2f(g.glGetUniformLocation(program, "uTexel"),
                              1.0F / static_cast<float>(targetW),
                              1.0F / static_cast<float>(targetH));
                g.glBindVertexArray(impl.emptyVao);
                g.glDrawArrays(GL_TRIANGLES, 0, 3);
                g.glBindVertexArray(0);
                g.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
                g.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
                g.glBindTexture(GL_TEXTURE_2D, 0);
                g.glUseProgram(0);
                g.glEnable(GL_DEPTH_TEST);
                checkGlError(g, "FXAA pass");
            });
    }

    runGraph();
    cueRange_ = impl.cueRange;
    gl.glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer);
    gl.glViewport(0, 0, targetW, targetH);

    if (!vssSettings.enabled) {
        status_ = VssFrameStatus{};
        return;
    }
    // A cached solve pass keeps what it showed last.
    status_ = impl.solveStatus;
    status_.shown = impl.shown;
    status_.dmin = impl.dmin;
    status_.dmax = impl.dmax;
    status_.preview = impl.shownFrame != nullptr && impl.shownFrame->preview;
    status_.errorBound = impl.shownFrame != nullptr ? impl.shownFrame->errorBound
                                                    : std::numeric_limits<double>::quiet_NaN();
}

// --- Probe (G-buffer read-back of single pixels) ---------------------------

namespace {

/// Restores the read framebuffer binding when it goes out of scope.
class ReadFramebufferGuard {
  public:
    explicit ReadFramebufferGuard(QOpenGLFunctions_4_1_Core& g) : g_(g) {
        GLint bound = 0;
        g_.glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &bound);
        previous_ = static_cast<GLuint>(bound);
        GLint buffer = 0;
        g_.glGetIntegerv(GL_READ_BUFFER, &buffer);
        previousBuffer_ = static_cast<GLenum>(buffer);
    }
    ~ReadFramebufferGuard() {
        g_.glBindFramebuffer(GL_READ_FRAMEBUFFER, previous_);
        g_.glReadBuffer(previousBuffer_);
    }
    ReadFramebufferGuard(const ReadFramebufferGuard&) = delete;
    ReadFramebufferGuard& operator=(const ReadFramebufferGuard&) = delete;
    ReadFramebufferGuard(ReadFramebufferGuard&&) = delete;
    ReadFramebufferGuard& operator=(ReadFramebufferGuard&&) = delete;

  private:
    QOpenGLFunctions_4_1_Core& g_;
    GLuint previous_ = 0;
    GLenum previousBuffer_ = GL_BACK;
};

/// True when the G-buffer framebuffer has its attachments (a geometry pass ran).
bool gbufferReadable(QOpenGLFunctions_4_1_Core& g, GLuint fbo) {
    if (fbo == 0) {
        return false;
    }
    g.glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
    GLint type = GL_NONE;
    g.glGetFramebufferAttachmentParameteriv(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                                            GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
    return type == GL_TEXTURE &&
           g.glCheckFramebufferStatus(GL_READ_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
}

}  // namespace

std::optional<ProbeSample> FrameRenderer::probe(const Camera& camera, int x, int y) const {
    if (!initialized() || renderSize_.x < 1 || renderSize_.y < 1 || x < 0 || y < 0 ||
        x >= renderSize_.x || y >= renderSize_.y) {
        return std::nullopt;
    }
    auto& g = impl_->f();
    const ReadFramebufferGuard guard(g);
    if (!gbufferReadable(g, impl_->geometryFbo)) {
        return std::nullopt;
    }
    ProbeSample sample;
    g.glPixelStorei(GL_PACK_ALIGNMENT, 4);
    g.glReadBuffer(GL_COLOR_ATTACHMENT2);
    GLuint id = 0;
    g.glReadPixels(x, y, 1, 1, GL_RED_INTEGER, GL_UNSIGNED_INT, &id);
    g.glReadBuffer(GL_COLOR_ATTACHMENT0);
    g.glReadPixels(x, y, 1, 1, GL_RED, GL_FLOAT, &sample.linearDepth);
    g.glReadBuffer(GL_COLOR_ATTACHMENT3);
    g.glReadPixels(x, y, 1, 1, GL_RED, GL_FLOAT, &sample.value);
    checkGlError(g, "probing the G-buffer");
    if (id == 0 || !std::isfinite(sample.linearDepth) || sample.linearDepth <= 0.0F) {
        return std::nullopt;
    }
    sample.objectId = id;
    // Pixel centre -> NDC -> view space at the linear depth d (z_view = -d).
    const glm::mat4 projection = camera.projectionMatrix();
    const float d = sample.linearDepth;
    const float ndcX =
        (static_cast<float>(x) + 0.5F) / static_cast<float>(renderSize_.x) * 2.0F - 1.0F;
    const float ndcY =
        (static_cast<float>(y) + 0.5F) / static_cast<float>(renderSize_.y) * 2.0F - 1.0F;
    const float zView = -d;
    // clip.x = P[0][0] x + P[2][0] z, clip.w = -z = d (glm: P[column][row]).
    sample.viewPosition =
        glm::vec3((ndcX * d - projection[2][0] * zView) / projection[0][0],
                  (ndcY * d - projection[2][1] * zView) / projection[1][1], zView);
    sample.worldPosition =
        glm::vec3(glm::inverse(camera.viewMatrix()) * glm::vec4(sample.viewPosition, 1.0F));
    return sample;
}

std::optional<std::pair<float, float>> FrameRenderer::visibleDepthRange() const {
    if (!initialized() || renderSize_.x < 1 || renderSize_.y < 1) {
        return std::nullopt;
    }
    auto& g = impl_->f();
    const ReadFramebufferGuard guard(g);
    if (!gbufferReadable(g, impl_->geometryFbo)) {
        return std::nullopt;
    }
    GLint width = 0;
    GLint height = 0;
    // The attachment's own size (the render size of the frame that drew it).
    GLint texture = 0;
    g.glGetFramebufferAttachmentParameteriv(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                                            GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &texture);
    g.glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(texture));
    g.glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &width);
    g.glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT, &height);
    g.glBindTexture(GL_TEXTURE_2D, 0);
    if (width < 1 || height < 1) {
        return std::nullopt;
    }
    std::vector<float> depth(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
    g.glReadBuffer(GL_COLOR_ATTACHMENT0);
    g.glPixelStorei(GL_PACK_ALIGNMENT, 4);
    g.glReadPixels(0, 0, width, height, GL_RED, GL_FLOAT, depth.data());
    checkGlError(g, "reading the visible depth range");
    float lo = std::numeric_limits<float>::infinity();
    float hi = -std::numeric_limits<float>::infinity();
    for (const float v : depth) {
        if (std::isfinite(v)) {
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
    }
    if (lo > hi) {
        return std::nullopt;
    }
    return std::make_pair(lo, hi);
}

// --- end probe -------------------------------------------------------------

}  // namespace vv::render
