// SPDX-License-Identifier: GPL-3.0-or-later
// Progressive VSS refinement in the viewer: a preview solve while the camera
// moves, the exact one after it stops, stale solves cancelled; and a
// benchmark-style run rotating the demo at 1280x720 (numbers printed, not
// asserted). Run under `xvfb-run -a` with QT_QPA_PLATFORM=xcb.
#include <gtest/gtest.h>

#include <QApplication>
#include <QComboBox>
#include <QElapsedTimer>
#include <QImage>
#include <QLabel>
#include <QMouseEvent>
#include <QThread>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <functional>
#include <glm/glm.hpp>
#include <map>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "ImageCompare.h"
#include "WaitUntil.h"
#include "gui/MainWindow.h"
#include "gui/ViewerWidget.h"
#include "vv/demo/DemoTree.h"
#include "vv/meshio/MeshLoader.h"
#include "vv/render/MeshRenderer.h"
#include "vv/render/RefinementPolicy.h"

namespace {

using vv::gui::ViewerWidget;

void ensureApplication() {
    if (QCoreApplication::instance() != nullptr) {
        return;
    }
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM") && qEnvironmentVariableIsEmpty("DISPLAY") &&
        qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY")) {
        qputenv("QT_QPA_PLATFORM", "offscreen");
    }
    ViewerWidget::installDefaultFormat();
    static int argc = 1;
    static char name[] = "vv_gui_tests";
    static char* argv[] = {name, nullptr};
    new QApplication(argc, argv);  // kept for the whole process
}

bool waitUntil(const std::function<bool()>& done, int timeoutMs = 60000) {
    return vv::test::pollUntil(done, std::chrono::milliseconds(timeoutMs), [] {
        QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
        QThread::msleep(1);
    });
}

/// A tube of radius r from a to b (axis along x or y).
void addTube(vv::scene::Mesh& mesh, glm::vec3 a, glm::vec3 b, float r) {
    constexpr int kSegments = 24;
    constexpr int kRings = 24;
    const glm::vec3 axis = glm::normalize(b - a);
    const glm::vec3 u = glm::normalize(glm::cross(axis, glm::vec3(0, 0, 1)));
    const glm::vec3 v = glm::cross(axis, u);
    const auto base = static_cast<std::uint32_t>(mesh.positions.size());
    for (int i = 0; i <= kRings; ++i) {
        const glm::vec3 c = a + (b - a) * (static_cast<float>(i) / kRings);
        for (int j = 0; j < kSegments; ++j) {
            const float phi = 2.0F * std::numbers::pi_v<float> * static_cast<float>(j) / kSegments;
            const glm::vec3 n = std::cos(phi) * u + std::sin(phi) * v;
            mesh.positions.push_back(c + r * n);
            mesh.normals.push_back(n);
        }
    }
    for (std::uint32_t i = 0; i < kRings; ++i) {
        for (std::uint32_t j = 0; j < kSegments; ++j) {
            const std::uint32_t p = base + i * kSegments + j;
            const std::uint32_t q = base + i * kSegments + (j + 1) % kSegments;
            mesh.indices.insert(mesh.indices.end(),
                                {p, p + kSegments, q, q, p + kSegments, q + kSegments});
        }
    }
}

/// Three tubes at different depths: a VSS with a real slope between them.
std::shared_ptr<const vv::scene::Scene> makeScene() {
    auto scene = std::make_shared<vv::scene::Scene>();
    vv::scene::Mesh mesh;
    mesh.name = "tubes";
    addTube(mesh, {-20, -12, 0}, {20, -12, 0}, 2.0F);
    addTube(mesh, {-20, 12, -25}, {20, 12, -25}, 2.0F);
    addTube(mesh, {0, -20, -10}, {0, 20, -10}, 1.5F);
    scene->meshes.push_back(std::move(mesh));
    return scene;
}

class Drag {
  public:
    explicit Drag(ViewerWidget& viewer)
        : viewer_(viewer), at_(viewer.width() / 2.0, viewer.height() / 2.0) {
        QMouseEvent press(QEvent::MouseButtonPress, at_, viewer_.mapToGlobal(at_), Qt::LeftButton,
                          Qt::LeftButton, Qt::NoModifier);
        QCoreApplication::sendEvent(&viewer_, &press);
    }
    void moveBy(QPointF delta) {
        at_ += delta;
        QMouseEvent move(QEvent::MouseMove, at_, viewer_.mapToGlobal(at_), Qt::NoButton,
                         Qt::LeftButton, Qt::NoModifier);
        QCoreApplication::sendEvent(&viewer_, &move);
    }
    void release() {
        QMouseEvent up(QEvent::MouseButtonRelease, at_, viewer_.mapToGlobal(at_), Qt::LeftButton,
                       Qt::NoButton, Qt::NoModifier);
        QCoreApplication::sendEvent(&viewer_, &up);
    }

  private:
    ViewerWidget& viewer_;
    QPointF at_;
};

bool exactShown(const ViewerWidget& viewer) {
    const auto& s = viewer.vssStatus();
    return s.shown && s.current && !s.preview && !s.pending;
}

bool previewShown(const ViewerWidget& viewer) {
    const auto& s = viewer.vssStatus();
    return s.shown && s.current && s.preview;
}

/// Largest |a - b| over pixels where both are finite; -1 when sizes differ
/// or no pixel is comparable.
double maxDifference(const vv::Image<float>& a, const vv::Image<float>& b, long* compared) {
    *compared = 0;
    if (a.width() != b.width() || a.height() != b.height() || a.width() == 0) {
        return -1.0;
    }
    double worst = 0.0;
    for (int y = 0; y < a.height(); ++y) {
        for (int x = 0; x < a.width(); ++x) {
            const float p = a.row(y)[x];
            const float q = b.row(y)[x];
            if (std::isfinite(p) && std::isfinite(q)) {
                worst = std::max(worst, static_cast<double>(std::abs(p - q)));
                ++*compared;
            }
        }
    }
    return *compared > 0 ? worst : -1.0;
}

/// The state of the pass `name` in the viewer's last frame (Pending: not in the graph).
vv::render::PassState passStateOf(const ViewerWidget& viewer, const char* name) {
    for (const auto& pass : viewer.lastPasses()) {
        if (pass.name == name) {
            return pass.state;
        }
    }
    return vv::render::PassState::Pending;
}

/// One view as a moving frame and as the settled frame.
struct MovingAndSettled {
    QImage moving;     ///< the frame drawn while the camera moves, with this view's preview VSS
    QImage settled;    ///< the same view after the release: exact VSS, occlusion, FXAA
    QSize movingSize;  ///< the moving frame's render size
    glm::ivec2 movingVssSize{0};  ///< the size its VSS was solved and shaded at
    bool ok = false;              ///< both frames were drawn
};

/// Drags the viewer by `moves` steps of `step`, holds the button until the
/// preview of the last view is on screen (a moving frame of exactly that
/// view), grabs it, releases and grabs the settled frame of the same view
/// once its exact VSS, occlusion and FXAA are drawn.
MovingAndSettled movingAndSettled(ViewerWidget& viewer, int moves, QPointF step) {
    MovingAndSettled out;
    viewer.setSettleDelay(600000);  // only the release settles
    Drag drag(viewer);
    for (int i = 0; i < moves; ++i) {
        const quint64 frames = viewer.framesWithScene();
        drag.moveBy(step);
        if (!waitUntil([&] { return viewer.framesWithScene() > frames; })) {
            drag.release();
            return out;
        }
    }
    if (!waitUntil([&] { return previewShown(viewer) && viewer.view().refinement().moving(); })) {
        drag.release();
        return out;
    }
    out.moving = viewer.grabFramebuffer();
    out.movingSize = viewer.lastRenderSize();
    out.movingVssSize = viewer.view().frameRenderer().lastVssSize();
    drag.release();
    out.ok = waitUntil([&] {
        return exactShown(viewer) && !viewer.occlusionDeferred() &&
               passStateOf(viewer, "fxaa") == vv::render::PassState::Executed;
    });
    out.settled = viewer.grabFramebuffer();
    return out;
}

class ProgressiveTest : public ::testing::Test {
  protected:
    static void SetUpTestSuite() { ensureApplication(); }

    void TearDown() override {
        window_.reset();
        QCoreApplication::processEvents();
    }

    /// A main window at `w` x `h` showing `scene` with the VSS on.
    ViewerWidget& open(std::shared_ptr<const vv::scene::Scene> scene, int w, int h,
                       const vv::render::VssSettings* vss = nullptr) {
        window_ = std::make_unique<vv::gui::MainWindow>();
        window_->resize(w, h);
        ViewerWidget& viewer = *window_->viewer();
        if (vss != nullptr) {
            viewer.setVssSettings(*vss);
        }
        window_->setScene(std::move(scene), QStringLiteral("progressive"));
        window_->show();
        return viewer;
    }

    std::unique_ptr<vv::gui::MainWindow> window_;
};

TEST_F(ProgressiveTest, PreviewWhileRotatingThenExactWithinTheTolerance) {
    ViewerWidget& viewer = open(makeScene(), 800, 600);
    ASSERT_TRUE(waitUntil([&] { return exactShown(viewer) || !viewer.renderError().isEmpty(); }))
        << "the first exact VSS never arrived";
    ASSERT_TRUE(viewer.renderError().isEmpty()) << viewer.renderError().toStdString();
    EXPECT_FALSE(viewer.view().refinement().moving());
    EXPECT_TRUE(waitUntil([&] {
        // The default fast solver: its error bound, not "exact".
        return window_->vssQualityLabel()->text().startsWith(QStringLiteral("VSS: within"));
    })) << window_->vssQualityLabel()->text().toStdString();

    // Hold the button after the drag: the settle timer alone decides (long here).
    viewer.setSettleDelay(600000);
    // Full-size preview frames, so preview and exact VSS compare pixel by pixel.
    viewer.setInteractiveScale(1.0F);
    Drag drag(viewer);
    drag.moveBy({60, 25});
    EXPECT_TRUE(viewer.view().refinement().moving());
    ASSERT_TRUE(waitUntil([&] { return previewShown(viewer); })) << "no preview VSS arrived";
    EXPECT_TRUE(viewer.view().refinement().moving());
    // AO is skipped while moving.
    for (const auto& pass : viewer.lastPasses()) {
        if (pass.name == "ssao") {
            EXPECT_EQ(pass.state, vv::render::PassState::Culled);
        }
    }
    EXPECT_TRUE(waitUntil([&] {
        return window_->vssQualityLabel()->text() == QStringLiteral("VSS: preview");
    })) << window_->vssQualityLabel()->text().toStdString();
    const vv::Image<float> preview = viewer.view().frameRenderer().shownHeight();

    // Released: the camera stopped, the exact solve of the same view follows.
    drag.release();
    EXPECT_FALSE(viewer.view().refinement().moving());
    ASSERT_TRUE(waitUntil([&] { return exactShown(viewer); })) << "no exact VSS after stopping";
    const vv::Image<float> exact = viewer.view().frameRenderer().shownHeight();
    EXPECT_TRUE(waitUntil([&] {
        // The default fast solver: its error bound, not "exact".
        return window_->vssQualityLabel()->text().startsWith(QStringLiteral("VSS: within"));
    })) << window_->vssQualityLabel()->text().toStdString();

    // Both are fast-solver results within their tolerance of the true z', so
    // they differ by at most the sum of the two tolerances.
    const vv::render::VssSettings& vss = viewer.vssSettings();
    const double bound = vss.previewTolerance + vss.solver.tolerance + 1e-5;
    long compared = 0;
    const double worst = maxDifference(preview, exact, &compared);
    EXPECT_GT(compared, static_cast<long>(preview.width()) * preview.height() / 4);
    EXPECT_GE(worst, 0.0);
    EXPECT_LE(worst, bound) << "preview and exact VSS differ by " << worst;
    std::printf("[progressive] preview vs exact: max |dz'| = %.4f (bound %.4f) over %ld pixels\n",
                worst, bound, compared);
}

// Settling shows the exact VSS as early as it can: that frame leaves out the
// ambient occlusion, and the frame right after adds it without solving again.
TEST_F(ProgressiveTest, SettlingShowsTheExactVssFirstThenTheOcclusionAndFxaa) {
    ViewerWidget& viewer = open(makeScene(), 640, 480);
    ASSERT_TRUE(waitUntil([&] { return exactShown(viewer) || !viewer.renderError().isEmpty(); }));
    ASSERT_TRUE(viewer.renderError().isEmpty()) << viewer.renderError().toStdString();
    const auto passState = [&](const char* name) { return passStateOf(viewer, name); };
    EXPECT_EQ(passState("ssao"), vv::render::PassState::Executed);
    EXPECT_EQ(passState("fxaa"), vv::render::PassState::Executed);
    EXPECT_FALSE(viewer.occlusionDeferred());

    // Every frame from the release on is recorded: (exact VSS shown, AO and FXAA states).
    struct Seen {
        bool exact;
        vv::render::PassState ssao;
        vv::render::PassState fxaa;
        vv::render::PassState vessels;
    };
    std::vector<Seen> frames;
    viewer.setSettleDelay(600000);
    Drag drag(viewer);
    drag.moveBy({40, 10});
    ASSERT_TRUE(waitUntil([&] { return previewShown(viewer); }));
    const QMetaObject::Connection record =
        QObject::connect(&viewer, &ViewerWidget::frameRendered, [&] {
            frames.push_back({exactShown(viewer), passState("ssao"), passState("fxaa"),
                              passState("vessel-shading")});
        });
    const quint64 prepared = viewer.view().solvesPreparedOnSettle();
    drag.release();
    EXPECT_TRUE(viewer.occlusionDeferred());
    // The moving frames were smaller: settling drew this view's G-buffer,
    // started the solve and shaded the vessels meanwhile.
    EXPECT_EQ(viewer.view().solvesPreparedOnSettle(), prepared + 1);
    ASSERT_TRUE(waitUntil([&] { return exactShown(viewer) && !viewer.occlusionDeferred(); }));
    const auto solved = viewer.view().frameRenderer().solveCounters().completed;
    ASSERT_TRUE(waitUntil([&] {
        return !frames.empty() && frames.back().exact &&
               frames.back().ssao == vv::render::PassState::Executed;
    })) << "the occlusion never followed the exact VSS";
    QObject::disconnect(record);

    // The first frame with the exact VSS had no occlusion; the one after had it.
    std::size_t firstExact = frames.size();
    for (std::size_t i = 0; i < frames.size(); ++i) {
        if (frames[i].exact) {
            firstExact = i;
            break;
        }
    }
    ASSERT_LT(firstExact + 1, frames.size());
    EXPECT_NE(frames[firstExact].ssao, vv::render::PassState::Executed);
    EXPECT_NE(frames[firstExact].fxaa, vv::render::PassState::Executed);
    EXPECT_EQ(frames[firstExact + 1].ssao, vv::render::PassState::Executed);
    EXPECT_EQ(frames[firstExact + 1].fxaa, vv::render::PassState::Executed);
    EXPECT_TRUE(frames[firstExact + 1].exact);
    EXPECT_EQ(viewer.view().frameRenderer().solveCounters().completed, solved)
        << "adding the occlusion solved again";
    // The vessels were shaded while the solve ran: the exact frame reused them.
    EXPECT_EQ(frames[firstExact].vessels, vv::render::PassState::Cached);

    // Kept vessel colours follow the style: another vessel colour re-shades them.
    const QImage before = viewer.grabFramebuffer();
    vv::render::MeshStyle style = viewer.style();
    style.vesselColor = glm::vec3(0.9F, 0.1F, 0.1F);
    const quint64 count = viewer.framesWithScene();
    viewer.setStyle(style);
    ASSERT_TRUE(waitUntil([&] { return viewer.framesWithScene() > count; }));
    EXPECT_EQ(passState("vessel-shading"), vv::render::PassState::Executed);
    const QImage after = viewer.grabFramebuffer();
    ASSERT_EQ(before.size(), after.size());
    int changed = 0;
    for (int y = 0; y < before.height(); y += 2) {
        for (int x = 0; x < before.width(); x += 2) {
            changed += before.pixel(x, y) != after.pixel(x, y) ? 1 : 0;
        }
    }
    EXPECT_GT(changed, 100) << "the vessels kept their old colour";
}

// A repaint nobody asked a frame for (an overlay child redrawing, an expose)
// keeps the last frame instead of running the whole graph again; a change
// of what is shown draws a new one.
TEST_F(ProgressiveTest, RepaintsWithoutAChangeKeepTheLastFrame) {
    ViewerWidget& viewer = open(makeScene(), 400, 300);
    ASSERT_TRUE(waitUntil([&] { return exactShown(viewer) && !viewer.occlusionDeferred(); }));
    // Let every frame that was asked for be drawn.
    quint64 frames = viewer.framesWithScene();
    for (int i = 0; i < 20; ++i) {
        QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
        QThread::msleep(10);
        if (viewer.framesWithScene() != frames) {
            frames = viewer.framesWithScene();
            i = 0;
        }
    }
    const QImage before = viewer.grabFramebuffer();

    // Qt-side repaints: the widget itself and its legend overlay child.
    static_cast<QWidget&>(viewer).repaint();
    for (QWidget* child : viewer.findChildren<QWidget*>()) {
        child->repaint();
    }
    QCoreApplication::processEvents(QEventLoop::AllEvents, 50);
    EXPECT_EQ(viewer.framesWithScene(), frames) << "a repaint without a change drew a new frame";
    const QImage kept = viewer.grabFramebuffer();
    ASSERT_EQ(kept.size(), before.size());
    EXPECT_TRUE(kept == before) << "the kept frame is not the last one drawn";

    // A real change draws a frame: the background, shown once the VSS is off.
    vv::render::VssSettings off = viewer.vssSettings();
    off.enabled = false;
    viewer.setVssSettings(off);
    viewer.setBackground({1.0F, 0.0F, 0.0F});
    ASSERT_TRUE(waitUntil([&] { return viewer.framesWithScene() > frames; }));
    const QImage after = viewer.grabFramebuffer();
    EXPECT_EQ(after.pixelColor(0, 0), QColor(255, 0, 0));
    EXPECT_NE(before.pixelColor(0, 0), QColor(255, 0, 0));
}

// Dynamic resolution: moving frames shrink when they take longer than the
// budget and grow back to full size when they are fast; a set scale stays.
TEST_F(ProgressiveTest, MovingFramesAdaptTheirSizeToTheFrameBudget) {
    ViewerWidget& viewer = open(makeScene(), 640, 480);
    ASSERT_TRUE(waitUntil([&] { return exactShown(viewer); }));
    EXPECT_GT(viewer.view().refinement().frameBudget(), 0.0);  // on by default
    viewer.setSettleDelay(600000);
    const auto rotate = [&](int moves) {
        Drag drag(viewer);
        for (int i = 0; i < moves; ++i) {
            const quint64 frames = viewer.framesWithScene();
            drag.moveBy({6, 2});
            EXPECT_TRUE(waitUntil([&] { return viewer.framesWithScene() > frames; }));
        }
        drag.release();
        EXPECT_TRUE(waitUntil([&] { return exactShown(viewer) && !viewer.occlusionDeferred(); }));
    };
    // No frame fits in 0.01 ms: down to the smallest scale.
    viewer.setFrameBudget(0.01);
    rotate(12);
    EXPECT_FLOAT_EQ(viewer.view().refinement().interactiveScale(),
                    ViewerWidget::kMinInteractiveScale);
    // Every frame fits in 100 s: up to full size, which the last moving frame used.
    viewer.setFrameBudget(1e5);
    rotate(12);
    EXPECT_FLOAT_EQ(viewer.view().refinement().interactiveScale(), 1.0F);
    // A set scale is fixed.
    viewer.setInteractiveScale(0.5F);
    EXPECT_EQ(viewer.view().refinement().frameBudget(), 0.0);
    rotate(3);
    EXPECT_FLOAT_EQ(viewer.view().refinement().interactiveScale(), 0.5F);
}

TEST_F(ProgressiveTest, WheelZoomSettlesByTheTimer) {
    ViewerWidget& viewer = open(makeScene(), 640, 480);
    ASSERT_TRUE(waitUntil([&] { return exactShown(viewer); }));
    viewer.setSettleDelay(150);
    const QPointF centre(viewer.width() / 2.0, viewer.height() / 2.0);
    QWheelEvent wheel(centre, viewer.mapToGlobal(centre), QPoint(), QPoint(0, 120), Qt::NoButton,
                      Qt::NoModifier, Qt::NoScrollPhase, false);
    QCoreApplication::sendEvent(&viewer, &wheel);
    EXPECT_TRUE(viewer.view().refinement().moving());
    bool settled = false;
    QObject::connect(&viewer, &ViewerWidget::cameraSettled, [&] { settled = true; });
    ASSERT_TRUE(waitUntil([&] { return settled; }, 10000)) << "the settle timer never fired";
    EXPECT_FALSE(viewer.view().refinement().moving());
    ASSERT_TRUE(waitUntil([&] { return exactShown(viewer); }));
}

TEST_F(ProgressiveTest, RotatingDuringAnExactSolveCancelsIt) {
    // The reference solver (every contour pixel, double precision) makes the
    // exact solve slow enough to be interrupted; the preview stays fast.
    vv::render::VssSettings vss;
    vss.solver.kind = vv::vss::SolverKind::Reference;
    ViewerWidget& viewer = open(makeScene(), 800, 600, &vss);
    ASSERT_TRUE(waitUntil([&] {
        return viewer.framesWithScene() > 0 && viewer.vssStatus().pending &&
               viewer.view().frameRenderer().solveCounters().submitted >= 1;
    }));
    QThread::msleep(30);            // the worker has picked the exact job up
    viewer.setSettleDelay(600000);  // the held drag stays a preview
    const auto before = viewer.view().frameRenderer().solveCounters();
    EXPECT_EQ(before.cancelled, 0U);
    EXPECT_EQ(before.completed, 0U) << "the exact solve finished too fast to be interrupted";

    Drag drag(viewer);
    drag.moveBy({50, 10});
    ASSERT_TRUE(waitUntil([&] {
        return viewer.view().frameRenderer().solveCounters().cancelled >= 1;
    })) << "the stale exact solve was not cancelled";
    ASSERT_TRUE(waitUntil([&] { return previewShown(viewer); }));
    drag.release();
    // The preview, then the exact solve of the new view.
    EXPECT_TRUE(waitUntil([&] {
        return viewer.view().frameRenderer().solveCounters().submitted >= before.submitted + 2;
    }));
    // The exact one was started by the settling itself (from a G-buffer drawn
    // for it), not by a frame.
    EXPECT_EQ(viewer.view().solvesPreparedOnSettle() + viewer.view().solvesRequestedOnSettle(), 1U);
}

TEST_F(ProgressiveTest, ReducedResolutionWhileMovingThenFull) {
    ViewerWidget& viewer = open(makeScene(), 800, 600);
    ASSERT_TRUE(waitUntil([&] { return exactShown(viewer); }));
    EXPECT_FLOAT_EQ(viewer.view().refinement().interactiveScale(), 0.5F);
    viewer.setInteractiveScale(0.5F);  // fixed: no dynamic resolution here
    const qreal ratio = viewer.devicePixelRatioF();
    const QSize full(static_cast<int>(std::lround(viewer.width() * ratio)),
                     static_cast<int>(std::lround(viewer.height() * ratio)));
    EXPECT_EQ(viewer.lastRenderSize(), full);

    viewer.setSettleDelay(600000);
    const quint64 directBefore = viewer.view().solvesRequestedOnSettle();
    Drag drag(viewer);
    drag.moveBy({40, 10});
    const quint64 frames = viewer.framesWithScene();
    ASSERT_TRUE(waitUntil([&] { return viewer.framesWithScene() > frames; }));
    EXPECT_TRUE(viewer.view().refinement().moving());
    const QSize half(static_cast<int>(std::lround(full.width() * 0.5)),
                     static_cast<int>(std::lround(full.height() * 0.5)));
    EXPECT_EQ(viewer.lastRenderSize(), half);
    // The preview VSS is solved at the reduced size too.
    ASSERT_TRUE(waitUntil([&] { return previewShown(viewer); }));
    EXPECT_EQ(viewer.view().frameRenderer().shownHeight().width(), half.width());

    // Settled: the preview depth has the wrong size for the exact solve, so
    // settling draws only the full-size G-buffer and submits the exact solve
    // from it, without a frame; the solve's arrival draws the one frame.
    const quint64 preparedBefore = viewer.view().solvesPreparedOnSettle();
    const auto countersBefore = viewer.view().frameRenderer().solveCounters();
    const quint64 framesBeforeRelease = viewer.framesWithScene();
    drag.release();
    EXPECT_EQ(viewer.view().solvesRequestedOnSettle(), directBefore);
    EXPECT_EQ(viewer.view().solvesPreparedOnSettle(), preparedBefore + 1);
    EXPECT_EQ(viewer.view().frameRenderer().solveCounters().submitted,
              countersBefore.submitted + 1);
    EXPECT_EQ(viewer.framesWithScene(), framesBeforeRelease);  // nothing drawn yet
    ASSERT_TRUE(waitUntil([&] { return exactShown(viewer); }));
    EXPECT_EQ(viewer.lastRenderSize(), full);
    EXPECT_EQ(viewer.view().frameRenderer().shownHeight().width(), full.width());
    // The frame that shows it found the G-buffer of the settled view cached.
    const auto& passes = viewer.lastPasses();
    const auto geometry = std::find_if(passes.begin(), passes.end(),
                                       [](const auto& p) { return p.name == "geometry"; });
    ASSERT_NE(geometry, passes.end());
    EXPECT_EQ(geometry->state, vv::render::PassState::Cached) << geometry->reason;
    // And no second solve was needed.
    EXPECT_EQ(viewer.view().frameRenderer().solveCounters().submitted,
              countersBefore.submitted + 1);
}

TEST_F(ProgressiveTest, SettlingAtFullResolutionRequestsTheExactSolveWithoutAFrame) {
    ViewerWidget& viewer = open(makeScene(), 800, 600);
    ASSERT_TRUE(waitUntil([&] { return exactShown(viewer); }));
    viewer.setInteractiveScale(1.0F);
    viewer.setSettleDelay(600000);
    Drag drag(viewer);
    drag.moveBy({40, 10});
    // The preview of this view arrived: its frame read this view's depth back.
    ASSERT_TRUE(waitUntil([&] { return previewShown(viewer); }));
    viewer.setInteractiveScale(1.0F);  // no-op for the size; lets a pending repaint run
    ASSERT_TRUE(waitUntil([&] { return previewShown(viewer); }));
    const auto before = viewer.view().frameRenderer().solveCounters();
    const quint64 directBefore = viewer.view().solvesRequestedOnSettle();
    const quint64 frames = viewer.framesWithScene();

    // The release is handled synchronously: the exact solve is submitted
    // before any event loop turn, hence before any frame is drawn.
    drag.release();
    EXPECT_FALSE(viewer.view().refinement().moving());
    EXPECT_EQ(viewer.framesWithScene(), frames);
    EXPECT_EQ(viewer.view().solvesRequestedOnSettle(), directBefore + 1);
    EXPECT_EQ(viewer.view().frameRenderer().solveCounters().submitted, before.submitted + 1);

    ASSERT_TRUE(waitUntil([&] { return exactShown(viewer); }));
    EXPECT_GT(viewer.framesWithScene(), frames);
    // No frame had to request it again.
    EXPECT_EQ(viewer.view().frameRenderer().solveCounters().submitted, before.submitted + 1);
    const qreal ratio = viewer.devicePixelRatioF();
    EXPECT_EQ(viewer.view().frameRenderer().shownHeight().width(),
              static_cast<int>(std::lround(viewer.width() * ratio)));
}

TEST_F(ProgressiveTest, PreviewArrivalsDrawNoFrameOfTheirOwnDuringADragButAPauseShowsThem) {
    ViewerWidget& viewer = open(makeScene(), 800, 600);
    ASSERT_TRUE(waitUntil([&] { return exactShown(viewer); }));
    viewer.setSettleDelay(600000);  // held: only the release settles
    viewer.setInteractiveScale(1.0F);
    int frames = 0;
    int solved = 0;
    QObject::connect(&viewer, &ViewerWidget::frameRendered, [&frames] { ++frames; });
    QObject::connect(&viewer, &ViewerWidget::vssSolved, [&solved] { ++solved; });
    Drag drag(viewer);
    constexpr int kMoves = 12;
    for (int i = 0; i < kMoves; ++i) {
        const int before = frames;
        const int solvedBefore = solved;
        drag.moveBy(QPointF(9, 3));
        ASSERT_TRUE(waitUntil([&] { return frames > before; }));
        // This move's preview arrives; the next move follows well within
        // the viewer's delay (before it, each arrival drew a frame here).
        ASSERT_TRUE(waitUntil([&] { return solved > solvedBefore; }));
        QElapsedTimer t;
        t.start();
        waitUntil([&] { return t.elapsed() >= 25; });
    }
    EXPECT_LE(frames, kMoves + kMoves / 3) << "preview arrivals drew frames of their own";
    EXPECT_GE(frames, kMoves);
    // The hand pauses (button still down): the last preview shows, solved
    // for this very view.
    ASSERT_TRUE(viewer.view().refinement().moving());
    EXPECT_TRUE(waitUntil([&] { return previewShown(viewer); }, 10000));
    drag.release();
    EXPECT_TRUE(waitUntil([&] { return exactShown(viewer); }));
}

TEST_F(ProgressiveTest, MovingFramesDrawTheSimplifiedGeometryOnceItIsReady) {
    window_ = std::make_unique<vv::gui::MainWindow>();
    window_->resize(800, 600);
    ViewerWidget& viewer = *window_->viewer();
    // The tubes have ~3,500 triangles: two simplified levels are built.
    viewer.setPreviewTriangles(2000);
    int ready = 0;
    QObject::connect(&viewer, &ViewerWidget::previewGeometryReady, [&ready] { ++ready; });
    window_->setScene(makeScene(), QStringLiteral("simplified"));
    window_->show();
    ASSERT_TRUE(
        waitUntil([&] { return exactShown(viewer) && viewer.view().hasPreviewGeometry(); }));
    EXPECT_EQ(ready, 1);
    EXPECT_FALSE(
        viewer.view().frameRenderer().lastFrameSimplified());  // still frames draw the full meshes
    EXPECT_EQ(viewer.view().frameRenderer().lastGeometryLevel(), 0U);
    const std::vector<std::size_t> levels = viewer.view().previewLevelTriangles();
    ASSERT_EQ(levels.size(), 2U);
    EXPECT_LE(levels[0], 2000U);
    EXPECT_GT(levels[0], 1000U);
    EXPECT_LE(levels[1], 2000U / 3U);
    EXPECT_GT(levels[1], 100U);

    viewer.setSettleDelay(600000);
    // Full-size moving frames (> 6,000 pixels) draw the finer level ...
    viewer.setInteractiveScale(1.0F);
    Drag drag(viewer);
    quint64 frames = viewer.framesWithScene();
    drag.moveBy(QPointF(15, 4));
    ASSERT_TRUE(waitUntil([&] { return viewer.framesWithScene() > frames; }));
    EXPECT_TRUE(viewer.view().refinement().moving());
    EXPECT_TRUE(viewer.view().frameRenderer().lastFrameSimplified());
    EXPECT_EQ(viewer.view().frameRenderer().lastGeometryLevel(), 1U);
    // ... tiny ones (a tenth of the size: fewer than 3 pixels a triangle of
    // the finer level) the coarser one.
    viewer.setInteractiveScale(0.1F);
    frames = viewer.framesWithScene();
    drag.moveBy(QPointF(15, 4));
    ASSERT_TRUE(waitUntil([&] { return viewer.framesWithScene() > frames; }));
    const QSize tiny = viewer.lastRenderSize();
    ASSERT_LT(static_cast<long long>(tiny.width()) * tiny.height(),
              static_cast<long long>(levels[0]) * vv::render::kPixelsPerPreviewTriangle)
        << tiny.width() << "x" << tiny.height();
    EXPECT_EQ(viewer.view().frameRenderer().lastGeometryLevel(), 2U);
    drag.release();
    ASSERT_TRUE(
        waitUntil([&] { return exactShown(viewer) && !viewer.view().refinement().moving(); }));
    EXPECT_FALSE(viewer.view()
                     .frameRenderer()
                     .lastFrameSimplified());  // the exact VSS is solved on the full meshes
    EXPECT_EQ(viewer.view().frameRenderer().lastGeometryLevel(), 0U);

    // A new scene drops the old preview until its own is ready.
    viewer.setPreviewTriangles(0);
    window_->setScene(makeScene(), QStringLiteral("no preview"));
    EXPECT_FALSE(viewer.view().hasPreviewGeometry());
}

TEST_F(ProgressiveTest, AClosedTreeIsDrawnWithBackFaceCullingAndOpenTubesWithout) {
    vv::demo::DemoTreeOptions demo;
    demo.generations = 3;
    demo.maxTriangles = 20000;
    auto tree = std::make_shared<vv::scene::Scene>();
    tree->meshes.push_back(vv::demo::generateDemoMesh(demo));
    ViewerWidget& viewer = open(tree, 400, 300);
    // The closures are checked on a worker thread; frames before that draw
    // both sides.
    ASSERT_TRUE(
        waitUntil([&] { return exactShown(viewer) && viewer.view().surfaceClosuresKnown(); }));
    Drag drag(viewer);
    const auto moveAndCount = [&] {
        const quint64 frames = viewer.framesWithScene();
        drag.moveBy(QPointF(10, 2));
        EXPECT_TRUE(waitUntil([&] { return viewer.framesWithScene() > frames; }));
        return viewer.view().meshRenderer().lastCulledMeshes();
    };
    EXPECT_EQ(moveAndCount(), 1U);  // watertight, seen from outside
    viewer.setBackFaceCulling(false);
    EXPECT_EQ(moveAndCount(), 0U);
    drag.release();
    ASSERT_TRUE(waitUntil([&] { return exactShown(viewer); }));

    ViewerWidget& tubes = open(makeScene(), 400, 300);
    ASSERT_TRUE(
        waitUntil([&] { return exactShown(tubes) && tubes.view().surfaceClosuresKnown(); }));
    Drag tubeDrag(tubes);
    const quint64 frames = tubes.framesWithScene();
    tubeDrag.moveBy(QPointF(10, 2));
    ASSERT_TRUE(waitUntil([&] { return tubes.framesWithScene() > frames; }));
    EXPECT_EQ(tubes.view().meshRenderer().lastCulledMeshes(),
              0U);  // open ends: the inside can be seen
    tubeDrag.release();
}

/// Per-pass GPU milliseconds (CPU where a pass has no GPU time) collected
/// over frames, printed as medians: where a frame's time goes.
/// The CPU time this process has used so far (all its threads: llvmpipe's,
/// the solver's, the GUI's), in milliseconds. Per frame and divided by the
/// cores, it is the frame's time on otherwise idle cores, whatever the load.
double processCpuMilliseconds() {
    timespec now{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
    return 1e3 * static_cast<double>(now.tv_sec) + 1e-6 * static_cast<double>(now.tv_nsec);
}

class PassTable {
  public:
    void add(const ViewerWidget& viewer) {
        for (const auto& t : viewer.view().lastTimings()) {
            ms_[t.pass].push_back(t.gpuMilliseconds.value_or(t.cpuMilliseconds));
        }
        paint_.push_back(viewer.lastPaintMilliseconds());
    }
    void print(const char* label) {
        std::printf("[bench]   %s, median ms per pass over %zu frames:", label, paint_.size());
        for (auto& [pass, values] : ms_) {
            std::printf(" %s %.1f (%zu)", pass.c_str(), median(values), values.size());
        }
        std::printf("; paintGL %.1f\n", median(paint_));
    }

  private:
    static double median(std::vector<double>& v) {
        if (v.empty()) {
            return 0.0;
        }
        std::sort(v.begin(), v.end());
        return v[v.size() / 2];
    }
    std::map<std::string, std::vector<double>> ms_;
    std::vector<double> paint_;
};

/// Benchmark-style: 30 rotations of the demo at 1280x720, each waiting for
/// its frame, then the time from the release until the exact VSS is shown.
/// Prints the numbers (docs/benchmarks/render.md); asserts only that it works.
// A benchmark, not a test of speed: it prints a table and is run by hand (see
// docs/benchmarks/render.md) with --gtest_also_run_disabled_tests.
TEST_F(ProgressiveTest, DISABLED_RotatingTheDemoBenchmark) {
    auto scene = std::make_shared<const vv::scene::Scene>(
        vv::meshio::loadScene({std::filesystem::path(VV_DEMO_VTP)}));
    // VV_BENCH_SIZE=WxH: the viewer at another size (screens up to 4K).
    QSize benchSize(1280, 720);
    if (const QStringList wh = qEnvironmentVariable("VV_BENCH_SIZE").split(QLatin1Char('x'));
        wh.size() == 2 && wh[0].toInt() > 0 && wh[1].toInt() > 0) {
        benchSize = QSize(wh[0].toInt(), wh[1].toInt());
    }
    ViewerWidget& viewer = open(scene, benchSize.width(), benchSize.height());
    // VV_BENCH_PASSES=1: per-pass GPU times too (waiting for the timers
    // serialises the frame a little, so fps are measured without them).
    const bool passTimes = qEnvironmentVariableIntValue("VV_BENCH_PASSES") != 0;
    viewer.setRecordTimings(passTimes);
    // VV_BENCH_OVERLAY=0: no legends, orientation marker or scale bar over
    // the frame (what repainting them costs Qt's composition per frame).
    if (qEnvironmentVariable("VV_BENCH_OVERLAY") == QStringLiteral("0")) {
        viewer.setLegendsVisible(false);
        viewer.setViewAnnotations({.orientationMarker = false, .scaleBar = false});
    }
    // VV_BENCH_CULLING=0: both sides of every triangle drawn (the old way).
    viewer.setBackFaceCulling(qEnvironmentVariable("VV_BENCH_CULLING") != QStringLiteral("0"));
    // The viewer itself at its size, whatever the toolbars take.
    ASSERT_TRUE(waitUntil([&] { return viewer.framesWithScene() > 0; }));
    // (Panels may still change their width after the first frame: resized
    // again until the viewer keeps its size.)
    for (int attempt = 0; attempt < 4 && viewer.size() != benchSize; ++attempt) {
        const QSize extra = window_->size() - viewer.size();
        window_->resize(benchSize + extra);
        static_cast<void>(waitUntil([&] { return viewer.size() == benchSize; }));
        static_cast<void>(waitUntil([&] { return exactShown(viewer); }));
    }
    ASSERT_TRUE(waitUntil([&] { return viewer.size() == benchSize && exactShown(viewer); }))
        << viewer.width() << "x" << viewer.height();
    // The simplified geometry for moving frames is built in the background.
    ASSERT_TRUE(waitUntil([&] { return viewer.view().hasPreviewGeometry(); }));
    std::printf("[bench] preview geometry: at most %zu triangles; levels:",
                viewer.previewTriangles());
    for (const std::size_t triangles : viewer.view().previewLevelTriangles()) {
        std::printf(" %zu", triangles);
    }
    std::printf("\n");

    // Progressive at half and at full interactive resolution, then off.
    // The scales (render, VSS) the frame budget chose.
    std::pair<float, float> dynamicScale{vv::render::RefinementPolicy::kMinInteractiveScale,
                                         vv::render::RefinementPolicy::kMinInteractiveScale};
    struct Config {
        bool progressive;
        float scale;
        double budget;  // > 0: dynamic resolution from `scale` on
    };
    // VV_BENCH_FPS=0 leaves the rotations out (only the SSIM rows below).
    // The fixed 0.42 row: the budget's step below half size.
    // Row 0: the default budget.
    std::vector<Config> configs = {
        Config{true, 0.5F, vv::render::RefinementPolicy::kDefaultFrameBudgetMs},
        Config{true, 0.5F, 0.0}, Config{true, 0.42F, 0.0}, Config{true, 1.0F, 0.0},
        Config{false, 1.0F, 0.0}};
    if (qEnvironmentVariable("VV_BENCH_FPS") == QStringLiteral("0")) {
        configs.clear();
    } else if (qEnvironmentVariable("VV_BENCH_FULL") == QStringLiteral("0")) {
        configs.resize(3);  // VV_BENCH_FULL=0: no full-size rows (a minute under load)
    }
    // VV_BENCH_ROWS=1,2: only these rows of the list above (from 0).
    if (const QString rows = qEnvironmentVariable("VV_BENCH_ROWS"); !rows.isEmpty()) {
        std::vector<Config> chosen;
        for (const QString& row : rows.split(QLatin1Char(','))) {
            const auto index = static_cast<std::size_t>(row.toUInt());
            if (index < configs.size()) {
                chosen.push_back(configs[index]);
            }
        }
        configs = chosen;
    }
    for (const Config config : configs) {
        const bool progressive = config.progressive;
        viewer.setProgressiveRefinement(progressive);
        viewer.setInteractiveScale(config.scale);
        viewer.setFrameBudget(config.budget);
        std::printf("[bench] frame budget %.0f ms (0 = fixed scale)\n", config.budget);
        viewer.setSettleDelay(150);
        ASSERT_TRUE(waitUntil([&] { return exactShown(viewer); }));
        if (config.budget > 0.0 && qEnvironmentVariable("VV_BENCH_WARMUP") != QStringLiteral("0")) {
            // Warm-up drag, not measured: the size dynamic resolution finds
            // stays for the next drags (it starts from `scale` only once).
            // VV_BENCH_WARMUP=0 leaves it out (the ramp is then measured).
            Drag warmUp(viewer);
            for (int i = 0; i < 8; ++i) {
                const quint64 frames = viewer.framesWithScene();
                warmUp.moveBy({-12, -3});
                ASSERT_TRUE(waitUntil([&] { return viewer.framesWithScene() > frames; }));
            }
            warmUp.release();
            ASSERT_TRUE(waitUntil([&] { return exactShown(viewer); }));
            std::printf("[bench]   after a warm-up drag of 8 moves: scale %.2f (VSS %.2f)\n",
                        static_cast<double>(viewer.view().refinement().interactiveScale()),
                        static_cast<double>(viewer.view().refinement().interactiveVssScale()));
        }
        const auto countersBefore = viewer.view().frameRenderer().solveCounters();
        const quint64 directBefore = viewer.view().solvesRequestedOnSettle();
        QSize movingSize;
        glm::ivec2 movingVssSize{0};
        std::size_t movingLevel = 0;
        std::size_t movingCulled = 0;
        std::vector<double> frameMs;
        std::vector<double> paintMs;  // paintGL of the frame each move waited for
        std::vector<double> cpuMs;    // the process's CPU time from each move to its frame
        int withCurrentVss = 0;
        int previews = 0;
        PassTable moving;
        PassTable settling;
        Drag drag(viewer);
        QElapsedTimer total;
        total.start();
        const double cpuAtStart = processCpuMilliseconds();
        std::vector<double> costMs;                    // what the frame budget saw
        std::map<std::pair<int, int>, int> sizesUsed;  // (render, VSS width): moves
        for (int i = 0; i < 30; ++i) {
            const quint64 frames = viewer.framesWithScene();
            QElapsedTimer t;
            t.start();
            const double cpuBefore = processCpuMilliseconds();
            drag.moveBy({12, 3});
            ASSERT_TRUE(waitUntil([&] { return viewer.framesWithScene() > frames; }));
            frameMs.push_back(static_cast<double>(t.nsecsElapsed()) / 1e6);
            cpuMs.push_back(processCpuMilliseconds() - cpuBefore);
            paintMs.push_back(viewer.lastPaintMilliseconds());
            costMs.push_back(viewer.view().refinement().lastFrameCost());
            moving.add(viewer);
            movingSize = viewer.lastRenderSize();
            movingVssSize = viewer.view().frameRenderer().lastVssSize();
            ++sizesUsed[{movingSize.width(), movingVssSize.x}];
            movingLevel = viewer.view().frameRenderer().lastGeometryLevel();
            movingCulled = viewer.view().meshRenderer().lastCulledMeshes();
            const auto& s = viewer.vssStatus();
            withCurrentVss += (s.shown && s.current) ? 1 : 0;
            previews += s.preview ? 1 : 0;
        }
        const double totalMs = static_cast<double>(total.nsecsElapsed()) / 1e6;
        // Over the 30 moves: also what Qt spends composing each frame after paintGL.
        const double cpuPerFrame = (processCpuMilliseconds() - cpuAtStart) / 30.0;
        QElapsedTimer settle;
        settle.start();
        const quint64 framesAtRelease = viewer.framesWithScene();
        const QMetaObject::Connection settleFrames =
            QObject::connect(&viewer, &ViewerWidget::frameRendered, [&] {
                settling.add(viewer);
                if (passTimes) {
                    std::printf("[bench]   frame after release (%s, %.0f ms after it):",
                                exactShown(viewer) ? "exact VSS" : "no exact VSS yet",
                                static_cast<double>(settle.nsecsElapsed()) / 1e6);
                    for (const auto& t : viewer.view().lastTimings()) {
                        std::printf(" %s %.1f", t.pass.c_str(),
                                    t.gpuMilliseconds.value_or(t.cpuMilliseconds));
                    }
                    std::printf("; paintGL %.1f\n", viewer.lastPaintMilliseconds());
                }
            });
        // The process's CPU time over all threads (llvmpipe's, the solver's,
        // the GUI's): divided by the cores, a floor under release -> exact.
        const std::clock_t cpuAtRelease = std::clock();
        drag.release();
        ASSERT_TRUE(waitUntil([&] { return exactShown(viewer); })) << "no exact VSS after rotating";
        QObject::disconnect(settleFrames);
        const double exactMs = static_cast<double>(settle.nsecsElapsed()) / 1e6;
        const double exactCpuMs =
            1000.0 * static_cast<double>(std::clock() - cpuAtRelease) / CLOCKS_PER_SEC;
        const quint64 framesAfterRelease = viewer.framesWithScene() - framesAtRelease;
        const bool direct = viewer.view().solvesRequestedOnSettle() > directBefore;
        const auto countersAfter = viewer.view().frameRenderer().solveCounters();

        std::vector<double> sorted = frameMs;
        std::sort(sorted.begin(), sorted.end());
        const double median = sorted[sorted.size() / 2];
        std::sort(paintMs.begin(), paintMs.end());
        // The rest of a frame is Qt composing the window and the event loop.
        std::printf(
            "[bench]   moving frames: paintGL median %.1f ms (min %.1f, max %.1f), "
            "geometry level %zu (0 = full meshes), meshes culled %zu\n",
            paintMs[paintMs.size() / 2], paintMs.front(), paintMs.back(), movingLevel,
            movingCulled);
        std::sort(cpuMs.begin(), cpuMs.end());
        const int cores = QThread::idealThreadCount();
        if (config.budget > 0.0) {
            std::printf("[bench]   frame budget: moves per render / VSS width:");
            for (const auto& [widths, moves] : sizesUsed) {
                std::printf(" %d/%d: %d", widths.first, widths.second, moves);
            }
            std::printf("\n");
            std::sort(costMs.begin(), costMs.end());
            std::printf(
                "[bench]   frame budget: measured frame cost median %.1f ms (min %.1f, "
                "max %.1f)\n",
                costMs[costMs.size() / 2], costMs.front(), costMs.back());
        }
        std::printf(
            "[bench]   moving frames: CPU time of the process %.1f ms per frame over the 30 "
            "moves (move -> frame median %.1f ms) = %.1f ms per frame on %d free cores "
            "(%.1f fps)\n",
            cpuPerFrame, cpuMs[cpuMs.size() / 2], cpuPerFrame / cores, cores,
            1000.0 * cores / cpuPerFrame);
        std::printf(
            "[bench] progressive=%s interactive scale %.2f (rendered %dx%d, VSS %dx%d while "
            "moving) "
            "%dx%d "
            "demo: 30 rotations in %.0f ms = %.1f fps; frame ms "
            "median %.0f, min %.0f, max %.0f; frames with this view's VSS %d/30 (preview %d); "
            "release -> exact VSS shown %.0f ms after %llu frame(s), solve requested on settle: "
            "%s (solve %.0f ms); solves submitted %llu, completed %llu, cancelled %llu\n",
            progressive ? "on" : "off", static_cast<double>(config.scale), movingSize.width(),
            movingSize.height(), movingVssSize.x, movingVssSize.y, viewer.width(), viewer.height(),
            totalMs, 30000.0 / totalMs, median, sorted.front(), sorted.back(), withCurrentVss,
            previews, exactMs, static_cast<unsigned long long>(framesAfterRelease),
            direct ? "yes" : "no", viewer.vssStatus().solveMilliseconds,
            static_cast<unsigned long long>(countersAfter.submitted - countersBefore.submitted),
            static_cast<unsigned long long>(countersAfter.completed - countersBefore.completed),
            static_cast<unsigned long long>(countersAfter.cancelled - countersBefore.cancelled));
        std::printf(
            "[bench]   release -> exact VSS: %.0f ms of CPU time in this process (%d cores); "
            "meshes culled in its G-buffer %zu\n",
            exactCpuMs, QThread::idealThreadCount(),
            viewer.view().meshRenderer().lastCulledMeshes());
        if (passTimes) {
            moving.print("moving");
            std::printf("[bench]   settle (exact solve requested / G-buffer prepared): %.1f ms\n",
                        viewer.view().lastSettleMilliseconds());
            settling.print("after release");
        }
        std::fflush(stdout);
        if (progressive) {
            EXPECT_GT(previews, 0) << "no rotation frame showed the preview VSS";
        } else {
            EXPECT_EQ(previews, 0);
        }
        if (config.budget > 0.0) {
            dynamicScale = {viewer.view().refinement().interactiveScale(),
                            viewer.view().refinement().interactiveVssScale()};
        }
    }

    // What a moving frame looks like: the same view as a moving frame (with
    // its own preview VSS) and as the settled frame (exact VSS, occlusion,
    // FXAA), compared by SSIM (1 - compareImages' difference: the worst of
    // Y, Cb, Cr). Two views (6 and 12 moves on from here), each at the
    // floor of dynamic resolution, at 0.35, at 0.5 and at the scale the
    // frame budget chose above: every scale drags to the view and back.
    // VV_BENCH_SHOTS=dir saves the frames as PNGs there.
    const QString shots = qEnvironmentVariable("VV_BENCH_SHOTS");
    if (qEnvironmentVariable("VV_BENCH_SSIM") == QStringLiteral("0")) {
        return;  // VV_BENCH_SSIM=0: the fps rows only
    }
    viewer.setProgressiveRefinement(true);
    // (render scale, VSS scale): the floor, the render size at 0.35 and 0.5
    // over a VSS at 0.25, and the VSS at the render size at 0.35, 0.42 and 0.5.
    std::vector<std::pair<float, float>> scales = {{0.25F, 0.25F}, {0.35F, 0.25F}, {0.5F, 0.25F},
                                                   {0.35F, 0.35F}, {0.42F, 0.42F}, {0.5F, 0.5F}};
    if (std::find(scales.begin(), scales.end(), dynamicScale) == scales.end()) {
        scales.push_back(dynamicScale);
    }
    for (int view = 1; view <= 2; ++view) {
        QImage firstSettled;
        for (const auto& [scale, vssScale] : scales) {
            viewer.setInteractiveScale(scale, vssScale);
            const MovingAndSettled frames = movingAndSettled(viewer, 6, {12, 3});
            ASSERT_TRUE(frames.ok) << "no moving and settled frame at scale " << scale;
            const vv::test::ImageComparison c =
                vv::test::compareImages(frames.moving, frames.settled);
            if (firstSettled.isNull()) {
                firstSettled = frames.settled;
            }
            std::printf(
                "[bench] view %d, moving frame at scale %.2f (%dx%d, VSS %dx%d) against the "
                "settled "
                "frame: SSIM %.3f (luma %.3f); settled frame against the first scale's: SSIM "
                "%.4f\n",
                view, static_cast<double>(scale), frames.movingSize.width(),
                frames.movingSize.height(), frames.movingVssSize.x, frames.movingVssSize.y,
                1.0 - c.difference, 1.0 - c.lumaDifference,
                1.0 - vv::test::compareImages(frames.settled, firstSettled).difference);
            if (!shots.isEmpty()) {
                const QString tag =
                    QString::asprintf("%d-%.2f-%.2f", view, static_cast<double>(scale),
                                      static_cast<double>(vssScale));
                frames.moving.save(shots + QStringLiteral("/moving-") + tag +
                                   QStringLiteral(".png"));
                frames.settled.save(shots + QStringLiteral("/settled-") + tag +
                                    QStringLiteral(".png"));
            }
            // Back to where this view's drags start.
            ASSERT_TRUE(movingAndSettled(viewer, 6, {-12, -3}).ok);
        }
        ASSERT_TRUE(movingAndSettled(viewer, 6, {12, 3}).ok);  // on to the next view
    }
    std::fflush(stdout);
}

}  // namespace
