// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/render/OffscreenRenderer.h"

#include <QGuiApplication>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFunctions_4_1_Core>
#include <QOpenGLVersionFunctionsFactory>
#include <QSurfaceFormat>
#include <algorithm>
#include <string>

#include "vv/core/Error.h"
#include "vv/render/LegendPainter.h"

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

OffscreenRenderer::OffscreenRenderer() {
    if (QGuiApplication::instance() == nullptr ||
        qobject_cast<QGuiApplication*>(QCoreApplication::instance()) == nullptr) {
        throw RenderError("offscreen rendering needs a QGuiApplication");
    }
    const QSurfaceFormat format = requestedFormat();
    surface_ = std::make_unique<QOffscreenSurface>();
    surface_->setFormat(format);
    surface_->create();
    if (!surface_->isValid()) {
        throw RenderError("no OpenGL 4.1 context: cannot create an offscreen surface (platform '" +
                          QGuiApplication::platformName().toStdString() + "')");
    }
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
    renderer_ = std::make_unique<FrameRenderer>();
    renderer_->initialize();
    description_ = renderer_->meshRenderer().glDescription();
}

OffscreenRenderer::~OffscreenRenderer() {
    if (context_ && surface_ && renderer_ && context_->makeCurrent(surface_.get())) {
        output_.reset();
        renderer_->release();
        context_->doneCurrent();
    }
    renderer_.reset();
    context_.reset();
    surface_.reset();
}

const std::vector<PassInfo>& OffscreenRenderer::lastPasses() const noexcept {
    return renderer_->lastPasses();
}

const std::optional<std::pair<double, double>>& OffscreenRenderer::lastCueDepthRange()
    const noexcept {
    return renderer_->lastCueDepthRange();
}

const VssFrameStatus& OffscreenRenderer::vssStatus() const noexcept {
    return renderer_->vssStatus();
}

Image<float> OffscreenRenderer::lastLinearDepth() const {
    const Image<float>& glOrder = renderer_->lastSolvedDepth();
    Image<float> out(glOrder.width(), glOrder.height());
    for (int y = 0; y < glOrder.height(); ++y) {
        std::copy(glOrder.row(y), glOrder.row(y) + glOrder.width(),
                  out.row(glOrder.height() - 1 - y));
    }
    return out;
}

const std::string& OffscreenRenderer::lastGraphText() const noexcept {
    return renderer_->lastGraphText();
}

std::vector<GlPassTiming> OffscreenRenderer::lastTimings() {
    CurrentContext current(*context_, *surface_);
    return renderer_->lastTimings();
}

QImage OffscreenRenderer::render(const io::Scene& scene, const OffscreenOptions& options) {
    if (options.width < 1 || options.height < 1 || options.width > kMaxSize ||
        options.height > kMaxSize) {
        throw InvalidArgumentError("image size must be within 1..16384 pixels per side, got " +
                                   std::to_string(options.width) + "x" +
                                   std::to_string(options.height));
    }
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

    // The shared pointer does not own the scene: it only lives for this call.
    const std::shared_ptr<const io::Scene> view(std::shared_ptr<const io::Scene>(), &scene);
    MeshRenderer& meshes = renderer_->meshRenderer();
    meshes.setScene(view);
    meshes.setStyle(options.style);
    renderer_->setSceneRevision(sceneFingerprint(scene));
    // Volume depth source: ray cast after the meshes; its box joins the bounds.
    renderer_->setVolume(options.volume, options.isoValue);
    Aabb bounds = scene.bounds();
    if (options.volume && !options.volume->empty()) {
        bounds.extend(options.volume->worldBounds());
    }

    Camera camera = options.camera.value_or(Camera());
    camera.setViewport(options.width, options.height);
    if (!options.camera) {
        camera.fit(bounds);
    } else {
        camera.setSceneBounds(bounds);
    }

    FrameSettings settings;
    settings.background = options.background;
    settings.vss = options.vss;
    settings.cue = options.cue;
    settings.ao = options.ao;
    settings.antialiasing = options.antialiasing;
    try {
        renderer_->render(camera, settings,
                          FrameTarget{output_->framebuffer(), options.width, options.height});
    } catch (...) {
        meshes.setScene(nullptr);
        throw;
    }
    lastRange_ = meshes.effectiveRange();
    meshes.setScene(nullptr);  // free the GPU copies; the scene is not ours to keep

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
    if (options.legends) {
        paintLegends(result, legendsFor(&scene, options.style, lastRange_, settings,
                                        renderer_->vssStatus(), renderer_->lastCueDepthRange()));
    }
    return result;
}

}  // namespace vv::render
