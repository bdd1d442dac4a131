// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/render/GlFramebufferCache.h"

#include <QOpenGLContext>
#include <QOpenGLFunctions_4_1_Core>
#include <algorithm>
#include <string>

#include "vv/core/Error.h"
#include "vv/render/GlResources.h"

namespace vv::render {

namespace {

/// The GL texture behind an attachment; throws for a wrapped framebuffer.
const GlTexture& attachment(const RenderTarget& target, const Texture& texture) {
    const GlTexture& gl = texture.objectAs<GlTexture>();
    if (gl.texture() == 0) {
        throw RenderError("render target '" + std::string(target.name) +
                          "': a wrapped framebuffer can only be a target on its own");
    }
    return gl;
}

}  // namespace

GlFramebufferCache::GlFramebufferCache(QOpenGLFunctions_4_1_Core& gl)
    : gl_(&gl), context_(QOpenGLContext::currentContext()) {}

GlFramebufferCache::~GlFramebufferCache() {
    if (QOpenGLContext::currentContext() != context_) {
        return;
    }
    for (const auto& entry : framebuffers_) {
        gl_->glDeleteFramebuffers(1, &entry.second);
    }
}

unsigned GlFramebufferCache::framebuffer(const RenderTarget& target) {
    if (target.colors.size() == 1 && target.depth == nullptr) {
        return target.colors.front()->objectAs<GlTexture>().framebuffer();
    }
    std::vector<unsigned> key;
    key.reserve(target.colors.size() + 1);
    for (const Texture* color : target.colors) {
        key.push_back(attachment(target, *color).texture());
    }
    key.push_back(target.depth != nullptr ? attachment(target, *target.depth).texture() : 0U);
    const auto found = framebuffers_.find(key);
    if (found != framebuffers_.end()) {
        return found->second;
    }

    auto& g = *gl_;
    GLint previous = 0;
    g.glGetIntegerv(GL_FRAMEBUFFER_BINDING, &previous);
    GLuint fbo = 0;
    g.glGenFramebuffers(1, &fbo);
    g.glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    std::vector<GLenum> buffers;
    for (std::size_t i = 0; i < target.colors.size(); ++i) {
        const GlTexture& color = attachment(target, *target.colors[i]);
        const auto point = static_cast<GLenum>(GL_COLOR_ATTACHMENT0 + i);
        g.glFramebufferTexture2D(GL_FRAMEBUFFER, point, color.target(), color.texture(), 0);
        buffers.push_back(point);
    }
    if (target.depth != nullptr) {
        const GlTexture& depth = attachment(target, *target.depth);
        g.glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, depth.target(),
                                 depth.texture(), 0);
    }
    if (buffers.empty()) {
        g.glDrawBuffer(GL_NONE);
        g.glReadBuffer(GL_NONE);
    } else {
        g.glDrawBuffers(static_cast<GLsizei>(buffers.size()), buffers.data());
    }
    const GLenum status = g.glCheckFramebufferStatus(GL_FRAMEBUFFER);
    g.glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(previous));
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        g.glDeleteFramebuffers(1, &fbo);
        throw RenderError("the framebuffer of render target '" + std::string(target.name) +
                          "' is incomplete");
    }
    checkGlError(g, "making the framebuffer of a render target");
    framebuffers_.emplace(std::move(key), fbo);
    return fbo;
}

void GlFramebufferCache::forget(unsigned texture) noexcept {
    const bool current = QOpenGLContext::currentContext() == context_;
    for (auto it = framebuffers_.begin(); it != framebuffers_.end();) {
        if (std::find(it->first.begin(), it->first.end(), texture) == it->first.end()) {
            ++it;
            continue;
        }
        if (current) {
            gl_->glDeleteFramebuffers(1, &it->second);
        }
        it = framebuffers_.erase(it);
    }
}

}  // namespace vv::render
