// SPDX-License-Identifier: GPL-3.0-or-later
// Opening DICOM in the GUI: File > Open Folder / a dropped folder reads the
// headers, the series chooser lists patients / studies / series and skipped
// files, and the chosen series is segmented into vessels on a worker. Run
// under `xvfb-run -a` with QT_QPA_PLATFORM=xcb (OpenGL 4.1 needed).
#include <gtest/gtest.h>

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QDropEvent>
#include <QLabel>
#include <QMessageBox>
#include <QMimeData>
#include <QPointer>
#include <QPushButton>
#include <QSpinBox>
#include <QTreeWidget>
#include <QTreeWidgetItemIterator>
#include <QUrl>
#include <filesystem>
#include <fstream>

#include "GuiFixture.h"
#include "gui/MainWindow.h"
#include "gui/SeriesDialog.h"
#include "gui/panels/DataPanel.h"
#include "vv/demo/DemoCtSeries.h"
#include "vv/dicom/SeriesWriter.h"

namespace {

namespace fs = std::filesystem;
using vv::test::waitUntil;

fs::path dicomDir() {
    return vv::test::panelTestDir() / "dicom";
}

/// Two CT series of the demo tree in one folder (a small and a smaller one),
/// plus a text file that is skipped.
class DicomGuiTest : public vv::test::GuiFixture {
  protected:
    static void SetUpTestSuite() {
        GuiFixture::SetUpTestSuite();
        fs::remove_all(dicomDir());
        vv::demo::DemoCtOptions options;
        options.dims = {64, 64, 48};
        options.generations = 3;
        const vv::demo::DemoCt cta = vv::demo::generateDemoCt(options);
        vv::dicom::CtSeriesWriteOptions write;
        write.seriesDescription = "demo CTA";
        write.patientName = "Demo^Patient";
        demoUid_ = vv::dicom::writeCtSeries(dicomDir() / "two" / "a", cta.volume, write);
        options.dims = {32, 32, 24};
        const vv::demo::DemoCt small = vv::demo::generateDemoCt(options);
        write.seriesDescription = "small CTA";
        smallUid_ = vv::dicom::writeCtSeries(dicomDir() / "two" / "b", small.volume, write);
        std::ofstream(dicomDir() / "two" / "notes.txt") << "not DICOM\n";
        fs::create_directories(dicomDir() / "empty" / "sub");
        std::ofstream(dicomDir() / "empty" / "readme.txt") << "no images here\n";
    }
    static void TearDownTestSuite() {
        std::error_code ec;
        fs::remove_all(dicomDir(), ec);
        GuiFixture::TearDownTestSuite();
    }

    static inline std::string demoUid_;
    static inline std::string smallUid_;
};

TEST_F(DicomGuiTest, FolderWithTwoSeriesShowsTheChooserAndLoadsVessels) {
    QPointer<vv::gui::SeriesDialog> dialog;
    QObject::connect(window_.get(), &vv::gui::MainWindow::seriesDialogShown, window_.get(),
                     [&dialog](vv::gui::SeriesDialog* d) { dialog = d; });
    window_->openDicom(QString::fromStdString((dicomDir() / "two").string()));
    ASSERT_TRUE(waitUntil([&] { return !dialog.isNull() || !window_->lastError().isEmpty(); }))
        << "no series dialog";
    ASSERT_FALSE(dialog.isNull()) << window_->lastError().toStdString();

    // The tree: one patient (named for the user), one study, two series, one skipped file.
    int series = 0;
    int greyed = 0;
    bool patientNamed = false;
    for (QTreeWidgetItemIterator it(dialog->tree()); *it != nullptr; ++it) {
        const QString text = (*it)->text(0);
        // As every dialog and the report write a name: "Family, Given".
        patientNamed = patientNamed || text == QStringLiteral("Patient: Demo, Patient");
        if (text.startsWith(QStringLiteral("Series"))) {
            ++series;
            EXPECT_EQ((*it)->text(1), QStringLiteral("CT"));
        }
        if (((*it)->flags() & Qt::ItemIsEnabled) == 0) {
            ++greyed;
            EXPECT_FALSE((*it)->text(2).isEmpty()) << "a skipped file without its reason";
        }
    }
    EXPECT_EQ(series, 2);
    EXPECT_EQ(greyed, 1);  // notes.txt
    EXPECT_TRUE(patientNamed);
    // A loadable series is preselected; CT defaults: 200..700 HU, bone removal on.
    EXPECT_FALSE(dialog->selectedSeriesUid().isEmpty());
    ASSERT_TRUE(dialog->selectSeries(QString::fromStdString(demoUid_)));
    EXPECT_TRUE(dialog->boneRemoval()->isChecked());
    EXPECT_TRUE(dialog->automaticThreshold()->isChecked());
    const vv::segmentation::SceneSourceOptions options = dialog->sceneSourceOptions();
    EXPECT_EQ(options.seriesInstanceUid, demoUid_);
    EXPECT_FALSE(options.segmentation.range.has_value());
    EXPECT_EQ(options.segmentation.keepComponents, 1);
    dialog->grab().save(
        QString::fromStdString((vv::test::panelTestDir() / "series-dialog.png").string()));

    dialog->accept();
    ASSERT_TRUE(waitUntil(
        [&] { return window_->viewer()->scene() != nullptr || !window_->lastError().isEmpty(); },
        60000));
    ASSERT_TRUE(window_->lastError().isEmpty()) << window_->lastError().toStdString();
    const auto scene = window_->viewer()->scene();
    ASSERT_EQ(scene->meshes.size(), 1U);
    EXPECT_EQ(scene->meshes[0].name, "vessels");
    EXPECT_GT(scene->meshes[0].triangleCount(), 1000U);
    ASSERT_TRUE(waitForFrames(2));
    window_->grab().save(
        QString::fromStdString((vv::test::panelTestDir() / "dicom-vessels.png").string()));
    // The patient name is not in the window title or the status bar.
    EXPECT_FALSE(window_->windowTitle().contains(QStringLiteral("Demo")));

    // The Data panel's series browser reopens the chooser on the same folder.
    QPushButton* browse = window_->dataPanel()->seriesButton();
    ASSERT_NE(browse, nullptr);
    EXPECT_TRUE(browse->toolTip().contains(QStringLiteral("two")))
        << browse->toolTip().toStdString();
    dialog.clear();
    browse->click();
    ASSERT_TRUE(waitUntil([&] { return !dialog.isNull() || !window_->lastError().isEmpty(); }));
    ASSERT_FALSE(dialog.isNull()) << window_->lastError().toStdString();
    int listed = 0;
    for (QTreeWidgetItemIterator it(dialog->tree()); *it != nullptr; ++it) {
        listed += (*it)->text(0).startsWith(QStringLiteral("Series")) ? 1 : 0;
    }
    EXPECT_EQ(listed, 2);
    dialog->reject();
    EXPECT_EQ(window_->viewer()->scene(), scene);  // browsing changes nothing
}

/// The chooser shows each modality's own default: for CT the CT angiography
/// range, for MR the rule (from the image histogram, when loaded) and never
/// CT's numbers; a range of one's own starts empty for MR and must be
/// complete before the series loads.
TEST_F(DicomGuiTest, SeriesChooserShowsTheDefaultOfTheSeriesModality) {
    vv::dicom::DicomScanResult scan;
    vv::dicom::DicomPatient& patient = scan.patients.emplace_back();
    patient.name = "Test^Large";
    vv::dicom::DicomStudy& study = patient.studies.emplace_back();
    study.date = "20250307";
    for (const char* modality : {"MR", "CT"}) {
        vv::dicom::DicomSeries& series = study.series.emplace_back();
        series.seriesInstanceUid = std::string("1.2.826.0.1.") + (modality[0] == 'M' ? "1" : "2");
        series.modality = modality;
        series.description = std::string(modality) + " angio";
        series.imageCount = 40;
        series.rows = 64;
        series.columns = 64;
    }
    vv::gui::SeriesDialog dialog(scan);
    dialog.show();
    auto* rule = dialog.findChild<QLabel*>(QStringLiteral("seriesThresholdRule"));
    ASSERT_NE(rule, nullptr);
    QPushButton* ok = dialog.findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok);
    EXPECT_EQ(dialog.tree()->topLevelItem(0)->text(0), QStringLiteral("Patient: Test, Large"));

    ASSERT_TRUE(dialog.selectSeries(QStringLiteral("1.2.826.0.1.1")));  // MR
    EXPECT_TRUE(dialog.automaticThreshold()->isChecked());
    EXPECT_TRUE(rule->isVisible());
    EXPECT_TRUE(rule->text().contains(QStringLiteral("MR"))) << rule->text().toStdString();
    EXPECT_TRUE(rule->text().contains(QStringLiteral("histogram"))) << rule->text().toStdString();
    for (const char* ct : {"200", "700", "HU"}) {
        EXPECT_FALSE(rule->text().contains(QString::fromLatin1(ct))) << rule->text().toStdString();
    }
    EXPECT_FALSE(dialog.lowerThreshold()->isVisible()) << "CT's numbers shown for an MR series";
    EXPECT_FALSE(dialog.upperThreshold()->isVisible());
    EXPECT_FALSE(dialog.boneRemoval()->isChecked());
    EXPECT_TRUE(ok->isEnabled());

    // A range of one's own for MR: empty fields, OK only once both are given.
    dialog.automaticThreshold()->setChecked(false);
    EXPECT_TRUE(dialog.lowerThreshold()->isVisible());
    EXPECT_TRUE(dialog.lowerThreshold()->text().trimmed().isEmpty())
        << dialog.lowerThreshold()->text().toStdString();
    EXPECT_FALSE(ok->isEnabled());
    dialog.lowerThreshold()->setValue(310.0);
    dialog.upperThreshold()->setValue(2400.0);
    EXPECT_TRUE(ok->isEnabled());
    const auto own = dialog.sceneSourceOptions().segmentation.range;
    ASSERT_TRUE(own.has_value());
    EXPECT_FLOAT_EQ(own->lower, 310.0F);
    EXPECT_FLOAT_EQ(own->upper, 2400.0F);

    dialog.automaticThreshold()->setChecked(true);
    ASSERT_TRUE(dialog.selectSeries(QStringLiteral("1.2.826.0.1.2")));  // CT
    EXPECT_TRUE(rule->text().contains(QStringLiteral("200"))) << rule->text().toStdString();
    EXPECT_TRUE(rule->text().contains(QStringLiteral("700"))) << rule->text().toStdString();
    EXPECT_TRUE(dialog.boneRemoval()->isChecked());
    EXPECT_FALSE(dialog.sceneSourceOptions().segmentation.range.has_value());
}

TEST_F(DicomGuiTest, DroppedSeriesFolderLoadsWithChosenOptions) {
    QMimeData mime;
    mime.setUrls(
        {QUrl::fromLocalFile(QString::fromStdString((dicomDir() / "two" / "a").string()))});
    QDragEnterEvent enter(QPoint(10, 10), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(window_.get(), &enter);
    EXPECT_TRUE(enter.isAccepted());
    QPointer<vv::gui::SeriesDialog> dialog;
    QObject::connect(window_.get(), &vv::gui::MainWindow::seriesDialogShown, window_.get(),
                     [&dialog](vv::gui::SeriesDialog* d) { dialog = d; });
    QDropEvent drop(QPointF(10, 10), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(window_.get(), &drop);
    ASSERT_TRUE(waitUntil([&] { return !dialog.isNull() || !window_->lastError().isEmpty(); }));
    ASSERT_FALSE(dialog.isNull()) << window_->lastError().toStdString();
    EXPECT_EQ(dialog->selectedSeriesUid(), QString::fromStdString(demoUid_));
    // Own options: a manual range and two components, no bone removal.
    dialog->automaticThreshold()->setChecked(false);
    dialog->componentsBox()->setValue(2);
    dialog->boneRemoval()->setChecked(false);
    const vv::segmentation::SceneSourceOptions options = dialog->sceneSourceOptions();
    ASSERT_TRUE(options.segmentation.range.has_value());
    EXPECT_FLOAT_EQ(options.segmentation.range->lower, 200.0F);
    EXPECT_FLOAT_EQ(options.segmentation.range->upper, 700.0F);
    EXPECT_EQ(options.segmentation.keepComponents, 2);
    EXPECT_EQ(options.segmentation.removeBone, std::optional<bool>(false));
    dialog->accept();
    ASSERT_TRUE(waitUntil(
        [&] { return window_->viewer()->scene() != nullptr || !window_->lastError().isEmpty(); },
        60000));
    ASSERT_TRUE(window_->lastError().isEmpty()) << window_->lastError().toStdString();
    EXPECT_EQ(window_->viewer()->scene()->meshes.size(), 1U);
}

TEST_F(DicomGuiTest, CancelledDialogLoadsNothing) {
    QPointer<vv::gui::SeriesDialog> dialog;
    QObject::connect(window_.get(), &vv::gui::MainWindow::seriesDialogShown, window_.get(),
                     [&dialog](vv::gui::SeriesDialog* d) { dialog = d; });
    window_->openDicom(QString::fromStdString((dicomDir() / "two").string()));
    ASSERT_TRUE(waitUntil([&] { return !dialog.isNull(); }));
    dialog->reject();
    QCoreApplication::processEvents();
    EXPECT_FALSE(window_->isLoading());
    EXPECT_EQ(window_->viewer()->scene(), nullptr);
}

TEST_F(DicomGuiTest, FolderWithoutImagesShowsAClearMessage) {
    bool dialogShown = false;
    QObject::connect(window_.get(), &vv::gui::MainWindow::seriesDialogShown, window_.get(),
                     [&dialogShown](vv::gui::SeriesDialog*) { dialogShown = true; });
    const QString empty = QString::fromStdString((dicomDir() / "empty").string());
    window_->openDicom(empty);
    ASSERT_TRUE(waitUntil([&] { return !window_->lastError().isEmpty(); }));
    EXPECT_FALSE(dialogShown);
    EXPECT_TRUE(window_->lastError().contains(QStringLiteral("no DICOM images found")))
        << window_->lastError().toStdString();
    EXPECT_TRUE(window_->lastError().contains(empty));
    auto* box = window_->findChild<QMessageBox*>(QStringLiteral("errorMessageBox"));
    ASSERT_NE(box, nullptr);
    box->accept();
    EXPECT_EQ(window_->viewer()->scene(), nullptr);

    // A missing folder: an error naming it, no crash.
    window_->openDicom(QString::fromStdString((dicomDir() / "missing").string()));
    ASSERT_TRUE(
        waitUntil([&] { return window_->lastError().contains(QStringLiteral("missing")); }));
}

}  // namespace
