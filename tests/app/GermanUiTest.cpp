// SPDX-License-Identifier: GPL-3.0-or-later
// The GUI in German, as a user who picked Deutsch sees it: the German
// translators installed as the application installs them and German numbers
// (QLocale::setDefault). The test loads the demo and a DICOM series, hovers,
// opens every panel and dialog, runs an image export, and collects every text
// a person can read (VisibleTexts.h). It fails on
//  (a) a text (or a line, or a "…: …" part of one) that is an English source
//      string of translations/vesselview_de.ts whose German differs, and
//  (b) a '.' decimal separator in a number.
// It names each finding and where it was found. The progress stages the
// modules report (English keys, no Qt) must all have a German translation.
#include <gtest/gtest.h>

#include <QAbstractButton>
#include <QCheckBox>
#include <QDateEdit>
#include <QDir>
#include <QFile>
#include <QHelpEvent>
#include <QLibraryInfo>
#include <QLocale>
#include <QMessageBox>
#include <QPointer>
#include <QProgressDialog>
#include <QRegularExpression>
#include <QTextDocumentFragment>
#include <QTimer>
#include <QTranslator>
#include <QXmlStreamReader>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <mutex>
#include <optional>
#include <set>
#include <string>

#include "GuiFixture.h"
#include "VisibleTexts.h"
#include "gui/DocumentController.h"
#include "gui/EngineTexts.h"
#include "gui/ExportImageDialog.h"
#include "gui/ExportWorker.h"
#include "gui/ReportDialog.h"
#include "gui/SeriesDialog.h"
#include "gui/pacs/NetworkPreferencesDialog.h"
#include "gui/pacs/PacsBrowser.h"
#include "vv/core/Progress.h"
#include "vv/demo/DemoCtSeries.h"
#include "vv/demo/DemoTree.h"
#include "vv/dicom/Dicom.h"
#include "vv/dicom/SeriesWriter.h"
#include "vv/meshio/MeshLoader.h"
#include "vv/render/LegendPainter.h"
#include "vv/segmentation/SceneSource.h"
#include "vv/segmentation/SegmentationPipeline.h"
#include "vv/segmentation/VolumeSegmentation.h"

namespace vv::test {
namespace {

namespace fs = std::filesystem;

/// A text as it is compared: without mnemonic '&', a trailing "…" or ':'.
QString normalised(QString text) {
    static const QRegularExpression mnemonic(QStringLiteral("&(?!&)"));
    text.remove(mnemonic);
    text.replace(QStringLiteral("&&"), QStringLiteral("&"));
    text = text.trimmed();
    while (text.endsWith(QChar(0x2026)) || text.endsWith(QLatin1Char(':'))) {
        text.chop(1);
    }
    return text.trimmed();
}

/// The English sources of vesselview_de.ts whose German differs: exact texts,
/// and patterns for those with placeholders (%1, %n: any text) that hold at
/// least 8 letters of their own.
struct EnglishSources {
    std::set<QString> exact;
    std::vector<std::pair<QString, QRegularExpression>> patterns;

    [[nodiscard]] std::optional<QString> match(const QString& text) const {
        const QString n = normalised(text);
        if (exact.count(n) != 0) {
            return n;
        }
        for (const auto& [source, pattern] : patterns) {
            if (pattern.match(n).hasMatch()) {
                return source;
            }
        }
        return std::nullopt;
    }
};

EnglishSources readEnglishSources() {
    EnglishSources sources;
    QFile file(QStringLiteral(VV_SOURCE_DIR "/translations/vesselview_de.ts"));
    if (!file.open(QIODevice::ReadOnly)) {
        ADD_FAILURE() << "cannot open vesselview_de.ts";
        return sources;
    }
    static const QRegularExpression placeholder(QStringLiteral("%L?(\\d{1,2}|n)"));
    QXmlStreamReader xml(&file);
    QString source;
    QString translation;
    bool numerus = false;
    bool obsolete = false;
    std::set<QString> same;  // sources some message leaves as they are ("Export")
    while (!xml.atEnd()) {
        xml.readNext();
        if (xml.isStartElement()) {
            if (xml.name() == QLatin1String("message")) {
                source.clear();
                translation.clear();
                obsolete = false;
                numerus = xml.attributes().value(QLatin1String("numerus")) == QLatin1String("yes");
            } else if (xml.name() == QLatin1String("source")) {
                source = xml.readElementText();
            } else if (xml.name() == QLatin1String("translation")) {
                const auto type = xml.attributes().value(QLatin1String("type"));
                obsolete = type == QLatin1String("vanished") || type == QLatin1String("obsolete");
                if (!numerus) {
                    translation = xml.readElementText();
                }
            } else if (xml.name() == QLatin1String("numerusform") && translation.isEmpty()) {
                translation = xml.readElementText();
            }
        } else if (xml.isEndElement() && xml.name() == QLatin1String("message")) {
            const QString english = normalised(source);
            if (normalised(translation) == english) {
                same.insert(english);  // the same in both languages ("VSS", "mm", "Pa")
            }
            if (obsolete || english.isEmpty() || same.count(english) != 0) {
                continue;
            }
            if (!english.contains(placeholder)) {
                sources.exact.insert(english);
                continue;
            }
            QString literal = english;
            literal.remove(placeholder);
            if (literal.count(QRegularExpression(QStringLiteral("[A-Za-z]"))) < 8) {
                continue;  // "%1: %2" would match anything
            }
            QString regex;
            qsizetype at = 0;
            for (auto it = placeholder.globalMatch(english); it.hasNext();) {
                const auto m = it.next();
                regex += QRegularExpression::escape(english.mid(at, m.capturedStart() - at)) +
                         QStringLiteral(".*");
                at = m.capturedEnd();
            }
            regex += QRegularExpression::escape(english.mid(at));
            sources.patterns.emplace_back(
                english, QRegularExpression(QRegularExpression::anchoredPattern(regex),
                                            QRegularExpression::DotMatchesEverythingOption));
        }
    }
    EXPECT_FALSE(xml.hasError()) << xml.errorString().toStdString();
    for (const QString& english : same) {
        sources.exact.erase(english);
    }
    std::erase_if(sources.patterns,
                  [&same](const auto& pattern) { return same.count(pattern.first) != 0; });
    return sources;
}

/// The parts of `text` compared with the sources: the whole text, each line,
/// and each part of a line around ": " and "; " (status messages join them).
QStringList parts(const QString& text) {
    QStringList all{text};
    for (const QString& line : text.split(QLatin1Char('\n'), Qt::SkipEmptyParts)) {
        all << line;
        static const QRegularExpression joint(QStringLiteral(": |; |\\t"));
        const QStringList pieces = line.split(joint, Qt::SkipEmptyParts);
        if (pieces.size() > 1) {
            all << pieces;
        }
    }
    return all;
}

/// Numbers written with a '.' decimal separator in `text`, leaving out (the
/// only exclusions): dotted chains with two or more dots (versions "6.4.2",
/// UIDs), German thousands grouping ("12.345"; so "2.186" passes too: a
/// blind spot), numbers touching letters (names: "a1.5b", "scan-1.5.vtp"),
/// and version numbers right after a product name ("OpenGL 4.1", "DICOM 3.0").
QStringList decimalPoints(const QString& text) {
    static const QRegularExpression number(
        QStringLiteral("(?<![\\w.])(\\d+(?:\\.\\d+)+)(?![\\w.]*\\w)"));
    static const QRegularExpression grouped(QStringLiteral("^[1-9]\\d{0,2}(\\.\\d{3})+$"));
    static const QRegularExpression product(
        QStringLiteral("(OpenGL|GLSL|Mesa|LLVM|Qt|VTK|DCMTK|VesselView|DICOM|"
                       "[Vv]ersion)[ :]*$"));
    QStringList found;
    for (auto it = number.globalMatch(text); it.hasNext();) {
        const auto m = it.next();
        const QString n = m.captured(1);
        if (n.count(QLatin1Char('.')) != 1 || grouped.match(n).hasMatch()) {
            continue;
        }
        if (product.match(text.left(m.capturedStart())).hasMatch()) {
            continue;
        }
        found << n;
    }
    return found;
}

/// The German translators installGerman() installed.
std::vector<QTranslator*>& germanTranslators() {
    static std::vector<QTranslator*> translators;
    return translators;
}

/// Installs the German translators as Translations.cpp does for a user who
/// picked Deutsch (ours and Qt's) and makes German the default locale.
void installGerman() {
    auto* own = new QTranslator(QCoreApplication::instance());
    germanTranslators().push_back(own);
    ASSERT_TRUE(own->load(QStringLiteral("vesselview_de"), QStringLiteral(VV_QM_DIR)));
    QCoreApplication::installTranslator(own);
    auto* qt = new QTranslator(QCoreApplication::instance());
    if (qt->load(QLocale(QLocale::German), QStringLiteral("qtbase"), QStringLiteral("_"),
                 QLibraryInfo::path(QLibraryInfo::TranslationsPath))) {
        QCoreApplication::installTranslator(qt);
        germanTranslators().push_back(qt);
    }
    QLocale::setDefault(QLocale(QLocale::German, QLocale::Germany));
}

/// `make()`'s result with the GUI in English (no translators, the C locale).
template <typename Make>
auto inEnglish(const Make& make) {
    for (QTranslator* t : germanTranslators()) {
        QCoreApplication::removeTranslator(t);
    }
    QLocale::setDefault(QLocale::c());
    auto result = make();
    for (QTranslator* t : germanTranslators()) {
        QCoreApplication::installTranslator(t);
    }
    QLocale::setDefault(QLocale(QLocale::German, QLocale::Germany));
    return result;
}

QString toQString(const std::string& text) {
    return QString::fromStdString(text);
}
[[maybe_unused]] QString toQString(const QString& text) {
    return text;
}

fs::path dicomDir() {
    return panelTestDir() / "german-dicom";
}

class GermanUiTest : public GuiFixture {
  protected:
    static void SetUpTestSuite() {
        qputenv("VV_DEMO_FILE", VV_DEMO_VTP);  // File > Open Demo opens the bundled tree
        GuiFixture::SetUpTestSuite();
        installGerman();
        fs::remove_all(dicomDir());
        demo::DemoCtOptions options;
        options.dims = {48, 48, 32};
        options.generations = 3;
        const demo::DemoCt cta = demo::generateDemoCt(options);
        dicom::CtSeriesWriteOptions write;
        write.seriesDescription = "demo CTA";
        dicom::writeCtSeries(dicomDir() / "series", cta.volume, write);
    }
    static void TearDownTestSuite() {
        std::error_code ec;
        fs::remove_all(dicomDir(), ec);
        GuiFixture::TearDownTestSuite();
    }

    /// Records what the status bar shows while the document loads.
    void watchLoading() {
        auto* doc = window_->document();
        QObject::connect(doc, &gui::DocumentController::loadStarted, window_.get(),
                         [this](const QString& text) {
                             texts_.add(QStringLiteral("status bar (loading)"), text);
                         });
        QObject::connect(doc, &gui::DocumentController::loadProgress, window_.get(),
                         [this](double, const QString& text) {
                             texts_.add(QStringLiteral("status bar (progress)"), text);
                         });
    }

    /// Collects the window with each dock (panel) raised in turn.
    void collectPanels() {
        for (QDockWidget* dock : window_->findChildren<QDockWidget*>()) {
            dock->show();
            dock->raise();
            QCoreApplication::processEvents();
            texts_.collect(window_.get());
        }
        texts_.collect(window_.get());
    }

    /// Runs `open`, then collects the modal window it opens and closes it.
    void collectModal(const std::function<void()>& open) {
        bool seen = false;
        QTimer::singleShot(200, window_.get(), [this, &seen] {
            if (QWidget* modal = QApplication::activeModalWidget()) {
                texts_.collect(modal);
                seen = true;
                modal->close();
            }
        });
        open();
        waitUntil([&] { return seen; }, 5000);
        EXPECT_TRUE(seen) << "no modal window opened";
    }

    /// The hover probe's tool tip at the centre of the view.
    /// The points of a grid over the view that hit a vessel.
    [[nodiscard]] std::vector<QPoint> vesselPoints() const {
        auto* viewer = window_->viewer();
        std::vector<QPoint> points;
        for (int y = 1; y < 16; ++y) {
            for (int x = 1; x < 16; ++x) {
                const QPoint p(viewer->width() * x / 16, viewer->height() * y / 16);
                if (viewer->probeAt(p)) {
                    points.push_back(p);
                }
            }
        }
        return points;
    }

    /// The hover probe over a vessel, then a measurement between two vessel
    /// points (the status bar's measure label).
    void hoverAndMeasure() {
        auto* viewer = window_->viewer();
        viewer->setHoverProbe(true);
        const std::vector<QPoint> points = vesselPoints();
        ASSERT_GE(points.size(), 2U) << "too few vessels in the view to hover and measure";
        const QPoint at = points.front();
        QHelpEvent help(QEvent::ToolTip, at, viewer->mapToGlobal(at));
        QCoreApplication::sendEvent(viewer, &help);
        QCoreApplication::processEvents();
        bool shown = false;
        for (const QWidget* top : QApplication::topLevelWidgets()) {
            shown = shown || (top->inherits("QTipLabel") && top->isVisible());
        }
        EXPECT_TRUE(shown) << "the hover probe shows no tool tip";
        texts_.collectTopLevels();
        window_->addMeasurePoint(*viewer->probeAt(at));
        window_->addMeasurePoint(*viewer->probeAt(points.back()));
        QCoreApplication::processEvents();
        texts_.collect(window_.get());
        window_->clearMeasurement();
    }

    /// Exports the view as a small PNG through File > Export Image, collecting
    /// the dialog and the progress dialog while it runs.
    void exportImage() {
        window_->exportImageAction()->trigger();
        auto* dialog = window_->findChild<gui::ExportImageDialog*>();
        ASSERT_NE(dialog, nullptr);
        texts_.collect(dialog);
        const QString file =
            QString::fromStdString((panelTestDir() / "german-export.png").string());
        dialog->fileEdit()->setText(file);
        dialog->keepAspectBox()->setChecked(false);
        dialog->widthBox()->setValue(640);
        dialog->heightBox()->setValue(400);
        runExport(*dialog);

        // Once more to the same file: the question before it is replaced.
        gui::ExportImageDialog again(*window_->viewer(), window_.get());
        again.fileEdit()->setText(file);  // the dialog above is gone
        again.show();
        again.accept();
        QMessageBox* box = nullptr;
        ASSERT_TRUE(waitUntil([&] {
            box = again.findChild<QMessageBox*>(QStringLiteral("replaceFilesBox"));
            return box != nullptr && box->isVisible();
        })) << "no question before replacing german-export.png";
        EXPECT_TRUE(box->text().startsWith(QStringLiteral("german-export.png ")))
            << box->text().toStdString();
        texts_.collect(box);
        box->button(QMessageBox::Cancel)->click();
    }

    /// Starts `dialog`'s export and collects what shows until it ends.
    void runExport(gui::ExportDialog& dialog) {
        bool finished = false;
        QObject::connect(&dialog, &gui::ExportDialog::exportStarted, window_.get(),
                         [&finished](gui::ExportWorker* worker) {
                             QObject::connect(worker, &gui::ExportWorker::finished,
                                              [&finished] { finished = true; });
                         });
        dialog.accept();
        EXPECT_TRUE(waitUntil(
            [&] {
                texts_.collectTopLevels();
                return finished;
            },
            180000));
        QCoreApplication::processEvents();
        texts_.collect(window_.get());  // the status bar's "Exported …"
    }

    /// File > Export Report: the dialog, then a PDF export.
    void exportReport() {
        window_->exportReportAction()->trigger();
        auto* dialog = window_->findChild<gui::ReportDialog*>();
        ASSERT_NE(dialog, nullptr) << "no report dialog";
        texts_.collect(dialog);
        dialog->pdfEdit()->setText(
            QString::fromStdString((panelTestDir() / "german-report.pdf").string()));
        runExport(*dialog);
    }

    /// The Display panel's performance overlay over a new frame.
    void performanceOverlay() {
        auto* box = window_->findChild<QCheckBox*>(QStringLiteral("displayPerformance"));
        ASSERT_NE(box, nullptr);
        box->setChecked(true);
        const quint64 frames = window_->viewer()->framesWithScene();
        window_->viewer()->resetCamera();
        ASSERT_TRUE(waitForFrames(frames + 1));
        QCoreApplication::processEvents();
        texts_.collect(window_.get());
        box->setChecked(false);
    }

    VisibleTexts texts_;
};

TEST_F(GermanUiTest, EveryVisibleTextIsGermanWithGermanNumbers) {
    ASSERT_EQ(QLocale().decimalPoint(), QStringLiteral(","));
    ASSERT_EQ(QCoreApplication::translate("vv::gui::MainWindow", "&File"), QStringLiteral("&Datei"))
        << "the German translation is not installed";
    watchLoading();
    texts_.collectMenus(*window_->menuBar());
    collectPanels();  // nothing loaded

    // A DICOM series: the chooser, loading, segmentation, the Segmentation panel.
    QPointer<gui::SeriesDialog> series;
    QObject::connect(window_.get(), &gui::MainWindow::seriesDialogShown, window_.get(),
                     [&series](gui::SeriesDialog* d) { series = d; });
    window_->openDicom(QString::fromStdString((dicomDir() / "series").string()));
    ASSERT_TRUE(waitUntil([&] { return !series.isNull() || !window_->lastError().isEmpty(); }))
        << "no series dialog";
    ASSERT_FALSE(series.isNull()) << window_->lastError().toStdString();
    QCoreApplication::processEvents();
    texts_.collect(series.data());
    series->accept();
    ASSERT_TRUE(waitUntil([&] { return !window_->isLoading() && window_->volume() != nullptr; }))
        << window_->lastError().toStdString();
    ASSERT_TRUE(waitForFrames(1));
    // The engine's English rule for the volume's default threshold (shown by
    // the Segmentation panel) is English the GUI must not show as is.
    const QString engineRule =
        QString::fromStdString(segmentation::defaultThresholdRange(*window_->volume()).rule);
    ASSERT_TRUE(waitUntil([&] {
        const auto* label = window_->findChild<QLabel*>(QStringLiteral("thresholdDefaultLabel"));
        return label != nullptr && !label->toolTip().isEmpty();
    }));
    collectPanels();

    // The demo: loading, the panels with an array shown, hover, the dialogs.
    window_->openDemo();
    ASSERT_TRUE(waitUntil([&] { return window_->isLoading(); }, 5000) ||
                !window_->shownFiles().isEmpty());
    ASSERT_TRUE(waitUntil([&] { return !window_->isLoading(); }, 60000));
    ASSERT_TRUE(window_->lastError().isEmpty()) << window_->lastError().toStdString();
    ASSERT_TRUE(waitForFrames(2));
    (void)waitForVss(60000);
    collectPanels();
    hoverAndMeasure();
    exportImage();

    exportReport();
    performanceOverlay();
    const auto help = window_->menuBar()->actions().last()->menu()->actions();
    for (QAction* action : help) {
        if (action->objectName().isEmpty() && action->shortcut().isEmpty() &&
            !action->isSeparator()) {
            collectModal([action] { action->trigger(); });  // Help > About
        }
    }
    texts_.add(QStringLiteral("Help > Keyboard Shortcuts"),
               QTextDocumentFragment::fromHtml(window_->shortcutSummary()).toPlainText());
    // An error message: a file that does not exist.
    window_->openFiles({QString::fromStdString((panelTestDir() / "missing.vtp").string())});
    ASSERT_TRUE(waitUntil([&] { return !window_->lastError().isEmpty(); }));
    // What happened, in German (the module's English detail is in the box's Details).
    EXPECT_TRUE(window_->lastError().contains(QStringLiteral("konnte nicht gelesen werden")))
        << window_->lastError().toStdString();
    QCoreApplication::processEvents();
    texts_.collectTopLevels();

    EnglishSources english = readEnglishSources();
    ASSERT_GT(english.exact.size(), 100U);
    english.exact.insert(normalised(engineRule));
    int englishCount = 0;
    int decimalCount = 0;
    for (const VisibleText& t : texts_.texts()) {
        for (const QString& part : parts(t.text)) {
            if (const auto source = english.match(part)) {
                ++englishCount;
                ADD_FAILURE() << "English in the German GUI: \"" << part.toStdString()
                              << "\" (source \"" << source->toStdString() << "\") at "
                              << t.where.toStdString();
                break;
            }
        }
        for (const QString& n : decimalPoints(t.text)) {
            ++decimalCount;
            ADD_FAILURE() << "'.' decimal separator in \"" << n.toStdString() << "\" in \""
                          << t.text.toStdString() << "\" at " << t.where.toStdString();
        }
    }
    EXPECT_EQ(englishCount, 0);
    EXPECT_EQ(decimalCount, 0);
    EXPECT_GT(texts_.texts().size(), 200U) << "suspiciously few texts collected";
    if (qEnvironmentVariableIsSet("VV_DUMP_TEXTS")) {
        for (const VisibleText& t : texts_.texts()) {
            std::cout << t.where.toStdString() << " | " << t.text.toStdString() << "\n";
        }
    }
}

/// The modules' progress stages as the loaders, the demo, DICOM and the
/// segmentation report them: each known to the GUI, and German.
TEST_F(GermanUiTest, ProgressStagesOfTheModulesAreGerman) {
    std::mutex lock;
    std::set<std::string> stages;
    const Progress progress(
        [&](double, std::string_view stage) {
            const std::lock_guard guard(lock);
            stages.insert(std::string(stage));
        },
        std::stop_token{});
    (void)meshio::loadScene({fs::path(VV_DEMO_VTP)}, {}, progress);
    const dicom::DicomScanResult scan = dicom::scanDicom(dicomDir() / "series", progress);
    ASSERT_FALSE(scan.allSeries().empty());
    segmentation::SceneSourceOptions options;
    segmentation::SceneSourceReport loaded;
    (void)segmentation::loadSceneSource(dicomDir() / "series", options, progress, &loaded);
    // The MR path too: its intensity correction's stages (issue 30).
    ASSERT_NE(loaded.volume, nullptr);
    auto mr = std::make_shared<scene::Volume>(*loaded.volume);
    mr->setModality("MR");
    mr->setUnit("");
    segmentation::SegmentationRequest request;
    request.volume = mr;
    (void)segmentation::runSegmentation(request, progress);
    demo::DemoTreeOptions small;
    small.generations = 2;
    (void)demo::generateDemoMesh(small, progress);
    stages.erase(std::string());
    ASSERT_GT(stages.size(), 5U);
    for (const std::string& stage : stages) {
        const QString key = QString::fromStdString(stage);
        EXPECT_TRUE(gui::isKnownStage(key)) << "a progress stage without translation: " << stage;
        EXPECT_NE(gui::translatedStage(key), key) << "not German: " << stage;
        // Not a file stage's pattern around English words ("the … wird geprüft").
        EXPECT_FALSE(gui::translatedStage(key).contains(QStringLiteral("the ")))
            << "half English: " << gui::translatedStage(key).toStdString();
    }
}

/// Dates are typed as they are shown: the report's patient fields take
/// 17.05.1960 (and ISO, and 17.5.1960), ask for TT.MM.JJJJ and name that form
/// when a date is wrong; the PACS query's date fields show four-digit years.
TEST_F(GermanUiTest, DateFieldsTakeTheGermanFormat) {
    window_->openFiles({QStringLiteral(VV_DEMO_VTP)});
    ASSERT_TRUE(waitUntil([&] { return window_->viewer()->scene() != nullptr; }, 60000));
    gui::ReportDialog dialog(*window_->viewer(), window_->reportSource(), window_.get());
    dialog.patientGroup()->setChecked(true);
    EXPECT_EQ(dialog.birthDateEdit()->placeholderText(), QStringLiteral("TT.MM.JJJJ"));
    EXPECT_EQ(dialog.studyDateEdit()->placeholderText(), QStringLiteral("TT.MM.JJJJ"));
    for (const char* typed : {"17.05.1960", "17.5.1960", " 1960-05-17 ", "19600517"}) {
        dialog.birthDateEdit()->setText(QString::fromLatin1(typed));
        EXPECT_TRUE(dialog.problem().isEmpty()) << typed << ": " << dialog.problem().toStdString();
        const auto job = dialog.jobOptions();
        ASSERT_TRUE(job.patient.has_value());
        EXPECT_EQ(job.patient->birthDate, "19600517") << typed;
    }
    dialog.birthDateEdit()->setText(QStringLiteral("31.02.1960"));
    const QString problem = dialog.problem();
    EXPECT_TRUE(problem.contains(QStringLiteral("31.02.1960"))) << problem.toStdString();
    EXPECT_TRUE(problem.contains(QStringLiteral("TT.MM.JJJJ"))) << problem.toStdString();
    EXPECT_TRUE(problem.contains(QStringLiteral("17.05.1960"))) << problem.toStdString();
    EXPECT_FALSE(problem.contains(QStringLiteral("YYYY"))) << problem.toStdString();
    EXPECT_FALSE(problem.contains(QStringLiteral("JJJJ-MM-TT"))) << problem.toStdString();

    gui::PacsBrowser browser(window_.get());
    auto* from = browser.findChild<QDateEdit*>(QStringLiteral("queryDateFrom"));
    ASSERT_NE(from, nullptr);
    EXPECT_EQ(from->displayFormat(), QStringLiteral("dd.MM.yyyy"));
    from->setDate(QDate(1960, 5, 17));
    EXPECT_EQ(from->text(), QStringLiteral("17.05.1960"));
}

/// An error in German: the kind of problem and the file in German as the
/// message, the module's own (English) words only in its Details part.
TEST_F(GermanUiTest, ErrorMessagesAreGermanWithTheDetailApart) {
    const fs::path broken = panelTestDir() / "kaputt.stl";
    {
        std::ofstream out(broken, std::ios::binary);
        out << "solid broken\nfacet normal 0 0 1\nouter loop\nvertex 0 0\n";
    }
    window_->openFiles({QString::fromStdString(broken.string())});
    QMessageBox* box = nullptr;
    ASSERT_TRUE(waitUntil([&] {
        box = window_->findChild<QMessageBox*>(QStringLiteral("errorMessageBox"));
        return box != nullptr;
    }));
    const QString text = box->text();
    const QString details = box->detailedText();
    EXPECT_TRUE(text.contains(QStringLiteral("kaputt.stl"))) << text.toStdString();
    ASSERT_FALSE(details.isEmpty()) << "no Details part";
    EXPECT_TRUE(details.contains(QStringLiteral("kaputt.stl"))) << details.toStdString();
    // No word of the module's English text in the German message (but the path).
    QString withoutPath = text;
    withoutPath.remove(QString::fromStdString(broken.string()));
    static const QRegularExpression word(QStringLiteral("[A-Za-z]{4,}"));
    QString detailWords = details;
    detailWords.remove(QString::fromStdString(broken.string()));
    for (auto it = word.globalMatch(detailWords); it.hasNext();) {
        const QString english = it.next().captured();
        EXPECT_FALSE(withoutPath.contains(english, Qt::CaseInsensitive))
            << "English \"" << english.toStdString()
            << "\" in the German message: " << text.toStdString();
    }
    EXPECT_FALSE(window_->lastError().contains(details))
        << "the status line carries the English detail: " << window_->lastError().toStdString();
    box->close();
}

/// DICOM > Preferences refusing settings it cannot save (two nodes of one
/// name, a node with an invalid AE title): the message names the setting in
/// German, the English detail of the settings module only in the message's
/// tooltip (it read "Nicht gespeichert: two nodes are called 'Radiologie'").
TEST_F(GermanUiTest, NetworkPreferencesRefuseInGermanWithTheDetailApart) {
    gui::PacsNode node;
    node.name = "Radiologie";
    node.node.aeTitle = "RADPACS";
    node.node.host = "10.1.2.3";
    node.node.port = 104;
    gui::PacsNode badAe = node;
    badAe.name = "Kardiologie";
    badAe.node.aeTitle = "BAD\\AE";
    static const QRegularExpression word(QStringLiteral("[A-Za-z]{4,}"));
    for (const gui::PacsNode& second : {node, badAe}) {
        const QString name = QString::fromStdString(second.name);
        const auto refused = [&] {
            gui::NetworkPreferencesDialog dialog(window_.get());
            dialog.storeFolderEdit()->setText(
                QString::fromStdString((panelTestDir() / "store").string()));
            dialog.addNode(node);
            dialog.addNode(second);
            dialog.accept();
            EXPECT_NE(dialog.result(), QDialog::Accepted) << "saved";
            return QStringList{dialog.error(), dialog.errorDetails()};
        };
        const QStringList german = refused();
        const QStringList english = inEnglish(refused);
        const QString& text = german.at(0);
        const QString& details = german.at(1);
        EXPECT_TRUE(text.contains(name)) << text.toStdString();
        EXPECT_NE(text, english.at(0)) << "the message is English in German";
        ASSERT_FALSE(details.isEmpty()) << "no detail";
        EXPECT_TRUE(details.contains(name)) << details.toStdString();
        // No word of the module's English text in the German message (but the node's name).
        QString detailWords = details;
        detailWords.remove(name);
        for (auto it = word.globalMatch(detailWords); it.hasNext();) {
            const QString englishWord = it.next().captured();
            EXPECT_FALSE(text.contains(englishWord, Qt::CaseInsensitive))
                << "English \"" << englishWord.toStdString()
                << "\" in the German message: " << text.toStdString();
        }
    }
}

/// The legends are painted on the view (no widget to read): their text
/// functions, called with the GUI in German, give German titles and ticks.
TEST_F(GermanUiTest, LegendTextsAreGerman) {
    const auto ticks = [] {
        QStringList labels;
        for (const auto& tick : render::legendTicks(0.0, 0.45)) {
            labels << toQString(tick.label);
        }
        for (const auto& tick : render::depthLegendTicks({.dmin = 10.0, .dmax = 87.5})) {
            labels << toQString(tick.label);
        }
        return labels;
    };
    for (const QString& label : ticks()) {
        EXPECT_TRUE(decimalPoints(label).isEmpty())
            << "'.' decimal separator in the legend tick \"" << label.toStdString() << "\"";
    }
    render::DepthLegend depth;
    depth.unit = "mm";
    render::DepthLegend distance = depth;
    distance.reference = render::DepthReference::Camera;
    const auto title = [&depth, &distance] {
        return QStringList{toQString(render::depthLegendTitle(depth)),
                           toQString(render::depthLegendTitle(distance)),
                           render::depthQuantityName(render::DepthReference::FrontmostVessel),
                           render::depthQuantityName(render::DepthReference::Camera)};
    };
    const QStringList english = inEnglish(title);
    const QStringList german = title();
    ASSERT_EQ(german.size(), english.size());
    for (qsizetype i = 0; i < german.size(); ++i) {
        EXPECT_TRUE(german[i] != english[i])
            << "the depth legend title is English in German: " << german[i].toStdString();
    }
}

}  // namespace
}  // namespace vv::test
