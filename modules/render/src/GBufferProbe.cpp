// SPDX-License-Identifier: GPL-3.0-or-later
#include "GBufferProbe.h"

#include <QOpenGLFunctions_4_1_Core>
#include <algorithm>
#include <cmath>
#include <limits>

#include "vv/core/ImageRange.h"
#include "vv/render/GlResources.h"

namespace vv::render {

namespace {

/// Restores the read framebuffer binding and its read buffer when it goes out of scope.
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

/// Reads texel (x, y) of a graph texture through its own framebuffer.
void readTexel(QOpenGLFunctions_4_1_Core& g, const Texture& texture, int x, int y, GLenum format,
               GLenum type, void* texel) {
    g.glBindFramebuffer(GL_READ_FRAMEBUFFER, texture.objectAs<GlTexture>().framebuffer());
    g.glReadBuffer(GL_COLOR_ATTACHMENT0);
    g.glReadPixels(x, y, 1, 1, format, type, texel);
}

}  // namespace

void GBufferProbe::setFrame(Texture linearDepth, Texture objectId, Texture parameter,
                            std::shared_ptr<const Image<float>> depth) {
    frame_.emplace(Frame{std::move(linearDepth), std::move(objectId), std::move(parameter)});
    depth_ = std::move(depth);
}

void GBufferProbe::clear() noexcept {
    frame_.reset();
    depth_.reset();
}

std::optional<ProbeSample> GBufferProbe::probe(QOpenGLFunctions_4_1_Core& g, const Camera& camera,
                                               glm::ivec2 renderSize, int x, int y) const {
    if (!frame_ || x < 0 || y < 0 || x >= renderSize.x || y >= renderSize.y) {
        return std::nullopt;
    }
    const ReadFramebufferGuard guard(g);
    ProbeSample sample;
    g.glPixelStorei(GL_PACK_ALIGNMENT, 4);
    GLuint id = 0;
    readTexel(g, frame_->objectId, x, y, GL_RED_INTEGER, GL_UNSIGNED_INT, &id);
    readTexel(g, frame_->linearDepth, x, y, GL_RED, GL_FLOAT, &sample.linearDepth);
    readTexel(g, frame_->parameter, x, y, GL_RED, GL_FLOAT, &sample.value);
    checkGlError(g, "probing the G-buffer");
    if (id == 0 || !std::isfinite(sample.linearDepth) || sample.linearDepth <= 0.0F) {
        return std::nullopt;
    }
    sample.objectId = id;
    // Pixel centre -> NDC -> view space at the linear depth d (z_view = -d).
    const glm::mat4 projection = camera.projectionMatrix();
    const float d = sample.linearDepth;
    const float ndcX =
        (static_cast<float>(x) + 0.5F) / static_cast<float>(renderSize.x) * 2.0F - 1.0F;
    const float ndcY =
        (static_cast<float>(y) + 0.5F) / static_cast<float>(renderSize.y) * 2.0F - 1.0F;
    const float zView = -d;
    // clip.x = P[0][0] x + P[2][0] z, clip.w = -z = d (glm: P[column][row]).
    sample.viewPosition =
        glm::vec3((ndcX * d - projection[2][0] * zView) / projection[0][0],
                  (ndcY * d - projection[2][1] * zView) / projection[1][1], zView);
    sample.worldPosition =
        glm::vec3(glm::inverse(camera.viewMatrix()) * glm::vec4(sample.viewPosition, 1.0F));
    return sample;
}

std::optional<std::pair<float, float>> GBufferProbe::visibleDepthRange(
    QOpenGLFunctions_4_1_Core& g) const {
    if (!frame_) {
        return std::nullopt;
    }
    if (depth_ == nullptr) {
        const ReadFramebufferGuard guard(g);
        depth_ = std::make_shared<const Image<float>>(
            readRedChannel(g, frame_->linearDepth.objectAs<GlTexture>()));
    }
    return finiteRange(depth_->view());
}

}  // namespace vv::render
