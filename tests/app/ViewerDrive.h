// SPDX-License-Identifier: GPL-3.0-or-later
// Driving the viewer as a person does, for the progressive-refinement tests
// (ProgressiveTest.cpp) and the demo rotation benchmark
// (bench/demo_rotation.cpp): the application, the event-turning wait, a
// mouse drag, what the VSS on screen is, and a main window fixture
// (waitUntil: GuiFixture.h).
#pragma once

#include <gtest/gtest.h>

#include <QApplication>
#include <QMouseEvent>
#include <QThread>
#include <chrono>
#include <functional>
#include <memory>
#include <utility>

#include "GuiFixture.h"
#include "gui/MainWindow.h"
#include "gui/ViewerWidget.h"

namespace vv::test {

inline void ensureApplication() {
    if (QCoreApplication::instance() != nullptr) {
        return;
    }
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM") && qEnvironmentVariableIsEmpty("DISPLAY") &&
        qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY")) {
        qputenv("QT_QPA_PLATFORM", "offscreen");
    }
    gui::ViewerWidget::installDefaultFormat();
    static int argc = 1;
    static char name[] = "vv_gui_tests";
    static char* argv[] = {name, nullptr};
    new QApplication(argc, argv);  // kept for the whole process
}

/// A left-button drag over the viewer, from its centre, one move at a time
/// (each move sent at once, as a person turning the view sends them).
class Drag {
  public:
    explicit Drag(gui::ViewerWidget& viewer)
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
    gui::ViewerWidget& viewer_;
    QPointF at_;
};

/// The exact VSS of this very view is on screen.
inline bool exactShown(const gui::ViewerWidget& viewer) {
    const auto& s = viewer.vssStatus();
    return s.shown && s.current && !s.preview && !s.pending;
}

/// The preview VSS of this very view is on screen.
inline bool previewShown(const gui::ViewerWidget& viewer) {
    const auto& s = viewer.vssStatus();
    return s.shown && s.current && s.preview;
}

/// The state of the pass `name` in the viewer's last frame (Pending: not in the graph).
inline render::PassState passStateOf(const gui::ViewerWidget& viewer, const char* name) {
    for (const auto& pass : viewer.lastPasses()) {
        if (pass.name == name) {
            return pass.state;
        }
    }
    return render::PassState::Pending;
}

/// A main window with its viewer, for tests and benchmarks that drive the view.
class ViewerWindowTest : public ::testing::Test {
  protected:
    static void SetUpTestSuite() { ensureApplication(); }

    void TearDown() override {
        window_.reset();
        QCoreApplication::processEvents();
    }

    /// A main window at `w` x `h` showing `scene` with the VSS on.
    gui::ViewerWidget& open(std::shared_ptr<const scene::Scene> scene, int w, int h,
                            const render::VssSettings* vss = nullptr) {
        window_ = std::make_unique<gui::MainWindow>();
        window_->resize(w, h);
        gui::ViewerWidget& viewer = *window_->viewer();
        if (vss != nullptr) {
            viewer.setVssSettings(*vss);
        }
        window_->setScene(std::move(scene), QStringLiteral("progressive"));
        window_->show();
        return viewer;
    }

    std::unique_ptr<gui::MainWindow> window_;
};

}  // namespace vv::test
