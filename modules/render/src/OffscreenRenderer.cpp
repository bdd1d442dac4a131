// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/render/OffscreenRenderer.h"

#include <QGuiApplication>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFramebufferObject>
#include <QOpenGLFunctions_4_1_Core>
#include <QOpenGLVersionFunctionsFactory>
#include <QSurfaceFormat>
#include <algorithm>
#include <string>

#include "vv/core/Error.h"

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
    renderer_ = std::make_unique<MeshRenderer>();
    renderer_->initialize();
    description_ = renderer_->glDescription();
}

OffscreenRenderer::~OffscreenRenderer() {
    if (context_ && surface_ && renderer_ && context_->makeCurrent(surface_.get())) {
        renderer_->release();
        context_->doneCurrent();
    }
    renderer_.reset();
    context_.reset();
    surface_.reset();
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

    GLint maxSamples = 0;
    gl->glGetIntegerv(GL_MAX_SAMPLES, &maxSamples);
    GLint maxRenderbuffer = 0;
    gl->glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &maxRenderbuffer);
    if (options.width > maxRenderbuffer || options.height > maxRenderbuffer) {
        throw InvalidArgumentError(
            "image size " + std::to_string(options.width) + "x" + std::to_string(options.height) +
            " exceeds this GPU's limit of " + std::to_string(maxRenderbuffer) + " pixels per side");
    }
    const int samples = std::clamp(options.samples, 0, static_cast<int>(maxSamples));
    const QSize size(options.width, options.height);

    QOpenGLFramebufferObjectFormat msFormat;
    msFormat.setAttachment(QOpenGLFramebufferObject::Depth);
    msFormat.setSamples(samples > 1 ? samples : 0);
    msFormat.setInternalTextureFormat(GL_RGBA8);
    QOpenGLFramebufferObject target(size, msFormat);
    if (!target.isValid()) {
        throw RenderError("cannot create a " + std::to_string(options.width) + "x" +
                          std::to_string(options.height) + " framebuffer with " +
                          std::to_string(samples) + " samples");
    }

    // The shared pointer does not own the scene: it only lives for this call.
    const std::shared_ptr<const io::Scene> view(std::shared_ptr<const io::Scene>(), &scene);
    renderer_->setScene(view);
    renderer_->setStyle(options.style);

    Camera camera = options.camera.value_or(Camera());
    camera.setViewport(options.width, options.height);
    if (!options.camera) {
        camera.fit(scene.bounds());
    } else {
        camera.setSceneBounds(scene.bounds());
    }

    target.bind();
    gl->glViewport(0, 0, options.width, options.height);
    gl->glClearColor(options.background.r, options.background.g, options.background.b, 1.0F);
    gl->glClearDepth(1.0);
    gl->glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    try {
        renderer_->draw(camera);
    } catch (...) {
        renderer_->setScene(nullptr);
        target.release();
        throw;
    }
    lastRange_ = renderer_->effectiveRange();
    target.release();

    // Resolve the samples into a plain framebuffer and read it back.
    QOpenGLFramebufferObject resolved(size, QOpenGLFramebufferObject::NoAttachment, GL_TEXTURE_2D,
                                      GL_RGBA8);
    if (!resolved.isValid()) {
        renderer_->setScene(nullptr);
        throw RenderError("cannot create the framebuffer to resolve the image into");
    }
    const QRect rect(QPoint(0, 0), size);
    QOpenGLFramebufferObject::blitFramebuffer(&resolved, rect, &target, rect, GL_COLOR_BUFFER_BIT,
                                              GL_NEAREST);
    QImage image = resolved.toImage();  // flipped to top-left origin
    renderer_->setScene(nullptr);       // free the GPU copies; the scene is not ours to keep
    if (image.isNull()) {
        throw RenderError("cannot read the rendered image back");
    }
    return image.convertToFormat(QImage::Format_RGB32);
}

}  // namespace vv::render
