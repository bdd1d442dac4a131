// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <chrono>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "vv/core/Image.h"
#include "vv/render/RenderGraphObserver.h"
#include "vv/render/RenderGraphResources.h"

class QOpenGLContext;
class QOpenGLFunctions;
class QOpenGLFunctions_4_1_Core;

namespace vv::render {

class GlFramebufferCache;

/// A graph texture on the GPU: a GL texture and a framebuffer object with it
/// attached (colour attachment 0, or the depth attachment for Depth32F), or a
/// wrapper around an existing framebuffer (e.g. a widget's default
/// framebuffer) that owns nothing.
///
/// GL objects are deleted by the destructor when the context that made them
/// is current; otherwise they are left to die with their context.
class GlTexture final : public TextureObject {
  public:
    /// Makes the texture and its FBO in the current context. Throws
    /// RenderError when no context is current or GL fails (out of memory,
    /// incomplete framebuffer).
    GlTexture(QOpenGLFunctions_4_1_Core& gl, const TextureDescriptor& descriptor);
    /// Wraps framebuffer `fbo` (0 = the default framebuffer) without a
    /// texture; owns nothing.
    GlTexture(const TextureDescriptor& descriptor, unsigned fbo) noexcept;
    ~GlTexture() override;
    GlTexture(const GlTexture&) = delete;
    GlTexture& operator=(const GlTexture&) = delete;
    GlTexture(GlTexture&&) = delete;
    GlTexture& operator=(GlTexture&&) = delete;

    [[nodiscard]] const TextureDescriptor& descriptor() const noexcept { return descriptor_; }
    /// The GL texture name; 0 for a wrapped framebuffer.
    [[nodiscard]] unsigned texture() const noexcept { return texture_; }
    /// The framebuffer that renders into this texture.
    [[nodiscard]] unsigned framebuffer() const noexcept { return fbo_; }
    /// GL_TEXTURE_2D or GL_TEXTURE_2D_MULTISAMPLE.
    [[nodiscard]] unsigned target() const noexcept;

    /// The framebuffer cache to tell when this texture dies (so that it
    /// drops the framebuffers it is attached to); the allocator sets it.
    void setFramebufferCache(std::weak_ptr<GlFramebufferCache> cache) noexcept {
        framebufferCache_ = std::move(cache);
    }

  private:
    QOpenGLFunctions_4_1_Core* gl_ = nullptr;
    QOpenGLContext* context_ = nullptr;
    TextureDescriptor descriptor_;
    unsigned texture_ = 0;
    unsigned fbo_ = 0;
    bool owned_ = false;
    std::weak_ptr<GlFramebufferCache> framebufferCache_;
};

/// Reads the first channel of a single-sampled float texture (e.g. the
/// R32F linear depth) back to main memory: row 0 is the BOTTOM row (GL
/// order). Leaves no read framebuffer bound. Throws RenderError when GL fails.
[[nodiscard]] Image<float> readRedChannel(QOpenGLFunctions_4_1_Core& gl, const GlTexture& texture);

/// GL internal format, pixel format and type of a graph texture format, e.g.
/// R32F -> (GL_R32F, GL_RED, GL_FLOAT).
struct GlFormat {
    unsigned internalFormat = 0;
    unsigned format = 0;
    unsigned type = 0;
};
[[nodiscard]] GlFormat glFormat(TextureFormat format) noexcept;

/// Makes GlTexture objects in the context current at construction (which
/// must be current whenever the graph allocates), and the framebuffers of
/// the render targets passes declare from them. Throws RenderError from the
/// constructor when no OpenGL 4.1 core context is current.
class GlResourceAllocator final : public ResourceAllocator {
  public:
    GlResourceAllocator();
    ~GlResourceAllocator() override;
    GlResourceAllocator(const GlResourceAllocator&) = delete;
    GlResourceAllocator& operator=(const GlResourceAllocator&) = delete;
    GlResourceAllocator(GlResourceAllocator&&) = delete;
    GlResourceAllocator& operator=(GlResourceAllocator&&) = delete;

    [[nodiscard]] std::unique_ptr<TextureObject> createTexture(
        const TextureDescriptor& descriptor) override;

    /// The framebuffers of declared render targets (GlFramebufferCache).
    [[nodiscard]] GlFramebufferCache& framebuffers() noexcept { return *framebuffers_; }

  private:
    QOpenGLFunctions_4_1_Core* gl_ = nullptr;
    std::shared_ptr<GlFramebufferCache> framebuffers_;
};

/// One pass's time in a frame: CPU (wall clock of the execute callback) and
/// GPU (GL timestamp queries around it, when the context has them).
struct GlPassTiming {
    std::string pass;
    double cpuMilliseconds = 0.0;
    std::optional<double> gpuMilliseconds;
};

/// Brackets each graph pass with a GL debug group named after it (when the
/// context has GL_KHR_debug, so that RenderDoc / apitrace show the passes)
/// and times it: CPU time always, GPU time with GL_TIMESTAMP queries
/// (core since OpenGL 3.3). Create and use it with the context current.
/// With the environment variable VV_PASS_FINISH=1 every pass ends with
/// glFinish, so that a pass's CPU time is its whole cost on a software
/// rasteriser (llvmpipe renders a pass when a later one reads its target,
/// and that wait shows in the later pass's CPU time otherwise); for
/// benchmarks only, it stalls a real GPU.
class GlPassObserver final : public PassObserver {
  public:
    GlPassObserver();
    ~GlPassObserver() override;
    GlPassObserver(const GlPassObserver&) = delete;
    GlPassObserver& operator=(const GlPassObserver&) = delete;
    GlPassObserver(GlPassObserver&&) = delete;
    GlPassObserver& operator=(GlPassObserver&&) = delete;

    void beginFrame() override;
    void beginPass(std::string_view pass) override;
    void endPass(std::string_view pass) override;
    void endFrame() override;

    /// The passes of the last frame, in execution order. Waits for the GPU
    /// timer results of that frame (the context must be current).
    [[nodiscard]] const std::vector<GlPassTiming>& timings();

    [[nodiscard]] bool hasDebugGroups() const noexcept { return pushGroup_ != nullptr; }
    [[nodiscard]] bool hasTimerQueries() const noexcept { return timerQueries_; }

    /// Deletes the queries; the context must be current. Safe to call twice.
    void release() noexcept;

  private:
    using PushGroup = void (*)(unsigned, unsigned, int, const char*);
    using PopGroup = void (*)();
    using Clock = std::chrono::steady_clock;

    QOpenGLFunctions_4_1_Core* gl_ = nullptr;
    QOpenGLContext* context_ = nullptr;
    PushGroup pushGroup_ = nullptr;
    PopGroup popGroup_ = nullptr;
    bool timerQueries_ = false;
    bool finishEachPass_ = false;
    std::vector<unsigned> queries_;  ///< pool, two timestamps per pass of a frame
    std::vector<GlPassTiming> timings_;
    std::size_t resolved_ = 0;  ///< timings_ entries whose GPU time is read
    Clock::time_point start_;
};

/// Checks glGetError(); throws RenderError naming `what` on an error.
void checkGlError(QOpenGLFunctions_4_1_Core& gl, std::string_view what);

/// The OpenGL 4.1 core functions of the current context. Throws RenderError
/// when no context is current or it is not OpenGL >= 4.1 core.
[[nodiscard]] QOpenGLFunctions_4_1_Core& currentGl41();

/// The largest width and height the current context renders in one piece:
/// min(GL_MAX_TEXTURE_SIZE, GL_MAX_RENDERBUFFER_SIZE, GL_MAX_VIEWPORT_DIMS).
[[nodiscard]] int maxRenderSide(QOpenGLFunctions& gl);

}  // namespace vv::render

namespace vv::render {

/// Compiles and links a program from two shader resources (e.g.
/// ":/vv/shaders/fullscreen.vert"), binding fragment output 0 to "fragColor".
/// Throws RenderError naming `what` with the GL log when a shader does not
/// compile or the program does not link.
[[nodiscard]] unsigned buildProgram(QOpenGLFunctions_4_1_Core& gl, std::string_view vertexResource,
                                    std::string_view fragmentResource, std::string_view what);

/// Like buildProgram() above, with a fragment shader made of several resources
/// concatenated in order (the first one starts with #version; e.g. a shared
/// material followed by a main()), and with `#define NAME` for each of
/// `fragmentDefines` right after its #version line: compile-time variants of
/// one shader (software rasterisers such as llvmpipe run both sides of a
/// branch on a uniform, so a variant is what actually skips the work).
/// Errors name every part and define.
[[nodiscard]] unsigned buildProgram(QOpenGLFunctions_4_1_Core& gl, std::string_view vertexResource,
                                    std::span<const std::string_view> fragmentResources,
                                    std::string_view what,
                                    std::span<const std::string_view> fragmentDefines = {});

}  // namespace vv::render
