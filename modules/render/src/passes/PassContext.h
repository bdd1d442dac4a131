// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// What the GL passes of a frame share besides graph resources: GL functions,
// the programs (each pass names its own), the framebuffers of declared render targets, the
// depth-scale texture and the mesh and volume renderers that draw. Internal to vv::render.

#include <glm/glm.hpp>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "vv/colormaps/DepthScale.h"
#include "vv/render/GlFramebufferCache.h"
#include "vv/render/GlResources.h"
#include "vv/render/MeshRenderer.h"
#include "vv/render/Program.h"
#include "vv/render/RenderGraph.h"
#include "vv/render/VolumeRenderer.h"

class QOpenGLFunctions_4_1_Core;

namespace vv::render {

class RectBatch;

/// The vertex shader of full-screen passes: one triangle over the target.
inline constexpr std::string_view kFullscreenVertex = ":/vv/shaders/fullscreen.vert";

/// How a pass builds one of its programs: a vertex shader resource, the
/// fragment resources concatenated, `#define`s, and a name for errors (also
/// the program's key in PassPrograms: one name, one program).
struct ProgramSpec {
    std::string_view vertex;
    std::span<const std::string_view> fragments;
    std::string_view what;
    std::span<const std::string_view> defines;
};

/// The programs of the frame's passes. Each pass names its own programs
/// (ProgramSpec, in its file) and gets them from here; a program is built
/// the first time a pass runs with it, so a frame that never runs a pass
/// never compiles its shaders. Lives with the renderer's GL context.
class PassPrograms {
  public:
    /// Keeps `gl` (the context current now and whenever get() is called).
    explicit PassPrograms(QOpenGLFunctions_4_1_Core& gl) noexcept : gl_(&gl) {}

    /// The program `spec.what`, built from `spec` on first use. Throws
    /// RenderError when a shader fails (and builds it again next time).
    [[nodiscard]] const Program& get(const ProgramSpec& spec);

  private:
    QOpenGLFunctions_4_1_Core* gl_;
    std::map<std::string, Program, std::less<>> programs_;
};

/// The depth colour scale as a 1-D RGBA8 texture, uploaded when it changes.
class DepthScaleLut {
  public:
    static constexpr int kSize = 256;

    /// Makes the texture (context current).
    explicit DepthScaleLut(QOpenGLFunctions_4_1_Core& gl);
    /// Deletes the texture when its context is current.
    ~DepthScaleLut();
    DepthScaleLut(const DepthScaleLut&) = delete;
    DepthScaleLut& operator=(const DepthScaleLut&) = delete;
    DepthScaleLut(DepthScaleLut&&) = delete;
    DepthScaleLut& operator=(DepthScaleLut&&) = delete;

    /// Holds `scale` afterwards (uploads it unless it is already there).
    /// Throws RenderError when GL fails.
    void upload(colormaps::DepthScale scale);
    [[nodiscard]] unsigned texture() const noexcept { return texture_; }

  private:
    QOpenGLFunctions_4_1_Core* gl_;
    QOpenGLContext* context_;
    unsigned texture_ = 0;
    std::optional<colormaps::DepthScale> uploaded_;
};

/// Handed by value to every pass: pointers to what FrameRenderer owns. A
/// pass's execute callback captures it by value.
struct PassContext {
    QOpenGLFunctions_4_1_Core* gl = nullptr;
    PassPrograms* programs = nullptr;
    GlFramebufferCache* framebuffers = nullptr;
    DepthScaleLut* scaleLut = nullptr;
    unsigned emptyVao = 0;       ///< for the full-screen triangle of fullscreen.vert
    RectBatch* rects = nullptr;  ///< for rects.vert
    MeshRenderer* meshes = nullptr;
    VolumeRenderer* volume = nullptr;

    /// Binds (GL_FRAMEBUFFER) the framebuffer of render target `id` of the
    /// running pass. Throws like GlFramebufferCache::framebuffer().
    void bindRenderTarget(const RenderGraph::Resources& resources, RenderTargetId id) const;
    /// What a full-screen pass starts with: bindRenderTarget(), a viewport of
    /// `size`, no depth test, no blending.
    void beginFullscreen(const RenderGraph::Resources& resources, RenderTargetId id,
                         glm::ivec2 size) const;
};

/// A single-sampled texture of `size` and `format`.
[[nodiscard]] inline TextureDescriptor sized(glm::ivec2 size, TextureFormat format) noexcept {
    return TextureDescriptor{size.x, size.y, format, 1};
}

/// The GL texture behind a graph texture; throws RenderGraphError for another backend's.
[[nodiscard]] const GlTexture& glTex(const Texture& texture);

/// Binds `texture` (0: none) to the active unit's 2-D target and, unless it
/// is 0, gives it bilinear (`linear`) or nearest taps for minification and
/// magnification. Pooled textures are nearest; a pass that reads one
/// bilinearly sets it back (endBilinearPass()).
void bindFiltered(QOpenGLFunctions_4_1_Core& gl, unsigned texture, bool linear);

/// Ends a full-screen pass that read `texture` on the active unit with
/// bilinear taps: nearest again and unbound, no program, the depth test back
/// on; then checks GL (RenderError naming `what`).
void endBilinearPass(QOpenGLFunctions_4_1_Core& gl, unsigned texture, const char* what);

/// Draws the full-screen triangle of fullscreen.vert with `vao`, then leaves
/// no state behind: no texture (1-D or 2-D) on units 0 .. units-1 (unit 0
/// active afterwards), no program.
void drawFullscreenAndUnbind(QOpenGLFunctions_4_1_Core& gl, unsigned vao, int units);

}  // namespace vv::render
