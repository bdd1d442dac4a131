// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QOpenGLWidget>
#include <QPoint>
#include <QSize>
#include <QString>
#include <QSurfaceFormat>
#include <QTimer>
#include <cstddef>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

#include "gui/LatestRun.h"
#include "vv/core/Image.h"
#include "vv/render/Camera.h"
#include "vv/render/FrameMeter.h"
#include "vv/render/FrameSettings.h"
#include "vv/render/LegendPainter.h"
#include "vv/render/MeshStyle.h"
#include "vv/render/RenderGraph.h"
#include "vv/render/ViewAnnotations.h"
#include "vv/render/ViewRenderer.h"
#include "vv/scene/Mesh.h"
#include "vv/scene/MeshTopology.h"
#include "vv/scene/Volume.h"

namespace vv::gui {

class ViewOverlay;

// --- Probe and measurement ---------------------------------------------------
/// What the viewer shows at one point of the widget (ViewerWidget::probeAt).
struct ProbeResult {
    QPointF widgetPosition;    ///< logical widget coordinates that were probed
    int meshIndex = -1;        ///< index into the scene's meshes; -1: the ray-cast volume
    QString objectName;        ///< the mesh's name
    QString arrayName;         ///< the array shown; empty when none
    QString unit;              ///< the array's unit; empty when unknown
    float value = 0.0F;        ///< the array's value; NaN when none is shown / no data here
    float linearDepth = 0.0F;  ///< distance along the viewing axis (scene units: mm)
    /// Depth behind the nearest visible vessel point (linear depth minus the
    /// smallest visible linear depth), mm.
    float depthBelowNearest = 0.0F;
    /// What the view's depth legend measures from: probeText() gives the
    /// depth behind the frontmost vessel, or the viewing distance (linearDepth)
    /// while a fixed VSS range is on.
    render::DepthReference depthReference = render::DepthReference::FrontmostVessel;
    glm::vec3 worldPosition{0.0F};  ///< scene coordinates (mm)
    /// The array is shown as labels and `value` is one: its name from the
    /// file ("" when it has none).
    std::optional<QString> labelName;
};
/// Two picked points seen with a camera: their 3-D distance (the same in
/// every view) and their depth difference along the camera's viewing
/// direction (b - a; > 0: b lies deeper; changes as the view turns), mm.
struct Measurement {
    float distance = 0.0F;
    float depthDifference = 0.0F;
};
[[nodiscard]] Measurement measure(const ProbeResult& a, const ProbeResult& b,
                                  const render::Camera& camera) noexcept;
// --- end probe -------------------------------------------------------------

/// The 3-D view: shows a Scene through the view renderer the offscreen path
/// uses too (render::ViewRenderer: vessels with Blinn-Phong and an optional
/// colour-mapped array, and the Void Space Surface behind them) with an orbit
/// camera. The widget keeps the input, the Qt plumbing (timers, overlays,
/// tooltips, signals, the GL context) and the background jobs that make the
/// simplified geometry and check the closures; the renderer keeps the scene
/// state and the refinement policy (render::RefinementPolicy). The VSS is solved on a
/// worker thread: until a new solve arrives the view shows the previous VSS
/// (same size) or none, then repaints (during a drag only when the camera
/// pauses: the next move's frame shows it anyway).
///
/// Progressive refinement: while the camera moves (a drag in progress, or
/// within settleDelay() of the last camera change) frames ask for a preview
/// solve (VssSettings::preview: fast solver, loose tolerance) and skip the
/// ambient occlusion, and are rendered at interactiveScale() of the full
/// resolution (upscaled into the widget). When the mouse is released or the
/// settle timer fires, the exact solve follows by itself: at once from the
/// depth the last preview frame read back when that frame was rendered at
/// full resolution (a frame follows when the solve arrives), else through
/// the next, full-resolution frame. A newer request cancels a stale solve.
/// Scenes with more than previewTriangles() triangles also get simplified
/// copies (meshio::simplifiedScene, built on a worker thread after setScene())
/// that the geometry pass draws while the camera moves, the coarser one in
/// small frames: on software rasterisers the triangle count, not the pixel
/// count, bounds those frames.
///
/// Mouse: left-drag rotates (arcball), right- or middle-drag or shift +
/// left-drag pans, the wheel zooms. Keys: R resets the view, F fits the data.
/// When OpenGL 4.1 core is not available the widget paints a message instead
/// and emits renderFailed().
class ViewerWidget : public QOpenGLWidget {
    Q_OBJECT

  public:
    explicit ViewerWidget(QWidget* parent = nullptr);
    ~ViewerWidget() override;

    /// The surface format the viewer needs: OpenGL 4.1 core, 24-bit depth, 4x MSAA.
    [[nodiscard]] static QSurfaceFormat requiredFormat();
    /// Makes requiredFormat() the application default. Call before the
    /// QApplication is constructed (as main() does).
    static void installDefaultFormat();
    /// Tries to create an OpenGL 4.1 core context (needs a QGuiApplication).
    /// Returns an empty string when that works, else a message for the user.
    /// Check before showing a viewer: on platforms without OpenGL, Qt cannot
    /// compose a window that contains a QOpenGLWidget at all.
    [[nodiscard]] static QString probeOpenGl();

    /// Marks the viewer unusable (e.g. after probeOpenGl() failed): it paints
    /// `reason` and emits renderFailed(reason).
    void setUnavailable(const QString& reason);

    /// Shows `scene` (nullptr clears) in its home orientation
    /// (render::homeRotation() of its frame: the anterior view for the patient
    /// frame), fitted to it. The scene is shared, never modified.
    void setScene(std::shared_ptr<const scene::Scene> scene);
    [[nodiscard]] const std::shared_ptr<const scene::Scene>& scene() const noexcept {
        return view_.scene();
    }
    /// Ray casts `volume` as the iso-surface at `isoValue` after the scene's
    /// meshes (FrameRenderer::setVolume): the VSS, AO, cues and the probe
    /// work on it as on meshes (its probe gives position and depth, no
    /// value). nullptr = none. Keeps the camera; the volume's box joins the
    /// bounds that fitToData() and setScene() frame and that decide the clip
    /// planes. The volume is shared, never modified.
    void setVolume(std::shared_ptr<const scene::Volume> volume, float isoValue);
    [[nodiscard]] const std::shared_ptr<const scene::Volume>& volume() const noexcept {
        return view_.volume();
    }
    [[nodiscard]] float isoValue() const noexcept { return view_.isoValue(); }
    /// The bounds of what is shown: the scene's and the volume's box.
    [[nodiscard]] Aabb dataBounds() const noexcept { return view_.dataBounds(); }

    void setStyle(const render::MeshStyle& style);
    [[nodiscard]] const render::MeshStyle& style() const noexcept { return view_.style(); }

    /// The VSS: on/off, depth scale, p, solver, iso-lines, strengths.
    void setVssSettings(const render::VssSettings& settings);
    [[nodiscard]] const render::VssSettings& vssSettings() const noexcept {
        return view_.displaySettings().vss;
    }
    /// Ambient occlusion over vessels + VSS (on by default).
    void setAoSettings(const render::AoSettings& settings);
    [[nodiscard]] const render::AoSettings& aoSettings() const noexcept {
        return view_.displaySettings().ao;
    }
    /// The depth cue on the vessels themselves (none by default).
    void setVesselCue(const render::VesselCueSettings& cue);
    [[nodiscard]] const render::VesselCueSettings& vesselCue() const noexcept {
        return view_.displaySettings().cue;
    }
    /// Draw coarse meshes from a smooth (Loop-subdivided) copy where their
    /// facets are large on screen (render::FrameSettings::smoothCoarseMeshes);
    /// the copy is made in the background for a scene that gets one
    /// (app::smoothCopyOf), once the switch is on.
    void setSmoothCoarseMeshes(bool on);
    [[nodiscard]] bool smoothCoarseMeshes() const noexcept {
        return view_.displaySettings().smoothCoarseMeshes;
    }
    /// Whether the last frame drew the smooth copy (the view shows it).
    [[nodiscard]] bool lastFrameSmoothed() const noexcept {
        return view_.frameRenderer().lastGeometryLevel() == render::kRefinedLevel;
    }
    /// The smooth copy drawn (its deviation from the mesh), or none yet.
    [[nodiscard]] const render::RefinedGeometry& smoothCopy() const noexcept {
        return view_.refinedGeometry();
    }
    /// Legends of the scales in use (depth bottom-left, parameter bottom-right),
    /// painted over the frame; on by default.
    void setLegendsVisible(bool visible);
    [[nodiscard]] bool legendsVisible() const noexcept { return legendsVisible_; }
    /// The orientation marker and the scale bar over the view, and the
    /// frame the scene is in (its patient letters); both on by default.
    void setViewAnnotations(const render::ViewAnnotations& annotations);
    [[nodiscard]] const render::ViewAnnotations& viewAnnotations() const noexcept {
        return annotations_;
    }
    /// The legends shown over the last frame (empty when none).
    [[nodiscard]] const render::Legends& shownLegends() const noexcept;
    /// What the last frame showed of the VSS.
    [[nodiscard]] const render::VssFrameStatus& vssStatus() const noexcept {
        return view_.frameRenderer().vssStatus();
    }
    /// Progressive refinement on (default) or off (every frame asks for the exact VSS).
    void setProgressiveRefinement(bool on);
    /// How long after the last camera change the camera counts as stopped (ms).
    void setSettleDelay(int milliseconds);
    [[nodiscard]] int settleDelay() const noexcept { return settleDelayMs_; }
    /// While the camera moves, a preview solve's arrival draws a frame only
    /// when no camera move drew one within this delay (the camera paused):
    /// during a drag the next move's frame shows the preview anyway, and a
    /// frame per arrival would double the work per mouse move.
    static constexpr int kPreviewArrivalDelayMs = 60;
    /// The delay above (ms), for tests that hold the camera's pace apart
    /// from the machine's.
    void setPreviewArrivalDelay(int milliseconds);
    [[nodiscard]] int previewArrivalDelay() const;
    /// Render size of frames while the camera moves, relative to the widget,
    /// in [0.1, 1] (default 0.5: a quarter of the pixels). 1 = full size,
    /// which lets the exact solve start from the last preview frame's depth.
    /// Setting it fixes the scale (setFrameBudget(0)); their VSS is solved
    /// and shaded at `vssScale` of the widget (at most `scale`; default:
    /// `scale`, see RefinementPolicy::setInteractiveScale).
    void setInteractiveScale(float scale, float vssScale = std::numeric_limits<float>::quiet_NaN());
    /// Dynamic resolution while the camera moves: after each moving frame the
    /// interactive scales step down (RefinementPolicy::kScaleSteps, with the
    /// VSS's: ~0.7 of the pixels a step) when the frame took over 1.15 x the budget,
    /// and up when it took under 0.6 x, so slow machines keep their frame
    /// rate and fast ones get full-size frames; in between the size holds
    /// (a preview VSS shows only at the size it was solved at). A frame
    /// runs from paintGL to the swap of the window Qt composes (frameSwapped),
    /// since that is what the frame rate sees: on software OpenGL the
    /// composition alone takes ~15 ms at 720p. Its cost is the work it took,
    /// not the wall time other processes stretch (render::FrameMeter,
    /// render::frameCostMilliseconds): CPU time on software OpenGL, CPU and
    /// GPU time (timer queries; each moving frame then waits for its GPU
    /// time) on a GPU. Default 30 ms; 0 = a fixed scale. Non-finite or
    /// negative values count as 0.
    void setFrameBudget(double milliseconds);
    static constexpr float kMinInteractiveScale = render::RefinementPolicy::kMinInteractiveScale;
    /// Triangle budget of the simplified geometry drawn while the camera
    /// moves (default 60,000); 0 = always draw the full meshes. Applies to
    /// scenes set afterwards. A second, coarser copy (a third of the budget)
    /// is built from the first; moving frames draw the finest copy with
    /// about one triangle per MeshRenderer's kPixelsPerPreviewTriangle
    /// pixels of their render size (render::choosePreviewLevel), so small
    /// frames on software rasterisers draw fewer triangles.
    void setPreviewTriangles(std::size_t triangles) noexcept { previewTriangles_ = triangles; }
    [[nodiscard]] std::size_t previewTriangles() const noexcept { return previewTriangles_; }
    /// MeshRenderer::setBackFaceCulling (on by default); off for comparisons.
    void setBackFaceCulling(bool on) noexcept { view_.meshRenderer().setBackFaceCulling(on); }
    /// The size (device pixels) the passes of the last frame ran at.
    [[nodiscard]] QSize lastRenderSize() const noexcept { return lastRenderSize_; }
    /// True from the moment the camera settles until the frame with the
    /// exact VSS is on screen: those frames leave out the ambient occlusion
    /// (the slowest pass on software rasterisers) and FXAA, and the frame
    /// right after adds them, so the exact VSS shows as early as it can.
    [[nodiscard]] bool occlusionDeferred() const noexcept {
        return view_.refinement().occlusionDeferred();
    }
    /// The passes of the last frame (state, reason, CPU time).
    [[nodiscard]] const std::vector<render::PassInfo>& lastPasses() const noexcept {
        return view_.frameRenderer().lastPasses();
    }
    /// Benchmarks: when on, every frame waits for its GPU timers and keeps
    /// the per-pass CPU / GPU times (view().lastTimings()) and the wall time of
    /// paintGL (lastPaintMilliseconds()). Off by default: waiting for the
    /// timers stalls the pipeline on real GPUs.
    void setRecordTimings(bool on) noexcept { view_.setRecordTimings(on); }
    /// Wall time of the last paintGL in milliseconds (with setRecordTimings(true)).
    [[nodiscard]] double lastPaintMilliseconds() const noexcept { return paintMilliseconds_; }
    /// The view renderer behind the widget, read-only, for what the widget
    /// does not forward: the refinement state (view().refinement():
    /// interactive scales, frame budget, moving), the last frame's sizes,
    /// geometry level and solve counters (view().frameRenderer()), the
    /// simplified levels, settle counters and times. Changes go through the
    /// widget's setters, which ask for a frame.
    [[nodiscard]] const render::ViewRenderer& view() const noexcept { return view_; }

    /// Background colour, sRGB in [0, 1].
    void setBackground(const glm::vec3& color);
    [[nodiscard]] const glm::vec3& background() const noexcept {
        return view_.displaySettings().background;
    }

    [[nodiscard]] const render::Camera& camera() const noexcept { return camera_; }
    /// Replaces the camera (its viewport follows the widget; the home
    /// orientation stays the scene's). Until the next setScene(),
    /// resetCamera() or fitToData() the view is no longer refitted when the
    /// widget resizes.
    void setCamera(const render::Camera& camera);

    /// Non-empty when OpenGL could not be used; the reason.
    [[nodiscard]] const QString& renderError() const noexcept { return error_; }
    /// "renderer / OpenGL version", empty before the first frame.
    [[nodiscard]] const QString& glDescription() const noexcept { return glDescription_; }
    /// Frames drawn since the current scene was set.
    [[nodiscard]] quint64 framesWithScene() const noexcept { return framesWithScene_; }

    // --- Probe and measurement -------------------------------------------
    /// What the last frame shows at `position` (logical widget coordinates):
    /// object, value, depth; nullopt when no vessel is there, no frame was
    /// drawn or OpenGL is unavailable. Makes the context current; reads three
    /// texels (and, once per frame, the whole depth for the nearest point).
    [[nodiscard]] std::optional<ProbeResult> probeAt(const QPointF& position);
    /// The tooltip text for `result`: object, value with unit, depth.
    [[nodiscard]] static QString probeText(const ProbeResult& result);
    /// Hover probe: a tooltip with probeText() while the mouse rests on a
    /// vessel (on by default).
    void setHoverProbe(bool on);
    [[nodiscard]] bool hoverProbe() const noexcept { return hoverProbe_; }
    /// Measure mode: a left click (press and release without moving) picks
    /// a point (pointPicked). Ctrl + left click picks in any mode.
    void setMeasureMode(bool on) noexcept { measureMode_ = on; }
    [[nodiscard]] bool measureMode() const noexcept { return measureMode_; }
    // --- end probe -------------------------------------------------------

  public slots:
    /// The scene's home orientation (see setScene()), fitted to the data.
    void resetCamera();
    /// Keeps the orientation, frames the data.
    void fitToData();

  signals:
    /// The simplified geometry of the current scene is ready (hasPreviewGeometry()).
    void previewGeometryReady();
    /// The smooth copy of a coarse scene is drawn from now on: it moves the
    /// wall by at most `largestMm`, by `meanMm` on average.
    void smoothCopyReady(double largestMm, double meanMm);
    /// A frame was drawn (emitted at the end of paintGL; connect queued to grab it).
    void frameRendered();
    /// A VSS solve for the current view arrived (a repaint follows).
    void vssSolved();
    /// The camera stopped moving; the exact VSS is requested (at once, or by the next frame).
    void cameraSettled();
    /// OpenGL cannot be used; `message` says why. Emitted at most once.
    void renderFailed(const QString& message);
    /// Drawing failed while a volume was ray cast (e.g. larger than this
    /// GPU's 3-D textures or memory): the viewer dropped the volume and goes
    /// on drawing the scene; `message` says why.
    void volumeFailed(const QString& message);
    /// A point was picked (measure mode click or Ctrl + click on a vessel).
    void pointPicked(const vv::gui::ProbeResult& result);
    /// A pick landed on the background (no vessel under the mouse).
    void pickMissed();

  protected:
    void initializeGL() override;
    void resizeGL(int width, int height) override;
    void paintGL() override;
    void showEvent(QShowEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;

  private:
    void fail(const QString& message);
    void releaseGl();
    void paintMessage(const QString& text);
    /// Asks for a new frame: paintGL draws only after such a request (or a
    /// resize / new context); other repaints keep the last frame.
    void requestFrame();
    /// A camera change by the user: preview quality until it settles.
    void cameraChanged();
    /// The camera stopped: the exact VSS is asked for (ViewRenderer::settle).
    void settle();
    /// A solve arrived (on the GUI thread): the frame that shows it.
    void solveArrived();
    /// Starts building the simplified geometry of the scene on a worker.
    void startPreviewGeometry();
    /// Makes the smooth copy of the scene in the background, when the
    /// switch is on and the scene has none yet.
    void startSmoothCopy();
    /// Starts scene::surfaceClosures of the scene's meshes on a worker.
    void startClosureCheck();
    /// The device pixels of the widget, drawn into its framebuffer.
    [[nodiscard]] render::FrameTarget frameTarget() const;

    /// Scene, style, display settings, refinement; the GPU side of the view.
    render::ViewRenderer view_;
    render::Camera camera_;
    bool autoFit_ = true;  ///< refit on resize until the user moves the camera
    bool legendsVisible_ = true;
    render::ViewAnnotations annotations_;
    /// A transparent child over the GL frame that paints the legends, the
    /// marker and the scale bar (so grabFramebuffer() stays the frame alone).
    ViewOverlay* viewOverlay_ = nullptr;
    QString error_;
    QString glDescription_;
    quint64 framesWithScene_ = 0;
    QSize lastRenderSize_;    ///< of the last frame paintGL drew
    bool frameDirty_ = true;  ///< a new frame was requested (requestFrame)
    enum class Drag { None, Rotate, Pan };
    Drag drag_ = Drag::None;
    QPointF lastMouse_;

    // Background jobs: the simplified copies (and their closures) and the
    // scene's closures, each the newest run's result only.
    /// The second simplified level has previewTriangles_ / this many triangles.
    static constexpr std::size_t kPreviewLevelRatio = 3;
    std::size_t previewTriangles_ = 60000;
    LatestRun<render::PreviewGeometry, AtDestruction::Wait> previewRun_{this};
    LatestRun<std::optional<render::RefinedGeometry>, AtDestruction::Wait> smoothRun_{this};
    LatestRun<std::vector<scene::SurfaceClosure>, AtDestruction::Wait> closureRun_{this};

    // Refinement timing: the settle timer, preview arrivals, the frame budget.
    int settleDelayMs_ = 150;
    QTimer* settleTimer_ = nullptr;
    QTimer* previewArrivalTimer_ = nullptr;
    /// Measures camera-move frames for the frame budget, up to their swap
    /// (frameSwapped).
    render::FrameMeter frameMeter_;
    double paintMilliseconds_ = 0.0;

    // --- Probe and measurement -------------------------------------------
    void hoverProbeNow();
    /// Handles a left-button release: picks when it was a click.
    void maybePick(QMouseEvent* event);
    bool hoverProbe_ = false;
    bool measureMode_ = false;
    QTimer* hoverTimer_ = nullptr;
    QPointF pressPosition_;
    bool pressMoved_ = false;
    // --- end probe -------------------------------------------------------
};

}  // namespace vv::gui
