// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/render/GlResources.h"

#include <QFile>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QOpenGLFunctions_4_1_Core>
#include <QOpenGLVersionFunctionsFactory>
#include <QSurfaceFormat>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "vv/core/Error.h"
#include "vv/render/GlFramebufferCache.h"

namespace vv::render {

namespace {

constexpr GLenum kDebugSourceApplication = 0x824A;  // GL_DEBUG_SOURCE_APPLICATION (KHR_debug)

std::string hex(GLenum value) {
    char buffer[16];
    std::snprintf(buffer, sizeof buffer, "0x%04x", value);
    return buffer;
}

}  // namespace

int maxRenderSide(QOpenGLFunctions& gl) {
    GLint texture = 0;
    GLint renderbuffer = 0;
    GLint viewport[2] = {0, 0};
    gl.glGetIntegerv(GL_MAX_TEXTURE_SIZE, &texture);
    gl.glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &renderbuffer);
    gl.glGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport);
    return std::min({texture, renderbuffer, viewport[0], viewport[1]});
}

void checkGlError(QOpenGLFunctions_4_1_Core& gl, std::string_view what) {
    const GLenum error = gl.glGetError();
    if (error == GL_NO_ERROR) {
        return;
    }
    // Drain the queue so the next check starts clean.
    for (int i = 0; i < 16 && gl.glGetError() != GL_NO_ERROR; ++i) {
    }
    if (error == GL_OUT_OF_MEMORY) {
        throw RenderError(std::string(what) + ": out of GPU memory");
    }
    throw RenderError(std::string(what) + ": OpenGL error " + hex(error));
}

QOpenGLFunctions_4_1_Core& currentGl41() {
    QOpenGLContext* context = QOpenGLContext::currentContext();
    if (context == nullptr) {
        throw RenderError("no current OpenGL context");
    }
    const QSurfaceFormat format = context->format();
    if (context->isOpenGLES() || format.majorVersion() < 4 ||
        (format.majorVersion() == 4 && format.minorVersion() < 1)) {
        throw RenderError("OpenGL 4.1 core is needed, the context has " +
                          std::string(context->isOpenGLES() ? "OpenGL ES " : "OpenGL ") +
                          std::to_string(format.majorVersion()) + "." +
                          std::to_string(format.minorVersion()));
    }
    auto* functions = QOpenGLVersionFunctionsFactory::get<QOpenGLFunctions_4_1_Core>(context);
    if (functions == nullptr || !functions->initializeOpenGLFunctions()) {
        throw RenderError("cannot resolve the OpenGL 4.1 core functions");
    }
    return *functions;
}

GlFormat glFormat(TextureFormat format) noexcept {
    switch (format) {
        case TextureFormat::R8:
            return {GL_R8, GL_RED, GL_UNSIGNED_BYTE};
        case TextureFormat::RGBA8:
            return {GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE};
        case TextureFormat::R16F:
            return {GL_R16F, GL_RED, GL_HALF_FLOAT};
        case TextureFormat::RGBA16F:
            return {GL_RGBA16F, GL_RGBA, GL_HALF_FLOAT};
        case TextureFormat::R32F:
            return {GL_R32F, GL_RED, GL_FLOAT};
        case TextureFormat::RG32F:
            return {GL_RG32F, GL_RG, GL_FLOAT};
        case TextureFormat::RGBA32F:
            return {GL_RGBA32F, GL_RGBA, GL_FLOAT};
        case TextureFormat::R32UI:
            return {GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT};
        case TextureFormat::Depth32F:
            return {GL_DEPTH_COMPONENT32F, GL_DEPTH_COMPONENT, GL_FLOAT};
    }
    return {GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE};
}

GlTexture::GlTexture(QOpenGLFunctions_4_1_Core& gl, const TextureDescriptor& descriptor)
    : gl_(&gl), context_(QOpenGLContext::currentContext()), descriptor_(descriptor), owned_(true) {
    if (context_ == nullptr) {
        throw RenderError("cannot make a texture: no current OpenGL context");
    }
    const GlFormat f = glFormat(descriptor.format);
    const bool multisampled = descriptor.samples > 1;
    const GLenum target = multisampled ? GL_TEXTURE_2D_MULTISAMPLE : GL_TEXTURE_2D;
    gl.glGetError();  // start clean
    gl.glGenTextures(1, &texture_);
    gl.glBindTexture(target, texture_);
    if (multisampled) {
        gl.glTexImage2DMultisample(target, descriptor.samples, f.internalFormat, descriptor.width,
                                   descriptor.height, GL_TRUE);
    } else {
        gl.glTexImage2D(target, 0, static_cast<GLint>(f.internalFormat), descriptor.width,
                        descriptor.height, 0, f.format, f.type, nullptr);
        gl.glTexParameteri(target, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        gl.glTexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        gl.glTexParameteri(target, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        gl.glTexParameteri(target, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    }
    gl.glBindTexture(target, 0);

    GLint previous = 0;
    gl.glGetIntegerv(GL_FRAMEBUFFER_BINDING, &previous);
    gl.glGenFramebuffers(1, &fbo_);
    gl.glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    const bool depth = descriptor.format == TextureFormat::Depth32F;
    gl.glFramebufferTexture2D(GL_FRAMEBUFFER, depth ? GL_DEPTH_ATTACHMENT : GL_COLOR_ATTACHMENT0,
                              target, texture_, 0);
    if (depth) {
        gl.glDrawBuffer(GL_NONE);
        gl.glReadBuffer(GL_NONE);
    }
    const GLenum status = gl.glCheckFramebufferStatus(GL_FRAMEBUFFER);
    gl.glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(previous));
    const GLenum error = gl.glGetError();
    if (error != GL_NO_ERROR || status != GL_FRAMEBUFFER_COMPLETE) {
        gl.glDeleteFramebuffers(1, &fbo_);
        gl.glDeleteTextures(1, &texture_);
        throw RenderError("cannot make a " + Texture::describe(descriptor) + " texture: " +
                          (error == GL_OUT_OF_MEMORY ? std::string("out of GPU memory")
                           : error != GL_NO_ERROR    ? "OpenGL error " + hex(error)
                                                     : "framebuffer status " + hex(status)));
    }
}

GlTexture::GlTexture(const TextureDescriptor& descriptor, unsigned fbo) noexcept
    : descriptor_(descriptor), fbo_(fbo) {}

GlTexture::~GlTexture() {
    if (const auto cache = framebufferCache_.lock()) {
        cache->forget(texture_);
    }
    if (!owned_ || gl_ == nullptr || QOpenGLContext::currentContext() != context_) {
        return;
    }
    gl_->glDeleteFramebuffers(1, &fbo_);
    gl_->glDeleteTextures(1, &texture_);
}

unsigned GlTexture::target() const noexcept {
    return descriptor_.samples > 1 ? GL_TEXTURE_2D_MULTISAMPLE : GL_TEXTURE_2D;
}

Image<float> readRedChannel(QOpenGLFunctions_4_1_Core& gl, const GlTexture& texture) {
    const auto& d = texture.descriptor();
    Image<float> image(d.width, d.height);
    gl.glBindFramebuffer(GL_READ_FRAMEBUFFER, texture.framebuffer());
    gl.glReadBuffer(GL_COLOR_ATTACHMENT0);
    gl.glPixelStorei(GL_PACK_ALIGNMENT, 4);
    gl.glReadPixels(0, 0, d.width, d.height, GL_RED, GL_FLOAT, image.data());
    gl.glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    checkGlError(gl, "reading a texture back");
    return image;
}

GlResourceAllocator::GlResourceAllocator()
    : gl_(&currentGl41()), framebuffers_(std::make_shared<GlFramebufferCache>(*gl_)) {}

GlResourceAllocator::~GlResourceAllocator() = default;

std::unique_ptr<TextureObject> GlResourceAllocator::createTexture(
    const TextureDescriptor& descriptor) {
    auto texture = std::make_unique<GlTexture>(*gl_, descriptor);
    texture->setFramebufferCache(framebuffers_);
    return texture;
}

GlPassObserver::GlPassObserver() : gl_(&currentGl41()), context_(QOpenGLContext::currentContext()) {
    if (context_->hasExtension("GL_KHR_debug")) {
        // Desktop GL names the KHR_debug entry points without a suffix.
        pushGroup_ = reinterpret_cast<PushGroup>(context_->getProcAddress("glPushDebugGroup"));
        popGroup_ = reinterpret_cast<PopGroup>(context_->getProcAddress("glPopDebugGroup"));
        if (pushGroup_ == nullptr || popGroup_ == nullptr) {
            pushGroup_ = nullptr;
            popGroup_ = nullptr;
        }
    }
    // Timestamp queries (glQueryCounter) are core since 3.3; a zero counter
    // size means the implementation does not really time. (Timestamps rather
    // than GL_TIME_ELAPSED: llvmpipe returned nonsense for the first elapsed
    // query of a context.)
    GLint bits = 0;
    gl_->glGetQueryiv(GL_TIMESTAMP, GL_QUERY_COUNTER_BITS, &bits);
    timerQueries_ = gl_->glGetError() == GL_NO_ERROR && bits > 0;
    const char* finish = std::getenv("VV_PASS_FINISH");
    finishEachPass_ = finish != nullptr && std::string_view(finish) == "1";
}

GlPassObserver::~GlPassObserver() {
    if (QOpenGLContext::currentContext() == context_) {
        release();
    }
}

void GlPassObserver::release() noexcept {
    if (!queries_.empty() && QOpenGLContext::currentContext() == context_) {
        gl_->glDeleteQueries(static_cast<GLsizei>(queries_.size()), queries_.data());
    }
    queries_.clear();
}

void GlPassObserver::beginFrame() {
    timings_.clear();
    resolved_ = 0;
}

void GlPassObserver::beginPass(std::string_view pass) {
    if (pushGroup_ != nullptr) {
        pushGroup_(kDebugSourceApplication, 0, static_cast<int>(pass.size()), pass.data());
    }
    const std::size_t index = timings_.size();
    timings_.push_back(GlPassTiming{std::string(pass), 0.0, std::nullopt});
    if (timerQueries_) {
        while (queries_.size() < 2 * (index + 1)) {
            GLuint query = 0;
            gl_->glGenQueries(1, &query);
            queries_.push_back(query);
        }
        gl_->glQueryCounter(queries_[2 * index], GL_TIMESTAMP);
    }
    if (finishEachPass_) {
        gl_->glFinish();
    }
    start_ = Clock::now();
}

void GlPassObserver::endPass(std::string_view pass) {
    static_cast<void>(pass);
    if (timings_.empty()) {
        return;
    }
    if (finishEachPass_) {
        gl_->glFinish();
    }
    timings_.back().cpuMilliseconds =
        std::chrono::duration<double, std::milli>(Clock::now() - start_).count();
    if (timerQueries_) {
        gl_->glQueryCounter(queries_[2 * (timings_.size() - 1) + 1], GL_TIMESTAMP);
    }
    if (popGroup_ != nullptr) {
        popGroup_();
    }
}

void GlPassObserver::endFrame() {}

const std::vector<GlPassTiming>& GlPassObserver::timings() {
    if (timerQueries_ && QOpenGLContext::currentContext() == context_) {
        for (; resolved_ < timings_.size(); ++resolved_) {
            GLuint64 begin = 0;
            GLuint64 end = 0;
            gl_->glGetQueryObjectui64v(queries_[2 * resolved_], GL_QUERY_RESULT, &begin);
            gl_->glGetQueryObjectui64v(queries_[2 * resolved_ + 1], GL_QUERY_RESULT, &end);
            timings_[resolved_].gpuMilliseconds =
                end >= begin ? static_cast<double>(end - begin) * 1e-6 : 0.0;
        }
    }
    return timings_;
}

}  // namespace vv::render

namespace vv::render {

namespace {

std::string readShader(std::string_view resource) {
    QFile file(QString::fromUtf8(resource.data(), static_cast<qsizetype>(resource.size())));
    if (!file.open(QIODevice::ReadOnly)) {
        throw RenderError(std::string(resource), "cannot read shader resource");
    }
    return file.readAll().toStdString();
}

/// One shader from the concatenation of `resources` (the first has #version),
/// with `#define NAME` for each of `defines` right after the #version line.
GLuint compile(QOpenGLFunctions_4_1_Core& gl, GLenum type,
               std::span<const std::string_view> resources,
               std::span<const std::string_view> defines = {}) {
    std::vector<std::string> sources;
    std::string names;
    for (const std::string_view resource : resources) {
        sources.push_back(readShader(resource));
        names += (names.empty() ? "" : " + ") + std::string(resource);
    }
    if (!defines.empty() && !sources.empty()) {
        std::string& first = sources.front();
        const std::size_t versionEnd = first.find('\n');
        if (first.rfind("#version", 0) != 0 || versionEnd == std::string::npos) {
            throw RenderError(names, "shader does not start with a #version line");
        }
        std::string lines;
        for (const std::string_view name : defines) {
            lines += "#define " + std::string(name) + "\n";
            names += " [" + std::string(name) + "]";
        }
        first.insert(versionEnd + 1, lines);
    }
    std::vector<const char*> texts;
    std::vector<GLint> lengths;
    for (const std::string& source : sources) {
        texts.push_back(source.c_str());
        lengths.push_back(static_cast<GLint>(source.size()));
    }
    const GLuint shader = gl.glCreateShader(type);
    if (shader == 0) {
        throw RenderError(names, "glCreateShader failed");
    }
    gl.glShaderSource(shader, static_cast<GLsizei>(texts.size()), texts.data(), lengths.data());
    gl.glCompileShader(shader);
    GLint ok = GL_FALSE;
    gl.glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (ok != GL_TRUE) {
        GLint size = 0;
        gl.glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &size);
        std::string log(static_cast<std::size_t>(std::max(size, 1)), '\0');
        gl.glGetShaderInfoLog(shader, static_cast<GLsizei>(log.size()), nullptr, log.data());
        log.resize(std::char_traits<char>::length(log.c_str()));
        gl.glDeleteShader(shader);
        throw RenderError(names, "shader does not compile:\n" + log);
    }
    return shader;
}

}  // namespace

unsigned buildProgram(QOpenGLFunctions_4_1_Core& gl, std::string_view vertexResource,
                      std::string_view fragmentResource, std::string_view what) {
    const std::string_view fragment[] = {fragmentResource};
    return buildProgram(gl, vertexResource, std::span<const std::string_view>(fragment), what);
}

unsigned buildProgram(QOpenGLFunctions_4_1_Core& gl, std::string_view vertexResource,
                      std::span<const std::string_view> fragmentResources, std::string_view what,
                      std::span<const std::string_view> fragmentDefines) {
    const std::string_view vertexParts[] = {vertexResource};
    const GLuint vertex = compile(gl, GL_VERTEX_SHADER, vertexParts);
    GLuint fragment = 0;
    try {
        fragment = compile(gl, GL_FRAGMENT_SHADER, fragmentResources, fragmentDefines);
    } catch (...) {
        gl.glDeleteShader(vertex);
        throw;
    }
    const GLuint program = gl.glCreateProgram();
    gl.glAttachShader(program, vertex);
    gl.glAttachShader(program, fragment);
    gl.glBindFragDataLocation(program, 0, "fragColor");
    gl.glLinkProgram(program);
    gl.glDetachShader(program, vertex);
    gl.glDetachShader(program, fragment);
    gl.glDeleteShader(vertex);
    gl.glDeleteShader(fragment);
    GLint ok = GL_FALSE;
    gl.glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (ok != GL_TRUE) {
        GLint size = 0;
        gl.glGetProgramiv(program, GL_INFO_LOG_LENGTH, &size);
        std::string log(static_cast<std::size_t>(std::max(size, 1)), '\0');
        gl.glGetProgramInfoLog(program, static_cast<GLsizei>(log.size()), nullptr, log.data());
        log.resize(std::char_traits<char>::length(log.c_str()));
        gl.glDeleteProgram(program);
        throw RenderError(std::string(what) + " shader program does not link:\n" + log);
    }
    return program;
}

}  // namespace vv::render
