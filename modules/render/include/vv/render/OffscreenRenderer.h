// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QImage>
#include <glm/glm.hpp>
#include <memory>
#include <optional>
#include <string>

#include "vv/io/Mesh.h"
#include "vv/render/Camera.h"
#include "vv/render/MeshRenderer.h"

class QOffscreenSurface;
class QOpenGLContext;

namespace vv::render {

/// What to render offscreen and how.
struct OffscreenOptions {
    int width = 1024;  ///< pixels, 1..16384
    int height = 768;  ///< pixels, 1..16384
    /// Background colour, sRGB in [0, 1].
    glm::vec3 background{0.13F, 0.14F, 0.16F};
    MeshStyle style;
    /// The view; nullopt = the default orientation fitted to the scene.
    /// A given camera gets its viewport set to width x height.
    std::optional<Camera> camera;
    /// Multisampling samples (anti-aliasing); 0 or 1 = none. Reduced to what
    /// the GL implementation supports.
    int samples = 4;
};

/// Renders scenes into images without a window: its own OpenGL 4.1 core
/// context on a QOffscreenSurface, a multisampled framebuffer object, the
/// same Camera and MeshRenderer as the viewer.
///
/// Needs a QGuiApplication and must be created, used and destroyed on the
/// thread that owns it (the GUI thread). With Qt's "offscreen" platform
/// plugin there may be no OpenGL at all; use xcb (under Xvfb when headless).
class OffscreenRenderer {
  public:
    /// Creates the context. Throws RenderError when there is no
    /// QGuiApplication or no OpenGL 4.1 core context can be made (the message
    /// says so and what was obtained instead), or the shaders fail.
    OffscreenRenderer();
    ~OffscreenRenderer();
    OffscreenRenderer(const OffscreenRenderer&) = delete;
    OffscreenRenderer& operator=(const OffscreenRenderer&) = delete;

    /// Renders `scene` (may have no meshes: then the image is all background)
    /// at options.width x options.height. Returns an opaque image in
    /// QImage::Format_RGB32. Throws InvalidArgumentError for a size out of
    /// range and RenderError when GL fails (framebuffer, out of memory).
    [[nodiscard]] QImage render(const io::Scene& scene, const OffscreenOptions& options);

    /// The value range the colour map spanned in the last render(); nullopt
    /// when no array was shown.
    [[nodiscard]] std::optional<std::pair<float, float>> lastRange() const noexcept {
        return lastRange_;
    }

    /// "renderer / OpenGL version" of the context.
    [[nodiscard]] const std::string& glDescription() const noexcept { return description_; }

  private:
    std::unique_ptr<QOffscreenSurface> surface_;
    std::unique_ptr<QOpenGLContext> context_;
    std::unique_ptr<MeshRenderer> renderer_;
    std::string description_;
    std::optional<std::pair<float, float>> lastRange_;
};

}  // namespace vv::render
