// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/analysis/AnalysisTask.h"

#include <algorithm>
#include <chrono>
#include <exception>
#include <string>
#include <utility>

#include "gui/StageProgress.h"
#include "vv/analysis/AnalysisError.h"
#include "vv/core/Error.h"

namespace vv::gui {

AnalysisTask::AnalysisTask(std::shared_ptr<const scene::Scene> scene,
                           analysis::CenterlineOptions options, QObject* parent)
    : QObject(parent), scene_(std::move(scene)), options_(std::move(options)) {
    connect(&run_.watcher(), &QFutureWatcher<Result>::finished, this, &AnalysisTask::deliver);
}

void AnalysisTask::start() {
    run_.start([this](std::stop_token stop) { return work(std::move(stop)); });
}

AnalysisTask::Result AnalysisTask::work(std::stop_token stop) {
    // Worker thread: reads scene_ and options_ (immutable while running),
    // emits progressChanged (queued to the GUI thread).
    Result result;
    if (scene_ == nullptr || scene_->meshes.empty()) {
        result.problem = {tr("The scene has no vessel surface to analyse."), {}};
        return result;
    }
    const Progress progress = stageProgress(
        [this](double fraction, const QString& stage) { emit progressChanged(fraction, stage); },
        std::move(stop));
    const auto started = std::chrono::steady_clock::now();
    try {
        result.analysis = std::make_shared<const analysis::VesselAnalysis>(
            analysis::analyseVessels(scene_->meshes.front(), options_, progress));
    } catch (const CancelledError&) {
        result.cancelled = true;
    } catch (const analysis::AnalysisError& e) {
        result.problem = {tr("The surface cannot be analysed."), QString::fromStdString(e.what())};
    } catch (const std::exception& e) {
        result.problem = describeProblem(e, FileAccess::Reading);
    }
    result.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return result;
}

void AnalysisTask::deliver() {
    const Result result = run_.result();
    workSeconds_ = result.seconds;
    if (result.cancelled || run_.stopRequested()) {
        emit cancelled();
    } else if (result.analysis) {
        emit succeeded(result.analysis);
    } else {
        emit failed(result.problem);
    }
    emit finished();
}

}  // namespace vv::gui
