// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/render/VolumeRenderer.h"

#include <QOpenGLContext>
#include <QOpenGLFunctions_4_1_Core>
#include <string>
#include <string_view>
#include <utility>

#include "vv/core/Error.h"
#include "vv/render/GlResources.h"

namespace vv::render {

VolumeRenderer::~VolumeRenderer() {
    if (context_ != nullptr && QOpenGLContext::currentContext() == context_) {
        release();
    }
}

void VolumeRenderer::initialize() {
    auto& gl = currentGl41();
    if (gl_ != nullptr && context_ == QOpenGLContext::currentContext()) {
        release();
    }
    gl_ = &gl;
    context_ = QOpenGLContext::currentContext();
    program_ = Program(gl, ":/vv/shaders/fullscreen.vert", ":/vv/shaders/raycast.frag",
                       "volume ray casting");
    gl.glGenVertexArrays(1, &vao_);
    uploaded_ = false;
    checkGlError(gl, "VolumeRenderer::initialize");
}

void VolumeRenderer::release() noexcept {
    if (gl_ == nullptr || QOpenGLContext::currentContext() != context_) {
        return;
    }
    gl_->glDeleteVertexArrays(1, &vao_);
    gl_->glDeleteTextures(1, &texture_);
    program_.release();
    vao_ = 0;
    texture_ = 0;
    uploaded_ = false;
    gl_ = nullptr;
    context_ = nullptr;
}

void VolumeRenderer::setVolume(std::shared_ptr<const scene::Volume> volume) noexcept {
    if (volume == volume_) {
        return;
    }
    volume_ = std::move(volume);
    uploaded_ = false;
}

void VolumeRenderer::upload() {
    auto& g = *gl_;
    const scene::Volume& v = *volume_;
    const glm::ivec3 dims = v.dims();
    GLint max3d = 0;
    g.glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &max3d);
    if (dims.x > max3d || dims.y > max3d || dims.z > max3d) {
        throw RenderError("the volume (" + std::to_string(dims.x) + "x" + std::to_string(dims.y) +
                          "x" + std::to_string(dims.z) +
                          " voxels) exceeds this GPU's 3-D texture limit of " +
                          std::to_string(max3d) + " voxels per side; crop or resample it");
    }
    if (texture_ == 0) {
        g.glGenTextures(1, &texture_);
    }
    g.glBindTexture(GL_TEXTURE_3D, texture_);
    g.glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    if (v.voxelType() == scene::VoxelType::Int16) {
        // Signed shorts into a float format are normalised (c / 32767) by GL;
        // the shader scales back. Half floats keep ~0.05 % of the value.
        g.glTexImage3D(GL_TEXTURE_3D, 0, GL_R16F, dims.x, dims.y, dims.z, 0, GL_RED, GL_SHORT,
                       v.int16Voxels().data());
        valueScale_ = 32767.0F;
    } else {
        g.glTexImage3D(GL_TEXTURE_3D, 0, GL_R32F, dims.x, dims.y, dims.z, 0, GL_RED, GL_FLOAT,
                       v.floatVoxels().data());
        valueScale_ = 1.0F;
    }
    g.glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    g.glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    g.glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    g.glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    g.glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
    g.glBindTexture(GL_TEXTURE_3D, 0);
    if (g.glGetError() == GL_OUT_OF_MEMORY) {
        throw RenderError("not enough GPU memory for the volume (" +
                          std::to_string(v.byteSize() / (1024 * 1024)) + " MiB)");
    }
    checkGlError(g, "uploading the volume");
    uploaded_ = true;
}

void VolumeRenderer::drawGBuffer(const Camera& camera, float isoValue, unsigned objectId) {
    if (gl_ == nullptr || !program_.valid()) {
        throw RenderError("VolumeRenderer::drawGBuffer before initialize()");
    }
    if (QOpenGLContext::currentContext() != context_) {
        throw RenderError("VolumeRenderer used without its OpenGL context current");
    }
    if (!volume_ || volume_->empty()) {
        return;
    }
    if (!uploaded_) {
        upload();
    }
    auto& g = *gl_;
    const glm::dmat4 view(camera.viewMatrix());
    const glm::dmat4 projection(camera.projectionMatrix());
    const glm::dmat4 indexToView = view * volume_->indexToWorld();
    const glm::mat4 viewToIndex(glm::inverse(indexToView));
    const glm::mat4 inverseProjection(glm::inverse(projection));
    const glm::mat4 indexToViewF(indexToView);
    const glm::mat4 projectionF(projection);
    // Gradients are covectors: index space -> view space by the inverse transpose.
    const glm::mat3 normalMatrix(glm::transpose(glm::inverse(glm::dmat3(indexToView))));
    const glm::vec3 dims(volume_->dims());

    g.glEnable(GL_DEPTH_TEST);
    g.glDepthFunc(GL_LESS);
    g.glDepthMask(GL_TRUE);
    g.glDisable(GL_CULL_FACE);
    g.glDisable(GL_BLEND);
    program_.use();
    const auto loc = [&](std::string_view name) { return program_.location(name); };
    g.glUniformMatrix4fv(loc("uInverseProjection"), 1, GL_FALSE, &inverseProjection[0][0]);
    g.glUniformMatrix4fv(loc("uProjection"), 1, GL_FALSE, &projectionF[0][0]);
    g.glUniformMatrix4fv(loc("uViewToIndex"), 1, GL_FALSE, &viewToIndex[0][0]);
    g.glUniformMatrix4fv(loc("uIndexToView"), 1, GL_FALSE, &indexToViewF[0][0]);
    g.glUniformMatrix3fv(loc("uNormalMatrix"), 1, GL_FALSE, &normalMatrix[0][0]);
    g.glUniform3fv(loc("uDims"), 1, &dims[0]);
    g.glUniform1f(loc("uIso"), isoValue / valueScale_);
    g.glUniform1ui(loc("uObjectId"), objectId);
    g.glUniform1i(loc("uVolume"), 0);
    g.glActiveTexture(GL_TEXTURE0);
    g.glBindTexture(GL_TEXTURE_3D, texture_);
    g.glBindVertexArray(vao_);
    g.glDrawArrays(GL_TRIANGLES, 0, 3);
    g.glBindVertexArray(0);
    g.glBindTexture(GL_TEXTURE_3D, 0);
    g.glUseProgram(0);
    checkGlError(g, "ray casting the volume");
}

}  // namespace vv::render
