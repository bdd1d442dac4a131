// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/MainWindow.h"

#include <QAction>
#include <QCloseEvent>
#include <QComboBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QGuiApplication>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QScreen>
#include <QSettings>
#include <QStackedWidget>
#include <QStatusBar>
#include <QTimer>
#include <QToolBar>
#include <QUrl>
#include <cmath>
#include <utility>

#include "gui/DocumentController.h"
#include "gui/ElidingLabel.h"
#include "gui/ExportImageDialog.h"
#include "gui/ExportSurfaceDialog.h"
#include "gui/HelpTexts.h"
#include "gui/LanguageMenu.h"
#include "gui/MeasureTool.h"
#include "gui/RecentFiles.h"
#include "gui/ReportDialog.h"
#include "gui/ScreenshotMode.h"
#include "gui/SeriesDialog.h"
#include "gui/ViewSettings.h"
#include "gui/ViewerWidget.h"
#include "gui/analysis/PlanningDocks.h"
#include "gui/analysis/PlanningState.h"
#include "gui/pacs/DicomMenu.h"
#include "gui/pacs/LocalStudyActions.h"
#include "gui/panels/AnalysisPanel.h"
#include "gui/panels/CollapsibleSection.h"
#include "gui/panels/DataPanel.h"
#include "gui/panels/DisplayPanel.h"
#include "gui/panels/FunctionalPanel.h"
#include "gui/panels/PanelUtil.h"
#include "gui/panels/SegmentationPanel.h"
#include "gui/panels/SidePanel.h"
#include "gui/panels/VssPanel.h"
#include "gui/study/StudyAnalysisDialog.h"
#include "gui/study/StudyRunDialog.h"
#include "vv/render/MeshStyle.h"

namespace vv::gui {

namespace {

const char* const kGeometryKey = "mainWindow/geometry";
const char* const kLayoutKey = "mainWindow/layout";
/// Bump when the docks change so that an old saved layout is not applied
/// (2: one side panel with sections instead of five tabbed docks).
constexpr int kLayoutVersion = 2;

/// The local files and folders of a drag.
QStringList localPaths(const QMimeData* mime) {
    QStringList paths;
    if (mime == nullptr || !mime->hasUrls()) {
        return paths;
    }
    for (const QUrl& url : mime->urls()) {
        if (url.isLocalFile()) {
            paths << url.toLocalFile();
        }
    }
    return paths;
}

}  // namespace

MainWindow::FirstGeometry MainWindow::firstGeometry(const QSize& available) {
    const QSize preferred(1280, 800);
    if (!available.isValid()) {
        return {preferred, false};
    }
    const QSize room = available - kFrameAllowance;
    const bool fits = room.width() >= preferred.width() && room.height() >= preferred.height();
    return {preferred.boundedTo(room.expandedTo(QSize(1, 1))), !fits};
}

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
    setWindowTitle(QStringLiteral("VesselView"));
    setAcceptDrops(true);

    document_ = new DocumentController(this);
    stack_ = new QStackedWidget(this);
    glMessage_ = new QLabel(stack_);
    glMessage_->setAlignment(Qt::AlignCenter);
    glMessage_->setWordWrap(true);
    glMessage_->setMargin(32);
    // Without OpenGL 4.1 the viewer stays out of the window (Qt cannot even
    // compose a window holding a QOpenGLWidget on a platform without GL); it
    // still exists, unparented and hidden, so the rest of the window works.
    const QString glProblem = ViewerWidget::probeOpenGl();
    if (glProblem.isEmpty()) {
        viewer_ = new ViewerWidget(stack_);
        slices_ = new SliceWorkspace(viewer_, stack_);
    } else {
        viewer_ = new ViewerWidget(nullptr);
        detachedViewer_.reset(viewer_);
        slices_ = new SliceWorkspace(nullptr, stack_);  // slice views need no OpenGL
    }
    stack_->addWidget(slices_);
    stack_->addWidget(glMessage_);
    setCentralWidget(stack_);

    connect(viewer_, &ViewerWidget::renderFailed, this, [this](const QString& message) {
        glMessage_->setText(message);
        stack_->setCurrentWidget(glMessage_);
        statusLabel_->setText(tr("OpenGL 4.1 is not available"));
        if (screenshot_ != nullptr) {
            screenshot_->fail(message);
        }
    });
    // Queued: grabbing the frame from inside paintGL would re-enter it.
    connect(viewer_, &ViewerWidget::frameRendered, this, &MainWindow::onFrameRendered,
            Qt::QueuedConnection);

    buildDocks();
    buildToolBar();
    buildMenus();
    buildStatusBar();
    connectDocument();
    defaultLayout_ = saveState(kLayoutVersion);
    const QSettings settings;
    if (!restoreGeometry(settings.value(QLatin1String(kGeometryKey)).toByteArray())) {
        const QScreen* screen = QGuiApplication::primaryScreen();
        const FirstGeometry first =
            firstGeometry(screen != nullptr ? screen->availableGeometry().size() : QSize());
        resize(first.size);
        if (first.maximized) {
            setWindowState(windowState() | Qt::WindowMaximized);
        }
    }
    restoreState(settings.value(QLatin1String(kLayoutKey)).toByteArray(), kLayoutVersion);
    restoreViewSettings(*viewer_, settings);
    syncControls();
    if (!glProblem.isEmpty()) {
        viewer_->setUnavailable(glProblem);  // renderFailed() shows the message
    }
}

MainWindow::~MainWindow() {
    // The document outlives the widgets it would talk to: it talks no more.
    disconnect(document_, nullptr, this, nullptr);
    document_->cancelLoad();
}

void MainWindow::connectDocument() {
    connect(document_, &DocumentController::loadStarted, this, [this](const QString& description) {
        statusLabel_->setText(description + QStringLiteral("…"));
        progressBar_->setValue(0);
        progressBar_->show();
        cancelButton_->show();
    });
    connect(document_, &DocumentController::loadProgress, this,
            [this](double fraction, const QString& status) {
                progressBar_->setValue(static_cast<int>(fraction * 1000.0));
                if (!status.isEmpty()) {
                    statusLabel_->setText(status);
                }
            });
    connect(document_, &DocumentController::loadEnded, this, [this] {
        progressBar_->hide();
        cancelButton_->hide();
    });
    connect(document_, &DocumentController::loadCancelled, this, [this] {
        statusLabel_->setText(tr("Cancelled"));
        if (screenshot_ != nullptr) {
            screenshot_->fail(tr("loading was cancelled"));
        }
    });
    connect(document_, &DocumentController::failed, this, &MainWindow::showError);
    connect(document_, &DocumentController::seriesScanned, this, &MainWindow::chooseSeries);
    connect(document_, &DocumentController::sceneChanged, this, &MainWindow::showScene);
    connect(document_, &DocumentController::sessionReady, this, [this](const Session& session) {
        applySession(*viewer_, session);
        if (session.measurement) {
            measure_->restore(*session.measurement);  // after the camera: the depth in its view
        }
        if (!session.layout.isEmpty()) {
            restoreState(session.layout, kLayoutVersion);
        }
        if (session.slices) {
            // The volume follows the scene: the slice views once it is there
            // (before sessionApplied, which is queued after this).
            QTimer::singleShot(
                0, slices_, [this, state = *session.slices] { slices_->applySessionState(state); });
        }
        if (session.planning) {
            // The centrelines are found again from the scene now shown.
            QTimer::singleShot(0, analysisPanel_, [this, state = *session.planning] {
                analysisPanel_->restoreSession(state);
            });
        }
    });
    connect(document_, &DocumentController::sceneShown, this, &MainWindow::sceneWasShown);
    connect(document_, &DocumentController::sessionApplied, this, &MainWindow::sessionApplied);
    connect(document_, &DocumentController::volumeChanged, this,
            [this](const std::shared_ptr<const scene::Volume>& volume,
                   const segmentation::SceneSourceOptions& loadedWith,
                   const segmentation::ThresholdRange& range) {
                segmentationPanel_->setVolume(volume, loadedWith.segmentation, range,
                                              loadedWith.surface);
                placeSegmentationSection(volume != nullptr);
                segmentationPanel_->showCutOff(document_->loadedReport().cutOff,
                                               document_->loadedReport().intensityCorrected);
                slices_->setVolume(volume, document_->labelMap());
                planningDocks_->setVolume(volume);
            });
    connect(document_, &DocumentController::recentFilesChanged, this,
            &MainWindow::rebuildRecentMenu);
}

void MainWindow::buildMenus() {
    buildFileMenu();
    buildViewMenu();

    dicomMenu_ = new DicomMenu(this);  // network preferences, PACS browser
    menuBar()->addMenu(dicomMenu_);
    listener_ = addLocalStudyActions(*this, *dicomMenu_);  // listener, Local Studies, Send

    // The depth-judgement study: its runner (the stimuli come from
    // `vesselview-cli study make`; the analysis is `study analyse`'s).
    QMenu* studyMenu = menuBar()->addMenu(tr("&Study"));
    studyMenu->addAction(tr("&Run Study…"), this, [this] {
        auto* dialog = new StudyRunDialog(this);
        dialog->setAttribute(Qt::WA_DeleteOnClose);
        dialog->open();
    });
    studyMenu->addAction(tr("&Analyse Results…"), this, [this] {
        auto* dialog = new StudyAnalysisDialog(this);
        dialog->setAttribute(Qt::WA_DeleteOnClose);
        dialog->open();
    });

    QMenu* help = menuBar()->addMenu(tr("&Help"));
    QAction* keys = help->addAction(tr("&Keyboard Shortcuts"), this, &MainWindow::showShortcuts);
    keys->setShortcut(QKeySequence::HelpContents);
    help->addAction(tr("&About VesselView"), this, &MainWindow::showAbout);
}

void MainWindow::buildFileMenu() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    QAction* open = file->addAction(tr("&Open…"), this, [this] {
        const QStringList files = QFileDialog::getOpenFileNames(this, tr("Open vessel meshes"),
                                                                QString(), meshFileFilter());
        if (!files.isEmpty()) {
            openFiles(files);
        }
    });
    open->setShortcut(QKeySequence::Open);
    QAction* openFolder = file->addAction(tr("Open &Folder…"), this, [this] {
        const QString folder = QFileDialog::getExistingDirectory(this, tr("Open DICOM folder"));
        if (!folder.isEmpty()) {
            openDicom(folder);
        }
    });
    openFolder->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_O));
    file->addAction(tr("Open &Demo"), this, &MainWindow::openDemo);
    recentMenu_ = file->addMenu(tr("Open &Recent"));
    rebuildRecentMenu();
    file->addSeparator();
    QAction* openSessionAction = file->addAction(tr("Open &Session…"), this, [this] {
        const QString path = QFileDialog::getOpenFileName(this, tr("Open session"), QString(),
                                                          tr("VesselView sessions (*.vvs)"));
        if (!path.isEmpty()) {
            openSession(path);
        }
    });
    openSessionAction->setObjectName(QStringLiteral("openSession"));
    QAction* saveSessionAction = file->addAction(tr("Save Session &As…"), this, [this] {
        QString path = QFileDialog::getSaveFileName(this, tr("Save session"), QString(),
                                                    tr("VesselView sessions (*.vvs)"));
        if (path.isEmpty()) {
            return;
        }
        if (QFileInfo(path).suffix().isEmpty()) {
            path += QStringLiteral(".vvs");
        }
        saveSessionTo(path);
    });
    saveSessionAction->setObjectName(QStringLiteral("saveSession"));
    saveSessionAction->setShortcut(QKeySequence::Save);
    file->addSeparator();
    exportImageAction_ = file->addAction(tr("&Export Image…"), this, [this] {
        auto* dialog = new ExportImageDialog(*viewer_, this);
        dialog->setAttribute(Qt::WA_DeleteOnClose);
        dialog->open();
    });
    exportImageAction_->setObjectName(QStringLiteral("exportImage"));
    exportImageAction_->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_E));
    exportReportAction_ = file->addAction(tr("Export Re&port…"), this, [this] {
        auto* dialog = new ReportDialog(*viewer_, document_->reportSource(), this);
        dialog->setAttribute(Qt::WA_DeleteOnClose);
        if (const auto slice = slices_->reportSlice()) {
            dialog->setSlice(slice->first, slice->second);
        }
        // The findings of the data's last report (or Send to PACS) to start from.
        dialog->findingsEdit()->setPlainText(document_->findings());
        if (auto planned = plannedReport()) {
            dialog->setMeasurements(std::move(planned->section), std::move(planned->groups));
        }
        connect(
            dialog, &ReportDialog::exportStarted, document_, [this, dialog](ExportWorker* worker) {
                const QString findings = dialog->findingsEdit()->toPlainText();
                document_->setFindings(findings);
                // Send to PACS offers the report once it is written.
                const DocumentController::ExportedReport exported{
                    QFileInfo(dialog->pdfEdit()->text().trimmed()).absoluteFilePath(), findings};
                connect(worker, &ExportWorker::succeeded, document_,
                        [this, exported] { document_->setExportedReport(exported); });
            });
        dialog->open();
    });
    exportReportAction_->setObjectName(QStringLiteral("exportReport"));
    exportReportAction_->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_E));
    exportSurfaceAction_ =
        file->addAction(tr("Export S&urface…"), this, &MainWindow::exportSurface);
    exportSurfaceAction_->setObjectName(QStringLiteral("exportSurface"));
    updateExportActions();
    file->addSeparator();
    QAction* quit = file->addAction(tr("&Quit"), this, &QWidget::close);
    quit->setShortcut(QKeySequence::Quit);
}

void MainWindow::buildViewMenu() {
    QMenu* view = menuBar()->addMenu(tr("&View"));
    QAction* reset = view->addAction(tr("&Reset Camera"), viewer_, &ViewerWidget::resetCamera);
    reset->setShortcut(Qt::Key_R);
    QAction* fit = view->addAction(tr("&Fit to Data"), viewer_, &ViewerWidget::fitToData);
    fit->setShortcut(Qt::Key_F);
    view->addSeparator();
    legendsAction_ = view->addAction(tr("Show &Legends"));
    legendsAction_->setObjectName(QStringLiteral("legendsToggle"));
    legendsAction_->setCheckable(true);
    legendsAction_->setChecked(viewer_->legendsVisible());
    connect(legendsAction_, &QAction::toggled, this, [this](bool on) {
        viewer_->setLegendsVisible(on);
        syncControls();
    });
    // The orientation marker and the scale bar (over the view and in exports).
    markerAction_ = view->addAction(tr("Show &Orientation Marker"));
    markerAction_->setObjectName(QStringLiteral("orientationMarkerToggle"));
    scaleBarAction_ = view->addAction(tr("Show &Scale Bar"));
    scaleBarAction_->setObjectName(QStringLiteral("scaleBarToggle"));
    scaleBarAction_->setToolTip(
        tr("A length in mm, true at the focal plane (the depth of the centre of rotation); "
           "nearer parts look larger, farther ones smaller"));
    for (QAction* action : {markerAction_, scaleBarAction_}) {
        action->setCheckable(true);
        connect(action, &QAction::toggled, this, [this] {
            render::ViewAnnotations annotations = viewer_->viewAnnotations();
            annotations.orientationMarker = markerAction_->isChecked();
            annotations.scaleBar = scaleBarAction_->isChecked();
            viewer_->setViewAnnotations(annotations);
        });
    }
    // Coarse meshes drawn smooth up close (a note says how far the wall moved).
    smoothAction_ = view->addAction(tr("Smooth &Coarse Meshes Up Close"));
    smoothAction_->setObjectName(QStringLiteral("smoothCoarseToggle"));
    smoothAction_->setCheckable(true);
    smoothAction_->setChecked(viewer_->smoothCoarseMeshes());
    smoothAction_->setToolTip(
        tr("Where a coarse mesh's facets are large on screen, draw it from a smooth "
           "(subdivided) copy, so that the lit void space surface shows no blob per facet; "
           "the status bar says how far the copy moves the wall"));
    connect(smoothAction_, &QAction::toggled, this, [this](bool on) {
        viewer_->setSmoothCoarseMeshes(on);
        showSmoothCopyNote();
    });
    connect(viewer_, &ViewerWidget::smoothCopyReady, this, [this] { showSmoothCopyNote(); });
    view->addAction(vssAction_);
    view->addAction(aoAction_);
    view->addAction(cvdAction_);
    view->addSeparator();
    measureAction_ = view->addAction(tr("&Measure Distance"));
    measureAction_->setObjectName(QStringLiteral("measureToggle"));
    measureAction_->setCheckable(true);
    measureAction_->setShortcut(Qt::Key_M);
    measureAction_->setToolTip(
        tr("Click two points on the vessels: their distance and depth difference "
           "(Ctrl + click works without this mode)"));
    connect(measureAction_, &QAction::toggled, this, [this](bool on) { measure_->setActive(on); });
    QAction* clearMeasure =
        view->addAction(tr("&Clear Measurement"), this, &MainWindow::clearMeasurement);
    clearMeasure->setObjectName(QStringLiteral("clearMeasurement"));
    // Leaving measure mode keeps the measurement: Esc (or Shift+M) clears it.
    clearMeasure->setShortcuts({QKeySequence(Qt::Key_Escape), QKeySequence(Qt::SHIFT | Qt::Key_M)});
    view->addSeparator();
    view->addMenu(slices_->menu());  // shown for scenes from a volume only
    QMenu* panelsMenu = view->addMenu(tr("&Panels"));
    for (QDockWidget* dock : docks_) {
        panelsMenu->addAction(dock->toggleViewAction());
    }
    panelsMenu->addAction(planningDocks_->profileDock()->toggleViewAction());
    panelsMenu->addAction(planningDocks_->measurementsDock()->toggleViewAction());
    panelsMenu->addSeparator();
    panelsMenu->addAction(tr("&Reset Layout"), this, &MainWindow::resetLayout);
    view->addSeparator();
    QAction* defaults =
        view->addAction(tr("Reset to &Defaults"), this, &MainWindow::resetToDefaults);
    defaults->setObjectName(QStringLiteral("resetToDefaults"));
    defaults->setToolTip(tr("Display settings and panel layout as in a fresh installation"));

    view->addMenu(new LanguageMenu(this));  // stored in QSettings, applied at the next start
}

void MainWindow::buildDocks() {
    vssPanel_ = new panels::VssPanel(viewer_, this);
    functionalPanel_ = new panels::FunctionalPanel(viewer_, this);
    displayPanel_ = new panels::DisplayPanel(viewer_, this);
    dataPanel_ = new panels::DataPanel(viewer_, this);
    segmentationPanel_ = new panels::SegmentationPanel(viewer_, this);
    planning_ = new PlanningState(this);
    analysisPanel_ = new panels::AnalysisPanel(viewer_, planning_, this);
    // One side panel, its parts one under the other: what a newcomer needs
    // first is open, the rest folded.
    sidePanel_ = new panels::SidePanel(this);
    sidePanel_->addSection(tr("Void Space Surface"), vssPanel_, true);
    sidePanel_->addSection(tr("Functional parameters"), functionalPanel_, true);
    sidePanel_->addSection(tr("Display"), displayPanel_, false);
    sidePanel_->addSection(tr("Data"), dataPanel_, false);
    sidePanel_->addSection(tr("Segmentation"), segmentationPanel_, false);
    sidePanel_->addSection(tr("Analysis"), analysisPanel_, false);
    auto* dock = new QDockWidget(tr("Side Panel"), this);
    dock->setObjectName(QStringLiteral("sidePanelDock"));
    dock->setWidget(sidePanel_);
    addDockWidget(Qt::RightDockWidgetArea, dock);
    docks_ << dock;
    buildPlanning();
    connect(vssPanel_, &panels::VssPanel::changed, this, &MainWindow::syncControls);
    connect(functionalPanel_, &panels::FunctionalPanel::changed, this, &MainWindow::syncControls);
    connect(displayPanel_, &panels::DisplayPanel::changed, this, &MainWindow::syncControls);
    connect(dataPanel_, &panels::DataPanel::changed, this, &MainWindow::syncControls);
    connect(dataPanel_, &panels::DataPanel::browseSeries, this, [this](const QString& path) {
        const QString folder =
            path.isEmpty() ? QFileDialog::getExistingDirectory(this, tr("Open DICOM folder"))
                           : path;
        if (!folder.isEmpty()) {
            openDicom(folder);
        }
    });
    connect(segmentationPanel_, &panels::SegmentationPanel::sceneReady, this,
            &MainWindow::showSegmentedScene);
    // An Apply becomes the document's segmentation (exports, report, PACS).
    connect(segmentationPanel_, &panels::SegmentationPanel::applied, document_,
            [this](const std::shared_ptr<const segmentation::SegmentationOutcome>& outcome,
                   const segmentation::SegmentationRequest& request) {
                app::SegmentationProvenance provenance = document_->segmentation();
                app::describeSegmentation(provenance, request, *outcome);
                document_->applySegmentation(outcome->scene, outcome->labelMap,
                                             std::move(provenance), request.segmentation,
                                             request.surface);
            });
    connect(segmentationPanel_, &panels::SegmentationPanel::labelMapReady, slices_,
            &SliceWorkspace::setLabelMap);
    // The seed can be picked in a slice as on the 3-D view.
    connect(slices_, &SliceWorkspace::sliceClicked, this, [this](const glm::dvec3& world) {
        if (segmentationPanel_->pickSeedButton()->isChecked()) {
            segmentationPanel_->pickSeed(glm::vec3(world));
        }
    });
    connect(segmentationPanel_, &panels::SegmentationPanel::statusMessage, this,
            [this](const QString& message) { statusLabel_->setText(message); });
}

void MainWindow::buildPlanning() {
    planningDocks_ = new PlanningDocks(this, viewer_, slices_, planning_, analysisPanel_);
    const auto status = [this](const QString& message) { statusLabel_->setText(message); };
    connect(planningDocks_, &PlanningDocks::statusMessage, this, status);
    connect(analysisPanel_, &panels::AnalysisPanel::statusMessage, this, status);
}

std::optional<PlanningReport> MainWindow::plannedReport() {
    return planningDocks_->plannedReport();
}

void MainWindow::buildToolBar() {
    QToolBar* bar = addToolBar(tr("Display"));
    bar->setObjectName(QStringLiteral("displayToolBar"));
    bar->setMovable(false);
    vssAction_ = bar->addAction(tr("VSS"));
    vssAction_->setObjectName(QStringLiteral("vssToggle"));
    vssAction_->setCheckable(true);
    vssAction_->setChecked(viewer_->vssSettings().enabled);
    vssAction_->setToolTip(
        tr("Void Space Surface: a depth-coded surface in the space between the vessels"));
    connect(vssAction_, &QAction::toggled, this, [this](bool on) {
        render::VssSettings vss = viewer_->vssSettings();
        vss.enabled = on;
        viewer_->setVssSettings(vss);
        syncControls();
    });
    aoAction_ = bar->addAction(tr("AO"));
    aoAction_->setObjectName(QStringLiteral("aoToggle"));
    aoAction_->setCheckable(true);
    aoAction_->setChecked(viewer_->aoSettings().enabled);
    aoAction_->setToolTip(tr("Ambient occlusion: shade the surface next to the vessels"));
    connect(aoAction_, &QAction::toggled, this, [this](bool on) {
        render::AoSettings ao = viewer_->aoSettings();
        ao.enabled = on;
        viewer_->setAoSettings(ao);
        syncControls();
    });
    bar->addSeparator();
    cvdAction_ = bar->addAction(tr("Colour-blind safe"));
    cvdAction_->setObjectName(QStringLiteral("colorBlindSafeToggle"));
    cvdAction_->setCheckable(true);
    cvdAction_->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_B));
    cvdAction_->setToolTip(
        tr("Colour-blind-safe mode (%1): dark-means-deep on the VSS, cividis on the vessels, "
           "no red/green depth cue")
            .arg(cvdAction_->shortcut().toString(QKeySequence::NativeText)));
    connect(cvdAction_, &QAction::toggled, this, &MainWindow::setColorBlindSafe);
}

void MainWindow::setColorBlindSafe(bool on) {
    const DisplayState current = displayState(*viewer_);
    if (on) {
        beforeColorBlindSafe_ = current;
        applyDisplayState(*viewer_, colorBlindSafe(current));
    } else {
        // Back to the colours from before (the defaults when the view was
        // already safe); everything else stays as it is now.
        const DisplayState before = beforeColorBlindSafe_.value_or(DisplayState{});
        DisplayState restored = current;
        restored.vss.scale = before.vss.scale;
        restored.style.colorMap = before.style.colorMap;
        restored.cue.cue = before.cue.cue;
        applyDisplayState(*viewer_, restored);
        beforeColorBlindSafe_.reset();
    }
    syncControls();
}

void MainWindow::syncControls() {
    vssPanel_->syncFromViewer();
    functionalPanel_->syncFromViewer();
    displayPanel_->syncFromViewer();
    dataPanel_->syncFromViewer();
    const QSignalBlocker vss(vssAction_);
    vssAction_->setChecked(viewer_->vssSettings().enabled);
    const QSignalBlocker ao(aoAction_);
    aoAction_->setChecked(viewer_->aoSettings().enabled);
    const QSignalBlocker cvd(cvdAction_);
    cvdAction_->setChecked(isColorBlindSafe(displayState(*viewer_)));
    if (legendsAction_ != nullptr) {
        const QSignalBlocker legends(legendsAction_);
        legendsAction_->setChecked(viewer_->legendsVisible());
    }
    if (smoothAction_ != nullptr && smoothAction_->isChecked() != viewer_->smoothCoarseMeshes()) {
        const QSignalBlocker smooth(smoothAction_);
        smoothAction_->setChecked(viewer_->smoothCoarseMeshes());
        showSmoothCopyNote();  // a session or a reset switched it
    }
    for (QAction* action : {markerAction_, scaleBarAction_}) {
        if (action != nullptr) {
            const QSignalBlocker blocker(action);
            action->setChecked(action == markerAction_
                                   ? viewer_->viewAnnotations().orientationMarker
                                   : viewer_->viewAnnotations().scaleBar);
        }
    }
    updateRangeLabel();
}

void MainWindow::showSmoothCopyNote() {
    const render::RefinedGeometry& copy = viewer_->smoothCopy();
    if (!viewer_->smoothCoarseMeshes() || !copy.scene || !viewer_->lastFrameSmoothed()) {
        smoothLabel_->hide();  // the image shows the mesh as it is
        return;
    }
    const QLocale locale;
    const QString largest = locale.toString(copy.largestDeviationMm, 'f', 2);
    smoothLabel_->setText(tr("Smoothed up close: wall ≤ %1 mm").arg(largest));
    smoothLabel_->setToolTip(tr("Coarse facets are drawn smoothed up close: the wall moves by at "
                                "most %1 mm (%2 mm on average)")
                                 .arg(largest, locale.toString(copy.meanDeviationMm, 'f', 3)));
    smoothLabel_->show();
}

QComboBox* MainWindow::arrayChooser() const {
    return functionalPanel_->arrayChooser();
}

QComboBox* MainWindow::colorMapChooser() const {
    return functionalPanel_->colorMapChooser();
}

QDoubleSpinBox* MainWindow::vssPowerBox() const {
    return vssPanel_->powerBox();
}

QComboBox* MainWindow::depthScaleChooser() const {
    return vssPanel_->scaleChooser();
}

QComboBox* MainWindow::vesselCueChooser() const {
    return displayPanel_->vesselCueChooser();
}

void MainWindow::resetToDefaults() {
    resetViewSettings(*viewer_);
    beforeColorBlindSafe_.reset();
    resetLayout();
    slices_->setSliceLayout(SliceLayout::ThreeDAndSlices);
    syncControls();
}

QString MainWindow::shortcutSummary() const {
    return HelpTexts::shortcuts(*menuBar());
}

void MainWindow::showShortcuts() {
    auto* box = new QMessageBox(QMessageBox::NoIcon, tr("Keyboard Shortcuts"), shortcutSummary(),
                                QMessageBox::Close, this);
    box->setObjectName(QStringLiteral("shortcutsBox"));
    box->setTextFormat(Qt::RichText);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
}

void MainWindow::resetLayout() {
    restoreState(defaultLayout_, kLayoutVersion);
    for (QDockWidget* dock : docks_) {
        dock->show();
    }
    for (panels::CollapsibleSection* section : sidePanel_->sections()) {
        section->resetToDefault();
    }
    planningDocks_->showForAnalysis();
}

void MainWindow::revealPanel(const QWidget* panel) {
    docks_.front()->show();
    sidePanel_->reveal(panel);
}

void MainWindow::buildStatusBar() {
    // The general message gives way ("…", whole in its tooltip) so that the
    // permanent parts (measurement, VSS quality, range) always show whole.
    statusLabel_ = new ElidingLabel(tr("Ready"), this);
    statusLabel_->setObjectName(QStringLiteral("statusMessage"));
    rangeLabel_ = new QLabel(this);
    rangeLabel_->setObjectName(QStringLiteral("arrayRangeLabel"));
    vssLabel_ = new QLabel(this);
    vssLabel_->setObjectName(QStringLiteral("vssQualityLabel"));
    smoothLabel_ = new QLabel(this);
    smoothLabel_->setObjectName(QStringLiteral("smoothCopyLabel"));
    smoothLabel_->hide();  // while no smooth copy is drawn
    progressBar_ = new QProgressBar(this);
    progressBar_->setRange(0, 1000);
    progressBar_->setMaximumWidth(240);
    progressBar_->setTextVisible(false);
    cancelButton_ = new QPushButton(tr("Cancel"), this);
    cancelButton_->setObjectName(QStringLiteral("cancelButton"));
    connect(cancelButton_, &QPushButton::clicked, this, [this] {
        if (document_->cancelLoad()) {
            statusLabel_->setText(tr("Cancelling…"));
        }
    });
    statusBar()->addWidget(statusLabel_, 1);
    measureLabel_ = new QLabel(this);
    measureLabel_->setObjectName(QStringLiteral("measureLabel"));
    measure_ = new MeasureTool(viewer_, measureLabel_, this);
    statusBar()->addPermanentWidget(measureLabel_);
    connect(viewer_, &ViewerWidget::pointPicked, measure_, &MeasureTool::addPoint);
    connect(viewer_, &ViewerWidget::pickMissed, measure_, &MeasureTool::missed);
    statusBar()->addPermanentWidget(smoothLabel_);
    statusBar()->addPermanentWidget(vssLabel_);
    statusBar()->addPermanentWidget(rangeLabel_);
    statusBar()->addPermanentWidget(progressBar_);
    statusBar()->addPermanentWidget(cancelButton_);
    progressBar_->hide();
    cancelButton_->hide();
}

void MainWindow::chooseSeries(const std::shared_ptr<const dicom::DicomScanResult>& scan,
                              const QString& path) {
    statusLabel_->setText(tr("Choose a series"));
    auto* dialog = new SeriesDialog(*scan, this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &QDialog::accepted, this, [this, dialog, path] {
        document_->openSeries(path, dialog->sceneSourceOptions(), dialog->seriesTitle());
    });
    connect(dialog, &QDialog::rejected, this, [this] { statusLabel_->setText(tr("Ready")); });
    dialog->open();
    emit seriesDialogShown(dialog);
}

void MainWindow::showSegmentedScene(std::shared_ptr<const scene::Scene> scene,
                                    const QString& status) {
    render::Camera camera = viewer_->camera();
    document_->showDerivedScene(std::move(scene), segmentationPanel_->showsPreview());
    camera.setSceneBounds(viewer_->dataBounds());  // clip planes of the new scene
    viewer_->setCamera(camera);
    statusLabel_->setText(status);
}

void MainWindow::showScene(const std::shared_ptr<const scene::Scene>& scene, const QString& title,
                           const QStringList& files) {
    clearMeasurement();  // points on the old data mean nothing on the new
    viewer_->setScene(scene);
    analysisPanel_->sceneChanged();  // so are centrelines and landmarks
    functionalPanel_->sceneChanged();
    dataPanel_->sceneChanged(title, files);
    dataPanel_->setDicomSource(document_->dicomSource());
}

void MainWindow::sceneWasShown() {
    // Scenes from DICOM are in the patient frame (LPS): the marker names patient sides.
    render::ViewAnnotations annotations = viewer_->viewAnnotations();
    annotations.frame =
        document_->scene() ? document_->scene()->frame : render::SceneFrame::Unknown;
    viewer_->setViewAnnotations(annotations);
    syncControls();
    const QString& title = document_->title();
    setWindowTitle(title.isEmpty()          ? QStringLiteral("VesselView")
                   : document_->showsDemo() ? tr("%1 (demo data) — VesselView").arg(title)
                                            : tr("%1 — VesselView").arg(title));
    if (const auto& scene = document_->scene()) {
        const std::size_t triangles = scene->triangleCount();
        const QString meshes =
            scene->meshes.size() == 1 ? tr("1 mesh") : tr("%1 meshes").arg(scene->meshes.size());
        statusLabel_->setText(
            tr("%1: %2, %3 triangles")
                .arg(title, meshes, QLocale().toString(static_cast<qulonglong>(triangles))));
    } else {
        statusLabel_->setText(tr("Ready"));
    }
    updateExportActions();
    emit sceneShown();
}

QString MainWindow::previewNotApplied() {
    return tr(
        "The Segmentation panel shows a preview: apply it first (a preview is never "
        "exported or sent)");
}

void MainWindow::updateExportActions() {
    const bool shown = viewer_->scene() != nullptr;
    const bool preview = document_->showsPreview();
    exportImageAction_->setEnabled(shown);
    exportImageAction_->setToolTip(shown ? QString()
                                         : tr("Open data first: there is nothing to export"));
    exportReportAction_->setEnabled(shown && !preview);
    exportReportAction_->setToolTip(!shown    ? exportImageAction_->toolTip()
                                    : preview ? previewNotApplied()
                                              : QString());
    // A surface segmented from a DICOM series (or the segments of a DICOM SEG).
    const bool segmented = shown && !document_->seriesUid().empty();
    exportSurfaceAction_->setEnabled(segmented && !preview);
    exportSurfaceAction_->setToolTip(
        !segmented ? tr("Only for vessels segmented from a DICOM series: open one with "
                        "File > Open Folder…")
        : preview  ? previewNotApplied()
                   : tr("The segmented vessel surface as STL, VTP or PLY, in patient millimetres"));
}

void MainWindow::exportSurface() {
    if (document_->seriesUid().empty() || !document_->segmentedScene() ||
        document_->showsPreview()) {
        return;
    }
    // The document's segmentation (as loaded or applied; a SEG's segments), never a preview.
    SurfaceExportSource source;
    source.scene = document_->segmentedScene();
    source.labels = document_->volume() ? document_->labelMap() : nullptr;
    source.provenance = document_->segmentation();
    auto* dialog = new ExportSurfaceDialog(std::move(source), this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->open();
}

bool MainWindow::saveSessionTo(const QString& path) {
    Session view = captureSession(*viewer_, {});
    view.layout = saveState(kLayoutVersion);
    view.slices = slices_->sessionState();
    view.measurement = measure_->completePoints();
    view.planning = analysisPanel_->sessionState();
    if (!document_->saveSession(path, std::move(view))) {
        return false;
    }
    // A preview is not the document's segmentation: the session keeps the
    // applied one, and says so.
    statusLabel_->setText(document_->showsPreview()
                              ? tr("Session saved to %1, with the applied segmentation (the "
                                   "preview on screen was not applied)")
                                    .arg(path)
                              : tr("Session saved to %1").arg(path));
    return true;
}

void MainWindow::updateRangeLabel() {
    const auto& scene = viewer_->scene();
    const std::string& array = viewer_->style().array;
    if (!scene || array.empty()) {
        rangeLabel_->clear();
        return;
    }
    // The range in use: the chosen one, else the array's full range.
    const auto range =
        viewer_->style().range ? viewer_->style().range : render::arrayRange(*scene, array);
    if (!range) {
        rangeLabel_->setText(tr("%1: no data").arg(panels::arrayLabel(*scene, array)));
        return;
    }
    rangeLabel_->setText(tr("%1: %2 – %3")
                             .arg(panels::arrayLabel(*scene, array))
                             .arg(QLocale().toString(range->first, 'g', 4),
                                  QLocale().toString(range->second, 'g', 4)));
}

void MainWindow::showError(const QString& title, const ProblemText& problem) {
    statusLabel_->setText(title + QStringLiteral(": ") + problem.summary);
    if (screenshot_ != nullptr) {
        screenshot_->fail(problem.summary + QLatin1Char(' ') + problem.details);
        return;
    }
    showProblem(this, QStringLiteral("errorMessageBox"), title, problem);
    emit loadFailed(problem.line());
}

void MainWindow::placeSegmentationSection(bool volumeShown) {
    panels::CollapsibleSection* section = sidePanel_->sectionOf(segmentationPanel_);
    if (section == nullptr) {
        return;
    }
    // A scene from a volume is shaped by its segmentation: on top and open.
    // Any other scene cannot use it: back to the bottom, as it was.
    sidePanel_->moveSection(section,
                            volumeShown ? 0 : static_cast<int>(sidePanel_->sections().size()));
    if (volumeShown) {
        sidePanel_->reveal(segmentationPanel_);
    }
}

void MainWindow::showLanguageProblem(const QString& note) {
    if (screenshot_ != nullptr) {
        return;
    }
    // No tr(): the translation is what is missing.
    auto* box = new QMessageBox(QMessageBox::Information, QStringLiteral("Language"), note,
                                QMessageBox::Ok, this);
    box->setObjectName(QStringLiteral("languageProblemBox"));
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
}

void MainWindow::rebuildRecentMenu() {
    recentMenu_->clear();
    const QStringList recent = DocumentController::recentFiles();
    int number = 1;
    for (const QString& file : recent) {
        // A series from a study store by what it says of itself, not by its
        // folder (a UID); an "&" in a name is shown, not taken as a shortcut.
        QString label = recent::label(file);
        label.replace(QLatin1Char('&'), QStringLiteral("&&"));
        QAction* action =
            recentMenu_->addAction(QStringLiteral("&%1 %2").arg(number++).arg(label), this,
                                   [this, file] { document_->openRecent(file); });
        action->setToolTip(file);
        action->setStatusTip(file);
    }
    if (!recent.isEmpty()) {
        recentMenu_->addSeparator();
    }
    QAction* clear = recentMenu_->addAction(tr("&Clear Recent Files"), document_,
                                            &DocumentController::clearRecentFiles);
    clear->setEnabled(!recent.isEmpty());
}

void MainWindow::setScreenshotTarget(const QString& path) {
    delete screenshot_;
    screenshot_ = nullptr;
    if (!path.isEmpty()) {
        // Screenshots show the default display, not what was remembered.
        resetViewSettings(*viewer_);
        syncControls();
        screenshot_ = new ScreenshotMode(*viewer_, path, this);
    }
}

namespace {

/// What holds of a settled VSS that is on screen: "exact" only for an exact
/// solver, else the solver's guaranteed error bound (in 1/255 of the depth
/// range) or that it gives none; with the solve's time. UI-locale numbers.
QString vssQualityText(const render::VssFrameStatus& status) {
    const QLocale locale;
    const QString ms =
        locale.toString(static_cast<qlonglong>(std::lround(status.solveMilliseconds)));
    if (status.errorBound == 0.0) {
        return MainWindow::tr("VSS: exact, %1 ms").arg(ms);
    }
    if (!std::isfinite(status.errorBound)) {
        return MainWindow::tr("VSS: approximate (no error bound), %1 ms").arg(ms);
    }
    return MainWindow::tr("VSS: within %1/255, %2 ms")
        .arg(locale.toString(status.errorBound * 255.0, 'g', 3), ms);
}

}  // namespace

void MainWindow::updateVssLabel() {
    const render::VssFrameStatus& status = viewer_->vssStatus();
    if (!viewer_->scene() || !viewer_->vssSettings().enabled) {
        vssLabel_->clear();
    } else if (!status.shown) {
        vssLabel_->setText(status.pending ? tr("VSS: solving…") : tr("VSS: none"));
    } else if (status.preview || !status.current) {
        vssLabel_->setText(tr("VSS: preview"));
    } else {
        vssLabel_->setText(vssQualityText(status));
    }
}

void MainWindow::onFrameRendered() {
    updateVssLabel();
    showSmoothCopyNote();
    vssPanel_->updateStatus();
    displayPanel_->frameRendered();
    if (screenshot_ != nullptr) {
        screenshot_->frameRendered();
    }
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
    if (DocumentController::canOpen(localPaths(event->mimeData()))) {
        event->acceptProposedAction();
    }
}

void MainWindow::dropEvent(QDropEvent* event) {
    if (document_->openDropped(localPaths(event->mimeData()))) {
        event->acceptProposedAction();
    }
}

void MainWindow::closeEvent(QCloseEvent* event) {
    document_->cancelLoad();
    if (screenshot_ == nullptr) {
        QSettings settings;
        settings.setValue(QLatin1String(kGeometryKey), saveGeometry());
        settings.setValue(QLatin1String(kLayoutKey), saveState(kLayoutVersion));
        saveViewSettings(*viewer_, settings);
    }
    event->accept();
}

QString MainWindow::aboutText() const {
    // The disclaimer the reports carry (File > Export Report sets it).
    const QString disclaimer = ReportDialog::disclaimer(QSettings());
    return HelpTexts::about(viewer_->glDescription()) +
           (disclaimer.isEmpty() ? QString()
                                 : QStringLiteral("<p><b>") + disclaimer.toHtmlEscaped() +
                                       QStringLiteral("</b></p>"));
}

void MainWindow::showAbout() {
    QMessageBox::about(this, tr("About VesselView"), aboutText());
}

}  // namespace vv::gui
