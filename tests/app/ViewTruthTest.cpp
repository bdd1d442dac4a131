// SPDX-License-Identifier: GPL-3.0-or-later
// What the window says is about the data on screen (issue 18): every panel
// shows the loaded scene's ranges only, the status bar says what holds of
// the VSS, the window title names the file and the demo.
#include <QAction>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QLabel>
#include <QLocale>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <memory>

#include "GuiFixture.h"
#include "gui/DocumentController.h"
#include "gui/ExportWorker.h"
#include "gui/panels/FunctionalPanel.h"
#include "gui/panels/HistogramWidget.h"
#include "vv/render/FrameSettings.h"
#include "vv/render/OffscreenRenderer.h"
#include "vv/render/ViewAnnotations.h"
#include "vv/report/ViewExport.h"

namespace vv::test {
namespace {

/// A tube along x (0..30) with a "wss" array running from `lo` to `hi`
/// (none when lo > hi).
std::shared_ptr<const scene::Scene> tubeWithWss(float lo, float hi) {
    auto scene = std::make_shared<scene::Scene>();
    scene::Mesh tube = vv::test::tube(
        {.radius = 2.0F, .start = glm::vec3(0.0F), .length = 30.0F, .segments = 16, .rings = 10});
    if (lo <= hi) {
        vv::test::addAxialArray(tube, "wss", "Pa", 0.0F,
                                [lo, hi](float x) { return lo + (hi - lo) * x / 30.0F; });
    }
    scene->meshes.push_back(std::move(tube));
    return scene;
}

class ViewTruthTest : public GuiFixture {
  protected:
    [[nodiscard]] QString shown(const char* name) const {
        const auto* box = window_->findChild<QDoubleSpinBox*>(QString::fromLatin1(name));
        return box == nullptr ? QStringLiteral("<missing>") : box->text();
    }
    [[nodiscard]] QString rangeLabel() const {
        const auto* label = window_->findChild<QLabel*>(QStringLiteral("arrayRangeLabel"));
        return label == nullptr ? QStringLiteral("<missing>") : label->text();
    }
    /// The panels' min / max fields and the status bar show [lo, hi] and nothing else.
    void expectRange(double lo, double hi) const {
        const auto* min = window_->findChild<QDoubleSpinBox*>(QStringLiteral("functionalRangeMin"));
        ASSERT_NE(min, nullptr);
        const QLocale locale;
        const QString low = locale.toString(lo, 'f', min->decimals());
        const QString high = locale.toString(hi, 'f', min->decimals());
        EXPECT_EQ(shown("functionalRangeMin"), low);
        EXPECT_EQ(shown("functionalRangeMax"), high);
        const auto* histogram = window_->functionalPanel()->histogram();
        EXPECT_NEAR(histogram->rangeLow(), lo, 1e-3);
        EXPECT_NEAR(histogram->rangeHigh(), hi, 1e-3);
        EXPECT_NEAR(histogram->minimum(), lo, 1e-3);
        EXPECT_NEAR(histogram->maximum(), hi, 1e-3);
        EXPECT_TRUE(rangeLabel().contains(locale.toString(hi, 'g', 4)))
            << rangeLabel().toStdString();
    }
};

TEST_F(ViewTruthTest, EveryRangeShownIsTheLoadedScenes) {
    window_->vssToggle()->setChecked(false);
    window_->setScene(tubeWithWss(0.0F, 30.0F), QStringLiteral("first"));
    ASSERT_TRUE(waitForFrames(1));
    expectRange(0.0, 30.0);

    // The same array name with another range: the new range everywhere.
    window_->setScene(tubeWithWss(100.0F, 160.0F), QStringLiteral("second"));
    ASSERT_TRUE(waitForFrames(1));
    expectRange(100.0, 160.0);

    // No array at all: no range from an earlier file anywhere.
    window_->setScene(tubeWithWss(1.0F, 0.0F), QStringLiteral("third"));
    ASSERT_TRUE(waitForFrames(1));
    const QLocale locale;
    for (const char* name : {"functionalRangeMin", "functionalRangeMax"}) {
        const QString text = shown(name);
        EXPECT_FALSE(text.contains(locale.toString(100.0, 'f', 0)) ||
                     text.contains(locale.toString(160.0, 'f', 0)))
            << name << ": " << text.toStdString();
        EXPECT_FALSE(text.contains(QLatin1Char('1')) || text.contains(QLatin1Char('6')))
            << name << ": " << text.toStdString();
    }
    EXPECT_TRUE(window_->functionalPanel()->histogram()->counts().empty());
    EXPECT_TRUE(rangeLabel().isEmpty()) << rangeLabel().toStdString();
}

TEST_F(ViewTruthTest, VssStatusSaysWhatHoldsOfTheSolver) {
    window_->setScene(makeTubeScene(), QStringLiteral("tube"));
    ASSERT_TRUE(waitForFrames(1));
    ASSERT_TRUE(waitForVss());
    QCoreApplication::processEvents();
    const render::VssSettings fast = window_->viewer()->vssSettings();
    ASSERT_EQ(fast.solver.kind, vss::SolverKind::Fast);
    const QString text = window_->vssQualityLabel()->text();
    EXPECT_FALSE(text.contains(QStringLiteral("exact"))) << text.toStdString();
    const QString bound = QLocale().toString(fast.solver.tolerance * 255.0, 'g', 3);
    EXPECT_TRUE(text.contains(QStringLiteral("within %1/255").arg(bound))) << text.toStdString();

    // The reference solver is exact, and the status says so.
    render::VssSettings exact = fast;
    exact.solver.kind = vss::SolverKind::Brute;
    window_->viewer()->setVssSettings(exact);
    ASSERT_TRUE(waitUntil(
        [&] {
            return window_->vssQualityLabel()->text().startsWith(QStringLiteral("VSS: exact, "));
        },
        60000))
        << window_->vssQualityLabel()->text().toStdString();
}

TEST_F(ViewTruthTest, WindowTitleNamesTheFileAndTheDemo) {
    window_->setScene(makeTubeScene(), QStringLiteral("aorta.vtp"));
    ASSERT_TRUE(waitForFrames(1));
    EXPECT_EQ(window_->windowTitle(), QStringLiteral("aorta.vtp — VesselView"));
    EXPECT_FALSE(window_->windowTitle().contains(QStringLiteral("demo")));

    qputenv("VV_DEMO_FILE", QByteArrayLiteral(VV_DEMO_VTP));
    window_->openDemo();
    ASSERT_TRUE(waitUntil([&] { return window_->windowTitle().contains(QStringLiteral("demo")); }))
        << window_->windowTitle().toStdString();
    const QString file = QFileInfo(QStringLiteral(VV_DEMO_VTP)).fileName();
    EXPECT_EQ(window_->windowTitle(), QStringLiteral("%1 (demo data) — VesselView").arg(file));

    // Other data, then the bundled demo file opened by its name: still the demo.
    window_->setScene(makeTubeScene(), QStringLiteral("aorta.vtp"));
    ASSERT_EQ(window_->windowTitle(), QStringLiteral("aorta.vtp — VesselView"));
    window_->openFiles({QStringLiteral(VV_DEMO_VTP)});
    ASSERT_TRUE(waitUntil([&] { return window_->windowTitle().contains(file); }))
        << window_->windowTitle().toStdString();
    EXPECT_EQ(window_->windowTitle(), QStringLiteral("%1 (demo data) — VesselView").arg(file));
}

/// The longest horizontal run of near-white pixels in `region` of `image`.
int longestWhiteRun(const QImage& image, const QRect& region) {
    int best = 0;
    const QRect inside = region.intersected(image.rect());
    for (int y = inside.top(); y <= inside.bottom(); ++y) {
        int run = 0;
        for (int x = inside.left(); x <= inside.right(); ++x) {
            const QRgb p = image.pixel(x, y);
            run = (qRed(p) > 200 && qGreen(p) > 200 && qBlue(p) > 200) ? run + 1 : 0;
            best = std::max(best, run);
        }
    }
    return best;
}

TEST_F(ViewTruthTest, ViewAndExportShowTheScaleBarAtTheFocalPlaneLength) {
    window_->vssToggle()->setChecked(false);
    window_->setScene(makeTubeScene(false), QStringLiteral("tube.vtp"));
    ASSERT_TRUE(waitForFrames(1));
    auto* viewer = window_->viewer();
    EXPECT_EQ(viewer->viewAnnotations().frame, render::SceneFrame::Unknown);  // a mesh file
    ASSERT_TRUE(viewer->viewAnnotations().scaleBar && viewer->viewAnnotations().orientationMarker);

    // In the view (frame and overlays as on screen).
    QCoreApplication::processEvents();
    const double ratio = viewer->devicePixelRatioF();
    const QImage shown = viewer->grab().toImage();
    const auto bar = render::scaleBarFor(viewer->camera(), QSizeF(viewer->size()));
    ASSERT_TRUE(bar);
    const QRect topRight(shown.width() / 2, 0, shown.width() / 2, shown.height() / 5);
    EXPECT_NEAR(longestWhiteRun(shown, topRight), bar->pixels * ratio, 2.0 * ratio);

    // In an export of another size: the bar follows that image's projection.
    render::OffscreenRenderer renderer;
    report::ViewExportOptions options;
    options.render = gui::currentViewOptions(*viewer, 900, 500);
    const report::RenderedView exported = report::renderView(renderer, *viewer->scene(), options);
    const render::Camera camera =
        render::OffscreenRenderer::cameraFor(*viewer->scene(), options.render);
    const auto exportedBar = render::scaleBarFor(camera, QSizeF(900.0, 500.0));
    ASSERT_TRUE(exportedBar);
    EXPECT_NEAR(longestWhiteRun(exported.image, QRect(450, 0, 450, 100)), exportedBar->pixels, 2.0);

    // View > Show Scale Bar off: gone from the view and the export.
    auto* toggle = window_->findChild<QAction*>(QStringLiteral("scaleBarToggle"));
    ASSERT_NE(toggle, nullptr);
    toggle->setChecked(false);
    const quint64 frames = viewer->framesWithScene();
    ASSERT_TRUE(waitForFrames(frames + 1));
    QCoreApplication::processEvents();
    EXPECT_LT(longestWhiteRun(viewer->grab().toImage(), topRight), bar->pixels * ratio / 2.0);
    options.render = gui::currentViewOptions(*viewer, 900, 500);
    EXPECT_LT(longestWhiteRun(report::renderView(renderer, *viewer->scene(), options).image,
                              QRect(450, 0, 450, 100)),
              exportedBar->pixels / 2.0);
}

TEST_F(ViewTruthTest, AnExportFramedAsTheViewHasTheViewsDepthRange) {
    // Two tubes, one turned away from the viewer: the deepest visible pixel
    // lies on a silhouette, where another resolution samples another depth.
    auto scene = std::make_shared<scene::Scene>();
    scene->meshes.push_back(vv::test::tube(
        {.radius = 2.0F, .start = glm::vec3(0.0F), .length = 30.0F, .segments = 32, .rings = 30}));
    scene::Mesh away = vv::test::tube(
        {.radius = 1.5F, .start = glm::vec3(0.0F), .length = 25.0F, .segments = 32, .rings = 30});
    const glm::mat4 turn = glm::rotate(glm::mat4(1.0F), glm::radians(60.0F), glm::vec3(0, 1, 0)) *
                           glm::rotate(glm::mat4(1.0F), glm::radians(35.0F), glm::vec3(0, 0, 1));
    for (glm::vec3& v : away.positions) {
        v = glm::vec3(turn * glm::vec4(v, 1.0F)) + glm::vec3(5.0F, 8.0F, 0.0F);
    }
    scene->meshes.push_back(std::move(away));
    window_->setScene(scene, QStringLiteral("tubes"));
    ASSERT_TRUE(waitForVss());
    auto* viewer = window_->viewer();
    const render::VssFrameStatus screen = viewer->vssStatus();
    ASSERT_LT(screen.dmin, screen.dmax);
    const QSize view = gui::viewPixelSize(*viewer);

    // Twice the view's pixels, framed as the view: the screen's range, so the
    // same depth colours and legend.
    render::OffscreenRenderer renderer;
    report::ViewExportOptions options;
    options.render = gui::currentViewOptions(*viewer, 2 * view.width(), 2 * view.height());
    EXPECT_EQ(options.render.display.vss.range.mode, vss::RangeMode::Fixed);
    const report::RenderedView exported = report::renderView(renderer, *scene, options);
    ASSERT_TRUE(exported.vss.shown);
    EXPECT_EQ(exported.vss.dmin, screen.dmin);
    EXPECT_EQ(exported.vss.dmax, screen.dmax);
    ASSERT_TRUE(exported.legends.depth.has_value());
    EXPECT_EQ(exported.legends.depth->dmin, screen.dmin);
    EXPECT_EQ(exported.legends.depth->dmax, screen.dmax);

    // Its own visible range at that size differs (what the pinning is for)...
    options.render.display.vss.range = {};
    const report::RenderedView own = report::renderView(renderer, *scene, options);
    EXPECT_NE(own.vss.dmax, screen.dmax);
    // ... and framed otherwise (another aspect) the export keeps its own.
    EXPECT_EQ(
        gui::currentViewOptions(*viewer, 2 * view.width(), view.height()).display.vss.range.mode,
        vss::RangeMode::Visible);
    // A fixed range chosen by the user stays as chosen.
    render::VssSettings fixed = viewer->vssSettings();
    fixed.range = {vss::RangeMode::Fixed, 1.0, 99.0};
    viewer->setVssSettings(fixed);
    const render::OffscreenOptions chosen =
        gui::currentViewOptions(*viewer, view.width(), view.height());
    EXPECT_EQ(chosen.display.vss.range.mode, vss::RangeMode::Fixed);
    EXPECT_EQ(chosen.display.vss.range.dmin, 1.0);
    EXPECT_EQ(chosen.display.vss.range.dmax, 99.0);
}

}  // namespace
}  // namespace vv::test
