// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstddef>
#include <map>
#include <vector>

#include "vv/render/RenderGraph.h"

class QOpenGLContext;
class QOpenGLFunctions_4_1_Core;

namespace vv::render {

/// The GL side of the render targets passes declare to the graph
/// (RenderGraph::Builder::declareRenderTarget): one framebuffer object per
/// set of attachments, made on first use and kept while its textures live.
///
/// A target of one colour texture and no depth draws into that texture's own
/// framebuffer (GlTexture::framebuffer(); also a wrapped one, e.g. the
/// screen). Other sets are keyed by their attachments' texture names; each
/// GlTexture made by GlResourceAllocator tells the cache when it dies
/// (forget()), so a name GL hands out again never finds a stale framebuffer.
/// Create and use it with one context current.
class GlFramebufferCache {
  public:
    explicit GlFramebufferCache(QOpenGLFunctions_4_1_Core& gl);
    /// Deletes the framebuffers when the context is current.
    ~GlFramebufferCache();
    GlFramebufferCache(const GlFramebufferCache&) = delete;
    GlFramebufferCache& operator=(const GlFramebufferCache&) = delete;
    GlFramebufferCache(GlFramebufferCache&&) = delete;
    GlFramebufferCache& operator=(GlFramebufferCache&&) = delete;

    /// The framebuffer that draws into `target`, with colour attachment i =
    /// target.colors[i] (draw buffers set to all of them) and the depth
    /// attachment. Does not bind it. Throws RenderError when an attachment is
    /// not a GL texture (a wrapped framebuffer can only be a target alone) or
    /// the framebuffer is incomplete.
    [[nodiscard]] unsigned framebuffer(const RenderTarget& target);

    /// Forgets (and, with the context current, deletes) the framebuffers that
    /// have texture `texture` attached.
    void forget(unsigned texture) noexcept;

    /// Framebuffers made and kept now.
    [[nodiscard]] std::size_t size() const noexcept { return framebuffers_.size(); }

  private:
    QOpenGLFunctions_4_1_Core* gl_;
    QOpenGLContext* context_;
    /// Key: the colour attachments' texture names, then the depth's (0 = none).
    std::map<std::vector<unsigned>, unsigned> framebuffers_;
};

}  // namespace vv::render
