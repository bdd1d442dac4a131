// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/ViewerWidget.h"

#include <QElapsedTimer>
#include <QGuiApplication>
#include <QHelpEvent>
#include <QKeyEvent>
#include <QLocale>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QPaintEvent>
#include <QPainter>
#include <QTimer>
#include <QToolTip>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <utility>

#include "common/SmoothCopy.h"
#include "gui/EngineTexts.h"
#include "gui/ViewOverlay.h"
#include "vv/core/Error.h"
#include "vv/core/Log.h"
#include "vv/meshio/MeshSimplify.h"
#include "vv/render/LegendPainter.h"
#include "vv/render/ViewPresets.h"

namespace vv::gui {

ViewerWidget::ViewerWidget(QWidget* parent) : QOpenGLWidget(parent) {
    viewOverlay_ = new ViewOverlay(this);
    viewOverlay_->setGeometry(rect());
    settleTimer_ = new QTimer(this);
    settleTimer_->setSingleShot(true);
    settleTimer_->setInterval(settleDelayMs_);
    connect(settleTimer_, &QTimer::timeout, this, &ViewerWidget::settle);
    previewArrivalTimer_ = new QTimer(this);
    previewArrivalTimer_->setSingleShot(true);
    previewArrivalTimer_->setInterval(kPreviewArrivalDelayMs);
    connect(previewArrivalTimer_, &QTimer::timeout, this, &ViewerWidget::requestFrame);
    connect(this, &QOpenGLWidget::frameSwapped, this, [this] {
        // Drawing plus Qt composing the window: what the frame rate sees
        // (on software OpenGL the composition alone takes ~15 ms at 720p),
        // by the work it took (render::frameCostMilliseconds).
        if (const auto frame = frameMeter_.atSwap()) {
            view_.refinement().frameMeasured(*frame);
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
    previewRun_.cancel();
    previewRun_.waitForFinished();
    closureRun_.waitForFinished();
    // ~QOpenGLWidget destroys the context after this body, when this object is
    // only a QOpenGLWidget and view_ is gone: its aboutToBeDestroyed must
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
    frameMeter_.release();
    view_.release();
    doneCurrent();
}

void ViewerWidget::setScene(std::shared_ptr<const scene::Scene> scene) {
    view_.setScene(std::move(scene));
    view_.refinement().forgetCosts();  // another scene, other frame costs
    startPreviewGeometry();
    startSmoothCopy();
    startClosureCheck();
    framesWithScene_ = 0;
    camera_.setViewport(width(), height());
    camera_.setHomeRotation(
        render::homeRotation(view_.scene() ? view_.scene()->frame : scene::SceneFrame::Unknown));
    camera_.reset();
    camera_.fit(dataBounds());
    autoFit_ = true;
    requestFrame();
}

void ViewerWidget::setVolume(std::shared_ptr<const scene::Volume> volume, float isoValue) {
    view_.setVolume(std::move(volume), isoValue);
    framesWithScene_ = 0;
    if (const Aabb box = dataBounds(); !box.empty()) {
        camera_.setSceneBounds(box);  // clip planes; the view stays
    }
    requestFrame();
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

/// The simplified copies of `scene` for moving frames: `budget` triangles,
/// then a `coarse`-triangle copy of that one (cheap) when worth it, each with
/// its closures (decimation may open a surface); none when cancelled or
/// failed (moving frames then draw the full meshes).
render::PreviewGeometry simplifiedLevels(const scene::Scene& scene, std::size_t budget,
                                         std::size_t coarse, const std::stop_token& stop) {
    // Not worth it below 1.5x the budget: the full meshes are cheap enough.
    const auto worthIt = [](std::size_t have, std::size_t wanted) {
        return wanted > 0 && have * 2 > wanted * 3;
    };
    if (!worthIt(scene.triangleCount(), budget)) {
        return {};
    }
    try {
        render::PreviewGeometry levels;
        auto fine = std::make_shared<const scene::Scene>(
            meshio::simplifiedScene(scene, budget, Progress({}, stop)));
        levels.scenes.push_back(fine);
        levels.closures.push_back(closuresOf(*fine));
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
        static const log::Category category{"vv.gui"};
        log::warning(category, std::string("no simplified geometry: ") + e.what());
        return {};
    }
}

}  // namespace

void ViewerWidget::startClosureCheck() {
    closureRun_.cancel();
    const std::shared_ptr<const scene::Scene> scene = view_.scene();
    if (!scene) {
        return;
    }
    closureRun_.start([scene](const std::stop_token&) { return closuresOf(*scene); },
                      [this](std::vector<scene::SurfaceClosure> closures) {
                          // The next frame culls; this one's pixels stay right.
                          view_.setSurfaceClosures(std::move(closures));
                      });
}

void ViewerWidget::startPreviewGeometry() {
    previewRun_.cancel();
    const std::shared_ptr<const scene::Scene> scene = view_.scene();
    if (!scene) {
        return;
    }
    const std::size_t budget = previewTriangles_;
    previewRun_.start(
        [scene, budget](const std::stop_token& stop) {
            // The budget, then a third of it: the renderer draws the coarser
            // one into small moving frames.
            return simplifiedLevels(*scene, budget, budget / kPreviewLevelRatio, stop);
        },
        [this](render::PreviewGeometry levels) {
            if (levels.scenes.empty()) {
                return;  // cancelled, failed, or not worth it
            }
            view_.setPreviewGeometry(std::move(levels));
            emit previewGeometryReady();
        });
}

void ViewerWidget::startSmoothCopy() {
    smoothRun_.cancel();
    const std::shared_ptr<const scene::Scene> scene = view_.scene();
    if (!scene || !smoothCoarseMeshes() || view_.refinedGeometry().scene) {
        return;
    }
    smoothRun_.start(
        [scene](const std::stop_token& stop) -> std::optional<render::RefinedGeometry> {
            try {
                return app::smoothCopyOf(*scene, Progress({}, stop));
            } catch (const CancelledError&) {
                return std::nullopt;
            }
        },
        [this, scene](std::optional<render::RefinedGeometry> copy) {
            if (!copy || view_.scene() != scene) {
                return;  // none wanted, cancelled, or another scene by now
            }
            const double largest = copy->largestDeviationMm;
            const double mean = copy->meanDeviationMm;
            view_.setRefinedGeometry(std::move(*copy));
            requestFrame();
            emit smoothCopyReady(largest, mean);
        });
}

void ViewerWidget::setSmoothCoarseMeshes(bool on) {
    if (on == smoothCoarseMeshes()) {
        return;
    }
    view_.setSmoothCoarseMeshes(on);
    if (on) {
        startSmoothCopy();
    }
    requestFrame();
}

void ViewerWidget::setStyle(const render::MeshStyle& style) {
    view_.setStyle(style);
    requestFrame();
}

void ViewerWidget::setVssSettings(const render::VssSettings& settings) {
    view_.setVssSettings(settings);
    requestFrame();
}

void ViewerWidget::setAoSettings(const render::AoSettings& settings) {
    view_.setAoSettings(settings);
    requestFrame();
}

void ViewerWidget::setVesselCue(const render::VesselCueSettings& cue) {
    view_.setVesselCue(cue);
    requestFrame();
}

void ViewerWidget::setBackground(const glm::vec3& color) {
    view_.setBackground(color);
    requestFrame();
}

void ViewerWidget::setLegendsVisible(bool visible) {
    legendsVisible_ = visible;
    requestFrame();
}

void ViewerWidget::setViewAnnotations(const render::ViewAnnotations& annotations) {
    annotations_ = annotations;
    requestFrame();
}

void ViewerWidget::setProgressiveRefinement(bool on) {
    view_.refinement().setProgressive(on);
    if (!on) {
        settle();
    }
}

void ViewerWidget::setSettleDelay(int milliseconds) {
    settleDelayMs_ = std::max(milliseconds, 0);
    settleTimer_->setInterval(settleDelayMs_);
}

void ViewerWidget::setPreviewArrivalDelay(int milliseconds) {
    previewArrivalTimer_->setInterval(std::max(milliseconds, 0));
}

int ViewerWidget::previewArrivalDelay() const {
    return previewArrivalTimer_->interval();
}

void ViewerWidget::setFrameBudget(double milliseconds) {
    view_.refinement().setFrameBudget(milliseconds);
}

void ViewerWidget::setInteractiveScale(float scale, float vssScale) {
    view_.refinement().setInteractiveScale(scale, vssScale);
    requestFrame();
}

void ViewerWidget::cameraChanged() {
    autoFit_ = false;
    if (view_.refinement().cameraMoved()) {
        settleTimer_->start();  // restarts: the camera settles settleDelay() after the last change
    }
    requestFrame();
}

void ViewerWidget::settle() {
    settleTimer_->stop();
    if (!view_.refinement().settle()) {
        return;
    }
    previewArrivalTimer_->stop();  // the settled frames show the newest VSS
    render::SettleResult result = render::SettleResult::None;
    if (error_.isEmpty() && view_.initialized() && !autoFit_) {
        bool current = false;
        result = view_.settle(camera_, frameTarget(), [this, &current] {
            makeCurrent();
            current = true;
        });
        if (current) {
            doneCurrent();
        }
    }
    emit cameraSettled();
    if (result == render::SettleResult::None) {
        requestFrame();  // the next frame reads the depth back and asks for the exact VSS
    }
}

void ViewerWidget::solveArrived() {
    emit vssSolved();
    // A newer solve is under way (e.g. the exact one after the camera
    // settled): its own arrival draws the frame that shows it; a frame now
    // would only delay it.
    if (view_.frameRenderer().solveInProgress()) {
        return;
    }
    if (view_.refinement().moving()) {
        // The next camera move's frame shows this preview anyway: a frame of
        // its own only when the camera pauses (no move within the delay).
        if (!previewArrivalTimer_->isActive()) {
            previewArrivalTimer_->start();
        }
        return;
    }
    requestFrame();
}

render::FrameTarget ViewerWidget::frameTarget() const {
    // The camera works in logical pixels, the frame in device pixels.
    const qreal ratio = devicePixelRatioF();
    return render::FrameTarget{defaultFramebufferObject(),
                               std::max(1, static_cast<int>(std::lround(width() * ratio))),
                               std::max(1, static_cast<int>(std::lround(height() * ratio)))};
}

void ViewerWidget::setCamera(const render::Camera& camera) {
    const glm::quat home = camera_.homeRotation();  // the scene's, whoever made `camera`
    camera_ = camera;
    camera_.setHomeRotation(home);
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
        view_.initialize();  // everything is uploaded anew by the next frame
        // Called on the solver's thread: hand the repaint to the GUI thread
        // (dropped if the widget is gone by then).
        view_.setSolveMode(render::FrameRenderer::SolveMode::Asynchronous, [this] {
            QMetaObject::invokeMethod(this, &ViewerWidget::solveArrived, Qt::QueuedConnection);
        });
        glDescription_ = QString::fromStdString(view_.meshRenderer().glDescription());
        frameMeter_.initialize();
        frameDirty_ = true;
    } catch (const vv::Error& e) {
        // In the UI language; the module's own words go to the log.
        static const log::Category category{"vv.gui"};
        log::warning(category, std::string("OpenGL set-up failed: ") + e.what());
        const QSurfaceFormat f = ctx->format();
        fail(tr("VesselView needs OpenGL 4.1 (core profile); this system offers OpenGL "
                "%1.%2.\n\n%3\n\nUpdate the graphics driver, or run with Mesa's software "
                "renderer (LIBGL_ALWAYS_SOFTWARE=1).")
                 .arg(f.majorVersion())
                 .arg(f.minorVersion())
                 .arg(describeProblem(e, FileAccess::Reading).line()));
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
    frameDirty_ = true;                // a new buffer: nothing to reuse
    view_.refinement().forgetCosts();  // other sizes, other frame costs
    camera_.setViewport(width(), height());
    viewOverlay_->setGeometry(rect());
}

const render::Legends& ViewerWidget::shownLegends() const noexcept {
    return viewOverlay_->legends();
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
    if (!error_.isEmpty() || !view_.initialized()) {
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
    frameDirty_ = false;  // requests made while drawing ask for the next frame
    QElapsedTimer paintTimer;
    paintTimer.start();
    frameMeter_.beginFrame();
    try {
        camera_.setViewport(width(), height());
        if (autoFit_) {
            // Until the user moves the camera, keep the data framed as the widget resizes.
            camera_.fit(camera_.sceneBounds());
        }
        const render::RefinementPolicy::AfterFrame after = view_.render(camera_, frameTarget());
        // Dynamic resolution: a camera-move frame's cost, up to the swap of
        // the window's composed frame (frameSwapped), sets the size of the
        // next camera move's frames; other frames measure nothing.
        frameMeter_.endFrame(after.measure);
        if (after.showedCameraMove) {
            previewArrivalTimer_->stop();  // this frame showed the newest preview
        }
        if (after.occlusionFrame) {
            // The exact VSS (or no VSS at all) is on screen: now the occlusion.
            QTimer::singleShot(0, this, &ViewerWidget::requestFrame);
        }
        const glm::ivec2 rendered = view_.frameRenderer().lastRenderSize();
        lastRenderSize_ = QSize(rendered.x, rendered.y);
        // The legends of the scales in use, the marker and the scale bar, over the GL frame.
        viewOverlay_->setFrame(legendsVisible_ ? view_.legends() : render::Legends{}, camera_,
                               annotations_);
    } catch (const vv::Error& e) {
        // In the UI language; the module's own words go to the log.
        static const log::Category category{"vv.gui"};
        log::warning(category, std::string("drawing failed: ") + e.what());
        const QString why = describeProblem(e, FileAccess::Reading).line();
        if (volume()) {
            // Most likely the volume (too big for a 3-D texture or the GPU's
            // memory): drop it and go on with the scene. When the error was
            // another, the next frame fails without a volume and says so.
            view_.setVolume(nullptr, view_.isoValue());
            QTimer::singleShot(0, this, [this, why] { emit volumeFailed(why); });
            requestFrame();
            return;
        }
        fail(tr("Drawing failed: %1").arg(why));
        paintMessage(error_);
        return;
    }
    if (scene() || volume()) {
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

Measurement measure(const ProbeResult& a, const ProbeResult& b,
                    const render::Camera& camera) noexcept {
    const glm::vec3 ab = b.worldPosition - a.worldPosition;
    return Measurement{glm::length(ab), glm::dot(ab, camera.forward())};
}

std::optional<ProbeResult> ViewerWidget::probeAt(const QPointF& position) {
    const std::shared_ptr<const scene::Scene>& shown = scene();
    if (!error_.isEmpty() || !view_.initialized() || (shown == nullptr && !volume()) ||
        lastRenderSize_.isEmpty() || width() < 1 || height() < 1) {
        return std::nullopt;
    }
    // Logical widget pixels -> the last frame's render pixels (GL rows, bottom up).
    const double sx = static_cast<double>(lastRenderSize_.width()) / width();
    const double sy = static_cast<double>(lastRenderSize_.height()) / height();
    const int x = static_cast<int>(std::floor(position.x() * sx));
    const int y = lastRenderSize_.height() - 1 - static_cast<int>(std::floor(position.y() * sy));
    makeCurrent();
    std::optional<render::ViewProbe> sample;
    try {
        sample = view_.probe(camera_, x, y);
    } catch (const vv::Error& e) {
        static const log::Category category{"vv.gui"};
        log::warning(category, std::string("probe failed: ") + e.what());
    }
    doneCurrent();
    if (!sample) {
        return std::nullopt;
    }
    ProbeResult result;
    result.widgetPosition = position;
    result.meshIndex = sample->meshIndex;
    result.arrayName = QString::fromStdString(sample->arrayName);
    result.unit = QString::fromStdString(sample->unit);
    result.value = sample->value;
    result.linearDepth = sample->linearDepth;
    result.depthBelowNearest = sample->depthBelowNearest;
    result.depthReference = sample->depthReference;
    result.worldPosition = sample->worldPosition;
    if (sample->label) {
        result.labelName = QString::fromStdString(sample->label->name);
    }
    result.objectName = sample->meshIndex < 0
                            ? tr("Volume (iso-surface at %1)").arg(static_cast<double>(isoValue()))
                            : QString::fromStdString(
                                  shown->meshes[static_cast<std::size_t>(sample->meshIndex)].name);
    return result;
}

QString ViewerWidget::probeText(const ProbeResult& result) {
    QStringList lines;
    lines << (result.objectName.isEmpty() ? tr("Object %1").arg(result.meshIndex + 1)
                                          : result.objectName);
    const QLocale locale;
    if (result.labelName) {
        // A label names a segment / group: "segment_id 2 (Left iliac)".
        const QString value = locale.toString(static_cast<qlonglong>(result.value));
        lines << (result.labelName->isEmpty()
                      ? tr("%1 %2").arg(result.arrayName, value)
                      : tr("%1 %2 (%3)").arg(result.arrayName, value, *result.labelName));
    } else if (!result.arrayName.isEmpty()) {
        const QString value = std::isfinite(result.value)
                                  ? locale.toString(static_cast<double>(result.value), 'g', 4)
                                  : tr("no data");
        lines << (result.unit.isEmpty() || !std::isfinite(result.value)
                      ? tr("%1: %2").arg(result.arrayName, value)
                      : tr("%1: %2 %3").arg(result.arrayName, value, result.unit));
    }
    // The depth legend's quantity, in its words (render::depthQuantityName()):
    // the number a person compares with the legend's.
    const float depth = result.depthReference == render::DepthReference::Camera
                            ? result.linearDepth
                            : result.depthBelowNearest;
    lines << tr("%1: %2 mm")
                 .arg(render::depthQuantityName(result.depthReference),
                      locale.toString(static_cast<double>(depth), 'f', 1));
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
