// SPDX-License-Identifier: GPL-3.0-or-later
// File > Export Image… and File > Export Report… driven programmatically
// (fields set, accept()), and the export worker: rendering on its own thread
// while the GUI thread's event loop keeps running. Needs a display:
// xvfb-run -a, QT_QPA_PLATFORM=xcb. PDFs are read back with pdftotext / pdfinfo.
#include <QAbstractButton>
#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QGroupBox>
#include <QImage>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QPointer>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QStyle>
#include <QTimer>
#include <QTranslator>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "ClippingCheck.h"
#include "GuiFixture.h"
#include "ReportTestUtil.h"
#include "gui/ExportImageDialog.h"
#include "gui/ExportWorker.h"
#include "gui/ReportDialog.h"
#include "vv/demo/DemoCtSeries.h"
#include "vv/demo/DemoTree.h"
#include "vv/dicom/SeriesWriter.h"
#include "vv/report/ReportJob.h"
#include "vv/report/ViewExport.h"

namespace vv::test {
namespace {

std::string readAll(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// What a finished worker reported.
struct Outcome {
    bool finished = false;
    bool succeeded = false;
    bool cancelled = false;
    QString message;
};

/// Records the outcome of `worker` into `outcome`.
void record(gui::ExportWorker* worker, const std::shared_ptr<Outcome>& outcome) {
    QObject::connect(worker, &gui::ExportWorker::succeeded, [outcome](const QString& message) {
        outcome->succeeded = true;
        outcome->message = message;
    });
    QObject::connect(worker, &gui::ExportWorker::failed,
                     [outcome](const QString& message) { outcome->message = message; });
    QObject::connect(worker, &gui::ExportWorker::cancelled,
                     [outcome] { outcome->cancelled = true; });
    QObject::connect(worker, &gui::ExportWorker::finished, [outcome] { outcome->finished = true; });
}

class ExportGuiTest : public GuiFixture {
  protected:
    void SetUp() override {
        GuiFixture::SetUp();
        dir_ = panelTestDir() / ::testing::UnitTest::GetInstance()->current_test_info()->name();
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }

    /// Shows the tube (wss on the vessels) and waits for its exact VSS.
    bool showTube() {
        window_->setScene(makeTubeScene(), QStringLiteral("tube"));
        return waitForFrames() && waitForVss();
    }

    /// Accepts `dialog` and waits until the export it started has finished.
    template <typename Dialog>
    std::shared_ptr<Outcome> exportWith(Dialog& dialog) {
        auto outcome = std::make_shared<Outcome>();
        QObject::connect(&dialog, &Dialog::exportStarted,
                         [outcome](gui::ExportWorker* worker) { record(worker, outcome); });
        dialog.accept();
        EXPECT_TRUE(waitUntil([&] { return outcome->finished; }, 120000)) << "no end of export";
        return outcome;
    }

    /// An image export of the current view at width x height.
    QImage exportImage(const std::string& name, int width, int height, bool legends,
                       bool transparent) {
        gui::ExportImageDialog dialog(*window_->viewer(), window_.get());
        const fs::path file = dir_ / name;
        dialog.fileEdit()->setText(QString::fromStdString(file.string()));
        dialog.keepAspectBox()->setChecked(false);
        dialog.widthBox()->setValue(width);
        dialog.heightBox()->setValue(height);
        dialog.legendsBox()->setChecked(legends);
        dialog.transparentBox()->setChecked(transparent);
        const auto outcome = exportWith(dialog);
        EXPECT_TRUE(outcome->succeeded) << outcome->message.toStdString();
        QImage image;
        EXPECT_TRUE(image.load(QString::fromStdString(file.string()), "PNG")) << file;
        return image;
    }

    /// The box asking to replace existing files over `dialog`, once shown; null after 5 s.
    static QMessageBox* replaceBox(const QWidget& dialog) {
        QMessageBox* box = nullptr;
        waitUntil(
            [&] {
                box = dialog.findChild<QMessageBox*>(QStringLiteral("replaceFilesBox"));
                return box != nullptr && box->isVisible();
            },
            5000);
        return box;
    }

    /// Clicks `box`'s Replace (true) or Cancel button and waits until it is gone.
    static void answer(QMessageBox* box, bool replace) {
        QAbstractButton* button = box->button(QMessageBox::Cancel);
        for (QAbstractButton* b : box->buttons()) {
            if (replace && box->buttonRole(b) == QMessageBox::DestructiveRole) {
                button = b;
            }
        }
        ASSERT_NE(button, nullptr);
        EXPECT_EQ(button->text(), replace ? QStringLiteral("&Replace") : QStringLiteral("Cancel"));
        const QPointer<QMessageBox> shown(box);
        button->click();
        EXPECT_TRUE(waitUntil([&] { return shown.isNull(); }, 5000)) << "the box stays";
    }

    /// `file` with `content`, last written an hour ago (so that a rewrite shows in its time).
    static fs::file_time_type earlierFile(const fs::path& file, const std::string& content) {
        std::ofstream(file, std::ios::binary) << content;
        const auto time = fs::file_time_type::clock::now() - std::chrono::hours(1);
        fs::last_write_time(file, time);
        return fs::last_write_time(file);
    }

    fs::path dir_;
};

TEST_F(ExportGuiTest, MenuEntriesNeedAScene) {
    QAction* image = window_->exportImageAction();
    QAction* report = window_->exportReportAction();
    ASSERT_NE(image, nullptr);
    ASSERT_NE(report, nullptr);
    EXPECT_FALSE(image->isEnabled());
    EXPECT_FALSE(report->isEnabled());
    EXPECT_FALSE(image->toolTip().isEmpty());
    EXPECT_EQ(image->shortcut(), QKeySequence(Qt::CTRL | Qt::Key_E));
    EXPECT_EQ(report->shortcut(), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_E));
    window_->setScene(makeTubeScene(), QStringLiteral("tube"));
    EXPECT_TRUE(image->isEnabled());
    EXPECT_TRUE(report->isEnabled());
}

TEST_F(ExportGuiTest, ImageHasTheSizeAskedForAndLegendsAndTransparencyShow) {
    ASSERT_TRUE(showTube());
    const QImage withLegends = exportImage("legends.png", 640, 400, true, false);
    const QImage without = exportImage("plain.png", 640, 400, false, false);
    EXPECT_EQ(withLegends.size(), QSize(640, 400));
    EXPECT_EQ(without.size(), QSize(640, 400));
    // The legends cover part of the image, not all of it.
    const double changed = changedFraction(withLegends, without);
    EXPECT_GT(changed, 0.002);
    EXPECT_LT(changed, 0.3);

    // The VSS fills the void around the tube: switched off, that void is background.
    window_->vssToggle()->setChecked(false);
    const QImage transparent = exportImage("transparent.png", 640, 400, false, true);
    ASSERT_TRUE(transparent.hasAlphaChannel());
    EXPECT_EQ(qAlpha(transparent.pixel(1, 1)), 0);  // background corner
    long clear = 0;
    long opaque = 0;
    for (int y = 0; y < transparent.height(); ++y) {
        for (int x = 0; x < transparent.width(); ++x) {
            const int alpha = qAlpha(transparent.pixel(x, y));
            clear += alpha == 0 ? 1 : 0;
            opaque += alpha == 255 ? 1 : 0;
        }
    }
    EXPECT_GT(clear, 640L * 400 / 10);  // the background
    EXPECT_GT(opaque, 640L * 4);        // the tube
}

TEST_F(ExportGuiTest, PresetsGiveTheirExactSizeKeepAspectFollowsTheViewAnd8KIsTheLimit) {
    ASSERT_TRUE(showTube());
    gui::ExportImageDialog dialog(*window_->viewer(), window_.get());
    const QSize view = gui::viewPixelSize(*window_->viewer());
    const double aspect = static_cast<double>(view.width()) / view.height();
    EXPECT_EQ(dialog.imageSize(), view);  // "View size" first
    EXPECT_TRUE(dialog.keepAspectBox()->isChecked());
    // A preset is its size exactly; the view (not 16:9 here) no longer locks the shape.
    ASSERT_GT(std::abs(aspect - 16.0 / 9.0), 0.01);
    dialog.sizeChooser()->setCurrentIndex(
        dialog.sizeChooser()->findData(gui::ExportImageDialog::Uhd4k));
    EXPECT_EQ(dialog.imageSize(), QSize(3840, 2160));
    EXPECT_FALSE(dialog.keepAspectBox()->isChecked());
    // Locking again: the height follows the width in the view's shape.
    dialog.keepAspectBox()->setChecked(true);
    EXPECT_EQ(dialog.imageSize().width(), 3840);
    EXPECT_NEAR(dialog.imageSize().height(), 3840.0 / aspect, 1.0);
    EXPECT_EQ(dialog.sizeChooser()->currentData().toInt(), gui::ExportImageDialog::Custom);

    dialog.keepAspectBox()->setChecked(false);
    dialog.widthBox()->setValue(8000);
    dialog.heightBox()->setValue(4000);
    EXPECT_FALSE(dialog.problem().isEmpty());
    const fs::path file = dir_ / "huge.png";
    dialog.fileEdit()->setText(QString::fromStdString(file.string()));
    bool started = false;
    QObject::connect(&dialog, &gui::ExportImageDialog::exportStarted,
                     [&started] { started = true; });
    dialog.accept();
    EXPECT_FALSE(started);
    EXPECT_NE(dialog.findChild<QMessageBox*>(QStringLiteral("exportProblemBox")), nullptr);
    EXPECT_FALSE(fs::exists(file));
}

/// A preset of another shape than the view no longer silently unticks "keep
/// the view's aspect ratio": a note says how the image differs from the view
/// (wider: more at the sides; narrower: part of the view left out), and
/// goes when the shapes agree again.
TEST_F(ExportGuiTest, APresetOfAnotherShapeSaysHowTheImageDiffersFromTheView) {
    ASSERT_TRUE(showTube());
    gui::ExportImageDialog dialog(*window_->viewer(), window_.get());
    dialog.show();
    const QSize view = gui::viewPixelSize(*window_->viewer());
    const double aspect = static_cast<double>(view.width()) / view.height();
    ASSERT_GT(std::abs(aspect - 16.0 / 9.0), 0.01);
    QLabel* note = dialog.aspectNote();
    ASSERT_NE(note, nullptr);
    EXPECT_FALSE(note->isVisible()) << note->text().toStdString();  // the view's size
    dialog.sizeChooser()->setCurrentIndex(
        dialog.sizeChooser()->findData(gui::ExportImageDialog::Uhd4k));
    ASSERT_FALSE(dialog.keepAspectBox()->isChecked());
    EXPECT_TRUE(note->isVisible()) << "the aspect changed without a word";
    const bool wider = 16.0 / 9.0 > aspect;
    EXPECT_TRUE(note->text().contains(wider ? QStringLiteral("wider") : QStringLiteral("narrower")))
        << note->text().toStdString();
    EXPECT_TRUE(note->text().contains(QStringLiteral("1.78:1"))) << note->text().toStdString();
    // The same shape again: no note.
    dialog.keepAspectBox()->setChecked(true);
    EXPECT_FALSE(note->isVisible()) << note->text().toStdString();
    // A custom size of another shape: the note again, the other way round.
    dialog.keepAspectBox()->setChecked(false);
    dialog.heightBox()->setValue(
        static_cast<int>(std::lround(dialog.widthBox()->value() / aspect * 2.0)));
    EXPECT_TRUE(note->isVisible());
    EXPECT_TRUE(note->text().contains(QStringLiteral("narrower"))) << note->text().toStdString();
}

TEST_F(ExportGuiTest, FourKPresetWrites3840x2160) {
    ASSERT_TRUE(showTube());
    gui::ExportImageDialog dialog(*window_->viewer(), window_.get());
    const fs::path file = dir_ / "uhd.png";
    dialog.fileEdit()->setText(QString::fromStdString(file.string()));
    ASSERT_TRUE(dialog.keepAspectBox()->isChecked());  // as the dialog opens
    dialog.sizeChooser()->setCurrentIndex(
        dialog.sizeChooser()->findData(gui::ExportImageDialog::Uhd4k));
    const auto outcome = exportWith(dialog);
    ASSERT_TRUE(outcome->succeeded) << outcome->message.toStdString();
    QImage image;
    ASSERT_TRUE(image.load(QString::fromStdString(file.string()), "PNG")) << file;
    EXPECT_EQ(image.size(), QSize(3840, 2160));
}

TEST_F(ExportGuiTest, FileFieldShowsThePathAndLongOnesEndInView) {
    window_->setScene(makeTubeScene(), QStringLiteral("tube"));
    gui::ExportImageDialog dialog(*window_->viewer(), window_.get());
    QLineEdit* edit = dialog.fileEdit();
    const auto room = [edit] {
        return edit->contentsRect().width() -
               2 * edit->style()->pixelMetric(QStyle::PM_DefaultFrameWidth, nullptr, edit) - 4;
    };
    // A path of a usual length is shown whole.
    const QString usual =
        QStringLiteral("/home/radiology/Pictures/2026-11/patient-study-vessels.png");
    edit->setText(usual);
    dialog.show();
    QCoreApplication::processEvents();
    EXPECT_LE(edit->fontMetrics().horizontalAdvance(usual), room())
        << usual.toStdString() << " is cut in a field of " << room() << " px";
    EXPECT_TRUE(ClippingCheck::problems(&dialog).empty());
    // A very long one: its file name in view, the whole path in the tooltip.
    const QString longer = QStringLiteral("/data/") + QString(60, QLatin1Char('x')) +
                           QStringLiteral("/") + QString(60, QLatin1Char('y')) +
                           QStringLiteral("/final-vessels.png");
    edit->setText(longer);
    QCoreApplication::processEvents();
    EXPECT_EQ(edit->toolTip().toStdString(), longer.toStdString());
    EXPECT_EQ(edit->cursorPosition(), longer.size());
    EXPECT_LE(edit->fontMetrics().horizontalAdvance(QStringLiteral("final-vessels.png")), room());
}

TEST_F(ExportGuiTest, ReportHasTheFindingsAndThePaperChosen) {
    ASSERT_TRUE(showTube());
    for (const bool letter : {false, true}) {
        gui::ReportDialog dialog(*window_->viewer(), window_->reportSource(), window_.get());
        const fs::path pdf = dir_ / (letter ? "letter.pdf" : "a4.pdf");
        dialog.pdfEdit()->setText(QString::fromStdString(pdf.string()));
        dialog.paperChooser()->setCurrentIndex(letter ? 1 : 0);
        dialog.findingsEdit()->setPlainText(
            QStringLiteral("Low wall shear stress distally.\nNo stenosis."));
        dialog.secondViewChooser()->setCurrentIndex(
            dialog.secondViewChooser()->findData(QStringLiteral("anterior")));
        dialog.pngBox()->setChecked(true);
        const fs::path png = dir_ / (letter ? "letter.png" : "a4.png");
        EXPECT_EQ(dialog.pngEdit()->text().toStdString(), png.string());  // beside the PDF
        const auto outcome = exportWith(dialog);
        ASSERT_TRUE(outcome->succeeded) << outcome->message.toStdString();
        EXPECT_TRUE(fs::exists(png));

        std::string text;
        ASSERT_EQ(report::test::runTool("pdftotext -layout '" + pdf.string() + "' -", text), 0)
            << text;
        EXPECT_NE(text.find("Low wall shear stress distally."), std::string::npos) << text;
        EXPECT_NE(text.find("No stenosis."), std::string::npos) << text;
        EXPECT_NE(text.find("Anterior view"), std::string::npos) << text;
        EXPECT_EQ(text.find("Patient"), std::string::npos) << text;  // a mesh: no patient
        std::string info;
        ASSERT_EQ(report::test::runTool("pdfinfo '" + pdf.string() + "'", info), 0) << info;
        EXPECT_NE(info.find(letter ? "612 x 792 pts" : "595 x 842 pts (A4)"), std::string::npos)
            << info;
    }
}

TEST_F(ExportGuiTest, ReportTakesAPatientForMeshesTheDisclaimerAndTheUiLanguage) {
    ASSERT_TRUE(showTube());
    // The UI in German, as Translations.cpp installs it.
    QTranslator german;
    ASSERT_TRUE(german.load(QStringLiteral("vesselview_de"), QStringLiteral(VV_QM_DIR)));
    QCoreApplication::installTranslator(&german);
    const QLocale before;
    QLocale::setDefault(QLocale(QLocale::German, QLocale::Germany));
    const std::shared_ptr<void> restore(nullptr, [&](void*) {
        QCoreApplication::removeTranslator(&german);
        QLocale::setDefault(before);
        QSettings().remove(QLatin1String(gui::ReportDialog::kDisclaimerKey));
    });
    QSettings().remove(QLatin1String(gui::ReportDialog::kDisclaimerKey));

    gui::ReportDialog dialog(*window_->viewer(), window_->reportSource(), window_.get());
    EXPECT_FALSE(dialog.patientGroup()->isHidden());  // a mesh: the patient can be entered
    EXPECT_FALSE(dialog.anonymiseBox()->isEnabled());
    dialog.patientGroup()->setChecked(true);
    EXPECT_TRUE(dialog.anonymiseBox()->isEnabled());
    dialog.patientNameEdit()->setText(QStringLiteral("Musterfrau^Erika"));
    dialog.patientIdEdit()->setText(QStringLiteral("P-4711"));
    dialog.birthDateEdit()->setText(QStringLiteral("1964-08-31"));
    dialog.sexChooser()->setCurrentIndex(dialog.sexChooser()->findData(QStringLiteral("F")));
    EXPECT_EQ(dialog.disclaimerEdit()->text(), QStringLiteral("Nicht für diagnostische Zwecke."));
    dialog.disclaimerEdit()->setText(QStringLiteral("Nur für Forschungszwecke."));
    dialog.studyDateEdit()->setText(QStringLiteral("2026-02-30"));
    EXPECT_FALSE(dialog.problem().isEmpty());  // no such date
    dialog.studyDateEdit()->setText(QStringLiteral("2026-03-01"));
    EXPECT_TRUE(dialog.problem().isEmpty()) << dialog.problem().toStdString();
    const fs::path pdf = dir_ / "bericht.pdf";
    dialog.pdfEdit()->setText(QString::fromStdString(pdf.string()));
    const auto outcome = exportWith(dialog);
    ASSERT_TRUE(outcome->succeeded) << outcome->message.toStdString();

    std::string text;
    ASSERT_EQ(report::test::runTool("pdftotext -layout '" + pdf.string() + "' -", text), 0);
    for (const char* expected :
         {"Gefäßbaum-Bericht", "Nur für Forschungszwecke.", "Patient und Untersuchung",
          "Musterfrau, Erika", "P-4711", "31.08.1964", "weiblich", "01.03.2026", "Befund",
          "Parameterstatistik", "100,0 %", "Darstellungseinstellungen"}) {
        EXPECT_NE(text.find(expected), std::string::npos) << expected << " in\n" << text;
    }
    for (const char* english : {"Findings", "Patient and study", "Rendering settings",
                                "Not for diagnostic use.", "100.0 %"}) {
        EXPECT_EQ(text.find(english), std::string::npos) << english << " in\n" << text;
    }
    // The disclaimer is remembered, and the About box shows it.
    EXPECT_TRUE(window_->aboutText().contains(QStringLiteral("Nur für Forschungszwecke.")));
}

TEST_F(ExportGuiTest, TheDefaultDisclaimerFollowsTheUiLanguage) {
    ASSERT_TRUE(showTube());
    const QLatin1String key(gui::ReportDialog::kDisclaimerKey);
    const std::shared_ptr<void> restore(nullptr, [key](void*) { QSettings().remove(key); });
    // An English report with the default line keeps no setting ...
    QSettings().remove(key);
    {
        gui::ReportDialog dialog(*window_->viewer(), window_->reportSource(), window_.get());
        EXPECT_EQ(dialog.disclaimerEdit()->text(), QStringLiteral("Not for diagnostic use."));
        dialog.pdfEdit()->setText(QString::fromStdString((dir_ / "english.pdf").string()));
        ASSERT_TRUE(exportWith(dialog)->succeeded);
    }
    EXPECT_FALSE(QSettings().contains(key));
    // ... and one that an earlier version stored is the default too: the
    // German UI shows the German line, not the English one.
    QSettings().setValue(key, QStringLiteral("Not for diagnostic use."));
    QTranslator german;
    ASSERT_TRUE(german.load(QStringLiteral("vesselview_de"), QStringLiteral(VV_QM_DIR)));
    QCoreApplication::installTranslator(&german);
    const std::shared_ptr<void> english(
        nullptr, [&german](void*) { QCoreApplication::removeTranslator(&german); });
    EXPECT_EQ(gui::ReportDialog::disclaimer(QSettings()),
              QStringLiteral("Nicht für diagnostische Zwecke."));
    // A line of one's own is kept as typed, in any language.
    QSettings().setValue(key, QStringLiteral("For research only."));
    EXPECT_EQ(gui::ReportDialog::disclaimer(QSettings()), QStringLiteral("For research only."));
}

TEST_F(ExportGuiTest, AnonymiseOnlyForDicomData) {
    ASSERT_TRUE(showTube());
    const gui::ReportDialog mesh(*window_->viewer(), window_->reportSource(), window_.get());
    EXPECT_FALSE(mesh.anonymiseBox()->isEnabled());
    EXPECT_FALSE(mesh.anonymiseBox()->isChecked());
    EXPECT_FALSE(mesh.anonymiseBox()->toolTip().isEmpty());
    EXPECT_FALSE(mesh.jobOptions().anonymise);

    report::ReportSource dicom;
    dicom.dicomPath = dir_ / "series";
    gui::ReportDialog fromDicom(*window_->viewer(), dicom, window_.get());
    EXPECT_TRUE(fromDicom.anonymiseBox()->isEnabled());
    fromDicom.anonymiseBox()->setChecked(true);
    EXPECT_TRUE(fromDicom.jobOptions().anonymise);
}

TEST_F(ExportGuiTest, DicomDataGivesThePatientBlockAndAnonymiseHidesIt) {
    const fs::path series = fs::absolute(dir_ / "series");
    demo::DemoCtOptions ct;
    ct.dims = {64, 64, 48};
    dicom::CtSeriesWriteOptions write;
    write.patientName = "Testpatient^Erika";
    write.patientId = "EXPORT-42";
    const std::string uid = dicom::writeCtSeries(series, demo::generateDemoCt(ct).volume, write);
    window_->openFiles({QString::fromStdString(series.string())});
    ASSERT_TRUE(waitUntil(
        [&] { return window_->viewer()->scene() != nullptr || !window_->lastError().isEmpty(); },
        300000));
    ASSERT_TRUE(window_->lastError().isEmpty()) << window_->lastError().toStdString();
    const report::ReportSource source = window_->reportSource();
    EXPECT_EQ(source.dicomPath, series);
    EXPECT_EQ(source.seriesInstanceUid, uid);
    for (const bool anonymise : {false, true}) {
        gui::ReportDialog dialog(*window_->viewer(), source, window_.get());
        ASSERT_TRUE(dialog.anonymiseBox()->isEnabled());
        dialog.anonymiseBox()->setChecked(anonymise);
        const fs::path pdf = dir_ / (anonymise ? "anonymous.pdf" : "named.pdf");
        dialog.pdfEdit()->setText(QString::fromStdString(pdf.string()));
        const auto outcome = exportWith(dialog);
        ASSERT_TRUE(outcome->succeeded) << outcome->message.toStdString();
        std::string text;
        ASSERT_EQ(report::test::runTool("pdftotext -layout '" + pdf.string() + "' -", text), 0);
        EXPECT_NE(text.find("Patient and study"), std::string::npos) << text;
        EXPECT_EQ(text.find("Testpatient") == std::string::npos, anonymise) << text;
        EXPECT_EQ(text.find("EXPORT-42") == std::string::npos, anonymise) << text;
        EXPECT_EQ(text.find("anonymised") != std::string::npos, anonymise) << text;
    }
}

TEST_F(ExportGuiTest, EverySecondViewsLegendDescribesItsOwnImage) {
    // The demo tree without arrays: only the depth legend is over the views.
    auto scene = std::make_shared<scene::Scene>();
    // (A smaller tree than the bundled one, drawn as its facets (the smooth
    // copy of a coarse mesh has tests of its own: SmoothCoarseTest): nine
    // reports stay quick.)
    scene::Mesh tree = demo::generateDemoMesh({.generations = 4, .maxTriangles = 40000});
    tree.pointArrays.clear();
    tree.cellArrays.clear();
    scene->meshes.push_back(std::move(tree));
    gui::ViewerWidget* viewer = window_->viewer();
    viewer->setSmoothCoarseMeshes(false);
    window_->setScene(scene, QStringLiteral("demo"));
    ASSERT_TRUE(waitForFrames() && waitForVss());
    const vss::DepthRange chosen = viewer->vssSettings().range;
    ASSERT_EQ(chosen.mode, vss::RangeMode::Visible);
    render::OffscreenRenderer renderer;
    const auto legendOfSecondView = [&](const std::string& name, const vss::DepthRange& range) {
        gui::ReportDialog dialog(*viewer, window_->reportSource(), window_.get());
        const int item = dialog.secondViewChooser()->findData(QString::fromStdString(name));
        EXPECT_GE(item, 0);
        dialog.secondViewChooser()->setCurrentIndex(item);
        report::ReportJobOptions job = dialog.jobOptions();
        EXPECT_TRUE(job.secondView.has_value());
        const fs::path pdf = dir_ / (name + ".pdf");
        job.outputs = {};
        job.outputs.pdf = pdf;
        (void)report::runReportJob(renderer, *scene, job);
        // What the second view shows, rendered on its own.
        const auto [dmin, dmax] = report::test::ownDepthRange(renderer, *scene, job.view,
                                                              *job.secondView, range, job.paper);
        const std::string caption = report::namedViewCaption(name);
        // A fixed range the user chose: the viewing distance, near to far.
        render::DepthLegend legend;
        legend.dmin = dmin;
        legend.dmax = dmax;
        legend.reference = range.mode == vss::RangeMode::Fixed
                               ? render::DepthReference::Camera
                               : render::DepthReference::FrontmostVessel;
        return report::test::depthLegendProblem(report::test::pdfWords(pdf), "Second",
                                                caption.substr(0, caption.find(' ')), legend);
    };
    // The first view has the screen's range; each second view its own.
    for (const std::string& name : report::test::namedViews()) {
        SCOPED_TRACE(name);
        const std::string problem = legendOfSecondView(name, chosen);
        EXPECT_TRUE(problem.empty()) << problem;
    }
    // A depth range the user fixed applies to both views.
    render::VssSettings fixed = viewer->vssSettings();
    fixed.range = {vss::RangeMode::Fixed, 5.0, 65.0};
    viewer->setVssSettings(fixed);
    ASSERT_TRUE(waitForVss());
    const std::string problem = legendOfSecondView("anterior", fixed.range);
    EXPECT_TRUE(problem.empty()) << problem;
}

/// The depth legend's title and tick labels, as painted.
QStringList legendText(const render::DepthLegend& legend) {
    QStringList text{QString::fromStdString(render::depthLegendTitle(legend))};
    for (const render::LegendTick& tick : render::depthLegendTicks(legend)) {
        text << tick.label;
    }
    return text;
}

/// Every depth legend and the probe say what their numbers are (issue 30,
/// item 10): with the visible range the depth behind the frontmost vessel,
/// and an export framed as the view (its range pinned) reads exactly as the
/// screen; with a fixed range the user chose, the viewing distance from near
/// to far, on the screen, the image export, both views of the report and in
/// the probe.
TEST_F(ExportGuiTest, EveryDepthLegendAndTheProbeSayWhatTheirNumbersMeasureFrom) {
    ASSERT_TRUE(showTube());
    gui::ViewerWidget* viewer = window_->viewer();
    render::MeshStyle style = viewer->style();
    style.array.clear();  // the depth legend alone over the views
    viewer->setStyle(style);
    viewer->setLegendsVisible(true);
    const auto screenLegend = [&] {
        const quint64 frames = viewer->framesWithScene();
        EXPECT_TRUE(waitUntil(
            [&] {
                return viewer->framesWithScene() > frames && !viewer->vssStatus().pending &&
                       !viewer->vssStatus().preview && viewer->shownLegends().depth.has_value();
            },
            60000));
        return viewer->shownLegends().depth.value_or(render::DepthLegend{});
    };
    const auto probeLine = [&] {
        std::optional<gui::ProbeResult> probe;
        for (int y = 1; y < 20 && !probe; ++y) {
            probe = viewer->probeAt(QPointF(0.5 * viewer->width(), y * viewer->height() / 20.0));
        }
        EXPECT_TRUE(probe.has_value());
        return std::pair{probe.value_or(gui::ProbeResult{}),
                         gui::ViewerWidget::probeText(probe.value_or(gui::ProbeResult{}))
                             .split(QLatin1Char('\n'))
                             .back()};
    };
    const QSize view = gui::viewPixelSize(*viewer);
    render::OffscreenRenderer renderer;
    const auto exportedLegend = [&] {
        report::ViewExportOptions options;
        options.render = gui::currentViewOptions(*viewer, 2 * view.width(), 2 * view.height());
        const report::RenderedView exported =
            report::renderView(renderer, *viewer->scene(), options);
        return exported.legends.depth.value_or(render::DepthLegend{});
    };
    // The report's first view and its anterior second view, as the PDF prints them.
    const auto reportProblems = [&](const std::string& name, const render::DepthLegend& first,
                                    const vss::DepthRange& range) {
        gui::ReportDialog dialog(*viewer, window_->reportSource(), window_.get());
        dialog.secondViewChooser()->setCurrentIndex(
            dialog.secondViewChooser()->findData(QStringLiteral("anterior")));
        report::ReportJobOptions job = dialog.jobOptions();
        const fs::path pdf = dir_ / (name + ".pdf");
        job.outputs = {};
        job.outputs.pdf = pdf;
        (void)report::runReportJob(renderer, *viewer->scene(), job);
        const auto words = report::test::pdfWords(pdf);
        const auto anterior = render::namedViewFromName("anterior");
        const auto [dmin, dmax] = report::test::ownDepthRange(renderer, *viewer->scene(), job.view,
                                                              *anterior, range, job.paper);
        render::DepthLegend second = first;
        second.dmin = dmin;
        second.dmax = dmax;
        const std::string caption = report::namedViewCaption("anterior");
        std::string problems = report::test::depthLegendProblem(words, "View", "The", first);
        const std::string secondProblem = report::test::depthLegendProblem(
            words, "Second", caption.substr(0, caption.find(' ')), second);
        if (!secondProblem.empty()) {
            problems += " | second view: " + secondProblem;
        }
        return problems;
    };

    // The visible range: the depth behind the frontmost vessel, from 0.
    const render::DepthLegend visible = screenLegend();
    EXPECT_EQ(visible.reference, render::DepthReference::FrontmostVessel);
    const QStringList screenText = legendText(visible);
    EXPECT_EQ(screenText.front(),
              render::depthQuantityName(render::DepthReference::FrontmostVessel) +
                  QStringLiteral(" (mm)"));
    EXPECT_EQ(QLocale().toDouble(screenText.at(1)), 0.0) << screenText.at(1).toStdString();
    EXPECT_EQ(legendText(exportedLegend()), screenText) << "the pinned export reads as the screen";
    const std::string visibleReport =
        reportProblems("visible", visible, viewer->vssSettings().range);
    EXPECT_TRUE(visibleReport.empty()) << visibleReport;
    const auto [nearProbe, nearLine] = probeLine();
    EXPECT_EQ(nearLine, QStringLiteral("%1: %2 mm")
                            .arg(render::depthQuantityName(render::DepthReference::FrontmostVessel),
                                 QLocale().toString(nearProbe.depthBelowNearest, 'f', 1)));

    // A fixed range the user chose: the viewing distance, near to far.
    render::VssSettings fixed = viewer->vssSettings();
    const double nearEnd = std::floor(visible.dmin) - 2.0;
    const double farEnd = std::ceil(visible.dmax) + 3.0;
    fixed.range = {.mode = vss::RangeMode::Fixed, .dmin = nearEnd, .dmax = farEnd};
    viewer->setVssSettings(fixed);
    const render::DepthLegend chosen = screenLegend();
    EXPECT_EQ(chosen.reference, render::DepthReference::Camera);
    const QStringList fixedText = legendText(chosen);
    EXPECT_EQ(fixedText.front(),
              render::depthQuantityName(render::DepthReference::Camera) + QStringLiteral(" (mm)"));
    EXPECT_EQ(QLocale().toDouble(fixedText.at(1)), nearEnd) << fixedText.at(1).toStdString();
    EXPECT_EQ(QLocale().toDouble(fixedText.back()), farEnd) << fixedText.back().toStdString();
    EXPECT_EQ(legendText(exportedLegend()), fixedText);
    const std::string fixedReport = reportProblems("fixed", chosen, fixed.range);
    EXPECT_TRUE(fixedReport.empty()) << fixedReport;
    const auto [farProbe, farLine] = probeLine();
    EXPECT_EQ(farLine, QStringLiteral("%1: %2 mm")
                           .arg(render::depthQuantityName(render::DepthReference::Camera),
                                QLocale().toString(farProbe.linearDepth, 'f', 1)));
    EXPECT_GE(farProbe.linearDepth, nearEnd);
    EXPECT_LE(farProbe.linearDepth, farEnd);
}

TEST_F(ExportGuiTest, ReportChecksItsOutputs) {
    ASSERT_TRUE(showTube());
    gui::ReportDialog dialog(*window_->viewer(), window_->reportSource(), window_.get());
    dialog.pdfEdit()->setText(QString::fromStdString((dir_ / "r.pdf").string()));
    EXPECT_TRUE(dialog.problem().isEmpty()) << dialog.problem().toStdString();
    dialog.dicomPdfBox()->setChecked(true);
    dialog.dicomPdfEdit()->setText(dialog.pdfEdit()->text());  // the same file twice
    EXPECT_FALSE(dialog.problem().isEmpty());
    dialog.dicomPdfEdit()->setText(QString::fromStdString((dir_ / "no" / "d.dcm").string()));
    EXPECT_FALSE(dialog.problem().isEmpty());  // no such folder
    // Statistics thresholds are there for the wss on the vessels (the CLI's default).
    EXPECT_TRUE(dialog.belowBox()->isEnabled());
    EXPECT_TRUE(dialog.belowBox()->isChecked());
    EXPECT_DOUBLE_EQ(dialog.belowValue()->value(), 0.4);
}

TEST_F(ExportGuiTest, ReportThresholdsShowTheUnitOfTheShownArray) {
    ASSERT_TRUE(showTube());
    auto* viewer = window_->viewer();
    ASSERT_EQ(viewer->style().array, "wss");
    const QLocale before;
    for (const QLocale& locale : {QLocale(QLocale::English, QLocale::UnitedStates),
                                  QLocale(QLocale::German, QLocale::Germany)}) {
        QLocale::setDefault(locale);
        const gui::ReportDialog dialog(*viewer, window_->reportSource(), window_.get());
        // What the fields show: the number and the unit of the wall shear stress.
        EXPECT_EQ(dialog.belowValue()->text(),
                  locale.toString(0.4, 'f', 3) + QStringLiteral(" Pa"));
        EXPECT_EQ(dialog.aboveValue()->text(),
                  locale.toString(0.0, 'f', 3) + QStringLiteral(" Pa"));
    }
    QLocale::setDefault(before);
    render::MeshStyle style = viewer->style();
    style.array = "pressure";
    viewer->setStyle(style);
    {
        const gui::ReportDialog dialog(*viewer, window_->reportSource(), window_.get());
        EXPECT_TRUE(dialog.belowValue()->text().endsWith(QStringLiteral(" mmHg")))
            << dialog.belowValue()->text().toStdString();
    }
    // An array without a unit: the number alone.
    auto scene = std::make_shared<scene::Scene>(*makeTubeScene(false));
    addAxialArray(scene->meshes[0], "segment", "", 0.0F,
                  [](float x) { return x > 15.0F ? 2.0F : 1.0F; });
    window_->setScene(scene, QStringLiteral("segments"));
    ASSERT_TRUE(waitForFrames());
    style = viewer->style();
    style.array = "segment";
    viewer->setStyle(style);
    const gui::ReportDialog dialog(*viewer, window_->reportSource(), window_.get());
    EXPECT_TRUE(dialog.belowBox()->isEnabled());
    EXPECT_EQ(dialog.belowValue()->text(), QLocale().toString(0.0, 'f', 3));
}

TEST_F(ExportGuiTest, CancelLeavesNoFileAndKeepsAnExistingOne) {
    ASSERT_TRUE(showTube());
    const fs::path pdf = dir_ / "existing.pdf";
    std::ofstream(pdf) << "the old report";
    gui::ReportDialog dialog(*window_->viewer(), window_->reportSource(), window_.get());
    dialog.pdfEdit()->setText(QString::fromStdString(pdf.string()));
    dialog.dicomScBox()->setChecked(true);
    const fs::path sc = dir_ / "existing-sc.dcm";
    auto outcome = std::make_shared<Outcome>();
    QObject::connect(&dialog, &gui::ReportDialog::exportStarted,
                     [outcome](gui::ExportWorker* worker) {
                         record(worker, outcome);
                         worker->cancel();  // at once, as a click on Cancel
                     });
    dialog.accept();
    QMessageBox* box = replaceBox(dialog);  // existing.pdf is there
    ASSERT_NE(box, nullptr) << "no question before replacing existing.pdf";
    answer(box, true);
    ASSERT_TRUE(waitUntil([&] { return outcome->finished; }, 120000));
    EXPECT_TRUE(outcome->cancelled);
    EXPECT_FALSE(outcome->succeeded);
    EXPECT_EQ(readAll(pdf), "the old report");
    EXPECT_FALSE(fs::exists(sc));
    EXPECT_EQ(report::test::listing(dir_), "existing.pdf ");
}

TEST_F(ExportGuiTest, ReportAsksBeforeReplacingAFileAndCancelKeepsItAndTheDialog) {
    ASSERT_TRUE(showTube());
    const fs::path pdf = dir_ / "report.pdf";
    const std::string earlier = "the report of the previous patient";
    const auto written = earlierFile(pdf, earlier);
    gui::ReportDialog dialog(*window_->viewer(), window_->reportSource(), window_.get());
    dialog.pdfEdit()->setText(QString::fromStdString(pdf.string()));
    dialog.show();
    bool started = false;
    QObject::connect(&dialog, &gui::ReportDialog::exportStarted, [&started] { started = true; });
    dialog.accept();
    QMessageBox* box = replaceBox(dialog);
    ASSERT_NE(box, nullptr) << "report.pdf was replaced without a question";
    EXPECT_EQ(box->text(), QStringLiteral("report.pdf already exists in %1. Replace it?")
                               .arg(QString::fromStdString(dir_.string())));
    EXPECT_EQ(box->windowModality(), Qt::WindowModal);
    EXPECT_EQ(static_cast<QAbstractButton*>(box->defaultButton()),
              box->button(QMessageBox::Cancel));
    answer(box, false);
    QCoreApplication::processEvents();
    EXPECT_FALSE(started);
    EXPECT_TRUE(dialog.isVisible());  // still open to choose another name
    EXPECT_EQ(readAll(pdf), earlier);
    EXPECT_EQ(fs::last_write_time(pdf), written);
    EXPECT_EQ(report::test::listing(dir_), "report.pdf ");
}

TEST_F(ExportGuiTest, ReportNamesEveryFileItWouldReplaceAndReplaceWritesThem) {
    ASSERT_TRUE(showTube());
    const fs::path pdf = dir_ / "report.pdf";
    const fs::path png = dir_ / "report.png";
    const auto pdfTime = earlierFile(pdf, "the earlier report");
    const auto pngTime = earlierFile(png, "the earlier image");
    gui::ReportDialog dialog(*window_->viewer(), window_->reportSource(), window_.get());
    dialog.pdfEdit()->setText(QString::fromStdString(pdf.string()));
    dialog.pngBox()->setChecked(true);      // report.png, beside the PDF
    dialog.dicomScBox()->setChecked(true);  // report-sc.dcm: new, not named
    auto outcome = std::make_shared<Outcome>();
    QObject::connect(&dialog, &gui::ReportDialog::exportStarted,
                     [outcome](gui::ExportWorker* worker) { record(worker, outcome); });
    dialog.accept();
    QMessageBox* box = replaceBox(dialog);
    ASSERT_NE(box, nullptr) << "two files were replaced without a question";
    EXPECT_EQ(box->text(),
              QStringLiteral("These files already exist:\n%1\n%2\nReplace them?")
                  .arg(QString::fromStdString(pdf.string()), QString::fromStdString(png.string())));
    answer(box, true);
    ASSERT_TRUE(waitUntil([&] { return outcome->finished; }, 120000)) << "no end of export";
    ASSERT_TRUE(outcome->succeeded) << outcome->message.toStdString();
    EXPECT_NE(fs::last_write_time(pdf), pdfTime);
    EXPECT_NE(fs::last_write_time(png), pngTime);
    std::string text;
    ASSERT_EQ(report::test::runTool("pdftotext -layout '" + pdf.string() + "' -", text), 0) << text;
    EXPECT_NE(text.find("Vessel tree report"), std::string::npos) << text;
    QImage image;
    EXPECT_TRUE(image.load(QString::fromStdString(png.string()), "PNG"));
    EXPECT_EQ(image.size(), gui::viewPixelSize(*window_->viewer()));
    EXPECT_EQ(report::test::listing(dir_), "report-sc.dcm report.pdf report.png ");
}

TEST_F(ExportGuiTest, ImageAsksBeforeReplacingAFileCancelKeepsItReplaceWritesIt) {
    ASSERT_TRUE(showTube());
    const fs::path png = dir_ / "vessels.png";
    const std::string earlier = "the image of the previous patient";
    const auto written = earlierFile(png, earlier);
    gui::ExportImageDialog dialog(*window_->viewer(), window_.get());
    // No suffix: ".png" is added, so vessels.png is what would be replaced.
    dialog.fileEdit()->setText(QString::fromStdString((dir_ / "vessels").string()));
    dialog.keepAspectBox()->setChecked(false);
    dialog.widthBox()->setValue(320);
    dialog.heightBox()->setValue(200);
    dialog.show();
    auto outcome = std::make_shared<Outcome>();
    bool started = false;
    QObject::connect(&dialog, &gui::ExportImageDialog::exportStarted,
                     [outcome, &started](gui::ExportWorker* worker) {
                         started = true;
                         record(worker, outcome);
                     });
    dialog.accept();
    QMessageBox* box = replaceBox(dialog);
    ASSERT_NE(box, nullptr) << "vessels.png was replaced without a question";
    EXPECT_EQ(box->text(), QStringLiteral("vessels.png already exists in %1. Replace it?")
                               .arg(QString::fromStdString(dir_.string())));
    answer(box, false);
    QCoreApplication::processEvents();
    EXPECT_FALSE(started);
    EXPECT_TRUE(dialog.isVisible());
    EXPECT_EQ(readAll(png), earlier);
    EXPECT_EQ(fs::last_write_time(png), written);

    dialog.accept();
    box = replaceBox(dialog);
    ASSERT_NE(box, nullptr) << "asked only once";
    answer(box, true);
    ASSERT_TRUE(waitUntil([&] { return outcome->finished; }, 120000)) << "no end of export";
    ASSERT_TRUE(outcome->succeeded) << outcome->message.toStdString();
    EXPECT_FALSE(dialog.isVisible());
    QImage image;
    ASSERT_TRUE(image.load(QString::fromStdString(png.string()), "PNG"));
    EXPECT_EQ(image.size(), QSize(320, 200));
    EXPECT_EQ(report::test::listing(dir_), "vessels.png ");
}

TEST_F(ExportGuiTest, TheDialogsProposeAFreeNameAndWriteItWithoutAQuestion) {
    ASSERT_TRUE(showTube());
    QSettings().setValue(QStringLiteral("export/folder"), QString::fromStdString(dir_.string()));
    const std::shared_ptr<void> restore(nullptr,
                                        [](void*) { QSettings().remove("export/folder"); });
    const auto proposed = [this](const char* name) {
        return QString::fromStdString((dir_ / name).string());
    };
    // An empty folder: the plain names.
    EXPECT_EQ(gui::ReportDialog(*window_->viewer(), window_->reportSource(), window_.get())
                  .pdfEdit()
                  ->text(),
              proposed("report.pdf"));
    EXPECT_EQ(gui::ExportImageDialog(*window_->viewer(), window_.get()).fileEdit()->text(),
              proposed("vessels.png"));

    // After earlier exports: the next free numbers, which replace nothing.
    const fs::path pdf = dir_ / "report.pdf";
    const auto pdfTime = earlierFile(pdf, "the earlier report");
    earlierFile(dir_ / "vessels.png", "the earlier image");
    earlierFile(dir_ / "vessels-2.png", "the image before");
    EXPECT_EQ(gui::ExportImageDialog(*window_->viewer(), window_.get()).fileEdit()->text(),
              proposed("vessels-3.png"));
    gui::ReportDialog dialog(*window_->viewer(), window_->reportSource(), window_.get());
    EXPECT_EQ(dialog.pdfEdit()->text(), proposed("report-2.pdf"));
    dialog.pngBox()->setChecked(true);
    EXPECT_EQ(dialog.pngEdit()->text(), proposed("report-2.png"));
    bool startedAtOnce = false;
    auto outcome = std::make_shared<Outcome>();
    QObject::connect(&dialog, &gui::ReportDialog::exportStarted,
                     [outcome, &startedAtOnce](gui::ExportWorker* worker) {
                         startedAtOnce = true;
                         record(worker, outcome);
                     });
    dialog.accept();
    EXPECT_TRUE(startedAtOnce) << "nothing to replace, yet no export";
    EXPECT_EQ(dialog.findChild<QMessageBox*>(QStringLiteral("replaceFilesBox")), nullptr);
    ASSERT_TRUE(waitUntil([&] { return outcome->finished; }, 120000)) << "no end of export";
    ASSERT_TRUE(outcome->succeeded) << outcome->message.toStdString();
    EXPECT_EQ(readAll(pdf), "the earlier report");
    EXPECT_EQ(fs::last_write_time(pdf), pdfTime);
    std::string info;
    EXPECT_EQ(report::test::runTool("pdfinfo '" + (dir_ / "report-2.pdf").string() + "'", info), 0)
        << info;
    EXPECT_EQ(report::test::listing(dir_),
              "report-2.pdf report-2.png report.pdf vessels-2.png vessels.png ");
}

TEST_F(ExportGuiTest, WorkerRendersWhileTheEventLoopRunsAndMatchesTheGuiThread) {
    ASSERT_TRUE(showTube());
    report::ViewExportOptions options;
    options.render = gui::currentViewOptions(*window_->viewer(), 1920, 1080);
    options.legends = false;
    const auto scene = window_->viewer()->scene();
    auto image = std::make_shared<QImage>();
    auto* worker = new gui::ExportWorker(
        QStringLiteral("test render"),
        [scene, options, image](render::OffscreenRenderer& renderer, const Progress&) {
            *image = report::renderView(renderer, *scene, options).image;
            return QString();
        },
        window_.get());
    auto outcome = std::make_shared<Outcome>();
    record(worker, outcome);
    // A timer on the GUI thread counts the times the event loop ran it while
    // the render had not finished: a render on the GUI thread would block
    // the loop from start() to its end, and no tick would fall in between.
    int ticksWhileRendering = 0;
    QTimer timer;
    QObject::connect(&timer, &QTimer::timeout,
                     [&] { ticksWhileRendering += outcome->finished ? 0 : 1; });
    timer.start(1);
    worker->start();
    ASSERT_TRUE(waitUntil([&] { return outcome->finished; }, 120000));
    timer.stop();
    delete worker;
    ASSERT_TRUE(outcome->succeeded) << outcome->message.toStdString();
    RecordProperty("timer_ticks", ticksWhileRendering);
    EXPECT_GE(ticksWhileRendering, 2) << "the GUI thread stood still while the view rendered";

    // The same view rendered on the GUI thread.
    render::OffscreenRenderer renderer;
    const QImage reference = report::renderView(renderer, *scene, options).image;
    ASSERT_EQ(image->size(), QSize(1920, 1080));
    EXPECT_LT(changedFraction(*image, reference), 0.001);
    QImage blank(image->size(), image->format());
    blank.fill(Qt::black);
    EXPECT_GT(changedFraction(*image, blank), 0.01);  // not an empty frame
}

}  // namespace
}  // namespace vv::test
