// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QPointer>
#include <cstddef>
#include <functional>
#include <glm/glm.hpp>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>

class QOpenGLContext;
class QOpenGLFunctions_4_1_Core;

namespace vv::render {

/// A linked GL program and the locations of its uniforms, looked up by name
/// once and then kept, so setting a uniform per frame costs no GL query.
///
/// Made with the context current (buildProgram()); that context must be
/// current whenever it is used. Deleted by release() or the destructor when
/// its context is current (otherwise it dies with the context, and a
/// destroyed context's program is never deleted in another). Move-only.
class Program {
  public:
    /// An empty program (valid() false).
    Program() noexcept = default;
    /// Builds `vertexResource` + the fragment resources concatenated, with
    /// `#define`s, like buildProgram(). Throws RenderError like it.
    Program(QOpenGLFunctions_4_1_Core& gl, std::string_view vertexResource,
            std::span<const std::string_view> fragmentResources, std::string_view what,
            std::span<const std::string_view> fragmentDefines = {});
    /// As above with one fragment resource.
    Program(QOpenGLFunctions_4_1_Core& gl, std::string_view vertexResource,
            std::string_view fragmentResource, std::string_view what);
    ~Program();
    Program(const Program&) = delete;
    Program& operator=(const Program&) = delete;
    Program(Program&& other) noexcept;
    Program& operator=(Program&& other) noexcept;

    [[nodiscard]] bool valid() const noexcept { return id_ != 0; }
    /// The GL program name; 0 when empty.
    [[nodiscard]] unsigned id() const noexcept { return id_; }

    /// Makes it the current program (glUseProgram).
    void use() const;
    /// The location of uniform `name`, from the cache after its first look-up;
    /// -1 when the program has no such active uniform (setting it then does
    /// nothing, as in GL).
    [[nodiscard]] int location(std::string_view name) const;

    /// Sets uniform `name` of this program, which must be in use.
    void set(std::string_view name, int value) const;
    void set(std::string_view name, float value) const;
    void set(std::string_view name, const glm::vec2& value) const;
    void set(std::string_view name, const glm::vec3& value) const;
    void set(std::string_view name, const glm::mat3& value) const;
    void set(std::string_view name, const glm::mat4& value) const;

    /// Deletes the program (its context current) and forgets the locations.
    /// Safe to call twice.
    void release() noexcept;

  private:
    struct NameHash {
        using is_transparent = void;
        std::size_t operator()(std::string_view name) const noexcept {
            return std::hash<std::string_view>{}(name);
        }
    };

    QOpenGLFunctions_4_1_Core* gl_ = nullptr;
    QPointer<QOpenGLContext> context_;  ///< null once that context is destroyed
    unsigned id_ = 0;
    mutable std::unordered_map<std::string, int, NameHash, std::equal_to<>> locations_;
};

}  // namespace vv::render
