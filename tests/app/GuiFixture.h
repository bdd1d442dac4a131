// SPDX-License-Identifier: GPL-3.0-or-later
// A MainWindow under a real display (xvfb-run, QT_QPA_PLATFORM=xcb) for the
// panel and colour-blind-safe tests: one QApplication per process, settings
// in a throw-away folder, helpers to wait for frames and to build scenes.
#pragma once

#include <gtest/gtest.h>

#include <QApplication>
#include <QDir>
#include <QImage>
#include <QLineEdit>
#include <QMouseEvent>
#include <QPointer>
#include <QThread>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <memory>
#include <numbers>
#include <string>
#include <utility>

#include "TestMeshes.h"
#include "WaitUntil.h"
#include "gui/ExportWorker.h"
#include "gui/MainWindow.h"
#include "gui/ReportDialog.h"
#include "gui/SeriesDialog.h"
#include "gui/ViewerWidget.h"
#include "vv/scene/Mesh.h"

namespace vv::test {

namespace fs = std::filesystem;

/// This process's folder under the build tree (screenshots, settings).
inline fs::path panelTestDir() {
    const fs::path dir = fs::path(VV_TEST_TMP) / "gui-panels" /
                         ("run-" + std::to_string(QCoreApplication::applicationPid()));
    fs::create_directories(dir);
    return dir;
}

/// A connection that ends with its scope. A slot that captures locals by
/// reference must not outlive them: a later signal (the next scene shown, the
/// next series chooser) would write into the stack of a function that has
/// returned.
class ScopedConnection {
  public:
    explicit ScopedConnection(QMetaObject::Connection connection)
        : connection_(std::move(connection)) {}
    ~ScopedConnection() { QObject::disconnect(connection_); }
    ScopedConnection(const ScopedConnection&) = delete;
    ScopedConnection& operator=(const ScopedConnection&) = delete;
    ScopedConnection(ScopedConnection&&) = delete;
    ScopedConnection& operator=(ScopedConnection&&) = delete;

  private:
    QMetaObject::Connection connection_;
};

/// Processes events until `done` holds or `timeoutMs` passed (a bound for a
/// broken program only: generous, so that load on CI never reaches it);
/// returns `done()`.
inline bool waitUntil(const std::function<bool()>& done, int timeoutMs = 60000) {
    return pollUntil(done, std::chrono::milliseconds(timeoutMs), [] {
        QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
        QThread::msleep(2);
    });
}

/// A left-button drag over `widget` from `from` to `to` (logical widget
/// coordinates) in one move, as a person turning the view does.
inline void leftDrag(QWidget* widget, const QPointF& from, const QPointF& to) {
    QMouseEvent press(QEvent::MouseButtonPress, from, widget->mapToGlobal(from), Qt::LeftButton,
                      Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(widget, &press);
    QMouseEvent move(QEvent::MouseMove, to, widget->mapToGlobal(to), Qt::NoButton, Qt::LeftButton,
                     Qt::NoModifier);
    QCoreApplication::sendEvent(widget, &move);
    QMouseEvent release(QEvent::MouseButtonRelease, to, widget->mapToGlobal(to), Qt::LeftButton,
                        Qt::NoButton, Qt::NoModifier);
    QCoreApplication::sendEvent(widget, &release);
}

/// A tube along x (radius 2, length 30) with "wss" (0..30, rising along it)
/// and "pressure" (100..70, falling) arrays.
inline std::shared_ptr<const scene::Scene> makeTubeScene(bool withArrays = true) {
    auto scene = std::make_shared<scene::Scene>();
    scene::Mesh tube = vv::test::tube(
        {.radius = 2.0F, .start = glm::vec3(0.0F), .length = 30.0F, .segments = 32, .rings = 30});
    if (withArrays) {
        vv::test::addAxialArray(tube, "pressure", "mmHg", 0.0F, [](float x) { return 100.0F - x; });
        vv::test::addAxialArray(tube, "wss", "Pa", 0.0F, [](float x) { return x; });
    }
    scene->meshes.push_back(std::move(tube));
    return scene;
}

/// Fraction of the pixels whose colour differs by more than 8 (of 255) in any
/// channel between two images of the same size (1 when the sizes differ).
inline double changedFraction(const QImage& a, const QImage& b) {
    if (a.size() != b.size() || a.isNull()) {
        return 1.0;
    }
    long changed = 0;
    for (int y = 0; y < a.height(); ++y) {
        for (int x = 0; x < a.width(); ++x) {
            const QRgb p = a.pixel(x, y);
            const QRgb q = b.pixel(x, y);
            const int d = std::max({std::abs(qRed(p) - qRed(q)), std::abs(qGreen(p) - qGreen(q)),
                                    std::abs(qBlue(p) - qBlue(q))});
            changed += d > 8 ? 1 : 0;
        }
    }
    return static_cast<double>(changed) / (static_cast<double>(a.width()) * a.height());
}

class GuiFixture : public ::testing::Test {
  protected:
    /// File > Export Report into `pdf` (`edit` first sees the dialog): empty
    /// when the report was written, else why not.
    QString exportReport(const fs::path& pdf,
                         const std::function<void(gui::ReportDialog&)>& edit = {}) {
        window_->exportReportAction()->trigger();
        auto* dialog = window_->findChild<gui::ReportDialog*>();
        if (dialog == nullptr) {
            return QStringLiteral("no Export Report dialog");
        }
        if (edit) {
            edit(*dialog);
        }
        dialog->pdfEdit()->setText(QString::fromStdString(pdf.string()));
        bool finished = false;
        QString failure;
        QObject::connect(dialog, &gui::ReportDialog::exportStarted, [&](gui::ExportWorker* worker) {
            QObject::connect(worker, &gui::ExportWorker::failed,
                             [&](const QString& message) { failure = message; });
            QObject::connect(worker, &gui::ExportWorker::finished, [&] { finished = true; });
        });
        dialog->accept();
        if (!waitUntil([&] { return finished; }, 120000)) {
            return QStringLiteral("no end of export");
        }
        return failure;
    }

    static void SetUpTestSuite() {
        if (QCoreApplication::instance() != nullptr) {
            return;
        }
        const QString config = QString::fromStdString((panelTestDir() / "config").string());
        QDir(config).removeRecursively();
        qputenv("XDG_CONFIG_HOME", config.toUtf8());
        if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM") &&
            qEnvironmentVariableIsEmpty("DISPLAY") &&
            qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY")) {
            qputenv("QT_QPA_PLATFORM", "offscreen");  // fails with a message instead of aborting
        }
        gui::ViewerWidget::installDefaultFormat();
        static int argc = 1;
        static char name[] = "vv_gui_panel_tests";
        static char* argv[] = {name, nullptr};
        new QApplication(argc, argv);  // kept for the whole process
        QCoreApplication::setOrganizationName(QStringLiteral("VesselViewPanelTest"));
        QCoreApplication::setApplicationName(QStringLiteral("VesselViewPanelTest"));
    }

    static void TearDownTestSuite() {
        std::error_code ec;
        fs::remove_all(panelTestDir() / "config", ec);
    }

    void SetUp() override {
        window_ = std::make_unique<gui::MainWindow>();
        window_->resize(1100, 700);
        window_->show();
    }

    void TearDown() override {
        window_.reset();
        QCoreApplication::processEvents();
    }

    /// Replaces the window with a fresh one (the defaults) and opens the
    /// session `path` in it; true once the session was applied.
    [[nodiscard]] bool openSessionInNewWindow(const QString& path) {
        window_ = std::make_unique<gui::MainWindow>();
        window_->resize(1100, 700);
        window_->show();
        bool applied = false;
        const ScopedConnection keep(QObject::connect(
            window_.get(), &gui::MainWindow::sessionApplied, [&applied] { applied = true; }));
        return window_->openSession(path) && waitUntil([&] { return applied; }, 60000);
    }

    /// Opens the DICOM folder `folder` as File > Open Folder does, accepts
    /// the series chooser as it comes and waits for its volume (a fatal
    /// failure naming the window's error otherwise).
    void openDicomFolder(const fs::path& folder) {
        const auto before = window_->volume();  // shown until the new one replaces it
        QPointer<gui::SeriesDialog> dialog;
        const vv::test::ScopedConnection keep1(
            QObject::connect(window_.get(), &gui::MainWindow::seriesDialogShown, window_.get(),
                             [&dialog](gui::SeriesDialog* d) { dialog = d; }));
        window_->openDicom(QString::fromStdString(folder.string()));
        ASSERT_TRUE(waitUntil([&] { return !dialog.isNull() || !window_->lastError().isEmpty(); }));
        ASSERT_FALSE(dialog.isNull()) << window_->lastError().toStdString();
        dialog->accept();
        ASSERT_TRUE(waitUntil(
            [&] {
                return (window_->volume() != nullptr && window_->volume() != before) ||
                       !window_->lastError().isEmpty();
            },
            60000));
        ASSERT_TRUE(window_->lastError().isEmpty()) << window_->lastError().toStdString();
    }

    /// Waits for `frames` frames with the current scene; false (and a test
    /// failure) when OpenGL is missing or they do not come.
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

    /// Waits until the VSS of the current view is shown (exact, not pending),
    /// at most `timeoutMs`.
    [[nodiscard]] bool waitForVss(int timeoutMs = 30000) const {
        const auto* viewer = window_->viewer();
        const bool ok = waitUntil(
            [&] {
                const auto& s = viewer->vssStatus();
                return !viewer->renderError().isEmpty() ||
                       (s.shown && s.current && !s.pending && !s.preview);
            },
            timeoutMs);
        const auto& s = viewer->vssStatus();
        EXPECT_TRUE(ok) << "the VSS never arrived: shown " << s.shown << " current " << s.current
                        << " pending " << s.pending << " preview " << s.preview;
        return ok && viewer->renderError().isEmpty();
    }

    std::unique_ptr<gui::MainWindow> window_;
};

}  // namespace vv::test
