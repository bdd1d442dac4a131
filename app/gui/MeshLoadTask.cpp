// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/MeshLoadTask.h"

#include <QtConcurrent/QtConcurrentRun>
#include <algorithm>
#include <cmath>
#include <exception>
#include <mutex>
#include <string>

#include "vv/core/Error.h"
#include "vv/core/Progress.h"
#include "vv/io/DemoTree.h"
#include "vv/io/MeshLoader.h"

namespace vv::gui {

namespace {

QString toQString(const std::filesystem::path& path) {
    return QString::fromStdString(path.string());
}

}  // namespace

MeshLoadTask* MeshLoadTask::loadFiles(std::vector<std::filesystem::path> files, QObject* parent) {
    return new MeshLoadTask(std::move(files), false, parent);
}

MeshLoadTask* MeshLoadTask::generateDemo(QObject* parent) {
    return new MeshLoadTask({}, true, parent);
}

MeshLoadTask::MeshLoadTask(std::vector<std::filesystem::path> files, bool demo, QObject* parent)
    : QObject(parent), files_(std::move(files)), demo_(demo) {
    if (demo_) {
        description_ = tr("Generating the demo vessel tree");
    } else if (files_.size() == 1) {
        description_ = tr("Loading %1").arg(toQString(files_.front().filename()));
    } else {
        description_ = tr("Loading %n file(s)", nullptr, static_cast<int>(files_.size()));
    }
    connect(&watcher_, &QFutureWatcher<Result>::finished, this, &MeshLoadTask::deliver);
}

MeshLoadTask::~MeshLoadTask() {
    stop_.request_stop();
    if (started_) {
        future_.waitForFinished();
    }
}

void MeshLoadTask::start() {
    if (started_) {
        return;
    }
    started_ = true;
    future_ = QtConcurrent::run([this, stop = stop_.get_token()] { return work(stop); });
    watcher_.setFuture(future_);
}

void MeshLoadTask::cancel() {
    stop_.request_stop();
}

bool MeshLoadTask::isRunning() const {
    return started_ && !future_.isFinished();
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
                emit progressChanged(
                    permille / 1000.0,
                    QString::fromUtf8(stage.data(), static_cast<qsizetype>(stage.size())));
            }
        },
        std::move(stop));
    try {
        progress.throwIfCancelled();
        auto scene = std::make_shared<io::Scene>();
        if (demo_) {
            scene->meshes.push_back(io::generateDemoMesh({}, progress));
        } else {
            *scene = io::loadScene(files_, {}, progress);
        }
        result.scene = std::move(scene);
    } catch (const CancelledError&) {
        result.cancelled = true;
    } catch (const vv::Error& e) {
        result.file = toQString(e.file());
        result.problem = QString::fromStdString(e.problem());
    } catch (const std::exception& e) {
        result.problem = tr("unexpected error: %1").arg(QString::fromStdString(e.what()));
    } catch (...) {
        result.problem = tr("unexpected error");
    }
    return result;
}

void MeshLoadTask::deliver() {
    const Result result = future_.result();
    // A cancel that came too late to stop the worker still discards its result.
    if (result.cancelled || stop_.stop_requested()) {
        emit cancelled();
    } else if (result.scene) {
        emit loaded(result.scene);
    } else {
        emit failed(result.file, result.problem);
    }
    emit finished();
}

}  // namespace vv::gui
