// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/MeshLoadTask.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <string>

#include "gui/EngineTexts.h"
#include "vv/core/Error.h"
#include "vv/core/Progress.h"
#include "vv/demo/DemoTree.h"
#include "vv/meshio/MeshLoader.h"
#include "vv/segmentation/SceneSource.h"

namespace vv::gui {

namespace {

QString toQString(const std::filesystem::path& path) {
    return QString::fromStdString(path.string());
}

}  // namespace

MeshLoadTask* MeshLoadTask::loadFiles(std::vector<std::filesystem::path> files, QObject* parent) {
    return new MeshLoadTask(std::move(files), false, {}, parent);
}

MeshLoadTask* MeshLoadTask::loadFiles(std::vector<std::filesystem::path> files,
                                      segmentation::SceneSourceOptions dicomOptions,
                                      QObject* parent) {
    return new MeshLoadTask(std::move(files), false, std::move(dicomOptions), parent);
}

MeshLoadTask* MeshLoadTask::scanDicom(std::filesystem::path path, QObject* parent) {
    auto* task = new MeshLoadTask({std::move(path)}, false, {}, parent);
    task->scan_ = true;
    task->description_ =
        tr("Reading the DICOM headers of %1").arg(toQString(task->files_.front().filename()));
    return task;
}

MeshLoadTask* MeshLoadTask::generateDemo(QObject* parent) {
    return new MeshLoadTask({}, true, {}, parent);
}

MeshLoadTask::MeshLoadTask(std::vector<std::filesystem::path> files, bool demo,
                           segmentation::SceneSourceOptions dicomOptions, QObject* parent)
    : QObject(parent),
      files_(std::move(files)),
      demo_(demo),
      dicomOptions_(std::move(dicomOptions)) {
    if (demo_) {
        description_ = tr("Generating the demo vessel tree");
    } else if (files_.size() == 1) {
        describeAs(toQString(files_.front().filename()));
    } else {
        description_ = tr("Loading %n file(s)", nullptr, static_cast<int>(files_.size()));
    }
    connect(&run_.watcher(), &QFutureWatcher<Result>::finished, this, &MeshLoadTask::deliver);
}

MeshLoadTask::~MeshLoadTask() = default;

void MeshLoadTask::describeAs(const QString& name) {
    description_ = tr("Loading %1").arg(name);
}

void MeshLoadTask::start() {
    run_.start([this](std::stop_token stop) { return work(std::move(stop)); });
}

void MeshLoadTask::cancel() {
    run_.cancel();
}

bool MeshLoadTask::isRunning() const {
    return run_.isRunning();
}

MeshLoadTask::Result MeshLoadTask::work(std::stop_token stop) {
    // Runs on the worker thread: touches only its arguments, files_ and
    // demo_ (immutable while running) and emits progressChanged (queued).
    Result result;
    // Throttles the signals; locked in case the engine reports from several threads.
    std::mutex throttle;
    int lastPermille = -1;
    std::string lastStage;
    Progress progress(
        [this, &throttle, &lastPermille, &lastStage](double fraction, std::string_view stage) {
            const int permille =
                static_cast<int>(std::lround(std::clamp(fraction, 0.0, 1.0) * 1000));
            const std::lock_guard lock(throttle);
            if (std::abs(permille - lastPermille) >= 5 || stage != lastStage) {
                lastPermille = permille;
                lastStage = std::string(stage);
                emit progressChanged(permille / 1000.0,
                                     translatedStage(QString::fromUtf8(
                                         stage.data(), static_cast<qsizetype>(stage.size()))));
            }
        },
        std::move(stop));
    try {
        progress.throwIfCancelled();
        if (scan_) {
            result.scan = std::make_shared<const dicom::DicomScanResult>(
                dicom::scanDicom(files_.front(), progress));
            return result;
        }
        auto scene = std::make_shared<scene::Scene>();
        if (demo_) {
            scene->meshes.push_back(demo::generateDemoMesh({}, progress));
        } else {
            // DICOM sources segmented one by one, meshes as before; the last
            // DICOM source's report.
            segmentation::SceneSourceReport report;
            *scene = segmentation::loadSceneSources(files_, dicomOptions_, progress, &report);
            if (std::any_of(files_.begin(), files_.end(),
                            [](const auto& f) { return segmentation::isDicomSource(f); })) {
                result.dicomReport = std::move(report);
            }
        }
        result.scene = std::move(scene);
    } catch (const CancelledError&) {
        result.cancelled = true;
    } catch (const vv::Error& e) {
        result.file = toQString(e.file());
        result.problem = describeProblem(e, FileAccess::Reading);
    } catch (const std::exception& e) {
        result.problem = describeProblem(e, FileAccess::Reading);
    } catch (...) {
        result.problem =
            describeProblem(std::runtime_error("unknown exception"), FileAccess::Reading);
    }
    return result;
}

void MeshLoadTask::deliver() {
    const Result result = run_.result();
    // A cancel that came too late to stop the worker still discards its result.
    if (result.cancelled || run_.stopRequested()) {
        emit cancelled();
    } else if (result.scan) {
        emit scanned(result.scan);
    } else if (result.scene) {
        dicomReport_ = result.dicomReport;
        emit loaded(result.scene);
    } else {
        emit failed(result.file, result.problem);
    }
    emit finished();
}

}  // namespace vv::gui
