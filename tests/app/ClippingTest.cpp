// SPDX-License-Identifier: GPL-3.0-or-later
// Nothing clipped, nothing hidden (issue 18): in English and German, at
// 1280 x 800 and 1920 x 1080, with the demo shown and every section of the
// side panel open, every label, button, combo box item, tab, group title,
// column and field of the side panel and of every dialog shows its whole
// text, no '&' shows literally, and nothing needs a horizontal scroll bar.
#include <gtest/gtest.h>

#include <QCheckBox>
#include <QDir>
#include <QDockWidget>
#include <QLayout>
#include <QMessageBox>
#include <QPointer>
#include <QStatusBar>
#include <QTabBar>
#include <QWindow>
#include <filesystem>
#include <string>
#include <vector>

#include "ClippingCheck.h"
#include "GuiFixture.h"
#include "StudyFolder.h"
#include "UiLanguage.h"
#include "gui/EngineTexts.h"
#include "gui/ExportImageDialog.h"
#include "gui/ExportSurfaceDialog.h"
#include "gui/ReportDialog.h"
#include "gui/SeriesDialog.h"
#include "gui/analysis/PlanningState.h"
#include "gui/pacs/LocalStudiesBrowser.h"
#include "gui/pacs/NetworkPreferencesDialog.h"
#include "gui/pacs/PacsBrowser.h"
#include "gui/pacs/SendDialog.h"
#include "gui/panels/AnalysisPanel.h"
#include "gui/panels/CollapsibleSection.h"
#include "gui/panels/SegmentationPanel.h"
#include "gui/panels/SidePanel.h"
#include "gui/study/StudyAnalysisDialog.h"
#include "gui/study/StudyRunDialog.h"
#include "vv/demo/DemoCtSeries.h"
#include "vv/dicom/Dicom.h"
#include "vv/dicom/SeriesWriter.h"

namespace {

using vv::test::listed;

namespace fs = std::filesystem;
using vv::test::ClippingCheck;
using vv::test::waitUntil;

struct Case {
    const char* language;
    int width;
    int height;
};

std::string caseName(const ::testing::TestParamInfo<Case>& info) {
    return std::string(info.param.language) + "_" + std::to_string(info.param.width) + "x" +
           std::to_string(info.param.height);
}

class ClippingTest : public vv::test::GuiFixture, public ::testing::WithParamInterface<Case> {
  protected:
    void SetUp() override {
        // As the application does (gui/Translations.cpp), before any widget exists.
        ASSERT_TRUE(vv::test::installUiLanguage(GetParam().language, VV_QM_DIR));
        GuiFixture::SetUp();
        window_->resize(GetParam().width, GetParam().height);
        // No simplified copies for moving frames (0: always the full
        // meshes): nothing here moves the view, and building them would
        // take as long again as loading the demo.
        window_->viewer()->setPreviewTriangles(0);
        bool shown = false;
        const vv::test::ScopedConnection keep1(QObject::connect(
            window_.get(), &vv::gui::MainWindow::sceneShown, [&shown] { shown = true; }));
        window_->openFiles({QStringLiteral(VV_DEMO_VTP)});
        ASSERT_TRUE(waitUntil([&] { return shown || !window_->lastError().isEmpty(); }))
            << "the demo did not load";
        ASSERT_TRUE(window_->lastError().isEmpty()) << window_->lastError().toStdString();
    }

    void TearDown() override {
        GuiFixture::TearDown();
        vv::test::removeUiLanguage();
    }

    /// Lets the layouts settle after showing or resizing.
    static void settle() {
        for (int i = 0; i < 10; ++i) {
            QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
        }
    }

    /// Shows `widget` as the user would see it (saved as `name`-<case>.png),
    /// expects that it cuts nothing off, and hides it again.
    void expectWhole(QWidget& widget, const std::string& name) {
        widget.show();
        // Laid out and on screen, also on a busy machine.
        EXPECT_TRUE(waitUntil(
            [&] { return widget.windowHandle() != nullptr && widget.windowHandle()->isExposed(); },
            10000))
            << name << " never appeared";
        if (widget.layout() != nullptr) {
            widget.layout()->activate();
        }
        settle();
        widget.grab().save(QString::fromStdString(
            (vv::test::panelTestDir() / (name + "-" + caseName({GetParam(), 0}) + ".png"))
                .string()));
        const std::vector<std::string> problems = ClippingCheck::problems(&widget);
        EXPECT_TRUE(problems.empty()) << "cut off in " << name << ":" << listed(problems);
        widget.hide();
    }

    static fs::path demoSeriesDir() { return vv::test::panelTestDir() / "clipping-dicom"; }

    /// A small CT series of the demo tree, for the series chooser.
    static vv::dicom::DicomScanResult demoSeries() {
        const fs::path dir = demoSeriesDir();
        if (!fs::exists(dir)) {
            vv::demo::DemoCtOptions options;
            options.dims = {32, 32, 24};
            options.generations = 3;
            vv::dicom::CtSeriesWriteOptions write;
            write.seriesDescription = "demo CTA";
            write.patientName = "Demo^Patient";
            (void)vv::dicom::writeCtSeries(dir, vv::demo::generateDemoCt(options).volume, write);
        }
        return vv::dicom::scanDicom(dir);
    }
};

TEST_P(ClippingTest, SidePanelShowsEveryTextInFull) {
    auto* side = window_->findChild<vv::gui::panels::SidePanel*>(QStringLiteral("sidePanel"));
    ASSERT_NE(side, nullptr);
    for (auto* section : side->findChildren<vv::gui::panels::CollapsibleSection*>()) {
        section->setExpanded(true);
    }
    ASSERT_TRUE(waitForFrames());
    settle();
    window_->grab().save(QString::fromStdString(
        (vv::test::panelTestDir() / ("window-" + caseName({GetParam(), 0}) + ".png")).string()));
    side->widget()->grab().save(QString::fromStdString(
        (vv::test::panelTestDir() / ("side-panel-" + caseName({GetParam(), 0}) + ".png"))
            .string()));
    std::vector<std::string> problems = ClippingCheck::problems(side);
    EXPECT_TRUE(problems.empty()) << "cut off in the side panel:" << listed(problems);
    // Tabs of docks stacked on each other ("Da…", "Da…") would hide panels.
    for (const QTabBar* tabs : window_->findChildren<QTabBar*>(Qt::FindDirectChildrenOnly)) {
        problems = ClippingCheck::problems(tabs);
        EXPECT_TRUE(tabs->isHidden() || tabs->count() < 2)
            << "panels hidden behind tabs:" << listed(problems);
    }
    EXPECT_LE(side->widget()->minimumSizeHint().width(), side->viewport()->width())
        << "the side panel's content is wider than the panel";
}

TEST_P(ClippingTest, SidePanelWithAVolumeShowsEveryTextInFull) {
    // A CT series: the Segmentation panel shows thresholds in HU, counts, a seed.
    demoSeries();
    QPointer<vv::gui::SeriesDialog> dialog;
    const vv::test::ScopedConnection keep1(
        QObject::connect(window_.get(), &vv::gui::MainWindow::seriesDialogShown, window_.get(),
                         [&dialog](vv::gui::SeriesDialog* shown) { dialog = shown; }));
    bool shown = false;
    const vv::test::ScopedConnection keep2(QObject::connect(
        window_.get(), &vv::gui::MainWindow::sceneShown, [&shown] { shown = true; }));
    window_->openDicom(QString::fromStdString(demoSeriesDir().string()));
    ASSERT_TRUE(waitUntil([&] { return !dialog.isNull() || !window_->lastError().isEmpty(); }));
    ASSERT_FALSE(dialog.isNull()) << window_->lastError().toStdString();
    dialog->accept();
    ASSERT_TRUE(waitUntil([&] { return shown || !window_->lastError().isEmpty(); }, 120000));
    ASSERT_TRUE(window_->lastError().isEmpty()) << window_->lastError().toStdString();
    ASSERT_NE(window_->volume(), nullptr);
    auto* side = window_->sidePanel();
    for (auto* section : side->findChildren<vv::gui::panels::CollapsibleSection*>()) {
        section->setExpanded(true);
    }
    // The cut-off warning (issue 30) with its longest text: two ends.
    vv::segmentation::CutOffVessel cut;
    cut.end = {-123.0, 45.0, 118.0};
    cut.farEnd = {-123.0, 45.0, 160.0};
    cut.lengthMm = 42.0;
    cut.radiusMm = 9.0;
    window_->segmentationPanel()->showCutOff({cut, cut}, false);
    settle();
    side->widget()->grab().save(QString::fromStdString(
        (vv::test::panelTestDir() / ("side-panel-volume-" + caseName({GetParam(), 0}) + ".png"))
            .string()));
    const std::vector<std::string> problems = ClippingCheck::problems(side);
    EXPECT_TRUE(problems.empty()) << "cut off in the side panel:" << listed(problems);
}

TEST_P(ClippingTest, TheAnalysisPanelAndTheViewsAlongThePathShowEveryTextInFull) {
    // The demo tree analysed, the longest preset and a free landmark placed,
    // a stenosis reference set: every row and button of the Analysis panel
    // is on screen, and the dock under the views.
    auto* side = window_->sidePanel();
    for (auto* section : side->findChildren<vv::gui::panels::CollapsibleSection*>()) {
        section->setExpanded(section->objectName() == QStringLiteral("analysisPanelSection"));
    }
    vv::gui::panels::AnalysisPanel* panel = window_->analysisPanel();
    panel->findCenterlines();
    ASSERT_TRUE(waitUntil([&] { return !panel->analysing(); }, 240000));
    vv::gui::PlanningState* state = window_->planning();
    ASSERT_TRUE(state->hasAnalysis()) << panel->statusLabel()->text().toStdString();
    state->setCursorMm(state->path().lengthMm() / 2.0);
    ASSERT_GE(state->placeLandmarkAtCursor(vv::planning::LandmarkKind::RightInternalIliacOrigin),
              0);
    state->setCursorMm(state->path().lengthMm() / 4.0);
    ASSERT_GE(state->placeLandmarkAtCursor(vv::planning::LandmarkKind::Free,
                                           QStringLiteral("Proximal landing zone")),
              0);
    (void)state->setReferenceAtCursor(true);
    settle();
    side->widget()->grab().save(QString::fromStdString(
        (vv::test::panelTestDir() / ("side-panel-analysis-" + caseName({GetParam(), 0}) + ".png"))
            .string()));
    std::vector<std::string> problems = ClippingCheck::problems(side);
    EXPECT_TRUE(problems.empty()) << "cut off in the Analysis panel:" << listed(problems);
    EXPECT_LE(side->widget()->minimumSizeHint().width(), side->viewport()->width())
        << "the Analysis panel is wider than the side panel";
    QWidget* along = window_->diameterProfileDock();
    ASSERT_TRUE(along->isVisible());
    window_->grab().save(QString::fromStdString(
        (vv::test::panelTestDir() / ("window-analysis-" + caseName({GetParam(), 0}) + ".png"))
            .string()));
    problems = ClippingCheck::problems(along);
    EXPECT_TRUE(problems.empty()) << "cut off along the path:" << listed(problems);
    ASSERT_TRUE(window_->measurementsDock()->isVisible());
    problems = ClippingCheck::problems(window_->measurementsDock());
    EXPECT_TRUE(problems.empty()) << "cut off in the measurements:" << listed(problems);

    // Export Report offers the measurements and their SR.
    const auto planned = window_->plannedReport();
    ASSERT_TRUE(planned.has_value());
    vv::gui::ReportDialog report(*window_->viewer(), window_->reportSource(), window_.get());
    report.setMeasurements(planned->section, planned->groups);
    ASSERT_NE(report.measurementsBox(), nullptr);
    report.dicomSrBox()->setChecked(true);
    expectWhole(report, "report-dialog-measurements");
}

TEST_P(ClippingTest, DialogsShowEveryTextInFull) {
    vv::gui::ExportImageDialog image(*window_->viewer(), window_.get());
    expectWhole(image, "export-image");
    vv::gui::ReportDialog report(*window_->viewer(), window_->reportSource(), window_.get());
    expectWhole(report, "report");
    vv::gui::SeriesDialog series(demoSeries(), window_.get());
    expectWhole(series, "series");
    // File > Export Surface… (issue 30), with the longer of its source texts.
    vv::gui::SurfaceExportSource surface;
    surface.labels = std::make_shared<vv::scene::LabelMap>();
    vv::gui::ExportSurfaceDialog exportSurface(surface, window_.get());
    expectWhole(exportSurface, "export-surface");
    // DICOM > Local Studies… and Send to PACS… (issue 21).
    vv::gui::LocalStudiesBrowser local(*window_->listenerService(), window_.get());
    ASSERT_TRUE(waitUntil([&] { return !local.isReading(); }, 15000));
    expectWhole(local, "local-studies");
    vv::gui::PacsSettings pacs;
    pacs.nodes.push_back({"Radiology PACS", {"ORTHANC", "pacs.example.org", 4242, {}}, true});
    vv::gui::SendDialog send(*window_->viewer(), window_->reportSource(), pacs, window_.get());
    expectWhole(send, "send");
    // As Help > About and Help > Keyboard Shortcuts show them.
    QMessageBox about(QMessageBox::NoIcon, QStringLiteral("About"), window_->aboutText(),
                      QMessageBox::Close, window_.get());
    about.setTextFormat(Qt::RichText);
    expectWhole(about, "about");
    QMessageBox keys(QMessageBox::NoIcon, QStringLiteral("Keys"), window_->shortcutSummary(),
                     QMessageBox::Close, window_.get());
    keys.setTextFormat(Qt::RichText);
    expectWhole(keys, "shortcuts");
}

/// The status bar with a measurement (its longest text: "… Punkt 1 um 44,7 mm
/// tiefer" was cut to "tiefe") beside the DICOM listener, the VSS quality and
/// the array's range; a long general message gives way instead.
TEST_P(ClippingTest, StatusBarShowsTheMeasurementInFull) {
    ASSERT_TRUE(waitForFrames());
    auto* viewer = window_->viewer();
    std::vector<vv::gui::ProbeResult> points;
    for (int y = 1; y < 40 && points.size() < 2; ++y) {
        for (int x = 1; x < 40 && points.size() < 2; ++x) {
            const auto hit =
                viewer->probeAt(QPointF(x * viewer->width() / 40.0, y * viewer->height() / 40.0));
            if (hit && (points.empty() ||
                        glm::distance(hit->worldPosition, points.front().worldPosition) > 50.0F)) {
                points.push_back(*hit);
            }
        }
    }
    ASSERT_EQ(points.size(), 2U) << "no two vessel points in view";
    for (const auto& point : points) {
        emit viewer->pointPicked(point);
    }
    auto* measure = window_->statusBar()->findChild<QLabel*>(QStringLiteral("measureLabel"));
    ASSERT_NE(measure, nullptr);
    EXPECT_FALSE(measure->text().isEmpty());
    window_->statusBar()
        ->findChild<QLabel*>(QStringLiteral("statusMessage"))
        ->setText(QStringLiteral("Preview (one voxel in 2 per axis): 37,688 triangles; components "
                                 "kept: 1 — Apply for full resolution"));
    settle();
    window_->statusBar()->grab().save(QString::fromStdString(
        (vv::test::panelTestDir() / ("status-bar-" + caseName({GetParam(), 0}) + ".png"))
            .string()));
    const std::vector<std::string> problems = ClippingCheck::problems(window_->statusBar());
    EXPECT_TRUE(problems.empty()) << "cut off in the status bar:" << listed(problems);
}

/// The DICOM menu's dialogs (Query PACS with its date fields, Preferences),
/// the Export Image dialog with its note about another shape, and an error
/// box with its details.
TEST_P(ClippingTest, MoreDialogsShowEveryTextInFull) {
    vv::gui::PacsBrowser query(window_.get());
    expectWhole(query, "query-pacs");
    vv::gui::NetworkPreferencesDialog preferences(window_.get());
    expectWhole(preferences, "network-preferences");
    // Study > Run Study… (issue 34) with its longest summary: a participant
    // who answered some of the images.
    const auto study = std::filesystem::path(VV_TEST_TMP) / "clipping-study" /
                       (std::string(GetParam().language) + std::to_string(GetParam().width));
    vv::study::test::writeStudyFolder(study);
    vv::study::Answer answered;
    answered.participant = "P07";
    answered.trial = 1;
    answered.stimulus = "tree-p1-VSS-CD";
    answered.scene = "tree";
    answered.condition = "VSS-CD";
    vv::study::appendAnswer(study / "results.csv", answered);
    vv::gui::StudyRunDialog run(window_.get());
    run.setStudyFolder(QString::fromStdString(study.string()));
    run.setParticipant(QStringLiteral("P07"));
    ASSERT_TRUE(run.participantSummary().contains(QStringLiteral("P07")));
    expectWhole(run, "run-study");
    // Study > Analyse Results… with a results file and its longest outcome:
    // an error naming the file and its line.
    vv::gui::StudyAnalysisDialog analysis(window_.get());
    analysis.addResultsFile(QString::fromStdString((study / "results.csv").string()));
    analysis.setPdfPath(QString::fromStdString((study / "study.pdf").string()));
    bool analysed = false;
    QObject::connect(&analysis, &vv::gui::StudyAnalysisDialog::finished,
                     [&analysed] { analysed = true; });
    ASSERT_TRUE(analysis.analyse());
    ASSERT_TRUE(waitUntil([&] { return analysed; }, 60000));
    expectWhole(analysis, "analyse-study");
    vv::gui::ExportImageDialog image(*window_->viewer(), window_.get());
    image.sizeChooser()->setCurrentIndex(
        image.sizeChooser()->findData(vv::gui::ExportImageDialog::Uhd4k));
    expectWhole(image, "export-image-4k");
    vv::gui::ProblemText problem{QStringLiteral("/data/aorta.vtp is damaged"),
                                 QStringLiteral("/data/aorta.vtp: binary STL truncated")};
    vv::gui::showProblem(window_.get(), QStringLiteral("problemBox"), QStringLiteral("Open"),
                         problem);
    auto* box = window_->findChild<QMessageBox*>(QStringLiteral("problemBox"));
    ASSERT_NE(box, nullptr);
    expectWhole(*box, "problem-box");
    box->close();
}

INSTANTIATE_TEST_SUITE_P(LanguagesAndSizes, ClippingTest,
                         ::testing::Values(Case{"en", 1280, 800}, Case{"en", 1920, 1080},
                                           Case{"de", 1280, 800}, Case{"de", 1920, 1080}),
                         caseName);

}  // namespace
