// SPDX-License-Identifier: GPL-3.0-or-later
#include "passes/RectBatch.h"

#include <QOpenGLContext>
#include <QOpenGLFunctions_4_1_Core>

#include "vv/render/GlResources.h"

namespace vv::render {

RectBatch::RectBatch(QOpenGLFunctions_4_1_Core& gl)
    : gl_(&gl), context_(QOpenGLContext::currentContext()) {
    gl.glGenVertexArrays(1, &vao_);
    gl.glGenBuffers(1, &buffer_);
    gl.glBindVertexArray(vao_);
    gl.glBindBuffer(GL_ARRAY_BUFFER, buffer_);
    gl.glEnableVertexAttribArray(0);
    gl.glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, nullptr);
    gl.glBindVertexArray(0);
    gl.glBindBuffer(GL_ARRAY_BUFFER, 0);
    checkGlError(gl, "RectBatch");
}

RectBatch::~RectBatch() {
    if (QOpenGLContext::currentContext() == context_) {
        gl_->glDeleteBuffers(1, &buffer_);
        gl_->glDeleteVertexArrays(1, &vao_);
    }
}

void RectBatch::draw(const std::vector<glm::ivec4>& rects) {
    if (rects.empty()) {
        return;
    }
    vertices_.clear();
    vertices_.reserve(rects.size() * 12);
    for (const glm::ivec4& r : rects) {
        const auto x0 = static_cast<float>(r.x);
        const auto y0 = static_cast<float>(r.y);
        const auto x1 = static_cast<float>(r.z);
        const auto y1 = static_cast<float>(r.w);
        vertices_.insert(vertices_.end(), {x0, y0, x1, y0, x1, y1, x0, y0, x1, y1, x0, y1});
    }
    auto& g = *gl_;
    g.glBindBuffer(GL_ARRAY_BUFFER, buffer_);
    g.glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices_.size() * sizeof(float)),
                   vertices_.data(), GL_STREAM_DRAW);
    g.glBindBuffer(GL_ARRAY_BUFFER, 0);
    g.glBindVertexArray(vao_);
    g.glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(vertices_.size() / 2));
    g.glBindVertexArray(0);
    checkGlError(g, "RectBatch::draw");
}

}  // namespace vv::render
