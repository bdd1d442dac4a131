// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Single pixels and the visible depth range of the last frame's G-buffer
// (FrameRenderer::probe, visibleDepthRange). Internal to vv::render.

#include <memory>
#include <optional>
#include <utility>

#include "vv/core/Image.h"
#include "vv/render/Camera.h"
#include "vv/render/FrameRenderer.h"
#include "vv/render/RenderGraphResources.h"

class QOpenGLFunctions_4_1_Core;

namespace vv::render {

/// Keeps the last frame's G-buffer textures (shared, so they outlive the
/// graph cache's reuse until the next frame replaces them) and, when the
/// frame read its linear depth back, that image.
class GBufferProbe {
  public:
    /// The G-buffer of the frame just drawn; `depth` is its linear depth on
    /// the CPU when the frame read it back ("depth-readback"), else null.
    void setFrame(Texture linearDepth, Texture objectId, Texture parameter,
                  std::shared_ptr<const Image<float>> depth);
    /// Forgets the frame (e.g. before the GL context goes away).
    void clear() noexcept;

    /// FrameRenderer::probe() of pixel (x, y) of a frame of `renderSize`
    /// drawn with `camera`; nullopt without a frame or a vessel there.
    /// Restores the read framebuffer binding. Throws RenderError when GL fails.
    [[nodiscard]] std::optional<ProbeSample> probe(QOpenGLFunctions_4_1_Core& gl,
                                                   const Camera& camera, glm::ivec2 renderSize,
                                                   int x, int y) const;

    /// The visible vessels' linear depth range (finite texels); nullopt
    /// without a frame or a visible vessel. Uses the frame's depth when it
    /// read it back, else reads it once and keeps it for this frame.
    /// Restores the read framebuffer binding. Throws RenderError when GL fails.
    [[nodiscard]] std::optional<std::pair<float, float>> visibleDepthRange(
        QOpenGLFunctions_4_1_Core& gl) const;

  private:
    struct Frame {
        Texture linearDepth;
        Texture objectId;
        Texture parameter;
    };
    std::optional<Frame> frame_;
    /// The frame's linear depth on the CPU: from the frame, or read on demand.
    mutable std::shared_ptr<const Image<float>> depth_;
};

}  // namespace vv::render
