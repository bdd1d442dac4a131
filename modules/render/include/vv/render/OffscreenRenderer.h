// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QImage>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "vv/render/Camera.h"
#include "vv/render/DisplaySettings.h"
#include "vv/render/FrameRenderer.h"
#include "vv/render/RefinedGeometry.h"
#include "vv/render/ViewAnnotations.h"
#include "vv/render/ViewRenderer.h"
#include "vv/scene/Mesh.h"
#include "vv/scene/MeshTopology.h"

class QOffscreenSurface;
class QOpenGLContext;

namespace vv::render {

/// What to render offscreen and how.
struct OffscreenOptions {
    int width = 1024;  ///< pixels, 1..16384
    int height = 768;  ///< pixels, 1..16384
    /// The display settings: background, mesh style, VSS (on by default:
    /// chromadepth, fast solver; void pixels show it where one exists, else
    /// the background), vessel cue (none by default), ambient occlusion over
    /// vessels + VSS and FXAA on the final image (both on by default; the
    /// VSS input is unaffected). Painted over the image: the legends of the
    /// scales in use (LegendPainter: the depth legend when a VSS is shown,
    /// the parameter legend when an array is), and the orientation marker
    /// and scale bar (paintViewAnnotations with the frame's camera and the
    /// scene's frame, viewAnnotations()). Unlike DisplaySettings{}, all three
    /// are off by default: the CLI and the GUI's exports take them from
    /// their display settings.
    DisplaySettings display{.vss = {},
                            .ao = {},
                            .cue = {},
                            .style = {},
                            .background = kDefaultBackground,
                            .legends = false,
                            .orientationMarker = false,
                            .scaleBar = false,
                            .antialiasing = true};
    /// The view; nullopt = the scene's home orientation (homeRotation() of
    /// its frame: anterior for the patient frame) fitted to the scene.
    /// A given camera gets its viewport set to width x height, unless it has
    /// a window (Camera::setWindow: one tile of a larger image): then its
    /// viewport stays and the window must be width x height.
    std::optional<Camera> camera;
    /// Multisampling samples: kept for compatibility and ignored, because the
    /// frame's G-buffer is not multisampled (the VSS needs one depth per
    /// pixel); edges are anti-aliased by FXAA instead (display.antialiasing).
    int samples = 4;
    /// Volume depth source: a volume ray cast into the G-buffer after the
    /// scene's meshes (FrameRenderer::setVolume) at the iso value `isoValue`
    /// (its units, e.g. HU); nullptr = none. Its world bounds join the
    /// scene's for the default camera and the clip planes.
    std::shared_ptr<const scene::Volume> volume;
    float isoValue = 150.0F;
    /// A refined copy of the scene (app::smoothCopyOf), drawn where its
    /// facets are coarse for the view when display.smoothCoarseMeshes is
    /// on; nullopt: the scene as it is. It must be the copy of the scene
    /// rendered (one mesh per mesh; else InvalidArgumentError).
    std::optional<RefinedGeometry> refined;
};

/// The orientation marker and scale bar `display` asks for, named in
/// `frame` (the rendered scene's scene::Scene::frame).
[[nodiscard]] ViewAnnotations viewAnnotations(const DisplaySettings& display,
                                              SceneFrame frame) noexcept;

/// Renders scenes into images without a window: its own OpenGL 4.1 core
/// context on a QOffscreenSurface and the same ViewRenderer (scene upload,
/// style, closures; its FrameRenderer's render graph: G-buffer, VSS solve,
/// VSS shading, composite) as the viewer, solving the VSS synchronously.
/// The graph's cache lives across render() calls, so a second render of the
/// same scene and view re-runs only what changed (e.g. a new colour scale
/// re-shades but does not re-solve). So do the scene's meshes on the GPU:
/// render() attaches the caller's scene for the call only, and a later
/// render of a scene with the same content (sceneFingerprint) — the tiles of
/// an export, a report's second view — uploads nothing again.
///
/// Needs a QGuiApplication. A renderer is created, used and destroyed on one
/// thread: its OpenGL context belongs to that thread. The default
/// constructor makes its own QOffscreenSurface, so it works on the GUI thread
/// only (Qt creates and destroys surfaces there). To render on a worker
/// thread, create the surface on the GUI thread with createSurface() and
/// construct the renderer on the worker with it (the context is created and
/// made current there; Qt allows a surface to be used from another thread).
/// With Qt's "offscreen" platform plugin there may be no OpenGL at all; use
/// xcb (under Xvfb when headless).
class OffscreenRenderer {
  public:
    /// Creates the surface and the context (on the GUI thread). Throws
    /// RenderError when there is no QGuiApplication or no OpenGL 4.1 core
    /// context can be made (the message says so and what was obtained
    /// instead), or the shaders fail.
    OffscreenRenderer();
    /// Creates the context on the calling thread (may be a worker) for
    /// `surface`, which was made by createSurface() on the GUI thread, is not
    /// owned, and must outlive the renderer (destroy it on the GUI thread
    /// afterwards). Throws as the default constructor.
    explicit OffscreenRenderer(QOffscreenSurface& surface);
    /// A surface in the format the renderer needs. Call on the GUI thread.
    /// Throws RenderError when there is no QGuiApplication or the surface
    /// cannot be created.
    [[nodiscard]] static std::unique_ptr<QOffscreenSurface> createSurface();
    ~OffscreenRenderer();
    OffscreenRenderer(const OffscreenRenderer&) = delete;
    OffscreenRenderer& operator=(const OffscreenRenderer&) = delete;

    /// Renders `scene` (may have no meshes: then the image is all background)
    /// at options.width x options.height. Returns an opaque image in
    /// QImage::Format_RGB32. Throws InvalidArgumentError for a size out of
    /// range and RenderError when GL fails (framebuffer, out of memory).
    [[nodiscard]] QImage render(const scene::Scene& scene, const OffscreenOptions& options);

    /// Renders only the G-buffer of `scene` (like render()) and returns its
    /// linear depth: width x height, row 0 = top, +Inf on background. Throws
    /// like render().
    [[nodiscard]] Image<float> renderDepth(const scene::Scene& scene,
                                           const OffscreenOptions& options);

    /// The camera render() draws `scene` with for `options`. Throws
    /// InvalidArgumentError when the camera's window does not match the size.
    [[nodiscard]] static Camera cameraFor(const scene::Scene& scene,
                                          const OffscreenOptions& options);

    /// The following renders show `external`'s VSS instead of solving one
    /// (FrameRenderer::setExternalVss); nullopt = solve as usual.
    void setExternalVss(std::optional<ExternalVss> external);

    /// Forgets the cached passes and frees their textures (GPU memory).
    void clearCache();

    /// How often a scene's meshes were uploaded: once per scene content
    /// (sceneFingerprint), not once per render.
    [[nodiscard]] std::uint64_t sceneUploads() const noexcept;

    /// MeshRenderer::setBackFaceCulling for the following renders (on by default).
    void setBackFaceCulling(bool enabled);
    /// Whether the last render drew the refined copy of its scene
    /// (OffscreenOptions::refined) rather than the scene.
    [[nodiscard]] bool lastFrameRefined() const noexcept;
    /// The scene the last render of `scene` with `options` drew: the refined
    /// copy's when lastFrameRefined(), else `scene` (for what reads the same
    /// geometry on the CPU: rasterizeDepth).
    [[nodiscard]] const scene::Scene& lastDrawnScene(
        const scene::Scene& scene, const OffscreenOptions& options) const noexcept;
    /// MeshRenderer::lastCulledMeshes of the last render's G-buffer.
    [[nodiscard]] std::size_t lastCulledMeshes() const noexcept;

    /// The value range the colour map spanned in the last render(); nullopt
    /// when no array was shown.
    [[nodiscard]] std::optional<std::pair<float, float>> lastRange() const noexcept {
        return lastRange_;
    }

    /// The passes of the last render() (state, reason, CPU time): e.g.
    /// "vss-solve" is Culled with the VSS off and Cached when only the colour
    /// scale changed.
    [[nodiscard]] const std::vector<PassInfo>& lastPasses() const noexcept;
    /// CPU and GPU milliseconds of the passes that ran in the last render().
    [[nodiscard]] std::vector<GlPassTiming> lastTimings();
    /// The depth range the last render()'s vessel cue used; nullopt without a cue.
    [[nodiscard]] const std::optional<std::pair<double, double>>& lastCueDepthRange()
        const noexcept;
    /// The VSS of the last render().
    [[nodiscard]] const VssFrameStatus& vssStatus() const noexcept;
    /// The G-buffer's linear depth read by the last VSS solve (row 0 = top,
    /// like the image; +Inf on background); empty when no solve ran yet.
    [[nodiscard]] Image<float> lastLinearDepth() const;
    /// The last render's graph as text, for debugging.
    [[nodiscard]] const std::string& lastGraphText() const noexcept;

    /// "renderer / OpenGL version" of the context.
    [[nodiscard]] const std::string& glDescription() const noexcept { return description_; }

    /// The largest width and height this context renders in one piece:
    /// min(GL_MAX_TEXTURE_SIZE, GL_MAX_RENDERBUFFER_SIZE, GL_MAX_VIEWPORT_DIMS),
    /// queried in the renderer's own context (so on the thread that uses it;
    /// no surface is created).
    [[nodiscard]] int maxRenderSide();

  private:
    /// Creates the context on `surface_` and the frame renderer.
    void createContext();
    /// Attaches `scene` to the view (uploading its meshes when its content is
    /// new) with the options' style, display settings and volume (context
    /// current; detach it again after the render); returns the camera.
    Camera setUpScene(const scene::Scene& scene, const OffscreenOptions& options);

    std::unique_ptr<QOffscreenSurface> ownSurface_;  ///< null with a borrowed surface
    QOffscreenSurface* surface_ = nullptr;
    std::unique_ptr<QOpenGLContext> context_;
    std::unique_ptr<ViewRenderer> view_;
    std::shared_ptr<GlTexture> output_;
    std::string description_;
    std::optional<std::pair<float, float>> lastRange_;
};

}  // namespace vv::render
