// SPDX-License-Identifier: GPL-3.0-or-later
// Progressive VSS refinement in the viewer: a preview solve while the camera
// moves, the exact one after it stops, stale solves cancelled (the demo
// rotation benchmark, bench/demo_rotation.cpp, drives the view the same way).
// Run under `xvfb-run -a` with QT_QPA_PLATFORM=xcb.
#include <gtest/gtest.h>

#include <QApplication>
#include <QImage>
#include <QLabel>
#include <QLocale>
#include <QMouseEvent>
#include <QThread>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <glm/glm.hpp>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "ViewerDrive.h"
#include "gui/MainWindow.h"
#include "gui/ViewerWidget.h"
#include "vv/demo/AneurysmPhantom.h"
#include "vv/demo/DemoTree.h"
#include "vv/render/MeshRenderer.h"
#include "vv/render/RefinementPolicy.h"

namespace progressive_test {

namespace {

using vv::gui::ViewerWidget;
using vv::test::Drag;
using vv::test::exactShown;
using vv::test::passStateOf;
using vv::test::previewShown;
using vv::test::waitUntil;
using ProgressiveTest = vv::test::ViewerWindowTest;

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
    // The worker has picked the exact job up.
    ASSERT_TRUE(waitUntil([&] {
        return viewer.framesWithScene() > 0 && viewer.vssStatus().pending &&
               viewer.view().frameRenderer().solveCounters().started >= 1;
    }));
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
    // Each move follows its preview's arrival well within the arrival delay,
    // however slowly this machine runs the test.
    viewer.setPreviewArrivalDelay(600000);
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
    }
    EXPECT_LE(frames, kMoves + kMoves / 3) << "preview arrivals drew frames of their own";
    EXPECT_GE(frames, kMoves);
    // The hand pauses (button still down): after the arrival delay the last
    // preview shows, solved for this very view.
    viewer.setPreviewArrivalDelay(ViewerWidget::kPreviewArrivalDelayMs);
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
    // Still frames draw the scene's own meshes, not a smooth copy of them.
    viewer.setSmoothCoarseMeshes(false);
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

TEST_F(ProgressiveTest, ACoarseSceneIsDrawnFromItsSmoothCopyWhileTheSwitchIsOn) {
    // An aorta of 2000 triangles: facets of 5-10 mm, tens of pixels here.
    vv::demo::AneurysmPhantomOptions aorta;
    aorta.targetTriangles = 2'000;
    auto scene = std::make_shared<vv::scene::Scene>();
    scene->meshes.push_back(vv::demo::makeAneurysmPhantom(aorta).mesh);
    window_ = std::make_unique<vv::gui::MainWindow>();
    window_->resize(800, 600);
    ViewerWidget& viewer = *window_->viewer();
    ASSERT_TRUE(viewer.smoothCoarseMeshes());  // the default
    window_->setScene(scene, QStringLiteral("coarse aorta"));
    window_->show();
    // Made in the background; still frames draw it once it is there.
    ASSERT_TRUE(waitUntil([&] {
        return exactShown(viewer) &&
               viewer.view().frameRenderer().lastGeometryLevel() == vv::render::kRefinedLevel;
    }));
    ASSERT_TRUE(viewer.smoothCopy().scene);
    EXPECT_EQ(viewer.smoothCopy().scene->triangleCount(), 4 * scene->triangleCount());
    EXPECT_FALSE(viewer.view().frameRenderer().lastFrameSimplified());
    // The status bar says how far it moves the wall, in the UI's numbers.
    QLabel* label = window_->smoothCopyLabel();
    ASSERT_TRUE(waitUntil([&] { return label->isVisible(); }));
    const QString largest = QLocale().toString(viewer.smoothCopy().largestDeviationMm, 'f', 2);
    EXPECT_TRUE(label->text().contains(largest)) << label->text().toStdString();
    EXPECT_GT(viewer.smoothCopy().largestDeviationMm, 0.0);

    // Off: the mesh as it is, and the status bar no longer says it.
    window_->smoothCoarseToggle()->trigger();
    EXPECT_FALSE(viewer.smoothCoarseMeshes());
    ASSERT_TRUE(waitUntil([&] {
        return exactShown(viewer) && viewer.view().frameRenderer().lastGeometryLevel() == 0U;
    }));
    EXPECT_FALSE(label->isVisible());
    // On again: the copy is kept, drawn at once.
    window_->smoothCoarseToggle()->trigger();
    ASSERT_TRUE(waitUntil([&] {
        return exactShown(viewer) &&
               viewer.view().frameRenderer().lastGeometryLevel() == vv::render::kRefinedLevel;
    }));
    EXPECT_TRUE(waitUntil([&] { return label->isVisible(); }));
    // Far away its facets are small on screen: the mesh as it is, and the
    // status bar says nothing of a copy the image does not show.
    vv::render::Camera far = viewer.camera();
    far.setDistance(40.0F * far.distance());
    viewer.setCamera(far);
    ASSERT_TRUE(waitUntil([&] {
        return exactShown(viewer) && viewer.view().frameRenderer().lastGeometryLevel() == 0U;
    }));
    EXPECT_TRUE(waitUntil([&] { return !label->isVisible(); }));
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

}  // namespace

}  // namespace progressive_test
