// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/MainWindow.h"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QComboBox>
#include <QCoreApplication>
#include <QDir>
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
#include <vector>

#include "gui/MeshLoadTask.h"
#include "gui/ViewerWidget.h"
#include "vv/colormaps/ColorMap.h"
#include "vv/colormaps/DepthScale.h"
#include "vv/core/AtomicFile.h"
#include "vv/core/Error.h"
#include "vv/io/MeshLoader.h"
#include "vv/render/MeshRenderer.h"

namespace vv::gui {

namespace {

constexpr int kMaxRecentFiles = 8;
const char* const kRecentFilesKey = "recentFiles";
/// Screenshot mode gives up when no frame was saved within this time.
constexpr int kScreenshotTimeoutMs = 10 * 60 * 1000;

bool hasSupportedExtension(const QString& file) {
    const QString suffix = "." + QFileInfo(file).suffix().toLower();
    const auto& extensions = io::supportedMeshExtensions();
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

/// "wss [Pa]" for an array that has a unit somewhere in the scene, else "wss".
QString arrayLabel(const io::Scene& scene, const std::string& name) {
    for (const auto& mesh : scene.meshes) {
        const io::DataArray* array = mesh.pointArray(name);
        if (array != nullptr && !array->unit.empty()) {
            return QString::fromStdString(name + " [" + array->unit + "]");
        }
    }
    return QString::fromStdString(name);
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

    buildMenus();
    buildToolBar();
    buildStatusBar();
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
    file->addAction(tr("Open &Demo"), this, &MainWindow::openDemo);
    recentMenu_ = file->addMenu(tr("Open &Recent"));
    rebuildRecentMenu();
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
    connect(legendsAction_, &QAction::toggled, viewer_, &ViewerWidget::setLegendsVisible);

    QMenu* help = menuBar()->addMenu(tr("&Help"));
    help->addAction(tr("&About VesselView"), this, &MainWindow::showAbout);
}

void MainWindow::buildToolBar() {
    QToolBar* bar = addToolBar(tr("Display"));
    bar->setObjectName(QStringLiteral("displayToolBar"));
    bar->setMovable(false);
    bar->addWidget(new QLabel(tr(" Array: "), bar));
    arrayCombo_ = new QComboBox(bar);
    arrayCombo_->setObjectName(QStringLiteral("arrayChooser"));
    arrayCombo_->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    arrayCombo_->setToolTip(tr("Point array shown on the vessel wall through the colour map"));
    arrayCombo_->addItem(tr("None"), QString());
    bar->addWidget(arrayCombo_);
    bar->addWidget(new QLabel(tr("  Colour map: "), bar));
    colorMapCombo_ = new QComboBox(bar);
    colorMapCombo_->setObjectName(QStringLiteral("colorMapChooser"));
    for (const auto map : colormaps::allColorMaps()) {
        colorMapCombo_->addItem(
            QString::fromUtf8(colormaps::displayName(map).data(),
                              static_cast<qsizetype>(colormaps::displayName(map).size())),
            static_cast<int>(map));
    }
    bar->addWidget(colorMapCombo_);
    connect(arrayCombo_, &QComboBox::currentIndexChanged, this, &MainWindow::applyStyle);
    connect(colorMapCombo_, &QComboBox::currentIndexChanged, this, &MainWindow::applyStyle);

    bar->addSeparator();
    vssAction_ = bar->addAction(tr("VSS"));
    vssAction_->setObjectName(QStringLiteral("vssToggle"));
    vssAction_->setCheckable(true);
    vssAction_->setChecked(viewer_->vssSettings().enabled);
    vssAction_->setToolTip(
        tr("Void Space Surface: a depth-coded surface in the space "
           "between the vessels"));
    bar->addWidget(new QLabel(tr(" p: "), bar));
    vssPowerBox_ = new QDoubleSpinBox(bar);
    vssPowerBox_->setObjectName(QStringLiteral("vssPower"));
    vssPowerBox_->setRange(0.25, 64.0);
    vssPowerBox_->setDecimals(2);
    vssPowerBox_->setSingleStep(0.5);
    vssPowerBox_->setValue(viewer_->vssSettings().solver.p);
    vssPowerBox_->setKeyboardTracking(false);  // solve once per entered value, not per digit
    vssPowerBox_->setToolTip(
        tr("Interpolation power p: higher values follow the nearest "
           "vessel more closely"));
    bar->addWidget(vssPowerBox_);
    bar->addWidget(new QLabel(tr("  Depth scale: "), bar));
    depthScaleCombo_ = new QComboBox(bar);
    depthScaleCombo_->setObjectName(QStringLiteral("depthScaleChooser"));
    for (const auto scale : colormaps::allDepthScales()) {
        const auto label = colormaps::displayName(scale);
        depthScaleCombo_->addItem(
            QString::fromUtf8(label.data(), static_cast<qsizetype>(label.size())),
            static_cast<int>(scale));
    }
    depthScaleCombo_->setCurrentIndex(
        depthScaleCombo_->findData(static_cast<int>(viewer_->vssSettings().scale)));
    bar->addWidget(depthScaleCombo_);
    connect(vssAction_, &QAction::toggled, this, &MainWindow::applyVss);
    QAction* aoAction = bar->addAction(tr("AO"));
    aoAction->setObjectName(QStringLiteral("aoToggle"));
    aoAction->setCheckable(true);
    aoAction->setChecked(viewer_->aoSettings().enabled);
    aoAction->setToolTip(tr("Ambient occlusion: shade the surface next to the vessels"));
    connect(aoAction, &QAction::toggled, this, [this](bool on) {
        render::AoSettings ao = viewer_->aoSettings();
        ao.enabled = on;
        viewer_->setAoSettings(ao);
    });
    bar->addSeparator();
    bar->addWidget(new QLabel(tr(" Vessel cue: "), bar));
    cueCombo_ = new QComboBox(bar);
    cueCombo_->setObjectName(QStringLiteral("vesselCueChooser"));
    cueCombo_->setToolTip(tr("A depth cue on the vessels themselves, for comparison"));
    for (const auto cue : render::allVesselCues()) {
        const auto label = render::displayName(cue);
        cueCombo_->addItem(QString::fromUtf8(label.data(), static_cast<qsizetype>(label.size())),
                           static_cast<int>(cue));
    }
    cueCombo_->setCurrentIndex(cueCombo_->findData(static_cast<int>(viewer_->vesselCue().cue)));
    bar->addWidget(cueCombo_);
    connect(cueCombo_, &QComboBox::currentIndexChanged, this, [this] {
        render::VesselCueSettings cue = viewer_->vesselCue();
        cue.cue = static_cast<render::VesselCue>(cueCombo_->currentData().toInt());
        viewer_->setVesselCue(cue);
    });
    connect(vssPowerBox_, &QDoubleSpinBox::valueChanged, this, &MainWindow::applyVss);
    connect(depthScaleCombo_, &QComboBox::currentIndexChanged, this, &MainWindow::applyVss);
}

void MainWindow::applyVss() {
    render::VssSettings settings = viewer_->vssSettings();
    settings.enabled = vssAction_->isChecked();
    settings.solver.p = vssPowerBox_->value();
    settings.scale = static_cast<colormaps::DepthScale>(depthScaleCombo_->currentData().toInt());
    vssPowerBox_->setEnabled(settings.enabled);
    depthScaleCombo_->setEnabled(settings.enabled);
    viewer_->setVssSettings(settings);
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
    statusBar()->addPermanentWidget(vssLabel_);
    statusBar()->addPermanentWidget(rangeLabel_);
    statusBar()->addPermanentWidget(progressBar_);
    statusBar()->addPermanentWidget(cancelButton_);
    progressBar_->hide();
    cancelButton_->hide();
}

QString MainWindow::meshFileFilter() {
    QStringList patterns;
    for (const auto& extension : io::supportedMeshExtensions()) {
        const QString e = QString::fromStdString(extension);
        patterns << "*" + e << "*" + e.toUpper();
    }
    return tr("Meshes (%1)").arg(patterns.join(' ')) + QStringLiteral(";;") + tr("All files (*)");
}

std::optional<QString> MainWindow::findDemoFile() {
    const QString fromEnv = qEnvironmentVariable("VV_DEMO_FILE");
    if (!fromEnv.isEmpty()) {
        return fromEnv;
    }
    const QDir exeDir(QCoreApplication::applicationDirPath());
    for (const char* relative :
         {"../resources/demo/vessel-tree.vtp", "../share/vesselview/demo/vessel-tree.vtp"}) {
        const QString candidate = QDir::cleanPath(exeDir.filePath(QString::fromLatin1(relative)));
        if (QFileInfo(candidate).isFile()) {
            return candidate;
        }
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
            [this, task, files](std::shared_ptr<const io::Scene> scene) {
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
                setScene(std::move(scene), title);
                addRecentFiles(files);
            });
    connect(task, &MeshLoadTask::failed, this,
            [this, task](const QString& file, const QString& problem) {
                QString what = file;
                if (what.isEmpty() && !task->files().empty()) {
                    what = QString::fromStdString(task->files().front().string());
                }
                const QString message = what.isEmpty() ? problem : tr("%1: %2").arg(what, problem);
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

void MainWindow::setScene(std::shared_ptr<const io::Scene> scene, const QString& title) {
    viewer_->setScene(scene);
    {
        const QSignalBlocker blocker(arrayCombo_);
        arrayCombo_->clear();
        arrayCombo_->addItem(tr("None"), QString());
        if (scene) {
            for (const auto& name : render::pointArrayNames(*scene)) {
                arrayCombo_->addItem(arrayLabel(*scene, name), QString::fromStdString(name));
            }
            const int index =
                arrayCombo_->findData(QString::fromStdString(render::defaultArrayName(*scene)));
            arrayCombo_->setCurrentIndex(std::max(index, 0));
        }
    }
    applyStyle();
    setWindowTitle(title.isEmpty() ? QStringLiteral("VesselView")
                                   : title + QStringLiteral(" — VesselView"));
    if (scene) {
        std::size_t triangles = 0;
        for (const auto& mesh : scene->meshes) {
            triangles += mesh.triangleCount();
        }
        const QString meshes =
            scene->meshes.size() == 1 ? tr("1 mesh") : tr("%1 meshes").arg(scene->meshes.size());
        statusLabel_->setText(
            tr("%1: %2, %3 triangles")
                .arg(title, meshes, QLocale().toString(static_cast<qulonglong>(triangles))));
    } else {
        statusLabel_->setText(tr("Ready"));
    }
    lastError_.clear();
    emit sceneShown();
}

void MainWindow::applyStyle() {
    render::MeshStyle style = viewer_->style();
    style.array = arrayCombo_->currentData().toString().toStdString();
    style.colorMap = static_cast<colormaps::ColorMap>(colorMapCombo_->currentData().toInt());
    style.range.reset();
    viewer_->setStyle(style);
    updateRangeLabel();
}

void MainWindow::updateRangeLabel() {
    const auto& scene = viewer_->scene();
    const std::string& array = viewer_->style().array;
    if (!scene || array.empty()) {
        rangeLabel_->clear();
        return;
    }
    const auto range = render::arrayRange(*scene, array);
    if (!range) {
        rangeLabel_->setText(tr("%1: no data").arg(arrayLabel(*scene, array)));
        return;
    }
    rangeLabel_->setText(tr("%1: %2 – %3")
                             .arg(arrayLabel(*scene, array))
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
    if (!screenshotPending_ || !viewer_->scene() || viewer_->framesWithScene() == 0) {
        return;
    }
    // With the VSS on, wait for the frame that shows the solved surface (the
    // solve runs on a worker and triggers that frame).
    if (viewer_->vssSettings().enabled && viewer_->vssStatus().pending) {
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
    if (!localFiles(event->mimeData(), true).isEmpty()) {
        event->acceptProposedAction();
    }
}

void MainWindow::dropEvent(QDropEvent* event) {
    const QStringList files = localFiles(event->mimeData(), true);
    if (!files.isEmpty()) {
        event->acceptProposedAction();
        openFiles(files);
    }
}

void MainWindow::closeEvent(QCloseEvent* event) {
    if (task_) {
        task_->cancel();
    }
    event->accept();
}

void MainWindow::showAbout() {
    const QString gl =
        viewer_->glDescription().isEmpty() ? tr("not initialised") : viewer_->glDescription();
    QMessageBox::about(
        this, tr("About VesselView"),
        tr("<h3>VesselView %1</h3>"
           "<p>A workstation for vessel trees: meshes with wall shear stress, pressure and "
           "other parameters on the vessel wall, and Void Space Surfaces.</p>"
           "<p>OpenGL: %2<br>Qt: %3</p>"
           "<p>Licensed under the GNU General Public License, version 3 or later.</p>")
            .arg(QStringLiteral(VV_VERSION), gl.toHtmlEscaped(), QString::fromLatin1(qVersion())));
}

}  // namespace vv::gui
