// SPDX-License-Identifier: GPL-3.0-or-later
// Issue 30, items 4 and 5 in the GUI: an MR series whose signal fades towards
// the head opens segmented along the whole aorta (the intensity correction,
// on for MR, unavailable for CT); turning the correction off shows the
// cut-off warning in the Segmentation panel, and once applied in the report;
// File > Export Surface… writes the applied segmentation (never a preview,
// which disables it) with its provenance, asks before it replaces a file and
// fails cleanly. Run under
// `xvfb-run -a` with QT_QPA_PLATFORM=xcb (OpenGL 4.1 needed).
#include <gtest/gtest.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkXMLPolyDataReader.h>

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPointer>
#include <QPushButton>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include "CtaSeriesFixture.h"
#include "GuiFixture.h"
#include "ReportTestUtil.h"
#include "gui/ExportSurfaceDialog.h"
#include "gui/MainWindow.h"
#include "gui/SeriesDialog.h"
#include "gui/panels/SegmentationPanel.h"
#include "vv/demo/VesselPhantom.h"
#include "vv/dicom/SeriesWriter.h"
#include "vv/segmentation/IntensityCorrection.h"

namespace vv::test {
namespace {

using gui::panels::SegmentationPanel;

fs::path mrDir() {
    return panelTestDir() / "mr-phantom";
}

fs::path ctDir() {
    return panelTestDir() / "mr-test-cta";
}

std::string fieldText(vtkPolyData* poly, const char* name) {
    auto* array = vtkStringArray::SafeDownCast(poly->GetFieldData()->GetAbstractArray(name));
    return array != nullptr && array->GetNumberOfValues() == 1 ? array->GetValue(0)
                                                               : std::string("<missing>");
}

vtkSmartPointer<vtkPolyData> readVtp(const fs::path& file) {
    vtkNew<vtkXMLPolyDataReader> reader;
    reader->SetFileName(file.c_str());
    reader->Update();
    return reader->GetOutput();
}

class MrSegmentationGuiTest : public GuiFixture {
  protected:
    static void SetUpTestSuite() {
        GuiFixture::SetUpTestSuite();
        demo::VesselPhantomOptions options;
        options.minGain = 0.3;
        phantom_ = std::make_unique<demo::VesselPhantom>(demo::generateVesselPhantom(options));
        dicom::CtSeriesWriteOptions write;
        write.modality = "MR";
        write.seriesDescription = "phantom MRA";
        fs::remove_all(mrDir());
        mrUid_ = dicom::writeCtSeries(mrDir(), phantom_->volume, write);
        cta_ = writeTestCtaSeries(ctDir());
    }
    static void TearDownTestSuite() {
        removeTestCtaSeries(ctDir(), cta_);
        std::error_code ec;
        fs::remove_all(mrDir(), ec);
        phantom_.reset();
        GuiFixture::TearDownTestSuite();
    }
    void SetUp() override {
        GuiFixture::SetUp();
        dir_ = panelTestDir() / ::testing::UnitTest::GetInstance()->current_test_info()->name();
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }

    [[nodiscard]] SegmentationPanel* panel() const { return window_->segmentationPanel(); }

    /// Opens the series in `dir` with the chooser's defaults and waits for the vessels.
    void open(const fs::path& dir) {
        QPointer<gui::SeriesDialog> dialog;
        const vv::test::ScopedConnection keep1(
            QObject::connect(window_.get(), &gui::MainWindow::seriesDialogShown, window_.get(),
                             [&dialog](gui::SeriesDialog* d) { dialog = d; }));
        window_->openDicom(QString::fromStdString(dir.string()));
        ASSERT_TRUE(waitUntil([&] { return !dialog.isNull() || !window_->lastError().isEmpty(); }));
        ASSERT_FALSE(dialog.isNull()) << window_->lastError().toStdString();
        dialog->accept();
        ASSERT_TRUE(waitUntil(
            [&] { return window_->volume() != nullptr || !window_->lastError().isEmpty(); },
            60000));
        ASSERT_TRUE(window_->lastError().isEmpty()) << window_->lastError().toStdString();
        ASSERT_TRUE(waitForFrames(1));
    }

    void waitForPreview(int before) const {
        ASSERT_TRUE(waitUntil(
            [&] { return panel()->previewsShown() > before && !panel()->isPreviewing(); }, 60000))
            << panel()->messageLabel()->text().toStdString();
    }

    /// The Export Surface dialog File > Export Surface… opened.
    [[nodiscard]] gui::ExportSurfaceDialog* openExportDialog() const {
        window_->exportSurfaceAction()->trigger();
        gui::ExportSurfaceDialog* dialog = nullptr;
        waitUntil([&] {
            dialog = window_->findChild<gui::ExportSurfaceDialog*>();
            return dialog != nullptr && dialog->isVisible();
        });
        return dialog;
    }

    /// Accepts `dialog` writing `file`; true when the export finished writing it.
    bool exportTo(gui::ExportSurfaceDialog* dialog, const fs::path& file) {
        bool finished = false;
        bool succeeded = false;
        QObject::connect(dialog, &gui::ExportDialog::exportStarted, [&](gui::ExportWorker* w) {
            QObject::connect(w, &gui::ExportWorker::succeeded, [&] { succeeded = true; });
            QObject::connect(w, &gui::ExportWorker::finished, [&] { finished = true; });
        });
        dialog->fileEdit()->setText(QString::fromStdString(file.string()));
        dialog->accept();
        return waitUntil([&] { return finished; }, 120000) && succeeded;
    }

    static inline std::unique_ptr<demo::VesselPhantom> phantom_;
    static inline std::string mrUid_;
    static inline std::unique_ptr<SyntheticCta> cta_;
    fs::path dir_;
};

TEST_F(MrSegmentationGuiTest, FadingMrIsCorrectedAndTheCutOffIsShownWithoutTheCorrection) {
    open(mrDir());
    // MR: the correction is on by default, the aorta's head end segmented.
    EXPECT_TRUE(panel()->correctionBox()->isEnabled());
    EXPECT_TRUE(panel()->correctionBox()->isChecked());
    EXPECT_FALSE(panel()->cutOffLabel()->isVisibleTo(panel()));
    const scene::LabelMap& labels = *window_->document()->labelMap();
    const glm::dvec3 top = phantom_->vessels.front().centerline.front();
    const glm::dvec3 ijk(phantom_->volume.worldToIndex() *
                         glm::dvec4(top.x, top.y, phantom_->volume.worldBounds().max.z - 2.0, 1.0));
    const glm::ivec3 voxel(glm::round(ijk));
    EXPECT_NE(labels.labels[labels.index(voxel.x, voxel.y, voxel.z)], 0);
    ASSERT_TRUE(waitUntil([&] { return panel()->gainField() != nullptr; }, 60000));
    const double correctedLower = panel()->lowerBox()->value();
    // The default that arrived is the range the scene was loaded with (up to
    // the boxes' rounding): no preview replaces the full-resolution scene.
    EXPECT_FALSE(panel()->isPreviewing());
    EXPECT_EQ(panel()->previewsShown(), 0);
    EXPECT_TRUE(panel()->showsFullResolution());

    // Off: the range follows the default of the plain values, and the preview
    // loses the aorta's top: the warning says so.
    const int before = panel()->previewsShown();
    panel()->correctionBox()->setChecked(false);
    waitForPreview(before);
    ASSERT_TRUE(waitUntil([&] { return panel()->defaultButton()->isEnabled(); }));
    EXPECT_NEAR(panel()->lowerBox()->value(),
                segmentation::defaultThresholdRange(*window_->volume()).lower, 0.5);
    EXPECT_NE(panel()->lowerBox()->value(), correctedLower);
    if (panel()->isPreviewing()) {
        waitForPreview(panel()->previewsShown());
    }
    ASSERT_TRUE(panel()->cutOffLabel()->isVisibleTo(panel()));
    const QString warning = panel()->cutOffLabel()->text();
    EXPECT_TRUE(warning.contains(QStringLiteral("towards the head"))) << warning.toStdString();
    EXPECT_TRUE(warning.contains(QStringLiteral("Correct the signal fall-off")))
        << warning.toStdString();
    window_->revealPanel(panel());
    QCoreApplication::processEvents();
    window_->grab().save(QString::fromStdString((dir_ / "cut-off-warning.png").string()));

    // On again: the whole aorta, no warning.
    const int again = panel()->previewsShown();
    panel()->correctionBox()->setChecked(true);
    waitForPreview(again);
    if (panel()->isPreviewing()) {
        waitForPreview(panel()->previewsShown());
    }
    EXPECT_FALSE(panel()->cutOffLabel()->isVisibleTo(panel()))
        << panel()->cutOffLabel()->text().toStdString();
}

TEST_F(MrSegmentationGuiTest, ExportReportOfTheAppliedSegmentationWarnsOfTheCutOff) {
    open(mrDir());
    // As loaded (corrected): the report's Segmentation section has no warning.
    const report::ReportSource loaded = window_->document()->reportSource();
    ASSERT_TRUE(loaded.segmentation);
    EXPECT_TRUE(loaded.segmentation->warnings.empty());
    ASSERT_TRUE(waitUntil([&] { return panel()->gainField() != nullptr; }, 60000));

    // Without the correction, applied: the report says the vessel may be cut off.
    const int before = panel()->previewsShown();
    panel()->correctionBox()->setChecked(false);
    waitForPreview(before);
    if (panel()->isPreviewing()) {
        waitForPreview(panel()->previewsShown());
    }
    EXPECT_TRUE(window_->document()->reportSource().segmentation->warnings.empty());  // a preview
    panel()->apply();
    ASSERT_TRUE(waitUntil([&] { return !panel()->isApplying(); }, 120000));
    ASSERT_TRUE(window_->exportReportAction()->isEnabled());
    // The panel's advice after Apply is still the correction's.
    EXPECT_TRUE(
        panel()->cutOffLabel()->text().contains(QStringLiteral("Correct the signal fall-off")))
        << panel()->cutOffLabel()->text().toStdString();
    const fs::path pdf = dir_ / "report.pdf";
    const QString failure = exportReport(pdf);
    ASSERT_TRUE(failure.isEmpty()) << failure.toStdString();
    std::string text;
    ASSERT_EQ(report::test::runTool("pdftotext '" + pdf.string() + "' -", text), 0) << text;
    std::replace(text.begin(), text.end(), '\n', ' ');
    text = report::test::withoutLigatures(text);
    EXPECT_NE(text.find("The vessel may be cut off"), std::string::npos) << text;
    EXPECT_NE(text.find("Intensity correction"), std::string::npos) << text;
}

TEST_F(MrSegmentationGuiTest, CtHasNoCorrectionAndNoWarning) {
    open(ctDir());
    EXPECT_FALSE(panel()->correctionBox()->isEnabled());
    EXPECT_FALSE(panel()->correctionBox()->isChecked());
    EXPECT_TRUE(panel()->correctionBox()->toolTip().contains(QStringLiteral("HU")))
        << panel()->correctionBox()->toolTip().toStdString();
    EXPECT_FALSE(panel()->cutOffLabel()->isVisibleTo(panel()));
    EXPECT_FALSE(panel()->segmentationOptions().correctIntensity.value_or(true));
}

TEST_F(MrSegmentationGuiTest, ExportSurfaceWritesWhatMadeItAndAsksBeforeReplacing) {
    // Meshes: nothing segmented to export.
    window_->setScene(makeTubeScene(), QStringLiteral("tube"));
    EXPECT_FALSE(window_->exportSurfaceAction()->isEnabled());
    EXPECT_TRUE(window_->exportSurfaceAction()->toolTip().contains(QStringLiteral("DICOM")));

    open(mrDir());
    ASSERT_TRUE(window_->exportSurfaceAction()->isEnabled());
    gui::ExportSurfaceDialog* dialog = openExportDialog();
    ASSERT_NE(dialog, nullptr);
    // The suffix follows the format and the format the suffix.
    dialog->fileEdit()->setText(QString::fromStdString((dir_ / "vessels.stl").string()));
    dialog->formatChooser()->setCurrentIndex(dialog->formatChooser()->findData(".vtp"));
    EXPECT_TRUE(dialog->fileEdit()->text().endsWith(QStringLiteral("vessels.vtp")));
    EXPECT_TRUE(dialog->sourceLabel()->text().contains(QStringLiteral("applied segmentation")));
    const fs::path shown = dir_ / "shown.vtp";
    ASSERT_TRUE(exportTo(dialog, shown));
    auto poly = readVtp(shown);
    EXPECT_EQ(static_cast<std::size_t>(poly->GetNumberOfPolys()),
              window_->viewer()->scene()->triangleCount());
    EXPECT_EQ(fieldText(poly, "series_instance_uid"), mrUid_);
    EXPECT_EQ(fieldText(poly, "modality"), "MR");
    EXPECT_EQ(fieldText(poly, "intensity_correction").rfind("on", 0), 0U);
    ASSERT_NE(poly->GetPointData()->GetArray("label"), nullptr);
    // On the phantom's vessels, in LPS mm.
    double x[3];
    poly->GetPoint(poly->GetNumberOfPoints() / 2, x);
    EXPECT_LT(std::abs(phantom_->signedDistance({x[0], x[1], x[2]})), 3.0);
    const vtkIdType loadedPoints = poly->GetNumberOfPoints();

    // A preview on screen is never exported: Export Surface and Export Report
    // wait for Apply, and say so.
    const int before = panel()->previewsShown();
    panel()->lowerBox()->setValue(panel()->lowerBox()->value() + 40.0);
    waitForPreview(before);
    EXPECT_FALSE(window_->exportSurfaceAction()->isEnabled());
    EXPECT_FALSE(window_->exportReportAction()->isEnabled());
    EXPECT_EQ(window_->exportSurfaceAction()->toolTip(), gui::MainWindow::previewNotApplied());
    EXPECT_TRUE(panel()->messageLabel()->text().contains(QStringLiteral("Apply it")));
    // Applied: the export is the applied segmentation, with its settings.
    panel()->apply();
    ASSERT_TRUE(waitUntil([&] { return !panel()->isApplying(); }, 120000));
    ASSERT_TRUE(window_->exportSurfaceAction()->isEnabled());
    dialog = openExportDialog();
    ASSERT_NE(dialog, nullptr);
    const fs::path full = dir_ / "full.vtp";
    ASSERT_TRUE(exportTo(dialog, full));
    poly = readVtp(full);
    EXPECT_EQ(static_cast<std::size_t>(poly->GetNumberOfPolys()),
              window_->viewer()->scene()->triangleCount());
    EXPECT_NE(poly->GetNumberOfPoints(), loadedPoints);
    EXPECT_EQ(fieldText(poly, "threshold_rule"), "chosen in the Segmentation panel");
    EXPECT_EQ(
        fieldText(poly, "threshold")
            .rfind(QLocale::c().toString(panel()->lowerBox()->value(), 'g', 4).toStdString(), 0),
        0U)
        << fieldText(poly, "threshold");
    // The ray-cast display shows no surface: the applied one is exported.
    panel()->setDisplay(SegmentationPanel::Display::RaycastIsoSurface);
    dialog = openExportDialog();
    ASSERT_NE(dialog, nullptr);
    const fs::path raycast = dir_ / "raycast.vtp";
    ASSERT_TRUE(exportTo(dialog, raycast));
    EXPECT_EQ(readVtp(raycast)->GetNumberOfPoints(), poly->GetNumberOfPoints());
    panel()->setDisplay(SegmentationPanel::Display::SurfaceMesh);

    // An existing file: asked first; Cancel writes nothing and keeps the dialog.
    const fs::path taken = dir_ / "taken.stl";
    { std::ofstream(taken) << "keep me"; }
    dialog = openExportDialog();
    ASSERT_NE(dialog, nullptr);
    dialog->fileEdit()->setText(QString::fromStdString(taken.string()));
    dialog->accept();
    QMessageBox* box = nullptr;
    ASSERT_TRUE(waitUntil([&] {
        box = dialog->findChild<QMessageBox*>(QStringLiteral("replaceFilesBox"));
        return box != nullptr && box->isVisible();
    }));
    box->button(QMessageBox::Cancel)->click();
    EXPECT_TRUE(waitUntil([&] { return !box->isVisible(); }));
    EXPECT_TRUE(dialog->isVisible());
    std::ifstream in(taken);
    EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), "keep me");

    // A folder that is not there: a message box naming the file; nothing written.
    const fs::path missing = dir_ / "missing" / "v.ply";
    dialog->fileEdit()->setText(QString::fromStdString(missing.string()));
    bool finished = false;
    QObject::connect(dialog, &gui::ExportDialog::exportStarted, [&](gui::ExportWorker* w) {
        QObject::connect(w, &gui::ExportWorker::finished, [&] { finished = true; });
    });
    dialog->accept();
    ASSERT_TRUE(waitUntil([&] { return finished; }, 120000));
    QMessageBox* error = nullptr;
    ASSERT_TRUE(waitUntil([&] {
        error = window_->findChild<QMessageBox*>(QStringLiteral("exportErrorBox"));
        return error != nullptr && error->isVisible();
    }));
    EXPECT_TRUE(error->text().contains(QString::fromStdString(missing.string())))
        << error->text().toStdString();
    error->close();
    EXPECT_FALSE(fs::exists(dir_ / "missing"));
}

}  // namespace
}  // namespace vv::test
