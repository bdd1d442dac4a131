// SPDX-License-Identifier: GPL-3.0-or-later
// The GUI under a real display: run under `xvfb-run -a` with
// QT_QPA_PLATFORM=xcb. Without OpenGL 4.1 the tests fail (they never skip).
#include <gtest/gtest.h>

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QDropEvent>
#include <QFileInfo>
#include <QKeyEvent>
#include <QMessageBox>
#include <QMimeData>
#include <QMouseEvent>
#include <QPushButton>
#include <QSettings>
#include <QThread>
#include <QUrl>
#include <QWheelEvent>
#include <QWindow>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <numbers>
#include <set>

#include "GuiFixture.h"
#include "ImageStats.h"
#include "gui/MainWindow.h"
#include "gui/ViewerWidget.h"
#include "vv/colormaps/DepthScale.h"
#include "vv/render/RenderGraph.h"

namespace {

namespace fs = std::filesystem;
using vv::gui::MainWindow;
using vv::test::waitUntil;

/// Where screenshots are kept for people to look at.
fs::path testDir() {
    const fs::path dir = fs::path(VV_TEST_TMP) / "gui";
    fs::create_directories(dir);
    return dir;
}

/// This process's own files and settings (ctest may run test cases in
/// parallel); removed when the suite ends.
fs::path workDir() {
    const fs::path dir = testDir() / ("run-" + std::to_string(QCoreApplication::applicationPid()));
    fs::create_directories(dir);
    return dir;
}

/// A tube along x with "wss" rising along it and "pressure" falling (GuiFixture.h).
std::shared_ptr<const vv::scene::Scene> makeScene() {
    return vv::test::makeTubeScene();
}

fs::path writeTetraStl(const std::string& name) {
    const fs::path file = workDir() / name;
    std::ofstream out(file);
    const float v[4][3] = {{0, 0, 0}, {10, 0, 0}, {0, 10, 0}, {0, 0, 10}};
    const int faces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    out << "solid tetra\n";
    for (const auto& f : faces) {
        out << " facet normal 0 0 0\n  outer loop\n";
        for (const int k : f) {
            out << "   vertex " << v[k][0] << " " << v[k][1] << " " << v[k][2] << "\n";
        }
        out << "  endloop\n endfacet\n";
    }
    out << "endsolid tetra\n";
    return file;
}

QRgb backgroundOf(const vv::gui::ViewerWidget& viewer) {
    const glm::vec3 b = viewer.background();
    return qRgb(static_cast<int>(std::lround(b.r * 255.0F)),
                static_cast<int>(std::lround(b.g * 255.0F)),
                static_cast<int>(std::lround(b.b * 255.0F)));
}

long vesselPixels(const QImage& image, QRgb background) {
    long count = 0;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            const QRgb p = image.pixel(x, y);
            const int d = std::max({std::abs(qRed(p) - qRed(background)),
                                    std::abs(qGreen(p) - qGreen(background)),
                                    std::abs(qBlue(p) - qBlue(background))});
            count += d > 3 ? 1 : 0;
        }
    }
    return count;
}

using vv::test::hueBins;

class GuiTest : public ::testing::Test {
  protected:
    static void SetUpTestSuite() {
        if (QCoreApplication::instance() != nullptr) {
            return;
        }
        // Settings (recent files) go to a throw-away folder, not the user's.
        const QString config = QString::fromStdString((workDir() / "config").string());
        QDir(config).removeRecursively();
        qputenv("XDG_CONFIG_HOME", config.toUtf8());
        // Without any display, xcb would abort the process; the offscreen
        // platform lets the tests fail with a message saying GL is missing.
        if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM") &&
            qEnvironmentVariableIsEmpty("DISPLAY") &&
            qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY")) {
            qputenv("QT_QPA_PLATFORM", "offscreen");
        }
        vv::gui::ViewerWidget::installDefaultFormat();
        static int argc = 1;
        static char name[] = "vv_gui_tests";
        static char* argv[] = {name, nullptr};
        new QApplication(argc, argv);  // kept for the whole process
        QCoreApplication::setOrganizationName(QStringLiteral("VesselViewTest"));
        QCoreApplication::setApplicationName(QStringLiteral("VesselViewTest"));
    }

    static void TearDownTestSuite() {
        std::error_code ec;
        fs::remove_all(workDir(), ec);
    }

    void SetUp() override {
        window_ = std::make_unique<MainWindow>();
        window_->resize(900, 600);
        EXPECT_TRUE(window_->vssToggle()->isChecked());  // on by default
        // Most tests count vessel pixels against the background: VSS off.
        window_->vssToggle()->setChecked(false);
        window_->show();
    }

    /// The state of `pass` in the viewer's last frame.
    [[nodiscard]] vv::render::PassState passState(const std::string& pass) const {
        for (const auto& info : window_->viewer()->lastPasses()) {
            if (info.name == pass) {
                return info.state;
            }
        }
        ADD_FAILURE() << "no pass " << pass;
        return vv::render::PassState::Pending;
    }

    void TearDown() override {
        window_.reset();
        QCoreApplication::processEvents();
    }

    /// Waits until at least `frames` frames were drawn with the current scene;
    /// fails the test when they do not come.
    [[nodiscard]] bool waitForFrames(quint64 frames = 1) const {
        const auto* viewer = window_->viewer();
        const bool ok = waitUntil([&] {
            return !viewer->renderError().isEmpty() || viewer->framesWithScene() >= frames;
        });
        EXPECT_TRUE(viewer->renderError().isEmpty())
            << viewer->renderError().toStdString() << " (run under xvfb-run, QT_QPA_PLATFORM=xcb)";
        EXPECT_TRUE(ok) << "no frame was drawn";
        return ok && viewer->renderError().isEmpty();
    }

    std::unique_ptr<MainWindow> window_;
};

TEST_F(GuiTest, ShowsVesselsWithWssColoursAndNeutralWithoutArray) {
    window_->setScene(makeScene(), QStringLiteral("test scene"));
    ASSERT_TRUE(waitForFrames());
    EXPECT_TRUE(window_->windowTitle().contains(QStringLiteral("test scene")));

    // WSS is chosen by default.
    QComboBox* arrays = window_->arrayChooser();
    ASSERT_EQ(arrays->count(), 3);  // None, pressure, wss
    EXPECT_EQ(arrays->itemData(0).toString(), QString());
    EXPECT_EQ(arrays->currentData().toString(), QStringLiteral("wss"));
    EXPECT_EQ(window_->viewer()->style().array, "wss");

    auto* viewer = window_->viewer();
    const QRgb background = backgroundOf(*viewer);
    const QImage mapped = viewer->grabFramebuffer();
    mapped.save(QString::fromStdString((testDir() / "gui-wss.png").string()), "PNG");
    window_->grab().save(QString::fromStdString((testDir() / "gui-window.png").string()), "PNG");
    ASSERT_FALSE(mapped.isNull());
    const long total = static_cast<long>(mapped.width()) * mapped.height();
    const long vessel = vesselPixels(mapped, background);
    EXPECT_GT(vessel, total / 50) << vessel << " of " << total;
    EXPECT_LT(vessel, total / 2) << vessel << " of " << total;
    EXPECT_GE(hueBins(mapped), 4U);  // viridis from purple to yellow

    const quint64 framesBefore = viewer->framesWithScene();
    arrays->setCurrentIndex(0);  // None
    EXPECT_TRUE(viewer->style().array.empty());
    ASSERT_TRUE(waitForFrames(framesBefore + 1));
    const QImage neutral = viewer->grabFramebuffer();
    neutral.save(QString::fromStdString((testDir() / "gui-neutral.png").string()), "PNG");
    EXPECT_LE(hueBins(neutral), 2U);
    EXPECT_NEAR(static_cast<double>(vesselPixels(neutral, background)), static_cast<double>(vessel),
                0.05 * static_cast<double>(vessel));
}

TEST_F(GuiTest, VssControlsShowTheSurfaceSolvedOffTheGuiThread) {
    using vv::render::PassState;
    auto* viewer = window_->viewer();
    window_->setScene(makeScene(), QStringLiteral("vss scene"));
    ASSERT_TRUE(waitForFrames());
    EXPECT_EQ(passState("vss-solve"), PassState::Culled);
    EXPECT_EQ(passState("vss-shading"), PassState::Culled);
    const QRgb background = backgroundOf(*viewer);
    const long total = static_cast<long>(viewer->width()) * viewer->height();
    const long vesselOnly = vesselPixels(viewer->grabFramebuffer(), background);

    // On: the solve runs on the worker; a repaint follows when it arrives.
    window_->vssToggle()->setChecked(true);
    EXPECT_TRUE(viewer->vssSettings().enabled);
    ASSERT_TRUE(waitUntil([&] { return viewer->vssStatus().shown && viewer->vssStatus().current; }))
        << "the VSS never arrived";
    const QImage withVss = viewer->grabFramebuffer();
    withVss.save(QString::fromStdString((testDir() / "gui-vss.png").string()), "PNG");
    EXPECT_GT(vesselPixels(withVss, background), vesselOnly + total / 4);

    // The depth scale re-shades without re-solving.
    quint64 frames = viewer->framesWithScene();
    window_->depthScaleChooser()->setCurrentIndex(window_->depthScaleChooser()->findData(
        static_cast<int>(vv::colormaps::DepthScale::DarkMeansDeep)));
    EXPECT_EQ(viewer->vssSettings().scale, vv::colormaps::DepthScale::DarkMeansDeep);
    ASSERT_TRUE(waitForFrames(frames + 1));
    EXPECT_EQ(passState("vss-solve"), PassState::Cached);
    EXPECT_EQ(passState("vss-shading"), PassState::Executed);

    // p re-solves (asynchronously), then the new VSS is shown.
    frames = viewer->framesWithScene();
    window_->vssPowerBox()->setValue(6.0);
    EXPECT_DOUBLE_EQ(viewer->vssSettings().solver.p, 6.0);
    ASSERT_TRUE(waitForFrames(frames + 1));
    EXPECT_EQ(passState("vss-solve"), PassState::Executed);
    ASSERT_TRUE(waitUntil([&] { return viewer->vssStatus().current; }));
    EXPECT_FALSE(viewer->vssStatus().pending);

    // Off again: no VSS passes, background in the void.
    frames = viewer->framesWithScene();
    window_->vssToggle()->setChecked(false);
    ASSERT_TRUE(waitForFrames(frames + 1));
    EXPECT_EQ(passState("vss-solve"), PassState::Culled);
    EXPECT_NEAR(static_cast<double>(vesselPixels(viewer->grabFramebuffer(), background)),
                static_cast<double>(vesselOnly), 0.02 * static_cast<double>(vesselOnly));
}

TEST_F(GuiTest, LoadsAFileOnAWorkerAndRemembersIt) {
    const fs::path file = writeTetraStl("tetra.stl");
    window_->openFiles({QString::fromStdString(file.string())});
    EXPECT_TRUE(window_->isLoading());
    ASSERT_TRUE(waitUntil([&] { return window_->viewer()->scene() != nullptr; }))
        << window_->lastError().toStdString();
    ASSERT_EQ(window_->viewer()->scene()->meshes.size(), 1U);
    EXPECT_EQ(window_->viewer()->scene()->meshes[0].triangleCount(), 4U);
    ASSERT_TRUE(waitForFrames());
    EXPECT_TRUE(waitUntil([&] { return !window_->isLoading(); }));
    EXPECT_EQ(window_->arrayChooser()->count(), 1);  // only "None": STL has no arrays
    const QImage image = window_->viewer()->grabFramebuffer();
    EXPECT_GT(vesselPixels(image, backgroundOf(*window_->viewer())),
              static_cast<long>(image.width()) * image.height() / 50);

    const QStringList recent = MainWindow::recentFiles();
    ASSERT_FALSE(recent.isEmpty());
    EXPECT_EQ(recent.front(), QFileInfo(QString::fromStdString(file.string())).absoluteFilePath());
}

/// The window reopens exactly where it was closed, however often: not a
/// title bar lower each time (saveGeometry / restoreGeometry).
TEST_F(GuiTest, TheWindowReopensWhereItWasClosed) {
    // Closing saves the view settings too (the VSS switched off in SetUp):
    // gone afterwards, so that the next test starts from the defaults.
    const std::shared_ptr<void> forget(nullptr, [](void*) { QSettings().clear(); });
    window_->setGeometry(QRect(137, 91, 1000, 640));
    ASSERT_TRUE(waitUntil([&] { return window_->windowHandle()->isExposed(); }));
    QCoreApplication::processEvents();
    const QRect first = window_->geometry();
    const QRect firstFrame = window_->frameGeometry();
    for (int reopen = 1; reopen <= 3; ++reopen) {
        window_->close();  // saves its geometry
        window_.reset();
        QCoreApplication::processEvents();
        window_ = std::make_unique<MainWindow>();
        window_->show();
        ASSERT_TRUE(waitUntil([&] { return window_->windowHandle()->isExposed(); }));
        // The window system may place it a moment after it shows.
        waitUntil([&] { return window_->geometry() == first; }, 2000);
        EXPECT_EQ(window_->geometry(), first) << "reopened " << reopen << " times";
        EXPECT_EQ(window_->frameGeometry(), firstFrame) << "reopened " << reopen << " times";
    }
}

TEST_F(GuiTest, RecentFilesKeepAtMostEight) {
    for (int i = 0; i < 10; ++i) {
        const fs::path file = writeTetraStl("tetra-" + std::to_string(i) + ".stl");
        window_->openFiles({QString::fromStdString(file.string())});
        ASSERT_TRUE(waitUntil([&] { return !window_->isLoading(); }));
    }
    const QStringList recent = MainWindow::recentFiles();
    EXPECT_EQ(recent.size(), 8);
    EXPECT_TRUE(recent.front().endsWith(QStringLiteral("tetra-9.stl")))
        << recent.front().toStdString();
}

TEST_F(GuiTest, LoadErrorNamesTheFileAndKeepsTheGuiResponsive) {
    const QString missing = QString::fromStdString((workDir() / "missing-file.stl").string());
    window_->openFiles({missing});
    ASSERT_TRUE(waitUntil([&] { return !window_->lastError().isEmpty(); }));
    EXPECT_TRUE(window_->lastError().contains(QStringLiteral("missing-file.stl")))
        << window_->lastError().toStdString();
    auto* box = window_->findChild<QMessageBox*>(QStringLiteral("errorMessageBox"));
    ASSERT_NE(box, nullptr);
    EXPECT_TRUE(box->text().contains(QStringLiteral("missing-file.stl")));
    box->close();
    EXPECT_EQ(window_->viewer()->scene(), nullptr);
}

TEST_F(GuiTest, DroppedFilesAreOpened) {
    const fs::path file = writeTetraStl("dropped.stl");
    QMimeData mime;
    mime.setUrls({QUrl::fromLocalFile(QString::fromStdString(file.string())),
                  QUrl::fromLocalFile(QStringLiteral("/tmp/notes.txt"))});
    QDragEnterEvent enter(QPoint(10, 10), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(window_.get(), &enter);
    EXPECT_TRUE(enter.isAccepted());
    QDropEvent drop(QPointF(10, 10), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(window_.get(), &drop);
    ASSERT_TRUE(waitUntil([&] { return window_->viewer()->scene() != nullptr; }))
        << window_->lastError().toStdString();
    EXPECT_TRUE(window_->windowTitle().contains(QStringLiteral("dropped.stl")));

    QMimeData unsupported;
    unsupported.setUrls({QUrl::fromLocalFile(QStringLiteral("/tmp/notes.txt"))});
    QDragEnterEvent refused(QPoint(10, 10), Qt::CopyAction, &unsupported, Qt::LeftButton,
                            Qt::NoModifier);
    refused.setAccepted(false);
    QCoreApplication::sendEvent(window_.get(), &refused);
    EXPECT_FALSE(refused.isAccepted());
}

TEST_F(GuiTest, DemoFileFromEnvironmentIsOpenedButNotRemembered) {
    const fs::path file = writeTetraStl("demo.stl");
    const QStringList recentBefore = MainWindow::recentFiles();
    qputenv("VV_DEMO_FILE", QByteArray::fromStdString(file.string()));
    ASSERT_EQ(MainWindow::findDemoFile(), QString::fromStdString(file.string()));
    window_->openDemo();
    qunsetenv("VV_DEMO_FILE");
    ASSERT_TRUE(waitUntil([&] { return window_->viewer()->scene() != nullptr; }))
        << window_->lastError().toStdString();
    EXPECT_EQ(window_->viewer()->scene()->meshes[0].triangleCount(), 4U);
    EXPECT_EQ(MainWindow::recentFiles(), recentBefore);
}

TEST_F(GuiTest, MouseAndKeysMoveTheCamera) {
    window_->setScene(makeScene(), QStringLiteral("camera"));
    ASSERT_TRUE(waitForFrames());
    auto* viewer = window_->viewer();
    const glm::quat home = viewer->camera().rotation();
    const float distance = viewer->camera().distance();
    const glm::vec3 target = viewer->camera().target();
    const QPointF centre(viewer->width() / 2.0, viewer->height() / 2.0);

    // Left-drag rotates.
    const QPointF to = centre + QPointF(80, 30);
    vv::test::leftDrag(viewer, centre, to);
    EXPECT_LT(std::abs(glm::dot(viewer->camera().rotation(), home)), 0.999F);
    EXPECT_FLOAT_EQ(viewer->camera().distance(), distance);

    // Right-drag pans.
    QMouseEvent pressRight(QEvent::MouseButtonPress, centre, viewer->mapToGlobal(centre),
                           Qt::RightButton, Qt::RightButton, Qt::NoModifier);
    QCoreApplication::sendEvent(viewer, &pressRight);
    QMouseEvent moveRight(QEvent::MouseMove, to, viewer->mapToGlobal(to), Qt::NoButton,
                          Qt::RightButton, Qt::NoModifier);
    QCoreApplication::sendEvent(viewer, &moveRight);
    QMouseEvent releaseRight(QEvent::MouseButtonRelease, to, viewer->mapToGlobal(to),
                             Qt::RightButton, Qt::NoButton, Qt::NoModifier);
    QCoreApplication::sendEvent(viewer, &releaseRight);
    EXPECT_GT(glm::length(viewer->camera().target() - target), 0.0F);

    // The wheel zooms in.
    QWheelEvent wheel(centre, viewer->mapToGlobal(centre), QPoint(), QPoint(0, 240), Qt::NoButton,
                      Qt::NoModifier, Qt::NoScrollPhase, false);
    QCoreApplication::sendEvent(viewer, &wheel);
    EXPECT_LT(viewer->camera().distance(), distance);

    // R resets to the home view.
    QKeyEvent key(QEvent::KeyPress, Qt::Key_R, Qt::NoModifier, QStringLiteral("r"));
    QCoreApplication::sendEvent(viewer, &key);
    EXPECT_NEAR(std::abs(glm::dot(viewer->camera().rotation(), home)), 1.0F, 1e-6F);
    EXPECT_NEAR(viewer->camera().distance(), distance, 1e-3F * distance);
    EXPECT_NEAR(glm::length(viewer->camera().target() - target), 0.0F, 1e-4F);
    ASSERT_TRUE(waitForFrames());
}

TEST_F(GuiTest, DemoIsGeneratedOnAWorkerWithWssShown) {
    qunsetenv("VV_DEMO_FILE");
    ASSERT_FALSE(MainWindow::findDemoFile().has_value());  // no bundled file next to the tests
    window_->openDemo();
    EXPECT_TRUE(window_->isLoading());
    ASSERT_TRUE(waitUntil([&] { return window_->viewer()->scene() != nullptr; }, 120000))
        << window_->lastError().toStdString();
    const auto& scene = *window_->viewer()->scene();
    ASSERT_EQ(scene.meshes.size(), 1U);
    EXPECT_GT(scene.meshes[0].triangleCount(), 1000U);
    EXPECT_EQ(window_->arrayChooser()->currentData().toString(), QStringLiteral("wss"));
    ASSERT_TRUE(waitForFrames());
    const QImage image = window_->viewer()->grabFramebuffer();
    image.save(QString::fromStdString((testDir() / "gui-demo.png").string()), "PNG");
    EXPECT_GT(vesselPixels(image, backgroundOf(*window_->viewer())),
              static_cast<long>(image.width()) * image.height() / 100);
    EXPECT_GE(hueBins(image), 3U);
    EXPECT_TRUE(window_->windowTitle().contains(QStringLiteral("demo")));
}

TEST_F(GuiTest, CancelledLoadShowsNothing) {
    qunsetenv("VV_DEMO_FILE");
    window_->openDemo();
    ASSERT_TRUE(window_->isLoading());
    auto* cancel = window_->findChild<QPushButton*>(QStringLiteral("cancelButton"));
    ASSERT_NE(cancel, nullptr);
    EXPECT_TRUE(cancel->isVisible());
    cancel->click();
    ASSERT_TRUE(waitUntil([&] { return !window_->isLoading(); }, 120000));
    // Whether the worker noticed in time or not, a cancelled result is discarded.
    EXPECT_EQ(window_->viewer()->scene(), nullptr);
    EXPECT_TRUE(window_->lastError().isEmpty()) << window_->lastError().toStdString();
    EXPECT_FALSE(cancel->isVisible());
}

TEST_F(GuiTest, ANewLoadReplacesTheOneInProgress) {
    qunsetenv("VV_DEMO_FILE");
    window_->openDemo();  // slow: generated
    const fs::path file = writeTetraStl("replacing.stl");
    window_->openFiles({QString::fromStdString(file.string())});
    ASSERT_TRUE(waitUntil([&] { return !window_->isLoading(); }, 120000));
    ASSERT_NE(window_->viewer()->scene(), nullptr);
    EXPECT_EQ(window_->viewer()->scene()->meshes[0].triangleCount(), 4U);
    // The abandoned demo never replaces it later.
    waitUntil([] { return false; }, 1500);
    EXPECT_EQ(window_->viewer()->scene()->meshes[0].triangleCount(), 4U);
}

TEST(GuiStaticTest, TheFirstWindowAndItsFrameFitSmallScreens) {
    // A 1280 x 800 screen: the client filled the free area, the window
    // manager's title bar pushed the window 20 px down and the status bar
    // below the edge. Small screens open maximized; the normal size keeps
    // room for a frame.
    for (const QSize available : {QSize(1280, 800), QSize(1280, 720), QSize(1280, 690)}) {
        const MainWindow::FirstGeometry first = MainWindow::firstGeometry(available);
        EXPECT_TRUE(first.maximized) << available.width() << "x" << available.height();
        const QSize framed = first.size + MainWindow::kFrameAllowance;
        EXPECT_LE(framed.width(), available.width());
        EXPECT_LE(framed.height(), available.height());
    }
    const MainWindow::FirstGeometry large = MainWindow::firstGeometry(QSize(3840, 2160));
    EXPECT_FALSE(large.maximized);
    EXPECT_EQ(large.size, QSize(1280, 800));
    const MainWindow::FirstGeometry fullHd = MainWindow::firstGeometry(QSize(1920, 1040));
    EXPECT_FALSE(fullHd.maximized);
    EXPECT_EQ(fullHd.size, QSize(1280, 800));
    EXPECT_EQ(MainWindow::firstGeometry(QSize()).size, QSize(1280, 800));
    EXPECT_FALSE(MainWindow::firstGeometry(QSize()).maximized);
}

TEST(GuiStaticTest, FileFilterListsEveryMeshFormat) {
    const QString filter = MainWindow::meshFileFilter();
    for (const char* e : {"*.stl", "*.obj", "*.ply", "*.vtk", "*.vtp", "*.vtu"}) {
        EXPECT_TRUE(filter.contains(QString::fromLatin1(e))) << e;
    }
}

}  // namespace
