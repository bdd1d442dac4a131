// SPDX-License-Identifier: GPL-3.0-or-later
// A DICOM scene in the GUI opens as a radiologist expects it: the anterior
// view, head up, the patient's left on the screen's right (as on the coronal
// slice beside it), whether the series was scanned head first or feet first;
// View > Reset Camera comes back to it; the camera buttons carry radiology's
// names; the orientation marker names the sides the slices name. Meshes
// without a patient frame keep their former home view and names. Run under
// `xvfb-run -a` with QT_QPA_PLATFORM=xcb.
#include <gtest/gtest.h>

#include <QAction>
#include <QComboBox>
#include <QKeyEvent>
#include <QToolButton>
#include <filesystem>
#include <functional>

#include "AnatomyPhantom.h"
#include "GuiFixture.h"
#include "gui/MainWindow.h"
#include "gui/ReportDialog.h"
#include "gui/panels/DisplayPanel.h"
#include "vv/render/ViewAnnotations.h"
#include "vv/render/ViewPresets.h"

namespace vv::test {
namespace {

class AnatomicalViewGuiTest : public GuiFixture {
  protected:
    /// Opens the phantom written on `grid` as File > Open Folder does and
    /// waits for a frame of it.
    void openPhantom(const PhantomGrid& grid) {
        const fs::path folder = panelTestDir() / "anatomy" / grid.patientPosition;
        writePhantomSeries(folder, grid);
        window_->vssToggle()->setChecked(false);  // the background stays background
        openDicomFolder(folder);
        if (HasFatalFailure()) {
            return;
        }
        ASSERT_TRUE(waitForFrames(1));
    }

    /// What the 3-D view draws (its frame, without the overlays) once
    /// `change` (nothing: what is shown now) has drawn a settled frame.
    [[nodiscard]] DrawnShape drawnAfter(const std::function<void()>& change = {}) const {
        gui::ViewerWidget* viewer = window_->viewer();
        int frames = 0;
        const QMetaObject::Connection counting = QObject::connect(
            viewer, &gui::ViewerWidget::frameRendered, viewer, [&frames] { ++frames; });
        if (change) {
            change();
        }
        EXPECT_TRUE(waitUntil([&] {
            const QSize device = viewer->size() * viewer->devicePixelRatioF();
            return (!change || frames > 0) && !viewer->view().refinement().moving() &&
                   viewer->lastRenderSize() == device;
        })) << "no settled frame";
        QObject::disconnect(counting);
        const glm::ivec3 bg(glm::round(viewer->background() * 255.0F));
        return {viewer->grabFramebuffer(), qRgb(bg.r, bg.g, bg.b)};
    }

    [[nodiscard]] QToolButton* cameraButton(const char* name) const {
        auto* button = window_->findChild<QToolButton*>(QLatin1String(name));
        EXPECT_NE(button, nullptr) << name;
        return button;
    }

    /// The Export Report dialog's label for the second view `name`.
    QString secondViewLabel(const char* name) {
        const gui::ReportDialog dialog(*window_->viewer(), window_->reportSource(), window_.get());
        const QComboBox* chooser = dialog.secondViewChooser();
        const int index = chooser->findData(QString::fromLatin1(name));
        return index < 0 ? QStringLiteral("(none)") : chooser->itemText(index);
    }
};

TEST_F(AnatomicalViewGuiTest, ADicomSceneOpensInTheAnteriorViewHeadFirstOrFeetFirst) {
    for (const PhantomGrid& grid : {headFirstGrid(), feetFirstGrid()}) {
        SCOPED_TRACE(grid.name);
        openPhantom(grid);
        if (HasFatalFailure()) {
            return;
        }
        gui::ViewerWidget* viewer = window_->viewer();
        EXPECT_EQ(viewer->scene()->frame, scene::SceneFrame::PatientLps);
        EXPECT_TRUE(showsAnteriorView(drawnAfter()));
        // The marker names the sides the coronal slice names: R left, L right, S up.
        const render::EdgeLabels edges =
            render::edgeLabels(viewer->camera(), viewer->viewAnnotations().frame);
        EXPECT_EQ(edges.left, QStringLiteral("R"));
        EXPECT_EQ(edges.right, QStringLiteral("L"));
        EXPECT_EQ(edges.top, QStringLiteral("S"));
        EXPECT_EQ(edges.bottom, QStringLiteral("I"));
        // Turned away and reset (R): the anterior view again.
        (void)drawnAfter([&] { leftDrag(viewer, QPointF(100, 100), QPointF(260, 180)); });
        EXPECT_TRUE(showsAnteriorView(drawnAfter([&] {
            QKeyEvent r(QEvent::KeyPress, Qt::Key_R, Qt::NoModifier);
            QCoreApplication::sendEvent(viewer, &r);
        })));
        // The view buttons: superior and inferior with anterior up.
        EXPECT_TRUE(
            showsAxialView(drawnAfter([&] { cameraButton("viewSuperior")->click(); }), true));
        EXPECT_TRUE(
            showsAxialView(drawnAfter([&] { cameraButton("viewInferior")->click(); }), false));
        EXPECT_TRUE(showsAnteriorView(drawnAfter([&] { cameraButton("viewFar")->click(); })))
            << "Far: the home orientation";
    }
}

TEST_F(AnatomicalViewGuiTest, TheButtonsAreNamedByAnatomyForPatientScenesOnly) {
    openPhantom(headFirstGrid());
    if (HasFatalFailure()) {
        return;
    }
    EXPECT_EQ(cameraButton("viewLeft")->text(), gui::panels::DisplayPanel::tr("Left lateral"));
    EXPECT_EQ(cameraButton("viewRight")->text(), gui::panels::DisplayPanel::tr("Right lateral"));
    // The report's second view is offered under the same names.
    EXPECT_EQ(secondViewLabel("left"), gui::panels::DisplayPanel::tr("Left lateral"));
    EXPECT_EQ(secondViewLabel("right"), gui::panels::DisplayPanel::tr("Right lateral"));
    // Each says where it looks from and what is up.
    EXPECT_TRUE(cameraButton("viewAnterior")->toolTip().contains(QStringLiteral("coronal slice")))
        << cameraButton("viewAnterior")->toolTip().toStdString();
    EXPECT_TRUE(cameraButton("viewSuperior")->toolTip().contains(QStringLiteral("anterior up")))
        << cameraButton("viewSuperior")->toolTip().toStdString();
    // A mesh has no anatomy: its former home view (down -z, +y up) and names.
    window_->setScene(makeTubeScene(), QStringLiteral("tube"));
    ASSERT_TRUE(waitForFrames(1));
    EXPECT_EQ(window_->viewer()->scene()->frame, scene::SceneFrame::Unknown);
    EXPECT_NEAR(std::abs(window_->viewer()->camera().rotation().w), 1.0F, 1e-6F);
    EXPECT_EQ(window_->viewer()->viewAnnotations().frame, render::SceneFrame::Unknown);
    EXPECT_EQ(cameraButton("viewLeft")->text(), gui::panels::DisplayPanel::tr("Left"));
    EXPECT_EQ(secondViewLabel("left"), gui::panels::DisplayPanel::tr("Left"));
}

}  // namespace
}  // namespace vv::test
