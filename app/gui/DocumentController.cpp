// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/DocumentController.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QTimer>
#include <algorithm>
#include <utility>
#include <vector>

#include "common/ResourcePaths.h"
#include "common/SegmentationText.h"
#include "gui/MeshLoadTask.h"
#include "gui/RecentFiles.h"
#include "gui/SeriesName.h"
#include "vv/core/Error.h"
#include "vv/meshio/MeshLoader.h"

namespace vv::gui {

namespace {

std::filesystem::path toPath(const QString& file) {
    return {QFile::encodeName(file).toStdString()};
}

bool isSessionFile(const QString& file) {
    return QFileInfo(file).suffix().compare(QLatin1String(kSessionSuffix), Qt::CaseInsensitive) ==
           0;
}

bool isMeshFile(const QString& file) {
    const QString suffix = "." + QFileInfo(file).suffix().toLower();
    const auto& extensions = meshio::supportedMeshExtensions();
    return std::any_of(extensions.begin(), extensions.end(),
                       [&](const std::string& e) { return suffix == QString::fromStdString(e); });
}

/// A folder, DICOMDIR or DICOM file: opened through the series chooser.
bool isDicomPath(const QString& file) {
    return QFileInfo(file).isDir() || segmentation::isDicomSource(toPath(file));
}

}  // namespace

DocumentController::DocumentController(QObject* parent) : QObject(parent) {}

DocumentController::~DocumentController() {
    if (!task_.isNull()) {
        disconnect(task_.data(), nullptr, this, nullptr);
        task_->cancel();
    }
}

void DocumentController::openFiles(const QStringList& files) {
    std::vector<std::filesystem::path> paths;
    QStringList names;
    for (const QString& f : files) {
        if (!f.isEmpty()) {
            paths.push_back(toPath(f));
            names << f;
        }
    }
    if (paths.empty()) {
        return;
    }
    startTask(MeshLoadTask::loadFiles(std::move(paths), this), names);
}

void DocumentController::openDicom(const QString& path) {
    if (path.isEmpty()) {
        return;
    }
    MeshLoadTask* task = MeshLoadTask::scanDicom(toPath(path), this);
    connect(task, &MeshLoadTask::scanned, this,
            [this, path](std::shared_ptr<const dicom::DicomScanResult> scan) {
                if (scan->allSeries().empty()) {
                    const int skipped = static_cast<int>(scan->skipped.size());
                    fail(tr("Cannot open"),
                         {tr("%1: no DICOM images found (%n file(s) skipped)", nullptr, skipped)
                              .arg(path),
                          {}});
                    return;
                }
                emit seriesScanned(std::move(scan), path);
            });
    // No files for the title / recent list: the chosen series' task has them.
    startTask(task, {});
}

void DocumentController::openSeries(const QString& path,
                                    const segmentation::SceneSourceOptions& options,
                                    const QString& title) {
    std::vector<std::filesystem::path> paths{toPath(path)};
    startTask(MeshLoadTask::loadFiles(std::move(paths), options, this), {path}, title);
}

void DocumentController::openRecent(const QString& file) {
    const std::optional<SeriesIdentity> series = recent::series(file);
    if (!series || series->uid.isEmpty()) {
        openFiles({file});
        return;
    }
    segmentation::SceneSourceOptions options;
    options.seriesInstanceUid = series->uid.toStdString();
    openSeries(file, options, seriesName(*series));
}

void DocumentController::openDemo() {
    if (const auto file = findDemoFile()) {
        std::vector<std::filesystem::path> paths{toPath(*file)};
        // Not remembered in the recent files: it is one menu entry away anyway.
        startTask(MeshLoadTask::loadFiles(std::move(paths), this), {});
    } else {
        startTask(MeshLoadTask::generateDemo(this), {});
    }
    demoTask_ = task_;
}

bool DocumentController::openSession(const QString& path) {
    Session session;
    try {
        session = loadSession(toPath(path));
    } catch (const vv::Error& e) {
        fail(tr("Cannot open the session"), describeProblem(e, FileAccess::Reading));
        return false;
    }
    if (session.files.isEmpty()) {
        // The session replaces whatever was being loaded.
        if (abandonTask()) {
            emit loadEnded();
        }
        openedFiles_.clear();
        shownFiles_.clear();
        seriesUid_.clear();
        seriesTitle_.clear();
        demo_ = false;
        setVolume(nullptr, {}, {});
        show(nullptr, QString(), std::move(session));
        return true;
    }
    const MeshLoadTask* before = task_.data();
    if (session.dicom && session.files.size() == 1) {
        std::vector<std::filesystem::path> paths{toPath(session.files.front())};
        // Named as when it was saved (its folder may be a UID), not after the folder.
        startTask(MeshLoadTask::loadFiles(std::move(paths), *session.dicom, this), session.files,
                  session.seriesTitle);
    } else {
        openFiles(session.files);
    }
    if (!task_.isNull() && task_.data() != before) {
        pendingSession_ = std::move(session);  // until the new task's files are shown
    }
    return true;
}

bool DocumentController::saveSession(const QString& path, Session view) {
    view.files.clear();
    view.dicom.reset();
    view.seriesTitle.clear();
    if (scene_) {
        for (const QString& f : shownFiles_) {
            view.files << QFileInfo(f).absoluteFilePath();
        }
        if (!seriesUid_.empty()) {
            // DICOM data: the series, and for an image series the settings of
            // the document's segmentation (never a preview's), so that the
            // session reopens without asking.
            segmentation::SceneSourceOptions dicom;
            dicom.seriesInstanceUid = seriesUid_;
            if (volume_) {
                dicom.segmentation = loadedWith_.segmentation;
                dicom.surface = loadedWith_.surface;
            }
            view.dicom = dicom;
            view.seriesTitle = seriesTitle_;
        }
    }
    try {
        app::saveSession(toPath(path), view);
    } catch (const vv::Error& e) {
        fail(tr("Cannot save the session"), describeProblem(e, FileAccess::Writing));
        return false;
    }
    return true;
}

bool DocumentController::openDropped(const QStringList& paths) {
    const auto session = std::find_if(paths.begin(), paths.end(), isSessionFile);
    if (session != paths.end()) {
        openSession(*session);
        return true;
    }
    QStringList meshes;
    std::copy_if(paths.begin(), paths.end(), std::back_inserter(meshes), isMeshFile);
    if (!meshes.isEmpty()) {
        openFiles(meshes);
        return true;
    }
    // A folder, DICOMDIR or DICOM file: the series chooser (the first one dropped).
    const auto dicom = std::find_if(paths.begin(), paths.end(), isDicomPath);
    if (dicom != paths.end()) {
        openDicom(*dicom);
        return true;
    }
    return false;
}

bool DocumentController::canOpen(const QStringList& paths) {
    return std::any_of(paths.begin(), paths.end(), [](const QString& f) {
        return isSessionFile(f) || isMeshFile(f) || isDicomPath(f);
    });
}

void DocumentController::setScene(std::shared_ptr<const scene::Scene> scene, const QString& title) {
    openedFiles_.clear();
    shownFiles_.clear();
    seriesUid_.clear();
    seriesTitle_.clear();
    demo_ = false;
    preview_ = false;
    setVolume(nullptr, {}, {});
    show(std::move(scene), title, std::nullopt);
}

void DocumentController::showDerivedScene(std::shared_ptr<const scene::Scene> scene, bool preview) {
    openedFiles_ = shownFiles_;
    preview_ = preview;
    show(std::move(scene), title_, std::nullopt);
}

void DocumentController::applySegmentation(std::shared_ptr<const scene::Scene> scene,
                                           std::shared_ptr<const scene::LabelMap> labelMap,
                                           app::SegmentationProvenance provenance,
                                           const segmentation::SegmentationOptions& options,
                                           const segmentation::SurfaceOptions& surface) {
    segmentedScene_ = std::move(scene);
    labelMap_ = std::move(labelMap);
    segmentation_ = std::move(provenance);
    loadedWith_.segmentation = options;
    loadedWith_.surface = surface;
    emit segmentationApplied();
}

bool DocumentController::cancelLoad() {
    if (task_.isNull()) {
        return false;
    }
    task_->cancel();
    return true;
}

QString DocumentController::dicomSource() const {
    const auto found = std::find_if(openedFiles_.begin(), openedFiles_.end(), [](const QString& f) {
        return segmentation::isDicomSource(toPath(f));
    });
    return found == openedFiles_.end() ? QString() : *found;
}

report::ReportSource DocumentController::reportSource() const {
    report::ReportSource source;
    for (const QString& file : shownFiles_) {
        const std::filesystem::path path = toPath(file);
        source.files.push_back(path);
        if (source.dicomPath.empty() && segmentation::isDicomSource(path)) {
            source.dicomPath = path;
            source.seriesInstanceUid = seriesUid_;
            source.seriesName = seriesTitle_.toStdString();  // never the UID folder
        }
    }
    if (volume_) {
        // How the image series was segmented, and whether a vessel may be cut off.
        source.segmentation = app::reportSegmentation(segmentation_);
    }
    // The demo tree (its bundled file, or generated when there is none): the
    // report says it is synthetic data.
    source.syntheticDemo =
        demo_ && std::all_of(source.files.begin(), source.files.end(),
                             [](const auto& file) { return vv::app::isDemoFile(file); });
    return source;
}

QString DocumentController::documentKey() const {
    if (shownFiles_.isEmpty()) {
        return QStringLiteral("scene:%1").arg(reinterpret_cast<quintptr>(scene_.get()));
    }
    return shownFiles_.join(QLatin1Char('\n')) + QLatin1Char('\n') +
           QString::fromStdString(seriesUid_);
}

QString DocumentController::findings() const {
    return findingsFor_ == documentKey() ? findings_ : QString();
}

void DocumentController::setFindings(const QString& findings) {
    findings_ = findings;
    findingsFor_ = documentKey();
}

DocumentController::ExportedReport DocumentController::exportedReport() const {
    return exportedReportFor_ == documentKey() ? exportedReport_ : ExportedReport{};
}

void DocumentController::setExportedReport(const ExportedReport& report) {
    exportedReport_ = report;
    exportedReportFor_ = documentKey();
}

QStringList DocumentController::recentFiles() {
    return recent::files();
}

void DocumentController::clearRecentFiles() {
    recent::clear();
    emit recentFilesChanged();
}

std::optional<QString> DocumentController::findDemoFile() {
    // $VV_DEMO_FILE, else relative to the binary: build tree or install prefix.
    if (const auto demo = vv::app::findDemoFile()) {
        return QFileInfo(*demo).absoluteFilePath();
    }
    return std::nullopt;
}

QString DocumentController::meshFileFilter() {
    QStringList patterns;
    for (const auto& extension : meshio::supportedMeshExtensions()) {
        const QString e = QString::fromStdString(extension);
        patterns << "*" + e << "*" + e.toUpper();
    }
    return tr("Meshes (%1)").arg(patterns.join(' ')) + QStringLiteral(";;") + tr("All files (*)");
}

bool DocumentController::abandonTask() {
    pendingSession_.reset();  // it waited for the old task's files
    if (task_.isNull()) {
        return false;
    }
    // The old task stops at its next progress report and deletes itself;
    // nothing it delivers reaches this document any more.
    MeshLoadTask* old = task_.data();
    disconnect(old, nullptr, this, nullptr);
    connect(old, &MeshLoadTask::finished, old, &QObject::deleteLater);
    old->cancel();
    task_ = nullptr;
    return true;
}

void DocumentController::startTask(MeshLoadTask* task, const QStringList& opened,
                                   const QString& title) {
    abandonTask();
    task_ = task;
    if (!title.isEmpty()) {
        task->describeAs(title);  // the status bar names the series as the title will
    }
    connect(task, &MeshLoadTask::progressChanged, this,
            [this, task](double fraction, const QString& stage) {
                if (task == task_) {
                    emit loadProgress(fraction, stage.isEmpty() ? QString()
                                                                : task->description() +
                                                                      QStringLiteral(": ") + stage);
                }
            });
    connect(task, &MeshLoadTask::loaded, this,
            [this, task, opened](std::shared_ptr<const scene::Scene> scene) {
                taskLoaded(task, opened, std::move(scene));
            });
    connect(task, &MeshLoadTask::failed, this,
            [this, task](const QString& file, const ProblemText& problem) {
                ProblemText shown = problem;
                if (file.isEmpty() && !task->files().empty()) {
                    // The problem names no file: the one being opened.
                    shown.summary = tr("%1: %2").arg(
                        QString::fromStdString(task->files().front().string()), problem.summary);
                }
                pendingSession_.reset();  // its files did not load
                fail(tr("Cannot open"), shown);
            });
    connect(task, &MeshLoadTask::cancelled, this, [this] {
        pendingSession_.reset();
        emit loadCancelled();
    });
    connect(task, &MeshLoadTask::finished, this, [this, task] { taskFinished(task); });
    emit loadStarted(task->description());
    task->start();
}

void DocumentController::taskLoaded(MeshLoadTask* task, const QStringList& opened,
                                    std::shared_ptr<const scene::Scene> scene) {
    // The title names the window: its strings keep the window's translation context.
    const int count = static_cast<int>(opened.size());
    const segmentation::SceneSourceReport& source = task->dicomReport();
    seriesUid_ = source.fromVolume || source.fromSegmentationObject ? source.seriesInstanceUid
                                                                    : std::string();
    // A DICOM series is named by what it says of itself, in today's UI
    // language (a session saved in another language, or a title given while
    // loading, does not stay).
    const std::optional<SeriesIdentity> series =
        seriesUid_.empty() ? std::nullopt : std::optional(seriesIdentity(source));
    seriesTitle_ = series ? seriesName(*series) : QString();
    QString title;
    if (!seriesTitle_.isEmpty() && count <= 1) {  // with other files: "%n files"
        title = seriesTitle_;
    } else if (count == 1) {
        title = QFileInfo(opened.front()).fileName();
    } else if (count > 1) {
        title = QCoreApplication::translate("vv::gui::MainWindow", "%n files", nullptr, count);
    } else if (!task->files().empty()) {
        title = QString::fromStdString(task->files().front().filename().string());
    } else {
        title = QCoreApplication::translate("vv::gui::MainWindow", "demo vessel tree");
    }
    openedFiles_ = opened;
    // The demo: opened as such, or its bundled file opened by name.
    const std::optional<QString> demoFile = findDemoFile();
    demo_ =
        task == demoTask_ ||
        (demoFile && std::any_of(task->files().begin(), task->files().end(), [&](const auto& f) {
             return QFileInfo(QFile::decodeName(f.string().c_str())).canonicalFilePath() ==
                    QFileInfo(*demoFile).canonicalFilePath();
         }));
    shownFiles_.clear();
    for (const auto& path : task->files()) {
        shownFiles_ << QFileInfo(QFile::decodeName(path.string().c_str())).absoluteFilePath();
    }
    preview_ = false;
    setVolume(nullptr, {}, {});
    if (!seriesUid_.empty()) {
        loadedReport_ = source;
        loadedWith_ = task->dicomOptions();
        segmentedScene_ = scene;
        segmentation_ = app::provenanceOf(source, loadedWith_);
    }
    show(std::move(scene), title, std::exchange(pendingSession_, std::nullopt));
    // A DICOM image series: keep its volume for the Segmentation panel.
    if (source.volume) {
        labelMap_ = source.labelMap;
        setVolume(source.volume, task->dicomOptions(), source.range);
    }
    recent::add(opened, opened.size() == 1 ? series : std::nullopt);
    if (!opened.isEmpty()) {
        emit recentFilesChanged();
    }
}

void DocumentController::taskFinished(MeshLoadTask* task) {
    task->deleteLater();
    if (task == task_) {
        task_ = nullptr;
        emit loadEnded();
    }
}

void DocumentController::show(std::shared_ptr<const scene::Scene> scene, const QString& title,
                              std::optional<Session> session) {
    scene_ = std::move(scene);
    title_ = title;
    emit sceneChanged(scene_, title_, openedFiles_);
    if (session) {
        // A session being opened: its settings and camera, now that its data is shown.
        emit sessionReady(*session);
        QTimer::singleShot(0, this, &DocumentController::sessionApplied);
    }
    lastError_.clear();
    emit sceneShown();
}

void DocumentController::setVolume(std::shared_ptr<const scene::Volume> volume,
                                   const segmentation::SceneSourceOptions& loadedWith,
                                   const segmentation::ThresholdRange& range) {
    volume_ = std::move(volume);
    if (!volume_) {
        labelMap_.reset();
        segmentedScene_.reset();
        segmentation_ = {};
        loadedReport_ = {};
        loadedWith_ = {};
    }
    emit volumeChanged(volume_, loadedWith, range);
}

void DocumentController::fail(const QString& title, const ProblemText& problem) {
    lastError_ = problem.line();
    emit failed(title, problem);
}

}  // namespace vv::gui
