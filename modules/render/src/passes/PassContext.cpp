// SPDX-License-Identifier: GPL-3.0-or-later
#include "passes/PassContext.h"

#include <QOpenGLContext>
#include <QOpenGLFunctions_4_1_Core>
#include <string_view>

namespace vv::render {

namespace {
constexpr std::string_view kFullscreen = ":/vv/shaders/fullscreen.vert";
}  // namespace

FullscreenPrograms FullscreenPrograms::build(QOpenGLFunctions_4_1_Core& gl) {
    const std::string_view vssFragment[] = {":/vv/shaders/vss.frag"};
    const std::string_view quickNormals[] = {"QUICK_NORMALS"};
    const std::string_view slopeTexture[] = {"SLOPE_TEXTURE"};
    FullscreenPrograms programs;
    programs.vss = Program(gl, kFullscreen, ":/vv/shaders/vss.frag", "VSS shading");
    programs.vssQuick =
        Program(gl, kFullscreen, vssFragment, "VSS shading (quick normals)", quickNormals);
    programs.vssSlope =
        Program(gl, kFullscreen, vssFragment, "VSS shading (fitted slopes)", slopeTexture);
    programs.composite = Program(gl, kFullscreen, ":/vv/shaders/composite.frag", "composite");
    const std::string_view compositeFragment[] = {":/vv/shaders/composite.frag"};
    const std::string_view reducedVss[] = {"REDUCED_VSS"};
    programs.compositeReducedVss =
        Program(gl, kFullscreen, compositeFragment, "composite (reduced VSS)", reducedVss);
    programs.ssao = Program(gl, kFullscreen, ":/vv/shaders/ssao.frag", "SSAO");
    programs.aoBlur = Program(gl, kFullscreen, ":/vv/shaders/aoblur.frag", "AO blur");
    programs.fxaa = Program(gl, kFullscreen, ":/vv/shaders/fxaa.frag", "FXAA");
    programs.upscale = Program(gl, kFullscreen, ":/vv/shaders/upscale.frag", "upscale");
    const std::string_view upscaleFragment[] = {":/vv/shaders/upscale.frag"};
    const std::string_view colorOnly[] = {"COLOR_ONLY"};
    programs.upscaleColor =
        Program(gl, kFullscreen, upscaleFragment, "upscale (colour only)", colorOnly);
    const std::string_view edges[] = {"EDGES"};
    const std::string_view edgesColorOnly[] = {"EDGES", "COLOR_ONLY"};
    constexpr std::string_view kRects = ":/vv/shaders/rects.vert";
    programs.upscaleEdges = Program(gl, kRects, upscaleFragment, "upscale (edges)", edges);
    programs.upscaleEdgesColor =
        Program(gl, kRects, upscaleFragment, "upscale (edges, colour only)", edgesColorOnly);
    return programs;
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
