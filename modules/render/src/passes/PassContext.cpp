// SPDX-License-Identifier: GPL-3.0-or-later
#include "passes/PassContext.h"

#include <QOpenGLContext>
#include <QOpenGLFunctions_4_1_Core>
#include <string_view>
#include <utility>

namespace vv::render {

const Program& PassPrograms::get(const ProgramSpec& spec) {
    if (const auto found = programs_.find(spec.what); found != programs_.end()) {
        return found->second;
    }
    Program program(*gl_, spec.vertex, spec.fragments, spec.what, spec.defines);
    return programs_.emplace(std::string(spec.what), std::move(program)).first->second;
}

DepthScaleLut::DepthScaleLut(QOpenGLFunctions_4_1_Core& gl)
    : gl_(&gl), context_(QOpenGLContext::currentContext()) {
    gl.glGenTextures(1, &texture_);
}

DepthScaleLut::~DepthScaleLut() {
    if (QOpenGLContext::currentContext() == context_) {
        gl_->glDeleteTextures(1, &texture_);
    }
}

void DepthScaleLut::upload(colormaps::DepthScale scale) {
    if (uploaded_ == scale) {
        return;
    }
    auto& g = *gl_;
    const auto table = colormaps::lut(scale, kSize);
    g.glBindTexture(GL_TEXTURE_1D, texture_);
    g.glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    g.glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA8, kSize, 0, GL_RGBA, GL_UNSIGNED_BYTE, table.data());
    g.glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    g.glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    g.glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    g.glBindTexture(GL_TEXTURE_1D, 0);
    checkGlError(g, "uploading the depth scale");
    uploaded_ = scale;
}

void PassContext::bindRenderTarget(const RenderGraph::Resources& resources,
                                   RenderTargetId id) const {
    gl->glBindFramebuffer(GL_FRAMEBUFFER, framebuffers->framebuffer(resources.renderTarget(id)));
}

void PassContext::beginFullscreen(const RenderGraph::Resources& resources, RenderTargetId id,
                                  glm::ivec2 size) const {
    bindRenderTarget(resources, id);
    gl->glViewport(0, 0, size.x, size.y);
    gl->glDisable(GL_DEPTH_TEST);
    gl->glDisable(GL_BLEND);
}

const GlTexture& glTex(const Texture& texture) {
    return texture.objectAs<GlTexture>();
}

void bindFiltered(QOpenGLFunctions_4_1_Core& gl, unsigned texture, bool linear) {
    gl.glBindTexture(GL_TEXTURE_2D, texture);
    if (texture != 0U) {
        const GLint filter = linear ? GL_LINEAR : GL_NEAREST;
        gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
        gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
    }
}

void endBilinearPass(QOpenGLFunctions_4_1_Core& gl, unsigned texture, const char* what) {
    bindFiltered(gl, texture, false);
    gl.glBindTexture(GL_TEXTURE_2D, 0);
    gl.glUseProgram(0);
    gl.glEnable(GL_DEPTH_TEST);
    checkGlError(gl, what);
}

void drawFullscreenAndUnbind(QOpenGLFunctions_4_1_Core& gl, unsigned vao, int units) {
    gl.glBindVertexArray(vao);
    gl.glDrawArrays(GL_TRIANGLES, 0, 3);
    gl.glBindVertexArray(0);
    for (int unit = units - 1; unit >= 0; --unit) {
        gl.glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
        gl.glBindTexture(GL_TEXTURE_2D, 0);
        gl.glBindTexture(GL_TEXTURE_1D, 0);
    }
    gl.glUseProgram(0);
}

}  // namespace vv::render
