// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>
#include <functional>
#include <glm/glm.hpp>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "vv/colormaps/DepthScale.h"
#include "vv/core/Image.h"
#include "vv/render/Camera.h"
#include "vv/render/FrameSettings.h"
#include "vv/render/GlResources.h"
#include "vv/render/MeshRenderer.h"
#include "vv/render/RenderGraph.h"
#include "vv/render/VolumeRenderer.h"
#include "vv/scene/Mesh.h"
#include "vv/vss/DepthNormalization.h"
#include "vv/vss/Solver.h"

class QOpenGLContext;

namespace vv::render {

/// Asynchronous solves so far (FrameRenderer::solveCounters()).
struct SolveCounters {
    std::uint64_t submitted = 0;  ///< jobs handed to the worker
    std::uint64_t started =
        0;  ///< jobs the worker picked up (a newer request replaces a queued one)
    std::uint64_t completed = 0;  ///< solves that finished
    std::uint64_t cancelled = 0;  ///< running solves stopped by a newer request
};

// --- Probe (G-buffer read-back of single pixels) -------------------------
/// What the last frame's G-buffer holds at one pixel (FrameRenderer::probe).
struct ProbeSample {
    std::uint32_t objectId = 0;  ///< 1 + the mesh's index in the scene (never 0 here)
    float linearDepth = 0.0F;    ///< distance along the viewing axis, scene units, > 0
    /// The shown array's value; NaN when no array is shown or the vertex has no data.
    float value = 0.0F;
    glm::vec3 viewPosition{0.0F};   ///< view space (the eye at the origin, looking down -z)
    glm::vec3 worldPosition{0.0F};  ///< scene coordinates
};
// --- end probe -------------------------------------------------------------

/// A VSS solved outside the renderer for a whole frame, for frames drawn in
/// parts (tiled export, report::renderView): the solve of the full image's
/// depth, cut to the part being drawn, plus the full frame's ranges, so that
/// every part shades, occludes and cues alike (FrameRenderer::setExternalVss).
struct ExternalVss {
    /// Must change whenever anything below changes: the passes that use it
    /// re-run when it does (the render graph caches by it).
    std::uint64_t version = 0;
    /// z' on void pixels, z on vessel pixels, NaN = no VSS, at the frame's
    /// render size in GL row order (bottom row first); empty = no VSS.
    Image<float> height;
    double dmin = 0.0;  ///< the range z is normalised over, scene units
    double dmax = 0.0;
    double solveMilliseconds = 0.0;
    double errorBound = std::numeric_limits<double>::quiet_NaN();
    /// The whole frame's visible vessel depth range (what a vessel cue uses
    /// without a VSS); nullopt when no vessel is visible.
    std::optional<std::pair<double, double>> visibleRange;
};

/// A content hash of what a scene draws: positions, normals and indices of
/// every mesh and its point arrays (names, components, values), for the
/// render graph's caching and re-using a scene's meshes on the GPU when the
/// scene object is not kept (ViewRenderer::setScene).
[[nodiscard]] std::uint64_t sceneFingerprint(const scene::Scene& scene) noexcept;

/// Renders a frame through the render graph (ARCHITECTURE.md, "How a frame
/// flows"), with OpenGL 4.1 core:
///
///  - "geometry": the vessels into the G-buffer (linear view depth R32F,
///    normal RGBA16F, object id R32UI, Depth32F); cached while camera,
///    viewport and scene stay.
///  - "depth-readback": the linear depth read back to the CPU, once per
///    G-buffer (cached with it), for the solve and the depth range.
///  - "vss-solve": solves the VSS of that depth (vss::solve, mask = finite
///    depth) and uploads the height image (R32F); cached while the depth,
///    p, solver and tolerance stay, so colour scale and iso-line changes
///    never re-solve. Synchronous, or on a worker thread (see SolveMode).
///  - "vessel-shading": the vessel colour (MeshRenderer's material or array
///    through the colour map, Blinn-Phong, optionally a VesselCue), deferred
///    from the G-buffer. A cue that needs depth reads the VSS's dmin / dmax
///    ("vss-solve") or, without a shown VSS, the visible range that
///    "depth-range" finds in the read-back depth (cached while the view
///    stays).
///  - "vss-shading": depth colour scale, iso-lines and height-field lighting.
///  - "ssao", "ao-blur" (AoSettings::enabled): occlusion from the linear
///    depth and the VSS height, then a depth-aware blur; cached while depth,
///    VSS and radius stay (the colour scale does not re-run them); at half
///    resolution per axis above AoSettings::fullResolutionPixels.
///  - "translucent": objects with opacity below 1 (ObjectStyle::opacity),
///    which the G-buffer leaves out, drawn forward back to front over a copy
///    of the opaque depth into a premultiplied layer
///    (MeshRenderer::drawTranslucent); culled when no object is translucent.
///  - "composite": the translucent layer over the vessels over the VSS over
///    the background, darkened by the AO, into the target (or, with
///    anti-aliasing, into a texture).
///  - "fxaa" (FrameSettings::antialiasing): FXAA into the target. The
///    G-buffer stays single-sampled, so the solve's depth is unchanged.
///
/// With the VSS off, nothing reads the VSS passes' outputs and the graph
/// culls them. The GL context current at initialize() must be current for
/// every call that touches GL; call release() before it goes away.
class FrameRenderer {
  public:
    enum class SolveMode {
        /// The solve runs inside the frame (CLI, offscreen, tests).
        Synchronous,
        /// The solve runs on a worker thread; the frame shows the previous
        /// VSS (same viewport size) or none until the result arrives, then
        /// `onSolved` is called on the worker thread: schedule a new frame
        /// from it (e.g. a queued QWidget::update()). A newer request cancels
        /// a stale solve; a stale solve that finishes while a newer request is
        /// queued is kept for display but does not call `onSolved`.
        Asynchronous,
    };

    FrameRenderer();
    ~FrameRenderer();
    FrameRenderer(const FrameRenderer&) = delete;
    FrameRenderer& operator=(const FrameRenderer&) = delete;
    FrameRenderer(FrameRenderer&&) = delete;
    FrameRenderer& operator=(FrameRenderer&&) = delete;

    /// Builds shaders and GL objects in the current context. Throws
    /// RenderError when no OpenGL 4.1 core context is current or a shader
    /// fails.
    void initialize();
    [[nodiscard]] bool initialized() const noexcept;
    /// Deletes every GL object (the context must be current) and stops the
    /// worker. Safe to call more than once.
    void release() noexcept;

    /// The mesh renderer: set its scene and style through it (context current).
    [[nodiscard]] MeshRenderer& meshRenderer() noexcept { return meshes_; }
    [[nodiscard]] const MeshRenderer& meshRenderer() const noexcept { return meshes_; }

    // --- Volume depth source (issue 5) ------------------------------------
    /// A volume drawn into the G-buffer after the meshes by first-hit
    /// iso-surface ray casting at `isoValue` (VolumeRenderer), so the VSS,
    /// shading and cues work on it as on meshes; nullptr = none. The volume
    /// is treated as immutable (a changed one needs a new object). Its object
    /// id is 1 + the number of meshes. Needs no GL context (uploads lazily).
    void setVolume(std::shared_ptr<const scene::Volume> volume, float isoValue);
    [[nodiscard]] const std::shared_ptr<const scene::Volume>& volume() const noexcept {
        return volume_.volume();
    }
    // --- end volume depth source -------------------------------------------

    /// Tells the graph that the scene's content changed (every value
    /// different from the last one re-runs the geometry and the solve).
    void setSceneRevision(std::uint64_t revision) noexcept { sceneRevision_ = revision; }

    /// Synchronous by default. Switching cancels a running solve.
    void setSolveMode(SolveMode mode, std::function<void()> onSolved = {});
    [[nodiscard]] SolveMode solveMode() const noexcept { return mode_; }

    /// Draws one frame into `target` and leaves that framebuffer bound.
    /// Throws RenderError when GL fails, InvalidArgumentError for bad solver
    /// options (p, tolerance), and what the graph throws.
    void render(const Camera& camera, const FrameSettings& settings, const FrameTarget& target);

    /// Runs only the geometry pass of this view (cached like render()'s) and
    /// returns the G-buffer's linear depth at the render size: GL row order
    /// (bottom row first), +Inf on background. Shades nothing; the target is
    /// left untouched but bound. Throws like render().
    [[nodiscard]] Image<float> renderDepth(const Camera& camera, const FrameSettings& settings,
                                           const FrameTarget& target);

    /// Frames drawn while `external` is set show its VSS instead of solving
    /// one (its height must have the render size: else render() throws
    /// InvalidArgumentError) and take a vessel cue's range from it;
    /// nullopt = solve as usual. Needs no GL context.
    void setExternalVss(std::optional<ExternalVss> external);

    /// Asynchronous mode with the VSS on: runs only the geometry pass of this
    /// view and submits its solve, shading nothing (the target is left
    /// untouched but bound). For the moment the camera settles: the exact
    /// solve starts at once instead of after a whole frame, and the frame
    /// drawn when it arrives finds the G-buffer cached. Returns false and
    /// does nothing otherwise. Throws like render().
    bool prepareSolve(const Camera& camera, const FrameSettings& settings,
                      const FrameTarget& target);

    /// The size the last frame's passes ran at (device pixels): the target's
    /// size scaled by FrameSettings::resolutionScale.
    [[nodiscard]] glm::ivec2 lastRenderSize() const noexcept { return renderSize_; }
    /// The size the last frame's VSS was solved and shaded at: its render
    /// size, or less (FrameSettings::vssResolutionScale).
    [[nodiscard]] glm::ivec2 lastVssSize() const noexcept { return vssSize_; }
    /// True when the last frame's G-buffer came from the simplified (preview) meshes.
    [[nodiscard]] bool lastFrameSimplified() const noexcept {
        return lastGeometryLevel_ > 0 && lastGeometryLevel_ != kRefinedLevel;
    }
    /// The meshes the last frame drew: 0 = the scene's, k = preview level k
    /// (MeshRenderer::drawGBuffer).
    [[nodiscard]] std::size_t lastGeometryLevel() const noexcept { return lastGeometryLevel_; }

    /// The compiled graph of the last frame (states, reasons, CPU times).
    [[nodiscard]] const std::vector<PassInfo>& lastPasses() const noexcept { return passes_; }
    /// The last frame's graph as text (RenderGraph::toText()).
    [[nodiscard]] const std::string& lastGraphText() const noexcept { return graphText_; }
    /// CPU and GPU time of the passes that ran in the last frame; waits for
    /// the GPU timers (context current).
    [[nodiscard]] const std::vector<GlPassTiming>& lastTimings();
    [[nodiscard]] const VssFrameStatus& vssStatus() const noexcept { return status_; }
    /// The depth range (dmin, dmax, scene units) the last frame's vessel cue
    /// normalised with; nullopt when the cue was None.
    [[nodiscard]] const std::optional<std::pair<double, double>>& lastCueDepthRange()
        const noexcept {
        return cueRange_;
    }

    /// The linear depth the last solve read back from the G-buffer: row 0 is
    /// the BOTTOM row (GL order), +Inf on background pixels. Empty before the
    /// first solve. For checks and depth export.
    [[nodiscard]] const Image<float>& lastSolvedDepth() const noexcept;

    /// Asynchronous mode: requests the solve that render(camera, settings,
    /// target) would request, from the linear depth the last solve request
    /// read back, when that depth shows the same view (camera, render size,
    /// scene revision): e.g. the exact solve as soon as the camera stops,
    /// reusing the last preview frame's depth, without drawing a frame first.
    /// Returns true when that solve is now queued, running or done (onSolved
    /// follows when it finishes); false, doing nothing, when the depth shows
    /// another view, the VSS is off or the mode is synchronous. Needs no GL
    /// context. Throws InvalidArgumentError for bad solver options.
    bool requestSolve(const Camera& camera, const FrameSettings& settings,
                      const FrameTarget& target);

    /// Asynchronous mode: true while a solve is queued or running. A result
    /// that arrives while this holds is already stale (a newer request will
    /// arrive after it): no need to draw a frame for it.
    [[nodiscard]] bool solveInProgress() const;
    /// Asynchronous mode: blocks until no solve is queued or running (tests).
    void waitForSolves();
    /// Asynchronous mode: how many solves were submitted, finished, cancelled
    /// since setSolveMode() (all zero in synchronous mode).
    [[nodiscard]] SolveCounters solveCounters() const;
    /// The VSS height the last frame showed (GL row order, NaN = no VSS);
    /// empty when none was shown. A copy, for checks.
    [[nodiscard]] Image<float> shownHeight() const;

    /// Forgets every cached pass result and pooled texture (context current).
    void clearCache();

    // --- Probe (G-buffer read-back of single pixels) ---------------------
    /// Reads pixel (x, y) of the last frame's G-buffer: x, y in render-size
    /// pixels (lastRenderSize()), row 0 at the BOTTOM (GL order). `camera`
    /// must be the camera that frame was rendered with (its aspect and field
    /// of view turn the depth into a position). Returns nullopt when no frame
    /// was rendered yet, (x, y) is outside the render size, or no vessel
    /// covers the pixel. Reads three texels (cheap enough per mouse move).
    /// Context current; throws RenderError when GL fails.
    [[nodiscard]] std::optional<ProbeSample> probe(const Camera& camera, int x, int y) const;
    /// The visible vessels' linear depth range (min, max; scene units) in the
    /// last frame's G-buffer, nullopt when no vessel is visible or no frame
    /// was rendered. Uses the depth the frame read back ("depth-readback")
    /// when it did; otherwise reads the whole linear depth back once (a few
    /// ms) and keeps it for that frame. Context current; throws RenderError
    /// when GL fails.
    [[nodiscard]] std::optional<std::pair<float, float>> visibleDepthRange() const;
    // --- end probe -------------------------------------------------------

  private:
    struct Impl;
    MeshRenderer meshes_;
    // Volume depth source: the ray caster, its iso value and a revision that
    // changes with either (geometry pass dependsOn, depth view keys).
    VolumeRenderer volume_;
    float volumeIso_ = 0.0F;
    std::uint64_t volumeRevision_ = 0;
    std::unique_ptr<Impl> impl_;
    SolveMode mode_ = SolveMode::Synchronous;
    /// What renderGraph() runs: the whole frame, up to the solve
    /// (prepareSolve) or the geometry only (renderDepth).
    enum class GraphMode { Frame, SolveOnly, DepthOnly };
    void renderGraph(const Camera& camera, const FrameSettings& settings, const FrameTarget& target,
                     GraphMode mode);
    /// The meshes a frame of `camera` and `settings` at `renderSize` draws:
    /// 0 = the scene's, k = the mesh renderer's preview level k
    /// (previewLevelFor), kRefinedLevel = its refined copy (refinedWanted).
    [[nodiscard]] std::size_t geometryLevel(const Camera& camera, const FrameSettings& settings,
                                            glm::ivec2 renderSize) const noexcept;
    /// The scene revision told apart for geometry `level` (geometryLevel()).
    [[nodiscard]] std::uint64_t geometryRevision(std::size_t level) const noexcept;
    /// What the depth of a view drawn at geometry `level` depends on besides
    /// the camera and size: geometryRevision() and which objects the style
    /// draws opaque (MeshStyle::depthKey). The solve worker's frames are
    /// told apart by it, so hiding an object re-solves the VSS.
    [[nodiscard]] std::uint64_t depthRevision(std::size_t level) const;

    std::uint64_t sceneRevision_ = 0;
    std::size_t lastGeometryLevel_ = 0;
    std::vector<PassInfo> passes_;
    std::string graphText_;
    VssFrameStatus status_;
    std::optional<std::pair<double, double>> cueRange_;
    glm::ivec2 vssSize_{0, 0};
    glm::ivec2 renderSize_{0, 0};
};

}  // namespace vv::render
