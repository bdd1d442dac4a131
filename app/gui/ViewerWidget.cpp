// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/ViewerWidget.h"

#include <QElapsedTimer>
#include <QFutureWatcher>
#include <QGuiApplication>
#include <QHelpEvent>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QPaintEvent>
#include <QPainter>
#include <QTimer>
#include <QToolTip>
#include <QWheelEvent>
#include <QtConcurrent/QtConcurrentRun>
#include <algorithm>
#include <array>
#include <cmath>
#include <exception>
#include <limits>
#include <utility>

#include "vv/core/Error.h"
#include "vv/core/Log.h"
#include "vv/meshio/MeshSimplify.h"
#include "vv/render/LegendPainter.h"

namespace vv::gui {

/// Paints the legends (LegendPainter) over the viewer; lets the mouse through.
class LegendOverlay : public QWidget {
  public:
    explicit LegendOverlay(QWidget* parent) : QWidget(parent) {
        setAttribute(Qt::WA_TransparentForMouseEvents);
        setAttribute(Qt::WA_NoSystemBackground);
        setAttribute(Qt::WA_TranslucentBackground);
        setFocusPolicy(Qt::NoFocus);
    }

    void setLegends(render::Legends legends) {
        const bool wasEmpty = legends_.empty();
        legends_ = std::move(legends);
        if (!(wasEmpty && legends_.empty())) {
            update();
        }
    }

    [[nodiscard]] const render::Legends& legends() const noexcept { return legends_; }

  protected:
    void paintEvent(QPaintEvent* event) override {
        Q_UNUSED(event);
        if (legends_.empty()) {
            return;
        }
        QPainter painter(this);
        render::paintLegends(painter, QRectF(rect()), legends_);
    }

  private:
    render::Legends legends_;
};

ViewerWidget::ViewerWidget(QWidget* parent) : QOpenGLWidget(parent) {
    legendOverlay_ = new LegendOverlay(this);
    legendOverlay_->setGeometry(rect());
    settleTimer_ = new QTimer(this);
    settleTimer_->setSingleShot(true);
    settleTimer_->setInterval(settleDelayMs_);
    connect(settleTimer_, &QTimer::timeout, this, &ViewerWidget::settle);
    previewArrivalTimer_ = new QTimer(this);
    previewArrivalTimer_->setSingleShot(true);
    previewArrivalTimer_->setInterval(kPreviewArrivalDelayMs);
    connect(previewArrivalTimer_, &QTimer::timeout, this, &ViewerWidget::requestFrame);
    frameClock_.start();
    connect(this, &QOpenGLWidget::frameSwapped, this, [this] {
        if (budgetFrameStart_) {
            // Drawing plus Qt composing the window: what the frame rate sees
            // (on software OpenGL the composition alone takes ~15 ms at 720p).
            adaptInteractiveScale(
                static_cast<double>(frameClock_.nsecsElapsed() - *budgetFrameStart_) / 1e6);
            budgetFrameStart_.reset();
        }
    });
    setFormat(requiredFormat());
    // The widget's buffer keeps its frame between paints, so that repaints
    // nobody asked a new frame for (an overlay child redrawing, an expose)
    // reuse it instead of running the whole graph again (paintGL).
    setUpdateBehavior(QOpenGLWidget::PartialUpdate);
    setFocusPolicy(Qt::StrongFocus);
    setMinimumSize(160, 120);
    setToolTip(
        tr("Left-drag: rotate · Right/middle or Shift+left-drag: pan · Wheel: zoom\n"
           "R: reset view · F: fit to data · Ctrl+click: measure"));
    setHoverProbe(true);
}

ViewerWidget::~ViewerWidget() {
    cancelPreviewGeometry();
    previewFuture_.waitForFinished();
    closureFuture_.waitForFinished();
    // ~QOpenGLWidget destroys the context after this body, when this object is
    // only a QOpenGLWidget and renderer_ is gone: its aboutToBeDestroyed must
    // not call releaseGl again (UBSan: downcast of a QOpenGLWidget, asan preset).
    if (QOpenGLContext* ctx = context()) {
        disconnect(ctx, &QOpenGLContext::aboutToBeDestroyed, this, &ViewerWidget::releaseGl);
    }
    releaseGl();
}

QSurfaceFormat ViewerWidget::requiredFormat() {
    QSurfaceFormat format;
    format.setRenderableType(QSurfaceFormat::OpenGL);
    format.setVersion(4, 1);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    format.setStencilBufferSize(8);
    // Single-sampled: every pass draws into the render graph's own textures,
    // and the last one is a full-screen triangle (FXAA or an upscaling blit)
    // into the widget. A multisampled widget buffer would only cost a 4x
    // write and a resolve per frame (~10-20 ms at 720p on llvmpipe).
    format.setSamples(0);
    return format;
}

void ViewerWidget::installDefaultFormat() {
    QSurfaceFormat::setDefaultFormat(requiredFormat());
}

QString ViewerWidget::probeOpenGl() {
    QOpenGLContext context;
    context.setFormat(requiredFormat());
    if (!context.create()) {
        return tr("No OpenGL context can be created here (platform '%1'). VesselView needs "
                  "OpenGL 4.1 (core profile): update the graphics driver, or run with Mesa's "
                  "software renderer (LIBGL_ALWAYS_SOFTWARE=1).")
            .arg(QGuiApplication::platformName());
    }
    const QSurfaceFormat f = context.format();
    if (context.isOpenGLES() || f.majorVersion() < 4 ||
        (f.majorVersion() == 4 && f.minorVersion() < 1)) {
        return tr("VesselView needs OpenGL 4.1 (core profile); this system offers %1 %2.%3. "
                  "Update the graphics driver, or run with Mesa's software renderer "
                  "(LIBGL_ALWAYS_SOFTWARE=1).")
            .arg(context.isOpenGLES() ? QStringLiteral("OpenGL ES") : QStringLiteral("OpenGL"))
            .arg(f.majorVersion())
            .arg(f.minorVersion());
    }
    return {};
}

void ViewerWidget::setUnavailable(const QString& reason) {
    fail(reason);
    requestFrame();
}

void ViewerWidget::releaseGl() {
    if (context() == nullptr) {
        return;
    }
    makeCurrent();
    renderer_.release();
    doneCurrent();
}

void ViewerWidget::setScene(std::shared_ptr<const scene::Scene> scene) {
    scene_ = std::move(scene);
    startPreviewGeometry();
    startClosureCheck();
    ++sceneRevision_;
    sceneDirty_ = true;
    framesWithScene_ = 0;
    camera_.setViewport(width(), height());
    camera_.reset();
    camera_.fit(dataBounds());
    autoFit_ = true;
    requestFrame();
}

void ViewerWidget::setVolume(std::shared_ptr<const scene::Volume> volume, float isoValue) {
    volume_ = std::move(volume);
    isoValue_ = isoValue;
    renderer_.setVolume(volume_, isoValue_);  // uploads lazily, no context needed
    framesWithScene_ = 0;
    nearestKey_.reset();
    if (const Aabb box = dataBounds(); !box.empty()) {
        camera_.setSceneBounds(box);  // clip planes; the view stays
    }
    requestFrame();
}

Aabb ViewerWidget::dataBounds() const noexcept {
    Aabb box = scene_ ? scene_->bounds() : Aabb{};
    if (volume_ && !volume_->empty()) {
        box.extend(volume_->worldBounds());
    }
    return box;
}

void ViewerWidget::cancelPreviewGeometry() {
    previewStop_.request_stop();
    previewStop_ = std::stop_source();
    previewScenes_.clear();
    previewClosures_.clear();
    previewDirty_ = true;
}

namespace {

/// scene::surfaceClosures, or every mesh Open (drawn two-sided, always right)
/// when the check fails (bad indices: the upload reports those; no memory).
std::vector<scene::SurfaceClosure> closuresOf(const scene::Scene& scene) {
    try {
        return scene::surfaceClosures(scene);
    } catch (const std::exception&) {
        return std::vector<scene::SurfaceClosure>(scene.meshes.size(), scene::SurfaceClosure::Open);
    }
}

}  // namespace

void ViewerWidget::startClosureCheck() {
    sceneClosures_.clear();
    closuresKnown_ = false;
    closuresDirty_ = false;
    if (!scene_) {
        return;
    }
    const std::shared_ptr<const scene::Scene> scene = scene_;
    closureFuture_ = QtConcurrent::run([scene] { return closuresOf(*scene); });
    auto* watcher = new QFutureWatcher<Closures>(this);
    connect(watcher, &QFutureWatcher<Closures>::finished, this, [this, watcher, scene] {
        watcher->deleteLater();
        if (scene != scene_) {
            return;  // checked for an older scene
        }
        sceneClosures_ = watcher->result();
        closuresKnown_ = true;
        closuresDirty_ = true;  // the next frame culls; this one's pixels stay right
    });
    watcher->setFuture(closureFuture_);
}

std::vector<std::size_t> ViewerWidget::previewLevelTriangles() const {
    std::vector<std::size_t> levels;
    for (const auto& preview : previewScenes_) {
        levels.push_back(preview->triangleCount());
    }
    return levels;
}

void ViewerWidget::startPreviewGeometry() {
    cancelPreviewGeometry();
    const std::size_t triangles = scene_ ? scene_->triangleCount() : 0;
    // Not worth it below 1.5x the budget: the full meshes are cheap enough.
    const auto worthIt = [](std::size_t have, std::size_t budget) {
        return budget > 0 && have * 2 > budget * 3;
    };
    if (!worthIt(triangles, previewTriangles_)) {
        return;
    }
    const std::shared_ptr<const scene::Scene> scene = scene_;
    const std::size_t budget = previewTriangles_;
    previewFuture_ = QtConcurrent::run(
        [scene, budget, worthIt, stop = previewStop_.get_token()]() -> PreviewGeometry {
            try {
                // The budget, then a third of it from that copy (cheap): the
                // renderer draws the coarser one into small moving frames.
                // Decimation may open a surface, so each copy is checked.
                PreviewGeometry levels;
                auto fine = std::make_shared<const scene::Scene>(
                    meshio::simplifiedScene(*scene, budget, Progress({}, stop)));
                levels.scenes.push_back(fine);
                levels.closures.push_back(closuresOf(*fine));
                const std::size_t coarse = budget / kPreviewLevelRatio;
                if (worthIt(fine->triangleCount(), coarse)) {
                    auto coarser = std::make_shared<const scene::Scene>(
                        meshio::simplifiedScene(*fine, coarse, Progress({}, stop)));
                    levels.closures.push_back(closuresOf(*coarser));
                    levels.scenes.push_back(std::move(coarser));
                }
                return levels;
            } catch (const CancelledError&) {
                return {};
            } catch (const vv::Error& e) {
                // No preview: moving frames draw the full meshes.
                static const log::Category category{"vv.gui"};
                log::warning(category, std::string("no simplified geometry: ") + e.what());
                return {};
            }
        });
    auto* watcher = new QFutureWatcher<PreviewGeometry>(this);
    connect(watcher, &QFutureWatcher<PreviewGeometry>::finished, this, [this, watcher, scene] {
        watcher->deleteLater();
        PreviewGeometry previews = watcher->result();
        if (previews.scenes.empty() || scene != scene_) {
            return;  // cancelled, failed, or built for an older scene
        }
        previewScenes_ = std::move(previews.scenes);
        previewClosures_ = std::move(previews.closures);
        previewDirty_ = true;
        emit previewGeometryReady();
    });
    watcher->setFuture(previewFuture_);
}

void ViewerWidget::setStyle(const render::MeshStyle& style) {
    style_ = style;
    styleDirty_ = true;
    requestFrame();
}

void ViewerWidget::setVssSettings(const render::VssSettings& settings) {
    vss_ = settings;
    requestFrame();
}

void ViewerWidget::setAoSettings(const render::AoSettings& settings) {
    ao_ = settings;
    requestFrame();
}

void ViewerWidget::setVesselCue(const render::VesselCueSettings& cue) {
    cue_ = cue;
    requestFrame();
}

void ViewerWidget::setLegendsVisible(bool visible) {
    legendsVisible_ = visible;
    requestFrame();
}

void ViewerWidget::setProgressiveRefinement(bool on) {
    progressive_ = on;
    if (!on) {
        settle();
    }
}

void ViewerWidget::setSettleDelay(int milliseconds) {
    settleDelayMs_ = std::max(milliseconds, 0);
    settleTimer_->setInterval(settleDelayMs_);
}

void ViewerWidget::cameraChanged() {
    autoFit_ = false;
    if (progressive_) {
        moving_ = true;
        cameraMoved_ = true;  // this frame may set the next move's size
        if (frameBudgetMs_ > 0.0) {
            interactiveScale_ = nextInteractiveScale_;
        }
        settleTimer_->start();  // restarts: the camera settles settleDelay() after the last change
    }
    requestFrame();
}

void ViewerWidget::settle() {
    settleTimer_->stop();
    if (!moving_) {
        return;
    }
    moving_ = false;
    previewArrivalTimer_->stop();  // the settled frames show the newest VSS
    // The exact VSS first, the occlusion in the frame after (paintGL).
    deferOcclusion_ = true;  // the AO and FXAA follow the exact VSS
    QElapsedTimer settleTimer;
    settleTimer.start();
    bool requested = false;
    bool prepared = false;
    if (error_.isEmpty() && renderer_.initialized() && !autoFit_) {
        // The last preview frame read back the depth of this very view (same
        // camera, same render size): start the exact solve now, and let its
        // arrival (vssSolved) draw the one frame that shows it.
        try {
            requested = renderer_.requestSolve(camera_, frameSettings(), frameTarget());
            if (!requested) {
                // The last frame was smaller or drew the simplified meshes:
                // draw only this view's full G-buffer and start its solve; the
                // solve's arrival draws the frame (its G-buffer then cached).
                makeCurrent();
                prepared = renderer_.prepareSolve(camera_, frameSettings(), frameTarget());
                doneCurrent();
            }
        } catch (const vv::Error&) {
            doneCurrent();
            requested = false;  // the next frame reports the problem
            prepared = false;
        }
    }
    settleMilliseconds_ = static_cast<double>(settleTimer.nsecsElapsed()) / 1e6;
    if (requested) {
        ++solvesRequestedOnSettle_;
    }
    if (prepared) {
        ++solvesPreparedOnSettle_;
    }
    emit cameraSettled();
    if (!requested && !prepared) {
        requestFrame();  // the next frame reads the depth back and asks for the exact VSS
    }
}

namespace {
/// The scales dynamic resolution steps through, each ~0.84 of the one
/// before (~0.7 of its pixels). Discrete, so that the size holds still while
/// the time fits: a new size cannot show the last preview VSS (a VSS is only
/// shown at the size it was solved at).
constexpr std::array<float, 9> kScaleSteps = {1.0F,  0.84F, 0.71F, 0.6F, 0.5F,
                                              0.42F, 0.35F, 0.3F,  0.25F};
}  // namespace

void ViewerWidget::adaptInteractiveScale(double milliseconds) {
    // The step at or below the current scale.
    std::size_t step = kScaleSteps.size() - 1;
    for (std::size_t i = 0; i < kScaleSteps.size(); ++i) {
        if (kScaleSteps[i] <= interactiveScale_ + 1e-4F) {
            step = i;
            break;
        }
    }
    if (milliseconds > 1.15 * frameBudgetMs_ && step + 1 < kScaleSteps.size()) {
        ++step;  // too slow: ~0.7 of the pixels
    } else if (milliseconds < 0.6 * frameBudgetMs_ && step > 0) {
        --step;  // ~1.4x the pixels would still fit
    }
    nextInteractiveScale_ = kScaleSteps[step];
}

void ViewerWidget::setFrameBudget(double milliseconds) {
    frameBudgetMs_ = std::isfinite(milliseconds) ? std::max(milliseconds, 0.0) : 0.0;
}

void ViewerWidget::setInteractiveScale(float scale) {
    frameBudgetMs_ = 0.0;  // a fixed scale
    interactiveScale_ = std::isfinite(scale) ? std::clamp(scale, 0.1F, 1.0F) : 1.0F;
    nextInteractiveScale_ = interactiveScale_;
    requestFrame();
}

render::FrameSettings ViewerWidget::frameSettings() const {
    render::FrameSettings settings;
    settings.background = background_;
    settings.vss = vss_;
    settings.ao = ao_;
    settings.cue = cue_;
    if (moving_) {
        // Preview while the camera moves: a quicker solve, no occlusion, no
        // FXAA (a reduced render size is blitted up instead), and a reduced
        // render size when the resolution of the target does not already
        // make the frame cheap.
        settings.vss.preview = true;
        settings.ao.enabled = false;
        settings.antialiasing = false;
        settings.resolutionScale = interactiveScale_;
        settings.simplifiedGeometry = true;
    } else if (deferOcclusion_) {
        // Until the exact VSS is on screen: without the occlusion and FXAA
        // (~120 ms and ~20 ms at 720p on llvmpipe), which the next frame adds.
        settings.ao.enabled = false;
        settings.antialiasing = false;
    }
    return settings;
}

render::FrameTarget ViewerWidget::frameTarget() const {
    // The camera works in logical pixels, the frame in device pixels.
    const qreal ratio = devicePixelRatioF();
    return render::FrameTarget{defaultFramebufferObject(),
                               std::max(1, static_cast<int>(std::lround(width() * ratio))),
                               std::max(1, static_cast<int>(std::lround(height() * ratio)))};
}

void ViewerWidget::setBackground(const glm::vec3& color) {
    background_ = color;
    requestFrame();
}

void ViewerWidget::setCamera(const render::Camera& camera) {
    camera_ = camera;
    camera_.setViewport(width(), height());
    autoFit_ = false;
    requestFrame();
}

void ViewerWidget::resetCamera() {
    camera_.setViewport(width(), height());
    camera_.reset();
    autoFit_ = true;
    requestFrame();
}

void ViewerWidget::fitToData() {
    camera_.setViewport(width(), height());
    const Aabb box = dataBounds();
    camera_.fit(box.empty() ? camera_.sceneBounds() : box);
    autoFit_ = true;
    requestFrame();
}

void ViewerWidget::fail(const QString& message) {
    if (!error_.isEmpty()) {
        return;
    }
    error_ = message;
    // Let the caller of paintGL / initializeGL finish first.
    QTimer::singleShot(0, this, [this] { emit renderFailed(error_); });
}

void ViewerWidget::showEvent(QShowEvent* event) {
    QOpenGLWidget::showEvent(event);
    // A widget that could not make any context never calls initializeGL.
    QTimer::singleShot(2000, this, [this] {
        if (isVisible() && error_.isEmpty() && (context() == nullptr || !context()->isValid())) {
            fail(
                tr("OpenGL could not be initialised: VesselView needs OpenGL 4.1 (core "
                   "profile). Update the graphics driver, or run with Mesa's software "
                   "renderer (LIBGL_ALWAYS_SOFTWARE=1)."));
            requestFrame();
        }
    });
}

void ViewerWidget::initializeGL() {
    QOpenGLContext* ctx = context();
    if (ctx == nullptr || !ctx->isValid()) {
        fail(tr("OpenGL could not be initialised: no valid OpenGL context."));
        return;
    }
    connect(ctx, &QOpenGLContext::aboutToBeDestroyed, this, &ViewerWidget::releaseGl,
            Qt::UniqueConnection);
    try {
        renderer_.initialize();
        // Called on the solver's thread: hand the repaint to the GUI thread
        // (dropped if the widget is gone by then).
        renderer_.setSolveMode(render::FrameRenderer::SolveMode::Asynchronous, [this] {
            QMetaObject::invokeMethod(
                this,
                [this] {
                    emit vssSolved();
                    // A newer solve is under way (e.g. the exact one after the
                    // camera settled): its own arrival draws the frame that
                    // shows it; a frame now would only delay it.
                    if (renderer_.solveInProgress()) {
                        return;
                    }
                    if (moving_) {
                        // The next camera move's frame shows this preview
                        // anyway: a frame of its own only when the camera
                        // pauses (no move within the delay).
                        if (!previewArrivalTimer_->isActive()) {
                            previewArrivalTimer_->start();
                        }
                        return;
                    }
                    requestFrame();
                },
                Qt::QueuedConnection);
        });
        glDescription_ = QString::fromStdString(renderer_.meshRenderer().glDescription());
        sceneDirty_ = true;
        styleDirty_ = true;
        frameDirty_ = true;
    } catch (const vv::Error& e) {
        const QSurfaceFormat f = ctx->format();
        fail(tr("VesselView needs OpenGL 4.1 (core profile); this system offers OpenGL "
                "%1.%2.\n\n%3\n\nUpdate the graphics driver, or run with Mesa's software "
                "renderer (LIBGL_ALWAYS_SOFTWARE=1).")
                 .arg(f.majorVersion())
                 .arg(f.minorVersion())
                 .arg(QString::fromStdString(e.what())));
    }
}

void ViewerWidget::requestFrame() {
    frameDirty_ = true;
    update();
}

void ViewerWidget::resizeGL(int w, int h) {
    // The camera works in logical pixels, like the mouse events.
    Q_UNUSED(w);
    Q_UNUSED(h);
    frameDirty_ = true;  // a new buffer: nothing to reuse
    camera_.setViewport(width(), height());
    legendOverlay_->setGeometry(rect());
}

const render::Legends& ViewerWidget::shownLegends() const noexcept {
    return legendOverlay_->legends();
}

void ViewerWidget::paintMessage(const QString& text) {
    QPainter painter(this);
    painter.fillRect(rect(), QColor(40, 40, 44));
    painter.setPen(Qt::white);
    QFont font = painter.font();
    font.setPointSizeF(font.pointSizeF() * 1.2);
    painter.setFont(font);
    painter.drawText(rect().adjusted(24, 24, -24, -24), Qt::AlignCenter | Qt::TextWordWrap, text);
}

void ViewerWidget::paintGL() {
    if (!error_.isEmpty() || !renderer_.initialized()) {
        // An unusable viewer still paints its message.
        paintMessage(error_.isEmpty() ? tr("OpenGL is not available.") : error_);
        return;
    }
    if (!frameDirty_) {
        // A repaint without a new frame requested (requestFrame): an overlay
        // child redrew or the window was exposed. The buffer still holds the
        // last frame (PartialUpdate); drawing it again would cost a whole
        // frame (hundreds of ms on software rasterisers) for the same pixels.
        return;
    }
    frameDirty_ = false;        // requests made while drawing ask for the next frame
    budgetFrameStart_.reset();  // only a camera-move frame below measures itself
    QElapsedTimer paintTimer;
    paintTimer.start();
    const qint64 paintStart = frameClock_.nsecsElapsed();
    try {
        render::MeshRenderer& meshes = renderer_.meshRenderer();
        if (sceneDirty_) {
            meshes.setScene(scene_);
            renderer_.setSceneRevision(sceneRevision_);
            sceneDirty_ = false;
            styleDirty_ = true;
            previewDirty_ = true;
            closuresDirty_ = closuresKnown_;  // the upload left every mesh Open
        }
        if (previewDirty_) {
            meshes.setPreviewScenes(previewScenes_);
            for (std::size_t level = 0; level < previewClosures_.size(); ++level) {
                meshes.setSurfaceClosures(level + 1, previewClosures_[level]);
            }
            previewDirty_ = false;
        }
        if (closuresDirty_ && scene_) {
            meshes.setSurfaceClosures(0, sceneClosures_);
            closuresDirty_ = false;
        }
        if (styleDirty_) {
            meshes.setStyle(style_);
            styleDirty_ = false;
        }
        camera_.setViewport(width(), height());
        if (autoFit_) {
            // Until the user moves the camera, keep the data framed as the widget resizes.
            camera_.fit(camera_.sceneBounds());
        }
        const render::FrameTarget target = frameTarget();
        const render::FrameSettings settings = frameSettings();
        renderer_.render(camera_, settings, target);
        if (recordTimings_) {
            timings_ = renderer_.lastTimings();
        }
        if (moving_ && cameraMoved_ && frameBudgetMs_ > 0.0) {
            // Dynamic resolution: this frame's time, up to the swap of the
            // window's composed frame (frameSwapped), sets the size of the
            // next camera move's frames. Frames in between (a preview solve
            // arrived) keep this size: the preview was solved at it.
            budgetFrameStart_ = paintStart;
        }
        if (cameraMoved_) {
            previewArrivalTimer_->stop();  // this frame showed the newest preview
        }
        cameraMoved_ = false;
        if (deferOcclusion_ && !moving_) {
            const render::VssFrameStatus& status = renderer_.vssStatus();
            if (!status.pending && !status.preview) {
                // The exact VSS (or no VSS at all) is on screen: now the occlusion.
                deferOcclusion_ = false;
                QTimer::singleShot(0, this, &ViewerWidget::requestFrame);
            }
        }
        const glm::ivec2 rendered = renderer_.lastRenderSize();
        lastRenderSize_ = QSize(rendered.x, rendered.y);
        shownRange_ = meshes.effectiveRange();
        // The legends of the scales in use, over the GL frame.
        legendOverlay_->setLegends(legendsVisible_
                                       ? render::legendsFor(scene_.get(), style_, shownRange_,
                                                            settings, renderer_.vssStatus(),
                                                            renderer_.lastCueDepthRange())
                                       : render::Legends{});
    } catch (const vv::Error& e) {
        const QString why = QString::fromStdString(e.what());
        if (volume_) {
            // Most likely the volume (too big for a 3-D texture or the GPU's
            // memory): drop it and go on with the scene. When the error was
            // another, the next frame fails without a volume and says so.
            volume_.reset();
            renderer_.setVolume(nullptr, 0.0F);
            QTimer::singleShot(0, this, [this, why] { emit volumeFailed(why); });
            requestFrame();
            return;
        }
        fail(tr("Drawing failed: %1").arg(why));
        paintMessage(error_);
        return;
    }
    if (scene_ || volume_) {
        ++framesWithScene_;
    }
    paintMilliseconds_ = static_cast<double>(paintTimer.nsecsElapsed()) / 1e6;
    emit frameRendered();
}

void ViewerWidget::mousePressEvent(QMouseEvent* event) {
    lastMouse_ = event->position();
    pressPosition_ = event->position();  // probe: a click picks
    pressMoved_ = false;
    const bool shift = (event->modifiers() & Qt::ShiftModifier) != 0;
    if (event->button() == Qt::LeftButton) {
        drag_ = shift ? Drag::Pan : Drag::Rotate;
    } else if (event->button() == Qt::RightButton || event->button() == Qt::MiddleButton) {
        drag_ = Drag::Pan;
    }
    event->accept();
}

void ViewerWidget::mouseMoveEvent(QMouseEvent* event) {
    const QPointF position = event->position();
    const glm::vec2 from(static_cast<float>(lastMouse_.x()), static_cast<float>(lastMouse_.y()));
    const glm::vec2 to(static_cast<float>(position.x()), static_cast<float>(position.y()));
    if (drag_ != Drag::None) {  // probe: a drag is not a click; no tooltip while moving
        const QPointF moved = position - pressPosition_;
        pressMoved_ = pressMoved_ || moved.manhattanLength() > 3.0;
        hoverTimer_->stop();
    } else if (hoverProbe_) {
        hoverTimer_->start();
    }
    if (drag_ == Drag::Rotate) {
        camera_.rotate(from, to);
        cameraChanged();
    } else if (drag_ == Drag::Pan) {
        camera_.pan(to - from);
        cameraChanged();
    }
    lastMouse_ = position;
    event->accept();
}

void ViewerWidget::mouseReleaseEvent(QMouseEvent* event) {
    maybePick(event);  // probe
    if (event->buttons() == Qt::NoButton) {
        drag_ = Drag::None;
        settle();  // released: the camera stopped, show the exact VSS now
    }
    event->accept();
}

void ViewerWidget::wheelEvent(QWheelEvent* event) {
    // 120 units = one notch; each notch zooms by 15 %.
    const double notches = event->angleDelta().y() / 120.0;
    if (notches != 0.0) {
        camera_.zoom(static_cast<float>(std::pow(1.15, notches)));
        cameraChanged();
    }
    event->accept();
}

void ViewerWidget::keyPressEvent(QKeyEvent* event) {
    switch (event->key()) {
        case Qt::Key_R:
            resetCamera();
            event->accept();
            return;
        case Qt::Key_F:
            fitToData();
            event->accept();
            return;
        default:
            QOpenGLWidget::keyPressEvent(event);
    }
}

// --- Probe and measurement -------------------------------------------------

namespace {

/// Over a vessel, Qt's tooltip event shows the probe instead of the viewer's
/// mouse help (which would otherwise replace the hover probe after a moment).
class ProbeToolTipFilter : public QObject {
  public:
    explicit ProbeToolTipFilter(ViewerWidget* viewer) : QObject(viewer), viewer_(viewer) {}

  protected:
    bool eventFilter(QObject* watched, QEvent* event) override {
        if (watched == viewer_ && event->type() == QEvent::ToolTip && viewer_->hoverProbe()) {
            const auto* help = static_cast<QHelpEvent*>(event);
            if (const auto result = viewer_->probeAt(QPointF(help->pos()))) {
                QToolTip::showText(help->globalPos(), ViewerWidget::probeText(*result), viewer_);
                return true;
            }
        }
        return QObject::eventFilter(watched, event);
    }

  private:
    ViewerWidget* viewer_;
};

}  // namespace

Measurement measure(const ProbeResult& a, const ProbeResult& b) noexcept {
    return Measurement{glm::length(b.worldPosition - a.worldPosition),
                       b.linearDepth - a.linearDepth};
}

std::optional<ProbeResult> ViewerWidget::probeAt(const QPointF& position) {
    if (!error_.isEmpty() || !renderer_.initialized() || (scene_ == nullptr && !volume_) ||
        lastRenderSize_.isEmpty() || width() < 1 || height() < 1) {
        return std::nullopt;
    }
    // Logical widget pixels -> the last frame's render pixels (GL rows, bottom up).
    const double sx = static_cast<double>(lastRenderSize_.width()) / width();
    const double sy = static_cast<double>(lastRenderSize_.height()) / height();
    const int x = static_cast<int>(std::floor(position.x() * sx));
    const int y = lastRenderSize_.height() - 1 - static_cast<int>(std::floor(position.y() * sy));
    makeCurrent();
    const auto read = [&]() -> std::optional<render::ProbeSample> {
        try {
            auto texel = renderer_.probe(camera_, x, y);
            const std::pair<quint64, std::uint64_t> key{framesWithScene_, sceneRevision_};
            if (texel && nearestKey_ != key) {
                const auto range = renderer_.visibleDepthRange();
                nearestDepth_ = range ? std::optional<float>(range->first) : std::nullopt;
                nearestKey_ = key;
            }
            return texel;
        } catch (const vv::Error& e) {
            static const log::Category category{"vv.gui"};
            log::warning(category, std::string("probe failed: ") + e.what());
            return std::nullopt;
        }
    };
    const std::optional<render::ProbeSample> sample = read();
    doneCurrent();
    const std::size_t meshCount = scene_ ? scene_->meshes.size() : 0U;
    if (!sample || sample->objectId == 0 || sample->objectId > meshCount + (volume_ ? 1U : 0U)) {
        return std::nullopt;
    }
    ProbeResult result;
    result.widgetPosition = position;
    result.linearDepth = sample->linearDepth;
    result.depthBelowNearest =
        std::max(0.0F, sample->linearDepth - nearestDepth_.value_or(sample->linearDepth));
    result.worldPosition = sample->worldPosition;
    if (sample->objectId > meshCount) {
        // The ray-cast volume (object id 1 + mesh count): position and depth, no value.
        result.objectName = tr("Volume (iso-surface at %1)").arg(static_cast<double>(isoValue_));
        result.value = std::numeric_limits<float>::quiet_NaN();
        return result;
    }
    result.meshIndex = static_cast<int>(sample->objectId - 1U);
    const scene::Mesh& mesh = scene_->meshes[static_cast<std::size_t>(result.meshIndex)];
    result.objectName = QString::fromStdString(mesh.name);
    // The array this object shows (its own choice or the scene's).
    const std::string& shown = style_.arrayOf(static_cast<std::size_t>(result.meshIndex));
    result.arrayName = QString::fromStdString(shown);
    if (const scene::DataArray* array = shown.empty() ? nullptr : mesh.pointArray(shown)) {
        result.unit = QString::fromStdString(array->unit);
    }
    result.value = shown.empty() ? std::numeric_limits<float>::quiet_NaN() : sample->value;
    return result;
}

QString ViewerWidget::probeText(const ProbeResult& result) {
    QStringList lines;
    lines << (result.objectName.isEmpty() ? tr("Object %1").arg(result.meshIndex + 1)
                                          : result.objectName);
    if (!result.arrayName.isEmpty()) {
        const QString value = std::isfinite(result.value)
                                  ? QString::number(static_cast<double>(result.value), 'g', 4)
                                  : tr("no data");
        lines << (result.unit.isEmpty() || !std::isfinite(result.value)
                      ? tr("%1: %2").arg(result.arrayName, value)
                      : tr("%1: %2 %3").arg(result.arrayName, value, result.unit));
    }
    lines << tr("Depth: %1 mm behind the nearest vessel point")
                 .arg(QString::number(static_cast<double>(result.depthBelowNearest), 'f', 1));
    return lines.join(QLatin1Char('\n'));
}

void ViewerWidget::setHoverProbe(bool on) {
    hoverProbe_ = on;
    if (hoverTimer_ == nullptr) {
        hoverTimer_ = new QTimer(this);
        hoverTimer_->setSingleShot(true);
        hoverTimer_->setInterval(120);
        connect(hoverTimer_, &QTimer::timeout, this, &ViewerWidget::hoverProbeNow);
        installEventFilter(new ProbeToolTipFilter(this));
    }
    if (on) {
        setMouseTracking(true);
    } else {
        hoverTimer_->stop();
    }
}

void ViewerWidget::hoverProbeNow() {
    if (!hoverProbe_ || drag_ != Drag::None) {
        return;
    }
    const QPointF position = lastMouse_;  // where the mouse came to rest
    if (const auto result = probeAt(position)) {
        QToolTip::showText(mapToGlobal(position.toPoint()), probeText(*result), this);
    } else {
        QToolTip::hideText();
    }
}

void ViewerWidget::maybePick(QMouseEvent* event) {
    if (event->button() != Qt::LeftButton || pressMoved_) {
        return;
    }
    const bool ctrl = (event->modifiers() & Qt::ControlModifier) != 0;
    if (!measureMode_ && !ctrl) {
        return;
    }
    if (const auto result = probeAt(event->position())) {
        emit pointPicked(*result);
    } else {
        emit pickMissed();
    }
}

// --- end probe -------------------------------------------------------------

}  // namespace vv::gui
