// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/render/OffscreenRenderer.h"

#include <QGuiApplication>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QOpenGLFunctions_4_1_Core>
#include <QOpenGLVersionFunctionsFactory>
#include <QPainter>
#include <QSurfaceFormat>
#include <algorithm>
#include <string>

#include "vv/core/Error.h"
#include "vv/render/GlResources.h"
#include "vv/render/LegendPainter.h"
#include "vv/render/ViewPresets.h"

namespace vv::render {

namespace {

constexpr int kMaxSize = 16384;

QSurfaceFormat requestedFormat() {
    QSurfaceFormat format;
    format.setRenderableType(QSurfaceFormat::OpenGL);
    format.setVersion(4, 1);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    return format;
}

std::string versionText(const QSurfaceFormat& format, bool es) {
    return std::string(es ? "OpenGL ES " : "OpenGL ") + std::to_string(format.majorVersion()) +
           "." + std::to_string(format.minorVersion()) +
           (format.profile() == QSurfaceFormat::CoreProfile ? " core" : "");
}

/// Makes the context current for a scope and releases it again.
class CurrentContext {
  public:
    CurrentContext(QOpenGLContext& context, QOffscreenSurface& surface) : context_(context) {
        if (!context_.makeCurrent(&surface)) {
            throw RenderError("cannot make the offscreen OpenGL context current");
        }
    }
    ~CurrentContext() { context_.doneCurrent(); }
    CurrentContext(const CurrentContext&) = delete;
    CurrentContext& operator=(const CurrentContext&) = delete;

  private:
    QOpenGLContext& context_;
};

}  // namespace

std::unique_ptr<QOffscreenSurface> OffscreenRenderer::createSurface() {
    if (QGuiApplication::instance() == nullptr ||
        qobject_cast<QGuiApplication*>(QCoreApplication::instance()) == nullptr) {
        throw RenderError("offscreen rendering needs a QGuiApplication");
    }
    auto surface = std::make_unique<QOffscreenSurface>();
    surface->setFormat(requestedFormat());
    surface->create();
    if (!surface->isValid()) {
        throw RenderError("no OpenGL 4.1 context: cannot create an offscreen surface (platform '" +
                          QGuiApplication::platformName().toStdString() + "')");
    }
    return surface;
}

OffscreenRenderer::OffscreenRenderer() : ownSurface_(createSurface()), surface_(ownSurface_.get()) {
    createContext();
}

OffscreenRenderer::OffscreenRenderer(QOffscreenSurface& surface) : surface_(&surface) {
    if (QGuiApplication::instance() == nullptr) {
        throw RenderError("offscreen rendering needs a QGuiApplication");
    }
    createContext();
}

void OffscreenRenderer::createContext() {
    const QSurfaceFormat format = requestedFormat();
    context_ = std::make_unique<QOpenGLContext>();
    context_->setFormat(format);
    if (!context_->create()) {
        throw RenderError("no OpenGL 4.1 core context can be created (platform '" +
                          QGuiApplication::platformName().toStdString() +
                          "'; OpenGL needs a display, e.g. xcb under Xvfb)");
    }
    const QSurfaceFormat got = context_->format();
    if (context_->isOpenGLES() || got.majorVersion() < 4 ||
        (got.majorVersion() == 4 && got.minorVersion() < 1)) {
        throw RenderError("no OpenGL 4.1 core context: the driver gave " +
                          versionText(got, context_->isOpenGLES()));
    }
    CurrentContext current(*context_, *surface_);
    view_ = std::make_unique<ViewRenderer>();
    view_->initialize();
    description_ = view_->meshRenderer().glDescription();
}

OffscreenRenderer::~OffscreenRenderer() {
    if (context_ && surface_ != nullptr && view_ && context_->makeCurrent(surface_)) {
        output_.reset();
        view_->release();
        context_->doneCurrent();
    }
    view_.reset();
    context_.reset();
    ownSurface_.reset();
}

const std::vector<PassInfo>& OffscreenRenderer::lastPasses() const noexcept {
    return view_->frameRenderer().lastPasses();
}

const std::optional<std::pair<double, double>>& OffscreenRenderer::lastCueDepthRange()
    const noexcept {
    return view_->frameRenderer().lastCueDepthRange();
}

const VssFrameStatus& OffscreenRenderer::vssStatus() const noexcept {
    return view_->frameRenderer().vssStatus();
}

namespace {

/// `glOrder` (bottom row first) with row 0 on top, like the image.
Image<float> topRowFirst(const Image<float>& glOrder) {
    Image<float> out(glOrder.width(), glOrder.height());
    for (int y = 0; y < glOrder.height(); ++y) {
        std::copy(glOrder.row(y), glOrder.row(y) + glOrder.width(),
                  out.row(glOrder.height() - 1 - y));
    }
    return out;
}

void checkSize(const OffscreenOptions& options) {
    if (options.width < 1 || options.height < 1 || options.width > kMaxSize ||
        options.height > kMaxSize) {
        throw InvalidArgumentError("image size must be within 1..16384 pixels per side, got " +
                                   std::to_string(options.width) + "x" +
                                   std::to_string(options.height));
    }
}

/// Detaches the caller's scene from the view when a render ends, also by an
/// exception: only its meshes on the GPU stay for the next render.
class SceneAttachment {
  public:
    explicit SceneAttachment(ViewRenderer& view) : view_(view) {}
    ~SceneAttachment() { view_.detachScene(); }
    SceneAttachment(const SceneAttachment&) = delete;
    SceneAttachment& operator=(const SceneAttachment&) = delete;
    SceneAttachment(SceneAttachment&&) = delete;
    SceneAttachment& operator=(SceneAttachment&&) = delete;

  private:
    ViewRenderer& view_;
};

}  // namespace

Image<float> OffscreenRenderer::lastLinearDepth() const {
    return topRowFirst(view_->frameRenderer().lastSolvedDepth());
}

ViewAnnotations viewAnnotations(const DisplaySettings& display, SceneFrame frame) noexcept {
    return {.orientationMarker = display.orientationMarker,
            .scaleBar = display.scaleBar,
            .frame = frame};
}

Camera OffscreenRenderer::cameraFor(const scene::Scene& scene, const OffscreenOptions& options) {
    Aabb bounds = scene.bounds();
    if (options.volume && !options.volume->empty()) {
        bounds.extend(options.volume->worldBounds());
    }
    Camera camera = options.camera.value_or(Camera());
    if (camera.window()) {
        const PixelRect& window = *camera.window();
        if (window.width != options.width || window.height != options.height) {
            throw InvalidArgumentError("the camera's window is " + std::to_string(window.width) +
                                       "x" + std::to_string(window.height) + ", the image " +
                                       std::to_string(options.width) + "x" +
                                       std::to_string(options.height));
        }
    } else {
        camera.setViewport(options.width, options.height);
    }
    if (!options.camera) {
        camera.setHomeRotation(homeRotation(scene.frame));
        camera.setRotation(camera.homeRotation());
        camera.fit(bounds);
    } else {
        camera.setSceneBounds(bounds);
    }
    return camera;
}

Camera OffscreenRenderer::setUpScene(const scene::Scene& scene, const OffscreenOptions& options) {
    const Camera camera = cameraFor(scene, options);
    // The shared pointer does not own the scene: it is attached for this
    // render only (SceneAttachment); the view keeps just its GPU meshes, for
    // the next render of the same content (tiles, report views).
    const std::shared_ptr<const scene::Scene> view(std::shared_ptr<const scene::Scene>(), &scene);
    view_->setScene(view, sceneFingerprint(scene));
    if (view_->uploadScene()) {  // checks the indices before surfaceClosures reads them
        // Once per scene content, not once per render.
        view_->setSurfaceClosures(scene::surfaceClosures(scene));
    }
    if (options.refined && options.refined->scene != view_->refinedGeometry().scene) {
        view_->setRefinedGeometry(*options.refined);
    } else if (!options.refined && view_->refinedGeometry().scene) {
        view_->setRefinedGeometry({});
    }
    view_->setDisplay(options.display);
    // Volume depth source: ray cast after the meshes; its box joins the bounds.
    view_->setVolume(options.volume, options.isoValue);
    return camera;
}

Image<float> OffscreenRenderer::renderDepth(const scene::Scene& scene,
                                            const OffscreenOptions& options) {
    checkSize(options);
    CurrentContext current(*context_, *surface_);
    const SceneAttachment attachment(*view_);
    const Camera camera = setUpScene(scene, options);
    return topRowFirst(view_->renderDepth(camera, FrameTarget{0, options.width, options.height}));
}

void OffscreenRenderer::setExternalVss(std::optional<ExternalVss> external) {
    view_->frameRenderer().setExternalVss(std::move(external));
}

void OffscreenRenderer::clearCache() {
    CurrentContext current(*context_, *surface_);
    output_.reset();
    view_->frameRenderer().clearCache();
}

void OffscreenRenderer::setBackFaceCulling(bool enabled) {
    // The G-buffer is meant to come out the same either way, so no pass
    // depends on the switch: forget the cached ones, so the next render draws.
    clearCache();
    view_->meshRenderer().setBackFaceCulling(enabled);
}

std::uint64_t OffscreenRenderer::sceneUploads() const noexcept {
    return view_->sceneUploads();
}

bool OffscreenRenderer::lastFrameRefined() const noexcept {
    return view_->frameRenderer().lastGeometryLevel() == kRefinedLevel;
}

const scene::Scene& OffscreenRenderer::lastDrawnScene(
    const scene::Scene& scene, const OffscreenOptions& options) const noexcept {
    return lastFrameRefined() && options.refined && options.refined->scene ? *options.refined->scene
                                                                           : scene;
}

std::size_t OffscreenRenderer::lastCulledMeshes() const noexcept {
    return view_->meshRenderer().lastCulledMeshes();
}

const std::string& OffscreenRenderer::lastGraphText() const noexcept {
    return view_->frameRenderer().lastGraphText();
}

std::vector<GlPassTiming> OffscreenRenderer::lastTimings() {
    CurrentContext current(*context_, *surface_);
    return view_->frameRenderer().lastTimings();
}

int OffscreenRenderer::maxRenderSide() {
    CurrentContext current(*context_, *surface_);
    return render::maxRenderSide(*context_->functions());
}

QImage OffscreenRenderer::render(const scene::Scene& scene, const OffscreenOptions& options) {
    checkSize(options);
    CurrentContext current(*context_, *surface_);
    auto* gl = QOpenGLVersionFunctionsFactory::get<QOpenGLFunctions_4_1_Core>(context_.get());
    if (gl == nullptr) {
        throw RenderError("cannot resolve the OpenGL 4.1 core functions");
    }
    GLint maxTexture = 0;
    gl->glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxTexture);
    if (options.width > maxTexture || options.height > maxTexture) {
        throw InvalidArgumentError(
            "image size " + std::to_string(options.width) + "x" + std::to_string(options.height) +
            " exceeds this GPU's limit of " + std::to_string(maxTexture) + " pixels per side");
    }
    const TextureDescriptor descriptor{options.width, options.height, TextureFormat::RGBA8, 1};
    if (!output_ || !(output_->descriptor() == descriptor)) {
        output_.reset();
        output_ = std::make_shared<GlTexture>(*gl, descriptor);
    }

    const SceneAttachment attachment(*view_);
    const Camera camera = setUpScene(scene, options);
    view_->render(camera, FrameTarget{output_->framebuffer(), options.width, options.height});
    lastRange_ = view_->shownRange();
    const Legends legends = options.display.legends ? view_->legends() : Legends{};

    QImage image(options.width, options.height, QImage::Format_RGBA8888);
    if (image.isNull()) {
        throw RenderError("cannot allocate the image to read the frame into");
    }
    gl->glBindFramebuffer(GL_READ_FRAMEBUFFER, output_->framebuffer());
    gl->glReadBuffer(GL_COLOR_ATTACHMENT0);
    gl->glPixelStorei(GL_PACK_ALIGNMENT, 4);
    gl->glPixelStorei(GL_PACK_ROW_LENGTH, static_cast<GLint>(image.bytesPerLine() / 4));
    gl->glReadPixels(0, 0, options.width, options.height, GL_RGBA, GL_UNSIGNED_BYTE, image.bits());
    gl->glPixelStorei(GL_PACK_ROW_LENGTH, 0);
    gl->glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    checkGlError(*gl, "reading the rendered image back");
    // GL rows start at the bottom.
    QImage result = image.mirrored(false, true).convertToFormat(QImage::Format_RGB32);
    if (options.display.legends) {
        paintLegends(result, legends);
    }
    // A tile (a camera window) is part of a larger image: that one has them.
    if ((options.display.orientationMarker || options.display.scaleBar) && !camera.window()) {
        QPainter painter(&result);
        paintViewAnnotations(painter, QRectF(result.rect()), camera,
                             viewAnnotations(options.display, scene.frame));
    }
    return result;
}

}  // namespace vv::render
