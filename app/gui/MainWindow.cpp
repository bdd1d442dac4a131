// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/MainWindow.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QComboBox>
#include <QCoreApplication>
#include <QDir>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QImage>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollArea>
#include <QSettings>
#include <QStackedWidget>
#include <QStatusBar>
#include <QTimer>
#include <QToolBar>
#include <QUrl>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <vector>

#include "common/ResourcePaths.h"
#include "gui/ExportImageDialog.h"
#include "gui/MeasureOverlay.h"
#include "gui/MeshLoadTask.h"
#include "gui/ReportDialog.h"
#include "gui/SeriesDialog.h"
#include "gui/Translations.h"
#include "gui/ViewSettings.h"
#include "gui/ViewerWidget.h"
#include "gui/panels/DataPanel.h"
#include "gui/panels/DisplayPanel.h"
#include "gui/panels/FunctionalPanel.h"
#include "gui/panels/PanelUtil.h"
#include "gui/panels/SegmentationPanel.h"
#include "gui/panels/VssPanel.h"
#include "vv/colormaps/ColorMap.h"
#include "vv/colormaps/DepthScale.h"
#include "vv/core/AtomicFile.h"
#include "vv/core/Error.h"
#include "vv/dicom/Versions.h"
#include "vv/meshio/MeshLoader.h"
#include "vv/meshio/Versions.h"
#include "vv/render/MeshRenderer.h"
#include "vv/segmentation/SceneSource.h"
#include "vv/vss/Versions.h"

namespace vv::gui {

namespace {

constexpr int kMaxRecentFiles = 8;
const char* const kRecentFilesKey = "recentFiles";
const char* const kGeometryKey = "mainWindow/geometry";
const char* const kLayoutKey = "mainWindow/layout";
/// Bump when the docks change so that an old saved layout is not applied.
constexpr int kLayoutVersion = 1;
/// The side panels' initial width (logical pixels).
constexpr int kDockWidth = 330;
/// Screenshot mode gives up when no frame was saved within this time.
constexpr int kScreenshotTimeoutMs = 10 * 60 * 1000;

bool hasSupportedExtension(const QString& file) {
    const QString suffix = "." + QFileInfo(file).suffix().toLower();
    const auto& extensions = meshio::supportedMeshExtensions();
    return std::any_of(extensions.begin(), extensions.end(),
                       [&](const std::string& e) { return suffix == QString::fromStdString(e); });
}

QStringList localFiles(const QMimeData* mime, bool supportedOnly) {
    QStringList files;
    if (mime == nullptr || !mime->hasUrls()) {
        return files;
    }
    for (const QUrl& url : mime->urls()) {
        if (url.isLocalFile()) {
            const QString file = url.toLocalFile();
            if (!supportedOnly || hasSupportedExtension(file)) {
                files << file;
            }
        }
    }
    return files;
}

}  // namespace

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
    setWindowTitle(QStringLiteral("VesselView"));
    setAcceptDrops(true);
    resize(1280, 800);

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
        stack_->addWidget(viewer_);
    } else {
        viewer_ = new ViewerWidget(nullptr);
        detachedViewer_.reset(viewer_);
    }
    stack_->addWidget(glMessage_);
    setCentralWidget(stack_);

    connect(viewer_, &ViewerWidget::renderFailed, this, [this](const QString& message) {
        glMessage_->setText(message);
        stack_->setCurrentWidget(glMessage_);
        statusLabel_->setText(tr("OpenGL 4.1 is not available"));
        if (!screenshotPath_.isEmpty()) {
            finishScreenshot(false, message);
        }
    });
    // Queued: grabbing the frame from inside paintGL would re-enter it.
    connect(viewer_, &ViewerWidget::frameRendered, this, &MainWindow::onFrameRendered,
            Qt::QueuedConnection);

    buildDocks();
    buildToolBar();
    buildMenus();
    buildStatusBar();
    defaultLayout_ = saveState(kLayoutVersion);
    const QSettings settings;
    restoreGeometry(settings.value(QLatin1String(kGeometryKey)).toByteArray());
    restoreState(settings.value(QLatin1String(kLayoutKey)).toByteArray(), kLayoutVersion);
    restoreViewSettings(*viewer_, settings);
    syncControls();
    if (!glProblem.isEmpty()) {
        viewer_->setUnavailable(glProblem);  // renderFailed() shows the message
    }
}

MainWindow::~MainWindow() {
    if (task_) {
        task_->cancel();
    }
}

void MainWindow::buildMenus() {
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
        auto* dialog = new ReportDialog(*viewer_, reportSource(), this);
        dialog->setAttribute(Qt::WA_DeleteOnClose);
        dialog->open();
    });
    exportReportAction_->setObjectName(QStringLiteral("exportReport"));
    exportReportAction_->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_E));
    updateExportActions();
    file->addSeparator();
    QAction* quit = file->addAction(tr("&Quit"), this, &QWidget::close);
    quit->setShortcut(QKeySequence::Quit);

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
    connect(measureAction_, &QAction::toggled, this, [this](bool on) {
        viewer_->setMeasureMode(on);
        if (!on) {
            clearMeasurement();
        } else if (measurePoints_.isEmpty()) {
            measureLabel_->setText(tr("Measure: click a point on a vessel"));
        }
    });
    QAction* clearMeasure =
        view->addAction(tr("&Clear Measurement"), this, &MainWindow::clearMeasurement);
    clearMeasure->setShortcut(Qt::SHIFT | Qt::Key_M);
    view->addSeparator();
    QMenu* panelsMenu = view->addMenu(tr("&Panels"));
    for (QDockWidget* dock : docks_) {
        panelsMenu->addAction(dock->toggleViewAction());
    }
    panelsMenu->addSeparator();
    panelsMenu->addAction(tr("&Reset Layout"), this, &MainWindow::resetLayout);
    view->addSeparator();
    QAction* defaults =
        view->addAction(tr("Reset to &Defaults"), this, &MainWindow::resetToDefaults);
    defaults->setObjectName(QStringLiteral("resetToDefaults"));
    defaults->setToolTip(tr("Display settings and panel layout as in a fresh installation"));

    // View > Language: stored in QSettings, applied at the next start.
    QMenu* language = view->addMenu(tr("&Language"));
    language->setObjectName(QStringLiteral("languageMenu"));
    auto* languages = new QActionGroup(language);
    const QString chosen = QSettings().value(QLatin1String(kLanguageKey)).toString();
    const auto addLanguage = [&](const QString& code, const QString& label) {
        QAction* action = language->addAction(label);
        action->setData(code);
        action->setCheckable(true);
        action->setChecked(code == chosen);
        languages->addAction(action);
        connect(action, &QAction::triggered, this, [this, code] {
            QSettings().setValue(QLatin1String(kLanguageKey), code);
            auto* box = new QMessageBox(QMessageBox::Information, tr("Language"),
                                        tr("The language changes when VesselView starts again."),
                                        QMessageBox::Ok, this);
            box->setAttribute(Qt::WA_DeleteOnClose);
            box->open();
        });
    };
    addLanguage(QString(), tr("System Default"));
    for (const QString& code : availableLanguages()) {
        addLanguage(code, languageName(code));
    }

    QMenu* help = menuBar()->addMenu(tr("&Help"));
    QAction* keys = help->addAction(tr("&Keyboard Shortcuts"), this, &MainWindow::showShortcuts);
    keys->setShortcut(QKeySequence::HelpContents);
    help->addAction(tr("&About VesselView"), this, &MainWindow::showAbout);
}

void MainWindow::buildDocks() {
    vssPanel_ = new panels::VssPanel(viewer_, this);
    functionalPanel_ = new panels::FunctionalPanel(viewer_, this);
    displayPanel_ = new panels::DisplayPanel(viewer_, this);
    dataPanel_ = new panels::DataPanel(viewer_, this);
    segmentationPanel_ = new panels::SegmentationPanel(viewer_, this);
    const std::pair<QWidget*, QString> panels[] = {
        {vssPanel_, tr("Void Space Surface")},    {functionalPanel_, tr("Functional parameters")},
        {displayPanel_, tr("Display")},           {dataPanel_, tr("Data")},
        {segmentationPanel_, tr("Segmentation")},
    };
    for (const auto& [panel, title] : panels) {
        auto* dock = new QDockWidget(title, this);
        dock->setObjectName(panel->objectName() + QStringLiteral("Dock"));
        auto* scroll = new QScrollArea(dock);
        scroll->setWidget(panel);
        scroll->setWidgetResizable(true);
        scroll->setFrameShape(QFrame::NoFrame);
        dock->setWidget(scroll);
        addDockWidget(Qt::RightDockWidgetArea, dock);
        if (!docks_.isEmpty()) {
            tabifyDockWidget(docks_.front(), dock);
        }
        docks_ << dock;
    }
    docks_.front()->raise();
    resizeDocks({docks_.front()}, {kDockWidth}, Qt::Horizontal);
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
    connect(segmentationPanel_, &panels::SegmentationPanel::statusMessage, this,
            [this](const QString& message) { statusLabel_->setText(message); });
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
    updateRangeLabel();
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
    syncControls();
}

QString MainWindow::shortcutSummary() const {
    QStringList rows;
    const auto row = [&rows](const QString& what, const QString& keys) {
        rows << QStringLiteral("<tr><td>%1</td><td><b>%2</b></td></tr>")
                    .arg(what.toHtmlEscaped(), keys.toHtmlEscaped());
    };
    const std::function<void(const QMenu*)> collect = [&](const QMenu* menu) {
        for (const QAction* action : menu->actions()) {
            if (action->menu() != nullptr) {
                collect(action->menu());
            } else if (!action->shortcut().isEmpty()) {
                row(action->text().remove(QLatin1Char('&')),
                    action->shortcut().toString(QKeySequence::NativeText));
            }
        }
    };
    for (const QAction* action : menuBar()->actions()) {
        if (action->menu() != nullptr) {
            collect(action->menu());
        }
    }
    row(tr("Rotate"), tr("left drag"));
    row(tr("Pan"), tr("right or middle drag, Shift + left drag"));
    row(tr("Zoom"), tr("mouse wheel"));
    row(tr("Pick a point to measure"), tr("Ctrl + click (any click in Measure mode)"));
    return QStringLiteral("<table cellspacing=\"6\">") + rows.join(QString()) +
           QStringLiteral("</table>");
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
    docks_.front()->raise();
}

void MainWindow::buildStatusBar() {
    statusLabel_ = new QLabel(tr("Ready"), this);
    rangeLabel_ = new QLabel(this);
    vssLabel_ = new QLabel(this);
    vssLabel_->setObjectName(QStringLiteral("vssQualityLabel"));
    progressBar_ = new QProgressBar(this);
    progressBar_->setRange(0, 1000);
    progressBar_->setMaximumWidth(240);
    progressBar_->setTextVisible(false);
    cancelButton_ = new QPushButton(tr("Cancel"), this);
    cancelButton_->setObjectName(QStringLiteral("cancelButton"));
    connect(cancelButton_, &QPushButton::clicked, this, [this] {
        if (task_) {
            task_->cancel();
            statusLabel_->setText(tr("Cancelling…"));
        }
    });
    statusBar()->addWidget(statusLabel_, 1);
    measureLabel_ = new QLabel(this);
    measureLabel_->setObjectName(QStringLiteral("measureLabel"));
    measureOverlay_ = new MeasureOverlay(viewer_);
    statusBar()->addPermanentWidget(measureLabel_);
    connect(viewer_, &ViewerWidget::pointPicked, this, &MainWindow::addMeasurePoint);
    connect(viewer_, &ViewerWidget::pickMissed, this,
            [this] { measureLabel_->setText(tr("Measure: no vessel under the mouse")); });
    statusBar()->addPermanentWidget(vssLabel_);
    statusBar()->addPermanentWidget(rangeLabel_);
    statusBar()->addPermanentWidget(progressBar_);
    statusBar()->addPermanentWidget(cancelButton_);
    progressBar_->hide();
    cancelButton_->hide();
}

QString MainWindow::meshFileFilter() {
    QStringList patterns;
    for (const auto& extension : meshio::supportedMeshExtensions()) {
        const QString e = QString::fromStdString(extension);
        patterns << "*" + e << "*" + e.toUpper();
    }
    return tr("Meshes (%1)").arg(patterns.join(' ')) + QStringLiteral(";;") + tr("All files (*)");
}

std::optional<QString> MainWindow::findDemoFile() {
    // $VV_DEMO_FILE, else relative to the binary: build tree or install prefix.
    if (const auto demo = vv::app::findDemoFile()) {
        return QFileInfo(*demo).absoluteFilePath();
    }
    return std::nullopt;
}

void MainWindow::openFiles(const QStringList& files) {
    std::vector<std::filesystem::path> paths;
    QStringList names;
    for (const QString& f : files) {
        if (!f.isEmpty()) {
            paths.emplace_back(QFile::encodeName(f).toStdString());
            names << f;
        }
    }
    if (paths.empty()) {
        return;
    }
    startTask(MeshLoadTask::loadFiles(std::move(paths), this), names);
}

void MainWindow::openDicom(const QString& path) {
    if (path.isEmpty()) {
        return;
    }
    MeshLoadTask* task = MeshLoadTask::scanDicom(QFile::encodeName(path).toStdString(), this);
    connect(task, &MeshLoadTask::scanned, this,
            [this, path](std::shared_ptr<const dicom::DicomScanResult> scan) {
                if (scan->allSeries().empty()) {
                    const int skipped = static_cast<int>(scan->skipped.size());
                    showError(tr("Cannot open"),
                              tr("%1: no DICOM images found (%n file(s) skipped)", nullptr, skipped)
                                  .arg(path));
                    return;
                }
                statusLabel_->setText(tr("Choose a series"));
                auto* dialog = new SeriesDialog(*scan, this);
                dialog->setAttribute(Qt::WA_DeleteOnClose);
                connect(dialog, &QDialog::accepted, this, [this, dialog, path] {
                    std::vector<std::filesystem::path> paths{QFile::encodeName(path).toStdString()};
                    startTask(MeshLoadTask::loadFiles(std::move(paths),
                                                      dialog->sceneSourceOptions(), this),
                              {path});
                });
                connect(dialog, &QDialog::rejected, this,
                        [this] { statusLabel_->setText(tr("Ready")); });
                dialog->open();
                emit seriesDialogShown(dialog);
            });
    // No files for the title / recent list: the chosen series' task has them.
    startTask(task, {});
}

void MainWindow::openDemo() {
    if (const auto file = findDemoFile()) {
        std::vector<std::filesystem::path> paths{QFile::encodeName(*file).toStdString()};
        // Not remembered in the recent files: it is one menu entry away anyway.
        startTask(MeshLoadTask::loadFiles(std::move(paths), this), {});
    } else {
        startTask(MeshLoadTask::generateDemo(this), {});
    }
}

void MainWindow::startTask(MeshLoadTask* task, const QStringList& files) {
    if (task_) {
        // The old task stops at its next progress report and deletes itself;
        // nothing it delivers reaches this window any more.
        MeshLoadTask* old = task_.data();
        disconnect(old, nullptr, this, nullptr);
        connect(old, &MeshLoadTask::finished, old, &QObject::deleteLater);
        old->cancel();
    }
    task_ = task;
    connect(task, &MeshLoadTask::progressChanged, this,
            [this, task](double fraction, const QString& stage) {
                if (task != task_) {
                    return;
                }
                progressBar_->setValue(static_cast<int>(fraction * 1000.0));
                if (!stage.isEmpty()) {
                    statusLabel_->setText(task->description() + QStringLiteral(": ") + stage);
                }
            });
    connect(task, &MeshLoadTask::loaded, this,
            [this, task, files](std::shared_ptr<const scene::Scene> scene) {
                QString title;
                if (files.size() == 1) {
                    title = QFileInfo(files.front()).fileName();
                } else if (files.size() > 1) {
                    title = tr("%n files", nullptr, static_cast<int>(files.size()));
                } else if (!task->files().empty()) {
                    title = QString::fromStdString(task->files().front().filename().string());
                } else {
                    title = tr("demo vessel tree");
                }
                sceneFiles_ = files;
                shownFiles_.clear();
                for (const auto& path : task->files()) {
                    shownFiles_
                        << QFileInfo(QFile::decodeName(path.string().c_str())).absoluteFilePath();
                }
                const segmentation::SceneSourceReport& source = task->dicomReport();
                shownSeriesUid_ = source.fromVolume || source.fromSegmentationObject
                                      ? source.seriesInstanceUid
                                      : std::string();
                setScene(std::move(scene), title);
                // A DICOM image series: keep its volume for the Segmentation panel.
                if (source.volume) {
                    volume_ = source.volume;
                    segmentationPanel_->setVolume(volume_, task->dicomOptions().segmentation,
                                                  source.range, task->dicomOptions().surface);
                }
                addRecentFiles(files);
            });
    connect(task, &MeshLoadTask::failed, this,
            [this, task](const QString& file, const QString& problem) {
                QString what = file;
                if (what.isEmpty() && !task->files().empty()) {
                    what = QString::fromStdString(task->files().front().string());
                }
                const QString message = what.isEmpty() ? problem : tr("%1: %2").arg(what, problem);
                pendingSession_.reset();  // its files did not load
                showError(tr("Cannot open"), message);
            });
    connect(task, &MeshLoadTask::cancelled, this, [this] {
        statusLabel_->setText(tr("Cancelled"));
        if (!screenshotPath_.isEmpty()) {
            finishScreenshot(false, tr("loading was cancelled"));
        }
    });
    connect(task, &MeshLoadTask::finished, this, &MainWindow::taskFinished);

    statusLabel_->setText(task->description() + QStringLiteral("…"));
    progressBar_->setValue(0);
    progressBar_->show();
    cancelButton_->show();
    task->start();
}

void MainWindow::taskFinished() {
    auto* task = qobject_cast<MeshLoadTask*>(sender());
    if (task != nullptr) {
        task->deleteLater();
    }
    if (task == task_) {
        task_ = nullptr;
        progressBar_->hide();
        cancelButton_->hide();
    }
}

void MainWindow::setScene(std::shared_ptr<const scene::Scene> scene, const QString& title) {
    // A scene from elsewhere: no volume behind it (a DICOM load sets it afterwards).
    volume_.reset();
    segmentationPanel_->setVolume(nullptr);
    showScene(std::move(scene), title);
}

void MainWindow::showSegmentedScene(std::shared_ptr<const scene::Scene> scene,
                                    const QString& status) {
    render::Camera camera = viewer_->camera();
    sceneFiles_ = shownFiles_;
    showScene(std::move(scene), sceneTitle_);
    camera.setSceneBounds(viewer_->dataBounds());  // clip planes of the new scene
    viewer_->setCamera(camera);
    statusLabel_->setText(status);
}

void MainWindow::showScene(std::shared_ptr<const scene::Scene> scene, const QString& title) {
    sceneTitle_ = title;
    clearMeasurement();  // points on the old data mean nothing on the new
    viewer_->setScene(scene);
    functionalPanel_->sceneChanged();
    dataPanel_->sceneChanged(title, sceneFiles_);
    QString dicomSource;
    for (const QString& file : sceneFiles_) {
        if (segmentation::isDicomSource(
                std::filesystem::path(QFile::encodeName(file).toStdString()))) {
            dicomSource = file;
            break;
        }
    }
    dataPanel_->setDicomSource(dicomSource);
    sceneFiles_.clear();
    if (pendingSession_) {
        // A session being opened: its settings and camera, now that its data is shown.
        const Session session = *pendingSession_;
        pendingSession_.reset();
        applySession(*viewer_, session);
        if (!session.layout.isEmpty()) {
            restoreState(session.layout, kLayoutVersion);
        }
        QTimer::singleShot(0, this, &MainWindow::sessionApplied);
    }
    syncControls();
    setWindowTitle(title.isEmpty() ? QStringLiteral("VesselView")
                                   : title + QStringLiteral(" — VesselView"));
    if (scene) {
        const std::size_t triangles = scene->triangleCount();
        const QString meshes =
            scene->meshes.size() == 1 ? tr("1 mesh") : tr("%1 meshes").arg(scene->meshes.size());
        statusLabel_->setText(
            tr("%1: %2, %3 triangles")
                .arg(title, meshes, QLocale().toString(static_cast<qulonglong>(triangles))));
    } else {
        statusLabel_->setText(tr("Ready"));
    }
    lastError_.clear();
    updateExportActions();
    emit sceneShown();
}

void MainWindow::updateExportActions() {
    const bool shown = viewer_->scene() != nullptr;
    for (QAction* action : {exportImageAction_, exportReportAction_}) {
        action->setEnabled(shown);
        action->setToolTip(shown ? QString() : tr("Open data first: there is nothing to export"));
    }
}

report::ReportSource MainWindow::reportSource() const {
    report::ReportSource source;
    for (const QString& file : shownFiles_) {
        const std::filesystem::path path(QFile::encodeName(file).toStdString());
        source.files.push_back(path);
        if (source.dicomPath.empty() && segmentation::isDicomSource(path)) {
            source.dicomPath = path;
            source.seriesInstanceUid = shownSeriesUid_;
        }
    }
    return source;
}

void MainWindow::addMeasurePoint(const ProbeResult& point) {
    if (measurePoints_.size() >= 2) {
        measurePoints_.clear();
    }
    measurePoints_ << point;
    measureOverlay_->setPoints(measurePoints_);
    const auto where = [](const ProbeResult& p) {
        return p.objectName.isEmpty() ? tr("object %1").arg(p.meshIndex + 1) : p.objectName;
    };
    if (measurePoints_.size() == 1) {
        measureLabel_->setText(tr("Measure: A on %1, %2 mm deep; click a second point")
                                   .arg(where(point))
                                   .arg(static_cast<double>(point.depthBelowNearest), 0, 'f', 1));
        return;
    }
    const Measurement m = measure(measurePoints_[0], measurePoints_[1]);
    const double depth = static_cast<double>(m.depthDifference);
    const QString deeper = std::abs(depth) < 0.05 ? tr("same depth")
                           : depth > 0.0 ? tr("B deeper by %1 mm").arg(std::abs(depth), 0, 'f', 1)
                                         : tr("A deeper by %1 mm").arg(std::abs(depth), 0, 'f', 1);
    measureLabel_->setText(
        tr("Distance A–B: %1 mm; %2").arg(static_cast<double>(m.distance), 0, 'f', 1).arg(deeper));
}

void MainWindow::clearMeasurement() {
    measurePoints_.clear();
    measureOverlay_->setPoints(measurePoints_);
    measureLabel_->setText(measureAction_ != nullptr && measureAction_->isChecked()
                               ? tr("Measure: click a point on a vessel")
                               : QString());
}

bool MainWindow::saveSessionTo(const QString& path) {
    Session session = captureSession(*viewer_, viewer_->scene() ? shownFiles_ : QStringList());
    session.layout = saveState(kLayoutVersion);
    if (viewer_->scene() && !shownSeriesUid_.empty()) {
        // DICOM data: the series, and for an image series the Segmentation
        // panel's settings, so that the session reopens without asking.
        segmentation::SceneSourceOptions dicom;
        dicom.seriesInstanceUid = shownSeriesUid_;
        if (volume_) {
            dicom.segmentation = segmentationPanel_->segmentationOptions();
            dicom.surface = segmentationPanel_->surfaceOptions();
        }
        session.dicom = dicom;
    }
    try {
        saveSession(std::filesystem::path(QFile::encodeName(path).toStdString()), session);
    } catch (const vv::Error& e) {
        showError(tr("Cannot save the session"), QString::fromStdString(e.what()));
        return false;
    }
    statusLabel_->setText(tr("Session saved to %1").arg(path));
    return true;
}

bool MainWindow::openSession(const QString& path) {
    Session session;
    try {
        session = loadSession(std::filesystem::path(QFile::encodeName(path).toStdString()));
    } catch (const vv::Error& e) {
        showError(tr("Cannot open the session"), QString::fromStdString(e.what()));
        return false;
    }
    if (session.files.isEmpty()) {
        setScene(nullptr, QString());
        applySession(*viewer_, session);
        if (!session.layout.isEmpty()) {
            restoreState(session.layout, kLayoutVersion);
        }
        syncControls();
        QTimer::singleShot(0, this, &MainWindow::sessionApplied);
        return true;
    }
    pendingSession_ = session;
    if (session.dicom && session.files.size() == 1) {
        std::vector<std::filesystem::path> paths{
            QFile::encodeName(session.files.front()).toStdString()};
        startTask(MeshLoadTask::loadFiles(std::move(paths), *session.dicom, this), session.files);
        return true;
    }
    openFiles(session.files);
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
                             .arg(static_cast<double>(range->first), 0, 'g', 4)
                             .arg(static_cast<double>(range->second), 0, 'g', 4));
}

void MainWindow::showError(const QString& title, const QString& message) {
    lastError_ = message;
    statusLabel_->setText(title + QStringLiteral(": ") + message);
    if (!screenshotPath_.isEmpty()) {
        finishScreenshot(false, message);
        return;
    }
    // Window-modal but not blocking: the event loop (and tests) keep running.
    auto* box = new QMessageBox(QMessageBox::Warning, title, message, QMessageBox::Ok, this);
    box->setObjectName(QStringLiteral("errorMessageBox"));
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
    emit loadFailed(message);
}

QStringList MainWindow::recentFiles() {
    QStringList files = QSettings().value(QLatin1String(kRecentFilesKey)).toStringList();
    files.removeAll(QString());
    while (files.size() > kMaxRecentFiles) {
        files.removeLast();
    }
    return files;
}

void MainWindow::addRecentFiles(const QStringList& files) {
    if (files.isEmpty()) {
        return;
    }
    QStringList recent = recentFiles();
    for (auto it = files.crbegin(); it != files.crend(); ++it) {
        const QString absolute = QFileInfo(*it).absoluteFilePath();
        recent.removeAll(absolute);
        recent.prepend(absolute);
    }
    while (recent.size() > kMaxRecentFiles) {
        recent.removeLast();
    }
    QSettings().setValue(QLatin1String(kRecentFilesKey), recent);
    rebuildRecentMenu();
}

void MainWindow::rebuildRecentMenu() {
    recentMenu_->clear();
    const QStringList recent = recentFiles();
    int number = 1;
    for (const QString& file : recent) {
        QAction* action = recentMenu_->addAction(
            QStringLiteral("&%1 %2").arg(number++).arg(QFileInfo(file).fileName()), this,
            [this, file] { openFiles({file}); });
        action->setToolTip(file);
        action->setStatusTip(file);
    }
    if (!recent.isEmpty()) {
        recentMenu_->addSeparator();
    }
    QAction* clear = recentMenu_->addAction(tr("&Clear Recent Files"), this, [this] {
        QSettings().remove(QLatin1String(kRecentFilesKey));
        rebuildRecentMenu();
    });
    clear->setEnabled(!recent.isEmpty());
}

void MainWindow::setScreenshotTarget(const QString& path) {
    if (!path.isEmpty()) {
        // Screenshots show the default display, not what was remembered.
        resetViewSettings(*viewer_);
        syncControls();
    }
    screenshotPath_ = path;
    screenshotPending_ = !path.isEmpty();
    if (screenshotPending_) {
        QTimer::singleShot(kScreenshotTimeoutMs, this, [this] {
            if (screenshotPending_) {
                finishScreenshot(false, tr("timed out waiting for the data to be shown"));
            }
        });
    }
}

void MainWindow::updateVssLabel() {
    const render::VssFrameStatus& status = viewer_->vssStatus();
    if (!viewer_->scene() || !viewer_->vssSettings().enabled) {
        vssLabel_->clear();
    } else if (!status.shown) {
        vssLabel_->setText(status.pending ? tr("VSS: solving…") : tr("VSS: none"));
    } else if (status.preview || !status.current) {
        vssLabel_->setText(tr("VSS: preview"));
    } else {
        vssLabel_->setText(tr("VSS: exact, %1 ms").arg(std::lround(status.solveMilliseconds)));
    }
}

void MainWindow::onFrameRendered() {
    updateVssLabel();
    vssPanel_->updateStatus();
    displayPanel_->frameRendered();
    if (!screenshotPending_ || !viewer_->scene() || viewer_->framesWithScene() == 0) {
        return;
    }
    // With the VSS on, wait for the frame that shows the solved surface (the
    // solve runs on a worker and triggers that frame), and for its occlusion.
    if ((viewer_->vssSettings().enabled && viewer_->vssStatus().pending) ||
        viewer_->occlusionDeferred()) {
        return;
    }
    screenshotPending_ = false;
    const QImage image = viewer_->grabFramebuffer();
    if (image.isNull()) {
        finishScreenshot(false, tr("the viewer's frame could not be read"));
        return;
    }
    try {
        const std::filesystem::path target(QFile::encodeName(screenshotPath_).toStdString());
        writeAtomically(target, [&](const std::filesystem::path& temporary) {
            if (!image.save(QFile::decodeName(temporary.c_str()), "PNG")) {
                throw IoError(target, "cannot write the PNG image");
            }
        });
    } catch (const vv::Error& e) {
        finishScreenshot(false, QString::fromStdString(e.what()));
        return;
    }
    finishScreenshot(
        true, tr("saved %1 (%2 x %3)").arg(screenshotPath_).arg(image.width()).arg(image.height()));
}

void MainWindow::finishScreenshot(bool ok, const QString& message) {
    screenshotPending_ = false;
    const QByteArray text = message.toLocal8Bit();
    std::fprintf(ok ? stdout : stderr, "vesselview: %s\n", text.constData());
    std::fflush(ok ? stdout : stderr);
    const int code = ok ? 0 : 1;
    // Exit from the event loop, also when called before exec() started.
    QTimer::singleShot(0, qApp, [code] { QCoreApplication::exit(code); });
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
    const QStringList any = localFiles(event->mimeData(), false);
    const bool session = std::any_of(any.begin(), any.end(), [](const QString& f) {
        return QFileInfo(f).suffix().compare(QLatin1String(kSessionSuffix), Qt::CaseInsensitive) ==
               0;
    });
    const bool dicom = std::any_of(any.begin(), any.end(), [](const QString& f) {
        return QFileInfo(f).isDir() ||
               segmentation::isDicomSource(QFile::encodeName(f).toStdString());
    });
    if (session || dicom || !localFiles(event->mimeData(), true).isEmpty()) {
        event->acceptProposedAction();
    }
}

void MainWindow::dropEvent(QDropEvent* event) {
    for (const QString& file : localFiles(event->mimeData(), false)) {
        if (QFileInfo(file).suffix().compare(QLatin1String(kSessionSuffix), Qt::CaseInsensitive) ==
            0) {
            event->acceptProposedAction();
            openSession(file);
            return;
        }
    }
    const QStringList files = localFiles(event->mimeData(), true);
    if (!files.isEmpty()) {
        event->acceptProposedAction();
        openFiles(files);
        return;
    }
    // A folder, DICOMDIR or DICOM file: the series chooser (the first one dropped).
    for (const QString& file : localFiles(event->mimeData(), false)) {
        if (QFileInfo(file).isDir() ||
            segmentation::isDicomSource(QFile::encodeName(file).toStdString())) {
            event->acceptProposedAction();
            openDicom(file);
            return;
        }
    }
}

void MainWindow::closeEvent(QCloseEvent* event) {
    if (task_) {
        task_->cancel();
    }
    if (screenshotPath_.isEmpty()) {
        QSettings settings;
        settings.setValue(QLatin1String(kGeometryKey), saveGeometry());
        settings.setValue(QLatin1String(kLayoutKey), saveState(kLayoutVersion));
        saveViewSettings(*viewer_, settings);
    }
    event->accept();
}

QString MainWindow::aboutText() const {
    const QString gl =
        viewer_->glDescription().isEmpty() ? tr("not initialised") : viewer_->glDescription();
    QStringList libraries;
    libraries << QStringLiteral("Qt %1 (%2)")
                     .arg(QString::fromLatin1(qVersion()),
                          tr("built with %1").arg(QStringLiteral(QT_VERSION_STR)));
    libraries << QStringLiteral("VTK ") + QString::fromStdString(meshio::vtkVersion());
    libraries << QStringLiteral("DCMTK ") + QString::fromStdString(dicom::dcmtkVersion());
    libraries << QStringLiteral("OpenCV ") + QString::fromStdString(vss::openCvVersion());
    for (QString& library : libraries) {
        library = library.toHtmlEscaped();
    }
    return tr("<h3>VesselView %1</h3>"
              "<p>A workstation for vessel trees: meshes with wall shear stress, pressure and "
              "other parameters on the vessel wall, and Void Space Surfaces.</p>"
              "<p>OpenGL: %2</p><p>Libraries: %3</p>"
              "<p>Licensed under the GNU General Public License, version 3 or later.</p>")
        .arg(QStringLiteral(VV_VERSION), gl.toHtmlEscaped(),
             libraries.join(QStringLiteral("<br>")));
}

void MainWindow::showAbout() {
    QMessageBox::about(this, tr("About VesselView"), aboutText());
}

}  // namespace vv::gui
