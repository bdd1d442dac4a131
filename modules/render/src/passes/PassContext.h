// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// What the GL passes of a frame share besides graph resources: GL functions,
// programs, the framebuffers of declared render targets, the depth-scale
// texture and the mesh and volume renderers that draw. Internal to vv::render.

#include <glm/glm.hpp>
#include <optional>

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

/// The full-screen programs of the frame's passes.
struct FullscreenPrograms {
    Program vss;       ///< vss.frag: the shader fits the height field's slopes
    Program vssQuick;  ///< vss.frag with QUICK_NORMALS (preview frames)
    Program vssSlope;  ///< vss.frag with SLOPE_TEXTURE (slopes from the solver)
    Program composite;
    /// composite.frag with REDUCED_VSS: the VSS's colour below the render size.
    Program compositeReducedVss;
    Program ssao;
    Program aoBlur;
    Program fxaa;
    Program upscale;  ///< upscale.frag: a reduced frame into the target, iso-lines at its size
    /// upscale.frag with COLOR_ONLY: where no iso-line reaches (UpscaleTiles.h).
    Program upscaleColor;
    /// upscale.frag with EDGES (and COLOR_ONLY) over rects.vert: along the
    /// vessels' silhouettes (with the iso-lines, and without any).
    Program upscaleEdges;
    Program upscaleEdgesColor;

    /// Builds them all in the current context. Throws RenderError when a
    /// shader fails.
    [[nodiscard]] static FullscreenPrograms build(QOpenGLFunctions_4_1_Core& gl);
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
    const FullscreenPrograms* programs = nullptr;
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

/// Draws the full-screen triangle of fullscreen.vert with `vao`, then leaves
/// no state behind: no texture (1-D or 2-D) on units 0 .. units-1 (unit 0
/// active afterwards), no program.
void drawFullscreenAndUnbind(QOpenGLFunctions_4_1_Core& gl, unsigned vao, int units);

}  // namespace vv::render
