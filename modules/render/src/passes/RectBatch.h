// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Draws many small rectangles of a render target in one call: two
// triangles each from a vertex buffer (rects.vert), for programs that only
// a small, scattered part of the target needs (upscale.frag's EDGES
// variant along the vessels' silhouettes). On software rasterisers a
// fragment program costs the same on every pixel of its draw, taken or
// not taken branches alike: scissored tiles of 64 pixels drew it on 16
// times the pixels that need it.

#include <glm/glm.hpp>
#include <vector>

class QOpenGLContext;
class QOpenGLFunctions_4_1_Core;

namespace vv::render {

class RectBatch {
  public:
    /// Made with `gl`'s context current. Throws RenderError when GL fails.
    explicit RectBatch(QOpenGLFunctions_4_1_Core& gl);
    /// Deletes its GL objects when its context is current (else they go
    /// with the context).
    ~RectBatch();
    RectBatch(const RectBatch&) = delete;
    RectBatch& operator=(const RectBatch&) = delete;
    RectBatch(RectBatch&&) = delete;
    RectBatch& operator=(RectBatch&&) = delete;

    /// Draws `rects` (target pixels: x0, y0, x1, y1, GL window coordinates)
    /// with the bound program, whose vertex stage is rects.vert (its
    /// uTargetSize set to the target's size). Leaves no vertex array
    /// bound. Throws RenderError when GL fails.
    void draw(const std::vector<glm::ivec4>& rects);

  private:
    QOpenGLFunctions_4_1_Core* gl_;
    QOpenGLContext* context_;
    unsigned vao_ = 0;
    unsigned buffer_ = 0;
    std::vector<float> vertices_;
};

}  // namespace vv::render
