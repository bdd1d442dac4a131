// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "vv/core/Image.h"
#include "vv/core/Math.h"
#include "vv/render/Camera.h"
#include "vv/render/DisplaySettings.h"
#include "vv/render/FrameRenderer.h"
#include "vv/render/FrameSettings.h"
#include "vv/render/LegendPainter.h"
#include "vv/render/MeshRenderer.h"
#include "vv/render/MeshStyle.h"
#include "vv/render/RefinedGeometry.h"
#include "vv/render/RefinementPolicy.h"
#include "vv/scene/Mesh.h"
#include "vv/scene/MeshTopology.h"
#include "vv/scene/Volume.h"

namespace vv::render {

/// Simplified copies of a scene for the frames drawn while the camera moves,
/// made outside the renderer (meshio::simplifiedScene: render links no
/// VTK), with the closures of their meshes (one list per copy, same order).
struct PreviewGeometry {
    std::vector<std::shared_ptr<const scene::Scene>> scenes;
    std::vector<std::vector<scene::SurfaceClosure>> closures;
};

/// What the last frame shows at one pixel (ViewRenderer::probe).
struct ViewProbe {
    int meshIndex = -1;        ///< index into the scene's meshes; -1: the ray-cast volume
    std::string arrayName;     ///< the array the object shows; empty when none
    std::string unit;          ///< that array's unit; empty when unknown
    float value = 0.0F;        ///< its value; NaN when none is shown or no data here
    float linearDepth = 0.0F;  ///< distance along the viewing axis, scene units
    /// Depth behind the nearest visible vessel point of the frame (>= 0).
    float depthBelowNearest = 0.0F;
    /// What the frame's depth scale is measured from (depthReference() of
    /// its VSS settings): the depth a person compares with the depth legend
    /// is depthBelowNearest for FrontmostVessel, linearDepth for Camera.
    DepthReference depthReference = DepthReference::FrontmostVessel;
    glm::vec3 worldPosition{0.0F};  ///< scene coordinates
    /// The label here when the array is shown as labels (shownLabels()).
    std::optional<scene::Label> label;
};

/// What the settle step started (ViewRenderer::settle).
enum class SettleResult {
    /// Nothing: the next frame reads the depth back and asks for the exact VSS.
    None,
    /// The exact solve, from the depth the last preview frame read back (it
    /// showed this very view at this size); no frame was drawn.
    Requested,
    /// Only this view's G-buffer was drawn and its exact solve started
    /// (FrameRenderer::prepareSolve); the frame that shows it finds it cached.
    Prepared,
};

/// One view of a scene, as the viewer and the offscreen renderer (hence the
/// CLI, the exports and the reports) draw it: owns the FrameRenderer (and
/// through it the MeshRenderer), keeps what the view shows — scene, levels
/// of detail, surface closures, volume, style, display settings — and hands
/// the GPU what changed when the next frame is drawn, and applies the
/// refinement policy (RefinementPolicy) to the frames of a moving camera.
///
/// A scene is uploaded once: a scene set with a content fingerprint
/// (sceneFingerprint) that matches the one on the GPU is only attached, its
/// meshes not uploaded again (OffscreenRenderer renders tiles and report
/// views of one scene this way); a scene set without one is new content.
///
/// Setters need no GL context (they take effect with the next frame);
/// initialize(), release(), render(), renderDepth() and settle() need the
/// context current that initialize() ran in.
class ViewRenderer {
  public:
    ViewRenderer() = default;
    ~ViewRenderer() = default;
    ViewRenderer(const ViewRenderer&) = delete;
    ViewRenderer& operator=(const ViewRenderer&) = delete;
    ViewRenderer(ViewRenderer&&) = delete;
    ViewRenderer& operator=(ViewRenderer&&) = delete;

    // --- GL lifetime ---------------------------------------------------------
    /// FrameRenderer::initialize(); everything is uploaded anew by the next
    /// frame. Throws like it.
    void initialize();
    [[nodiscard]] bool initialized() const noexcept { return frame_.initialized(); }
    /// FrameRenderer::release(): deletes every GL object (context current).
    void release() noexcept { frame_.release(); }
    /// FrameRenderer::setSolveMode.
    void setSolveMode(FrameRenderer::SolveMode mode, std::function<void()> onSolved = {}) {
        frame_.setSolveMode(mode, std::move(onSolved));
    }

    // --- Scene, levels of detail, closures, volume ---------------------------
    /// Shows `scene` (nullptr: none) as new content: uploaded by the next
    /// frame; its levels of detail and closures are unknown until set.
    void setScene(std::shared_ptr<const scene::Scene> scene);
    /// Shows `scene`, whose content has the fingerprint `content`
    /// (sceneFingerprint: equal fingerprints promise equal positions,
    /// normals, indices and point arrays). When it is the content on the GPU,
    /// the meshes, levels and closures stay and the scene is only attached.
    void setScene(std::shared_ptr<const scene::Scene> scene, std::uint64_t content);
    [[nodiscard]] const std::shared_ptr<const scene::Scene>& scene() const noexcept {
        return scene_;
    }
    /// Lets go of the scene (nothing is drawn until the next setScene()) and
    /// keeps its meshes on the GPU for a later setScene() of the same content.
    void detachScene() noexcept;
    /// What the render graph knows the scene's content by: the fingerprint,
    /// or a revision that changes with each setScene() without one.
    [[nodiscard]] std::uint64_t sceneRevision() const noexcept { return revision_; }
    /// Uploads (or attaches) the scene now if the next frame would (context
    /// current). Returns true when it uploaded meshes. Throws like
    /// MeshRenderer::setScene (RenderError, InvalidArgumentError for bad
    /// indices); the scene then stays to be uploaded.
    bool uploadScene();
    /// How often a scene's meshes were uploaded (MeshRenderer::sceneUploads).
    [[nodiscard]] std::uint64_t sceneUploads() const noexcept {
        return frame_.meshRenderer().sceneUploads();
    }

    /// The simplified copies of the current scene (empty: none), drawn by
    /// frames with FrameSettings::simplifiedGeometry (moving frames).
    void setPreviewGeometry(PreviewGeometry geometry);
    [[nodiscard]] bool hasPreviewGeometry() const noexcept { return !previews_.scenes.empty(); }
    /// Triangles of each simplified level, finest first (empty without).
    [[nodiscard]] std::vector<std::size_t> previewLevelTriangles() const;

    /// The refined copy of the current scene (no scene: none), drawn by
    /// frames with FrameSettings::smoothCoarseMeshes where the scene's
    /// facets are coarse for the view. setScene() drops it.
    void setRefinedGeometry(RefinedGeometry geometry);
    [[nodiscard]] const RefinedGeometry& refinedGeometry() const noexcept { return refined_; }

    /// The closures of the current scene's meshes (scene::surfaceClosures),
    /// for back-face culling; until set, every mesh is drawn two-sided.
    void setSurfaceClosures(std::vector<scene::SurfaceClosure> closures);
    [[nodiscard]] bool surfaceClosuresKnown() const noexcept { return closuresKnown_; }

    /// A volume ray cast after the meshes (FrameRenderer::setVolume); nullptr = none.
    void setVolume(std::shared_ptr<const scene::Volume> volume, float isoValue);
    [[nodiscard]] const std::shared_ptr<const scene::Volume>& volume() const noexcept {
        return frame_.volume();
    }
    [[nodiscard]] float isoValue() const noexcept { return isoValue_; }
    /// The bounds of what is shown: the scene's box and the volume's.
    [[nodiscard]] Aabb dataBounds() const noexcept;

    // --- Style and display settings ------------------------------------------
    /// The mesh style, handed to the mesh renderer by the next frame.
    void setStyle(const MeshStyle& style);
    [[nodiscard]] const MeshStyle& style() const noexcept { return style_; }
    void setVssSettings(const VssSettings& settings) noexcept { display_.vss = settings; }
    void setAoSettings(const AoSettings& settings) noexcept { display_.ao = settings; }
    void setVesselCue(const VesselCueSettings& cue) noexcept { display_.cue = cue; }
    void setBackground(const glm::vec3& color) noexcept { display_.background = color; }
    void setAntialiasing(bool on) noexcept { display_.antialiasing = on; }
    void setSmoothCoarseMeshes(bool on) noexcept { display_.smoothCoarseMeshes = on; }
    /// The style and the still frames' settings of `display` at once
    /// (setStyle(display.style), frameSettings(display)); its legends and
    /// annotations are the caller's to paint.
    void setDisplay(const DisplaySettings& display);
    /// The display settings (what a still frame is drawn with).
    [[nodiscard]] const FrameSettings& displaySettings() const noexcept { return display_; }

    // --- Refinement ----------------------------------------------------------
    /// The refinement policy: tell it about camera moves and measured frames.
    [[nodiscard]] RefinementPolicy& refinement() noexcept { return refinement_; }
    [[nodiscard]] const RefinementPolicy& refinement() const noexcept { return refinement_; }
    /// What the next frame is drawn with: the display settings as the
    /// refinement policy adjusts them.
    [[nodiscard]] FrameSettings frameSettings() const noexcept {
        return refinement_.frameSettings(display_);
    }

    // --- Frames ----------------------------------------------------------------
    /// Hands the GPU what changed (scene, levels, closures, style) and draws
    /// one frame of `camera` into `target` with frameSettings(). Returns what
    /// the refinement policy asks to follow. Throws like FrameRenderer::render.
    RefinementPolicy::AfterFrame render(const Camera& camera, const FrameTarget& target);
    /// Like render(), only the G-buffer's linear depth (FrameRenderer::renderDepth).
    [[nodiscard]] Image<float> renderDepth(const Camera& camera, const FrameTarget& target);
    /// The settle step, after RefinementPolicy::settle() returned true:
    /// requests the exact solve from the depth the last preview frame read
    /// back when that depth shows this view at this size (no GL); otherwise
    /// draws only this view's G-buffer and submits its solve, calling
    /// `makeCurrent` first (asynchronous solves with the VSS on). A vv::Error
    /// on the way gives None (the next frame reports it).
    SettleResult settle(const Camera& camera, const FrameTarget& target,
                        const std::function<void()>& makeCurrent);
    /// How often settle() requested / prepared the exact solve.
    [[nodiscard]] std::uint64_t solvesRequestedOnSettle() const noexcept { return requested_; }
    [[nodiscard]] std::uint64_t solvesPreparedOnSettle() const noexcept { return prepared_; }
    /// Wall time of the last settle() in milliseconds.
    [[nodiscard]] double lastSettleMilliseconds() const noexcept { return settleMilliseconds_; }

    /// When on, each frame waits for its GPU timers and keeps the per-pass
    /// times (lastTimings()). Off by default: waiting stalls real GPUs.
    void setRecordTimings(bool on) noexcept { recordTimings_ = on; }
    [[nodiscard]] bool recordTimings() const noexcept { return recordTimings_; }
    /// The last frame's per-pass times (empty unless recordTimings()).
    [[nodiscard]] const std::vector<GlPassTiming>& lastTimings() const noexcept { return timings_; }

    /// What the last frame shows at (x, y), in its render pixels
    /// (FrameRenderer::lastRenderSize(), row 0 at the BOTTOM): the object, its
    /// array's value, depth and position; nullopt where no object is. The
    /// frame's nearest visible depth is read once per frame. `camera` is the
    /// one the frame was drawn with. Context current; throws RenderError when
    /// GL fails.
    [[nodiscard]] std::optional<ViewProbe> probe(const Camera& camera, int x, int y);

    /// The legends of the scales the last frame used (empty before one).
    [[nodiscard]] Legends legends() const;
    /// The colour-map range of the last frame; nullopt when no array is shown.
    [[nodiscard]] std::optional<std::pair<float, float>> shownRange() const noexcept {
        return frame_.meshRenderer().effectiveRange();
    }

    [[nodiscard]] FrameRenderer& frameRenderer() noexcept { return frame_; }
    [[nodiscard]] const FrameRenderer& frameRenderer() const noexcept { return frame_; }
    [[nodiscard]] MeshRenderer& meshRenderer() noexcept { return frame_.meshRenderer(); }
    [[nodiscard]] const MeshRenderer& meshRenderer() const noexcept {
        return frame_.meshRenderer();
    }

  private:
    /// Hands the mesh renderer what changed since the last frame.
    void prepareFrame();

    FrameRenderer frame_;
    RefinementPolicy refinement_;
    FrameSettings display_;
    FrameSettings lastSettings_;  ///< what the last frame was drawn with
    MeshStyle style_;
    std::shared_ptr<const scene::Scene> scene_;
    /// The labels scene_ shows, for legends() and probe() on every frame.
    mutable ShownLabelsCache labelCache_;
    /// The fingerprint of scene_, when it was set with one.
    std::optional<std::uint64_t> content_;
    /// The fingerprint of the meshes on the GPU; nullopt when unknown.
    std::optional<std::uint64_t> uploaded_;
    std::uint64_t revision_ = 0;
    std::uint64_t nextRevision_ = 0;
    PreviewGeometry previews_;
    RefinedGeometry refined_;
    std::vector<scene::SurfaceClosure> closures_;  ///< of scene_'s meshes
    bool closuresKnown_ = false;
    float isoValue_ = 0.0F;
    bool sceneDirty_ = false;     ///< scene_ not uploaded or attached yet
    bool previewDirty_ = false;   ///< previews_ not uploaded yet
    bool refinedDirty_ = false;   ///< refined_ not uploaded yet
    bool closuresDirty_ = false;  ///< closures_ known but not handed over yet
    bool styleDirty_ = true;
    std::uint64_t requested_ = 0;
    std::uint64_t prepared_ = 0;
    double settleMilliseconds_ = 0.0;
    bool recordTimings_ = false;
    std::vector<GlPassTiming> timings_;
    std::uint64_t frames_ = 0;  ///< frames drawn by render()
    /// The nearest visible depth of frame `first` (probe()).
    std::optional<std::pair<std::uint64_t, std::optional<float>>> nearest_;
};

}  // namespace vv::render
