// SPDX-License-Identifier: GPL-3.0-or-later
// demo_rotation: the viewer rotating the bundled demo tree as a person drags
// it, frame after frame (frames per second, each pass's time, the frame
// budget's choices, release -> exact VSS), and what a moving frame looks like
// against the settled one (SSIM). A GoogleTest program so that it drives the
// view with the progressive-refinement tests' own helpers
// (tests/app/ViewerDrive.h); not a ctest test: it measures, it judges
// nothing but that it works. Options through the environment (VV_BENCH_*,
// below; docs/benchmarks/render.md has the commands and the tables):
//
//   xvfb-run -a -s "-screen 0 1920x1080x24" env QT_QPA_PLATFORM=xcb
//     [VV_BENCH_SIZE=WxH] [VV_BENCH_FULL=0] [VV_BENCH_ROWS=0,1] [VV_BENCH_SSIM=0]
//     [VV_BENCH_PASSES=1 VV_PASS_FINISH=1] build/release/bench/demo_rotation
//   (one command line)
#include <gtest/gtest.h>

#include <QElapsedTimer>
#include <QImage>
#include <QThread>
#include <algorithm>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "ImageCompare.h"
#include "ViewerDrive.h"
#include "vv/meshio/MeshLoader.h"
#include "vv/render/MeshRenderer.h"
#include "vv/render/RefinementPolicy.h"

namespace {

using vv::gui::ViewerWidget;
using vv::test::Drag;
using vv::test::exactShown;
using vv::test::passStateOf;
using vv::test::previewShown;
using vv::test::waitUntil;
using DemoRotation = vv::test::ViewerWindowTest;

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

/// 30 rotations of the demo at 1280x720, each waiting for its frame, then the
/// time from the release until the exact VSS is shown; then the moving and
/// settled frames of two views compared by SSIM. Prints the numbers
/// (docs/benchmarks/render.md); asserts only that it works.
TEST_F(DemoRotation, RotatingTheDemo) {
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
