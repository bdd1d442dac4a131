// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/render/Program.h"

#include <QOpenGLContext>
#include <QOpenGLFunctions_4_1_Core>
#include <utility>

#include "vv/render/GlResources.h"

namespace vv::render {

Program::Program(QOpenGLFunctions_4_1_Core& gl, std::string_view vertexResource,
                 std::span<const std::string_view> fragmentResources, std::string_view what,
                 std::span<const std::string_view> fragmentDefines)
    : gl_(&gl),
      context_(QOpenGLContext::currentContext()),
      id_(buildProgram(gl, vertexResource, fragmentResources, what, fragmentDefines)) {}

Program::Program(QOpenGLFunctions_4_1_Core& gl, std::string_view vertexResource,
                 std::string_view fragmentResource, std::string_view what)
    : gl_(&gl),
      context_(QOpenGLContext::currentContext()),
      id_(buildProgram(gl, vertexResource, fragmentResource, what)) {}

Program::~Program() {
    release();
}

Program::Program(Program&& other) noexcept
    : gl_(std::exchange(other.gl_, nullptr)),
      context_(std::exchange(other.context_, nullptr)),
      id_(std::exchange(other.id_, 0U)),
      locations_(std::move(other.locations_)) {
    other.locations_.clear();
}

Program& Program::operator=(Program&& other) noexcept {
    if (this != &other) {
        release();
        gl_ = std::exchange(other.gl_, nullptr);
        context_ = std::exchange(other.context_, nullptr);
        id_ = std::exchange(other.id_, 0U);
        locations_ = std::move(other.locations_);
        other.locations_.clear();
    }
    return *this;
}

void Program::release() noexcept {
    if (id_ != 0 && gl_ != nullptr && context_ != nullptr &&
        QOpenGLContext::currentContext() == context_) {
        gl_->glDeleteProgram(id_);
    }
    id_ = 0;
    locations_.clear();
}

void Program::use() const {
    gl_->glUseProgram(id_);
}

int Program::location(std::string_view name) const {
    const auto found = locations_.find(name);
    if (found != locations_.end()) {
        return found->second;
    }
    const std::string key(name);
    const GLint location = gl_->glGetUniformLocation(id_, key.c_str());
    locations_.emplace(key, location);
    return location;
}

void Program::set(std::string_view name, int value) const {
    gl_->glUniform1i(location(name), value);
}

void Program::set(std::string_view name, float value) const {
    gl_->glUniform1f(location(name), value);
}

void Program::set(std::string_view name, const glm::vec2& value) const {
    gl_->glUniform2f(location(name), value.x, value.y);
}

void Program::set(std::string_view name, const glm::vec3& value) const {
    gl_->glUniform3f(location(name), value.x, value.y, value.z);
}

void Program::set(std::string_view name, const glm::mat3& value) const {
    gl_->glUniformMatrix3fv(location(name), 1, GL_FALSE, &value[0][0]);
}

void Program::set(std::string_view name, const glm::mat4& value) const {
    gl_->glUniformMatrix4fv(location(name), 1, GL_FALSE, &value[0][0]);
}

}  // namespace vv::render
